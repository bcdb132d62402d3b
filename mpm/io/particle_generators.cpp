#include "mpm/io/particle_generators.hpp"

#include <algorithm>
#include <cmath>

#include "common/finite_number.hpp"
#include "common/input_error.hpp"
#include "common/number_text.hpp"
#include "mpm/io/ascii_files.hpp"
#include "mpm/io/dimension_keys.hpp"
#include "mpm/io/json_keys.hpp"

namespace mpm::io {
namespace {

std::string num(double v) { return common::number_text(v, 10); }

/// Gauss-Legendre points on [-1, 1] for n = 1..5 (the points of CB-Geo's quadrature of that order).
std::vector<double> gauss_points(int n) {
  switch (n) {
    case 1: return {0.0};
    case 2: return {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
    case 3: return {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
    case 4: {
      const double a = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(1.2)), b = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(1.2));
      return {-b, -a, a, b};
    }
    default: {
      const double a = std::sqrt(5 - 2 * std::sqrt(10.0 / 7)) / 3, b = std::sqrt(5 + 2 * std::sqrt(10.0 / 7)) / 3;
      return {-b, -a, 0.0, a, b};
    }
  }
}

}  // namespace

bool inside_region(const Grid& grid, const ParticleRecord& p) {
  const auto x = position_of(p);
  for (int d = 0; d < grid.dim; ++d)
    if (!(x[d] >= grid.region_min[d] && x[d] <= grid.region_max[d])) return false;
  return true;
}

std::string position_text(const ParticleRecord& p, int dim) {
  const auto x = position_of(p);
  std::string s = "(";
  for (int d = 0; d < dim; ++d) s += (d ? ", " : "") + num(x[d]);
  return s + ")";
}

GeneratedParticles read_generators(StrictObject& root, const std::vector<MaterialSpec>& materials, const Lattice& lattice,
                                   const std::map<long long, std::vector<long long>>& cell_sets,
                                   const std::filesystem::path& dir, bool load_files) {
  const Grid& grid = lattice.grid;
  const int dim = grid.dim;
  GeneratedParticles out;
  const nlohmann::json& list = root.required("particles");
  if (!list.is_array() || list.empty()) root.fail("particles", "expected a non-empty array of {\"generator\": {...}}");
  for (std::size_t k = 0; k < list.size(); ++k) {
    StrictObject entry(list[k], root.file(), "particles[" + std::to_string(k) + "]");
    StrictObject g = entry.object("generator");
    const std::string type = g.string("type");
    const long long material = g.integer("material_id");
    if (std::none_of(materials.begin(), materials.end(), [&](const MaterialSpec& m) { return static_cast<long long>(m.id) == material; }))
      g.fail("material_id", "material " + std::to_string(material) + " is not defined in materials");
    check_dimension_word(g, "particle_type", "P", dim);
    check_dimension_word(g, "io_type", "Ascii", dim);
    g.boolean_or("check_duplicates", false);  // duplicates are always checked: no particle file may repeat a point
    const long long pset = g.integer_or("pset_id", -1);
    std::vector<FilePoint> xs;
    std::string shown;
    if (type == "file") {
      shown = g.string("location");
      if (load_files) xs = read_particle_coordinates(dir / shown, shown, dim);
    } else if (type == "gauss") {
      // CB-Geo's quadratures: up to 5 points per direction in 2D, 4 in 3D (1, 8, 27 or 64 per hexahedron).
      const long long max_nppd = dim == 3 ? 4 : 5;
      const long long nppd = g.integer("nparticles_per_dir");
      if (nppd < 1 || nppd > max_nppd)
        g.fail("nparticles_per_dir", "expected an integer in 1.." + std::to_string(max_nppd) + ", got " + std::to_string(nppd));
      const long long cset = g.integer("cset_id");
      std::vector<long long> cells;
      if (cset == -1) {
        for (std::size_t c = 0; c < lattice.cell_ij.size(); ++c) cells.push_back(static_cast<long long>(c));
      } else {
        const auto it = cell_sets.find(cset);
        if (it == cell_sets.end()) g.fail("cset_id", "cell set " + std::to_string(cset) + " is not defined in the entity sets");
        cells = it->second;
      }
      const double per_cell = std::pow(static_cast<double>(nppd), dim);
      // Counted before generating: 1e8 cells x 25 points must be an error, not std::bad_alloc.
      if (const auto problem = common::size_problem(static_cast<double>(cells.size()) * per_cell, sizeof(ParticleRecord),
                                                    "particles");
          !problem.empty())
        g.fail("nparticles_per_dir", problem);
      const auto pts = gauss_points(static_cast<int>(nppd));
      const std::size_t nz = dim == 3 ? pts.size() : 1;
      // Points x fastest, then y, then z, in each cell (as the 2D reader always has).
      for (long long c : cells) {
        const LatticeCell& cell = lattice.cell_ij[static_cast<std::size_t>(c)];
        FilePoint centre{};
        for (int d = 0; d < dim; ++d) centre[d] = grid.origin[d] + (cell[d] + 0.5) * grid.spacing[d];
        for (std::size_t iz = 0; iz < nz; ++iz)
          for (double eta : pts)
            for (double xi : pts) {
              FilePoint x = centre;
              x[0] += 0.5 * grid.spacing[0] * xi;
              x[1] += 0.5 * grid.spacing[1] * eta;
              if (dim == 3) x[2] += 0.5 * grid.spacing[2] * pts[iz];
              xs.push_back(x);
            }
      }
      shown = g.where("cset_id");
    } else {
      g.fail("type", "unsupported generator \"" + type + "\" (expected file or gauss)");
    }
    g.finish();
    entry.finish();
    for (std::size_t p = 0; p < xs.size(); ++p) {
      ParticleRecord r{};
      r.id = static_cast<std::int64_t>(out.records.size());
      r.coord_x = xs[p][0];
      r.coord_y = xs[p][1];
      r.coord_z = xs[p][2];
      r.material_id = static_cast<std::uint32_t>(material);
      r.status = 1;
      r.cell_id = -1;
      if (!inside_region(grid, r)) {
        std::string box;
        for (int d = 0; d < dim; ++d)
          box += (d ? " x [" : "[") + num(grid.region_min[d]) + ", " + num(grid.region_max[d]) + "]";
        throw common::InputError(shown, "particle " + std::to_string(p) + " at " + position_text(r, dim) +
                                            " is outside the grid's cells " + box);
      }
      if (pset >= 0) out.psets[pset].push_back(r.id);
      out.records.push_back(r);
    }
  }
  return out;
}

void check_no_duplicates(const std::vector<ParticleRecord>& ps, const std::string& where) {
  std::vector<std::pair<std::array<double, kMaxDim>, std::int64_t>> keyed;
  keyed.reserve(ps.size());
  for (const auto& p : ps) keyed.push_back({position_of(p), p.id});
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t k = 1; k < keyed.size(); ++k)
    if (keyed[k].first == keyed[k - 1].first) {
      const auto& x = keyed[k].first;
      const bool three = x[2] != 0;
      throw common::InputError(where, "particles " + std::to_string(keyed[k - 1].second) + " and " +
                                          std::to_string(keyed[k].second) + " are at the same point (" + num(x[0]) + ", " +
                                          num(x[1]) + (three ? ", " + num(x[2]) : std::string()) + ")");
    }
}

}  // namespace mpm::io
