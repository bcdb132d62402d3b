#pragma once
// VTK XML files for ParaView, written by hand (the format is a few lines of XML and raw appended
// binary; a VTK dependency would add ~100 MB of packages for that): particle PolyData (.vtp), a
// time collection (.pvd) and the background grid as a RectilinearGrid (.vtr).
// Format: "VTK File Formats", VTK User's Guide 11th ed., Kitware 2010, section "XML File Formats"
// (appended raw data: each array is a UInt64 byte count followed by its little-endian bytes).
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "mpm/problem/deck.hpp"
#include "mpm/io/particle_fields.hpp"

namespace mpm::io {

/// Particles as PolyData vertices at `xyz` (n x 3) with point arrays `fields`.
void write_particles_vtp(const std::filesystem::path& file, std::span<const double> xyz,
                         std::span<const ParticleField> fields);

struct PvdEntry {
  double time;
  std::string file;  ///< relative to the .pvd
};

/// A ParaView data collection: one dataset per time.
void write_pvd(const std::filesystem::path& file, std::span<const PvdEntry> entries);

/// The background grid of `deck` (its lattice nodes, halo ring included; a 2D grid is one layer at z = 0,
/// extent 0 0 along z) with node arrays fixed_x, fixed_y and, on a 3D grid, fixed_z (1 where a velocity
/// constraint holds that component), friction (the Coulomb coefficient of a friction constraint, 0
/// elsewhere) and in_mesh (1 inside the mesh region, over every axis of the grid).
void write_grid_vtr(const std::filesystem::path& file, const Deck& deck);

}  // namespace mpm::io
