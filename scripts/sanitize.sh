#!/usr/bin/env bash
# The sanitizer stage of CI: builds uuvplan and the test programs with clang 14,
# AddressSanitizer and UBSan (float-cast-overflow too; any finding aborts) in build-fuzz/ (the
# fuzz targets share it), runs the io-layer tests there, then FUZZ_SECONDS (default 60; CI's
# test.sh gives 20) of each fuzz target (scripts/fuzz.sh). Which tests, and why not all:
# docs/validation.md, "Sanitizers".
# Usage: scripts/sanitize.sh [--configure-only] [FUZZ_SECONDS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${UUVPLAN_FUZZ_BUILD_DIR:-$root/build-fuzz}"
"$root/scripts/install-deps.sh"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# The io layer's test suites (every reader and writer, every case file, the CLI on good and
# malformed input: Cases/MalformedInput.*); only the test files that define one are compiled
# here (UUVPLAN_TEST_SUITES).
suites='Read|Write|Io|IO|Csv|Truth|Vehicle|Pool|Campaign|Cases|ScheduleJson|Cli|Malformed|WellFormed|Concurrent'
# Warnings are errors in the gcc build (scripts/build.sh); clang's other warnings are not
# made errors here. -O1: sanitized code at full optimisation hides little and builds slower.
# -gline-tables-only: a sanitizer report's stack has file:line; full -g costs 13-22% more
# compile time per file (docs/validation.md, "Sanitizers").
cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DUUVPLAN_SANITIZE=ON \
  -DUUVPLAN_FUZZ=ON -DUUVPLAN_BUILD_BENCH=OFF -DUUVPLAN_TEST_SUITES="$suites" \
  "${launcher[@]}" >/dev/null
[ "${1:-}" = "--configure-only" ] && exit 0
seconds="${1:-60}"
start=$SECONDS
cmake --build "$build" -j"$(nproc)" --target uuvplan --target io_tests --target cli_tests >&2
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Not here: Cli.Demo* (the demo's 60 s wall-time budget is a release-build figure: 89 s under
# ASan), nor ScheduleInformation (it checks the planner's numbers, 8.7 s in the release build
# and 147 s under ASan; the schedule JSON it reads is ScheduleJson's).
(cd "$build" && ctest -j"$(nproc)" --output-on-failure -E '^Cli\.Demo' -R "^($suites)")
echo "sanitize.sh: sanitized build and io tests took $((SECONDS - start)) s"
"$root/scripts/fuzz.sh" "$seconds"
echo "sanitize.sh: total $((SECONDS - start)) s"
