// Verification: drained triaxial compression and extension of the 3D Mohr-Coulomb return
// (constitutive/mohr_coulomb_3d.hpp), driven as the laboratory test is, in a frame rotated away from the
// coordinate axes (so every stress and strain component is non-zero): the cell pressure pc held on the two
// lateral axes (mixed control, lateral strain solved by secant iterations), the axial strain driven in steps.
//
// References
//   [CH]  Chen & Han (1988), Plasticity for Structural Engineers, Springer, ch. 2: Mohr-Coulomb with
//         Kp = (1 + sin phi) / (1 - sin phi): triaxial compression fails at s_a = Kp pc + 2 c sqrt(Kp) (axial
//         stress, compression positive), triaxial extension at s_a = pc / Kp - 2 c / sqrt(Kp).
//   [SPO] de Souza Neto, Peric & Owen (2008), Computational Methods for Plasticity, sec. 8.2: the flow on the
//         triaxial edges; at a stress plateau the strain increment is all plastic, so its dilatancy is the
//         flow rule's: compression d(e_v) / d(e_a) = -2 sin psi / (1 - sin psi), extension
//         d(e_v) / d(e_a) = 2 sin psi / (1 + sin psi) (tension positive).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "constitutive/mohr_coulomb_3d.hpp"
#include "support/tolerance.hpp"

namespace {

using constitutive::IsotropicElasticity;
using constitutive::MohrCoulombStrength;
using constitutive::Strain6;
using constitutive::Stress6;

constexpr double kDeg = M_PI / 180.0;

/// A symmetric strain tensor as (exx, eyy, ezz, gxy, gyz, gxz), engineering shears.
Strain6 engineering(const Eigen::Matrix3d& e) {
  Strain6 v;
  v << e(0, 0), e(1, 1), e(2, 2), 2 * e(0, 1), 2 * e(1, 2), 2 * e(0, 2);
  return v;
}

struct TriaxialResult {
  double axial_stress;      ///< local zz, Pa (tension positive)
  double lateral_error;     ///< largest |local xx or yy + pc| over the run, Pa
  double shear;             ///< largest local off-diagonal stress over the run, Pa
  double dilatancy;         ///< d(e_v) / d(e_a) over the last step
  double worst_yield;       ///< the largest main-plane yield value over the run, Pa
  constitutive::ReturnRegion region;
};

/// The test in the frame `r` (local axes = its columns; local z the axial direction): from the
/// hydrostatic -pc, `steps` axial strain increments `dez`, the lateral local stresses held at -pc.
TriaxialResult triaxial(const IsotropicElasticity& el, const MohrCoulombStrength& st, double pc, double dez, int steps,
                        const Eigen::Matrix3d& r) {
  const constitutive::MohrCoulombReturnMap map(el, constitutive::MohrCoulombSurface(st));
  Stress6 s;
  {
    const Eigen::Matrix3d m = -pc * Eigen::Matrix3d::Identity();
    s << m(0, 0), m(1, 1), m(2, 2), 0, 0, 0;
  }
  const double lateral_stiffness = 2 * (el.bulk_modulus + el.shear_modulus / 3.0);  // d(s_xx)/d(e) for exx = eyy = e
  TriaxialResult out{};
  double d = 0.0, dv = 0.0;
  for (int k = 0; k < steps; ++k) {
    // Secant iterations on the lateral strain increment d (exx = eyy = d by symmetry).
    auto local_after = [&](double lateral, constitutive::MohrCoulombUpdate3D& up) {
      const Eigen::Matrix3d de_local = Eigen::Vector3d(lateral, lateral, dez).asDiagonal();
      const Strain6 de = engineering(r * de_local * r.transpose());
      up = constitutive::mohr_coulomb_return_3d(constitutive::elastic_trial_3d(s, de, el), map);
      return Eigen::Matrix3d(r.transpose() * constitutive::stress_tensor(up.stress) * r);
    };
    constitutive::MohrCoulombUpdate3D up{};
    double d0 = d, f0 = local_after(d0, up)(0, 0) + pc;
    double d1 = d0 - f0 / lateral_stiffness;
    Eigen::Matrix3d local = local_after(d1, up);
    for (int it = 0; it < 100 && std::abs(local(0, 0) + pc) > 1e-12 * pc; ++it) {
      const double f1 = local(0, 0) + pc;
      const double slope = (f1 - f0) / (d1 - d0);
      d0 = d1;
      f0 = f1;
      d1 -= f1 / (std::abs(slope) > 1e-6 * lateral_stiffness ? slope : lateral_stiffness);
      local = local_after(d1, up);
    }
    d = d1;
    dv = 2 * d + dez;
    s = up.stress;
    out.lateral_error = std::max({out.lateral_error, std::abs(local(0, 0) + pc), std::abs(local(1, 1) + pc)});
    out.shear = std::max({out.shear, std::abs(local(0, 1)), std::abs(local(1, 2)), std::abs(local(0, 2))});
    out.axial_stress = local(2, 2);
    out.region = up.region;
    const Eigen::Vector3d p = constitutive::principal_stresses(s).sorted;
    out.worst_yield = std::max(out.worst_yield, (p[0] - p[2]) + (p[0] + p[2]) * std::sin(st.friction) -
                                                    2 * st.cohesion * std::cos(st.friction));
  }
  out.dilatancy = dv / dez;
  return out;
}

const IsotropicElasticity kElastic = IsotropicElasticity::from_young_poisson(20e6, 0.3);
const Eigen::Matrix3d kFrame = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())).toRotationMatrix();

