// mpm against CB-Geo MPM on the three reference decks of tests/data/reference_runs/cbgeo (CB-Geo
// develop 53fcb76, 2 threads; inputs by tools/make_decks.py, summaries by tools/summarize.py; see that
// folder's README.md section 2). mpm is a different implementation (its own cell search, reduction
// order, GIMP weights and Mohr-Coulomb return map), so fields cannot agree to CB-Geo's own rerun
// scatter. Each tolerance below says what it covers; free fall is exact and is compared tightly.
#include <gtest/gtest.h>

#include <iostream>

#include "mpm_run.hpp"
#include "support/tolerance.hpp"

using namespace mpm_regression;

namespace {

void print_row(const char* what, double step, double ours, double ref) {
  std::cout << "  " << what << " step " << step << ": mpm " << ours << "  CB-Geo " << ref << "  rel diff "
            << (ref != 0 ? (ours - ref) / std::abs(ref) : ours - ref) << "\n";
}

}  // namespace

TEST(CbGeoReference, ElasticBlockDrop) {
  // 64-particle elastic block (ED2Q4, USF, FLIP) falling 0.36 s onto a fixed base, then rebounding.
  const fs::path dir = copy_case("elastic_block_drop", "block");
  const auto run = run_mpm(dir, "mpm.json", "--threads 1");  // 64 particles: one thread is faster
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");  // not a terminal: no progress line, and nothing else to say
  EXPECT_EQ(run.out, "");
  const auto ref = read_csv(kCases / "elastic_block_drop/ref/summary.csv");
  ASSERT_EQ(ref.at("step").size(), 5u);
  for (std::size_t r = 0; r < ref.at("step").size(); ++r) {
    const auto step = static_cast<long long>(ref.at("step")[r]);
    const auto ours = stats_of(mpm::io::read_particle_table(dir / "results/block_drop" / mpm::io::particle_file_name(step, 1001)));
    ASSERT_EQ(ours.n, 64u);
    EXPECT_CLOSE(ours.mass, ref.at("total_mass")[r], 0, 1e-12);
    EXPECT_CLOSE(ours.cx, ref.at("centroid_x")[r], 1e-9, 0);  // symmetric: no drift
    print_row("centroid_y", step, ours.cy, ref.at("centroid_y")[r]);
    print_row("mean_vy", step, ours.vy, ref.at("mean_vy")[r]);
    print_row("kinetic_energy", step, ours.ke, ref.at("kinetic_energy")[r]);
    print_row("min_stress_yy", step, ours.min_syy, ref.at("min_stress_yy")[r]);
    if (ref.at("time")[r] < 0.3) {
      // Free fall (steps 0, 250, 500): v = -g t, y = y0 - g t^2 / 2 in both codes, up to round-off.
      EXPECT_CLOSE(ours.cy, ref.at("centroid_y")[r], 1e-9, 0);
      EXPECT_CLOSE(ours.vy, ref.at("mean_vy")[r], 1e-9, 0);
      EXPECT_CLOSE(ours.ke, ref.at("kinetic_energy")[r], 1e-6, 1e-9);
    } else {
      // Impact and rebound (steps 750, 1000): an intentional difference from CB-Geo (mpm/README.md
      // "Boundary conditions under FLIP"). CB-Geo hands FLIP a zero acceleration at the fixed base, so
      // the particles in the base cell keep their 3.5 m/s into the wall while the grid holds their
      // positions; here FLIP gets the constrained nodal velocity change, the wall stops them as PIC
      // does, and the impact dissipates more: the block rebounds slower (mean vy 2.55 against CB-Geo's
      // 3.02 m/s at step 1000, kinetic energy -20 %). The values below are this code's (mpm, 1 thread,
      // branch h/mpm-bc, issue 10), kept as the regression; CB-Geo's are printed above for comparison.
      struct Impact { double cy, vy, ke, min_syy; };
      const Impact ours_ref = step == 750 ? Impact{1.31525, -2.7305, 26235.0, -389140.0}
                                          : Impact{1.44984, 2.55237, 23074.9, -55928.3};
      EXPECT_CLOSE(ours.cy, ours_ref.cy, 1e-4, 0);
      EXPECT_CLOSE(ours.vy, ours_ref.vy, 1e-3, 1e-3);
      EXPECT_CLOSE(ours.ke, ours_ref.ke, 0, 1e-3);
      EXPECT_CLOSE(ours.min_syy, ours_ref.min_syy, 0, 1e-2);
      EXPECT_CLOSE(ours.cy, ref.at("centroid_y")[r], 0.03, 0);  // still the same rebound within 3 cm
      if (step == 1000) {
        EXPECT_LT(ours.vy, ref.at("mean_vy")[r]);  // and the direction of the difference
      }
    }
  }
  // Particle by particle in free fall (step 250): exact kinematics.
  const auto mine = mpm::io::read_particle_table(dir / "results/block_drop/particles0250.h5");
  const auto theirs = read_gz_table(kCases / "elastic_block_drop/ref/particles0250.h5.gz");
  ASSERT_EQ(mine.size(), theirs.size());
  for (std::size_t k = 0; k < mine.size(); ++k) {
    ASSERT_EQ(mine[k].id, theirs[k].id);
    EXPECT_CLOSE(mine[k].coord_x, theirs[k].coord_x, 1e-9, 0);
    EXPECT_CLOSE(mine[k].coord_y, theirs[k].coord_y, 1e-9, 0);
    EXPECT_CLOSE(mine[k].velocity_y, theirs[k].velocity_y, 1e-9, 0);
    EXPECT_CLOSE(mine[k].stress_yy, theirs[k].stress_yy, 1e-6, 0);  // stress-free fall
  }
}

