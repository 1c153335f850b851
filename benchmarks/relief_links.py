"""The default site's cloud links with the walls' relief, against an independent ICP.

The default site planned ``--registration cloud`` at its defaults (the parametric facade:
25 % windows, 150 mm reveals; cloud floor 1 mm) with a 40 mm scan step at 10 m (the
rehearsal's clouds small enough for the ICP). Each cloud link's two scans are rehearsed
(the openings cut into the walls: reveals return, glass does not) ``trials`` times with
their own noise, the child moved by a start error, and registered by the independent ICP
of ``tests/icp.py``. Per link: the link model's predicted σ (``cloud_link``), the ICP's
RMS error per axis and their ratio. Writes the ``relief-links`` section of
benchmarks/RESULTS.md.

Run: ``.venv/bin/python benchmarks/relief_links.py [--trials 3]``
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

from _results import machine, write_section  # noqa: E402
from icp import icp, patches_of  # noqa: E402

from planner.pipeline.engine.judge import workbench_of  # noqa: E402
from planner.pipeline.engine.planning import plan  # noqa: E402
from planner.pipeline.inputs.requirements import PlanSettings  # noqa: E402
from planner.pipeline.network.clouds import cloud_link, surfaces  # noqa: E402
from planner.pipeline.survey.rehearsal import rehearse  # noqa: E402

STEP_MM_AT_10M = 40.0
START_M = np.array([0.005, 0.005, 0.0])  # the child's start error (a coarse alignment)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--trials", type=int, default=3)
    args = ap.parse_args()
    commit = subprocess.run(
        ["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True, check=False
    ).stdout.strip()
    p = plan(settings=PlanSettings(registration="cloud", step_mm_at_10m=STEP_MM_AT_10M))
    ctx = workbench_of(p).ctx
    at = p.scan_stations.set_index("station_id")
    rows = []
    for link in p.links[p.links["kind"] == "cloud"].itertuples():
        a, b = link.station_a, link.station_b
        xy = at.loc[[a, b], ["x", "y"]].to_numpy(dtype=float)
        pred = np.sqrt(np.diag(cloud_link(ctx, surfaces(ctx, xy), 0, 1).cov)[:3])
        t = time.perf_counter()
        errors = []
        for k in range(args.trials):
            r = rehearse(p, beams_per_station=10**8, seed=200 + k, stations=[a, b])
            by = {s.station_id: s for s in r.scans}
            pa, pb = patches_of(by[a], by[b].position), patches_of(by[b], by[a].position)
            child = by[b].world_xyz[pb] + START_M
            e = icp(by[a].world_xyz[pa], child, by[b].position, iters=15)[:3] + START_M * 1000
            errors.append(e)
        sim = np.sqrt(np.mean(np.square(errors), axis=0))
        rows.append(
            f"| {a}→{b} | {link.overlap_pct:.0f} % | {', '.join(f'{v:.2f}' for v in pred)} | "
            f"{', '.join(f'{v:.2f}' for v in sim)} | "
            f"{', '.join(f'{v:.2f}' for v in sim / pred)} | "
            f"{np.sqrt((sim**2).sum() / (pred**2).sum()):.2f} |"
        )
        print(rows[-1], f"({time.perf_counter() - t:.0f} s)", flush=True)
    lines = [
        "## Cloud links with the walls' relief against an ICP (benchmarks/relief_links.py)",
        "",
        machine(),
        f"Default site, `--registration cloud` at its defaults (parametric facade 25 % / "
        f"150 mm, cloud floor 1 mm), scan step {STEP_MM_AT_10M:g} mm at 10 m, commit {commit}; "
        f"{args.trials} rehearsals per link, the child started {START_M[0] * 1000:g} mm east and "
        f"{START_M[1] * 1000:g} mm north, registered by tests/icp.py (15 iterations). "
        f"{int(p.coverage['meets'].sum())} of {len(p.scanned)} samples met.",
        "",
        "| link | overlap | predicted σ x, y, z [mm] | ICP RMS x, y, z [mm] | ratio x, y, z "
        "| ratio of the totals |",
        "|---|---|---|---|---|---|",
        *rows,
    ]
    write_section("relief-links", lines)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
