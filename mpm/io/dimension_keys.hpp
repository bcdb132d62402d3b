#pragma once
// The keys of a CB-Geo deck whose values name the problem's dimension (FORMATS.md sections 5 and 7):
// analysis.type MPMExplicit2D / MPMExplicit3D, mesh.io_type Ascii2D / Ascii3D, node_type N2D / N3D,
// cell_type ED2Q4 / ED2Q16G or ED3H8 / ED3H64G, particle_type P2D / P3D, the material types
// (LinearElastic2D / 3D, MohrCoulomb2D / 3D) and gravity's 2 or 3 components. The dimension is chosen once,
// by analysis.type; every other key must agree with it, and a value of the other dimension is an error
// saying so ("a 3D cell type ... in a 2D analysis").
#include <string>

#include "mpm/problem/deck.hpp"

namespace mpm::io {

class StrictObject;

/// analysis.type: 2 for MPMExplicit2D, 3 for MPMExplicit3D; fails naming the key otherwise.
int read_analysis_dimension(StrictObject& analysis);

/// mesh.io_type and mesh.node_type (optional; the dimension's value) and mesh.cell_type (required).
CellType read_mesh_cell_type(StrictObject& mesh, int dim);

/// materials[k].type.
MaterialType read_material_type(StrictObject& material, int dim);

/// external_loading_conditions.gravity: [gx, gy] or [gx, gy, gz], into analysis.gravity (and gravity_z).
void read_gravity(StrictObject& loads, int dim, Analysis& analysis);

/// An optional key whose value is `stem` + "2D" or "3D" (io_type "Ascii", particle_type "P", node_type "N"):
/// absent, or the dimension's value; otherwise an error naming the key.
void check_dimension_word(StrictObject& object, const std::string& key, const std::string& stem, int dim);

}  // namespace mpm::io
