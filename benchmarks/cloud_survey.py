"""The promise of plans registered cloud to cloud, hybrid and by targets against an
independent virtual survey (tests/virtual_survey.py with tests/cloud_survey.py): every cloud
link's two scans simulated in the plan's scene and registered by an ICP the planner does not
use (tests/icp.py) from the scanner's pre-alignment, the network adjusted with those links
and the targets (and, beside it, registered pair by pair), every sample's error against its
limits. Per link: the ICP's largest RMS at the child's facade points over the plan's
predicted link error. Writes the ``cloud-survey`` section of benchmarks/RESULTS.md.

Run: ``.venv/bin/python benchmarks/cloud_survey.py [--samples 12] [--trials 200]``
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
from cloud_survey import surveyed  # noqa: E402
from virtual_survey import report, survey, world_of  # noqa: E402

from planner.pipeline.engine.planning import plan  # noqa: E402
from planner.pipeline.inputs.requirements import PlanSettings  # noqa: E402
from planner.synthetic import town  # noqa: E402


def link_ratios(w, p) -> list[float]:
    """Per cloud link: the surveyed RMS at the child's facade points (largest over points
    and axes) over the plan's predicted link error (links.csv ``link_rms_mm``)."""
    out = []
    links = p.links.set_index(["station_a", "station_b"])
    for (i, j), e in w.cloud_errors.items():
        pts = w.xyz[w.station == j]
        if not len(pts):
            continue
        r = (pts - w.station_xyz[j]) * 1000.0
        g = np.zeros((len(r), 3, 6))
        g[:, :, :3] = np.eye(3)
        g[:, 0, 4], g[:, 0, 5] = r[:, 2], -r[:, 1]
        g[:, 1, 3], g[:, 1, 5] = -r[:, 2], r[:, 0]
        g[:, 2, 3], g[:, 2, 4] = r[:, 1], -r[:, 0]
        rms = np.sqrt(np.mean(np.einsum("pij,sj->spi", g, e) ** 2, axis=0)).max()
        predicted = links.loc[(w.station_ids[i], w.station_ids[j]), "link_rms_mm"]
        out.append(float(rms / predicted))
    return out


def run(samples: int, trials: int, only: str | None) -> dict:
    from planner.cityio import site_from_cityjson
    from planner.synthetic3d import lod2_town

    sites = {
        "default site": lambda st: plan(settings=st),
        "10-building block": lambda st: plan(town(10, seed=0), settings=st),
        "LoD2 town (8)": lambda st: plan(site_from_cityjson(lod2_town(8, seed=0)), settings=st),
    }
    coarse = {"10-building block": {"grid_m": 3.0, "sample_spacing_m": 3.0}}
    out = {}
    for name, make in sites.items():
        for mode in ("cloud", "hybrid", "targets"):
            key = f"{name}, {mode}"
            if only and only not in key:
                continue
            t0 = time.perf_counter()
            p = make(PlanSettings(registration=mode, time_limit_s=900, **coarse.get(name, {})))
            planned = time.perf_counter() - t0
            t0 = time.perf_counter()
            w = surveyed(world_of(p), p, samples)
            icp_s = time.perf_counter() - t0
            r = report(survey(w, trials=trials, seed=0))
            pw = report(survey(w, trials=trials, seed=0, processing="pairwise"))
            ratios = link_ratios(w, p)
            r |= {
                "stations": len(p.scan_stations),
                "targets": len(p.targets),
                "cloud_links": len(w.cloud_errors),
                "links_median": float(np.median(ratios)) if ratios else np.nan,
                "links_p95": float(np.percentile(ratios, 95)) if ratios else np.nan,
                "links_max": float(np.max(ratios)) if ratios else np.nan,
                "pairwise_false": pw["false_meets_3se"],
                "plan_s": round(planned, 1),
                "icp_s": round(icp_s, 1),
            }
            out[key] = r
            print(key, r, flush=True)
    return out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--samples", type=int, default=12)
    ap.add_argument("--trials", type=int, default=200)
    ap.add_argument("--only", default=None, help="run only the cases whose name holds this")
    args = ap.parse_args()
    results = run(args.samples, args.trials, args.only)

    def f(v):
        return " / ".join(f"{x:.2f}" for x in v)

    lines = [
        "## Cloud links against an independent virtual survey (benchmarks/cloud_survey.py)",
        "",
        machine(),
        f"Each cloud link surveyed {args.samples} times (its two scans simulated in the plan's "
        "scene at 25 mm at 10 m with the plan's noise and the surfaces' own error, thinned to "
        "the registration spacing, registered by tests/icp.py from the scanner's "
        f"pre-alignment); {args.trials} trials of the frame, the network adjusted with those "
        "links and the targets. Links: the surveyed RMS at the child's facade points over the "
        "plan's link error (median, 95th percentile, largest). False meets: samples marked met "
        "whose simulated RMS exceeds a limit by more than 3 standard errors (in brackets: by "
        "anything); pairwise: the same survey registered pair by pair (a plan made for one "
        "adjustment is not promised for that). Ratios: simulated / promised RMS at the met "
        "samples, m_x / m_y / m_z; reg: the registration part.",
        "",
        "| case | stations | targets | cloud links | links median / p95 / max | met "
        "| false meets | pairwise false | median | p95 | reg median | reg p95 | plan | ICP |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for key, r in results.items():
        lines.append(
            f"| {key} | {r['stations']} | {r['targets']} | {r['cloud_links']} | "
            f"{r['links_median']:.2f} / {r['links_p95']:.2f} / {r['links_max']:.2f} | "
            f"{r['met']} of {r['samples']} | {r['false_meets_3se']} ({r['false_meets_any']}) | "
            f"{r['pairwise_false']} | {f(r['median'])} | {f(r['p95'])} | "
            f"{f(r['reg_median'])} | {f(r['reg_p95'])} | {r['plan_s']} s | {r['icp_s']} s |"
        )
    write_section("cloud-survey", lines)


if __name__ == "__main__":
    main()
