#pragma once
// Mohr-Coulomb perfect plasticity in plane strain: elastic predictor + exact return mapping in principal
// stresses onto the face, both edges and the apex of the Mohr-Coulomb pyramid, with an optional Rankine
// tension cutoff (its plane, its edges and its corners with the pyramid), and the consistent tangent.
//
// References
//   [SPO]  de Souza Neto, Peric & Owen (2008), Computational Methods for Plasticity, Wiley:
//          sec. 8.2 (Mohr-Coulomb: return mapping in principal stresses to the main plane, the edges and
//          the apex, and its consistent tangent), Boxes 8.4-8.6; Appendix A (derivatives of isotropic
//          tensor functions, two-dimensional case: the "spin" term of the tangent).
//   [CDA]  Clausen, Damkilde & Andersen (2006), Efficient return algorithms for associated plasticity with
//          multiple yield planes, IJNME 66:1036-1059 (return to planes / lines / points in principal space,
//          the multi-plane linear systems, the Rankine tension cutoff and its corners).
//
// Conventions: Pa, tension positive; principal stresses sorted s1 >= s2 >= s3 (s3 the most compressive).
//   Yield (main plane), [SPO] sec. 8.2:    f = (s1 - s3) + (s1 + s3) sin(phi) - 2 c cos(phi) <= 0
//   Flow potential:                        g = (s1 - s3) + (s1 + s3) sin(psi)
//   Tension cutoff (Rankine, associated):  s_i - T <= 0 with T = min(tension_cutoff, c cot(phi)).
// Plane strain: the total out-of-plane strain increment is zero; szz is tracked through the elastic law.
//
// Hot path: no allocation, no virtual call, no exception. The elastic test is a few flops; plastic states
// solve at most a 3x3 linear system per active-set candidate.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <memory>

