// The analysis chain (constraints ... analysis), analyze, and time/stage control.
#include <cstdio>
#include <iostream>
#include <optional>

#include "fem_tcl/analysis/strength_reduction.hpp"
#include "fem_tcl/tcl/commands.hpp"

namespace fem::tcl {

namespace {

void mark_dirty(Context& ctx) { ctx.analysis_dirty = true; }

/// Fills what the user did not give with OpenSees' defaults, with a warning as OpenSees prints.
analysis::AnalysisConfig complete_chain(Context& ctx) {
  AnalysisChain& c = ctx.chain;
  const bool transient = c.transient.value_or(false);
  const char* kind = transient ? "Transient" : "Static";
  const auto warn = [&](const char* what, const char* fallback) {
    std::cerr << "WARNING analysis " << kind << " - no " << what << " yet specified, " << fallback
              << " default will be used\n";
  };
  if (!c.handler) { warn("ConstraintHandler", "PlainHandler"); c.handler = analysis::HandlerType::Plain; }
  if (!c.numberer) { warn("DOF_Numberer", "RCM"); c.numberer = "RCM"; }
  if (!c.system) { warn("LinearSOE", "ProfileSPD"); c.system = "ProfileSPD"; }
  if (!c.test) c.test = analysis::TestConfig{};  // OpenSees creates its default test silently
  if (!c.algorithm) { warn("EquiSolnAlgo", "NewtonRaphson"); c.algorithm = analysis::AlgorithmConfig{}; }
  if (!c.integrator) {
    analysis::IntegratorConfig ic;
    if (transient) {
      warn("Integrator", "Newmark 0.5 0.25");
      ic.type = analysis::IntegratorType::Newmark;
    } else {
      warn("Integrator", "LoadControl 1.0");
    }
    c.integrator = ic;
  }
  analysis::AnalysisConfig config;
  config.handler = *c.handler;
  config.penalty_sp = c.penalty_sp;
  config.penalty_mp = c.penalty_mp;
  config.numberer = *c.numberer;
  config.system = *c.system;
  config.test = *c.test;
  config.algorithm = *c.algorithm;
  config.integrator = *c.integrator;
  config.transient = transient;
  return config;
}

}  // namespace

std::string cmd_constraints(Context& ctx, common::CommandArgs& args) {
  const std::string type = args.word("type (Plain, Transformation or Penalty)");
  if (type == "Plain") ctx.chain.handler = analysis::HandlerType::Plain;
  else if (type == "Transformation") ctx.chain.handler = analysis::HandlerType::Transformation;
  else if (type == "Penalty") {
    ctx.chain.handler = analysis::HandlerType::Penalty;
    ctx.chain.penalty_sp = args.number("alphaS");
    ctx.chain.penalty_mp = args.number("alphaM");
    if (!(ctx.chain.penalty_sp > 0.0) || !(ctx.chain.penalty_mp > 0.0)) args.fail("expected alphaS > 0 and alphaM > 0");
  } else args.fail("unknown constraint handler '" + type + "'");
  args.expect_end();
  mark_dirty(ctx);
  return {};
}

std::string cmd_numberer(Context& ctx, common::CommandArgs& args) {
  std::string type = args.word("type (Plain, RCM, AMD, ParallelPlain or ParallelRCM)");
  // OpenSees' Parallel* numberers number a sequential model as the plain ones do
  if (type == "ParallelPlain" || type == "ParallelRCM") type = type.substr(8);
  if (type != "Plain" && type != "RCM" && type != "AMD") args.fail("unknown numberer '" + type + "'");
  args.expect_end();
  ctx.chain.numberer = type;
  mark_dirty(ctx);
  return {};
}

std::string cmd_system(Context& ctx, common::CommandArgs& args) {
  const std::string type = args.word("type");
  analysis::SolverKind kind{};
  if (!analysis::solver_kind_for(type, kind)) args.fail("unknown system '" + type + "'");
  // solver tuning flags of OpenSees (-piv, -lvalueFact, ...) do not change results; accept them
  while (!args.empty()) {
    const std::string w = args.word("option");
    if (w.empty() || w[0] != '-') args.fail("unexpected argument '" + w + "'");
    if (!args.empty() && common::CommandArgs::parse_number(args.peek())) args.word("option value");
  }
  ctx.chain.system = type;
  mark_dirty(ctx);
  return {};
}

std::string cmd_test(Context& ctx, common::CommandArgs& args) {
  ctx.chain.test = analysis::parse_test(args);
  mark_dirty(ctx);
  return {};
}

std::string cmd_algorithm(Context& ctx, common::CommandArgs& args) {
  ctx.chain.algorithm = analysis::parse_algorithm(args);
  mark_dirty(ctx);
  return {};
}

std::string cmd_integrator(Context& ctx, common::CommandArgs& args) {
  ctx.chain.integrator = analysis::parse_integrator(args);
  mark_dirty(ctx);
  return {};
}

std::string cmd_analysis(Context& ctx, common::CommandArgs& args) {
  const std::string type = args.word("type (Static, Transient or VariableTransient)");
  if (type == "Static") ctx.chain.transient = false;
  else if (type == "Transient" || type == "VariableTransient") ctx.chain.transient = true;
  else args.fail("unknown analysis type '" + type + "' (Static, Transient or VariableTransient)");
  args.expect_end();
  ctx.chain.variable_time_step = type == "VariableTransient";
  const analysis::AnalysisConfig config = complete_chain(ctx);
  if (config.transient == config.integrator.is_static()) {
    args.fail(std::string("integrator ") + (config.transient ? "is static" : "is transient") +
              "; use " + (config.transient ? "Newmark, HHT or CentralDifference" : "LoadControl or DisplacementControl") +
              " with analysis " + type);
  }
  mark_dirty(ctx);
  return {};
}

std::string cmd_analyze(Context& ctx, common::CommandArgs& args) {
  const int steps = args.integer("numSteps");
  if (steps < 0) args.fail("expected numSteps >= 0");
  if (!ctx.chain.transient) args.fail("no analysis defined; use 'analysis Static' or 'analysis Transient' first");
  double dt = 0.0, dt_min = 0.0, dt_max = 0.0;
  int jd = 0;
  if (*ctx.chain.transient) {
    dt = args.number("dt");
    if (!(dt > 0.0)) args.fail("expected dt > 0");
    if (ctx.chain.variable_time_step) {  // OpenSees: analyze numIncr deltaT dtMin dtMax Jd
      dt_min = args.number("dtMin");
      dt_max = args.number("dtMax");
      jd = args.integer("Jd");
      if (!(dt_min > 0.0) || !(dt_max >= dt_min)) args.fail("expected 0 < dtMin <= dtMax");
      if (jd < 1) args.fail("expected Jd >= 1 (the desired iterations per step)");
    }
  } else if (!args.empty()) {
    args.number("dt");  // OpenSees ignores dt for static analyses
  }
  args.expect_end();
  if (ctx.analysis_dirty || !ctx.analysis) {
    const analysis::AnalysisConfig config = complete_chain(ctx);
    if (config.transient == config.integrator.is_static()) {
      args.fail("the integrator does not match the analysis type (LoadControl and DisplacementControl need Static; "
                "Newmark, HHT, CentralDifference need Transient)");
    }
    ctx.analysis = std::make_unique<analysis::Analysis>(ctx.domain, config);
    ctx.analysis_dirty = false;
  }
  const int result = ctx.chain.variable_time_step ? ctx.analysis->analyze_variable(steps, dt, dt_min, dt_max, jd)
                                                  : ctx.analysis->analyze(steps, dt);
  if (result < 0) ++ctx.failed_analyses;
  return std::to_string(result);
}

std::string cmd_strength_reduction(Context& ctx, common::CommandArgs& args) {
  const analysis::StrengthReductionOptions options = analysis::parse_strength_reduction(args);
  for (int tag : options.materials) {
    auto it = ctx.materials.find(tag);
    if (it == ctx.materials.end()) args.fail("nDMaterial " + std::to_string(tag) + " does not exist");
    if (!it->second->reducible_strength()) {
      args.fail("nDMaterial " + std::to_string(tag) + " (" + it->second->type_name() +
                ") has no strength to reduce (MohrCoulomb and DruckerPrager have)");
    }
  }
  if (!ctx.chain.transient || *ctx.chain.transient) {
    args.fail("needs a static analysis: define 'integrator LoadControl' and 'analysis Static' first");
  }
  const analysis::StrengthReductionResult result =
      analysis::strength_reduction(ctx.domain, complete_chain(ctx), options, std::cerr);
  char text[64];
  std::snprintf(text, sizeof text, "%.6g", result.factor);
  return text;
}

std::string cmd_load_const(Context& ctx, common::CommandArgs& args) {
  ctx.domain.set_load_const();
  if (args.flag("-time")) ctx.domain.set_committed_time(args.number("-time value"));
  args.expect_end();
  return {};
}

std::string cmd_set_time(Context& ctx, common::CommandArgs& args) {
  const double t = args.number("time");
  args.expect_end();
  ctx.domain.set_committed_time(t);
  return {};
}

std::string cmd_get_time(Context& ctx, common::CommandArgs& args) {
  std::string format = "%f";
  if (!args.empty()) {
    format = args.word("format");
    // exactly one floating-point conversion: %[flags][width][.precision](f|e|E|g|G)
    std::size_t i = 0;
    std::size_t conversions = 0;
    for (; i < format.size(); ++i) {
      if (format[i] != '%') continue;
      if (i + 1 < format.size() && format[i + 1] == '%') { ++i; continue; }
      std::size_t j = i + 1;
      while (j < format.size() && std::string_view("-+ #0").find(format[j]) != std::string_view::npos) ++j;
      while (j < format.size() && std::isdigit(static_cast<unsigned char>(format[j]))) ++j;
      if (j < format.size() && format[j] == '.') {
        ++j;
        while (j < format.size() && std::isdigit(static_cast<unsigned char>(format[j]))) ++j;
      }
      if (j >= format.size() || std::string_view("feEgG").find(format[j]) == std::string_view::npos) {
        args.fail("expected a format with one %f, %e or %g conversion, got '" + format + "'");
      }
      ++conversions;
      i = j;
    }
    if (conversions != 1) args.fail("expected a format with one %f, %e or %g conversion, got '" + format + "'");
  }
  args.expect_end();
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, format.c_str(), ctx.domain.time());
  return buffer;
}

