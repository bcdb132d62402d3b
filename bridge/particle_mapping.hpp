#pragma once
// Nodes -> material points (the paper, "Hybrid FEM-MPM", Figure 3b): n x n particles per element at
// the Gauss-Legendre points, values from the element's bilinear shape functions.
#include <array>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#include "bridge/stress_recovery.hpp"
#include "bridge/transfer_state.hpp"
#include "mpm/io/particle_table.hpp"

namespace bridge {

/// Leaves the memory of new elements untouched on resize (no serial zero fill): the parallel loop that
/// fills the records value-initialises each one (padding included), so every thread touches its own
/// pages first.
template <class T>
struct UninitializedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U*) noexcept {}
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// The particles, in id order (contiguous: pass as std::span to mpm::io::write_particle_table).
using ParticleList = std::vector<mpm::ParticleRecord, UninitializedAllocator<mpm::ParticleRecord>>;

enum class VolumeSplit { Jacobian, Area };

struct MappingOptions {
  int particles_per_direction = 4;
  Recovery recovery = Recovery::InverseDistance;
  /// Jacobian: V_p = det J(xi_p) w_p (the element's own quadrature; sums to the area exactly).
  /// Area: V_p = A w_p / 4 (the paper's "element area x Gauss weight").
  VolumeSplit volume_split = VolumeSplit::Jacobian;
};

/// Tags of the elements whose Jacobian determinant is <= 0 somewhere in the current configuration
/// (the minimum of the bilinear det J is at a corner), or in the model's own coordinates when
/// `reference` (nodes listed clockwise, or a quad that is not convex).
std::vector<long> inverted_elements(const TransferState& state, bool reference = false);

/// CB-Geo's Mohr-Coulomb state variables for `stress` (cb-geo/mpm include/materials/mohr_coulomb.tcc,
/// compute_stress_invariants): phi, psi, cohesion, epsilon = sqrt(3) p (p = I1/3, tension positive),
/// rho = sqrt(2 J2), theta = acos(3 sqrt(3) J3 / (2 J2^1.5)) / 3 in [0, pi/3] (0 when J2 = 0),
/// pdstrain = 0. Returns the count (7).
unsigned mohr_coulomb_state(const MpmMaterial& m, const Stress6& stress, double* svars);

/// Where each element's particles go: element e's particles are slot[e] * n^2 ... slot[e] * n^2 + n^2 - 1.
/// The elements are grouped by material (the materials in state order, each material's elements in
/// element order), so that the deck's one particle file per material (CB-Geo's generator per
/// material_id) numbers the particles as the HDF5 file does.
std::vector<std::size_t> particle_slots(const TransferState& state);

/// An element's particle points in their numbering order q = j n + i (eta-major): natural coordinates of
/// the n x n Gauss-Legendre points, their weight w_i w_j and the element's shape functions there. Element e's
/// particle q has id particle_slots(state)[e] * n^2 + q (generate_particles).
struct ParticlePoint {
  double xi, eta, w;
  std::array<double, 4> shape;
};
std::vector<ParticlePoint> particle_points(int n);

/// Generates the particles: n x n Gauss-Legendre points in (xi, eta) per element, eta-major, grouped by
/// material (the materials in state order, each material's elements in element order: id =
/// (slot of the element in that order) * n^2 + j * n + i). Position, displacement, velocity and stress from the nodal
/// values with N_a; volume from the current geometry, mass = density x reference volume (so the
/// total mass equals sum density x reference area exactly); nsize = 2/n; cell_id -1; status 1.
ParticleList generate_particles(const TransferState& state,
                                                        const std::vector<Stress6>& nodal_stress,
                                                        const MappingOptions& options);

}  // namespace bridge
