// Unit tests of mpm::core::Simulation: CB-Geo's particle defaults, the time step, snapshots, exact
// resume and determinism, particles leaving the grid, numerical and input errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/cpu_variants.hpp"
#include "common/input_error.hpp"
#include "mpm/core/simulation.hpp"
#include "support/tolerance.hpp"
#include "support/mpm_test_decks.hpp"

namespace {

using namespace mpm_test;
using mpm::core::Simulation;
using mpm::ParticleRecord;

/// A small Mohr-Coulomb column that collapses (K0 stresses, rough base, roller wall).
Deck collapsing_column(mpm::Scheme scheme, CellType type, const std::string& smoothing = "none") {
  Deck deck = mpm_test::collapsing_column(make_grid(0, 0, 0.5, 16, 8, type), mohr_coulomb(3, 1800, 5e6, 0.3, 30, 200, 0),
                                          2, 3, 2, 0.4);
  deck.analysis.scheme = scheme;
  deck.analysis.cfl = 0.5;
  deck.analysis.dt = 1.0;
  deck.analysis.stress_smoothing = smoothing;
  return deck;
}

bool identical(const std::vector<ParticleRecord>& a, const std::vector<ParticleRecord>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(ParticleRecord)) == 0;
}

TEST(Simulation, AppliesCbGeoParticleDefaults) {
  Deck deck;
  deck.grid = make_grid(0, 0, 1.0, 4, 4, CellType::Gimp16);
  deck.materials.push_back(elastic(0, 2000, 1e6, 0.3));
  fill_block(deck, 0, 1, 0, 1, 2, 0);  // 4 particles in cell (0, 0)
  ParticleRecord lone{};
  lone.id = 10;
  lone.coord_x = 2.5;
  lone.coord_y = 2.5;
  deck.particles.push_back(lone);
  deck.analysis.dt = 1e-3;
  const Simulation sim(deck, 1);
  const auto ps = sim.snapshot();
  ASSERT_EQ(ps.size(), 5u);
  EXPECT_EQ(ps[0].volume, 0.25);
  EXPECT_EQ(ps[0].mass, 500.0);
  EXPECT_EQ(ps[0].nsize_x, 1.0);
  EXPECT_EQ(ps[4].id, 10);
  EXPECT_EQ(ps[4].volume, 1.0);
  EXPECT_EQ(ps[4].nsize_y, 2.0);
  EXPECT_EQ(ps[4].nstate_vars, 0u);
}

TEST(Simulation, GivenVolumeWithoutSizeGetsTheDefaultSize) {
  Deck deck;
  deck.grid = make_grid(0, 0, 1.0, 4, 4, CellType::Gimp16);
  deck.materials.push_back(elastic(0, 2000, 1e6, 0.3));
  fill_block(deck, 0, 1, 0, 1, 2, 0);
  for (auto& p : deck.particles) p.volume = 0.2;  // e.g. from mesh.particles_volumes; no nsize, no mass
  deck.analysis.dt = 1e-3;
  const auto ps = Simulation(deck, 1).snapshot();
  EXPECT_EQ(ps[0].volume, 0.2);
  EXPECT_EQ(ps[0].mass, 400.0);
  EXPECT_EQ(ps[0].nsize_x, 1.0);
  EXPECT_EQ(ps[0].nsize_y, 1.0);
}

TEST(Simulation, AutomaticTimeStepFromCfl) {
  Deck deck = collapsing_column(mpm::Scheme::USL, CellType::Linear4);
  const double K = 5e6 / (3 * 0.4), G = 5e6 / 2.6, cp = std::sqrt((K + 4 * G / 3) / 1800);
  EXPECT_CLOSE(Simulation(deck, 1).dt(), 0.5 * 0.5 / cp, 0, 1e-14);
  deck.analysis.dt = 1e-4;  // the deck's dt is an upper bound
  EXPECT_EQ(Simulation(deck, 1).dt(), 1e-4);
  deck.analysis.cfl = 0;
  deck.first_step = 7;
  const Simulation sim(deck, 1);
  EXPECT_EQ(sim.step_index(), 7);
  EXPECT_CLOSE(sim.time(), 7e-4, 1e-18, 1e-15);
}

