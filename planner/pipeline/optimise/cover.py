"""The station optimiser: fewest stations such that every sample is seen by enough stations
that meet every requirement there — a set multi-cover problem.

1. Classical reductions to a fixed point (:mod:`planner.pipeline.optimise.reduce`): forced stations,
   implied samples, dominated candidates.
2. The rest splits into independent parts (no candidate meets samples of two parts: streets,
   courtyards), each solved on its own.
3. Per part: greedy set cover (the start and the fallback), the packing bound and a
   Lagrangian bound (subgradient ascent on the samples' multipliers; any multipliers give a
   valid bound, approaching the LP relaxation's value); when these meet, the greedy cover is
   proven optimal. Otherwise the ascent also yields covers (greedy weighted by its
   multipliers), the best of which a row-weighting local search improves
   (:mod:`planner.pipeline.optimise.localsearch`); the integer program on the union of the
   smallest of them is solved by HiGHS (``highspy``), started from the best cover, the union
   doubled while it is solved within its node limit; when every cover's union was solved,
   the whole integer program is searched to its node limit, its dual bound kept when it is
   stronger.

Every step is bounded by work — ascent steps, local-search steps, branch-and-bound nodes
(:data:`ASCENT_STEPS`, :data:`LOCAL_STEPS`, :data:`MIP_NODES`), HiGHS on one thread — so
the same problem gives the same stations on any machine, however loaded. The time limit is
a backstop in this process's CPU seconds (:func:`time.process_time`: other work on the
machine does not spend it) for a problem too large for those bounds: it stops the search
early (status "time limit"), never the first cover.

The lower bound reported is the sum over parts of the best bound proven for each plus the
forced stations: a real bound on the fewest stations, whatever stopped the solver.
"""

from __future__ import annotations

import contextlib
import os
import sys
import time
from collections.abc import Iterator
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import connected_components

from planner.errors import PlannerError
from planner.pipeline.optimise.localsearch import row_weighting_search
from planner.pipeline.optimise.reduce import reduce_cover
from planner.polar import separated_directions

__all__ = ["CoverSolution", "greedy_cover", "lagrangian_bound", "lp_bound", "solve_cover"]


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
    #: what the reductions removed ("reductions") and the independent parts ("parts")
    details: dict = field(default_factory=dict)


#: Steps of the subgradient ascent between two covers of the Lagrangian heuristic.
HEURISTIC_EVERY = 25
#: Steps of the subgradient ascent at most (it stops sooner once its bound proves a cover
#: optimal or its step has shrunk to nothing).
ASCENT_STEPS = 1500
#: The smallest covers of the Lagrangian heuristic merged first (then twice as many, while
#: the integer program on their union is solved within :data:`MIP_NODES`). Chosen on the
#: 50-building district's cover (14 292 × 59 148): first 3 / 5 / 7 / 10 / 15 covers gave
#: 52–55 stations.
MERGE_FIRST = 10
#: Steps of the row-weighting local search at most
#: (:mod:`planner.pipeline.optimise.localsearch`; it stops sooner after
#: :data:`~planner.pipeline.optimise.localsearch.STALL_STEPS` without a smaller cover).
LOCAL_STEPS = 400_000
#: Branch-and-bound nodes of each HiGHS integer program at most (one thread: the same
#: nodes, the same answer, on any machine).
MIP_NODES = 2000
#: HiGHS keeps time on the wall clock: it is given this many wall seconds per CPU second of
#: the backstop left (a machine this loaded still reaches the node limit first).
HIGHS_WALL_PER_CPU_S = 4.0
#: The subgradient ascent: the weight of the previous direction in the next …
MOMENTUM = 0.9
#: … and the steps without a better bound after which the step length is halved.
STALL_STEPS = 50


