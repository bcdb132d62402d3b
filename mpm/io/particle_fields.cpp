#include "mpm/io/particle_fields.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mpm::io {
namespace {

constexpr std::array<const char*, 7> kMohrCoulombStateVariables = {"phi",   "psi",   "cohesion", "epsilon",
                                                                   "rho",   "theta", "pdstrain"};
constexpr double kDegrees = 180.0 / std::numbers::pi;
constexpr std::uint32_t kMohrCoulombCount = kMohrCoulombStateVariables.size();

/// A field whose value per particle (and per component) is `value(p, component)`.
template <class Value>
ParticleField real_field(const char* name, FieldKind kind, std::span<const ParticleRecord> ps, Value value) {
  ParticleField f{name, kind, false, {}, {}};
  const int nc = components(kind);
  f.real.reserve(ps.size() * static_cast<std::size_t>(nc));
  for (const auto& p : ps)
    for (int c = 0; c < nc; ++c) f.real.push_back(value(p, c));
  return f;
}

template <class Value>
ParticleField integer_field(const char* name, std::span<const ParticleRecord> ps, Value value) {
  ParticleField f{name, FieldKind::Scalar, true, {}, {}};
  f.whole.reserve(ps.size());
  for (const auto& p : ps) f.whole.push_back(static_cast<std::int64_t>(value(p)));
  return f;
}

/// State variable k of a Mohr-Coulomb particle, else 0.
double mohr_coulomb_state(const ParticleRecord& p, std::size_t k) {
  return p.nstate_vars == kMohrCoulombCount ? p.svars[k] : 0.0;
}

/// The particle's extent along one axis of a grid of `dim` axes, m: from its natural size, else the side of
/// the square (2D) or cube (3D) of its volume.
double extent(double nsize, double cell, double volume, int dim) {
  if (nsize > 0) return 0.5 * nsize * cell;
  return dim == 3 ? std::cbrt(std::max(volume, 0.0)) : std::sqrt(std::max(volume, 0.0));
}

/// A record's component along `axis`: itself on the grid's axes, 0 beyond them (a 2D particle shows z = 0
/// whatever its record holds).
double on_axis(const Grid& grid, int axis, double value) { return axis < grid.dim ? value : 0.0; }

/// The radius of the particle's square (2D) or cube (3D) of its extents' area or volume: half the side.
double equivalent_radius(const ParticleRecord& p, const Grid& grid) {
  const auto& h = grid.spacing;
  const double ex = extent(p.nsize_x, h[0], p.volume, grid.dim), ey = extent(p.nsize_y, h[1], p.volume, grid.dim);
  if (grid.dim == 3) {
    const double ez = extent(p.nsize_z, h[2], p.volume, grid.dim), cube = ex * ey * ez;
    return 0.5 * (std::isfinite(cube) ? std::cbrt(cube) : std::cbrt(ex) * std::cbrt(ey) * std::cbrt(ez));
  }
  // sqrt(ex) sqrt(ey) where ex ey overflows (found by fuzzing: a resumed bilinear-cell particle with
  // nsize 1e68 x 1e247, which the physics ignores, gave a radius of inf).
  const double area = ex * ey;
  return 0.5 * (std::isfinite(area) ? std::sqrt(area) : std::sqrt(ex) * std::sqrt(ey));
}

}  // namespace

std::vector<double> particle_coordinates(std::span<const ParticleRecord> particles, const Grid& grid) {
  std::vector<double> xyz;
  xyz.reserve(3 * particles.size());
  for (const auto& p : particles) xyz.insert(xyz.end(), {p.coord_x, p.coord_y, on_axis(grid, 2, p.coord_z)});
  return xyz;
}

std::span<const char* const> mohr_coulomb_state_variable_names() { return kMohrCoulombStateVariables; }

ParticleField state_variable_field(std::span<const ParticleRecord> particles, const std::string& name) {
  const auto* it = std::find(kMohrCoulombStateVariables.begin(), kMohrCoulombStateVariables.end(), name);
  if (it == kMohrCoulombStateVariables.end()) throw std::invalid_argument("unknown state variable " + name);
  const auto k = static_cast<std::size_t>(it - kMohrCoulombStateVariables.begin());
  ParticleField f = real_field(*it, FieldKind::Scalar, particles, [&](const auto& p, int) { return mohr_coulomb_state(p, k); });
  return f;
}

