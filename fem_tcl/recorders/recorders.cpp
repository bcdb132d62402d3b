#include "fem_tcl/recorders/recorders.hpp"

#include <cerrno>
#include <cstring>
#include <iostream>

#include "common/printable_text.hpp"
#include "fem_tcl/recorders/envelope_recorder.hpp"

namespace fem::recorders {

TextRecorder::TextRecorder(RecorderOptions options) : options_(std::move(options)) {
  if (options_.path.empty()) return;  // a source of values only (EnvelopeRecorder)
  out_.open(options_.path, std::ios::out | std::ios::trunc);
  if (!out_) throw common::InputError("recorder", "cannot open '" + options_.path + "' for writing");
  out_.precision(options_.precision);
  if (options_.close_on_write) out_.close();
}

TextRecorder::~TextRecorder() {
  if (out_.is_open()) out_.close();
}

void TextRecorder::check_stream(const char* what) {
  if (out_.fail() && !failed_) {
    failed_ = true;  // reported once; the file is incomplete from this row on
    throw common::OutputError("recorder -file " + options_.path + ": " + what + " failed (" + std::strerror(errno) +
                              "); the recorder file is incomplete");
  }
}

void TextRecorder::record(double time) {
  // OpenSees Recorder -dT rule with relative tolerance 1e-5 (NodeRecorder::record).
  if (options_.delta_t != 0.0) {
    if (time - next_time_ < -options_.delta_t * 1e-5) return;
    next_time_ = time + options_.delta_t;
  }
  row_.clear();
  if (options_.time_column) row_.push_back(time);
  const std::size_t before = row_.size();
  time_ = time;
  collect(row_);
  if (row_.size() == before) return;  // nothing to write (e.g. a Node recorder without -dof)
  if (failed_) return;
  if (options_.close_on_write) {
    out_.open(options_.path, std::ios::out | std::ios::app);
    out_.precision(options_.precision);
    check_stream("reopening the file");
  }
  out_ << row_[0];
  for (std::size_t i = 1; i < row_.size(); ++i) out_ << ' ' << row_[i];
  out_ << '\n';
  check_stream("writing a row");
  if (options_.close_on_write) {
    out_.close();
    check_stream("closing the file");
  }
}

void TextRecorder::flush() {
  if (failed_ || !out_.is_open()) return;
  out_.flush();
  check_stream("writing");
}

NodeRecorder::NodeRecorder(RecorderOptions options, domain::Domain& domain, std::vector<int> nodes,
                           std::vector<int> dofs, NodeResponse response, bool all_nodes,
                           std::vector<std::shared_ptr<const domain::TimeSeries>> series)
    : TextRecorder(std::move(options)), domain_(domain), nodes_(std::move(nodes)), dofs_(std::move(dofs)),
      response_(response), all_nodes_(all_nodes), series_(std::move(series)) {}

void NodeRecorder::collect(std::vector<double>& row) {
  if (dofs_.empty()) return;
  if (all_nodes_) {  // the domain's nodes at the first record, in tag order, as OpenSees
    all_nodes_ = false;
    for (const auto& [tag, n] : domain_.nodes()) nodes_.push_back(tag);
  }
  if (response_ == NodeResponse::Reaction) domain_.compute_reactions();
  for (int tag : nodes_) {
    const domain::Node* n = domain_.find_node(tag);
    if (n == nullptr) {
      row.insert(row.end(), dofs_.size(), 0.0);
      continue;
    }
    const domain::NodeVector* v = nullptr;
    switch (response_) {
      case NodeResponse::Disp: v = &n->disp; break;
      case NodeResponse::Vel: v = &n->vel; break;
      case NodeResponse::Accel: v = &n->accel; break;
      case NodeResponse::IncrDisp: v = &n->incr_disp; break;
      case NodeResponse::Reaction: v = &n->reaction; break;
      case NodeResponse::Unbalance: v = &n->load; break;
    }
    for (std::size_t j = 0; j < dofs_.size(); ++j)
      row.push_back((*v)[dofs_[j]] + (j < series_.size() && series_[j] ? series_[j]->factor(time()) : 0.0));
  }
}

ElementRecorder::ElementRecorder(RecorderOptions options, domain::Domain& domain,
                                 std::vector<std::pair<int, std::size_t>> elements, std::vector<std::string> response)
    : TextRecorder(std::move(options)), domain_(domain), elements_(std::move(elements)), response_(std::move(response)) {}

void ElementRecorder::collect(std::vector<double>& row) {
  for (const auto& [tag, width] : elements_) {
    domain::Element* e = domain_.find_element(tag);
    const auto values = e != nullptr ? e->response(response_) : std::nullopt;
    if (values && values->size() == width) row.insert(row.end(), values->begin(), values->end());
    else row.insert(row.end(), width, 0.0);
  }
}

void MeshQualityRecorder::collect(std::vector<double>& row) {
  if (domain_.elements().empty()) return;
  const domain::MeshQuality q = domain_.mesh_quality();
  row.push_back(q.min_det_j);
  row.push_back(q.min_det_j_element);
  row.push_back(q.min_ratio);
  row.push_back(q.min_ratio_element);
}

namespace {

std::vector<int> read_integers(common::CommandArgs& args) {
  std::vector<int> out;
  while (auto v = args.optional_integer()) out.push_back(*v);
  return out;
}

}  // namespace

std::unique_ptr<domain::Recorder> parse_recorder(common::CommandArgs& args, domain::Domain& domain,
                                                 const std::map<int, std::shared_ptr<domain::TimeSeries>>& series) {
  const std::string type = args.word("type (Node, Element, EnvelopeNode, EnvelopeElement or MeshQuality)");
  const bool envelope = type == "EnvelopeNode" || type == "EnvelopeElement";
  if (type != "Node" && type != "Element" && type != "MeshQuality" && !envelope) {
    args.fail("unknown recorder type '" + type + "' (Node, Element, EnvelopeNode, EnvelopeElement or MeshQuality)");
  }
  const bool is_node = type == "Node" || type == "EnvelopeNode";
  const bool is_mesh = type == "MeshQuality";
  RecorderOptions opt;
  std::vector<int> tags, dofs;
  std::vector<std::shared_ptr<const domain::TimeSeries>> dof_series;  // -timeSeries, per -dof entry
  bool have_dof = false, have_file = false;
  bool selected = false;  // a -node/-nodeRange/-ele/-eleRange/-region option was given (OpenSees: else all)
  std::vector<std::string> response;
  while (!args.empty()) {
    if (args.flag("-file")) { opt.path = args.word("-file name"); have_file = true; }
    else if (args.flag("-time")) opt.time_column = true;
    else if (args.flag("-dT")) {
      opt.delta_t = args.number("-dT value");
      if (!(opt.delta_t >= 0.0)) args.fail("expected -dT >= 0");
    } else if (args.flag("-precision")) {
      opt.precision = args.integer("-precision value");
      if (opt.precision < 1 || opt.precision > 17) args.fail("expected 1 <= -precision <= 17");
    } else if (args.flag("-closeOnWrite")) opt.close_on_write = true;
    else if (is_node && args.flag("-node")) {
      selected = true;
      auto t = read_integers(args);
      if (t.empty()) args.fail("missing node tags after -node");
      tags.insert(tags.end(), t.begin(), t.end());
    } else if (is_node && args.flag("-nodeRange")) {
      selected = true;
      const int a = args.integer("-nodeRange start"), b = args.integer("-nodeRange end");
      for (const auto& [tag, n] : domain.nodes()) if (tag >= a && tag <= b) tags.push_back(tag);
    } else if (!is_mesh && args.flag("-region")) {  // OpenSees: the region's nodes / elements, in its order
      selected = true;
      const int r = args.integer("-region tag");
      const domain::MeshRegion* region = domain.find_region(r);
      if (region == nullptr) args.fail("region " + std::to_string(r) + " does not exist");
      const std::vector<int>& t = is_node ? region->nodes : region->elements;
      tags.insert(tags.end(), t.begin(), t.end());
    } else if (is_node && args.flag("-timeSeries")) {  // OpenSees: one series per dof, added to the response
      const auto t = read_integers(args);
      if (t.empty()) args.fail("missing time series tags after -timeSeries");
      for (int tag : t) {
        const auto it = series.find(tag);
        if (it == series.end()) args.fail("timeSeries " + std::to_string(tag) + " does not exist");
        dof_series.push_back(it->second);
      }
    } else if (is_node && args.flag("-dof")) {
      have_dof = true;
      for (int d : read_integers(args)) {
        if (d < 1 || d > domain::kMaxNodeDofs) args.fail("expected -dof values 1, 2 or 3, got " + std::to_string(d));
        dofs.push_back(d - 1);
      }
    } else if (!is_node && !is_mesh && args.flag("-ele")) {
      if (args.peek() == "all") {  // OpenSees: no selection, so every element of the domain (below)
        args.word("all");
        continue;
      }
      selected = true;
      auto t = read_integers(args);
      if (t.empty()) args.fail("missing element tags after -ele (tags or all)");
      tags.insert(tags.end(), t.begin(), t.end());
    } else if (!is_node && !is_mesh && args.flag("-eleRange")) {
      selected = true;
      const int a = args.integer("-eleRange start"), b = args.integer("-eleRange end");
      for (const auto& [tag, e] : domain.elements()) if (tag >= a && tag <= b) tags.push_back(tag);
    } else if (is_mesh) {
      args.fail("unexpected argument '" + args.peek() + "' (recorder MeshQuality -file f <-time> <-dT dt> <-precision n>)");
    } else if (!args.peek().empty() && args.peek()[0] == '-' && !common::CommandArgs::parse_number(args.peek())) {
      args.fail("unknown option '" + args.peek() + "'");
    } else {
      // the first word that is not an option starts the response
      while (!args.empty()) response.push_back(args.word("response"));
    }
  }
  if (!have_file) args.fail("missing -file name (only file output is supported)");
  if (is_mesh) return std::make_unique<MeshQualityRecorder>(opt, domain);
  if (response.empty()) args.fail("missing response (e.g. disp, reaction, stress)");
  // Without a selection OpenSees records every node (at the first record: NodeRecorder::initialize) or
  // every element (those defined now, here).
  if (!is_node && !selected)
    for (const auto& [tag, e] : domain.elements()) tags.push_back(tag);
  // With no element selected the response words are never checked: "-time abc 1 stresses" would
  // record an empty file.
  if (!is_node && tags.empty())
    args.fail("no elements selected (give -ele tags, -ele all or -eleRange a b with existing elements), so the response '" +
              common::printable(response[0]) + "' cannot be checked and nothing would be recorded");
  if (is_node) {
    NodeResponse r{};
    const std::string& w = response[0];
    if (w == "disp") r = NodeResponse::Disp;
    else if (w == "vel") r = NodeResponse::Vel;
    else if (w == "accel") r = NodeResponse::Accel;
    else if (w == "incrDisp") r = NodeResponse::IncrDisp;
    else if (w == "reaction") r = NodeResponse::Reaction;
    else if (w == "unbalance") r = NodeResponse::Unbalance;
    else args.fail("unknown node response '" + w + "' (disp, vel, accel, incrDisp, reaction or unbalance)");
    if (response.size() > 1) args.fail("unexpected argument '" + response[1] + "' after the response");
    std::vector<int> nodes;
    // Every node recorded must have every dof asked for (a -dof 3 on a 2-dof node is an error); without a
    // selection, the nodes of now are checked (a node added later without the dof records 0).
    const auto check_dofs = [&](const domain::Node& n) {
      for (int d : dofs) {
        if (d >= n.ndf) {
          args.fail("-dof " + std::to_string(d + 1) + ": node " + std::to_string(n.tag) + " has " +
                    std::to_string(n.ndf) + " dofs (model -ndf " + std::to_string(n.ndf) + ")");
        }
      }
    };
    for (int t : tags) {
      check_dofs(domain.node(t, args.command()));  // must exist now
      nodes.push_back(t);
    }
    if (!selected) for (const auto& [tag, n] : domain.nodes()) check_dofs(*n);
    if (!have_dof) {
      std::cerr << "WARNING recorder Node -file " << opt.path
                << ": no -dof given, so nothing will be written (as OpenSees); add e.g. -dof 1 2\n";
    }
    if (envelope) {
      return std::make_unique<EnvelopeRecorder>(  // the source without a file: the envelope writes
          opt, std::make_unique<NodeRecorder>(RecorderOptions{}, domain, std::move(nodes), std::move(dofs), r, !selected,
                                              std::move(dof_series)));
    }
    return std::make_unique<NodeRecorder>(opt, domain, std::move(nodes), std::move(dofs), r, !selected,
                                          std::move(dof_series));
  }
  std::vector<std::pair<int, std::size_t>> elements;
  for (int t : tags) {
    domain::Element& e = domain.element(t, args.command());
    const auto values = e.response(response);
    if (!values) {
      std::string joined;
      for (const auto& w : response) joined += (joined.empty() ? "" : " ") + w;
      args.fail("element " + std::to_string(t) + " (" + e.type_name() + ") has no response '" + joined + "'");
    }
    elements.emplace_back(t, values->size());
  }
  if (envelope) {
    return std::make_unique<EnvelopeRecorder>(
        opt, std::make_unique<ElementRecorder>(RecorderOptions{}, domain, std::move(elements), std::move(response)));
  }
  return std::make_unique<ElementRecorder>(opt, domain, std::move(elements), std::move(response));
}

}  // namespace fem::recorders
