#pragma once
// The 3D particle materials (CB-Geo's LinearElastic3D and MohrCoulomb3D): the interface of the plane-strain
// ones (materials.hpp: from(), initial_state(), update(), separated(), set_invariants()) on a full stress.
// Stress (sxx, syy, szz, sxy, syz, sxz), Pa, tension positive; strain increment (dexx, deyy, dezz, dgxy,
// dgyz, dgxz), engineering shears (CB-Geo's Vector6d order for both). State variables as the plane-strain
// materials (the same 7 of Mohr-Coulomb, CB-Geo's order). A plane-strain increment (dezz = dgyz = dgxz = 0)
// on a plane stress gives the plane-strain material's stress to round-off (tests/unit/mpm/
// core_materials_3d_test.cpp).
#include <cstddef>
#include <type_traits>

#include "constitutive/mohr_coulomb_3d.hpp"
#include "mpm/core/materials.hpp"
#include "mpm/problem/deck.hpp"

namespace mpm::core {

/// Isotropic linear elasticity, hypoelastic rate form (CB-Geo LinearElastic3D): dsigma = D : deps,
/// dsii = (K + 4G/3) deii + (K - 2G/3)(dejj + dekk), dsij = G dgij (i != j).
struct LinearElastic3D {
  double bulk = 0, shear = 0;
  static constexpr std::size_t kStateCount = 0;
  static LinearElastic3D from(const MaterialSpec& spec) {
    const LinearElastic e = LinearElastic::from(spec);
    return {e.bulk, e.shear};
  }
  void initial_state(double* /*svars*/) const {}
  static constexpr bool separated(double /*mass*/, double /*volume*/) { return false; }
  void update(double* stress, const double* dstrain, double* /*svars*/) const {
    // The plane-strain material's a1, a2 (materials.hpp LinearElastic): its bits for a plane-strain increment.
    const double a1 = bulk + 4.0 / 3.0 * shear, a2 = bulk - 2.0 / 3.0 * shear;
    stress[0] += a1 * dstrain[0] + a2 * (dstrain[1] + dstrain[2]);
    stress[1] += a2 * (dstrain[0] + dstrain[2]) + a1 * dstrain[1];
    stress[2] += a2 * (dstrain[0] + dstrain[1]) + a1 * dstrain[2];
    for (int i = 3; i < 6; ++i) stress[i] += shear * dstrain[i];
  }
};

/// CB-Geo's MohrCoulomb3D: the elastic trial (constitutive::elastic_trial_3d) and the return of a general
/// stress in principal space (constitutive/mohr_coulomb_3d.hpp: face, both edges, apex, Rankine cutoff at
/// the material's tension_cutoff, as the plane-strain material), with MohrCoulombParameters' softening
/// (the strength reached at the start of the step), pdstrain (sqrt(2/3) |dev(deps_p)| over the six
/// components) and stress-free separation.
struct MohrCoulomb3D : MohrCoulombParameters {
  static MohrCoulomb3D from(const MaterialSpec& spec) { return {MohrCoulombParameters::from(spec)}; }
  void update(double* stress, const double* dstrain, double* svars) const;
  /// A return's stress, and its plastic strain increment added to pdstrain (svars[6]).
  static void store(const constitutive::MohrCoulombUpdate3D& r, double* stress, double* svars);
  /// CB-Geo's invariant state variables of `stress` (svars[3..5]), for output (as MohrCoulomb's).
  static void set_invariants(const double* stress, double* svars) {
    set_invariants_of(Eigen::Map<const constitutive::Stress6>(stress), svars);
  }
};

/// A 3D material of the deck (its type: LinearElastic3D = LinearElastic2D, MohrCoulomb3D = MohrCoulomb2D).
using Material3D = MaterialOf<LinearElastic3D, MohrCoulomb3D>;
/// The materials of a dim-dimensional engine: stress components 4 (plane strain) or 6, strain increments
/// 3 or 6.
template <int dim>
using MaterialFor = std::conditional_t<dim == 2, Material, Material3D>;
template <int dim>
inline constexpr int kStressComponents = dim == 2 ? 4 : 6;
template <int dim>
inline constexpr int kStrainComponents = dim == 2 ? 3 : 6;

}  // namespace mpm::core
