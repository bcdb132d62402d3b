#pragma once
// Comparison of recorder text files and query output against golden files (tests/data/reference_runs,
// README sections 1 and 3), and running fem_tcl on a scratch copy of a case folder.
//   recorder files: same row and column counts; |ref - out| <= rel * max(|ref|, |out|) + abs_frac * S,
//                   S = largest |value| of the reference file outside the time column
//   stdout:         token by token; numbers |ref - out| <= rel * max(|ref|,|out|) + abs, words equal
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include "support/scratch.hpp"

namespace test_support {

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Whitespace-separated numbers, one vector per line.
inline std::vector<std::vector<double>> read_numeric_table(const std::filesystem::path& path) {
  std::vector<std::vector<double>> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::vector<double> row;
    std::string token;
    while (ls >> token) row.push_back(std::strtod(token.c_str(), nullptr));
    rows.push_back(std::move(row));
  }
  return rows;
}

inline ::testing::AssertionResult compare_recorder_files(const std::filesystem::path& reference,
                                                         const std::filesystem::path& output, bool time_column,
                                                         double rel = 1e-5, double abs_frac = 1e-7) {
  if (!std::filesystem::exists(output)) return ::testing::AssertionFailure() << output << " was not written";
  const auto ref = read_numeric_table(reference);
  const auto out = read_numeric_table(output);
  if (ref.size() != out.size()) {
    return ::testing::AssertionFailure() << output.filename() << ": " << out.size() << " rows, reference has "
                                         << ref.size();
  }
  double scale = 0.0;
  for (const auto& row : ref) {
    for (std::size_t j = time_column ? 1 : 0; j < row.size(); ++j) scale = std::max(scale, std::abs(row[j]));
  }
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if (ref[i].size() != out[i].size()) {
      return ::testing::AssertionFailure() << output.filename() << " row " << i + 1 << ": " << out[i].size()
                                           << " columns, reference has " << ref[i].size();
    }
    for (std::size_t j = 0; j < ref[i].size(); ++j) {
      const double r = ref[i][j], o = out[i][j];
      const double tol = rel * std::max(std::abs(r), std::abs(o)) + abs_frac * scale;
      if (!std::isfinite(o) || std::abs(r - o) > tol) {
        std::ostringstream os;
        os.precision(17);
        os << output.filename().string() << " row " << i + 1 << " column " << j + 1 << ": " << o
           << " vs reference " << r << " (allowed " << tol << ")";
        return ::testing::AssertionFailure() << os.str();
      }
    }
  }
  return ::testing::AssertionSuccess();
}

