#include "mpm/core/stress_remedy.hpp"

#include "common/input_error.hpp"

namespace mpm::core {

StressSmoothing parse_stress_smoothing(const std::string& name) {
  if (name == "none" || name.empty()) return StressSmoothing::None;
  if (name == "cell_volumetric") return StressSmoothing::CellVolumetric;
  if (name == "nodal_strain") return StressSmoothing::NodalStrain;
  if (name == "nodal_volumetric") return StressSmoothing::NodalVolumetric;
  if (name == "cell_strain") return StressSmoothing::CellStrain;
  throw common::InputError("analysis.stress_smoothing",
                           "expected \"none\", \"cell_volumetric\", \"cell_strain\", \"nodal_strain\" or "
                           "\"nodal_volumetric\", got \"" + name + "\"");
}

bool is_cell_remedy(StressSmoothing s) {
  return s == StressSmoothing::CellVolumetric || s == StressSmoothing::CellStrain;
}

NodalProjection nodal_projection(StressSmoothing s) {
  if (s == StressSmoothing::NodalStrain) return {3, false};
  if (s == StressSmoothing::NodalVolumetric) return {1, true};
  return {0, false};
}

void nodal_values(StressSmoothing s, const double* de, double* values) {
  if (s == StressSmoothing::NodalStrain) {
    for (int f = 0; f < 3; ++f) values[f] = de[f];
  } else if (s == StressSmoothing::NodalVolumetric) {
    values[0] = de[0] + de[1];
  }
}

void apply_nodal_values(StressSmoothing s, const double* smoothed, double* de) {
  if (s == StressSmoothing::NodalStrain) {
    for (int f = 0; f < 3; ++f) de[f] = smoothed[f];
  } else if (s == StressSmoothing::NodalVolumetric) {
    set_volumetric(de, 1, smoothed[0]);
  }
}

void set_volumetric(double* de, std::size_t n, double mean_v) {
  for (std::size_t i = 0; i < n; ++i) {
    double* e = de + 3 * i;
    const double shift = 0.5 * (mean_v - (e[0] + e[1]));
    e[0] += shift;
    e[1] += shift;
  }
}

void blend_to_cell_mean(double* de, std::size_t n, const double mean[3], double keep) {
  for (std::size_t i = 0; i < n; ++i) {
    double* e = de + 3 * i;
    // The deviation from the mean, less its volumetric part (plane strain: the in-plane trace).
    const double dxx = e[0] - mean[0], dyy = e[1] - mean[1], dgxy = e[2] - mean[2];
    const double half_dv = 0.5 * (dxx + dyy);
    e[0] = mean[0] + keep * (dxx - half_dv);
    e[1] = mean[1] + keep * (dyy - half_dv);
    e[2] = mean[2] + keep * dgxy;
  }
}

}  // namespace mpm::core
