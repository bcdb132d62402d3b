// Verification: Terzaghi's one-dimensional consolidation with the u-p elements SSPquadUP and quadUP
// (fem_tcl/elements/ssp_quad_up.hpp, four_node_quad_up.hpp).
//
// An 8 m column of elastic soil (E 2e4 kPa, nu 0.25: constrained modulus M = E (1 - nu) / ((1 + nu)(1 - 2 nu))
// = 24,000 kPa), saturated (Kf 2.2e6 kPa, porosity n = 0.375), laterally confined, impermeable and fixed at
// the base, drained at the top, loaded at the top by q = 20 kPa (ramped over 1 s, then held).
// - Undrained (instantaneous) response of a compressible pore fluid under oedometric loading:
//   p0 = q / (1 + n M / Kf) (Biot 1941; Verruijt, "Theory and Problems of Poroelasticity", 2016, eq. 2.39 in
//   one dimension), checked at the end of the ramp, where the flow has not yet reached the lower half.
// - Consolidation: (1/M + n/Kf) dp/dt = k d2p/dz2 with k the hydraulic conductivity over the unit weight of
//   water (OpenSees' permeability), so cv = k / (1/M + n/Kf), and Terzaghi's series (Terzaghi 1943;
//   Verruijt 2016, eq. 1.37) p(z, t) = p0 sum_m (2 / M_m) sin(M_m z / H) exp(-M_m^2 Tv), M_m = pi (2m + 1) / 2,
//   z from the drained top, H = 8 m, Tv = cv t / H^2, t from the middle of the ramp.
// The isochrones at Tv = 0.05, 0.2 and 0.5 must lie within 2 % of p0 of the series at every node.
// The same model is a golden run of real OpenSees 3.8.0 (tests/data/reference_runs/opensees/up_terzaghi_
// sspquadup): see tests/regression/fem/up_reference_runs_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "fem_script.hpp"
#include "fem_tcl/tcl/interpreter.hpp"

