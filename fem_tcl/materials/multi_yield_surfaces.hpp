#pragma once
// The multi-yield-surface mechanism shared by OpenSees' PressureIndependMultiYield and PressureDependMultiYield02
// (fem_tcl/materials/pressure_independ_multi_yield.hpp, pressure_depend_multi_yield02.hpp): nested yield surfaces
// in deviatoric stress space (Prevost 1985, Soil Dyn. Earthquake Eng. 4(1):9-17; Elgamal, Yang, Parra & Ragheb
// 2003, Int. J. Plasticity 19:883-905, eq. 1; Yang, Elgamal & Parra 2003, J. Geotech. Geoenviron. Eng.
// 129(12):1119-1127),
//
//   f_m = 3/2 (s - h a_m) : (s - h a_m) - (h M_m)^2 = 0,       m = 1 .. n,
//
// each with a plastic shear modulus H_m, where h is the cone height: 1 for the pressure-independent model (its
// centres a_m and sizes M_m are stresses), p_r - p for the pressure-dependent one (a_m and M_m are stress ratios
// of a Drucker-Prager cone with its apex at the residual pressure p_r; tension positive, p < 0 in compression).
// What is here, as OpenSees implements it:
//   - the surfaces of a hyperbolic backbone or of user (shear strain, G / Gmax) points (setUpSurfaces);
//   - the search for the active surface at the switch to plasticity and the re-centring on the stress
//     (elast2Plast, initSurfaceUpdate);
//   - the number of sub-increments of a strain increment (setSubStrainRate), the sub-incremented update loop
//     (getStress), the stress correction onto the active surface with the crossing into the next one
//     (stressCorrection, its recursion), the scaling onto a surface (deviatorScaling), Mroz's (1967, J. Mech.
//     Phys. Solids 15:163-175) translation of the active surface (updateActiveSurface) and the
//     re-centring of the inner surfaces at a load reversal (updateInnerSurface).
// The flow rule (the plastic correction from the contact point) and the elastic predictor are the models' own.
//
// Tensors are 6-vectors (xx yy zz xy yz xz) with tensor (not engineering) shear; a : b counts the shear twice.
#include <cmath>
#include <string>
#include <vector>

#include "fem_tcl/materials/nd_material.hpp"

