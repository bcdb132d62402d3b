#pragma once
// The energy audit of a run: where nothing but gravity and fixed or frictional walls acts on the body,
// its mechanical energy can only fall (friction, plasticity, damping and a transfer's own dissipation
// take energy out; nothing puts it in). A numerical instability of the explicit step (a time step too
// large for the scheme, cell-crossing noise feeding a vibration) shows as energy that grows instead, long
// before the velocities run away. The audit compares each output state with the start: a warning when
// the energy has grown by kWarningGrowth, a numerical failure beyond kGrowthLimit.
//
//   E = kinetic + gravitational + elastic strain energy (J per metre of thickness),
//   kinetic   = sum 1/2 m |v|^2,
//   potential = sum m |g| h, h the height above the grid's lowest corner along g (so E >= 0),
//   strain    = sum V w(sigma), w = (1 + nu) / (2 E) sigma:sigma - nu / (2 E) (tr sigma)^2, the
//               complementary energy density of the elastic part (plane strain: sigma_zz included).
// Not audited (active() false, reason() says why): runs with work done from outside, namely nodal forces,
// particle tractions, a shaken base and walls that move (a velocity constraint with a velocity != 0).
#include <span>
#include <string>
#include <vector>

#include "mpm/problem/deck.hpp"
#include "mpm/problem/particle_record.hpp"

namespace mpm::core {

struct MechanicalEnergy {
  double kinetic = 0, potential = 0, strain = 0;
  double total() const { return kinetic + potential + strain; }
};

class EnergyAudit {
 public:
  /// Energy above (1 + kWarningGrowth) times the start's: a warning; above (1 + kGrowthLimit): the stop.
  static constexpr double kWarningGrowth = 0.10;
  static constexpr double kGrowthLimit = 0.25;

  explicit EnergyAudit(const Deck& deck);
  bool active() const { return reason_.empty(); }
  /// Why the run is not audited ("" when it is).
  const std::string& reason() const { return reason_; }

  MechanicalEnergy measure(std::span<const ParticleRecord> particles) const;
  /// Records the start state (the first call) or checks a later one: returns a warning the first time
  /// the energy has grown beyond kWarningGrowth (else ""); throws common::NumericalError naming the
  /// growth, the time and what to change beyond kGrowthLimit.
  std::string check(double time, std::span<const ParticleRecord> particles);

 private:
  std::string reason_;
  Eigen::Vector2d gravity_;
  double lowest_ = 0;  ///< -g . x / |g| of the grid's lowest corner along g (the height datum), m
  std::vector<MaterialSpec> materials_;
  bool started_ = false, warned_ = false;
  double start_time_ = 0, start_ = 0;  ///< time and E of the start state
};

}  // namespace mpm::core