TEST(Simulation, MohrCoulombStateVariablesInSnapshot) {
  Simulation sim(collapsing_column(mpm::Scheme::MUSL, CellType::Gimp16), 1);
  for (int i = 0; i < 50; ++i) sim.step();
  const auto ps = sim.snapshot();
  double pd_max = 0;
  for (const auto& p : ps) {
    ASSERT_EQ(p.nstate_vars, 7u);
    EXPECT_EQ(p.material_id, 3u);
    EXPECT_CLOSE(p.svars[0], 30 * std::acos(-1.0) / 180, 1e-15, 0);
    EXPECT_CLOSE(p.svars[3], std::sqrt(3.0) * (p.stress_xx + p.stress_yy + p.stress_zz) / 3, 1e-9, 1e-12);
    pd_max = std::max(pd_max, p.svars[6]);
  }
  EXPECT_GT(pd_max, 0.0);  // the toe yields
  for (std::size_t i = 1; i < ps.size(); ++i) EXPECT_LT(ps[i - 1].id, ps[i].id);
}

TEST(Simulation, MixedMaterialsMatchSingleMaterialRuns) {
  // Two blocks that share no node (4 cells apart), one Mohr-Coulomb (id 0) and one elastic (id 1),
  // settle on a fixed base. Each node sum involves one block only, in the same (key, id) order as in
  // a run of that block alone, so the mixed-material path must reproduce both runs bit for bit.
  auto make = [](bool with_mc, bool with_elastic) {
    Deck deck;
    deck.grid = make_grid(0, 0, 0.5, 20, 8, CellType::Gimp16);
    deck.materials.push_back(mohr_coulomb(0, 1800, 5e6, 0.3, 30, 200, 0));
    deck.materials.push_back(elastic(1, 2000, 1e7, 0.25));
    if (with_mc) fill_block(deck, 0, 2, 0, 2, 2, 0, 0);
    if (with_elastic) fill_block(deck, 5, 7, 0, 2, 2, 1, 1000);
    deck.velocity_constraints.push_back({nodes_where(deck.grid, [](double, double y) { return y <= 1e-9; }), 1, 0.0});
    deck.analysis.scheme = mpm::Scheme::MUSL;
    deck.analysis.gravity = {0, -9.81};
    deck.analysis.dt = 1e-3;
    return deck;
  };
  Simulation mixed(make(true, true), 1), mc(make(true, false), 1), el(make(false, true), 1);
  for (int i = 0; i < 100; ++i) {
    mixed.step();
    mc.step();
    el.step();
  }
  std::vector<ParticleRecord> both = mc.snapshot();
  const auto e = el.snapshot();
  both.insert(both.end(), e.begin(), e.end());
  const auto m = mixed.snapshot();
  EXPECT_TRUE(identical(m, both));
  EXPECT_EQ(m.front().nstate_vars, 7u);
  EXPECT_EQ(m.back().nstate_vars, 0u);
  double syy = 0;
  for (const auto& p : e) syy += p.stress_yy;
  EXPECT_LT(syy, 0.0);  // the elastic block carries its weight
}

TEST(Simulation, PicRemovesVelocityModesTheGridCannotSeeFlipKeepsThem) {
  // 3 x 3 particles in one bilinear cell, x velocities u (1, -2, 1) along each row: zero momentum at
  // all four nodes (sum N u = 0 for both hat functions), a mode the grid cannot see (the FLIP null
  // space, e.g. Brackbill & Ruppel 1986). PIC (velocity_update) replaces the particle velocity by the
  // grid's, zero here; FLIP keeps the mode; a blend b damps it by (1 - b) per step.
  auto run = [](bool pic, double blend) {
    Deck deck;
    deck.grid = make_grid(0, 0, 1.0, 4, 4, CellType::Linear4);
    deck.materials.push_back(elastic(0, 1000, 1e3, 0.0));
    fill_block(deck, 1, 2, 1, 2, 3, 0);  // at 1/6, 1/2, 5/6 of the cell
    const double u[3] = {0.01, -0.02, 0.01};
    for (int i = 0; i < 9; ++i) deck.particles[i].velocity_x = u[i % 3];
    deck.analysis.dt = 1e-3;
    deck.analysis.velocity_update = pic;
    deck.analysis.pic_blend = blend;
    Simulation sim(deck, 1);
    sim.step();
    return sim.snapshot();
  };
  const auto flip = run(false, 0.0), pic = run(true, 0.0), blend = run(false, 0.25);
  EXPECT_CLOSE(flip[0].velocity_x, 0.01, 1e-12, 0);
  EXPECT_CLOSE(pic[0].velocity_x, 0.0, 1e-15, 0);
  EXPECT_CLOSE(blend[0].velocity_x, 0.75 * 0.01, 1e-12, 0);
  EXPECT_CLOSE(flip[0].coord_x, pic[0].coord_x, 1e-15, 0);  // positions follow the grid either way
}

