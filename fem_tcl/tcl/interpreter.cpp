#include "fem_tcl/tcl/interpreter.hpp"

#include <tcl.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <iterator>
#include <sstream>
#include <vector>

#include "common/input_error.hpp"
#include "common/printable_text.hpp"
#include "fem_tcl/tcl/commands.hpp"

namespace fem::tcl {

void Context::eval(const std::string& script) {
  if (Tcl_EvalEx(interp, script.c_str(), static_cast<int>(script.size()), 0) != TCL_OK) throw TclScriptError{};
}

void Context::wipe() {
  wipe_analysis();
  domain.clear();
  materials.clear();
  uniaxial_materials.clear();
  current_pattern = nullptr;
  eigen = {};
}

void Context::wipe_analysis() {
  analysis.reset();
  chain = AnalysisChain{};
  analysis_dirty = true;
}

struct Interpreter::Binding {
  Context* context;
  const CommandEntry* entry;
};

namespace {

/// The one boundary where C++ exceptions become TCL_ERROR.
int dispatch(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  const auto* binding = static_cast<const Interpreter::Binding*>(static_cast<void*>(data));
  const CommandEntry& entry = *binding->entry;
  std::vector<std::string> words;
  words.reserve(static_cast<std::size_t>(objc));
  for (int i = 1; i < objc; ++i) words.emplace_back(Tcl_GetString(objv[i]));
  std::string name(entry.name);
  for (int i = 0; i < entry.name_words && i < static_cast<int>(words.size()); ++i) name += " " + words[i];
  try {
    // Any command but analyze may change a parameter an analysis keeps (Domain::command_revision).
    if (entry.name != "analyze") binding->context->domain.touch_commands();
    common::CommandArgs args(name, std::string(entry.usage), std::move(words));
    const std::string result = entry.run(*binding->context, args);
    Tcl_SetObjResult(interp, Tcl_NewStringObj(result.c_str(), static_cast<int>(result.size())));
    return TCL_OK;
  } catch (const TclScriptError&) {
    return TCL_ERROR;  // a nested script failed; its message and errorInfo are in place
  } catch (const std::exception& e) {
    // every command error carries the command's usage line (output failures are not usage errors)
    const bool output = dynamic_cast<const common::OutputError*>(&e) != nullptr;
    std::string message = e.what();
    if (!output && message.find("usage:") == std::string::npos) message += "; usage: " + std::string(entry.usage);
    binding->context->last_error = message;
    binding->context->last_error_status = output ? 1 : dynamic_cast<const common::NumericalError*>(&e) ? 3 : 2;
    Tcl_SetObjResult(interp, Tcl_NewStringObj(message.c_str(), static_cast<int>(message.size())));
    return TCL_ERROR;
  }
}

/// Flushes every recorder; false (and the message on stderr) when one could not be written.
bool flush_recorders_reporting(Context& ctx) {
  try {
    ctx.domain.flush_recorders();
    return true;
  } catch (const std::exception& e) {
    std::cerr << common::printable(e.what()) << "\n";
    return false;
  }
}

void flush_on_exit(ClientData data) {
  // Tcl's `exit` runs this before exiting: a recorder that cannot be written turns the exit status into 1.
  if (!flush_recorders_reporting(*static_cast<Context*>(static_cast<void*>(data)))) std::_Exit(1);
}

// OpenSees sends `puts` without a channel to stderr (quirk 10).
constexpr const char* kPutsScript = R"tcl(
rename puts ::tcl::builtin_puts
proc puts {args} {
  set n [llength $args]
  if {$n == 1} { return [::tcl::builtin_puts stderr [lindex $args 0]] }
  if {$n == 2 && [lindex $args 0] eq "-nonewline"} { return [::tcl::builtin_puts -nonewline stderr [lindex $args 1]] }
  return [uplevel 1 [list ::tcl::builtin_puts {*}$args]]
}
)tcl";

}  // namespace