namespace fem::materials::multi_yield {

inline constexpr double kLowLimit = 1e-15;  ///< OpenSees' LOW_LIMIT
inline constexpr double kUpLimit = 1e30;    ///< OpenSees' UP_LIMIT: the plastic modulus of a surface that adds no strain
inline constexpr double kPi = 3.14159265358979;  ///< the value of pi these materials have in OpenSees
inline constexpr double kDegree = kPi / 180.0;

// --- tensor helpers on (xx yy zz xy yz xz) ----------------------------------------------------------------
/// a : b of two symmetric tensors (OpenSees' operator &&).
inline double contract(const Vector6& a, const Vector6& b) {
  return a.head<3>().dot(b.head<3>()) + 2.0 * a.tail<3>().dot(b.tail<3>());
}
inline double mean(const Vector6& t) { return (t[0] + t[1] + t[2]) / 3.0; }
inline Vector6 deviator(const Vector6& t) {
  Vector6 d = t;
  d.head<3>().array() -= mean(t);
  return d;
}
/// The von Mises measure sqrt(3/2 t : t) of a deviatoric tensor.
inline double mises(const Vector6& dev) { return std::sqrt(1.5 * contract(dev, dev)); }
/// The tensor of deviator `dev` (made deviatoric) and mean `p`.
inline Vector6 with_mean(const Vector6& dev, double p) {
  Vector6 t = deviator(dev);
  t.head<3>().array() += p;
  return t;
}
/// Engineering plane strain (exx eyy gxy) -> tensor (xx yy zz xy yz xz).
inline Vector6 strain_tensor(const Vector3& e) {
  Vector6 t = Vector6::Zero();
  t << e[0], e[1], 0.0, 0.5 * e[2], 0.0, 0.0;
  return t;
}
/// The smallest non-negative root of A x^2 + B x + C = 0 (OpenSees' secondOrderEqn); throws
/// common::NumericalError naming `what` when there is none.
double smallest_nonnegative_root(double A, double B, double C, const char* what);

// --- the surfaces --------------------------------------------------------------------------------------------
/// One yield surface: centre a (deviatoric, xx yy zz xy yz xz), size M (in sqrt(3/2 s:s)), plastic shear
/// modulus H; a and M are multiplied by the cone height h where the surface is used.
struct YieldSurface {
  Vector6 center = Vector6::Zero();
  double size = 0;
  double modulus = 0;
};

/// The cone height h of a mean stress p: 1 (pressure independent), or p_r - p (pressure dependent).
struct Cone {
  bool pressure_dependent = false;
  double residual_pressure = 0;  ///< p_r (> 0)
  double height(double p) const { return pressure_dependent ? residual_pressure - p : 1.0; }
};

/// A deviatoric trial stress and its mean (the mean is unused by a pressure-independent model).
struct StressPoint {
  Vector6 dev = Vector6::Zero();
  double mean = 0;
};

/// OpenSees' hyperbolic backbone tau = G g / (1 + g / g_r) in octahedral measures, with g_r such that it
/// reaches the peak octahedral strength tau_f at the octahedral shear strain g_max (OpenSees setUpSurfaces; the
/// OpenSees manual, "PressureDependMultiYield02 Material", peakShearStra).
struct HyperbolicBackbone {
  double shear_modulus = 0;
  double ref_strain = 0;  ///< g_r = g_max tau_f / (G g_max - tau_f)
  /// Throws common::InputError (`where`) unless G g_max > tau_f.
  HyperbolicBackbone(double G, double peak_strength, double peak_strain, const std::string& where);
  /// The octahedral shear strain at octahedral stress tau.
  double strain(double tau) const { return tau * ref_strain / (shear_modulus * ref_strain - tau); }
};

/// OpenSees' plastic modulus of a backbone segment of elasto-plastic modulus 2 d tau / d gamma = Hep:
/// H = 2 G Hep / (2 G - Hep), kUpLimit where Hep >= 2 G, clamped to [0, kUpLimit].
double plastic_modulus(double G, double elasto_plastic);

/// n surfaces at octahedral stresses m tau_f / n of the hyperbola (sizes 3 tau / sqrt(2) / cone), the last one
/// (failure) with H = 0 (setUpSurfaces, automatic branch). Index 0 is unused, as OpenSees'.
std::vector<YieldSurface> hyperbolic_surfaces(const HyperbolicBackbone& backbone, double peak_strength, int n,
                                              double cone);

/// Throws common::InputError (`where`) unless the user points (gamma_i, G_i / Gmax) have positive, increasing
/// shear strains and stresses G (G_i / Gmax) gamma_i.
void validate_user_points(const std::vector<double>& points, const std::string& where);
/// The surfaces of user points (gamma_i, G_i / Gmax), i = 1 .. n, at shear stresses tau_i = G (G_i/Gmax) gamma_i
/// (sizes sqrt(3) tau_i / cone): validated (common::InputError naming `where`) to have positive, increasing shear
/// strains and stresses and positive plastic moduli.
std::vector<YieldSurface> user_surfaces(double G, const std::vector<double>& points, double cone,
                                        const std::string& where);

/// The two versions of OpenSees' updateActiveSurface.
enum class Translation {
  /// PressureIndependMultiYield: a stress outside the next surface is an error; a motion with |B| and |C| below
  /// 1e-10 is skipped.
  Strict,
  /// PressureDependMultiYield02: a stress outside the next surface leaves the active surface where it is; no
  /// 1e-10 skip.
  Lenient,
};

/// The nested surfaces of one integration point and its active surface (0: inside the first).
class MultiYieldSurfaces {
 public:
  MultiYieldSurfaces() = default;
  MultiYieldSurfaces(std::vector<YieldSurface> surfaces, Translation translation)
      : surfaces_(std::move(surfaces)), translation_(translation) {}

