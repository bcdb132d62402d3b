// mpm::io outputs of a 3D deck (Grid::dim = 3, issue 37), written the way mpm's main hands a Simulation's
// state to them (ResultsWriter::write_start / write_output with Simulation::snapshot() records and
// file_extras()) and read back: CB-Geo's /table, the /xdmf datasets and particles.xdmf (XYZ geometry,
// 3-component vectors, 6-component symmetric tensors xx yy zz xy yz xz), the VTK particle files, grid.vtr
// over three axes, series.csv's 3D columns, the 9-column /apic_affine dataset and its count check, and
// /pore_pressure (the same 3 columns in 3D). The 2D outputs are covered by results_test.cpp.
#include <gtest/gtest.h>

#include <hdf5.h>
#include <hdf5_hl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/input_error.hpp"
#include "mpm/io/particle_fields.hpp"
#include "mpm/io/particle_table.hpp"
#include "mpm/io/results.hpp"
#include "mpm/io/resume_extras.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace fs = std::filesystem;
using mpm::ParticleRecord;

namespace {

/// A 4 x 3 x 2-cell lattice of 0.5 m cells from (1, 2, 3): nodes 5 x 4 x 3.
mpm::Grid grid_3d() {
  mpm::Grid g;
  g.dim = 3;
  g.origin = {1, 2, 3};
  g.spacing = {0.5, 0.5, 0.5};
  g.nodes_per_axis = {5, 4, 3};
  g.region_min = {1.5, 2, 3};  // the first layer of nodes along x lies outside the mesh region
  g.region_max = {3, 3.5, 4};
  return g;
}

/// Three particles with every member of CB-Geo's 3D record set to a distinct value.
std::vector<ParticleRecord> three_particles() {
  std::vector<ParticleRecord> ps(3);
  for (int k = 0; k < 3; ++k) {
    ParticleRecord& p = ps[k];
    const double s = k + 1;
    p.id = 10 + k;
    p.mass = 2.0 * s;
    p.volume = 0.125 / 8;
    p.coord_x = 1.6 + 0.3 * k, p.coord_y = 2.2 + 0.4 * k, p.coord_z = 3.1 + 0.25 * k;
    p.displacement_x = 0.01 * s, p.displacement_y = -0.02 * s, p.displacement_z = 0.03 * s;
    p.nsize_x = p.nsize_y = p.nsize_z = 1.0;  // 2 x 2 x 2 particles per cell: 0.25 m each
    p.velocity_x = 1 * s, p.velocity_y = -2 * s, p.velocity_z = 3 * s;
    p.stress_xx = -100 * s, p.stress_yy = -200 * s, p.stress_zz = -300 * s;
    p.tau_xy = 10 * s, p.tau_yz = 20 * s, p.tau_xz = 30 * s;
    p.strain_xx = 1e-3 * s, p.strain_yy = 2e-3 * s, p.strain_zz = 3e-3 * s;
    p.gamma_xy = 4e-3 * s, p.gamma_yz = 6e-3 * s, p.gamma_xz = 8e-3 * s;
    p.epsilon_v = 6e-3 * s;
    p.cell_id = k;
    p.material_id = 1;
  }
  return ps;
}

/// An APIC 3D deck writing into `dir`/results/run, 101 steps, an output every 50.
mpm::Deck deck_3d(const fs::path& dir) {
  mpm::Deck deck;
  deck.working_dir = dir;
  deck.grid = grid_3d();
  deck.analysis.nsteps = 101;
  deck.analysis.transfer = mpm::Transfer::APIC;
  deck.analysis.gravity = Eigen::Vector2d(0, 0);
  deck.analysis.gravity_z = -10;
  deck.output.path = "results/";
  deck.output.uuid = "run";
  deck.output.output_steps = 50;
  deck.output.vtk_fields = {"velocity", "stress", "strain", "displacement"};
  deck.velocity_constraints.push_back({{0, 1, 2}, 2, 0.0});  // z fixed on three nodes of the bottom layer
  deck.velocity_constraints.push_back({{3}, 0, 0.0});
  return deck;
}

std::vector<mpm::AffineMatrix<3>> affine_rows() {
  return {{{1, 2, 3, 4, 5, 6, 7, 8, 9}}, {{-0.5, 1e-300, 0, -0.0, 2.5e-17, 1.0 / 3, 7, -8, 1e300}}, {{0, 0, 0, 0, 0, 0, 0, 0, -1}}};
}

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The values of DataArray `name` of a VTK XML file with raw appended data (vtk_files.hpp): its offset
/// attribute, then a UInt64 byte count and the bytes after the "_" of <AppendedData>.
template <class T>
std::vector<T> vtk_array(const std::string& xml, const std::string& name) {
  const auto at = xml.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return {};
  const auto off = xml.find("offset=\"", at) + 8;
  const std::size_t offset = std::stoull(xml.substr(off, xml.find('"', off) - off));
  const std::size_t data = xml.find("<AppendedData encoding=\"raw\">\n   _") + 34;
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, xml.data() + data + offset, sizeof bytes);
  std::vector<T> values(bytes / sizeof(T));
  std::memcpy(values.data(), xml.data() + data + offset + sizeof bytes, bytes);
  return values;
}

