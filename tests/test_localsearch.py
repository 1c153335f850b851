"""The row-weighting local search (:mod:`planner.pipeline.optimise.localsearch`) on a
recorded hard instance, and the optimiser's bound against the LP relaxation (HiGHS)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.optimize import linprog

from planner.pipeline.optimise.cover import greedy_cover, lagrangian_bound, solve_cover
from planner.pipeline.optimise.localsearch import row_weighting_search
from tests.test_optimise import random_cover

DATA = Path(__file__).parent / "data" / "covers"
#: the best cover of the 50-building grid any method had found before the local search
#: (tests/data/covers/README.md), its forced station included
BEST_KNOWN = 50


def load(name: str) -> tuple[sp.csr_matrix, np.ndarray, int]:
    z = np.load(DATA / f"{name}.npz")
    a = sp.csr_matrix(
        (np.ones(len(z["indices"]), dtype=bool), z["indices"], z["indptr"]), shape=tuple(z["shape"])
    )
    return a, z["demand"].astype(np.int64), int(z["forced"][0])


def _covers(a: sp.csr_matrix, demand: np.ndarray, chosen: np.ndarray) -> bool:
    x = np.zeros(a.shape[1])
    x[chosen] = 1.0
    return bool((a.astype(float) @ x >= demand).all())


def test_the_search_beats_the_best_known_cover_of_the_50_building_grid():
    """From the greedy cover (51 + 1 forced), 5 000 steps (a few seconds) reach a cover
    below the best any method had found (50): feasible, and never below the LP's bound."""
    a, d, forced = load("district50")
    g = greedy_cover(a, d)
    found = row_weighting_search(a, d, g, np.inf, max_steps=5000, seed=0)
    assert _covers(a, d, found)
    assert len(found) + forced <= BEST_KNOWN - 3  # stations
    assert len(found) >= 35  # the LP relaxation of the instance is 34.83


@pytest.mark.parametrize("seed", range(6))
def test_the_bound_is_never_above_the_lp_optimum_and_covers_stay_covers(seed):
    """On small random multi-covers: the Lagrangian bound and the optimiser's proven bound
    at most the LP relaxation's optimum (HiGHS); every cover the search returns serves
    every row its demand, with no more columns than it started from."""
    a, d = random_cover(70, 110, 0.05, seed=seed, max_demand=2)
    lp = linprog(np.ones(a.shape[1]), A_ub=-a, b_ub=-d, bounds=(0, 1), method="highs")
    assert lp.status == 0
    g = greedy_cover(a, d)
    assert lagrangian_bound(a, d, len(g), np.inf, iterations=300) <= lp.fun + 1e-6
    sol = solve_cover(a, d, 3.0, "auto")
    assert sol.lower_bound <= np.ceil(lp.fun - 1e-9) + 1e-9
    assert sol.objective >= lp.fun - 1e-9
    found = row_weighting_search(a, d, g, np.inf, max_steps=3000, seed=seed)
    assert _covers(a, d, found) and len(found) <= len(g)
