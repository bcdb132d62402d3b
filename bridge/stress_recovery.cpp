#include "bridge/stress_recovery.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace bridge {
namespace {

/// Node -> adjacent elements, compressed (CSR).
struct Adjacency {
  std::vector<std::size_t> offset;
  std::vector<int> elements;
};

Adjacency node_elements(const TransferState& state) {
  Adjacency adj;
  const std::size_t nn = state.reference.size();
  adj.offset.assign(nn + 1, 0);
  for (const auto& e : state.elements)
    for (int a : e.nodes) ++adj.offset[static_cast<std::size_t>(a) + 1];
  for (std::size_t i = 0; i < nn; ++i) adj.offset[i + 1] += adj.offset[i];
  adj.elements.resize(adj.offset[nn]);
  std::vector<std::size_t> fill(adj.offset.begin(), adj.offset.end() - 1);
  for (std::size_t e = 0; e < state.elements.size(); ++e)
    for (int a : state.elements[e].nodes) adj.elements[fill[static_cast<std::size_t>(a)]++] = static_cast<int>(e);
  return adj;
}

/// Gauss-point positions in the current configuration, in gauss_stress order.
std::vector<Vec2> gauss_positions(const TransferState& state) {
  std::vector<Vec2> out(state.gauss_stress.size());
  const auto one = opensees_gauss_points(1);
  const auto four = opensees_gauss_points(4);
  for (std::size_t e = 0; e < state.elements.size(); ++e) {
    const auto& el = state.elements[e];
    const QuadNodes x = state.current_nodes(el);
    const auto& pts = el.gauss_points == 1 ? one : four;
    for (std::size_t g = 0; g < pts.size(); ++g) out[state.gauss_offset[e] + g] = map_point(x, pts[g].x(), pts[g].y());
  }
  return out;
}

std::vector<Stress6> inverse_distance(const TransferState& state) {
  const std::size_t nn = state.reference.size();
  std::vector<Stress6> sum(nn, Stress6{});
  std::vector<double> weight(nn, 0.0);
  const auto gp = gauss_positions(state);
  for (std::size_t e = 0; e < state.elements.size(); ++e) {
    const auto& el = state.elements[e];
    const QuadNodes x = state.current_nodes(el);
    // Distances below 1e-12 of the element size count as coincident (weight 1e12 / size).
    const double floor = 1e-12 * std::sqrt(std::abs(quad_area(x)) + 1e-300);
    for (std::size_t g = state.gauss_offset[e]; g < state.gauss_offset[e + 1]; ++g) {
      for (int a = 0; a < 4; ++a) {
        const auto node = static_cast<std::size_t>(el.nodes[a]);
        const double w = 1.0 / std::max((x[a] - gp[g]).norm(), floor);
        for (int k = 0; k < 6; ++k) sum[node][k] += w * state.gauss_stress[g][k];
        weight[node] += w;
      }
    }
  }
  for (std::size_t i = 0; i < nn; ++i)
    if (weight[i] > 0)
      for (int k = 0; k < 6; ++k) sum[i][k] /= weight[i];
  return sum;
}

/// Superconvergent patch recovery (Zienkiewicz & Zhu 1992): per node, least squares over the patch
/// Gauss points of sigma ~ P(x) a with P = (1, x, y[, xy]) in coordinates centred on the node and
/// scaled by the patch size; the nodal value is a_0.
std::vector<Stress6> patch_recovery(const TransferState& state) {
  const std::size_t nn = state.reference.size();
  const Adjacency adj = node_elements(state);
  const auto gp = gauss_positions(state);
  std::vector<Stress6> out(nn, Stress6{});
  std::vector<char> in_patch(state.elements.size(), 0);
  std::vector<int> patch;
  std::vector<int> grown;
  patch.reserve(64);
  grown.reserve(64);
  for (std::size_t node = 0; node < nn; ++node) {
    if (adj.offset[node] == adj.offset[node + 1]) continue;  // not used by any element
    patch.assign(adj.elements.begin() + static_cast<std::ptrdiff_t>(adj.offset[node]),
                 adj.elements.begin() + static_cast<std::ptrdiff_t>(adj.offset[node + 1]));
    for (int e : patch) in_patch[static_cast<std::size_t>(e)] = 1;
    const Vec2 xn = state.current(static_cast<int>(node));
    bool solved = false;
    for (int ring = 0; ring < 4 && !solved; ++ring) {
      bool all_four = true;
      std::size_t points = 0;
      double scale = 0;
      for (int e : patch) {
        const auto ue = static_cast<std::size_t>(e);
        all_four = all_four && state.elements[ue].gauss_points == 4;
        for (std::size_t g = state.gauss_offset[ue]; g < state.gauss_offset[ue + 1]; ++g) {
          scale = std::max(scale, (gp[g] - xn).cwiseAbs().maxCoeff());
          ++points;
        }
      }
      const int terms = all_four ? 4 : 3;
      if (points >= static_cast<std::size_t>(terms) && scale > 0) {
        Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
        Eigen::Matrix<double, 4, 6> b = Eigen::Matrix<double, 4, 6>::Zero();
        for (int e : patch) {
          const auto ue = static_cast<std::size_t>(e);
          for (std::size_t g = state.gauss_offset[ue]; g < state.gauss_offset[ue + 1]; ++g) {
            const Vec2 r = (gp[g] - xn) / scale;
            const Eigen::Vector4d p(1, r.x(), r.y(), terms == 4 ? r.x() * r.y() : 0.0);
            a.noalias() += p * p.transpose();
            for (int k = 0; k < 6; ++k) b.col(k) += p * state.gauss_stress[g][k];
          }
        }
        if (terms == 3) a(3, 3) = 1;  // decouple the unused term
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(a, Eigen::EigenvaluesOnly);
        const double lmin = eig.eigenvalues()(0), lmax = eig.eigenvalues()(3);
        if (lmin > 1e-10 * lmax) {
          const Eigen::Matrix<double, 4, 6> coef = a.ldlt().solve(b);
          for (int k = 0; k < 6; ++k) out[node][k] = coef(0, k);
          solved = true;
        }
      }
      if (!solved) {
        // Grow the patch by one ring: every element touching a node of the current patch.
        grown = patch;
        for (int e : patch)
          for (int a : state.elements[static_cast<std::size_t>(e)].nodes)
            for (std::size_t k = adj.offset[static_cast<std::size_t>(a)]; k < adj.offset[static_cast<std::size_t>(a) + 1]; ++k) {
              const int f = adj.elements[k];
              if (!in_patch[static_cast<std::size_t>(f)]) {
                in_patch[static_cast<std::size_t>(f)] = 1;
                grown.push_back(f);
              }
            }
        if (grown.size() == patch.size()) break;  // the whole mesh is too small for a fit
        patch.swap(grown);
      }
    }
    for (int e : patch) in_patch[static_cast<std::size_t>(e)] = 0;
    if (!solved) {
      // Degenerate patch (e.g. a single element of one Gauss point): its plain average.
      Stress6 avg{};
      std::size_t count = 0;
      for (std::size_t k = adj.offset[node]; k < adj.offset[node + 1]; ++k) {
        const auto ue = static_cast<std::size_t>(adj.elements[k]);
        for (std::size_t g = state.gauss_offset[ue]; g < state.gauss_offset[ue + 1]; ++g, ++count)
          for (int c = 0; c < 6; ++c) avg[c] += state.gauss_stress[g][c];
      }
      for (int c = 0; c < 6; ++c) out[node][c] = avg[c] / static_cast<double>(count);
    }
  }
  return out;
}

}  // namespace

std::vector<Stress6> recover_nodal_stress(const TransferState& state, Recovery method) {
  return method == Recovery::InverseDistance ? inverse_distance(state) : patch_recovery(state);
}

Stress6 interpolate(const std::array<double, 4>& n, const std::array<const Stress6*, 4>& nodal) {
  Stress6 s{};
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 6; ++k) s[k] += n[a] * (*nodal[a])[k];
  return s;
}

}  // namespace bridge
