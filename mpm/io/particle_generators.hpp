#pragma once
// CB-Geo's particle generators (the deck's "particles" list; CB-Geo include/mesh.tcc
// generate_particles): "file" (an Ascii2D / Ascii3D file of coordinates) and "gauss" (the Gauss points of
// each cell of a cell set), in 2D and 3D, with each generated particle checked to lie in the grid's cells.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "mpm/io/lattice.hpp"
#include "mpm/problem/deck.hpp"

namespace mpm::io {

class StrictObject;

struct GeneratedParticles {
  std::vector<ParticleRecord> records;                ///< ids 0, 1, ... in generator order
  std::map<long long, std::vector<long long>> psets;  ///< from the generators' pset_id
};

/// The generators of `root`'s "particles" list on `lattice` (its grid's dim: P2D / Ascii2D or P3D /
/// Ascii3D). `cell_sets`: the entity sets' cell sets (gauss cset_id); `load_files`: false on resume (the
/// file generators' files are not read, only their keys checked). Errors name the generator's key or the
/// file and line.
GeneratedParticles read_generators(StrictObject& root, const std::vector<MaterialSpec>& materials, const Lattice& lattice,
                                   const std::map<long long, std::vector<long long>>& cell_sets,
                                   const std::filesystem::path& dir, bool load_files);

/// An error naming `where` when two particles share a point.
void check_no_duplicates(const std::vector<ParticleRecord>& ps, const std::string& where);

/// The position of particle `p` (entries d >= dim are 0 by CB-Geo's 2D convention).
inline std::array<double, kMaxDim> position_of(const ParticleRecord& p) { return {p.coord_x, p.coord_y, p.coord_z}; }

/// Whether particle `p` lies in the grid's region, on each of its dim axes.
bool inside_region(const Grid& grid, const ParticleRecord& p);

/// "(x, y)" or "(x, y, z)" of particle `p`, for messages (10 significant digits).
std::string position_text(const ParticleRecord& p, int dim);

}  // namespace mpm::io