def greedy_cover(
    a: sp.csr_matrix,
    demand: np.ndarray,
    weights: np.ndarray | None = None,
) -> np.ndarray:
    """Greedy multi-cover: repeatedly take the column that serves the most unmet demand, then
    drop chosen columns that became redundant (their rows are served enough without them).

    ``weights`` (one per row, default 1) weigh the rows served: the Lagrangian heuristic of
    Beasley ("A Lagrangian heuristic for set-covering problems", Naval Research Logistics 37,
    1990, https://doi.org/10.1002/1520-6750(199002)37:1<151::AID-NAV3220370110>3.0.CO;2-2)
    uses the multipliers, so rows hard to cover count more. A column's gain is kept up to
    date as rows are served (each row is handled once), not recomputed for every pick.
    """
    a = sp.csr_matrix(a, dtype=np.float64)
    at = a.T.tocsr()
    w = np.ones(a.shape[0]) if weights is None else np.asarray(weights, dtype=np.float64)
    need = demand.astype(np.int64).copy()
    gain = at @ np.where(need > 0, w, 0.0)
    taken = np.zeros(a.shape[1], dtype=bool)
    while True:
        score = np.where(taken, -1.0, gain)
        j = int(np.argmax(score))
        if score[j] <= 1e-12:
            break  # all served, or the rest cannot be
        taken[j] = True
        rows = at.indices[at.indptr[j] : at.indptr[j + 1]]
        need[rows] -= 1
        served = rows[need[rows] == 0]
        if len(served):  # these rows no longer count for any column
            sub = a[served]
            gain -= np.bincount(
                sub.indices, weights=np.repeat(w[served], np.diff(sub.indptr)), minlength=len(gain)
            )
    served = np.asarray(a @ taken.astype(np.float64)).ravel()
    chosen = np.flatnonzero(taken)
    for j in chosen[np.argsort((at @ w)[chosen], kind="stable")]:  # least served first
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
            bound += int(demand[i])
    return int(max(bound, demand.max(initial=0)))


def lagrangian_bound(
    a: sp.csr_matrix,
    demand: np.ndarray,
    upper: float,
    deadline: float,
    iterations: int = ASCENT_STEPS,
    covers: list[np.ndarray] | None = None,
) -> float:
    """A lower bound on the fewest columns by Lagrangian relaxation of the cover rows.

    For multipliers u ≥ 0, L(u) = Σ dᵢuᵢ + Σⱼ min(0, 1 − Σ_{i∈j} uᵢ) is a valid bound on the
    integer (and the LP) optimum; subgradient ascent (Held, Wolfe & Crowder, "Validation of
    subgradient optimization", Mathematical Programming 6, 1974,
    https://doi.org/10.1007/BF01580223; step rule of Beasley 1987) raises it towards the LP
    relaxation's value. ``upper``: a known cover's size (for the step length; the ascent
    stops once the bound, rounded up, reaches it).

    The ascent moves along the subgradients averaged with weights decaying by ``MOMENTUM``
    per step rather than along the last one alone, as the volume algorithm does (Barahona &
    Anbil, "The volume algorithm: producing primal solutions with a subgradient method",
    Mathematical Programming 87, 2000, https://doi.org/10.1007/s101070050002): on the
    50-building district's cover the bound reaches 42.09 in 6 s where the plain ascent
    stalls at 40.63 (the LP relaxation is 42.73; benchmarks/RESULTS.md).

    ``covers``: when a list is given, the Lagrangian heuristic (Beasley 1990, see
    :func:`greedy_cover`) appends to it, every ``HEURISTIC_EVERY`` steps, the greedy cover
    weighted by the multipliers of that step; a smaller one also shortens the steps.
    """
    a = sp.csr_matrix(a, dtype=np.float64)
    at = a.T.tocsr()
    d = demand.astype(np.float64)
    col_size = np.asarray(a.sum(axis=0)).ravel()
    u = 1.0 / a.multiply(col_size).max(axis=1).toarray().ravel()  # feasible dual: Aᵀu ≤ 1
    best, step, stall = -np.inf, 2.0, 0
    direction = np.zeros_like(d)
    for it in range(iterations):
        reduced = 1.0 - at @ u
        x = reduced < 0
        value = d @ u + reduced[x].sum()
        if value > best + 1e-9:
            best, stall = value, 0
        else:
            stall += 1
            if stall >= STALL_STEPS:
                step, stall = step / 2, 0
        if covers is not None and it % HEURISTIC_EVERY == 0:
            covers.append(greedy_cover(a, demand, u + 1e-6))
            upper = min(upper, len(covers[-1]))
        if best > upper - 1 + 1e-6:  # rounded up, the bound proves that cover optimal
            break
        g = d - a @ x.astype(np.float64)
        g[(u <= 0) & (g < 0)] = 0.0  # no move out of u ≥ 0
        if not g.any() or step < 1e-5 or time.process_time() > deadline:
            break  # (a zero projected subgradient: u is optimal)
        direction = g + MOMENTUM * direction
        direction[(u <= 0) & (direction < 0)] = 0.0
        # the step over the larger of the two norms (g is integer, so |g| ≥ 1): no step is
        # longer than step × (upper − value), even where the averaged direction has faded
        norm = max(direction @ direction, g @ g)
        u = np.maximum(0.0, u + step * max(upper - value, 1e-3) / norm * direction)
    return float(best)


