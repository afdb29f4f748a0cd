#!/usr/bin/env bash
# The long-log comparison on one machine, in one run: `uuvplan identify` against the plain
# NumPy/SciPy script (bench/plain_identify.py) on the 1,000,000-row position-only surge trial
# (bench/position_identify_bench --write, seeded), alternating, best of N runs of each (the
# machine is shared: the best run is the least disturbed one). Prints wall and CPU seconds and
# the peak RSS of each, the CSV's size, and the estimates.
#   bench/position_identify.sh [--input legs|sine] [N] [UUVPLAN_BINARY]...
#       (default legs, 5 runs, build/uuvplan; sine: the force changes at every row)
# Needs the optional benchmark dependencies: scripts/install-deps.sh --bench.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${UUVPLAN_BUILD_DIR:-$root/build}"
input=legs
if [ "${1:-}" = "--input" ]; then
  input="${2:?--input needs legs or sine}"
  shift 2
fi
runs="${1:-5}"
shift || true
binaries=("$@")
[ ${#binaries[@]} -gt 0 ] || binaries=("$build/uuvplan")
python=/usr/bin/python3  # Debian's, which has python3-numpy and python3-scipy
if ! "$python" -c 'import numpy, scipy' 2>/dev/null; then
  echo "position_identify.sh: NumPy/SciPy missing: run scripts/install-deps.sh --bench" >&2
  exit 2
fi
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
"$build/bench/position_identify_bench" --write "$dir/campaign" --rows 1000000 --input "$input" >/dev/null
csv="$(ls "$dir"/campaign/trials/*.csv)"
csv_bytes="$(stat -c %s "$csv")"
echo "trial: $(wc -l <"$csv") lines, $csv_bytes bytes of CSV"
# The best (lowest wall) of the "wall user sys rss" lines on stdin, and the highest peak RSS of
# them all (time's %M is in KiB; MB here are 10^6 bytes, the CSV's unit) against the CSV's size.
best() {
  sort -n | awk -v csv="$csv_bytes" 'NR == 1 { wall = $1; cpu = $2 + $3 } $4 > rss { rss = $4 }
    END { printf "wall %.2f s, CPU %.2f s, peak RSS (highest of the runs) %.1f MB = %.2f x the CSV\n",
                 wall, cpu, rss * 1024 / 1e6, rss * 1024 / csv }'
}
declare -A times
for ((i = 0; i < runs; i++)); do
  for b in "${binaries[@]}"; do
    /usr/bin/time -f "%e %U %S %M" -o "$dir/t" "$b" identify "$dir/campaign" >"$dir/out" 2>/dev/null || true
    times[$b]+="$(cat "$dir/t")"$'\n'
  done
  /usr/bin/time -f "%e %U %S %M" -o "$dir/t" "$python" "$root/bench/plain_identify.py" "$dir/campaign" >"$dir/py"
  times[py]+="$(cat "$dir/t")"$'\n'
done
for b in "${binaries[@]}"; do
  echo "$b identify, best of $runs: $(printf '%s' "${times[$b]}" | best)"
  "$b" identify "$dir/campaign" 2>/dev/null | grep -E '^  [a-z]+ +(m|k|kq|bias) |note|WARNING' || true
done
echo "plain_identify.py, best of $runs: $(printf '%s' "${times[py]}" | best)"
cat "$dir/py"
