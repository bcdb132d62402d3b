#pragma once
// A run's outputs under <working_dir>/<post_processing.path>/<uuid>/:
//   particles<step>.h5  CB-Geo's particle table ("/table", resumable by CB-Geo and by mpm) plus, for
//                       ParaView, plain datasets under "/xdmf" (XDMF cannot address the members of
//                       a compound dataset, so the fields are repeated as numeric arrays);
//   particles.xdmf      a temporal collection of Polyvertex grids over those files, the first frame
//                       being the start state (initial_state.h5: the generated particles, or the
//                       state resumed from, e.g. the FEM transfer state);
//   grid.vtr            the background grid (VTK RectilinearGrid) with its boundary conditions;
//   particles<step>.vtp + particles.pvd  when post_processing.vtk / vtk_statevars ask for VTK files;
//   series.csv          one row per output step (and the last step): see SeriesRow.
// Every file is written to a temporary name and renamed, so none is ever seen half-written.
#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mpm/problem/deck.hpp"
#include "mpm/io/particle_table.hpp"

namespace mpm::io {

/// One row of series.csv, computed from a particle state alone (so a resumed run writes the same
/// rows as the uninterrupted one). The vertical axis is the grid's last one (y in 2D, z in 3D: CB-Geo's
/// 3D decks hang gravity on z); the horizontal ones are the others.
struct SeriesRow {
  int dim = 2;                    ///< the grid's dimension: which columns the row has (series_header)
  long long step = 0;
  double time = 0;                ///< s
  double runout_x_p98 = 0;        ///< runout L: 98th percentile of particle x, m (numpy's linear percentile)
  double runout_y_p98 = 0;        ///< 3D only: 98th percentile of particle y, m
  double height_p995 = 0;         ///< height H: 99.5th percentile of the particles' vertical coordinate, m
  double potential_energy = 0;    ///< -sum m (g . x), J (per metre in 2D; = sum m |g| y for g = (0, -|g|))
  double kinetic_energy_x = 0;    ///< sum 1/2 m vx^2, J (per metre in 2D)
  double kinetic_energy_y = 0;    ///< sum 1/2 m vy^2
  double kinetic_energy_z = 0;    ///< 3D only: sum 1/2 m vz^2
  double max_speed = 0;           ///< max |v|, m/s
  std::size_t particle_count = 0;
  double dt = 0;                  ///< s
  /// Checkerboard index (dimensionless): the RMS over particles of the deviation of the particle's shear
  /// stresses (tau_xy; in 3D the vector tau_xy, tau_yz, tau_xz) from their mean over the particles in its
  /// grid cell, divided by rho |g| H_col, where rho = sum m / sum V, H_col = height_p995 - the lowest
  /// vertical coordinate (the current column height) and the cell is the lattice cell holding the
  /// particle's centre. 0 for a smooth field; NaN when rho |g| H_col = 0 (no gravity).
  double checkerboard_index = 0;
};

/// numpy.percentile(values, q) with its default linear interpolation; values is reordered.
double percentile(std::vector<double> values, double q);

/// The row of `particles` on `grid`; gravity (m/s2) is (gravity.x, gravity.y, gravity_z), gravity_z
/// counting on a 3D grid only (Analysis::gravity, Analysis::gravity_z).
SeriesRow summarize_state(long long step, double time, double dt, std::span<const ParticleRecord> particles,
                          const Grid& grid, const Eigen::Vector2d& gravity, double gravity_z = 0);

/// The CSV header of series.csv for a grid of `dim` axes. 2D: step, time, runout_x_p98, height_y_p995,
/// potential_energy, kinetic_energy_x, kinetic_energy_y, max_speed, n_particles, dt, checkerboard_index;
/// 3D: runout_y_p98 after runout_x_p98, height_z_p995 for height_y_p995 and kinetic_energy_z after
/// kinetic_energy_y.
const std::string& series_header(int dim = 2);

/// One frame of particles.xdmf (and particles.pvd): a file of the results folder.
struct XdmfFrame {
  long long step;
  double time;
  std::size_t count;
  std::string file;  ///< h5 file name in the results folder
};

class ResultsWriter {
 public:
  /// Touches nothing on disk until the first write.
  explicit ResultsWriter(const Deck& deck);

  std::filesystem::path folder() const { return folder_; }
  std::filesystem::path particle_file(long long step) const;

  /// The state before the first step (the first frame): initial_state.h5 (+ .vtp). A resumed run
  /// whose folder already holds earlier frames keeps those instead.
  void write_start(double time, std::span<const ParticleRecord> particles);
  /// An output step: particles<step>.h5 (unless Output::particle_output_steps leaves it out), then
  /// particles.xdmf and series.csv rewritten. `extras` go beside the file's "/table" (the APIC matrices,
  /// one per record in the same order, and the lagged friction strengths; particle_table.hpp), and so do the
  /// resumed particles' pore pressure rows when the deck has them (resume_extras.hpp carried_pore_pressure).
  void write_output(long long step, double time, double dt, std::span<const ParticleRecord> particles,
                    const ParticleFileExtras& extras = {});
  /// A series.csv row only (the last step of a run when it is not an output step).
  void write_series_row(long long step, double time, double dt, std::span<const ParticleRecord> particles);
  /// The last good state after a numerical failure: particles<step>.h5 (resumable), listed in the XDMF.
  std::filesystem::path write_state(long long step, double time, std::span<const ParticleRecord> particles,
                                    const ParticleFileExtras& extras = {});

 private:
  static constexpr const char* kStartFile = "initial_state.h5";
  void prepare();
  /// Throws common::InputError naming the first output path of the run (the folder, grid.vtr, the start
  /// state, every particle file the output steps will write, series.csv, particles.xdmf / .pvd) that
  /// exists and is not a regular file, before anything is written.
  void check_output_targets() const;
  void write_particles(long long step, double time, std::span<const ParticleRecord> particles,
                       const ParticleFileExtras& extras);
  void add_frame(const XdmfFrame& frame, std::span<const ParticleRecord> particles);
  std::optional<XdmfFrame> read_start_frame() const;
  bool writes_vtk() const;
  static std::string vtp_name(const std::string& h5_name);
  void add_row(const SeriesRow& row);
  void write_series() const;
  void write_xdmf() const;

  const Deck& deck_;
  std::filesystem::path folder_;
  bool prepared_ = false;
  std::vector<std::string> rows_;  ///< formatted series.csv rows
  std::vector<long long> row_steps_;
  std::vector<XdmfFrame> frames_;  ///< sorted by step
};

}  // namespace mpm::io
