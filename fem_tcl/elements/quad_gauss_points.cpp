#include "fem_tcl/elements/quad_gauss_points.hpp"

#include <Eigen/LU>

#include "common/command_args.hpp"
#include "common/input_error.hpp"

namespace fem::elements {

namespace {
constexpr double kG = 0.5773502691896258;  // 1/sqrt(3)
constexpr double kPts[4][2] = {{-kG, -kG}, {kG, -kG}, {kG, kG}, {-kG, kG}};
constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};
}  // namespace

QuadGaussPoints quad_gauss_points(const std::array<domain::Node*, 4>& nodes, double thickness,
                                  const std::string& where) {
  if (!(thickness > 0.0)) throw common::InputError(where, "expected thickness > 0");
  QuadGaussPoints gp;
  for (int g = 0; g < 4; ++g) {
    const double xi = kPts[g][0], eta = kPts[g][1];
    Eigen::Matrix<double, 2, 4> dNloc;  // d N / d(xi, eta)
    Eigen::Vector4d N;
    for (int a = 0; a < 4; ++a) {
      N[a] = 0.25 * (1.0 + kXi[a] * xi) * (1.0 + kEta[a] * eta);
      dNloc(0, a) = 0.25 * kXi[a] * (1.0 + kEta[a] * eta);
      dNloc(1, a) = 0.25 * kEta[a] * (1.0 + kXi[a] * xi);
    }
    Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // J(i, j) = d x_j / d xi_i
    for (int a = 0; a < 4; ++a) {
      J(0, 0) += dNloc(0, a) * nodes[a]->crd[0];
      J(0, 1) += dNloc(0, a) * nodes[a]->crd[1];
      J(1, 0) += dNloc(1, a) * nodes[a]->crd[0];
      J(1, 1) += dNloc(1, a) * nodes[a]->crd[1];
    }
    const double detJ = J.determinant();
    if (!(detJ > 0.0)) {
      throw common::InputError(where, "nodes are collapsed, clockwise or form a non-convex quadrilateral "
                                      "(detJ <= 0 at a Gauss point; give them counter-clockwise)");
    }
    gp[g].dN = J.inverse() * dNloc;
    gp[g].N = N;
    gp[g].dvol = detJ * thickness;  // unit weights
  }
  return gp;
}

Eigen::Matrix<double, 3, 8> quad_strain_matrix(const QuadGaussPoint& g) {
  Eigen::Matrix<double, 3, 8> B = Eigen::Matrix<double, 3, 8>::Zero();
  for (int a = 0; a < 4; ++a) {
    B(0, 2 * a) = g.dN(0, a);
    B(1, 2 * a + 1) = g.dN(1, a);
    B(2, 2 * a) = g.dN(1, a);
    B(2, 2 * a + 1) = g.dN(0, a);
  }
  return B;
}

Eigen::Matrix<double, 8, 8> quad_stiffness(const QuadGaussPoints& points,
                                           const std::function<Eigen::Matrix3d(int)>& tangent) {
  Eigen::Matrix<double, 8, 8> K = Eigen::Matrix<double, 8, 8>::Zero();
  for (int g = 0; g < 4; ++g) {
    const Eigen::Matrix3d D = tangent(g);
    const Eigen::Matrix<double, 3, 8> B = quad_strain_matrix(points[g]);
    K.noalias() += points[g].dvol * (B.transpose() * D * B);
  }
  return K;
}

QuadMaterialPoints::QuadMaterialPoints(const std::array<domain::Node*, 4>& nodes, const materials::NDMaterial& material,
                                       materials::PlaneType plane, double thickness, const std::string& where) {
  for (auto& m : materials_) m = material.copy_for(plane);
  gp_ = quad_gauss_points(nodes, thickness, where);
}

void QuadMaterialPoints::update(const std::array<domain::Node*, 4>& nodes) {
  for (int g = 0; g < 4; ++g) {
    materials::Vector3 eps = materials::Vector3::Zero();
    for (int a = 0; a < 4; ++a) {
      const auto u = nodes[a]->solid_disp();
      eps[0] += gp_[g].dN(0, a) * u[0];
      eps[1] += gp_[g].dN(1, a) * u[1];
      eps[2] += gp_[g].dN(0, a) * u[1] + gp_[g].dN(1, a) * u[0];
    }
    materials_[g]->set_trial_strain(eps);
  }
}

Eigen::Matrix<double, 8, 8> QuadMaterialPoints::stiffness(bool initial) const {
  return quad_stiffness(gp_, [&](int g) { return initial ? materials_[g]->initial_tangent() : materials_[g]->tangent(); });
}

void QuadMaterialPoints::commit_state() {
  for (auto& m : materials_) m->commit_state();
}
void QuadMaterialPoints::revert_to_last_commit() {
  for (auto& m : materials_) m->revert_to_last_commit();
}
void QuadMaterialPoints::revert_to_start() {
  for (auto& m : materials_) m->revert_to_start();
}

bool QuadMaterialPoints::set_parameter(std::string_view name, double value) {
  bool any = false;
  for (auto& m : materials_) any = m->set_parameter(name, value) || any;
  return any;
}

bool QuadMaterialPoints::update_stage(int stage) {
  bool any = false;
  for (auto& m : materials_) any = m->update_stage(stage) || any;
  return any;
}

std::optional<std::vector<double>> QuadMaterialPoints::response(const std::vector<std::string>& args) const {
  if (args.empty()) return std::nullopt;
  const std::string& what = args[0];
  if (what == "stress" || what == "stresses" || what == "strain" || what == "strains") {
    const bool stress = what.rfind("stress", 0) == 0;
    std::vector<double> out;
    out.reserve(12);
    for (const auto& m : materials_) {
      const materials::Vector3& v = stress ? m->stress() : m->strain();
      out.insert(out.end(), v.data(), v.data() + 3);
    }
    return out;
  }
  if (what == "stress3D" || what == "fullStress") {  // 4 Gauss points x (sxx syy szz sxy syz sxz)
    std::vector<double> out;
    out.reserve(24);
    for (const auto& m : materials_) {
      const materials::Vector6 v = m->stress_3d();
      out.insert(out.end(), v.data(), v.data() + 6);
    }
    return out;
  }
  if ((what == "material" || what == "integrPoint") && args.size() >= 3) {
    const auto k = common::CommandArgs::parse_integer(args[1]);
    if (!k || *k < 1 || *k > 4) return std::nullopt;
    return materials_[static_cast<std::size_t>(*k - 1)]->response(args[2]);
  }
  return std::nullopt;
}

}  // namespace fem::elements
