#pragma once
// `timeSeries Path` (OpenSees 3.8 SRC/domain/pattern/PathSeries.cpp OPS_PathSeries, PathSeries.cpp,
// PathTimeSeries.cpp), with OpenSees' choice between the two classes and their end behaviour:
//   -dt dt (-values {..} | -filePath f) <-factor c> <-useLast> <-prependZero> <-startTime t0>  -> PathSeries
//   -time {..} -values {..} | -fileTime ft -filePath fv | -file pairs <-factor c>               -> PathTimeSeries
#include <string>
#include <vector>

#include "common/command_args.hpp"
#include "fem_tcl/domain/time_series.hpp"

namespace fem::domain {

/// Equally spaced values v_k at t0 + k dt (OpenSees PathSeries::getFactor):
///   t < t0 -> 0; s = (t - t0)/dt, k = floor(s); k + 1 >= n -> (useLast ? c v_{n-1} : 0) -- so the last
///   sample's own time already counts as past the end; else c (v_k + (v_{k+1} - v_k)(s - k)).
class PathSeries final : public TimeSeries {
 public:
  PathSeries(int tag, std::vector<double> values, double dt, double cfactor, bool use_last, double start_time);
  double factor(double t) const override;
  double end_time() const { return start_ + dt_ * static_cast<double>(values_.size() - 1); }
  const std::vector<double>& values() const { return values_; }  ///< v_k, before the factor
  double dt() const { return dt_; }
  double cfactor() const { return c_; }
  double start_time() const { return start_; }

 private:
  std::vector<double> values_;
  double dt_, c_;
  bool use_last_;
  double start_;
  mutable bool warned_ = false;
};

/// (time, value) pairs (OpenSees PathTimeSeries::getFactor, its stateful interval walk kept as is):
///   t < t_0 -> 0; t == t_loc -> c v_loc; t > t_last -> (useLast ? c v_last : 0); else linear interpolation
///   in the interval found by walking from the last one.
class PathTimeSeries final : public TimeSeries {
 public:
  PathTimeSeries(int tag, std::vector<double> times, std::vector<double> values, double cfactor, bool use_last);
  double factor(double t) const override;

 private:
  std::vector<double> times_;
  std::vector<double> values_;
  double c_;
  bool use_last_;
  mutable std::size_t loc_ = 0;  ///< OpenSees' currentTimeLoc
  mutable bool warned_ = false;
};

/// `timeSeries Path tag <options>` (args at the tag). Throws common::InputError for a zero or negative -dt,
/// an unreadable file, a file with a non-numeric entry (file and line named), lists of different lengths,
/// decreasing times or no usable choice of options; warns where OpenSees quietly ignores an option.
std::shared_ptr<TimeSeries> parse_path_series(common::CommandArgs& args);

}  // namespace fem::domain
