#pragma once
// CB-Geo's Ascii2D and Ascii3D text inputs (FORMATS.md sections 5 and 7; CB-Geo include/io/io_mesh_ascii.tcc): mesh.txt,
// particles.txt, particle stresses, volumes and cells, constraint files. A line containing '#' or
// '!' is a comment and blank lines are skipped, as in CB-Geo; unlike CB-Geo every count and every
// number is checked, and each error names "file:line" and what was expected.
#include <Eigen/Core>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "mpm/problem/deck.hpp"

namespace mpm::io {

/// A point read from a 2D or 3D file: x, y (and z in 3D; 0 in 2D).
using FilePoint = std::array<double, kMaxDim>;

/// One data line of a text file: its 1-based line number and its whitespace-separated words.
struct TextLine {
  int number = 0;
  std::vector<std::string> words;
};

/// The data lines of `file` (comments and blank lines removed). `shown` is the name used in
/// messages (the path as the deck gives it). Throws common::InputError when the file is missing.
std::vector<TextLine> read_data_lines(const std::filesystem::path& file, const std::string& shown);

/// The number in `word` of `line`; an error "shown:line: ..." when it is not one.
double parse_double(const std::string& shown, const TextLine& line, std::size_t word);
long long parse_integer(const std::string& shown, const TextLine& line, std::size_t word);

struct MeshFile {
  int dim = 2;
  std::vector<FilePoint> nodes;               ///< in file order (file node id = index)
  std::vector<std::vector<long long>> cells;  ///< file node ids per cell, in file order
};

/// mesh.txt: "nnodes ncells", nnodes lines "x y" (2D; "x y 0" too) or "x y z" (`dim` 3), ncells lines of
/// `nodes_per_cell` node ids.
MeshFile read_mesh_file(const std::filesystem::path& file, const std::string& shown, int dim, int nodes_per_cell);

/// particles.txt: "n", then n lines "x y" (2D; "x y 0" too) or "x y z" (`dim` 3).
std::vector<FilePoint> read_particle_coordinates(const std::filesystem::path& file, const std::string& shown, int dim);

/// particles_stresses: "n", then n lines "sxx syy szz sxy syz sxz" (Pa).
std::vector<std::array<double, 6>> read_particle_stresses(const std::filesystem::path& file, const std::string& shown);

/// Lines of exactly `columns` numbers (no header), e.g. particles_volumes "id volume".
std::vector<std::vector<double>> read_columns(const std::filesystem::path& file, const std::string& shown,
                                              std::size_t columns);

/// A direction column of such a file (`shown`, row `entry`): 0 (x), 1 (y) or, with `dim` 3, 2 (z); throws
/// InputError otherwise.
int axis_column(const std::string& shown, double value, std::size_t entry, int dim = 2);

}  // namespace mpm::io
