// The liquefied strength with softening (issue 36, "Liquefied strength"): a phi = 0 Mohr-Coulomb (Tresca)
// material whose cohesion softens linearly from a peak c_p to a residual c_r as the plastic deviatoric
// strain pdstrain goes from peak_pdstrain to residual_pdstrain (CB-Geo's MohrCoulomb softening,
// include/materials/mohr_coulomb.tcc; mpm/core/materials.hpp), in a homogeneous simple-shear element test
// run through the engine: every node of the grid carries a prescribed velocity vx = gdot * y, vy = 0
// (velocity_constraints), so each particle shears at the rate gdot (bilinear cells reproduce the linear
// field exactly) from an isotropic stress -p0.
//
// Closed form (elastoplasticity with linear strain softening in simple shear: the one-dimensional model
// with linear hardening, here of negative modulus, of de Souza Neto, Peric & Owen 2008, Computational
// Methods for Plasticity, ch. 6, with Tresca's yield of their sec. 8.2 for the strength): with sxx = syy =
// szz the Mohr circle of the shear is centred on the mean stress and the Tresca yield s1 - s3 = 2c is
// |tau| = c (szz the intermediate principal stress). For phi = psi = 0 the plastic strain is pure
// shear, gamma_p = gamma - tau / G, and the equivalent plastic deviatoric strain the engine accumulates,
// sqrt(2/3) |dev(d eps_p)| (CB-Geo's dpdstrain), is pdstrain = pd0 + gamma_p / sqrt(3). Its cohesion is
//   c(pd) = c_p (pd <= pd_p),  c_p - H (pd - pd_p) (pd_p < pd < pd_r),  c_r (pd >= pd_r),
//   H = (c_p - c_r) / (pd_r - pd_p).
// Starting unloaded with pdstrain pd0:
//   tau = G gamma                                       while G gamma <= c(pd0) (elastic)
//   tau = c_p - H (pd0 + (gamma - tau / G) / sqrt(3) - pd_p), i.e.
//       = (c_p - H (pd0 - pd_p + gamma / sqrt(3))) / (1 - H / (sqrt(3) G)),  clamped to [c_r, c_p].
// As in CB-Geo, a step uses the cohesion of the pdstrain reached at its start, so the engine lags the
// closed form by H dpdstrain per step (22 Pa here): 60 Pa absolute tolerance (0.3 % of c_p, 1.2 % of c_r).
//
// A particle's initial pdstrain starts its softening: the resume file's state variables (CB-Geo's
// MohrCoulomb order, FORMATS.md section 4: phi, psi, cohesion, epsilon, rho, theta, pdstrain, restored when
// nstate_vars is 7) are read back through the deck reader (analysis.resume), and the shear then yields at
// c(pd0) and follows the same path from there; a file whose nstate_vars is not 7 starts at the peak.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "mpm/core/simulation.hpp"
#include "mpm/io/deck_reader.hpp"
#include "mpm/io/particle_table.hpp"
#include "support/mpm_test_decks.hpp"
#include "support/scratch.hpp"
#include "support/tolerance.hpp"

