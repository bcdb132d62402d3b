#pragma once
// The transfer report: mass, momentum and energies before (FEM) and after (particles), and how far the
// particles' stresses are from the FEM Gauss-point stresses.
#include <span>
#include <vector>

#include "bridge/stress_recovery.hpp"
#include "bridge/transfer_state.hpp"
#include "mpm/io/particle_table.hpp"

namespace bridge {

/// Transfer bookkeeping: the FEM side (nodal lumped masses from the elements) against the particles.
struct TransferTotals {
  double mass = 0;                   ///< kg per m thickness
  Vec2 momentum = Vec2::Zero();      ///< kg m/s per m
  double kinetic_energy = 0;         ///< J per m
  double potential_energy = 0;       ///< J per m, sum m g y (y from the coordinate origin)
};

struct TransferReport {
  TransferTotals fem, particles;
  double stress_rms_relative = 0;    ///< sqrt(sum |dsigma|^2 / sum |sigma|^2) over the FEM Gauss points
  double stress_max_relative = 0;    ///< max |dsigma| / max |sigma|
  double stress_max_abs = 0;         ///< Pa
  long stress_max_element = 0;       ///< element tag where |dsigma| is largest
  double min_jacobian = 0;           ///< smallest det J over the elements (current configuration)
  long min_jacobian_element = 0;
  std::size_t particle_count = 0;
};

/// FEM totals use the row-sum lumped nodal masses m_a = sum_e rho_e int N_a dA (reference
/// configuration, 2x2 Gauss); the stress difference compares each FEM Gauss point's stress with the
/// particles' field (sum_a N_a sigma_a) at the same point, |s| = sqrt(s:s) with the full tensor.
/// Throws common::InputError when a figure is not finite (values too large for double precision).
TransferReport make_report(const TransferState& state, const std::vector<Stress6>& nodal_stress,
                           std::span<const mpm::ParticleRecord> particles);

}  // namespace bridge
