#!/usr/bin/env bash
# Monte Carlo of one identification method on a case's own schedule: `schedule` of the case's
# vehicle and pool (--dof D), N campaigns `simulate`d from its truth (seeds 101…100+N), each
# identified with `--method M`; prints per parameter the mean and RMS of z = (θ̂ − θ)/σ and the
# count of 95% intervals that cover the truth (docs/validation.md, "RLS σ").
#   bench/method_coverage.sh CASE DOF N METHOD [UUVPLAN_BINARY]
#   e.g. bench/method_coverage.sh vsor yaw 20 rls
# Needs python3 with PyYAML (scripts/install-deps.sh --bench).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
case_name="$1" dof="$2" n="$3" method="$4"
uuvplan="${5:-$root/build/uuvplan}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
"$uuvplan" schedule "$root/cases/$case_name/vehicle.yaml" --pool "$root/cases/$case_name/pool.yaml" \
  --dof "$dof" --json "$dir/plan.json" >/dev/null || true  # exit 1: a DOF the pool cannot host
for ((s = 101; s < 101 + n; s++)); do
  "$uuvplan" simulate --truth "$root/cases/$case_name/truth.yaml" --plan "$dir/plan.json" \
    --out "$dir/c$s" --seed "$s" >/dev/null
  "$uuvplan" identify "$dir/c$s" --method "$method" --json "$dir/r$s.json" >/dev/null || true
done
/usr/bin/python3 - "$root/cases/$case_name/truth.yaml" "$dir" <<'PY'
import glob, json, math, sys, yaml
truth = yaml.safe_load(open(sys.argv[1]))["dofs"]
z = {}
for f in sorted(glob.glob(sys.argv[2] + "/r*.json")):
    for dof, d in json.load(open(f))["dofs"].items():
        params = truth[dof]["params"]
        for name, p in d["params"].items():
            value, sigma = p.get("value"), p.get("sigma")
            true = params.get("eta", {}).get(name[4:]) if name.startswith("eta.") else params.get(name)
            if true is None or value is None or not sigma:
                continue
            z.setdefault(dof + " " + name, []).append((value - true) / sigma)
for k, zs in sorted(z.items()):
    rms = math.sqrt(sum(x * x for x in zs) / len(zs))
    cover = sum(abs(x) < 1.959964 for x in zs)
    print(f"{k:28s} n {len(zs):3d}  mean z {sum(zs) / len(zs):+.2f}  RMS z {rms:.2f}  95% cover {cover}/{len(zs)}")
PY
