#!/usr/bin/env bash
# Installs dependencies, builds, and runs the default test suite (labels unit, verification, regression);
# then builds the suite again with AddressSanitizer + UndefinedBehaviorSanitizer (+ float-cast-overflow)
# into build-asan/ and runs the unit and regression labels and the fuzz smoke run there
# (scripts/build_sanitized.sh; GEOFLOW_SKIP_SANITIZERS=1 skips that stage).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
ctest --test-dir build -j"$(nproc)" --output-on-failure -L 'unit|verification|regression'
if [ "${GEOFLOW_SKIP_SANITIZERS:-0}" != 1 ]; then
  scripts/build_sanitized.sh
  ctest --test-dir build-asan -j"$(nproc)" --output-on-failure -L 'unit|regression|fuzz'
fi
