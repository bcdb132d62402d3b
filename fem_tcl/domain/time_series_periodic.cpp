#include "fem_tcl/domain/time_series_periodic.hpp"

#include <cmath>

namespace fem::domain {

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;

struct Window {
  double t_start, t_end;
};

Window read_window(common::CommandArgs& args) {
  const double a = args.number("tStart"), b = args.number("tEnd");
  if (!std::isfinite(a) || !std::isfinite(b)) args.fail("expected finite tStart and tEnd");
  return {a, b};
}

double read_period(common::CommandArgs& args) {
  const double T = args.number("period");
  if (!(T != 0.0) || !std::isfinite(T)) args.fail("expected a finite, non-zero period");
  return T;
}
}  // namespace

TrigSeries::TrigSeries(int tag, double t_start, double t_end, double period, double phase, double cfactor,
                       double zero_shift)
    : TimeSeries(tag), t_start_(t_start), t_end_(t_end), period_(period), phase_(phase), c_(cfactor),
      zero_(zero_shift) {}

double TrigSeries::factor(double t) const {
  if (t < t_start_ || t > t_end_) return 0.0;
  const double phi = zero_ == 0.0 ? phase_ : phase_ - period_ / kTwoPi * std::asin(zero_ / c_);
  return c_ * std::sin(kTwoPi * (t - t_start_) / period_ + phi) + zero_;
}

double PulseSeries::factor(double t) const {
  if (t < t_start_ || t > t_end_) return 0.0;
  const double s = (t + phase_ - t_start_) / period_;
  const double k = s - std::floor(s);
  if (k < width_) return c_ + zero_;
  if (k < 1.0) return zero_;
  return 0.0;
}

std::shared_ptr<TimeSeries> parse_trig_series(common::CommandArgs& args) {
  const int tag = args.integer("tag");
  const Window w = read_window(args);
  const double T = read_period(args);
  double phase = 0.0, c = 1.0, zero = 0.0;
  while (!args.empty()) {
    if (args.flag("-phaseShift") || args.flag("-shift")) phase = args.number("-phaseShift value");
    else if (args.flag("-factor")) c = args.number("-factor value");
    else if (args.flag("-zeroShift")) zero = args.number("-zeroShift value");
    else args.fail("unknown option '" + args.peek() + "'");
  }
  if (zero != 0.0 && !(std::abs(zero) <= std::abs(c))) args.fail("-zeroShift must not exceed -factor in magnitude (asin)");
  return std::make_shared<TrigSeries>(tag, w.t_start, w.t_end, T, phase, c, zero);
}

std::shared_ptr<TimeSeries> parse_rectangular_series(common::CommandArgs& args) {
  const int tag = args.integer("tag");
  const Window w = read_window(args);
  double c = 1.0;
  while (!args.empty()) {
    if (args.flag("-factor")) c = args.number("-factor value");
    else args.fail("unknown option '" + args.peek() + "'");
  }
  return std::make_shared<RectangularSeries>(tag, w.t_start, w.t_end, c);
}

std::shared_ptr<TimeSeries> parse_pulse_series(common::CommandArgs& args) {
  const int tag = args.integer("tag");
  const Window w = read_window(args);
  const double T = read_period(args);
  double width = 0.5, phase = 0.0, c = 1.0, zero = 0.0;
  while (!args.empty()) {
    if (args.flag("-width")) width = args.number("-width value");
    else if (args.flag("-phaseShift") || args.flag("-shift")) phase = args.number("-phaseShift value");
    else if (args.flag("-factor")) c = args.number("-factor value");
    else if (args.flag("-zeroShift")) zero = args.number("-zeroShift value");
    else args.fail("unknown option '" + args.peek() + "'");
  }
  return std::make_shared<PulseSeries>(tag, w.t_start, w.t_end, T, width, phase, c, zero);
}

}  // namespace fem::domain
