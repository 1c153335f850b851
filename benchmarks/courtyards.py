"""Closed courtyards and gateways (run by hand; never part of the test suite).

    .venv/bin/python benchmarks/courtyards.py                 # both sites, every variant
    .venv/bin/python benchmarks/courtyards.py --sizes 10      # the city block only
    PLANNER_SRC=/path/to/old/checkout .venv/bin/python benchmarks/courtyards.py --label before

Synthetic perimeter blocks (:func:`planner.synthetic.town`, seed 1): closed rings of
terraced buildings around courtyards, each entered through a gateway under a building —
``closed`` (the footprints alone, as a real export shows them), ``passage`` (the gateways
marked, role passage). Planned by the command a surveyor types (``planner plan site.geojson
--max-xy-mm 6 --max-z-mm 8 --no-booklet --district off``, default scanner, time limit
600 s) as a separate process; ``PLANNER_SRC`` runs another checkout's code on the same
files (the code before gateways: ``--label before``, only the ``closed`` variant). Per run:
stations, samples met, stations not tied to the network, wall time. Results: the
``courtyards`` section of benchmarks/RESULTS.md (rows of earlier labels kept).
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _results import machine, write_section

HERE = Path(__file__).resolve().parent
RUNS = HERE / "courtyard_runs.json"


def write_site(path: Path, n: int, gateways: str) -> None:
    from planner.synthetic import town, town_geojson

    path.write_text(json.dumps(town_geojson(town(n, seed=1, gateways=gateways))))


def run(site: Path, out: Path, district: str = "off") -> dict:
    env = dict(os.environ)
    if os.environ.get("PLANNER_SRC"):
        env["PYTHONPATH"] = os.environ["PLANNER_SRC"]
    cmd = [sys.executable, "-m", "planner", "plan", str(site), "--max-xy-mm", "6"]
    cmd += ["--max-z-mm", "8", "--no-booklet", "--district", district, "--time-limit-s", "600"]
    cmd += ["--out", str(out), "-q"]
    t0 = time.monotonic()
    # run outside the checkout: ``python -m`` puts the working folder first on the path
    done = subprocess.run(cmd, capture_output=True, text=True, env=env, check=False, cwd=out.parent)
    wall = time.monotonic() - t0
    if done.returncode not in (0, 1):
        sys.exit(f"planner failed ({done.returncode}): {done.stderr[-2000:]}")
    summary = (out / "summary.txt").read_text()
    stations = int(re.search(r"^Stations: (\d+)", summary, re.M)[1])
    found = re.search(r"requirement.*?: (\d+) of (\d+)", summary)
    untied = re.search(r"(\d+) of the \d+ stations cannot be tied", summary)
    blocks = re.search(r"District network: (\d+) of (\d+) blocks tied", summary)
    return {
        "stations": stations,
        "met": int(found[1]),
        "samples": int(found[2]),
        "untied": int(untied[1]) if untied else 0,
        "wall_s": wall,
        "courtyard_named": "The courtyard enclosed by" in summary,
        "blocks_tied": f"{blocks[1]} of {blocks[2]}" if blocks else "",
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=int, nargs="+", default=[10, 50])
    ap.add_argument("--label", default="after")
    args = ap.parse_args()
    variants = ["closed"] if os.environ.get("PLANNER_SRC") else ["closed", "passage", "district"]
    runs = json.loads(RUNS.read_text()) if RUNS.exists() else {}
    with tempfile.TemporaryDirectory() as tmp:
        for n in args.sizes:
            for g in variants:
                if g == "district" and n < 50:
                    continue
                site = Path(tmp) / f"block{n}-{g}.geojson"
                write_site(site, n, "passage" if g == "district" else g)
                r = run(site, Path(tmp) / f"out{n}{g}", "on" if g == "district" else "off")
                r.update(buildings=n, gateways=g, label=args.label)
                print(r, flush=True)
                runs[f"{n}-{g}-{args.label}"] = r
    RUNS.write_text(json.dumps(runs, indent=1) + "\n")
    lines = [
        "## Closed courtyards and gateways (benchmarks/courtyards.py)",
        "",
        machine(),
        "`planner plan site.geojson --max-xy-mm 6 --max-z-mm 8 --no-booklet --district off` "
        "(default scanner) on synthetic perimeter blocks (seed 1) whose courtyards are entered "
        "through gateways under a building: `closed` — the footprints alone; `passage` — the "
        "gateways marked (role passage); `district` — the same, block by block on Dask "
        "(`--district on`), the blocks' networks tied across their seams. `before`: the code "
        "before passages and ground regions, on the same files.",
        "",
        "| buildings | gateways | code | stations | samples met | stations untied | "
        "courtyard named | blocks tied | wall |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for r in sorted(runs.values(), key=lambda r: (r["buildings"], r["gateways"], r["label"])):
        lines.append(
            f"| {r['buildings']} | {r['gateways']} | {r['label']} | {r['stations']} | "
            f"{r['met']} of {r['samples']} | {r['untied']} | "
            f"{'yes' if r['courtyard_named'] else 'no'} | {r.get('blocks_tied', '')} | "
            f"{r['wall_s']:.1f} s |"
        )
    write_section("courtyards", lines)


if __name__ == "__main__":
    main()
