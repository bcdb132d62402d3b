#pragma once
// The Mohr-Coulomb soil of the MPM material tests and benchmark: softening from phi 30 / psi 5 deg, c 1000 Pa
// to 20 / 0 deg, c 100 Pa between plastic deviatoric strains 0.01 and 0.05, tension cutoff 50 Pa.
#include <cmath>

#include "mpm/problem/deck.hpp"

namespace mpm_test {

inline mpm::MaterialSpec softening_soil(mpm::MaterialType type = mpm::MaterialType::MohrCoulomb2D) {
  mpm::MaterialSpec s;
  s.type = type;
  s.density = 2000;
  s.youngs_modulus = 1e7;
  s.poisson_ratio = 0.3;
  const double deg = std::acos(-1.0) / 180;
  s.friction = 30 * deg;
  s.dilation = 5 * deg;
  s.cohesion = 1000;
  s.residual_friction = 20 * deg;
  s.residual_dilation = 0;
  s.residual_cohesion = 100;
  s.peak_pdstrain = 0.01;
  s.residual_pdstrain = 0.05;
  s.tension_cutoff = 50;
  s.softening = true;
  return s;
}

}  // namespace mpm_test