TEST(Triaxial3D, CompressionReachesChenAndHansLimitWithTheFlowRulesDilatancy) {
  for (const double c : {10e3, 0.0}) {
    const MohrCoulombStrength st{30 * kDeg, 10 * kDeg, c, std::numeric_limits<double>::infinity()};
    const double pc = 100e3, kp = (1 + std::sin(st.friction)) / (1 - std::sin(st.friction));
    const double limit = kp * pc + 2 * c * std::sqrt(kp);  // [CH], compression positive
    const TriaxialResult t = triaxial(kElastic, st, pc, -2e-4, 300, kFrame);  // 6 % axial strain
    std::printf("triaxial compression, c = %g kPa: axial %.6f kPa (limit %.6f), dilatancy %.9f (flow rule %.9f)\n",
                c / 1e3, -t.axial_stress / 1e3, limit / 1e3, t.dilatancy,
                -2 * std::sin(st.dilation) / (1 - std::sin(st.dilation)));
    EXPECT_EQ(t.region, constitutive::ReturnRegion::EdgeTriaxialCompression);
    EXPECT_CLOSE(-t.axial_stress, limit, 0.0, 1e-9);
    EXPECT_LT(t.lateral_error, 1e-9 * pc);
    EXPECT_LT(t.shear, 1e-8 * pc);
    EXPECT_LT(t.worst_yield, 1e-6 * pc);  // never outside the surface
    EXPECT_CLOSE(t.dilatancy, -2 * std::sin(st.dilation) / (1 - std::sin(st.dilation)), 1e-9, 1e-6);
  }
}

TEST(Triaxial3D, ExtensionReachesChenAndHansLimitWithTheFlowRulesDilatancy) {
  const MohrCoulombStrength st{30 * kDeg, 10 * kDeg, 10e3, std::numeric_limits<double>::infinity()};
  const double pc = 100e3, kp = (1 + std::sin(st.friction)) / (1 - std::sin(st.friction));
  const double limit = pc / kp - 2 * st.cohesion / std::sqrt(kp);  // [CH], compression positive
  const TriaxialResult t = triaxial(kElastic, st, pc, 2e-4, 300, kFrame);
  std::printf("triaxial extension: axial %.6f kPa (limit %.6f), dilatancy %.9f (flow rule %.9f)\n",
              -t.axial_stress / 1e3, limit / 1e3, t.dilatancy, 2 * std::sin(st.dilation) / (1 + std::sin(st.dilation)));
  EXPECT_EQ(t.region, constitutive::ReturnRegion::EdgeTriaxialExtension);
  EXPECT_CLOSE(-t.axial_stress, limit, 0.0, 1e-9);
  EXPECT_LT(t.lateral_error, 1e-9 * pc);
  EXPECT_LT(t.shear, 1e-8 * pc);
  EXPECT_LT(t.worst_yield, 1e-6 * pc);
  EXPECT_CLOSE(t.dilatancy, 2 * std::sin(st.dilation) / (1 + std::sin(st.dilation)), 1e-9, 1e-6);
}

}  // namespace
