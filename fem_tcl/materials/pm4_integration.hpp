#pragma once
// The explicit stress integration the PM4 models share: OpenSees' integrate(), elastic_integrator,
// explicit_integrator, ForwardEuler, ModifiedEuler, RungeKutta4, MaxStrainInc and Stress_Correction, which PM4Sand.cpp
// and PM4Silt.cpp (commit 2890cb36) carry as near-identical copies. The models differ in their elastic moduli and
// state-dependent surfaces (the hooks of pm4::Model) and in two details of the driver (pm4::Variant).
//
// Conventions as pm4_common.hpp: in-plane tensors (xx, yy, xy), compression positive, stress-like vectors store
// the tensor shear, strain-like ones the engineering shear.
#include "fem_tcl/materials/pm4_common.hpp"

namespace fem::materials::pm4 {

/// The history of one integration point (OpenSees' *_n members and their trial twins), compression positive.
struct History {
  Vector3 strain = Vector3::Zero();          ///< total, engineering shear
  Vector3 stress = Vector3::Zero();          ///< the model's stress (without stress_offset)
  Vector3 elastic_strain = Vector3::Zero();
  Vector3 alpha = Vector3::Zero();           ///< back-stress ratio
  Vector3 alpha_in = Vector3::Zero();        ///< apparent back-stress ratio at the last reversal
  Vector3 alpha_in_p = Vector3::Zero();      ///< its previous value
  Vector3 alpha_in_true = Vector3::Zero();   ///< the true back-stress ratio at the last reversal
  Vector3 alpha_in_max = Vector3::Zero();
  Vector3 alpha_in_min = Vector3::Zero();
  Vector3 fabric = Vector3::Zero();          ///< fabric-dilatancy tensor z
  Vector3 fabric_in = Vector3::Zero();       ///< z at the last reversal
  double void_ratio = 0;
  double z_cum = 0, z_peak = 0;              ///< cumulative and peak |z| (updated at commit)
  Vector3 stress_offset = Vector3::Zero();   ///< OpenSees' mSigma_b: reported stress = stress + offset
};

/// What OpenSees keeps in plain members between trials (never reset from a committed copy): a trial starts from
/// the last trial's values, as in OpenSees.
struct Carried {
  double K = 0, G = 0, Kp = 0, dgamma = 0;   ///< moduli, plastic modulus, plastic multiplier
  double Mb = 0, Md = 0, Mcur = 0;           ///< bounding, dilatancy and current stress ratios
  double p_zp = 0, z_xp = 0;                 ///< p and |z| p at the reversal of largest |z| p
  bool p_zp_unset = true;
  Matrix3 ce = Matrix3::Zero(), cep = Matrix3::Zero();  ///< elastic matrix; the one kept for TanType 1 / 2
};

struct State {
  History history;
  Carried carried;
};

/// The state-dependent quantities at one point (OpenSees GetStateDependent): the yield-surface normal n, the
/// plastic flow direction R = n + D / 3 I, the dilatancy image alpha_d, b = alpha_b - alpha, the dilatancy D,
/// the plastic modulus Kp and the hardening coefficient h.
struct Hardening {
  Vector3 n, R, alpha_d, b;
  double D = 0, Kp = 0, h = 0;
};

/// The explicit schemes (OpenSees' IntScheme).
enum class Scheme {
  ModifiedEuler = 1,              ///< modified Euler with error control over the whole step
  ForwardEuler = 2,               ///< one forward-Euler step
  RungeKutta4 = 3,                ///< two fixed halves of classical fourth-order Runge-Kutta
  ForwardEulerMaxStrain = 4,      ///< forward Euler on sub-increments of at most 1e-5 strain
  ModifiedEulerMaxStrain = 5,     ///< modified Euler on sub-increments of at most 1e-5 strain
};

/// What a PM4 model supplies to the integration. The hooks read and write the model's own trial state (the State
/// handed to integrate()), as OpenSees' member functions do.
class Model {
 public:
  /// The moduli of the elastic stage (stage 0) at the committed stress, before its update: PM4Sand recomputes
  /// them, PM4Silt keeps the carried ones (its elastic_integrator calls no GetElasticModuli).
  virtual void elastic_stage_moduli(const Vector3& committed_stress, double& K, double& G) = 0;
  /// The moduli of the plastic stage at `stress` (OpenSees' 5-argument GetElasticModuli); sets the carried
  /// current stress ratio Mcur.
  virtual void elastic_moduli(const Vector3& stress, double& K, double& G) = 0;
  /// OpenSees GetStateDependent at (stress, alpha, fabric) with shear modulus G at void ratio e; sets the
  /// carried Mb and Md.
  virtual Hardening state_dependent(const Vector3& stress, const Vector3& alpha, const Vector3& fabric, double G,
                                    double void_ratio) = 0;

 protected:
  ~Model() = default;
};

/// Where PM4Sand.cpp and PM4Silt.cpp differ in the driver itself (besides Model::elastic_stage_moduli).
struct Variant {
  /// PM4Sand: the plastic stage sets the void ratio of the trial strain before its elastic check; PM4Silt only
  /// inside the schemes (an elastic trial keeps the last value).
  bool void_ratio_before_elastic_check = true;
  /// PM4Silt: the first Runge-Kutta stage replaces a negative denominator Kp + 2G - K D n : r by
  /// Kp = -(2G - K D n : r) / 2, h = 3 Kp / (2 p b : n) (the carried Kp too); PM4Sand leaves it.
  bool rk4_floors_negative_denominator = false;
};

/// The model constants one trial reads.
struct Settings {
  Scheme scheme = Scheme::ModifiedEulerMaxStrain;
  double m = 0.01;      ///< yield-surface size
  double tol_f = 1e-8;  ///< yield-surface tolerance
  double cz = 0;        ///< fabric growth rate
  double z_max = 0;     ///< fabric limit
  double Mc = 0;        ///< critical-state stress ratio
  double p_min = 0;     ///< the smallest p the model uses
  double e_init = 0;    ///< void ratio at zero strain
  Variant variant;
};

/// e = e0 - (1 + e0) tr(strain) (compression positive).
inline double void_ratio_at(double e_init, const Vector3& strain) { return e_init - (1.0 + e_init) * trace(strain); }

/// One trial (OpenSees integrate()): `trial.history.strain` holds the new total strain, the rest of
/// `trial.history` the committed history, `trial.carried` what the last trial left. A loading reversal updates
/// the reversal memory (manual section 2, "Loading reversals"); then stage 0 is linear elastic and stage 1
/// the elastic predictor / yield-surface intersection / explicit scheme of OpenSees' explicit_integrator.
void integrate(Model& model, const Settings& settings, int stage, State& trial, const History& committed);

/// The shared part of OpenSees' commitState after the model's moduli and bounding-surface correction:
/// z_cum += |dz| / sqrt(2), z_peak = max(z_peak, |z| / sqrt(2)), the void ratio, the elastic matrix (and the
/// elasto-plastic one OpenSees builds from zero vectors: the elastic matrix).
void commit_history(const Settings& settings, State& trial, const History& committed);

}  // namespace fem::materials::pm4
