// Part of engine.cpp, included there (one translation unit: each CPU variant of the step inlines every
// callee of its unit, common/cpu_variants.hpp): g2p, for one particle and for a stencil run of four
// (stencil_runs.hpp).

namespace mpm::core {

/// Grid-to-particle update (Sulsky et al. 1994, eqs. 21-22; CB-Geo compute_updated_position):
/// FLIP v += dt sum N a, PIC v = sum N v_new, blended (VelocityTransfer::particle_velocity); APIC
/// (Affine) v = sum N v_new and the new B_p (Jiang et al. 2015; affine_matrix_at); x += dt sum N v_new.
/// Flags NaN or runaway velocity (a particle moving more than a cell per step) and particles leaving
/// the mesh region (an error, or removed when locate_particles is false). With `also` StrainIncrements
/// (USL) it also stores the strain increment from the updated grid velocity, read from the same nodes.
/// With RemapMomentum (MUSL) it also maps the updated particle momentum m N v back to the nodes
/// (Sulsky, Zhou & Schreyer 1995, eq. 20), into the chunk's band, in the same pass (APIC: the particle's
/// affine field, MomentumContribution at its old position, where B_p was just formed, with the affine
/// weights p2g formed there). The four particles of a stencil run go together (g2p_run).
template <class Shape, bool Affine>
void Engine::g2p_chunk(std::size_t c, G2pAlso also) {
  double* band = also == G2pAlso::RemapMomentum ? cleared_band(c) : nullptr;
  merge_.open(c, chunk_[c], chunk_[c + 1]);
  for (std::size_t k = chunk_[c]; k < chunk_[c + 1];) {
    if (run_lane_[k] == 0) {
      g2p_run<Shape, Affine>(c, k, also, band);
      k += kRunLanes;
    } else {
      g2p_particle<Shape, Affine>(c, k, also, band);
      ++k;
    }
  }
}

/// g2p_chunk's work for the particle at iteration index k, outside a stencil run (`band`: the chunk's
/// band, MUSL).
template <class Shape, bool Affine>
void Engine::g2p_particle(std::size_t c, std::size_t k, G2pAlso also, double* band) {
  constexpr int W = Shape::kWidth;
  // Bilinear APIC reads C_p = sum v grad w^T (the velocity gradient) as well (velocity_transfer.hpp).
  constexpr bool kBilinearAffine = Affine && std::is_same_v<Shape, LinearShape>;
  const std::uint32_t p = order_[k];
  const StencilWeights<W> w(&weights_[4 * W * k]);  // not in a run: a block of its own
  double dxs[W] = {}, dys[W] = {};                   // APIC: node minus particle, per axis
  if constexpr (Affine)
    for (int a = 0; a < W; ++a) {
      dxs[a] = stencil_offset_[2 * k] + a * grid_.spacing[0];
      dys[a] = stencil_offset_[2 * k + 1] + a * grid_.spacing[1];
    }
  const GridSums sums =
      gather_updated<W, Affine>(updated_.data(), static_cast<std::size_t>(base_[k]), node_row_stride(), w, dxs, dys,
                                also == G2pAlso::StrainIncrements || kBilinearAffine);
  if (also == G2pAlso::StrainIncrements) sums.L.strain_increment(dt_, &dstrain_[3 * k]);
  const double vgx = sums.v[0], vgy = sums.v[1];
  const double vx = Affine ? vgx : transfer_.particle_velocity(cur_.velocity[0][p], vgx, sums.a[0], dt_);
  const double vy = Affine ? vgy : transfer_.particle_velocity(cur_.velocity[1][p], vgy, sums.a[1], dt_);
  nxt_.velocity[0][k] = vx;
  nxt_.velocity[1][k] = vy;
  double B_old[4] = {0, 0, 0, 0};
  if constexpr (Affine) new_affine_matrix<Shape>(k, p, sums, vgx, vgy, also == G2pAlso::RemapMomentum ? B_old : nullptr);
  if (also == G2pAlso::RemapMomentum) {
    const MomentumContribution<Shape, Affine> momentum(cur_.mass[p], vx, vy, Double2{B_old[0], B_old[2]},
                                                       Double2{B_old[1], B_old[3]},
                                                       Affine ? &affine_weights_[2 * W * k] : nullptr, w);
    scatter_momentum(band + local_[k], bands_[c].row_stride(), w, momentum);
  }
  place_particle(c, k, p, vgx, vgy, vx, vy);
}

/// g2p_particle for the four particles of the stencil run at iteration indices k .. k + 3, in the lanes
/// of Double4 (the same operations per lane, so the same bits): the sums from their shared stencil,
/// MUSL's remapped momentum into it at once.
template <class Shape, bool Affine>
void Engine::g2p_run(std::size_t c, std::size_t k, G2pAlso also, double* band) {
  constexpr int W = Shape::kWidth;
  constexpr bool kBilinearAffine = Affine && std::is_same_v<Shape, LinearShape>;
  const StencilWeights4<W> w4(&weights_[4 * W * k]);
  const auto first = static_cast<std::size_t>(base_[k]);
  std::uint32_t p[kRunLanes];
  for (int l = 0; l < kRunLanes; ++l) p[l] = order_[k + l];
  GridSums4 sums;
  if constexpr (Affine) {
    Double4 dxs4[W], dys4[W], ox = splat4(0.0), oy = ox;
    for (int l = 0; l < kRunLanes; ++l) {
      ox[l] = stencil_offset_[2 * (k + l)];
      oy[l] = stencil_offset_[2 * (k + l) + 1];
    }
    for (int a = 0; a < W; ++a) {
      dxs4[a] = ox + a * grid_.spacing[0];
      dys4[a] = oy + a * grid_.spacing[1];
    }
    sums = gather_updated_affine4(updated_.data(), first, node_row_stride(), w4, dxs4, dys4,
                                  also == G2pAlso::StrainIncrements || kBilinearAffine);
  } else {
    sums = gather_updated4(updated_.data(), first, node_row_stride(), w4,
                           also == G2pAlso::StrainIncrements);
  }
  if (also == G2pAlso::StrainIncrements)
    for (int l = 0; l < kRunLanes; ++l) sums.L.lane(l).strain_increment(dt_, &dstrain_[3 * (k + l)]);
  Double4 vx = sums.vx, vy = sums.vy;
  if constexpr (!Affine) {
    Double4 vx_old, vy_old;
    for (int l = 0; l < kRunLanes; ++l) {
      vx_old[l] = cur_.velocity[0][p[l]];
      vy_old[l] = cur_.velocity[1][p[l]];
    }
    vx = transfer_.particle_velocity(vx_old, sums.vx, sums.ax, dt_);
    vy = transfer_.particle_velocity(vy_old, sums.vy, sums.ay, dt_);
  }
  store4(&nxt_.velocity[0][k], vx);
  store4(&nxt_.velocity[1][k], vy);
  alignas(32) double B_old[4][kRunLanes] = {};  // APIC, MUSL: entry e (xx xy yx yy) of lane l's B at x^n
  if constexpr (Affine)
    for (int l = 0; l < kRunLanes; ++l) {
      double b[4];
      new_affine_matrix<Shape>(k + l, p[l], sums.lane(l), sums.vx[l], sums.vy[l],
                               also == G2pAlso::RemapMomentum ? b : nullptr);
      if (also == G2pAlso::RemapMomentum)
        for (int e = 0; e < 4; ++e) B_old[e][l] = b[e];
    }
  if (also == G2pAlso::RemapMomentum) {
    Double4 m;
    for (int l = 0; l < kRunLanes; ++l) m[l] = cur_.mass[p[l]];
    double* band_row = band + local_[k];
    const std::size_t row_stride = bands_[c].row_stride();
    if constexpr (Affine) {
      const Double4 mB[4] = {m * load4(B_old[0]), m * load4(B_old[1]), m * load4(B_old[2]), m * load4(B_old[3])};
      scatter_affine_momentum4(band_row, row_stride, w4,
                               AffineMomentum4<W>(m * vx, m * vy, mB, &affine_weights_[2 * W * k], w4), nullptr);
    } else {
      scatter_momentum4(band_row, row_stride, w4, m * vx, m * vy);
    }
  }
  place_run(c, k, p, sums.vx, sums.vy, vx, vy);
}

/// APIC: the new B_p of the particle at iteration index k (storage index p) into nxt_.affine, from its
/// stencil sums: B = sum N v (x_i - x_p)^T and C = sum v grad w^T (xx xy yx yy), read at x^(n+1) (vg =
/// sum N v_new moves it there; affine_matrix_at); with `at_old` also as read at x^n, for MUSL's remap.
template <class Shape>
void Engine::new_affine_matrix(std::size_t k, std::uint32_t p, const GridSums& sums, double vgx, double vgy,
                               double* at_old) {
  const double B[4] = {sums.b_dx[0], sums.b_dy[0], sums.b_dx[1], sums.b_dy[1]};
  const double C[4] = {sums.L.d_dx[0], sums.L.d_dy[0], sums.L.d_dx[1], sums.L.d_dy[1]};
  const double x0 = cur_.position[0][p], y0 = cur_.position[1][p];
  const double x = x0 + dt_ * vgx, y = y0 + dt_ * vgy;  // place_particle's x^(n+1)
  const int max_i = cells_per_axis_[0] - 1, max_j = cells_per_axis_[1] - 1;
  const auto& origin = grid_.origin;
  const auto& h = grid_.spacing;
  affine_matrix_at(Shape{}, B, C, (x - origin[0]) * inv_h_[0], (y - origin[1]) * inv_h_[1], max_i, max_j, h[0], h[1],
                   &nxt_.affine[4 * k]);
  if (at_old)
    affine_matrix_at(Shape{}, B, C, (x0 - origin[0]) * inv_h_[0], (y0 - origin[1]) * inv_h_[1], max_i, max_j, h[0],
                     h[1], at_old);
}

/// g2p's last part for the particle at iteration index k (storage index p): x += dt sum N v_new and the
/// displacement alike (vg = sum N v_new), the checks (v = the particle's new velocity), its new key
/// and its record for the re-sort.
void Engine::place_particle(std::size_t c, std::size_t k, std::uint32_t p, double vgx, double vgy, double vx,
                            double vy) {
  const double x = cur_.position[0][p] + dt_ * vgx, y = cur_.position[1][p] + dt_ * vgy;
  const double h = smallest_cell_side();
  nxt_.position[0][k] = x;
  nxt_.position[1][k] = y;
  nxt_.displacement[0][k] = cur_.displacement[0][p] + dt_ * vgx;
  nxt_.displacement[1][k] = cur_.displacement[1][p] + dt_ * vgy;
  const double speed = std::sqrt(vx * vx + vy * vy);
  // A uGIMP particle is on the grid while its domain (half-size lp = l h) overlaps the mesh region:
  // it can sit up to lp beyond a fixed boundary, where its stencil still lies in the halo ring (its
  // support reaches the constrained nodes and one moving node: N = l/4 at the boundary, so it can
  // drift past it by a fraction of lp). Linear particles must stay inside the region. The test is
  // false for a NaN coordinate, so with a speed within one cell per step it implies finite values;
  // inside the region itself (most particles) the margin (>= 0) is not needed.
  const auto& lo = grid_.region_min;
  const auto& hi = grid_.region_max;
  const auto within = [&](double mx, double my) {
    return x >= lo[0] - mx && x <= hi[0] + mx && y >= lo[1] - my && y <= hi[1] + my;
  };
  const bool on_grid = within(0.0, 0.0) || within(gimp_margin_ * cur_.half_size[0][p] * grid_.spacing[0],
                                                  gimp_margin_ * cur_.half_size[1][p] * grid_.spacing[1]);
  const auto place_on_grid = [&] {
    nxt_.key[k] = cell_key({x, y});
    merge_.record(c, k, nxt_.key[k] == cur_.key[p] ? OrderMerge::Status::Kept : OrderMerge::Status::Moved);
  };
  if (on_grid && speed * dt_ <= h) {
    place_on_grid();
    return;
  }
  if (!std::isfinite(vx) || !std::isfinite(vy) || !std::isfinite(x) || !std::isfinite(y)) {
    report(c, k, ProblemKind::VelocityNotFinite, cur_.id[p], vx, vy);
  } else if (!(speed * dt_ <= h)) {  // an overflowing speed too
    report(c, k, ProblemKind::RunawayVelocity, cur_.id[p], speed, h / dt_);
  }
  if (!on_grid) {
    nxt_.key[k] = kRemoved;
    merge_.record(c, k, OrderMerge::Status::Removed);
    if (locate_) report(c, k, ProblemKind::LeftTheGrid, cur_.id[p], x, y);
  } else {
    place_on_grid();
  }
}

/// place_particle for the four particles of the stencil run at iteration indices k .. k + 3 (storage
/// indices p[0..3]), in the lanes of Double4 (vg = sum N v_new, v = the new velocities): the same
/// operations lane by lane (lanes.hpp), so the same bits. When one of them is outside the mesh region
/// proper or too fast, all four go through place_particle in order instead (its margins, reports and
/// removal).
void Engine::place_run(std::size_t c, std::size_t k, const std::uint32_t* p, Double4 vgx, Double4 vgy, Double4 vx,
                       Double4 vy) {
  static_assert(kRunLanes == 4, "a stencil run is one Double4");
  Double4 x0, y0, ux0, uy0;
  for (int l = 0; l < kRunLanes; ++l) {
    x0[l] = cur_.position[0][p[l]];
    y0[l] = cur_.position[1][p[l]];
    ux0[l] = cur_.displacement[0][p[l]];
    uy0[l] = cur_.displacement[1][p[l]];
  }
  const Double4 dt = splat4(dt_);
  const Double4 x = x0 + dt * vgx, y = y0 + dt * vgy;
  const Double4 speed = constitutive::sqrt_each(vx * vx + vy * vy);
  const auto& lo = grid_.region_min;
  const auto& hi = grid_.region_max;
  const auto fast = (x >= splat4(lo[0])) & (x <= splat4(hi[0])) & (y >= splat4(lo[1])) & (y <= splat4(hi[1])) &
                    (speed * dt <= splat4(smallest_cell_side()));
  if (!(fast[0] & fast[1] & fast[2] & fast[3]) || !keys_fit_int32_) {
    for (int l = 0; l < kRunLanes; ++l) place_particle(c, k + l, p[l], vgx[l], vgy[l], vx[l], vy[l]);
    return;
  }
  // The destinations first: each store4 (a memcpy) could alias a vector's own pointers.
  double* const to[4] = {&nxt_.position[0][k], &nxt_.position[1][k], &nxt_.displacement[0][k],
                         &nxt_.displacement[1][k]};
  std::int64_t* const key_to = &nxt_.key[k];
  std::int64_t key_was[kRunLanes];
  for (int l = 0; l < kRunLanes; ++l) key_was[l] = cur_.key[p[l]];
  store4(to[0], x);
  store4(to[1], y);
  store4(to[2], ux0 + dt * vgx);
  store4(to[3], uy0 + dt * vgy);
  const Long4 keys = cell_keys({x, y});
  __builtin_memcpy(key_to, &keys, sizeof keys);
  for (int l = 0; l < kRunLanes; ++l)
    merge_.record(c, k + l, keys[l] == key_was[l] ? OrderMerge::Status::Kept : OrderMerge::Status::Moved);
}

/// cell_key of four positions inside the mesh region, in lanes (32-bit keys: keys_fit_int32_).
Long4 Engine::cell_keys(const std::array<Double4, kDim>& x) const {
  const auto clamp = [](Int4 v, int hi) {
    v = v < 0 ? Int4{0, 0, 0, 0} : v;
    return v > hi ? Int4{hi, hi, hi, hi} : v;
  };
  Double4 s[kDim];
  Int4 i[kDim];
  for (int d = 0; d < kDim; ++d) {
    s[d] = (x[d] - splat4(grid_.origin[d])) * splat4(inv_h_[d]);
    i[d] = clamp(__builtin_convertvector(s[d], Int4), cells_per_axis_[d] - 1);  // truncation, as static_cast<int>
  }
  Int4 cell = i[kDim - 1];  // axis 0 fastest, as cell_key
  for (int d = kDim - 2; d >= 0; --d) cell = cell * cells_per_axis_[d] + i[d];
  Int4 key = kKeysPerCell * cell;
  if (grid_.cell_type == CellType::Gimp16) {  // the quadrant, GimpShape::nearest_node(s) > i
    const Double4 half = splat4(0.5);
    for (int d = 0; d < kDim; ++d) key += (__builtin_convertvector(s[d] + half, Int4) > i[d]) & (1 << d);
  }
  return __builtin_convertvector(key, Long4);
}

}  // namespace mpm::core
