// Verification of the FEM -> MPM mapping (the paper, "Hybrid FEM-MPM", Figures 2-3) against exact fields:
// - constant stress is reproduced exactly by both recoveries (the patch test, Irons & Razzaque 1972;
//   Zienkiewicz, Taylor & Zhu 2013, sec. 9.3);
// - a linear stress field: inverse-distance weighting (IDW) has an O(h) error that shrinks with refinement;
//   superconvergent patch recovery (SPR) reproduces it exactly (Zienkiewicz & Zhu 1992, IJNME 33, p. 1336:
//   the patch polynomial contains the field);
// - a quadratic field: SPR's error is below IDW's (Zienkiewicz & Zhu 1992, sec. 5);
// - mass = sum rho x reference area exactly; particle volumes sum to the current area exactly
//   (Gauss-Legendre integrates the linear det J exactly, Abramowitz & Stegun 1964, 25.4.29);
// - rigid-body velocity fields (linear in x) are interpolated exactly, and total momentum equals the
//   FEM's lumped nodal momentum exactly for any nodal velocities (row-sum lumping = the same integral).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "bridge/particle_mapping.hpp"
#include "bridge/stress_recovery.hpp"
#include "bridge/transfer_report.hpp"
#include "mesh_fixture.hpp"
#include "support/tolerance.hpp"

