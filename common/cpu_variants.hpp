#pragma once
// Hot kernels in two builds, the one taken at run time by the CPU: GCC function multi-versioning (an
// ifunc, resolved once at load time) compiles a function marked CPU_VARIANTS for the portable x86-64
// baseline (SSE2) and for AVX2, with every callee of its translation unit inlined into each (flatten).
// Only AVX2 is asked, not FMA, so no multiply-add is contracted: each operation is the baseline's, lane
// by lane, and the results are bit for bit the same (`mpm_core_benchmark --checksum` compares them). What
// AVX2 buys on these kernels is its three-operand encoding: fewer register moves (mpm/README.md,
// Performance). Other compilers and targets get the one portable build.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define CPU_VARIANTS __attribute__((target_clones("avx2", "default"), flatten))
#else
#define CPU_VARIANTS
#endif

namespace common {
/// Whether the kernels run with 4-double (256-bit) vector registers: the AVX2 variant taken on this
/// CPU, or a whole build for AVX2. Without them a 4-double vector is two 2-double ones and code written
/// for four lanes (mpm/core/stencil_runs.hpp) costs more than it saves.
inline bool wide_vector_kernels() {
#if defined(__AVX2__)
  return true;
#elif defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}
}  // namespace common
