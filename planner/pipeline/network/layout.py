"""The network's layout (:class:`Layout`): which stations link to which, the datum (the
control network when three control points are seen, else the station that keeps the chain
shortest in error) and the tree of registrations from it, each station joined where its
accumulated error is smallest (:func:`planner.registration_error.propagate`); and the sphere
stands set up so far (:class:`Stands`).
"""

from __future__ import annotations

import heapq
import itertools
from collections.abc import Sequence
from dataclasses import replace
from functools import cached_property

import numpy as np
from scipy.cluster.hierarchy import DisjointSet
from scipy.spatial.distance import cdist

from planner.pipeline.evaluation.evaluate import Context
from planner.pipeline.geometry.visibility import stand_blocks
from planner.pipeline.network import clouds
from planner.pipeline.network.bridges import link_groups, shared_targets, strong_link
from planner.pipeline.network.clouds import CloudLink
from planner.pipeline.network.links import (
    a_matrix,
    all_targets_error,
    choose_link_targets,
    probe_points,
)
from planner.pipeline.network.targets import (
    Sight,
    SightCache,
    TargetCandidates,
    centre_rms,
    item_sizes,
    target_sight_offset,
)
from planner.registration_error import (
    CONTROL,
    datum_lean_mm,
)

__all__ = [
    "HIDDEN_DETOUR",
    "Layout",
    "Stands",
]