TEST(CbGeoReference, MohrCoulombColumnGimpShort) {
  // 1280-particle Mohr-Coulomb column (ED2Q16G, USF, FLIP, K0 stresses, frictional base), 5001 steps.
  const fs::path dir = copy_case("mc_column_gimp_short", "column");
  const auto run = run_mpm(dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto ref = read_csv(kCases / "mc_column_gimp_short/ref/summary.csv");
  const auto series = read_csv(dir / "results/mc_column/series.csv");
  ASSERT_EQ(ref.at("step").size(), 21u);
  ASSERT_EQ(series.at("step").size(), 21u);  // one row per output step; step 5000 is the last one
  for (std::size_t r = 0; r < ref.at("step").size(); ++r) {
    const auto step = static_cast<long long>(ref.at("step")[r]);
    ASSERT_EQ(series.at("step")[r], ref.at("step")[r]);
    const auto ours = stats_of(mpm::io::read_particle_table(dir / "results/mc_column" / mpm::io::particle_file_name(step, 5001)));
    ASSERT_EQ(ours.n, 1280u);
    EXPECT_CLOSE(ours.mass, ref.at("total_mass")[r], 0, 1e-12);
    // series.csv is computed from the same state as the file.
    EXPECT_CLOSE(series.at("runout_x_p98")[r], ours.p98x, 0, 1e-10);
    EXPECT_CLOSE(series.at("kinetic_energy_x")[r] + series.at("kinetic_energy_y")[r], ours.ke, 1e-6, 1e-10);
    EXPECT_CLOSE(series.at("time")[r], ref.at("time")[r], 1e-12, 1e-10);
    print_row("runout", step, ours.p98x, ref.at("runout_x_p98")[r]);
    print_row("kinetic_energy", step, ours.ke, ref.at("kinetic_energy")[r]);
    print_row("max_speed", step, ours.vmax, ref.at("max_speed")[r]);
    // Runout grows by 0.32 m over the run: 1 cm (3 % of that growth) covers a different return map
    // (measured: at most 1.3 mm).
    EXPECT_CLOSE(ours.p98x, ref.at("runout_x_p98")[r], 0.01, 0);
    EXPECT_CLOSE(ours.p995y, ref.at("height_y_p995")[r], 0.01, 0);
    // Kinetic energy and peak speed: within 5 % once the collapse is under way (t >= 0.05 s;
    // measured at most 0.9 % and 1.1 %), and within 30 % + a small absolute part in the first
    // 0.05 s, when both are small and set by the initial elastic wave of the K0 state.
    if (ref.at("time")[r] >= 0.05) {
      EXPECT_CLOSE(ours.ke, ref.at("kinetic_energy")[r], 0, 0.05);
      EXPECT_CLOSE(ours.vmax, ref.at("max_speed")[r], 0, 0.05);
    } else {
      EXPECT_CLOSE(ours.ke, ref.at("kinetic_energy")[r], 1.0, 0.30);
      EXPECT_CLOSE(ours.vmax, ref.at("max_speed")[r], 0.01, 0.30);
    }
  }
  // The last state particle by particle: positions within 3 cm (6 % of a cell) of CB-Geo's
  // (measured 1.2 cm; CB-Geo's own 2-thread scatter is 0.2 mm).
  const auto mine = mpm::io::read_particle_table(dir / "results/mc_column/particles5000.h5");
  const auto theirs = read_gz_table(kCases / "mc_column_gimp_short/ref/particles5000.h5.gz");
  ASSERT_EQ(mine.size(), theirs.size());
  double worst = 0;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    ASSERT_EQ(mine[k].id, theirs[k].id);
    ASSERT_EQ(mine[k].nstate_vars, 7u);
    worst = std::max({worst, std::abs(mine[k].coord_x - theirs[k].coord_x), std::abs(mine[k].coord_y - theirs[k].coord_y)});
  }
  std::cout << "  largest particle position difference at step 5000: " << worst << " m\n";
  EXPECT_LT(worst, 0.03);
}

