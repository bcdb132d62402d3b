#pragma once
// A small CB-Geo 3D deck (MPMExplicit3D, Ascii3D, ED3H8) written into a folder, for the mpm reader's and
// the mpm program's 3D tests. The grid: origin (1, -1, 0), cells of 1 x 0.5 x 2 m, 3 x 2 x 2 cells (4 x 3 x
// 3 nodes); the mesh file lists its nodes in reverse lattice order (file id = 35 - lattice index) so the
// reader's mapping from file ids to the lattice is exercised. Eight particles at the 2 x 2 x 2 quarter
// points of cell (1, 1, 0); node set 0 the z = 0 face (velocity z fixed), node set 1 the x = 1 face
// (friction, normal -x); LinearElastic3D; gravity (0, 0, -9.81).
#include <array>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace test_support {

struct SmallDeck3d {
  static constexpr std::array<int, 3> kNodes = {4, 3, 3};
  static constexpr std::array<double, 3> kOrigin = {1.0, -1.0, 0.0};
  static constexpr std::array<double, 3> kSpacing = {1.0, 0.5, 2.0};
  static constexpr int kNodeCount = 36;

  /// The lattice index of lattice node (i, j, k), x fastest.
  static int lattice_index(int i, int j, int k) { return i + kNodes[0] * (j + kNodes[1] * k); }
  /// The file id of lattice node (i, j, k).
  static int file_id(int i, int j, int k) { return kNodeCount - 1 - lattice_index(i, j, k); }

  /// Writes mesh.txt (CB-Geo's ED3H8 order), particles.txt, entity_sets.json; returns the deck (not written).
  static nlohmann::json write(const std::filesystem::path& dir) {
    std::ofstream mesh(dir / "mesh.txt");
    mesh << "#! elementShape hexahedron\n" << kNodeCount << " 12\n";
    for (int id = 0; id < kNodeCount; ++id) {
      const int index = kNodeCount - 1 - id;
      const int i = index % kNodes[0], j = (index / kNodes[0]) % kNodes[1], k = index / (kNodes[0] * kNodes[1]);
      mesh << kOrigin[0] + i * kSpacing[0] << " " << kOrigin[1] + j * kSpacing[1] << " " << kOrigin[2] + k * kSpacing[2] << "\n";
    }
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) {
          // ED3H8: the lower z face counter-clockwise from the lowest corner, then the upper face.
          for (int dk = 0; dk < 2; ++dk)
            mesh << file_id(i, j, k + dk) << " " << file_id(i + 1, j, k + dk) << " " << file_id(i + 1, j + 1, k + dk) << " "
                 << file_id(i, j + 1, k + dk) << (dk ? "\n" : " ");
        }
    std::ofstream particles(dir / "particles.txt");
    particles << "8\n";
    for (const double z : {0.5, 1.5})
      for (const double y : {-0.375, -0.125})
        for (const double x : {2.25, 2.75}) particles << x << " " << y << " " << z << "\n";
    std::string bottom, left;
    for (int j = 0; j < kNodes[1]; ++j)
      for (int i = 0; i < kNodes[0]; ++i) bottom += (bottom.empty() ? "" : ", ") + std::to_string(file_id(i, j, 0));
    for (int k = 0; k < kNodes[2]; ++k)
      for (int j = 0; j < kNodes[1]; ++j) left += (left.empty() ? "" : ", ") + std::to_string(file_id(0, j, k));
    std::ofstream(dir / "entity_sets.json") << R"({"node_sets": [{"id": 0, "set": [)" << bottom << R"(]}, {"id": 1, "set": [)"
                                            << left << R"(]}], "cell_sets": [{"id": 4, "set": [0, 11]}]})";
    return nlohmann::json::parse(R"({
      "title": "small 3D",
      "mesh": {"mesh": "mesh.txt", "entity_sets": "entity_sets.json", "cell_type": "ED3H8", "io_type": "Ascii3D",
               "node_type": "N3D", "isoparametric": false,
               "boundary_conditions": {"velocity_constraints": [{"nset_id": 0, "dir": 2, "velocity": 0.0}],
                                       "friction_constraints": [{"nset_id": 1, "dir": 0, "sign_n": -1, "friction": 0.3}]}},
      "particles": [{"generator": {"type": "file", "location": "particles.txt", "io_type": "Ascii3D", "pset_id": 0,
                                   "particle_type": "P3D", "material_id": 0, "check_duplicates": true}}],
      "materials": [{"id": 0, "type": "LinearElastic3D", "density": 1800.0, "youngs_modulus": 1e6, "poisson_ratio": 0.2}],
      "external_loading_conditions": {"gravity": [0.0, 0.0, -9.81]},
      "analysis": {"type": "MPMExplicit3D", "mpm_scheme": "usf", "dt": 1e-3, "nsteps": 10, "uuid": "small3d",
                   "velocity_update": false, "resume": {"resume": false, "uuid": "small3d", "step": 0}},
      "post_processing": {"path": "results/", "output_steps": 5}
    })");
  }
};

}  // namespace test_support
