#pragma once
// The explicit MPM engine: one Simulation per run, built from a validated Deck.
//
// A step reads as the algorithm (Sulsky, Chen & Schreyer 1994; Bardenhagen & Kober 2004 for uGIMP;
// USF/USL/MUSL as in CB-Geo's include/solvers/mpm_scheme/*.tcc):
// (Engine::run_step; every node phase first sums the chunks' grid bands in chunk order):
//   USF : p2g(mass, momentum)  nodal_velocity  update_stress  p2g(forces)  update_grid  g2p
//   USL : p2g(all)  update_grid  g2p (+ strain increments)  update_stress
//   MUSL: p2g(all)  update_grid  g2p (+ remap of the updated momentum to the nodes)  nodal_velocity
//         update_stress
// update_grid = (nodal velocity,) Cundall damping, v += a dt, then at constrained nodes the friction and
//               velocity constraints in momentum form, FLIP getting (v_new - v_old) / dt (nodal_constraints.hpp);
// update_stress = strain increment, checkerboard remedy, material (one templated loop per material type).
// Particles are stored as structure-of-arrays, sorted by cell (and stencil quadrant) then id each step (deterministic; the
// order depends only on the state that the snapshot records, so a resume continues bit-identically).
//
// Semantics worth knowing (CB-Geo's where not stated):
// - dt: analysis.dt, or with analysis.cfl > 0 the smaller of analysis.dt (if > 0) and cfl h / c_p,
//   c_p = sqrt((K + 4G/3) / rho) of the stiffest material; fixed for the run.
// - analysis.transfer: FLIP (velocity_update false), PIC (velocity_update true), or APIC; pic_blend in
//   [0, 1] blends the FLIP and PIC velocity updates (velocity_transfer.hpp).
// - analysis.stress_smoothing: "none", "cell_volumetric" (cell-mean volumetric strain increment),
//   "cell_strain" (cell-mean strain increment plus 0.1 of the deviatoric deviation: the remedy to use),
//   "nodal_strain" (mass-weighted nodal smoothing of the strain increment) or "nodal_volumetric"
//   (volume-weighted nodal smoothing of the volumetric increment); see stress_remedy.hpp.
// - A particle has left the grid when it is outside the mesh region (uGIMP: when its whole domain of
//   half-size lp = nsize h / 4 is); an error with locate_particles, else it is removed.
// - A velocity is "runaway" when the particle would move more than one cell in one step (|v| dt > h).
// - The particle volume follows its own volumetric strain increment (CB-Geo uses the cell-centre rate);
//   CB-Geo's invariant state variables (epsilon, rho, theta) are computed from the stress at snapshot.
// - USL drops the internal force of nodes lighter than 2 % of a full node (engine.hpp small_mass_): particles
//   entering empty cells (vanishing nodal mass; Sulsky, Zhou & Schreyer 1995) no longer run away.
// - APIC on linear (ED2Q4) cells can run away where particles enter empty cells: use uGIMP cells with APIC.
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "mpm/problem/deck.hpp"
#include "mpm/problem/particle_record.hpp"

namespace mpm::core {

class Engine;  // implementation (mpm/core/engine.hpp)

/// How the engine computes, where the choice cannot change a result (tests and benchmarks compare them).
struct ExecutionOptions {
  /// Four particles on one stencil in the lanes of a 4-double vector (stencil_runs.hpp) where the CPU
  /// has 256-bit registers; false: every particle through the one-particle kernels. Bit for bit the same.
  bool stencil_runs = true;
};

class Simulation {
 public:
  /// Builds particles, grid and materials from `deck`. `threads` <= 0: OpenMP's default.
  /// Applies CB-Geo's defaults to particles with volume <= 0 (volume = cell area / particles in the
  /// cell, mass = density * volume, nsize = 2 / sqrt(particles in the cell)).
  explicit Simulation(const Deck& deck, int threads = 0, ExecutionOptions options = {});
  ~Simulation();
  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// One explicit step. Throws common::NumericalError naming the step, particle id and field on a
  /// NaN or runaway velocity, and on a particle leaving the grid when locate_particles is true
  /// ("step 1234: particle 56 left the grid at (x, y)"). After a throw the state is that of the
  /// last completed step (snapshot() returns the last good state).
  void step();
  /// The loop step that step() will run next (starts at deck.first_step).
  long long step_index() const;
  /// Simulated time of the current state: step_index() * dt() (the state after loop step s is at
  /// t = (s + 1) dt, as in a fresh CB-Geo run), so it is the same after a resume.
  double time() const;
  double dt() const;
  /// dt c_p / h (c_p of the stiffest material, h the smaller cell side): above 1 the step is unstable.
  double courant_number() const;
  std::size_t particle_count() const;
  /// Full particle state in CB-Geo's record form, sorted by particle id (exact doubles).
  std::vector<ParticleRecord> snapshot() const;
  /// The APIC affine matrices B_p (Bxx, Bxy, Byx, Byy, m^2/s) in snapshot() order; empty unless the
  /// transfer is APIC. Written beside the particle table so that a resumed run continues bit for bit.
  std::vector<std::array<double, 4>> affine_snapshot() const;
  /// The lagged friction strengths (lagged_friction.hpp) by node; nullopt unless a friction constraint
  /// has a normal_lag. Written beside the particle table for the same reason.
  std::optional<std::vector<FrictionMemoryRecord>> friction_memory_snapshot() const;
  /// Both of the above, as a particle file carries them.
  ParticleFileExtras file_extras() const { return {affine_snapshot(), friction_memory_snapshot()}; }

 private:
  std::unique_ptr<Engine> engine_;
};

}  // namespace mpm::core
