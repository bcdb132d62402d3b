#pragma once
// OpenSees Node / Element recorder text files (FORMATS.md section 2): no header, one row per committed
// step, values separated by single spaces, optional leading time column (`-time`), 6 significant
// digits unless `-precision n`. The file is indexed once (time, width and line of each row); a row's
// values are parsed only when asked for.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bridge {

class RecorderFile {
 public:
  struct Row {
    int line = 0;              ///< 1-based line number in the file
    std::size_t offset = 0;    ///< byte offset of the row's first character
    std::size_t length = 0;    ///< bytes up to (not including) the newline
    std::size_t width = 0;     ///< number of values including the time column
    double time = 0;           ///< the first value when the file has a time column
    bool terminated = true;    ///< ends with a newline (a recorder always writes one: else the row was cut)
  };

  /// Reads and indexes `file`. Throws common::InputError "<file>:<line>: ..." when the file is
  /// missing or empty, a value is not a number, or rows differ in width. A last row without its
  /// newline (the file was cut while being written) is kept, unterminated, so the rows before it
  /// stay usable; values() refuses it.
  explicit RecorderFile(std::filesystem::path file, bool has_time_column = true);

  const std::filesystem::path& path() const { return path_; }
  bool has_time_column() const { return has_time_; }
  const std::vector<Row>& rows() const { return rows_; }
  /// Values per row, time column included.
  std::size_t width() const { return rows_.front().width; }
  /// Values per row without the time column.
  std::size_t data_width() const { return width() - (has_time_ ? 1 : 0); }

  /// Indices of every row whose time equals `t` within the printed precision: the row's own digits
  /// (at least 6), or `t_digits` when `t` was itself read from a recorder printed with fewer, whichever
  /// is coarser. Several rows match after `loadConst -time 0` (the time restarts). Throws InputError
  /// listing the nearest times when no row matches.
  std::vector<std::size_t> rows_at_time(double t, int t_digits = 17) const;

  /// The last of rows_at_time(t); `ambiguous` (if given) receives the lines of all matches.
  std::size_t find_time(double t, std::vector<int>* ambiguous = nullptr) const;

  /// Index of row `n` (1-based; negative counts from the end: -1 is the last row). Throws InputError.
  std::size_t find_row(long n) const;

  /// The values of row `index`, time column excluded, each times `scale` (a unit conversion); a value
  /// that is not finite, or becomes so when scaled, is an InputError naming the file, line and column.
  std::vector<double> values(std::size_t index, double scale = 1.0) const;

  /// Significant digits printed in the time of row `index` (at least 6: a recorder prints 6 unless
  /// `-precision` says otherwise, and "0.5" stands for 0.500000).
  int time_digits(std::size_t index) const;

  /// "<file>:<line>" of row `index`, for messages.
  std::string where(std::size_t index) const;

 private:
  std::filesystem::path path_;
  bool has_time_;
  std::string text_;
  std::vector<Row> rows_;
  std::vector<int> time_digits_;  ///< significant digits printed in each row's time value
};

}  // namespace bridge
