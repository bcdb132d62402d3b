#include "fem_tcl/analysis/strength_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <ostream>
#include <string>

#include "common/input_error.hpp"

namespace fem::analysis {

namespace {

constexpr const char* kCommand = "strengthReduction";
constexpr double kGrowth = 1.5;      // bracketing factor
constexpr double kSmallest = 0.01;   // below this F the model is not in equilibrium for any strength
constexpr double kLargest = 100.0;   // above this F the model is taken as not failing at all

/// The state a trial starts from: nodes, material points and time (restored after each trial).
class DomainSnapshot {
 public:
  explicit DomainSnapshot(domain::Domain& domain) : domain_(domain) {
    for (const auto& [tag, n] : domain.nodes()) nodes_.push_back(*n);
    for (const auto& [tag, e] : domain.elements()) elements_.push_back(e->save_state());
    time_ = domain.time();
    committed_time_ = domain.committed_time();
  }
  void restore() const {
    std::size_t i = 0;
    for (const auto& [tag, n] : domain_.nodes()) *n = nodes_[i++];
    i = 0;
    for (const auto& [tag, e] : domain_.elements()) e->restore_state(*elements_[i++]);
    domain_.set_committed_time(committed_time_);
    domain_.set_time(time_);
  }
  /// Largest |u - u_snapshot| over the nodes (trial displacements).
  double largest_increment() const {
    double m = 0.0;
    std::size_t i = 0;
    for (const auto& [tag, n] : domain_.nodes()) m = std::max(m, (n->solid_disp() - nodes_[i++].committed_disp.head<2>()).norm());
    return m;
  }
  /// Largest |u| of the snapshot (committed displacements).
  double largest_displacement() const {
    double m = 0.0;
    for (const auto& n : nodes_) m = std::max(m, n.committed_disp.head<2>().norm());
    return m;
  }

 private:
  domain::Domain& domain_;
  std::vector<domain::Node> nodes_;
  std::vector<std::unique_ptr<domain::ElementState>> elements_;
  double time_ = 0.0, committed_time_ = 0.0;
};

class Search {
 public:
  Search(domain::Domain& domain, const AnalysisConfig& config, const StrengthReductionOptions& options,
         std::ostream& log)
      : domain_(domain), options_(options), log_(log), start_(domain), analysis_(domain, trial_config(config)) {
    for (const auto& [tag, e] : domain.elements()) {
      if (options.materials.count(e->material_tag())) targets_.push_back(e.get());
    }
    if (targets_.empty()) throw common::InputError(kCommand, "no element uses the -materials given");
    result_.reference_displacement = start_.largest_displacement();
    if (options.criterion == FailureCriterion::Displacement) {
      result_.displacement_limit = options.displacement_limit.value_or(options.displacement_ratio *
                                                                        result_.reference_displacement);
      if (!(result_.displacement_limit > 0.0)) {
        throw common::InputError(kCommand, "the displacement criterion needs a reference: the state has no "
                                           "displacement (apply gravity first, or give -displacementLimit d)");
      }
    }
  }

  StrengthReductionResult run() {
    domain_.set_trial_commits(true);
    try {
      bracket();
      while (result_.upper - result_.lower > options_.tolerance) {
        const double mid = 0.5 * (result_.lower + result_.upper);
        (trial(mid) ? result_.upper : result_.lower) = mid;
      }
    } catch (...) {
      finish();
      throw;
    }
    finish();
    result_.factor = 0.5 * (result_.lower + result_.upper);
    return result_;
  }

 private:
  static AnalysisConfig trial_config(AnalysisConfig config) {
    if (config.transient || !config.integrator.is_static()) {
      throw common::InputError(kCommand, "needs a static analysis ('integrator LoadControl' and 'analysis Static')");
    }
    config.integrator.d_lambda = 0.0;  // the loads stay as they are (loadConst or not)
    config.integrator.desired_iter = 0;
    return config;
  }

  void finish() {
    start_.restore();  // the saved material states carry their own strength factor
    domain_.set_trial_commits(false);
  }

  /// Finds lower (stable) < upper (failing): the given bracket (default 1, 1.5), widened by factors of 1.5.
  void bracket() {
    double lo = options_.lower.value_or(1.0);
    double hi = options_.upper.value_or(lo * kGrowth);
    if (trial(lo)) {
      hi = lo;
      lo = hi / kGrowth;
      while (true) {
        if (lo < kSmallest) {
          throw common::InputError(kCommand, "the model fails even at F = " + number(hi) + " (strengths x " +
                                                 number(1.0 / hi) + "): check its supports and loads");
        }
        if (!trial(lo)) break;
        hi = lo;
        lo /= kGrowth;
      }
    } else {
      while (!trial(hi)) {
        lo = hi;
        hi *= kGrowth;
        if (hi > kLargest) {
          throw common::InputError(kCommand, "no failure up to F = " + number(lo) +
                                                 " (does the mechanism cross only non-reducible materials?)");
        }
      }
    }
    result_.lower = lo;
    result_.upper = hi;
  }

