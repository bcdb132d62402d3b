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

/// Four doubles: one value of each of four particles. One AVX register in the AVX2 variants of the
/// kernels (common/cpu_variants.hpp), two SSE2 registers elsewhere; lane by lane the scalar operations,
/// as Double2.
using Double4 = double __attribute__((vector_size(32)));
inline Double4 splat4(double v) { return Double4{v, v, v, v}; }
/// Unaligned load / store of four consecutive doubles.
inline Double4 load4(const double* p) {
  Double4 v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
inline void store4(double* p, Double4 v) { __builtin_memcpy(p, &v, sizeof v); }
/// Four integers, one per particle: 32-bit (a truncated Double4, __builtin_convertvector) and 64-bit.
using Int4 = std::int32_t __attribute__((vector_size(16)));
using Long4 = std::int64_t __attribute__((vector_size(32)));

/// Four blocks of four values (block l at p + 4 l) as four Double4 of one value each (v[c] lane l =
/// p[4 l + c]), and back: a 4 x 4 transpose.
inline void load_transposed4(const double* p, Double4 v[4]) {
  const Double4 r0 = load4(p), r1 = load4(p + 4), r2 = load4(p + 8), r3 = load4(p + 12);
  const Double4 t0 = __builtin_shufflevector(r0, r1, 0, 4, 2, 6), t1 = __builtin_shufflevector(r0, r1, 1, 5, 3, 7);
  const Double4 t2 = __builtin_shufflevector(r2, r3, 0, 4, 2, 6), t3 = __builtin_shufflevector(r2, r3, 1, 5, 3, 7);
  v[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
  v[1] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
  v[2] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
  v[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}
inline void store_transposed4(const Double4 v[4], double* p) {
  Double4 r[4];
  load_transposed4(&v[0][0], r);  // the transpose is its own inverse
  for (int l = 0; l < 4; ++l) store4(p + 4 * l, r[l]);
}
/// Four blocks of three values (block l at p + 3 l) as three Double4 (v[c] lane l = p[3 l + c]).
inline void load_transposed4x3(const double* p, Double4 v[3]) {
  const Double4 a = load4(p), b = load4(p + 4), c = load4(p + 8);
  v[0] = __builtin_shufflevector(__builtin_shufflevector(a, b, 0, 3, 6, 6), c, 0, 1, 2, 5);
  v[1] = __builtin_shufflevector(__builtin_shufflevector(a, b, 1, 4, 7, 7), c, 0, 1, 2, 6);
  v[2] = __builtin_shufflevector(__builtin_shufflevector(a, b, 2, 5, 5, 5), c, 0, 1, 4, 7);
}

/// The same for a vector V of any width (Double2 or Double4): every lane v, m ? a : b,
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
