#include "mpm/core/materials.hpp"

#include <cmath>

#include "constitutive/mohr_coulomb.hpp"
#include "constitutive/stress_invariants.hpp"

namespace mpm::core {

namespace {
double bulk_modulus(const MaterialSpec& s) { return s.youngs_modulus / (3.0 * (1.0 - 2.0 * s.poisson_ratio)); }
double shear_modulus(const MaterialSpec& s) { return s.youngs_modulus / (2.0 * (1.0 + s.poisson_ratio)); }
}  // namespace

LinearElastic LinearElastic::from(const MaterialSpec& spec) { return {bulk_modulus(spec), shear_modulus(spec)}; }

MohrCoulomb MohrCoulomb::from(const MaterialSpec& spec) {
  MohrCoulomb m;
  m.bulk = bulk_modulus(spec);
  m.shear = shear_modulus(spec);
  m.stiffness = constitutive::PlaneStrainStiffness({m.bulk, m.shear});
  m.phi_peak = spec.friction;
  m.psi_peak = spec.dilation;
  m.c_peak = spec.cohesion;
  m.phi_residual = spec.residual_friction;
  m.psi_residual = spec.residual_dilation;
  m.c_residual = spec.residual_cohesion;
  m.pdstrain_peak = spec.peak_pdstrain;
  m.pdstrain_residual = spec.residual_pdstrain;
  m.tension_cutoff = spec.tension_cutoff;
  m.softening = spec.softening;
  m.separation_density = spec.separation_volume_ratio > 0 ? spec.density / spec.separation_volume_ratio : 0.0;
  m.peak_surface = constitutive::MohrCoulombSurface({m.phi_peak, m.psi_peak, m.c_peak, m.tension_cutoff});
  m.residual_surface =
      constitutive::MohrCoulombSurface({m.phi_residual, m.psi_residual, m.c_residual, m.tension_cutoff});
  const constitutive::IsotropicElasticity el{m.bulk, m.shear};
  m.peak_map = constitutive::MohrCoulombReturnMap(el, m.peak_surface);
  m.residual_map = constitutive::MohrCoulombReturnMap(el, m.residual_surface);
  return m;
}

void MohrCoulomb::initial_state(double* svars) const {
  // CB-Geo initialise_state_variables: peak strength, zero invariants, zero pdstrain.
  svars[0] = phi_peak;
  svars[1] = psi_peak;
  svars[2] = c_peak;
  svars[3] = svars[4] = svars[5] = svars[6] = 0.0;
}

void MohrCoulomb::update_general(double* stress, const double* dstrain, double* svars) const {
  const double pdstrain = svars[6];
  // Linear softening over pdstrain (CB-Geo mohr_coulomb.tcc, compute_stress, before the predictor).
  if (softening && pdstrain > pdstrain_peak) {
    if (pdstrain < pdstrain_residual) {
      const double t = (pdstrain - pdstrain_residual) / (pdstrain_peak - pdstrain_residual);
      svars[0] = phi_residual + (phi_peak - phi_residual) * t;
      svars[1] = psi_residual + (psi_peak - psi_residual) * t;
      svars[2] = c_residual + (c_peak - c_residual) * t;
    } else {
      svars[0] = phi_residual;
      svars[1] = psi_residual;
      svars[2] = c_residual;
    }
  }
  const constitutive::PlaneStrainStress s = Eigen::Map<const Eigen::Vector4d>(stress);
  const constitutive::PlaneStrainStrain de = Eigen::Map<const Eigen::Vector3d>(dstrain);
  const constitutive::PlaneStrainStress trial = constitutive::elastic_trial(s, de, stiffness);
  const constitutive::MohrCoulombStrength strength{svars[0], svars[1], svars[2], tension_cutoff};
  const auto has_angles_of = [&](const constitutive::MohrCoulombSurface& cached) {
    return strength.friction == cached.strength.friction && strength.dilation == cached.strength.dilation;
  };
  // The maps were built from peak_surface and residual_surface: their strengths, without a call.
  const constitutive::MohrCoulombReturnMap* map =
      has_strength_of(peak_map, peak_surface, svars)
          ? &peak_map
          : (has_strength_of(residual_map, residual_surface, svars) ? &residual_map : nullptr);
  if (map != nullptr && map->admits(trial)) {  // elastic: the trial stands, the state is unchanged
    Eigen::Map<Eigen::Vector4d> out(stress);
    out = trial;
    return;
  }
  constitutive::MohrCoulombUpdate r;
  if (map != nullptr) {
    r = map->apply_plastic(trial);
  } else {
    constitutive::MohrCoulombSurface surface;
    if (has_angles_of(peak_surface)) {
      surface = peak_surface;
    } else if (has_angles_of(residual_surface)) {
      surface = residual_surface;
    } else {
      surface = constitutive::MohrCoulombSurface(strength);
    }
    surface.strength = strength;  // the trigonometry depends on the angles only
    r = constitutive::mohr_coulomb_return(trial, {bulk, shear}, surface);
  }
  store(r, stress, svars);
}

void MohrCoulomb::store(const constitutive::MohrCoulombUpdate& r, double* stress, double* svars) {
  Eigen::Map<Eigen::Vector4d>(stress, 4) = r.stress;
  // svars[3..5] (epsilon, rho, theta) are functions of the stress alone: set_invariants() fills them
  // when the state is written out, not in the hot loop.
  if (r.region != constitutive::ReturnRegion::Elastic) {
    const Eigen::Vector4d& dp = r.plastic_strain_increment;
    const double mean = (dp[0] + dp[1] + dp[2]) / 3.0;
    const double d0 = dp[0] - mean, d1 = dp[1] - mean, d2 = dp[2] - mean, d3 = 0.5 * dp[3];
    svars[6] += std::sqrt(2.0 / 3.0 * (d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * d3 * d3));
  }
}

void MohrCoulomb::set_invariants(const double* stress, double* svars) {
  const constitutive::PlaneStrainStress s(stress[0], stress[1], stress[2], stress[3]);
  svars[3] = constitutive::haigh_epsilon(s);
  svars[4] = constitutive::haigh_rho(s);
  svars[5] = constitutive::lode_angle(s);
}

Material Material::from(const MaterialSpec& spec) {
  Material m;
  m.type = spec.type;
  m.id = spec.id;
  m.density = spec.density;
  const double k = bulk_modulus(spec), g = shear_modulus(spec);
  m.p_wave_modulus = k + 4.0 / 3.0 * g;
  if (spec.type == MaterialType::LinearElastic2D) {
    m.elastic = LinearElastic::from(spec);
    m.state_count = LinearElastic::kStateCount;
  } else {
    m.mohr_coulomb = MohrCoulomb::from(spec);
    m.state_count = MohrCoulomb::kStateCount;
  }
  return m;
}

}  // namespace mpm::core
