// fem2mpm on u-p results (issue 36, items 1 and 2) through the programs: fem_tcl runs up_column.tcl (a saturated
// PM4Sand column of SSPquadUP or quadUP elements, shaken until the loose sand's r_u passes 0.7; or drained and
// elastic), fem2mpm transfers it with --pore-pressure, mpm resumes from the file. Checked:
// - exact bookkeeping (the definitions of bridge/pore_pressure.hpp): each particle's stress is the dry transfer's
//   (the effective stress) minus its pore pressure p on the three normal components, bit for bit; the mass is
//   the FEM's (rho W H = 1900 kg/m3 x 1 m x 4 m = 7600 kg/m); at the element centres (--ppd 1) p is the mean of
//   the element's recorded nodal pore pressures and r_u = (p - p0) / sigma'v0 the FEM's, sigma'v0 the element's
//   own -sigma'yy at the end of the gravity stage (the authors' r_u: Sordo, Rathje & Kumar, arXiv 2412.08040);
// - a u-p run without pore pressure (every node drained, p = 0) transfers to the same particles as the dry
//   transfer of the same files, byte for byte;
// - the liquefied particles' strengths by each rule (liquefied_strength.hpp: Olson & Stark 2002; Idriss &
//   Boulanger 2008; a strength table), grouped by material, their rows following them;
// - mpm carries /pore_pressure unchanged into its outputs and refuses a malformed one (file and row named);
// - bad inputs: exit 2, one line naming the file, line or option, nothing written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bridge/fem_model.hpp"
#include "bridge/liquefied_strength.hpp"
#include "mpm/io/particle_table.hpp"
#include "support/recorder_compare.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace {

namespace fs = std::filesystem;
const fs::path kBin = fs::path(GEOFLOW_BIN_DIR);

struct Result {
  int code = -1;
  std::string out, err;
};

Result run(const std::string& program, const std::string& args, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  // In `dir`: fem_tcl writes its recorder files there.
  const std::string cmd = "cd '" + dir.string() + "' && " + (kBin / program).string() + " " + args + " > " + out.string() +
                          " 2> " + err.string() + " < /dev/null";
  const int status = std::system(cmd.c_str());
  Result r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = test_support::read_text(out);
  r.err = test_support::read_text(err);
  return r;
}

/// Runs up_column.tcl in a fresh folder after `preamble` (Tcl: `set ele quadUP`, `set drained 1`, `set steps N`).
fs::path fem_run(const std::string& name, const std::string& preamble) {
  const fs::path dir = test_support::fresh_scratch_folder("bridge_up", name);
  fs::copy_file(fs::path(GEOFLOW_SOURCE_DIR) / "tests/regression/bridge/up_column.tcl", dir / "up_column.tcl");
  std::ofstream(dir / "run.tcl") << preamble << "\nsource up_column.tcl\n";
  const Result r = run("fem_tcl", "run.tcl", dir);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("gravity: 0"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.out.find("shaking: 0"), std::string::npos) << r.out << r.err;
  return dir;
}

bool have_programs() { return fs::exists(kBin / "fem_tcl") && fs::exists(kBin / "fem2mpm") && fs::exists(kBin / "mpm"); }

std::string files(const fs::path& d, bool pore_pressure = true) {
  return "--model " + (d / "model.json").string() + " --disp " + (d / "disp.out").string() + " --vel " +
         (d / "vel.out").string() + " --stress " + (d / "stress.out").string() + " --units kN" +
         (pore_pressure ? " --pore-pressure " + (d / "pp.out").string() : std::string());
}

struct Transfer {
  std::vector<mpm::ParticleRecord> particles;
  std::vector<mpm::PorePressureRecord> rows;  ///< empty for a dry transfer
  nlohmann::json report;
};

Transfer transfer(const std::string& args, const fs::path& out, const fs::path& dir) {
  const Result r = run("fem2mpm", args + " --out " + out.string(), dir);
  EXPECT_EQ(r.code, 0) << r.err;
  Transfer t;
  if (r.code != 0) return t;
  fs::path h5;  // the one particle file (its step zero-padded to the deck's nsteps)
  for (const auto& entry : fs::directory_iterator(out / "results/column")) h5 = entry.path();
  if (h5.empty()) return t;
  t.particles = mpm::io::read_particle_table(h5);
  t.rows = mpm::io::read_pore_pressure_dataset(h5, t.particles.size()).value_or(std::vector<mpm::PorePressureRecord>{});
  t.report = nlohmann::json::parse(test_support::read_text(out / "report.json"));
  return t;
}

