#pragma once
// Gauss-point stresses -> nodal stresses: the paper's inverse-distance weighting ("Hybrid FEM-MPM",
// Figure 3a) and superconvergent patch recovery (Zienkiewicz & Zhu 1992).
#include <array>
#include <vector>

#include "bridge/transfer_state.hpp"

namespace bridge {

enum class Recovery { InverseDistance, PatchRecovery };
/// Nodal stresses recovered from the Gauss points.
/// InverseDistance: sigma_a = sum_g sigma_g / d_ag / sum_g 1/d_ag over the Gauss points g of the
/// elements around node a, d in the current configuration (the paper, "Hybrid FEM-MPM").
/// PatchRecovery: least-squares fit of a polynomial (1, x, y for one-point elements; 1, x, y, xy for
/// 2x2-point elements) to the Gauss-point values of the patch of elements around the node, evaluated
/// at the node (Zienkiewicz & Zhu 1992, Int. J. Numer. Meth. Eng. 33, 1331-1364, eqs. 6-12). Where the
/// patch is too small (boundary nodes) it grows by one ring of elements until the fit is determined.
std::vector<Stress6> recover_nodal_stress(const TransferState& state, Recovery method);

/// The stress field the particles sample: sum_a N_a(xi) sigma_a.
Stress6 interpolate(const std::array<double, 4>& n, const std::array<const Stress6*, 4>& nodal);

}  // namespace bridge
