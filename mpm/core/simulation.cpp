#include "mpm/core/simulation.hpp"

#include "mpm/core/engine.hpp"

namespace mpm::core {

Simulation::Simulation(const Deck& deck, int threads, ExecutionOptions options)
    : engine_(std::make_unique<Engine>(deck, threads, options)) {}
Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;

void Simulation::step() { engine_->step(); }
long long Simulation::step_index() const { return engine_->step_index(); }
double Simulation::time() const { return engine_->time(); }
double Simulation::dt() const { return engine_->dt(); }
double Simulation::courant_number() const { return engine_->courant_number(); }
std::size_t Simulation::particle_count() const { return engine_->particle_count(); }
std::vector<ParticleRecord> Simulation::snapshot() const { return engine_->snapshot(); }
std::vector<std::array<double, 4>> Simulation::affine_snapshot() const { return engine_->affine_snapshot(); }
std::optional<std::vector<FrictionMemoryRecord>> Simulation::friction_memory_snapshot() const {
  return engine_->friction_memory_snapshot();
}

}  // namespace mpm::core
