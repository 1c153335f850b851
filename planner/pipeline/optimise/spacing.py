"""One set-up per spot: chosen stations closer than the crew's spacing merged.

A set cover has no sense of distance: two candidates 2 m apart are two stations to it
when each meets a few samples the other misses (round a corner, past a pillar). To a crew
they are one spot set up twice, and once the crew has scanned from one spot only, the plan
no longer matches what was scanned. :func:`merge_close` takes the chosen stations' pairs
closer than the spacing, closest first, and replaces each pair by one candidate — one of
the two where it does (the plan changes least), else the candidate nearest the pair's
middle — that meets, with the other chosen stations, every sample's demand the pair met,
and stands at least the spacing from every other station. A pair no one candidate can
replace is kept and returned, so the plan can say why.

Pure combinatorics on the cover's sparse matrix (samples × candidates) and the candidates'
positions.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
from scipy.spatial import cKDTree

__all__ = ["Merged", "close_pairs", "merge_close", "merge_options"]


@dataclass
class Merged:
    """The chosen candidates after merging, the pairs merged (``(a, b, into)``) and the
    pairs kept closer than the spacing (``(a, b)``), all candidate indices."""

    chosen: np.ndarray
    merged: list[tuple[int, int, int]] = field(default_factory=list)
    kept: list[tuple[int, int]] = field(default_factory=list)


def close_pairs(xy: np.ndarray, spacing_m: float) -> list[tuple[int, int]]:
    """The pairs of points ``xy`` (n, 2) [m] closer than ``spacing_m`` [m], closest first
    (row indices, ``i < j``)."""
    if len(xy) < 2 or spacing_m <= 0:
        return []
    pairs = np.array(sorted(cKDTree(xy).query_pairs(spacing_m)), dtype=np.int64).reshape(-1, 2)
    d = np.hypot(*(xy[pairs[:, 0]] - xy[pairs[:, 1]]).T)
    keep = d < spacing_m
    order = np.argsort(d[keep], kind="stable")
    return [(int(a), int(b)) for a, b in pairs[keep][order]]


def merge_close(
    ok: sp.csr_matrix,
    demand: np.ndarray,
    chosen: np.ndarray,
    xy: np.ndarray,
    spacing_m: float,
    keep: np.ndarray | None = None,
) -> Merged:
    """Merge the ``chosen`` candidates closer than ``spacing_m`` [m] (see the module).

    Parameters
    ----------
    ok : csr_matrix, shape (samples, candidates)
        Whether a candidate meets a sample.
    demand : ndarray of int, shape (samples,)
        How many chosen stations each sample needs.
    chosen : ndarray of int
        The chosen candidates (indices into ``xy`` and the columns of ``ok``).
    xy : ndarray, shape (candidates, 2)
        The candidates' positions [m].
    spacing_m : float
        The least distance between two set-ups a crew keeps [m]; 0: nothing is merged.
    keep : ndarray of int, optional
        Candidates never moved or dropped (locked or placed by hand).
    """
    chosen = np.unique(np.asarray(chosen, dtype=np.int64))
    out = Merged(chosen=chosen)
    if spacing_m <= 0 or len(chosen) < 2:
        return out
    fixed = set(np.asarray(keep if keep is not None else [], dtype=np.int64).tolist())
    mats = (sp.csr_matrix(ok, dtype=np.int32), sp.csc_matrix(ok, dtype=np.int32))
    tree = cKDTree(xy)
    have = set(chosen.tolist())
    refused: set[tuple[int, int]] = set()
    while True:
        now = np.array(sorted(have), dtype=np.int64)
        todo = [
            (int(now[a]), int(now[b]))
            for a, b in close_pairs(xy[now], spacing_m)
            if (int(now[a]), int(now[b])) not in refused
        ]
        if not todo:
            break
        a, b = todo[0]
        into = _one_for_two(mats, demand, now, xy, tree, spacing_m, a, b, fixed)
        if into is None:
            refused.add((a, b))
            continue
        have -= {a, b}
        have.add(into)
        out.merged.append((a, b, into))
    out.chosen = np.array(sorted(have), dtype=np.int64)
    out.kept = [
        (int(out.chosen[a]), int(out.chosen[b])) for a, b in close_pairs(xy[out.chosen], spacing_m)
    ]
    return out


def _one_for_two(
    mats: tuple[sp.csr_matrix, sp.csc_matrix],
    demand: np.ndarray,
    now: np.ndarray,
    xy: np.ndarray,
    tree: cKDTree,
    spacing_m: float,
    a: int,
    b: int,
    fixed: set[int],
) -> int | None:
    """The one candidate that can stand for ``a`` and ``b`` (see the module), or None;
    ``mats`` the cover's matrix by rows and by columns."""
    okr, okc = mats
    if a in fixed and b in fixed:
        return None
    rest = now[(now != a) & (now != b)]
    served = np.asarray(okc[:, rest].sum(axis=1)).ravel() if len(rest) else 0
    need = np.maximum(np.asarray(demand) - served, 0)
    if need.max(initial=0) > 1:  # a sample the two must both see: no one candidate can
        return None
    rows = np.flatnonzero(need)
    options = np.array(merge_options(xy, rest, a, b, spacing_m, fixed, tree), dtype=np.int64)
    if len(rows):
        counts = np.asarray(okr[rows][:, options].sum(axis=0)).ravel()
        options = options[counts == len(rows)]
    return int(options[0]) if len(options) else None


def merge_options(
    xy: np.ndarray,
    rest: np.ndarray,
    a: int,
    b: int,
    spacing_m: float,
    fixed: set[int],
    tree: cKDTree | None = None,
) -> list[int]:
    """The candidates (indices into ``xy``) that may stand for the pair ``a``, ``b``: the
    fixed one alone where one is fixed (locked, placed by hand); else ``a``, ``b`` and the
    candidates within ``spacing_m`` of their middle, nearest first — each at least
    ``spacing_m`` from every other station (``rest``). The one rule of both merges."""
    if a in fixed or b in fixed:
        options = np.array([a if a in fixed else b], dtype=np.int64)
    else:
        mid = (xy[a] + xy[b]) / 2.0
        tree = cKDTree(xy) if tree is None else tree
        near = np.array(tree.query_ball_point(mid, spacing_m), dtype=np.int64)
        near = near[(near != a) & (near != b)]
        order = np.argsort(np.hypot(*(xy[near] - mid).T), kind="stable")
        options = np.concatenate([[a, b], near[order]]).astype(np.int64)
    if len(rest) and len(options):
        gap = np.hypot(*(xy[options][:, None, :] - xy[rest][None, :, :]).transpose(2, 0, 1))
        options = options[gap.min(axis=1) >= spacing_m]
    return options.tolist()
