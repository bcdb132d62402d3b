#pragma once
// The fem2mpm command: options (CLI11), the transfer pipeline and its report. main.cpp only calls run_cli.
#include <iosfwd>

namespace bridge {

/// Runs fem2mpm with the given arguments; prints the report to `out` and errors (one line) to `err`.
/// Returns 0 on success, 2 on an input error (nothing written), 1 on any other failure.
int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace bridge
