"""The search for linking stations: where two groups of stations cannot be linked, the
fewest candidates that chain them into one (:func:`find_bridges`), by targets, cloud to cloud
or either (:func:`linking_hops`), as many hops as needed.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import connected_components

from planner.pipeline.evaluation.evaluate import Context
from planner.pipeline.network.targets import Sight, SightCache, TargetCandidates

__all__ = [
    "BRIDGE_CHUNK",
    "BRIDGE_RADIUS_M",
    "LINK_GRID_M",
    "MAX_BRIDGE_SEARCHES",
    "MIN_SPREAD_M",
    "find_bridges",
    "link_groups",
    "linking_hops",
    "shared_targets",
    "strong_link",
]


#: Linking stations are searched on a grid this coarse (a subset of the candidates) [m].
LINK_GRID_M = 4.0


def _coarse(cand_xy: np.ndarray, grid_m: float) -> np.ndarray:
    cells = np.floor(cand_xy / grid_m + 1e-9).astype(np.int64)
    _, first = np.unique(cells, axis=0, return_index=True)
    return np.sort(first)


def shared_targets(sight: Sight, tc: TargetCandidates, a: int, b: int) -> np.ndarray:
    """Targets (not control points) both stations can use."""
    both = sight.usable[:, a] & sight.usable[:, b] & ~tc.is_control
    return np.flatnonzero(both)


def link_groups(k: int, edges: Sequence[tuple[int, int]]) -> np.ndarray:
    """The group (0, 1, …, by each group's lowest station) of each of ``k`` stations joined
    by ``edges`` (scipy's connected components)."""
    pairs = np.asarray(list(edges), dtype=np.int64).reshape(-1, 2)
    graph = sp.coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(k, k))
    return connected_components(graph, directed=False)[1]


#: Common targets closer than this to one line do not fix a registration [m].
MIN_SPREAD_M = 0.3


def _spread(points: np.ndarray) -> bool:
    """Whether three or more target positions (n, 3) are not all on one line."""
    if len(points) < 3:
        return False
    sv = np.linalg.svd(points - points.mean(axis=0), compute_uv=False)
    return bool(sv[1] > MIN_SPREAD_M)


def strong_link(sight: Sight, tc: TargetCandidates, a: int, b: int, xyz: np.ndarray) -> bool:
    """Whether two stations share three or more targets that fix a registration."""
    return _spread(xyz[shared_targets(sight, tc, a, b)])


def _bridge_pool(ctx: Context, cand_xy: np.ndarray, stations: list[int]) -> np.ndarray:
    """Candidates a linking station is looked for among: a coarse grid of them (not the
    stations themselves) within :data:`BRIDGE_RADIUS_M` of a station."""
    pool = _coarse(cand_xy, max(LINK_GRID_M, ctx.settings.grid_m))
    pool = pool[~np.isin(pool, stations)]
    near = np.hypot(*(cand_xy[pool, None, :] - cand_xy[None, stations, :]).transpose(2, 0, 1))
    return pool[near.min(axis=1) <= BRIDGE_RADIUS_M]


class _PoolHops:
    """Which pool candidates could register to which (P × P), a row made only when the
    search reaches that candidate (``hops[rows]``, (len(rows), P)): a chain is mostly one
    candidate beside the stations, so most rows are never asked. ``strike`` rules a hop out
    both ways (in the rows kept: ``make_rows`` returns new arrays, never views)."""

    def __init__(self, n: int, make_rows: Callable[[np.ndarray], np.ndarray]) -> None:
        self.n, self._make = n, make_rows
        self._rows: dict[int, np.ndarray] = {}

    def __len__(self) -> int:
        return self.n

    def __getitem__(self, rows: np.ndarray) -> np.ndarray:
        at = np.asarray(rows, dtype=np.int64).tolist()
        new = [i for i in dict.fromkeys(at) if i not in self._rows]
        if not self._rows and len(new) > self.n / 2:  # most of them: all at once
            new = list(range(self.n))
        if new:
            self._rows.update(zip(new, self._make(np.array(new, dtype=np.int64)), strict=True))
        return np.stack([self._rows[i] for i in at]) if at else np.zeros((0, self.n), bool)

    def strike(self, a: int, b: int) -> None:
        self[np.array([a, b])]  # made, then edited
        self._rows[a][b] = self._rows[b][a] = False


@dataclass
class _Hops:
    """Which pool candidates could register to which (``adj``, P × P, made as asked) and to
    which stations (``to_st``, P × K) — a necessary condition, cheap for every pair — and
    ``ok(i, j, to_station)``, the full check of one hop."""

    pool: np.ndarray
    adj: Callable[[np.ndarray], np.ndarray]  # pool positions (F,) → their rows (F, P)
    to_st: np.ndarray
    ok: Callable[[int, int, bool], bool]


def _target_hops(
    seen: SightCache, pool: np.ndarray, sight: Sight, deadline: float = math.inf
) -> _Hops | None:
    """Hops by targets: three common targets, checked not to lie on one line. Candidates of
    the pool not reached by ``deadline`` (a :func:`time.monotonic` time; none is passed in
    planning) are left out; None if none is reached."""
    tc = seen.tc
    parts = []  # the pool's sights, a chunk at a time while the time lasts
    for k in range(0, len(pool), BRIDGE_CHUNK):
        if time.monotonic() > deadline:
            break
        parts.append(seen.usable(pool[k : k + BRIDGE_CHUNK]))
    if not parts:
        return None
    pool = pool[: sum(p.shape[1] for p in parts)]
    u_pool = np.hstack(parts) & ~tc.is_control[:, None]
    u_st = sight.usable & ~tc.is_control[:, None]
    rows = u_pool.any(axis=1)  # the targets no pool candidate sees count for no hop
    pool_seen = u_pool[rows].astype(np.float32)
    to_st = (pool_seen.T @ u_st[rows].astype(np.float32)) >= 3

    def adj(at: np.ndarray) -> np.ndarray:  # three common targets, exact in float32 < 2**24
        if len(at) == len(pool):  # every row: the symmetric product, half the work
            return ((pool_seen.T @ pool_seen) >= 3)[at]
        return (pool_seen[:, at].T @ pool_seen) >= 3

    def ok(i: int, j: int, to_station: bool) -> bool:
        other = u_st[:, j] if to_station else u_pool[:, j]
        return _spread(tc.xyz[u_pool[:, i] & other])

    return _Hops(pool, adj, to_st, ok)


#: The number of bits set in each 4-bit number.
_BITS = np.array([bin(v).count("1") for v in range(16)])


def _cloud_hops(
    ctx: Context, seen: SightCache, stations: list[int], pool: np.ndarray
) -> _Hops | None:
    """Hops cloud to cloud: scans overlapping by the settings' minimum, checked to fix
    every direction (:attr:`~planner.pipeline.network.clouds.CloudLink.fixed`)."""
    k = len(stations)
    every = np.concatenate([stations, pool]).astype(np.int64)
    over = seen.clouds.overlapping(every, seen.cand_xy, ctx.settings.min_overlap_pct)
    axes = seen.clouds.wall_axes(every, seen.cand_xy)
    over &= _BITS[axes[:, None] & axes[None, :]] >= 2  # two walls in common, not parallel
    np.fill_diagonal(over, False)

    def ok(i: int, j: int, to_station: bool) -> bool:
        parent = stations[j] if to_station else int(pool[j])
        return seen.clouds.link(parent, int(pool[i]), seen.cand_xy).fixed

    among = over[k:, k:]
    return _Hops(pool, lambda at: among[at], over[k:, :k], ok)


def linking_hops(
    ctx: Context,
    seen: SightCache,
    cand_xy: np.ndarray,
    stations: list[int],
    mode: str,
    sight: Sight,
) -> _Hops | None:
    """The hops a linking station can make in the registration ``mode``: by targets (seen
    as ``sight`` says), cloud to cloud, or (hybrid) either. None: no pool."""
    pool = _bridge_pool(ctx, cand_xy, stations)
    if not len(pool):
        return None
    by_targets = None if mode == "cloud" else _target_hops(seen, pool, sight)
    if mode == "targets" or (by_targets is None and mode == "hybrid"):
        return by_targets
    pool = pool if by_targets is None else by_targets.pool
    by_clouds = _cloud_hops(ctx, seen, stations, pool)
    if by_targets is None:
        return by_clouds
    t_ok, c_ok = by_targets.ok, by_clouds.ok
    t_adj, c_adj = by_targets.adj, by_clouds.adj
    return _Hops(
        pool,
        lambda at: t_adj(at) | c_adj(at),
        by_targets.to_st | by_clouds.to_st,
        lambda i, j, to_station: t_ok(i, j, to_station) or c_ok(i, j, to_station),
    )


def find_bridges(hops: _Hops, groups: np.ndarray) -> list[int]:
    """The fewest linking candidates that chain every group of stations into one: a
    breadth-first search over the pool's hops, from one group to the nearest other,
    repeated until one group is left or none can be reached. A chain found is checked hop
    by hop (:attr:`_Hops.ok`) and a hop that fails is struck off before searching again."""
    adj, to_st = _PoolHops(len(hops.pool), hops.adj), hops.to_st.copy()
    added: list[int] = []
    groups = groups.copy()
    for _ in range(MAX_BRIDGE_SEARCHES):
        if groups.max() == 0:
            break
        chain = _bfs_chain(adj, to_st, groups)
        if chain is None:
            break
        # check the chain's hops: group 0 → chain[-1] → … → chain[0] → another group
        bad = False
        for a, b in zip(chain[1:], chain[:-1], strict=True):
            if not hops.ok(a, b, False):
                adj.strike(a, b)
                bad = True
        for end, mine in ((chain[-1], groups == 0), (chain[0], groups > 0)):
            for s in np.flatnonzero(to_st[end] & mine):
                if not hops.ok(end, int(s), True):
                    to_st[end, s] = False
                    bad = True
        if bad:
            continue
        added += [int(hops.pool[i]) for i in chain]
        # the reached group joins group 0
        hit = {int(g) for i in chain for g in groups[to_st[i] & (groups > 0)]}
        groups = np.where(np.isin(groups, list(hit)), 0, groups)
        groups = np.unique(groups, return_inverse=True)[1]
    return added


#: Linking stations are searched this close to the stations they link [m].
BRIDGE_RADIUS_M = 60.0


#: The bridge search computes its candidates' sights this many at a time (a deadline given
#: to :func:`_target_hops` is checked between chunks).
BRIDGE_CHUNK = 512


#: How many chains the bridge search tries (each failing hop struck off) before giving up.
MAX_BRIDGE_SEARCHES = 200


def _bfs_chain(
    adj: np.ndarray | _PoolHops, hop: np.ndarray, groups: np.ndarray
) -> list[int] | None:
    """Shortest chain of pool candidates from group 0 to any other group (pool indices,
    the one touching the other group first), or None; ``adj`` (P, P; rows are read only
    for the candidates reached) and ``hop`` (P, K): the hops among the pool and from the
    pool to the stations.

    Breadth-first, a level at a time on the boolean hop matrix; within a level the order is
    that of a plain queue (by parent, then index), so the chain found is the queue's."""
    frontier = np.flatnonzero(hop[:, groups == 0].any(axis=1))
    goal = hop[:, groups > 0].any(axis=1)
    prev = np.full(len(adj), -2)  # -2: not reached; -1: a start
    prev[frontier] = -1
    while len(frontier):
        hit = frontier[goal[frontier]]
        if len(hit):
            i, chain = int(hit[0]), []
            while i != -1:
                chain.append(i)
                i = int(prev[i])
            return chain
        reach = adj[frontier]  # (F, P)
        new = np.flatnonzero(reach.any(axis=0) & (prev == -2))
        if not len(new):
            return None
        first = reach[:, new].argmax(axis=0)  # the earliest parent in queue order
        prev[new] = frontier[first]
        frontier = new[np.lexsort((new, first))]
    return None
