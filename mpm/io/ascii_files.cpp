#include "mpm/io/ascii_files.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/input_error.hpp"

namespace mpm::io {
namespace {

std::string at_line(const std::string& shown, int line) { return shown + ":" + std::to_string(line); }

/// The header count of a counted file ("n" or "nnodes ncells").
long long header_count(const std::string& shown, const TextLine& line, std::size_t word, const char* what) {
  const long long n = parse_integer(shown, line, word);
  if (n < 0) throw common::InputError(at_line(shown, line.number), std::string(what) + " must be >= 0, got " + std::to_string(n));
  return n;
}

/// The data lines of a file whose first line is the count of the lines that follow (CB-Geo's particle
/// and stress files): checks the header and the count, returns the lines with the header first.
std::vector<TextLine> read_counted_lines(const std::filesystem::path& file, const std::string& shown,
                                         const std::string& counted, const std::string& found_suffix) {
  auto lines = read_data_lines(file, shown);
  if (lines.empty()) throw common::InputError(shown, "empty file (expected the particle count on the first line)");
  if (lines.front().words.size() != 1)
    throw common::InputError(at_line(shown, lines.front().number), "expected the particle count (1 integer)");
  const long long n = header_count(shown, lines.front(), 0, "particle count");
  if (static_cast<long long>(lines.size()) - 1 != n)
    throw common::InputError(shown, "header says " + std::to_string(n) + " " + counted + ", found " +
                                        std::to_string(lines.size() - 1) + found_suffix);
  return lines;
}

/// The word-th word of a data line, or an error naming the line when it has fewer words.
const std::string& word_of(const std::string& shown, const TextLine& line, std::size_t word) {
  if (word >= line.words.size())
    throw common::InputError(at_line(shown, line.number), "expected at least " + std::to_string(word + 1) +
                                                             " numbers, got " + std::to_string(line.words.size()));
  return line.words[word];
}

/// The "x y" (or "x y 0") of one coordinate line of a 2D file, the "x y z" of a 3D one; `what` names the
/// line in errors ("node 3", "particle 7") and `file_kind` the file ("mesh", "deck").
FilePoint parse_point(const std::string& shown, const TextLine& l, const std::string& what, const char* file_kind, int dim) {
  FilePoint p{};
  if (dim == 3) {
    if (l.words.size() != 3)
      throw common::InputError(at_line(shown, l.number), what + ": expected \"x y z\", got " + std::to_string(l.words.size()) +
                                                             " values" + (l.words.size() == 2 ? " (a 2D file in a 3D analysis?)" : ""));
    for (int d = 0; d < 3; ++d) p[d] = parse_double(shown, l, d);
    return p;
  }
  if (l.words.size() != 2 && l.words.size() != 3)
    throw common::InputError(at_line(shown, l.number),
                             what + ": expected \"x y\", got " + std::to_string(l.words.size()) + " values");
  if (l.words.size() == 3 && parse_double(shown, l, 2) != 0.0)
    throw common::InputError(at_line(shown, l.number), what + ": a 2D " + file_kind + " needs z = 0");
  p[0] = parse_double(shown, l, 0);
  p[1] = parse_double(shown, l, 1);
  return p;
}

}  // namespace

std::vector<TextLine> read_data_lines(const std::filesystem::path& file, const std::string& shown) {
  std::ifstream in(file);
  if (!in) throw common::InputError(shown, "file not found or not readable (looked for " + file.string() + ")");
  std::vector<TextLine> lines;
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    if (text.find('#') != std::string::npos || text.find('!') != std::string::npos) continue;
    std::istringstream words(text);
    TextLine line{number, {}};
    for (std::string w; words >> w;) line.words.push_back(w);
    if (!line.words.empty()) lines.push_back(std::move(line));
  }
  return lines;
}

