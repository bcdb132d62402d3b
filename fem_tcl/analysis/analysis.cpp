#include "fem_tcl/analysis/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <unordered_map>

#include "common/input_error.hpp"
#include "common/number_text.hpp"

namespace fem::analysis {

Analysis::Analysis(domain::Domain& domain, AnalysisConfig config)
    : domain_(domain), config_(std::move(config)), test_(config_.test) {
  SolverKind kind{};
  if (!solver_kind_for(config_.system, kind)) throw common::InputError("system", "unknown system '" + config_.system + "'");
  if (config_.integrator.type == IntegratorType::CentralDifference && config_.algorithm.type != AlgorithmType::Linear) {
    throw common::InputError("integrator CentralDifference", "needs 'algorithm Linear' (an explicit scheme takes one solve per step)");
  }
  solver_ = std::make_unique<LinearSolver>(kind);
  d_lambda_ = config_.integrator.d_lambda;
  if (config_.integrator.type == IntegratorType::DisplacementControl) control_.emplace(config_.integrator);
}

void Analysis::setup() {
  if (version_ == domain_.version()) return;
  kept_.valid = false;
  nodes_.clear();
  std::unordered_map<const domain::Node*, int> index;
  for (const auto& [tag, n] : domain_.nodes()) {
    index[n.get()] = static_cast<int>(nodes_.size());
    nodes_.push_back(n.get());
  }
  // Each node's dofs are consecutive in the full-dof vectors: node i owns first_dof_[i] .. + ndf - 1.
  first_dof_.assign(nodes_.size() + 1, 0);
  for (std::size_t i = 0; i < nodes_.size(); ++i) first_dof_[i + 1] = first_dof_[i] + nodes_[i]->ndf;
  const int ndof = first_dof_.back();
  dof_node_.resize(ndof);
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    for (int d = 0; d < nodes_[i]->ndf; ++d) dof_node_[first_dof_[i] + d] = static_cast<int>(i);
  constexpr int kFree = 0, kFixed = -1;
  std::vector<int> state(ndof, kFree);
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    for (int d = 0; d < nodes_[i]->ndf; ++d) if (nodes_[i]->fixed[d]) state[first_dof_[i] + d] = kFixed;
  }
  const bool penalty = config_.handler == HandlerType::Penalty;
  prescribed_.clear();
  penalty_pairs_.clear();
  for (const auto& [tag, p] : domain_.patterns()) {
    for (const auto& sp : p->prescribed) {
      const domain::Node* n = domain_.find_node(sp.node);
      if (!n) continue;
      if (sp.dof >= n->ndf) continue;  // refused by `sp`; a node re-made with fewer dofs keeps none
      const int dof = first_dof_[index[n]] + sp.dof;
      state[dof] = kFixed;
      prescribed_.push_back({dof, p.get(), sp.value});
    }
  }
  if (penalty) {
    // Penalty (OpenSees PenaltySP_FE / PenaltyMP_FE): every dof keeps its equation; fixed and prescribed
    // dofs get alphaS on the diagonal, equalDOF pairs alphaM [1 -1; -1 1].
    for (int i = 0; i < ndof; ++i) {
      if (state[i] == kFixed) {
        bool from_pattern = false;
        for (const auto& p : prescribed_) from_pattern = from_pattern || p.dof == i;
        if (!from_pattern) prescribed_.push_back({i, nullptr, 0.0});
        state[i] = kFree;
      }
    }
  }
  // equalDOF: the constrained dof takes the retained dof's equation (a transformation with T = I).
  std::vector<int> alias(ndof, -1);
  for (const auto& c : domain_.equal_dofs()) {
    const domain::Node* r = domain_.find_node(c.retained);
    const domain::Node* k = domain_.find_node(c.constrained);
    if (!r || !k) continue;
    for (int d : c.dofs) {
      if (d >= r->ndf || d >= k->ndf) continue;  // refused by `equalDOF`
      const int rd = first_dof_[index[r]] + d, kd = first_dof_[index[k]] + d;
      if (penalty) penalty_pairs_.push_back({rd, kd});
      else alias[kd] = rd;
      if (!penalty && state[kd] == kFixed && state[rd] == kFree) {
        std::cerr << "WARNING equalDOF " << c.retained << ' ' << c.constrained << ": dof " << d + 1 << " of the constrained node "
                  << c.constrained << " is also fixed, so the tie is not enforced (node " << c.retained
                  << " stays free in it); fix the retained node instead\n";
      }
    }
  }
  eq_.assign(ndof, -1);
  neq_ = 0;
  for (int i = 0; i < ndof; ++i) {
    if (state[i] == kFree && alias[i] < 0) eq_[i] = neq_++;
  }
  tied_to_prescribed_.clear();
  for (int i = 0; i < ndof; ++i) {
    if (alias[i] >= 0 && state[i] == kFree) {
      int r = alias[i];
      for (int guard = 0; guard < ndof && alias[r] >= 0; ++guard) r = alias[r];
      eq_[i] = state[r] == kFree ? eq_[r] : -1;
      // a dof tied to a prescribed one moves with it (OpenSees' TransformationDOF_Group: the constrained dof
      // is the retained one, sp included)
      if (state[r] != kFree) tied_to_prescribed_.push_back({i, r});
    }
  }
  if (!domain_.equal_dofs().empty() && config_.handler == HandlerType::Plain) {
    std::cerr << "WARNING constraints Plain: equalDOF constraints are enforced by transformation\n";
  }

