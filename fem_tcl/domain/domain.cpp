#include "fem_tcl/domain/domain.hpp"

#include <iostream>

#include "common/input_error.hpp"

namespace fem::domain {

Node& Domain::add_node(int tag, double x, double y, int ndf, const std::string& where) {
  if (nodes_.count(tag)) throw common::InputError(where, "node " + std::to_string(tag) + " already exists");
  auto node = std::make_unique<Node>();
  node->tag = tag;
  node->ndf = ndf;
  node->crd = Vector2(x, y);
  Node& ref = *node;
  nodes_.emplace(tag, std::move(node));
  ++version_;
  return ref;
}

void Domain::add_element(std::unique_ptr<Element> element, const std::string& where) {
  const int tag = element->tag();
  if (elements_.count(tag)) throw common::InputError(where, "element " + std::to_string(tag) + " already exists");
  elements_.emplace(tag, std::move(element));
  ++version_;
}

void Domain::add_pattern(std::unique_ptr<LoadPattern> pattern, const std::string& where) {
  const int tag = pattern->tag();
  if (patterns_.count(tag)) throw common::InputError(where, "load pattern " + std::to_string(tag) + " already exists");
  patterns_.emplace(tag, std::move(pattern));
  ++version_;
}

bool Domain::remove_element(int tag) {
  const bool removed = elements_.erase(tag) > 0;
  if (removed) ++version_;
  return removed;
}

bool Domain::remove_node(int tag, const std::string& where) {
  const auto it = nodes_.find(tag);
  if (it == nodes_.end()) return false;
  for (const auto& [etag, e] : elements_)
    for (int a = 0; a < e->num_nodes(); ++a)
      if (e->nodes()[a] == it->second.get())
        throw common::InputError(where, "node " + std::to_string(tag) + " is a node of element " + std::to_string(etag) +
                                            "; remove the element first");
  std::erase_if(equal_dofs_, [&](const EqualDof& c) { return c.retained == tag || c.constrained == tag; });
  nodes_.erase(it);
  ++version_;
  return true;
}

bool Domain::remove_pattern(int tag) {
  const bool removed = patterns_.erase(tag) > 0;
  if (removed) ++version_;
  return removed;
}

void Domain::clear() {
  flush_recorders();
  recorders_.clear();
  next_recorder_tag_ = 0;
  patterns_.clear();
  elements_.clear();
  nodes_.clear();
  equal_dofs_.clear();
  rayleigh_ = {};
  regions_.clear();
  warned_ratio_ = warned_inverted_ = false;
  time_ = committed_time_ = 0.0;
  ground_accel_.setZero();
  ++version_;
}

Node* Domain::find_node(int tag) {
  auto it = nodes_.find(tag);
  return it == nodes_.end() ? nullptr : it->second.get();
}
const Node* Domain::find_node(int tag) const {
  auto it = nodes_.find(tag);
  return it == nodes_.end() ? nullptr : it->second.get();
}
Node& Domain::node(int tag, const std::string& where) {
  Node* n = find_node(tag);
  if (!n) throw common::InputError(where, "node " + std::to_string(tag) + " does not exist");
  return *n;
}
Element* Domain::find_element(int tag) {
  auto it = elements_.find(tag);
  return it == elements_.end() ? nullptr : it->second.get();
}
Element& Domain::element(int tag, const std::string& where) {
  Element* e = find_element(tag);
  if (!e) throw common::InputError(where, "element " + std::to_string(tag) + " does not exist");
  return *e;
}
LoadPattern* Domain::find_pattern(int tag) {
  auto it = patterns_.find(tag);
  return it == patterns_.end() ? nullptr : it->second.get();
}

void Domain::refresh_lists() const {
  if (list_version_ == version_) return;
  node_list_.clear();
  element_list_.clear();
  for (const auto& [tag, n] : nodes_) node_list_.push_back(n.get());
  for (const auto& [tag, e] : elements_) element_list_.push_back(e.get());
  list_version_ = version_;
}

void Domain::apply_loads(double time) {
  refresh_lists();
  for (Node* n : node_list_) n->load.setZero();
  for (Element* e : element_list_) e->zero_load();
  ground_accel_.setZero();
  for (auto& [tag, p] : patterns_) p->apply(*this, time);
}

void Domain::set_load_const() {
  for (auto& [tag, p] : patterns_) p->set_load_const();
}

void Domain::update_elements() {
  for (auto& [tag, e] : elements_) e->update();
}

void Domain::commit() {
  refresh_lists();
  for (Node* n : node_list_) n->commit();
  for (Element* e : element_list_) e->commit_state();
  committed_time_ = time_;
  if (trial_commits_) return;
  check_mesh_quality();
  record();
}

MeshQuality Domain::mesh_quality() const {
  MeshQuality q;
  bool first = true;
  refresh_lists();
  for (const Element* e : element_list_) {
    const int tag = e->tag();
    if (!e->is_continuum()) continue;  // zero-length springs have no area
    const double d = e->min_corner_jacobian();
    const double r = e->min_corner_jacobian_ratio();
    if (first || d < q.min_det_j) { q.min_det_j = d; q.min_det_j_element = tag; }
    if (first || r < q.min_ratio) { q.min_ratio = r; q.min_ratio_element = tag; }
    first = false;
  }
  return q;
}

void Domain::check_mesh_quality() {
  if (elements_.empty() || (warned_inverted_ && (warned_ratio_ || mesh_warn_ratio_ <= 0.0))) return;
  const MeshQuality q = mesh_quality();
  if (q.min_det_j_element == 0) return;  // no continuum element
  if (!warned_ratio_ && mesh_warn_ratio_ > 0.0 && q.min_ratio < mesh_warn_ratio_ && q.min_det_j > 0.0) {
    warned_ratio_ = true;
    std::cerr << "WARNING mesh quality: at t = " << committed_time_ << " element " << q.min_ratio_element
              << " has a corner det J of " << q.min_ratio << " times its reference value (below the threshold "
              << mesh_warn_ratio_ << ", meshQuality -warn); the mesh is distorting\n";
  }
  if (!warned_inverted_ && q.min_det_j <= 0.0) {
    warned_inverted_ = true;
    warned_ratio_ = true;
    std::cerr << "WARNING mesh quality: at t = " << committed_time_ << " element " << q.min_det_j_element
              << " is inverted (corner det J = " << q.min_det_j
              << " <= 0); results past this time are not meaningful\n";
  }
}

void Domain::record() {
  for (auto& [tag, r] : recorders_) r->record(time_);
}

void Domain::flush_recorders() {
  for (auto& [tag, r] : recorders_) r->flush();
}

bool Domain::remove_recorder(int tag) {
  for (auto it = recorders_.begin(); it != recorders_.end(); ++it) {
    if (it->first == tag) {
      it->second->flush();
      recorders_.erase(it);
      return true;
    }
  }
  return false;
}

void Domain::revert_to_last_commit() {
  for (auto& [tag, n] : nodes_) n->revert_to_last_commit();
  for (auto& [tag, e] : elements_) e->revert_to_last_commit();
  time_ = committed_time_;
  update_elements();
}

void Domain::revert_to_start() {
  for (auto& [tag, n] : nodes_) n->revert_to_start();
  for (auto& [tag, e] : elements_) e->revert_to_start();
  time_ = committed_time_ = 0.0;
  update_elements();
}

void Domain::compute_reactions() {
  for (auto& [tag, n] : nodes_) n->reaction = -n->load;
  ElementVector f;
  for (auto& [tag, e] : elements_) {
    e->form_resisting_force(f);
    const int per_node = e->dofs_per_node();
    for (int i = 0; i < e->num_nodes(); ++i) {
      for (int d = 0; d < per_node; ++d) e->nodes()[i]->reaction[d] += f[per_node * i + d];
    }
  }
}

void Domain::set_rayleigh(const RayleighFactors& f) {
  rayleigh_ = f;
  for (auto& [tag, e] : elements_) e->set_rayleigh(f);
  for (auto& [tag, n] : nodes_) n->rayleigh_alpha_m = f.alpha_m;
}

const MeshRegion* Domain::find_region(int tag) const {
  const auto it = regions_.find(tag);
  return it == regions_.end() ? nullptr : &it->second;
}

void PlainPattern::apply(Domain& domain, double time) {
  const double f = factor(time);
  last_factor_ = f;
  for (const auto& l : nodal_loads) {
    if (Node* n = domain.find_node(l.node)) n->load += f * l.force;
  }
  for (const auto& sw : self_weight) {
    for (int etag : sw.elements) {
      if (Element* e = domain.find_element(etag)) e->add_self_weight(f, sw.xf, sw.yf);
    }
  }
}

void UniformExcitation::apply(Domain& domain, double time) {
  const double ag = factor(time);
  last_factor_ = ag;
  Vector2 a = Vector2::Zero();
  a[dof_] = ag;
  domain.add_ground_accel(dof_, ag);
  for (auto& [tag, n] : domain.nodes()) {
    if (n->has_mass) n->load[dof_] -= n->mass[dof_] * ag;
  }
  for (auto& [tag, e] : domain.elements()) e->add_inertia_load(a);
}

}  // namespace fem::domain
