"""The optimiser: reductions keep the optimum, parts are solved independently, the bounds are
real bounds, HiGHS starts from the greedy cover, and ``milp`` is strict."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
import scipy.sparse as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

import planner.pipeline.optimise.cover as opt
from planner.errors import PlannerError
from planner.pipeline.optimise.reduce import reduce_cover, subset_pairs
from planner.pipeline.optimise.spacing import close_pairs, merge_close


def random_cover(n_rows=80, n_cols=120, density=0.05, seed=3, max_demand=1):
    """A random multi-cover instance; every row can be met ``demand`` times."""
    rng = np.random.default_rng(seed)
    a = (rng.random((n_rows, n_cols)) < density).astype(np.int8)
    for i in range(n_rows):
        a[i, rng.integers(n_cols)] = 1
    demand = np.minimum(rng.integers(1, max_demand + 1, n_rows), a.sum(axis=1))
    return sp.csr_matrix(a), demand


def brute_force(a: sp.csr_matrix, demand: np.ndarray) -> int:
    """The fewest columns by trying every subset, smallest first (tiny instances only)."""
    dense = a.toarray().astype(int)
    for k in range(a.shape[1] + 1):
        for cols in itertools.combinations(range(a.shape[1]), k):
            if (dense[:, list(cols)].sum(axis=1) >= demand).all():
                return k
    raise AssertionError("no cover")


def lp_value(a: sp.csr_matrix, demand: np.ndarray) -> float:
    m = a.shape[1]
    res = linprog(np.ones(m), A_ub=-a.toarray(), b_ub=-demand, bounds=(0, 1), method="highs")
    assert res.status == 0
    return float(res.fun)


def covers(a, demand, chosen) -> bool:
    return bool((np.asarray(a[:, chosen].sum(axis=1)).ravel() >= demand).all())


@settings(max_examples=60, deadline=None)
@given(
    seed=st.integers(0, 10_000),
    n_rows=st.integers(1, 12),
    n_cols=st.integers(1, 11),
    density=st.floats(0.1, 0.6),
    max_demand=st.integers(1, 3),
)
def test_reductions_and_solver_keep_the_optimum(seed, n_rows, n_cols, density, max_demand):
    """On random multi-cover instances, the reduced problem solved (forced + parts) has the
    optimum found by trying every subset of the unreduced problem, and is a valid cover."""
    a, d = random_cover(n_rows, n_cols, density, seed, max_demand)
    best = brute_force(a, d)
    sol = opt.solve_cover(a, d, time_limit_s=10)
    assert covers(a, d, sol.chosen)
    assert sol.objective == best and sol.status == "optimal"
    assert sol.lower_bound == best
    # the reduced problem alone: forced columns + its own optimum = the whole optimum
    red = reduce_cover(a, d)
    rest = brute_force(red.a, red.demand) if red.a.shape[0] else 0
    assert len(red.forced) + rest == best


def test_subset_pairs_are_exactly_the_subsets():
    a, _ = random_cover(60, 40, 0.08, seed=11)
    a = sp.csr_matrix(a[:, :6])  # few items: many subset pairs, identical sets too
    dense = a.toarray().astype(bool)
    x, y = subset_pairs(a)
    found = set(zip(x.tolist(), y.tolist(), strict=True))
    truth = {
        (i, j)
        for i in range(len(dense))
        for j in range(len(dense))
        if i != j and dense[i].any() and not (dense[i] & ~dense[j]).any()
    }
    assert found == truth and len(truth) > 100
    # only some sets as the subset; one pair per subset or per superset that has any
    among = np.arange(len(dense)) % 3 == 0
    x, y = subset_pairs(a, among=among)
    assert set(zip(x.tolist(), y.tolist(), strict=True)) == {p for p in truth if among[p[0]]}
    for side, witness in ((0, "x"), (1, "y")):
        pairs = list(zip(*subset_pairs(a, witness=witness), strict=True))
        assert set(pairs) <= truth
        assert sorted(p[side] for p in pairs) == sorted({p[side] for p in truth})
    x, y = subset_pairs(a, allowed=lambda x, y: x < y)
    assert set(zip(x.tolist(), y.tolist(), strict=True)) == {p for p in truth if p[0] < p[1]}


def test_reductions_remove_what_they_should():
    """A row met by one candidate forces it; an identical-or-smaller column goes; a row
    whose candidates include another row's goes."""
    a = sp.csr_matrix(
        np.array(
            [
                [1, 0, 0, 0],  # only column 0: forced
                [0, 1, 1, 0],  # columns 1, 2
                [0, 1, 1, 1],  # implied by the row above
                [0, 0, 1, 1],
            ]
        )
    )
    red = reduce_cover(a, np.ones(4, dtype=int))
    # row 2 goes (implied by row 1); columns 1 and 3 go (inside column 2); then rows 1 and
    # 3 have column 2 alone: forced, and nothing is left to solve
    assert red.counts["implied rows"] >= 1 and red.counts["dominated columns"] == 2
    assert red.forced.tolist() == [0, 2] and red.a.shape[0] == 0
    assert sorted(opt.solve_cover(a, np.ones(4, dtype=int)).chosen.tolist()) == [0, 2]


