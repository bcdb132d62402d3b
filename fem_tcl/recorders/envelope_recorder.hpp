#pragma once
// OpenSees' EnvelopeNode and EnvelopeElement recorders (EnvelopeNodeRecorder.cpp): the response of a Node
// or Element recorder followed over the analysis, and written as three rows, the minimum, the maximum and
// the largest absolute value of each column; with -time each value is preceded by the time it occurred
// at ("t v" pairs). OpenSees writes the rows when the recorder is destroyed; here every flush rewrites the
// file with the envelope so far (at exit, wipe and `remove recorder`), so the file always holds the rows
// of the steps recorded. Site-response scripts use it for peak-acceleration and peak-strain profiles.
#include <memory>
#include <vector>

#include "fem_tcl/recorders/recorders.hpp"

namespace fem::recorders {

class EnvelopeRecorder final : public domain::Recorder {
 public:
  /// `source`: a Node or Element recorder made without a file, read for its values at each record.
  EnvelopeRecorder(RecorderOptions options, std::unique_ptr<TextRecorder> source);
  ~EnvelopeRecorder() override;
  void record(double time) override;
  void flush() override;

 private:
  RecorderOptions options_;
  std::unique_ptr<TextRecorder> source_;
  double next_time_ = 0.0;
  bool dirty_ = false;
  std::vector<double> row_;
  /// Per column: the extreme values and the times they occurred at (min, max, abs max).
  std::vector<double> min_, max_, abs_, t_min_, t_max_, t_abs_;
};

}  // namespace fem::recorders
