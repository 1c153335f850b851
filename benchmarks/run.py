"""Benchmarks of the planner (run by hand; never part of the test suite).

    .venv/bin/python benchmarks/run.py            # all cases, writes benchmarks/RESULTS.md
    .venv/bin/python benchmarks/run.py --case default
    .venv/bin/python benchmarks/run.py --case district-50 --time-limit-s 30 --no-write

Measures, each case in a fresh subprocess (so peak memory is the case's own):
candidate × sample evaluations per second, end-to-end plan time, peak resident memory.
Targets: default site <= 1 s, district of 50 buildings <= 60 s, evaluation >= 20 million
pairs per second on one core; the district's station count proven optimal or within 2 % of
a real lower bound in <= 20 s of optimisation. Two 50-building districts: a grid of 50
free-standing boxes (``district-50``) and the synthetic city's 50 buildings (``town-50``:
terraced blocks with shared walls and courtyards, :func:`planner.synthetic.town`).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

from _results import machine, write_section

HERE = Path(__file__).resolve().parent
CASES = ["default", "large-courtyard", "district-50", "town-50"]


def build_site(case: str):
    import numpy as np
    from shapely.geometry import Polygon, box

    from planner.site import Building, Site
    from planner.siteio import default_site

    if case == "default":
        return default_site()
    e0, n0 = 400_000.0, 5_600_000.0
    if case == "large-courtyard":
        # 150 × 100 m block, 18 m high, an L-shaped notch and a 90 × 50 m courtyard
        outer = [(0, 0), (150, 0), (150, 70), (120, 70), (120, 100), (0, 100)]
        hole = [(30, 25), (30, 75), (105, 75), (105, 25)]
        poly = Polygon([(e0 + x, n0 + y) for x, y in outer], [[(e0 + x, n0 + y) for x, y in hole]])
        return Site([Building("block", poly, 18.0)], name=case)
    if case == "town-50":  # the synthetic city: terraces, shared walls, courtyards
        from planner.synthetic import town

        return town(50, seed=0)
    if case == "district-50":
        rng = np.random.default_rng(50)
        blds = []
        for i in range(50):
            row, col = divmod(i, 10)
            x0, y0 = col * 45.0, row * 40.0
            w, d = rng.uniform(15, 30), rng.uniform(10, 22)
            blds.append(
                Building(
                    f"b{i:02d}",
                    box(e0 + x0, n0 + y0, e0 + x0 + w, n0 + y0 + d),
                    float(rng.uniform(9, 25)),
                )
            )
        return Site(blds, name=case)
    raise SystemExit(f"unknown case {case!r}; cases: {', '.join(CASES)}")


def run_case(case: str, time_limit_s: float | None = None) -> dict:
    """Run one case in this process and return its measurements."""
    import numpy as np

    from planner.pipeline.engine.planning import plan
    from planner.pipeline.evaluation.evaluate import Context, evaluate_candidates
    from planner.pipeline.geometry.candidates import candidate_grid
    from planner.pipeline.geometry.facades import build_facades
    from planner.pipeline.inputs.requirements import PlanSettings, Requirements
    from planner.pipeline.inputs.resolved import reach_m
    from planner.scanner import Scanner

    site = build_site(case)
    sc = Scanner.from_name("leica-4mm-60urad")
    req = Requirements(max_xy_mm=5.0, max_z_mm=5.0)
    st = PlanSettings() if time_limit_s is None else PlanSettings(time_limit_s=time_limit_s)
    t0 = time.perf_counter()
    p = plan(site, sc, req, st)
    total = time.perf_counter() - t0
    # evaluation throughput, measured on its own (a second pass, same inputs)
    fac = build_facades(site, st.sample_spacing_m, st.sample_height_step_m)
    reach = reach_m(sc, req, st)
    cand = candidate_grid(site, fac, reach, st.grid_m, st.clearance_m)
    ctx = Context.build(site, fac, sc, req, st, reach)
    pairs = sum(
        len(ctx.front_candidates(f, cand)) * len(ctx.samples_of[f]) for f in range(fac.n_facades)
    )
    t1 = time.perf_counter()
    evaluate_candidates(ctx, cand)
    t_eval = time.perf_counter() - t1
    rss_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return {
        "case": case,
        "buildings": len(site.planned),
        "facades": int(fac.n_facades),
        "samples": len(fac.z),
        "candidates": len(cand),
        "pairs": int(pairs),
        "eval_s": t_eval,
        "pairs_per_s": pairs / t_eval,
        "plan_s": total,
        "stages_s": {k: round(v, 3) for k, v in p.timings_s.items()},
        "stations": len(p.stations),
        "solver": f"{p.solver.method} ({p.solver.status})",
        "optimum": f"{p.solver.objective} ≥ {p.solver.lower_bound:g} (gap {100 * p.solver.gap:.1f} %)",
        "reductions": f"{p.solver.reductions}; {p.solver.parts} part(s)",
        "unmet": len(p.unmet),
        "peak_rss_mb": rss_mb,
        "np": np.__version__,
    }


def main() -> None:
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--case", choices=CASES)
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--no-write", action="store_true", help="do not update RESULTS.md")
    ap.add_argument(
        "--time-limit-s", type=float, help="the plan's time limit (default: PlanSettings')"
    )
    args = ap.parse_args()
    if args.child:
        print(json.dumps(run_case(args.case, args.time_limit_s)))
        return
    if args.time_limit_s is not None and not args.no_write:
        ap.error("--time-limit-s measures another budget than the table's: add --no-write")
    results = []
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", MKL_NUM_THREADS="1")
    for case in [args.case] if args.case else CASES:
        out = subprocess.run(
            [sys.executable, __file__, "--case", case, "--child"]
            + ([] if args.time_limit_s is None else ["--time-limit-s", str(args.time_limit_s)]),
            env=env,
            capture_output=True,
            text=True,
            check=True,
        )
        r = json.loads(out.stdout.strip().splitlines()[-1])
        results.append(r)
        print(
            f"{case:16s} plan {r['plan_s']:6.2f} s  eval {r['pairs'] / 1e6:7.2f} M pairs "
            f"in {r['eval_s']:5.2f} s = {r['pairs_per_s'] / 1e6:5.1f} M/s  peak {r['peak_rss_mb']:6.0f} MB  "
            f"stations {r['stations']:3d} ({r['solver']}) unmet {r['unmet']}  stages {r['stages_s']}"
        )
    if not args.no_write:
        lines = [
            "## Single process (benchmarks/run.py)",
            "",
            f"{machine()}; one thread.",
            "Requirements 5 mm / 5 mm, scanner leica-4mm-60urad, default settings (grid 2 m, samples 2 m × 2 m).",
            "",
            "| case | buildings | samples | candidates | pairs evaluated | evaluation | pairs/s | plan end-to-end | peak RSS | stations | samples met | solver | fewest by the scanner ≥ proven bound |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|",
        ]
        for r in results:
            lines.append(
                f"| {r['case']} | {r['buildings']} | {r['samples']} | {r['candidates']} | "
                f"{r['pairs'] / 1e6:.2f} M | {r['eval_s']:.2f} s | {r['pairs_per_s'] / 1e6:.1f} M/s | "
                f"{r['plan_s']:.2f} s | {r['peak_rss_mb']:.0f} MB | {r['stations']} | {r['samples'] - r['unmet']} | {r['solver']} | {r['optimum']} |"
            )
        lines += ["", "Stage times (s):", ""]
        lines += [f"- {r['case']}: {r['stages_s']}" for r in results]
        lines += ["", "Set-cover reductions (first choice of stations):", ""]
        lines += [f"- {r['case']}: {r['reductions']}" for r in results]
        lines += ["", "Targets: default <= 1 s, district <= 60 s, >= 20 M pairs/s."]
        write_section("cases", lines)


if __name__ == "__main__":
    main()
