#pragma once
// The MPM input deck for the transferred scene (FORMATS.md section 5, CB-Geo's schema): mpm.json with
// a `resume` block pointing at the particle file, a uniform background grid (mesh.txt; ED2Q16G GIMP
// cells with CB-Geo's halo ring of nodes, or ED2Q4), entity_sets.json (wall and base node sets),
// velocity and friction constraints, and particles.txt (the particle positions, so that the deck is
// complete also for a fresh start).
#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bridge/ground_motion.hpp"
#include "bridge/nodal_loads.hpp"
#include "bridge/transfer_state.hpp"
#include "mpm/io/particle_table.hpp"

namespace bridge {

enum class Wall { None, Roller, Fixed };
/// The grid's base. Contact: a one-sided frictional contact (mpm's reading of a friction constraint without a
/// normal velocity constraint: the base stops the soil's approach, never pulls it, and friction acts where it
/// presses); Friction: CB-Geo's frictional base (y-velocity 0, bilateral, and Coulomb friction), on which an
/// elastic body sliding under FLIP or APIC flutters and stalls (mpm/README.md "Friction and flutter").
enum class Base { Contact, Friction, Roller, Fixed };

/// Where the FEM supports put the grid's edges (boundary_extraction): the default grid is aligned so that
/// each is a grid line and is extended only beyond the free sides. Unset members are free sides.
struct GridAnchors {
  std::optional<double> left, right;  ///< x of the left / right wall, m
  std::optional<double> base;         ///< y of the base, m (the grid starts one cell row lower)
};

struct DeckOptions {
  std::string uuid = "column";
  long long step = 0;                         ///< step number of the particle file (resume.step)
  std::optional<double> cell_size;            ///< m; default sqrt(mean reference element area)
  std::optional<std::array<double, 4>> extent;///< xmin xmax ymin ymax; default bounding box + 3 widths right, 0.25 height up
  bool gimp = true;                           ///< ED2Q16G (true) or ED2Q4
  Wall left = Wall::Roller, right = Wall::Roller;
  Base base = Base::Contact;
  double base_friction = 0.4;
  /// The base friction's normal_lag (slip distance m, reference speed m/s; mpm/core/lagged_friction.hpp);
  /// unset: CB-Geo's instantaneous Coulomb friction.
  std::optional<std::array<double, 2>> base_lag;
  /// m; the base node set (and its constraint) is every node at or below this height. Default: the grid's
  /// bottom edge. Give the FEM base (e.g. 0) with an extent one cell row lower, so that a GIMP particle
  /// that dips a hair below the base still lies inside the grid.
  std::optional<double> base_y;
  /// The FEM supports' lines (default grid and base height); unset: the legacy default (left edge at the
  /// model, runout area 3 widths to the right, base at the grid's bottom edge).
  std::optional<GridAnchors> anchors;
  std::optional<double> dt;                   ///< s; default cfl * h / c_p
  double cfl = 0.1;
  double duration = 10;                       ///< s of MPM time after the transfer
  std::optional<long long> nsteps;            ///< overrides duration
  std::optional<long long> output_steps;      ///< default: every 0.5 s, at most nsteps - 1
  std::string scheme = "usf";
  bool velocity_update = false;               ///< true: PIC (CB-Geo's key; same as transfer "pic")
  /// analysis.transfer: "apic" (default: it brings the study's columns to rest without a PIC blend,
  /// docs/study/transfer_comparison.md), "flip" or "pic".
  std::string transfer = "apic";
  double damping = 0;                         ///< Cundall damping factor
  /// analysis.stress_smoothing, the checkerboard remedy (mpm/core/stress_remedy.hpp): "none" (CB-Geo's
  /// behaviour) or one of mpm::io::stress_smoothing_methods(); "none" is not written.
  std::string stress_smoothing = "none";
  /// The record that goes on shaking the base after the transfer (ground_motion.hpp); unset: none.
  std::optional<GroundMotion> ground_motion;
  /// The FEM's nodal loads on the particles (nodal_loads.hpp); written as one particle set and one
  /// particle_surface_traction per loaded particle and direction.
  std::vector<ParticleLoad> particle_loads;
};

/// The background grid: cells cover [x0, x0 + nx h] x [y0, y0 + ny h]; GIMP adds one node ring.
struct GridSpec {
  double x0 = 0, y0 = 0, h = 1;
  int nx = 0, ny = 0;
  bool gimp = true;
  int halo() const { return gimp ? 1 : 0; }
  int nodes_x() const { return nx + 1 + 2 * halo(); }
  int nodes_y() const { return ny + 1 + 2 * halo(); }
  /// 0-based node id of lattice point (i, j), i in [-halo, nx + halo].
  long node_id(int i, int j) const { return static_cast<long>(j + halo()) * nodes_x() + (i + halo()); }
};

struct DeckText {
  GridSpec grid;
  double base_y = 0;                          ///< m: the base node set is every node at or below it
  std::vector<std::string> warnings;          ///< grid choices the user should know (a wall off its FEM line)
  double dt = 0;
  long long nsteps = 0, output_steps = 0;
  std::string particle_file;                  ///< results/<uuid>/particles<step>.h5, relative to the deck
  std::string mpm_json, mesh_txt, entity_sets_json;
  /// The particle coordinate files of the deck's generators (name, body): particles.txt for one
  /// material, particles_material<id>.txt per material for several.
  std::vector<std::pair<std::string, std::string>> particle_files;
  /// The ground motion after the transfer, in MPM time (empty: the deck has no base_acceleration).
  MotionTable base_motion;
};

/// Chooses the grid for options that passed check_deck_options (throws common::InputError naming the
/// option when a particle lies outside the requested extent or the grid is too large).
GridSpec choose_grid(const TransferState& state, std::span<const mpm::ParticleRecord> particles,
                     const DeckOptions& options, std::vector<std::string>* warnings = nullptr);

/// The checks that need the options alone (dt or the Courant number, steps or duration, output steps,
/// scheme, base friction, damping, run name, extent): run before any file is read, so a bad option fails
/// at once (`fem2mpm --check-options`, and before a driver's FEM run). Throws common::InputError naming
/// the option.
void check_deck_options(const DeckOptions& options);

/// Checks the options and chooses the grid, dt, nsteps, output interval and particle file name
/// (everything but the text bodies). Throws common::InputError naming the option.
DeckText plan_deck(const TransferState& state, std::span<const mpm::ParticleRecord> particles,
                   const DeckOptions& options);

/// Fills the text bodies of a deck planned by plan_deck (no checks left to fail).
void format_deck(const TransferState& state, std::span<const mpm::ParticleRecord> particles,
                 const DeckOptions& options, DeckText& deck);

/// plan_deck then format_deck.
DeckText build_deck(const TransferState& state, std::span<const mpm::ParticleRecord> particles,
                    const DeckOptions& options);

}  // namespace bridge