namespace {

using namespace mpm_test;

// The material: E = 10 MPa, nu = 0.3 (G = 3.846 MPa), rho = 1800 kg/m3, phi = psi = 0, cohesion 20 kPa
// softening to 5 kPa between pdstrain 0.01 and 0.05.
constexpr double kRho = 1800, kE = 1e7, kNu = 0.3;
constexpr double kPeak = 20e3, kResidual = 5e3, kPdPeak = 0.01, kPdResidual = 0.05;
constexpr double kP0 = 100e3;     // Pa, isotropic initial compression (keeps s1 < 0: no tension cutoff)
constexpr double kRate = 0.1;     // 1/s, engineering shear strain rate
constexpr double kDt = 1e-3;      // s: d gamma = 1e-4 per step
constexpr double kGammaEnd = 0.15;
const double kShear = kE / (2 * (1 + kNu));
const double kSqrt3 = std::sqrt(3.0);

double cohesion_at(double pd) {
  if (pd <= kPdPeak) return kPeak;
  if (pd >= kPdResidual) return kResidual;
  return kPeak - (kPeak - kResidual) * (pd - kPdPeak) / (kPdResidual - kPdPeak);
}

/// tau(gamma) of the closed form above, from an unloaded particle with plastic deviatoric strain pd0.
double closed_form_tau(double gamma, double pd0) {
  if (kShear * gamma <= cohesion_at(pd0)) return kShear * gamma;
  const double h = (kPeak - kResidual) / (kPdResidual - kPdPeak);
  const double tau = (kPeak - h * (pd0 - kPdPeak + gamma / kSqrt3)) / (1 - h / (kSqrt3 * kShear));
  return std::clamp(tau, kResidual, kPeak);
}

mpm::MaterialSpec softening_material() {
  mpm::MaterialSpec m = mohr_coulomb(0, kRho, kE, kNu, 0.0, kPeak, 0.0);
  m.residual_cohesion = kResidual;
  m.peak_pdstrain = kPdPeak;
  m.residual_pdstrain = kPdResidual;
  m.softening = true;
  return m;
}

/// The element: 0.5 m bilinear cells, 4 x 2 of them; 2 x 2 particles per cell in [0.5, 1.5] x [0, 1]
/// (16 particles); every node row j prescribed vx = kRate * y_j, vy = 0; no gravity; USF, PIC.
Deck shear_deck() {
  Deck deck;
  deck.grid = make_grid(0, 0, 0.5, 4, 2, CellType::Linear4);
  deck.materials.push_back(softening_material());
  fill_block(deck, 0.5, 1.5, 0.0, 1.0, 2, 0);
  for (auto& p : deck.particles) p.stress_xx = p.stress_yy = p.stress_zz = -kP0;
  for (int j = 0; j < deck.grid.nodes_per_axis[1]; ++j) {
    const double y = deck.grid.origin[1] + j * deck.grid.spacing[1];
    const auto row = nodes_where(deck.grid, [y](double, double yn) { return std::abs(yn - y) < 1e-9; });
    deck.velocity_constraints.push_back({row, 0, kRate * y});
    deck.velocity_constraints.push_back({row, 1, 0.0});
  }
  deck.analysis.scheme = mpm::Scheme::USF;
  deck.analysis.transfer = mpm::Transfer::PIC;
  deck.analysis.velocity_update = true;
  deck.analysis.dt = kDt;
  return deck;
}

struct PathError {
  double tau = 0;       ///< largest |tau - closed form| over the particles and the samples, Pa
  double cohesion = 0;  ///< largest |svars cohesion - c(svars pdstrain)|, Pa
  double pdstrain = 0;  ///< largest |svars pdstrain - (pd0 + (gamma - tau / G) / sqrt(3))|
  double first_yield = 0;  ///< the largest tau of the path (the strength at first yield: softening only lowers it), Pa
  double tau_end = 0, pd_end = 0;
};

/// Shears the deck's particles to kGammaEnd, comparing every particle's tau with the closed form from pd0
/// after every step (gamma from the particle's own strain, gamma_xy).
PathError shear(const Deck& deck, double pd0) {
  mpm::core::Simulation sim(deck, 1);
  PathError e;
  for (long long n = 0; n * kDt * kRate < kGammaEnd - 1e-12; ++n) {
    sim.step();
    for (const auto& p : sim.snapshot()) {
      const double gamma = p.gamma_xy, tau = p.tau_xy;
      EXPECT_EQ(p.nstate_vars, 7u);
      e.tau = std::max(e.tau, std::abs(tau - closed_form_tau(gamma, pd0)));
      e.cohesion = std::max(e.cohesion, std::abs(p.svars[2] - cohesion_at(p.svars[6])));
      e.pdstrain = std::max(e.pdstrain, std::abs(p.svars[6] - (pd0 + std::max(0.0, gamma - tau / kShear) / kSqrt3)));
      EXPECT_EQ(p.stress_xx, -kP0);  // pure shear: the normal stresses stay isotropic
      EXPECT_EQ(p.stress_yy, -kP0);
      e.first_yield = std::max(e.first_yield, tau);
      e.tau_end = tau;
      e.pd_end = p.svars[6];
    }
  }
  EXPECT_CLOSE(e.tau_end, closed_form_tau(kGammaEnd, pd0), 60.0, 0.0);
  return e;
}

// --- The programmed path from a fresh particle ----------------------------------------------------

TEST(LiquefiedSoftening, SimpleShearFollowsThePeakToResidualPath) {
  const PathError e = shear(shear_deck(), 0.0);
  std::printf("largest |tau - closed form| %.1f Pa, |c - c(pd)| %.1f Pa, |pd - closed form| %.2e; first yield %.0f Pa, "
              "end tau %.0f Pa pd %.4f\n",
              e.tau, e.cohesion, e.pdstrain, e.first_yield, e.tau_end, e.pd_end);
  EXPECT_LT(e.tau, 60.0);
  EXPECT_LT(e.cohesion, 60.0);
  EXPECT_LT(e.pdstrain, 2e-4);
  EXPECT_CLOSE(e.first_yield, kPeak, 60.0, 0.0);
  EXPECT_GT(e.pd_end, kPdResidual);  // the path reaches the residual strength...
  EXPECT_CLOSE(e.tau_end, kResidual, 1e-6, 0.0);  // ...and stays there exactly
}

// --- The initial pdstrain of a resume file starts the softening -----------------------------------

/// Writes a CB-Geo deck for the element (mesh generator, one velocity-constraint file row per node and
/// direction, the softening material in degrees) resuming from results/shear/particles0000.h5, whose
/// particles are those of shear_deck() with svars = [0, 0, c_p, 0, 0, 0, pd0] and nstate_vars `count`.
/// Returns the deck as mpm's reader reads it.
Deck resumed_deck(const std::string& name, double pd0, unsigned count) {
  const auto dir = test_support::fresh_scratch_folder("geoflow_liquefied_softening", name);
  const Deck base = shear_deck();
  const long long nsteps = static_cast<long long>(std::lround(kGammaEnd / (kRate * kDt))) + 1;
  std::vector<mpm::ParticleRecord> records = mpm::core::Simulation(base, 1).snapshot();  // masses, volumes
  for (auto& r : records) {
    r.nstate_vars = count;
    std::fill(std::begin(r.svars), std::end(r.svars), 0.0);
    r.svars[2] = kPeak;
    r.svars[6] = pd0;
  }
  std::filesystem::create_directories(dir / "results/shear");
  mpm::io::write_particle_table(dir / "results/shear" / mpm::io::particle_file_name(0, nsteps), records);
  std::ofstream vel(dir / "velocity.txt");
  const mpm::Grid& g = base.grid;
  for (int j = 0; j < g.nodes_per_axis[1]; ++j)
    for (int i = 0; i < g.nodes_per_axis[0]; ++i) {
      vel << i + j * g.nodes_per_axis[0] << " 0 " << kRate * (g.origin[1] + j * g.spacing[1]) << "\n";
      vel << i + j * g.nodes_per_axis[0] << " 1 0\n";
    }
  vel.close();
  std::ofstream(dir / "mpm.json") << R"({
  "mesh": {"generator": {"origin": [0, 0], "cell_size": [0.5, 0.5], "cells": [4, 2]}, "cell_type": "ED2Q4",
           "boundary_conditions": {"velocity_constraints": [{"file": "velocity.txt"}]}},
  "particles": [{"generator": {"type": "gauss", "nparticles_per_dir": 2, "cset_id": -1, "material_id": 0, "pset_id": 0,
                               "io_type": "Ascii2D", "particle_type": "P2D", "check_duplicates": false}}],
  "materials": [{"id": 0, "type": "MohrCoulomb2D", "density": 1800, "youngs_modulus": 1e7, "poisson_ratio": 0.3,
                 "friction": 0, "dilation": 0, "cohesion": 20000, "residual_friction": 0, "residual_dilation": 0,
                 "residual_cohesion": 5000, "peak_pdstrain": 0.01, "residual_pdstrain": 0.05, "tension_cutoff": 0,
                 "softening": true}],
  "analysis": {"type": "MPMExplicit2D", "mpm_scheme": "usf", "velocity_update": true, "locate_particles": true,
               "dt": 0.001, "nsteps": )" << nsteps << R"(, "damping": {"type": "Cundall", "damping_factor": 0.0},
               "resume": {"resume": true, "uuid": "shear", "step": 0}},
  "post_processing": {"path": "results/", "output_steps": 100}
})";
  return mpm::io::read_deck(dir, "mpm.json");
}