def _highs(a: sp.csr_matrix, demand: np.ndarray, start: np.ndarray, time_limit_s: float):
    """The integer program by HiGHS, started from the cover ``start`` (column indices).

    Returns (optimal?, chosen columns or None, dual bound or None). The solve runs in HiGHS's
    own thread, so Ctrl+C, SIGTERM or SIGHUP stop it at once (cancelled, then re-raised).
    """
    import highspy  # heavy: only when solving

    h = _cover_model(a, demand, np.ones(a.shape[1]), time_limit_s, integer=True)
    h.setOptionValue("mip_rel_gap", 0.0)
    h.setOptionValue("mip_max_nodes", MIP_NODES)
    x0 = np.zeros(a.shape[1])
    x0[start] = 1.0
    _set_start(h, highspy, x0)
    _run(h)
    status = h.getModelStatus()
    info = h.getInfo()
    has_x = info.primal_solution_status == 2  # kSolutionStatusFeasible
    x = np.flatnonzero(np.asarray(h.getSolution().col_value) > 0.5) if has_x else None
    dual = info.mip_dual_bound if np.isfinite(info.mip_dual_bound) else None
    return status == highspy.HighsModelStatus.kOptimal, x, dual


def lp_bound(a: sp.csr_matrix, demand: np.ndarray, cost: np.ndarray, time_limit_s: float) -> float:
    """The LP relaxation's optimum of the cover of least ``cost`` (each column at most once),
    by HiGHS's dual simplex: a lower bound on the integer optimum, less a margin for the
    solver's tolerances; 0.0 (still a bound) when it is not solved within the time."""
    import highspy

    if not (demand > 0).any():
        return 0.0
    h = _cover_model(a, demand, cost, time_limit_s, integer=False)
    h.setOptionValue("solver", "simplex")
    h.setOptionValue("simplex_strategy", 1)  # dual
    _run(h)
    if h.getModelStatus() != highspy.HighsModelStatus.kOptimal:
        return 0.0
    value = float(h.getInfo().objective_function_value)
    return max(0.0, value - 1e-6 * max(1.0, abs(value)))


def _cover_model(
    a: sp.csr_matrix, demand: np.ndarray, cost: np.ndarray, time_limit_s: float, integer: bool
):
    """A HiGHS instance holding min cᵀx, Ax ≥ demand, 0 ≤ x ≤ 1 (x integer or not); quiet,
    one thread, ``time_limit_s``."""
    import highspy

    n, m = a.shape
    with _c_stdout_to_null():
        h = highspy.Highs()
    h.setOptionValue("output_flag", False)
    h.setOptionValue("time_limit", float(time_limit_s))
    h.setOptionValue("threads", 1)
    ac = sp.csc_matrix(a, dtype=np.float64)
    lp = highspy.HighsLp()
    lp.num_col_, lp.num_row_ = m, n
    lp.col_cost_ = np.asarray(cost, dtype=np.float64)
    lp.col_lower_ = np.zeros(m)
    lp.col_upper_ = np.ones(m)
    lp.row_lower_ = demand.astype(np.float64)
    lp.row_upper_ = np.full(n, highspy.kHighsInf)
    lp.a_matrix_.format_ = highspy.MatrixFormat.kColwise
    lp.a_matrix_.start_ = ac.indptr
    lp.a_matrix_.index_ = ac.indices
    lp.a_matrix_.value_ = ac.data
    if integer:
        lp.integrality_ = [highspy.HighsVarType.kInteger] * m
    h.passModel(lp)
    return h


