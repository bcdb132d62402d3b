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

MohrCoulombParameters MohrCoulombParameters::from(const MaterialSpec& spec) {
  MohrCoulombParameters m;
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

void MohrCoulombParameters::initial_state(double* svars) const {
  // CB-Geo initialise_state_variables: peak strength, zero invariants, zero pdstrain.
  svars[0] = phi_peak;
  svars[1] = psi_peak;
  svars[2] = c_peak;
  svars[3] = svars[4] = svars[5] = svars[6] = 0.0;
}

void MohrCoulombParameters::soften(double* svars) const {
  const double pdstrain = svars[6];
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
}

constitutive::MohrCoulombSurface MohrCoulombParameters::surface_of(const double* svars) const {
  const constitutive::MohrCoulombStrength strength{svars[0], svars[1], svars[2], tension_cutoff};
  const auto has_angles_of = [&](const constitutive::MohrCoulombSurface& cached) {
    return strength.friction == cached.strength.friction && strength.dilation == cached.strength.dilation;
  };
  constitutive::MohrCoulombSurface surface;
  if (has_angles_of(peak_surface)) {
    surface = peak_surface;
  } else if (has_angles_of(residual_surface)) {
    surface = residual_surface;
  } else {
    surface = constitutive::MohrCoulombSurface(strength);
  }
  surface.strength = strength;  // the trigonometry depends on the angles only
  return surface;
}

void MohrCoulomb::update_general(double* stress, const double* dstrain, double* svars) const {
  soften(svars);  // CB-Geo mohr_coulomb.tcc, compute_stress: the strength before the predictor
  const constitutive::PlaneStrainStress s = Eigen::Map<const Eigen::Vector4d>(stress);
  const constitutive::PlaneStrainStrain de = Eigen::Map<const Eigen::Vector3d>(dstrain);
  const constitutive::PlaneStrainStress trial = constitutive::elastic_trial(s, de, stiffness);
  // The maps were built from peak_surface and residual_surface: their strengths, without a call.
  const constitutive::MohrCoulombReturnMap* map = map_of(svars);
  if (map != nullptr && map->admits(trial)) {  // elastic: the trial stands, the state is unchanged
    Eigen::Map<Eigen::Vector4d> out(stress);
    out = trial;
    return;
  }
  const constitutive::MohrCoulombUpdate r =
      map != nullptr ? map->apply_plastic(trial)
                     : constitutive::mohr_coulomb_return(trial, {bulk, shear}, surface_of(svars));
  store(r, stress, svars);
}

void MohrCoulomb::store(const constitutive::MohrCoulombUpdate& r, double* stress, double* svars) {
  Eigen::Map<Eigen::Vector4d>(stress, 4) = r.stress;
  // svars[3..5] (epsilon, rho, theta) are functions of the stress alone: set_invariants() fills them
  // when the state is written out, not in the hot loop.
  if (r.region != constitutive::ReturnRegion::Elastic)
    svars[6] += plastic_deviatoric_strain<1>(r.plastic_strain_increment.data());
}

void MohrCoulombParameters::set_invariants_of(const constitutive::Stress6& s, double* svars) {
  svars[3] = constitutive::haigh_epsilon(s);
  svars[4] = constitutive::haigh_rho(s);
  svars[5] = constitutive::lode_angle(s);
}

void MohrCoulomb::set_invariants(const double* stress, double* svars) {
  set_invariants_of(constitutive::to_stress6(Eigen::Map<const Eigen::Vector4d>(stress)), svars);
}

}  // namespace mpm::core
