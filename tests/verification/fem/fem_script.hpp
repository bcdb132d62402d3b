#pragma once
// Small helpers shared by the fem verification tests: run Tcl through fem_tcl's interpreter and read state.
#include <gtest/gtest.h>

#include <string>

#include "fem_tcl/tcl/interpreter.hpp"

namespace fem_verification {

inline void run(fem::tcl::Interpreter& interp, const std::string& script) {
  std::string message;
  ASSERT_TRUE(interp.eval_script(script, "test", message)) << message;
}

inline double node_disp(fem::tcl::Interpreter& interp, int tag, int dof) {
  return interp.context().domain.find_node(tag)->disp[dof];
}

inline std::vector<double> element_response(fem::tcl::Interpreter& interp, int tag, const std::string& what) {
  return *interp.context().domain.find_element(tag)->response({what});
}

}  // namespace fem_verification
