"""A plan a crew follows: the default site and a 10-building perimeter block with its gateway
marked (``town(10, seed=1, gateways="passage")``), each with the Leica RTC360 and the Leica
P50 at their defaults — the stations by purpose, the closest two set-ups, the targets, the
most standing at once against the kit, the field time. Writes the ``crew-plan`` section of
benchmarks/RESULTS.md, with the same measures of an earlier commit beside them where given.

Run: ``.venv/bin/python benchmarks/crew_plan.py [--json OUT] [--before BEFORE.json]``

``--json`` writes the measures (to compare a commit with another: run this script against
the other's tree, ``PYTHONPATH=OTHER_TREE python benchmarks/crew_plan.py --json x.json``,
with no section written).
"""

from __future__ import annotations

import argparse
import json
import subprocess
import time

import numpy as np
from _results import machine, write_section
from scipy.spatial.distance import pdist, squareform

from planner.pipeline.engine.planning import plan
from planner.scanner import load_scanner
from planner.synthetic import town

#: The kit the measures are held against (the default inventory's counts since d28a20d).
KIT = {"sphere-200": 6, "sphere-400": 2}
SITES = {
    "default site": lambda: None,
    "10-building block": lambda: town(10, seed=1, gateways="passage"),
}
SCANNERS = ("leica-rtc360", "leica-p50")


def measure(site_name: str, scanner: str) -> dict:
    """One case's measures."""
    t0 = time.perf_counter()
    p = plan(SITES[site_name](), load_scanner(scanner))
    wall = time.perf_counter() - t0
    st = p.stations[p.stations["purpose"] != "traverse"]
    d = squareform(pdist(st[["x", "y"]].to_numpy(float)))
    np.fill_diagonal(d, np.inf)
    i, j = np.unravel_index(np.argmin(d), d.shape)
    kit = p.route.kit.set_index("item")
    return {
        "site": site_name,
        "scanner": scanner,
        "stations": len(st),
        "purposes": {k: int(v) for k, v in st["purpose"].value_counts().items()},
        "closest_m": round(float(d[i, j]), 1),
        "closest": f"{st['station_id'].iloc[i]}–{st['station_id'].iloc[j]}",
        "pairs_under_5m": int((d < 5.0).sum() // 2),
        "targets": len(p.targets),
        "most_at_once": {str(k): int(r["most_at_once"]) for k, r in kit.iterrows()},
        "field_min": round(float(p.route.total_min)),
        "setup_min": float(p.route.table["setup_min"].iloc[0]),
        "met": int(p.scanned["meets"].sum()),
        "samples": len(p.scanned),
        "wall_s": round(wall, 1),
    }


def _hm(minutes: float) -> str:
    return f"{int(minutes // 60)} h {int(minutes % 60):02d}"


def _row(m: dict) -> str:
    purposes = ", ".join(f"{n} {k}" for k, n in sorted(m["purposes"].items()))
    kit = "; ".join(
        f"{item} {n}" + (f" of {KIT[item]}" if item in KIT else "")
        for item, n in sorted(m["most_at_once"].items())
    )
    return (
        f"| {m['site']} | {m['scanner']} | {m['stations']} ({purposes}) | {m['closest_m']:.1f} m "
        f"({m['closest']}); {m['pairs_under_5m']} under 5 m | {m['targets']} | {kit} | "
        f"{_hm(m['field_min'])} ({m['setup_min']:g} min a set-up) | {m['met']} of {m['samples']} |"
    )


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--json", default=None)
    ap.add_argument("--before", default=None)
    args = ap.parse_args()
    commit = subprocess.run(
        ["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True, check=False
    ).stdout.strip()
    rows = [{**measure(s, sc), "commit": commit} for s in SITES for sc in SCANNERS]
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
        if args.before is None:
            return
    head = (
        "| site | scanner | stations (by purpose) | closest set-ups | targets | most standing "
        "at once (of the kit's) | field time | samples met |"
    )
    lines = [
        "## A plan a crew follows (benchmarks/crew_plan.py)",
        "",
        machine(),
        f"`plan(site, scanner)` at the defaults, commit {commit}. The kit: the default "
        "inventory's six 200 mm and two 400 mm spheres (checkerboards printed as needed).",
        "",
        head,
        "|---|---|---|---|---|---|---|---|",
        *(_row(m) for m in rows),
    ]
    if args.before:
        with open(args.before) as f:
            before = json.load(f)
        lines += [
            "",
            f"Before (the same measures, {before[0].get('commit', 'earlier')}):",
            "",
            head,
        ]
        lines += ["|---|---|---|---|---|---|---|---|", *(_row(m) for m in before)]
    write_section("crew-plan", lines)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
