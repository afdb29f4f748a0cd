#!/usr/bin/env bash
# Installs the dependencies (Debian packages, if missing) and builds uuvplan into build/.
# Usage: scripts/build.sh [--target T]... [extra cmake -D options...]
# Every script configures build/ the same way (warnings as errors), so the demo and the tests
# share one build and nothing is compiled twice; --target builds only what is named.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
build="${UUVPLAN_BUILD_DIR:-$root/build}"
targets=()
options=()
while [ $# -gt 0 ]; do
  case "$1" in
    --target) targets+=(--target "$2"); shift 2 ;;
    *) options+=("$1"); shift ;;
  esac
done
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # ccache caches the files that include a precompiled header (UUVPLAN_PCH) only with these
  export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}"
  # Paths below the checkout hashed relative to it: two checkouts share the cache.
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-true}"
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUUVPLAN_WERROR=ON "${launcher[@]}" \
  "${options[@]}" >/dev/null
cmake --build "$build" -j"$(nproc)" "${targets[@]}" >&2