TEST(Simulation, PrescribedNodalVelocityCarriesTheParticles) {
  // Every node's x velocity fixed to 0.5 m/s: the grid velocity field is uniform, the particles move
  // with it (x += 0.5 dt per step) and stay stress free, and under FLIP as under PIC their velocity
  // becomes 0.5: FLIP gets the constrained nodes' velocity change (v_new - v_old) / dt
  // (nodal_constraints.hpp). It used to get zero there (CB-Geo), leaving particles at rest that moved.
  Deck deck;
  deck.grid = make_grid(0, 0, 1.0, 6, 4, CellType::Gimp16);
  deck.materials.push_back(elastic(0, 1000, 1e5, 0.3));
  fill_block(deck, 1, 2, 1, 2, 2, 0);
  deck.velocity_constraints.push_back({nodes_where(deck.grid, [](double, double) { return true; }), 0, 0.5});
  deck.analysis.dt = 1e-2;
  for (bool pic : {false, true}) {
    deck.analysis.velocity_update = pic;
    Simulation sim(deck, 1);
    for (int i = 0; i < 100; ++i) sim.step();
    for (const auto& p : sim.snapshot()) {
      EXPECT_CLOSE(p.displacement_x, 0.5, 1e-12, 0);
      EXPECT_CLOSE(p.velocity_x, 0.5, 1e-12, 0);
      EXPECT_CLOSE(p.stress_xx, 0.0, 1e-6, 0);
    }
  }
}

TEST(Simulation, CundallDampingBringsAColumnToRestFaster) {
  auto kinetic_after = [](double damping) {
    Deck deck;
    deck.grid = make_grid(0, 0, 0.5, 2, 12, CellType::Linear4);
    deck.materials.push_back(elastic(0, 1000, 1e6, 0.0));
    fill_block(deck, 0, 1, 0, 5, 2, 0);
    deck.velocity_constraints.push_back({nodes_where(deck.grid, [](double, double y) { return y <= 1e-9; }), 1, 0.0});
    deck.velocity_constraints.push_back({nodes_where(deck.grid, [](double, double) { return true; }), 0, 0.0});
    deck.analysis.gravity = {0, -9.81};
    deck.analysis.scheme = mpm::Scheme::MUSL;
    deck.analysis.cfl = 0.5;
    deck.analysis.dt = 1.0;
    deck.analysis.cundall_damping = damping;
    Simulation sim(deck, 1);
    while (sim.time() < 1.0) sim.step();
    return totals(sim.snapshot()).kinetic;
  };
  const double undamped = kinetic_after(0.0), damped = kinetic_after(0.2);
  EXPECT_GT(undamped, 10.0);  // the undamped column rings (J per m)
  EXPECT_LT(damped, 0.01 * undamped);
}

class Resume : public ::testing::TestWithParam<std::tuple<mpm::Scheme, CellType, std::string, int>> {};

TEST_P(Resume, ContinuesBitIdentically) {
  const auto [scheme, type, smoothing, threads] = GetParam();
  const Deck deck = collapsing_column(scheme, type, smoothing);
  Simulation full(deck, threads);
  std::vector<ParticleRecord> middle;
  for (int i = 0; i < 60; ++i) {
    if (i == 25) middle = full.snapshot();
    full.step();
  }
  Deck resumed_deck = deck;
  resumed_deck.particles = middle;
  resumed_deck.resumed = true;
  resumed_deck.first_step = 25;
  Simulation resumed(resumed_deck, threads);
  EXPECT_TRUE(identical(resumed.snapshot(), middle));
  while (resumed.step_index() < 60) resumed.step();
  EXPECT_EQ(resumed.step_index(), full.step_index());
  EXPECT_EQ(resumed.time(), full.time());
  EXPECT_TRUE(identical(resumed.snapshot(), full.snapshot()));
}