std::vector<ParticleField> particle_fields(std::span<const ParticleRecord> ps, const Grid& grid) {
  using K = FieldKind;
  const bool three = grid.dim == 3;
  std::vector<ParticleField> f;
  f.push_back(real_field("velocity", K::Vector, ps, [&](const auto& p, int c) {
    return on_axis(grid, c, c == 0 ? p.velocity_x : c == 1 ? p.velocity_y : p.velocity_z);
  }));
  f.push_back(real_field("displacement", K::Vector, ps, [&](const auto& p, int c) {
    return on_axis(grid, c, c == 0 ? p.displacement_x : c == 1 ? p.displacement_y : p.displacement_z);
  }));
  f.push_back(real_field("size", K::Vector, ps, [&](const auto& p, int c) {
    const double nsize = c == 0 ? p.nsize_x : c == 1 ? p.nsize_y : p.nsize_z;
    return c < grid.dim ? extent(nsize, grid.spacing[static_cast<std::size_t>(c)], p.volume, grid.dim) : 0.0;
  }));
  f.push_back(real_field("stress", K::Tensor6, ps, [](const auto& p, int c) {
    const double s[6] = {p.stress_xx, p.stress_yy, p.stress_zz, p.tau_xy, p.tau_yz, p.tau_xz};
    return s[c];
  }));
  f.push_back(real_field("strain", K::Tensor6, ps, [](const auto& p, int c) {
    const double e[6] = {p.strain_xx, p.strain_yy, p.strain_zz, 0.5 * p.gamma_xy, 0.5 * p.gamma_yz, 0.5 * p.gamma_xz};
    return e[c];
  }));
  f.push_back(real_field("mass", K::Scalar, ps, [](const auto& p, int) { return p.mass; }));
  f.push_back(real_field("volume", K::Scalar, ps, [](const auto& p, int) { return p.volume; }));
  f.push_back(real_field("radius", K::Scalar, ps, [&](const auto& p, int) { return equivalent_radius(p, grid); }));
  f.push_back(real_field("stress_xx", K::Scalar, ps, [](const auto& p, int) { return p.stress_xx; }));
  f.push_back(real_field("stress_yy", K::Scalar, ps, [](const auto& p, int) { return p.stress_yy; }));
  f.push_back(real_field("stress_zz", K::Scalar, ps, [](const auto& p, int) { return p.stress_zz; }));
  f.push_back(real_field("tau_xy", K::Scalar, ps, [](const auto& p, int) { return p.tau_xy; }));
  if (three) {
    f.push_back(real_field("tau_yz", K::Scalar, ps, [](const auto& p, int) { return p.tau_yz; }));
    f.push_back(real_field("tau_xz", K::Scalar, ps, [](const auto& p, int) { return p.tau_xz; }));
  }
  f.push_back(real_field("strain_xx", K::Scalar, ps, [](const auto& p, int) { return p.strain_xx; }));
  f.push_back(real_field("strain_yy", K::Scalar, ps, [](const auto& p, int) { return p.strain_yy; }));
  if (three) f.push_back(real_field("strain_zz", K::Scalar, ps, [](const auto& p, int) { return p.strain_zz; }));
  f.push_back(real_field("gamma_xy", K::Scalar, ps, [](const auto& p, int) { return p.gamma_xy; }));
  if (three) {
    f.push_back(real_field("gamma_yz", K::Scalar, ps, [](const auto& p, int) { return p.gamma_yz; }));
    f.push_back(real_field("gamma_xz", K::Scalar, ps, [](const auto& p, int) { return p.gamma_xz; }));
  }
  f.push_back(real_field("epsilon_v", K::Scalar, ps, [](const auto& p, int) { return p.epsilon_v; }));
  f.push_back(real_field("friction", K::Scalar, ps, [](const auto& p, int) { return kDegrees * mohr_coulomb_state(p, 0); }));
  f.push_back(real_field("dilation", K::Scalar, ps, [](const auto& p, int) { return kDegrees * mohr_coulomb_state(p, 1); }));
  f.push_back(real_field("cohesion", K::Scalar, ps, [](const auto& p, int) { return mohr_coulomb_state(p, 2); }));
  f.push_back(real_field("pdstrain", K::Scalar, ps, [](const auto& p, int) { return mohr_coulomb_state(p, 6); }));
  f.push_back(integer_field("id", ps, [](const auto& p) { return p.id; }));
  f.push_back(integer_field("material_id", ps, [](const auto& p) { return p.material_id; }));
  f.push_back(integer_field("cell_id", ps, [](const auto& p) { return p.cell_id; }));
  f.push_back(integer_field("status", ps, [](const auto& p) { return p.status; }));
  return f;
}

}  // namespace mpm::io