std::vector<double> read_xdmf_dataset(const fs::path& file, const char* name, std::vector<hsize_t>& dims) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << file;
  int rank = 0;
  H5LTget_dataset_ndims(f, name, &rank);
  dims.assign(static_cast<std::size_t>(rank), 0);
  H5LTget_dataset_info(f, name, dims.data(), nullptr, nullptr);
  std::size_t n = 1;
  for (auto d : dims) n *= d;
  std::vector<double> v(n);
  EXPECT_GE(H5LTread_dataset_double(f, name, v.data()), 0) << name;
  H5Fclose(f);
  return v;
}

}  // namespace

TEST(Results3d, ParticleTableAndXdmfDatasetsHoldTheWhole3dRecord) {
  const test_support::ScratchDir dir("geoflow_results_3d_table");
  const mpm::Deck deck = deck_3d(dir.path());
  const auto ps = three_particles();
  mpm::io::ResultsWriter w(deck);
  w.write_start(0.0, ps);
  w.write_output(50, 0.05, 1e-3, ps, {{}, std::nullopt, affine_rows()});
  const fs::path file = w.folder() / "particles050.h5";

  // CB-Geo's table: the same 53-member record as in 2D, every 3D member back bit for bit.
  const auto back = mpm::io::read_particle_table(file);
  ASSERT_EQ(back.size(), ps.size());
  for (std::size_t k = 0; k < ps.size(); ++k)
    EXPECT_EQ(std::memcmp(&back[k], &ps[k], sizeof(ParticleRecord)), 0) << "particle " << k;

  std::vector<hsize_t> dims;
  const auto xyz = read_xdmf_dataset(file, "/xdmf/coordinates", dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3, 3}));
  EXPECT_EQ(xyz[3 * 2 + 2], ps[2].coord_z);
  const auto velocity = read_xdmf_dataset(file, "/xdmf/velocity", dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3, 3}));
  EXPECT_EQ(velocity[3 * 1 + 2], ps[1].velocity_z);
  EXPECT_EQ(read_xdmf_dataset(file, "/xdmf/displacement", dims)[2], ps[0].displacement_z);
  const auto size = read_xdmf_dataset(file, "/xdmf/size", dims);
  EXPECT_EQ(std::vector<double>(size.begin(), size.begin() + 3), (std::vector<double>{0.25, 0.25, 0.25}));
  EXPECT_CLOSE(read_xdmf_dataset(file, "/xdmf/radius", dims)[0], 0.125, 0, 1e-15);  // half the side of the equal cube
  const auto stress = read_xdmf_dataset(file, "/xdmf/stress", dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3, 6}));
  EXPECT_EQ(std::vector<double>(stress.begin() + 6, stress.begin() + 12),
            (std::vector<double>{-200, -400, -600, 20, 40, 60}));  // xx yy zz xy yz xz
  const auto strain = read_xdmf_dataset(file, "/xdmf/strain", dims);
  EXPECT_EQ(std::vector<double>(strain.begin(), strain.begin() + 6),
            (std::vector<double>{1e-3, 2e-3, 3e-3, 2e-3, 3e-3, 4e-3}));  // tensorial shears: gamma / 2
  for (const char* scalar : {"/xdmf/tau_yz", "/xdmf/tau_xz", "/xdmf/strain_zz", "/xdmf/gamma_yz", "/xdmf/gamma_xz"}) {
    EXPECT_EQ(read_xdmf_dataset(file, scalar, dims).size(), 3u) << scalar;
    EXPECT_EQ(dims, (std::vector<hsize_t>{3})) << scalar;
  }
  EXPECT_EQ(read_xdmf_dataset(file, "/xdmf/gamma_xz", dims)[2], ps[2].gamma_xz);

  // The XDMF file: XYZ geometry of n x 3, vectors n x 3, symmetric tensors n x 6, the 3D scalars listed.
  const std::string xdmf = slurp(w.folder() / "particles.xdmf");
  for (const char* text : {"<Geometry GeometryType=\"XYZ\">\n     <DataItem Dimensions=\"3 3\" NumberType=\"Float\" "
                           "Precision=\"8\" Format=\"HDF\">particles050.h5:/xdmf/coordinates</DataItem>",
                           "<Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n     <DataItem "
                           "Dimensions=\"3 3\"",
                           "<Attribute Name=\"stress\" AttributeType=\"Tensor6\" Center=\"Node\">\n     <DataItem "
                           "Dimensions=\"3 6\"",
                           "<Attribute Name=\"strain\" AttributeType=\"Tensor6\" Center=\"Node\">\n     <DataItem "
                           "Dimensions=\"3 6\"",
                           "<Attribute Name=\"tau_xz\" AttributeType=\"Scalar\" Center=\"Node\">\n     <DataItem "
                           "Dimensions=\"3\"",
                           "initial_state.h5:/xdmf/gamma_yz"})
    EXPECT_NE(xdmf.find(text), std::string::npos) << text;
}

