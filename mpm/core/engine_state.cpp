// What the Engine hands out between steps: a step's first problem as an error, and the particles' state for
// output and resume (CB-Geo records sorted by id, the APIC matrices, the lagged friction memory).
#include <algorithm>
#include <sstream>

#include "common/input_error.hpp"
#include "mpm/core/engine.hpp"

namespace mpm::core {

void Engine::throw_first_error() const {
  const Problem* first = nullptr;
  for (const auto& p : problems_)
    if (p.kind != ProblemKind::None && (first == nullptr || p.k < first->k)) first = &p;
  if (first == nullptr) return;
  std::ostringstream os;
  os.precision(10);
  os << "step " << step_index_ << ": particle " << first->id;
  switch (first->kind) {
    case ProblemKind::VelocityNotFinite: os << " velocity is not finite (" << first->a << ", " << first->b << ")"; break;
    case ProblemKind::RunawayVelocity: os << " velocity runaway: speed " << first->a << " m/s exceeds one cell per step (" << first->b << " m/s)"; break;
    case ProblemKind::LeftTheGrid: os << " left the grid at (" << first->a << ", " << first->b << ")"; break;
    case ProblemKind::StressNotFinite:
    case ProblemKind::None: os << " stress is not finite (sxx " << first->a << ", syy " << first->b << ")"; break;
  }
  throw common::NumericalError(os.str());
}

std::vector<std::uint32_t> Engine::live_by_id() const {
  std::vector<std::uint32_t> by_id(order_.begin(), order_.end());
  std::sort(by_id.begin(), by_id.end(), [&](std::uint32_t a, std::uint32_t b) { return cur_.id[a] < cur_.id[b]; });
  return by_id;
}

std::vector<std::array<double, 4>> Engine::affine_snapshot() const {
  if (!transfer_.affine()) return {};
  const std::vector<std::uint32_t> by_id = live_by_id();
  std::vector<std::array<double, 4>> out(by_id.size());
  for (std::size_t k = 0; k < by_id.size(); ++k) std::copy_n(&cur_.affine[4 * by_id[k]], 4, out[k].data());
  return out;
}

std::optional<std::vector<FrictionMemoryRecord>> Engine::friction_memory_snapshot() const {
  if (!lagged_friction_) return std::nullopt;
  std::vector<FrictionMemoryRecord> out;
  for (std::size_t n = 0; n < nodes_; ++n)
    if (const std::int32_t c = constraint_of_[n]; c >= 0)
      if (const NormalMemory& m = normal_memory_[static_cast<std::size_t>(c)]; m.force >= 0.0)
        out.push_back({static_cast<std::int64_t>(n), m.force, m.mass});
  return out;
}

void Engine::restore_friction_memory(const std::vector<FrictionMemoryRecord>& memory) {
  for (std::size_t k = 0; k < memory.size(); ++k) {
    const FrictionMemoryRecord& r = memory[k];
    const std::string where = "friction_memory[" + std::to_string(k) + "]";
    const std::int32_t c = r.node >= 0 && static_cast<std::size_t>(r.node) < nodes_ ? constraint_of_[static_cast<std::size_t>(r.node)] : -1;
    if (c < 0 || !constraints_[static_cast<std::size_t>(c)].lag.active())
      throw common::InputError(where, "node " + std::to_string(r.node) + " has no friction constraint with a normal_lag");
    if (!(r.force >= 0.0 && std::isfinite(r.force)) || !(r.mass > 0.0 && std::isfinite(r.mass)))
      throw common::InputError(where, "expected a finite force >= 0 and mass > 0");
    normal_memory_[static_cast<std::size_t>(c)] = NormalMemory{r.force, r.mass};
  }
}

std::vector<ParticleRecord> Engine::snapshot() const {
  std::vector<ParticleRecord> out;
  out.reserve(order_.size());
  for (std::uint32_t p : live_by_id()) {  // by id: the indices sorted, not the records
    ParticleRecord r{};
    const Material& mat = materials_[cur_.material[p]];
    r.id = cur_.id[p];
    r.mass = cur_.mass[p];
    r.volume = cur_.volume[p];
    r.coord_x = cur_.position[0][p];
    r.coord_y = cur_.position[1][p];
    r.displacement_x = cur_.displacement[0][p];
    r.displacement_y = cur_.displacement[1][p];
    r.nsize_x = 4.0 * cur_.half_size[0][p];
    r.nsize_y = 4.0 * cur_.half_size[1][p];
    r.velocity_x = cur_.velocity[0][p];
    r.velocity_y = cur_.velocity[1][p];
    r.stress_xx = cur_.stress[4 * p];
    r.stress_yy = cur_.stress[4 * p + 1];
    r.stress_zz = cur_.stress[4 * p + 2];
    r.tau_xy = cur_.stress[4 * p + 3];
    r.strain_xx = cur_.exx[p];
    r.strain_yy = cur_.eyy[p];
    r.gamma_xy = cur_.gxy[p];
    r.epsilon_v = cur_.epsv[p];
    r.cell_id = -1;
    r.status = 1;
    r.material_id = mat.id;
    r.nstate_vars = static_cast<std::uint32_t>(mat.state_count);
    for (std::size_t i = 0; i < mat.state_count; ++i) r.svars[i] = cur_.svars[p * kStateVariables + i];
    if (mat.type == MaterialType::MohrCoulomb2D) {
      const double s[4] = {r.stress_xx, r.stress_yy, r.stress_zz, r.tau_xy};
      MohrCoulomb::set_invariants(s, r.svars);
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace mpm::core
