#!/usr/bin/env bash
# Installs dependencies, builds everything with warnings as errors, and runs the whole test
# suite (ctest), then prints the total time and the ten slowest tests; then the sanitizer and
# fuzz stage (scripts/sanitize.sh). This is the README's test command and what .ci/run runs.
# Tests that need ../shared (real logs, not shipped) are reported as skipped with their reason
# when it is absent.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export UUVPLAN_BUILD_DIR="${UUVPLAN_BUILD_DIR:-$root/build}"
start=$SECONDS
"$root/scripts/build.sh"
cd "$UUVPLAN_BUILD_DIR"
log="$UUVPLAN_BUILD_DIR/ctest.log"
status=0
ctest --output-on-failure -j"$(nproc)" 2>&1 | tee "$log" || status=$?
echo "Slowest tests:"
grep -E '^ *[0-9]+/[0-9]+ Test +#' "$log" | sed -E 's/^.*Test +#[0-9]+: ([^ ]+) .* ([0-9.]+) sec$/\2 s  \1/' |
  sort -rn | awk 'NR <= 10 { print "  " $0 }'  # reads to the end: no SIGPIPE under pipefail
# Each skipped test with its reason (GTEST_SKIP's message, the line after "Skipped" in ctest's
# log), one line each: without ../shared the real-data tests (docs/validation.md, twins).
awk '/^[0-9]+\/[0-9]+ Test: / { name = $3 }
     skip { print "  skipped: " name ": " $0; skip = 0 }
     /: Skipped$/ { skip = 1 }' "$UUVPLAN_BUILD_DIR/Testing/Temporary/LastTest.log" 2>/dev/null || true
echo "test.sh: build and tests took $((SECONDS - start)) s"
grep -E 'tests passed|tests failed' "$log" | tail -1  # ctest's summary, last
# The sanitizer stage, quick: the io tests under ASan + UBSan at -O0 and 20 s of two of the six
# fuzz targets, taken in turn by the commit (scripts/sanitize.sh --quick); the full stage
# (`scripts/sanitize.sh`: -O1, every fuzz target for 60 s) is the longer run of
# docs/validation.md, "Sanitizers". UUVPLAN_SKIP_SANITIZE=1 skips it for a quick local run.
if [ "${UUVPLAN_SKIP_SANITIZE:-0}" != 1 ]; then
  "$root/scripts/sanitize.sh" --quick "${UUVPLAN_FUZZ_SECONDS:-20}" || status=1
fi
echo "test.sh: total $((SECONDS - start)) s"
exit "$status"
