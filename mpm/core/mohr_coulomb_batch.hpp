#pragma once
// The elastic fast path of the Mohr-Coulomb update over four particles at once (issue 13): the elastic
// trial sigma + D de and the strict test of constitutive::MohrCoulombReturnMap::admits on it, each
// particle in one lane of a Double4. Most particles of a runout are elastic in a step (~75 % on the
// paper's column); for them the trial is the update, and the four trials and tests cost about what one
// scalar update does. Each lane computes the scalar expressions in their order (elastic_trial,
// principal_extremes, inside), so the stresses it writes are the scalar update's bit for bit; a lane
// that fails the strict test (plastic, on the surface within its tolerance, softening, another strength,
// NaN) is left to MohrCoulomb::update, which repeats the test with its tolerance.
#include <cmath>
#include <cstddef>

#include "mpm/core/lanes.hpp"
#include "mpm/core/materials.hpp"

namespace mpm::core {

class MohrCoulombElasticBatch {
 public:
  static constexpr std::size_t kLanes = 4;

  explicit MohrCoulombElasticBatch(const MohrCoulomb& m) : model_(m), enabled_(m.peak_map.valid()) {
    if (!enabled_) return;
    const auto& el = m.peak_map.elasticity();
    const auto& surface = m.peak_map.surface();
    g_ = el.shear_modulus;
    two_g_ = 2.0 * g_;
    lambda_ = el.bulk_modulus - 2.0 * g_ / 3.0;  // as elastic_trial
    sin_phi_ = surface.sin_phi;
    two_c_cos_ = 2.0 * surface.strength.cohesion * surface.cos_phi;  // as inside()
    cutoff_ = surface.strength.tension_cutoff;
    tension_ = m.peak_map.tension_active();
  }

  /// For four consecutive particles (stress [4][4] sxx syy szz sxy, dstrain [4][3] exx eyy gxy, state
  /// variables [4][`state_stride`]): writes the trial into `stress` for each particle the fast path
  /// settles and returns them as a bit mask (bit i: particle i); the others are left as they were.
  unsigned update(double* stress, const double* dstrain, const double* svars, std::size_t state_stride) const {
    if (!enabled_) return 0;
    // One lane a particle (filled element by element: no function returns a Double4, see lanes.hpp).
    Double4 s0{}, s1{}, s2{}, s3{}, e0{}, e1{}, e2{}, phi{}, psi{}, c{}, pdstrain{};
    for (std::size_t i = 0; i < kLanes; ++i) {
      s0[i] = stress[4 * i];
      s1[i] = stress[4 * i + 1];
      s2[i] = stress[4 * i + 2];
      s3[i] = stress[4 * i + 3];
      e0[i] = dstrain[3 * i];
      e1[i] = dstrain[3 * i + 1];
      e2[i] = dstrain[3 * i + 2];
      const double* sv = svars + i * state_stride;
      phi[i] = sv[0];
      psi[i] = sv[1];
      c[i] = sv[2];
      pdstrain[i] = sv[6];
    }
    // At the peak strength and not softening: where the scalar update would use peak_map.
    const auto& peak = model_.peak_surface.strength;
    Mask4 elastic = (phi == peak.friction) & (psi == peak.dilation) & (c == peak.cohesion);
    if (model_.softening) elastic &= pdstrain <= model_.pdstrain_peak;
    const Double4 zero{}, lambda = zero + lambda_, two_g = zero + two_g_, g = zero + g_;
    // elastic_trial
    const Double4 dvol = e0 + e1;
    const Double4 t0 = s0 + lambda * dvol + two_g * e0, t1 = s1 + lambda * dvol + two_g * e1;
    const Double4 t2 = s2 + lambda * dvol, t3 = s3 + g * e2;
    // principal_extremes
    const Double4 center = 0.5 * (t0 + t1), half = 0.5 * (t0 - t1);
    const Double4 rr = half * half + t3 * t3;
    Double4 radius = rr;
    for (std::size_t i = 0; i < kLanes; ++i) radius[i] = std::sqrt(rr[i]);
    const Double4 a = center + radius, b = center - radius;
    const Double4 top = t2 >= a ? t2 : a, bottom = t2 >= b ? b : t2;
    // inside(), the strict branch
    const Double4 f_main = (top - bottom) + (top + bottom) * sin_phi_ - two_c_cos_;
    elastic &= f_main <= zero;
    if (tension_) elastic &= top - cutoff_ <= zero;
    // The settled lanes take their trial; the others keep their stress for the scalar update.
    const Double4 n0 = elastic ? t0 : s0, n1 = elastic ? t1 : s1, n2 = elastic ? t2 : s2, n3 = elastic ? t3 : s3;
    unsigned settled = 0;
    for (std::size_t i = 0; i < kLanes; ++i) {
      double* s = stress + 4 * i;
      s[0] = n0[i];
      s[1] = n1[i];
      s[2] = n2[i];
      s[3] = n3[i];
      settled |= elastic[i] ? 1u << i : 0u;
    }
    return settled;
  }

 private:
  const MohrCoulomb& model_;
  bool enabled_;
  double g_ = 0, two_g_ = 0, lambda_ = 0, sin_phi_ = 0, two_c_cos_ = 0, cutoff_ = 0;
  bool tension_ = false;
};

}  // namespace mpm::core
