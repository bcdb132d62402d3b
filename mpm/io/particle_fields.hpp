#pragma once
// The per-particle arrays a visualiser shows, defined once for every writer (the XDMF datasets of
// particles<step>.h5 and the VTK PolyData files): names, components and values.
//
// Conventions (ParaView's and VTK's, vtkDataSetAttributes: a 6-component tensor is symmetric): a vector has 3
// components (z = 0 in 2D, whatever the record holds); a symmetric tensor has 6, in the order xx yy zz xy yz
// xz (CB-Geo's record order), the same in 2D (yz = xz = 0) and 3D. The strain tensor holds tensorial shear components (gamma / 2), so
// its eigenvalues are principal strains; the CB-Geo engineering shear strain stays in gamma_xy.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mpm/problem/deck.hpp"
#include "mpm/io/particle_table.hpp"

namespace mpm::io {

enum class FieldKind { Scalar, Vector, Tensor6 };

/// Components of a field of `kind` (1, 3 or 6).
constexpr int components(FieldKind kind) { return kind == FieldKind::Scalar ? 1 : kind == FieldKind::Vector ? 3 : 6; }

/// One array over the particles, in particle order. Ids, flags and indices are integers.
struct ParticleField {
  std::string name;
  FieldKind kind = FieldKind::Scalar;
  bool integer = false;
  std::vector<double> real;          ///< n * components values when !integer
  std::vector<std::int64_t> whole;   ///< n values when integer (always scalar)
};

/// Particle centres as n x 3 values (z = 0 on a 2D grid, coord_z on a 3D one).
std::vector<double> particle_coordinates(std::span<const ParticleRecord> particles, const Grid& grid);

/// Every field, in a fixed order: vectors (velocity, displacement, size), tensors (stress, strain),
/// scalars (mass, volume, radius, the stress and strain components (on a 3D grid also tau_yz, tau_xz,
/// strain_zz, gamma_yz, gamma_xz, each after its 2D neighbours), epsilon_v, the Mohr-Coulomb state
/// variables friction, dilation (degrees), cohesion (Pa), pdstrain) and integers (id, material_id,
/// cell_id, status). A particle whose material has no such state variable shows 0.
/// `size` is the particle's extent (m): nsize times half the cell size per axis (CB-Geo's natural
/// size 2/ppd covers 1/ppd of the cell), or the side of the square (2D) or cube (3D) of the volume where nsize is not set (0 along z in 2D); `radius`
/// is half the side of the square of the same area (3D: of the cube of the same volume), the radius ParaView's
/// Point Gaussian representation
/// needs ("Scale by array", shader "Plain square") to show each particle at its true extent.
std::vector<ParticleField> particle_fields(std::span<const ParticleRecord> particles, const Grid& grid);

/// CB-Geo Mohr-Coulomb state variable names in their svars order (FORMATS.md section 4).
std::span<const char* const> mohr_coulomb_state_variable_names();

/// The array of CB-Geo state variable `name` (one of mohr_coulomb_state_variable_names()), raw
/// (angles in radians, as CB-Geo's VTK writer gives them); 0 for particles without it.
/// Throws std::invalid_argument for an unknown name.
ParticleField state_variable_field(std::span<const ParticleRecord> particles, const std::string& name);

}  // namespace mpm::io
