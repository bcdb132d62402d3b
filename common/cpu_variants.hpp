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
