#pragma once
// Factor of safety by shear strength reduction (Zienkiewicz, Humpheson & Lewis 1975; Griffiths & Lane 1999,
// Geotechnique 49(3):387-403; Dawson, Roth & Drescher 1999, Geotechnique 49(6):835-840): the largest factor F
// for which the model stays in equilibrium with the strengths c / F, atan(tan phi / F), atan(tan psi / F)
// (materials/reducible_strength.hpp) under its current loads.
//
// Each trial F starts from the state the command found (the committed state after the gravity stage and the
// stage switch), lowers the strength in `steps` static steps F_k = F (1 - (1 - k/n)^2) (k = 1..n: coarse steps
// while the material is still elastic, fine ones as F is approached), each step by the script's algorithm and
// test with the loads constant (LoadControl with dLambda = 0); a step that does not converge is cut in halves up
// to `max_cuts` times. The state is restored after each trial and at the end (node and material states, time).
//
// Failure criterion of a trial (documented in fem_tcl/README.md):
//   convergence   a step does not converge within the test's iteration limit at the deepest cut
//                 (Griffiths & Lane 1999, sec. "Failure criterion");
//   displacement  (default) that, or the largest nodal displacement increment of the trial (from the state the
//                 command found) exceeding ratio x the largest nodal displacement of that state (the gravity
//                 displacement), or an absolute limit. SSPquad meshes need it: their elastic hourglass
//                 stiffness (McGann et al. 2012) carries the load past collapse, so Newton keeps converging while
//                 the displacement increment grows by orders of magnitude.
// Search: bracketing from F = 1 (or the given bracket) by factors of 1.5, then bisection until the bracket is
// narrower than the tolerance; F is the bracket's midpoint.
#include <iosfwd>
#include <optional>
#include <set>
#include <vector>

#include "common/command_args.hpp"
#include "fem_tcl/analysis/analysis.hpp"
#include "fem_tcl/domain/domain.hpp"

namespace fem::analysis {

enum class FailureCriterion { Convergence, Displacement };

struct StrengthReductionOptions {
  std::set<int> materials;                 ///< -materials {tags}
  std::optional<double> lower, upper;      ///< -bracket Flo Fhi (Flo stable, Fhi failing; widened if not)
  double tolerance = 0.005;                ///< -tol: width of the final bracket in F
  FailureCriterion criterion = FailureCriterion::Displacement;  ///< -criterion convergence|displacement
  double displacement_ratio = 5.0;         ///< -displacementRatio r: limit = r x the largest start displacement
  std::optional<double> displacement_limit;  ///< -displacementLimit d: absolute limit (length), replaces the ratio
  int steps = 10;                          ///< -steps n: strength steps per trial
  int max_cuts = 4;                        ///< -maxCuts m: halvings of a step that does not converge
  int max_trials = 60;                     ///< -maxTrials
};

/// `strengthReduction -materials {tags} ?options?` (args after the command name).
StrengthReductionOptions parse_strength_reduction(common::CommandArgs& args);

struct StrengthReductionTrial {
  double factor = 0.0;
  bool converged = true;         ///< every step converged (false: a step failed at the deepest cut)
  bool failed = false;           ///< by the criterion
  long iterations = 0;           ///< Newton iterations of all steps, cut attempts included
  int steps = 0;                 ///< converged steps
  int cuts = 0;                  ///< step halvings
  double max_displacement = 0.0;  ///< largest nodal displacement increment from the start state
};

struct StrengthReductionResult {
  double factor = 0.0;       ///< F, the midpoint of [lower, upper]
  double lower = 0.0;        ///< largest stable trial
  double upper = 0.0;        ///< smallest failing trial
  double reference_displacement = 0.0;  ///< largest nodal displacement of the start state
  double displacement_limit = 0.0;      ///< the displacement criterion's limit (0 with -criterion convergence)
  std::vector<StrengthReductionTrial> trials;
};

/// Runs the search on `domain` with `config` (a static LoadControl analysis; its dLambda is replaced by 0) and
/// the elements whose material tag is in options.materials; one line per trial on `log`. The domain's state
/// is restored at the end. Throws common::InputError when the analysis is not static, no element uses the
/// materials, the search cannot bracket F, or the displacement criterion has no reference displacement.
StrengthReductionResult strength_reduction(domain::Domain& domain, const AnalysisConfig& config,
                                           const StrengthReductionOptions& options, std::ostream& log);

}  // namespace fem::analysis