class Layout:
    """Stations, what they see, which pairs can be linked, and the best tree of
    registrations over them (datum and links, the accumulated error at each station)."""

    def __init__(
        self,
        ctx: Context,
        seen: SightCache,
        cand_xy: np.ndarray,
        stations: list[int],
        probes: dict[int, np.ndarray],
        goal_mm: float,
        datum: int | None = None,
        chain: Sequence[int] | None = None,
        cap: int | None = None,
    ) -> None:
        tc, st = seen.tc, ctx.settings
        #: a leap-frogging kit's layout: links only between set-ups next to each other in
        #: ``chain`` (positions in ``stations``, the visiting order), each of at most ``cap``
        #: targets (:mod:`planner.pipeline.engine.kit`)
        self.cap = cap if cap is not None else st.max_targets_per_link
        self.ctx, self.tc, self.goal_mm, self.seen = ctx, tc, goal_mm, seen
        self.by_hand = seen.by_hand if seen.by_hand.any() else None
        self.stations = stations
        self.probes = probes
        self.sight = seen(stations)
        k = self.k = len(stations)
        self.station_xyz = np.column_stack([cand_xy[stations], ctx.station_z(cand_xy[stations])])
        self.mode = st.registration_for(ctx.scanner)
        self._cloud_errors: dict[tuple[int, int], float] = {}
        self._clouds: dict[tuple[int, int], CloudLink | None] = {}
        self._judged_at: dict[int, np.ndarray] = {}  # of :meth:`probes_of`, as asked
        self.surf = self.overlap = None
        pairs = set()
        if self.mode != "cloud":
            pairs |= {
                (a, b)
                for a in range(k)
                for b in range(a + 1, k)
                if strong_link(self.sight, tc, a, b, tc.xyz)
            }
        if self.mode != "targets" and k > 1:
            self.surf = seen.clouds.take(np.array(stations), cand_xy)
            self.overlap = clouds.overlap_matrix(self.surf)
            pairs |= {
                (a, b)
                for a, b in zip(
                    *np.nonzero(np.triu(self.overlap >= st.min_overlap_pct, 1)), strict=True
                )
                if self.cloud(int(a), int(b)) is not None
            }
        if chain is not None:
            chain = [int(c) for c in chain]
            nearby = {frozenset(ab) for ab in itertools.pairwise(chain)}
            pairs = {(a, b) for a, b in pairs if frozenset((a, b)) in nearby}
        self.pairs = sorted((int(a), int(b)) for a, b in pairs)
        # by candidate index (CONTROL for the control network), shared by the layouts of a
        # plan: a link depends on its two stations and the child's facade points only
        self._memo = seen.memo_for(goal_mm)
        self._links: dict[tuple[int, int], tuple[list[int], float]] = {}
        self._bounds: dict[tuple[int, int], float] = {}  # of :meth:`bound`
        self._sigma2 = np.full((k, len(tc.xyz)), np.nan)  # σ² of :meth:`sigma`, as asked
        # the datum: the control network if any station sees three control points, else the
        # station from which the tree of registrations accumulates the least error
        # (Dijkstra on the links' variances; with 6 parameters, plus the datum's tilt at
        # each station's facade points), the choice keeping the worst station best
        roots: list[int] = []
        if tc.is_control.any():
            seen_ctl = any(np.isfinite(self.link(CONTROL, j)[1]) for j in range(k))
            roots = [CONTROL] if seen_ctl else []
        kept = not roots and datum in stations  # kept from the network this one grows from
        if kept:
            roots = [stations.index(datum)]
        best = self._best_tree(roots or range(k))
        if kept and best is not None and len(best[3]) < k:  # it does not reach them all
            free = self._best_tree(range(k))
            best = free if len(free[3]) > len(best[3]) else best
        self.datum, self.tree, self.cost = best[1:] if best else (None, [], {})
        self.worst_var = max(self.cost.values()) if self.cost else np.inf

    def _best_tree(self, roots: Sequence[int]) -> tuple | None:
        """(key, root, tree, cost) of the root whose tree reaches the most stations, then
        keeps the worst station's error smallest — with 6 parameters, its variance plus the
        datum's lean at its facade points (:meth:`datum_tilt_var`); ties go to the lowest
        root. The most central root is tried first, then the others. Once a root's tree
        reaches every station, another root's search stops at the first station worse than
        that tree's worst: it cannot win (and none of its links is made)."""
        roots = list(roots)
        if len(roots) > 1:
            first = _central(self.station_xyz[roots])  # a position in roots
            roots = [roots[first], *roots[:first], *roots[first + 1 :]]
        best = None
        for root in roots:
            tilt = self.datum_tilt_var(root)
            beaten = best[0][1] if best is not None and best[0][0] == -self.k else np.inf
            grown = _tree(root, self.k, self.pairs, self.link, self.bound, (tilt, beaten))
            if grown is None:
                continue
            tree, cost = grown
            worst = max((c + tilt[j] for j, c in cost.items()), default=np.inf)
            key = (-len(cost), worst, root)  # ties: the first root
            if best is None or key < best[0]:
                best = (key, root, tree, cost)
        return best

    def datum_tilt_var(self, root: int) -> np.ndarray:
        """(K,) the largest height variance [mm²] the datum's tilt gives each station's
        facade points with ``root`` as the datum (none for a levelled scanner, whose
        stations keep their own tilt, or for the control network):
        :func:`~planner.registration_error.datum_tilt_cov`."""
        sc = self.ctx.scanner
        if root == CONTROL or self.ctx.settings.tilt_model(sc) != "datum":
            return np.zeros(self.k)
        xy, starts = self._probe_xy
        far = np.maximum.reduceat(np.hypot(*(xy - self.station_xyz[root, :2]).T), starts)
        return np.square(datum_lean_mm(far, sc.datum_tilt_rms_arcsec))

    @cached_property
    def _probe_xy(self) -> tuple[np.ndarray, np.ndarray]:
        """Every station's facade points (:meth:`probe`) in plan, one after another, and
        where each station's begin (for :meth:`datum_tilt_var`, asked for every root)."""
        pts = [self.probe(j)[:, :2] for j in range(self.k)]
        starts = np.cumsum([0, *(len(p) for p in pts[:-1])])
        return np.concatenate(pts), starts

    def sigma(self, j: int, t: int) -> float:
        """Centre RMS of target t from station j with the largest item it could need."""
        return self._sigmas(j, [t])[0]

    def _sigmas(self, j: int, targets: list[int]) -> list[float]:
        """:meth:`sigma` of each of ``targets``, kept in the plan's memo; those not yet in
        it computed together (:func:`~planner.pipeline.network.targets.centre_rms` of many)."""
        keys = [("rms", self.stations[j], t) for t in targets]
        new = [n for n, key in enumerate(keys) if key not in self._memo]
        if new:
            at = np.array([targets[n] for n in new], dtype=np.int64)
            size = item_sizes(self.ctx, self.tc, at, self.sight.need_mm[at, j])
            rms = centre_rms(self.ctx, self.tc, self.sight, at, j, size)
            self._memo.update(zip([keys[n] for n in new], rms.tolist(), strict=True))
        return [self._memo[key] for key in keys]

    def sigma2(self, j: int, targets: np.ndarray) -> np.ndarray:
        """:meth:`sigma` squared for each of ``targets`` from station j (kept by station: a
        station's targets are asked again by each of its links)."""
        row = self._sigma2[j]
        todo = targets[np.isnan(row[targets])].tolist()
        for t, sigma in zip(todo, self._sigmas(j, todo), strict=True):
            row[t] = sigma**2
        return row[targets]

    def probe(self, j: int) -> np.ndarray:
        """The facade points station j serves (a linking station: its targets' spread)."""
        pts = self.probes.get(j)
        if pts is None or not len(pts):
            seen = np.flatnonzero(self.sight.usable[:, j])
            if not len(seen):
                return self.station_xyz[j : j + 1] + np.array([[1.0, 0.0, 0.0]])
            pts = self.tc.xyz[seen]
        return pts

    def probes_of(self, j: int) -> np.ndarray:
        """The points a link's error at station j is judged at
        (:func:`~planner.pipeline.network.links.probe_points` of :meth:`probe`), made once for the
        layout."""
        if j not in self._judged_at:
            self._judged_at[j] = probe_points(self.probe(j), self.station_xyz[j])
        return self._judged_at[j]

    def cloud(self, i: int, j: int) -> CloudLink | None:
        """The cloud-to-cloud registration of j to i, if their scans overlap enough and their
        common surfaces fix it (None otherwise); where the plan rehearsed it, with the
        rehearsal, its variance scaled at j's facade points
        (:meth:`~planner.pipeline.network.clouds.CloudLink.checked`)."""
        if self.surf is None or i == CONTROL:
            return None
        if (i, j) not in self._clouds:
            a, b = self.stations[i], self.stations[j]
            cl = self.seen.clouds.link(a, b, self.seen.cand_xy)
            check = self.seen.clouds.checks.get((a, b))
            if check is not None:
                cl = cl.checked(check, self.probes_of(j), self.station_xyz[j])
            ok = cl.holds and cl.overlap_pct >= self.ctx.settings.min_overlap_pct
            self._clouds[(i, j)] = cl if ok else None
        return self._clouds[(i, j)]

    def unchecked(self) -> list[tuple[int, int]]:
        """The tree's cloud links (positions) not yet rehearsed
        (:meth:`planner.pipeline.network.clouds.SurfaceCache.check`)."""
        out = []
        for i, j in self.tree:
            cl = self.cloud(i, j)
            if cl is not None and cl.check is None:
                out.append((i, j))
        return out

    def check(self, i: int, j: int) -> None:
        """Rehearse the cloud link of j to i (kept for the plan)."""
        self.seen.clouds.check(self.stations[i], self.stations[j], self.seen.cand_xy)
        self._clouds.pop((i, j), None)
        self._cloud_errors.pop((i, j), None)

    def link(
        self, i: int, j: int, placed: set[int] | None = None, stands: Stands | None = None
    ) -> tuple[list[int], float]:
        """Targets and error of registering j to i (i may be CONTROL); cached unless
        ``placed`` (targets already set up, preferred) is given; ``stands``: the spheres set
        up and the sight lines in use, which rule out targets hidden or hiding. Cloud to
        cloud (no targets): the cloud link; hybrid: the cloud link unless it is weaker than
        the goal and the targets do better."""
        cl = self.cloud(i, j)
        if cl is not None or self.mode == "cloud":
            err = self._cloud_error(cl, i, j) if cl is not None else np.inf
            if self.mode == "cloud" or err <= self.goal_mm:
                return [], err
            by_targets = self._target_link(i, j, placed, stands)
            return by_targets if by_targets[1] < err else ([], err)
        return self._target_link(i, j, placed, stands)

    def bound(self, i: int, j: int) -> float:
        """A lower bound [mm] of :meth:`link`'s error of j to i, cheap where the link is not
        yet known: the error with every common target
        (:func:`~planner.pipeline.network.links.all_targets_error`). A link known, cloud to cloud,
        or to the control network: its own error."""
        key = (i, j)
        if key not in self._bounds:
            cached = key in self._links or (i != CONTROL and self._shared_key(i, j) in self._memo)
            if cached or i == CONTROL or self.mode == "cloud" or self.cloud(i, j) is not None:
                self._bounds[key] = self.link(i, j)[1]
            else:  # kept for the plan's layouts, as the links are (:meth:`_shared_key`)
                common = shared_targets(self.sight, self.tc, i, j)
                shared = ("bound", *self._shared_key(i, j), common.tobytes())
                if shared not in self._memo:
                    self._memo[shared] = (
                        all_targets_error(
                            common,
                            self.tc.xyz,
                            self.sigma2(i, common) + self.sigma2(j, common),
                            self.station_xyz[j],
                            self.probes_of(j),
                            self.ctx.scanner.is_levelled,
                        )
                        if len(common) >= 3
                        else np.inf
                    )
                self._bounds[key] = self._memo[shared]
        return self._bounds[key]

    def _shared_key(self, i: int, j: int) -> tuple:
        """The key of the link of j to i in the memo the plan's layouts share."""
        st_i = self.stations[i] if i != CONTROL else CONTROL
        return (st_i, self.stations[j], self.probes_of(j).tobytes(), self.cap)

    def _cloud_error(self, cl: CloudLink, i: int, j: int) -> float:
        """The cloud link of j to i: its own error at j's facade points [mm] (kept per
        link; ``cl.parent`` is a position in the pair it was computed from, not i)."""
        if (i, j) not in self._cloud_errors:
            self._cloud_errors[(i, j)] = self.error_at_probes(cl.cov, j)
        return self._cloud_errors[(i, j)]

    def error_at_probes(self, cov: np.ndarray, j: int) -> float:
        """The largest RMS [mm] a pose covariance ``cov`` (at station j) gives the facade
        points j serves, along any axis; inf where the covariance leaves a direction free."""
        if not np.isfinite(np.diag(cov)).all():
            return np.inf
        pts = self.probes_of(j)
        g = a_matrix((pts - self.station_xyz[j]) * 1000.0, levelled=False)
        return float(np.sqrt(np.einsum("nij,jk,nik->ni", g, cov, g).max()))

    def _target_link(
        self, i: int, j: int, placed: set[int] | None = None, stands: Stands | None = None
    ) -> tuple[list[int], float]:
        key = (i, j)
        if placed is None and key in self._links:
            return self._links[key]
        probe = self.probes_of(j)
        shared = self._shared_key(i, j)
        if placed is None and shared in self._memo:
            self._links[key] = self._memo[shared]
            return self._links[key]
        tc = self.tc
        if i == CONTROL:
            common = np.flatnonzero(self.sight.usable[:, j] & tc.is_control)
        else:
            common = shared_targets(self.sight, tc, i, j)
        if stands is not None:
            common = common[~stands.hidden((i, j), common)]
        if i == CONTROL:
            s2 = np.array([tc.control_rms_mm[t] ** 2 + self.sigma(j, t) ** 2 for t in common])
        else:
            s2 = self.sigma2(i, common) + self.sigma2(j, common)
        out: tuple[list[int], float] = ([], np.inf)
        free = np.ones(len(common), dtype=bool)
        while free.sum() >= 3:
            out = self._choose(i, j, common[free], s2[free], probe, placed or set())
            hiding = stands.among((i, j), out[0]) if stands is not None else []
            if not hiding:  # no sphere of the choice hides another of it
                break
            free &= ~np.isin(common, hiding)
            out = ([], np.inf)
        if placed is None:
            self._links[key] = self._memo[shared] = out
        return out

    def _choose(
        self,
        i: int,
        j: int,
        common: np.ndarray,
        s2: np.ndarray,
        probe: np.ndarray,
        placed: set[int],
    ) -> tuple[list[int], float]:
        """:func:`~planner.pipeline.network.links.choose_link_targets` for the link of j to i over
        ``common`` (``s2`` their variances), kept for the plan's layouts: the choice depends on the
        two stations, the targets offered, which of them are placed and the points it is judged at
        only (the rest is the memo's key: :meth:`SightCache.memo_for`)."""
        reused = np.isin(common, list(placed))
        key = (
            "choose",
            self.stations[i] if i != CONTROL else CONTROL,
            self.stations[j],
            probe.tobytes(),
            common.tobytes(),
            reused.tobytes(),
            self.cap,
        )
        if key not in self._memo:
            self._memo[key] = choose_link_targets(
                common,
                self.tc.xyz,
                s2,
                self.station_xyz[j],
                probe,
                reused,
                self.ctx.scanner.is_levelled,
                self.cap,
                self.goal_mm,
                self.by_hand,
            )
        targets, error = self._memo[key]
        return list(targets), error

    def weak_groups(self, weak_mm: float) -> np.ndarray:
        """Groups of stations joined by links whose own error is at most ``weak_mm``. Only
        what the groups need is made: the links already known first (the tree's), then a
        pair only while its stations are in different groups, and a link only where its
        bound is within ``weak_mm``."""
        joined = DisjointSet(range(self.k))
        ok = []
        known = sorted(
            self.pairs, key=lambda ab: ab not in self._links and ab[::-1] not in self._links
        )
        for a, b in known:
            if joined.connected(a, b):
                continue
            ways = ((a, b), (b, a)) if (b, a) not in self._links else ((b, a), (a, b))
            if any(self.bound(i, j) <= weak_mm and self.link(i, j)[1] <= weak_mm for i, j in ways):
                joined.merge(a, b)
                ok.append((a, b))
        return link_groups(self.k, ok)


