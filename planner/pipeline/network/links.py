"""The targets of one link (:func:`choose_link_targets`).

For two stations, the common targets are chosen greedily to make the child's registration
error at the facade points it serves smallest — not a fixed three, not by a spread rule: a
thin triangle or targets all at one height show up as a large predicted error and are
avoided — reusing targets already placed, up to ``max_targets_per_link``. The error of each
candidate target added is evaluated for many at once by a compiled kernel
(:func:`all_targets_error`).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from planner.registration_error import (
    MAX_CONDITION,
    scaled_condition,
)

__all__ = [
    "BOUND_MARGIN",
    "MAX_PROBES",
    "MIN_GAIN",
    "a_matrix",
    "all_targets_error",
    "choose_link_targets",
    "probe_points",
]


#: A link stops taking targets once adding one improves its error by less than this.
MIN_GAIN = 0.03


#: The weak prior that lets the greedy target choice start from no targets (σ: 1 m, 0.6°).
_PRIOR = np.diag([1e-6] * 3 + [1e4] * 3)


def a_matrix(lever_mm: np.ndarray, levelled: bool) -> np.ndarray:
    """(…, 3, p) design rows of a target at ``lever_mm`` from the child station."""
    x, y, z = lever_mm[..., 0], lever_mm[..., 1], lever_mm[..., 2]
    a = np.zeros((*lever_mm.shape[:-1], 3, 6))
    a[..., 0, 0] = a[..., 1, 1] = a[..., 2, 2] = 1.0  # the shift
    a[..., 0, 4], a[..., 0, 5] = z, -y  # the small rotation's lever
    a[..., 1, 3], a[..., 1, 5] = -z, x
    a[..., 2, 3], a[..., 2, 4] = y, -x
    return a[..., [0, 1, 2, 5]] if levelled else a


def _probe_errors(n_mats: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """Largest per-axis RMS [mm] of the child's error at the probe points, for a stack of
    positive-definite normal matrices (B, p, p) of its registration (the link alone; their
    lower triangles are read); ``rows`` (3P, p) the probes' design rows. NaN for a matrix
    that is not positive definite. Whether a matrix fixes the registration is for the caller
    to judge (:func:`_well_posed`). The same numbers as rᵀ·inv(N)·r to rounding (a test:
    1e-10 relative; they differ in the last bits, about 1e-14), not bit for bit."""
    out = np.empty(len(n_mats))
    _probe_errors_kernel(np.ascontiguousarray(n_mats), np.ascontiguousarray(rows), out)
    return out


@njit(cache=True, nogil=True)
def _probe_errors_kernel(n_mats, rows, out):  # pragma: no cover - compiled
    """:func:`_probe_errors` compiled, matrix by matrix: N = L·Lᵀ (Cholesky), each probe
    row's variance rᵀN⁻¹r = |L⁻¹r|² by forward substitution, the largest, its root. NaN
    for a matrix that is not positive definite."""
    p = n_mats.shape[1]
    low = np.empty((p, p))
    z = np.empty(p)
    for b in range(n_mats.shape[0]):
        ok = True
        for i in range(p):
            for k in range(i + 1):
                acc = n_mats[b, i, k]
                for m in range(k):
                    acc -= low[i, m] * low[k, m]
                if i == k:
                    if not acc > 0.0:
                        ok = False
                        break
                    low[i, i] = np.sqrt(acc)
                else:
                    low[i, k] = acc / low[k, k]
            if not ok:
                break
        if not ok:
            out[b] = np.nan
            continue
        worst = 0.0
        for r in range(rows.shape[0]):
            var = 0.0
            for i in range(p):
                acc = rows[r, i]
                for m in range(i):
                    acc -= low[i, m] * z[m]
                z[i] = acc / low[i, i]
                var += z[i] * z[i]
            worst = max(worst, var)
        out[b] = np.sqrt(worst)


def _well_posed(n_mats: np.ndarray, order: np.ndarray) -> int | None:
    """The first of ``order`` (indices into the stack ``n_mats``) whose matrix fixes a
    registration (:func:`~planner.registration_error.scaled_condition`), or None. One
    matrix at a time: the greedy choice needs only its best trial's, and that is nearly
    always the first."""
    for i in order:
        if scaled_condition(n_mats[i]) < MAX_CONDITION:
            return int(i)
    return None


#: The facade points a link's error is judged at: the farthest from the station and a
#: spread of the rest (the error grows with the lever arm, so these bound it).
MAX_PROBES = 16


def probe_points(points: np.ndarray, station: np.ndarray) -> np.ndarray:
    if len(points) <= MAX_PROBES:
        return points
    d = np.linalg.norm(points - station, axis=1)
    far = np.argsort(d)[-MAX_PROBES // 2 :]
    spread = np.linspace(0, len(points) - 1, MAX_PROBES // 2).astype(int)
    return points[np.unique(np.concatenate([far, spread]))]


#: How much below the error with every common target a link's bound is taken, so that the
#: arithmetic's rounding (the matrices differ only in the order they are summed where a link
#: takes them all) can never lift the bound over the link's own error.
BOUND_MARGIN = 1e-3


def all_targets_error(
    common: np.ndarray,
    xyz: np.ndarray,
    sigma2: np.ndarray,
    child_xyz: np.ndarray,
    probes: np.ndarray,
    levelled: bool,
) -> float:
    """A lower bound [mm] of the error :func:`choose_link_targets` gives a link over
    ``common``: the error with every one of them. The targets a link chooses are some of
    ``common``, and a target more only adds to the normal matrix (N_all ⪰ N_chosen, so
    each probe's variance with N_all is the smaller); 0 where every common target together
    does not fix the registration (that bound says nothing)."""
    a = a_matrix((xyz[common] - child_xyz) * 1000.0, levelled)
    n_mat = np.einsum("cip,ciq->pq", a / sigma2[:, None, None], a)
    if scaled_condition(n_mat) >= MAX_CONDITION:
        return 0.0
    g = a_matrix((probes - child_xyz) * 1000.0, levelled)
    error = float(_probe_errors(n_mat[None], g.reshape(-1, g.shape[-1]))[0])
    return error * (1.0 - BOUND_MARGIN)


def choose_link_targets(
    common: np.ndarray,
    xyz: np.ndarray,
    sigma2: np.ndarray,
    child_xyz: np.ndarray,
    probes: np.ndarray,
    reused: np.ndarray,
    levelled: bool,
    max_targets: int,
    goal_mm: float,
    must: np.ndarray | None = None,
) -> tuple[list[int], float]:
    """Greedy choice among ``common`` targets (σ_i² + σ_j² per target in ``sigma2``):
    each step adds the target that lowers the child's predicted error at ``probes`` (the
    points :meth:`Layout.probes_of` picks) most (a target already placed, flagged in
    ``reused``, wins within :data:`MIN_GAIN`), until three are chosen and the
    goal is met, adding no longer helps, or ``max_targets`` are chosen. Targets flagged in
    ``must`` (placed by the surveyor) come first, whatever they add. Returns the targets
    and the link's error [mm] (inf if they cannot fix the registration)."""
    prior = _PRIOR if not levelled else _PRIOR[np.ix_([0, 1, 2, 5], [0, 1, 2, 5])]
    a = a_matrix((xyz[common] - child_xyz) * 1000.0, levelled)  # (C, 3, p)
    contrib = np.einsum("cip,ciq->cpq", a, a) / sigma2[:, None, None]
    g = a_matrix((probes - child_xyz) * 1000.0, levelled)
    rows = g.reshape(-1, g.shape[-1])  # (3P, p): the probes' design rows
    chosen = [] if must is None else [int(c) for c in np.flatnonzero(must[common])]
    chosen = chosen[: int(max_targets)]
    n_mat = contrib[chosen].sum(axis=0) if chosen else np.zeros(prior.shape)
    error = np.inf
    if chosen and scaled_condition(n_mat + prior) < MAX_CONDITION:
        error = float(_probe_errors((n_mat + prior)[None], rows)[0])
    free = np.ones(len(common), dtype=bool)
    free[chosen] = False
    while len(chosen) < max_targets:
        left = np.flatnonzero(free)
        if not len(left) or (len(chosen) >= 3 and error <= goal_mm):
            break  # three chosen and the goal met: whatever a trial gave, the loop ends here
        mats = n_mat + contrib[left] + prior
        trial = _probe_errors(mats, rows)
        order = np.argsort(trial, kind="stable")
        best = _well_posed(mats, order)
        new_error = np.inf if best is None else float(trial[best])
        best = 0 if best is None else best
        if np.isfinite(new_error) and reused[left].any():
            r = _well_posed(mats, order[reused[left][order]])
            if r is not None and trial[r] <= new_error * (1 + MIN_GAIN):
                best, new_error = r, float(trial[r])
        if len(chosen) >= 3 and new_error > error * (1 - MIN_GAIN):
            break
        chosen.append(int(left[best]))
        free[left[best]] = False
        n_mat = n_mat + contrib[left[best]]
        error = new_error
    if len(chosen) < 3 or scaled_condition(n_mat) > MAX_CONDITION:
        return [], np.inf
    return [int(common[c]) for c in chosen], float(_probe_errors(n_mat[None], rows)[0])
