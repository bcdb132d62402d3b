#pragma once
// The explicit MPM engine: one Simulation per run, built from a validated io::Deck.
//
// A step reads as the algorithm (Sulsky, Chen & Schreyer 1994; Bardenhagen & Kober 2004 for uGIMP;
// USF/USL/MUSL as in CB-Geo's include/solvers/mpm_scheme/*.tcc):
//   USF : reset_grid  p2g_mass_momentum  velocity_bc  nodal_velocity  update_stress  p2g_forces  integrate_grid  g2p
//   USL : reset_grid  p2g_mass_momentum  velocity_bc  nodal_velocity  p2g_forces  integrate_grid  g2p  update_stress
//   MUSL: reset_grid  p2g_mass_momentum  velocity_bc  nodal_velocity  p2g_forces  integrate_grid  g2p
//         remap_momentum (p2g of updated particle momentum)  update_stress
// Particles are stored as structure-of-arrays, sorted by cell then id each step (deterministic; the
// order depends only on the state that the snapshot records, so a resume continues bit-identically).
#include <cstddef>
#include <memory>
#include <vector>

#include "mpm/io/deck.hpp"
#include "mpm/io/particle_table.hpp"

namespace mpm::core {

class Engine;  // implementation (mpm/core/engine.hpp)

class Simulation {
 public:
  /// Builds particles, grid and materials from `deck`. `threads` <= 0: OpenMP's default.
  /// Applies CB-Geo's defaults to particles with volume <= 0 (volume = cell area / particles in the
  /// cell, mass = density * volume, nsize = 2 / sqrt(particles in the cell)).
  explicit Simulation(const io::Deck& deck, int threads = 0);
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
  std::size_t particle_count() const;
  /// Full particle state in CB-Geo's record form, sorted by particle id (exact doubles).
  std::vector<io::ParticleRecord> snapshot() const;

 private:
  std::unique_ptr<Engine> engine_;
};

}  // namespace mpm::core
