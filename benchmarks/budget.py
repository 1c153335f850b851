"""The time budget, end to end (run by hand; never part of the test suite).

    .venv/bin/python benchmarks/budget.py                  # 144 buildings: 60 s, then 900 s
    .venv/bin/python benchmarks/budget.py --budgets 60     # only the 60 s run

A synthetic city of 144 buildings (:func:`planner.synthetic.town`: perimeter blocks of
terraced buildings, the size and density of the real 144-building Prague block that ran
for over 15 min with ``--time-limit-s 60``), planned by the command a surveyor types —
``planner plan town.geojson --time-limit-s B --max-xy-mm 6 --max-z-mm 8`` with the default
scanner, the booklet and every file, district mode as ``auto`` chooses — as a separate
process. Per budget: the wall time from the command's start to its exit, the peak memory of
the largest process, stations, samples met, and what the plan says the budget cut short.
Target (issue 26): wall time within the budget + 10 % + 5 s. Results: the ``budget``
section of benchmarks/RESULTS.md.
"""

from __future__ import annotations

import argparse
import json
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _results import machine, write_section

ROOT = Path(__file__).resolve().parent.parent
PLANNER = ROOT / ".venv" / "bin" / "planner"
N_BUILDINGS = 144


def write_town(path: Path, n: int) -> None:
    from planner.synthetic import town, town_geojson

    path.write_text(json.dumps(town_geojson(town(n, seed=0))))


def run(site: Path, out: Path, budget: float) -> dict:
    cmd = [str(PLANNER), "plan", str(site), "--time-limit-s", f"{budget:g}"]
    cmd += ["--max-xy-mm", "6", "--max-z-mm", "8", "--out", str(out), "-q"]
    t0 = time.monotonic()
    done = subprocess.run(cmd, capture_output=True, text=True, check=False)
    wall = time.monotonic() - t0
    peak_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    if done.returncode not in (0, 1):
        sys.exit(f"planner failed ({done.returncode}): {done.stderr[-2000:]}")
    summary = (out / "summary.txt").read_text()
    stations = int(re.search(r"^Stations: (\d+)", summary, re.M)[1])
    found = re.search(r"requirement.*?: (\d+) of (\d+)", summary)
    met, total = int(found[1]), int(found[2])
    cut = [
        line.split("cut short: ")[1].split(". The plan")[0]
        for line in summary.splitlines()
        if line.startswith("Time budget: the ") and "cut short" in line
    ]
    booklet = [line for line in summary.splitlines() if "booklet" in line and "Time budget" in line]
    return {
        "budget_s": budget,
        "wall_s": wall,
        "allowed_s": 1.1 * budget + 5.0,
        "peak_mb": peak_mb,
        "stations": stations,
        "met": met,
        "samples": total,
        "district": "District:" in summary,
        "cut": "; ".join(cut) or "nothing",
        "booklet": booklet[0].split("Time budget: ")[1][:90] if booklet else "every page",
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--budgets", type=float, nargs="+", default=[60.0, 900.0])
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        site = Path(tmp) / f"town{N_BUILDINGS}.geojson"
        write_town(site, N_BUILDINGS)
        for budget in args.budgets:
            r = run(site, Path(tmp) / f"out{budget:g}", budget)
            print(r, flush=True)
            rows.append(r)
    lines = [
        "## The time budget, end to end (benchmarks/budget.py)",
        "",
        machine(),
        f"`planner plan town{N_BUILDINGS}.geojson --time-limit-s B --max-xy-mm 6 --max-z-mm 8` "
        f"(default scanner, booklet and every file; district mode as `auto` chose) on a "
        f"synthetic city of {N_BUILDINGS} buildings, as a separate process.",
        "",
        "| budget | wall | allowed (+10 % + 5 s) | peak memory | district | stations | "
        "samples met | cut short | booklet |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append(
            f"| {r['budget_s']:g} s | {r['wall_s']:.1f} s | {r['allowed_s']:.0f} s | "
            f"{r['peak_mb']:.0f} MB | {'yes' if r['district'] else 'no'} | {r['stations']} | "
            f"{r['met']} of {r['samples']} | {r['cut']} | {r['booklet']} |"
        )
    write_section("budget", lines)


if __name__ == "__main__":
    main()
