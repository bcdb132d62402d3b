#pragma once
// The progress line of a run, on a terminal only: "step 1200/5001  t 0.1201 s  dt 1e-04 s
// 1280 particles  ETA 0:03", redrawn in place at most 5 times a second. Silent when stderr is
// not a terminal (logs and test output stay clean).
#include <chrono>
#include <cstddef>
#include <cstdio>

namespace mpm::io {

class ProgressLine {
 public:
  /// `first_step`..`nsteps` is the range of loop steps this run executes.
  ProgressLine(long long first_step, long long nsteps, std::FILE* stream = stderr);
  bool enabled() const { return enabled_; }
  /// After loop step `step` completed.
  void update(long long step, double time, double dt, std::size_t particles);
  /// Ends the line (call before printing anything else).
  void finish();

 private:
  std::FILE* stream_;
  bool enabled_;
  bool drawn_ = false;
  long long first_, nsteps_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace mpm::io
