#pragma once
// Stress invariants in CB-Geo MPM's conventions (the Mohr-Coulomb state variables written to the particle
// table as svars_3..5: epsilon, rho, theta; see FORMATS.md section 4 and CB-Geo include/materials/
// mohr_coulomb.tcc, compute_stress_invariants, with the utilities of material_utility.tcc).
//
// Stress vectors, Pa, tension positive:
//   plane strain (sxx, syy, szz, sxy)           -- constitutive::PlaneStrainStress
//   full         (sxx, syy, szz, sxy, syz, sxz) -- CB-Geo's Vector6d order
//
//   p       = (sxx + syy + szz) / 3                      mean stress (tension positive)
//   J2      = 1/6 [(sxx-syy)^2 + (syy-szz)^2 + (szz-sxx)^2] + sxy^2 + syz^2 + sxz^2
//   J3      = det(s), s the deviator
//   epsilon = sqrt(3) p                                  (Haigh-Westergaard hydrostatic coordinate)
//   rho     = sqrt(2 J2)                                 (deviatoric radius)
//   theta   = 1/3 acos( (3 sqrt(3) / 2) J3 / J2^(3/2) )  in [0, pi/3] (cosine convention; theta = 0 at
//             triaxial extension s1 > s2 = s3, pi/3 at triaxial compression s1 = s2 > s3); the argument is
//             taken as 0 (theta = pi/6) when J2 <= tolerance, and clamped to [-1, 1] (as CB-Geo).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

namespace constitutive {

using Stress6 = Eigen::Matrix<double, 6, 1>;

/// Plane-strain (sxx, syy, szz, sxy) as a full (sxx, syy, szz, sxy, syz, sxz) vector.
inline Stress6 to_stress6(const Eigen::Vector4d& s) {
  Stress6 out;
  out << s[0], s[1], s[2], s[3], 0.0, 0.0;
  return out;
}

inline double mean_stress(const Stress6& s) { return (s[0] + s[1] + s[2]) / 3.0; }

inline double j2_invariant(const Stress6& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return (a * a + b * b + c * c) / 6.0 + s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
}

inline double j3_invariant(const Stress6& s) {
  const double p = mean_stress(s);
  const double dx = s[0] - p, dy = s[1] - p, dz = s[2] - p;
  const double xy = s[3], yz = s[4], xz = s[5];
  return dx * dy * dz + 2.0 * xy * yz * xz - dx * yz * yz - dy * xz * xz - dz * xy * xy;
}

/// CB-Geo's epsilon = sqrt(3) p.
inline double haigh_epsilon(const Stress6& s) { return std::sqrt(3.0) * mean_stress(s); }
/// CB-Geo's rho = sqrt(2 J2).
inline double haigh_rho(const Stress6& s) { return std::sqrt(2.0 * j2_invariant(s)); }
/// CB-Geo's Lode angle (cosine convention, [0, pi/3]); `tolerance` on J2 as CB-Geo's default (machine epsilon).
inline double lode_angle(const Stress6& s, double tolerance = std::numeric_limits<double>::epsilon()) {
  const double j2 = j2_invariant(s);
  double arg = 0.0;
  if (std::abs(j2) > tolerance) arg = (3.0 * std::sqrt(3.0) / 2.0) * j3_invariant(s) / std::pow(j2, 1.5);
  arg = std::clamp(arg, -1.0, 1.0);
  return std::acos(arg) / 3.0;
}

inline double mean_stress(const Eigen::Vector4d& s) { return (s[0] + s[1] + s[2]) / 3.0; }
inline double j2_invariant(const Eigen::Vector4d& s) { return j2_invariant(to_stress6(s)); }
inline double j3_invariant(const Eigen::Vector4d& s) { return j3_invariant(to_stress6(s)); }
inline double haigh_epsilon(const Eigen::Vector4d& s) { return std::sqrt(3.0) * mean_stress(s); }
inline double haigh_rho(const Eigen::Vector4d& s) { return haigh_rho(to_stress6(s)); }
inline double lode_angle(const Eigen::Vector4d& s, double tolerance = std::numeric_limits<double>::epsilon()) {
  return lode_angle(to_stress6(s), tolerance);
}

}  // namespace constitutive
