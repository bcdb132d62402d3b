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
/// rows as the uninterrupted one).
struct SeriesRow {
  long long step = 0;
  double time = 0;                ///< s
  double runout_x_p98 = 0;        ///< runout L: 98th percentile of particle x, m (numpy's linear percentile)
  double height_y_p995 = 0;       ///< height H: 99.5th percentile of particle y, m
  double potential_energy = 0;    ///< -sum m (g . x), J per metre (= sum m |g| y for g = (0, -|g|))
  double kinetic_energy_x = 0;    ///< sum 1/2 m vx^2, J per metre
  double kinetic_energy_y = 0;    ///< sum 1/2 m vy^2, J per metre
  double max_speed = 0;           ///< max |v|, m/s
  std::size_t particle_count = 0;
  double dt = 0;                  ///< s
  /// Checkerboard index (dimensionless): the RMS over particles of (tau_xy of the particle minus the
  /// mean tau_xy of the particles in its grid cell), divided by rho |g| H_col, where rho = sum m /
  /// sum V, H_col = height_y_p995 - min y (the current column height) and the cell is the lattice cell
  /// holding the particle's centre. 0 for a smooth field; NaN when rho |g| H_col = 0 (no gravity).
  double checkerboard_index = 0;
};

/// numpy.percentile(values, q) with its default linear interpolation; values is reordered.
double percentile(std::vector<double> values, double q);

SeriesRow summarize_state(long long step, double time, double dt, std::span<const ParticleRecord> particles,
                          const Grid& grid, const Eigen::Vector2d& gravity);

/// The CSV header of series.csv.
const std::string& series_header();

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