TEST(Simulation, ApicResumeContinuesBitIdenticallyFromItsMatrices) {
  // The APIC state is (v_p, B_p): resumed with the matrices of the snapshot the run continues bit for
  // bit; resumed from zero matrices (a particle file without them) it does not.
  for (const auto& [scheme, type] : {std::make_pair(mpm::Scheme::MUSL, CellType::Gimp16),
                                     std::make_pair(mpm::Scheme::USF, CellType::Linear4)}) {
    Deck deck = collapsing_column(scheme, type);
    deck.analysis.transfer = mpm::Transfer::APIC;
    Simulation full(deck, 2);
    Deck resumed_deck = deck, zero_deck = deck;
    for (int i = 0; i < 60; ++i) {
      if (i == 25) {
        resumed_deck.particles = zero_deck.particles = full.snapshot();
        resumed_deck.particle_affine = full.affine_snapshot();
      }
      full.step();
    }
    ASSERT_EQ(resumed_deck.particle_affine.size(), resumed_deck.particles.size());
    resumed_deck.resumed = zero_deck.resumed = true;
    resumed_deck.first_step = zero_deck.first_step = 25;
    Simulation resumed(resumed_deck, 2), zero(zero_deck, 2);
    EXPECT_TRUE(resumed.affine_snapshot() == resumed_deck.particle_affine);
    while (resumed.step_index() < 60) resumed.step();
    while (zero.step_index() < 60) zero.step();
    EXPECT_TRUE(identical(resumed.snapshot(), full.snapshot()));
    EXPECT_TRUE(resumed.affine_snapshot() == full.affine_snapshot());
    EXPECT_FALSE(identical(zero.snapshot(), full.snapshot()));
  }
}

