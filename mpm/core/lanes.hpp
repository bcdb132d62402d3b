#pragma once
// Two doubles operated on together: one SSE2 register on any x86-64 (and one NEON register on AArch64),
// through the GCC/Clang vector extension: no intrinsics, no -march flag. Each operation acts on each lane
// exactly as the scalar operation does (IEEE, no reassociation), so a kernel written on Double2 gives
// the scalar kernel's results bit for bit. The lanes are the x and y axes of one particle, or the x and
// y components of one vector; comparisons give lane masks for select(), which is what keeps the
// piecewise shape functions free of branches.
#include <cstdint>

namespace mpm::core {

using Double2 = double __attribute__((vector_size(16)));
using Mask2 = std::int64_t __attribute__((vector_size(16)));

inline Double2 splat2(double v) { return Double2{v, v}; }
/// Per lane: m ? a : b.
inline Double2 select(Mask2 m, Double2 a, Double2 b) { return m ? a : b; }
/// Per lane |v| (-0.0 stays -0.0: callers only compare it or use it where the sign of zero is lost).
inline Double2 abs2(Double2 v) { return select(v < splat2(0.0), -v, v); }

/// The same for a vector V of any width (Double2, or stencil_runs.hpp's Double4): every lane v, m ? a : b,
/// and |v| per lane.
template <class V>
inline V splat(double v) {
  V r;
  for (int i = 0; i < static_cast<int>(sizeof(V) / sizeof(double)); ++i) r[i] = v;
  return r;
}
template <class M, class V>
inline V lane_select(M m, V a, V b) {
  return m ? a : b;
}
template <class V>
inline V lane_abs(V v) {
  return lane_select(v < splat<V>(0.0), -v, v);
}

}  // namespace mpm::core
