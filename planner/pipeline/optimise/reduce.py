"""Classical reductions of the set multi-cover problem, applied before any solver.

Rows are samples, each needing ``demand`` columns (stations) out of those that meet it;
every reduction below keeps at least one optimal solution (Garfinkel & Nemhauser, *Integer
Programming*, Wiley 1972, ch. 8; Beasley, "An algorithm for set covering problem", European
Journal of Operational Research 31, 1987, https://doi.org/10.1016/0377-2217(87)90141-X):

- **forced columns**: a row met by no more columns than it needs takes them all;
- **implied rows**: a row whose columns include all of another row's columns, needing no more
  than that row, is met whenever that row is;
- **dominated columns**: a column whose rows are all rows of another column, where every one
  of those rows needs a single station, can always be swapped for that column.

Repeated to a fixed point; after the first pass a new pair can only have for its subset a
set that lost members since, so later passes look only there. Subset pairs are found
exactly: candidates share the subset's rarest item (its pivot); random members of the subset
are looked up in the superset's bit set to discard most non-pairs cheaply, and the survivors
are checked word by word.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

__all__ = ["Reduced", "reduce_cover", "subset_pairs"]

#: Bit sets larger than this are not built: dominance is then skipped (said in the counts).
MAX_BITSET_BYTES = 1.5e9
#: Random members of a subset checked in its candidate superset before the exact check.
_PROBES = 6


def _bitsets(sets: sp.csr_matrix) -> np.ndarray:
    """One row of packed 64-bit words per set (bit ``k`` of the set = item ``k``)."""
    n, m = sets.shape
    out = np.zeros((n, (m + 63) // 64), dtype=np.uint64)
    rows = np.repeat(np.arange(n), np.diff(sets.indptr))
    items = sets.indices.astype(np.int64)
    bit = np.left_shift(np.uint64(1), (items & 63).astype(np.uint64))
    np.bitwise_or.at(out, (rows, items >> 6), bit)
    return out


def _copies(sets: sp.csr_matrix) -> np.ndarray:
    """(n,) bool: the rows of ``sets`` equal to a row before them (none where the bit sets
    would be too large)."""
    n, m = sets.shape
    if n == 0 or n * ((m + 63) // 64) * 8 > MAX_BITSET_BYTES:
        return np.zeros(n, dtype=bool)
    sets = sp.csr_matrix(sets)
    sets.sort_indices()
    _, first, inverse = np.unique(_bitsets(sets), axis=0, return_index=True, return_inverse=True)
    return np.arange(n) != first[inverse.ravel()]


def subset_pairs(
    sets: sp.csr_matrix,
    seed: int = 0,
    chunk: int = 20_000,
    allowed: Callable[[np.ndarray, np.ndarray], np.ndarray] | None = None,
    witness: str | None = None,
    among: np.ndarray | None = None,
    deadline: float = math.inf,
) -> tuple[np.ndarray, np.ndarray] | None:
    """Pairs ``(x, y)``, ``x != y``, with items(x) ⊆ items(y), for the rows of ``sets`` (a
    sparse 0/1 matrix, one row per set); ``None`` when the bit sets would be too large, or
    ``deadline`` (a :func:`time.process_time` time) passes before every pair is checked.

    ``allowed(x, y)``: a mask of the pairs wanted, applied before any set is compared.
    ``witness``: ``None`` for every pair; ``"x"`` (``"y"``) for one pair per subset
    (superset) that has any — enough to know which sets a rule removes, and far fewer
    comparisons where most sets have many partners. ``among``: a mask of the sets that may
    be the subset ``x`` (default all).
    """
    sets = sp.csr_matrix(sets)
    sets.sort_indices()
    n, m = sets.shape
    if n * ((m + 63) // 64) * 8 > MAX_BITSET_BYTES:
        return None
    size = np.diff(sets.indptr)
    members = sets.T.tocsr()
    degree = np.diff(members.indptr)
    # the pivot of each set: its item in the fewest sets; a superset must hold it too
    full = np.flatnonzero(size > 0)
    key = degree[sets.indices].astype(np.int64) * m + sets.indices
    pivot = np.minimum.reduceat(key, sets.indptr[full]) % m if len(full) else full
    xs = full if among is None else full[among[full]]
    pivot = pivot if among is None else pivot[among[full]]
    count = degree[pivot]
    x = np.repeat(xs, count)
    first = np.cumsum(count) - count
    rank = np.arange(len(x)) - np.repeat(first, count)  # y's place among x's candidates
    y = members.indices[np.repeat(members.indptr[pivot], count) + rank]
    keep = (x != y) & (size[x] <= size[y])
    if allowed is not None:
        keep &= allowed(x, y)
    x, y, rank = x[keep], y[keep], rank[keep]
    if time.process_time() > deadline:
        return None
    bits = _bitsets(sets)
    rng = np.random.default_rng(seed)
    for _ in range(_PROBES):  # a true superset holds every member: only non-pairs drop out
        if time.process_time() > deadline:
            return None
        item = sets.indices[sets.indptr[x] + (rng.random(len(x)) * size[x]).astype(np.int64)]
        word = bits[y, item >> 6] >> (item & 63).astype(np.uint64)
        held = (word & np.uint64(1)).astype(bool)
        x, y, rank = x[held], y[held], rank[held]
    if witness is not None:  # each set's first candidates first; found sets skip the rest
        order = np.argsort(rank, kind="stable")
        x, y = x[order], y[order]
    side = {"x": x, "y": y}.get(witness)
    found = np.zeros(n, dtype=bool)
    exact = np.zeros(len(x), dtype=bool)
    for lo in range(0, len(x), chunk):
        if time.process_time() > deadline:
            return None
        at = np.arange(lo, min(lo + chunk, len(x)))
        if side is not None:
            at = at[~found[side[at]]]
        a, b = x[at], y[at]
        exact[at] = ~(bits[a] & ~bits[b]).any(axis=1)
        if side is not None:
            at = at[exact[at]]
            first_of = np.unique(side[at], return_index=True)[1]
            exact[at] = False
            exact[at[first_of]] = True
            found[side[at]] = True
    return x[exact], y[exact]


@dataclass
class Reduced:
    """The reduced problem: ``a`` (rows × columns kept), the ``demand`` left on its rows,
    ``columns`` (the original index of each column kept) and ``forced`` (original indices of
    the columns every optimal plan may take); ``counts`` of what each rule removed."""

    a: sp.csr_matrix
    demand: np.ndarray
    columns: np.ndarray
    forced: np.ndarray
    counts: dict[str, int] = field(default_factory=dict)

    def describe(self) -> str:
        c = self.counts
        text = (
            f"{c.get('forced', 0)} forced, {c.get('implied rows', 0)} implied rows, "
            f"{c.get('dominated columns', 0)} dominated columns removed"
        )
        if c.get("skipped"):
            text += " (dominance skipped: too large)"
        if c.get("stopped"):
            text += " (stopped by the time budget)"
        return text


def _implied_rows(
    a: sp.csr_matrix, demand: np.ndarray, among: np.ndarray | None, deadline: float
) -> np.ndarray | None:
    """The rows another row implies — cols(x) ⊆ cols(y) and demand(x) ≥ demand(y): y goes —
    looked for among the rows ``among`` marks (None: all); None where the search was cut."""
    size = np.diff(a.indptr)
    pairs = subset_pairs(
        a,
        allowed=lambda x, y, d=demand, n=size: (
            (d[x] >= d[y]) & ((n[x] < n[y]) | (d[x] > d[y]) | (x < y))
        ),
        witness="y",
        among=among,
        deadline=deadline,
    )
    return None if pairs is None else np.unique(pairs[1])


def _dominated_columns(
    cols: sp.csr_matrix, demand: np.ndarray, among: np.ndarray | None, deadline: float
) -> np.ndarray | None:
    """The columns (``cols``: candidates × samples) another dominates — rows(x) ⊆ rows(y),
    every row of x needing one station: x goes. First the copies (the same rows as a column
    before them: most of a large grid where few rows are left), then the subsets among the
    columns left, looked for among those ``among`` marks (None: all); None where the search
    was cut."""
    single = np.asarray(cols @ (demand > 1).astype(np.int64)).ravel() == 0
    size = np.diff(cols.indptr)
    copy = _copies(cols) & single
    rest = np.flatnonzero(~copy)
    pairs = subset_pairs(
        cols[rest],
        allowed=lambda x, y, one=single[rest], n=size[rest]: one[x] & ((n[x] < n[y]) | (x > y)),
        witness="x",
        among=None if among is None else among[rest],
        deadline=deadline,
    )
    if pairs is None:
        return None
    return np.union1d(np.flatnonzero(copy), rest[np.unique(pairs[0])])


def reduce_cover(a: sp.csr_matrix, demand: np.ndarray, deadline: float = math.inf) -> Reduced:
    """Apply the reductions (module docstring) to a fixed point, or until ``deadline`` (a
    :func:`time.process_time` time; every pass leaves an exact reduction of the problem).

    ``a``: samples × candidates, nonzero where the candidate meets the sample; ``demand``:
    stations each sample needs, already capped at its number of candidates.
    """
    a = sp.csr_matrix(a, dtype=np.int8)
    a.eliminate_zeros()
    a.data[:] = 1
    demand = np.asarray(demand, dtype=np.int64)
    columns = np.arange(a.shape[1])
    forced: list[np.ndarray] = []
    counts = {"forced": 0, "implied rows": 0, "dominated columns": 0, "skipped": 0}
    # the rows (columns) that lost members since their last pass; None: look at all
    rows_new: np.ndarray | None = None
    cols_new: np.ndarray | None = None
    while True:
        before = a.shape
        # rows served or without demand go; columns that meet nothing go
        live = demand > 0
        a, demand = a[live], demand[live]
        used = np.flatnonzero(np.diff(a.tocsc().indptr) > 0)
        a, columns = a[:, used].tocsr(), columns[used]
        if rows_new is not None:
            rows_new, cols_new = rows_new[live], cols_new[used]
        if a.shape[0] == 0:
            break
        if time.process_time() > deadline:
            counts["stopped"] = 1
            break
        # forced: every column of a row that needs all of them
        tight = np.diff(a.indptr) <= demand
        if tight.any():
            take = np.unique(a[tight].indices)
            forced.append(columns[take])
            counts["forced"] += len(take)
            demand = demand - np.asarray(a[:, take].sum(axis=1)).ravel()
            rest = np.setdiff1d(np.arange(a.shape[1]), take)
            a, columns = a[:, rest].tocsr(), columns[rest]
            rows_new = cols_new = None  # demands changed: every pair is new
            continue
        # implied rows: cols(x) ⊆ cols(y) and demand(x) ≥ demand(y) → y goes
        drop = _implied_rows(a, demand, rows_new, deadline)
        if drop is None:
            counts["stopped" if time.process_time() > deadline else "skipped"] = 1
            break
        if cols_new is not None:
            cols_new[a[drop].indices] = True
        rows_new = np.zeros(a.shape[0] - len(drop), dtype=bool)
        if len(drop):
            counts["implied rows"] += len(drop)
            keep = np.setdiff1d(np.arange(a.shape[0]), drop)
            a, demand = a[keep], demand[keep]
        # dominated columns: rows(x) ⊆ rows(y), all rows of x needing one → x goes
        cols = a.T.tocsr()
        drop = _dominated_columns(cols, demand, cols_new, deadline)
        if drop is None:
            counts["stopped" if time.process_time() > deadline else "skipped"] = 1
            break
        rows_new[cols[drop].indices] = True
        cols_new = np.zeros(a.shape[1] - len(drop), dtype=bool)
        if len(drop):
            counts["dominated columns"] += len(drop)
            keep = np.setdiff1d(np.arange(a.shape[1]), drop)
            a, columns = a[:, keep].tocsr(), columns[keep]
        if a.shape == before:
            break
    chosen = np.unique(np.concatenate(forced)) if forced else np.empty(0, dtype=np.int64)
    return Reduced(a=a, demand=demand, columns=columns, forced=chosen, counts=counts)