  elements_.clear();
  element_eq_.clear();
  std::size_t entries = 0;
  for (const auto& [tag, e] : domain_.elements()) {
    elements_.push_back(e.get());
    ElementEquations ids;
    ids.count = e->num_dofs();
    const int per_node = e->dofs_per_node();
    for (int a = 0; a < e->num_nodes(); ++a) {
      const int first = first_dof_[index[e->nodes()[a]]];
      for (int d = 0; d < per_node; ++d) ids.eq[per_node * a + d] = eq_[first + d];
    }
    element_eq_.push_back(ids);
    entries += static_cast<std::size_t>(ids.count * ids.count);
  }
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(entries + neq_);
  for (int i = 0; i < neq_; ++i) triplets.emplace_back(i, i, 0.0);
  for (const auto& pp : penalty_pairs_) {
    triplets.emplace_back(eq_[pp.retained], eq_[pp.constrained], 0.0);
    triplets.emplace_back(eq_[pp.constrained], eq_[pp.retained], 0.0);
  }
  for (const auto& ids : element_eq_) {
    for (int i = 0; i < ids.count; ++i) {
      if (ids.eq[i] < 0) continue;
      for (int j = 0; j < ids.count; ++j) if (ids.eq[j] >= 0) triplets.emplace_back(ids.eq[i], ids.eq[j], 0.0);
    }
  }
  Eigen::SparseMatrix<double> A(neq_, neq_);
  A.setFromTriplets(triplets.begin(), triplets.end());
  A.makeCompressed();
  const auto position = [&](int row, int col) {
    const int* begin = A.innerIndexPtr() + A.outerIndexPtr()[col];
    const int* end = A.innerIndexPtr() + A.outerIndexPtr()[col + 1];
    const int* it = std::lower_bound(begin, end, row);
    return static_cast<int>(it - A.innerIndexPtr());
  };
  element_pos_.clear();
  element_pos_.reserve(entries);
  element_pos_first_.assign(element_eq_.size() + 1, 0);
  for (std::size_t e = 0; e < element_eq_.size(); ++e) {
    const auto& ids = element_eq_[e];
    const int n = ids.count;
    for (int j = 0; j < n; ++j) {  // column-major, as the element matrix
      for (int i = 0; i < n; ++i) {
        element_pos_.push_back((ids.eq[i] >= 0 && ids.eq[j] >= 0) ? position(ids.eq[i], ids.eq[j]) : -1);
      }
    }
    element_pos_first_[e + 1] = element_pos_.size();
  }
  diag_pos_.resize(neq_);
  for (int i = 0; i < neq_; ++i) diag_pos_[i] = position(i, i);
  penalty_diag_pos_.clear();
  penalty_pair_pos_.clear();
  if (penalty) {
    for (const auto& p : prescribed_) penalty_diag_pos_.push_back(diag_pos_[eq_[p.dof]]);
    for (const auto& pp : penalty_pairs_) {
      const int r = eq_[pp.retained], c = eq_[pp.constrained];
      penalty_pair_pos_.push_back({position(r, r), position(r, c), position(c, r), position(c, c)});
    }
  }
  solver_->set_pattern(std::move(A));
  R_.setZero(neq_);
  dx_.setZero(neq_);
  full_.setZero(ndof);
  U_.setZero(ndof); Ud_.setZero(ndof); Udd_.setZero(ndof);
  Ut_.setZero(ndof); Utd_.setZero(ndof); Utm1_.setZero(ndof);
  have_previous_ = false;
  forces_current_ = false;
  if (control_) control_reference();  // before the version is taken: a failed reference is retried, never used
  version_ = domain_.version();
}