namespace constitutive {

/// Plane-strain stress (sxx, syy, szz, sxy), Pa, tension positive.
using PlaneStrainStress = Eigen::Vector4d;
/// Plane-strain strain (increment) (exx, eyy, gxy), engineering shear gxy = 2 exy; ezz = 0.
using PlaneStrainStrain = Eigen::Vector3d;

struct IsotropicElasticity {
  double bulk_modulus;   ///< K, Pa
  double shear_modulus;  ///< G, Pa
  /// From Young's modulus E (Pa) and Poisson's ratio nu: K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu)).
  static IsotropicElasticity from_young_poisson(double young, double poisson) {
    return {young / (3.0 * (1.0 - 2.0 * poisson)), young / (2.0 * (1.0 + poisson))};
  }
};

struct MohrCoulombStrength {
  double friction;        ///< phi, rad, 0 <= phi < pi/2 (phi = 0 is Tresca: no apex)
  double dilation;        ///< psi, rad, 0 <= psi <= phi (non-associated flow when psi != phi)
  double cohesion;        ///< c >= 0, Pa (zero works: no division by zero, no NaN)
  double tension_cutoff;  ///< max principal stress allowed (Rankine cutoff), Pa; +infinity = none.
                          ///< Values at or above the apex c cot(phi) are clamped there (= no cutoff).
};

/// A MohrCoulombStrength with the trigonometry of its angles evaluated once: callers whose strength
/// changes rarely (per material, or per softening update) build it once and pass it to every update,
/// instead of paying sin / cos of phi and psi on every call. The overloads taking a strength build one.
struct MohrCoulombSurface {
  MohrCoulombStrength strength{};
  double sin_phi = 0.0, cos_phi = 1.0;  ///< of strength.friction
  double sin_psi = 0.0;                 ///< of strength.dilation
  MohrCoulombSurface() = default;
  explicit MohrCoulombSurface(const MohrCoulombStrength& st);
};

/// Where the return mapping ended (the active yield planes).
enum class ReturnRegion : std::uint8_t {
  Elastic,                  ///< trial state admissible: returned bit for bit
  Face,                     ///< main plane only
  EdgeTriaxialCompression,  ///< s1 = s2 > s3 (main plane + the plane with s2 in place of s1)
  EdgeTriaxialExtension,    ///< s1 > s2 = s3 (main plane + the plane with s2 in place of s3)
  Apex,                     ///< s1 = s2 = s3 = c cot(phi)
  TensionCutoff,            ///< s1 = T only
  TensionShearEdge,         ///< s1 = T on the main plane
  TensionCutoffEdge,        ///< s1 = s2 = T (two tension planes)
  TensionCorner,            ///< a point where tension planes meet the pyramid or each other (incl. s1 = s2 = s3 = T)
};

const char* to_string(ReturnRegion region);

/// The return in sorted principal space: the returned principal values (s1 >= s2 >= s3) and the region.
struct PrincipalUpdate {
  Eigen::Vector3d stress;
  ReturnRegion region;
};

struct MohrCoulombUpdate {
  PlaneStrainStress stress;                  ///< updated stress (sxx, syy, szz, sxy)
  Eigen::Vector4d plastic_strain_increment;  ///< (dexx, deyy, dezz, dgxy) plastic, engineering shear
  ReturnRegion region;
};

/// The moduli of the plane-strain elastic trial: lambda = K - 2G/3, 2G and G, formed once per material.
struct PlaneStrainStiffness {
  double lambda = 0.0, two_g = 0.0, g = 0.0;
  PlaneStrainStiffness() = default;
  explicit PlaneStrainStiffness(const IsotropicElasticity& el)
      : lambda(el.bulk_modulus - 2.0 * el.shear_modulus / 3.0), two_g(2.0 * el.shear_modulus), g(el.shear_modulus) {}
};

/// The square root of a double, or of each lane of a GCC vector of doubles (the batched elastic test of
/// mpm/core/materials.hpp): correctly rounded either way (IEEE 754), so both give the same bits. On
/// x86-64 two lanes per SSE2 instruction (the scalar loop pays a library call check per lane for errno).
inline double sqrt_each(double v) { return std::sqrt(v); }
template <class V>
inline V sqrt_each(V v) {
  constexpr int kLanes = static_cast<int>(sizeof(V) / sizeof(double));
#if defined(__SSE2__)
  if constexpr (kLanes % 2 == 0) {
    using Pair = double __attribute__((vector_size(16)));
    for (int i = 0; i < kLanes; i += 2) {
      Pair pair;
      __builtin_memcpy(&pair, reinterpret_cast<const double*>(&v) + i, sizeof pair);
      pair = __builtin_ia32_sqrtpd(pair);
      __builtin_memcpy(reinterpret_cast<double*>(&v) + i, &pair, sizeof pair);
    }
    return v;
  }
#endif
  for (int i = 0; i < kLanes; ++i) v[i] = std::sqrt(v[i]);
  return v;
}

/// Elastic trial stress: stress + D dstrain with dezz = 0, so dszz = (K - 2G/3)(dexx + deyy). T is double
/// or a GCC vector of doubles (one state per lane): the same operations, so the same bits per lane.
template <class T>
inline void elastic_trial_of(const T stress[4], const T dstrain[3], const PlaneStrainStiffness& d, T trial[4]) {
  const T dvol = dstrain[0] + dstrain[1];
  trial[0] = stress[0] + d.lambda * dvol + d.two_g * dstrain[0];
  trial[1] = stress[1] + d.lambda * dvol + d.two_g * dstrain[1];
  trial[2] = stress[2] + d.lambda * dvol;
  trial[3] = stress[3] + d.g * dstrain[2];
}
/// (Inline: the MPM calls it once per particle per step.)
inline PlaneStrainStress elastic_trial(const PlaneStrainStress& stress, const PlaneStrainStrain& dstrain,
                                       const PlaneStrainStiffness& d) {
  const double s[4] = {stress[0], stress[1], stress[2], stress[3]}, de[3] = {dstrain[0], dstrain[1], dstrain[2]};
  double t[4];
  elastic_trial_of(s, de, d, t);
  return {t[0], t[1], t[2], t[3]};
}
inline PlaneStrainStress elastic_trial(const PlaneStrainStress& stress, const PlaneStrainStrain& dstrain,
                                       const IsotropicElasticity& el) {
  return elastic_trial(stress, dstrain, PlaneStrainStiffness(el));
}

/// The largest and smallest principal values s1, s3 of a plane-strain stress (the in-plane Mohr circle
/// and szz), without the directions: what the elastic test reads. T as in elastic_trial_of.
template <class T>
struct Extremes {
  T s1, s3;
};
template <class T>
inline Extremes<T> principal_extremes(T sxx, T syy, T szz, T sxy) {
  const T center = 0.5 * (sxx + syy);
  const T half = 0.5 * (sxx - syy);
  const T radius = sqrt_each(half * half + sxy * sxy);
  const T a = center + radius, b = center - radius;
  return {szz >= a ? szz : a, szz >= b ? b : szz};
}
using PrincipalExtremes = Extremes<double>;
inline PrincipalExtremes principal_extremes(const PlaneStrainStress& s) {
  return principal_extremes(s[0], s[1], s[2], s[3]);
}

/// The elastic test without tolerance ([SPO] Box 8.4 (ii)): the main plane f = (s1 - s3) + (s1 + s3) sin phi
/// - 2 c cos phi <= 0 and, where the cutoff is in force, s1 <= T. True for most states; a state on the
/// surface within round-off needs the full test (inside(), mohr_coulomb.cpp). T as in elastic_trial_of
/// (for a vector, a lane mask).
template <class T>
inline auto strictly_inside(T s1, T s3, double sin_phi, double two_c_cos_phi, bool tension, double tension_cutoff) {
  const auto main_plane = (s1 - s3) + (s1 + s3) * sin_phi - two_c_cos_phi <= 0.0;
  return tension ? main_plane && s1 - tension_cutoff <= 0.0 : main_plane;
}

/// Elastic predictor + closest-point return in principal stress space ([SPO] Boxes 8.4-8.6; [CDA])
/// onto face / edges / apex (+ tension cutoff). A trial state inside the surface (f <= tol) is returned
/// unchanged, bit for bit, with region Elastic and a zero plastic strain increment.
MohrCoulombUpdate mohr_coulomb_update(const PlaneStrainStress& stress, const PlaneStrainStrain& dstrain,
                                      const IsotropicElasticity& elasticity, const MohrCoulombStrength& strength);
MohrCoulombUpdate mohr_coulomb_update(const PlaneStrainStress& stress, const PlaneStrainStrain& dstrain,
                                      const IsotropicElasticity& elasticity, const MohrCoulombSurface& surface);

/// The same return, starting from an elastic trial stress (for callers that build the trial themselves).
MohrCoulombUpdate mohr_coulomb_return(const PlaneStrainStress& trial_stress, const IsotropicElasticity& elasticity,
                                      const MohrCoulombStrength& strength);
MohrCoulombUpdate mohr_coulomb_return(const PlaneStrainStress& trial_stress, const IsotropicElasticity& elasticity,
                                      const MohrCoulombSurface& surface);

/// mohr_coulomb_return for one elasticity and one surface, with what depends on them alone formed once
/// (the yield planes, each active-set candidate's matrix and inverse, the tension cutoff's state):
/// apply(trial) gives mohr_coulomb_return(trial, elasticity, surface) bit for bit, with less work per
/// plastic state. Immutable; copies share the data (safe to use from several threads).
class MohrCoulombReturnMap {
 public:
  MohrCoulombReturnMap() = default;
  MohrCoulombReturnMap(const IsotropicElasticity& elasticity, const MohrCoulombSurface& surface);
  bool valid() const { return data_ != nullptr; }
  MohrCoulombUpdate apply(const PlaneStrainStress& trial_stress) const;
  /// The first part of admits(), on the principal extremes of a trial (T as in elastic_trial_of: for a
  /// vector, a lane mask); a trial it refuses may still admit at round-off.
  template <class T>
  auto strictly_admits(const Extremes<T>& t) const {
    return strictly_inside(t.s1, t.s3, sin_phi_, two_c_cos_phi_, tension_, tension_cutoff_);
  }
  /// True when apply() would find the trial elastic (the same test, without the spectral directions):
  /// the cheap first check of a stress update, where most points are elastic.
  bool admits(const PlaneStrainStress& trial_stress) const {
    const PrincipalExtremes t = principal_extremes(trial_stress);
    return strictly_admits(t) || admits_at_round_off(t);
  }
  /// The second: a trial strictly_admits() refused lies on the surface within round-off.
  bool admits_at_round_off(const PrincipalExtremes& t) const;
  /// apply() for a trial that admits() refused (the elastic test is not repeated).
  MohrCoulombUpdate apply_plastic(const PlaneStrainStress& trial_stress) const;
  /// The return in sorted principal space, which plane strain and 3D share (mohr_coulomb_3d.hpp): the
  /// trial's principal values s1 >= s2 >= s3 in, the returned ones and the region out (Elastic: unchanged).
  PrincipalUpdate apply_principal(const Eigen::Vector3d& sorted_trial) const;
  const MohrCoulombSurface& surface() const;
  const IsotropicElasticity& elasticity() const;

