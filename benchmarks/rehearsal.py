"""The rehearsal and the re-plan, measured (run by hand; never part of the test suite).

    .venv/bin/python benchmarks/rehearsal.py [--trials 16]

1. **Simulated clouds**: for the default site and a 10-building perimeter block
   (``planner.synthetic.town(10)``), the plan's scans simulated at the default beams per
   station and written as E57 and LAZ: points, file sizes, seconds per station.
2. **Re-plan**: the default site with S02 and S09 moved 3 m and S05 skipped — the extra
   stations and the seconds ``replan`` takes (target: under 5 s).
3. **ICP agreement**: the default site planned ``--registration cloud`` at a 60 mm step
   with no patch floor (``cloud_floor_mm = 0``: the simulation has no roughness); every
   cloud link's two scans rehearsed ``trials`` times at that step and registered by the
   independent ICP of ``tests/icp.py``; per axis, the RMS of the ICP's shift errors against
   the link model's predicted σ (``planner.pipeline.network.clouds.cloud_link``), and the same
   with noise-free clouds (the negative control: the check can fail).

Results: the ``rehearsal`` section of benchmarks/RESULTS.md.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

from _results import machine, write_section  # noqa: E402
from icp import link_errors  # noqa: E402

from planner.pipeline.engine.judge import workbench_of  # noqa: E402
from planner.pipeline.engine.planning import plan  # noqa: E402
from planner.pipeline.geometry.scene import Scene  # noqa: E402
from planner.pipeline.inputs.requirements import PlanSettings  # noqa: E402
from planner.pipeline.network.clouds import cloud_link, surfaces  # noqa: E402
from planner.pipeline.survey.asscanned import replan  # noqa: E402
from planner.pipeline.survey.pointclouds import e57_bytes, laz_bytes  # noqa: E402
from planner.pipeline.survey.rehearsal import DEFAULT_BEAMS_PER_STATION, rehearse  # noqa: E402
from planner.synthetic import town  # noqa: E402


def clouds() -> list[str]:
    rows = [
        "| site | stations | beams per station | step at 10 m | points | simulate | per station | "
        "E57 | LAZ | write E57 + LAZ |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for name, site in (("default", None), ("block-10", town(10, seed=1))):
        p = plan(site) if site is not None else plan()
        scene = Scene(p.site, "rays")
        t = time.perf_counter()
        r = rehearse(p, scene=scene)
        sim = time.perf_counter() - t
        t = time.perf_counter()
        e57, laz = e57_bytes(r), laz_bytes(r)
        write = time.perf_counter() - t
        n = len(r.scans)
        rows.append(
            f"| {name} | {n} | {DEFAULT_BEAMS_PER_STATION:,} | {r.step_mm_at_10m:.1f} mm | "
            f"{r.n_points / 1e6:.2f} M | {sim:.1f} s | {sim / n:.2f} s | {len(e57) / 1e6:.0f} MB | "
            f"{len(laz) / 1e6:.0f} MB | {write:.1f} s |"
        )
        print(rows[-1], flush=True)
    return rows


def replanning() -> list[str]:
    p = plan()
    st = p.scan_stations[["station_id", "x", "y"]].copy()
    st = st[st["station_id"] != "S05"].copy()
    st.loc[st["station_id"] == "S02", "x"] += 3.0
    st.loc[st["station_id"] == "S09", "y"] += 3.0
    t = time.perf_counter()
    r = replan(p, st)
    took = time.perf_counter() - t
    lines = [
        "",
        f"Re-plan (default site; S02 and S09 moved 3 m, S05 skipped): {took:.2f} s (target < 5 s).",
        "",
        "```",
        r.summary(),
        "```",
    ]
    print("\n".join(lines), flush=True)
    return lines


def agreement(trials: int) -> list[str]:
    st = PlanSettings(registration="cloud", cloud_floor_mm=0.0, step_mm_at_10m=60.0)
    p = plan(settings=st)
    ctx = workbench_of(p).ctx
    at = p.scan_stations.set_index("station_id")
    rows = [
        "",
        f"ICP agreement: default site, --registration cloud, step 60 mm at 10 m, cloud floor "
        f"0 mm; {trials} trials per link (tests/icp.py).",
        "",
        "| link | overlap | predicted σ x, y, z [mm] | ICP RMS x, y, z [mm] | ratio x, y, z | "
        "ratio of the totals | typical (median) ratio | noise-free ICP, largest [mm] |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for link in p.links[p.links["kind"] == "cloud"].itertuples():
        a, b = link.station_a, link.station_b
        xy = at.loc[[a, b], ["x", "y"]].to_numpy(dtype=float)
        model = cloud_link(ctx, surfaces(ctx, xy), 0, 1)
        pred = np.sqrt(np.diag(model.cov)[:3])
        t = time.perf_counter()
        e = link_errors(p, a, b, trials)[:, :3]
        zero = np.abs(link_errors(p, a, b, 1, noise=False)[:, :3]).max()
        sim = np.sqrt((e**2).mean(axis=0))
        total = np.sqrt((e**2).sum(axis=1).mean() / (pred**2).sum())
        # the median |error| against a 3-D normal's (0.888 σ): the ICP's typical trial
        typical = np.median(np.linalg.norm(e, axis=1)) / (0.888 * np.sqrt((pred**2).sum()))
        rows.append(
            f"| {a}→{b} | {link.overlap_pct:.0f} % | {', '.join(f'{v:.3f}' for v in pred)} | "
            f"{', '.join(f'{v:.3f}' for v in sim)} | "
            f"{', '.join(f'{v:.2f}' for v in sim / pred)} | {total:.2f} | {typical:.2f} | "
            f"{zero:.4f} |"
        )
        print(rows[-1], f"({time.perf_counter() - t:.0f} s)", flush=True)
    return rows


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--trials", type=int, default=16)
    args = ap.parse_args()
    lines = ["## Rehearsal and re-plan (benchmarks/rehearsal.py)", "", machine() + ".", ""]
    lines += clouds()
    lines += replanning()
    lines += agreement(args.trials)
    write_section("rehearsal", lines)


if __name__ == "__main__":
    main()
