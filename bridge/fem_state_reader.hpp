#pragma once
// Assembles the TransferState (SI units) from the model description and the recorder files at the
// transfer time: recorder column layouts, the row for the time, stress components per Gauss point,
// units, densities, materials and gravity. Everything the user may get wrong is checked here, before
// any output is written.
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bridge/fem_model.hpp"
#include "bridge/pore_pressure.hpp"
#include "bridge/transfer_state.hpp"

namespace bridge {

/// Unit systems of the FEM files: SI (N, m, s, Pa, kg/m3) or kN (kN, m, s, kPa, Mg/m3: stresses,
/// moduli and densities x 1000 to SI).
enum class Units { SI, kN };

/// Material data given on the command line; they complete or replace what the model file says
/// (values in the FEM units; angles in degrees). They apply to every FEM material.
struct MaterialOverrides {
  std::optional<std::string> type;  ///< "elastic" or "mohr-coulomb"
  std::optional<double> E, nu, density, phi_deg, cohesion, psi_deg, tension;
};

struct ReadOptions {
  std::filesystem::path disp, vel, stress;  ///< vel may be empty (zero velocities)
  /// A Node recorder of `unbalance` (the applied nodal loads); empty: no loads carried over.
  std::filesystem::path loads;
  std::optional<double> time;               ///< transfer time; neither time nor row: the last row
  std::optional<long> row;                  ///< 1-based row (negative from the end)
  std::optional<std::vector<long>> nodes;   ///< the Node recorders' node order (default: all, tag order)
  std::optional<std::vector<long>> elements;///< the Element recorder's element order (default: all, tag order)
  Units units = Units::SI;
  MaterialOverrides material;
  /// Per FEM material (by its name/tag in the model file; `--material 2:phi=30`): applied after `material`.
  std::map<std::string, MaterialOverrides> per_material;
  std::optional<double> gravity;            ///< m/s2; default from the body forces, else 9.81
  /// With 3 stress components per Gauss point: szz = nu (sxx + syy) (plane strain, default) or 0
  /// (plane-stress FEM models).
  bool plane_stress = false;
  /// A u-p model's pore pressure and reference state (pore_pressure.hpp); unset: a dry transfer.
  std::optional<PorePressureOptions> pore_pressure;
};

struct AssembledState {
  TransferState state;
  std::string source_row;                   ///< "<disp file>:<line>" of the row used, for messages
  int stress_components = 3;                ///< values per Gauss point in the stress file (3, 5 or 6)
  std::size_t triangles_split = 0;          ///< Tri31 elements mapped as 3 quads each (split_triangles)
  std::vector<std::string> notes;           ///< what the user should know (derived szz, zero velocity, ...)
  std::vector<std::string> warnings;        ///< suspicious input (units)
  /// u-p transfers: the reference row ("<disp file>:<line>"), its time and how it was found.
  std::string reference_row, reference_how;
  double reference_time = 0;
};

/// Throws common::InputError naming the file and line (or option) on any inconsistency.
AssembledState read_fem_state(const FemModel& model, const ReadOptions& options);

/// Throws InputError("<where>: [type: ]expected elastic or mohr-coulomb, got ...") unless `type` is one of them.
void check_material_type(const std::string& type, const std::string& where, const std::string& key_prefix = "");

/// Parses one `--material NAME:key=value[,key=value...]` (keys type, E, nu, density, phi, cohesion or c, psi,
/// tension; values in the FEM units, angles in degrees) into `into[NAME]`. Throws InputError naming `option`.
void parse_material_override(const std::string& text, const std::string& option,
                             std::map<std::string, MaterialOverrides>& into);

/// Parses a tag list "1-35,40 42" (commas or spaces, a-b ranges). Throws InputError naming `option`.
std::vector<long> parse_tag_list(const std::string& text, const std::string& option);

}  // namespace bridge
