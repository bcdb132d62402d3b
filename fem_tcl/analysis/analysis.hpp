#pragma once
// One analysis (OpenSees StaticAnalysis / DirectIntegrationAnalysis): dof numbering with the constraints
// eliminated, the sparse system, the integrator's predictor/corrector, the algorithm and the commit.
// `analyze` returns 0 or a negative code as OpenSees does; a failed step is reverted to the last commit,
// so a script that ignores the code keeps the last converged state, never a diverged one.
#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fem_tcl/analysis/algorithm.hpp"
#include "fem_tcl/analysis/convergence_test.hpp"
#include "fem_tcl/analysis/displacement_control.hpp"
#include "fem_tcl/analysis/integrator.hpp"
#include "fem_tcl/analysis/linear_solver.hpp"
#include "fem_tcl/domain/domain.hpp"

namespace fem::analysis {

enum class HandlerType { Plain, Transformation, Penalty };

struct AnalysisConfig {
  HandlerType handler = HandlerType::Plain;
  double penalty_sp = 0.0;  ///< Penalty alphaS (single-point constraints)
  double penalty_mp = 0.0;  ///< Penalty alphaM (equalDOF)
  std::string numberer = "RCM";
  std::string system = "ProfileSPD";
  TestConfig test;
  AlgorithmConfig algorithm;
  IntegratorConfig integrator;
  bool transient = false;
};

struct AnalysisStats {
  long steps = 0;
  long iterations = 0;
  long factorizations = 0;
};

/// The result of `eigen` (Analysis::eigen_modes).
struct EigenModes {
  std::vector<double> eigenvalues;      ///< lambda = omega^2 (1/s^2), ascending
  std::vector<int> node_tags;           ///< the nodes of the shapes, in tag order
  std::vector<int> node_first_dof;      ///< per node of node_tags: its first entry in a shape (ndf entries)
  std::vector<Eigen::VectorXd> shapes;  ///< per mode: the dofs of each node; phi^T M phi = 1, 0 at fixed dofs
};

class Analysis final : public StepProblem {
 public:
  Analysis(domain::Domain& domain, AnalysisConfig config);

  /// Runs `steps` steps (dt ignored by static analyses). Returns 0, or -2 (step could not start),
  /// -3 (the algorithm failed or the system is singular; warning on stderr, state reverted).
  int analyze(int steps, double dt);
  /// OpenSees' VariableTransient (VariableTimeStepDirectIntegrationAnalysis::analyze): steps of dt_k until
  /// steps * dt of time is done (the last step may pass it); after every step, converged or not,
  /// dt_{k+1} = dt_k jd / n_k with n_k the convergence tests of the step (a failed one counts max_iter + 1,
  /// as OpenSees' tests do), kept in [dt_min, dt_max] (below dt_min: dt_min - DBL_EPSILON, so that a
  /// further failure ends the analysis); a failed step is reverted and retried with the new dt unless its
  /// dt was already <= dt_min, which returns the failure code. Where OpenSees would retry a failed step
  /// with a dt no smaller (Jd >= max_iter + 1) and loop for ever, the dt is halved (warning). Returns 0 or
  /// the negative code of analyze().
  int analyze_variable(int steps, double dt, double dt_min, double dt_max, int jd);
  /// OpenSees' `eigen`: the n lowest modes of K phi = lambda M phi, K the current tangent and M the lumped
  /// mass of the free equations (eigen_analysis.cpp). Throws common::NumericalError when K is singular
  /// or fewer than n equations carry mass.
  EigenModes eigen_modes(int n);
  const AnalysisStats& stats() const { return stats_; }
  const ConvergenceTest& test() const { return test_; }
  const AnalysisConfig& config() const { return config_; }
  int equations() const override { return neq_; }

  // StepProblem
  void form_tangent() override;
  void form_unbalance() override;
  const Eigen::VectorXd& unbalance() const override { return R_; }
  void solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) override;
  void update(const Eigen::VectorXd& dU) override;
  const Eigen::VectorXd& tested_increment(const Eigen::VectorXd& solved) const override {
    return control_ ? control_increment_ : solved;
  }

