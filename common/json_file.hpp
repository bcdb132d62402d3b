#pragma once
// Reading a JSON input file strictly and with one-line errors: a key given twice in one object is an
// error (nlohmann would keep the last value silently), and a syntax error or a number that overflows a
// double (1e400) names the file and the key path ("mpm.json: analysis.dt: number 1e400 overflows a
// double"), never nlohmann's "[json.exception.out_of_range.406] ...".
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace common {

/// Parses `text`; `shown` names the file in messages. Throws common::InputError.
nlohmann::json parse_json_text(const std::string& text, const std::string& shown);

/// Reads and parses `file`; `shown` names it in messages. Throws common::InputError (also when the
/// file cannot be read).
nlohmann::json parse_json_file(const std::filesystem::path& file, const std::string& shown);

}  // namespace common
