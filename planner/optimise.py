"""The station optimiser: fewest stations such that every sample is seen by enough stations
that meet every requirement there — a set multi-cover problem.

Solved exactly as an integer program with ``scipy.optimize.milp`` (HiGHS) under a time limit,
with greedy set cover as the fallback and as an upper bound (scipy's milp takes no initial
solution, so the greedy count is given to HiGHS as the constraint ``Σx <= greedy``).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.optimize import Bounds, LinearConstraint, milp

__all__ = ["CoverSolution", "greedy_cover", "solve_cover"]


@dataclass
class CoverSolution:
    """Chosen candidate indices and how they were found."""

    chosen: np.ndarray
    method: str  # "milp" or "greedy"
    status: str  # "optimal", "time limit", "greedy only", "nothing to cover"
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
    return a[:, used].tocsc().tocsr(), demand, used


def greedy_cover(a: sp.csr_matrix, demand: np.ndarray) -> np.ndarray:
    """Greedy multi-cover: repeatedly take the column that serves the most unmet demand."""
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
        rows = at.indices[at.indptr[j] : at.indptr[j + 1]]
        need[rows] -= 1
    return np.array(chosen, dtype=np.int64)


def solve_cover(
    ok: sp.csr_matrix, demand: np.ndarray, time_limit_s: float = 20.0, method: str = "auto"
) -> CoverSolution:
    """Fewest columns of ``ok`` (samples × candidates) covering each row ``demand`` times.

    ``demand`` must already be capped at what each row can get (its number of candidates).
    ``method``: "auto" (milp, greedy as fallback), "milp" or "greedy".
    """
    t0 = time.perf_counter()
    a, dem, used = _reduce(sp.csr_matrix(ok), np.asarray(demand))
    if a.shape[0] == 0:
        return CoverSolution(
            np.empty(0, dtype=np.int64),
            "greedy",
            "nothing to cover",
            0,
            0.0,
            0.0,
            time.perf_counter() - t0,
            0,
        )
    g = greedy_cover(a, dem)
    greedy_solution = CoverSolution(
        np.sort(used[g]),
        "greedy",
        "greedy only",
        len(g),
        None,
        None,
        time.perf_counter() - t0,
        len(g),
    )
    if method == "greedy":
        return greedy_solution
    n = a.shape[1]
    constraints = [
        LinearConstraint(a.astype(float), lb=dem, ub=np.inf),
        LinearConstraint(np.ones((1, n)), lb=0, ub=len(g)),
    ]
    remaining = max(1.0, time_limit_s - (time.perf_counter() - t0))
    res = milp(
        np.ones(n),
        integrality=np.ones(n),
        bounds=Bounds(0, 1),
        constraints=constraints,
        options={"time_limit": remaining, "disp": False, "presolve": True},
    )
    seconds = time.perf_counter() - t0
    if res.x is None:
        greedy_solution.seconds = seconds
        greedy_solution.status = f"greedy (milp: {res.message})"
        return greedy_solution
    x = np.flatnonzero(res.x > 0.5)
    bound = getattr(res, "mip_dual_bound", None)
    if res.status == 0:
        bound = float(len(x)) if bound is None or not np.isfinite(bound) else bound
    if len(x) > len(g):  # a time-limited incumbent worse than greedy: keep greedy
        greedy_solution.lower_bound = bound
        greedy_solution.gap = None if bound is None else (len(g) - bound) / len(g)
        greedy_solution.seconds = seconds
        greedy_solution.status = "greedy (milp incumbent worse at the time limit)"
        return greedy_solution
    bound_val = None if bound is None or not np.isfinite(bound) else float(np.ceil(bound - 1e-6))
    gap = None if bound_val is None else max(0.0, (len(x) - bound_val) / len(x))
    status = "optimal" if res.status == 0 else "time limit"
    return CoverSolution(np.sort(used[x]), "milp", status, len(x), bound_val, gap, seconds, len(g))
