#!/usr/bin/env bash
# Runs every command on every case (and on the real campaigns when ../shared is present) with
# two uuvplan programs and compares what they print and write, byte for byte: a refactoring
# changes no output. The reference is a git revision, built once into build-ref/<rev> from a
# worktree, or an existing program.
#
# Usage: scripts/same_outputs.sh [REV | --ref PROGRAM] [--new PROGRAM] [--keep DIR]
#   REV        the revision to compare with (default: HEAD)
#   --ref P    compare with program P instead of building REV
#   --new P    the program under test (default: build/uuvplan, built by scripts/build.sh)
#   --keep D   leave both runs' outputs in D/ref and D/new
# Exit 0 when every output agrees, 1 when one differs (the differences are printed).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
rev=HEAD ref="" new="" keep=""
while [ $# -gt 0 ]; do
  case "$1" in
    --ref) ref="$2"; shift 2 ;;
    --new) new="$2"; shift 2 ;;
    --keep) keep="$2"; shift 2 ;;
    *) rev="$1"; shift ;;
  esac
done

if [ -z "$new" ]; then
  "$root/scripts/build.sh" --target uuvplan
  new="$root/build/uuvplan"
fi
if [ -z "$ref" ]; then
  sha=$(git -C "$root" rev-parse --short "$rev")
  ref_dir="$root/build-ref/$sha"
  if [ ! -x "$ref_dir/build/uuvplan" ]; then
    rm -rf "$ref_dir/src"
    mkdir -p "$ref_dir"
    git -C "$root" archive "$sha" | tar -x -C "$ref_dir" --one-top-level=src
    UUVPLAN_BUILD_DIR="$ref_dir/build" "$ref_dir/src/scripts/build.sh" --target uuvplan
  fi
  ref="$ref_dir/build/uuvplan"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
shared="$root/../shared/data"

for side in ref new; do
  if [ "$side" = ref ]; then program="$ref"; else program="$new"; fi
  "$root/scripts/every_output.sh" "$program" "$work/$side"
done
[ -d "$shared" ] || echo "same_outputs: ../shared absent: the real campaigns are not compared"

# Paths name the run's own directory; the comparison is of everything else.
status=0
while IFS= read -r f; do
  if ! diff -q <(sed "s#$work/ref#RUN#g" "$work/ref/$f") <(sed "s#$work/new#RUN#g" "$work/new/$f") \
      >/dev/null 2>&1; then
    echo "differs: $f"
    diff <(sed "s#$work/ref#RUN#g" "$work/ref/$f") <(sed "s#$work/new#RUN#g" "$work/new/$f") |
      head -20 || true
    status=1
  fi
done < <(cd "$work/ref" && find . -type f | sort)
missing=$(diff <(cd "$work/ref" && find . -type f | sort) <(cd "$work/new" && find . -type f | sort) || true)
if [ -n "$missing" ]; then
  echo "the two runs wrote different files:"; echo "$missing"; status=1
fi
count=$(cd "$work/ref" && find . -type f | wc -l)
if [ -n "$keep" ]; then mkdir -p "$keep"; cp -r "$work/ref" "$work/new" "$keep/"; fi
[ "$status" = 0 ] && echo "same_outputs: all $count outputs identical"
exit "$status"
