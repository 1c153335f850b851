"""What the walls are made of: the default site and a 50-building town planned with the
Leica RTC360 with no material known (the datasheet's reference surface), in dark brick,
with glass curtain walls, dry and wet; and the default site registered cloud to cloud with
plain walls and with the parametric facade's reveals. Stations, samples met of those
demanded, samples not demanded (glass), what the other survey day costs, plan time.
Writes the ``materials`` section of benchmarks/RESULTS.md.

Run: ``.venv/bin/python benchmarks/materials.py [--quick]`` (``--quick``: the default site
only).
"""

from __future__ import annotations

import argparse
import subprocess
import time
from dataclasses import replace

import numpy as np
from _results import machine, write_section

from planner.pipeline.engine.conditions import condition_sensitivity
from planner.pipeline.engine.planning import plan
from planner.pipeline.inputs.requirements import PlanSettings
from planner.scanner import load_scanner
from planner.siteio import default_site
from planner.synthetic import town
from planner.zones import parse_zone

SCANNER = "leica-rtc360"


def _mixed(site, seed: int = 2):
    """Every building a material: a tenth glass curtain walls, the rest plaster, red brick
    or dark brick in equal shares (drawn with ``seed``)."""
    rng = np.random.default_rng(seed)
    kinds = rng.choice(
        ["plaster", "brick", "brick-dark", "glass"], len(site.buildings), p=[0.3, 0.3, 0.3, 0.1]
    )
    return replace(
        site,
        buildings=[replace(b, material=str(k)) for b, k in zip(site.buildings, kinds, strict=True)],
    )


def _glass_front(site):
    """The default site's main building with its longest street facade a curtain wall."""
    return replace(site, zones=[*site.zones, parse_zone("facade=main-f10,material=glass", "cw")])


CASES = [
    # (site name, site, settings, what)
    ("default site", default_site, {}, "no material known"),
    ("default site", default_site, {"default_material": "brick-dark"}, "dark brick, dry"),
    (
        "default site",
        default_site,
        {"default_material": "brick-dark", "surface_condition": "wet"},
        "dark brick, wet",
    ),
    (
        "default site",
        lambda: _glass_front(default_site()),
        {"default_material": "brick"},
        "red brick, main-f10 a curtain wall",
    ),
    (
        "default site",
        default_site,
        {"registration": "cloud", "window_share": 0.0},
        "cloud to cloud, plain walls",
    ),
    (
        "default site",
        default_site,
        {"registration": "cloud"},
        "cloud to cloud, reveals (25 % windows, 0.15 m)",
    ),
    ("50-building town", lambda: town(50, seed=1), {}, "no material known"),
    (
        "50-building town",
        lambda: _mixed(town(50, seed=1)),
        {},
        "mixed: plaster, brick, dark brick, 10 % glass; dry",
    ),
    (
        "50-building town",
        lambda: _mixed(town(50, seed=1)),
        {"surface_condition": "wet"},
        "the same, wet",
    ),
]


def measure(site_name, make, options, what) -> dict:
    site = make()
    t0 = time.perf_counter()
    p = plan(site, load_scanner(SCANNER), settings=PlanSettings(**options))
    wall = time.perf_counter() - t0
    other = "dry" if options.get("surface_condition") == "wet" else "wet"
    day = condition_sensitivity(p, other)
    glass = next((m for m in p.messages if m.startswith("Not demanded")), "")
    return {
        "site": site_name,
        "what": what,
        "stations": int((p.stations["purpose"] != "traverse").sum()),
        "met": int(p.scanned["meets"].sum()),
        "samples": len(p.scanned),
        "not_demanded": int(glass.split()[2]) if glass else 0,
        "other_day": None if day is None else f"{other}: {day[0]} of {day[1]}",
        "links": p.links["kind"].value_counts().to_dict() if len(p.links) else {},
        "wall_s": round(wall, 1),
    }


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    commit = subprocess.run(
        ["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True, check=False
    ).stdout.strip()
    rows = []
    for case in CASES:
        if args.quick and case[0] != "default site":
            continue
        rows.append(measure(*case))
        print(rows[-1], flush=True)
    lines = [
        "## What the walls are made of (benchmarks/materials.py)",
        "",
        machine(),
        f"`plan(site, leica-rtc360, PlanSettings(...))`, commit {commit}, the default time "
        "budget. 'Other day': the same stations and registration judged on the other survey "
        "day (samples met then, of those met as planned).",
        "",
        "| site | walls | stations | samples met | not demanded (glass) | other day | links "
        "| plan time |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        links = ", ".join(f"{n} {k}" for k, n in sorted(r["links"].items())) or "—"
        lines.append(
            f"| {r['site']} | {r['what']} | {r['stations']} | {r['met']} of {r['samples']} | "
            f"{r['not_demanded']} | {r['other_day'] or '—'} | {links} | {r['wall_s']:.1f} s |"
        )
    write_section("materials", lines)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
