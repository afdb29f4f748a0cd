#!/usr/bin/env bash
# The sanitizer stage: builds uuvplan and the io layer's test programs with clang 14,
# AddressSanitizer and UBSan (float-cast-overflow too; any finding aborts), runs the io layer's
# tests there, then fuzzes the readers (scripts/fuzz.sh). Two sizes (docs/validation.md,
# "Sanitizers"):
#   full (default): -O1 in build-fuzz/, every io suite, each of the seven fuzz targets for
#     FUZZ_SECONDS (default 60);
#   --quick (CI: scripts/test.sh): -O0 in build-fuzz-quick/ (half the compile time; unoptimised
#     code hides nothing from ASan), the io suites but the CLI tests that run a numerical
#     command at length, and two of the seven fuzz targets for FUZZ_SECONDS each, taken in turn by
#     the commit count (four consecutive commits fuzz every reader; UUVPLAN_FUZZ_TARGETS names
#     others).
# Usage: scripts/sanitize.sh [--quick] [--configure-only] [FUZZ_SECONDS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
quick=0
configure_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1; shift ;;
    --configure-only) configure_only=1; shift ;;
    *) break ;;
  esac
done
if [ "$quick" = 1 ]; then  # fuzz.sh configures the same directory through these
  export UUVPLAN_SANITIZE_OPT=-O0
  export UUVPLAN_FUZZ_BUILD_DIR="${UUVPLAN_FUZZ_BUILD_DIR:-$root/build-fuzz-quick}"
fi
build="${UUVPLAN_FUZZ_BUILD_DIR:-$root/build-fuzz}"
opt="${UUVPLAN_SANITIZE_OPT:--O1}"
"$root/scripts/install-deps.sh"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# The io layer's test suites (every reader and writer, every case file, the CLI on good and
# malformed input: Cases/MalformedInput.*); only the test files that define one are compiled
# here (UUVPLAN_TEST_SUITES).
suites='Read|Write|Io|IO|Csv|Truth|Vehicle|Pool|Campaign|Cases|ScheduleJson|Cli|Malformed|WellFormed|Concurrent|Import'
# Warnings are errors in the gcc build (scripts/build.sh); clang's other warnings are not
# made errors here. -O1 (full): sanitized code at full optimisation hides little and builds
# slower. -gline-tables-only: a sanitizer report's stack has file:line; full -g costs 13-22%
# more compile time per file (docs/validation.md, "Sanitizers").
cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$opt -gline-tables-only" -DUUVPLAN_SANITIZE=ON \
  -DUUVPLAN_FUZZ=ON -DUUVPLAN_BUILD_BENCH=OFF -DUUVPLAN_TEST_SUITES="$suites" \
  "${launcher[@]}" >/dev/null
[ "$configure_only" = 1 ] && exit 0
seconds="${1:-60}"
start=$SECONDS
cmake --build "$build" -j"$(nproc)" --target uuvplan --target io_tests --target cli_tests >&2
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Not here: Cli.Demo* (the demo's 60 s wall-time budget is a release-build figure: 89 s under
# ASan), nor ScheduleInformation (it checks the planner's numbers, 8.7 s in the release build
# and 147 s under ASan; the schedule JSON it reads is ScheduleJson's). Not in --quick: the two
# CLI tests that identify or diagnose a campaign and then plan or score the model they wrote
# (66 s at -O1; a ROMEO schedule ran over 5 minutes at -O0): the vehicle file written and read
# is VehicleModelIo's, and the full stage runs them. Nor, in --quick, the five real BlueROV bags
# imported then identified twice (101 s of the stage's 149 s of tests at -O0 when ../shared is
# present): the bag reader is ImportFormats' and the fuzzers', the rest is identification.
exclude='^Cli\.Demo'
if [ "$quick" = 1 ]; then
  exclude='^(Cli\.(Demo|DiagnoseWritesTheModelAndScoreScoresIt$|IdentifyWritesTheModelAndScheduleUsesIt$)|ImportRealBags\.)'
fi
(cd "$build" && ctest -j"$(nproc)" --output-on-failure -E "$exclude" -R "^($suites)")
echo "sanitize.sh: sanitized build ($opt) and io tests took $((SECONDS - start)) s"
targets=()
if [ "$quick" = 1 ]; then
  if [ -n "${UUVPLAN_FUZZ_TARGETS:-}" ]; then
    read -r -a targets <<<"$UUVPLAN_FUZZ_TARGETS"
  else
    pairs=("csv vehicle" "pool truth" "campaign plan" "recording csv")
    turn=$(git -C "$root" rev-list --count HEAD 2>/dev/null || echo 0)
    read -r -a targets <<<"${pairs[$((turn % 4))]}"
  fi
fi
"$root/scripts/fuzz.sh" "$seconds" "${targets[@]}"
echo "sanitize.sh: total $((SECONDS - start)) s"
