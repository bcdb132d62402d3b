#include "fem_tcl/domain/time_series.hpp"

#include <fstream>
#include <sstream>

namespace fem::domain {

PathSeries::PathSeries(int tag, std::vector<double> times, std::vector<double> values, double cfactor)
    : TimeSeries(tag), times_(std::move(times)), values_(std::move(values)), c_(cfactor) {}

double PathSeries::factor(double t) const {
  const std::size_t n = times_.size();
  if (n == 0 || t < times_.front() || t > times_.back()) return 0.0;
  if (n == 1) return c_ * values_[0];
  if (last_ + 1 >= n || times_[last_] > t) last_ = 0;
  while (last_ + 2 < n && times_[last_ + 1] < t) ++last_;
  const double t0 = times_[last_], t1 = times_[last_ + 1];
  const double v0 = values_[last_], v1 = values_[last_ + 1];
  if (t1 == t0) return c_ * v1;
  return c_ * (v0 + (v1 - v0) * (t - t0) / (t1 - t0));
}

namespace {

std::vector<double> parse_list(common::CommandArgs& args, std::string_view what) {
  const std::string text = args.word(what);
  std::istringstream in(text);
  std::vector<double> out;
  std::string token;
  while (in >> token) {
    const auto v = common::CommandArgs::parse_finite_number(token);
    if (!v) args.fail("expected a list of finite numbers for " + std::string(what) + ", got '" + token + "'");
    out.push_back(*v);
  }
  return out;
}

std::vector<double> read_file_values(common::CommandArgs& args, const std::string& path) {
  std::ifstream in(path);
  if (!in) args.fail("cannot open file '" + path + "'");
  std::vector<double> out;
  std::string token;
  while (in >> token) {
    const auto v = common::CommandArgs::parse_finite_number(token);
    if (!v) args.fail("file '" + path + "': expected finite numbers, got '" + token + "'");
    out.push_back(*v);
  }
  return out;
}

}  // namespace

std::shared_ptr<TimeSeries> parse_time_series(common::CommandArgs& args) {
  const std::string type = args.word("type (Constant, Linear or Path)");
  const int tag = args.integer("tag");
  double cfactor = 1.0;
  if (type == "Constant" || type == "Linear") {
    while (!args.empty()) {
      if (args.flag("-factor")) cfactor = args.number("-factor value");
      else args.fail("unknown option '" + args.peek() + "'");
    }
    if (type == "Constant") return std::make_shared<ConstantSeries>(tag, cfactor);
    return std::make_shared<LinearSeries>(tag, cfactor);
  }
  if (type == "Path") {
    std::vector<double> times, values;
    double dt = 0.0, start = 0.0;
    bool have_dt = false;
    while (!args.empty()) {
      if (args.flag("-factor")) cfactor = args.number("-factor value");
      else if (args.flag("-dt")) { dt = args.number("-dt value"); have_dt = true; }
      else if (args.flag("-values")) values = parse_list(args, "-values");
      else if (args.flag("-time")) times = parse_list(args, "-time");
      else if (args.flag("-filePath")) values = read_file_values(args, args.word("-filePath file"));
      else if (args.flag("-fileTime")) times = read_file_values(args, args.word("-fileTime file"));
      else if (args.flag("-startTime")) start = args.number("-startTime value");
      else if (args.flag("-prependZero")) { values.insert(values.begin(), 0.0); }
      else args.fail("unknown option '" + args.peek() + "'");
    }
    if (values.empty()) args.fail("missing -values or -filePath");
    if (times.empty()) {
      if (!have_dt || !(dt > 0.0)) args.fail("missing -dt (> 0) or -time");
      times.resize(values.size());
      for (std::size_t i = 0; i < values.size(); ++i) times[i] = start + dt * static_cast<double>(i);
    }
    if (times.size() != values.size()) args.fail("-time and -values have different lengths");
    for (std::size_t i = 1; i < times.size(); ++i) {
      if (times[i] < times[i - 1]) args.fail("-time values must not decrease");
    }
    return std::make_shared<PathSeries>(tag, std::move(times), std::move(values), cfactor);
  }
  args.fail("unknown timeSeries type '" + type + "'");
}

}  // namespace fem::domain
