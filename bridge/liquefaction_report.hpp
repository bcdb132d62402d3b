#pragma once
// The u-p part of the transfer report (issue 36, item 3): the reference state, the sign convention of the
// particles' total stress, r_u at the particles, the liquefied mass and the largest depth below the ground
// surface where r_u reaches the threshold, the strength of the particles below the threshold (drained, from
// their FEM material) and above it (liquefied_strength.hpp), with the particles per material.
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bridge/liquefied_strength.hpp"
#include "bridge/transfer_state.hpp"
#include "mpm/io/particle_table.hpp"

namespace bridge {

/// The height of the ground surface of the current mesh: at x, the highest point of an element edge above x.
class GroundSurface {
 public:
  explicit GroundSurface(const TransferState& state);
  /// The surface height at x (-inf where no element lies above x).
  double height(double x) const;

 private:
  struct Edge {
    double x0, y0, x1, y1;  ///< x0 <= x1
  };
  std::vector<Edge> edges_;
  std::vector<std::vector<std::size_t>> buckets_;
  double x0_ = 0, width_ = 1;
};

struct LiquefactionReport {
  std::string file;  ///< --pore-pressure
  std::string reference_row, reference_how;
  double reference_time = 0;
  double threshold = 0.7;
  double mass = 0;                ///< kg/m, all particles
  std::size_t liquefied = 0;      ///< particles with r_u > threshold
  double liquefied_mass = 0;      ///< kg/m
  double max_ru = 0;
  double max_ru_x = 0, max_ru_y = 0;
  /// The largest depth below the ground surface (GroundSurface, the current mesh) of a particle with r_u >=
  /// threshold, m, and that particle's position; unset when none.
  std::optional<double> max_depth;
  double max_depth_x = 0, max_depth_y = 0;
  std::size_t no_reference = 0;   ///< particles with sigma'v0 <= 0 (r_u 0)
  LiquefiedSummary strength;
  struct MaterialCount {
    unsigned id = 0;
    std::string text;             ///< type and strength, or the liquefied material's origin
    std::size_t particles = 0;
    double mass = 0;
  };
  std::vector<MaterialCount> drained, liquefied_materials;
};

/// The figures of `particles` (after the strengths were assigned) and their pore pressure rows (same order).
LiquefactionReport make_liquefaction_report(const TransferState& state, std::span<const mpm::ParticleRecord> particles,
                                            std::span<const mpm::PorePressureRecord> rows, double threshold,
                                            std::size_t no_reference, const LiquefiedSummary& strength);

/// The report's lines for the terminal (each starting with two spaces, ending with a newline).
std::string liquefaction_text(const LiquefactionReport& r);

/// report.json's "pore_pressure" object.
nlohmann::ordered_json liquefaction_json(const LiquefactionReport& r);

}  // namespace bridge
