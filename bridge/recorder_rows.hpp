#pragma once
// Which row of each recorder file holds the state to transfer, and which holds the reference state of a u-p
// model (the end of the gravity stage, for sigma'v0 and the hydrostatic pore pressure). Recorders of one
// analysis record the same steps; after `loadConst -time 0` or `setTime 0` the time column restarts, so a
// time may name a row of each stage: a row is identified by its time AND which repeat of that time it is.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "bridge/recorder_file.hpp"

namespace bridge {

/// A row of the displacement file (the reference layout), and which of the rows at its time it is.
struct TransferRow {
  std::size_t index = 0;
  double time = 0;
  int time_digits = 17;
  std::size_t occurrence = 0;  ///< among the rows at `time`, 0 the first
  std::size_t count = 1;       ///< rows at `time`
};

/// Describes row `index` of `file` (its time, printed digits and repeat).
TransferRow describe_row(const RecorderFile& file, std::size_t index);

/// The transfer row of the displacement file: by time when given (the last row at that time, with a note
/// naming the others), else by row number, else the last complete row (a note says so).
TransferRow pick_transfer_row(const RecorderFile& file, std::optional<double> time, std::optional<long> row,
                              std::vector<std::string>& notes);

/// The row of another recorder of the same analysis at `row` of `reference`: the same time and, when the time
/// repeats, the same one of its repeats, so stage-1 displacements never meet stage-2 stresses. Throws
/// common::InputError naming both files when the two did not record the same steps.
std::size_t matching_row(const RecorderFile& file, const RecorderFile& reference, const TransferRow& row);

/// The reference row of a u-p transfer in `file` (the displacement file), at or before the transfer row:
/// - `time` given (--reference-time): the last row at that time at or before the transfer row; an InputError
///   naming `option` when no row has that time (the nearest times listed) or only later rows do;
/// - else the end of the gravity stage: the last row before the time column restarts lower (OpenSees
///   `setTime 0.0` or `loadConst -time 0.0` before the shaking), the last such restart at or before the
///   transfer row; when the time never decreases there and the first row is at t = 0 (recorders made after the
///   gravity stage and a `record` at `setTime 0`), that first row. Otherwise an InputError naming `option`
///   asks for it.
/// `how` receives a few words on how the row was found, for the report.
TransferRow pick_reference_row(const RecorderFile& file, const TransferRow& transfer, std::optional<double> time,
                               const std::string& option, std::string& how);

}  // namespace bridge
