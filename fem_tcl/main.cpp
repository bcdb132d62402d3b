// fem_tcl: the OpenSees-compatible Tcl FEM interpreter (see fem_tcl/tcl/interpreter.hpp).
#include "fem_tcl/tcl/interpreter.hpp"

int main(int argc, char** argv) { return fem::tcl::run_main(argc, argv); }
