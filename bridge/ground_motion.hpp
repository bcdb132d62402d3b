#pragma once
// The ground motion that keeps shaking the MPM run after a transfer made during an earthquake
// (fem2mpm --ground-motion): the record the FEM script's UniformExcitation read (an OpenSees
// `timeSeries Path -dt DT -filePath FILE -factor F`), cut at the transfer time and written into the MPM
// deck as CB-Geo's Linear math function with mpm's base_acceleration (mpm/core/body_force.hpp). Both runs
// are then made in the frame of the moving base: UniformExcitation's responses are relative to the
// ground, and so are the MPM's under base_acceleration, so the transferred velocities need no change.
#include <filesystem>
#include <string>
#include <vector>

#include "fem_tcl/domain/time_series_path.hpp"

namespace bridge {

/// A record as OpenSees' `timeSeries Path -dt DT -filePath FILE -factor F` reads it (fem::domain::PathSeries:
/// value k at t = k dt from k = 0, linear between samples, 0 from the last sample's time on: no -useLast),
/// and the UniformExcitation direction it drives.
struct GroundMotion {
  GroundMotion(int dof, double dt, double factor, std::vector<double> values)
      : dof(dof), record(0, std::move(values), dt, factor, false, 0.0) {}
  int dof;  ///< 1 = x, 2 = y
  fem::domain::PathSeries record;
  double at(double t) const { return record.factor(t); }
};

/// Reads `file` (whitespace-separated numbers, any number per line, as OpenSees' -filePath). Throws
/// common::InputError naming the file and line for a word that is not a finite number, an empty file,
/// and naming `option` for dt <= 0 or a dof other than 1 or 2.
GroundMotion read_ground_motion(const std::filesystem::path& file, double dt, double factor, int dof,
                                const std::string& option);

/// The part of the record after the FEM time `t_transfer`, as points (t_mpm, a) of a CB-Geo Linear function
/// with t_mpm = t - t_transfer + t0_mpm (t0_mpm: the MPM time of the transferred state), from the value at
/// t_transfer to a closing zero just after the record's end. Empty when the record ends by t_transfer.
struct MotionTable {
  std::vector<double> t, a;
};
MotionTable motion_after(const GroundMotion& motion, double t_transfer, double t0_mpm);

}  // namespace bridge