class LiquefiedSofteningResumed : public testing::TestWithParam<double> {};

TEST_P(LiquefiedSofteningResumed, InitialPdstrainFromTheParticleFileStartsTheSoftening) {
  const double pd0 = GetParam();
  const Deck deck = resumed_deck("pd" + std::to_string(pd0), pd0, 7);
  ASSERT_TRUE(deck.resumed);
  ASSERT_EQ(deck.particles.size(), 16u);
  EXPECT_EQ(deck.particles.front().svars[6], pd0);
  const PathError e = shear(deck, pd0);
  std::printf("pd0 %.3f: first yield %.0f Pa (c(pd0) %.0f Pa), largest |tau - closed form| %.1f Pa, end pd %.4f\n", pd0,
              e.first_yield, cohesion_at(pd0), e.tau, e.pd_end);
  EXPECT_CLOSE(e.first_yield, cohesion_at(pd0), 60.0, 0.0);
  EXPECT_LT(e.tau, 60.0);
  EXPECT_LT(e.cohesion, 60.0);
  EXPECT_LT(e.pdstrain, 2e-4);
}

// Before the softening range (the peak plateau is shorter), inside it (c(0.03) = 12.5 kPa), past it (residual).
INSTANTIATE_TEST_SUITE_P(Pdstrain, LiquefiedSofteningResumed, testing::Values(0.005, 0.03, 0.08),
                         [](const testing::TestParamInfo<double>& info) {
                           return "pd0_" + std::to_string(static_cast<int>(std::lround(info.param * 1000))) + "e_3";
                         });

TEST(LiquefiedSoftening, StateVariablesOfAnotherCountAreNotRestored) {
  // nstate_vars 0 (a file written for an elastic material, or without state): the particle starts at the
  // peak with pdstrain 0, whatever its svars columns hold (CB-Geo restores them only when the counts match).
  const Deck deck = resumed_deck("count0", 0.03, 0);
  const PathError e = shear(deck, 0.0);
  EXPECT_CLOSE(e.first_yield, kPeak, 60.0, 0.0);
  EXPECT_LT(e.tau, 60.0);
}

}  // namespace