Interpreter::Interpreter() : context_(std::make_unique<Context>()) {
  Tcl_FindExecutable(nullptr);
  Tcl_Interp* interp = Tcl_CreateInterp();
  context_->interp = interp;
  Tcl_Init(interp);  // a missing init.tcl only disables `unknown`/auto-loading, not the core commands
  for (const CommandEntry& entry : command_table()) {
    bindings_.push_back(std::make_unique<Binding>(Binding{context_.get(), &entry}));
    Tcl_CreateObjCommand(interp, std::string(entry.name).c_str(), dispatch,
                         static_cast<ClientData>(static_cast<void*>(bindings_.back().get())), nullptr);
  }
  Tcl_Eval(interp, kPutsScript);
  Tcl_CreateExitHandler(flush_on_exit, static_cast<ClientData>(static_cast<void*>(context_.get())));
}

Interpreter::~Interpreter() {
  Tcl_DeleteExitHandler(flush_on_exit, static_cast<ClientData>(static_cast<void*>(context_.get())));
  flush_recorders_reporting(*context_);
  Tcl_DeleteInterp(context_->interp);
}

void Interpreter::set_arguments(const std::string& argv0, const std::vector<std::string>& args) {
  Tcl_Interp* interp = context_->interp;
  Tcl_Obj* list = Tcl_NewListObj(0, nullptr);
  for (const auto& a : args) Tcl_ListObjAppendElement(interp, list, Tcl_NewStringObj(a.c_str(), -1));
  Tcl_SetVar2Ex(interp, "argv", nullptr, list, TCL_GLOBAL_ONLY);
  Tcl_SetVar2Ex(interp, "argc", nullptr, Tcl_NewIntObj(static_cast<int>(args.size())), TCL_GLOBAL_ONLY);
  Tcl_SetVar2Ex(interp, "argv0", nullptr, Tcl_NewStringObj(argv0.c_str(), -1), TCL_GLOBAL_ONLY);
}

namespace {
/// The lines of a loop body a command sits in, from errorInfo's frames inside the file (innermost
/// first): '("for" body line 3)' means the third line of the body, which starts on the loop's own line
/// (Tcl's bodies open with the brace there). Summed from the outermost loop in, so an error in a meshing
/// loop names its own line, not the loop's first. A frame of another kind (an if branch, a procedure,
/// eval) ends the sum there: its body's first line is not known from the trace.
int loop_body_offset(const std::string& trace, std::size_t file_frame) {
  std::vector<int> body_lines;  // innermost first
  std::size_t pos = 0;
  while (pos < file_frame) {
    const std::size_t end = std::min(trace.find('\n', pos), file_frame);
    const std::string line = trace.substr(pos, end - pos);
    pos = end + 1;
    const std::size_t open = line.find_first_not_of(' ');
    if (open == std::string::npos || line[open] != '(' || line.back() != ')') continue;  // not a frame
    int n = 0;
    bool loop = false;
    for (const char* kind : {"(\"for\" body line ", "(\"foreach\" body line ", "(\"while\" body line "}) {
      if (line.compare(open, std::strlen(kind), kind) == 0) {
        n = std::atoi(line.c_str() + open + std::strlen(kind));
        loop = n > 0;
      }
    }
    if (loop) {
      body_lines.push_back(n);
    } else {
      body_lines.clear();  // inside another kind of frame: only the loops outside it count
    }
  }
  int offset = 0;
  for (int n : body_lines) offset += n - 1;
  return offset;
}

/// "file:line: message": the innermost file in errorInfo ('(file "x.tcl" line N)', e.g. inside `source`),
/// else `name` and the -errorline of the evaluated script; the line is that of the failing command inside
/// the loops around it (loop_body_offset).
std::string error_message(Tcl_Interp* interp, const std::string& name) {
  std::string message = Tcl_GetStringResult(interp);
  const char* info = Tcl_GetVar(interp, "errorInfo", TCL_GLOBAL_ONLY);
  const std::string trace = info ? info : "";
  const std::string marker = "(file \"";
  const auto at = trace.find(marker);
  if (at != std::string::npos) {
    const auto name_end = trace.find("\" line ", at + marker.size());
    if (name_end != std::string::npos) {
      const auto line_start = name_end + 7;
      const auto line_end = trace.find(')', line_start);
      if (line_end != std::string::npos) {
        const int line = std::atoi(trace.substr(line_start, line_end - line_start).c_str()) + loop_body_offset(trace, at);
        return trace.substr(at + marker.size(), name_end - at - marker.size()) + ":" + std::to_string(line) + ": " +
               message;
      }
    }
  }
  Tcl_Obj* options = Tcl_GetReturnOptions(interp, TCL_ERROR);
  Tcl_IncrRefCount(options);
  Tcl_Obj* key = Tcl_NewStringObj("-errorline", -1);
  Tcl_IncrRefCount(key);
  Tcl_Obj* line_obj = nullptr;
  int line = 0;
  if (Tcl_DictObjGet(interp, options, key, &line_obj) == TCL_OK && line_obj) Tcl_GetIntFromObj(interp, line_obj, &line);
  Tcl_DecrRefCount(key);
  Tcl_DecrRefCount(options);
  return name + ":" + std::to_string(line + loop_body_offset(trace, trace.size())) + ": " + message;
}
}  // namespace

