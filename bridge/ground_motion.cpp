#include "bridge/ground_motion.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "common/input_error.hpp"
#include "common/number_text.hpp"

namespace bridge {

double GroundMotion::at(double t) const {
  if (values.empty() || t < 0) return 0.0;
  const double s = t / dt;
  const auto k = static_cast<std::size_t>(std::floor(s));
  if (k + 1 >= values.size()) return k + 1 == values.size() && s == static_cast<double>(k) ? factor * values[k] : 0.0;
  const double w = s - static_cast<double>(k);
  return factor * (values[k] + w * (values[k + 1] - values[k]));
}

GroundMotion read_ground_motion(const std::filesystem::path& file, double dt, double factor, int dof,
                                const std::string& option) {
  if (!(dt > 0) || !std::isfinite(dt))
    throw common::InputError(option + "-dt", "expected a time step > 0, got " + common::number_text(dt, 10));
  if (!std::isfinite(factor)) throw common::InputError(option + "-factor", "expected a finite number");
  if (dof != 1 && dof != 2) throw common::InputError(option + "-dir", "expected 1 (x) or 2 (y), got " + std::to_string(dof));
  std::ifstream in(file);
  if (!in) throw common::InputError(file.string(), "cannot open the ground-motion file (" + option + ")");
  GroundMotion m{dof, dt, factor, {}};
  std::string line;
  for (long line_no = 1; std::getline(in, line); ++line_no) {
    std::istringstream words(line);
    for (std::string w; words >> w;) {
      std::size_t used = 0;
      double v = 0;
      try {
        v = std::stod(w, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != w.size() || !std::isfinite(v))
        throw common::InputError(file.string() + ":" + std::to_string(line_no), "expected a number, got '" + w + "'");
      m.values.push_back(v);
    }
  }
  if (m.values.empty()) throw common::InputError(file.string(), "the ground-motion file has no values (" + option + ")");
  return m;
}

MotionTable motion_after(const GroundMotion& motion, double t_transfer, double t0_mpm) {
  MotionTable out;
  const double t_end = static_cast<double>(motion.values.size() - 1) * motion.dt;
  if (t_transfer >= t_end) return out;
  const auto shifted = [&](double t) { return t - t_transfer + t0_mpm; };
  out.t.push_back(t0_mpm);
  out.a.push_back(motion.at(std::max(t_transfer, 0.0)));
  for (std::size_t k = 0; k < motion.values.size(); ++k) {
    const double t = static_cast<double>(k) * motion.dt;
    if (t <= t_transfer) continue;
    out.t.push_back(shifted(t));
    out.a.push_back(motion.factor * motion.values[k]);
  }
  out.t.push_back(shifted(t_end) + 1e-6 * motion.dt);  // OpenSees' Path drops to 0 past its end (no -useLast)
  out.a.push_back(0.0);
  return out;
}

}  // namespace bridge
