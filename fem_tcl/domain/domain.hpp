#pragma once
// The model: nodes, elements, constraints, load patterns, time and the recorders called at each commit
// (OpenSees Domain, reduced to what a 2D continuum analysis needs).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fem_tcl/domain/element.hpp"
#include "fem_tcl/domain/load_pattern.hpp"
#include "fem_tcl/domain/node.hpp"
#include "fem_tcl/domain/recorder.hpp"

namespace fem::domain {

/// `equalDOF retained constrained dofs..` (dofs 0-based).
struct EqualDof { int retained; int constrained; std::vector<int> dofs; };

/// `region` (OpenSees MeshRegion): a labelled set of nodes and elements, in the order given (no duplicates).
struct MeshRegion {
  std::vector<int> nodes, elements;
};

/// Whole-mesh distortion measures (not in OpenSees): the smallest corner det J (deformed configuration) and
/// the smallest corner ratio det J / det J(reference), with the elements where they occur (tag 0: no element).
struct MeshQuality {
  double min_det_j = 0.0;
  int min_det_j_element = 0;
  double min_ratio = 0.0;
  int min_ratio_element = 0;
};

class Domain {
 public:
  // --- building (throw common::InputError naming `where` on a duplicate or missing tag) ---
  /// A node with `ndf` dofs (2, or 3 for u-p elements) at (x, y).
  Node& add_node(int tag, double x, double y, int ndf, const std::string& where);
  void add_element(std::unique_ptr<Element> element, const std::string& where);
  void add_pattern(std::unique_ptr<LoadPattern> pattern, const std::string& where);
  void add_equal_dof(EqualDof c) { equal_dofs_.push_back(std::move(c)); ++version_; }
  /// Adds a recorder and returns its tag (0, 1, 2, ... in creation order, as OpenSees' `recorder` result).
  int add_recorder(std::unique_ptr<Recorder> r) {
    recorders_.push_back({next_recorder_tag_, std::move(r)});
    return next_recorder_tag_++;
  }
  bool remove_recorder(int tag);
  /// `remove element tag`: the element and its materials go; its nodes stay (a node left without stiffness
  /// makes the next system singular, named). Element recorders write zeros in its columns from then on.
  bool remove_element(int tag);
  /// `remove node tag`: only a node no element uses (throws common::InputError naming one that does); its
  /// equalDOF ties, loads and sp go with it. Node recorders write zeros in its columns from then on.
  bool remove_node(int tag, const std::string& where);
  bool remove_pattern(int tag);
  void remove_recorders() { flush_recorders(); recorders_.clear(); }
  void clear();

  Node* find_node(int tag);
  const Node* find_node(int tag) const;
  Node& node(int tag, const std::string& where);
  Element* find_element(int tag);
  Element& element(int tag, const std::string& where);
  LoadPattern* find_pattern(int tag);

  const std::map<int, std::unique_ptr<Node>>& nodes() const { return nodes_; }
  const std::map<int, std::unique_ptr<Element>>& elements() const { return elements_; }
  const std::map<int, std::unique_ptr<LoadPattern>>& patterns() const { return patterns_; }
  const std::vector<EqualDof>& equal_dofs() const { return equal_dofs_; }

  /// Incremented by every change that alters the dof numbering or the sparsity pattern.
  long version() const { return version_; }
  void touch() { ++version_; }
  /// Incremented before every command but `analyze` (interpreter.cpp): any command may have changed a
  /// parameter (a material's moduli, a mass, the Rayleigh factors), so an analysis may keep its elastic
  /// matrix only while this is unchanged.
  long command_revision() const { return command_revision_; }
  void touch_commands() { ++command_revision_; }

  // --- time and loads ---
  double time() const { return time_; }
  double committed_time() const { return committed_time_; }
  void set_time(double t) { time_ = t; }
  /// `setTime` / `loadConst -time`: sets current and committed time.
  void set_committed_time(double t) { time_ = committed_time_ = t; }
  /// Zeroes nodal and element loads, then applies every pattern at `time` (OpenSees Domain::applyLoad).
  void apply_loads(double time);
  /// `loadConst`: freezes every pattern at its current factor.
  void set_load_const();
  /// Ground acceleration per direction applied at the last apply_loads (sum of UniformExcitations).
  const Vector2& ground_accel() const { return ground_accel_; }
  void add_ground_accel(int dof, double a) { ground_accel_[dof] += a; }

  // --- state ---
  void update_elements();
  /// Commits nodes and elements, then calls the recorders (OpenSees Domain::commit).
  void commit();
  void revert_to_last_commit();
  void revert_to_start();
  /// Reactions = -(nodal load) + sum of element resisting forces (quirk 7).
  void compute_reactions();
  void record();
  /// Trial commits (`strengthReduction`'s trials): commits still commit, but call no recorder and check no
  /// mesh quality, so the recorders and the once-only warnings see only the script's own analyses.
  void set_trial_commits(bool on) { trial_commits_ = on; }
  void flush_recorders();
  /// `rayleigh`: the factors of every element and node of the domain now (later ones get none, as OpenSees).
  void set_rayleigh(const RayleighFactors& f);
  /// Defines or replaces region `tag`.
  void set_region(int tag, MeshRegion region) { regions_[tag] = std::move(region); }
  const MeshRegion* find_region(int tag) const;

  // --- mesh distortion monitor (checked at every commit; one warning each on stderr) ---
  /// Current (trial) configuration; O(elements), no allocation.
  MeshQuality mesh_quality() const;
  /// Ratio det J / det J(reference) below which the first warning is printed (0 disables it).
  void set_mesh_warning_ratio(double r) { mesh_warn_ratio_ = r; warned_ratio_ = false; }
  double mesh_warning_ratio() const { return mesh_warn_ratio_; }
  const RayleighFactors& rayleigh() const { return rayleigh_; }

 private:
  std::map<int, std::unique_ptr<Node>> nodes_;
  std::map<int, std::unique_ptr<Element>> elements_;
  std::map<int, std::unique_ptr<LoadPattern>> patterns_;
  std::vector<EqualDof> equal_dofs_;
  std::vector<std::pair<int, std::unique_ptr<Recorder>>> recorders_;
  int next_recorder_tag_ = 0;
  RayleighFactors rayleigh_;
  std::map<int, MeshRegion> regions_;
  double time_ = 0.0;
  double committed_time_ = 0.0;
  Vector2 ground_accel_ = Vector2::Zero();
  long version_ = 0;
  long command_revision_ = 0;
  double mesh_warn_ratio_ = 0.5;
  bool warned_ratio_ = false;
  bool warned_inverted_ = false;
  bool trial_commits_ = false;
  void check_mesh_quality();
  /// The nodes and elements in tag order as plain vectors, for the loops of every step (apply_loads,
  /// commit, mesh_quality) without walking the maps; rebuilt when version_ moved (every change of the maps
  /// moves it).
  void refresh_lists() const;
  mutable std::vector<Node*> node_list_;
  mutable std::vector<Element*> element_list_;
  mutable long list_version_ = -1;
};

}  // namespace fem::domain
