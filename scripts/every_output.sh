#!/usr/bin/env bash
# Runs every command on every case (and on the real campaigns when ../shared is present) with one
# uuvplan program and keeps what each prints and writes in DIR: NAME.stdout, NAME.stderr,
# NAME.status and the files the commands write. Used by same_outputs.sh (two programs compared)
# and no_placeholders.sh (no output holds a value that was never computed).
#
# Usage: scripts/every_output.sh PROGRAM DIR   (DIR is created; it must not exist or be empty)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
[ $# -eq 2 ] || { echo "usage: $0 PROGRAM DIR" >&2; exit 2; }
UUVPLAN="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
mkdir -p "$2"
[ -z "$(ls -A "$2")" ] || { echo "$2: not empty" >&2; exit 2; }
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
  # BlueROV2 (geometry-derived mappings, a dead band): one DOF, as planning all four takes ~50 s.
  local b="$c/bluerov2"
  run bluerov2-schedule schedule "$b/vehicle.yaml" --pool "$b/pool.yaml" --dof surge \
    --json bluerov2-plan.json --commands bluerov2-commands
  run bluerov2-simulate simulate --truth "$b/truth.yaml" --plan bluerov2-plan.json \
    --out bluerov2-run --seed 1 --json bluerov2-simulate.json
  run bluerov2-identify identify bluerov2-run/campaign.yaml --json bluerov2-identify.json
  run bluerov2-diagnose diagnose bluerov2-run/campaign.yaml --json bluerov2-diagnose.json \
    --write-vehicle bluerov2-extended.yaml
  run bluerov2-score score bluerov2-extended.yaml bluerov2-run/campaign.yaml \
    --json bluerov2-score.json
  # log: a retry of a planned trial (another run's log) appended to a copy of a campaign.
  cp -r romeo-run romeo-log-run
  run romeo-simulate-retry simulate --truth "$c/romeo/truth.yaml" --plan romeo-plan.json \
    --out romeo-retry-run --seed 2
  local first_trial
  first_trial=$(ls romeo-run/trials | head -1)
  run romeo-log log romeo-log-run/campaign.yaml "romeo-retry-run/trials/$first_trial" \
    --trial again --plan romeo-plan.json --planned "${first_trial%.csv}"
  if [ -d "$shared" ]; then
    for campaign in bluerov-yaw-2016/campaign_all.yaml tartan-pool-2022/campaign.yaml; do
      local name="${campaign%%/*}"
      run "$name-identify" identify "$shared/$campaign" --json "$name-identify.json"
      run "$name-diagnose" diagnose "$shared/$campaign" --json "$name-diagnose.json"
    done
    run bluerov-import import "$shared/bluerov-yaw-2016/bags" --map "$c/bluerov-2016/import.yaml" \
      --out bluerov-import --json bluerov-import.json
    run bluerov-import-identify identify bluerov-import/campaign.yaml \
      --json bluerov-import-identify.json
  fi
}

cd "$2" && run_all
