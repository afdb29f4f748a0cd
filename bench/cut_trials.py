#!/usr/bin/python3
"""Cuts the one trial of a campaign into N trials of equal rows (docs/performance.md, "100 trials
of 3,000 rows"): each from its own t = 0 (times as exact decimals), its first row given the
force in force then, its campaign start the cut's time.

    bench/position_identify_bench --write SRC --rows 300000
    python3 bench/cut_trials.py SRC 100 DEST
"""
import pathlib
import shutil
import sys
from decimal import Decimal


def main(src, pieces, dest):
    src, dest = pathlib.Path(src), pathlib.Path(dest)
    lines = next((src / "trials").glob("*.csv")).read_text().split("\n")
    head, rows = lines[:2], [line for line in lines[2:] if line]
    (dest / "trials").mkdir(parents=True)
    shutil.copy(src / "vehicle.yaml", dest / "vehicle.yaml")
    campaign = ["vehicle: vehicle.yaml", "trials:"]
    per = len(rows) // pieces
    force = None
    for k in range(pieces):
        chunk = rows[k * per:(k + 1) * per]
        t0 = Decimal(chunk[0].split(",")[0])
        out = []
        for j, row in enumerate(chunk):
            t, f, p = row.split(",")
            force = f or force
            out.append(f"{format((Decimal(t) - t0).normalize(), 'f')},{force if j == 0 else f},{p}")
        (dest / "trials" / f"t{k:03d}.csv").write_text("\n".join(head + out) + "\n")
        campaign += [f"  - file: trials/t{k:03d}.csv", "    dof: surge", "    mapping: surge-front",
                     "    use: fit", f"    start: {format(t0.normalize(), 'f')}"]
    (dest / "campaign.yaml").write_text("\n".join(campaign) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit("usage: cut_trials.py SRC_CAMPAIGN_DIR PIECES DEST_DIR")
    main(sys.argv[1], int(sys.argv[2]), sys.argv[3])
