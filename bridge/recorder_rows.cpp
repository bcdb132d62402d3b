#include "bridge/recorder_rows.hpp"

#include <algorithm>

#include "common/input_error.hpp"
#include "common/number_text.hpp"

namespace bridge {
namespace {

std::string fmt(double v) { return common::number_text(v, 9); }

std::string line_list(const RecorderFile& f, const std::vector<std::size_t>& rows) {
  std::string all;
  for (std::size_t r : rows) all += (all.empty() ? "" : ", ") + std::to_string(f.rows()[r].line);
  return all;
}

}  // namespace

TransferRow describe_row(const RecorderFile& file, std::size_t index) {
  TransferRow out;
  out.index = index;
  out.time = file.rows()[index].time;
  out.time_digits = file.time_digits(index);
  const auto same_time = file.rows_at_time(out.time, out.time_digits);
  out.count = same_time.size();
  out.occurrence = static_cast<std::size_t>(std::find(same_time.begin(), same_time.end(), index) - same_time.begin());
  return out;
}

TransferRow pick_transfer_row(const RecorderFile& file, std::optional<double> time, std::optional<long> row,
                              std::vector<std::string>& notes) {
  std::size_t index = 0;
  if (time) {
    std::vector<int> lines;
    index = file.find_time(*time, &lines);
    if (lines.size() > 1) {
      std::string all;
      for (int l : lines) all += (all.empty() ? "" : ", ") + std::to_string(l);
      notes.push_back(file.path().string() + ": time " + fmt(*time) + " appears on lines " + all +
                      " (the time restarts after loadConst -time); using the last, line " +
                      std::to_string(file.rows()[index].line) + " (choose another with --row)");
    }
  } else if (row) {
    index = file.find_row(*row);
  } else {
    index = file.rows().size() - 1;
    const bool cut = !file.rows()[index].terminated && index > 0;
    if (cut) --index;
    notes.push_back("no --time given: using the last " + std::string(cut ? "complete " : "") + "row of " +
                    file.path().string() + " (line " + std::to_string(file.rows()[index].line) + ", t = " +
                    fmt(file.rows()[index].time) + ")" + (cut ? "; the row after it was cut while being written" : ""));
  }
  return describe_row(file, index);
}

std::size_t matching_row(const RecorderFile& file, const RecorderFile& reference, const TransferRow& row) {
  const auto same_time = file.rows_at_time(row.time, row.time_digits);
  if (same_time.size() == row.count) return same_time[row.occurrence];
  throw common::InputError(
      file.path().string(),
      "time " + fmt(row.time) + " is on line(s) " + line_list(file, same_time) + " here but on line(s) " +
          line_list(reference, reference.rows_at_time(row.time, row.time_digits)) + " of " +
          reference.path().string() + " (transfer row: line " + std::to_string(reference.rows()[row.index].line) +
          "): the recorders did not record the same steps; record them over the same analyses, or transfer at a "
          "time that is on one row of each");
}

TransferRow pick_reference_row(const RecorderFile& file, const TransferRow& transfer, std::optional<double> time,
                               const std::string& option, std::string& how) {
  const auto& rows = file.rows();
  if (time) {
    std::vector<std::size_t> found;
    try {
      found = file.rows_at_time(*time);
    } catch (const common::InputError& e) {
      throw common::InputError(option + " " + fmt(*time), e.what());
    }
    std::optional<std::size_t> index;
    for (std::size_t r : found)
      if (r <= transfer.index) index = r;
    if (!index)
      throw common::InputError(option + " " + fmt(*time),
                               file.path().string() + ": time " + fmt(*time) + " is on line(s) " + line_list(file, found) +
                                   ", after the transfer row (line " + std::to_string(rows[transfer.index].line) +
                                   "): the reference state (the end of the gravity stage) must come before the transfer");
    how = "given (" + option + "), " + file.path().string() + " line " + std::to_string(rows[*index].line);
    return describe_row(file, *index);
  }
  for (std::size_t r = transfer.index; r >= 1; --r)
    if (rows[r].time < rows[r - 1].time) {
      how = "the end of the gravity stage: the last row before the time restarts lower (" + file.path().string() +
            " line " + std::to_string(rows[r - 1].line) + ", t = " + fmt(rows[r - 1].time) + "; line " +
            std::to_string(rows[r].line) + ", t = " + fmt(rows[r].time) + ")";
      return describe_row(file, r - 1);
    }
  // recorders made after the gravity stage, their first row written at t = 0 (`setTime 0`, `record`): that row
  // is the gravity state
  if (rows.front().time == 0.0 && transfer.index > 0) {
    how = "the end of the gravity stage: the first row, at t = 0, before the shaking (" + file.path().string() +
          " line " + std::to_string(rows.front().line) + ")";
    return describe_row(file, 0);
  }
  throw common::InputError(option, "required: the time column of " + file.path().string() + " never decreases up to the "
                                   "transfer row (line " + std::to_string(rows[transfer.index].line) + ") and does not "
                                   "start at t = 0, so the end of the gravity stage (the last row before `setTime 0.0` "
                                   "restarts the time, or a first row recorded at t = 0) cannot be found; give the time "
                                   "of the row that holds the gravity state");
}

}  // namespace bridge
