#pragma once
// What PM4Sand (pm4sand.hpp) and PM4Silt (pm4silt.hpp) share as NDMaterials: OpenSees' state protocol (trial /
// commit / revert / revert-to-start over the shared integration of pm4_integration.hpp), the stages, the
// setParameter names and responses both OpenSees classes (PM4Sand.cpp, PM4Silt.cpp, commit 2890cb36) answer, the
// published stress and tangent, the common keys of `print -JSON`, and the steps of initialize(stress) that both
// take. Each model supplies its parameters, elastic moduli, state-dependent surfaces (the pm4::Model hooks) and
// its own initialisation, commands and keys (the hooks below); what is OpenSees' own quirk is cited in the model
// files.
//
// Conventions as pm4_common.hpp: inside, compression positive; at this interface strain (exx eyy gxy) and stress
// (sxx syy sxy), tension positive.
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/command_args.hpp"
#include "fem_tcl/materials/nd_material.hpp"
#include "fem_tcl/materials/pm4_integration.hpp"

namespace fem::materials::pm4 {

/// The value of pi OpenSees' PM4Sand.cpp and PM4Silt.cpp use (phi_cv -> M = 2 sin(phi_cv) and back).
constexpr double kPi = 3.14159265359;

/// The shared part of a PM4 model as an NDMaterial. `Parameters` is the model's parameter struct
/// (PM4SandParameters, PM4SiltParameters): the members named alike in both (G0, density, P_atm, nu, h0, nd, Ado,
/// z_max, cz, ce, phi_cv, Cgd, Ckaf, m, scheme, tangent_type, tol_f, tol_r) are read here. Defined in
/// pm4_material.cpp and instantiated there for the two models.
template <class Parameters>
class Material : public NDMaterial, protected Model {
 public:
  std::string type_name() const override { return type_; }
  /// Plane strain only: the PM4 models are 2D and OpenSees gives no plane-stress copy (common::InputError). The
  /// copy (OpenSees getCopy) is the model's fresh_copy() with its parent's stage (OpenSees' stage flag is one
  /// static variable shared by every material of the class).
  std::unique_ptr<NDMaterial> copy_for(PlaneType plane) const override;

  void set_trial_strain(const Vector3& strain) override;
  const Vector3& strain() const override { return strain_; }
  const Vector3& stress() const override { return stress_; }
  const Matrix3& tangent() const override { return tangent_; }
  /// OpenSees' getInitialTangent: the current elastic matrix (state dependent in stage 1).
  Matrix3 initial_tangent() const override { return trial_.carried.ce; }
  /// OpenSees commitState: the moduli at the new stress; in stage 1 a stress ratio beyond Mb scaled back onto the
  /// bounding surface (alpha onto its image) where the model does it (corrects_at_commit); then
  /// pm4::commit_history (z_cum, z_peak, the void ratio, the elastic matrix).
  void commit_state() override;
  /// The whole committed state, the carried members included (OpenSees' revertToLastCommit does nothing; its next
  /// trial restarts from the committed history anyway).
  void revert_to_last_commit() override;
  /// OpenSees' revertToStart: the model re-initialised from the current trial stress (stress and strain kept).
  void revert_to_start() override;

  double density() const override { return params_.density; }
  /// (sxx, syy, szz, sxy, 0, 0): the model has no out-of-plane stress; szz is reported as its 2D mean stress
  /// (sxx + syy) / 2, so that the tensor's mean stress is the model's p.
  Vector6 stress_3d() const override;

  /// The names both OpenSees classes take (setParameter): updateMaterialStage / materialState, FirstCall (the
  /// model re-initialised from the committed stress), PostShake (post-shaking reconsolidation on),
  /// IntegrationScheme, refShearModulus / ShearModulus, poissonRatio (0.5 is 0.4999, as OpenSees'
  /// GetElasticModuli), voidRatio (e0 such that the current volumetric strain gives e = value); then the model's
  /// own (set_model_parameter); false for any other name.
  bool set_parameter(std::string_view name, double value) override;
  /// 0 = elastic, 1 = plastic; any other stage throws common::InputError.
  bool update_stage(int stage) override;
  /// OpenSees' responses: stress(es) (3), strain(s) (3), state (16: elastic strain, alpha, fabric, alpha_in, e,
  /// the plastic multiplier, G, Kp; compression positive), alpha / backstressratio, fabric, alpha_in / alphain (the
  /// committed ones), tracker(s) (3 each); and stress3D / fullStress (6).
  std::optional<std::vector<double>> response(std::string_view name) const override;
  /// The keys both models print under the same name (OpenSees' argument names), then the model's (add_json).
  nlohmann::json to_json() const override;

  /// The parameters in force (defaults resolved; those derived at the first initialisation once initialised).
  const Parameters& parameters() const { return params_; }
  /// M = 2 sin(phi_cv), the critical-state stress ratio q / p with q = 2 sqrt(((sxx - syy)/2)^2 + sxy^2).
  double critical_stress_ratio() const { return Mc_; }
  int stage() const { return stage_; }