@contextlib.contextmanager
def _c_stdout_to_null() -> Iterator[None]:
    """The process's standard output (file descriptor 1) sent to the null device: HiGHS
    prints its banner there while an instance is made, before any option can turn its output
    off (ERGO-Code/HiGHS issues 1932 and 2749), and the planner's standard output carries
    the plan's summary."""
    sys.stdout.flush()
    try:
        saved = os.dup(1)
    except OSError:  # no standard output at all: nothing to keep clean
        yield
        return
    try:
        with open(os.devnull, "wb") as null:
            os.dup2(null.fileno(), 1)
        yield
    finally:
        os.dup2(saved, 1)
        os.close(saved)


def _run(h) -> None:
    """Solve in HiGHS's own thread, so that Ctrl+C, SIGTERM or SIGHUP stop it at once
    (cancelled, then re-raised)."""
    h.startSolve()
    try:
        while not h.wait(0.1)[0]:
            pass
    except BaseException:
        h.cancelSolve()
        h.wait(5.0)
        raise


def _set_start(h, highspy, x0: np.ndarray) -> None:
    sol = highspy.HighsSolution()
    sol.col_value = list(x0)
    sol.value_valid = True
    h.setSolution(sol)


def _components(a: sp.csr_matrix) -> np.ndarray:
    """Label each row by its independent part (0, 1, …; rows joined through shared columns)."""
    graph = sp.bmat([[None, a], [a.T, None]]).tocsr()
    _, label = connected_components(graph, directed=False)
    return np.unique(label[: a.shape[0]], return_inverse=True)[1]


@dataclass
class _Part:
    """One independent part's answer."""

    chosen: np.ndarray
    bound: int
    greedy: int
    how: str

    @property
    def proven(self) -> bool:
        return self.bound >= len(self.chosen)


def _merge(
    a: sp.csr_matrix, demand: np.ndarray, covers: list[np.ndarray], deadline: float
) -> tuple[np.ndarray, bool]:
    """The fewest columns out of the union of ``covers`` (each a cover of ``a``): the integer
    program on that small core, reduced first and started from the smallest cover.

    Solution merging, the core problem of Caprara, Fischetti & Toth ("A heuristic method for
    the set covering problem", Operations Research 47, 1999,
    https://doi.org/10.1287/opre.47.5.730) built from the Lagrangian heuristic's covers.
    Returns (columns, proven optimal on the core).
    """
    best = min(covers, key=len)
    core = np.unique(np.concatenate(covers))
    red = reduce_cover(a[:, core], demand)
    if not red.a.shape[0]:
        return core[red.forced], True
    start = np.flatnonzero(np.isin(core[red.columns], best))  # HiGHS repairs it if need be
    optimal, x, _ = _highs(red.a, red.demand, start, _wall_s(deadline))
    if x is None or len(x) + len(red.forced) >= len(best):
        return best, optimal
    return np.union1d(core[red.forced], core[red.columns[x]]), optimal


def _wall_s(deadline: float) -> float:
    """HiGHS's wall-clock limit for the CPU backstop ``deadline`` (a
    :func:`time.process_time` time): :data:`HIGHS_WALL_PER_CPU_S` per CPU second left."""
    return HIGHS_WALL_PER_CPU_S * max(0.0, deadline - time.process_time())