def test_dominance_is_not_used_where_a_row_needs_two():
    """Column 0 ⊂ column 1, but the row needs both: column 0 must stay."""
    a = sp.csr_matrix(np.array([[1, 1], [0, 1]]))
    sol = opt.solve_cover(a, np.array([2, 1]))
    assert sorted(sol.chosen.tolist()) == [0, 1]


def test_parts_solved_independently_sum_up():
    a1, d1 = random_cover(40, 30, 0.12, seed=5)
    a2, d2 = random_cover(50, 35, 0.10, seed=6, max_demand=2)
    whole = sp.block_diag([a1, a2]).tocsr()
    sol = opt.solve_cover(whole, np.concatenate([d1, d2]), time_limit_s=30)
    s1 = opt.solve_cover(a1, d1, time_limit_s=30)
    s2 = opt.solve_cover(a2, d2, time_limit_s=30)
    assert sol.status == s1.status == s2.status == "optimal"
    assert sol.objective == s1.objective + s2.objective
    assert sol.details["parts"] >= 2


def test_lagrangian_bound_is_below_the_lp_and_close_to_it():
    a, d = random_cover(150, 200, 0.04, seed=9)
    lp = lp_value(a, d)
    g = opt.greedy_cover(a, d)
    bound = opt.lagrangian_bound(a, d, len(g), deadline=np.inf, iterations=3000)
    assert bound <= lp + 1e-6  # stations: a valid bound never exceeds the LP optimum
    assert bound >= 0.999 * lp  # and the ascent along averaged subgradients gets close to it
    assert bound >= opt.packing_lower_bound(a, d) - 1


def test_lagrangian_bound_never_passes_the_lp_on_small_instances():
    """Small instances whose multipliers have directions along which the bound is flat (a
    row needing both of its two columns): the averaged direction once carried the ascent
    off along them (multipliers of 1e15, a 'bound' of 2^30 from cancellation)."""
    for seed in range(80):
        a, d = random_cover(9 + seed % 7, 7 + seed % 5, 0.2, seed=seed, max_demand=2)
        lp = lp_value(a, d)
        upper = a.shape[1]  # every column: a cover
        bound = opt.lagrangian_bound(a, d, upper, np.inf, 3000)
        assert bound <= lp + 1e-6
        # near the LP, or far enough up to prove a cover of ``upper`` columns optimal
        assert bound >= 0.95 * lp - 1e-6 or np.ceil(bound - 1e-6) >= upper


def test_lp_bound_is_the_lp_relaxation_at_any_prices():
    """HiGHS's dual simplex through ``lp_bound`` against scipy's LP, unit and uneven prices;
    never above the integer optimum (brute force)."""
    for seed in range(12):
        a, d = random_cover(10, 8, 0.3, seed=seed, max_demand=2)
        price = np.random.default_rng(seed).choice([1.0, 0.5, 1 / 3], a.shape[1])
        for c in (np.ones(a.shape[1]), price):
            res = linprog(c, A_ub=-a.toarray(), b_ub=-d, bounds=(0, 1), method="highs")
            assert opt.lp_bound(a, d, c, 10.0) == pytest.approx(res.fun, abs=1e-5)  # stations
        assert opt.lp_bound(a, d, np.ones(a.shape[1]), 10.0) <= brute_force(a, d) + 1e-9
    assert opt.lp_bound(a, np.zeros_like(d), np.ones(a.shape[1]), 10.0) == 0.0