 private:
  struct Data;
  std::shared_ptr<const Data> data_;
  // What admits() reads, beside the pointer: sin phi, 2 c cos phi, the cutoff and whether it is in force.
  double sin_phi_ = 0.0, two_c_cos_phi_ = 0.0, tension_cutoff_ = 0.0;
  bool tension_ = false;
};

/// MohrCoulombReturnMap::apply_principal without a map (each active-set candidate's matrix formed when it
/// is tried, as mohr_coulomb_return; the same result bit for bit): for a strength that changes from point to
/// point (CB-Geo's softening, mpm/core/materials_3d.hpp), where a map per point would allocate.
PrincipalUpdate mohr_coulomb_return_principal(const Eigen::Vector3d& sorted_trial,
                                              const IsotropicElasticity& elasticity, const MohrCoulombSurface& surface);

/// Consistent (algorithmic) tangent d(sxx, syy, szz, sxy) / d(exx, eyy, gxy) of the update at this trial stress
/// ([SPO] sec. 8.2 in principal space, mapped back with the spin term of [SPO] Appendix A).
Eigen::Matrix<double, 4, 3> mohr_coulomb_tangent_4x3(const PlaneStrainStress& trial_stress,
                                                     const IsotropicElasticity& elasticity,
                                                     const MohrCoulombStrength& strength);

/// Consistent tangent d(sxx, syy, sxy) / d(exx, eyy, gxy) (the rows of the 4x3 without szz).
Eigen::Matrix3d mohr_coulomb_tangent(const PlaneStrainStress& trial_stress, const IsotropicElasticity& elasticity,
                                     const MohrCoulombStrength& strength);

/// Yield function value of the main plane (Pa; > 0 outside), for tests and diagnostics.
double mohr_coulomb_yield(const PlaneStrainStress& stress, const MohrCoulombStrength& strength);

}  // namespace constitutive