void Analysis::form_tangent() {
  const bool elastic = config_.algorithm.elastic_tangent;
  if (elastic && kept_.valid && kept_.revision == domain_.command_revision() && kept_.c1 == c1_ && kept_.c2 == c2_ &&
      kept_.c3 == c3_)
    return;  // the matrix factored last is this one (KeptMatrix)
  kept_.valid = false;
  bool fixed = elastic;
  double* values = solver_->matrix().valuePtr();
  solver_->zero_values();
  // `algorithm Newton -initial`: the initial stiffness replaces the current tangent (OpenSees INITIAL_TANGENT)
  // `-elasticTangent` (fem_tcl): the elastic stiffness, the same matrix every step (factored once per dt)
  const domain::SystemWeights weights{c1_, c2_, c3_,
                                      config_.algorithm.elastic_tangent   ? domain::StiffnessKind::Elastic
                                      : config_.algorithm.initial_tangent ? domain::StiffnessKind::Initial
                                                                          : domain::StiffnessKind::Current};
  domain::ElementMatrix ke;
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    domain::Element& el = *elements_[e];
    el.form_system_matrix(weights, ke);
    fixed = fixed && el.system_matrix_fixed(weights);
    const int* pos = element_pos_.data() + element_pos_first_[e];
    const double* k = ke.data();
    const int entries = static_cast<int>(ke.size());
    for (int i = 0; i < entries; ++i) {
      if (pos[i] >= 0) values[pos[i]] += k[i];
    }
  }
  if (c2_ != 0.0 || c3_ != 0.0) {
    for (std::size_t n = 0; n < nodes_.size(); ++n) {
      if (!nodes_[n]->has_mass) continue;
      const double cm = c3_ + c2_ * nodes_[n]->rayleigh_alpha_m;
      for (int d = 0; d < nodes_[n]->ndf; ++d) {
        const int q = eq_[first_dof_[n] + d];
        if (q >= 0) values[diag_pos_[q]] += cm * nodes_[n]->mass[d];
      }
    }
  }
  if (config_.handler == HandlerType::Penalty && c1_ != 0.0) {
    const double a = c1_ * config_.penalty_sp, m = c1_ * config_.penalty_mp;
    for (int pos : penalty_diag_pos_) values[pos] += a;
    for (const auto& p : penalty_pair_pos_) {
      values[p[0]] += m; values[p[1]] -= m; values[p[2]] -= m; values[p[3]] += m;
    }
  }
  // A free dof that nothing stiffens makes the system singular: name it.
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    for (int d = 0; d < nodes_[n]->ndf; ++d) {
      const int q = eq_[first_dof_[n] + d];
      if (q >= 0 && values[diag_pos_[q]] == 0.0) {
        throw common::NumericalError(
            "the system matrix is singular: node " + std::to_string(nodes_[n]->tag) + " dof " + std::to_string(d + 1) +
            (d == 2 ? " (pore pressure) has no equation (the u-p elements' flow equations are rate equations: run "
                      "a transient analysis, or fix the dof)"
             : c1_ == 0.0 ? " has no mass (an explicit integrator's matrix is the mass: give the "
                            "materials a rho or the node a mass)"
                          : " has no stiffness (unconnected node or missing support)"));
      }
    }
  }
  solver_->factor();
  if (fixed) kept_ = {true, domain_.command_revision(), c1_, c2_, c3_};
}

