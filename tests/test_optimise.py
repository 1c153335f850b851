"""The optimiser's engines: greedy, the packing bound, milp in-process and in a worker."""

from __future__ import annotations

import subprocess
import sys
import time

import numpy as np
import pytest
import scipy.sparse as sp

import planner.pipeline.optimise as opt


def random_cover(n_rows=80, n_cols=120, density=0.05, seed=3):
    """A small random set-cover instance HiGHS proves optimal in well under a second."""
    rng = np.random.default_rng(seed)
    a = sp.random(n_rows, n_cols, density=density, random_state=rng, format="csr").astype(bool)
    a = a.tolil()
    for i in range(n_rows):  # every row coverable
        a[i, rng.integers(n_cols)] = True
    return a.tocsr(), np.ones(n_rows, dtype=int)


def test_greedy_covers_and_packing_bound_is_a_bound():
    a, d = random_cover()
    g = opt.greedy_cover(a, d)
    assert (np.asarray(a[:, g].sum(axis=1)).ravel() >= 1).all()
    exact = opt.solve_cover(a, d, time_limit_s=30)
    assert exact.status == "optimal"
    assert opt.packing_lower_bound(a, d) <= exact.objective <= len(g)


def test_worker_process_gives_the_in_process_answer(monkeypatch):
    a, d = random_cover()
    inside = opt.solve_cover(a, d, time_limit_s=30)
    monkeypatch.setattr(opt, "IN_PROCESS_NNZ", 0)
    worker = opt.solve_cover(a, d, time_limit_s=30)
    assert worker.status == "optimal" and worker.objective == inside.objective


def test_deadline_stops_a_solver_that_does_not_return(monkeypatch):
    """HiGHS presolve can ignore its time limit; the worker is then killed at the deadline
    (time limit + 5 s) and the greedy cover is the plan, with the packing-bound gap."""
    a, d = random_cover()
    monkeypatch.setattr(opt, "IN_PROCESS_NNZ", 0)
    real_popen = subprocess.Popen

    def stuck(cmd, **kw):
        return real_popen([sys.executable, "-c", "import time; time.sleep(120)"], **kw)

    monkeypatch.setattr(opt.subprocess, "Popen", stuck)
    t0 = time.perf_counter()
    sol = opt.solve_cover(a, d, time_limit_s=1.0)
    elapsed = time.perf_counter() - t0
    assert elapsed < 1.0 + 5.0 + 3.0  # s: the limit, the grace, start-up slack
    assert sol.method == "greedy" and "stopped at the time limit" in sol.status
    assert sol.lower_bound == opt.packing_lower_bound(*opt._reduce(a, d)[:2])
    assert sol.gap == pytest.approx((sol.objective - sol.lower_bound) / sol.objective)
