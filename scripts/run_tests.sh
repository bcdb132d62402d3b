#!/usr/bin/env bash
# Installs dependencies, builds, and runs the default test suite (labels unit, verification, regression).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
ctest --test-dir build -j"$(nproc)" --output-on-failure -L 'unit|verification|regression'
