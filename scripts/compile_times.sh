#!/usr/bin/env bash
# The compile time of every translation unit of a target, from nothing (no ccache: what a new
# user waits for). Configures build-times/ as scripts/build.sh configures build/ (Release,
# warnings as errors), builds the target with a launcher that times each compile, then prints
# the wall time of the whole build and the N slowest translation units (docs/performance.md).
# Usage: scripts/compile_times.sh [N=15] [TARGET=uuvplan] [JOBS=nproc]
#   UUVPLAN_TIMES_DIR: the build directory (default build-times/, removed first).
set -euo pipefail
if [ "${1:-}" = "--time-one" ]; then  # the launcher: times one compiler call
  shift
  src="?"
  prev=""
  for a in "$@"; do  # the source is the argument after -c
    if [ "$prev" = "-c" ]; then src="$a"; fi
    prev="$a"
  done
  # wall, user and system seconds (bash's `time`; the compiler's own messages go to stderr)
  TIMEFORMAT="%R %U %S $src"
  exec 3>&2
  { time "$@" 2>&3; } 2>>"$UUVPLAN_TIMES_LOG"
  exit
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
n="${1:-15}"
target="${2:-uuvplan}"
jobs="${3:-$(nproc)}"
build="${UUVPLAN_TIMES_DIR:-$root/build-times}"
"$root/scripts/install-deps.sh"
rm -rf "$build"
mkdir -p "$build"
export UUVPLAN_TIMES_LOG="$build/compile_times.log"
export CCACHE_DISABLE=1
: >"$UUVPLAN_TIMES_LOG"
start=$(date +%s.%N)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DUUVPLAN_WERROR=ON \
  "-DCMAKE_CXX_COMPILER_LAUNCHER=$root/scripts/compile_times.sh;--time-one" >/dev/null
configured=$(date +%s.%N)
cmake --build "$build" -j"$jobs" --target "$target" >/dev/null
end=$(date +%s.%N)
awk -v root="$root/" -v n="$n" -v start="$start" -v configured="$configured" -v end="$end" \
    -v jobs="$jobs" -v target="$target" '
  { t = $2 + $3; sum += t; wall += $1; count++; name = $4; sub(root, "", name)
    line[count] = sprintf("%7.1f s  %s", t, name); time[count] = t }
  END {
    printf "compile_times: %s from nothing (no ccache, -j%d): %.0f s wall (configure %.0f s); %d translation units, %.0f s of compiler CPU time (user + system; %.0f s wall summed)\n", target, jobs, end - start, configured - start, count, sum, wall
    for (i = 1; i <= count; i++) order[i] = i
    for (i = 2; i <= count; i++) { k = order[i]; j = i - 1; while (j > 0 && time[order[j]] < time[k]) { order[j + 1] = order[j]; j-- } order[j + 1] = k }
    printf "slowest %d (CPU seconds: unchanged by the load of the machine):\n", n
    for (i = 1; i <= n && i <= count; i++) print line[order[i]]
  }' "$UUVPLAN_TIMES_LOG"
