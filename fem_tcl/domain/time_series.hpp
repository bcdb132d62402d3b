#pragma once
// Load factor as a function of (pseudo-)time: OpenSees ConstantSeries, LinearSeries, PathSeries / PathTimeSeries.
#include <memory>
#include <vector>

#include "common/command_args.hpp"

namespace fem::domain {

class TimeSeries {
 public:
  explicit TimeSeries(int tag) : tag_(tag) {}
  virtual ~TimeSeries() = default;
  int tag() const { return tag_; }
  virtual double factor(double time) const = 0;

 private:
  int tag_;
};

class ConstantSeries final : public TimeSeries {
 public:
  ConstantSeries(int tag, double cfactor) : TimeSeries(tag), c_(cfactor) {}
  double factor(double) const override { return c_; }

 private:
  double c_;
};

/// factor(t) = c t.
class LinearSeries final : public TimeSeries {
 public:
  LinearSeries(int tag, double cfactor) : TimeSeries(tag), c_(cfactor) {}
  double factor(double t) const override { return c_ * t; }

 private:
  double c_;
};

/// Piecewise-linear interpolation of (time, value) pairs, scaled by cfactor; 0 outside [t_first, t_last]
/// (quirk 11). Equally spaced values (-dt) start at startTime.
class PathSeries final : public TimeSeries {
 public:
  PathSeries(int tag, std::vector<double> times, std::vector<double> values, double cfactor);
  double factor(double t) const override;

 private:
  std::vector<double> times_;
  std::vector<double> values_;
  double c_;
  mutable std::size_t last_ = 0;  ///< interval hint (monotone time in analyses)
};

/// `timeSeries Constant|Linear|Path tag ...` (args start at the type word).
std::shared_ptr<TimeSeries> parse_time_series(common::CommandArgs& args);

}  // namespace fem::domain