void Analysis::form_unbalance() {
  R_.setZero();
  const bool dynamic = config_.transient;
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    const domain::Node& nd = *nodes_[n];
    for (int d = 0; d < nd.ndf; ++d) {
      const int q = eq_[first_dof_[n] + d];
      if (q < 0) continue;
      double r = nd.load[d];
      if (dynamic && nd.has_mass) r -= nd.mass[d] * (nd.accel[d] + nd.rayleigh_alpha_m * nd.vel[d]);
      R_[q] += r;
    }
  }
  domain::ElementVector f;
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    if (!forces_current_) elements_[e]->form_unbalance(config_.transient, f);
    const domain::ElementVector& fe = forces_current_ ? element_force_[e] : f;
    const auto& ids = element_eq_[e];
    double sum = 0.0;
    for (int i = 0; i < ids.count; ++i) {
      sum += fe[i];
      if (ids.eq[i] >= 0) R_[ids.eq[i]] -= fe[i];
    }
    // A material state that diverged shows on the constrained dofs too, where the residual never sees it
    // (found by fuzzing: an undrained DSS whose solid dofs are all prescribed kept a NaN PM4Silt stress
    // through 6,000 converged steps): the step fails instead of committing it.
    if (!std::isfinite(sum))
      throw common::NumericalError("the resisting force of element " + std::to_string(elements_[e]->tag()) +
                                   " is not finite (its material state diverged)");
  }
  if (config_.handler == HandlerType::Penalty) {
    const auto disp = [&](int i) { return nodes_[dof_node_[i]]->disp[i - first_dof_[dof_node_[i]]]; };
    for (const auto& p : prescribed_) R_[eq_[p.dof]] += config_.penalty_sp * (prescribed_value(p) - disp(p.dof));
    for (const auto& pp : penalty_pairs_) {
      const double gap = config_.penalty_mp * (disp(pp.constrained) - disp(pp.retained));
      R_[eq_[pp.retained]] += gap;
      R_[eq_[pp.constrained]] -= gap;
    }
  }
}

void Analysis::solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) { solver_->solve(rhs, x); }

void Analysis::update_elements() {
  // Transient: the unbalance contribution of each element right after its update, while its nodes and
  // material are in cache; form_unbalance sums them in the same order (the same sums bit for bit).
  forces_current_ = false;
  if (!config_.transient) {
    for (domain::Element* e : elements_) e->update();
    return;
  }
  element_force_.resize(elements_.size());
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    elements_[e]->update();
    elements_[e]->form_unbalance(true, element_force_[e]);
  }
  forces_current_ = true;
}

double Analysis::prescribed_value(const Prescribed& p) const {
  return p.pattern ? p.pattern->factor(domain_.time()) * p.value : 0.0;
}

void Analysis::update(const Eigen::VectorXd& dU) {
  if (control_) control_update(dU);
  else apply_free_increment(dU);
}

void Analysis::apply_free_increment(const Eigen::VectorXd& dU) {
  const int ndof = static_cast<int>(eq_.size());
  for (int i = 0; i < ndof; ++i) full_[i] = eq_[i] >= 0 ? dU[eq_[i]] : 0.0;
  apply_increment(full_);
}

void Analysis::control_reference() {
  const IntegratorConfig& ic = config_.integrator;
  const std::string where = "integrator DisplacementControl";
  int equation = -2;
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    if (nodes_[n]->tag != ic.control_node) continue;
    if (ic.control_dof >= nodes_[n]->ndf) {
      throw common::InputError(where, "node " + std::to_string(ic.control_node) + " has no dof " +
                                          std::to_string(ic.control_dof + 1));
    }
    equation = eq_[first_dof_[n] + ic.control_dof];
  }
  if (equation == -2) throw common::InputError(where, "node " + std::to_string(ic.control_node) + " does not exist");
  if (equation < 0) {
    throw common::InputError(where, "node " + std::to_string(ic.control_node) + " dof " +
                                        std::to_string(ic.control_dof + 1) + " is fixed or constrained");
  }
  // phat = R(lambda + 1) at the committed state (OpenSees DisplacementControl::domainChanged)
  const double lambda = domain_.committed_time();
  domain_.set_time(lambda + 1.0);
  domain_.apply_loads(lambda + 1.0);
  forces_current_ = false;
  form_unbalance();
  const Eigen::VectorXd phat = R_;
  domain_.set_time(lambda);
  domain_.apply_loads(lambda);
  if (phat.isZero(0.0)) throw common::InputError(where, "zero reference load (no load grows with the load factor)");
  control_->set_reference(phat, equation);
  control_dUhat_.setZero(neq_);
  control_increment_.setZero(neq_);
}

void Analysis::control_predictor() {
  form_tangent();
  solve(control_->reference_load(), control_dUhat_);
  const double d_lambda = control_->predictor(control_dUhat_);
  control_increment_ = d_lambda * control_dUhat_;
  apply_free_increment(control_increment_);
  const double lambda = step_start_time_ + d_lambda;
  domain_.set_time(lambda);
  domain_.apply_loads(lambda);
}