#: A link whose targets the spheres of earlier links hide is registered to another station
#: instead if that link's error is within this factor of its own (or within the goal); else
#: it keeps its targets, and the network's message says to set such spheres up only after
#: those scans (which ones is not yet named: the field booklet's set-up order is to come).
HIDDEN_DETOUR = 1.5


class Stands:
    """The sphere targets set up so far, as obstacles to the other targets' sight lines
    (:func:`~planner.pipeline.geometry.visibility.stand_blocks`; each as big as the largest sphere
    of the inventory, the size a later user may still need), and the sight lines in use, which
    a further sphere must not hide."""

    def __init__(self, ctx: Context, tc: TargetCandidates, station_xyz: np.ndarray) -> None:
        sizes = [i.size_mm for i in ctx.settings.inventory if i.type == "sphere"]
        self.radius_m = max(sizes, default=0.0) / 2000.0
        self.tc, self.station_xyz = tc, station_xyz
        self.end = tc.xyz.copy()
        # where target sights end (:func:`~planner.pipeline.network.targets.sights`)
        self.end[:, :2] += target_sight_offset(ctx, tc)[:, None] * tc.normal
        self.spheres: list[int] = []
        self.lines: set[tuple[int, int]] = set()  # (station column, target)

    def _blocks(self, src: np.ndarray, dst: np.ndarray, own: np.ndarray) -> np.ndarray:
        """Whether the spheres set up hide each sight line (``own``: its target)."""
        block = stand_blocks(src, dst, self.tc.xyz[self.spheres], self.radius_m)
        return (block & (own[:, None] != np.array(self.spheres)[None, :])).any(axis=1)

    def hidden(self, stations: Sequence[int], targets: np.ndarray) -> np.ndarray:
        """Mask over ``targets``: hidden from one of ``stations`` (columns; CONTROL
        skipped) by a sphere set up, or a sphere that would hide a sight line in use."""
        out = np.zeros(len(targets), dtype=bool)
        own = [j for j in stations if j != CONTROL]
        if not len(targets):
            return out
        if self.spheres and own:
            src = np.repeat(self.station_xyz[own], len(targets), axis=0)
            tt = np.tile(targets, len(own))
            out |= self._blocks(src, self.end[tt], tt).reshape(len(own), -1).any(axis=0)
        new = (self.tc.type[targets] == "sphere") & ~np.isin(targets, self.spheres)
        if self.lines and new.any():
            lines = sorted(self.lines)
            src = self.station_xyz[[j for j, _ in lines]]
            dst = self.end[[t for _, t in lines]]
            hides = stand_blocks(src, dst, self.tc.xyz[targets[new]], self.radius_m)
            out[new] |= hides.any(axis=0)
        return out

    def among(self, stations: Sequence[int], targets: Sequence[int]) -> list[int]:
        """The spheres not yet set up among ``targets`` that hide another of them from one
        of ``stations`` (columns; CONTROL skipped)."""
        own = [j for j in stations if j != CONTROL]
        targets = np.asarray(targets, dtype=np.int64)
        new = targets[(self.tc.type[targets] == "sphere") & ~np.isin(targets, self.spheres)]
        if not len(new) or not own:
            return []
        src = np.repeat(self.station_xyz[own], len(targets), axis=0)
        tt = np.tile(targets, len(own))
        block = stand_blocks(src, self.end[tt], self.tc.xyz[new], self.radius_m)
        block &= tt[:, None] != new[None, :]
        return [int(u) for u in new[block.any(axis=0)]]

    def hide(self, sight: Sight, targets: Sequence[int]) -> Sight:
        """``sight`` (a copy) with those of ``targets`` the spheres set up hide from a
        station not usable from it (a link's own sight lines kept: the few a link can only
        have behind another's sphere, which the network's message tells)."""
        usable = sight.usable.copy()
        rows = np.asarray(sorted(targets), dtype=np.int64)
        tt, jj = np.nonzero(usable[rows])
        tt = rows[tt]
        if self.spheres and len(tt):
            hidden = self._blocks(self.station_xyz[jj], self.end[tt], tt)
            hidden &= [(j, t) not in self.lines for j, t in zip(jj, tt, strict=True)]
            usable[tt[hidden], jj[hidden]] = False
        return replace(sight, usable=usable)

    def set_up(self, stations: Sequence[int], targets: Sequence[int]) -> None:
        """Targets now in use, seen from ``stations`` (columns; CONTROL skipped)."""
        for t in targets:
            if self.tc.type[t] == "sphere" and t not in self.spheres:
                self.spheres.append(int(t))
            self.lines |= {(int(j), int(t)) for j in stations if j != CONTROL}


