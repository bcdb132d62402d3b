#include "mpm/io/resume_extras.hpp"

#include <set>
#include <stdexcept>

#include "common/input_error.hpp"
#include "mpm/io/particle_table.hpp"

namespace mpm::io {
namespace {

/// The deck's `dim`-axis matrices (`affine`, Deck::particle_affine or particle_affine_3d) from `file`.
template <int dim>
void read_resume_affine(const std::filesystem::path& file, const std::string& rshown, Deck& deck,
                        std::vector<AffineMatrix<dim>>& affine) {
  if (auto rows = read_affine_dataset<dim>(file, deck.particles.size())) {
    affine = std::move(*rows);
  } else {
    affine.clear();
    deck.warnings.push_back(rshown + " has no /" + std::string(kAffineDataset) +
                            " dataset: the APIC transfer resumes from zero affine matrices (not bit for bit the run "
                            "that wrote it, if that run used APIC)");
  }
}

void read_resume_affine(const std::filesystem::path& file, const std::string& rshown, Deck& deck) {
  if (deck.analysis.transfer != Transfer::APIC) return;
  if (deck.grid.dim == 3) read_resume_affine<3>(file, rshown, deck, deck.particle_affine_3d);
  else read_resume_affine<2>(file, rshown, deck, deck.particle_affine);
}

void read_resume_friction_memory(const std::filesystem::path& file, const std::string& shown, const std::string& rshown,
                                 Deck& deck) {
  std::set<std::int64_t> lagged;
  for (const FrictionConstraint& c : deck.friction_constraints)
    if (c.lag_slip_distance > 0) lagged.insert(c.nodes.begin(), c.nodes.end());
  if (lagged.empty()) return;
  auto memory = read_friction_memory_dataset(file);
  if (!memory) {
    deck.warnings.push_back(shown + ": friction_constraints[].normal_lag: " + rshown + " has no /" +
                            std::string(kFrictionMemoryDataset) + " dataset: the lagged strengths restart from the "
                            "instantaneous normal forces (not bit for bit the run that wrote it, if that run had the lag)");
    return;
  }
  for (std::size_t k = 0; k < memory->size(); ++k)
    if (!lagged.contains((*memory)[k].node))
      throw common::InputError(rshown, "dataset \"/" + std::string(kFrictionMemoryDataset) + "\" row " + std::to_string(k) +
                                           ": node " + std::to_string((*memory)[k].node) + " has no friction constraint "
                                           "with a normal_lag in " + shown);
  deck.friction_memory = std::move(*memory);
}

void read_resume_pore_pressure(const std::filesystem::path& file, Deck& deck) {
  deck.particle_pore_pressure = read_pore_pressure_dataset(file, deck.particles.size());
}

}  // namespace

void read_resume_extras(const std::filesystem::path& file, const std::string& shown, const std::string& rshown,
                        Deck& deck) {
  read_resume_affine(file, rshown, deck);
  read_resume_friction_memory(file, shown, rshown, deck);
  read_resume_pore_pressure(file, deck);
}

std::vector<PorePressureRecord> carried_pore_pressure(const Deck& deck, std::span<const ParticleRecord> particles) {
  std::vector<PorePressureRecord> rows;
  if (!deck.particle_pore_pressure) return rows;
  const auto& all = *deck.particle_pore_pressure;
  rows.reserve(particles.size());
  std::size_t k = 0;  // both sorted by id: one merge pass
  for (const ParticleRecord& p : particles) {
    while (k < deck.particles.size() && deck.particles[k].id < p.id) ++k;
    if (k == deck.particles.size() || deck.particles[k].id != p.id)
      throw std::logic_error("carried_pore_pressure: particle " + std::to_string(p.id) + " is not in the resumed deck");
    rows.push_back(all[k]);
  }
  return rows;
}

}  // namespace mpm::io