TEST(Results3d, VtkParticleFilesAndGridOverThreeAxes) {
  const test_support::ScratchDir dir("geoflow_results_3d_vtk");
  const mpm::Deck deck = deck_3d(dir.path());
  const auto ps = three_particles();
  mpm::io::ResultsWriter w(deck);
  w.write_output(0, 0.001, 1e-3, ps);
  const std::string vtp = slurp(w.folder() / "particles000.vtp");
  EXPECT_NE(vtp.find("<Piece NumberOfPoints=\"3\" NumberOfVerts=\"3\""), std::string::npos);
  for (const char* a : {"Name=\"Points\" NumberOfComponents=\"3\"", "Name=\"velocity\" NumberOfComponents=\"3\"",
                        "Name=\"displacement\" NumberOfComponents=\"3\"", "Name=\"stress\" NumberOfComponents=\"6\"",
                        "Name=\"strain\" NumberOfComponents=\"6\""})
    EXPECT_NE(vtp.find(a), std::string::npos) << a;
  const auto points = vtk_array<double>(vtp, "Points");
  ASSERT_EQ(points.size(), 9u);
  EXPECT_EQ(points[3 * 2 + 2], ps[2].coord_z);
  const auto velocity = vtk_array<double>(vtp, "velocity");
  ASSERT_EQ(velocity.size(), 9u);
  EXPECT_EQ(velocity[2], ps[0].velocity_z);
  const auto stress = vtk_array<double>(vtp, "stress");
  ASSERT_EQ(stress.size(), 18u);
  EXPECT_EQ(std::vector<double>(stress.begin(), stress.begin() + 6), (std::vector<double>{-100, -200, -300, 10, 20, 30}));
  EXPECT_NE(slurp(w.folder() / "particles.pvd").find("file=\"particles000.vtp\""), std::string::npos);

  // grid.vtr: extents and coordinates on three axes, a fixed_z array, in_mesh over the three axes.
  const std::string grid = slurp(w.folder() / "grid.vtr");
  EXPECT_NE(grid.find("WholeExtent=\"0 4 0 3 0 2\""), std::string::npos);
  EXPECT_NE(grid.find("<Piece Extent=\"0 4 0 3 0 2\">"), std::string::npos);
  EXPECT_EQ(vtk_array<double>(grid, "x"), (std::vector<double>{1, 1.5, 2, 2.5, 3}));
  EXPECT_EQ(vtk_array<double>(grid, "y"), (std::vector<double>{2, 2.5, 3, 3.5}));
  EXPECT_EQ(vtk_array<double>(grid, "z"), (std::vector<double>{3, 3.5, 4}));
  const auto fixed_x = vtk_array<std::int64_t>(grid, "fixed_x"), fixed_z = vtk_array<std::int64_t>(grid, "fixed_z");
  ASSERT_EQ(fixed_z.size(), 60u);
  EXPECT_EQ(std::count(fixed_z.begin(), fixed_z.end(), 1), 3);
  EXPECT_EQ(fixed_z[2], 1);
  EXPECT_EQ(fixed_x[3], 1);
  EXPECT_EQ(std::count(fixed_x.begin(), fixed_x.end(), 1), 1);
  const auto in_mesh = vtk_array<std::int64_t>(grid, "in_mesh");
  ASSERT_EQ(in_mesh.size(), 60u);
  EXPECT_EQ(std::count(in_mesh.begin(), in_mesh.end(), 1), 4 * 4 * 3);  // all but the x = 1 layer
  EXPECT_EQ(in_mesh[0 + 5 * (1 + 4 * 2)], 0);
  EXPECT_EQ(in_mesh[4 + 5 * (3 + 4 * 2)], 1);  // node (4, 3, 2): the far corner, index i + nx (j + ny k)
}