def textbook_greedy(a, demand, w):
    """Greedy multi-cover recounting every column's (weighted) gain at every pick, then
    dropping redundant columns, least-weighted first."""
    dense = a.toarray().astype(float)
    need = demand.astype(int).copy()
    taken = np.zeros(a.shape[1], dtype=bool)
    while True:
        gain = np.where(taken, -1.0, dense.T @ np.where(need > 0, w, 0.0))
        j = int(np.argmax(gain))
        if gain[j] <= 0:
            break
        taken[j] = True
        need -= dense[:, j].astype(int)
    served = dense @ taken
    chosen = np.flatnonzero(taken)
    for j in chosen[np.argsort((dense.T @ w)[chosen], kind="stable")]:
        rows = dense[:, j] > 0
        if (served[rows] - 1 >= demand[rows]).all():
            taken[j] = False
            served[rows] -= 1
    return np.flatnonzero(taken)


def test_greedy_keeps_its_gains_up_to_date():
    """The greedy cover updates a column's gain as rows are served instead of recounting
    them all at every pick: the same columns as the textbook greedy, weighted or not."""
    for seed in range(6):
        a, d = random_cover(60, 80, 0.06, seed=seed, max_demand=2)
        w = np.random.default_rng(seed).integers(1, 5, a.shape[0]).astype(float)
        assert opt.greedy_cover(a, d, w).tolist() == textbook_greedy(a, d, w).tolist()
        assert opt.greedy_cover(a, d).tolist() == textbook_greedy(a, d, np.ones(len(d))).tolist()


def test_lagrangian_heuristic_and_merging_improve_on_greedy():
    """The covers found along the ascent (greedy weighted by the multipliers) are covers and
    smaller than the plain greedy one; the integer program on their union is smaller still
    or equal, and never below the bound."""
    import time

    a, d = random_cover(300, 400, 0.02, seed=0, max_demand=2)
    g = opt.greedy_cover(a, d)
    pool = [g]
    bound = opt.lagrangian_bound(a, d, len(g), np.inf, covers=pool)
    assert len(pool) > 10 and all(covers(a, d, c) for c in pool)
    best = min(pool, key=len)
    assert len(best) <= len(g) - 5  # 86 → 79 columns on this instance
    merged, _ = opt._merge(a, d, pool, time.monotonic() + 5)
    assert covers(a, d, merged)
    assert bound <= len(merged) <= len(best)


def test_highs_starts_from_greedy_and_never_returns_worse():
    """With almost no time, HiGHS still returns the greedy start (or better), never nothing;
    the bound reported is a true bound (≤ the proven optimum found with time)."""
    a, d = random_cover(120, 150, 0.04, seed=2)
    g = opt.greedy_cover(a, d)
    quick = opt.solve_cover(a, d, time_limit_s=0.01)
    assert covers(a, d, quick.chosen) and quick.objective <= len(g)
    full = opt.solve_cover(a, d, time_limit_s=60)
    assert full.status == "optimal"
    assert quick.lower_bound <= full.objective <= quick.objective


def test_the_same_cover_whatever_the_clock_says(monkeypatch):
    """The search is bounded by work: a wall clock racing an hour a look gives the same
    cover as a calm one (the backstop is this process's CPU time, which other work on the
    machine does not spend). Negative control: a CPU backstop of nothing stops the search
    at its first cover, and says "time limit"."""
    import time

    a, d = random_cover(100, 120, 0.04, seed=1)
    calm = opt.solve_cover(a, d, time_limit_s=60)
    real, looks = time.monotonic, [0]

    def racing() -> float:
        looks[0] += 1
        return real() + 3600.0 * looks[0]

    monkeypatch.setattr(time, "monotonic", racing)
    hurried = opt.solve_cover(a, d, time_limit_s=60)
    assert hurried.chosen.tolist() == calm.chosen.tolist()
    assert hurried.status == calm.status != "time limit"
    assert calm.status == "optimal" and calm.objective == 22  # (greedy: 24)
    stopped = opt.solve_cover(a, d, time_limit_s=0.0, method="auto")
    assert stopped.status == "time limit" and covers(a, d, stopped.chosen)
    assert stopped.objective == 24  # the first covers: the search stopped before it began


