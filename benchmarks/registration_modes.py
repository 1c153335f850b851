"""Registration by targets, cloud to cloud and hybrid on three sites: the default site, a
10-building perimeter block with its gateway marked, and a single straight street (two
150 m terraces facing each other across 15 m). Default scanner, 6/8 mm. Writes the
``registration-modes`` section of benchmarks/RESULTS.md.

Run: ``.venv/bin/python benchmarks/registration_modes.py``
"""

from __future__ import annotations

import time

import numpy as np
from _results import machine, write_section
from shapely.geometry import box

from planner.pipeline.engine.planning import plan
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.site import Building, Site
from planner.synthetic import town

E0, N0 = 500_000.0, 5_400_000.0


def street() -> Site:
    rows = [
        Building("north", box(E0, N0 + 25, E0 + 150, N0 + 35), 15.0),
        Building("south", box(E0, N0, E0 + 150, N0 + 10), 15.0),
    ]
    return Site(rows, crs="EPSG:25833")


def main() -> None:
    sites = {
        "default site": None,
        "10-building block (gateway marked)": town(10, seed=1, gateways="passage"),
        "straight street": street(),
    }
    req = Requirements(max_xy_mm=6.0, max_z_mm=8.0)
    lines = [
        "## Registration by targets, cloud to cloud and hybrid (benchmarks/registration_modes.py)",
        "",
        machine(),
        "`plan(site, requirements=6/8 mm, settings=PlanSettings(registration=MODE))`, default scanner. "
        "Worst link: the link with the largest own error (overlap of its two scans, its "
        "predicted RMS at the child's facade points, the direction that error is largest in).",
        "",
        "| site | mode | stations | targets | samples met | untied | cloud links | worst link "
        "| wall |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for name, site in sites.items():
        for mode in ("targets", "cloud", "hybrid"):
            t0 = time.perf_counter()
            p = plan(site, requirements=req, settings=PlanSettings(registration=mode))
            wall = time.perf_counter() - t0
            lk = p.links
            worst = ""
            if len(lk):
                w = lk.loc[lk["link_rms_mm"].idxmax()]
                ov = f"{w['overlap_pct']:.0f} %" if np.isfinite(w["overlap_pct"]) else "n/a"
                worst = (
                    f"{w['station_a']}→{w['station_b']} ({w['kind']}, overlap {ov}, "
                    f"{w['link_rms_mm']:.2f} mm, {w['weakest_direction']})"
                )
            untied = sum("cannot be tied" in m for m in p.messages)
            met = int(p.coverage["meets"][~p.coverage["party_wall"]].sum())
            n = int((~p.coverage["party_wall"]).sum())
            row = (
                f"| {name} | {mode} | {len(p.stations)} | {len(p.targets)} | {met} of {n} | "
                f"{'yes' if untied else 'no'} | {int((lk['kind'] == 'cloud').sum())} | {worst} | "
                f"{wall:.1f} s |"
            )
            print(row, flush=True)
            lines.append(row)
    write_section("registration-modes", lines)


if __name__ == "__main__":
    main()
