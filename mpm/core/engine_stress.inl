// Part of engine.cpp, included there (one translation unit: each CPU variant of the step inlines every
// callee of its unit, common/cpu_variants.hpp): the stress phase, strain increments from the grid, the
// checkerboard remedies (stress_remedy.hpp) and the materials' updates with their dispatch.

namespace mpm::core {

namespace {
/// Dispatch for a run where every particle has the same material: one instantiation per model. update4:
/// four consecutive particles at once where the model has it (MohrCoulomb::update4).
template <class Model>
struct SameMaterial {
  const Model& model;
  void operator()(std::uint32_t /*material*/, double* s, const double* de, double* sv) const { model.update(s, de, sv); }
  void update4(const std::uint32_t* /*material*/, double* s, const double* de, double* sv) const {
    if constexpr (requires { model.update4(s, de, sv); })
      model.update4(s, de, sv);
    else
      for (int l = 0; l < 4; ++l) model.update(s + 4 * l, de + 3 * l, sv + kStateVariables * l);
  }
  bool separated(std::uint32_t /*material*/, double mass, double volume) const { return model.separated(mass, volume); }
};
/// Dispatch for mixed materials: a switch on the material type (no virtual call).
struct MixedMaterials {
  const std::vector<Material>& materials;
  void operator()(std::uint32_t material, double* s, const double* de, double* sv) const {
    const Material& m = materials[material];
    if (m.type == MaterialType::MohrCoulomb2D)
      m.mohr_coulomb.update(s, de, sv);
    else
      m.elastic.update(s, de, sv);
  }
  void update4(const std::uint32_t* material, double* s, const double* de, double* sv) const {
    for (int l = 0; l < 4; ++l) (*this)(material[l], s + 4 * l, de + 3 * l, sv + kStateVariables * l);
  }
  bool separated(std::uint32_t material, double mass, double volume) const {
    const Material& m = materials[material];
    return m.type == MaterialType::MohrCoulomb2D && m.mohr_coulomb.separated(mass, volume);
  }
};
}  // namespace


/// Stress update: strain increment from the nodal velocity at the particle (or the one g2p stored),
/// the selected checkerboard remedy (stress_remedy.hpp), then the material's stress update and the
/// carried state (next buffer). A nodal remedy needs every chunk's values at the nodes first, hence
/// its barriers. With AfterStress::MapForces (USF) each chunk then maps its forces from the updated
/// stress into its band (p2g_chunk, kForces): the same sums, in the same order, as a separate p2g pass
/// after a barrier, while the chunk's particles are still in cache.
template <class Shape>
void Engine::update_stress(StrainFrom from, AfterStress then) {
  wait_for_previous_phase();
  const bool strain_ready = from == StrainFrom::G2p;
  const bool map_forces = then == AfterStress::MapForces;
  if (nodal_projection(smoothing_).values > 0) {
    for_each_chunk([&](std::size_t c) {
      if (!strain_ready) compute_strain_increments<Shape>(c);
      scatter_remedy_values<Shape>(c);
    });
#pragma omp barrier
    for_each_row([&](int j) { nodal_remedy_row(j); });
#pragma omp barrier
    for_each_chunk([&](std::size_t c) {
      gather_remedy_values<Shape>(c);
      update_material_state(c);
      if (map_forces) p2g_chunk<Shape, false>(c, kForces);
    });
  } else {
    const bool cell_remedy = is_cell_remedy(smoothing_);
    for_each_chunk([&](std::size_t c) {
      if (!strain_ready) compute_strain_increments<Shape>(c);
      if (cell_remedy) apply_cell_remedy(c);
      update_material_state(c);
      if (map_forces) p2g_chunk<Shape, false>(c, kForces);
    });
  }
}

/// (dexx, deyy, dgxy) = dt (dvx/dx, dvy/dy, dvx/dy + dvy/dx), the gradient of the nodal velocity at the
/// particle (CB-Geo compute_strain_rate, without its 1e-15 flush to zero).
template <class Shape>
void Engine::compute_strain_increments(std::size_t c) {
  constexpr int W = Shape::kWidth;
  for (std::size_t k = chunk_[c]; k < chunk_[c + 1]; ++k) {
    const auto first = static_cast<std::size_t>(base_[k]);
    if (run_lane_[k] == 0) {
      const VelocityGradient4 L = gather_velocity_gradient4(velocity_.data(), kVectorStride, first, node_row_stride(),
                                                            StencilWeights4<W>(&weights_[4 * W * k]));
      for (int l = 0; l < kRunLanes; ++l) L.lane(l).strain_increment(dt_, &dstrain_[3 * (k + l)]);
      k += kRunLanes - 1;
      continue;
    }
    const StencilWeights<W> w(&weights_[4 * W * k]);  // not in a run: a block of its own
    gather_velocity_gradient(velocity_.data(), kVectorStride, first, node_row_stride(), w)
        .strain_increment(dt_, &dstrain_[3 * k]);
  }
}

/// A cell remedy on every cell of chunk c (chunks start at cell boundaries, so each cell lies in one
/// chunk; its particles are consecutive in iteration order).
void Engine::apply_cell_remedy(std::size_t c) {
  const std::size_t k1 = chunk_[c + 1];
  std::size_t a = chunk_[c];
  while (a < k1) {
    const std::int64_t this_cell = cell_of(cur_.key[order_[a]]);
    std::size_t b = a + 1;
    while (b < k1 && cell_of(cur_.key[order_[b]]) == this_cell) ++b;
    const std::uint32_t* cell = &order_[a];
    core::apply_cell_remedy(smoothing_, &dstrain_[3 * a], b - a, [&](std::size_t i) { return cur_.volume[cell[i]]; });
    a = b;
  }
}

/// Nodal remedy, 1/3: w N values into the chunk's band (slots 0-2), and w N into slot 3 when the
/// weight is the volume (a mass weight is normalised by the nodal mass).
template <class Shape>
void Engine::scatter_remedy_values(std::size_t c) {
  constexpr int W = Shape::kWidth;
  const NodalProjection proj = nodal_projection(smoothing_);
  double* g = cleared_band(c);
  const std::size_t row_stride = bands_[c].row_stride();
  for (std::size_t k = chunk_[c]; k < chunk_[c + 1]; ++k) {
    const StencilWeights<W> sw = stencil_weights<W>(k);
    const double *wx = sw.wx, *wy = sw.wy;
    const std::uint32_t p = order_[k];
    const double w = proj.volume_weighted ? cur_.volume[p] : cur_.mass[p];
    double values[3];
    nodal_values(smoothing_, &dstrain_[3 * k], values);
    double* band_row = g + local_[k];
    for (int b = 0; b < W; ++b, band_row += row_stride) {
      double* gn = band_row;
      for (int a = 0; a < W; ++a, gn += kBandValues) {
        const double wN = w * wx[a] * wy[b];
        for (int f = 0; f < proj.values; ++f) gn[f] += wN * values[f];
        if (proj.volume_weighted) gn[3] += wN;
      }
    }
  }
}

/// Nodal remedy, 2/3: nodal value = sum w N value / sum w N (summed in chunk order).
void Engine::nodal_remedy_row(int j) {
  const NodalProjection proj = nodal_projection(smoothing_);
  double* s = thread_row_sums();
  sum_bands_of_row(j, 4, s);
  for (int i = box_lo_[0]; i < box_hi_[0]; ++i, s += kBandValues) {
    const std::size_t n = static_cast<std::size_t>(i) + static_cast<std::size_t>(j) * node_row_stride();
    const double weight = proj.volume_weighted ? s[3] : mass_[n];
    const double inv_w = weight > (proj.volume_weighted ? 0.0 : mass_tolerance_) ? 1.0 / weight : 0.0;
    for (int f = 0; f < proj.values; ++f) nodal_remedy_[3 * n + f] = s[f] * inv_w;
  }
}

/// Nodal remedy, 3/3: the nodal values interpolated back, sum N value_i, applied to the increment.
template <class Shape>
void Engine::gather_remedy_values(std::size_t c) {
  constexpr int W = Shape::kWidth;
  const int nv = nodal_projection(smoothing_).values;
  for (std::size_t k = chunk_[c]; k < chunk_[c + 1]; ++k) {
    const StencilWeights<W> sw = stencil_weights<W>(k);
    const double *wx = sw.wx, *wy = sw.wy;
    double e[3] = {0, 0, 0};
    std::size_t node_row = static_cast<std::size_t>(base_[k]);
    for (int b = 0; b < W; ++b, node_row += node_row_stride()) {
      const double* en = &nodal_remedy_[3 * node_row];
      for (int a = 0; a < W; ++a, en += 3) {
        const double N = wx[a] * wy[b];
        for (int f = 0; f < nv; ++f) e[f] += N * en[f];
      }
    }
    apply_nodal_values(smoothing_, e, &dstrain_[3 * k]);
  }
}

/// Material dispatch for one chunk: one templated loop per material model when all particles share a
/// material, else a switch on the material type per particle (no virtual call either way).
void Engine::update_material_state(std::size_t c) {
  const std::size_t k0 = chunk_[c], k1 = chunk_[c + 1];
  if (uniform_material_) {
    const Material& m = materials_[0];
    if (m.type == MaterialType::MohrCoulomb2D)
      update_material_state(k0, k1, c, SameMaterial<MohrCoulomb>{m.mohr_coulomb});
    else
      update_material_state(k0, k1, c, SameMaterial<LinearElastic>{m.elastic});
  } else {
    update_material_state(k0, k1, c, MixedMaterials{materials_});
  }
}

/// The material's stress update with the (possibly smoothed) increment, volume *= 1 + de_v (CB-Geo
/// update_volume, here with the particle's own increment), no stress once separated (materials.hpp),
/// the strain sums, and the particle fields carried unchanged, all into the next buffer.
template <class Dispatch>
void Engine::update_material_state(std::size_t k0, std::size_t k1, std::size_t c, const Dispatch& dispatch) {
  // The stress and state variables are updated in place in the next buffer (whole-block copies first:
  // no partial-store stalls), four particles at a time (their blocks follow one another there).
  // copy_in(k) returns p = order_[k], the particle's index in the current buffer, for carry(k, p).
  const auto copy_in = [&](std::size_t k) {
    const std::uint32_t p = order_[k];
    copy_doubles<4>(&cur_.stress[4 * p], &nxt_.stress[4 * k]);
    copy_doubles<kStateVariables>(&cur_.svars[p * kStateVariables], &nxt_.svars[k * kStateVariables]);
    return p;
  };
  const auto carry = [&](std::size_t k, std::uint32_t p) {
    const double* de = &dstrain_[3 * k];
    double* s = &nxt_.stress[4 * k];
    const double dv = de[0] + de[1];
    nxt_.volume[k] = cur_.volume[p] * (1.0 + dv);
    if (dispatch.separated(cur_.material[p], cur_.mass[p], nxt_.volume[k])) {
      std::fill_n(s, 4, 0.0);
      // A separated particle's volume grows no further (it may shrink, and reloads once compacted): pulled
      // apart by its neighbours' motion it grew without bound, to V = e^872 V0 = inf at 34 s of the tailings
      // dam's softening run (scripts/tailings_dam/study.py --quick --duration 40), and inf x 0 stress in its
      // nodal force V sigma grad N made the velocities NaN.
      if (dispatch.separated(cur_.material[p], cur_.mass[p], cur_.volume[p]))
        nxt_.volume[k] = std::min(nxt_.volume[k], cur_.volume[p]);
    }
    nxt_.epsv[k] = cur_.epsv[p] + dv;
    nxt_.exx[k] = cur_.exx[p] + de[0];
    nxt_.eyy[k] = cur_.eyy[p] + de[1];
    nxt_.gxy[k] = cur_.gxy[p] + de[2];
    nxt_.id[k] = cur_.id[p];
    nxt_.material[k] = cur_.material[p];
    nxt_.mass[k] = cur_.mass[p];
    for (int d = 0; d < kDim; ++d) nxt_.half_size[d][k] = cur_.half_size[d][p];
    if (!cur_.traction_slot.empty()) nxt_.traction_slot[k] = cur_.traction_slot[p];
    if (!std::isfinite(s[0] + s[1] + s[2] + s[3])) report(c, k, ProblemKind::StressNotFinite, cur_.id[p], s[0], s[1]);
  };
  std::size_t k = k0;
  for (; k + 4 <= k1; k += 4) {
    std::uint32_t p[4], material[4];
    for (std::size_t l = 0; l < 4; ++l) {
      p[l] = copy_in(k + l);
      material[l] = cur_.material[p[l]];
    }
    dispatch.update4(material, &nxt_.stress[4 * k], &dstrain_[3 * k], &nxt_.svars[k * kStateVariables]);
    for (std::size_t l = 0; l < 4; ++l) carry(k + l, p[l]);
  }
  for (; k < k1; ++k) {
    const std::uint32_t p = copy_in(k);
    dispatch(cur_.material[p], &nxt_.stress[4 * k], &dstrain_[3 * k], &nxt_.svars[k * kStateVariables]);
    carry(k, p);
  }
}

}  // namespace mpm::core
