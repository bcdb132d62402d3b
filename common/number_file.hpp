#pragma once
// A text file of numbers, as OpenSees reads a Path series' -filePath / -fileTime: whitespace-separated
// words, any number of them per line, each a finite number.
#include <filesystem>
#include <vector>

namespace common {

/// The numbers of `file` in order. Throws InputError "<file>: cannot open the file" or
/// "<file>:<line>: expected a number, got '<word>'" (for a word that is not a finite number).
std::vector<double> read_number_file(const std::filesystem::path& file);

}  // namespace common
