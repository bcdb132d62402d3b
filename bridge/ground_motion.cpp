#include "bridge/ground_motion.hpp"

#include <cmath>

#include "common/input_error.hpp"
#include "common/number_file.hpp"
#include "common/number_text.hpp"

namespace bridge {

GroundMotion read_ground_motion(const std::filesystem::path& file, double dt, double factor, int dof,
                                const std::string& option) {
  if (!(dt > 0) || !std::isfinite(dt))
    throw common::InputError(option + "-dt", "expected a time step > 0, got " + common::number_text(dt, 10));
  if (!std::isfinite(factor)) throw common::InputError(option + "-factor", "expected a finite number");
  if (dof != 1 && dof != 2) throw common::InputError(option + "-dir", "expected 1 (x) or 2 (y), got " + std::to_string(dof));
  std::vector<double> values = common::read_number_file(file);
  if (values.empty()) throw common::InputError(file.string(), "the ground-motion file has no values (" + option + ")");
  return GroundMotion(dof, dt, factor, std::move(values));
}

MotionTable motion_after(const GroundMotion& motion, double t_transfer, double t0_mpm) {
  MotionTable out;
  const fem::domain::PathSeries& r = motion.record;
  const double t_end = r.end_time();
  if (t_transfer >= t_end) return out;
  const auto shifted = [&](double t) { return t - t_transfer + t0_mpm; };
  out.t.push_back(t0_mpm);
  out.a.push_back(motion.at(std::max(t_transfer, 0.0)));
  for (std::size_t k = 0; k < r.values().size(); ++k) {
    const double t = static_cast<double>(k) * r.dt();
    if (t <= t_transfer) continue;
    out.t.push_back(shifted(t));
    out.a.push_back(r.cfactor() * r.values()[k]);
  }
  out.t.push_back(shifted(t_end) + 1e-6 * r.dt());  // OpenSees' Path is 0 from its last sample on (no -useLast)
  out.a.push_back(0.0);
  return out;
}

}  // namespace bridge
