#!/usr/bin/env bash
# Installs dependencies, builds everything with warnings as errors, and runs the whole test
# suite (ctest). This is the README's test command and what .ci/run runs.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export UUVPLAN_BUILD_DIR="${UUVPLAN_BUILD_DIR:-$root/build}"
"$root/scripts/build.sh" -DUUVPLAN_WERROR=ON
cd "$UUVPLAN_BUILD_DIR"
ctest --output-on-failure -j"$(nproc)"
