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

# run NAME ARGS...: one command, its stdout, stderr and exit status kept under NAME.
run() {
  local name="$1"; shift
  local out="$PWD/$name"
  "$UUVPLAN" "$@" >"$out.stdout" 2>"$out.stderr" && echo 0 >"$out.status" ||
    echo $? >"$out.status"
}

# The whole set, in the current directory, with the program $UUVPLAN.
run_all() {
  local c="$root/cases"
  # The DOFs each case's truth gives parameters for (the virtual pool runs only those).
  local -A truth_dofs=([romeo]="" [payload60]="" [uris]="--dof surge" [vsor]="--dof yaw --dof heave")
  for case in romeo payload60 uris vsor; do
    local v="$c/$case/vehicle.yaml" p="$c/$case/pool.yaml" t="$c/$case/truth.yaml"
    run "$case-schedule-all" schedule "$v" --pool "$p" --json "$case-plan-all.json"
    run "$case-check-pool-all" check-pool "$v" --pool "$p" --plan "$case-plan-all.json" \
      --json "$case-check-all.json"
    # shellcheck disable=SC2086
    run "$case-schedule" schedule "$v" --pool "$p" ${truth_dofs[$case]} --json "$case-plan.json" \
      --commands "$case-commands"
    run "$case-simulate" simulate --truth "$t" --plan "$case-plan.json" --out "$case-run" --seed 1 \
      --json "$case-simulate.json"
    run "$case-identify" identify "$case-run/campaign.yaml" --json "$case-identify.json"
    run "$case-diagnose" diagnose "$case-run/campaign.yaml" --json "$case-diagnose.json" \
      --write-vehicle "$case-extended.yaml"
    run "$case-score" score "$case-extended.yaml" "$case-run/campaign.yaml" --json "$case-score.json"
    run "$case-next" next "$case-run/campaign.yaml" --pool "$p" --json "$case-next.json"
  done
  run romeo-report report romeo-run/campaign.yaml --out romeo-report
  run romeo-loop loop --truth "$c/romeo/truth.yaml" --pool "$c/romeo/pool.yaml" --dof surge \
    --seed 3 --json romeo-loop.json
  run asv-schedule schedule "$c/asv/vehicle.yaml" --pool "$c/asv/pool.yaml" --model coupled \
    --json asv-plan.json
  run asv-simulate simulate --truth "$c/asv/truth.yaml" --plan asv-plan.json --out asv-run --seed 1
  run asv-identify identify asv-run/campaign.yaml --model coupled --json asv-identify.json
  run demo demo --out demo-run --seed 1
  if [ -d "$shared" ]; then
    for campaign in bluerov-yaw-2016/campaign_all.yaml tartan-pool-2022/campaign.yaml; do
      local name="${campaign%%/*}"
      run "$name-identify" identify "$shared/$campaign" --json "$name-identify.json"
      run "$name-diagnose" diagnose "$shared/$campaign" --json "$name-diagnose.json"
    done
  fi
}

for side in ref new; do
  mkdir -p "$work/$side"
  if [ "$side" = ref ]; then export UUVPLAN="$ref"; else export UUVPLAN="$new"; fi
  (cd "$work/$side" && run_all)
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