def test_milp_method_is_strict(monkeypatch):
    """``method="milp"`` never falls back to greedy silently; ``auto`` does, and says so
    (its work bounds reached, not the time: "work limit")."""
    a, d = random_cover(60, 80, 0.06, seed=4)
    monkeypatch.setattr(opt, "_highs", lambda *a, **k: (False, None, None))
    monkeypatch.setattr(opt, "packing_lower_bound", lambda a, d: 0)
    monkeypatch.setattr(opt, "lagrangian_bound", lambda *a, **k: 0.0)
    monkeypatch.setattr(opt, "reduce_cover", lambda a, d, deadline=None: _unreduced(a, d))
    with pytest.raises(PlannerError, match="not proven optimal"):
        opt.solve_cover(a, d, 5.0, "milp")
    auto = opt.solve_cover(a, d, 5.0, "auto")
    assert auto.method in ("greedy", "local search") and auto.status == "work limit"
    assert covers(a, d, auto.chosen) and auto.lower_bound == 0


def _unreduced(a, d):
    from planner.pipeline.optimise.reduce import Reduced

    a = sp.csr_matrix(a)
    return Reduced(a=a, demand=d, columns=np.arange(a.shape[1]), forced=np.empty(0, dtype=int))


def test_interrupt_cancels_the_solver(monkeypatch):
    """Ctrl+C (or SIGTERM turned into an exception) while HiGHS runs: the solve is
    cancelled and the exception goes on, so the plan folder's clean-up runs."""
    import highspy

    calls = []
    real_wait, real_cancel = highspy.Highs.wait, highspy.Highs.cancelSolve

    def wait(self, timeout):  # Ctrl+C during the first wait; then the solve is joined
        calls.append(timeout)
        if len(calls) == 1:
            raise KeyboardInterrupt
        return real_wait(self, timeout)

    def cancel(self):
        cancelled.append(1)
        return real_cancel(self)

    monkeypatch.setattr(highspy.Highs, "wait", wait, raising=False)
    cancelled = []
    monkeypatch.setattr(highspy.Highs, "cancelSolve", cancel)
    a, d = random_cover(60, 80, 0.06, seed=4)
    with pytest.raises(KeyboardInterrupt):
        opt._highs(a, d, opt.greedy_cover(a, d), 5.0)
    assert cancelled and calls


def test_highs_prints_nothing_on_the_standard_output(capfd):
    """HiGHS writes its licence banner to the C standard output when an instance is made;
    the planner's standard output carries the summary, and ``-q`` promises quiet."""
    a, demand = random_cover(n_rows=30, n_cols=40, seed=5)
    assert opt.lp_bound(a, demand, np.ones(a.shape[1]), 5.0) > 0
    opt._highs(a, demand, np.arange(a.shape[1]), 5.0)
    out, err = capfd.readouterr()
    assert "HiGHS" not in out + err
    assert out == ""


def test_copied_columns_go_first_and_the_optimum_stays():
    """A grid of candidates over few rows is mostly copies (the same samples met): the
    first of each stays, a copy goes only where its rows need one station, and the reduced
    problem keeps the optimum of the whole (an integer program on both)."""
    from scipy.optimize import Bounds, LinearConstraint, milp

    from planner.pipeline.optimise.reduce import _copies

    cols = sp.csr_matrix(np.array([[1, 0, 1], [0, 1, 0], [1, 0, 1], [1, 0, 1], [0, 0, 0]]))
    assert _copies(cols).tolist() == [False, False, True, True, False]

    def optimum(a, d):
        if a.shape[0] == 0:
            return 0
        m = a.shape[1]
        res = milp(
            np.ones(m),
            constraints=LinearConstraint(a.toarray(), lb=d),
            integrality=np.ones(m),
            bounds=Bounds(0, 1),
        )
        assert res.status == 0
        return round(res.fun)

    rng = np.random.default_rng(5)
    for trial in range(20):
        patterns = rng.random((6, 12)) < 0.4
        a = sp.csr_matrix(patterns[:, rng.integers(0, 12, 400)].astype(np.int8))
        need = 1 if trial % 2 else rng.integers(1, 3, 6)  # every row one station, or some two
        d = np.minimum(need, np.diff(a.indptr))
        live = d > 0
        a, d = sp.csr_matrix(a[live]), d[live]
        red = reduce_cover(a, d)
        if trial % 2:
            assert red.counts["dominated columns"] > 300  # 400 columns, 12 patterns
        assert len(red.forced) + optimum(red.a, red.demand) == optimum(a, d)


