#include "bridge/recorder_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/input_error.hpp"
#include "common/number_text.hpp"
#include "common/printable_text.hpp"

namespace bridge {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// Calls token(begin, end) for each blank-separated token of the characters [from, to) of `data`.
template <class F>
void for_each_token(const char* data, std::size_t from, std::size_t to, F&& token) {
  std::size_t i = from;
  while (i < to) {
    while (i < to && is_space(data[i])) ++i;
    if (i >= to) break;
    std::size_t j = i;
    while (j < to && !is_space(data[j])) ++j;
    token(data + i, data + j);
    i = j;
  }
}

/// Parses one number token [begin, end); false when it is not a whole number.
bool parse_token(const char* begin, const char* end, double& value) {
  if (begin != end && *begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  return ec == std::errc() && ptr == end;
}

/// Significant digits written in a number token ("0.000102767" -> 6, "0.2" -> 1, "-2.33e-20" -> 3).
int significant_digits(const char* begin, const char* end) {
  int digits = 0;
  bool leading = true;
  for (const char* p = begin; p != end; ++p) {
    if (*p == 'e' || *p == 'E') break;
    if (*p < '0' || *p > '9') continue;
    if (leading && *p == '0') continue;
    leading = false;
    ++digits;
  }
  return std::max(digits, 1);
}

/// A time quoted in an error message (9 significant digits).
std::string time_text(double t) { return common::number_text(t, 9); }

}  // namespace

RecorderFile::RecorderFile(std::filesystem::path file, bool has_time_column)
    : path_(std::move(file)), has_time_(has_time_column) {
  std::ifstream in(path_, std::ios::binary);
  if (!in) throw common::InputError(path_.string(), "cannot open the recorder file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  text_ = buffer.str();

  const char* data = text_.data();
  const std::size_t size = text_.size();
  std::size_t pos = 0;
  int line = 0;
  while (pos < size) {
    ++line;
    std::size_t eol = text_.find('\n', pos);
    const bool terminated = eol != std::string::npos;
    if (!terminated) eol = size;
    Row row;
    row.line = line;
    row.offset = pos;
    row.length = eol - pos;
    row.terminated = terminated;
    // Count and check tokens; parse the first one as the time.
    int digits = 6;
    bool cut_number = false;  // a number cut short in an unterminated last row ("1.2e")
    for_each_token(data, pos, eol, [&](const char* begin, const char* end) {
      double v = 0;
      if (cut_number) return;
      if (!parse_token(begin, end, v)) {
        if (!terminated && !rows_.empty()) {
          cut_number = true;
          return;
        }
        throw common::InputError(path_.string() + ":" + std::to_string(line),
                                 "expected a number, got '" + common::printable(std::string(begin, end).substr(0, 40)) + "'" +
                                     (terminated ? "" : " (the file looks truncated)"));
      }
      if (row.width == 0) {
        if (has_time_ && !std::isfinite(v))
          throw common::InputError(path_.string() + ":" + std::to_string(line),
                                   "the time column is '" + std::string(begin, end) + "' (expected a finite time)");
        row.time = v;
        digits = significant_digits(begin, end);
      }
      ++row.width;
    });
    pos = terminated ? eol + 1 : size;
    if (row.width == 0) {
      if (terminated && pos < size)
        throw common::InputError(path_.string() + ":" + std::to_string(line), "empty line inside the recorder file");
      continue;  // trailing blank line
    }
    if (!rows_.empty() && (cut_number || row.width != rows_.front().width)) {
      const bool last = pos >= size;
      if (last && !terminated) {  // cut while being written: the rows before it stay usable
        rows_.push_back(row);
        time_digits_.push_back(digits);
        break;
      }
      throw common::InputError(
          path_.string() + ":" + std::to_string(line),
          std::to_string(row.width) + " values in this row, but " + std::to_string(rows_.front().width) +
              " in the first row" + (last ? " (the file is truncated: the last row is incomplete)" : ""));
    }
    rows_.push_back(row);
    time_digits_.push_back(digits);
  }
  if (rows_.empty()) throw common::InputError(path_.string(), "the recorder file is empty (no committed step was recorded)");
  if (has_time_ && rows_.front().width < 2)
    throw common::InputError(path_.string() + ":1", "expected a time column and at least one value (recorder with -time)");
}

int RecorderFile::time_digits(std::size_t index) const { return std::min(std::max(time_digits_.at(index), 6), 17); }

std::vector<std::size_t> RecorderFile::rows_at_time(double t, int t_digits) const {
  if (!has_time_) throw common::InputError(path_.string(), "--time needs recorder files written with -time; use --row");
  std::vector<std::size_t> found;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const double tr = rows_[r].time;
    const int digits = std::min(time_digits(r), std::max(t_digits, 6));
    const double magnitude = std::max(std::abs(tr), std::abs(t));
    const double tol = magnitude > 0 ? 0.5 * std::pow(10.0, std::floor(std::log10(magnitude)) - digits + 1) : 0;
    if (std::abs(tr - t) <= tol * (1 + 1e-9) + 1e-300) found.push_back(r);
  }
  if (!found.empty()) return found;
  // Nearest times below and above, for the message.
  std::optional<std::size_t> below, above;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const double tr = rows_[r].time;
    if (tr < t && (!below || tr > rows_[*below].time)) below = r;
    if (tr > t && (!above || tr < rows_[*above].time)) above = r;
  }
  std::string nearest;
  if (below) nearest += time_text(rows_[*below].time) + " (line " + std::to_string(rows_[*below].line) + ")";
  if (above) nearest += std::string(nearest.empty() ? "" : ", ") + time_text(rows_[*above].time) + " (line " +
                        std::to_string(rows_[*above].line) + ")";
  throw common::InputError(path_.string(), "no row at time " + time_text(t) + "; nearest times: " + nearest + "; " +
                                               std::to_string(rows_.size()) + " rows from t = " +
                                               time_text(rows_.front().time) + " to " + time_text(rows_.back().time));
}