def _central(xyz: np.ndarray) -> int:
    """The station nearest all others (the smallest farthest distance): the root the
    search for the datum tries first (:meth:`Layout._best_tree`)."""
    return int(np.argmin(cdist(xyz[:, :2], xyz[:, :2]).max(axis=1)))


def _tree(
    root: int,
    k: int,
    pairs: Sequence[tuple[int, int]],
    link,
    bound=None,
    beaten: tuple[np.ndarray, float] | None = None,
) -> tuple[list, dict] | None:
    """Registrations from ``root`` reaching every station it can, each joined where its
    accumulated error variance is smallest (Dijkstra); and that variance per station.

    ``bound(i, j)``, a lower bound of ``link(i, j)``'s error, makes a link only when the
    search reaches it: a link waits in the queue at its bound, and is made, and queued again
    at its own error, when it comes first. The bound never passes the error, so the links
    come out of the queue in the same order, and the tree is the same, as with every link
    made at once (ties: the lower station, then the lower parent).

    ``beaten`` (extra, worst): None as soon as a station's variance plus its extra must pass
    worst (the caller has a tree that reaches every station and is better): the station just
    reached, or any not yet reached, whose variance can only be larger."""
    neighbours: dict[int, list[int]] = {i: [] for i in range(k)}
    for a, b in pairs:
        neighbours[a].append(b)
        neighbours[b].append(a)
    # (variance, station, parent, made: the link's own error, not its bound)
    if root == CONTROL:
        start = [(link(CONTROL, j)[1] ** 2, j, CONTROL, True) for j in range(k)]
        heap = [s for s in start if np.isfinite(s[0])]
    else:
        heap = [(0.0, root, None, True)]
    cost: dict[int, float] = {}
    heapq.heapify(heap)
    tree = []
    left = np.ones(k, dtype=bool)  # not yet reached
    while heap:
        c, node, parent, made = heapq.heappop(heap)
        if node in cost:
            continue
        if not made:  # the link waited at its bound and comes first: make it
            err = link(parent, node)[1]
            if np.isfinite(err):
                heapq.heappush(heap, (cost[parent] + err**2, node, parent, True))
            continue
        cost[node] = c
        if beaten is not None and c + beaten[0][left].max() > beaten[1]:
            return None
        left[node] = False
        if parent is not None:
            tree.append((parent, node))
        for nb in neighbours[node]:
            if nb not in cost:
                err = link(node, nb)[1] if bound is None else bound(node, nb)
                if np.isfinite(err):
                    heapq.heappush(heap, (c + err**2, nb, node, bound is None))
    return tree, cost
