"""Row-weighting local search for the station cover (:func:`row_weighting_search`).

The unicost set (multi-)cover's best covers at district scale are found by local search,
not by the integer program: on the 50-building grid a row-weighting search reaches covers
HiGHS needs many minutes for. The method is RWLS of Gao, Weise & Li ("An efficient local
search heuristic with row weighting for the unicost set covering problem", European Journal
of Operational Research 246(3), 750–761, 2015, https://doi.org/10.1016/j.ejor.2015.05.038),
here for a demand of one or more stations per sample:

- start from a cover; whenever every row is served, keep it as the best and drop the column
  whose loss is least, so the search always looks for a cover one smaller;
- a step drops the selected column whose loss is least (not the one just added), then adds,
  for a random row still short, the column serving it whose gain is largest (not one just
  dropped whose neighbourhood has not changed since: configuration checking);
- every row still short gets one more unit of weight after the step: rows that stay hard to
  serve weigh more, and the search moves on from where it is stuck.

A column's score is the weighted demand it would serve (unselected: rows short of their
demand) or lose (selected: rows served no more than their demand), kept up to date move by
move. Compiled with numba.
"""

from __future__ import annotations

import time

import numpy as np
import scipy.sparse as sp
from numba import njit

__all__ = ["row_weighting_search"]

#: Steps between two looks at the clock.
STEPS_PER_CHECK = 2000
#: The search stops after this many steps without a smaller cover (on the 50-building grid's
#: cover the last improvement came about 15 000 steps after the one before).
STALL_STEPS = 40_000


def row_weighting_search(
    a: sp.csr_matrix,
    demand: np.ndarray,
    start: np.ndarray,
    deadline: float,
    *,
    seed: int = 0,
    max_steps: int = 10**9,
    floor: int = 0,
) -> np.ndarray:
    """The smallest cover found from the cover ``start`` (column indices of ``a``, rows ×
    columns, each row served ``demand`` times) by ``deadline`` (a :func:`time.process_time`
    time), ``max_steps``, :data:`STALL_STEPS` without a smaller one, or one of ``floor``
    columns (a proven bound: none is smaller). Deterministic for a ``seed`` and a step
    count.

    Examples
    --------
    >>> a = sp.csr_matrix(np.array([[1, 1, 0, 0], [0, 1, 1, 0], [0, 0, 1, 1], [1, 0, 0, 1]]))
    >>> len(row_weighting_search(a, np.ones(4, int), np.arange(4), 1e18, max_steps=200))
    2
    """
    a = sp.csr_matrix(a)
    at = a.T.tocsr()
    d = np.asarray(demand, dtype=np.int64)
    x = np.zeros(a.shape[1], dtype=np.bool_)
    x[np.asarray(start, dtype=np.int64)] = True
    best = x.copy()
    rng = np.random.default_rng(seed)
    state = _start(a, at, d, x)
    steps, size, since = 0, int(best.sum()), 0
    while steps < max_steps and time.process_time() < deadline and since < STALL_STEPS:
        if size <= floor:
            break
        n = min(STEPS_PER_CHECK, max_steps - steps)
        _run(
            a.indptr,
            a.indices,
            at.indptr,
            at.indices,
            d,
            *state,
            best,
            n,
            steps,
            int(rng.integers(2**31)),
        )
        steps += n
        now = int(best.sum())
        since = 0 if now < size else since + n
        size = now
    return np.flatnonzero(best)


def _start(a: sp.csr_matrix, at: sp.csr_matrix, d: np.ndarray, x: np.ndarray) -> tuple:
    """The search's arrays, which numba works on in place: the columns chosen, every row's
    cover and weight, every column's score, time stamp and whether it may be added
    (configuration checking), the rows short of their demand (a list, each row's place in
    it, and their count)."""
    cov = np.asarray(a @ x.astype(np.int64)).ravel().astype(np.int64)
    w = np.ones(a.shape[0], dtype=np.int64)
    rows = np.flatnonzero(cov < d)
    short = np.zeros(a.shape[0], dtype=np.int64)
    where = -np.ones(a.shape[0], dtype=np.int64)
    short[: len(rows)] = rows
    where[rows] = np.arange(len(rows))
    x = x.copy()
    stamp = np.zeros(a.shape[1], dtype=np.int64)
    free = np.ones(a.shape[1], dtype=np.bool_)
    n_short = np.array([len(rows)], dtype=np.int64)
    return x, cov, w, _scores(a, at, d, x, cov, w), stamp, free, short, where, n_short


def _scores(a, at, d, x, cov, w) -> np.ndarray:
    """Every column's score (module docstring)."""
    gain_rows = np.where(cov < d, w, 0)
    loss_rows = np.where(cov <= d, w, 0)
    gain = at @ gain_rows
    loss = at @ loss_rows
    return np.where(x, -loss, gain).astype(np.int64)


