#pragma once
// The strength of the liquefied particles (issue 36, item 2). A particle whose excess pore pressure ratio at
// the transfer is r_u > threshold (--liquefied, default 0.7: the authors' criterion, Sordo, Rathje & Kumar,
// arXiv 2412.08040) becomes a CB-Geo MohrCoulomb2D particle with phi = 0, psi = 0 and a cohesion Sr, the
// residual (steady-state) undrained strength of the liquefied soil, by one of three rules:
//   (a) table: the authors' bins of sigma'v0 with a peak and a residual cohesion per bin, softening linearly
//       between two plastic deviatoric strains (--liquefied-table, format in bridge/README.md; their transfer
//       script bts2222/FEM-MPM-Transfer uses 50 kPa bins);
//   (b) ratio: Sr = R sigma'v0 (--residual-ratio R; the liquefied strength ratio of Olson & Stark 2002,
//       "Liquefied strength ratio from liquefaction flow failure case histories", Can. Geotech. J. 39,
//       629-647: su(LIQ)/sigma'vo = 0.03 + 0.0075 (N1)60 +- 0.03 for (N1)60 <= 12, i.e. about 0.05 to 0.12);
//   (c) penetration: Sr / sigma'v0 from (N1)60cs-Sr per FEM material (--residual-n160cs), Idriss & Boulanger
//       2008, "Soil Liquefaction During Earthquakes", EERI MNO-12, section on residual shear strength (the
//       same relations as Idriss & Boulanger 2007, 4th ICEGE, paper 1166):
//         void redistribution could be significant (default):
//           Sr / sigma'vc = exp(N / 16 + ((N - 16) / 21.2)^3 - 3.0)
//         void redistribution negligible:
//           Sr / sigma'vc = exp(N / 16 + ((N - 16) / 21.2)^3 - 3.0) (1 + exp(N / 2.4 - 6.6))
//       both at most tan(phi') (the drained friction angle of the particle's FEM material), N = (N1)60cs-Sr.
// Rules (b) and (c) give a residual strength only: --liquefied-softening K E1 E2 makes the peak K Sr,
// softening to Sr between E1 and E2 (default none). A particle's equivalent deviatoric strain since the
// reference state (pore_pressure.hpp, --strain) starts its softening (svars pdstrain, and its cohesion the
// softened one there, as mpm's MohrCoulomb computes it); without --strain it starts at 0.
// --effective-friction: the particles below the threshold keep their FEM material's drained friction angle on
// their effective stress at the transfer, as a slope-stability analysis with a pore-pressure ratio does
// (Bishop & Morgenstern 1960, Geotechnique 10(4) 129-150): MPM carries the total stress and no pore pressure,
// so a particle with pore pressure p and total mean stress sigma_m (compression positive) gets
// tan(phi_eq) = (1 - p / sigma_m) tan(phi') (the pore pressure of the transfer held); without it they keep
// phi' on the total stress (the and the authors' choice), which counts the pore pressure as contact
// stress. tan(phi_eq) is rounded to the same kind of grid as Sr, one material per FEM material and value.
// Particles of equal strength share one MPM material: rule (a) one per FEM material and bin; rules (b) and
// (c) Sr rounded to a geometric grid of relative step --strength-step (default 0.05: within 2.5 % of each
// particle's Sr), one material per FEM material and grid value, the step widened until there are at most
// --max-liquefied-materials (default 20) of them. Liquefied materials keep their FEM material's
// density, E and nu; their tension cutoff is 0 (a liquefied soil carries no tension).
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bridge/particle_mapping.hpp"
#include "bridge/transfer_state.hpp"
#include "mpm/io/particle_table.hpp"

