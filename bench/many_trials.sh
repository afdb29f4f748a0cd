#!/usr/bin/env bash
# The load test of many trials: a campaign of N trials, each a copy of one real 2,926-row BlueROV yaw
# log (../shared/data/bluerov-yaw-2016/trials/yaw_1.csv, 125 Hz gyro), half of them fit and half
# validate, identified by `uuvplan identify`; prints wall, CPU and peak RSS (/usr/bin/time -v).
# Memory must grow with the rows (N × 2,926), not with N². The copies are the same log, which
# the campaign reader refuses (counted twice): --accept-implausible reads them with a warning.
#   bench/many_trials.sh [N]... [--binary UUVPLAN]       (default N: 200 2000; build/uuvplan)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
binary="${UUVPLAN_BUILD_DIR:-$root/build}/uuvplan"
counts=()
while [ $# -gt 0 ]; do
  case "$1" in
    --binary) binary="$2"; shift 2 ;;
    *) counts+=("$1"); shift ;;
  esac
done
[ ${#counts[@]} -gt 0 ] || counts=(200 2000)
data="$root/../shared/data/bluerov-yaw-2016"
[ -f "$data/trials/yaw_1.csv" ] || { echo "many_trials.sh: needs ../shared (real data)" >&2; exit 77; }
rows_per_log=$(($(grep -vc '^#' "$data/trials/yaw_1.csv") - 1))  # data rows: no comments, no header
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
for n in "${counts[@]}"; do
  c="$dir/c$n"
  mkdir -p "$c/trials"
  cp "$data/vehicle.yaml" "$c/"
  {
    echo "vehicle: vehicle.yaml"
    echo "trials:"
    for ((i = 0; i < n; i++)); do
      cp "$data/trials/yaw_1.csv" "$c/trials/yaw_$i.csv"
      use=fit; [ $((i % 2)) -eq 1 ] && use=validate
      printf '  - file: trials/yaw_%d.csv\n    dof: yaw\n    mapping: yaw\n    use: %s\n    start: %d\n' \
        "$i" "$use" $((i * 100))
    done
  } >"$c/campaign.yaml"
  /usr/bin/time -v -o "$dir/time" "$binary" identify "$c" --accept-implausible >"$dir/out" 2>&1 && rc=0 || rc=$?
  rss=$(awk -F': ' '/Maximum resident/ {print $2}' "$dir/time")
  wall=$(awk -F': ' '/Elapsed \(wall/ {print $2}' "$dir/time")
  cpu=$(awk -F': ' '/User time/ {u=$2} /System time/ {s=$2} END {printf "%.2f", u + s}' "$dir/time")
  echo "$n trials ($((n * rows_per_log)) rows, $((n / 2 + n % 2)) fit): exit $rc, wall $wall, CPU $cpu s, peak RSS $((rss / 1024)) MB"
  grep -E '^  yaw  |status' "$dir/out" | head -8 || true
done
