#pragma once
// What a resumed run reads from its particle file beside CB-Geo's "/table": the APIC matrices and the
// lagged friction strengths (particle_table.hpp), without which it does not continue bit for bit.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "mpm/problem/deck.hpp"

namespace mpm::io {

/// On resume, from the resume `file` (named `rshown` in messages; the deck is named `shown`):
/// - with the APIC transfer, deck.particle_affine (a 2D deck, 4 columns) or deck.particle_affine_3d (a 3D
///   deck, 9 columns) from kAffineDataset (rows in deck.particles order; another column count is a
///   common::InputError naming the file and the dataset). A
///   file without it (written by CB-Geo, by fem2mpm or by a FLIP / PIC run) resumes from zero matrices,
///   with a warning in deck.warnings; other transfers ignore the dataset;
/// - with a friction_constraints[].normal_lag, deck.friction_memory from kFrictionMemoryDataset; a row
///   whose node has no lagged friction constraint is a common::InputError naming the file and row. A
///   file without it restarts the memory from the instantaneous normal forces, with a warning; decks
///   without a lag ignore the dataset.
/// - deck.particle_pore_pressure from kPorePressureDataset when the file has it (a u-p transfer's p, sigma'v0
///   and r_u; one row per particle, finite values: else a common::InputError naming the file and row).
void read_resume_extras(const std::filesystem::path& file, const std::string& shown, const std::string& rshown,
                        Deck& deck);

/// The pore pressure rows of `particles` (a state sorted by id, as Simulation::snapshot gives it; particles
/// are only ever removed) from deck.particle_pore_pressure (sorted with deck.particles by id): each particle
/// keeps its transfer-time row. Empty when the deck has none.
std::vector<PorePressureRecord> carried_pore_pressure(const Deck& deck, std::span<const ParticleRecord> particles);

}  // namespace mpm::io