TEST(CbGeoReference, ResumeFromHdf5Bar) {
  // A clamped elastic bar resumed from results/bar_resume/particles000.h5 (steps 1..200).
  const fs::path dir = copy_case("resume_from_h5", "bar");
  const auto run = run_mpm(dir, "mpm.json", "--threads 1");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto ref = read_csv(kCases / "resume_from_h5/ref/tip_velocity.csv");
  for (std::size_t r = 1; r < ref.at("step").size(); ++r) {
    const auto step = static_cast<long long>(ref.at("step")[r]);
    const auto ps = mpm::io::read_particle_table(dir / "results/bar_resume" / mpm::io::particle_file_name(step, 201));
    ASSERT_EQ(ps.size(), 288u);
    double m = 0, vx = 0, ux = 0, ke = 0;
    for (const auto& p : ps) {
      ke += 0.5 * p.mass * (p.velocity_x * p.velocity_x + p.velocity_y * p.velocity_y);
      if (p.id % 48 != 47) continue;
      m += p.mass;
      vx += p.mass * p.velocity_x;
      ux += p.mass * p.displacement_x;
    }
    vx /= m;
    ux /= m;
    print_row("tip_vx", step, vx, ref.at("tip_vx")[r]);
    // The axial tip velocity swings +-0.05 m/s: 2.5e-3 m/s is 5 % of its amplitude; tip displacement
    // (up to 2 mm) within 1e-4 m; kinetic energy within 5 %.
    EXPECT_CLOSE(vx, ref.at("tip_vx")[r], 2.5e-3, 0);
    EXPECT_CLOSE(ux, ref.at("tip_ux")[r], 1e-4, 0);
    EXPECT_CLOSE(ke, ref.at("kinetic_energy")[r], 0, 0.05);
  }
  // The resume input is not overwritten (CB-Geo: the loop starts at step + 1).
  EXPECT_EQ(fs::file_size(dir / "results/bar_resume/particles000.h5"),
            fs::file_size(kCases / "resume_from_h5/results/bar_resume/particles000.h5"));
}