/// Recorder files compared column by column: same rows and columns, and every value within `fraction` of
/// its column's largest |reference value| over the whole record, plus 1e-7 S for round-off noise (S the
/// file's largest |value| outside the time column): the criterion for nonlinear runs whose error is best
/// judged against each quantity's own range (a shear stress beside a vertical one).
/// With `rows` > 0 only the first `rows` rows are compared (the files may differ in length after them); the
/// column peaks are still those of the whole reference record.
inline ::testing::AssertionResult compare_recorder_columns(const std::filesystem::path& reference,
                                                           const std::filesystem::path& output, bool time_column,
                                                           double fraction, double* worst_fraction = nullptr,
                                                           std::size_t rows = 0) {
  if (!std::filesystem::exists(output)) return ::testing::AssertionFailure() << output << " was not written";
  const auto full_ref = read_numeric_table(reference);
  auto out = read_numeric_table(output);
  auto ref = full_ref;
  if (rows > 0) {
    if (out.size() < rows || ref.size() < rows) {
      return ::testing::AssertionFailure() << output.filename() << ": fewer than the " << rows << " rows compared";
    }
    ref.resize(rows);
    out.resize(rows);
  }
  if (ref.size() != out.size()) {
    return ::testing::AssertionFailure() << output.filename() << ": " << out.size() << " rows, reference has "
                                         << ref.size();
  }
  std::vector<double> peak;
  double scale = 0.0;
  for (const auto& row : full_ref) {
    if (peak.size() < row.size()) peak.resize(row.size(), 0.0);
    for (std::size_t j = time_column ? 1 : 0; j < row.size(); ++j) {
      peak[j] = std::max(peak[j], std::abs(row[j]));
      scale = std::max(scale, std::abs(row[j]));
    }
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    if (ref[i].size() != out[i].size()) {
      return ::testing::AssertionFailure() << output.filename() << " row " << i + 1 << ": " << out[i].size()
                                           << " columns, reference has " << ref[i].size();
    }
    for (std::size_t j = 0; j < ref[i].size(); ++j) {
      const double r = ref[i][j], o = out[i][j];
      const bool time = time_column && j == 0;
      const double tol = time ? 1e-6 * std::max(std::abs(r), 1.0) : fraction * peak[j] + 1e-7 * scale;
      if (!std::isfinite(o) || std::abs(r - o) > tol) {
        std::ostringstream os;
        os.precision(17);
        os << output.filename().string() << " row " << i + 1 << " column " << j + 1 << ": " << o << " vs reference "
           << r << " (allowed " << tol << ", the column's peak " << peak[j] << ")";
        return ::testing::AssertionFailure() << os.str();
      }
      if (!time && peak[j] > 1e-6 * scale) worst = std::max(worst, std::abs(r - o) / peak[j]);  // not noise columns
    }
  }
  if (worst_fraction) *worst_fraction = worst;
  return ::testing::AssertionSuccess();
}

inline ::testing::AssertionResult compare_tokens(const std::string& reference, const std::string& output,
                                                 double rel = 1e-9, double abs = 1e-12) {
  std::istringstream rs(reference), os(output);
  std::vector<std::string> r, o;
  for (std::string t; rs >> t;) r.push_back(t);
  for (std::string t; os >> t;) o.push_back(t);
  if (r.size() != o.size()) {
    return ::testing::AssertionFailure() << o.size() << " tokens, reference has " << r.size() << "\n--- output:\n"
                                         << output;
  }
  for (std::size_t i = 0; i < r.size(); ++i) {
    char* end_r = nullptr;
    char* end_o = nullptr;
    const double x = std::strtod(r[i].c_str(), &end_r);
    const double y = std::strtod(o[i].c_str(), &end_o);
    const bool numbers = end_r && *end_r == '\0' && end_r != r[i].c_str() && end_o && *end_o == '\0' &&
                         end_o != o[i].c_str();
    if (numbers) {
      if (!(std::abs(x - y) <= rel * std::max(std::abs(x), std::abs(y)) + abs)) {
        return ::testing::AssertionFailure() << "token " << i + 1 << ": '" << o[i] << "' vs reference '" << r[i] << "'";
      }
    } else if (r[i] != o[i]) {
      return ::testing::AssertionFailure() << "token " << i + 1 << ": '" << o[i] << "' vs reference '" << r[i] << "'";
    }
  }
  return ::testing::AssertionSuccess();
}

/// Runs `<bin_dir>/fem_tcl <script> <args>` in `dir`, stdout -> stdout.txt, stderr -> stderr.txt.
/// Returns the exit status.
inline int run_fem_tcl(const std::filesystem::path& bin_dir, const std::filesystem::path& dir,
                       const std::string& script, const std::string& args = "") {
  const std::string cmd = "cd '" + dir.string() + "' && '" + (bin_dir / "fem_tcl").string() + "' '" + script + "' " +
                          args + " > stdout.txt 2> stderr.txt";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// What a run_fem_tcl run in `dir` printed: standard output, then standard error.
inline std::string fem_tcl_output(const std::filesystem::path& dir) {
  return read_text(dir / "stdout.txt") + read_text(dir / "stderr.txt");
}

}  // namespace test_support
