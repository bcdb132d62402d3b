#include "fem_tcl/materials/pm4_material.hpp"

#include <algorithm>
#include <cmath>

#include "common/input_error.hpp"
#include "common/number_text.hpp"
#include "fem_tcl/materials/pm4sand.hpp"
#include "fem_tcl/materials/pm4silt.hpp"

// Moved from pm4sand.cpp and pm4silt.cpp, where the two copies were the same line for line (OpenSees' PM4Sand.cpp
// and PM4Silt.cpp of commit 2890cb36 carry them as near-identical copies too); the operations and their order are
// unchanged, so that both models' results stay bit-identical. Where the two OpenSees classes differ, the model
// supplies a hook (pm4_material.hpp) and cites the quirk.

namespace fem::materials::pm4 {

namespace {

std::string number_text(double v) { return common::number_text(v, 10); }

}  // namespace

// --- construction, copies -----------------------------------------------------------------------------------

// OpenSees' constructors: M = 2 sin(phi_cv), p_min = P_atm / 200.
template <class Parameters>
Material<Parameters>::Material(int tag, const char* type, const char* shear_modulus_name, const Parameters& params,
                               Variant variant)
    : NDMaterial(tag), params_(params), type_(type), shear_modulus_name_(shear_modulus_name), variant_(variant) {
  Mc_ = 2.0 * std::sin(params_.phi_cv / 180.0 * kPi);
  p_min_ = params_.P_atm / 200.0;
}

template <class Parameters>
void Material<Parameters>::start(double e0) {
  History& h = committed_.history;
  Carried& c = committed_.carried;
  h.void_ratio = e0;
  h.z_peak = params_.z_max / 100000.0;
  c.Mb = c.Md = Mc_;  // OpenSees leaves them unset until the first initialisation
  plain_moduli(Vector3(params_.P_atm, params_.P_atm, 0.0), c.K, c.G);
  c.ce = c.cep = elastic_stiffness(c.K, c.G);
  trial_ = committed_;
  publish();
}

template <class Parameters>
std::unique_ptr<NDMaterial> Material<Parameters>::copy_for(PlaneType plane) const {
  if (plane != PlaneType::PlaneStrain)
    throw common::InputError(where(), std::string(type_) + " is a plane-strain (2D) model: it has no plane-stress form");
  std::unique_ptr<Material> copy = fresh_copy();
  copy->stage_ = stage_;
  return copy;
}

template <class Parameters>
void Material<Parameters>::publish() {
  const History& t = trial_.history;
  stress_ = -(t.stress + t.stress_offset);
  strain_ = -t.strain;
  tangent_ = params_.tangent_type == 0 ? trial_.carried.ce : trial_.carried.cep;
}

template <class Parameters>
Vector6 Material<Parameters>::stress_3d() const {
  Vector6 s = Vector6::Zero();
  s << stress_[0], stress_[1], 0.5 * (stress_[0] + stress_[1]), stress_[2], 0.0, 0.0;
  return s;
}

template <class Parameters>
void Material<Parameters>::plain_moduli(const Vector3& stress, double& K, double& G) const {
  double pn = mean_stress(stress);
  if (pn <= p_min_) pn = p_min_;
  G = stage_ == 0 ? params_.G0 * params_.P_atm : params_.G0 * params_.P_atm * std::sqrt(pn / params_.P_atm);
  K = bulk_modulus(G, params_.nu);
}

// --- initialisation steps -------------------------------------------------------------------------------------

template <class Parameters>
double Material<Parameters>::begin_initialization(const Vector3& initial, double p_floor) {
  trial_.history = committed_.history;  // an uncommitted trial is dropped
  History& t = trial_.history;
  double p0 = mean_stress(initial);
  if (p0 < p_floor) {
    t.stress = p_floor * identity();
    t.stress_offset = initial - t.stress;
    p0 = p_floor;
    t.alpha.setZero();
  } else {
    t.stress = initial;
    t.stress_offset.setZero();
    t.alpha = deviator(initial) / p0;
  }
  return p0;
}

template <class Parameters>
void Material<Parameters>::cap_initial_stress_ratio(const Vector3& initial, double p0) {
  History& t = trial_.history;
  const Carried& c = trial_.carried;
  const double M_cut = std::max(c.Mb, c.Md);
  const double M_in = std::sqrt(2.0) * norm(deviator(t.stress)) / p0;
  if (M_in > M_cut) {
    const Vector3 r = (t.stress - p0 * identity()) / p0 * M_cut / M_in;
    t.stress = p0 * identity() + r * p0;
    t.stress_offset = initial - t.stress;
    t.alpha = r * (M_cut - params_.m) / M_cut;
  }
}

template <class Parameters>
void Material<Parameters>::finish_initialization(double p0, const Vector3& alpha_in) {
  History& t = trial_.history;
  Carried& c = trial_.carried;
  t.z_cum = 0.0;
  elastic_moduli(t.stress, c.K, c.G);
  c.ce = c.cep = elastic_stiffness(c.K, c.G);
  c.Kp = 100.0 * c.G;
  t.alpha_in = alpha_in;
  t.alpha_in_p.setZero();
  t.alpha_in_true = t.alpha_in_max = t.alpha_in_min = t.alpha;
  t.fabric.setZero();
  t.fabric_in.setZero();
  t.z_peak = params_.z_max / 100000.0;
  c.p_zp = std::max(p0, p_min_) / 100.0;
  c.z_xp = 0.0;
  c.p_zp_unset = true;
  committed_ = trial_;
  publish();
}

// --- the stress update ----------------------------------------------------------------------------------------

template <class Parameters>
Settings Material<Parameters>::settings() const {
  Settings s;
  s.scheme = static_cast<Scheme>(params_.scheme);
  s.m = params_.m;
  s.tol_f = params_.tol_f;
  s.cz = params_.cz;
  s.z_max = params_.z_max;
  s.Mc = Mc_;
  s.p_min = p_min_;
  s.e_init = void_ratio_at_zero_strain();
  s.variant = variant_;
  return s;
}

template <class Parameters>
void Material<Parameters>::set_trial_strain(const Vector3& strain) {
  trial_.history = committed_.history;  // the carried members stay as the last trial left them (OpenSees)
  trial_.history.strain = -strain;
  integrate(*this, settings(), stage_, trial_, committed_.history);
  publish();
}

// --- commit / revert ------------------------------------------------------------------------------------------

template <class Parameters>
void Material<Parameters>::commit_state() {
  History& t = trial_.history;
  Carried& c = trial_.carried;
  elastic_moduli(t.stress, c.K, c.G);
  if (c.Mcur > c.Mb && stage_ != 0 && corrects_at_commit(t.stress)) {
    const double p = mean_stress(t.stress);
    const Vector3 r = deviator(t.stress) * (c.Mb / c.Mcur / p);
    t.stress = p * identity() + r * p;
    t.alpha = r * (c.Mb - params_.m) / c.Mb;
  }
  commit_history(settings(), trial_, committed_.history);  // z_cum, z_peak, e, ce; cep = ce
  committed_ = trial_;
  publish();
}

template <class Parameters>
void Material<Parameters>::revert_to_last_commit() {
  trial_ = committed_;
  publish();
}

template <class Parameters>
void Material<Parameters>::revert_to_start() {
  initialize(trial_.history.stress);
}

// --- commands -------------------------------------------------------------------------------------------------

template <class Parameters>
void Material<Parameters>::parameter_error(std::string_view name, const std::string& what) const {
  throw common::InputError("setParameter " + std::string(name) + " (" + where() + ")", what);
}

template <class Parameters>
bool Material<Parameters>::update_stage(int stage) {
  if (stage != 0 && stage != 1)
    throw common::InputError("updateMaterialStage -material " + std::to_string(tag()),
                             std::string(type_) + " stages are 0 (elastic) and 1 (plastic), got stage " + std::to_string(stage));
  stage_ = stage;
  return true;
}

template <class Parameters>
bool Material<Parameters>::set_parameter(std::string_view name, double value) {
  if (name == "updateMaterialStage" || name == "materialState") {
    if (value != std::floor(value)) parameter_error(name, "expected an integer stage (0 or 1), got " + number_text(value));
    return update_stage(static_cast<int>(value));
  }
  if (name == "FirstCall") {  // re-initialise from the committed stress (any value, as OpenSees)
    initialize(committed_.history.stress);
    return true;
  }
  if (name == "PostShake") {  // post-shaking reconsolidation on (any value, as OpenSees)
    post_shake_ = true;
    elastic_moduli(trial_.history.stress, trial_.carried.K, trial_.carried.G);
    committed_.carried.K = trial_.carried.K;
    committed_.carried.G = trial_.carried.G;
    committed_.carried.Mcur = trial_.carried.Mcur;
    return true;
  }
  if (name == "IntegrationScheme") {
    const int scheme = static_cast<int>(value);
    if (value != std::floor(value) || scheme < 1 || scheme > 5)
      parameter_error(name, "IntegrationScheme: expected 1, 2, 3, 4 or 5, got " + number_text(value));
    params_.scheme = scheme;
    return true;
  }
  if (name == "refShearModulus" || name == "ShearModulus") {
    if (!(value > 0.0)) {
      parameter_error(name, std::string(shear_modulus_name_) + ": expected " + shear_modulus_name_ + " > 0, got " +
                                number_text(value));
    }
    params_.G0 = value;
    return true;
  }
  if (name == "poissonRatio") {  // OpenSees' GetElasticModuli takes nu >= 0.5 as 0.4999
    if (!(value >= 0.0 && value <= 0.5)) parameter_error(name, "nu: expected 0 <= nu <= 0.5, got " + number_text(value));
    params_.nu = value == 0.5 ? 0.4999 : value;
    return true;
  }
  if (name == "voidRatio") {  // e0 such that the current volumetric strain gives e = value
    const double strain_v = trace(trial_.history.strain);
    set_void_ratio_at_zero_strain((value + strain_v) / (1.0 - strain_v));
    return true;
  }
  return set_model_parameter(name, value);
}

// --- responses, JSON ------------------------------------------------------------------------------------------

template <class Parameters>
std::optional<std::vector<double>> Material<Parameters>::response(std::string_view name) const {
  const auto list = [](const Vector3& v) { return std::vector<double>{v[0], v[1], v[2]}; };
  const History& t = trial_.history;
  const History& n = committed_.history;
  if (name == "stress" || name == "stresses") return list(stress_);
  if (name == "strain" || name == "strains") return list(strain_);
  if (name == "alpha" || name == "backstressratio") return list(n.alpha);
  if (name == "fabric") return list(n.fabric);
  if (name == "alpha_in" || name == "alphain") return list(n.alpha_in);
  if (name == "tracker" || name == "trackers") return list(tracker());
  if (name == "state") {  // OpenSees getState (model sign convention: compression positive)
    const State& r = state_reported();
    std::vector<double> s;
    s.reserve(16);
    for (const Vector3* v : {&t.elastic_strain, &r.history.alpha, &r.history.fabric, &r.history.alpha_in}) {
      s.insert(s.end(), v->data(), v->data() + 3);
    }
    s.push_back(t.void_ratio);
    s.push_back(r.carried.dgamma);
    s.push_back(trial_.carried.G);
    s.push_back(trial_.carried.Kp);
    return s;
  }
  return NDMaterial::response(name);
}

template <class Parameters>
nlohmann::json Material<Parameters>::to_json() const {
  const Parameters& p = params_;
  nlohmann::json entry{{"name", std::to_string(tag())},
                       {"type", type_},
                       {"Den", p.density},
                       {"P_atm", p.P_atm},
                       {"nu", p.nu},
                       {"h0", p.h0},
                       {"nd", p.nd},
                       {"Ado", p.Ado},
                       {"z_max", p.z_max},
                       {"cz", p.cz},
                       {"ce", p.ce},
                       {"phicv", p.phi_cv},
                       {"Cgd", p.Cgd},
                       {"Ckaf", p.Ckaf},
                       {"IntScheme", p.scheme},
                       {"TanType", p.tangent_type},
                       {"TolF", p.tol_f},
                       {"TolR", p.tol_r},
                       {"materialStage", stage_}};
  add_json(entry);
  return entry;
}

// --- the commands' arguments ----------------------------------------------------------------------------------

void read_optional_arguments(common::CommandArgs& args, std::span<const std::pair<const char*, double*>> optional) {
  for (const auto& [what, target] : optional) {
    if (args.empty()) break;
    *target = args.number(what);
  }
  args.expect_end();
}

int whole_argument(common::CommandArgs& args, double value, const char* what) {
  if (value >= 0.0 && value != std::floor(value))
    args.fail(std::string("expected an integer ") + what + ", got " + number_text(value));
  return value < 0.0 ? -1 : static_cast<int>(std::min(value, 1e6));
}

void resolve_integration_options(int& scheme, int& tangent_type, double& tol_f, double& tol_r, double default_tol_f,
                                 double default_tol_r, const std::string& where) {
  const auto check = [&](bool ok, const std::string& what) {
    if (!ok) throw common::InputError(where, what);
  };
  const int given_scheme = scheme, given_tangent_type = tangent_type;
  const double given_tol_f = tol_f, given_tol_r = tol_r;
  scheme = given_scheme < 0 ? 5 : given_scheme;
  check(scheme >= 1 && scheme <= 5,
        "IntScheme: expected 1 (modified Euler), 2 (forward Euler), 3 (Runge-Kutta 4), 4 or 5 (forward / modified "
        "Euler with at most 1e-5 strain per sub-step), got " + std::to_string(given_scheme));
  tangent_type = given_tangent_type < 0 ? 0 : given_tangent_type;
  check(tangent_type >= 0 && tangent_type <= 2,
        "TanType: expected 0 (elastic), 1 or 2 (elastic matrix of the last commit), got " +
            std::to_string(given_tangent_type));
  tol_f = given_tol_f < 0.0 ? default_tol_f : given_tol_f;
  tol_r = given_tol_r < 0.0 ? default_tol_r : given_tol_r;
  check(tol_f > 0.0, "TolF: expected TolF > 0, got " + number_text(given_tol_f));
  check(tol_r > 0.0, "TolR: expected TolR > 0, got " + number_text(given_tol_r));
}

// The two models (explicit instantiation: the definitions stay in this file).
template class Material<PM4SandParameters>;
template class Material<PM4SiltParameters>;

}  // namespace fem::materials::pm4