std::size_t RecorderFile::find_time(double t, std::vector<int>* ambiguous) const {
  const auto found = rows_at_time(t);
  if (ambiguous)
    for (std::size_t r : found) ambiguous->push_back(rows_[r].line);
  return found.back();
}

std::size_t RecorderFile::find_row(long n) const {
  const long count = static_cast<long>(rows_.size());
  const long index = n > 0 ? n - 1 : count + n;
  if (n == 0 || index < 0 || index >= count)
    throw common::InputError(path_.string(), "no row " + std::to_string(n) + " (the file has " + std::to_string(count) +
                                                 " rows; 1 is the first, -1 the last)");
  return static_cast<std::size_t>(index);
}

std::vector<double> RecorderFile::values(std::size_t index, double scale) const {
  const Row& row = rows_.at(index);
  // A recorder ends every row with a newline: a last row without one was cut while being written (a
  // number in it may be cut short and still parse).
  if (!row.terminated)
    throw common::InputError(where(index), "the last row has no final newline: the file was cut while it was being "
                                           "written (choose an earlier row with --time or --row)");
  std::vector<double> out;
  out.reserve(row.width);
  bool skip = has_time_;
  std::size_t column = 0;
  for_each_token(text_.data(), row.offset, row.offset + row.length, [&](const char* begin, const char* end) {
    double v = 0;
    parse_token(begin, end, v);  // checked while indexing
    ++column;
    if (!std::isfinite(v))
      throw common::InputError(where(index), "value " + std::to_string(column) + " is '" + std::string(begin, end) +
                                                 "' (the FEM state in this row is not finite: the analysis diverged?)");
    if (!skip) {
      const double scaled = v * scale;
      if (!std::isfinite(scaled))
        throw common::InputError(where(index), "value " + std::to_string(column) + " is '" + std::string(begin, end) +
                                                   "', not finite in SI units (times " + common::number_text(scale, 6) + ")");
      out.push_back(scaled);
    }
    skip = false;
  });
  return out;
}

std::string RecorderFile::where(std::size_t index) const {
  return path_.string() + ":" + std::to_string(rows_.at(index).line);
}

}  // namespace bridge
