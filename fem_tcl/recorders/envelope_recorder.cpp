#include "fem_tcl/recorders/envelope_recorder.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

#include "common/input_error.hpp"

namespace fem::recorders {

EnvelopeRecorder::EnvelopeRecorder(RecorderOptions options, std::unique_ptr<TextRecorder> source)
    : options_(std::move(options)), source_(std::move(source)) {
  std::ofstream probe(options_.path, std::ios::out | std::ios::trunc);  // as a Node recorder: fail now, not at the end
  if (!probe) throw common::InputError("recorder", "cannot open '" + options_.path + "' for writing");
}

EnvelopeRecorder::~EnvelopeRecorder() {
  try {
    flush();
  } catch (...) {  // a destructor reports nothing; flush_recorders at exit has reported a failing disk
  }
}

void EnvelopeRecorder::record(double time) {
  // OpenSees' -dT rule (EnvelopeNodeRecorder::record: timeStamp >= nextTimeStampToRecord)
  if (options_.delta_t != 0.0) {
    if (time < next_time_) return;
    next_time_ = time + options_.delta_t;
  }
  row_.clear();
  source_->values(row_, time);
  if (min_.empty()) {
    min_ = max_ = row_;
    abs_.resize(row_.size());
    for (std::size_t i = 0; i < row_.size(); ++i) abs_[i] = std::abs(row_[i]);
    t_min_.assign(row_.size(), time);
    t_max_ = t_abs_ = t_min_;
  } else {
    for (std::size_t i = 0; i < row_.size() && i < min_.size(); ++i) {
      const double v = row_[i];
      if (v < min_[i]) {
        min_[i] = v;
        t_min_[i] = time;
      } else if (v > max_[i]) {
        max_[i] = v;
        t_max_[i] = time;
      } else {
        continue;
      }
      if (std::abs(v) > abs_[i]) {  // a new extreme of either sign may be the largest in magnitude
        abs_[i] = std::abs(v);
        t_abs_[i] = time;
      }
    }
  }
  dirty_ = true;
}

void EnvelopeRecorder::flush() {
  if (!dirty_) return;
  std::ofstream out(options_.path, std::ios::out | std::ios::trunc);
  out.precision(options_.precision);
  const auto line = [&](const std::vector<double>& v, const std::vector<double>& t) {
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i > 0) out << ' ';
      if (options_.time_column) out << t[i] << ' ';
      out << v[i];
    }
    out << '\n';
  };
  line(min_, t_min_);
  line(max_, t_max_);
  line(abs_, t_abs_);
  out.close();
  if (out.fail())
    throw common::OutputError("recorder -file " + options_.path + ": writing the envelope failed (" +
                              std::strerror(errno) + ")");
  dirty_ = false;
}

}  // namespace fem::recorders