std::string cmd_wipe(Context& ctx, common::CommandArgs& args) {
  args.expect_end();
  ctx.wipe();
  return {};
}

std::string cmd_wipe_analysis(Context& ctx, common::CommandArgs& args) {
  args.expect_end();
  ctx.wipe_analysis();
  return {};
}

std::string cmd_reset(Context& ctx, common::CommandArgs& args) {
  args.expect_end();
  ctx.domain.revert_to_start();
  return {};
}

std::string cmd_remove(Context& ctx, common::CommandArgs& args) {
  const std::string what = args.word("what (recorders, recorder, loadPattern, element, node or sp)");
  if (what == "recorders") {
    ctx.domain.remove_recorders();
  } else if (what == "recorder") {
    const int tag = args.integer("recorder tag");
    if (!ctx.domain.remove_recorder(tag)) args.fail("recorder " + std::to_string(tag) + " does not exist");
  } else if (what == "loadPattern" || what == "pattern") {
    const int tag = args.integer("pattern tag");
    if (!ctx.domain.remove_pattern(tag)) args.fail("load pattern " + std::to_string(tag) + " does not exist");
    ctx.analysis_dirty = true;
  } else if (what == "timeSeries") {
    // OpenSees `remove timeSeries tag`: the tag is free for a new series; a pattern built with it keeps it
    const int tag = args.integer("timeSeries tag");
    if (ctx.time_series.erase(tag) == 0) args.fail("timeSeries " + std::to_string(tag) + " does not exist");
  } else if (what == "element" || what == "ele") {
    // OpenSees `remove element tag` (an excavation): gone from the next step on; its nodes stay.
    const int tag = args.integer("element tag");
    if (!ctx.domain.remove_element(tag)) args.fail("element " + std::to_string(tag) + " does not exist");
    ctx.analysis_dirty = true;
  } else if (what == "node") {
    // OpenSees `remove node tag`: after its elements (an excavation's free nodes)
    const int tag = args.integer("node tag");
    if (!ctx.domain.remove_node(tag, args.command())) args.fail("node " + std::to_string(tag) + " does not exist");
    ctx.analysis_dirty = true;
  } else if (what == "sp") {
    // OpenSees `remove sp nodeTag dofTag <patternTag>`: the fix on that dof (Domain::removeSP_Constraint),
    // or the pattern's sp; the dof is free from the next step on, so the force it carried becomes unbalance
    // (an excavation, a support taken away). Nothing to remove: OpenSees goes on quietly; fem_tcl warns.
    const int node = args.integer("nodeTag");
    const int dof = args.integer("dofTag");
    std::optional<int> pattern;
    if (!args.empty()) pattern = args.integer("patternTag");
    args.expect_end();
    domain::Node& n = ctx.domain.node(node, args.command());
    if (dof < 1 || dof > n.ndf) {
      args.fail("expected dofTag 1.." + std::to_string(n.ndf) + " (node " + std::to_string(node) + " has " +
                std::to_string(n.ndf) + "), got " + std::to_string(dof));
    }
    bool removed = false;
    if (!pattern) {
      removed = n.fixed[static_cast<std::size_t>(dof - 1)];
      n.fixed[static_cast<std::size_t>(dof - 1)] = false;
    } else {
      domain::LoadPattern* p = ctx.domain.find_pattern(*pattern);
      if (!p) args.fail("load pattern " + std::to_string(*pattern) + " does not exist");
      const auto before = p->prescribed.size();
      std::erase_if(p->prescribed, [&](const domain::PrescribedDisp& sp) { return sp.node == node && sp.dof == dof - 1; });
      removed = p->prescribed.size() != before;
    }
    if (!removed) {
      std::cerr << "WARNING remove sp: node " << node << " dof " << dof << " has no sp constraint"
                << (pattern ? " in pattern " + std::to_string(*pattern) : std::string()) << "; nothing removed\n";
    }
    ctx.domain.touch();
    ctx.analysis_dirty = true;
    return {};
  } else {
    args.fail("unknown object '" + what + "' (recorders, recorder, loadPattern, timeSeries, element, node or sp)");
  }
  args.expect_end();
  return {};
}

}  // namespace fem::tcl
