// PressureDependMultiYield02 (fem_tcl/materials/pressure_depend_multi_yield02.hpp) in drained plane-strain simple
// shear: the normal stresses sxx and syy held at their K0-consolidation values (mixed control, Newton on exx and
// eyy) while gxy is driven. What the model is built to give (Elgamal, Yang, Parra &
// Ragheb 2003, Int. J. Plasticity 19:883-905; Yang, Elgamal & Parra 2003, J. Geotech.
// Geoenviron. Eng. 129(12):1119-1127; the OpenSees manual, "PressureDependMultiYield02 Material"):
// - the failure surface is the Drucker-Prager cone of frictionAng (Elgamal et al. 2003, eq. 1, with
//   M_f = 6 sin(phi) / (3 - sin(phi))): under monotonic drained shear the stress ratio sqrt(3/2 s:s) / (p' + p_r)
//   rises to M_f and never passes it;
// - below the phase transformation stress ratio eta_PT = 6 sin(PTAng) / (3 - sin(PTAng)) the soil contracts,
//   above it (loading) it dilates: the plastic volumetric strain is least where the stress ratio is eta_PT;
// - cyclic drained shear below the phase transformation densifies the soil cycle after cycle.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <iostream>
#include <vector>

#include "fem_tcl/materials/pressure_depend_multi_yield02.hpp"
#include "support/tolerance.hpp"

namespace {

using fem::materials::PressureDependMultiYield02;
using fem::materials::PressureDependMultiYield02Parameters;
using fem::materials::Vector3;

constexpr double kPi = 3.14159265358979;

double compression_ratio(double phi_deg) {
  const double s = std::sin(phi_deg * kPi / 180.0);
  return 6.0 * s / (3.0 - s);
}

// The medium sand of the golden run (tests/data/reference_runs/opensees/up_dss_pdmy02/model.tcl).
PressureDependMultiYield02Parameters sand() {
  PressureDependMultiYield02Parameters p;
  p.density = 1.8;
  p.shear_modulus = 6.0e4;
  p.bulk_modulus = 1.6e5;
  p.friction_deg = 31.0;
  p.peak_shear_strain = 0.1;
  p.ref_pressure = 101.0;
  p.pressure_exponent = 0.5;
  p.pt_deg = 26.0;
  p.contraction1 = 0.067;
  p.contraction3 = 0.23;
  p.dilation1 = 0.06;
  p.dilation3 = 0.27;
  p.void_ratio = 0.68;
  return p;
}

/// Drives one point in drained simple shear: sxx and syy held, gxy prescribed, committed step by step.
class DrainedShear {
 public:
  explicit DrainedShear(const PressureDependMultiYield02Parameters& p) : material_(1, p) {
    // K0 consolidation in stage 0 to syy = -80 kPa (exx = 0), then the plastic stage.
    const double D = p.bulk_modulus + 4.0 * p.shear_modulus / 3.0;
    strain_ = Vector3(0.0, -80.0 / D, 0.0);
    material_.set_trial_strain(strain_);
    material_.commit_state();
    target_ = material_.stress().head<2>();
    material_.update_stage(1);
  }

  /// One step to shear strain gamma; returns false when Newton on (exx, eyy) does not converge. The Jacobian is
  /// taken by differences: OpenSees' tangent leaves out the non-associated volumetric flow.
  bool shear_to(double gamma) {
    Vector3 e(strain_[0], strain_[1], gamma);
    const auto residual = [&](const Vector3& trial) -> Eigen::Vector2d {
      material_.set_trial_strain(trial);
      return material_.stress().head<2>() - target_;
    };
    for (int it = 0; it < 30; ++it) {
      const Eigen::Vector2d r = residual(e);
      if (r.norm() < 1e-8) {
        material_.commit_state();
        strain_ = e;
        return true;
      }
      Eigen::Matrix2d J;
      for (int k = 0; k < 2; ++k) {
        Vector3 ek = e;
        ek[k] += 1e-9;
        J.col(k) = (residual(ek) - r) / 1e-9;
      }
      e.head<2>() -= J.inverse() * r;
    }
    return false;
  }

  double volumetric_strain() const { return strain_[0] + strain_[1]; }
  /// sqrt(3/2 s:s) / (|p'| + p_r): the stress ratio of the cone (the response's last column times M_f).
  double stress_ratio() const {
    const auto s = material_.stress_3d();
    const double p = (s[0] + s[1] + s[2]) / 3.0;
    const double j2 = 0.5 * ((s[0] - p) * (s[0] - p) + (s[1] - p) * (s[1] - p) + (s[2] - p) * (s[2] - p)) + s[3] * s[3];
    return std::sqrt(3.0 * j2) / (std::abs(p) + material_.residual_pressure());
  }
  double shear_stress() const { return material_.stress()[2]; }
  /// p' = (sxx + syy + szz) / 3, tension positive.
  double mean_effective_stress() const { return material_.stress_3d().head<3>().mean(); }
  PressureDependMultiYield02& material() { return material_; }

