"""The plan's promise against a virtual survey (tests/virtual_survey.py): the default plan
and a 10-building perimeter block (``town(10, seed=0)``, grid 3 m, samples every 3 m),
default scanner and requirement (5 mm), every station tilted (the datum's too), every
target scanned point by point and fitted, targets hidden by placed spheres left out, the
scans adjusted together with the datum's frame held. Writes the ``virtual-survey`` section
of benchmarks/RESULTS.md; ``--record FILE`` also writes the numbers as JSON, and the
section shows those of ``virtual_survey_before.json`` (the same survey of the plans made
before the datum's levelling and the target-centre terms) beside them.

Run: ``.venv/bin/python benchmarks/virtual_survey.py [--trials 400] [--record FILE]``
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

from _results import machine, write_section  # noqa: E402
from virtual_survey import report, survey, world_of  # noqa: E402

from planner.pipeline.engine.planning import plan  # noqa: E402
from planner.pipeline.inputs.requirements import PlanSettings  # noqa: E402
from planner.synthetic import town  # noqa: E402

BEFORE = HERE / "virtual_survey_before.json"


def run(trials: int) -> dict:
    from planner.cityio import footprints_of, site_from_cityjson
    from planner.siteio import site_from_geojson
    from planner.synthetic3d import lod2_town

    model = site_from_cityjson(lod2_town(8, seed=0))  # the world of the last two
    drawn = site_from_geojson(footprints_of(model))
    sites = {
        "default site": (lambda: plan(), None),
        "10-building block": (
            lambda: plan(town(10, seed=0), settings=PlanSettings(grid_m=3.0, sample_spacing_m=3.0)),
            None,
        ),
        "LoD2 town (8), planned from the model": (lambda: plan(model), model),
        "LoD2 town (8), planned from footprints": (lambda: plan(drawn), model),
    }
    out = {}
    for name, (make, world) in sites.items():
        t0 = time.perf_counter()
        p = make()
        planned = time.perf_counter() - t0
        w = world_of(p, world)
        t0 = time.perf_counter()
        r = report(survey(w, trials=trials, seed=0))
        r |= {
            "stations": len(p.stations),
            "targets": len(p.targets),
            "plan_s": round(planned, 1),
            "survey_s": round(time.perf_counter() - t0, 1),
            "trials": trials,
        }
        out[name] = r
        print(name, r, flush=True)
    return out


def _rows(label: str, results: dict) -> list[str]:
    def f(v):
        return " / ".join(f"{x:.2f}" for x in v)

    return [
        f"| {label} | {site} | {r['stations']} | {r['met']} of {r['samples']} | "
        f"{r['false_meets_3se']} ({r['false_meets_any']}) | {r['hidden']} | "
        f"{r.get('unreached_met', '')} | {f(r['median'])} | "
        f"{f(r['p95'])} | {f(r['reg_median'])} | {f(r['reg_p95'])} | {r['survey_s']} s |"
        for site, r in results.items()
    ]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--trials", type=int, default=400)
    ap.add_argument("--record", type=Path)
    args = ap.parse_args()
    results = run(args.trials)
    if args.record:
        args.record.write_text(json.dumps(results, indent=1))
    lines = [
        "## The promise against a virtual survey (benchmarks/virtual_survey.py)",
        "",
        machine(),
        f"{args.trials} trials of the frame (tilts, target points, adjustment), 20 000 of "
        "the point noise. False meets: samples marked met whose simulated RMS exceeds a limit "
        "by more than 3 standard errors of the simulation (in brackets: by anything). Ratios: "
        "simulated / promised RMS at the samples marked met, m_x / m_y / m_z; reg: the "
        "registration part alone. The LoD2 town's world is its 3-D model: a met sample whose "
        "beam, cast by the survey's own rays from its station, meets something before it or "
        "no wall where the plan puts one is unreached (a false meet).",
        "",
        "| code | site | stations | met | false meets | hidden sights | met samples unreached "
        "| median | p95 | reg median | reg p95 | survey |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    if BEFORE.exists():
        lines += _rows("before", json.loads(BEFORE.read_text()))
    lines += _rows("now", results)
    write_section("virtual-survey", lines)


if __name__ == "__main__":
    main()
