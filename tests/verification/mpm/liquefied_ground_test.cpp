// Liquefied ground in MPM (issue 36, "Verification"): a liquefied soil is a phi = 0 Mohr-Coulomb (Tresca)
// material whose cohesion is its residual undrained strength Sr.
//
// 1. A liquefied infinite slope. A layer of thickness h (normal to the slope) on a slope beta carries on a
//    plane parallel to the surface at depth d the shear tau = rho g d sin(beta) (= gamma z sin(beta)
//    cos(beta) with z = d / cos(beta) the vertical depth: the infinite-slope analysis, e.g. Duncan, Wright &
//    Brandon 2014, Soil Strength and Slope Stability, 2nd ed.). With the strength Sr on the slip plane at
//    depth d the layer above it stays at rest while Sr > rho g d sin(beta), and otherwise slides as
//    Newmark's (1965, Geotechnique 15, 139-160) rigid block on a plane of resistance Sr: per unit area
//      rho d a = rho g d sin(beta) - Sr,   a = g sin(beta) - Sr / (rho d).
//    Set-up: the layer is horizontal and gravity is tilted, g (sin beta, -cos beta) (CB-Geo's
//    external_loading_conditions.gravity); its base node row is fixed in x and y (a rough, no-slip base),
//    so the layer shears within itself. It starts at rest in the infinite slope's stress state with the
//    liquefied soil's isotropic normal stress, sxx = syy = szz = -rho g cos(beta) (h - y), sxy = rho g
//    sin(beta) (h - y) (K0 = 1: a liquefied soil carries its normal stress as pore pressure; then the
//    Tresca circle's radius is the shear on horizontal planes and yield is sxy = Sr).
//    Where it yields: where the initial sxy exceeds Sr (the lowest 30 % for Sr = 0.7 rho g h sin(beta))
//    it drops to Sr in the first step; after that the particles above the base cell gain almost no
//    plastic strain (from 0.2 t_end to t_end: 2e-5 of the base cell's on 0.25 m cells, 1.2e-3 on 0.125 m):
//    the slip is the base cell, between the fixed node row and the first moving one. The moving nodes
//    carry the layer less the mass mapped to the fixed row (half the base cell for particles on sub-cell
//    centres, uGIMP and bilinear alike) and are held back by the base cell's shear sxy = Sr (the nodal
//    force of the base cell on the nodes above the fixed row is exactly its particles' mean sxy per unit
//    length), so the discrete slip plane is the base cell's mid-height and the closed form applies with
//    d = h' = h - h_c / 2 (h_c the cell); h' -> h as the cell shrinks. Measured as the layer's momentum per unit
//    length divided by rho h' (the base cell's particles move at a fraction of the layer's speed).
//    With d = h instead the closed form is 18 % faster here; on a cell of half the size (second case)
//    the result follows h - h_c / 2 again. The layer is long (100 m) with free ends; the ends' stress
//    waves (c_p = 39 m/s) reach the measured middle 10 m after 1.16 s: measured to t = 1 s.
//    Measured (USF and MUSL, APIC, uGIMP): acceleration, velocity and displacement within 0.3 % (USF
//    0.00 % in v; MUSL one step's a dt behind, -0.26 %; the displacement offset is the explicit step's
//    x_{n+1} = x_n + v_{n+1} dt, 1 / n after n steps); on 0.125 m cells 0.00 % in a and v, +0.2 % in u.
//    On fem2mpm's default base instead (a one-sided frictional contact, mu = 0.4, which holds the base
//    row: 0.4 x 34 kPa > Sr) +0.3 % in a and v.
//    The top row moves at the same speed give or take the layer's shear vibration (period 4 h / c_s =
//    0.39 s; -2.4 % at 1 s, +12 % at 0.5 s on 0.125 m cells): printed, not asserted. Sr 20 % above the
//    threshold: the middle does not move (|u| ~ 1e-16 m; 0.6 mm on the contact, whose bottom row starts to
//    vibrate at ~0.6 s) and does not yield.
//    Not asserted, found here: on this no-slip base FLIP slides 6.0-6.5 % slower (USF and MUSL, CFL 0.1-0.4)
//    and PIC hardly moves (terminal velocity 0.09 m/s at CFL 0.4, 0.046 at 0.2, 0.023 at 0.1, instead
//    of a growing a t): the momentum that particles of the base cell map to the fixed nodes is removed
//    there every step, a drag of order rho h_c v / dt that does not vanish with the cell and grows as
//    dt falls. APIC maps the base cell's linear velocity profile exactly (zero at the fixed node) and
//    loses nothing. The same on a sticking frictional base (CB-Geo's or the contact, mu = 0.6): FLIP
//    -6.5 % / -5.9 % in a, PIC -86 % in v at 1 s, APIC 0.0 % / +0.3 %.
// 2. Level ground with a liquefied layer does not run out: with no static shear on horizontal planes no
//    flow is driven whatever Sr is (flow liquefaction needs the static shear stress to exceed the residual
//    strength: Kramer 1996, Geotechnical Earthquake Engineering, ch. 9). A firm elastic base, a liquefied
//    layer (Sr = 2 kPa), a Mohr-Coulomb crust; rollers at both sides, a fixed base; gravity only, 5 s.
//    Displacement < 1 % of the liquefied layer's thickness and no plastic flow after the first second.
//    The layer across the whole width stays at rest to round-off (its K0 states are in equilibrium); a
//    liquefied lens within firm ground (K0 = 1 in it, 0.5 beside it: it pushes the firm ground sideways)
//    moves 3.2 mm (APIC; FLIP 3.5 mm) and vibrates (no damping), its plastic strain fixed after 0.5 s.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "support/mpm_test_decks.hpp"
#include "support/tolerance.hpp"

