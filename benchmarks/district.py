"""District mode scaling (run by hand; never part of the test suite).

    .venv/bin/python benchmarks/district.py                      # 1, 10, 50, 200 × 1, 2 workers
    .venv/bin/python benchmarks/district.py --sizes 1 10 --workers 2
    .venv/bin/python benchmarks/district.py --sizes 1000 --workers 2   # adds its rows

Each run's rows are kept in benchmarks/district_runs.json (a later run of the same size and
workers replaces its row), so the table can be filled in several sittings.

Synthetic towns (:func:`planner.synthetic.town`: perimeter blocks of terraced buildings,
shared walls, courtyards, mixed heights, vertex noise) planned by ``plan_district`` on a
``LocalCluster`` of 1 or 2 worker processes (2 GB each), blocks of 250 m. Per run: wall time,
the workers' peak memory, stations, the proven bound (the larger of the blocks' covers at
shared prices and the far-apart blocks' sum), the sum of the blocks' own bounds, samples
met. Results: the ``district`` section of
benchmarks/RESULTS.md. Targets (issue 12): 1000 buildings in <= 10 min, <= 2 GB per worker,
time about linear in the buildings.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from _results import machine, write_section


def run(n: int, workers: int) -> dict:
    from planner.pipeline.district.blocks import partition
    from planner.pipeline.district.schedule import plan_district
    from planner.scanner import load_scanner
    from planner.synthetic import town

    site = town(n, seed=0)
    t0 = time.perf_counter()
    p = plan_district(site, load_scanner("leica-4mm-60urad"), workers=workers)
    wall = time.perf_counter() - t0
    s = p.solver
    cov = p.scanned
    return {
        "buildings": n,
        "workers": workers,
        "blocks": len(partition(site)),
        "samples": len(cov),
        "wall_s": wall,
        "peak_mb": p.timings_s.get("worker_peak_mb", 0.0),
        "stations": len(p.stations),
        "removed": s.redundant_removed,
        "per_building_s": wall / n,
        "cover": s.objective,
        "bound": s.lower_bound,
        "shared": s.shared_bound,
        "block_bounds": s.block_bound_sum,
        "met": int(cov["meets"].sum()),
        "pairs_per_s": s.pairs / max(p.timings_s["blocks_s"], 1e-9),
        "blocks_s": p.timings_s["blocks_s"],
        "bound_wait_s": p.timings_s["bound_wait_s"],
        "stitch_s": p.timings_s["stitch_s"],
    }


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", type=int, nargs="+", default=[1, 10, 50, 200])
    ap.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    args = ap.parse_args()
    store = Path(__file__).resolve().parent / "district_runs.json"
    kept = json.loads(store.read_text()) if store.exists() else []
    for n in args.sizes:
        for w in args.workers:
            r = run(n, w)
            print(r, flush=True)
            kept = [k for k in kept if (k["buildings"], k["workers"]) != (n, w)] + [r]
            kept.sort(key=lambda k: (k["buildings"], k["workers"]))
            store.write_text(json.dumps(kept, indent=1) + "\n")
    rows = kept
    lines = [
        "## District mode on Dask (benchmarks/district.py)",
        "",
        machine(),
        "",
        "| buildings | workers | blocks | samples | wall [s] | per building [s] "
        "| peak per worker [MB] | stations | removed on block edges | covering | proven bound "
        "| gap | sum of block bounds | met | pairs/s (per block-second) |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r['buildings']} | {r['workers']} | {r['blocks']} | {r['samples']} | "
            f"{r['wall_s']:.1f} | {r['wall_s'] / r['buildings']:.2f} | {r['peak_mb']:.0f} | "
            f"{r['stations']} | {r.get('removed', '—')} | {r['cover']} | "
            f"{r['bound']:g} | {1 - r['bound'] / max(r['cover'], 1):.0%} | "
            f"{r['block_bounds']:g} | {r['met']} of {r['samples']} | "
            f"{r['pairs_per_s'] / 1e6:.1f} M |"
        )
    lines += [
        "",
        "The proven bound is the larger of the sum of the blocks' cover LPs with every "
        "candidate priced 1 / (the blocks whose samples it meets) and the sum of the bounds "
        "of blocks pairwise farther apart than the sum of their meeting reaches (they share "
        "no station); the sum of all block bounds is not a bound of the whole (a station on "
        "a block edge may serve two blocks). Gap: (covering − bound) / covering. Stations "
        "removed on block edges: covering stations no unmet sample is scanned from whose "
        "every met sample a station of its own or a neighbouring block still meets. Targets: 1000 buildings in <= 10 min, <= 2 GB per "
        "worker.",
    ]
    write_section("district", lines)


if __name__ == "__main__":
    main()