void Analysis::control_update(const Eigen::VectorXd& dUbar) {
  solve(control_->reference_load(), control_dUhat_);  // with the factorization of this iteration
  const double d_lambda = control_->corrector(dUbar, control_dUhat_);
  control_increment_ = dUbar + d_lambda * control_dUhat_;
  apply_free_increment(control_increment_);
  const double lambda = domain_.time() + d_lambda;
  domain_.set_time(lambda);
  domain_.apply_loads(lambda);
}

void Analysis::apply_increment(const Eigen::VectorXd& full) {
  const IntegratorConfig& ic = config_.integrator;
  const int nn = static_cast<int>(nodes_.size());
  switch (ic.type) {
    case IntegratorType::LoadControl:
    case IntegratorType::DisplacementControl:
      for (int n = 0; n < nn; ++n) {
        for (int d = 0; d < nodes_[n]->ndf; ++d) {
          nodes_[n]->disp[d] += full[first_dof_[n] + d];
          nodes_[n]->incr_disp[d] += full[first_dof_[n] + d];
        }
      }
      break;
    case IntegratorType::Newmark:
    case IntegratorType::HHT: {
      const double alpha = ic.type == IntegratorType::HHT ? ic.alpha : 1.0;
      U_ += full;
      Ud_ += c2_ / alpha * full;   // c2_ holds alpha * gamma / (beta dt)
      Udd_ += c3_ * full;
      for (int n = 0; n < nn; ++n) {
        domain::Node& nd = *nodes_[n];
        for (int d = 0; d < nd.ndf; ++d) {
          const int i = first_dof_[n] + d;
          if (alpha == 1.0) {
            nd.disp[d] = U_[i];
            nd.vel[d] = Ud_[i];
          } else {
            nd.disp[d] = Ut_[i] + alpha * (U_[i] - Ut_[i]);
            nd.vel[d] = Utd_[i] + alpha * (Ud_[i] - Utd_[i]);
          }
          nd.accel[d] = Udd_[i];
          nd.incr_disp[d] = nd.disp[d] - nd.committed_disp[d];
        }
      }
      break;
    }
    case IntegratorType::CentralDifference:
      // OpenSees CentralDifference::update: velocity by the backward difference c2 (3 U - 4 Ut + Ut-1),
      // acceleration (Udot - Utdot) / dt.
      for (int n = 0; n < nn; ++n) {
        domain::Node& nd = *nodes_[n];
        for (int d = 0; d < nd.ndf; ++d) {
          const int i = first_dof_[n] + d;
          nd.disp[d] += full[i];
          nd.incr_disp[d] += full[i];
          nd.vel[d] = c2_ * (3.0 * nd.disp[d] - 4.0 * Ut_[i] + Utm1_[i]);
          nd.accel[d] = (nd.vel[d] - Utd_[i]) / dt_;
        }
      }
      break;
  }
  update_elements();
}

void Analysis::impose_prescribed() {
  if ((prescribed_.empty() && tied_to_prescribed_.empty()) || config_.handler == HandlerType::Penalty) return;
  full_.setZero();
  const double t = domain_.time();
  for (const auto& p : prescribed_) {
    const int n = dof_node_[p.dof], d = p.dof - first_dof_[n];
    full_[p.dof] = p.pattern->factor(t) * p.value - nodes_[n]->disp[d];
  }
  for (const auto& [tied, root] : tied_to_prescribed_) {
    const int n = dof_node_[tied], r = dof_node_[root];
    full_[tied] = nodes_[r]->disp[root - first_dof_[r]] + full_[root] - nodes_[n]->disp[tied - first_dof_[n]];
  }
  apply_increment(full_);
}