namespace {

using namespace mpm_test;
using mpm::Scheme;
using mpm::Transfer;

constexpr double kG = 9.81;
double deg(double a) { return a * std::acos(-1.0) / 180.0; }
std::string scheme_name(Scheme s) { return s == Scheme::USF ? "USF" : (s == Scheme::USL ? "USL" : "MUSL"); }
std::string transfer_name(Transfer t) { return t == Transfer::APIC ? "APIC" : (t == Transfer::PIC ? "PIC" : "FLIP"); }

// --- 1. The liquefied infinite slope ------------------------------------------------------------------

/// beta = 15 deg, h = 2 m, a 100 m layer with 15 m of grid beyond its downslope end, uGIMP cells, 2 x 2
/// particles per cell, liquefied soil rho = 1800 kg/m3, E = 2 MPa, nu = 0.3, phi = psi = 0, cohesion
/// Sr = ratio x rho g h sin(beta); APIC, CFL 0.4 (dt 2.6 ms on 0.25 m cells).
struct SlopeSpec {
  double beta_deg = 15, h = 2.0, hc = 0.25, length = 100, room = 15;
  double rho = 1800, E = 2e6, nu = 0.3;
  double sr_ratio = 0.7;
  double t_end = 1.0;
  Scheme scheme = Scheme::USF;
  /// The base: false, fixed in x and y (no slip); true, fem2mpm's default base, a one-sided frictional
  /// contact (friction_constraints alone) with its default coefficient 0.4, which holds (0.4 x 34 kPa of
  /// normal stress against Sr = 6.4 kPa).
  bool contact = false;
};

/// The middle 10 m of the layer (particles by their initial x).
struct Zone {
  double v = 0, u = 0;      ///< the moving layer's velocity and displacement: momentum / (rho h' L), m/s and m
  double v_top = 0;         ///< the mean velocity of the top particle row, m/s
  double u_max = 0;         ///< the largest |displacement| of a particle, m
  double pd_above = 0;      ///< the largest pdstrain of a particle above the base cell
  double pd_base = 1e300;   ///< the smallest pdstrain of a particle in the base cell
};

Zone measure(const std::vector<mpm::ParticleRecord>& ps, const SlopeSpec& s) {
  Zone z;
  double m = 0, top = 0;
  for (const auto& p : ps) {
    const double x0 = p.coord_x - p.displacement_x, y0 = p.coord_y - p.displacement_y;
    if (std::abs(x0 - 0.5 * s.length) > 5.0) continue;
    m += p.mass;
    z.v += p.mass * p.velocity_x;
    z.u += p.mass * p.displacement_x;
    z.u_max = std::max(z.u_max, std::hypot(p.displacement_x, p.displacement_y));
    if (y0 > s.h - 0.5 * s.hc / 2) {
      z.v_top += p.velocity_x;
      top += 1;
    }
    if (y0 > s.hc)
      z.pd_above = std::max(z.pd_above, p.svars[6]);
    else
      z.pd_base = std::min(z.pd_base, p.svars[6]);
  }
  const double moving = s.h / (s.h - 0.5 * s.hc);  // mass of the zone over the mass on its moving nodes
  z.v *= moving / m;
  z.u *= moving / m;
  z.v_top /= top;
  return z;
}

struct SlopeRun {
  Zone early, half, end;  ///< at 0.2 t_end, 0.5 t_end and t_end
  double t_half = 0, t_end = 0, a = 0, a_h = 0;
};

SlopeRun run_slope(const SlopeSpec& s) {
  const double b = deg(s.beta_deg);
  const double sr = s.sr_ratio * s.rho * kG * s.h * std::sin(b);
  Deck deck;
  deck.grid = make_grid(0, 0, s.hc, static_cast<int>(std::lround((s.length + s.room) / s.hc)),
                        static_cast<int>(std::lround(s.h / s.hc)) + 2, CellType::Gimp16);
  deck.materials.push_back(mohr_coulomb(0, s.rho, s.E, s.nu, 0.0, sr, 0.0));
  fill_block(deck, 0, s.length, 0, s.h, 2, 0);
  for (auto& p : deck.particles) {
    p.stress_xx = p.stress_yy = p.stress_zz = -s.rho * kG * std::cos(b) * (s.h - p.coord_y);
    p.tau_xy = s.rho * kG * std::sin(b) * (s.h - p.coord_y);
  }
  const auto base = nodes_where(deck.grid, [](double, double y) { return y <= 1e-9; });  // halo row included
  if (s.contact) {
    deck.friction_constraints.push_back({base, 1, -1, 0.4});
  } else {
    deck.velocity_constraints.push_back({base, 0, 0.0});
    deck.velocity_constraints.push_back({base, 1, 0.0});
  }
  deck.analysis.gravity = {kG * std::sin(b), -kG * std::cos(b)};
  deck.analysis.scheme = s.scheme;
  deck.analysis.transfer = Transfer::APIC;
  deck.analysis.cfl = 0.4;
  deck.analysis.dt = 1.0;
  deck.analysis.locate_particles = false;  // the free ends spread; the downslope one may leave the grid
  mpm::core::Simulation sim(deck, 1);
  SlopeRun r;
  r.a = kG * std::sin(b) - sr / (s.rho * (s.h - 0.5 * s.hc));
  r.a_h = kG * std::sin(b) - sr / (s.rho * s.h);
  while (sim.time() < 0.2 * s.t_end - 1e-12) sim.step();
  r.early = measure(sim.snapshot(), s);
  while (sim.time() < 0.5 * s.t_end - 1e-12) sim.step();
  r.half = measure(sim.snapshot(), s);
  r.t_half = sim.time();
  while (sim.time() < s.t_end - 1e-12) sim.step();
  r.end = measure(sim.snapshot(), s);
  r.t_end = sim.time();
  return r;
}

void expect_slides_as_the_closed_form(const SlopeSpec& s) {
  const SlopeRun r = run_slope(s);
  const double t = r.t_end;
  const double a_measured = (r.end.v - r.half.v) / (r.t_end - r.t_half);
  std::printf("h_c %.3f m: a %.4f m/s2 (closed form with h' = h - h_c/2: %.4f, with h: %.4f); at t = %.2f s v %.4f m/s "
              "(a t %.4f), u %.4f m (a t^2/2 %.4f), top row v %.4f m/s; pdstrain above the base cell %.2e at %.2f s, "
              "%.2e at the end; base cell >= %.3f\n",
              s.hc, a_measured, r.a, r.a_h, t, r.end.v, r.a * t, r.end.u, 0.5 * r.a * t * t, r.end.v_top, r.early.pd_above,
              0.2 * s.t_end, r.end.pd_above, r.end.pd_base);
  EXPECT_CLOSE(a_measured, r.a, 0.0, 0.03);
  EXPECT_CLOSE(r.end.v, r.a * t, 0.0, 0.03);
  EXPECT_CLOSE(r.half.v, r.a * r.t_half, 0.0, 0.03);
  EXPECT_CLOSE(r.end.u, 0.5 * r.a * t * t, 0.0, 0.03);
  // The slip is the base cell: every particle of it yields (its plastic shear ~ u / h_c), and after the
  // first drop to Sr the particles above it gain less than 1 % of its plastic strain.
  EXPECT_GT(r.end.pd_base, 0.1 * r.end.u / s.hc);
  EXPECT_LT(r.end.pd_above - r.early.pd_above, 0.01 * r.end.pd_base);
}

class LiquefiedInfiniteSlope : public testing::TestWithParam<std::tuple<Scheme, bool>> {};

TEST_P(LiquefiedInfiniteSlope, SlidesAtTheClosedFormRateWhenSrIsBelowTheDrivingShear) {
  SlopeSpec s;
  std::tie(s.scheme, s.contact) = GetParam();
  s.sr_ratio = 0.7;  // 30 % below rho g h sin(beta)
  expect_slides_as_the_closed_form(s);
}

TEST_P(LiquefiedInfiniteSlope, StaysAtRestWhenSrIsAboveTheDrivingShear) {
  SlopeSpec s;
  std::tie(s.scheme, s.contact) = GetParam();
  s.sr_ratio = 1.2;  // 20 % above
  const SlopeRun r = run_slope(s);
  std::printf("largest displacement in the middle %.2e m at %.2f s, %.2e m at %.2f s, %.2e m at %.2f s (mean %.2e m); "
              "pdstrain %.2e\n",
              r.early.u_max, 0.2 * s.t_end, r.half.u_max, r.t_half, r.end.u_max, r.t_end, r.end.u, r.end.pd_above);
  // Against 0.32 m when sliding. The fixed base: ~1e-16 m. The contact: its bottom particle row starts to
  // vibrate on it at ~0.6 s (0.6 mm by 1 s, the kinetic energy 0.1 J per metre of layer; 0.9-1.5 mm up
  // to 2.5 s, mostly the ends' waves then): mpm/README.md "Friction and flutter".
  EXPECT_LT(r.end.u_max, s.contact ? 1e-3 : 1e-6);
  EXPECT_EQ(r.end.pd_above, 0.0);
  EXPECT_EQ(r.end.pd_base, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Apic, LiquefiedInfiniteSlope,
                         testing::Values(std::tuple{Scheme::USF, false}, std::tuple{Scheme::MUSL, false},
                                         std::tuple{Scheme::USF, true}),
                         [](const testing::TestParamInfo<LiquefiedInfiniteSlope::ParamType>& info) {
                           return scheme_name(std::get<0>(info.param)) + (std::get<1>(info.param) ? "_Contact" : "_Fixed");
                         });

TEST(LiquefiedInfiniteSlopeRefined, FollowsTheBaseCellOfHalfTheSize) {
  // h_c = 0.125 m: h' = 1.9375 m, a = 0.704 m/s2 (0.643 on 0.25 m cells). Half the time (dt halves), so a
  // layer half as long keeps its ends away from the middle.
  SlopeSpec s;
  s.hc = 0.125;
  s.length = 50;
  s.room = 8;
  s.t_end = 0.5;
  expect_slides_as_the_closed_form(s);
}

// --- 2. Level ground with a liquefied layer ------------------------------------------------------------

/// 16 m wide on 0.5 m uGIMP cells (2 x 2 particles per cell), rho = 1800 kg/m3 throughout: a firm elastic
/// base 1 m thick (E = 30 MPa, nu = 0.3, K0 = nu / (1 - nu)), the liquefied layer 2 m (phi = 0, Sr = 2
/// kPa, E = 2 MPa, K0 = 1), a crust 1 m (phi 30 deg, c 5 kPa, E 10 MPa, K0 = 0.5); with `lens` the liquefied
/// soil only in 5 <= x <= 11 and the crust's material beside it. syy = -rho g (H - y). Rollers at x = 0
/// and 16 m, the base row fixed; gravity only; CFL 0.4, 5 s.
struct LevelResult {
  double u_max = 0;          ///< the largest particle displacement over the run, m
  double pd_1s = 0, pd_end = 0;  ///< the largest pdstrain of the liquefied particles at 1 s and at the end
};

LevelResult run_level(bool lens, Scheme scheme, Transfer transfer) {
  constexpr double rho = 1800, width = 16, hc = 0.5, base = 1, liquefied = 2, crust = 1, H = base + liquefied + crust;
  Deck deck;
  deck.grid = make_grid(0, 0, hc, static_cast<int>(width / hc), static_cast<int>(H / hc) + 2, CellType::Gimp16);
  deck.materials.push_back(elastic(0, rho, 30e6, 0.3));
  deck.materials.push_back(mohr_coulomb(1, rho, 2e6, 0.3, 0.0, 2e3, 0.0));
  deck.materials.push_back(mohr_coulomb(2, rho, 10e6, 0.3, 30.0, 5e3, 0.0));
  fill_block(deck, 0, width, 0, base, 2, 0);
  fill_block(deck, 0, width, base, base + liquefied, 2, 1);
  fill_block(deck, 0, width, base + liquefied, H, 2, 2);
  for (auto& p : deck.particles) {
    if (lens && p.material_id == 1 && (p.coord_x < 5 || p.coord_x > 11)) p.material_id = 2;
    const double k0 = p.material_id == 1 ? 1.0 : (p.material_id == 0 ? 0.3 / 0.7 : 0.5);
    p.stress_yy = -rho * kG * (H - p.coord_y);
    p.stress_xx = p.stress_zz = k0 * p.stress_yy;
  }
  deck.velocity_constraints.push_back({nodes_where(deck.grid, [](double x, double) { return x <= 1e-9; }), 0, 0.0});
  deck.velocity_constraints.push_back({nodes_where(deck.grid, [](double x, double) { return x >= width - 1e-9; }), 0, 0.0});
  const auto bottom = nodes_where(deck.grid, [](double, double y) { return y <= 1e-9; });
  deck.velocity_constraints.push_back({bottom, 0, 0.0});
  deck.velocity_constraints.push_back({bottom, 1, 0.0});
  deck.analysis.gravity = {0, -kG};
  deck.analysis.scheme = scheme;
  deck.analysis.transfer = transfer;
  deck.analysis.cfl = 0.4;
  deck.analysis.dt = 1.0;
  mpm::core::Simulation sim(deck, 1);
  LevelResult r;
  double next = 0.1;
  while (sim.time() < 5.0 - 1e-12) {
    sim.step();
    if (sim.time() < next - 1e-12) continue;
    next += 0.1;
    double pd = 0;
    for (const auto& p : sim.snapshot()) {
      r.u_max = std::max(r.u_max, std::hypot(p.displacement_x, p.displacement_y));
      if (p.material_id == 1) pd = std::max(pd, p.svars[6]);
    }
    if (sim.time() < 1.0 + 1e-9) r.pd_1s = pd;
    r.pd_end = pd;
  }
  return r;
}

class LiquefiedLevelGround : public testing::TestWithParam<std::tuple<bool, Scheme, Transfer>> {};

TEST_P(LiquefiedLevelGround, DoesNotRunOut) {
  const auto [lens, scheme, transfer] = GetParam();
  const LevelResult r = run_level(lens, scheme, transfer);
  std::printf("largest displacement over 5 s %.2e m (1 %% of the layer: 0.02 m); liquefied pdstrain %.2e at 1 s, %.2e at 5 s\n",
              r.u_max, r.pd_1s, r.pd_end);
  EXPECT_LT(r.u_max, 0.01 * 2.0);
  EXPECT_LT(r.pd_end - r.pd_1s, 1e-4);  // no plastic flow once the lens has pushed its neighbours aside
}

INSTANTIATE_TEST_SUITE_P(
    Cases, LiquefiedLevelGround,
    testing::Values(std::tuple{false, Scheme::USF, Transfer::APIC}, std::tuple{true, Scheme::USF, Transfer::APIC},
                    std::tuple{true, Scheme::MUSL, Transfer::APIC}, std::tuple{true, Scheme::USF, Transfer::FLIP}),
    [](const testing::TestParamInfo<LiquefiedLevelGround::ParamType>& info) {
      return std::string(std::get<0>(info.param) ? "Lens_" : "Layer_") + scheme_name(std::get<1>(info.param)) + "_" +
             transfer_name(std::get<2>(info.param));
    });

}  // namespace
