#pragma once
// The state the Tcl commands act on: the model (Domain), the named objects the model builder keeps
// (materials, time series), the analysis chain as the user set it, and the current load pattern.
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "fem_tcl/analysis/analysis.hpp"
#include "fem_tcl/domain/domain.hpp"
#include "fem_tcl/domain/time_series.hpp"
#include "fem_tcl/materials/nd_material.hpp"
#include "fem_tcl/materials/uniaxial_material.hpp"

struct Tcl_Interp;

namespace fem::tcl {

/// Thrown by a command whose nested Tcl script failed: the Tcl result and errorInfo are already set.
struct TclScriptError {};

struct AnalysisChain {
  std::optional<analysis::HandlerType> handler;
  double penalty_sp = 0.0;
  double penalty_mp = 0.0;
  std::optional<std::string> numberer;
  std::optional<std::string> system;
  std::optional<analysis::TestConfig> test;
  std::optional<analysis::AlgorithmConfig> algorithm;
  std::optional<analysis::IntegratorConfig> integrator;
  std::optional<bool> transient;  ///< set by `analysis Static|Transient|VariableTransient`
  bool variable_time_step = false;  ///< `analysis VariableTransient`: analyze takes dt dtMin dtMax Jd
};

struct Context {
  Tcl_Interp* interp = nullptr;
  bool model_defined = false;
  int ndf = 2;  ///< dofs of the nodes the builder makes now (`model -ndf`: 2, or 3 for u-p elements)
  domain::Domain domain;
  std::map<int, std::unique_ptr<materials::NDMaterial>> materials;
  materials::UniaxialMaterialMap uniaxial_materials;
  std::map<int, std::shared_ptr<domain::TimeSeries>> time_series;
  AnalysisChain chain;
  std::unique_ptr<analysis::Analysis> analysis;  ///< rebuilt when the chain changes
  bool analysis_dirty = true;
  analysis::EigenModes eigen;  ///< the last `eigen` (nodeEigenvector reads it)
  domain::LoadPattern* current_pattern = nullptr;  ///< inside `pattern Plain ... {body}`
  int failed_analyses = 0;  ///< `analyze` calls that returned < 0 (reported again at exit)
  /// The last command error and the exit status it maps to (2 input, 1 output, 3 numerical), so that
  /// an uncaught error exits with the status of its kind.
  std::string last_error;
  int last_error_status = 2;

  /// Evaluates `script` in the interpreter; throws TclScriptError when it fails.
  void eval(const std::string& script);
  /// wipe: the model, materials, analysis and recorders (time series are kept, FORMATS.md section 1).
  void wipe();
  void wipe_analysis();
};

}  // namespace fem::tcl