 private:
  struct Prescribed { int dof; const domain::LoadPattern* pattern; double value; };  ///< pattern null: fix
  struct PenaltyPair { int retained; int constrained; };  ///< full-dof indices
  double prescribed_value(const Prescribed& p) const;
  void setup();
  void new_step(double dt);
  void apply_increment(const Eigen::VectorXd& full);  // full-dof increment through the integrator
  void apply_free_increment(const Eigen::VectorXd& dU);  // free-equation increment, through apply_increment
  void commit_step(double dt);
  /// One step of dt: setup, predictor, solve; the state is reverted (warning on stderr) when it fails.
  /// Returns 0 (converged, not yet committed) or -3; `iterations` counts the algorithm's iterations.
  int try_step(double dt, int& iterations);
  /// After a converged try_step: its iterations (LoadControl's Jd) and the step counted, then the commit.
  void commit_converged_step(double dt, int iterations);
  void impose_prescribed();
  /// The lumped mass of the free equations (elements, then nodal `mass`), summed where dofs share one.
  Eigen::VectorXd equation_masses() const;
  /// Trial strains of every element from the nodes' trial displacements (vector loop, no map walk); in a
  /// transient analysis each element's unbalance contribution is formed in the same pass (element_force_).
  void update_elements();

  domain::Domain& domain_;
  AnalysisConfig config_;
  ConvergenceTest test_;
  AlgorithmWorkspace workspace_;
  std::unique_ptr<LinearSolver> solver_;
  long version_ = -1;

  std::vector<domain::Node*> nodes_;
  std::vector<domain::Element*> elements_;
  /// The equations of an element's dofs, in its dof order (-1: fixed or not an equation).
  struct ElementEquations {
    std::array<int, domain::kMaxElementDofs> eq{};
    int count = 0;
  };
  std::vector<int> first_dof_;                   ///< per node: its first full dof (ndf consecutive); last: total
  std::vector<int> dof_node_;                    ///< per full dof: the index of its node
  std::vector<int> eq_;                          ///< per full dof: equation or -1
  /// equalDOF ties whose retained dof is fixed or prescribed: (constrained, retained) full dofs; the
  /// constrained one follows the retained one's value when the prescribed values are imposed.
  std::vector<std::pair<int, int>> tied_to_prescribed_;
  std::vector<ElementEquations> element_eq_;
  /// Value positions in A (or -1) of each element matrix entry, column-major, element e's from
  /// element_pos_first_[e].
  std::vector<int> element_pos_;
  std::vector<std::size_t> element_pos_first_;
  std::vector<int> diag_pos_;                    ///< per equation
  std::vector<Prescribed> prescribed_;   ///< eliminated (Plain/Transformation) or penalized (Penalty)
  std::vector<PenaltyPair> penalty_pairs_;
  std::vector<int> penalty_diag_pos_;     ///< per prescribed_ entry, Penalty only
  std::vector<std::array<int, 4>> penalty_pair_pos_;  ///< (rr, rc, cr, cc) per pair
  int neq_ = 0;

  Eigen::VectorXd R_;
  /// Per element, its form_unbalance at the state of the last update_elements (one pass over the elements
  /// per iteration instead of two); valid while forces_current_.
  std::vector<domain::ElementVector> element_force_;
  bool forces_current_ = false;
  Eigen::VectorXd full_;  ///< full-dof work vector
  Eigen::VectorXd dx_;
  // Newmark / HHT / central-difference state (full dofs)
  Eigen::VectorXd U_, Ud_, Udd_, Ut_, Utd_, Utm1_;
  bool have_previous_ = false;
  double c1_ = 1.0, c2_ = 0.0, c3_ = 0.0;  ///< tangent = c1 K + c2 C + c3 M
  /// The factored matrix of an `-elasticTangent` algorithm, kept from one form_tangent to the next while
  /// nothing that enters it can have changed: every element's linear terms fixed (Element::
  /// linear_terms_fixed), no Rayleigh term on a current or committed tangent, the same c1 c2 c3 and no
  /// command in between (Domain::command_revision). Reset by setup().
  struct KeptMatrix {
    bool valid = false;
    long revision = 0;
    double c1 = 0.0, c2 = 0.0, c3 = 0.0;
  } kept_;
  double step_start_time_ = 0.0;
  double dt_ = 0.0;
  double d_lambda_ = 0.0;
  int last_iterations_ = 1;
  // DisplacementControl: the integrator, A^-1 phat, and the increment its last update applied
  std::optional<DisplacementControl> control_;
  Eigen::VectorXd control_dUhat_, control_increment_;
  /// Applies the predictor (new_step) and each correction (update) of DisplacementControl.
  void control_predictor();
  void control_update(const Eigen::VectorXd& dUbar);
  /// At a rebuild: the control dof's equation and the reference load phat = R(lambda + 1).
  void control_reference();
  AnalysisStats stats_;
};

}  // namespace fem::analysis
