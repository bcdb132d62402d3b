#pragma once
// The embedded Tcl 8.6 interpreter with fem_tcl's commands, and the program's entry point.
#include <memory>
#include <string>
#include <vector>

#include "fem_tcl/tcl/context.hpp"

namespace fem::tcl {

class Interpreter {
 public:
  Interpreter();
  ~Interpreter();
  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;

  /// Sets argv0, argv and argc as tclsh does.
  void set_arguments(const std::string& argv0, const std::vector<std::string>& args);
  /// Evaluates a script; on error returns false and sets `message` to "file:line: message".
  bool eval_file(const std::string& path, std::string& message);
  bool eval_script(const std::string& script, const std::string& name, std::string& message);
  /// Evaluates `script` and returns its Tcl result; throws common::InputError("script:line: message").
  std::string eval(const std::string& script);
  Context& context() { return *context_; }
  struct Binding;  ///< (context, command entry) handed to Tcl as ClientData

 private:
  std::unique_ptr<Context> context_;
  std::vector<std::unique_ptr<Binding>> bindings_;
};

/// `fem_tcl [--help] [script.tcl [args..]]`; returns the process exit code.
int run_main(int argc, char** argv);

}  // namespace fem::tcl
