// Verification: energy behaviour of the implicit integrators on a linear undamped system in free vibration.
// The trapezoidal rule (Newmark gamma = 1/2, beta = 1/4) conserves E = 1/2 v.M v + 1/2 u.K u exactly once
// the acceleration is in equilibrium (Hughes 2000, The Finite Element Method, sec. 9.1.3 / 9.3.2, energy
// method); HHT with alpha < 1 (OpenSees convention) is dissipative: its energy decays over the response,
// though not monotonically step by step, and never grows beyond the start value
// (Hilber, Hughes & Taylor 1977, Earthquake Eng. Struct. Dyn. 5:283-292, spectral radius < 1).
#include <gtest/gtest.h>

#include "fem_script.hpp"
#include "support/tolerance.hpp"

namespace {

/// Total energy from the nodal velocities (lumped mass) and the elements' internal forces (no loads).
double energy(fem::tcl::Interpreter& interp) {
  double kinetic = 0.0, strain = 0.0;
  for (const auto& [tag, element] : interp.context().domain.elements()) {
    auto* e = dynamic_cast<fem::domain::SolidElement*>(element.get());
    const auto& m = e->lumped_mass();
    const auto& f = e->resisting_force();
    const auto u = e->trial_displacement();
    const auto v = e->trial_velocity();
    for (int i = 0; i < 8; ++i) {
      kinetic += 0.5 * m[i] * v[i] * v[i];
      strain += 0.5 * u[i] * f[i];
    }
  }
  return kinetic + strain;
}

std::vector<double> energy_history(const std::string& integrator, int steps, double dt) {
  fem::tcl::Interpreter interp;
  fem_verification::run(interp, std::string(R"tcl(
model basic -ndm 2 -ndf 2
set nx 4; set ny 8
for {set j 0} {$j <= $ny} {incr j} {
  for {set i 0} {$i <= $nx} {incr i} { node [expr {$j*($nx+1) + $i + 1}] [expr {0.5*$i + 0.05*$j}] [expr {0.5*$j}] }
}
fixY 0.0 1 1
nDMaterial ElasticIsotropic 1 1.0e4 0.3 2.0
set e 0
for {set j 0} {$j < $ny} {incr j} {
  for {set i 0} {$i < $nx} {incr i} {
    incr e
    set n1 [expr {$j*($nx+1) + $i + 1}]
    element SSPquad $e $n1 [expr {$n1+1}] [expr {$n1+$nx+2}] [expr {$n1+$nx+1}] 1 PlaneStrain 1.0
  }
}
timeSeries Constant 1
pattern Plain 1 1 { load [expr {$ny*($nx+1) + $nx + 1}] 5.0 -2.0 }
constraints Transformation; numberer RCM; system BandGeneral; test NormDispIncr 1e-12 10; algorithm Newton
integrator LoadControl 1.0; analysis Static
if {[analyze 1] != 0} { error "preload failed" }
remove loadPattern 1
loadConst -time 0.0
wipeAnalysis
constraints Transformation; numberer RCM; system BandGeneral; test NormDispIncr 1e-12 10; algorithm Newton
)tcl") + "integrator " + integrator + "\nanalysis Transient\n");
  std::vector<double> history;
  for (int s = 0; s < steps; ++s) {
    fem_verification::run(interp, "analyze 1 " + std::to_string(dt));
    history.push_back(energy(interp));
  }
  return history;
}

TEST(NewmarkEnergy, AverageAccelerationConservesEnergy) {
  const auto e = energy_history("Newmark 0.5 0.25", 300, 0.002);
  ASSERT_GT(e[0], 0.0);
  for (std::size_t i = 1; i < e.size(); ++i) EXPECT_CLOSE(e[i], e[0], 0.0, 1e-9) << "step " << i + 1;
}

TEST(NewmarkEnergy, HHTDissipatesAndNeverCreatesEnergy) {
  const auto e = energy_history("HHT 0.8", 300, 0.02);
  for (std::size_t i = 1; i < e.size(); ++i) EXPECT_LE(e[i], e[0] * (1.0 + 1e-3)) << "step " << i + 1;
  double first = 0.0, last = 0.0;
  for (int i = 0; i < 50; ++i) { first += e[i]; last += e[e.size() - 1 - i]; }
  EXPECT_LT(last, 0.99 * first);
  // alpha = 1 is Newmark's average acceleration rule: conservative again
  const auto n = energy_history("HHT 1.0", 100, 0.02);
  for (std::size_t i = 1; i < n.size(); ++i) EXPECT_CLOSE(n[i], n[0], 0.0, 1e-9) << "step " << i + 1;
}

}  // namespace