bool Interpreter::eval_file(const std::string& path, std::string& message) {
  Tcl_Interp* interp = context_->interp;
  Tcl_SetVar2Ex(interp, "argv0", nullptr, Tcl_NewStringObj(path.c_str(), -1), TCL_GLOBAL_ONLY);
  if (Tcl_EvalFile(interp, path.c_str()) == TCL_OK) return true;
  message = error_message(interp, path);
  return false;
}

bool Interpreter::eval_script(const std::string& script, const std::string& name, std::string& message) {
  Tcl_Interp* interp = context_->interp;
  if (Tcl_EvalEx(interp, script.c_str(), static_cast<int>(script.size()), TCL_EVAL_GLOBAL) == TCL_OK) return true;
  message = error_message(interp, name);
  return false;
}

std::string Interpreter::eval(const std::string& script) {
  std::string message;
  if (!eval_script(script, "script", message)) throw common::InputError(message);
  return Tcl_GetStringResult(context_->interp);
}

int run_main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << "usage: fem_tcl [script.tcl [args..]]\n"
                 "  Runs an OpenSees-compatible Tcl script (2D solids: SSPquad, quad, zeroLength; ElasticIsotropic and the\n"
                 "  registered nDMaterials; static and transient analyses; Node/Element recorders).\n"
                 "  With no script, the commands are read from standard input.\n"
                 "  The script's arguments are in $argv ($argc of them); $argv0 is the script's path.\n"
                 "  An uncaught error prints 'file:line: message' on stderr (one line, non-printable bytes\n"
                 "  escaped) and exits with status 2 (bad input: a script or command error), 1 (an output\n"
                 "  file could not be written, e.g. a recorder on a full disk) or 3 (numerical failure).\n";
    return 0;
  }
  Interpreter interpreter;
  std::string message;
  bool ok = false;
  if (args.empty()) {
    interpreter.set_arguments(argv[0], {});
    std::string script((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
    ok = interpreter.eval_script(script, "stdin", message);
  } else {
    interpreter.set_arguments(args[0], std::vector<std::string>(args.begin() + 1, args.end()));
    ok = interpreter.eval_file(args[0], message);
  }
  std::cout.flush();
  const bool flushed = flush_recorders_reporting(interpreter.context());
  if (interpreter.context().failed_analyses > 0) {
    std::cerr << "WARNING fem_tcl: " << interpreter.context().failed_analyses
              << " analyze call(s) failed (returned < 0); the state after each failure is the last converged one\n";
  }
  if (!ok) {
    std::cerr << common::printable(message) << "\n";
    const Context& ctx = interpreter.context();
    const bool from_command = !ctx.last_error.empty() && message.find(ctx.last_error) != std::string::npos;
    return from_command ? ctx.last_error_status : 2;
  }
  if (!std::cout) {
    std::cerr << "fem_tcl: writing to standard output failed\n";
    return 1;
  }
  return flushed ? 0 : 1;
}

}  // namespace fem::tcl