 protected:
  /// `type` is OpenSees' class name (messages, JSON); `shear_modulus_name` the model's name of G0 in messages;
  /// `params` resolved. Sets M and p_min = P_atm / 200; the model's constructor then calls start().
  Material(int tag, const char* type, const char* shear_modulus_name, const Parameters& params, Variant variant);

  // --- the model's hooks (besides pm4::Model's) -------------------------------------------------------------
  /// OpenSees' initialize(stress) (FirstCall, reset, revertToStart); built from the steps below.
  virtual void initialize(const Vector3& stress) = 0;
  /// A new material from the current parameters in the start state (OpenSees getCopy).
  virtual std::unique_ptr<Material> fresh_copy() const = 0;
  /// e0, the void ratio at zero strain, and its change by `voidRatio`.
  virtual double void_ratio_at_zero_strain() const = 0;
  virtual void set_void_ratio_at_zero_strain(double e0) = 0;
  /// Whether commit_state scales a stress ratio beyond Mb back onto the bounding surface at `stress` (stage 1).
  virtual bool corrects_at_commit(const Vector3& stress) const { (void)stress; return true; }
  /// The model's own setParameter names; false for a name it does not know.
  virtual bool set_model_parameter(std::string_view name, double value) { (void)name; (void)value; return false; }
  /// The `tracker` response.
  virtual Vector3 tracker() const { return Vector3::Zero(); }
  /// The state whose alpha, fabric, alpha_in and plastic multiplier `state` reports (OpenSees getState).
  virtual const State& state_reported() const { return committed_; }
  /// The model's own JSON keys (and those it names differently).
  virtual void add_json(nlohmann::json& entry) const = 0;

  // --- shared steps -----------------------------------------------------------------------------------------
  /// The constructor's start state: zero stress, void ratio e0, stage 0 moduli at p = P_atm (plain_moduli),
  /// Mb = Md = M (OpenSees leaves them unset until the first initialisation), z_peak = z_max / 1e5.
  void start(double e0);
  /// G = G0 P_atm (stage 0) or G0 P_atm sqrt(p / P_atm) (OpenSees' 3-argument GetElasticModuli), p not below
  /// p_min; K = 2 (1 + nu) / (3 (1 - 2 nu)) G.
  void plain_moduli(const Vector3& stress, double& K, double& G) const;
  /// The constants of one trial of the shared integration.
  Settings settings() const;
  /// The start of initialize(stress): the trial history reset to the committed one (an uncommitted trial is
  /// dropped); the stress `initial` with its mean stress p0 raised to `p_floor` if below (the difference kept as a
  /// stress offset, so the reported stress, hence the equilibrium, is unchanged); the back-stress ratio its stress
  /// ratio (0 when raised). Returns p0.
  double begin_initialization(const Vector3& initial, double p_floor);
  /// A stress ratio beyond the outer of the bounding and dilatancy surfaces (the carried Mb, Md) scaled onto it,
  /// the difference kept as stress offset, alpha onto the surface's image.
  void cap_initial_stress_ratio(const Vector3& initial, double p0);
  /// The end of initialize(stress): z_cum = 0, the moduli at the stress, Kp = 100 G, the reversal memory at alpha
  /// (alpha_in = `alpha_in`), the fabric cleared, z_peak = z_max / 1e5, p_zp = max(p0, p_min) / 100; committed.
  void finish_initialization(double p0, const Vector3& alpha_in);
  /// The message prefix: "nDMaterial <type> <tag>".
  std::string where() const { return std::string("nDMaterial ") + type_ + " " + std::to_string(tag()); }
  /// Throws common::InputError for `setParameter name` on this material.
  [[noreturn]] void parameter_error(std::string_view name, const std::string& what) const;

  Parameters params_;
  double Mc_ = 0;     ///< the critical-state stress ratio M
  double p_min_ = 0;  ///< the smallest p the model uses
  int stage_ = 0;
  bool post_shake_ = false;
  State committed_, trial_;

 private:
  void publish();

  const char* type_;                ///< OpenSees' class name
  const char* shear_modulus_name_;  ///< the model's name of G0 (messages)
  Variant variant_;
  Vector3 stress_ = Vector3::Zero(), strain_ = Vector3::Zero();  ///< tension positive, as reported
  Matrix3 tangent_ = Matrix3::Zero();
};

/// OpenSees' positional optional arguments (OPS_PM4SandMaterial and OPS_PM4SiltMaterial read them all as
/// doubles): as many as are given, in order, then the end of the command.
void read_optional_arguments(common::CommandArgs& args, std::span<const std::pair<const char*, double*>> optional);
/// IntScheme or TanType read as a double: -1 (the default) when negative, else a whole number (capped at 1e6 for
/// the model's check); a fraction is an error of the command.
int whole_argument(common::CommandArgs& args, double value, const char* what);
/// IntScheme and TanType (negative: 5 and 0) checked against 1..5 and 0..2; TolF and TolR (negative: the model's
/// defaults) checked > 0 (common::InputError, `where` first).
void resolve_integration_options(int& scheme, int& tangent_type, double& tol_f, double& tol_r, double default_tol_f,
                                 double default_tol_r, const std::string& where);

}  // namespace fem::materials::pm4
