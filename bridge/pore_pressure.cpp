#include "bridge/pore_pressure.hpp"

#include <algorithm>
#include <cmath>

#include "bridge/stress_recovery.hpp"
#include "common/input_error.hpp"
#include "common/number_text.hpp"

namespace bridge {
namespace {

std::string tag_text(const std::vector<long>& tags) {
  if (tags.size() <= 6) {
    std::string s;
    for (std::size_t i = 0; i < tags.size(); ++i) s += (i ? " " : "") + std::to_string(tags[i]);
    return s;
  }
  return std::to_string(tags.front()) + " .. " + std::to_string(tags.back()) + " (" + std::to_string(tags.size()) + ")";
}

/// Scalar Gauss-point values recovered to the nodes as the stress is (--recovery), one per node.
std::vector<double> recover_scalar(const TransferState& state, const std::vector<double>& gauss, Recovery method) {
  TransferState copy;  // the geometry and elements of `state`, the scalar in the first stress component
  copy.reference = state.reference;
  copy.displacement = state.displacement;
  copy.elements = state.elements;
  copy.gauss_offset = state.gauss_offset;
  copy.gauss_stress.resize(gauss.size());
  for (std::size_t g = 0; g < gauss.size(); ++g) copy.gauss_stress[g] = {gauss[g], 0, 0, 0, 0, 0};
  const auto nodal = recover_nodal_stress(copy, method);
  std::vector<double> out(nodal.size());
  for (std::size_t i = 0; i < nodal.size(); ++i) out[i] = nodal[i][0];
  return out;
}

}  // namespace

std::vector<long> pore_pressure_layout(const FemModel& model, const PorePressureOptions& options) {
  std::vector<long> tags;
  if (options.nodes) {
    tags = *options.nodes;
    for (long tag : tags) {
      const int i = model.node_index(tag);
      if (i < 0) throw common::InputError("--pp-nodes", "node " + std::to_string(tag) + " is not in " + model.source.string());
      if (model.nodes[static_cast<std::size_t>(i)].ndf < 3)
        throw common::InputError("--pp-nodes", "node " + std::to_string(tag) + " has " +
                                                   std::to_string(model.nodes[static_cast<std::size_t>(i)].ndf) +
                                                   " dofs in " + model.source.string() + ": no pore pressure (dof 3)");
    }
    return tags;
  }
  for (const auto& [tag, index] : model.node_by_tag)
    if (model.nodes[static_cast<std::size_t>(index)].ndf >= 3) tags.push_back(tag);
  if (tags.empty())
    throw common::InputError(model.source.string(), "--pore-pressure: the model has no 3-dof (u-p) node (\"ndf\": 3); "
                                                    "OpenSees 3.8 prints it for every node: was the model built with "
                                                    "-ndf 3?");
  return tags;
}

void read_nodal_pore_pressure(const FemModel& model, const PorePressureOptions& options, const RecorderFile& disp,
                              const TransferRow& transfer, const TransferRow& reference, double factor,
                              TransferState& state, std::vector<std::string>& notes) {
  const std::vector<long> tags = pore_pressure_layout(model, options);
  const RecorderFile file(options.file);
  const std::size_t width = file.data_width();
  if (width != tags.size()) {
    std::string detected;
    if (width + 1 == tags.size()) detected = "; the file seems to have no time column: record with -time";
    else if (width == 2 * tags.size() || width == 3 * tags.size())
      detected = "; that is " + std::to_string(width / tags.size()) + " values per node: record the pore pressure alone, -dof 3 vel";
    throw common::InputError(file.where(file.rows().size() - 1),
                             std::to_string(width) + " values after the time column, but the layout has " +
                                 std::to_string(tags.size()) + " nodes (" +
                                 (options.nodes ? "--pp-nodes " + tag_text(tags)
                                                : "every 3-dof node in tag order, " + tag_text(tags)) +
                                 ") x 1 value (-dof 3 vel); give the recorder's node order with --pp-nodes" + detected);
  }
  const auto at = [&](const TransferRow& row) {
    const auto v = file.values(matching_row(file, disp, row), factor);
    std::vector<double> nodal(model.nodes.size(), 0.0);
    for (std::size_t k = 0; k < tags.size(); ++k) nodal[static_cast<std::size_t>(model.node_index(tags[k]))] = v[k];
    return nodal;
  };
  state.pore_pressure = at(transfer);
  state.reference_pore_pressure = at(reference);
  // Every node of a u-p element must have its pore pressure recorded.
  std::vector<char> recorded(model.nodes.size(), 0);
  for (long tag : tags) recorded[static_cast<std::size_t>(model.node_index(tag))] = 1;
  for (const auto& e : model.elements)
    if (e.pore_pressure)
      for (int a = 0; a < node_count(e.kind); ++a)
        if (!recorded[static_cast<std::size_t>(e.nodes[a])])
          throw common::InputError(options.file.string(), "no column for node " + std::to_string(e.node_tags[a]) +
                                                              ", a pore-pressure node of u-p element " +
                                                              std::to_string(e.tag) + "; record every u-p node");
  notes.push_back(options.file.string() + ": pore pressure of " + std::to_string(tags.size()) + " nodes (dof 3, " +
                  (options.nodes ? "--pp-nodes" : "every 3-dof node in tag order") + ")");
}

std::vector<double> equivalent_shear_strain(std::span<const double> now, std::span<const double> before, int components) {
  const std::size_t c = static_cast<std::size_t>(components);
  std::vector<double> out(now.size() / c);
  for (std::size_t g = 0; g < out.size(); ++g) {
    const double* a = &now[g * c];
    const double* b = &before[g * c];
    const double exx = a[0] - b[0], eyy = a[1] - b[1];
    const double ezz = c == 6 ? a[2] - b[2] : 0.0;
    const double gxy = c == 6 ? a[3] - b[3] : a[2] - b[2];
    const double gyz = c == 6 ? a[4] - b[4] : 0.0, gxz = c == 6 ? a[5] - b[5] : 0.0;
    const double mean = (exx + eyy + ezz) / 3.0;
    const double dxx = exx - mean, dyy = eyy - mean, dzz = ezz - mean;
    // e:e with tensor shear strains gamma / 2
    const double ee = dxx * dxx + dyy * dyy + dzz * dzz + 0.5 * (gxy * gxy + gyz * gyz + gxz * gxz);
    out[g] = std::sqrt(2.0 / 3.0 * ee);
  }
  return out;
}

ParticlePorePressure particle_pore_pressure(const TransferState& state, const MappingOptions& options) {
  const std::size_t gauss = state.gauss_stress.size();
  std::vector<double> sigma_v0(gauss);
  for (std::size_t g = 0; g < gauss; ++g) sigma_v0[g] = -state.reference_gauss_stress[g][1];
  const std::vector<double> nodal_sv0 = recover_scalar(state, sigma_v0, options.recovery);
  const bool strained = !state.gauss_shear_strain.empty();
  const std::vector<double> nodal_strain =
      strained ? recover_scalar(state, state.gauss_shear_strain, options.recovery) : std::vector<double>{};

  const int n = options.particles_per_direction;
  const std::size_t per_element = static_cast<std::size_t>(n * n);
  const std::vector<ParticlePoint> points = particle_points(n);
  const std::vector<std::size_t> slot = particle_slots(state);
  ParticlePorePressure out;
  out.rows.resize(state.elements.size() * per_element);
  if (strained) out.shear_strain.resize(out.rows.size());
  for (std::size_t e = 0; e < state.elements.size(); ++e) {
    const TransferElement& el = state.elements[e];
    const std::size_t first = slot[e] * per_element;
    for (std::size_t q = 0; q < per_element; ++q) {
      const auto& N = points[q].shape;
      double p = 0, p0 = 0, sv0 = 0, pd = 0;
      for (int a = 0; a < 4; ++a) {
        const auto node = static_cast<std::size_t>(el.nodes[a]);
        p += N[a] * state.pore_pressure[node];
        p0 += N[a] * state.reference_pore_pressure[node];
        sv0 += N[a] * nodal_sv0[node];
        if (strained) pd += N[a] * nodal_strain[node];
      }
      double ru = 0;
      if (sv0 > 0) ru = (p - p0) / sv0;
      else ++out.no_reference;
      out.rows[first + q] = {p, sv0, ru};
      if (strained) out.shear_strain[first + q] = std::max(pd, 0.0);
    }
  }
  return out;
}

void apply_total_stress(std::span<mpm::ParticleRecord> particles, std::span<const mpm::PorePressureRecord> rows) {
  for (std::size_t k = 0; k < particles.size(); ++k) {
    mpm::ParticleRecord& r = particles[k];
    const double p = rows[k].pressure;
    r.stress_xx -= p;
    r.stress_yy -= p;
    r.stress_zz -= p;
    if (r.nstate_vars == 7) r.svars[3] = std::sqrt(3.0) * ((r.stress_xx + r.stress_yy + r.stress_zz) / 3.0);
  }
}

}  // namespace bridge
