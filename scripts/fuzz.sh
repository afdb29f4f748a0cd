#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ (clang 14, ASan + UBSan with float-cast-overflow) in
# build-fuzz/ and runs each for SECONDS (default 60) on its corpus, seeded from cases/ and
# tests/data (valid files and the malformed-input suite). Findings (crashes, sanitizer
# reports, an exception other than model::InputError, > 2 GB, > 10 s on one input) are saved
# to build-fuzz/findings/<target>-*; the script then exits 1. Each finding must become a case
# of tests/data/bad (docs/validation.md, "Fuzzing").
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
#   TARGET: csv vehicle pool truth campaign plan recording
#   UUVPLAN_FUZZ_BUILD_DIR, UUVPLAN_SANITIZE_OPT: the build directory and optimisation level
#   (scripts/sanitize.sh --quick sets both: build-fuzz-quick/, -O0).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(csv vehicle pool truth campaign plan recording)
build="${UUVPLAN_FUZZ_BUILD_DIR:-$root/build-fuzz}"
"$root/scripts/sanitize.sh" --configure-only
for t in "${targets[@]}"; do build_targets+=(--target "fuzz_$t"); done
cmake --build "$build" -j"$(nproc)" "${build_targets[@]}" >&2

# Seeds: every file of the target's format in cases/ and tests/data (good and bad).
seed() {  # seed TARGET PATTERN...
  local dir="$build/corpus/$1"; shift
  mkdir -p "$dir"
  for f in "$@"; do [ -f "$f" ] && cp -n "$f" "$dir/" 2>/dev/null || true; done
}
d="$root/tests/data"
seed csv "$d"/io/trials/*.csv "$d"/bad/*.csv "$d"/bad/cases/csv_*.csv
seed vehicle "$root"/cases/*/vehicle.yaml "$d"/io/vehicle.yaml "$d"/bad/cases/vehicle_*.yaml
seed pool "$root"/cases/*/pool.yaml "$d"/io/pool.yaml "$d"/bad/cases/pool_*.yaml
seed truth "$root"/cases/*/truth*.yaml "$d"/io/truth.yaml "$d"/bad/cases/truth_*.yaml
seed campaign "$d"/io/campaign.yaml "$d"/bad/cases/campaign_*.yaml "$d"/bad/cases/csv_*.yaml
seed plan "$d"/romeo/*.json "$d"/bad/cases/plan_*.json
seed recording "$d"/io/recordings/*

mkdir -p "$build/findings"
status=0
for t in "${targets[@]}"; do
  echo "fuzz_$t: ${seconds} s on $(ls "$build/corpus/$t" | wc -l) inputs"
  # -rss_limit_mb: 2 GB, the work limit; -timeout: one input may take 10 s at most.
  if ! (cd "$build" && nice "./fuzz/fuzz_$t" "corpus/$t" -max_total_time="$seconds" \
      -rss_limit_mb=2048 -timeout=10 -max_len=65536 -print_final_stats=1 \
      -artifact_prefix="findings/$t-" >"fuzz-$t.log" 2>&1); then
    echo "fuzz_$t: FINDING, see $build/fuzz-$t.log and $build/findings/" >&2
    status=1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz-$t.log" | tr '\n' ' ' || true
  echo
done
exit "$status"
