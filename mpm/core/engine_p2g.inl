// Part of engine.cpp, included there (one translation unit: each CPU variant of the step inlines every
// callee of its unit, common/cpu_variants.hpp): p2g's shape functions and scatter, for one particle and
// for a stencil run of four (stencil_runs.hpp).

namespace mpm::core {

/// p2g of the particle at iteration index k.
template <class Shape, bool Affine>
void Engine::scatter_particle(std::size_t k, double* g, std::size_t row_stride, bool mass_momentum, bool forces,
                              bool forces_from_next) {
  constexpr int W = Shape::kWidth;
  const std::uint32_t p = order_[k];
  const StencilWeights<W> w(&weights_[4 * W * k]);  // not in a run: a block of its own
  const double m = cur_.mass[p];
  double* band_row = g + local_[k];
  if (mass_momentum) {
    const double* B = &cur_.affine[4 * p];  // xx xy yx yy
    const MomentumContribution<Shape, Affine> momentum(m, cur_.velocity[0][p], cur_.velocity[1][p],
                                                       Double2{B[0], B[2]}, Double2{B[1], B[3]},
                                                       Affine ? &affine_weights_[2 * W * k] : nullptr, w);
    scatter_mass_momentum(band_row, row_stride, w, m, momentum);
  }
  if (forces) {
    const double V = forces_from_next ? nxt_.volume[k] : cur_.volume[p];
    const double* sp = forces_from_next ? &nxt_.stress[4 * k] : &cur_.stress[4 * p];
    Double2 external{m * body_force_now_[0], m * body_force_now_[1]};
    if (!cur_.traction_slot.empty()) {
      if (const std::int32_t slot = cur_.traction_slot[p]; slot >= 0) {
        const Vec2 t = loads_.traction_force(slot, V, m / materials_[cur_.material[p]].density);
        external += Double2{t.x(), t.y()};
      }
    }
    scatter_forces(band_row, row_stride, w, external, V, sp[0], sp[1], sp[3]);
  }
}

/// The shape functions of the particle at iteration index k, or of the four from k on when they form a
/// stencil run (the same sort key, so the same cell and stencil quadrant, and the same first node):
/// base_, local_, run_lane_ and the weights (interleaved for a run), APIC's offsets and affine weights.
/// Returns whether k starts a run.
template <class Shape, bool Affine>
bool Engine::evaluate_shape_functions(std::size_t c, std::size_t k) {
  constexpr int W = Shape::kWidth;
  double ih[kDim];  // 1 / h per axis, as eval_axes takes it
  for (int d = 0; d < kDim; ++d) ih[d] = inv_h_[d];
  // Sorted by key: the fourth particle on has the first one's key only if the four between do. Runs
  // only with 4-double registers (stencil_runs_) and in decks without surface tractions (whose
  // particles p2g maps one by one), so that every particle the one-particle kernels of p2g and g2p see
  // has a block of its own.
  if (stencil_runs_ && cur_.traction_slot.empty() && k + kRunLanes <= chunk_[c + 1] &&
      cur_.key[order_[k + kRunLanes - 1]] == cur_.key[order_[k]] && evaluate_run<Shape, Affine>(c, k))
    return true;
  const std::uint32_t p = order_[k];
  double s[kDim], l[kDim];  // per axis: lattice coordinate, half-size (cell units)
  int max_cell[kDim], first[kDim];
  for (int d = 0; d < kDim; ++d) {
    s[d] = (cur_.position[d][p] - grid_.origin[d]) * ih[d];
    l[d] = cur_.half_size[d][p];
    max_cell[d] = cells_per_axis_[d] - 1;
  }
  Shape::template eval_axes<kDim>(s, l, max_cell, ih, first, &weights_[4 * W * k]);
  set_stencil(c, k, first[0], first[1], -1);
  if constexpr (Affine) {  // APIC: the first node's offset and the affine weights, for this step's phases
    double* offset = &stencil_offset_[2 * k];
    for (int d = 0; d < kDim; ++d) offset[d] = grid_.origin[d] + first[d] * grid_.spacing[d] - cur_.position[d][p];
    affine_weights(Shape{}, StencilWeights<W>(&weights_[4 * W * k]), offset[0], offset[1], grid_.spacing[0],
                   grid_.spacing[1], &affine_weights_[2 * W * k]);
  }
  return false;
}

/// The shape functions of the four particles from k, interleaved (weights_; APIC's affine weights
/// alike), when they share the first node (a particle beyond the grid's edge can differ from its cell's
/// others); false, and nothing written, when they do not.
template <class Shape, bool Affine>
bool Engine::evaluate_run(std::size_t c, std::size_t k) {
  constexpr int W = Shape::kWidth;
  int bi[kRunLanes], bj[kRunLanes];
  Double4 sx = splat4(0.0), sy = sx, lx = sx, ly = sx;
  for (int l = 0; l < kRunLanes; ++l) {
    const std::uint32_t p = order_[k + static_cast<std::size_t>(l)];
    sx[l] = (cur_.position[0][p] - grid_.origin[0]) * inv_h_[0];
    sy[l] = (cur_.position[1][p] - grid_.origin[1]) * inv_h_[1];
    lx[l] = cur_.half_size[0][p];
    ly[l] = cur_.half_size[1][p];
    Shape::first_node(sx[l], sy[l], cells_per_axis_[0] - 1, cells_per_axis_[1] - 1, bi[l], bj[l]);
    if (bi[l] != bi[0] || bj[l] != bj[0]) return false;
  }
  Double4 w[W], dw[W];
  double* wk = &weights_[4 * W * k];
  eval_run_axis(Shape{}, sx, lx, bi[0], inv_h_[0], w, dw);
  for (int a = 0; a < W; ++a) {
    store4(wk + 4 * a, w[a]);
    store4(wk + 4 * (2 * W + a), dw[a]);
  }
  Double4 ox = splat4(0.0), oy = splat4(0.0), a[W];  // APIC: first node minus particle, affine weights of an axis
  if constexpr (Affine) {
    for (int l = 0; l < kRunLanes; ++l)
      ox[l] = grid_.origin[0] + bi[0] * grid_.spacing[0] - cur_.position[0][order_[k + l]];
    affine_weights_run_axis(Shape{}, w, dw, ox, grid_.spacing[0], a);
    for (int e = 0; e < W; ++e) store4(&affine_weights_[2 * W * k + 4 * e], a[e]);
  }
  eval_run_axis(Shape{}, sy, ly, bj[0], inv_h_[1], w, dw);
  for (int a = 0; a < W; ++a) {
    store4(wk + 4 * (W + a), w[a]);
    store4(wk + 4 * (3 * W + a), dw[a]);
  }
  if constexpr (Affine) {
    for (int l = 0; l < kRunLanes; ++l)
      oy[l] = grid_.origin[1] + bj[0] * grid_.spacing[1] - cur_.position[1][order_[k + l]];
    affine_weights_run_axis(Shape{}, w, dw, oy, grid_.spacing[1], a);
    for (int e = 0; e < W; ++e) store4(&affine_weights_[2 * W * k + 4 * (W + e)], a[e]);
    for (int l = 0; l < kRunLanes; ++l) {
      stencil_offset_[2 * (k + l)] = ox[l];
      stencil_offset_[2 * (k + l) + 1] = oy[l];
    }
  }
  for (int l = 0; l < kRunLanes; ++l) set_stencil(c, k + static_cast<std::size_t>(l), bi[0], bj[0], l);
  return true;
}

/// Iteration index k's stencil: first node (bi, bj), its place in the chunk's band, its lane in a run.
void Engine::set_stencil(std::size_t c, std::size_t k, int bi, int bj, std::int32_t lane) {
  run_lane_[k] = lane;
  base_[k] = bi + bj * nodes_per_axis_[0];
  const Band& band = bands_[c];
  constexpr int values = static_cast<int>(kBandValues);  // int arithmetic, as local_
  local_[k] = static_cast<std::int32_t>(values * ((bj - band.lo[1]) * (band.hi[0] - band.lo[0]) + (bi - band.lo[0])));
}

/// p2g of the four particles of a stencil run from k (APIC: the momentum with the particles' matrices),
/// each node's sums in particle order.
template <int W, bool Affine>
void Engine::scatter_run(std::size_t k, double* g, std::size_t row_stride, bool mass_momentum, bool forces,
                         bool forces_from_next) {
  const StencilWeights4<W> w(&weights_[4 * W * k]);
  double* band_row = g + local_[k];
  const std::uint32_t* p = &order_[k];
  const Double4 m{cur_.mass[p[0]], cur_.mass[p[1]], cur_.mass[p[2]], cur_.mass[p[3]]};
  if (mass_momentum) {
    const double *vx_of = cur_.velocity[0].data(), *vy_of = cur_.velocity[1].data();
    const Double4 vx{vx_of[p[0]], vx_of[p[1]], vx_of[p[2]], vx_of[p[3]]};
    const Double4 vy{vy_of[p[0]], vy_of[p[1]], vy_of[p[2]], vy_of[p[3]]};
    if constexpr (Affine) {
      const double* B[kRunLanes] = {&cur_.affine[4 * p[0]], &cur_.affine[4 * p[1]], &cur_.affine[4 * p[2]],
                                    &cur_.affine[4 * p[3]]};
      Double4 mB[4];  // m B_p: xx xy yx yy
      for (int e = 0; e < 4; ++e) mB[e] = m * Double4{B[0][e], B[1][e], B[2][e], B[3][e]};
      const AffineMomentum4<W> momentum(m * vx, m * vy, mB, &affine_weights_[2 * W * k], w);
      scatter_affine_momentum4(band_row, row_stride, w, momentum, &m);
    } else {
      scatter_mass_momentum4(band_row, row_stride, w, m, m * vx, m * vy);
    }
  }
  if (forces) {
    Double4 V = splat4(0.0), sxx = V, syy = V, sxy = V;
    for (int l = 0; l < kRunLanes; ++l) {
      const std::size_t kl = k + static_cast<std::size_t>(l);
      V[l] = forces_from_next ? nxt_.volume[kl] : cur_.volume[p[l]];
      const double* sp = forces_from_next ? &nxt_.stress[4 * kl] : &cur_.stress[4 * p[l]];
      sxx[l] = sp[0];
      syy[l] = sp[1];
      sxy[l] = sp[3];
    }
    scatter_forces4(band_row, row_stride, w, m * body_force_now_[0], m * body_force_now_[1], V, sxx, syy, sxy);
  }
}

}  // namespace mpm::core