void Analysis::new_step(double dt) {
  const IntegratorConfig& ic = config_.integrator;
  const int nn = static_cast<int>(nodes_.size());
  step_start_time_ = domain_.committed_time();
  // A finite dLambda or dt can still carry the time past the largest double (found by fuzzing:
  // LoadControl -1e308, whose second step wrote a time of -inf into the recorders): the step fails.
  const double step = ic.type == IntegratorType::LoadControl ? d_lambda_ : dt;
  if (ic.type != IntegratorType::DisplacementControl && !std::isfinite(step_start_time_ + step))
    throw common::NumericalError("the time (or load factor) " + common::number_text(step_start_time_, 6) + " + " +
                                 common::number_text(step, 6) + " is not finite");
  switch (ic.type) {
    case IntegratorType::LoadControl: {
      if (ic.desired_iter > 0 && last_iterations_ > 0) {
        d_lambda_ *= static_cast<double>(ic.desired_iter) / last_iterations_;
        d_lambda_ = std::clamp(d_lambda_, std::min(ic.min_lambda, ic.max_lambda), std::max(ic.min_lambda, ic.max_lambda));
      }
      c1_ = 1.0; c2_ = 0.0; c3_ = 0.0;
      const double t = step_start_time_ + d_lambda_;
      domain_.set_time(t);
      domain_.apply_loads(t);
      break;
    }
    case IntegratorType::DisplacementControl:
      c1_ = 1.0; c2_ = 0.0; c3_ = 0.0;
      control_predictor();
      break;
    case IntegratorType::Newmark:
    case IntegratorType::HHT: {
      const double alpha = ic.type == IntegratorType::HHT ? ic.alpha : 1.0;
      const double g = ic.gamma, b = ic.beta;
      c1_ = alpha;
      c2_ = alpha * g / (b * dt);
      c3_ = 1.0 / (b * dt * dt);
      for (int n = 0; n < nn; ++n) {
        domain::Node& nd = *nodes_[n];
        for (int d = 0; d < nd.ndf; ++d) {
          const int i = first_dof_[n] + d;
          const double cv = nd.committed_vel[d], ca = nd.committed_accel[d];
          Ut_[i] = nd.committed_disp[d];
          Utd_[i] = cv;
          U_[i] = Ut_[i];
          Ud_[i] = (1.0 - g / b) * cv + dt * (1.0 - 0.5 * g / b) * ca;
          Udd_[i] = -cv / (b * dt) + (1.0 - 0.5 / b) * ca;
          nd.disp[d] = U_[i];
          nd.vel[d] = alpha == 1.0 ? Ud_[i] : Utd_[i] + alpha * (Ud_[i] - Utd_[i]);
          nd.accel[d] = Udd_[i];
          nd.incr_disp[d] = 0.0;
        }
      }
      const double t = step_start_time_ + alpha * dt;
      domain_.set_time(t);
      domain_.apply_loads(t);
      update_elements();
      break;
    }
    case IntegratorType::CentralDifference: {
      c1_ = 0.0;
      c2_ = 0.5 / dt;
      c3_ = 1.0 / (dt * dt);
      dt_ = dt;
      if (!have_previous_) {
        // as OpenSees CentralDifference::domainChanged: U(t - dt) is taken equal to U(t)
        std::cerr << "WARNING: CentralDifference::domainChanged() - assuming Ut-1 = Ut\n";
        for (int n = 0; n < nn; ++n) {
          for (int d = 0; d < nodes_[n]->ndf; ++d) {
            const int i = first_dof_[n] + d;
            Ut_[i] = Utm1_[i] = nodes_[n]->committed_disp[d];
            Utd_[i] = nodes_[n]->committed_vel[d];
          }
        }
        have_previous_ = true;
      }
      // Trial state at t chosen so that the increment dU = U(t+dt) - U(t) solves
      // (M/dt^2 + C/(2dt)) dU = P(t) - F(U(t)) + M (Ut - Ut-1)/dt^2 - C (Ut - Ut-1)/(2dt).
      for (int n = 0; n < nn; ++n) {
        domain::Node& nd = *nodes_[n];
        for (int d = 0; d < nd.ndf; ++d) {
          const int i = first_dof_[n] + d;
          nd.disp[d] = Ut_[i];
          nd.vel[d] = c2_ * (Ut_[i] - Utm1_[i]);
          nd.accel[d] = c3_ * (Utm1_[i] - Ut_[i]);
          nd.incr_disp[d] = 0.0;
        }
      }
      // equilibrium at t: loads at the start of the step
      domain_.set_time(step_start_time_);
      domain_.apply_loads(step_start_time_);
      update_elements();
      break;
    }
  }
  impose_prescribed();
}

