#pragma once
// The FEM state at the transfer time in SI units: what the readers assemble from the model file and
// the recorder rows, and what the mapping (stress_recovery, particle_mapping) works on.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "bridge/quad_geometry.hpp"

namespace bridge {

/// Full stress tensor, Pa, tension positive: sxx syy szz sxy syz sxz.
using Stress6 = std::array<double, 6>;

/// What the MPM side needs of one material (SI units, angles in radians).
struct MpmMaterial {
  enum class Type { LinearElastic2D, MohrCoulomb2D };
  unsigned id = 0;
  std::string fem_name;     ///< the FEM material name it came from
  Type type = Type::LinearElastic2D;
  double density = 0;       ///< kg/m3
  double youngs_modulus = 0, poisson_ratio = 0;  ///< Pa, -
  double friction = 0, dilation = 0;             ///< rad
  double cohesion = 0, tension_cutoff = 0;       ///< Pa
  /// CB-Geo's linear softening (MohrCoulomb2D peak_pdstrain, residual_pdstrain, residual_cohesion): the
  /// cohesion falls from `cohesion` to `residual_cohesion` (Pa) between the plastic deviatoric strains
  /// peak_pdstrain and residual_pdstrain; friction and dilation stay. Unset: no softening.
  struct Softening {
    double residual_cohesion = 0, peak_pdstrain = 0, residual_pdstrain = 0;
  };
  std::optional<Softening> softening;
  /// The particles of this material: how they were chosen (for the report; "" for a FEM material).
  std::string origin;
};

struct TransferElement {
  long tag = 0;
  std::array<int, 4> nodes{};   ///< indices into the node arrays, counter-clockwise (the first node_count)
  int node_count = 4;           ///< 4, or 3 for a triangle until split_triangles makes it three quads
  int gauss_points = 1;         ///< 1 (SSPquad at the centre, Tri31 at the centroid) or 4 (quad, OpenSees order)
  double density = 0;           ///< kg/m3
  unsigned material = 0;        ///< index into TransferState::materials
};

/// The FEM state at the transfer time (SI units).
struct TransferState {
  double time = 0;                        ///< FEM time of the row used
  std::vector<Vec2> reference;            ///< node reference coordinates, m
  std::vector<Vec2> displacement;         ///< m
  std::vector<Vec2> velocity;             ///< m/s
  std::vector<Vec2> load;                 ///< applied nodal loads, N per unit thickness (--loads; empty: none)
  std::vector<TransferElement> elements;
  std::vector<std::size_t> gauss_offset;  ///< element e's Gauss points are [gauss_offset[e], gauss_offset[e+1])
  std::vector<Stress6> gauss_stress;      ///< Pa
  std::vector<MpmMaterial> materials;
  double gravity = 9.81;                  ///< m/s2, acting in -y
  /// u-p models transferred with --pore-pressure (pore_pressure.hpp), else all empty: the pore pressure per
  /// node at the transfer time and at the reference time (Pa, compression positive; 0 at nodes without a
  /// pore-pressure dof), and the effective stress per Gauss point at the reference time (Pa, tension positive),
  /// for sigma'v0. gauss_stress is then the effective stress at the transfer time.
  std::vector<double> pore_pressure, reference_pore_pressure;
  std::vector<Stress6> reference_gauss_stress;
  /// The equivalent deviatoric strain since the reference time per Gauss point (--strain), else empty.
  std::vector<double> gauss_shear_strain;

  Vec2 current(int node) const { return reference[static_cast<std::size_t>(node)] + displacement[static_cast<std::size_t>(node)]; }
  QuadNodes current_nodes(const TransferElement& e) const;
  QuadNodes reference_nodes(const TransferElement& e) const;
  /// Fills gauss_offset from the elements' Gauss point counts.
  void index_gauss_points();
};

/// A new element list for a state, built element by element (triangles split, materials left out): the
/// elements and every per-Gauss-point field of theirs, renumbered together; install() puts them in place.
class RenumberedElements {
 public:
  explicit RenumberedElements(const TransferState& state) : state_(state) {}
  /// Appends element `el` with old Gauss points [g0, g1) (each once, in order).
  void add(const TransferElement& el, std::size_t g0, std::size_t g1);
  bool empty() const { return elements_.empty(); }
  /// The new elements and fields into `state` (the one given to the constructor), Gauss points re-indexed.
  void install(TransferState& state);

 private:
  const TransferState& state_;
  std::vector<TransferElement> elements_;
  std::vector<Stress6> stress_, reference_stress_;
  std::vector<double> shear_strain_;
};

}  // namespace bridge
