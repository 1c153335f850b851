"""Whether a change keeps the plans: plan a corpus of sites and compare two runs (by hand;
never part of the test suite). For speed work that must not change what is planned.

    .venv/bin/python benchmarks/same_plans.py save /tmp/before.pkl    # on the code before
    .venv/bin/python benchmarks/same_plans.py save /tmp/after.pkl     # on the code after
    .venv/bin/python benchmarks/same_plans.py compare /tmp/before.pkl /tmp/after.pkl

The corpus (about a minute and a half): the default plan and one at 3 / 3 mm, every
catalogue scanner on the default site with the 3-D and the paper's model (coarse samples), a
ten-building block registered by targets, cloud to cloud and hybrid, a gated block, and
pairwise registration. Compared: the stations, targets and links tables as text, the
messages, and every number of the coverage table (exactly: a difference in the last bit is
reported). ``save`` prints each plan's time and keeps the commit of the code it ran;
``compare`` writes its verdict to the "same_plans" section of benchmarks/RESULTS.md.
"""

from __future__ import annotations

import pickle
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from planner import PlanSettings, Requirements, plan
from planner.scanner import Scanner, catalogue
from planner.siteio import default_site
from planner.synthetic import town

COARSE = {"sample_spacing_m": 4.0, "sample_height_step_m": 4.0, "grid_m": 3.0}
BLOCK = {"grid_m": 3.0, "sample_spacing_m": 3.0}


def corpus() -> dict:
    jobs = {
        "default": lambda: plan(),
        "3/3 mm": lambda: plan(requirements=Requirements(max_xy_mm=3, max_z_mm=3)),
        "pairwise": lambda: plan(settings=PlanSettings(registration_processing="pairwise")),
        "gated block": lambda: plan(
            town(10, seed=1, gateways="passage"), None, None, PlanSettings(**COARSE)
        ),
    }
    for name in sorted(catalogue()):
        for model in ("3d", "paper"):
            jobs[f"{name}, {model}"] = lambda n=name, m=model: plan(
                default_site(), Scanner.from_name(n), None, PlanSettings(model=m, **COARSE)
            )
    for mode in ("targets", "cloud", "hybrid"):
        jobs[f"block, {mode}"] = lambda m=mode: plan(
            town(10, seed=0), None, None, PlanSettings(registration=m, **BLOCK)
        )
    return jobs


def fingerprint(p) -> dict:
    numbers = p.coverage.select_dtypes("number")
    return {
        "tables": [p.stations.to_csv(), p.targets.to_csv(), p.links.to_csv()],
        "messages": list(p.messages),
        "columns": list(numbers.columns),
        "coverage": numbers.to_numpy(),
        "meets": p.coverage["meets"].to_numpy(),
        "station_id": p.coverage["station_id"].to_numpy(),
    }


def commit() -> str:
    """The commit of the planner package this process imports (its repository's HEAD; a
    "+" where its files differ from it), or "?" outside a repository."""
    import planner

    where = Path(planner.__file__).resolve().parent

    def git(*args: str) -> str:
        return subprocess.run(
            ["git", "-C", str(where), *args], capture_output=True, text=True, check=True
        ).stdout.strip()

    try:
        head = git("rev-parse", "--short", "HEAD")
        return head + ("+" if git("status", "--porcelain", "--", ".") else "")
    except (OSError, subprocess.CalledProcessError):
        return "?"


def save(path: str) -> None:
    out: dict = {"_commit": commit()}
    for name, job in corpus().items():
        t0 = time.perf_counter()
        out[name] = fingerprint(job())
        print(f"{name:36s} {time.perf_counter() - t0:6.2f} s", flush=True)
    with open(path, "wb") as f:
        pickle.dump(out, f)


def compare(before: str, after: str) -> int:
    with open(before, "rb") as f:
        a = pickle.load(f)
    with open(after, "rb") as f:
        b = pickle.load(f)
    differ = 0
    names = sorted((a.keys() & b.keys()) - {"_commit"})
    for name in names:
        x, y = a[name], b[name]
        what = [k for k in ("tables", "messages", "columns") if x[k] != y[k]]
        what += [k for k in ("meets", "station_id") if not np.array_equal(x[k], y[k])]
        if x["coverage"].shape != y["coverage"].shape or not np.array_equal(
            x["coverage"], y["coverage"], equal_nan=True
        ):
            what.append("coverage numbers")
        if what:
            differ += 1
            print(f"{name}: {', '.join(what)} differ")
    verdict = f"{len(names)} plans compared, {differ} differ"
    print(verdict)
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from _results import machine, write_section

    write_section(
        "same_plans",
        [
            "## The same plans before and after a change (benchmarks/same_plans.py)",
            "",
            machine(),
            "",
            f"Code {a.get('_commit', '?')} against {b.get('_commit', '?')}: {verdict}.",
        ],
    )
    return 1 if differ else 0


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "save":
        save(sys.argv[2])
    elif len(sys.argv) == 4 and sys.argv[1] == "compare":
        sys.exit(compare(sys.argv[2], sys.argv[3]))
    else:
        sys.exit(__doc__)