TEST(Results3d, SeriesHasTheThirdAxisColumns) {
  const test_support::ScratchDir dir("geoflow_results_3d_series");
  mpm::Deck deck = deck_3d(dir.path());
  auto ps = three_particles();
  const auto row = mpm::io::summarize_state(5, 0.5, 1e-3, ps, deck.grid, deck.analysis.gravity, deck.analysis.gravity_z);
  EXPECT_EQ(row.dim, 3);
  double pe = 0, kz = 0;
  for (const auto& p : ps) pe += p.mass * 10 * p.coord_z, kz += 0.5 * p.mass * p.velocity_z * p.velocity_z;
  EXPECT_CLOSE(row.potential_energy, pe, 1e-12, 0);
  EXPECT_CLOSE(row.kinetic_energy_z, kz, 1e-12, 0);
  EXPECT_CLOSE(row.max_speed, 3 * std::sqrt(14.0), 1e-12, 0);  // |(3, -6, 9)|
  EXPECT_CLOSE(row.height_p995, 3.1 + 0.25 * 2 * 0.995, 1e-12, 0);  // numpy.percentile(z, 99.5)
  EXPECT_CLOSE(row.runout_y_p98, 2.2 + 0.4 * 2 * 0.98, 1e-12, 0);
  EXPECT_EQ(row.checkerboard_index, 0.0);  // three cells, one particle each: no deviation ...
  // ... unless two share a cell: the deviation of the shear vector from the cell mean.
  ps[1].coord_x = ps[0].coord_x, ps[1].coord_y = ps[0].coord_y, ps[1].coord_z = ps[0].coord_z;
  const auto shared = mpm::io::summarize_state(5, 0.5, 1e-3, ps, deck.grid, deck.analysis.gravity, -10);
  const double deviation = 0.5 * std::sqrt(10.0 * 10 + 20.0 * 20 + 30.0 * 30);  // half the difference, per particle
  const double rho = (2.0 + 4 + 6) / (3 * 0.125 / 8), height = shared.height_p995 - ps[0].coord_z;
  EXPECT_CLOSE(shared.checkerboard_index, std::sqrt(2 * deviation * deviation / 3) / (rho * 10 * height), 0, 1e-12);

  mpm::io::ResultsWriter w(deck);
  w.write_output(0, 0.001, 1e-3, ps);
  const std::string series = slurp(w.folder() / "series.csv");
  const std::string header = mpm::io::series_header(3);
  EXPECT_EQ(header,
            "step,time,runout_x_p98,runout_y_p98,height_z_p995,potential_energy,kinetic_energy_x,kinetic_energy_y,"
            "kinetic_energy_z,max_speed,n_particles,dt,checkerboard_index");
  ASSERT_EQ(series.rfind(header + "\n0,0.001,", 0), 0u) << series;
  const std::string first = series.substr(header.size() + 1);
  EXPECT_EQ(std::count(first.begin(), first.end(), ','), 12);
  // A resumed 3D run reads its 13-column rows back (the frame count of the n_particles column).
  deck.resumed = true;
  deck.first_step = 1;
  mpm::io::ResultsWriter resumed(deck);
  resumed.write_output(50, 0.051, 1e-3, ps);
  const std::string continued = slurp(w.folder() / "series.csv");
  EXPECT_NE(continued.find("\n0,0.001,"), std::string::npos) << continued;
  EXPECT_NE(continued.find("\n50,0.051,"), std::string::npos);
  const std::string xdmf = slurp(w.folder() / "particles.xdmf");
  EXPECT_NE(xdmf.find("NumberOfElements=\"3\""), std::string::npos);
  EXPECT_NE(xdmf.find("particles000.h5"), std::string::npos);
}

