#pragma once
// Running one of the project's programs from a test: a shell command line with stdout and stderr
// captured to files in a scratch folder, and the exit status (or the signal that ended it).
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/recorder_compare.hpp"

namespace test_support {

struct ProgramResult {
  int exit_code = -1;  ///< -1 when the program did not exit normally
  int signal = 0;      ///< the signal that ended it, 0 when it exited
  std::string out, err;
};

/// Runs `command` (a shell line) with stdout and stderr captured in `dir`.
inline ProgramResult run_program(const std::string& command, const std::filesystem::path& dir) {
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string line = command + " > '" + out.string() + "' 2> '" + err.string() + "' < /dev/null";
  const int status = std::system(line.c_str());
  ProgramResult r;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  else if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.out = read_text(out);
  r.err = read_text(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

}  // namespace test_support