namespace {

using fem::tcl::Interpreter;
using fem_verification::run;

constexpr double kE = 2.0e4, kNu = 0.25, kKf = 2.2e6, kVoid = 0.6, kQ = 20.0, kH = 8.0;
constexpr int kElements = 16;
const double kPermeability = 1.0e-5 / 9.81;  // hydraulic conductivity 1e-5 m/s over gamma_w (kN/m3)

double constrained_modulus() { return kE * (1.0 - kNu) / ((1.0 + kNu) * (1.0 - 2.0 * kNu)); }
double porosity() { return kVoid / (1.0 + kVoid); }
double undrained_pressure() { return kQ / (1.0 + porosity() * constrained_modulus() / kKf); }
double consolidation_coefficient() { return kPermeability / (1.0 / constrained_modulus() + porosity() / kKf); }

/// Terzaghi's series at depth z below the drained top.
double terzaghi(double z, double Tv) {
  double p = 0.0;
  for (int m = 0; m < 200; ++m) {
    const double Mm = M_PI * (2 * m + 1) / 2.0;
    p += 2.0 / Mm * std::sin(Mm * z / kH) * std::exp(-Mm * Mm * Tv);
  }
  return undrained_pressure() * p;
}

/// The column of the golden run, with `element` SSPquadUP or quadUP; left nodes 1, 3, .. 2 n + 1 bottom to top.
std::string column_script(const std::string& element) {
  std::ostringstream s;
  s.precision(17);
  const double h = kH / kElements;
  s << "model basic -ndm 2 -ndf 3\n";
  for (int j = 0; j <= kElements; ++j) s << "node " << 2 * j + 1 << " 0 " << j * h << "\nnode " << 2 * j + 2 << " 1 " << j * h << "\n";
  s << "fix 1 1 1 0\nfix 2 1 1 0\n";
  for (int j = 1; j <= kElements; ++j) s << "fix " << 2 * j + 1 << " 1 0 0\nfix " << 2 * j + 2 << " 1 0 0\n";
  s << "fix " << 2 * kElements + 1 << " 0 0 1\nfix " << 2 * kElements + 2 << " 0 0 1\n";
  s << "nDMaterial ElasticIsotropic 1 " << kE << " " << kNu << " 2.0\n";
  for (int j = 0; j < kElements; ++j) {
    const int n1 = 2 * j + 1;
    s << "element " << element << " " << j + 1 << " " << n1 << " " << n1 + 1 << " " << n1 + 3 << " " << n1 + 2;
    if (element == "SSPquadUP") {
      s << " 1 1.0 " << kKf << " 1.0 " << kPermeability << " " << kPermeability << " " << kVoid << " 1.0e-6 0.0 0.0\n";
    } else {  // quadUP: thick matTag bulk fmass hPerm vPerm b1 b2; bulk the combined modulus Kf / n
      s << " 1.0 1 " << kKf / porosity() << " 1.0 " << kPermeability << " " << kPermeability << " 0.0 0.0\n";
    }
  }
  s << "timeSeries Path 1 -time {0.0 1.0 1.0e10} -values {0.0 1.0 1.0}\n";
  s << "pattern Plain 1 1 { load " << 2 * kElements + 1 << " 0.0 " << -0.5 * kQ << " 0.0; load " << 2 * kElements + 2
    << " 0.0 " << -0.5 * kQ << " 0.0 }\n";
  s << "constraints Transformation\nnumberer RCM\nsystem UmfPack\ntest NormDispIncr 1e-8 30\nalgorithm Newton\n"
       "integrator Newmark 0.6 0.3025\nanalysis Transient\n";
  return s.str();
}

double pore_pressure(Interpreter& interp, int node) { return interp.context().domain.find_node(node)->vel[2]; }

class Terzaghi : public ::testing::TestWithParam<const char*> {};

TEST_P(Terzaghi, UndrainedResponseThenTheSeriesIsochrones) {
  Interpreter interp;
  run(interp, column_script(GetParam()));
  run(interp, "analyze 100 0.01");  // the ramp, t = 1 s
  const double p0 = undrained_pressure();
  // the lower half: the flow from the top has not reached it (cv t = 0.024 m^2)
  double undrained_worst = 0.0;
  for (int j = 0; j <= kElements / 2; ++j) {
    undrained_worst = std::max(undrained_worst, std::abs(pore_pressure(interp, 2 * j + 1) - p0));
    EXPECT_NEAR(pore_pressure(interp, 2 * j + 1), p0, 1e-3 * p0) << "node " << 2 * j + 1;
  }
  std::printf("%s: undrained p0 = %.6g kPa, largest difference %.3g %% of p0\n", GetParam(), p0, 100 * undrained_worst / p0);
  const double dt = 10.0, cv = consolidation_coefficient();
  double t = 1.0;
  for (double Tv : {0.05, 0.2, 0.5}) {
    const int steps = static_cast<int>(std::lround((Tv * kH * kH / cv + 0.5 - t) / dt));
    run(interp, "analyze " + std::to_string(steps) + " " + std::to_string(dt));
    t += steps * dt;
    const double Tv_now = cv * (t - 0.5) / (kH * kH);  // from the middle of the ramp
    double worst = 0.0;
    for (int j = 0; j <= kElements; ++j) {
      const double z = kH - j * kH / kElements;
      worst = std::max(worst, std::abs(pore_pressure(interp, 2 * j + 1) - terzaghi(z, Tv_now)));
    }
    std::printf("%s: Tv = %.3f, largest difference from the series %.3g %% of p0\n", GetParam(), Tv_now, 100 * worst / p0);
    EXPECT_LT(worst, 0.02 * p0) << GetParam() << " at Tv = " << Tv_now;
  }
}

INSTANTIATE_TEST_SUITE_P(UpElements, Terzaghi, ::testing::Values("SSPquadUP", "quadUP"));

}  // namespace
