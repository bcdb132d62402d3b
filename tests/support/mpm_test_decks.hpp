#pragma once
// Small MPM decks built in code for the engine's unit and verification tests (no files needed).
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "mpm/core/simulation.hpp"
#include "mpm/problem/deck.hpp"

namespace mpm_test {

using mpm::CellType;
using mpm::Deck;

/// A uniform grid of cells_x x cells_y cells of size h with its lower-left corner at (x0, y0). GIMP
/// grids get CB-Geo's halo ring: one extra node around the region on every side.
inline mpm::Grid make_grid(double x0, double y0, double h, int cells_x, int cells_y, CellType type) {
  mpm::Grid g;
  const int halo = type == CellType::Gimp16 ? 1 : 0;
  const double corner[2] = {x0, y0};
  const int cells[2] = {cells_x, cells_y};
  for (int d = 0; d < 2; ++d) {
    g.origin[d] = corner[d] - halo * h;
    g.spacing[d] = h;
    g.nodes_per_axis[d] = cells[d] + 1 + 2 * halo;
    g.region_min[d] = corner[d];
    g.region_max[d] = corner[d] + cells[d] * h;
  }
  g.cell_type = type;
  return g;
}

inline mpm::MaterialSpec elastic(unsigned id, double rho, double E, double nu) {
  mpm::MaterialSpec m;
  m.id = id;
  m.type = mpm::MaterialType::LinearElastic2D;
  m.density = rho;
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  return m;
}

inline mpm::MaterialSpec mohr_coulomb(unsigned id, double rho, double E, double nu, double phi_deg, double c,
                                          double psi_deg) {
  mpm::MaterialSpec m = elastic(id, rho, E, nu);
  m.type = mpm::MaterialType::MohrCoulomb2D;
  const double d2r = std::acos(-1.0) / 180.0;
  m.friction = m.residual_friction = phi_deg * d2r;
  m.dilation = m.residual_dilation = psi_deg * d2r;
  m.cohesion = m.residual_cohesion = c;
  m.tension_cutoff = 0.0;
  return m;
}

/// Fills the rectangle [xa, xb] x [ya, yb] (whole cells) with ppd x ppd particles per cell at the cell's
/// sub-cell centres, volume 0 (the engine applies CB-Geo's defaults). Returns the first id used.
inline std::int64_t fill_block(Deck& deck, double xa, double xb, double ya, double yb, int ppd, unsigned material,
                               std::int64_t first_id = -1) {
  const double h = deck.grid.spacing[0];
  std::int64_t id = first_id >= 0 ? first_id : static_cast<std::int64_t>(deck.particles.size());
  const std::int64_t start = id;
  const int nx = static_cast<int>(std::lround((xb - xa) / h)) * ppd;
  const int ny = static_cast<int>(std::lround((yb - ya) / h)) * ppd;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mpm::ParticleRecord r{};
      r.id = id++;
      r.coord_x = xa + (i + 0.5) * h / ppd;
      r.coord_y = ya + (j + 0.5) * h / ppd;
      r.material_id = material;
      deck.particles.push_back(r);
    }
  return start;
}

/// Lattice indices of the nodes whose coordinates satisfy `pred`.
inline std::vector<int> nodes_where(const mpm::Grid& g, const std::function<bool(double, double)>& pred) {
  std::vector<int> out;
  for (int j = 0; j < g.nodes_per_axis[1]; ++j)
    for (int i = 0; i < g.nodes_per_axis[0]; ++i)
      if (pred(g.origin[0] + i * g.spacing[0], g.origin[1] + j * g.spacing[1]))
        out.push_back(i + j * g.nodes_per_axis[0]);
  return out;
}

/// The collapsing Mohr-Coulomb column of the tests: particles (ppd x ppd per cell) fill [0, width] x
/// [0, height] of `grid` with K0 = 0.5 geostatic stresses, syy = -rho g (height - y), sxx = szz = syy / 2
/// (g = 9.81 m/s2, also the deck's gravity); a roller wall at x = 0 (and at x = right_wall when > 0);
/// the base y = 0 fixed in y with Coulomb friction `base_friction` (CB-Geo friction_constraints, sign_n -1).
/// The caller sets the scheme and the time step.
inline Deck collapsing_column(const mpm::Grid& grid, const mpm::MaterialSpec& material, double width,
                              double height, int ppd, double base_friction, double right_wall = 0.0) {
  constexpr double g = 9.81;
  Deck deck;
  deck.grid = grid;
  deck.materials.push_back(material);
  fill_block(deck, 0, width, 0, height, ppd, material.id);
  for (auto& p : deck.particles) {
    p.stress_yy = -material.density * g * (height - p.coord_y);
    p.stress_xx = p.stress_zz = 0.5 * p.stress_yy;
  }
  deck.velocity_constraints.push_back({nodes_where(grid, [](double x, double) { return x <= 1e-9; }), 0, 0.0});
  if (right_wall > 0.0)
    deck.velocity_constraints.push_back(
        {nodes_where(grid, [&](double x, double) { return x >= right_wall - 1e-9; }), 0, 0.0});
  const auto base = nodes_where(grid, [](double, double y) { return y <= 1e-9; });
  deck.velocity_constraints.push_back({base, 1, 0.0});
  deck.friction_constraints.push_back({base, 1, -1, base_friction});
  deck.analysis.gravity = {0, -g};
  return deck;
}

