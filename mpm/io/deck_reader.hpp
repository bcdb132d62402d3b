#pragma once
// Reading a CB-Geo MPM input deck (mpm.json + the files it names) into an Deck.
#include <filesystem>
#include <string>

#include "mpm/problem/deck.hpp"

namespace mpm::io {

/// Reads `working_dir`/`input_file` with CB-Geo's schema (FORMATS.md section 5; CB-Geo
/// include/solvers/mpm_base.tcc, include/io/io_mesh_ascii.tcc) plus this project's extensions
/// (mpm/README.md). Strict: every key not implemented here, every malformed value and every
/// inconsistent file is a common::InputError whose one-line message names the file, line or key
/// path and what was expected. Reads only; writes nothing.
Deck read_deck(const std::filesystem::path& working_dir, const std::string& input_file);

/// The scheme names of analysis.stress_smoothing (extension) the reader accepts.
const std::vector<std::string>& stress_smoothing_methods();

}  // namespace mpm::io
