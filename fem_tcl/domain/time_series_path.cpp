#include "fem_tcl/domain/time_series_path.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

#include "common/input_error.hpp"
#include "common/number_file.hpp"

namespace fem::domain {

namespace {

/// Once per series, and only when it matters: a record that ends at 0 returns the same 0 either way.
void warn_past_end(bool& warned, int tag, double t, double t_end, double last_value) {
  if (warned || last_value == 0.0) return;
  warned = true;
  std::cerr << "WARNING timeSeries Path " << tag << ": queried at t = " << t << ", past its end (t = " << t_end
            << ", last value " << last_value
            << "); it returns 0 from there on, as OpenSees (give -useLast to hold the last value)\n";
}

}  // namespace

PathSeries::PathSeries(int tag, std::vector<double> values, double dt, double cfactor, bool use_last,
                       double start_time)
    : TimeSeries(tag), values_(std::move(values)), dt_(dt), c_(cfactor), use_last_(use_last), start_(start_time) {}

double PathSeries::factor(double t) const {
  if (t < start_) return 0.0;
  const double s = (t - start_) / dt_;
  const double k = std::floor(s);
  if (k + 1.0 >= static_cast<double>(values_.size())) {
    if (use_last_) return c_ * values_.back();
    warn_past_end(warned_, tag(), t, end_time(), c_ * values_.back());
    return 0.0;
  }
  const auto i = static_cast<std::size_t>(k);
  return c_ * (values_[i] + (values_[i + 1] - values_[i]) * (s - k));
}

PathTimeSeries::PathTimeSeries(int tag, std::vector<double> times, std::vector<double> values, double cfactor,
                               bool use_last)
    : TimeSeries(tag), times_(std::move(times)), values_(std::move(values)), c_(cfactor), use_last_(use_last) {}

double PathTimeSeries::factor(double t) const {
  const std::size_t n = times_.size();
  double t1 = times_[loc_];
  if (t < t1 && loc_ == 0) return 0.0;
  if (t == t1) return c_ * values_[loc_];
  const auto past_end = [&] {
    if (use_last_) return c_ * values_[n - 1];
    warn_past_end(warned_, tag(), t, times_[n - 1], c_ * values_[n - 1]);
    return 0.0;
  };
  if (t > t1 && loc_ == n - 1) return past_end();
  double t2 = times_[loc_ + 1];
  if (t > t2) {
    while (t > t2 && loc_ < n - 2) {
      ++loc_;
      t1 = t2;
      t2 = times_[loc_ + 1];
    }
    if (t > t2) return past_end();
  } else if (t < t1) {
    while (t < t1 && loc_ > 0) {
      --loc_;
      t2 = t1;
      t1 = times_[loc_];
    }
    if (t < t1) return 0.0;
  }
  const double v1 = values_[loc_], v2 = values_[loc_ + 1];
  return c_ * (v1 + (v2 - v1) * (t - t1) / (t2 - t1));
}

namespace {

/// common::read_number_file, its error as this command's.
std::vector<double> read_number_file(common::CommandArgs& args, const std::string& path) {
  try {
    return common::read_number_file(path);
  } catch (const common::InputError& e) {
    args.fail(e.what());
  }
}

/// `-values {list}` or `-values v1 v2 ..` (OpenSees takes a Tcl list or the numbers that follow).
std::vector<double> number_list(common::CommandArgs& args, std::string_view what) {
  std::vector<double> out;
  const std::string first = args.word(what);
  const auto tokens = common::CommandArgs::split_list(first);
  if (!tokens) args.fail("expected a list of numbers for " + std::string(what) + ", got an unmatched brace or quote");
  for (std::string token : *tokens) {
    // Tcl_GetDouble takes surrounding white space: a nodeDisp result ("   -0.001") is a number
    token.erase(0, token.find_first_not_of(" \t\n\r"));
    token.erase(token.find_last_not_of(" \t\n\r") + 1);
    const auto v = common::CommandArgs::parse_number(token);
    if (!v || !std::isfinite(*v)) args.fail("expected a list of numbers for " + std::string(what) + ", got '" + token + "'");
    out.push_back(*v);
  }
  while (auto v = args.optional_number()) out.push_back(*v);
  return out;
}

}  // namespace

std::shared_ptr<TimeSeries> parse_path_series(common::CommandArgs& args) {
  int tag = args.integer("tag");
  double cfactor = 1.0, dt = 0.0, start = 0.0;
  bool have_dt = false, use_last = false, prepend_zero = false, have_start = false;
  std::vector<double> values, times;
  std::string file_path, file_time, file_pairs;
  while (!args.empty()) {
    if (args.flag("-dt") || args.flag("-dT")) { dt = args.number("-dt value"); have_dt = true; }
    else if (args.flag("-tag")) tag = args.integer("-tag value");
    else if (args.flag("-values")) values = number_list(args, "-values");
    else if (args.flag("-time")) times = number_list(args, "-time");
    else if (args.flag("-factor")) cfactor = args.number("-factor value");
    else if (args.flag("-useLast")) use_last = true;
    else if (args.flag("-prependZero")) prepend_zero = true;
    else if (args.flag("-startTime") || args.flag("-tStart")) { start = args.number("-startTime value"); have_start = true; }
    else if (args.flag("-filePath")) file_path = args.word("-filePath file");
    else if (args.flag("-fileTime")) file_time = args.word("-fileTime file");
    else if (args.flag("-file")) file_pairs = args.word("-file file");
    else args.fail("unknown option '" + args.peek() + "'");
  }
  if (!std::isfinite(cfactor) || !std::isfinite(start)) args.fail("expected a finite -factor and -startTime");
  const auto ignored = [&](bool given, const char* option, const char* kind) {
    if (given) {
      std::cerr << "WARNING " << args.command() << ": " << option << " is ignored with " << kind
                << " (as OpenSees 3.8)\n";
    }
  };
  // OpenSees' order of choice: dt & values, dt & filePath, time & values, fileTime & filePath, file.
  const bool dt_series = have_dt && (!values.empty() || !file_path.empty());
  if (have_dt && !(dt > 0.0) && (!values.empty() || !file_path.empty()) && times.empty() && file_time.empty()) {
    args.fail("-dt must be > 0, got " + std::to_string(dt));
  }
  if (dt_series && dt > 0.0) {
    if (values.empty()) values = read_number_file(args, file_path);
    if (values.empty()) args.fail("no values (empty -values list or file)");
    ignored(!times.empty() || !file_time.empty(), "-time/-fileTime", "-dt");
    if (prepend_zero) values.insert(values.begin(), 0.0);
    return std::make_shared<PathSeries>(tag, std::move(values), dt, cfactor, use_last, start);
  }
  bool pairs_file = false;
  if (times.empty() || values.empty()) {
    if (!file_time.empty() && !file_path.empty()) {
      times = read_number_file(args, file_time);
      values = read_number_file(args, file_path);
    } else if (!file_pairs.empty()) {
      const std::vector<double> pairs = read_number_file(args, file_pairs);
      if (pairs.size() % 2 != 0) args.fail("file '" + file_pairs + "': expected time value pairs, got an odd count");
      for (std::size_t k = 0; k < pairs.size(); k += 2) { times.push_back(pairs[k]); values.push_back(pairs[k + 1]); }
      pairs_file = true;
    } else {
      args.fail("expected -dt dt with -values or -filePath, or -time with -values, or -fileTime with -filePath, or -file");
    }
  }
  if (times.size() != values.size()) {
    args.fail("the times and values have different lengths (" + std::to_string(times.size()) + " and " +
              std::to_string(values.size()) + ")");
  }
  if (values.empty()) args.fail("no values (empty list or file)");
  for (std::size_t k = 1; k < times.size(); ++k) {
    if (times[k] < times[k - 1]) args.fail("times must not decrease (entry " + std::to_string(k + 1) + ")");
  }
  // OpenSees 3.8 builds PathTimeSeries from -time/-values and -fileTime/-filePath without these options.
  ignored(use_last && !pairs_file, "-useLast", "-time/-fileTime");
  ignored(prepend_zero, "-prependZero", "-time/-fileTime/-file");
  ignored(have_start, "-startTime", "-time/-fileTime/-file");
  return std::make_shared<PathTimeSeries>(tag, std::move(times), std::move(values), cfactor, use_last && pairs_file);
}

}  // namespace fem::domain