  /// Runs one trial from the start state; returns true when it fails by the criterion.
  bool trial(double factor) {
    if (static_cast<int>(result_.trials.size()) >= options_.max_trials) {
      throw common::InputError(kCommand, "no factor of safety within " + std::to_string(options_.max_trials) +
                                             " trials (-maxTrials)");
    }
    start_.restore();
    StrengthReductionTrial t;
    t.factor = factor;
    const int n = options_.steps;
    double current = 0.0;  // F of the last converged step (0: the start state, strength not yet reduced)
    for (int k = 1; k <= n && !t.failed; ++k) {
      const double s = 1.0 - static_cast<double>(k) / n;
      const double target = factor * (1.0 - s * s);
      double increment = target - current;
      const double smallest = increment / std::pow(2.0, options_.max_cuts);
      while (current < target && !t.failed) {
        const double next = std::min(target, current + increment);
        for (domain::Element* e : targets_) e->reduce_strength(next);
        const long before = analysis_.stats().iterations;
        const int code = analysis_.analyze(1, 0.0);
        t.iterations += analysis_.stats().iterations - before;
        if (code == 0) {
          current = next;
          ++t.steps;
          t.max_displacement = std::max(t.max_displacement, start_.largest_increment());
          if (options_.criterion == FailureCriterion::Displacement && t.max_displacement > result_.displacement_limit) {
            t.failed = true;
          }
        } else if (increment > smallest * 1.000001) {
          increment *= 0.5;
          ++t.cuts;
        } else {
          t.converged = false;
          t.failed = true;
        }
      }
    }
    result_.trials.push_back(t);
    report(t);
    return t.failed;
  }

  void report(const StrengthReductionTrial& t) {
    char line[320];
    std::snprintf(line, sizeof line,
                  "strengthReduction trial %zu: F = %.5f %s, %ld iterations (%d steps, %d cuts), largest "
                  "displacement %.6g -> %s\n",
                  result_.trials.size(), t.factor, t.converged ? "converged" : "not converged", t.iterations,
                  t.steps, t.cuts, t.max_displacement,
                  !t.failed ? "stable" : !t.converged ? "failed (no convergence)" : "failed (displacement)");
    log_ << line << std::flush;
  }

  static std::string number(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.4g", v);
    return b;
  }

  domain::Domain& domain_;
  const StrengthReductionOptions& options_;
  std::ostream& log_;
  DomainSnapshot start_;
  Analysis analysis_;
  std::vector<domain::Element*> targets_;
  StrengthReductionResult result_;
};

}  // namespace

StrengthReductionOptions parse_strength_reduction(common::CommandArgs& args) {
  StrengthReductionOptions o;
  bool have_materials = false;
  const auto positive = [&](const char* what) {
    const double v = args.number(what);
    if (!(v > 0.0) || !std::isfinite(v)) args.fail(std::string("expected ") + what + " > 0");
    return v;
  };
  while (!args.empty()) {
    if (args.flag("-materials")) {
      const std::string list = args.word("-materials {tags}");
      std::size_t at = 0;
      while (at < list.size()) {
        const std::size_t begin = list.find_first_not_of(" \t\n{}", at);
        if (begin == std::string::npos) break;
        const std::size_t end = std::min(list.find_first_of(" \t\n{}", begin), list.size());
        const std::string word = list.substr(begin, end - begin);
        const auto tag = common::CommandArgs::parse_integer(word);
        if (!tag) args.fail("expected -materials {tags} (integers), got '" + word + "'");
        o.materials.insert(*tag);
        at = end;
      }
      have_materials = !o.materials.empty();
    } else if (args.flag("-bracket")) {
      o.lower = positive("-bracket Flo");
      o.upper = positive("-bracket Fhi");
      if (!(*o.upper > *o.lower)) args.fail("expected -bracket Flo Fhi with Flo < Fhi");
    } else if (args.flag("-tol")) {
      o.tolerance = positive("-tol");
    } else if (args.flag("-criterion")) {
      const std::string c = args.word("-criterion (convergence or displacement)");
      if (c == "convergence") o.criterion = FailureCriterion::Convergence;
      else if (c == "displacement") o.criterion = FailureCriterion::Displacement;
      else args.fail("expected -criterion convergence or displacement, got '" + c + "'");
    } else if (args.flag("-displacementRatio")) {
      o.displacement_ratio = positive("-displacementRatio");
    } else if (args.flag("-displacementLimit")) {
      o.displacement_limit = positive("-displacementLimit");
    } else if (args.flag("-steps")) {
      o.steps = args.integer("-steps");
      if (o.steps < 1) args.fail("expected -steps n >= 1");
    } else if (args.flag("-maxCuts")) {
      o.max_cuts = args.integer("-maxCuts");
      if (o.max_cuts < 0 || o.max_cuts > 20) args.fail("expected -maxCuts m in 0..20");
    } else if (args.flag("-maxTrials")) {
      o.max_trials = args.integer("-maxTrials");
      if (o.max_trials < 2) args.fail("expected -maxTrials >= 2");
    } else {
      args.fail("unknown option '" + args.peek() + "'");
    }
  }
  if (!have_materials) args.fail("expected -materials {tags}");
  return o;
}

StrengthReductionResult strength_reduction(domain::Domain& domain, const AnalysisConfig& config,
                                           const StrengthReductionOptions& options, std::ostream& log) {
  Search search(domain, config, options, log);
  return search.run();
}

}  // namespace fem::analysis
