// A block on a shaken frictional base against Newmark's (1965) rigid sliding block. The base moves with a
// ground acceleration a_g(t) (external_loading_conditions.base_acceleration; mpm/core/body_force.hpp: the
// run is made in the base's frame, every particle feels -m a_g besides gravity). On a horizontal Coulomb
// base the yield acceleration is a_y = mu g: below it the block moves with the ground; above it the block
// slips relative to the base at -(a_g - mu g) while a_g lasts and then decelerates at mu g until the
// relative velocity is zero. For a rectangular pulse a_g = A over [0, t1] (Newmark 1965, Geotechnique 15,
// 139-160, the rectangular pulse of his Fig. 10; e.g. Kramer 1996, section 10.6.1.2):
//   relative velocity at t1: -(A - mu g) t1;  rest at t1 A / (mu g);
//   permanent relative displacement  d = -(A - mu g) t1^2 A / (2 mu g).
// The block: elastic (E = 100 MPa, nu = 0: the sliding block of sliding_block_test.cpp, stiffer, and
// without its flutter at nu > 0, mpm/README.md "Friction and flutter"), 2 m x 1 m, 0.25 m uGIMP cells,
// APIC (the transfer of fem2mpm decks and the study). Measured: v +0.4 %, d +0.8 % (PIC the same); with
// E = 10 MPa +1.3 % and +3.0 %: the elastic block's base vibration lets nodes stick for moments, so the
// friction falls short of mu N. 3 % covers it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/mpm_test_decks.hpp"
#include "support/tolerance.hpp"

namespace {

using namespace mpm_test;
using mpm::Scheme;

constexpr double kG = 9.81, kMu = 0.3, kPulse = 0.5;  // s

struct Shaken {
  MeanMotion end_of_pulse, end;
};

Shaken shake(double amplitude, Scheme scheme, double t_end) {
  SlidingBlockSpec spec;
  spec.angle_deg = 0.0;
  spec.mu = kMu;
  spec.E = 1e8;
  spec.nu = 0.0;
  spec.x0 = 2.0;
  spec.cells_x = 20;
  spec.type = CellType::Gimp16;
  Deck deck = sliding_block(spec);
  deck.analysis.scheme = scheme;
  deck.analysis.transfer = mpm::Transfer::APIC;
  deck.analysis.cfl = 0.4;
  deck.analysis.dt = 1.0;
  mpm::BaseAcceleration base;
  base.dir = 0;
  base.acceleration = amplitude;
  base.history = mpm::LinearFunction{{0.0, kPulse, kPulse + 1e-9}, {1.0, 1.0, 0.0}};  // a rectangular pulse of length kPulse
  deck.base_acceleration = base;
  mpm::core::Simulation sim(deck, 1);
  Shaken s;
  // The explicit step from t_n takes a_g(t_n): the pulse acts on the steps that start before kPulse.
  while (sim.time() < kPulse - 1e-12) sim.step();
  s.end_of_pulse = mean_motion(sim.snapshot());
  s.end_of_pulse.t = sim.time();
  while (sim.time() < t_end - 1e-12) sim.step();
  s.end = mean_motion(sim.snapshot());
  s.end.t = sim.time();
  return s;
}

class BaseShaking : public testing::TestWithParam<Scheme> {};

TEST_P(BaseShaking, SlidesAsNewmarksRigidBlockAboveTheYieldAcceleration) {
  const double A = 0.5 * kG, ay = kMu * kG;
  const Shaken s = shake(A, GetParam(), 1.2);  // at rest from t1 A / (mu g) = 0.83 s
  const double t1 = s.end_of_pulse.t;
  std::printf("end of pulse t = %.4f s: v %.4f m/s (Newmark %.4f); t = %.2f s: d %.4f m (Newmark %.4f), v %.2e m/s\n", t1,
              s.end_of_pulse.vx, -(A - ay) * t1, s.end.t, s.end.ux, -(A - ay) * t1 * t1 * A / (2 * ay), s.end.vx);
  EXPECT_CLOSE(s.end_of_pulse.vx, -(A - ay) * t1, 0.0, 0.03);
  EXPECT_CLOSE(s.end.ux, -(A - ay) * t1 * t1 * A / (2 * ay), 0.0, 0.03);
  EXPECT_LT(std::abs(s.end.vx), 0.01);  // at rest on the base again
}

TEST_P(BaseShaking, MovesWithTheGroundBelowTheYieldAcceleration) {
  const Shaken s = shake(0.2 * kG, GetParam(), 1.0);  // a_g < mu g: no slip
  std::printf("relative displacement %.2e m, velocity %.2e m/s\n", s.end.ux, s.end.vx);
  EXPECT_LT(std::abs(s.end_of_pulse.ux), 2e-3);  // elastic shear of the block only
  EXPECT_LT(std::abs(s.end.ux), 2e-3);
}

INSTANTIATE_TEST_SUITE_P(Schemes, BaseShaking, testing::Values(Scheme::USF, Scheme::MUSL),
                         [](const testing::TestParamInfo<Scheme>& info) {
                           return std::string(info.param == Scheme::USF ? "USF" : "MUSL");
                         });

}  // namespace
