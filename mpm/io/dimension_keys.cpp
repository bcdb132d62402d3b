#include "mpm/io/dimension_keys.hpp"

#include "mpm/io/json_keys.hpp"

namespace mpm::io {
namespace {

/// "a 3D" / "a 2D".
std::string dimension_words(int dim) { return "a " + std::to_string(dim) + "D"; }

}  // namespace

int read_analysis_dimension(StrictObject& a) {
  const std::string type = a.string("type");
  if (type == "MPMExplicit2D") return 2;
  if (type == "MPMExplicit3D") return 3;
  a.fail("type", "unsupported analysis \"" + type + "\" (expected MPMExplicit2D or MPMExplicit3D)");
}

void check_dimension_word(StrictObject& g, const std::string& key, const std::string& stem, int dim) {
  const nlohmann::json* v = g.optional(key);
  if (!v) return;
  const std::string want = stem + std::to_string(dim) + "D";
  const std::string other = stem + std::to_string(dim == 3 ? 2 : 3) + "D";
  if (!v->is_string()) g.fail(key, "expected the string \"" + want + "\", got " + json_kind(*v));
  const std::string word = v->get<std::string>();
  if (word == want) return;
  if (word == other) g.fail(key, "\"" + word + "\" in " + dimension_words(dim) + " analysis (expected \"" + want + "\")");
  g.fail(key, "unsupported value \"" + word + "\" (expected \"" + want + "\")");
}

CellType read_mesh_cell_type(StrictObject& mesh, int dim) {
  check_dimension_word(mesh, "io_type", "Ascii", dim);
  check_dimension_word(mesh, "node_type", "N", dim);
  const std::string cell = mesh.string("cell_type");
  const char* linear = dim == 3 ? "ED3H8" : "ED2Q4";
  const char* gimp = dim == 3 ? "ED3H64G" : "ED2Q16G";
  const std::string expected = std::string("(expected ") + linear + " or " + gimp + ")";
  if (cell == linear) return CellType::Linear4;
  if (cell == gimp) return CellType::Gimp16;
  const bool other = dim == 3 ? (cell == "ED2Q4" || cell == "ED2Q16G") : (cell == "ED3H8" || cell == "ED3H64G");
  if (other)
    mesh.fail("cell_type", "a " + std::to_string(dim == 3 ? 2 : 3) + "D cell type (\"" + cell + "\") in " +
                               dimension_words(dim) + " analysis " + expected);
  mesh.fail("cell_type", "unsupported cell type \"" + cell + "\" " + expected);
}

MaterialType read_material_type(StrictObject& m, int dim) {
  const std::string type = m.string("type");
  const std::string d = std::to_string(dim) + "D", other = std::to_string(dim == 3 ? 2 : 3) + "D";
  if (type == "LinearElastic" + d) return MaterialType::LinearElastic2D;  // == LinearElastic3D: the model
  if (type == "MohrCoulomb" + d) return MaterialType::MohrCoulomb2D;      // == MohrCoulomb3D
  const std::string expected = "(expected LinearElastic" + d + " or MohrCoulomb" + d + ")";
  if (type == "LinearElastic" + other || type == "MohrCoulomb" + other)
    m.fail("type", "a " + other + " material (\"" + type + "\") in " + dimension_words(dim) + " analysis " + expected);
  m.fail("type", "unsupported material \"" + type + "\" " + expected);
}

void read_gravity(StrictObject& l, int dim, Analysis& an) {
  const nlohmann::json* g = l.optional("gravity");
  if (!g) return;  // absent: no gravity, as without the block
  bool ok = g->is_array() && g->size() == static_cast<std::size_t>(dim);
  for (std::size_t k = 0; ok && k < g->size(); ++k) ok = (*g)[k].is_number();
  if (!ok)
    l.fail("gravity", dim == 3 ? "expected [gx, gy, gz] (3 numbers, m/s^2)" : "expected [gx, gy] (2 numbers, m/s^2)");
  an.gravity = Eigen::Vector2d((*g)[0].get<double>(), (*g)[1].get<double>());
  an.gravity_z = dim == 3 ? (*g)[2].get<double>() : 0.0;
}

}  // namespace mpm::io
