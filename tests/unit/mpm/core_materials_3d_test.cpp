// Unit tests of mpm/core/materials_3d.hpp (CB-Geo's LinearElastic3D and MohrCoulomb3D): 3D Hooke against
// its closed form; plane-strain increments against the plane-strain materials (materials.hpp), softening
// and pdstrain included; a conventional triaxial compression path against the closed-form failure
// deviator; objectivity under a rotation of axes; the apex / tension return of a cohesionless material;
// separation.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>

#include "constitutive/mohr_coulomb_3d.hpp"
#include "mpm/core/materials.hpp"
#include "mpm/core/materials_3d.hpp"
#include "support/mpm_softening_soil.hpp"
#include "support/tolerance.hpp"

namespace {

using mpm::core::LinearElastic;
using mpm::core::LinearElastic3D;
using mpm::core::MohrCoulomb;
using mpm::core::MohrCoulomb3D;
constexpr double kDeg = 3.14159265358979323846 / 180.0;

mpm::MaterialSpec mc_spec() { return mpm_test::softening_soil(mpm::MaterialType::MohrCoulomb3D); }

Eigen::Matrix3d tensor(const double* v, double shear_factor) {
  Eigen::Matrix3d m;
  m << v[0], shear_factor * v[3], shear_factor * v[5],  //
      shear_factor * v[3], v[1], shear_factor * v[4],   //
      shear_factor * v[5], shear_factor * v[4], v[2];
  return m;
}
/// R v R^T of a 6-vector (CB-Geo order; shear_factor 1 for stress, 1/2 for engineering strain).
void rotate(const Eigen::Matrix3d& r, const double* v, double shear_factor, double* out) {
  const Eigen::Matrix3d m = r * tensor(v, shear_factor) * r.transpose();
  out[0] = m(0, 0), out[1] = m(1, 1), out[2] = m(2, 2);
  out[3] = m(0, 1) / shear_factor, out[4] = m(1, 2) / shear_factor, out[5] = m(0, 2) / shear_factor;
}

TEST(LinearElastic3D, HookeClosedForm) {
  mpm::MaterialSpec s;
  s.youngs_modulus = 2e7;
  s.poisson_ratio = 0.25;
  const LinearElastic3D m = LinearElastic3D::from(s);
  double stress[6] = {-1e3, 2e3, -3e3, 4e2, -5e2, 6e2};
  const double s0[6] = {-1e3, 2e3, -3e3, 4e2, -5e2, 6e2};
  const double de[6] = {1e-4, -2e-4, 0.5e-4, 3e-4, -1e-4, 2e-4};
  m.update(stress, de, nullptr);
  // sigma = lambda tr(e) I + 2 G e (gamma = 2 e shear), lambda = E nu / ((1 + nu)(1 - 2 nu)), G = E / (2 (1 + nu)).
  const double E = 2e7, nu = 0.25, lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  const double tr = de[0] + de[1] + de[2];
  for (int i = 0; i < 3; ++i) EXPECT_CLOSE(stress[i], s0[i] + lambda * tr + 2 * G * de[i], 1e-8, 1e-12);
  for (int i = 3; i < 6; ++i) EXPECT_CLOSE(stress[i], s0[i] + G * de[i], 1e-8, 1e-12);
}

TEST(LinearElastic3D, PlaneStrainIncrementIsThePlaneStrainMaterial) {
  mpm::MaterialSpec s;
  s.youngs_modulus = 3e7;
  s.poisson_ratio = 0.3;
  const LinearElastic m2 = LinearElastic::from(s);
  const LinearElastic3D m3 = LinearElastic3D::from(s);
  double s2[4] = {-1e3, -2e3, -1.5e3, 3e2}, s3[6] = {-1e3, -2e3, -1.5e3, 3e2, 0, 0};
  const double de2[3] = {1e-4, -3e-4, 2e-4}, de3[6] = {1e-4, -3e-4, 0, 2e-4, 0, 0};
  m2.update(s2, de2, nullptr);
  m3.update(s3, de3, nullptr);
  // The same a1, a2 products and sums (materials_3d.hpp): equal, not only to round-off.
  for (int i = 0; i < 3; ++i) EXPECT_EQ(s3[i], s2[i]);
  EXPECT_EQ(s3[3], s2[3]);
  EXPECT_EQ(s3[4], 0.0);
  EXPECT_EQ(s3[5], 0.0);
}

TEST(MohrCoulomb3D, MaterialOfTheDeck) {
  const mpm::core::Material3D m = mpm::core::Material3D::from(mc_spec());
  EXPECT_EQ(m.state_count, 7u);
  const mpm::core::Material m2 = mpm::core::Material::from(mc_spec());
  EXPECT_EQ(m.p_wave_modulus, m2.p_wave_modulus);
  EXPECT_EQ(m.mohr_coulomb.phi_peak, 30 * kDeg);
  static_assert(std::is_same_v<mpm::core::MaterialFor<2>, mpm::core::Material>);
  static_assert(mpm::core::kStressComponents<3> == 6 && mpm::core::kStrainComponents<3> == 6);
}

// Plane-strain increments (dezz = dgyz = dgxz = 0) through both materials: loading in shear and compression
// to the peak surface, softening through pdstrain 0.01..0.05 to the residual strength, then extension
// to the tension cutoff. Stress, strength and pdstrain agree to round-off at every step.
TEST(MohrCoulomb3D, PlaneStrainPathIsThePlaneStrainMaterial) {
  const MohrCoulomb m2 = MohrCoulomb::from(mc_spec());
  const MohrCoulomb3D m3 = MohrCoulomb3D::from(mc_spec());
  double s2[4] = {-2e4, -1.5e4, -1.8e4, 1e3}, s3[6] = {-2e4, -1.5e4, -1.8e4, 1e3, 0, 0};
  double sv2[7], sv3[7];
  m2.initial_state(sv2);
  m3.initial_state(sv3);
  int plastic = 0, softened = 0;
  for (int step = 0; step < 400; ++step) {
    double de2[3];
    if (step < 300) {  // shear with some compression
      de2[0] = -1e-5, de2[1] = 0.4e-5, de2[2] = 4e-4;
    } else {  // extension: tension cutoff, its corners and the apex of the residual pyramid
      de2[0] = 2e-4, de2[1] = 1e-4, de2[2] = -1e-4;
    }
    const double de3[6] = {de2[0], de2[1], 0, de2[2], 0, 0};
    const double pd = sv2[6];
    m2.update(s2, de2, sv2);
    m3.update(s3, de3, sv3);
    if (sv2[6] > pd) ++plastic;
    if (sv2[6] > 0.01 && sv2[6] < 0.05) ++softened;
    const double scale = 1e-9 * std::max({std::abs(s2[0]), std::abs(s2[1]), std::abs(s2[2]), 1e3});
    for (int i = 0; i < 4; ++i) ASSERT_CLOSE(s3[i], s2[i], scale, 1e-9) << "step " << step << " stress " << i;
    ASSERT_CLOSE(s3[4], 0.0, scale, 0) << "step " << step;
    ASSERT_CLOSE(s3[5], 0.0, scale, 0) << "step " << step;
    for (int i : {0, 1, 2}) ASSERT_CLOSE(sv3[i], sv2[i], 1e-12, 1e-9) << "step " << step << " svar " << i;
    ASSERT_CLOSE(sv3[6], sv2[6], 1e-14, 1e-9) << "step " << step;
  }
  EXPECT_GT(plastic, 200);
  EXPECT_GT(softened, 20);
  EXPECT_EQ(sv3[0], m3.phi_residual);  // past residual_pdstrain
  EXPECT_LE(std::max({s3[0], s3[1], s3[2]}), m3.tension_cutoff * (1 + 1e-9));
}

// Conventional triaxial compression (compression positive in the closed form: sigma_a axial, sigma_r
// radial): from an isotropic p0, axial strain with radial strain -nu times it keeps sigma_r = p0 while
// elastic, so p = p0 + q / 3. The Mohr-Coulomb surface in triaxial compression is
//   q = 6 sin(phi) / (3 - sin(phi)) p + 6 c cos(phi) / (3 - sin(phi))
// (Coulomb's sigma_1 - sigma_3 = (sigma_1 + sigma_3) sin(phi) + 2 c cos(phi) with sigma_1 = p + 2 q / 3,
// sigma_3 = p - q / 3: the slope M = 6 sin(phi) / (3 - sin(phi)) of critical-state texts), which the path
// (sigma_3 = p0, q = sigma_1 - p0) meets at q_f = 2 (p0 sin(phi) + c cos(phi)) / (1 - sin(phi)). The update stays elastic up to
// q_f, and every later state lies on that line, on the triaxial compression edge (sigma_r equal).
TEST(MohrCoulomb3D, TriaxialCompressionReachesClosedFormDeviator) {
  mpm::MaterialSpec spec = mc_spec();
  spec.softening = false;
  spec.tension_cutoff = 1e30;  // none (clamped at the apex)
  const MohrCoulomb3D m = MohrCoulomb3D::from(spec);
  const double phi = spec.friction, c = spec.cohesion, sp = std::sin(phi), E = spec.youngs_modulus;
  const double nu = spec.poisson_ratio, p0 = 5e4;
  const double qf = 2 * (p0 * sp + c * std::cos(phi)) / (1 - sp);
  const auto failure_q = [&](double p) { return (6 * sp * p + 6 * c * std::cos(phi)) / (3 - sp); };
  double s[6] = {-p0, -p0, -p0, 0, 0, 0}, sv[7];
  m.initial_state(sv);
  const int n = 50;
  const double dea = -qf / (E * n);  // axial (z) strain increment that brings q to q_f in n steps
  const double de[6] = {-nu * dea, -nu * dea, dea, 0, 0, 0};
  for (int step = 0; step < n; ++step) m.update(s, de, sv);
  EXPECT_EQ(sv[6], 0.0);  // elastic up to q_f (within round-off of the surface)
  const double q_at_yield = s[0] - s[2], p_at_yield = -(s[0] + s[1] + s[2]) / 3;
  EXPECT_CLOSE(q_at_yield, qf, 1e-9 * p0, 1e-9);
  EXPECT_CLOSE(p_at_yield, p0 + qf / 3, 1e-9 * p0, 1e-9);
  EXPECT_CLOSE(q_at_yield, failure_q(p_at_yield), 1e-9 * p0, 1e-9);
  for (int step = 0; step < 100; ++step) {
    m.update(s, de, sv);
    const double q = s[0] - s[2], p = -(s[0] + s[1] + s[2]) / 3;
    ASSERT_CLOSE(s[0], s[1], 1e-9 * p0, 0) << "step " << step;  // the triaxial compression edge
    ASSERT_CLOSE(q, failure_q(p), 1e-9 * p0, 1e-10) << "step " << step;
  }
  EXPECT_GT(sv[6], 0.0);
}

// Objectivity: rotate the stress and the strain increment, update, rotate back: the same stress and state
// to round-off, for random states (elastic, face, edges, apex, tension cutoff), at peak and softened strength.
TEST(MohrCoulomb3D, InvariantUnderRotationOfAxes) {
  const MohrCoulomb3D m = MohrCoulomb3D::from(mc_spec());
  std::mt19937_64 rng(37);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int plastic = 0;
  for (int k = 0; k < 2000; ++k) {
    double s[6], de[6], sv[7];
    const double p = -1e4 * (1.0 + unit(rng));
    for (int i = 0; i < 3; ++i) s[i] = p + 5e3 * unit(rng);
    for (int i = 3; i < 6; ++i) s[i] = 3e3 * unit(rng);
    const double scale = std::pow(10.0, -5.0 + 2.0 * unit(rng));
    for (double& d : de) d = scale * unit(rng);
    m.initial_state(sv);
    if (k % 3 == 1) sv[6] = 0.02 + 0.04 * (0.5 + 0.5 * unit(rng));  // softened (or residual) strength
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(3.0 * unit(rng), Eigen::Vector3d(unit(rng), unit(rng), unit(rng)).normalized())
            .toRotationMatrix();
    double sr[6], der[6], svr[7];
    rotate(r, s, 1.0, sr);
    rotate(r, de, 0.5, der);
    std::copy(sv, sv + 7, svr);
    m.update(s, de, sv);
    m.update(sr, der, svr);
    double back[6];
    rotate(r.transpose(), sr, 1.0, back);
    const double tol = 1e-9 * std::max({std::abs(s[0]), std::abs(s[1]), std::abs(s[2]), 1e3});
    for (int i = 0; i < 6; ++i) ASSERT_CLOSE(back[i], s[i], tol, 1e-9) << "case " << k << " stress " << i;
    for (int i : {0, 1, 2}) ASSERT_EQ(svr[i], sv[i]) << "case " << k;  // the same softening
    ASSERT_CLOSE(svr[6], sv[6], 1e-15, 1e-8) << "case " << k;
    if (sv[6] > 0 && k % 3 != 1) ++plastic;
  }
  EXPECT_GT(plastic, 200);
}

// Cohesionless (c = 0): the apex is the origin and the cutoff is clamped there, so any trial in tension
// returns to zero stress (hydrostatic: the apex; with shear: the tension corner), with a plastic strain;
// a compressive trial outside the pyramid returns onto it with no principal stress in tension.
TEST(MohrCoulomb3D, CohesionlessApexAndTensionReturn) {
  mpm::MaterialSpec spec = mc_spec();
  spec.cohesion = spec.residual_cohesion = 0;
  spec.tension_cutoff = 0;
  spec.softening = false;
  const MohrCoulomb3D m = MohrCoulomb3D::from(spec);
  const double scale = 1e4;
  {
    double s[6] = {-1e3, -1e3, -1e3, 0, 0, 0}, sv[7];
    m.initial_state(sv);
    const double de[6] = {1e-3, 1e-3, 1e-3, 0, 0, 0};  // hydrostatic extension
    m.update(s, de, sv);
    for (double v : s) EXPECT_CLOSE(v, 0.0, 1e-9 * scale, 0);
  }
  {
    double s[6] = {-1e3, -2e3, -1.5e3, 3e2, -2e2, 1e2}, sv[7];
    m.initial_state(sv);
    const double de[6] = {2e-3, 1e-3, 1.5e-3, 1e-3, -2e-3, 5e-4};  // extension with shear
    m.update(s, de, sv);
    for (double v : s) EXPECT_CLOSE(v, 0.0, 1e-9 * scale, 0);
    EXPECT_GT(sv[6], 0.0);
  }
  {
    double s[6] = {-1e4, -1e4, -1e4, 0, 0, 0}, sv[7];
    m.initial_state(sv);
    const double de[6] = {2e-3, -1e-3, 0, 3e-3, 1e-3, -2e-3};  // shear beyond the pyramid
    m.update(s, de, sv);
    EXPECT_GT(sv[6], 0.0);
    const constitutive::MohrCoulombStrength st{spec.friction, spec.dilation, 0.0, 0.0};
    const constitutive::Stress6 out = Eigen::Map<const constitutive::Stress6>(s);
    EXPECT_CLOSE(constitutive::mohr_coulomb_yield_3d(out, st), 0.0, 1e-9 * scale, 0);
    EXPECT_LE(constitutive::principal_stresses(out).sorted[0], 1e-9 * scale);
  }
}

TEST(MohrCoulomb3D, SeparationAsThePlaneStrainMaterial) {
  const MohrCoulomb3D m3 = MohrCoulomb3D::from(mc_spec());
  const MohrCoulomb m2 = MohrCoulomb::from(mc_spec());
  // density 2000, separation_volume_ratio 3: below 2000 / 3 kg/m3 a particle carries no stress.
  EXPECT_FALSE(m3.separated(1.0, 1.0 / 700.0));
  EXPECT_TRUE(m3.separated(1.0, 1.0 / 600.0));
  for (double v : {1e-4, 1.0 / 667.0, 1.0 / 666.0, 1e-2}) EXPECT_EQ(m3.separated(1.0, v), m2.separated(1.0, v));
  EXPECT_FALSE(LinearElastic3D::separated(1.0, 1e3));
}

TEST(MohrCoulomb3D, InvariantsOfAFullStress) {
  double sv[7] = {};
  const double s[6] = {-3e4, -1e4, -2e4, 0, 0, 0};
  MohrCoulomb3D::set_invariants(s, sv);
  double sv2[7] = {};
  const double s2[4] = {-3e4, -1e4, -2e4, 0};
  MohrCoulomb::set_invariants(s2, sv2);
  for (int i = 3; i < 6; ++i) EXPECT_EQ(sv[i], sv2[i]);
}

}  // namespace