def _solve_part(
    a: sp.csr_matrix, demand: np.ndarray, deadline: float, method: str, steps: int
) -> _Part:
    """Greedy cover and its bounds; then, where they differ, the Lagrangian heuristic's best
    cover (``steps`` of ascent), the local search, solution merging and the whole integer
    program — each to its work bound, or to the backstop ``deadline``."""
    g = greedy_cover(a, demand)
    bound = packing_lower_bound(a, demand)
    if bound >= len(g):
        return _Part(g, len(g), len(g), "greedy = packing bound")
    covers = [g]
    ascent = lagrangian_bound(a, demand, len(g), deadline, iterations=steps, covers=covers)
    bound = max(bound, int(np.ceil(ascent - 1e-6)))
    best = min(covers, key=len)
    if bound >= len(best) or method == "greedy":
        return _Part(best, min(bound, len(best)), len(g), "greedy, Lagrangian bound")
    how = "greedy, Lagrangian bound"
    searched = (
        best
        if method == "milp"
        else row_weighting_search(a, demand, best, deadline, max_steps=LOCAL_STEPS, floor=bound)
    )
    if len(searched) < len(best):
        best, how = searched, "row-weighting local search"
        covers.append(searched)
    if bound >= len(best):
        return _Part(best, bound, len(g), how)
    ranked = sorted(covers, key=len)  # merged from the smallest: a core grown while solved
    k = MERGE_FIRST
    while time.process_time() < deadline and len(covers) > 1:
        merged, core_solved = _merge(a, demand, [best, *ranked[:k]], deadline)
        if len(merged) < len(best):
            best, how = merged, "integer program on the Lagrangian heuristic's covers"
        if not core_solved:  # a larger core, or the whole program, would not be either
            return _Part(best, min(bound, len(best)), len(g), how)
        if k >= len(ranked):
            break
        k *= 2
    if time.process_time() >= deadline:
        how += " (the time limit stopped it before the integer program)"
        return _Part(best, min(bound, len(best)), len(g), how)
    optimal, x, dual = _highs(a, demand, best, _wall_s(deadline))
    if dual is not None:
        bound = max(bound, int(np.ceil(dual - 1e-6)))
    if x is not None and len(x) <= len(best):
        best, how = x, "integer program"
    return _Part(best, len(best) if optimal else min(bound, len(best)), len(g), how)


def solve_cover(
    ok: sp.csr_matrix, demand: np.ndarray, time_limit_s: float = 20.0, method: str = "auto"
) -> CoverSolution:
    """Fewest columns of ``ok`` (samples × candidates) covering each row ``demand`` times.

    ``demand`` must already be capped at what each row can get (its number of candidates).
    ``method``: "auto" (the integer program where the bounds do not already prove the greedy
    cover optimal), "milp" (an error unless every part is proven optimal) or "greedy"
    (greedy cover with its bounds; with ``time_limit_s`` 0, the greedy covers alone). The
    search is bounded by work (module docstring); ``time_limit_s`` is its backstop. The
    bound reported is always a proven lower bound on the fewest stations.
    """
    t0 = time.perf_counter()
    deadline = time.process_time() + max(0.0, time_limit_s)  # CPU seconds: see the module
    ok = sp.csr_matrix(ok)
    demand = np.asarray(demand, dtype=np.int64)
    red = reduce_cover(ok, demand, deadline)
    details: dict = {"reductions": red.describe()}
    chosen, parts = [red.forced], []
    if red.a.shape[0]:
        label = _components(red.a)
        order = np.argsort(np.bincount(label), kind="stable")  # small parts first
        steps = ASCENT_STEPS if time_limit_s > 0 else 1
        for p in order:
            rows = np.flatnonzero(label == p)
            sub = red.a[rows]
            cols = np.flatnonzero(np.diff(sub.tocsc().indptr) > 0)
            sub = sub[:, cols].tocsr()
            part = _solve_part(sub, red.demand[rows], deadline, method, steps)
            chosen.append(red.columns[cols[part.chosen]])
            parts.append(part)
    chosen_all = np.unique(np.concatenate(chosen)).astype(np.int64)
    n = len(chosen_all)
    bound = len(red.forced) + sum(p.bound for p in parts)
    proven = all(p.proven for p in parts)
    used_milp = any(p.how.startswith("integer program") for p in parts)
    searched = any(p.how.startswith("row-weighting") for p in parts)
    details["parts"] = len(parts)
    greedy_total = len(red.forced) + sum(p.greedy for p in parts)
    if method == "milp" and not proven:
        raise PlannerError(
            f"the integer program was not proven optimal within {MIP_NODES} nodes or the "
            f"time limit of {time_limit_s:g} s ({n} stations, lower bound {bound}); accept "
            "the best plan found (--method auto)"
        )
    if not red.a.shape[0] and not len(red.forced):
        status = "nothing to cover"
    elif proven:
        status = "optimal"
    elif method == "greedy":
        status = "as requested"
    elif time.process_time() >= deadline:
        status = "time limit"
    else:
        status = "work limit"
    return CoverSolution(
        chosen=chosen_all,
        method="milp" if used_milp else "local search" if searched else "greedy",
        status=status,
        objective=n,
        lower_bound=float(min(bound, n)),
        gap=0.0 if n == 0 else max(0.0, (n - bound) / n),
        seconds=time.perf_counter() - t0,
        greedy_objective=greedy_total,
        details=details,
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
