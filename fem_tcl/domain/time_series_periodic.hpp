#pragma once
// Closed-form time series of OpenSees 3.8 (SRC/domain/pattern/TrigSeries.cpp, RectangularSeries.cpp,
// PulseSeries.cpp), with their formulas as written there:
//   Trig/Sine tag tStart tEnd period <-phaseShift p> <-factor c> <-zeroShift z>:
//     tStart <= t <= tEnd: c sin(2 pi (t - tStart)/T + phi) + z, phi = p - T/(2 pi) asin(z/c); else 0
//   Rectangular tag tStart tEnd <-factor c>: c on [tStart, tEnd], else 0
//   Pulse tag tStart tEnd period <-width w> <-phaseShift p> <-factor c> <-zeroShift z>:
//     on [tStart, tEnd], k = frac((t + p - tStart)/T): c + z for k < w, z otherwise; else 0
#include "common/command_args.hpp"
#include "fem_tcl/domain/time_series.hpp"

namespace fem::domain {

class TrigSeries final : public TimeSeries {
 public:
  TrigSeries(int tag, double t_start, double t_end, double period, double phase, double cfactor, double zero_shift);
  double factor(double t) const override;

 private:
  double t_start_, t_end_, period_, phase_, c_, zero_;
};

class RectangularSeries final : public TimeSeries {
 public:
  RectangularSeries(int tag, double t_start, double t_end, double cfactor)
      : TimeSeries(tag), t_start_(t_start), t_end_(t_end), c_(cfactor) {}
  double factor(double t) const override { return t >= t_start_ && t <= t_end_ ? c_ : 0.0; }

 private:
  double t_start_, t_end_, c_;
};

class PulseSeries final : public TimeSeries {
 public:
  PulseSeries(int tag, double t_start, double t_end, double period, double width, double phase, double cfactor,
              double zero_shift)
      : TimeSeries(tag), t_start_(t_start), t_end_(t_end), period_(period), width_(width), phase_(phase),
        c_(cfactor), zero_(zero_shift) {}
  double factor(double t) const override;

 private:
  double t_start_, t_end_, period_, width_, phase_, c_, zero_;
};

/// `timeSeries Trig|Sine|Rectangular|Pulse tag ...` (args at the tag). A zero period is an error (OpenSees
/// replaces it by pi for Trig and 1 for Pulse with a warning).
std::shared_ptr<TimeSeries> parse_trig_series(common::CommandArgs& args);
std::shared_ptr<TimeSeries> parse_rectangular_series(common::CommandArgs& args);
std::shared_ptr<TimeSeries> parse_pulse_series(common::CommandArgs& args);

}  // namespace fem::domain