@njit(cache=True)
def _touch(i, delta, ap, ai, d, x, cov, w, score, free):
    """Row ``i``'s cover changes by ``delta`` (±1): the scores of its columns follow, and
    they may be added again (their neighbourhood changed)."""
    c0, c1 = cov[i], cov[i] + delta
    g0 = w[i] if c0 < d[i] else 0
    g1 = w[i] if c1 < d[i] else 0
    l0 = w[i] if c0 <= d[i] else 0
    l1 = w[i] if c1 <= d[i] else 0
    for k in range(ap[i], ap[i + 1]):
        j = ai[k]
        if x[j]:
            score[j] += l0 - l1
        else:
            score[j] += g1 - g0
        free[j] = True
    cov[i] = c1


@njit(cache=True)
def _flip(j, ap, ai, tp, ti, d, x, cov, w, score, free, short, where, n_short):
    """Add or drop column ``j``: its rows' covers, the scores, the rows still short."""
    delta = -1 if x[j] else 1
    # the column's own score flips sign: computed from its rows after the move
    for k in range(tp[j], tp[j + 1]):
        i = ti[k]
        before = cov[i] < d[i]
        _touch(i, delta, ap, ai, d, x, cov, w, score, free)
        after = cov[i] < d[i]
        if after and not before:
            where[i] = n_short[0]
            short[n_short[0]] = i
            n_short[0] += 1
        elif before and not after:
            p = where[i]
            last = short[n_short[0] - 1]
            short[p] = last
            where[last] = p
            where[i] = -1
            n_short[0] -= 1
    x[j] = not x[j]
    s = 0
    for k in range(tp[j], tp[j + 1]):
        i = ti[k]
        if x[j]:
            s -= w[i] if cov[i] <= d[i] else 0
        else:
            s += w[i] if cov[i] < d[i] else 0
    score[j] = s


@njit(cache=True)
def _drop_best(x, score, stamp, forbid):
    """The selected column losing least (oldest first on ties), not ``forbid``."""
    best, bs, bt = -1, -(2**62), 2**62
    for j in range(len(x)):
        if x[j] and j != forbid and (score[j] > bs or (score[j] == bs and stamp[j] < bt)):
            best, bs, bt = j, score[j], stamp[j]
    return best


@njit(cache=True)
def _run(
    ap, ai, tp, ti, d, x, cov, w, score, stamp, free, short, where, n_short, best, n, t0, seed
):
    np.random.seed(seed)  # noqa: NPY002 (numba compiles the legacy generator, not Generator)
    added = -1
    n_best = 0
    for j in range(len(best)):
        if best[j]:
            n_best += 1
    for step in range(n):
        t = t0 + step + 1
        while n_short[0] == 0:  # a cover: keep it, and look for one smaller
            n_x = 0
            for j in range(len(x)):
                if x[j]:
                    n_x += 1
            if n_x < n_best:
                best[:] = x
                n_best = n_x
            j = _drop_best(x, score, stamp, -1)
            if j < 0:
                return
            _flip(j, ap, ai, tp, ti, d, x, cov, w, score, free, short, where, n_short)
            stamp[j] = t
        j = _drop_best(x, score, stamp, added)
        if j >= 0:
            _flip(j, ap, ai, tp, ti, d, x, cov, w, score, free, short, where, n_short)
            stamp[j] = t
            free[j] = False
        if n_short[0] == 0:
            continue
        i = short[np.random.randint(n_short[0])]  # noqa: NPY002 (as above)
        pick, ps, pt = -1, -(2**62), 2**62
        for k in range(ap[i], ap[i + 1]):
            c = ai[k]
            if x[c] or not free[c]:
                continue
            if score[c] > ps or (score[c] == ps and stamp[c] < pt):
                pick, ps, pt = c, score[c], stamp[c]
        if pick < 0:  # every column of the row was just dropped: take the best anyway
            for k in range(ap[i], ap[i + 1]):
                c = ai[k]
                if not x[c] and (score[c] > ps or (score[c] == ps and stamp[c] < pt)):
                    pick, ps, pt = c, score[c], stamp[c]
        if pick < 0:
            continue
        _flip(pick, ap, ai, tp, ti, d, x, cov, w, score, free, short, where, n_short)
        stamp[pick] = t
        added = pick
        for q in range(n_short[0]):  # the rows still short weigh one more
            r = short[q]
            w[r] += 1
            for k in range(ap[r], ap[r + 1]):
                c = ai[k]
                if x[c]:
                    if cov[r] <= d[r]:
                        score[c] -= 1
                elif cov[r] < d[r]:
                    score[c] += 1
