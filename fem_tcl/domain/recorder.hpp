#pragma once
// What the domain calls at every commit (OpenSees Recorder::record); concrete recorders live in fem::recorders.
namespace fem::domain {

class Recorder {
 public:
  virtual ~Recorder() = default;
  /// Writes a row for the committed state at `time` (subject to the recorder's own -dT rule).
  virtual void record(double time) = 0;
  /// Flushes buffered output to disk.
  virtual void flush() = 0;
};

}  // namespace fem::domain
