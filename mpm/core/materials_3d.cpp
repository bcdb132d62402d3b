#include "mpm/core/materials_3d.hpp"

#include "constitutive/mohr_coulomb_3d.hpp"

namespace mpm::core {

void MohrCoulomb3D::update(double* stress, const double* dstrain, double* svars) const {
  soften(svars);  // CB-Geo mohr_coulomb.tcc, compute_stress: the strength before the predictor
  const constitutive::IsotropicElasticity el{bulk, shear};
  const constitutive::Stress6 trial = constitutive::elastic_trial_3d(
      Eigen::Map<const constitutive::Stress6>(stress), Eigen::Map<const constitutive::Strain6>(dstrain), el);
  // The peak or residual map where the particle has that strength (most particles, most steps: the
  // closed-form elastic test first), else a surface of its own strength (no allocation).
  const constitutive::MohrCoulombReturnMap* map = map_of(svars);
  store(map != nullptr ? constitutive::mohr_coulomb_return_3d(trial, *map)
                       : constitutive::mohr_coulomb_return_3d(trial, el, surface_of(svars)),
        stress, svars);
}

void MohrCoulomb3D::store(const constitutive::MohrCoulombUpdate3D& r, double* stress, double* svars) {
  Eigen::Map<constitutive::Stress6> out(stress);
  out = r.stress;
  if (r.region != constitutive::ReturnRegion::Elastic)
    svars[6] += plastic_deviatoric_strain<3>(r.plastic_strain_increment.data());
}

}  // namespace mpm::core
