#pragma once
// The output keys of a deck's post_processing object that choose VTK files (CB-Geo's "vtk" and
// "vtk_statevars"), read apart from read_deck so the deck reader does not grow with each format.
#include "mpm/io/deck.hpp"
#include "mpm/io/json_keys.hpp"

namespace mpm::io {

/// Reads post_processing.vtk (attribute names: CB-Geo's "displacements", "velocities", "stresses",
/// "strains", or any particle_fields() name) and post_processing.vtk_statevars (CB-Geo's
/// ["pdstrain", ...] or [{"phase_id": 0, "statevars": ["pdstrain", ...]}]) into `out`.
/// Throws common::InputError naming the key for an unknown attribute or state variable.
void read_vtk_keys(StrictObject& post_processing, Output& out);

}  // namespace mpm::io
