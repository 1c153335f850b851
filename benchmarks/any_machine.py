"""The same plan on any machine (issue 65): ``planner plan`` on a few sites, idle and beside
CPU-bound processes (``--load N``: N busy loops, a load of about N + 1 on this machine),
the files' hashes compared and the wall time of each. Writes the ``any-machine`` section of
benchmarks/RESULTS.md.

Run: ``.venv/bin/python benchmarks/any_machine.py [--load 6]``
"""

from __future__ import annotations

import argparse
import hashlib
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from _results import machine, write_section  # noqa: E402

from planner.synthetic import town, town_geojson  # noqa: E402

PLANNER = [sys.executable, "-m", "planner"]
FILES = ("stations.csv", "targets.csv", "coverage.csv", "plan.geojson", "summary.txt")


def _sites(folder: Path) -> dict[str, list[str]]:
    block = folder / "block.geojson"
    block.write_text(json.dumps(town_geojson(town(10, seed=0))))
    lod2 = folder / "lod2.city.json"
    from planner.synthetic3d import lod2_town

    lod2.write_text(json.dumps(lod2_town(8, seed=0)))
    return {
        "default site": [],
        "10-building block (3 m grid)": [str(block), "--grid-m", "3", "--sample-spacing-m", "3"],
        "LoD2 town (8), P50": [str(lod2), "--scanner", "leica-p50"],
    }


def _digest(out: Path, name: str) -> str:
    data = (out / name).read_bytes()
    if name == "summary.txt":  # its timings line is the one thing that must differ
        data = b"\n".join(ln for ln in data.splitlines() if b" s)" not in ln and b"took" not in ln)
    return hashlib.sha256(data).hexdigest()[:12]


def _plan(args: list[str], out: Path) -> tuple[float, int, str]:
    t = time.perf_counter()
    r = subprocess.run([*PLANNER, "plan", *args, "--out", str(out), "-q"], capture_output=True)
    wall = time.perf_counter() - t
    if r.returncode not in (0, 1):
        raise SystemExit(r.stderr.decode()[-2000:])
    return wall, r.returncode, "".join(_digest(out, n)[:4] for n in FILES)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--load", type=int, default=6)
    load = ap.parse_args().load
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for name, args in _sites(folder).items():
            idle = _plan(args, folder / "idle")
            busy = [
                subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(load)
            ]
            try:
                loaded = _plan(args, folder / "loaded")
            finally:
                for b in busy:
                    b.kill()
            same = all(_digest(folder / "idle", n) == _digest(folder / "loaded", n) for n in FILES)
            stations = sum(1 for _ in (folder / "idle" / "stations.csv").open()) - 1
            rows.append(
                f"| {name} | {stations} | {'identical' if same else 'DIFFER'} ({idle[2]}) | "
                f"{idle[0]:.1f} s | {loaded[0]:.1f} s |"
            )
            print(rows[-1], flush=True)
    write_section(
        "any-machine",
        [
            "## The same plan on any machine (benchmarks/any_machine.py)",
            "",
            machine(),
            "",
            f"`planner plan` idle, then beside {load} CPU-bound processes (a load of about "
            f"{load + 1} on this machine), default 60 s budget. Files compared: "
            f"{', '.join(FILES)} (the summary without its timings line).",
            "",
            "| site | set-ups | files, loaded against idle (hash prefixes) | idle | loaded |",
            "|---|---|---|---|---|",
            *rows,
        ],
    )


if __name__ == "__main__":
    main()
