#pragma once
// The pore pressure of a u-p FEM model (OpenSees / fem_tcl SSPquadUP and FourNodeQuadUP; FORMATS.md section 6)
// carried to the particles (issue 36, item 1):
// - the nodal pore pressure p (dof 3 of the 3-dof nodes, which OpenSees stores as the dof's VELOCITY: recorded
//   with `recorder Node ... -dof 3 vel`; compression positive) at the transfer row and at the reference row
//   (the end of the gravity stage: the hydrostatic p0), read from `--pore-pressure`;
// - per particle: p and p0 from the element's nodes with its bilinear shape functions at the particle (the
//   field the u-p element itself interpolates, Zienkiewicz, Taylor & Zhu 2013, sec. 6.3); sigma'v0 = -sigma'yy
//   of the reference row's effective stress, recovered to the nodes and interpolated like the stress
//   (--recovery); r_u = (p - p0) / sigma'v0 (the authors' definition: Sordo, Rathje & Kumar, arXiv 2412.08040,
//   and their transfer script bts2222/FEM-MPM-Transfer);
// - the particle's TOTAL stress sigma = sigma' - p I in CB-Geo's convention (tension positive, so the pore
//   pressure, compression positive, is subtracted from the three normal stresses); the shear stresses are
//   the effective ones.
// Units: Pa; p, p0 and sigma'v0 compression positive.
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bridge/fem_model.hpp"
#include "bridge/particle_mapping.hpp"
#include "bridge/recorder_file.hpp"
#include "bridge/recorder_rows.hpp"
#include "bridge/transfer_state.hpp"
#include "mpm/io/particle_table.hpp"

namespace bridge {

/// The u-p inputs (fem2mpm --pore-pressure, --pp-nodes, --reference-time, --strain).
struct PorePressureOptions {
  std::filesystem::path file;                  ///< Node recorder: -time ... -dof 3 vel
  /// Its column order; default: every 3-dof node of the model in tag order (a mixed model has 2-dof nodes too).
  std::optional<std::vector<long>> nodes;
  /// The reference row's time; default: the end of the gravity stage (recorder_rows.hpp pick_reference_row).
  std::optional<double> reference_time;
  /// Element recorder of `strain` (3 values per Gauss point, exx eyy gamma_xy; or 6, exx eyy ezz gxy gyz gxz),
  /// in the stress file's element order: the equivalent deviatoric strain since the reference row starts the
  /// softening of the liquefied particles. Empty: they start at 0.
  std::filesystem::path strain;
};

/// The column layout of the pore-pressure file: node tags, in order (options.nodes, or every 3-dof node in tag
/// order). Throws common::InputError naming --pp-nodes for a tag that is not in the model or has fewer than 3
/// dofs, or the model file when it has no 3-dof node.
std::vector<long> pore_pressure_layout(const FemModel& model, const PorePressureOptions& options);

/// Reads `file`'s rows matching `transfer` and `reference` of `disp` into state.pore_pressure and
/// state.reference_pore_pressure (one value per model node, times `factor` to Pa; 0 at nodes not in the
/// layout). Throws common::InputError naming the file and line when a row's length disagrees with the layout.
void read_nodal_pore_pressure(const FemModel& model, const PorePressureOptions& options, const RecorderFile& disp,
                              const TransferRow& transfer, const TransferRow& reference, double factor,
                              TransferState& state, std::vector<std::string>& notes);

/// The equivalent deviatoric strain sqrt(2/3 e:e) of the strain increment between two rows of an element
/// strain recorder, per Gauss point (e the deviator of d eps, plane strain: d eps_zz = 0 unless recorded;
/// engineering shear strains in the file). `components` is 3 or 6 per Gauss point.
std::vector<double> equivalent_shear_strain(std::span<const double> now, std::span<const double> before, int components);

/// What every particle carries of the pore pressure.
struct ParticlePorePressure {
  std::vector<mpm::PorePressureRecord> rows;  ///< one per particle, in generate_particles' (id) order
  std::vector<double> shear_strain;               ///< per particle; empty without --strain
  std::size_t no_reference = 0;                   ///< particles with sigma'v0 <= 0 (r_u set to 0 there)
};

/// p, sigma'v0, r_u (and the equivalent deviatoric strain) at every particle of generate_particles(state,
/// ..., options), in the same order. The state must hold the u-p fields (read_fem_state with pore_pressure).
ParticlePorePressure particle_pore_pressure(const TransferState& state, const MappingOptions& options);

/// sigma = sigma' - p I on every particle (CB-Geo: tension positive); a Mohr-Coulomb particle's epsilon
/// (sqrt(3) x mean stress) follows.
void apply_total_stress(std::span<mpm::ParticleRecord> particles, std::span<const mpm::PorePressureRecord> rows);

}  // namespace bridge
