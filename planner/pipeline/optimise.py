"""The station optimiser: fewest stations such that every sample is seen by enough stations
that meet every requirement there — a set multi-cover problem.

Solved exactly as an integer program with ``scipy.optimize.milp`` (HiGHS) under a time limit,
with greedy set cover as the fallback and as an upper bound (scipy's milp takes no initial
solution, so the greedy count is given to HiGHS as the constraint ``Σx <= greedy``).

HiGHS does not look at the clock during presolve, which on large sites (10 000 samples ×
30 000 candidates) can run for many minutes. So large models run in a separate process that
is stopped at the time limit; the greedy cover is then the plan, and its gap is measured
against a packing lower bound (samples that share no candidate each need a station of their
own).
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import scipy.sparse as sp

from planner.errors import PlannerError
from planner.polar import separated_directions

__all__ = ["CoverSolution", "greedy_cover", "solve_cover"]


@dataclass(kw_only=True)
class CoverSolution:
    """Chosen candidate indices and how they were found."""

    chosen: np.ndarray
    method: str  # "milp" or "greedy"
    status: str  # e.g. "optimal", "time limit", "as requested", "nothing to cover"
    objective: int
    lower_bound: float | None
    gap: float | None  # (objective − bound) / objective
    seconds: float
    greedy_objective: int | None = None


def _reduce(a: sp.csr_matrix, demand: np.ndarray) -> tuple[sp.csr_matrix, np.ndarray, np.ndarray]:
    """Drop rows without demand and duplicate rows; keep only columns that cover something.

    Returns the reduced matrix, its demand and the original column index of each column.
    """
    keep = demand > 0
    a = a[keep]
    demand = demand[keep]
    # duplicate rows: same set of columns and same demand
    a = a.tocsr()
    a.sort_indices()
    keys = {}
    rows = []
    for i in range(a.shape[0]):
        key = (a.indices[a.indptr[i] : a.indptr[i + 1]].tobytes(), int(demand[i]))
        if key not in keys:
            keys[key] = i
            rows.append(i)
    a = a[rows]
    demand = demand[rows]
    used = np.flatnonzero(np.asarray(a.sum(axis=0)).ravel() > 0)
    return a[:, used].tocsr(), demand, used


def greedy_cover(a: sp.csr_matrix, demand: np.ndarray) -> np.ndarray:
    """Greedy multi-cover: repeatedly take the column that serves the most unmet demand, then
    drop chosen columns that became redundant (their rows are served enough without them)."""
    a = sp.csr_matrix(a, dtype=np.int32)
    at = a.T.tocsr()
    need = demand.astype(np.int64).copy()
    chosen: list[int] = []
    taken = np.zeros(a.shape[1], dtype=bool)
    while need.max(initial=0) > 0:
        gain = at @ (need > 0).astype(np.int32)
        gain[taken] = -1
        j = int(np.argmax(gain))
        if gain[j] <= 0:
            break  # the rest cannot be served
        chosen.append(j)
        taken[j] = True
        need[at.indices[at.indptr[j] : at.indptr[j + 1]]] -= 1
    served = a @ taken.astype(np.int32)
    for j in sorted(chosen, key=lambda c: at.indptr[c + 1] - at.indptr[c]):
        rows = at.indices[at.indptr[j] : at.indptr[j + 1]]
        if (served[rows] - 1 >= demand[rows]).all():
            taken[j] = False
            served[rows] -= 1
    return np.flatnonzero(taken)


def packing_lower_bound(a: sp.csr_matrix, demand: np.ndarray) -> int:
    """A lower bound on the number of columns: rows that pairwise share no column each need
    their own (``demand`` of them); rows are taken greedily, fewest columns first."""
    a = sp.csr_matrix(a)
    sizes = np.diff(a.indptr)
    used = np.zeros(a.shape[1], dtype=bool)
    bound = 0
    for i in np.argsort(sizes, kind="stable"):
        cols = a.indices[a.indptr[i] : a.indptr[i + 1]]
        if demand[i] > 0 and not used[cols].any():
            used[cols] = True
            bound += 1
    # a multi-cover row needs demand[i] distinct columns; the packing counts it once, which
    # stays a valid (weaker) bound; strengthen with the largest single demand
    return int(max(bound, demand.max(initial=0)))


def _milp(a: sp.csr_matrix, dem: np.ndarray, upper: int, time_limit_s: float):
    from scipy.optimize import Bounds, LinearConstraint, milp  # heavy: only when solving

    n = a.shape[1]
    constraints = [
        LinearConstraint(a.astype(float), lb=dem, ub=np.inf),
        LinearConstraint(np.ones((1, n)), lb=0, ub=upper),
    ]
    res = milp(
        np.ones(n),
        integrality=np.ones(n),
        bounds=Bounds(0, 1),
        constraints=constraints,
        options={"time_limit": time_limit_s, "disp": False, "presolve": True},
    )
    return res.status, res.message, res.x, getattr(res, "mip_dual_bound", None)


#: Models up to this many nonzeros are solved in-process (HiGHS presolve is quick there);
#: larger ones in a separate process that is stopped at the time limit.
IN_PROCESS_NNZ = 400_000


def _milp_with_deadline(a, dem, upper, time_limit_s):
    """Run the integer program, stopping it at ``time_limit_s`` (+ a grace of 1 s) for sure.

    Large models run in a worker process (``python -m planner.pipeline._milp_worker``), killed
    at the deadline; not a fork (a fork of a process with threads, such as a Jupyter kernel, can
    deadlock) and not multiprocessing's spawn (it re-runs the caller's main module).
    """
    if a.nnz <= IN_PROCESS_NNZ:
        return _milp(a, dem, upper, time_limit_s)
    a = sp.csr_matrix(a)
    with tempfile.TemporaryDirectory(prefix="planner-milp-") as tmp:
        src, dst = Path(tmp) / "in.npz", Path(tmp) / "out.npz"
        np.savez(
            src,
            data=a.data,
            indices=a.indices,
            indptr=a.indptr,
            shape=np.array(a.shape),
            dem=dem,
            upper=upper,
            time_limit=time_limit_s,
        )
        proc = subprocess.Popen(
            [sys.executable, "-m", "planner.pipeline._milp_worker", str(src), str(dst)],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
        )
        try:
            _, err = proc.communicate(timeout=time_limit_s + 1.0)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.communicate()
            return (
                1,
                "stopped at the time limit (HiGHS presolve does not check the clock)",
                None,
                None,
            )
        if proc.returncode != 0 or not dst.exists():
            tail = err.decode(errors="replace").strip().splitlines()[-1:] or ["no message"]
            return 4, f"the solver process failed ({tail[0]})", None, None
        with np.load(dst) as r:
            x = r["x"] if bool(r["has_x"]) else None
            dual = None if np.isnan(r["dual"]) else float(r["dual"])
            return int(r["status"]), str(r["message"]), x, dual


def solve_cover(
    ok: sp.csr_matrix, demand: np.ndarray, time_limit_s: float = 20.0, method: str = "auto"
) -> CoverSolution:
    """Fewest columns of ``ok`` (samples × candidates) covering each row ``demand`` times.

    ``demand`` must already be capped at what each row can get (its number of candidates).
    ``method``: "auto" (milp, greedy as fallback), "milp" (the integer program or an error)
    or "greedy". The greedy cover is
    always computed; its gap is measured against the packing bound, or the integer
    program's dual bound when that is better.
    """
    t0 = time.perf_counter()
    a, dem, used = _reduce(sp.csr_matrix(ok), np.asarray(demand))
    if a.shape[0] == 0:
        return CoverSolution(
            chosen=np.empty(0, dtype=np.int64),
            method="greedy",
            status="nothing to cover",
            objective=0,
            lower_bound=0.0,
            gap=0.0,
            seconds=time.perf_counter() - t0,
            greedy_objective=0,
        )
    g = greedy_cover(a, dem)
    packing = packing_lower_bound(a, dem)
    greedy = CoverSolution(
        chosen=np.sort(used[g]),
        method="greedy",
        status="as requested",
        objective=len(g),
        lower_bound=float(packing),
        gap=(len(g) - packing) / len(g),
        seconds=time.perf_counter() - t0,
        greedy_objective=len(g),
    )
    if packing == len(g):
        greedy.status, greedy.gap = "optimal: meets the packing lower bound", 0.0
        return greedy
    if method == "greedy":
        return greedy
    remaining = max(1.0, time_limit_s - (time.perf_counter() - t0))
    status, message, x_raw, dual = _milp_with_deadline(a, dem, len(g), remaining)
    greedy.seconds = time.perf_counter() - t0
    if x_raw is None:
        if method == "milp":
            raise PlannerError(
                f"the integer program found no plan within the time limit of "
                f"{time_limit_s:g} s ({message}); raise the time limit (--time-limit-s) or "
                "let the planner fall back to greedy set cover (--method auto)"
            )
        greedy.status = f"integer program: {message}"
        return greedy
    x = np.flatnonzero(x_raw > 0.5)
    bound = float(packing)
    if status == 0:
        bound = float(len(x))
    elif dual is not None and np.isfinite(dual):
        bound = max(bound, float(np.ceil(dual - 1e-6)))
    if len(x) > len(g):  # a time-limited incumbent worse than greedy: keep greedy
        greedy.lower_bound, greedy.gap = bound, (len(g) - bound) / len(g)
        greedy.status = "integer program stopped at the time limit with a worse plan"
        return greedy
    return CoverSolution(
        chosen=np.sort(used[x]),
        method="milp",
        status="optimal" if status == 0 else "time limit",
        objective=len(x),
        lower_bound=bound,
        gap=max(0.0, (len(x) - bound) / len(x)),
        seconds=greedy.seconds,
        greedy_objective=len(g),
    )


def spread_views(
    ok: sp.csr_matrix,
    demand: np.ndarray,
    chosen: np.ndarray,
    cand_xy: np.ndarray,
    sample_xy: np.ndarray,
    min_angle_deg: float,
) -> np.ndarray:
    """Add stations until every sample that needs ``demand`` ≥ 2 stations is met by that
    many chosen stations seeing it from directions at least ``min_angle_deg`` apart (in
    plan, from the sample): a sample met twice from beside the same spot has one view, not
    two. Greedy: the candidate that completes the most samples first. Samples no candidate
    can complete stay as they are (the plan reports them)."""
    ok = sp.csr_matrix(ok)
    taken = np.zeros(ok.shape[1], dtype=bool)
    taken[np.asarray(chosen, dtype=np.int64)] = True
    rows = np.flatnonzero(demand >= 2)
    cols_of = {int(i): ok.indices[ok.indptr[i] : ok.indptr[i + 1]] for i in rows}
    az_of = {}  # azimuth of every candidate meeting the row, seen from its sample [deg]
    for i, cols in cols_of.items():
        d = cand_xy[cols] - sample_xy[i]
        az_of[i] = np.degrees(np.arctan2(d[:, 1], d[:, 0]))

    def views(i: int) -> int:
        return separated_directions(az_of[i][taken[cols_of[i]]], min_angle_deg)

    def helpers(i: int, now: int) -> np.ndarray:
        """The candidates whose addition gives row i one more view."""
        cols, az = cols_of[i], az_of[i]
        mask = taken[cols]
        if now == 0:
            return cols[~mask]
        if now == 1:  # a second view: at least the angle from some view taken
            gap = np.abs((az[~mask, None] - az[None, mask] + 180.0) % 360.0 - 180.0)
            return cols[~mask][(gap >= min_angle_deg).any(axis=1)]
        more = [
            c
            for c, a in zip(cols[~mask], az[~mask], strict=True)
            if separated_directions(np.append(az[mask], a), min_angle_deg) > now
        ]
        return np.asarray(more, dtype=np.int64)

    now = {int(i): views(int(i)) for i in rows}
    short = [i for i in now if now[i] < demand[i]]
    while short:
        gain = np.zeros(ok.shape[1], dtype=np.int64)
        for i in short:
            np.add.at(gain, helpers(i, now[i]), 1)
        if not gain.any():
            break
        taken[int(np.argmax(gain))] = True  # the most rows helped (the lowest index on ties)
        for i in short:
            now[i] = views(i)
        short = [i for i in short if now[i] < demand[i]]
    return np.flatnonzero(taken)
