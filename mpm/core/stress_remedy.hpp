#pragma once
// Checkerboard remedies (analysis.stress_smoothing): corrections of the particles' strain increments
// (dexx, deyy, dgxy) before the material's stress update. The engine (engine.cpp update_stress) hands
// them one cell's particles at a time (cell remedies) or maps the values they name through the nodes
// and back (nodal remedies); the arithmetic lives here, free of the engine's threading and storage.
//
// Why a remedy is needed: with many particles per cell the bilinear (or uGIMP) velocity field of a
// cell must satisfy the nearly isochoric plastic flow of Mohr-Coulomb (psi = 0) at every particle:
// the cell locks volumetrically and the pressure, and through the yield surface the shear stress,
// oscillates from particle to particle (the checkerboard of Sordo, Rathje & Kumar, Figure 9). Within
// a cell the shear increment also varies linearly with the position (the parasitic shear of bilinear
// elements in bending, e.g. Cook, Malkus, Plesha & Witt 2002, Concepts and Applications of FEA, 6.13).
#include <cstddef>
#include <string>

namespace mpm::core {

/// Checkerboard remedies selectable with analysis.stress_smoothing.
enum class StressSmoothing {
  None,
  /// "cell_volumetric": every particle of a cell gets the cell's volume-weighted mean volumetric strain
  /// increment (its deviatoric increment is kept): the cell-constant dilatation of the B-bar / F-bar
  /// family (Hughes 1980, IJNME 15, the B-bar method; in MPM: Coombs, Charlton, Cortis & Augarde 2018,
  /// "Overcoming volumetric locking in material point methods", CMAME 333), which removes the
  /// particle-to-particle pressure oscillation inside a cell.
  CellVolumetric,
  /// "nodal_strain": mass-weighted nodal smoothing of the strain increment (all three components):
  /// de_i = sum_p m_p N_ip de_p / m_i at the nodes, then de_p = sum_i N_ip de_i back at the particles
  /// (the projection CB-Geo's pressure_smoothing applies to the pressure, include/particles/particle.tcc
  /// map_pressure_to_nodes / compute_pressure_smoothing, here for the strain increment). Its null space
  /// holds the grid's 2h velocity modes (v_i alternating from node to node: their smoothed strain is
  /// zero), which meet no stiffness and grow on fine grids; see docs/study/README.md.
  NodalStrain,
  /// "nodal_volumetric": the volumetric increment smoothed through the nodes, volume-weighted,
  /// dv_i = sum_p V_p N_ip dv_p / sum_p V_p N_ip, dv_p = sum_i N_ip dv_i, the deviatoric increment kept:
  /// the F-bar volume averaging on the grid of Zhao, Jiang & Choo (2023, "Circumventing volumetric
  /// locking in explicit material point methods", IJNME 124), here in rate (increment) form. The
  /// deviatoric part keeps its full stiffness, so no velocity mode goes unresisted.
  NodalVolumetric,
  /// "cell_strain": the cell-mean (volume-weighted) strain increment, i.e. the strain at the cell
  /// centre of a one-point rule, plus kCellStrainStabilization times each particle's deviatoric
  /// deviation from it (its volumetric deviation is dropped, as in cell_volumetric). The fraction keeps
  /// the hourglass modes of the cell (zero mean strain) stiff, as the assumed-strain hourglass control
  /// of one-point elements does (Belytschko & Bindeman 1993, CMAME 105; Flanagan & Belytschko 1981,
  /// IJNME 17), and scales the parasitic within-cell shear by the same fraction.
  CellStrain,
};

/// The share of the deviatoric within-cell variation cell_strain keeps (hourglass stiffness).
inline constexpr double kCellStrainStabilization = 0.1;

/// Parses analysis.stress_smoothing; throws common::InputError naming the key otherwise.
StressSmoothing parse_stress_smoothing(const std::string& name);

/// True for the remedies that work on each cell's particles (cell_volumetric, cell_strain).
bool is_cell_remedy(StressSmoothing s);

/// How a nodal remedy maps the particles' values: how many (<= 3) and whether the particle weight is
/// its volume (else its mass, normalised by the nodal mass). 0 values: not a nodal remedy.
struct NodalProjection {
  int values = 0;
  bool volume_weighted = false;
};
NodalProjection nodal_projection(StressSmoothing s);

/// The values a nodal remedy maps for a particle with strain increment de.
void nodal_values(StressSmoothing s, const double* de, double* values);

/// Replaces the particle's increment de using the values interpolated back from the nodes.
void apply_nodal_values(StressSmoothing s, const double* smoothed, double* de);

/// A cell remedy on one cell's n particles: de holds 3 values per particle, volume(i) is the volume of
/// the cell's i-th particle. A uniform increment is left exactly as it is.
template <class VolumeOf>
void apply_cell_remedy(StressSmoothing s, double* de, std::size_t n, VolumeOf&& volume);

// --- the kernels behind apply_cell_remedy (declared for the unit tests) ---

/// Volume-weighted mean of the cell's increments (3 components).
template <class VolumeOf>
void cell_mean_strain(const double* de, std::size_t n, VolumeOf&& volume, double mean[3]);
/// cell_volumetric: dexx + deyy := mean_v for every particle, split equally (deviatoric part kept).
void set_volumetric(double* de, std::size_t n, double mean_v);
/// cell_strain: de := mean + keep * dev(de - mean).
void blend_to_cell_mean(double* de, std::size_t n, const double mean[3], double keep);

template <class VolumeOf>
void cell_mean_strain(const double* de, std::size_t n, VolumeOf&& volume, double mean[3]) {
  double vsum = 0.0, sum[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const double V = volume(i);
    vsum += V;
    for (int f = 0; f < 3; ++f) sum[f] += V * de[3 * i + f];
  }
  for (int f = 0; f < 3; ++f) mean[f] = sum[f] / vsum;
}

template <class VolumeOf>
void apply_cell_remedy(StressSmoothing s, double* de, std::size_t n, VolumeOf&& volume) {
  if (s == StressSmoothing::CellVolumetric) {
    // The volume-weighted mean volumetric increment (summed as one value: the historical arithmetic).
    double vsum = 0.0, dvsum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double V = volume(i);
      vsum += V;
      dvsum += V * (de[3 * i] + de[3 * i + 1]);
    }
    set_volumetric(de, n, dvsum / vsum);
  } else if (s == StressSmoothing::CellStrain) {
    double mean[3];
    cell_mean_strain(de, n, volume, mean);
    blend_to_cell_mean(de, n, mean, kCellStrainStabilization);
  }
}

}  // namespace mpm::core
