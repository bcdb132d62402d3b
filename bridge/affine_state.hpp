#pragma once
// The APIC state of the transferred particles (mpm's analysis.transfer "apic"; Jiang, Schroeder, Selle,
// Teran & Stomakhin 2015): each particle carries, beside its velocity, the affine matrix B_p, read by the
// next p2g as v(x) = v_p + B_p D_p^-1 (x - x_p). The FEM field has that affine part: its velocity
// gradient L_p at the particle. fem2mpm writes B_p = L_p D_p (D_p = sum_i w_ip (x_i - x_p)(x_i - x_p)^T
// for the MPM grid at the particle's position), so the resumed run starts from the FEM's velocity field
// to first order, not from zero matrices (which drop the rotation and shearing of each particle's
// neighbourhood at the first p2g).
#include <array>
#include <span>
#include <vector>

#include "bridge/mpm_deck.hpp"
#include "bridge/particle_mapping.hpp"
#include "bridge/transfer_state.hpp"
#include "mpm/io/particle_table.hpp"

namespace bridge {

/// 2 x 2 row-major: xx xy yx yy.
using Matrix2 = std::array<double, 4>;

/// The FEM velocity gradient L_ij = d v_i / d x_j (1/s) at every particle of generate_particles (same
/// order): its element's nodal velocities and the bilinear shape-function gradients on the current
/// geometry at the particle's Gauss point (Zienkiewicz, Taylor & Zhu 2013, sec. 6.3).
std::vector<Matrix2> particle_velocity_gradients(const TransferState& state, const MappingOptions& options);

/// APIC's matrices B_p = L_p D_p on `grid` (D_p diagonal: uGIMP with the particle's half-size nsize h / 4,
/// or bilinear, as mpm/core/velocity_transfer.hpp computes it), for mpm's "/apic_affine" dataset.
std::vector<Matrix2> apic_matrices(std::span<const mpm::ParticleRecord> particles, std::span<const Matrix2> gradients,
                                   const GridSpec& grid);

}  // namespace bridge
