#!/usr/bin/env bash
# Configures and builds the test suite and the three programs with -fsanitize=address,undefined
# -fsanitize=float-cast-overflow into build-asan/ (-O2 -g1 without NDEBUG, so assert() is checked too; no benchmarks, no
# verification tier: it is not run there).
# Run its tests with: ctest --test-dir build-asan -L 'unit|regression|fuzz'
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" \
  -DGEOFLOW_SANITIZE=address,undefined -DGEOFLOW_TEST_TIERS="unit;regression" \
  -DGEOFLOW_BUILD_BENCHMARKS=OFF > build-asan.log 2>&1 || { cat build-asan.log; exit 1; }
cmake --build build-asan -j"$(nproc)" >> build-asan.log 2>&1 || { tail -50 build-asan.log; exit 1; }
echo "build-asan: ok (log in build-asan.log)"
