#pragma once
// Text recorders in OpenSees' format (FORMATS.md section 2): one row per committed step, values separated
// by single spaces, default C++ stream formatting at `-precision` significant digits (6 by default),
// optional leading time column, `-dT` rows on OpenSees' absolute "next time" rule (quirk 6).
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/command_args.hpp"
#include "fem_tcl/domain/domain.hpp"
#include "fem_tcl/domain/time_series.hpp"

namespace fem::recorders {

struct RecorderOptions {
  std::string path;
  bool time_column = false;
  double delta_t = 0.0;
  int precision = 6;
  bool close_on_write = false;
};

/// A row-per-commit text file with the -dT rule and -closeOnWrite. An empty path opens no file: the
/// recorder is then only a source of values (EnvelopeRecorder).
class TextRecorder : public domain::Recorder {
 public:
  explicit TextRecorder(RecorderOptions options);
  ~TextRecorder() override;
  void record(double time) final;
  void flush() override;
  /// The values of a row at `time` (without the time column): what an envelope recorder reads.
  void values(std::vector<double>& row, double time) {
    time_ = time;
    collect(row);
  }

 protected:
  /// Appends the row's values (without the time column).
  virtual void collect(std::vector<double>& row) = 0;
  /// The time of the row being collected.
  double time() const { return time_; }

 private:
  /// Throws common::OutputError naming the file the first time the stream has failed.
  void check_stream(const char* what);

  RecorderOptions options_;
  std::ofstream out_;
  bool failed_ = false;
  double next_time_ = 0.0;
  double time_ = 0.0;
  std::vector<double> row_;
};

/// Node responses; Unbalance is OpenSees' "unbalance" (Node::getUnbalancedLoad): the applied nodal loads of the
/// patterns at the step, with UniformExcitation's inertia load -M R a_g (EarthquakePattern::applyLoad).
enum class NodeResponse { Disp, Vel, Accel, IncrDisp, Reaction, Unbalance };

class NodeRecorder final : public TextRecorder {
 public:
  /// `all_nodes`: no node was selected, so (as OpenSees) every node of the domain at the first record.
  /// `series` (OpenSees -timeSeries): per entry of `dofs`, a series whose factor is added to the response
  /// (the ground motion, for absolute accelerations under UniformExcitation), or null.
  NodeRecorder(RecorderOptions options, domain::Domain& domain, std::vector<int> nodes, std::vector<int> dofs,
               NodeResponse response, bool all_nodes = false,
               std::vector<std::shared_ptr<const domain::TimeSeries>> series = {});

 protected:
  /// Each node looked up by tag: a node removed since (`remove node`) writes zeros in its columns.
  void collect(std::vector<double>& row) override;

 private:
  domain::Domain& domain_;
  std::vector<int> nodes_;
  std::vector<int> dofs_;  ///< 0-based
  NodeResponse response_;
  bool all_nodes_;
  std::vector<std::shared_ptr<const domain::TimeSeries>> series_;
};

class ElementRecorder final : public TextRecorder {
 public:
  /// `elements`: tags, each with the number of values its response gives.
  ElementRecorder(RecorderOptions options, domain::Domain& domain, std::vector<std::pair<int, std::size_t>> elements,
                  std::vector<std::string> response);

 protected:
  /// Each element's response, looked up by tag: an element removed since (`remove element`) writes zeros,
  /// so every row keeps the columns of the header's elements.
  void collect(std::vector<double>& row) override;

 private:
  domain::Domain& domain_;
  std::vector<std::pair<int, std::size_t>> elements_;
  std::vector<std::string> response_;
};

/// `recorder MeshQuality -file f <-time> <-dT dt> <-precision n>` (not in OpenSees): per commit
/// `[time] minDetJ elementTag minRatio elementTag` over the whole mesh (Domain::mesh_quality).
class MeshQualityRecorder final : public TextRecorder {
 public:
  MeshQualityRecorder(RecorderOptions options, const domain::Domain& domain)
      : TextRecorder(std::move(options)), domain_(domain) {}

 protected:
  void collect(std::vector<double>& row) override;

 private:
  const domain::Domain& domain_;
};

/// `recorder Node|Element|EnvelopeNode|EnvelopeElement|MeshQuality ...` (args start at the type word).
/// Throws common::InputError.
/// `series`: the model's time series (for -timeSeries).
std::unique_ptr<domain::Recorder> parse_recorder(common::CommandArgs& args, domain::Domain& domain,
                                                 const std::map<int, std::shared_ptr<domain::TimeSeries>>& series);

}  // namespace fem::recorders