/// An elastic block sliding down a Coulomb base: gravity rotated by `angle_deg` (g (sin a, -cos a)), the
/// block [x0, x0 + width] x [0, height] (ppd x ppd particles per cell) on the base y = 0 of a grid of
/// `cells_x` x ceil(height / h) + 1 cells, which carries CB-Geo's friction constraint (dir 1, sign_n -1,
/// coefficient mu) and, unless one_sided, is fixed in y. The block starts at rest in its K0 = nu / (1 - nu) state under
/// the normal gravity component. Analytic motion (rigid block, Coulomb friction; e.g. Bardenhagen,
/// Brackbill & Sulsky 2000, CMAME 187, section 5): for mu < tan a, x(t) = a_s t^2 / 2, v = a_s t with
/// a_s = g (sin a - mu cos a); for mu >= tan a it stays at rest. The caller sets the scheme and dt.
struct SlidingBlockSpec {
  double angle_deg = 30.0, mu = 0.3;
  double width = 2.0, height = 1.0, x0 = 0.5;
  double h = 0.25;
  int cells_x = 40, ppd = 2;
  double rho = 1000, E = 1e6, nu = 0.3;
  CellType type = CellType::Linear4;
  /// true: the base is the friction constraint alone, a one-sided frictional contact (fem2mpm --base
  /// contact); false: CB-Geo's base, also fixed in y (bilateral).
  bool one_sided = false;
  /// true: the block starts in the self-weight state of a layer on the slope, the shear that carries the
  /// down-slope load included (sigma_xy = rho g sin(a) (H - y)); false: the normal stresses only.
  bool slope_start = false;
  /// The base's normal_lag (mpm/core/lagged_friction.hpp): slip distance (m; 0: none) and reference speed (m/s).
  double lag_slip_distance = 0.0, lag_reference_velocity = 0.0;
};
inline Deck sliding_block(const SlidingBlockSpec& s) {
  constexpr double g = 9.81;
  const double a = s.angle_deg * std::acos(-1.0) / 180.0;
  Deck deck;
  deck.grid = make_grid(0, 0, s.h, s.cells_x, static_cast<int>(std::ceil(s.height / s.h - 1e-9)) + 1, s.type);
  deck.materials.push_back(elastic(0, s.rho, s.E, s.nu));
  fill_block(deck, s.x0, s.x0 + s.width, 0.0, s.height, s.ppd, 0);
  const double k0 = s.nu / (1.0 - s.nu);
  for (auto& p : deck.particles) {
    p.stress_yy = -s.rho * g * std::cos(a) * (s.height - p.coord_y);
    p.stress_xx = p.stress_zz = k0 * p.stress_yy;
    if (s.slope_start) p.tau_xy = s.rho * g * std::sin(a) * (s.height - p.coord_y);
  }
  const auto base = nodes_where(deck.grid, [](double, double y) { return y <= 1e-9; });
  if (!s.one_sided) deck.velocity_constraints.push_back({base, 1, 0.0});
  deck.friction_constraints.push_back({base, 1, -1, s.mu, s.lag_slip_distance, s.lag_reference_velocity});
  deck.analysis.gravity = {g * std::sin(a), -g * std::cos(a)};
  return deck;
}

/// Mass-weighted mean displacement and velocity of a snapshot (t: its time, set by the caller).
struct MeanMotion {
  double ux = 0, vx = 0, vy = 0, t = 0;
};
inline MeanMotion mean_motion(const std::vector<mpm::ParticleRecord>& ps) {
  MeanMotion r;
  double m = 0;
  for (const auto& p : ps) {
    m += p.mass;
    r.ux += p.mass * p.displacement_x;
    r.vx += p.mass * p.velocity_x;
    r.vy += p.mass * p.velocity_y;
  }
  r.ux /= m;
  r.vx /= m;
  r.vy /= m;
  return r;
}

/// Sums over a snapshot.
struct Totals {
  double mass = 0, mx = 0, my = 0, px = 0, py = 0, kinetic = 0;
};
inline Totals totals(const std::vector<mpm::ParticleRecord>& ps) {
  Totals t;
  for (const auto& p : ps) {
    t.mass += p.mass;
    t.mx += p.mass * p.coord_x;
    t.my += p.mass * p.coord_y;
    t.px += p.mass * p.velocity_x;
    t.py += p.mass * p.velocity_y;
    t.kinetic += 0.5 * p.mass * (p.velocity_x * p.velocity_x + p.velocity_y * p.velocity_y);
  }
  return t;
}

}  // namespace mpm_test
