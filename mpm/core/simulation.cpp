#include "mpm/core/simulation.hpp"

#include <stdexcept>

namespace mpm::core {

/// Placeholder until the engine lands (the interface is what the io helper codes against).
class Engine {
 public:
  explicit Engine(const io::Deck& deck) : step_(deck.first_step), dt_(deck.analysis.dt), particles_(deck.particles) {}
  long long step_ = 0;
  double dt_ = 0;
  std::vector<io::ParticleRecord> particles_;
};

Simulation::Simulation(const io::Deck& deck, int /*threads*/) : engine_(std::make_unique<Engine>(deck)) {}
Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;
void Simulation::step() { throw std::logic_error("mpm::core::Simulation::step: not implemented yet"); }
long long Simulation::step_index() const { return engine_->step_; }
double Simulation::time() const { return static_cast<double>(engine_->step_) * engine_->dt_; }
double Simulation::dt() const { return engine_->dt_; }
std::size_t Simulation::particle_count() const { return engine_->particles_.size(); }
std::vector<io::ParticleRecord> Simulation::snapshot() const { return engine_->particles_; }

}  // namespace mpm::core
