#include "common/number_file.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "common/command_args.hpp"
#include "common/input_error.hpp"
#include "common/printable_text.hpp"

namespace common {

std::vector<double> read_number_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "cannot open the file");
  std::vector<double> out;
  std::string line;
  for (long line_no = 1; std::getline(in, line); ++line_no) {
    std::istringstream words(line);
    for (std::string word; words >> word;) {
      const auto v = CommandArgs::parse_finite_number(word);
      if (!v) throw InputError(file.string() + ":" + std::to_string(line_no), "expected a number, got '" + printable(word) + "'");
      out.push_back(*v);
    }
  }
  return out;
}

}  // namespace common
