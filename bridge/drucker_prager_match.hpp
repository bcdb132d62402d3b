#pragma once
// A Drucker-Prager cone (OpenSees' nDMaterial DruckerPrager) matched to the Mohr-Coulomb strength the MPM
// side uses (CB-Geo MohrCoulomb2D), in plane strain.
//
// OpenSees' cone, tension positive: f = ||s|| + rho I1 - sqrt(2/3) sigma_y = 0 with ||s|| = sqrt(2 J2), i.e.
//   sqrt(J2) + alpha I1 - k = 0,   alpha = rho / sqrt(2),   k = sigma_y / sqrt(3).
// The plane-strain match (Drucker & Prager 1952, Q. Appl. Math. 10(2) 157-165; de Souza Neto, Peric & Owen
// 2008, Computational Methods for Plasticity, section 6.4.3): with associated flow the cone and Mohr-Coulomb
// give the same plane-strain collapse load when
//   alpha = tan(phi) / sqrt(9 + 12 tan^2 phi),   k = 3 c / sqrt(9 + 12 tan^2 phi),
// inverted as
//   tan(phi) = 3 alpha / sqrt(1 - 12 alpha^2),   c = k / sqrt(1 - 12 alpha^2)   (needs 12 alpha^2 < 1),
// and the dilation angle likewise from rho_bar. Both cones then share their apex, I1 = sqrt(2/3) sigma_y / rho
// (OpenSees' tension cutoff T0), i.e. mean stress c cot(phi). Hardening of the cone is not carried over.
#include <optional>

namespace bridge {

struct MohrCoulombStrength {
  double phi_deg = 0;   ///< friction angle, degrees
  double cohesion = 0;  ///< in the units of sigma_y
  double psi_deg = 0;   ///< dilation angle, degrees
};

/// nullopt when rho or rho_bar is too large for a plane-strain match (rho >= 1/sqrt(6): phi would be 90).
std::optional<MohrCoulombStrength> plane_strain_mohr_coulomb(double sigma_y, double rho, double rho_bar);

}  // namespace bridge
