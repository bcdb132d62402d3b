#include "bridge/drucker_prager_match.hpp"

#include <cmath>
#include <numbers>

namespace bridge {
namespace {

/// Friction (or dilation) angle in degrees of a cone slope alpha = rho / sqrt(2); nullopt when 12 alpha^2 >= 1.
std::optional<double> angle_deg(double rho) {
  const double alpha = rho / std::sqrt(2.0);
  const double root = 1 - 12 * alpha * alpha;
  if (!(root > 0)) return std::nullopt;
  return std::atan(3 * alpha / std::sqrt(root)) * 180 / std::numbers::pi;
}

}  // namespace

std::optional<MohrCoulombStrength> plane_strain_mohr_coulomb(double sigma_y, double rho, double rho_bar) {
  const auto phi = angle_deg(rho), psi = angle_deg(rho_bar);
  if (!phi || !psi) return std::nullopt;
  const double alpha = rho / std::sqrt(2.0);
  const double k = sigma_y / std::sqrt(3.0);
  return MohrCoulombStrength{*phi, k / std::sqrt(1 - 12 * alpha * alpha), *psi};
}

}  // namespace bridge
