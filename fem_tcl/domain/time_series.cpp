#include "fem_tcl/domain/time_series.hpp"

#include "fem_tcl/domain/time_series_path.hpp"
#include "fem_tcl/domain/time_series_periodic.hpp"

namespace fem::domain {

namespace {

std::shared_ptr<TimeSeries> parse_constant_or_linear(common::CommandArgs& args, bool linear) {
  const int tag = args.integer("tag");
  double cfactor = 1.0;
  while (!args.empty()) {
    if (args.flag("-factor")) cfactor = args.number("-factor value");
    else args.fail("unknown option '" + args.peek() + "'");
  }
  if (linear) return std::make_shared<LinearSeries>(tag, cfactor);
  return std::make_shared<ConstantSeries>(tag, cfactor);
}

}  // namespace

std::shared_ptr<TimeSeries> parse_time_series(common::CommandArgs& args) {
  const std::string type = args.word("type (Constant, Linear, Path, Trig, Rectangular or Pulse)");
  if (type == "Constant" || type == "ConstantSeries") return parse_constant_or_linear(args, false);
  if (type == "Linear" || type == "LinearSeries") return parse_constant_or_linear(args, true);
  if (type == "Path" || type == "Series") return parse_path_series(args);
  if (type == "Trig" || type == "TrigSeries" || type == "Sine" || type == "SineSeries") return parse_trig_series(args);
  if (type == "Rectangular") return parse_rectangular_series(args);
  if (type == "Pulse" || type == "PulseSeries") return parse_pulse_series(args);
  args.fail("unknown timeSeries type '" + type + "' (Constant, Linear, Path, Trig, Sine, Rectangular, Pulse)");
}

}  // namespace fem::domain