TEST(Simulation, LaggedFrictionResumeContinuesBitIdenticallyFromItsMemory) {
  // With a normal_lag the state includes each base node's lagged strength N_s (lagged_friction.hpp):
  // resumed with the memory of the snapshot the run continues bit for bit; resumed without it (the
  // strengths restart from the instantaneous normal forces) it does not; a memory for a node without a
  // lagged friction is refused.
  Deck deck = collapsing_column(mpm::Scheme::MUSL, CellType::Gimp16);
  ASSERT_EQ(deck.friction_constraints.size(), 1u);
  deck.friction_constraints[0].lag_slip_distance = 0.01;
  deck.friction_constraints[0].lag_reference_velocity = 0.1;
  Simulation full(deck, 2);
  Deck resumed_deck = deck, fresh_deck = deck;
  for (int i = 0; i < 60; ++i) {
    if (i == 25) {
      resumed_deck.particles = fresh_deck.particles = full.snapshot();
      resumed_deck.friction_memory = full.friction_memory_snapshot().value();
    }
    full.step();
  }
  ASSERT_FALSE(resumed_deck.friction_memory.empty());
  resumed_deck.resumed = fresh_deck.resumed = true;
  resumed_deck.first_step = fresh_deck.first_step = 25;
  Simulation resumed(resumed_deck, 2), fresh(fresh_deck, 2);
  EXPECT_TRUE(resumed.friction_memory_snapshot().value() == resumed_deck.friction_memory);
  while (resumed.step_index() < 60) resumed.step();
  while (fresh.step_index() < 60) fresh.step();
  EXPECT_TRUE(identical(resumed.snapshot(), full.snapshot()));
  EXPECT_TRUE(resumed.friction_memory_snapshot() == full.friction_memory_snapshot());
  EXPECT_FALSE(identical(fresh.snapshot(), full.snapshot()));

  EXPECT_FALSE(Simulation(collapsing_column(mpm::Scheme::MUSL, CellType::Gimp16), 1).friction_memory_snapshot());
  Deck stray = resumed_deck;
  stray.friction_memory = {{static_cast<std::int64_t>(stray.grid.node_count() - 1), 1.0, 1.0}};
  try {
    Simulation sim(stray, 1);
    ADD_FAILURE() << "the top corner node has no lagged friction";
  } catch (const common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("friction_memory[0]"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    SchemesShapesRemediesThreads, Resume,
    ::testing::Values(std::make_tuple(mpm::Scheme::USF, CellType::Gimp16, std::string("none"), 1),
                      std::make_tuple(mpm::Scheme::USL, CellType::Gimp16, std::string("none"), 2),
                      std::make_tuple(mpm::Scheme::MUSL, CellType::Linear4, std::string("nodal_strain"), 2),
                      std::make_tuple(mpm::Scheme::MUSL, CellType::Gimp16, std::string("cell_volumetric"), 2),
                      std::make_tuple(mpm::Scheme::MUSL, CellType::Gimp16, std::string("cell_strain"), 2),
                      std::make_tuple(mpm::Scheme::USF, CellType::Gimp16, std::string("nodal_volumetric"), 2)));

TEST(Simulation, BitIdenticalForAnyThreadCount) {
  // Work is split into chunks that depend on the particle state only, and their grid contributions
  // are summed in chunk order: the thread count cannot change a bit.
  using mpm::Transfer;
  const std::tuple<mpm::Scheme, const char*, Transfer> cases[] = {
      {mpm::Scheme::MUSL, "none", Transfer::FLIP},
      {mpm::Scheme::MUSL, "nodal_strain", Transfer::FLIP},
      {mpm::Scheme::USF, "nodal_strain", Transfer::FLIP},
      {mpm::Scheme::USL, "cell_volumetric", Transfer::FLIP},
      {mpm::Scheme::MUSL, "cell_strain", Transfer::FLIP},
      {mpm::Scheme::MUSL, "nodal_volumetric", Transfer::FLIP},
      {mpm::Scheme::MUSL, "none", Transfer::APIC}};
  for (const auto& [scheme, smoothing, transfer] : cases) {
    Deck deck = collapsing_column(scheme, CellType::Gimp16, smoothing);
    deck.analysis.transfer = transfer;
    deck.grid = make_grid(0, 0, 0.25, 48, 32, CellType::Gimp16);
    deck.particles.clear();
    fill_block(deck, 0, 4, 0, 7, 4, 3);  // 7,168 particles
    for (auto& p : deck.particles) {
      p.stress_yy = -1800 * 9.81 * (7 - p.coord_y);
      p.stress_xx = p.stress_zz = 0.5 * p.stress_yy;
    }
    const auto& g = deck.grid;
    deck.velocity_constraints = {{nodes_where(g, [](double x, double) { return x <= 1e-9; }), 0, 0.0},
                                 {nodes_where(g, [](double, double y) { return y <= 1e-9; }), 1, 0.0}};
    deck.friction_constraints = {{nodes_where(g, [](double, double y) { return y <= 1e-9; }), 1, -1, 0.4}};
    ASSERT_GT(deck.particles.size(), 3 * 2048u);  // several chunks
    Simulation one(deck, 1), two(deck, 2), three(deck, 3), again(deck, 2);
    for (int i = 0; i < 10; ++i) {
      one.step();
      two.step();
      three.step();
      again.step();
    }
    EXPECT_TRUE(identical(one.snapshot(), two.snapshot())) << smoothing;
    EXPECT_TRUE(identical(one.snapshot(), three.snapshot())) << smoothing;
    EXPECT_TRUE(identical(two.snapshot(), again.snapshot())) << smoothing;
    EXPECT_TRUE(one.affine_snapshot() == three.affine_snapshot()) << smoothing;
  }
}

TEST(Simulation, StencilRunsChangeNoBit) {
  // Four particles on one stencil go through the lanes of a 4-double vector (stencil_runs.hpp, the g2p of
  // engine_g2p.inl), every other particle through the one-particle kernels; each lane evaluates its
  // particle's expressions and every node adds the four contributions in particle order, so switching the
  // runs off must not change a bit: of any scheme, transfer, cell type and remedy, over steps in which
  // particles change cell and stencil quadrant (the re-sort) and the column yields.
  if (!common::wide_vector_kernels()) GTEST_SKIP() << "no 256-bit vector registers: the runs are off either way";
  using mpm::Scheme;
  using mpm::Transfer;
  struct Case {
    const char* name;
    Scheme scheme;
    CellType type;
    Transfer transfer;
    double pic_blend;
    const char* smoothing;
  };
  const Case cases[] = {{"USF uGIMP FLIP", Scheme::USF, CellType::Gimp16, Transfer::FLIP, 0.0, "none"},
                        {"USL uGIMP FLIP + 20 % PIC", Scheme::USL, CellType::Gimp16, Transfer::FLIP, 0.2, "none"},
                        {"MUSL uGIMP FLIP cell_strain", Scheme::MUSL, CellType::Gimp16, Transfer::FLIP, 0.0, "cell_strain"},
                        {"USF uGIMP APIC", Scheme::USF, CellType::Gimp16, Transfer::APIC, 0.0, "none"},
                        {"USL uGIMP APIC", Scheme::USL, CellType::Gimp16, Transfer::APIC, 0.0, "none"},
                        {"MUSL uGIMP APIC nodal_volumetric", Scheme::MUSL, CellType::Gimp16, Transfer::APIC, 0.0,
                         "nodal_volumetric"},
                        {"MUSL bilinear FLIP", Scheme::MUSL, CellType::Linear4, Transfer::FLIP, 0.0, "none"},
                        {"USF bilinear APIC", Scheme::USF, CellType::Linear4, Transfer::APIC, 0.0, "none"}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    // 4 x 4 particles per cell: uGIMP runs are the four particles of a cell's stencil quadrant (the sort
    // key), bilinear runs four of a cell's particles; with 2 x 2 per cell there would be no uGIMP run.
    Deck deck = mpm_test::collapsing_column(make_grid(0, 0, 0.5, 16, 8, c.type),
                                            mohr_coulomb(3, 1800, 5e6, 0.3, 30, 200, 0), 2, 3, 4, 0.4);
    deck.analysis.scheme = c.scheme;
    deck.analysis.cfl = 0.5;
    deck.analysis.dt = 1.0;
    deck.analysis.stress_smoothing = c.smoothing;
    deck.analysis.transfer = c.transfer;
    deck.analysis.pic_blend = c.pic_blend;
    Simulation runs(deck, 2), one_by_one(deck, 2, mpm::core::ExecutionOptions{false});
    for (int i = 0; i < 150; ++i) {
      runs.step();
      one_by_one.step();
    }
    const auto a = runs.snapshot(), b = one_by_one.snapshot();
    double largest_displacement = 0.0;
    for (const auto& p : a)
      largest_displacement = std::max(largest_displacement, std::hypot(p.displacement_x, p.displacement_y));
    EXPECT_GT(largest_displacement, 0.25);  // more than half a cell: particles have changed cell
    EXPECT_TRUE(identical(a, b));
    EXPECT_TRUE(runs.affine_snapshot() == one_by_one.affine_snapshot());
  }
}

TEST(Simulation, ParticleLeavingTheGridIsAnErrorNamingIt) {
  Deck deck;
  deck.grid = make_grid(0, 0, 1.0, 4, 4, CellType::Linear4);
  deck.materials.push_back(elastic(0, 1000, 1e5, 0.3));
  fill_block(deck, 2, 3, 2, 3, 1, 0);
  deck.particles[0].id = 56;
  deck.particles[0].velocity_x = 20.0;  // leaves through x = 4 after a few steps
  deck.analysis.dt = 0.01;
  Simulation sim(deck, 1);
  std::vector<ParticleRecord> last_good;
  try {
    for (int i = 0; i < 100; ++i) {
      last_good = sim.snapshot();
      sim.step();
    }
    FAIL() << "no error";
  } catch (const common::NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("particle 56 left the grid at (4."), std::string::npos) << what;
    EXPECT_EQ(what.rfind("step ", 0), 0u) << what;
  }
  EXPECT_TRUE(identical(sim.snapshot(), last_good));  // the failed step left no trace
}

TEST(Simulation, GimpParticleMayOverhangTheRegionByItsHalfSize) {
  // uGIMP: a particle is on the grid while its domain (half-size lp = nsize h / 4) overlaps the region.
  Deck deck;
  deck.grid = make_grid(0, 0, 1.0, 4, 4, CellType::Gimp16);
  deck.materials.push_back(elastic(0, 1000, 1e3, 0.3));
  fill_block(deck, 1, 2, 0, 1, 4, 0);  // lowest particles at y = 0.125, lp = 0.125
  for (auto& p : deck.particles) p.velocity_y = -1.0;
  deck.analysis.dt = 0.01;
  Simulation sim(deck, 1);
  for (int i = 0; i < 20; ++i) sim.step();  // lowest row at y = -0.075: overhangs, still on the grid
  double ymin = 1;
  for (const auto& p : sim.snapshot()) ymin = std::min(ymin, p.coord_y);
  EXPECT_LT(ymin, 0.0);
  try {
    for (int i = 0; i < 10; ++i) sim.step();  // y < -lp: its whole domain has left
    FAIL() << "no error";
  } catch (const common::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("left the grid"), std::string::npos) << e.what();
  }
}

