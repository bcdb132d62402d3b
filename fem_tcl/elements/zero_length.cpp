#include "fem_tcl/elements/zero_length.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>
#include <utility>

namespace fem::elements {

ZeroLength::ZeroLength(int tag, domain::Node* i, domain::Node* j,
                       std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats, std::vector<int> dirs,
                       const Eigen::Vector3d& x_axis, int do_rayleigh)
    : SolidElement(tag, i, j), mats_(std::move(mats)), dirs_(std::move(dirs)), do_rayleigh_(do_rayleigh) {
  // OpenSees ZeroLength::setUp with yp = z cross x (2D): z' = x' cross yp, y' = z' cross x'.
  const Eigen::Vector3d yp(-x_axis[1], x_axis[0], 0.0);
  const Eigen::Vector3d z = x_axis.cross(yp);
  const Eigen::Vector3d y = z.cross(x_axis);
  if (x_axis.norm() == 0.0 || y.norm() == 0.0 || z.norm() == 0.0) {
    throw common::InputError("element zeroLength " + std::to_string(tag),
                             "-orient: the x axis is zero or along the global z axis, the orientation is singular");
  }
  transformation_.row(0) = x_axis.normalized();
  transformation_.row(1) = y.normalized();
  transformation_.row(2) = z.normalized();
  for (int d : dirs_) axis_.emplace_back(transformation_(d, 0), transformation_(d, 1));
  // OpenSees setDomain: the relative state when the element enters the domain is the zero deformation.
  d0_ = j->solid_disp() - i->solid_disp();
  v0_ = j->vel.head<2>() - i->vel.head<2>();
  // OpenSees warns (and goes on) when the nodes are not coincident.
  const double length = (j->crd - i->crd).norm();
  const double scale = std::max(i->crd.norm(), j->crd.norm());
  if (length > 1.0e-6 * scale) {
    std::cerr << "WARNING element zeroLength " << tag << ": nodes " << i->tag << " and " << j->tag
              << " are " << length << " apart (not coincident); the element acts as if they were\n";
  }
}

void ZeroLength::update() {
  const domain::Node& ni = *nodes()[0];
  const domain::Node& nj = *nodes()[1];
  const Eigen::Vector2d du = nj.solid_disp() - ni.solid_disp() - d0_;
  const Eigen::Vector2d dv = nj.vel.head<2>() - ni.vel.head<2>() - v0_;
  for (std::size_t k = 0; k < mats_.size(); ++k) mats_[k]->set_trial_strain(axis_[k].dot(du), axis_[k].dot(dv));
}

template <class Weight>
void ZeroLength::assemble(Matrix8& out, Weight weight) const {
  out.setZero();
  for (std::size_t k = 0; k < mats_.size(); ++k) {
    const double w = weight(*mats_[k]);
    if (w == 0.0) continue;
    Eigen::Vector4d b;
    b << -axis_[k][0], -axis_[k][1], axis_[k][0], axis_[k][1];
    out.topLeftCorner<4, 4>().noalias() += w * b * b.transpose();
  }
}

const Matrix8& ZeroLength::tangent_stiffness() {
  assemble(K_, [](const materials::UniaxialMaterial& m) { return m.tangent(); });
  return K_;
}

const Matrix8& ZeroLength::initial_stiffness() {
  assemble(K_, [](const materials::UniaxialMaterial& m) { return m.initial_tangent(); });
  return K_;
}

const Matrix8* ZeroLength::damping_tangent() {
  if (do_rayleigh_ == 1) return nullptr;
  bool any = false;
  for (const auto& m : mats_) any = any || m->damp_tangent() != 0.0;
  if (!any) return nullptr;
  assemble(C_, [](const materials::UniaxialMaterial& m) { return m.damp_tangent(); });
  return &C_;
}

const Vector8& ZeroLength::resisting_force() {
  force_.setZero();
  for (std::size_t k = 0; k < mats_.size(); ++k) {
    const double s = mats_[k]->stress();
    force_[0] -= axis_[k][0] * s;
    force_[1] -= axis_[k][1] * s;
    force_[2] += axis_[k][0] * s;
    force_[3] += axis_[k][1] * s;
  }
  return force_;
}

void ZeroLength::commit_state() {
  for (auto& m : mats_) m->commit_state();
  update_committed_tangent();
}
void ZeroLength::revert_to_last_commit() {
  for (auto& m : mats_) m->revert_to_last_commit();
}
void ZeroLength::revert_to_start() {
  for (auto& m : mats_) m->revert_to_start();
}

Vector8 ZeroLength::rayleigh_force() {
  // OpenSees Element::getRayleighDampingForces (no mass): (betaK K + betaK0 K0 + betaKc Kc) v.
  Vector8 f = Vector8::Zero();
  const domain::RayleighFactors& r = rayleigh();
  if (!r.any()) return f;
  const Vector8 v = trial_velocity();
  if (r.beta_k != 0.0) f += r.beta_k * (tangent_stiffness() * v);
  if (r.beta_k0 != 0.0) f += r.beta_k0 * (initial_stiffness() * v);
  if (r.beta_kc != 0.0) f += r.beta_kc * (committed_tangent() * v);
  return f;
}

std::optional<std::vector<double>> ZeroLength::response(const std::vector<std::string>& args) {
  if (args.empty()) return std::nullopt;
  const std::string& name = args[0];
  const std::size_t n = mats_.size();
  std::vector<double> out;
  if (name == "force" || name == "forces" || name == "globalForces" || name == "globalforces") {
    const Vector8& f = resisting_force();
    return std::vector<double>(f.data(), f.data() + 4);  // P1_1 P1_2 P2_1 P2_2
  }
  if (name == "basicForce" || name == "basicForces" || name == "localForce" || name == "localForces") {
    for (const auto& m : mats_) out.push_back(m->stress());
    return out;
  }
  if (name == "defo" || name == "deformations" || name == "deformation" || name == "basicDeformation") {
    for (const auto& m : mats_) out.push_back(m->strain());
    return out;
  }
  if (name == "defoANDforce" || name == "deformationANDforces" || name == "deformationsANDforces") {
    for (const auto& m : mats_) out.push_back(m->strain());
    for (const auto& m : mats_) out.push_back(m->stress());
    return out;
  }
  if (name == "basicStiffness") {  // n x n, diagonal, row by row
    out.assign(n * n, 0.0);
    for (std::size_t k = 0; k < n; ++k) out[k * n + k] = mats_[k]->tangent();
    return out;
  }
  if (name == "material" && args.size() > 2) {
    const auto k = common::CommandArgs::parse_integer(args[1]);
    if (!k || *k < 1 || *k > static_cast<int>(n)) return std::nullopt;
    return mats_[static_cast<std::size_t>(*k - 1)]->response(args[2]);
  }
  if (name == "xaxis" || name == "yaxis" || name == "zaxis") {
    const int row = name == "xaxis" ? 0 : name == "yaxis" ? 1 : 2;
    return std::vector<double>{transformation_(row, 0), transformation_(row, 1), transformation_(row, 2)};
  }
  if (name == "materials") {
    for (const auto& m : mats_) out.push_back(m->tag());
    return out;
  }
  if (name == "directions") {
    for (int d : dirs_) out.push_back(d + 1);
    return out;
  }
  if (name == "dampingForces" || name == "rayleighForces") {
    const Vector8 f = do_rayleigh_ == 1 ? rayleigh_force() : Vector8::Zero();
    return std::vector<double>(f.data(), f.data() + 4);
  }
  return std::nullopt;
}

nlohmann::ordered_json ZeroLength::to_json() const {
  // OpenSees ZeroLength::Print (OPS_PRINT_PRINTMODEL_JSON): dof names by direction 0..5.
  static const char* const kDofNames[] = {"P", "Vy", "Vz", "T", "My", "Mz"};
  nlohmann::ordered_json j;
  j["name"] = tag();
  j["type"] = "ZeroLength";
  j["nodes"] = {nodes()[0]->tag, nodes()[1]->tag};
  j["materials"] = nlohmann::ordered_json::array();
  for (const auto& m : mats_) j["materials"].push_back(std::to_string(m->tag()));
  j["dof"] = nlohmann::ordered_json::array();
  for (int d : dirs_) j["dof"].push_back(kDofNames[d]);
  j["transMatrix"] = nlohmann::ordered_json::array();
  for (int r = 0; r < 3; ++r) {
    j["transMatrix"].push_back({transformation_(r, 0), transformation_(r, 1), transformation_(r, 2)});
  }
  return j;
}

std::unique_ptr<domain::Element> parse_zero_length(common::CommandArgs& args, const ElementBuildContext& ctx) {
  const int tag = args.integer("eleTag");
  const int i = args.integer("iNode");
  const int j = args.integer("jNode");
  if (!args.flag("-mat")) args.fail("expected -mat matTag1 ..");
  std::vector<int> mat_tags;
  while (auto m = args.optional_integer()) mat_tags.push_back(*m);
  if (mat_tags.empty()) args.fail("expected at least one uniaxialMaterial tag after -mat");
  if (!args.flag("-dir") && !args.flag("-dof")) args.fail("expected -dir dir1 .. after the material tags");
  std::vector<int> dirs;
  for (std::size_t k = 0; k < mat_tags.size(); ++k) {
    const int d = args.integer("direction (one per material)");
    // OpenSees accepts 1..6 and gives a 2D, 2-dof element a zero row for 3..6 (no stiffness at all).
    if (d < 1 || d > 2) {
      args.fail("-dir " + std::to_string(d) + " is outside 1..ndf (the model has ndf 2: 1 = local x, 2 = local y)");
    }
    dirs.push_back(d - 1);
  }
  Eigen::Vector3d x_axis(1.0, 0.0, 0.0);
  int do_rayleigh = 0;
  while (!args.empty()) {
    if (args.flag("-orient")) {
      for (int k = 0; k < 3; ++k) x_axis[k] = args.number("-orient x component");
      // yp (3 more values) is read and, as in OpenSees' 2D zeroLength, not used: y' = z cross x'.
      if (args.optional_number()) {
        args.number("-orient yp component");
        args.number("-orient yp component");
      }
      if (!x_axis.allFinite()) args.fail("-orient: expected finite components");
    } else if (args.flag("-doRayleigh")) {
      do_rayleigh = 1;
      if (auto f = args.optional_integer()) {
        if (*f != 0 && *f != 1) args.fail("-doRayleigh: expected 0 or 1, got " + std::to_string(*f));
        do_rayleigh = *f;
      }
    } else if (args.peek() == "-dampMats" || args.peek() == "-damp") {
      args.fail("option '" + args.peek() + "' is not supported (give the dashpot as a Viscous material)");
    } else if (args.optional_integer()) {
      args.fail("more directions than materials (" + std::to_string(mat_tags.size()) + " after -mat)");
    } else {
      args.fail("unknown option '" + args.peek() + "'");
    }
  }
  domain::Node* ni = ctx.domain.find_node(i);
  domain::Node* nj = ctx.domain.find_node(j);
  if (!ni) args.fail("node " + std::to_string(i) + " does not exist");
  if (!nj) args.fail("node " + std::to_string(j) + " does not exist");
  if (i == j) args.fail("iNode and jNode are the same node");
  std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
  for (int m : mat_tags) mats.push_back(ctx.uniaxial_material(args, m).copy());
  return std::make_unique<ZeroLength>(tag, ni, nj, std::move(mats), std::move(dirs), x_axis, do_rayleigh);
}

namespace {
struct UniaxialTrialState final : domain::ElementState {
  std::vector<std::pair<double, double>> strain_and_rate;
};
}  // namespace

std::unique_ptr<domain::ElementState> ZeroLength::save_state() const {
  auto state = std::make_unique<UniaxialTrialState>();
  for (const auto& m : mats_) state->strain_and_rate.emplace_back(m->strain(), m->strain_rate());
  return state;
}

void ZeroLength::restore_state(const domain::ElementState& saved) {
  const auto& state = dynamic_cast<const UniaxialTrialState&>(saved);
  for (std::size_t k = 0; k < mats_.size() && k < state.strain_and_rate.size(); ++k)
    mats_[k]->set_trial_strain(state.strain_and_rate[k].first, state.strain_and_rate[k].second);
}

}  // namespace fem::elements
