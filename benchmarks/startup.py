"""Start-up and end-to-end time of the command (run by hand; never part of the test suite).

    .venv/bin/python benchmarks/startup.py     # writes its section of benchmarks/RESULTS.md

Each figure is the median of whole-process runs (a fresh interpreter every time):
``python -c "import planner"`` and ``planner plan --out TMP -q`` on the default site.
Targets (foundation issue): ``import planner`` <= 0.25 s, ``planner plan`` <= 0.8 s.
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _results import machine, write_section

RUNS = 7


def timed(cmd: list[str]) -> float:
    t0 = time.perf_counter()
    subprocess.run(cmd, check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - t0


def main() -> None:
    planner = str(Path(sys.executable).with_name("planner"))
    with tempfile.TemporaryDirectory() as tmp:
        cases = {
            "python -c 'import planner'": [sys.executable, "-c", "import planner"],
            "python -c 'pass' (the interpreter alone)": [sys.executable, "-c", "pass"],
            "planner plan --out DIR -q (default site)": [planner, "plan", "--out", tmp, "-q"],
        }
        rows = []
        for label, cmd in cases.items():
            timed(cmd)  # warm the file cache
            times = [timed(cmd) for _ in range(RUNS)]
            rows.append((label, statistics.median(times), min(times), max(times)))
            print(
                f"{label:45s} median {rows[-1][1]:.3f} s (min {rows[-1][2]:.3f}, max {rows[-1][3]:.3f})"
            )
    lines = [
        "## Start-up and end-to-end time",
        "",
        f"`benchmarks/startup.py`, {machine()}; median of {RUNS} whole-process runs.",
        "",
        "| command | median | min | max |",
        "|---|---|---|---|",
        *[f"| `{label}` | {med:.3f} s | {lo:.3f} s | {hi:.3f} s |" for label, med, lo, hi in rows],
        "",
        "Targets: `import planner` <= 0.25 s; `planner plan` on the default site <= 0.8 s.",
    ]
    write_section("startup", lines)


if __name__ == "__main__":
    main()