  /// 1-based as OpenSees' (index 0 unused).
  const std::vector<YieldSurface>& surfaces() const { return surfaces_; }
  std::vector<YieldSurface>& surfaces() { return surfaces_; }
  const YieldSurface& operator[](int m) const { return surfaces_[static_cast<std::size_t>(m)]; }
  YieldSurface& operator[](int m) { return surfaces_[static_cast<std::size_t>(m)]; }
  int count() const { return static_cast<int>(surfaces_.size()) - 1; }
  int active() const { return active_; }
  void set_active(int m) { active_ = m; }

  /// f_m at the deviator `dev` and cone height h: > 0 outside surface m (OpenSees yieldFunc).
  double yield_value(int m, const Vector6& dev, double h) const;
  /// Whether `dev` lies beyond the surface next to the active one (false on the failure surface).
  bool crosses_next(const Vector6& dev, double h) const;
  /// The point of the active surface on the ray from its centre through `dev` (OpenSees getContactStress).
  Vector6 contact_point(const Vector6& dev, double h) const;
  /// Brings `dev` onto surface k: from inside by scaling about the centre (k < n), onto the failure surface
  /// by scaling about the origin (OpenSees deviatorScaling).
  void scale_onto(Vector6& dev, int k, double h) const;

  /// The switch to plasticity (elast2Plast's search): the active surface is the outermost one `dev` lies
  /// beyond; beyond the failure surface `dev` is brought onto it and true returned. Call centre_on() next.
  bool place(Vector6& dev, double h);
  /// Surfaces 1..active (not the failure surface) centred on the ray from the origin through `dev`, so that
  /// `dev` lies on each (OpenSees initSurfaceUpdate).
  void centre_on(const Vector6& dev, double h);
  /// Load reversal: the inner surfaces 1..active-1 re-centred so they touch the active one at `dev` (Mroz;
  /// OpenSees updateInnerSurface). The caller then sets the active surface to 0.
  void recentre_inner(const Vector6& dev, double h);
  /// Mroz's translation of the active surface towards the conjugate point of the next one, by just as much
  /// that `dev` lies on it (OpenSees updateActiveSurface; Prevost 1985, the kinematic hardening rule).
  void translate_active(const Vector6& dev, double h);

  /// The number of sub-increments of a strain increment of deviator `de_dev` (OpenSees setSubStrainRate):
  /// about one surface spacing of stress each, at most n; G and the plastic moduli scaled by `modulus_factor`.
  int substeps(const Vector6& de_dev, double G, double modulus_factor, double h) const;

  /// The plastic correction of a trial stress (OpenSees stressCorrection and its recursion): `flow(trial,
  /// crossed)` returns the trial along the model's flow rule from its contact point on the active surface
  /// (`crossed`: the active surface was entered in this correction); then the deviator is scaled onto the
  /// active surface, and where it lies beyond the next surface that one becomes active and it repeats.
  template <class Flow>
  void correct(StressPoint& trial, const Cone& cone, Flow&& flow) {
    bool crossed = false;
    for (int guard = 0; guard <= count(); ++guard) {
      flow(trial, crossed);
      const double h = cone.height(trial.mean);
      scale_onto(trial.dev, active_, h);
      if (!crosses_next(trial.dev, h)) return;
      ++active_;
      crossed = true;
    }
  }

  /// The sub-incremented update (OpenSees getStress, stage 1): for each of `substeps` sub-increments,
  /// `predict(i, trial)` sets the elastic trial (and handles a load reversal); a trial beyond the next surface
  /// is corrected onto the active one (correct()) and the active surface translated; then `after(i, trial)`.
  template <class Predict, class Flow, class After>
  void integrate(int substeps, StressPoint& trial, const Cone& cone, Predict&& predict, Flow&& flow,
                 After&& after) {
    for (int i = 0; i < substeps; ++i) {
      predict(i, trial);
      if (active_ == 0 && !crosses_next(trial.dev, cone.height(trial.mean))) continue;
      if (active_ == 0) active_ = 1;
      correct(trial, cone, flow);
      translate_active(trial.dev, cone.height(trial.mean));
      after(i, trial);
    }
  }

 private:
  std::vector<YieldSurface> surfaces_;
  Translation translation_ = Translation::Strict;
  int active_ = 0;
};

}  // namespace fem::materials::multi_yield