double parse_double(const std::string& shown, const TextLine& line, std::size_t word) {
  const std::string& w = word_of(shown, line, word);
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(w.c_str(), &end);
  if (end == w.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    throw common::InputError(at_line(shown, line.number), "\"" + w + "\" is not a finite number");
  return v;
}

long long parse_integer(const std::string& shown, const TextLine& line, std::size_t word) {
  const std::string& w = word_of(shown, line, word);
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(w.c_str(), &end, 10);
  if (end == w.c_str() || *end != '\0' || errno == ERANGE)
    throw common::InputError(at_line(shown, line.number), "\"" + w + "\" is not an integer");
  return v;
}

MeshFile read_mesh_file(const std::filesystem::path& file, const std::string& shown, int dim, int nodes_per_cell) {
  const auto lines = read_data_lines(file, shown);
  if (lines.empty()) throw common::InputError(shown, "empty file (expected \"nnodes ncells\" on the first line)");
  const TextLine& head = lines.front();
  if (head.words.size() != 2)
    throw common::InputError(at_line(shown, head.number), "expected \"nnodes ncells\" (2 integers)");
  const long long nnodes = header_count(shown, head, 0, "nnodes");
  const long long ncells = header_count(shown, head, 1, "ncells");
  if (nnodes == 0 || ncells == 0) throw common::InputError(at_line(shown, head.number), "nnodes and ncells must be > 0");
  const long long found = static_cast<long long>(lines.size()) - 1;
  if (found != nnodes + ncells)
    throw common::InputError(shown, "header says " + std::to_string(nnodes) + " nodes + " + std::to_string(ncells) +
                                        " cells = " + std::to_string(nnodes + ncells) + " data lines, found " +
                                        std::to_string(found) + (found < nnodes + ncells ? " (truncated file?)" : ""));
  MeshFile mesh;
  mesh.dim = dim;
  mesh.nodes.reserve(nnodes);
  for (long long k = 1; k <= nnodes; ++k) {
    mesh.nodes.push_back(parse_point(shown, lines[k], "node " + std::to_string(k - 1), "mesh", dim));
  }
  mesh.cells.reserve(ncells);
  for (long long k = nnodes + 1; k < static_cast<long long>(lines.size()); ++k) {
    const TextLine& l = lines[k];
    const long long cell = k - nnodes - 1;
    if (static_cast<int>(l.words.size()) != nodes_per_cell)
      throw common::InputError(at_line(shown, l.number), "cell " + std::to_string(cell) + ": expected " +
                                                            std::to_string(nodes_per_cell) + " node ids for this cell_type, got " +
                                                            std::to_string(l.words.size()));
    std::vector<long long> ids;
    for (int w = 0; w < nodes_per_cell; ++w) {
      const long long id = parse_integer(shown, l, w);
      if (id < 0 || id >= nnodes)
        throw common::InputError(at_line(shown, l.number), "cell " + std::to_string(cell) + ": node id " +
                                                              std::to_string(id) + " is not in 0.." + std::to_string(nnodes - 1));
      ids.push_back(id);
    }
    mesh.cells.push_back(std::move(ids));
  }
  return mesh;
}

std::vector<FilePoint> read_particle_coordinates(const std::filesystem::path& file, const std::string& shown, int dim) {
  const auto lines = read_counted_lines(file, shown, "particles", " coordinate lines");
  std::vector<FilePoint> xs;
  xs.reserve(lines.size() - 1);
  for (std::size_t k = 1; k < lines.size(); ++k) {
    xs.push_back(parse_point(shown, lines[k], "particle " + std::to_string(k - 1), "deck", dim));
  }
  return xs;
}

std::vector<std::array<double, 6>> read_particle_stresses(const std::filesystem::path& file, const std::string& shown) {
  const auto lines = read_counted_lines(file, shown, "stress lines", "");
  std::vector<std::array<double, 6>> out;
  out.reserve(lines.size() - 1);
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const TextLine& l = lines[k];
    if (l.words.size() != 6)
      throw common::InputError(at_line(shown, l.number), "expected 6 stresses \"sxx syy szz sxy syz sxz\", got " +
                                                            std::to_string(l.words.size()) + " values");
    std::array<double, 6> s{};
    for (int c = 0; c < 6; ++c) s[c] = parse_double(shown, l, c);
    out.push_back(s);
  }
  return out;
}

std::vector<std::vector<double>> read_columns(const std::filesystem::path& file, const std::string& shown,
                                              std::size_t columns) {
  std::vector<std::vector<double>> rows;
  for (const auto& l : read_data_lines(file, shown)) {
    if (l.words.size() != columns)
      throw common::InputError(at_line(shown, l.number), "expected " + std::to_string(columns) + " values, got " +
                                                            std::to_string(l.words.size()));
    std::vector<double> row(columns);
    for (std::size_t c = 0; c < columns; ++c) row[c] = parse_double(shown, l, c);
    rows.push_back(std::move(row));
  }
  return rows;
}

int axis_column(const std::string& shown, double value, std::size_t entry, int dim) {
  if (!(value == 0 || value == 1 || (dim == 3 && value == 2)))
    throw common::InputError(shown, "entry " + std::to_string(entry) + ": dir must be " + (dim == 3 ? "0, 1 or 2" : "0 or 1"));
  return static_cast<int>(value);
}

}  // namespace mpm::io
