#pragma once
// Mohr-Coulomb perfect plasticity for a general (3D) stress: the plane-strain return of mohr_coulomb.hpp
// (face, both edges, apex, Rankine cutoff; [SPO] Boxes 8.4-8.6, [CDA]) on the principal values of the full
// symmetric stress tensor. The return happens in sorted principal space, which plane strain and 3D share
// (MohrCoulombReturnMap::apply_principal); what is 3D is the spectral decomposition (the full 3x3
// eigenproblem, where plane strain has the in-plane Mohr circle and szz) and putting the returned values
// back on the trial's principal axes. An isotropic return keeps those axes ([SPO] sec. 8.1: the return
// mapping of an isotropic model is coaxial with the trial), so sigma = sum_i s_i v_i v_i^T.
//
// Conventions (CB-Geo's Vector6d order, as stress_invariants.hpp): stress (sxx, syy, szz, sxy, syz, sxz),
// Pa, tension positive; strain (exx, eyy, ezz, gxy, gyz, gxz) with engineering shears g = 2 e.
//
// No consistent tangent here: the explicit MPM, which this serves (CB-Geo's MohrCoulomb3D), needs none.
#include <Eigen/Core>

#include "constitutive/mohr_coulomb.hpp"
#include "constitutive/stress_invariants.hpp"

namespace constitutive {

/// A 3D strain (increment) (exx, eyy, ezz, gxy, gyz, gxz), engineering shears.
using Strain6 = Eigen::Matrix<double, 6, 1>;

struct MohrCoulombUpdate3D {
  Stress6 stress;                   ///< updated stress (sxx, syy, szz, sxy, syz, sxz)
  Strain6 plastic_strain_increment;  ///< C (trial - stress), engineering shears
  ReturnRegion region;
};

/// Isotropic elastic trial: stress + lambda tr(de) I + 2 G de (normal), + G g (shear).
inline Stress6 elastic_trial_3d(const Stress6& stress, const Strain6& dstrain, const IsotropicElasticity& el) {
  const double g = el.shear_modulus, lambda = el.bulk_modulus - 2.0 * g / 3.0;
  const double dvol = dstrain[0] + dstrain[1] + dstrain[2];
  Stress6 trial;
  for (int i = 0; i < 3; ++i) trial[i] = stress[i] + lambda * dvol + 2.0 * g * dstrain[i];
  for (int i = 3; i < 6; ++i) trial[i] = stress[i] + g * dstrain[i];
  return trial;
}

/// The stress as a symmetric 3x3 tensor.
Eigen::Matrix3d stress_tensor(const Stress6& stress);

/// The principal values of a symmetric stress, sorted s1 >= s2 >= s3, and their unit directions (column i
/// of `axes` belongs to sorted[i]; an orthonormal basis, also where values repeat).
struct PrincipalStresses {
  Eigen::Vector3d sorted;
  Eigen::Matrix3d axes;
};
PrincipalStresses principal_stresses(const Stress6& stress);
/// sum_i values_i axes_i axes_i^T as (sxx, syy, szz, sxy, syz, sxz).
Stress6 on_principal_axes(const Eigen::Matrix3d& axes, const Eigen::Vector3d& values);

/// Closest-point return of a 3D trial stress with `map`'s elasticity and surface: a trial inside the
/// surface (within round-off, as the plane-strain test) is returned unchanged, bit for bit, with region
/// Elastic and a zero plastic strain increment.
MohrCoulombUpdate3D mohr_coulomb_return_3d(const Stress6& trial_stress, const MohrCoulombReturnMap& map);
/// The same for one call (forms the return map: callers with many points keep one per material).
MohrCoulombUpdate3D mohr_coulomb_return_3d(const Stress6& trial_stress, const IsotropicElasticity& elasticity,
                                           const MohrCoulombStrength& strength);
/// The same without a return map (no allocation; the elastic test on the iteratively computed principal
/// values): for a strength that changes from point to point (softening).
MohrCoulombUpdate3D mohr_coulomb_return_3d(const Stress6& trial_stress, const IsotropicElasticity& elasticity,
                                           const MohrCoulombSurface& surface);
/// Elastic predictor + return.
MohrCoulombUpdate3D mohr_coulomb_update_3d(const Stress6& stress, const Strain6& dstrain,
                                           const IsotropicElasticity& elasticity, const MohrCoulombStrength& strength);

/// Yield function value of the main plane on the 3D principal values (Pa; > 0 outside).
double mohr_coulomb_yield_3d(const Stress6& stress, const MohrCoulombStrength& strength);

}  // namespace constitutive