void Analysis::commit_step(double dt) {
  const IntegratorConfig& ic = config_.integrator;
  const int nn = static_cast<int>(nodes_.size());
  if (ic.type == IntegratorType::HHT && ic.alpha != 1.0) {
    for (int n = 0; n < nn; ++n) {
      for (int d = 0; d < nodes_[n]->ndf; ++d) {
        nodes_[n]->disp[d] = U_[first_dof_[n] + d];
        nodes_[n]->vel[d] = Ud_[first_dof_[n] + d];
        nodes_[n]->accel[d] = Udd_[first_dof_[n] + d];
      }
    }
    update_elements();
  }
  if (!ic.is_static()) domain_.set_time(step_start_time_ + dt);
  if (ic.type == IntegratorType::CentralDifference) {
    for (int n = 0; n < nn; ++n) {
      for (int d = 0; d < nodes_[n]->ndf; ++d) {
        const int i = first_dof_[n] + d;
        Utm1_[i] = Ut_[i];
        Ut_[i] = nodes_[n]->disp[d];
        Utd_[i] = nodes_[n]->vel[d];
      }
    }
  }
  domain_.commit();
}

void Analysis::commit_converged_step(double dt, int iterations) {
  last_iterations_ = std::max(iterations, 1);
  ++stats_.steps;
  commit_step(dt);
}

int Analysis::try_step(double dt, int& iterations) {
  iterations = 0;
  try {
    setup();
    forces_current_ = false;  // the domain may have changed since the last step (Tcl commands, a revert)
    new_step(dt);
    if (!solve_step(config_.algorithm, *this, test_, workspace_, iterations)) {
      std::cerr << "WARNING " << (config_.transient ? "DirectIntegrationAnalysis" : "StaticAnalysis")
                << "::analyze() - the Algorithm failed at time " << domain_.time()
                << "; the domain is reverted to the last committed state (t = " << domain_.committed_time()
                << ")\n";
      domain_.revert_to_last_commit();
      stats_.iterations += iterations;
      return -3;
    }
  } catch (const common::NumericalError& e) {
    std::cerr << "WARNING analyze: " << e.what() << " at time " << domain_.time()
              << "; the domain is reverted to the last committed state (t = " << domain_.committed_time() << ")\n";
    domain_.revert_to_last_commit();
    return -3;
  }
  stats_.iterations += iterations;
  return 0;
}

int Analysis::analyze(int steps, double dt) {
  if (config_.transient && !(dt > 0.0)) throw common::InputError("analyze", "expected dt > 0 for a transient analysis");
  for (int s = 0; s < steps; ++s) {
    int iterations = 0;
    if (const int result = try_step(dt, iterations); result < 0) return result;
    commit_converged_step(dt, iterations);
  }
  stats_.factorizations = solver_->factorizations();
  return 0;
}

int Analysis::analyze_variable(int steps, double dt, double dt_min, double dt_max, int jd) {
  if (!config_.transient) throw common::InputError("analyze", "a variable time step needs a transient analysis");
  if (!(dt > 0.0)) throw common::InputError("analyze", "expected dt > 0 for a transient analysis");
  const double total = steps * dt;
  double done = 0.0, current = dt;
  while (done < total) {
    int iterations = 0;
    const int result = try_step(current, iterations);
    if (result == 0) {
      commit_converged_step(current, iterations);
      done += current;
    } else if (current <= dt_min) {
      std::cerr << "WARNING VariableTimeStepDirectIntegrationAnalysis::analyze() - failed at time "
                << domain_.committed_time() << "\n";
      stats_.factorizations = solver_->factorizations();
      return result;
    }
    // determineDt: a failed step ran all max_iter tests and one more was counted (OpenSees' tests).
    const int tests = std::max(result == 0 ? iterations : iterations + 1, 1);
    const double failed_dt = current;
    current *= static_cast<double>(jd) / tests;
    if (result != 0 && current >= failed_dt) {
      // Jd >= max_iter + 1 (or a step that failed before its tests): OpenSees retries with a dt no smaller
      // and loops for ever; halve it instead.
      std::cerr << "WARNING VariableTransient: Jd = " << jd << " would not shrink the failed step (" << tests
                << " tests); retrying with dt / 2\n";
      current = 0.5 * failed_dt;
    }
    if (current < dt_min) current = dt_min - std::numeric_limits<double>::epsilon();
    else if (current > dt_max) current = dt_max;
  }
  stats_.factorizations = solver_->factorizations();
  return 0;
}

}  // namespace fem::analysis
