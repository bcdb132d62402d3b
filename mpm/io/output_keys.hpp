#pragma once
// The output keys of a deck's post_processing object that choose VTK files (CB-Geo's "vtk" and
// "vtk_statevars"), read apart from read_deck so the deck reader does not grow with each format.
#include "mpm/problem/deck.hpp"
#include "mpm/io/json_keys.hpp"

namespace mpm::io {

/// Reads post_processing.vtk (attribute names: CB-Geo's "displacements", "velocities", "stresses",
/// "strains", or any particle_fields() name) and post_processing.vtk_statevars (CB-Geo's
/// ["pdstrain", ...] or [{"phase_id": 0, "statevars": ["pdstrain", ...]}]) into `out`.
/// Throws common::InputError naming the key for an unknown attribute or state variable.
void read_vtk_keys(StrictObject& post_processing, Output& out);

/// Reads the extension post_processing.particle_output_steps (Output::particle_output_steps) of a run of
/// `nsteps` steps; out.output_steps must be read already. Throws common::InputError naming the key for
/// anything but an array of distinct multiples of output_steps in [0, nsteps).
void read_particle_output_steps(StrictObject& post_processing, long long nsteps, Output& out);

}  // namespace mpm::io
