"""The real building in 3-D: ray throughput of the scene, and plans from city models against
plans from the same buildings' footprints, each audited against the model.

    .venv/bin/python benchmarks/scene3d.py            # writes the scene3d section of RESULTS.md
    .venv/bin/python benchmarks/scene3d.py --no-write

1. Ray throughput (``planner.pipeline.geometry.scene.Scene``): occlusion and first-hit rays per
   second, and sight lines with their clearance (five rays each where the first is clear),
   on the synthetic LoD2 town of 20 buildings and on 2 000 random boxes (24 000 triangles,
   the issue's yardstick); the prism test's sight lines per second on the default site for
   comparison.
2. Plans: the synthetic LoD2 towns (``planner.synthetic3d.lod2_town``: 8 and 20 buildings)
   and the real samples shipped in tests/data/citymodels, each planned from the model and
   from its footprints with the highest point (as a surveyor without the model draws them),
   leica-p50, 6/8 mm as in the issue's trial, samples demanded and met, the audit of the met
   samples against the model (seen / hidden / no wall) and the plan's time.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from _results import machine, write_section  # noqa: E402

DATA = HERE.parent / "tests" / "data" / "citymodels"


def _boxes_site(n: int = 2000):
    import shapely

    from planner.site import Building, Obstacle, Site

    rng = np.random.default_rng(0)
    tri = []
    from planner.mesh import extrude

    for _ in range(n):
        x, y = rng.uniform(0, 300, 2)
        w, d = rng.uniform(5, 20, 2)
        tri.append(extrude(shapely.box(x, y, x + w, y + d), 0.0, float(rng.uniform(5, 30))))
    mesh = np.concatenate(tri)
    far = Building("far", shapely.box(150, 320, 160, 330), 10.0)
    return Site([far], obstacles=[Obstacle("boxes", shapely.box(0, 0, 1, 1), 1.0, mesh=mesh)])


def throughput() -> list[dict]:
    from planner.cityio import site_from_cityjson
    from planner.pipeline.geometry.scene import Scene
    from planner.pipeline.geometry.visibility import clear_height
    from planner.siteio import default_site
    from planner.synthetic3d import lod2_town

    rows = []
    rng = np.random.default_rng(1)
    for name, site in [
        ("LoD2 town, 20 buildings", site_from_cityjson(lod2_town(20, seed=0))),
        ("2 000 random boxes", _boxes_site()),
    ]:
        scene = Scene(site, "rays")
        tri = scene.mesh[0]
        lo, hi = tri.reshape(-1, 3).min(axis=0), tri.reshape(-1, 3).max(axis=0)
        n = 1_000_000
        a = rng.uniform(lo, hi, (n, 3))
        b = rng.uniform(lo, hi, (n, 3))
        a[:, 2] = lo[2] + 1.5
        scene.occluded(a[:1000], b[:1000] - a[:1000])  # the engine built
        t = time.perf_counter()
        blocked = scene.occluded(a, b - a)
        occl = n / (time.perf_counter() - t)
        t = time.perf_counter()
        scene.seen(a, b)
        lines = n / (time.perf_counter() - t)
        t = time.perf_counter()
        scene.first_hit(a, b - a, np.linalg.norm(b - a, axis=1))
        first = n / (time.perf_counter() - t)
        rows.append(
            {
                "scene": name,
                "triangles": len(tri),
                "occlusion_rays_per_s": occl,
                "sight_lines_per_s": lines,
                "first_hit_rays_per_s": first,
                "blocked_share": float(blocked.mean()),
            }
        )
    site = default_site()
    prisms = Scene(site, "prisms")
    x0, y0, x1, y1 = Scene(site, "rays")._extent()
    n = 1_000_000
    src = np.column_stack([rng.uniform(x0 - 30, x1 + 30, n), rng.uniform(y0 - 30, y1 + 30, n)])
    dst = np.column_stack([rng.uniform(x0 - 30, x1 + 30, n), rng.uniform(y0 - 30, y1 + 30, n)])
    clear_height(src[:100], 1.5, dst[:100], prisms.edges, prisms.edge_heights)
    t = time.perf_counter()
    clear_height(src, 1.5, dst, prisms.edges, prisms.edge_heights)
    per = n / (time.perf_counter() - t)
    rays = Scene(site, "rays")
    s3 = np.column_stack([src, np.full(n, 1.5)])
    d3 = np.column_stack([dst, np.full(n, 8.0)])
    rays.seen(s3[:100], d3[:100])
    t = time.perf_counter()
    rays.seen(s3, d3)
    per_rays = n / (time.perf_counter() - t)
    rows.append(
        {
            "scene": "default site (prism test vs rays with clearance)",
            "triangles": rays.n_triangles,
            "prism_lines_per_s": per,
            "sight_lines_per_s": per_rays,
        }
    )
    return rows


def _cases():
    from planner.cityio import read_city_model, site_from_cityjson
    from planner.synthetic3d import lod2_town

    for n in (8, 20):
        model = site_from_cityjson(lod2_town(n, seed=0))
        yield f"synthetic LoD2 town, {n} buildings", model
    yield (
        "Munich, TUM entrance (CityGML 3.0, Bavaria LoD2)",
        read_city_model(DATA / "munich_tum_entrance_lod2.citygml3.gml"),
    )
    yield (
        "Delft, 3DBAG house (CityJSON Sequence)",
        read_city_model(
            DATA / "delft_3dbag.city.jsonl", buildings=["NL.IMBAG.Pand.0503100000005156"]
        ),
    )
    yield (
        "Yokosuka, Museum of Art (CityGML 2.0, PLATEAU, 2 parts)",
        read_city_model(
            DATA / "yokosuka_plateau_lod2.gml",
            buildings=["bldg_16418b2d-dc75-4731-ae04-90bbef1d66fe"],
        ),
    )


def plans() -> list[dict]:
    from planner.cityio import footprints_of
    from planner.pipeline.engine.judge import workbench_of
    from planner.pipeline.engine.planning import plan
    from planner.pipeline.geometry.audit import audit_plan
    from planner.pipeline.inputs.requirements import PlanSettings, Requirements
    from planner.siteio import site_from_geojson

    req = Requirements(max_xy_mm=6.0, max_z_mm=8.0)
    st = PlanSettings(time_limit_s=120)
    rows = []
    for name, model in _cases():
        drawn = site_from_geojson(footprints_of(model))
        for source, site in (("footprints", drawn), ("model", model)):
            t = time.perf_counter()
            p = plan(site, "leica-p50", req, st)
            took = time.perf_counter() - t
            table = audit_plan(p, model)
            counts = table["status"].value_counts()
            rows.append(
                {
                    "case": name,
                    "from": source,
                    "samples": len(p.scanned),
                    "met": int(p.scanned["meets"].sum()),
                    "stations": len(p.scan_stations),
                    "seen": int(counts.get("seen", 0)),
                    "hidden": int(counts.get("hidden", 0)),
                    "no_wall": int(counts.get("no wall", 0)),
                    "plan_s": took,
                    "engine": workbench_of(p).ctx.scene.engine
                    if workbench_of(p) is not None
                    else "",
                }
            )
            print(rows[-1], flush=True)
    return rows


def _millions(r: dict, key: str) -> str:
    return f"{r[key] / 1e6:.2f} M" if key in r else ""


def main() -> None:
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--no-write", action="store_true")
    args = ap.parse_args()
    rays = throughput()
    print(json.dumps(rays, indent=1))
    cases = plans()
    if args.no_write:
        return
    lines = [
        "## The scene: rays, and plans from city models (benchmarks/scene3d.py)",
        "",
        machine(),
        "",
        "Ray throughput (1 000 000 random segments each, two threads):",
        "",
        "| scene | triangles | occlusion rays/s | sight lines/s (with the clearance) | first-hit rays/s | prism test lines/s |",
        "|---|---|---|---|---|---|",
    ]
    for r in rays:
        cells = [
            _millions(r, k)
            for k in (
                "occlusion_rays_per_s",
                "sight_lines_per_s",
                "first_hit_rays_per_s",
                "prism_lines_per_s",
            )
        ]
        lines.append(f"| {r['scene']} | {r['triangles']:,} | " + " | ".join(cells) + " |")
    lines += [
        "",
        "Plans from the model and from its footprints (each building's ground outline with its highest point, as a surveyor without the model draws it), leica-p50, m_x, m_y ≤ 6 mm, m_z ≤ 8 mm, default settings; every sample marked met audited against the model (`planner audit`):",
        "",
        "| case | planned from | samples demanded | met | stations | seen | hidden | no wall | plan |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for r in cases:
        met = max(r["met"], 1)
        lines.append(
            f"| {r['case']} | {r['from']} | {r['samples']} | {r['met']} | {r['stations']} | "
            f"{r['seen']} ({100 * r['seen'] / met:.1f} %) | {r['hidden']} ({100 * r['hidden'] / met:.1f} %) | "
            f"{r['no_wall']} ({100 * r['no_wall'] / met:.1f} %) | {r['plan_s']:.1f} s |"
        )
    write_section("scene3d", lines)


if __name__ == "__main__":
    main()