TEST(Results3d, AffineDatasetHasNineColumnsAndItsCountIsChecked) {
  const test_support::ScratchDir dir("geoflow_results_3d_affine");
  mpm::Deck deck = deck_3d(dir.path());
  const auto ps = three_particles();
  const auto affine = affine_rows();
  mpm::io::ResultsWriter w(deck);
  w.write_output(50, 0.05, 1e-3, ps, {{}, std::nullopt, affine});
  const fs::path file = w.folder() / "particles050.h5";

  const auto back = mpm::io::read_affine_dataset<3>(file, 3);
  ASSERT_TRUE(back.has_value());
  ASSERT_EQ(back->size(), 3u);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_EQ(std::memcmp((*back)[k].data(), affine[k].data(), sizeof affine[k]), 0) << "row " << k;  // -0.0 too

  // Resuming a 3D APIC deck fills Deck::particle_affine_3d; the 2D member stays empty.
  mpm::Deck resumed = deck_3d(dir.path());
  resumed.particles = ps;
  mpm::io::read_resume_extras(file, "mpm.json", "particles050.h5", resumed);
  EXPECT_TRUE(resumed.particle_affine.empty());
  EXPECT_TRUE(resumed.particle_affine_3d == affine);
  EXPECT_TRUE(resumed.warnings.empty());

  // The wrong column count for the deck's dimension: one line naming the file and the dataset.
  mpm::Deck flat = resumed;
  flat.grid.dim = 2;
  auto expect_refused = [&](mpm::Deck& d, const fs::path& f, const std::string& shape) {
    try {
      mpm::io::read_resume_extras(f, "mpm.json", f.filename().string(), d);
      ADD_FAILURE() << "accepted " << f;
    } catch (const common::InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      EXPECT_NE(m.find(f.string()), std::string::npos) << m;
      EXPECT_NE(m.find("dataset \"/apic_affine\" must be " + shape), std::string::npos) << m;
    }
  };
  expect_refused(flat, file, "3 x 4 floats");  // a 3D file on a 2D deck
  const fs::path file_2d = dir.path() / "particles_2d.h5";
  const std::vector<mpm::AffineMatrix<2>> affine_2d(3, {{1, 2, 3, 4}});
  mpm::io::write_particle_table(file_2d, ps, [&](std::int64_t h5) { mpm::io::write_affine_dataset(h5, affine_2d, "2d"); });
  mpm::Deck deep = deck_3d(dir.path());
  deep.particles = ps;
  expect_refused(deep, file_2d, "3 x 9 floats");  // a 2D file on a 3D deck
  EXPECT_THROW(mpm::io::read_affine_dataset<3>(file, 2), common::InputError);  // a row count other than /table's
}

TEST(Results3d, PorePressureRowsAreTheSameInThreeDimensions) {
  const test_support::ScratchDir dir("geoflow_results_3d_pore");
  mpm::Deck deck = deck_3d(dir.path());
  deck.particles = three_particles();
  deck.particle_pore_pressure = std::vector<mpm::PorePressureRecord>{{1e3, 2e3, 0.1}, {2e3, 3e3, 0.2}, {3e3, 4e3, 0.3}};
  mpm::io::ResultsWriter w(deck);
  // A particle removed on the way: the others keep their rows.
  const std::vector<ParticleRecord> left{deck.particles[0], deck.particles[2]};
  w.write_output(50, 0.05, 1e-3, left);
  const auto rows = mpm::io::read_pore_pressure_dataset(w.folder() / "particles050.h5", 2);
  ASSERT_TRUE(rows.has_value());
  EXPECT_EQ(*rows, (std::vector<mpm::PorePressureRecord>{{1e3, 2e3, 0.1}, {3e3, 4e3, 0.3}}));
  mpm::Deck resumed = deck_3d(dir.path());
  resumed.particles = left;
  mpm::io::read_resume_extras(w.folder() / "particles050.h5", "mpm.json", "particles050.h5", resumed);
  ASSERT_TRUE(resumed.particle_pore_pressure.has_value());
  EXPECT_EQ(*resumed.particle_pore_pressure, *rows);
}
