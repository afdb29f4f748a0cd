#!/usr/bin/env bash
# `uuvplan schedule` on every DOF of each case in cases/ (its vehicle and pool, the verdict
# included): CPU seconds (user + sys) per DOF and for the whole schedule, the best of RUNS, and
# the schedule's status; with a second binary, the same for it in the same run, turn by turn
# (docs/performance.md, "Planning the cases").
# Usage: bench/schedule_cases.sh [RUNS] [NEW_UUVPLAN] [OLD_UUVPLAN] [CASE...]
#   defaults: 1 run, build/uuvplan, no old binary, romeo payload60 bluerov2 uris vsor.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
runs="${1:-1}"
new="${2:-$root/build/uuvplan}"
old="${3:-}"
shift $(($# < 3 ? $# : 3))
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(romeo payload60 bluerov2 uris vsor)

# Best CPU seconds of `runs` runs of `uuvplan schedule` and the status of the last.
cpu_of() {
  local bin="$1" case_dir="$2" best="" status=""
  shift 2
  for _ in $(seq "$runs"); do
    local t
    /usr/bin/time -o /tmp/schedule_cases_time.$$ -f "%U %S" "$bin" schedule \
      "$case_dir/vehicle.yaml" --pool "$case_dir/pool.yaml" "$@" > /tmp/schedule_cases.$$ \
      2>/dev/null || true  # exit 1: a pool that cannot host every trial
    t=$(tail -1 /tmp/schedule_cases_time.$$ | awk '{ printf "%.2f", $1 + $2 }')
    status=$(head -1 /tmp/schedule_cases.$$ | sed -E 's/.*\): //')
    best=$(awk -v a="$t" -v b="$best" 'BEGIN { print (b == "" || a < b) ? a : b }')
  done
  rm -f /tmp/schedule_cases.$$ /tmp/schedule_cases_time.$$
  echo "$best $status"
}

printf '%-10s %-7s %14s %14s\n' case dof "new CPU s" "old CPU s"
for c in "${cases[@]}"; do
  dir="$root/cases/$c"
  dofs=$(awk '/^sensors:/ { s = 1; next } s && /^[a-z]/ { s = 0 }
              s && /^  [a-z]+:/ { sub(":", "", $1); print $1 }' "$dir/vehicle.yaml")
  for d in $dofs all; do
    args=()
    [ "$d" = all ] || args=(--dof "$d")
    n=$(cpu_of "$new" "$dir" "${args[@]}")
    o="-"
    [ -z "$old" ] || o=$(cpu_of "$old" "$dir" "${args[@]}")
    printf '%-10s %-7s %14s %14s\n' "$c" "$d" "${n%% *}" "${o%% *}"
    [ "$d" != all ] || echo "  status: new ${n#* }${old:+, old ${o#* }}"
  done
done
