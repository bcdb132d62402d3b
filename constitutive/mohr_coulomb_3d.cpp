#include "constitutive/mohr_coulomb_3d.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace constitutive {

Eigen::Matrix3d stress_tensor(const Stress6& s) {
  Eigen::Matrix3d m;
  m << s[0], s[3], s[5],  //
      s[3], s[1], s[4],   //
      s[5], s[4], s[2];
  return m;
}

PrincipalStresses principal_stresses(const Stress6& s) {
  const Eigen::Matrix3d m = stress_tensor(s);
  // Householder tridiagonalisation + implicit QR: accurate where eigenvalues (nearly) repeat, which the
  // closed-form (trigonometric) solution is not, and the edges of the pyramid are exactly there.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m);
  PrincipalStresses p;
  p.sorted = solver.eigenvalues().reverse();  // the solver's are ascending
  p.axes = solver.eigenvectors().rowwise().reverse();
  return p;
}

Stress6 on_principal_axes(const Eigen::Matrix3d& axes, const Eigen::Vector3d& values) {
  const Eigen::Matrix3d m = axes * values.asDiagonal() * axes.transpose();
  Stress6 out;
  out << m(0, 0), m(1, 1), m(2, 2), 0.5 * (m(0, 1) + m(1, 0)), 0.5 * (m(1, 2) + m(2, 1)), 0.5 * (m(0, 2) + m(2, 0));
  return out;
}

namespace {
/// The return of `trial` on its principal axes: `principal` maps the sorted principal values to the
/// returned ones (PrincipalUpdate); the plastic strain increment from the stress correction.
template <class PrincipalReturn>
MohrCoulombUpdate3D return_on_principal_axes(const Stress6& trial, const IsotropicElasticity& el,
                                             const PrincipalReturn& principal) {
  const PrincipalStresses p = principal_stresses(trial);
  const PrincipalUpdate pu = principal(p.sorted);
  if (pu.region == ReturnRegion::Elastic) return {trial, Strain6::Zero(), ReturnRegion::Elastic};
  MohrCoulombUpdate3D up;
  up.stress = on_principal_axes(p.axes, pu.stress);
  up.region = pu.region;
  // The total strain is fixed, so the plastic strain increment is C (trial - stress) ([SPO] sec. 8.2).
  const Stress6 ds = trial - up.stress;
  const double mean = (ds[0] + ds[1] + ds[2]) / 3.0;
  const double g2 = 2.0 * el.shear_modulus, k3 = 3.0 * el.bulk_modulus;
  for (int i = 0; i < 3; ++i) up.plastic_strain_increment[i] = (ds[i] - mean) / g2 + mean / k3;
  for (int i = 3; i < 6; ++i) up.plastic_strain_increment[i] = ds[i] / el.shear_modulus;
  return up;
}
}  // namespace

MohrCoulombUpdate3D mohr_coulomb_return_3d(const Stress6& trial, const MohrCoulombReturnMap& map) {
  // Most points are elastic: their test takes the eigenvalues alone, in closed form (the trigonometric
  // solution, ~4x cheaper than the iterative one), and passes only with a margin of 1e-10 of the stress
  // scale, far above that solution's round-off; a point nearer the surface takes the accurate path below.
  {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> direct;
    direct.computeDirect(stress_tensor(trial), Eigen::EigenvaluesOnly);
    const Eigen::Vector3d& v = direct.eigenvalues();  // ascending
    const double margin = 1e-10 * std::max(v.cwiseAbs().maxCoeff(), map.surface().strength.cohesion);
    if (map.strictly_admits(Extremes<double>{v[2] + margin, v[0] - margin}))
      return {trial, Strain6::Zero(), ReturnRegion::Elastic};
  }
  return return_on_principal_axes(trial, map.elasticity(),
                                  [&](const Eigen::Vector3d& sorted) { return map.apply_principal(sorted); });
}

MohrCoulombUpdate3D mohr_coulomb_return_3d(const Stress6& trial, const IsotropicElasticity& el,
                                           const MohrCoulombSurface& surface) {
  return return_on_principal_axes(trial, el, [&](const Eigen::Vector3d& sorted) {
    return mohr_coulomb_return_principal(sorted, el, surface);
  });
}

MohrCoulombUpdate3D mohr_coulomb_return_3d(const Stress6& trial, const IsotropicElasticity& el,
                                           const MohrCoulombStrength& st) {
  return mohr_coulomb_return_3d(trial, MohrCoulombReturnMap(el, MohrCoulombSurface(st)));
}

MohrCoulombUpdate3D mohr_coulomb_update_3d(const Stress6& stress, const Strain6& dstrain,
                                           const IsotropicElasticity& el, const MohrCoulombStrength& st) {
  return mohr_coulomb_return_3d(elastic_trial_3d(stress, dstrain, el), el, st);
}

double mohr_coulomb_yield_3d(const Stress6& stress, const MohrCoulombStrength& st) {
  const Eigen::Vector3d s = principal_stresses(stress).sorted;
  return (s[0] - s[2]) + (s[0] + s[2]) * std::sin(st.friction) - 2.0 * st.cohesion * std::cos(st.friction);
}

}  // namespace constitutive