TEST(Simulation, ParticleLeavingTheGridIsRemovedWithoutLocate) {
  Deck deck;
  deck.grid = make_grid(0, 0, 1.0, 4, 4, CellType::Linear4);
  deck.materials.push_back(elastic(0, 1000, 1e5, 0.3));
  fill_block(deck, 0, 1, 2, 3, 1, 0);
  fill_block(deck, 2, 3, 2, 3, 1, 0);
  deck.particles[1].velocity_x = 20.0;
  deck.analysis.dt = 0.01;
  deck.analysis.locate_particles = false;
  Simulation sim(deck, 1);
  for (int i = 0; i < 20; ++i) sim.step();
  ASSERT_EQ(sim.particle_count(), 1u);
  EXPECT_EQ(sim.snapshot()[0].id, 0);
}

TEST(Simulation, RunawayVelocityIsAnErrorNamingStepParticleAndField) {
  Deck deck;
  deck.grid = make_grid(0, 0, 1.0, 4, 4, CellType::Linear4);
  deck.materials.push_back(elastic(0, 1000, 1e5, 0.3));
  fill_block(deck, 1, 3, 1, 3, 2, 0);
  deck.particles[5].velocity_y = 500.0;  // more than one cell per step
  deck.analysis.dt = 0.01;
  deck.first_step = 1234;
  Simulation sim(deck, 2);
  try {
    sim.step();
    FAIL() << "no error";
  } catch (const common::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("step 1234: particle 5 velocity runaway"), std::string::npos) << e.what();
  }
  EXPECT_EQ(sim.step_index(), 1234);
}

