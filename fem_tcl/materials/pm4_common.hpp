#pragma once
// Plane tensor algebra and yield-surface helpers of the PM4 family of bounding-surface plasticity models for
// liquefaction analyses: PM4Sand (Boulanger & Ziotopoulou 2017, "PM4Sand (Version 3.1): a sand plasticity model
// for earthquake engineering applications", Report UCD/CGM-17/01, UC Davis) and PM4Silt (Boulanger &
// Ziotopoulou 2018, Report UCD/CGM-18/01), as OpenSees implements them (SRC/material/nD/UWmaterials/PM4Sand.cpp,
// PM4Silt.cpp, commit 2890cb36). Both share the yield surface, the tensor conventions and the explicit stress
// integration; they differ in the state-dependent hardening and dilatancy, which each model file implements.
//
// Conventions (as the models' manuals and OpenSees' implementation):
//  - the models are two-dimensional: a tensor is its in-plane 2 x 2 block stored as (xx, yy, xy); there is no
//    out-of-plane component; the mean stress is p = (sxx + syy) / 2 and the deviator s = sigma - p I2
//    (manual section 2, "Stress and strain tensors");
//  - compression positive (geotechnical) inside the model; an NDMaterial negates at its boundary;
//  - stress-like ("contravariant") vectors store the tensor's xy component, strain-like ("covariant") vectors
//    store the engineering shear 2 exy; a : b of two stress-like tensors is a0 b0 + a1 b1 + 2 a2 b2.
#include <Eigen/Core>
#include <cmath>

namespace fem::materials::pm4 {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

/// The tolerance OpenSees' PM4 models use for "zero" (neutral loading, tiny normals, intersection ends).
constexpr double kSmall = 1e-10;
/// sqrt(1/2): the yield surface's radius per unit m p, and alpha = sqrt(1/2) (M - m) n for the model surfaces.
inline const double kRootHalf = std::sqrt(0.5);

/// The second-order identity I2 = (1, 1, 0).
inline Vector3 identity() { return Vector3(1.0, 1.0, 0.0); }
inline double trace(const Vector3& t) { return t[0] + t[1]; }
/// p = (sxx + syy) / 2 (compression positive inside the models).
inline double mean_stress(const Vector3& t) { return 0.5 * trace(t); }
/// t - tr(t) / 2 I2.
inline Vector3 deviator(const Vector3& t) {
  const double tr = trace(t);
  return Vector3(t[0] - 0.5 * tr, t[1] - 0.5 * tr, t[2]);
}
/// a : b of two stress-like tensors (OpenSees DoubleDot2_2_Contr).
inline double contract(const Vector3& a, const Vector3& b) { return a[0] * b[0] + a[1] * b[1] + 2.0 * a[2] * b[2]; }
/// a : b of a stress-like and a strain-like tensor: the plain dot product (OpenSees DoubleDot2_2_Mixed).
inline double contract_mixed(const Vector3& a, const Vector3& b) { return a.dot(b); }
/// sqrt(t : t) of a stress-like tensor.
inline double norm(const Vector3& t) { return std::sqrt(contract(t, t)); }
/// A strain-like vector (engineering shear) as a stress-like one (tensor shear): the shear halved.
inline Vector3 tensor_shear(const Vector3& strain_like) {
  return Vector3(strain_like[0], strain_like[1], 0.5 * strain_like[2]);
}
/// A stress-like vector as a strain-like one: the shear doubled.
inline Vector3 engineering_shear(const Vector3& stress_like) {
  return Vector3(stress_like[0], stress_like[1], 2.0 * stress_like[2]);
}
/// Macaulay brackets <x> = max(x, 0) and the step H(x) (1 for x > 0, else 0).
inline double macaulay(double x) { return x > 0.0 ? x : 0.0; }
inline double step(double x) { return x > 0.0 ? 1.0 : 0.0; }

/// The plane-strain elastic matrix d sigma / d (exx, eyy, gxy) of bulk modulus K and shear modulus G, written
/// as OpenSees' GetStiffness: [[K + 4G/3, K - 2G/3, 0], [K - 2G/3, K + 4G/3, 0], [0, 0, G]].
Matrix3 elastic_stiffness(double K, double G);
/// K = 2 (1 + nu) / (3 (1 - 2 nu)) G (manual, "Elastic moduli").
inline double bulk_modulus(double G, double nu) { return 2.0 / 3.0 * (1.0 + nu) / (1.0 - 2.0 * nu) * G; }

/// The yield surface f = || s - p alpha || - sqrt(1/2) m p, a small cone around the back-stress ratio alpha
/// (manual, "Yield surface"); f > 0 outside.
double yield_function(const Vector3& stress, const Vector3& alpha, double m);
/// Its unit deviatoric normal n = (s - p alpha) / ||s - p alpha|| (OpenSees GetNormalToYield): (0, 0, sqrt(1/2))
/// (simple shear) where |p| < kSmall, and the unnormalised s - p alpha where its norm is below kSmall.
Vector3 yield_normal(const Vector3& stress, const Vector3& alpha);

/// The fraction a in [a0, a1] of an elastic stress increment dsigma from `stress` at which the yield surface is
/// crossed: Pegasus iterations (regula falsi with the Illinois-type weight of OpenSees' IntersectionFactor), at
/// most 10, stopping at |f| < tol_f; 0 when not found, 1 above 1 - kSmall, 0 below kSmall or for NaN.
double elastic_fraction(const Vector3& stress, const Vector3& dsigma, const Vector3& alpha, double m, double tol_f,
                        double a0 = 0.0, double a1 = 1.0);
/// The same after elastic unloading from a point on the surface (OpenSees IntersectionFactor_Unloading): the
/// increment is scanned in 20 sub-steps per pass (9 passes) for the bracket where f crosses tol_f again, which
/// elastic_fraction() then refines.
double elastic_fraction_after_unloading(const Vector3& stress, const Vector3& dsigma, const Vector3& alpha, double m,
                                        double tol_f);

/// The number of equal sub-increments that keep every strain component's increment at or below
/// `max_increment` (OpenSees MaxStrainInc: floor(max |de_i| / max_increment) + 1 when the largest exceeds it,
/// else 1). Throws common::NumericalError beyond 1e6 sub-steps (a diverged iteration, not a load step).
int strain_substeps(const Vector3& strain_increment, double max_increment);

}  // namespace fem::materials::pm4