def _corner_cover():
    """Two chosen stations 2 m apart (0 and 1), each meeting samples the other misses, a
    candidate between them (2) meeting all of them, one far off (3) meeting the rest."""
    a = np.array(
        [
            [1, 0, 1, 0],
            [1, 0, 1, 0],
            [0, 1, 1, 0],
            [0, 0, 0, 1],
        ]
    )
    xy = np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 0.5], [40.0, 0.0]])
    return sp.csr_matrix(a), np.ones(4, dtype=np.int64), xy


def test_two_stations_on_one_spot_become_one_that_meets_what_both_did():
    a, demand, xy = _corner_cover()
    m = merge_close(a, demand, np.array([0, 1, 3]), xy, spacing_m=5.0)
    assert m.chosen.tolist() == [2, 3] and m.merged == [(0, 1, 2)] and m.kept == []
    served = np.asarray(a[:, m.chosen].sum(axis=1)).ravel()
    assert (served >= demand).all()
    # one of the pair does where it meets what the other did
    a2 = a.tolil()
    a2[2, 0] = 1
    m = merge_close(sp.csr_matrix(a2), demand, np.array([0, 1, 3]), xy, spacing_m=5.0)
    assert m.chosen.tolist() == [0, 3]  # the first of the pair kept: the plan changes least


def test_a_pair_no_one_set_up_replaces_is_kept_and_returned():
    a, demand, xy = _corner_cover()
    a = a.tolil()
    a[:, 2] = 0  # nothing between them
    m = merge_close(sp.csr_matrix(a), demand, np.array([0, 1, 3]), xy, spacing_m=5.0)
    assert m.chosen.tolist() == [0, 1, 3] and m.merged == [] and m.kept == [(0, 1)]
    # a sample both must see (demand 2) cannot be met by one
    a, demand, xy = _corner_cover()
    demand[0] = 2
    assert merge_close(a, demand, np.array([0, 1, 3]), xy, 5.0).kept == [(0, 1)]
    # a station placed by hand is never moved: the other goes only if the hand one does
    assert merge_close(a, np.ones(4, int), np.array([0, 1, 3]), xy, 5.0, keep=[0]).kept == [(0, 1)]
    # spacing 0 merges nothing; 1.5 m leaves a pair 2 m apart alone
    three = np.array([0, 1, 3])
    assert merge_close(a, np.ones(4, int), three, xy, 0.0).chosen.tolist() == [0, 1, 3]
    assert close_pairs(xy[[0, 1, 3]], 1.5) == []
    assert close_pairs(xy, 5.0) == [(0, 2), (1, 2), (0, 1)]  # closest first


def test_the_default_plan_keeps_the_crews_spacing(default_plan):
    from sites import assert_spaced

    assert_spaced(default_plan)
    assert "Station spacing: no two set-ups closer than 5 m" in default_plan.summary()
    assert default_plan.solver.spacing_untried == 0
    # negative control: with no spacing kept, the same site's plan has two set-ups 4 m
    # apart (the registration rounds put them there) and one station more, no sample more
    from dataclasses import replace

    from planner.pipeline.engine.planning import plan

    loose = plan(settings=replace(default_plan.settings, station_spacing_m=0.0))
    xy = loose.stations[["x", "y"]].to_numpy()
    assert close_pairs(xy, 5.0) and len(loose.stations) == len(default_plan.stations) + 1
    assert loose.scanned["meets"].sum() == default_plan.scanned["meets"].sum()