/// A bad input: exit 2, one line on stderr containing every one of `needles`, and no output.
void expect_clean_failure(const std::string& args, const fs::path& dir, const std::vector<std::string>& needles) {
  const fs::path out = dir / "refused";
  const Result r = run("fem2mpm", args + " --out " + out.string(), dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  for (const auto& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << "missing '" << n << "' in: " << r.err;
  EXPECT_FALSE(fs::exists(out)) << "output written despite the error";
}

/// Total stress = effective stress - p on the normal components, bit for bit, against the dry transfer of the
/// same files; everything else identical; the mass the FEM's.
void expect_total_stress_bookkeeping(const fs::path& fem, const std::string& time) {
  const Transfer up = transfer(files(fem) + " --time " + time, fem / "up", fem);
  const Transfer dry = transfer(files(fem, false) + " --time " + time, fem / "dry", fem);
  ASSERT_EQ(up.particles.size(), 256u);
  ASSERT_EQ(dry.particles.size(), up.particles.size());
  ASSERT_EQ(up.rows.size(), up.particles.size());
  double mass = 0, largest_p = 0;
  for (std::size_t k = 0; k < up.particles.size(); ++k) {
    const auto& a = up.particles[k];
    const auto& b = dry.particles[k];
    const double p = up.rows[k].pressure;
    largest_p = std::max(largest_p, std::abs(p));
    ASSERT_EQ(a.id, b.id);
    ASSERT_EQ(a.coord_x, b.coord_x);
    ASSERT_EQ(a.coord_y, b.coord_y);
    ASSERT_EQ(a.mass, b.mass);
    ASSERT_EQ(a.stress_xx, b.stress_xx - p) << "particle " << k;
    ASSERT_EQ(a.stress_yy, b.stress_yy - p) << "particle " << k;
    ASSERT_EQ(a.stress_zz, b.stress_zz - p) << "particle " << k;
    ASSERT_EQ(a.tau_xy, b.tau_xy);
    ASSERT_EQ(a.material_id, b.material_id);  // no strength rule: every particle keeps its drained material
    ASSERT_EQ(a.svars[3], std::sqrt(3.0) * ((a.stress_xx + a.stress_yy + a.stress_zz) / 3.0));  // epsilon follows
    mass += a.mass;
  }
  EXPECT_GT(largest_p, 30e3);  // the base is at 4 m of water and more (Pa): p is not trivially zero
  EXPECT_CLOSE(mass, 7600.0, 0, 1e-13);
  EXPECT_CLOSE(up.report["fem"]["mass"].get<double>(), 7600.0, 0, 1e-13);
  EXPECT_EQ(up.report["pore_pressure"]["reference"]["time"].get<double>(), 6000.0);  // the end of the gravity stage
}

TEST(UpTransfer, TotalStressIsTheEffectiveStressMinusThePorePressureSSPquadUP) {
  if (!have_programs()) GTEST_SKIP() << "build fem_tcl, fem2mpm and mpm first";
  expect_total_stress_bookkeeping(fem_run("ssp", ""), "1.5");
}

TEST(UpTransfer, TotalStressIsTheEffectiveStressMinusThePorePressureQuadUP) {
  if (!have_programs()) GTEST_SKIP() << "build fem_tcl, fem2mpm and mpm first";
  expect_total_stress_bookkeeping(fem_run("quad", "set ele quadUP\nset steps 100"), "0.5");
}

// r_u at the element centres (--ppd 1: one particle per element, at its centre, where nothing moved relative to
// the element) against the FEM's own figures, from the recorder files alone (written with 17 digits): p and p0
// are the means of the element's four nodal pore pressures at the transfer and reference rows (the element's own
// interpolation: to round-off), and r_u = (p - p0) / sigma'v0 to round-off with the particle's sigma'v0. That
// sigma'v0 is the element's -sigma'yy at the reference row mapped like the stress (--recovery spr, exact for a
// field linear in depth); this FEM's field departs from linear by a few 1e-5 kPa (its element-to-element steps of
// 4.4145 kPa differ by up to 7e-5 kPa: the u-p element's pressure stabilization), so the particles' sigma'v0 is
// the element's within 3e-5 (relative) and r_u the FEM's within 3e-5.
TEST(UpTransfer, RuAtTheElementCentresIsTheFems) {
  if (!have_programs()) GTEST_SKIP() << "build fem_tcl, fem2mpm and mpm first";
  const fs::path fem = fem_run("ru", "set precision 17");  // the recorders' full precision: comparisons to round-off
  const Transfer t = transfer(files(fem) + " --row -1 --ppd 1 --recovery spr", fem / "deck", fem);  // t = 1.5 to 17 digits
  ASSERT_EQ(t.particles.size(), 16u);
  const auto pp = test_support::read_numeric_table(fem / "pp.out");
  const auto stress = test_support::read_numeric_table(fem / "stress.out");
  // Rows: 10 gravity (t = 500 .. 5000), 2 plastic (5500, 6000), then the shaking from t = 0.005.
  ASSERT_EQ(pp[11][0], 6000.0);
  ASSERT_EQ(pp[12][0], 0.005);
  const auto& now = pp[11 + 300];
  ASSERT_CLOSE(now[0], 1.5, 0, 1e-12);
  const bridge::FemModel model = bridge::read_fem_model(fem / "model.json");
  double largest = 0;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const auto& el = model.elements[e];
    double p = 0, p0 = 0;
    for (int a = 0; a < 4; ++a) {
      const auto column = static_cast<std::size_t>(el.node_tags[static_cast<std::size_t>(a)]);  // tags 1..27 in order
      p += 0.25 * 1000 * now[column];
      p0 += 0.25 * 1000 * pp[11][column];
    }
    const double sigma_v0 = -1000 * stress[11][1 + 3 * e + 1];
    const double ru = (p - p0) / sigma_v0;
    // Elements 1-4 are material 1 and come first: particle e is element e's.
    const auto& row = t.rows[e];
    EXPECT_CLOSE(row.pressure, p, 1e-9, 1e-12) << "element " << el.tag;
    EXPECT_CLOSE(row.ru, (p - p0) / row.sigma_v0, 1e-12, 1e-12) << "element " << el.tag;
    EXPECT_CLOSE(row.sigma_v0, sigma_v0, 0, 3e-5) << "element " << el.tag;
    EXPECT_CLOSE(row.ru, ru, 3e-5, 0) << "element " << el.tag;
    largest = std::max(largest, ru);
  }
  EXPECT_GT(largest, 0.8);  // the loose sand liquefied
  EXPECT_CLOSE(t.report["pore_pressure"]["max_ru"]["value"].get<double>(), largest, 3e-5, 0);
}

// A u-p column without any pore pressure (every node drained, elastic): --pore-pressure changes nothing in /table.
TEST(UpTransfer, ADrainedUpRunGivesTheDryTransfersParticles) {
  if (!have_programs()) GTEST_SKIP() << "build fem_tcl, fem2mpm and mpm first";
  const fs::path fem = fem_run("drained", "set drained 1");
  const Transfer up = transfer(files(fem) + " --time 1.5", fem / "up", fem);
  const Transfer dry = transfer(files(fem, false) + " --time 1.5", fem / "dry", fem);
  ASSERT_EQ(up.particles.size(), 256u);
  ASSERT_EQ(dry.particles.size(), up.particles.size());
  EXPECT_EQ(std::memcmp(up.particles.data(), dry.particles.data(), up.particles.size() * sizeof(mpm::ParticleRecord)), 0);
  ASSERT_EQ(up.rows.size(), up.particles.size());
  for (const auto& row : up.rows) {
    EXPECT_EQ(row.pressure, 0.0);
    EXPECT_EQ(row.ru, 0.0);
    EXPECT_GT(row.sigma_v0, 0.0);
  }
  EXPECT_EQ(up.report["pore_pressure"]["liquefied"]["particles"].get<int>(), 0);
  EXPECT_FALSE(up.report["pore_pressure"]["max_depth"]["found"].get<bool>());
}

/// For each particle of `t`, its row in `reference` (a transfer of the same state without a strength rule) by
/// position: the rows must have followed their particles through the regrouping.
std::vector<std::size_t> match_by_position(const Transfer& t, const Transfer& reference) {
  std::map<std::pair<double, double>, std::size_t> at;
  for (std::size_t k = 0; k < reference.particles.size(); ++k) at[{reference.particles[k].coord_x, reference.particles[k].coord_y}] = k;
  std::vector<std::size_t> out;
  for (const auto& p : t.particles) {
    const auto it = at.find({p.coord_x, p.coord_y});
    EXPECT_NE(it, at.end());
    out.push_back(it == at.end() ? 0 : it->second);
  }
  return out;
}

// The liquefied particles' strengths: Olson & Stark's ratio with softening, Idriss & Boulanger's (N1)60cs-Sr
// relation, the strength table; grouped by material (ids follow the materials), rows with their particles;
// mpm then carries the rows unchanged and refuses a malformed dataset.
TEST(UpTransfer, LiquefiedParticlesGetTheirResidualStrengthAndMpmCarriesTheRows) {
  if (!have_programs()) GTEST_SKIP() << "build fem_tcl, fem2mpm and mpm first";
  const fs::path fem = fem_run("liquefied", "");
  const std::string base = files(fem) + " --time 1.5 --ppd 2 --max-liquefied-materials 100";
  const Transfer plain = transfer(base, fem / "plain", fem);
  ASSERT_EQ(plain.particles.size(), 64u);

  // (b) Sr = 0.1 sigma'v0, peak 2 Sr softening to Sr between pdstrain 0 and 0.2, starting at --strain's.
  const Transfer ratio = transfer(base + " --residual-ratio 0.1 --liquefied-softening 2 0 0.2 --strain " +
                                      (fem / "strain.out").string() + " --nsteps 101 --output-steps 50",
                                  fem / "ratio", fem);
  ASSERT_EQ(ratio.particles.size(), 64u);
  const auto deck = nlohmann::json::parse(test_support::read_text(fem / "ratio/mpm.json"));
  std::map<unsigned, nlohmann::json> materials;
  for (const auto& m : deck["materials"]) materials[m["id"].get<unsigned>()] = m;
  const auto match = match_by_position(ratio, plain);
  std::size_t liquefied = 0;
  double liquefied_mass = 0, mass = 0;
  for (std::size_t k = 0; k < ratio.particles.size(); ++k) {
    const auto& p = ratio.particles[k];
    ASSERT_EQ(p.id, static_cast<std::int64_t>(k));
    if (k > 0) {
      ASSERT_GE(p.material_id, ratio.particles[k - 1].material_id);  // grouped by material
    }
    const auto& row = ratio.rows[k];
    EXPECT_EQ(row, plain.rows[match[k]]);  // the row followed its particle
    mass += p.mass;
    const auto& m = materials.at(p.material_id);
    if (row.ru > 0.7) {
      ++liquefied;
      liquefied_mass += p.mass;
      EXPECT_EQ(m["friction"].get<double>(), 0.0);
      EXPECT_TRUE(m["softening"].get<bool>());
      const double sr = m["residual_cohesion"].get<double>();
      EXPECT_CLOSE(sr, 0.1 * row.sigma_v0, 0, 0.0251);  // on the 5 % grid: within 2.5 %
      EXPECT_CLOSE(m["cohesion"].get<double>(), 2 * sr, 0, 1e-12);
      EXPECT_EQ(m["residual_pdstrain"].get<double>(), 0.2);
      EXPECT_EQ(m["tension_cutoff"].get<double>(), 0.0);
      ASSERT_EQ(p.nstate_vars, 7u);
      const double pd = p.svars[6];
      EXPECT_GT(pd, 0.0);  // the shaking sheared the column
      const double c = pd >= 0.2 ? sr : sr + (2 * sr - sr) * (pd - 0.2) / (0.0 - 0.2);  // CB-Geo's linear softening
      EXPECT_CLOSE(p.svars[2], c, 1e-9, 1e-12);
      EXPECT_EQ(p.svars[0], 0.0);
    } else {
      EXPECT_LT(p.material_id, 2u);  // the FEM materials: drained, phi_cv
      EXPECT_EQ(m["friction"].get<double>(), 32.0);
      EXPECT_EQ(p.svars[6], 0.0);
    }
  }
  EXPECT_GT(liquefied, 0u);
  EXPECT_LT(liquefied, ratio.particles.size());
  EXPECT_CLOSE(mass, 7600.0, 0, 1e-13);
  const auto& up = ratio.report["pore_pressure"];
  EXPECT_EQ(up["liquefied"]["particles"].get<std::size_t>(), liquefied);
  EXPECT_CLOSE(up["liquefied"]["mass"].get<double>(), liquefied_mass, 0, 1e-12);
  EXPECT_TRUE(up["max_depth"]["found"].get<bool>());
  EXPECT_GT(up["max_depth"]["depth"].get<double>(), 1.0);
  EXPECT_LT(up["max_depth"]["depth"].get<double>(), 4.0);
  std::size_t counted = 0;
  for (const auto& m : up["liquefied_materials"]) counted += m["particles"].get<std::size_t>();
  EXPECT_EQ(counted, liquefied);

  // mpm resumes and writes the rows unchanged into every output, particle by particle.
  const Result mpm = run("mpm", "-f " + (fem / "ratio").string() + "/ -i mpm.json", fem);
  ASSERT_EQ(mpm.code, 0) << mpm.err;
  for (const char* step : {"050", "100"}) {
    const fs::path file = fem / "ratio/results/column" / (std::string("particles") + step + ".h5");
    const auto later = mpm::io::read_particle_table(file);
    const auto rows = mpm::io::read_pore_pressure_dataset(file, later.size());
    ASSERT_TRUE(rows.has_value()) << file;
    ASSERT_EQ(later.size(), ratio.particles.size());
    for (std::size_t k = 0; k < later.size(); ++k) EXPECT_EQ((*rows)[k], ratio.rows[static_cast<std::size_t>(later[k].id)]);
  }
  // A malformed dataset: one line naming the file and the row, exit 2.
  {
    const fs::path file = fem / "ratio/results/column/particles000.h5";
    auto rows = ratio.rows;
    rows[3].ru = std::nan("");
    fs::remove(file);
    mpm::io::write_particle_table(file, ratio.particles,
                                  [&](std::int64_t h5) { mpm::io::write_pore_pressure_dataset(h5, rows, "test"); });
    const Result bad = run("mpm", "-f " + (fem / "ratio").string() + "/ -i mpm.json", fem);
    EXPECT_EQ(bad.code, 2) << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_NE(bad.err.find("particles000.h5"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("\"/pore_pressure\" row 3"), std::string::npos) << bad.err;
  }

  // (c) Idriss & Boulanger 2008 with (N1)60cs-Sr = 8 for the loose sand: Sr / sigma'v0 of their relation.
  const Transfer ib = transfer(base + " --residual-n160cs 2:8", fem / "ib", fem);
  const auto ib_deck = nlohmann::json::parse(test_support::read_text(fem / "ib/mpm.json"));
  const double expected = bridge::idriss_boulanger_residual_ratio(8, bridge::VoidRedistribution::Significant);
  EXPECT_CLOSE(expected, std::exp(0.5 + std::pow(-8.0 / 21.2, 3) - 3.0), 0, 1e-15);
  for (std::size_t k = 0; k < ib.particles.size(); ++k) {
    if (!(ib.rows[k].ru > 0.7)) continue;
    const auto& m = ib_deck["materials"][ib.particles[k].material_id];
    EXPECT_CLOSE(m["cohesion"].get<double>(), expected * ib.rows[k].sigma_v0, 0, 0.0251);
    EXPECT_FALSE(m["softening"].get<bool>());
  }

  // (a) A table of 3 bins (kPa): each liquefied particle's cohesions are its bin's.
  std::ofstream(fem / "table.csv") << "# sigma'v0 bins (the authors' form)\n"
                                      "sigma_v0_upper_kPa,peak_cohesion_kPa,residual_cohesion_kPa,peak_pdstrain,residual_pdstrain\n"
                                      "10, 3, 1.5, 0, 1\n20, 5.6, 2.8, 0, 1\ninf, 7.4, 3.7, 0, 1\n";
  const Transfer table = transfer(base + " --liquefied-table " + (fem / "table.csv").string(), fem / "table", fem);
  const auto table_deck = nlohmann::json::parse(test_support::read_text(fem / "table/mpm.json"));
  std::size_t in_table = 0;
  for (std::size_t k = 0; k < table.particles.size(); ++k) {
    if (!(table.rows[k].ru > 0.7)) continue;
    ++in_table;
    const double s = table.rows[k].sigma_v0;
    const auto& m = table_deck["materials"][table.particles[k].material_id];
    const double peak = s < 10e3 ? 3e3 : s < 20e3 ? 5.6e3 : 7.4e3;
    EXPECT_EQ(m["cohesion"].get<double>(), peak);
    EXPECT_EQ(m["residual_cohesion"].get<double>(), peak / 2);
    EXPECT_EQ(m["residual_pdstrain"].get<double>(), 1.0);
  }
  EXPECT_EQ(in_table, liquefied);
  EXPECT_LE(table_deck["materials"].size(), 2u + 3u);
}

TEST(UpTransfer, BadInputsFailCleanly) {
  if (!have_programs()) GTEST_SKIP() << "build fem_tcl, fem2mpm and mpm first";
  const fs::path fem = fem_run("errors", "set steps 20");
  const std::string model = "--model " + (fem / "model.json").string() + " --units kN";
  const std::string rest = " --disp " + (fem / "disp.out").string() + " --stress " + (fem / "stress.out").string();
  const std::string pp = " --pore-pressure " + (fem / "pp.out").string();
  // A pore-pressure file whose rows hold one node too few (26 values for 27 u-p nodes).
  {
    std::istringstream rows(test_support::read_text(fem / "pp.out"));
    std::ofstream cut(fem / "short.out");
    for (std::string line; std::getline(rows, line);) cut << line.substr(0, line.rfind(' ')) << '\n';
  }
  expect_clean_failure(model + rest + " --pore-pressure " + (fem / "short.out").string(), fem,
                       {"short.out:32", "26 values after the time column", "27 nodes", "--pp-nodes"});
  // ... or one row of another length than the others.
  {
    std::istringstream rows(test_support::read_text(fem / "pp.out"));
    std::ofstream odd(fem / "odd.out");
    int n = 0;
    for (std::string line; std::getline(rows, line);) odd << (++n == 5 ? line.substr(0, line.rfind(' ')) : line) << '\n';
  }
  expect_clean_failure(model + rest + " --pore-pressure " + (fem / "odd.out").string(), fem, {"odd.out:5"});
  // A --reference-time that is not in the file: the nearest times are listed.
  expect_clean_failure(model + rest + pp + " --reference-time 1234", fem, {"--reference-time 1234", "no row at time 1234"});
  // A reference time after the transfer row.
  expect_clean_failure(model + rest + pp + " --time 0.05 --reference-time 0.1", fem,
                       {"--reference-time 0.1", "after the transfer row"});
  // Files whose time never restarts (the gravity rows cut off): the reference time must be given.
  for (const char* f : {"disp.out", "stress.out", "pp.out"}) {
    std::istringstream rows(test_support::read_text(fem / f));
    std::ofstream cut(fem / (std::string("shaking_") + f));
    int n = 0;
    for (std::string line; std::getline(rows, line);)
      if (++n > 12) cut << line << '\n';
  }
  expect_clean_failure(model + " --disp " + (fem / "shaking_disp.out").string() + " --stress " +
                           (fem / "shaking_stress.out").string() + " --pore-pressure " + (fem / "shaking_pp.out").string(),
                       fem, {"--reference-time: required", "never decreases"});
  // A strength table with unsorted bins, and one with a bad header.
  std::ofstream(fem / "unsorted.csv") << "sigma_v0_upper_kPa,peak_cohesion_kPa,residual_cohesion_kPa,peak_pdstrain,residual_pdstrain\n"
                                         "50, 3, 1.5, 0, 1\n# a comment\n40, 5, 2.5, 0, 1\n";
  expect_clean_failure(model + rest + pp + " --liquefied-table " + (fem / "unsorted.csv").string(), fem,
                       {"unsorted.csv:4", "unsorted bins", "40"});
  std::ofstream(fem / "header.csv") << "sigma,peak,residual\n50, 3, 1.5\n";
  expect_clean_failure(model + rest + pp + " --liquefied-table " + (fem / "header.csv").string(), fem,
                       {"header.csv:1", "expected the header"});
  // u-p options without --pore-pressure, two rules at once, a material without (N1)60cs that liquefies.
  expect_clean_failure(model + rest + " --residual-ratio 0.1", fem, {"--residual-ratio", "needs --pore-pressure"});
  expect_clean_failure(model + rest + pp + " --residual-ratio 0.1 --residual-n160cs 2:8", fem, {"one residual strength rule"});
  expect_clean_failure(model + rest + pp + " --residual-n160cs 7:8", fem, {"--residual-n160cs 7", "no material '7'"});
  expect_clean_failure(model + rest + pp + " --pp-nodes 1-30", fem, {"--pp-nodes", "node 28 is not in"});
}

}  // namespace