namespace {

using bridge::Recovery;
using bridge::Stress6;
using bridge::Vec2;
using bridge_test::MeshSpec;

Stress6 linear_field(const Vec2& x) {
  return {-1e5 + 3e4 * x.x() - 2e4 * x.y(), -2e5 + 1e4 * x.x() + 5e4 * x.y(), -9e4 + 2e4 * x.y(),
          1e4 - 7e3 * x.x() + 4e3 * x.y(), 0, 0};
}

Stress6 quadratic_field(const Vec2& x) {
  return {-1e5 + 4e4 * x.x() * x.x() - 2e4 * x.x() * x.y(), -2e5 + 3e4 * x.y() * x.y(), -9e4 + 1e4 * x.x() * x.y(),
          1e4 * x.x() * x.x() - 2e4 * x.y() * x.y(), 0, 0};
}

/// RMS over particles of |sigma_p - exact(x_p)|, relative to the RMS of |exact|.
double particle_error(const bridge::TransferState& st, Recovery method, Stress6 (*exact)(const Vec2&)) {
  const auto nodal = bridge::recover_nodal_stress(st, method);
  bridge::MappingOptions o;
  const auto particles = bridge::generate_particles(st, nodal, o);
  double err = 0, ref = 0;
  for (const auto& p : particles) {
    const Stress6 e = exact(Vec2(p.coord_x, p.coord_y));
    const double mapped[6] = {p.stress_xx, p.stress_yy, p.stress_zz, p.tau_xy, p.tau_yz, p.tau_xz};
    for (int k = 0; k < 6; ++k) {
      err += (mapped[k] - e[k]) * (mapped[k] - e[k]);
      ref += e[k] * e[k];
    }
  }
  return std::sqrt(err / ref);
}

TEST(BridgeMapping, ConstantStressIsExactThroughTheWholeMapping) {
  const Stress6 c{-1.2e5, -3.4e5, -1.1e5, 2.5e4, 0, 0};
  for (int gp : {1, 4})
    for (Recovery method : {Recovery::InverseDistance, Recovery::PatchRecovery}) {
      MeshSpec s;
      s.gauss_points = gp;
      const auto st = bridge_test::make_state(s, [&](const Vec2&) { return c; });
      const auto nodal = bridge::recover_nodal_stress(st, method);
      const auto particles = bridge::generate_particles(st, nodal, {});
      ASSERT_EQ(particles.size(), 64u * 16u);
      for (const auto& p : particles) {
        ASSERT_CLOSE(p.stress_xx, c[0], 1e-9, 1e-13);
        ASSERT_CLOSE(p.stress_yy, c[1], 1e-9, 1e-13);
        ASSERT_CLOSE(p.stress_zz, c[2], 1e-9, 1e-13);
        ASSERT_CLOSE(p.tau_xy, c[3], 1e-9, 1e-13);
      }
      const auto rep = bridge::make_report(st, nodal, particles);
      EXPECT_LT(rep.stress_rms_relative, 1e-13);
    }
}

TEST(BridgeMapping, LinearFieldIdwErrorShrinksWithRefinementSprExact) {
  for (int gp : {1, 4}) {
    double previous = 1;
    for (int n : {8, 16, 32}) {
      MeshSpec s;
      s.nx = s.ny = n;
      s.gauss_points = gp;
      const auto st = bridge_test::make_state(s, linear_field);
      const double idw = particle_error(st, Recovery::InverseDistance, linear_field);
      const double spr = particle_error(st, Recovery::PatchRecovery, linear_field);
      // IDW: first order; bounded by the field's variation over one element and halving with h.
      EXPECT_LT(idw, 0.1 * 8.0 / n) << "gp " << gp << ", n " << n;
      if (n > 8) {
        EXPECT_LT(idw, 0.7 * previous) << "gp " << gp << ", n " << n;
      }
      previous = idw;
      EXPECT_LT(spr, 1e-12) << "gp " << gp << ", n " << n;
    }
  }
}

TEST(BridgeMapping, PatchRecoveryBeatsInverseDistanceOnQuadraticField) {
  for (int gp : {1, 4}) {
    double spr_previous = 1;
    for (int n : {8, 16, 32}) {
      MeshSpec s;
      s.nx = s.ny = n;
      s.gauss_points = gp;
      const auto st = bridge_test::make_state(s, quadratic_field);
      const double idw = particle_error(st, Recovery::InverseDistance, quadratic_field);
      const double spr = particle_error(st, Recovery::PatchRecovery, quadratic_field);
      std::printf("quadratic field, %d Gauss point(s), %2d x %2d elements: particle stress RMS error IDW %.3e, SPR %.3e\n",
                  gp, n, n, idw, spr);
      EXPECT_LT(spr, 0.5 * idw) << "gp " << gp << ", n " << n;
      if (n > 8) {
        EXPECT_LT(spr, 0.5 * spr_previous);
      }
      spr_previous = spr;
    }
  }
}

TEST(BridgeMapping, MassIsConservedExactlyAndVolumesSumToCurrentArea) {
  for (auto split : {bridge::VolumeSplit::Jacobian, bridge::VolumeSplit::Area})
    for (int ppd : {1, 2, 3, 4, 5}) {
      MeshSpec s;
      const auto st = bridge_test::make_state(s, linear_field);
      bridge::MappingOptions o;
      o.particles_per_direction = ppd;
      o.volume_split = split;
      const auto particles = bridge::generate_particles(st, bridge::recover_nodal_stress(st, Recovery::InverseDistance), o);
      double mass_ref = 0, area_cur = 0, mass = 0, volume = 0;
      for (const auto& e : st.elements) {
        mass_ref += e.density * bridge::quad_area(st.reference_nodes(e));
        area_cur += bridge::quad_area(st.current_nodes(e));
      }
      for (const auto& p : particles) {
        mass += p.mass;
        volume += p.volume;
        ASSERT_GT(p.volume, 0);
        ASSERT_CLOSE(p.nsize_x, 2.0 / ppd, 0, 1e-15);
        ASSERT_EQ(p.cell_id, -1);
        ASSERT_EQ(p.status, 1);
      }
      EXPECT_CLOSE(mass, mass_ref, 0, 1e-13);
      EXPECT_CLOSE(volume, area_cur, 0, 1e-13);
      // Per element too.
      const std::size_t per = static_cast<std::size_t>(ppd * ppd);
      for (std::size_t e = 0; e < st.elements.size(); ++e) {
        double me = 0;
        for (std::size_t q = 0; q < per; ++q) me += particles[e * per + q].mass;
        ASSERT_CLOSE(me, st.elements[e].density * bridge::quad_area(st.reference_nodes(st.elements[e])), 0, 1e-13);
      }
    }
}

TEST(BridgeMapping, RigidBodyVelocityIsExactAndMomentumIsConserved) {
  MeshSpec s;
  auto st = bridge_test::make_state(s, linear_field);
  const Vec2 v0(1.5, -0.7), centre(1.0, 0.5);
  const double omega = 0.3;
  for (std::size_t i = 0; i < st.reference.size(); ++i) {
    const Vec2 r = st.current(static_cast<int>(i)) - centre;
    st.velocity[i] = v0 + omega * Vec2(-r.y(), r.x());
  }
  const auto nodal = bridge::recover_nodal_stress(st, Recovery::InverseDistance);
  const auto particles = bridge::generate_particles(st, nodal, {});
  for (const auto& p : particles) {
    const Vec2 r = Vec2(p.coord_x, p.coord_y) - centre;
    const Vec2 v = v0 + omega * Vec2(-r.y(), r.x());
    ASSERT_CLOSE(p.velocity_x, v.x(), 1e-13, 1e-13);
    ASSERT_CLOSE(p.velocity_y, v.y(), 1e-13, 1e-13);
  }
  // Momentum: particles = FEM lumped nodes, exactly, for any nodal velocity field.
  for (std::size_t i = 0; i < st.velocity.size(); ++i) st.velocity[i] = Vec2(std::sin(3.0 * i), std::cos(7.0 * i));
  const auto p2 = bridge::generate_particles(st, nodal, {});
  const auto rep = bridge::make_report(st, nodal, p2);
  EXPECT_CLOSE(rep.particles.momentum.x(), rep.fem.momentum.x(), 1e-9, 1e-12);
  EXPECT_CLOSE(rep.particles.momentum.y(), rep.fem.momentum.y(), 1e-9, 1e-12);
  EXPECT_CLOSE(rep.particles.mass, rep.fem.mass, 0, 1e-13);
}

// A mesh too small for any patch fit (one one-point element): SPR falls back to the element's value,
// which is also what IDW gives; the constant field stays exact.
TEST(BridgeMapping, SingleElementPatchFallsBackToItsValue) {
  MeshSpec s;
  s.nx = s.ny = 1;
  const Stress6 c{-5e4, -7e4, -3e4, 1e3, 0, 0};
  const auto st = bridge_test::make_state(s, [&](const Vec2&) { return c; });
  for (Recovery method : {Recovery::InverseDistance, Recovery::PatchRecovery}) {
    const auto nodal = bridge::recover_nodal_stress(st, method);
    ASSERT_EQ(nodal.size(), 4u);
    for (const auto& n : nodal)
      for (int k = 0; k < 6; ++k) EXPECT_CLOSE(n[k], c[k], 1e-9, 1e-14);
  }
}

// Deterministic to the byte, padding included (DESIGN.md: same input -> bit-identical output).
TEST(BridgeMapping, RecordsAreByteReproducible) {
  MeshSpec s;
  const auto st = bridge_test::make_state(s, quadratic_field);
  const auto nodal = bridge::recover_nodal_stress(st, Recovery::PatchRecovery);
  const auto a = bridge::generate_particles(st, nodal, {});
  const auto b = bridge::generate_particles(st, nodal, {});
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(mpm::ParticleRecord)), 0);
  // The padding after `status` (bytes 241-243) and `nstate_vars` (252-255) is zero.
  const auto* bytes = reinterpret_cast<const unsigned char*>(a.data());
  for (int k : {241, 242, 243, 252, 253, 254, 255}) EXPECT_EQ(bytes[k], 0) << "byte " << k;
}

TEST(BridgeMapping, InvertedElementsAreNamed) {
  MeshSpec s;
  s.nx = s.ny = 3;
  s.deform = false;
  auto st = bridge_test::make_state(s, linear_field);
  // Push node (2,2) up and right past the far corner of element 9 (whose lower-left corner it is):
  // element 9 folds over; element 5 (upper-right corner) only stretches.
  st.displacement[2 * 4 + 2] = Vec2(3.0, 3.0);
  const auto bad = bridge::inverted_elements(st);
  EXPECT_NE(std::find(bad.begin(), bad.end(), 9L), bad.end());
  EXPECT_EQ(std::find(bad.begin(), bad.end(), 5L), bad.end());
  s.deform = true;
  EXPECT_TRUE(bridge::inverted_elements(bridge_test::make_state(s, linear_field)).empty());
}

}  // namespace
