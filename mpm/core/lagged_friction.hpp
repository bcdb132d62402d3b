#pragma once
// Coulomb friction whose strength follows the normal force with a lag in slip (the simplified
// Prakash-Clifton law: Prakash & Clifton 1993, ASME AMD 165, 33; in the form of Cochard & Rice 2000,
// "Fault rupture between dissimilar materials: ill-posedness, regularization, and slip-pulse
// response", JGR 105(B11), 25891, and Ranjith & Rice 2001, JMPS 49, 341):
//   dN_s/dt = -(|V| + V*) / L (N_s - N),   tangential strength mu N_s,
// with N the normal force, V the slip speed, L the slip over which the strength catches up with a
// change of N and V* a reference speed (the lag in time at rest is L / V*).
//
// Why: sliding with Coulomb friction on an elastic body is ill-posed above a nu-dependent mu (Renardy
// 1992, J. Elasticity 27, 281; Adams 1995; Martins, Guimaraes & Faria 1995): the Poisson coupling of
// tangential traction and normal force grows a flutter faster the finer the grid. Without
// dissipation (FLIP, APIC) a block on CB-Geo's bilateral base stalls (-88 % in v at 2 s) and a block at
// its friction limit creeps 0.1-0.26 m in 1 s; the lag regularises the law (Cochard & Rice show the
// simplified Prakash-Clifton law makes the problem well-posed): mpm/README.md "Friction with a lag".
//
// Opt-in per friction constraint (friction_constraints[].normal_lag); without it the friction is
// CB-Geo's instantaneous Coulomb rule. The memory N_s is held per constrained node (the wall is fixed in
// space): a node that material first touches starts from its instantaneous N, and one it leaves (no mass,
// or a one-sided contact it no longer touches) forgets. The memory is written beside the particle table
// (io::kFrictionMemoryDataset), so that a resumed run continues bit for bit.
#include <cmath>

namespace mpm::core {

/// The lag of one frictional wall; slip_distance 0: none (instantaneous Coulomb).
struct NormalLag {
  double slip_distance = 0.0;       ///< L (m)
  double reference_velocity = 0.0;  ///< V* (m/s)
  bool active() const { return slip_distance > 0.0; }
};

/// A node's lagged normal force N_s; negative: no memory yet (the node has not been touched since the
/// material last left it).
struct NormalMemory {
  double force = -1.0;
  double mass = 0.0;  ///< the node's mass when the force was last updated
  void forget() { force = -1.0; }
};

/// One step of the law, implicit in N_s (unconditionally stable for any dt): N_s <- (N_s + r N) / (1 + r),
/// r = dt (|V| + V*) / L; the first touch starts at N. `mass`: the node's mass now. Where it has fallen
/// (material leaving the node: the contact's area shrinks) N_s falls in proportion first, the lag
/// applying to the traction, not to the area: else the trailing edge of a sliding body keeps the strength
/// of the load it carried and drags it (the block on bilinear cells under USL: -28 % in v at 2 s). Returns
/// the new N_s.
inline double lag_normal_force(NormalMemory& memory, double normal_force, double slip_speed, double dt,
                               const NormalLag& lag, double mass) {
  if (memory.force >= 0.0 && mass < memory.mass) memory.force *= mass / memory.mass;  // material leaving
  memory.mass = mass;
  if (memory.force < 0.0) {
    memory.force = normal_force;
  } else {
    // As the weights 1 / (1 + r) and r / (1 + r): finite for any r, the instantaneous N when r overflows.
    const double r = dt * (std::abs(slip_speed) + lag.reference_velocity) / lag.slip_distance;
    const double keep = 1.0 / (1.0 + r);
    memory.force = keep * memory.force + (1.0 - keep) * normal_force;
  }
  return memory.force;
}

}  // namespace mpm::core