 private:
  PressureDependMultiYield02 material_;
  Vector3 strain_;
  Eigen::Vector2d target_;
};

TEST(PressureDependMultiYield02Drained, MonotonicShearReachesTheFrictionCone) {
  const auto p = sand();
  DrainedShear test(p);
  const double m_f = compression_ratio(p.friction_deg);
  double largest = 0.0;
  for (int step = 1; step <= 2000; ++step) {
    ASSERT_TRUE(test.shear_to(step * 5e-5)) << "step " << step;  // to gamma = 10 %
    largest = std::max(largest, test.stress_ratio());
  }
  // The cone is reached (to 0.5 %) and never passed (beyond round-off).
  EXPECT_CLOSE(test.stress_ratio(), m_f, 0.0, 5e-3);
  EXPECT_LE(largest, m_f * (1.0 + 1e-9));
  const auto response = *test.material().response("stress");
  EXPECT_CLOSE(response[4], test.stress_ratio() / m_f, 1e-12, 1e-12);
}

// The plastic volumetric strain: the total less the elastic part, d eps_v^e = dp' / B(p') with
// B = B_r ((p' + p_r) / (p_ref + p_r))^d, integrated step by step at the step's mean p'.
TEST(PressureDependMultiYield02Drained, ContractsBelowThePhaseTransformationAndDilatesAbove) {
  const auto p = sand();
  DrainedShear test(p);
  const double eta_pt = compression_ratio(p.pt_deg), m_f = compression_ratio(p.friction_deg);
  const double pr = test.material().residual_pressure();
  const auto bulk = [&](double confinement) {  // B at p' (compression positive)
    return p.bulk_modulus * std::pow((confinement + pr) / (p.ref_pressure + pr), p.pressure_exponent);
  };
  double volume = test.volumetric_strain(), mean = test.mean_effective_stress();
  double plastic = 0.0, least = 0.0, ratio_at_least = 0.0;
  for (int step = 1; step <= 2000; ++step) {
    ASSERT_TRUE(test.shear_to(step * 5e-5)) << "step " << step;  // to gamma = 10 %
    const double v = test.volumetric_strain(), m = test.mean_effective_stress();
    plastic += (v - volume) - (m - mean) / bulk(-0.5 * (m + mean));  // tension positive; p' = -mean
    volume = v;
    mean = m;
    if (plastic < least) {
      least = plastic;
      ratio_at_least = test.stress_ratio();
    }
  }
  // Contraction first (compression negative), then dilation past the start.
  EXPECT_LT(least, -5e-6);
  EXPECT_GT(plastic, least + 5e-4);
  // The turn from contraction to dilation sits at the phase-transformation ratio (to 0.5 %; the cone M_f is 1.244,
  // eta_PT 1.027, so the check tells them apart).
  std::cout << "least plastic volumetric strain " << least << " at stress ratio " << ratio_at_least << " (eta_PT "
            << eta_pt << "), " << plastic << " at 10 % shear\n";
  EXPECT_CLOSE(ratio_at_least, eta_pt, 0.0, 0.005);
  EXPECT_GT(std::abs(ratio_at_least - m_f), 0.1);
}

TEST(PressureDependMultiYield02Drained, CyclicShearBelowThePhaseTransformationDensifies) {
  const auto p = sand();
  DrainedShear test(p);
  const double amplitude = 2e-4;  // a shear stress well below the phase transformation
  const int per_quarter = 20;
  std::vector<double> end_of_cycle;
  double largest_ratio = 0.0;
  for (int cycle = 0; cycle < 6; ++cycle) {
    for (int i = 1; i <= 4 * per_quarter; ++i) {
      const double phase = 2.0 * kPi * i / (4.0 * per_quarter);
      ASSERT_TRUE(test.shear_to(amplitude * std::sin(phase))) << "cycle " << cycle << " step " << i;
      largest_ratio = std::max(largest_ratio, test.stress_ratio());
    }
    end_of_cycle.push_back(test.volumetric_strain());
  }
  EXPECT_LT(largest_ratio, compression_ratio(p.pt_deg));
  // Each cycle adds contraction (the volumetric strain, compression negative, keeps falling) ...
  for (std::size_t c = 1; c < end_of_cycle.size(); ++c) {
    EXPECT_LT(end_of_cycle[c], end_of_cycle[c - 1] - 1e-7) << "cycle " << c;
  }
  // ... and the later cycles add no more than the second (the sixth about two thirds of it in this run).
  for (std::size_t c = 1; c < end_of_cycle.size(); ++c) std::cout << "cycle " << c + 1 << ": " << end_of_cycle[c] - end_of_cycle[c - 1] << "\n";
  const double first = end_of_cycle[1] - end_of_cycle[0];
  const double last = end_of_cycle[5] - end_of_cycle[4];
  EXPECT_LE(std::abs(last), std::abs(first) * (1.0 + 1e-6));
}

}  // namespace
