#pragma once
// OpenSees' PressureIndependMultiYield clay (fem_tcl/materials/pressure_independ_multi_yield.hpp) as the
// perfectly plastic Mohr-Coulomb strength of the MPM side (CB-Geo MohrCoulomb2D), in plane strain.
//
// With frictionAng = 0 its failure surface is von Mises, q_f = sqrt(3 J2) = 2 c (c = cohesi; the octahedral
// strength 2 sqrt(2) c / 3). Its plastic flow is deviatoric along s (the failure surface never moves), so in
// plane strain steady flow has s_zz = 0, sigma_2 = (sigma_1 + sigma_3) / 2 and sqrt(J2) = (sigma_1 - sigma_3) / 2:
// the largest shear stress at failure is q_f / sqrt(3) = 2 c / sqrt(3), the Tresca (phi = 0) cohesion of the same
// plane-strain strength. The hyperbolic backbone below the strength (its nested surfaces) is not carried over.
// frictionAng > 0 has no such match: its cone is frozen at the confinement of the switch to plasticity,
// a strength that differs from particle to particle.
#include <cmath>

namespace bridge {

/// The Tresca cohesion of a frictionless PressureIndependMultiYield material of cohesi `c`, in c's units.
inline double multi_yield_tresca_cohesion(double c) { return 2.0 * c / std::sqrt(3.0); }

}  // namespace bridge
