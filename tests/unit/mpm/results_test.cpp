// mpm::io outputs: the series.csv statistics (definitions in mpm/io/results.hpp), the particle files
// with their /xdmf datasets, particles.xdmf, and how a resumed run continues series.csv.
#include <gtest/gtest.h>

#include <hdf5.h>
#include <hdf5_hl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <fstream>
#include <sstream>

#include "common/input_error.hpp"
#include "mpm/io/particle_fields.hpp"
#include "mpm/io/results.hpp"
#include "support/tolerance.hpp"

namespace fs = std::filesystem;
using mpm::ParticleRecord;

namespace {

std::vector<ParticleRecord> four_particles() {
  // Four particles in lattice cell (1, 1) of a 1 m grid, mass 2, volume 0.001 (rho 2000).
  std::vector<ParticleRecord> ps(4);
  const double xy[4][2] = {{1.25, 1.25}, {1.75, 1.25}, {1.25, 1.75}, {1.75, 1.75}};
  for (int k = 0; k < 4; ++k) {
    ps[k].id = k;
    ps[k].mass = 2.0;
    ps[k].volume = 0.001;
    ps[k].coord_x = xy[k][0];
    ps[k].coord_y = xy[k][1];
    ps[k].velocity_x = k;
    ps[k].velocity_y = -1.0;
  }
  return ps;
}

mpm::Grid unit_grid() {
  mpm::Grid g;
  g.nodes_per_axis = {5, 4, 0};
  g.region_max = {4, 3, 0};
  return g;
}

std::string slurp(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A run of 101 steps with an output every 50 steps into results/run/ of an emptied scratch folder
/// named `tag` + the process id.
mpm::Deck output_deck(const std::string& tag) {
  mpm::Deck deck;
  deck.working_dir = fs::temp_directory_path() / (tag + std::to_string(::getpid()));
  fs::remove_all(deck.working_dir);
  deck.grid = unit_grid();
  deck.analysis.nsteps = 101;
  deck.output.path = "results/";
  deck.output.uuid = "run";
  deck.output.output_steps = 50;
  return deck;
}

}  // namespace

TEST(Series, PercentileIsNumpysLinearInterpolation) {
  std::vector<double> v;
  for (int k = 10; k >= 1; --k) v.push_back(k);
  // numpy.percentile(range(1, 11), 98) = 9.82, (.., 99.5) = 9.955, (.., 50) = 5.5
  EXPECT_CLOSE(mpm::io::percentile(v, 98), 9.82, 1e-12, 0);
  EXPECT_CLOSE(mpm::io::percentile(v, 99.5), 9.955, 1e-12, 0);
  EXPECT_CLOSE(mpm::io::percentile(v, 50), 5.5, 1e-12, 0);
  EXPECT_EQ(mpm::io::percentile({3.0}, 98), 3.0);
}

TEST(Series, EnergiesSpeedAndCounts) {
  const auto ps = four_particles();
  const auto row = mpm::io::summarize_state(7, 0.5, 1e-3, ps, unit_grid(), Eigen::Vector2d(0, -10));
  EXPECT_EQ(row.step, 7);
  EXPECT_EQ(row.particle_count, 4u);
  EXPECT_CLOSE(row.potential_energy, 2 * 10 * (1.25 * 2 + 1.75 * 2), 1e-9, 0);
  EXPECT_CLOSE(row.kinetic_energy_x, 0.5 * 2 * (0 + 1 + 4 + 9), 1e-12, 0);
  EXPECT_CLOSE(row.kinetic_energy_y, 0.5 * 2 * 4, 1e-12, 0);
  EXPECT_CLOSE(row.max_speed, std::sqrt(10.0), 1e-12, 0);
  EXPECT_CLOSE(row.runout_x_p98, 1.75, 1e-12, 0);
  EXPECT_EQ(row.checkerboard_index, 0.0);  // no shear stress at all
}

TEST(Series, CheckerboardIndexIsTheRmsDeviationFromTheCellMeanOverRhoGH) {
  auto ps = four_particles();
  const double t = 300.0;
  for (int k = 0; k < 4; ++k) ps[k].tau_xy = 1000.0 + ((k == 0 || k == 3) ? t : -t);  // checkerboard around 1000 Pa
  const auto row = mpm::io::summarize_state(0, 0, 1e-3, ps, unit_grid(), Eigen::Vector2d(0, -10));
  const double height = mpm::io::percentile({1.25, 1.25, 1.75, 1.75}, 99.5) - 1.25;
  EXPECT_CLOSE(row.checkerboard_index, t / (2000.0 * 10.0 * height), 1e-15, 1e-12);
  // The same shear stress in every particle: a smooth field, index 0.
  for (auto& p : ps) p.tau_xy = 1000.0;
  EXPECT_EQ(mpm::io::summarize_state(0, 0, 1e-3, ps, unit_grid(), Eigen::Vector2d(0, -10)).checkerboard_index, 0.0);
}

TEST(Results, WritesParticleFilesXdmfAndSeries) {
  mpm::Deck deck = output_deck("geoflow_results_");
  deck.analysis.gravity = Eigen::Vector2d(0, -9.81);
  mpm::io::ResultsWriter w(deck);
  EXPECT_FALSE(fs::exists(w.folder()));  // nothing written before the first output
  const auto ps = four_particles();
  w.write_output(0, 0.001, 0.001, ps);
  w.write_output(50, 0.051, 0.001, ps);
  w.write_series_row(77, 0.078, 0.001, ps);
  const fs::path folder = deck.working_dir / "results/run";
  ASSERT_TRUE(fs::exists(folder / "particles000.h5"));
  ASSERT_TRUE(fs::exists(folder / "particles050.h5"));
  EXPECT_FALSE(fs::exists(folder / "particles077.h5"));
  for (const auto& e : fs::directory_iterator(folder))
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();

  // The CB-Geo table reads back exactly; the /xdmf datasets hold the same numbers.
  const auto back = mpm::io::read_particle_table(folder / "particles050.h5");
  ASSERT_EQ(back.size(), 4u);
  EXPECT_EQ(back[2].coord_y, 1.75);
  const hid_t f = H5Fopen((folder / "particles050.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  std::vector<double> coords(12), vel(12);
  EXPECT_GE(H5LTread_dataset_double(f, "/xdmf/coordinates", coords.data()), 0);
  EXPECT_GE(H5LTread_dataset_double(f, "/xdmf/velocity", vel.data()), 0);
  H5Fclose(f);
  EXPECT_EQ(coords[3 * 2 + 1], 1.75);
  EXPECT_EQ(vel[3 * 3], 3.0);

  const std::string xdmf = slurp(folder / "particles.xdmf");
  EXPECT_NE(xdmf.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_NE(xdmf.find("particles000.h5:/xdmf/coordinates"), std::string::npos);
  EXPECT_NE(xdmf.find("particles050.h5:/xdmf/coordinates"), std::string::npos);
  EXPECT_NE(xdmf.find("<Time Value=\"0.051\"/>"), std::string::npos);
  EXPECT_NE(xdmf.find("TopologyType=\"Polyvertex\" NumberOfElements=\"4\""), std::string::npos);

  const std::string series = slurp(folder / "series.csv");
  EXPECT_EQ(series.rfind(mpm::io::series_header() + "\n0,0.001,", 0), 0u) << series;
  EXPECT_NE(series.find("\n50,0.051,"), std::string::npos);
  EXPECT_NE(series.find("\n77,0.078,"), std::string::npos);

  // A run resumed from step 50 keeps the rows up to 50 and continues from there.
  deck.resumed = true;
  deck.first_step = 51;
  mpm::io::ResultsWriter resumed(deck);
  resumed.write_output(100, 0.101, 0.001, ps);
  const std::string continued = slurp(folder / "series.csv");
  EXPECT_NE(continued.find("\n50,0.051,"), std::string::npos);
  EXPECT_EQ(continued.find("\n77,"), std::string::npos);
  EXPECT_NE(continued.find("\n100,0.101,"), std::string::npos);
  const std::string xdmf2 = slurp(folder / "particles.xdmf");
  EXPECT_NE(xdmf2.find("particles000.h5"), std::string::npos);
  EXPECT_NE(xdmf2.find("particles100.h5"), std::string::npos);
  fs::remove_all(deck.working_dir);
}

// post_processing.particle_output_steps: particle files only after the listed output steps, a series
// row after every output step, and the XDMF lists only the files written.
TEST(Results, ParticleFilesOnlyAtTheListedOutputSteps) {
  mpm::Deck deck = output_deck("geoflow_results_steps_");
  deck.output.particle_output_steps = {0, 100};
  mpm::io::ResultsWriter w(deck);
  const auto ps = four_particles();
  for (long long step : {0, 50, 100}) w.write_output(step, 0.001 * (step + 1), 0.001, ps);
  const fs::path folder = deck.working_dir / "results/run";
  EXPECT_TRUE(fs::exists(folder / "particles000.h5"));
  EXPECT_FALSE(fs::exists(folder / "particles050.h5"));
  EXPECT_TRUE(fs::exists(folder / "particles100.h5"));
  const std::string series = slurp(folder / "series.csv");
  for (const char* row : {"\n0,0.001,", "\n50,0.051,", "\n100,0.101,"}) EXPECT_NE(series.find(row), std::string::npos) << row;
  const std::string xdmf = slurp(folder / "particles.xdmf");
  EXPECT_EQ(xdmf.find("particles050.h5"), std::string::npos);
  EXPECT_NE(xdmf.find("particles100.h5"), std::string::npos);
  fs::remove_all(deck.working_dir);
}

TEST(ParticleFields, TensorsInParaViewOrderSizesAndStateVariables) {
  auto ps = four_particles();
  ps[1].stress_xx = 1, ps[1].stress_yy = 2, ps[1].stress_zz = 3, ps[1].tau_xy = 4;
  ps[1].gamma_xy = 0.2;
  ps[1].nsize_x = ps[1].nsize_y = 0.5;  // 4 x 4 particles per 1 m cell: 0.25 m each
  ps[3].nsize_x = 1e68, ps[3].nsize_y = 1e247;  // finite, whose product overflows (a fuzzed resume file)
  ps[2].nstate_vars = 7;                // a Mohr-Coulomb particle: phi = 30 degrees, c = 5 kPa
  ps[2].svars[0] = std::numbers::pi / 6, ps[2].svars[2] = 5e3, ps[2].svars[6] = 0.01;
  const auto fields = mpm::io::particle_fields(ps, unit_grid());
  auto field = [&](const std::string& name) {
    const auto it = std::find_if(fields.begin(), fields.end(), [&](const auto& f) { return f.name == name; });
    EXPECT_NE(it, fields.end()) << name;
    return *it;
  };
  const auto stress = field("stress");
  ASSERT_EQ(stress.kind, mpm::io::FieldKind::Tensor6);
  EXPECT_EQ(std::vector<double>(stress.real.begin() + 6, stress.real.begin() + 12), (std::vector<double>{1, 2, 3, 4, 0, 0}));
  EXPECT_EQ(field("strain").real[6 + 3], 0.1);  // tensorial shear = gamma / 2
  EXPECT_EQ(field("size").real[3], 0.25);
  EXPECT_EQ(field("size").real[0], std::sqrt(0.001));  // no nsize: the side of the particle's area
  EXPECT_EQ(field("radius").real[1], 0.125);
  EXPECT_TRUE(std::isfinite(field("radius").real[3]));  // sqrt(ex) sqrt(ey), not sqrt(ex ey) = inf
  EXPECT_CLOSE(field("radius").real[3], 0.5 * std::sqrt(0.5e68) * std::sqrt(0.5e247), 0.0, 1e-12);
  EXPECT_CLOSE(field("friction").real[2], 30.0, 1e-12, 0.0);
  EXPECT_EQ(field("friction").real[1], 0.0);  // no state variables: 0
  EXPECT_EQ(field("cohesion").real[2], 5e3);
  EXPECT_EQ(field("pdstrain").real[2], 0.01);
  const auto id = field("id");
  EXPECT_TRUE(id.integer);
  EXPECT_EQ(id.whole, (std::vector<std::int64_t>{0, 1, 2, 3}));
  EXPECT_EQ(mpm::io::state_variable_field(ps, "cohesion").real[2], 5e3);
}

TEST(Results, StartFrameGridAndVtkFiles) {
  mpm::Deck deck = output_deck("geoflow_results_vtk_");
  deck.output.vtk_fields = {"stress"};
  deck.output.vtk_statevars = {"pdstrain"};
  deck.velocity_constraints.push_back({{0, 1, 2}, 1, 0.0});
  const auto ps = four_particles();
  mpm::io::ResultsWriter w(deck);
  w.write_start(0.0, ps);
  w.write_output(0, 0.001, 0.001, ps);
  const fs::path folder = deck.working_dir / "results/run";
  for (const char* f : {"initial_state.h5", "initial_state.vtp", "particles000.vtp", "particles.pvd", "grid.vtr"})
    EXPECT_TRUE(fs::exists(folder / f)) << f;
  const std::string xdmf = slurp(folder / "particles.xdmf");
  const auto start = xdmf.find("initial_state.h5:/xdmf/coordinates"), first = xdmf.find("particles000.h5");
  EXPECT_NE(start, std::string::npos);
  EXPECT_LT(start, first);  // the start state is the first frame
  EXPECT_NE(xdmf.find("AttributeType=\"Tensor6\""), std::string::npos);
  EXPECT_NE(xdmf.find("NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">initial_state.h5:/xdmf/id"), std::string::npos);
  const std::string pvd = slurp(folder / "particles.pvd");
  EXPECT_NE(pvd.find("timestep=\"0\" group=\"\" part=\"0\" file=\"initial_state.vtp\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("file=\"particles000.vtp\""), std::string::npos);
  const std::string vtp = slurp(folder / "particles000.vtp");
  for (const char* a : {"Name=\"stress\" NumberOfComponents=\"6\"", "Name=\"pdstrain\"", "Name=\"id\"", "Name=\"radius\""})
    EXPECT_NE(vtp.find(a), std::string::npos) << a;
  EXPECT_EQ(vtp.find("Name=\"velocity\""), std::string::npos);  // not asked for
  const std::string grid = slurp(folder / "grid.vtr");
  EXPECT_NE(grid.find("WholeExtent=\"0 4 0 3 0 0\""), std::string::npos);

  // A resumed run with earlier frames keeps the earlier start frame (its step and time are in the file).
  deck.resumed = true;
  deck.first_step = 1;
  std::ofstream(folder / "series.csv") << mpm::io::series_header() << "\n0,0.001,1,1,0,0,0,0,4,0.001,0\n";
  mpm::io::ResultsWriter resumed(deck);
  resumed.write_start(0.002, ps);
  resumed.write_output(50, 0.051, 0.001, ps);
  const std::string xdmf2 = slurp(folder / "particles.xdmf");
  EXPECT_NE(xdmf2.find("<Time Value=\"0\"/>"), std::string::npos) << xdmf2.substr(0, 400);
  EXPECT_EQ(xdmf2.find("<Time Value=\"0.002\"/>"), std::string::npos);
  fs::remove_all(deck.working_dir);
}

TEST(Results, EveryOutputPathIsCheckedBeforeTheFirstFileIsWritten) {
  // A particle file of a later output step, particles.xdmf, or the results folder itself that is not a
  // regular file (directory) is refused with common::InputError before grid.vtr or the start state exist.
  for (const std::string blocked : {"particles050.h5", "particles.xdmf", "series.csv"}) {
    mpm::Deck deck = output_deck("geoflow_results_blocked_");
    const fs::path folder = deck.working_dir / "results/run";
    fs::create_directories(folder / blocked);
    mpm::io::ResultsWriter w(deck);
    EXPECT_THROW(w.write_start(0, four_particles()), common::InputError) << blocked;
    EXPECT_FALSE(fs::exists(folder / "grid.vtr")) << blocked;
    EXPECT_FALSE(fs::exists(folder / "initial_state.h5")) << blocked;
    fs::remove_all(deck.working_dir);
  }
  mpm::Deck deck = output_deck("geoflow_results_folder_");
  fs::create_directories(deck.working_dir / "results");
  std::ofstream(deck.working_dir / "results/run") << "a file where the results folder goes\n";
  mpm::io::ResultsWriter w(deck);
  EXPECT_THROW(w.write_start(0, four_particles()), common::InputError);
  fs::remove_all(deck.working_dir);
}
