"""Large sites (issue 52), run by hand; never part of the test suite.

    .venv/bin/python benchmarks/large_sites.py --label after          # every case
    .venv/bin/python benchmarks/large_sites.py --label before --cases district-50

Cases, each planned as the ``planner plan`` command would (one process, or block by block on
a local Dask cluster of 2 workers where the site is more work than one process does well),
with the default time budget unless the case says otherwise:

- ``district-50``: 50 free-standing boxes on a 45 × 40 m grid (benchmarks/run.py's case),
  the paper's example scanner (no compensator);
- ``district-50-rtc360``: the same with the Leica RTC360 (its profile's registration);
- ``perimeter-144``: a synthetic city of 144 terraced buildings in perimeter blocks
  (:func:`planner.synthetic.town`), the paper's example scanner;
- ``scattered-49``: 49 buildings of one client in 12 groups across 3 km
  (:func:`planner.synthetic.scattered`), the paper's example scanner;
- ``cover-district-50``: the optimiser alone on district-50's recorded first cover
  (tests/data/covers), 20 s: the cover and the bound, its forced station counted.

Per case: samples, stations, the proven bound and the gap, samples met, wall time. Each
run's rows are kept under its label in benchmarks/large_sites_runs.json, and the section
``large-sites`` of benchmarks/RESULTS.md shows every label's rows side by side.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from _results import machine, write_section

RUNS = Path(__file__).resolve().parent / "large_sites_runs.json"
CASES = ["cover-district-50", "district-50", "district-50-rtc360", "perimeter-144", "scattered-49"]
#: the recorded first cover of district-50 (tests/data/covers/README.md)
COVER = Path(__file__).resolve().parent.parent / "tests" / "data" / "covers" / "district50.npz"


def site_of(case: str):
    from planner.synthetic import scattered, town

    if case.startswith("district-50"):
        import sys

        sys.path.insert(0, str(Path(__file__).parent))
        from run import build_site

        return build_site("district-50")
    if case == "perimeter-144":
        return town(144, seed=0)
    if case == "scattered-49":
        return scattered(49, 12, seed=0)
    raise SystemExit(f"unknown case {case!r}; cases: {', '.join(CASES)}")


def run_cover() -> dict:
    import numpy as np
    import scipy.sparse as sp

    from planner.pipeline.optimise.cover import solve_cover

    z = np.load(COVER)
    a = sp.csr_matrix(
        (np.ones(len(z["indices"]), dtype=bool), z["indices"], z["indptr"]), shape=tuple(z["shape"])
    )
    forced = int(z["forced"][0])
    solve_cover(a[:50], z["demand"][:50].astype(np.int64), 1.0)  # compiled before timing
    t0 = time.perf_counter()
    s = solve_cover(a, z["demand"].astype(np.int64), 20.0)
    wall = time.perf_counter() - t0
    cover, bound = s.objective + forced, float(s.lower_bound) + forced
    return {
        "case": "cover-district-50",
        "mode": f"optimiser ({s.method})",
        "buildings": 50,
        "samples": a.shape[0],
        "stations": cover,
        "cover": cover,
        "bound": bound,
        "gap_pct": 100.0 * (cover - bound) / cover,
        "met": a.shape[0],
        "wall_s": wall,
        "first_message": "",
    }


def run(case: str) -> dict:
    if case == "cover-district-50":
        return run_cover()
    from planner.pipeline.district.blocks import needs_district
    from planner.pipeline.district.schedule import plan_district
    from planner.pipeline.engine.planning import plan
    from planner.pipeline.inputs.requirements import PlanSettings, Requirements
    from planner.scanner import load_scanner

    site = site_of(case)
    scanner = load_scanner("leica-rtc360" if case.endswith("rtc360") else "leica-4mm-60urad")
    st = PlanSettings()
    district = needs_district(site, st) and case != "district-50" and "rtc360" not in case
    try:  # jobs of buildings far apart (issue 52): each its own plan, as the command does
        from planner.pipeline.district.groups import job_groups
        from planner.pipeline.district.groups import plan as jobs_or_one

        jobs = len(job_groups(site, scanner, Requirements(), st)[0]) > 1
    except ImportError:  # the code before
        jobs = False
    t0 = time.perf_counter()
    if jobs:
        p = jobs_or_one(site, scanner)
    elif district:
        p = plan_district(site, scanner, settings=st, workers=2)
    else:
        p = plan(site, scanner)
    wall = time.perf_counter() - t0
    s, cov = p.solver, p.scanned
    bound = s.lower_bound
    return {
        "case": case,
        "mode": "jobs" if jobs else "district" if district else "one process",
        "buildings": len(site.planned),
        "samples": len(cov),
        "stations": len(p.stations),
        "cover": s.objective,
        "bound": bound,
        "gap_pct": 100.0 * (s.objective - bound) / s.objective if s.objective else 0.0,
        "met": int(cov["meets"].sum()),
        "wall_s": wall,
        "first_message": next((m for m in p.messages if "group" in m.lower()), ""),
    }


def table(runs: dict) -> list[str]:
    lines = [
        "Cases as benchmarks/large_sites.py describes them; each label's rows from one run of",
        "the code at that time (`--label`).",
        "",
        "| label | case | mode | buildings | samples | stations | cover ≥ bound (gap) | met | wall |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for label, rows in runs.items():
        for r in rows:
            lines.append(
                f"| {label} | {r['case']} | {r['mode']} | {r['buildings']} | {r['samples']} | "
                f"{r['stations']} | {r['cover']} ≥ {r['bound']:.1f} ({r['gap_pct']:.1f} %) | "
                f"{r['met']} of {r['samples']} | {r['wall_s']:.0f} s |"
            )
    for label, rows in runs.items():
        lines.append("")
        lines.append(f"{label}: {rows[0].get('machine', '')}")
    return lines


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--label", required=True)
    ap.add_argument("--cases", nargs="+", default=CASES, choices=CASES)
    ap.add_argument("--no-write", action="store_true")
    a = ap.parse_args()
    runs = json.loads(RUNS.read_text()) if RUNS.exists() else {}
    rows = []
    for case in a.cases:
        r = run(case) | {"machine": machine()}
        print(json.dumps(r), flush=True)
        rows.append(r)
    old = [r for r in runs.get(a.label, []) if r["case"] not in a.cases]
    runs[a.label] = old + rows
    if not a.no_write:
        RUNS.write_text(json.dumps(runs, indent=1) + "\n")
        write_section(
            "large-sites", ["## Large sites (benchmarks/large_sites.py)", "", *table(runs)]
        )


if __name__ == "__main__":
    main()