namespace bridge {

/// One row of the strength table, SI: particles with sigma'v0 below `sigma_v0_upper` (and at or above the
/// previous row's) get a cohesion softening from `peak_cohesion` to `residual_cohesion` (Pa) between the plastic
/// deviatoric strains `peak_pdstrain` and `residual_pdstrain`.
struct StrengthBin {
  double sigma_v0_upper = 0;  ///< Pa, may be +inf
  double peak_cohesion = 0, residual_cohesion = 0;
  double peak_pdstrain = 0, residual_pdstrain = 0;
};

/// Parses a strength table (CSV; bridge/README.md): '#' comments and blank lines, a header naming the columns
/// sigma_v0_upper_<u>,peak_cohesion_<u>,residual_cohesion_<u>,peak_pdstrain,residual_pdstrain with <u> kPa or Pa,
/// then one row per bin, upper bounds strictly increasing. Throws common::InputError "<shown>:<line>: ..." at
/// the first bad line.
std::vector<StrengthBin> parse_strength_table(const std::string& text, const std::string& shown);
/// Reads and parses `file` (an InputError naming it when it cannot be read).
std::vector<StrengthBin> read_strength_table(const std::filesystem::path& file);

enum class VoidRedistribution { Significant, Negligible };

/// Idriss & Boulanger (2008) Sr / sigma'vc for N = (N1)60cs-Sr (above), before the tan(phi') cap.
double idriss_boulanger_residual_ratio(double n160cs, VoidRedistribution v);

struct LiquefiedOptions {
  double threshold = 0.7;  ///< r_u above it: liquefied
  enum class Rule { None, Table, Ratio, Penetration } rule = Rule::None;
  std::vector<StrengthBin> table;
  std::string table_file;  ///< for messages
  double ratio = 0;        ///< rule Ratio: Sr / sigma'v0
  std::map<std::string, double> n160cs;  ///< rule Penetration: (N1)60cs-Sr per FEM material name
  VoidRedistribution void_redistribution = VoidRedistribution::Significant;
  /// Rules Ratio and Penetration: peak cohesion = peak_factor Sr, softening to Sr between pd_peak and
  /// pd_residual (peak_factor 1: no softening).
  double peak_factor = 1, pd_peak = 0, pd_residual = 0;
  double strength_step = 0.05;  ///< relative step of the Sr grid (rules Ratio and Penetration)
  /// At most this many liquefied materials of rules Ratio and Penetration: the grid's step is widened (by
  /// factors of 1.25 in log) until the particles' strengths fall on at most this many grid values. The same
  /// bound applies, separately, to the materials of --effective-friction.
  std::size_t max_materials = 20;
  /// --effective-friction: the friction of the particles below the threshold reduced by their pore pressure.
  bool effective_friction = false;
};

/// Checks the options alone (threshold finite, ratio > 0, factor >= 1, strain range, step in (0, 1]); throws
/// common::InputError naming the option.
void check_liquefied_options(const LiquefiedOptions& options);

/// What the liquefied particles became.
struct LiquefiedSummary {
  std::string rule;                 ///< the rule with its source, one line
  std::size_t liquefied = 0;        ///< particles with r_u > threshold
  std::size_t softened_at_start = 0;///< liquefied particles that start past their peak strain (--strain)
  std::vector<unsigned> materials;  ///< ids of the liquefied materials made (state.materials), in id order
  std::string effective_friction;   ///< --effective-friction: what it did, one line ("" without it)
  std::vector<unsigned> effective_materials;  ///< ids of its materials, in id order
  std::vector<std::string> warnings;
};

/// Marks the particles with r_u > options.threshold (rows, in particle order) and, with a rule, gives them
/// their liquefied material (appended to state.materials, ids after the FEM materials'): material_id, the 7
/// Mohr-Coulomb state variables of their (total) stress, pdstrain = shear_strain (empty: 0) and the cohesion
/// softened to it. Throws common::InputError naming the option or table file (a particle above the table's
/// last bin, a material without (N1)60cs).
LiquefiedSummary assign_liquefied_strength(TransferState& state, std::span<mpm::ParticleRecord> particles,
                                           std::span<const mpm::PorePressureRecord> rows,
                                           std::span<const double> shear_strain, const LiquefiedOptions& options);

/// Orders the particles by material (stable: within a material in their previous order) and renumbers their
/// ids 0, 1, ..., as the deck's one particle file per material needs. Returns the order: new particle k was
/// particle order[k].
std::vector<std::size_t> group_by_material(ParticleList& particles);

}  // namespace bridge
