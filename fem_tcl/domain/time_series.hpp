#pragma once
// Load factor as a function of (pseudo-)time: OpenSees ConstantSeries and LinearSeries here; Path in
// time_series_path.hpp; Trig, Rectangular and Pulse in time_series_periodic.hpp.
#include <memory>
#include <string>
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

/// `timeSeries Constant|Linear|Path|Series|Trig|Sine|Rectangular|Pulse tag ...` (args start at the type word).
std::shared_ptr<TimeSeries> parse_time_series(common::CommandArgs& args);

}  // namespace fem::domain