TEST(Simulation, InputErrorsNameTheProblem) {
  Deck deck = collapsing_column(mpm::Scheme::USF, CellType::Linear4);
  Deck bad_material = deck;
  bad_material.particles[3].material_id = 9;
  try {
    Simulation sim(bad_material, 1);
    FAIL();
  } catch (const common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("material_id 9"), std::string::npos) << e.what();
  }
  Deck outside = deck;
  outside.particles[0].coord_x = -1;
  EXPECT_THROW(Simulation(outside, 1), common::InputError);
  Deck smoothing = deck;
  smoothing.analysis.stress_smoothing = "bilateral";
  try {
    Simulation sim(smoothing, 1);
    FAIL();
  } catch (const common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("analysis.stress_smoothing"), std::string::npos) << e.what();
  }
  Deck gimp_without_halo = deck;
  gimp_without_halo.grid.cell_type = CellType::Gimp16;
  EXPECT_THROW(Simulation(gimp_without_halo, 1), common::InputError);
  Deck three_d = deck;  // a 3D grid for the 2D engine (the deck reader does not make one yet)
  three_d.grid.dim = 3;
  try {
    Simulation sim(three_d, 1);
    FAIL();
  } catch (const common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("3D grid"), std::string::npos) << e.what();
  }
  // Transfers that contradict each other in a deck built in code (the reader refuses them in JSON).
  Deck apic_pic = deck;
  apic_pic.analysis.transfer = mpm::Transfer::APIC;
  apic_pic.analysis.velocity_update = true;
  EXPECT_THROW(Simulation(apic_pic, 1), common::InputError);
  Deck apic_blend = deck;
  apic_blend.analysis.transfer = mpm::Transfer::APIC;
  apic_blend.analysis.pic_blend = 0.02;
  EXPECT_THROW(Simulation(apic_blend, 1), common::InputError);
  Deck short_affine = deck;
  short_affine.analysis.transfer = mpm::Transfer::APIC;
  short_affine.particle_affine.resize(2);
  EXPECT_THROW(Simulation(short_affine, 1), common::InputError);
}

}  // namespace
