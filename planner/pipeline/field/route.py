"""Field logistics: a walkable visiting order for the stations and the field time.

* **Where one can walk**: round buildings and obstacles (kept ``WALK_CLEARANCE_M`` away),
  not through no-go areas unless nothing else reaches a station (a street crossed, say; the
  leg says so). The walk graph is a visibility graph: the corners of the blocked areas
  (buffered) and the stations, joined wherever the straight line between two of them is
  free; shortest walks by Dijkstra (``scipy.sparse.csgraph``).
* **Visiting order**: the shortest open path through the stations on those walking
  distances — nearest neighbour from every start, then 2-opt (Croes 1958) to a local optimum
  — and, where scans are registered cloud to cloud, put in the order that keeps every scan
  registered to one scanned before it (its link in the plan's network: overlapping clouds
  or common targets), so that they can be registered on site as they come (Cyclone FIELD
  360, SCENE's on-site registration); a station waits only as long as none of the stations
  it is linked to has been scanned. ``registers_to`` names the earlier scans it is linked to.
* **Targets as kit**: a target is placed before the first station that scans it and
  collected after the last, so the kit leap-frogs along the visiting order; per inventory
  item the route counts the most standing at once and says where the crew's count
  (:class:`~planner.targets.TargetItem`'s ``count``) falls short.
* **Time per station**: walk from the previous station, the targets set up before its
  scan and those collected after it, the set-up, the scan
  and the images: the scan is the station's sector (its facade samples and targets, with a
  margin) over the scanner's vertical field — the full dome for a scanner that cannot scan
  a sector — at the plan's setting (:class:`~planner.scanner.Preset`: its step, its rate,
  or the maker's stated full-dome time shared out by the points, :mod:`planner.fieldwork`);
  the images take the scanner's ``imaging_s`` when imaging is on. The route is split into
  sessions of at most ``session_h``.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import pandas as pd
import shapely
from scipy.sparse import coo_matrix, csr_matrix
from scipy.sparse.csgraph import dijkstra
from scipy.spatial import cKDTree

from planner.fieldwork import scan_points, scan_time_s
from planner.pipeline.inputs.requirements import PlanSettings
from planner.pipeline.inputs.schema import KIT_COLUMNS, ROUTE_COLUMNS, id_key
from planner.scanner import Preset, Scanner
from planner.site import Site
from planner.spacing import resolve_step_mm
from planner.targets import TargetItem

__all__ = ["FieldRoute", "field_route", "kit_words", "view_sectors", "walk_paths"]

#: Distance kept from buildings and obstacles when walking [m] (at most half the clearance).
WALK_CLEARANCE_M = 0.4
#: A metre walked through a no-go area counts as this many when choosing the way.
NO_GO_PENALTY = 20.0
#: Margin added on both sides of a station's scan sector [deg].
SECTOR_MARGIN_DEG = 5.0
#: Each walk-graph node is joined to at most this many nearest nodes (beyond a small graph).
NEIGHBOURS = 40
#: Up to this many stations the order is chosen on the full matrix of walking distances.
EXACT_MAX_STATIONS = 400
#: Nearest-neighbour paths are tried from up to 150 starts, fewer where the stations are so
#: many that the starts would look at more than this many matrix entries in all.
ORDER_WORK = 1e8
#: Beyond this many stations, 2-opt reverses only stretches of up to this many stations …
TWO_OPT_WINDOW = 400
#: … and looks at this many of the best reversals in a pass.
MOVES_PER_PASS = 2000


@dataclass
class FieldRoute:
    """The visiting order and field time of a plan (:data:`ROUTE_COLUMNS`), each leg's
    walked polyline (from the previous station; the first is empty) and the rate used."""

    table: pd.DataFrame
    legs: list[np.ndarray] = field(default_factory=list)
    rate_hz: float = 0.0
    rate_assumed: bool = False
    #: the scanner's setting the scans are timed at ('' a step of the user's own)
    preset: str = ""
    #: the scanner scans a sector only (else the full dome at every station)
    sector_scan: bool = True
    #: the targets as kit (:data:`KIT_COLUMNS`): owned, used, most standing at once
    kit: pd.DataFrame = field(default_factory=lambda: pd.DataFrame(columns=KIT_COLUMNS))
    #: scans registered cloud to cloud on site, each to one scanned before it
    on_site: bool = False

    @property
    def notes(self) -> list[str]:
        """What the order and the walks need said (from the table: one source for both)."""
        t, out = self.table, []
        if self.on_site and len(t):
            alone = t["station_id"][t["registers_to"] == ""].iloc[1:]
            out.append(
                "Scan order: every scan is registered to one scanned before it."
                if not len(alone)
                else "Scan order: every scan is registered to one scanned before it, but "
                f"{', '.join(alone)} (linked to no scan before)."
            )
        for k in self.kit.itertuples():
            if k.owned and k.most_at_once > k.owned:
                out.append(f"Kit: {kit_words(k)}.")
        walks = t[t["walk_note"] != ""] if len(t) else t
        if len(walks):
            out.append(
                f"Walks to {', '.join(walks['station_id'])}: "
                f"{'; '.join(sorted(set(walks['walk_note'])))}."
            )
        return out

    def renamed(
        self, stations: dict[str, str], targets: dict[str, str] | None = None
    ) -> FieldRoute:
        """The route with its stations and targets renamed (old id → new; others kept),
        every list of ids in id order."""
        targets = targets or {}

        def ids(text: str, names: dict[str, str]) -> str:
            return " ".join(sorted((names.get(s, s) for s in text.split(" ") if s), key=id_key))

        t = self.table
        t = t.assign(
            station_id=t["station_id"].map(lambda s: stations.get(s, s)),
            links_to=t["links_to"].map(lambda v: ids(v, stations)),
            registers_to=t["registers_to"].map(lambda v: ids(v, stations)),
            targets_to_set=t["targets_to_set"].map(lambda v: ids(v, targets)),
            targets_to_collect=t["targets_to_collect"].map(lambda v: ids(v, targets)),
        )
        kit = self.kit.assign(at_station=self.kit["at_station"].map(lambda s: stations.get(s, s)))
        return replace(self, table=t, kit=kit)

    @property
    def total_min(self) -> float:
        return float(self.table["station_min"].sum()) if len(self.table) else 0.0

    @property
    def sessions(self) -> int:
        return int(self.table["session"].max()) if len(self.table) else 0

    def summary(self) -> str:
        """One paragraph for the summary, the report and the dashboard."""
        t = self.table
        if not len(t):
            return "Field time: no stations."
        order = " → ".join(t["station_id"])
        rate = f"{self.rate_hz:,.0f} points/s".replace(",", " ")
        rate += " (assumed: the scanner profile gives none)" if self.rate_assumed else ""
        setting = f"setting '{self.preset}', " if self.preset else ""
        dome = "" if self.sector_scan else " (full dome: the scanner cannot scan a sector)"
        imaging = t["imaging_min"].sum()
        return (
            f"Field time: {_hm(self.total_min)} in {self.sessions} session(s) — walk "
            f"{t['walk_m'].sum() / 1000:.2f} km ({_hm(t['walk_min'].sum())}), "
            f"{int(t['targets_to_set'].str.len().gt(0).sum())} stop(s) placing "
            f"{_count_ids(t['targets_to_set'])} targets ({_hm(t['targets_min'].sum())}) and "
            f"collecting {_count_ids(t['targets_to_collect'])} ({_hm(t['collect_min'].sum())}), "
            f"set-up {_hm(t['setup_min'].sum())} ({t['setup_min'].iloc[0]:g} min a station), "
            f"scanning {_hm(t['scan_min'].sum())}{dome} at "
            f"{setting}step {t['step_mm_at_10m'].iloc[0]:g} mm at 10 m, {rate}"
            + (f", imaging {_hm(imaging)}" if imaging > 0 else "")
            + f". Visiting order: {order}."
            + "".join(f" {n}" for n in self.notes)
        )


def _hm(minutes: float) -> str:
    m = round(minutes)
    return f"{m // 60} h {m % 60:02d} min" if m >= 60 else f"{m} min"


def _count_ids(col: pd.Series) -> int:
    return int(sum(len([s for s in v.split(" ") if s]) for v in col))


# -- sectors ------------------------------------------------------------------------------
def view_sectors(
    stations: pd.DataFrame, coverage: pd.DataFrame, targets: pd.DataFrame | None = None
) -> dict[str, tuple[float, float, float]]:
    """Each station's scan sector: the circle without its largest empty gap between the
    samples it is assigned (and the targets it scans). (start, end) azimuth in degrees
    clockwise from grid north (the sector runs clockwise from start to end) and the farthest
    assigned point's horizontal distance [m]."""
    pts: dict[str, list[np.ndarray]] = {}
    cov = coverage[coverage["station_id"].notna() & (coverage["station_id"] != "")]
    for sid, rows in cov.groupby("station_id"):
        pts.setdefault(str(sid), []).append(rows[["x", "y"]].to_numpy(float))
    if targets is not None and len(targets):
        for sids, x, y in zip(targets["station_ids"], targets["x"], targets["y"], strict=True):
            for sid in sids:
                pts.setdefault(str(sid), []).append(np.array([[x, y]], float))
    out = {}
    st = stations.set_index("station_id")
    for sid, parts in pts.items():
        if sid not in st.index:
            continue
        xy = np.vstack(parts)
        dx, dy = xy[:, 0] - st.at[sid, "x"], xy[:, 1] - st.at[sid, "y"]
        az = np.sort(np.degrees(np.arctan2(dx, dy)) % 360.0)
        gaps = np.diff(np.append(az, az[0] + 360.0))
        k = int(np.argmax(gaps))
        start, end = az[(k + 1) % len(az)], az[k]
        out[sid] = (float(start), float(end), float(np.hypot(dx, dy).max()))
    return out


# -- where one can walk -------------------------------------------------------------------
@dataclass
class _WalkGraph:
    nodes: np.ndarray  # (V, 2), the stations first
    n_stations: int
    length: coo_matrix  # geometric length of each free edge
    weight: csr_matrix  # length with the no-go penalty (what the order minimises)


def _walk_graph(site: Site, points: np.ndarray, clearance_m: float) -> _WalkGraph:
    c = min(WALK_CLEARANCE_M, max(0.05, clearance_m / 2.0))
    hard = [g for _, g, _ in site.blockers]  # buildings without their passages, obstacles
    soft = [a.geometry for a in site.no_go]
    hard_b = [g.buffer(c, quad_segs=2) for g in hard]
    soft_b = [g.buffer(c, quad_segs=2) for g in soft]
    corners = []
    for g in [*hard_b, *soft_b]:
        ring = shapely.get_coordinates(
            shapely.simplify(g.buffer(0.1, quad_segs=2, join_style="mitre"), 0.1).boundary
        )
        corners.append(ring)
    corner_xy = np.vstack(corners) if corners else np.empty((0, 2))
    hard_tree = shapely.STRtree(hard_b)
    if len(corner_xy):
        corner_xy = np.unique(np.round(corner_xy, 2), axis=0)
        inside = hard_tree.query(shapely.points(corner_xy), predicate="intersects")[0]
        corner_xy = np.delete(corner_xy, np.unique(inside), axis=0)
    nodes = np.vstack([points, corner_xy])
    n = len(nodes)
    if n <= 2 * NEIGHBOURS:
        i, j = np.triu_indices(n, 1)
    else:
        _, nb = cKDTree(nodes).query(nodes, k=NEIGHBOURS + 1)
        i = np.repeat(np.arange(n), NEIGHBOURS)
        j = nb[:, 1:].ravel()
        keep = (j < n) & (i < j)
        pairs = np.unique(np.column_stack([i[keep], j[keep]]), axis=0)
        i, j = pairs[:, 0], pairs[:, 1]
    segs = shapely.linestrings(np.stack([nodes[i], nodes[j]], axis=1))
    blocked = np.zeros(len(segs), bool)
    blocked[hard_tree.query(segs, predicate="intersects")[0]] = True
    length = np.hypot(*(nodes[i] - nodes[j]).T)
    weight = length.copy()
    if soft_b:
        hit = shapely.STRtree(soft_b).query(segs, predicate="intersects")
        for s in np.unique(hit[0]):
            inside = sum(segs[s].intersection(soft_b[k]).length for k in hit[1][hit[0] == s])
            weight[s] += (NO_GO_PENALTY - 1.0) * inside
    i, j, length, weight = i[~blocked], j[~blocked], length[~blocked], weight[~blocked]
    sym = (np.concatenate([i, j]), np.concatenate([j, i]))
    return _WalkGraph(
        nodes=nodes,
        n_stations=len(points),
        length=coo_matrix((np.concatenate([length, length]), sym), shape=(n, n)),
        weight=csr_matrix((np.concatenate([weight, weight]) + 1e-9, sym), shape=(n, n)),
    )


def walk_paths(site: Site, points: np.ndarray, clearance_m: float = 1.0) -> np.ndarray:
    """Walking distances between every pair of ``points`` (N, 2) [m], round buildings,
    obstacles and no-go areas (crossed only where nothing else reaches; inf: no way)."""
    g = _walk_graph(site, np.asarray(points, float).reshape(-1, 2), clearance_m)
    _, pred = _shortest(g, np.arange(g.n_stations))
    k = g.n_stations
    return np.array([[_leg(g, a, b, pred[a])[0] for b in range(k)] for a in range(k)])


def _shortest(g: _WalkGraph, sources: np.ndarray, limit: float = np.inf):
    """Weights to every node and predecessor rows of the shortest walks from ``sources``."""
    return dijkstra(g.weight, indices=sources, return_predecessors=True, limit=limit)


def _leg(g: _WalkGraph, a: int, b: int, pred: np.ndarray) -> tuple[float, np.ndarray | None]:
    """Walked length [m] and polyline from station a to station b on a's tree."""
    if a == b:
        return 0.0, g.nodes[[a]]
    if pred[b] < 0:
        return math.inf, None
    seq = [b]
    while seq[-1] != a:
        seq.append(int(pred[seq[-1]]))
    path = g.nodes[seq[::-1]]
    return float(np.hypot(*np.diff(path, axis=0).T).sum()), path


# -- visiting order -----------------------------------------------------------------------
def _open_path_order(d: np.ndarray) -> np.ndarray:
    """A short open path through all points of the distance matrix ``d``: nearest
    neighbour from up to 150 starts spread over the points (fewer for thousands, see
    :data:`ORDER_WORK`), the best improved by 2-opt."""
    n = len(d)
    if n <= 2:
        return np.arange(n)
    big = np.where(np.isfinite(d), d, np.nanmax(np.where(np.isfinite(d), d, 0)) * 10 + 1e6)
    best, best_len = None, math.inf
    starts = int(min(n, 150, max(4, ORDER_WORK // (n * n))))
    for s in np.unique(np.linspace(0, n - 1, starts).astype(int)):
        seen = np.zeros(n, bool)
        order = [s]
        seen[s] = True
        for _ in range(n - 1):
            row = np.where(seen, np.inf, big[order[-1]])
            nxt = int(np.argmin(row))
            order.append(nxt)
            seen[nxt] = True
        length = big[order[:-1], order[1:]].sum()
        if length < best_len - 1e-9:
            best, best_len = np.array(order), length
    return _two_opt(best, big)


def _two_opt(order: np.ndarray, d: np.ndarray, max_passes: int = 50) -> np.ndarray:
    """2-opt on an open path: reverse ``order[i..j]`` while that shortens it (stretches of
    up to :data:`TWO_OPT_WINDOW` stations where there are more). Each pass makes the best
    reversals whose stretches, with a station either side, do not overlap: each one's gain
    stays what it was computed as."""
    n = len(order)
    i, j = np.triu_indices(n, 1)
    if n > TWO_OPT_WINDOW:
        near = j - i <= TWO_OPT_WINDOW
        i, j = i[near], j[near]
    for _ in range(max_passes):
        o = order
        prev = np.concatenate([[-1], o[:-1]])  # node before position i
        nxt = np.concatenate([o[1:], [-1]])  # node after position j
        before = np.where(prev[i] >= 0, d[prev[i], o[i]], 0.0) + np.where(
            nxt[j] >= 0, d[o[j], nxt[j]], 0.0
        )
        after = np.where(prev[i] >= 0, d[prev[i], o[j]], 0.0) + np.where(
            nxt[j] >= 0, d[o[i], nxt[j]], 0.0
        )
        gain = before - after
        better = np.flatnonzero(gain > 1e-9)
        if not len(better):
            break
        better = better[np.argsort(-gain[better], kind="stable")][:MOVES_PER_PASS]
        order = o.copy()
        touched = np.zeros(n + 2, dtype=bool)  # positions −1 … n, shifted by one
        for a, b in zip(i[better], j[better], strict=True):
            if not touched[a : b + 3].any():
                touched[a : b + 3] = True
                order[a : b + 1] = o[a : b + 1][::-1]
    return order


def _registered_order(
    order: np.ndarray, neighbours: list[set[int]], d: np.ndarray | None
) -> np.ndarray:
    """``order`` changed as little as it takes for every station to come after one it is
    linked to (``neighbours``), but the first of each group of linked stations: each step
    takes the first station in ``order`` not yet visited that is linked to a visited one or
    starts a group none of whose stations is visited. Tried on ``order`` and its reverse, the
    shorter on walking distances ``d`` kept."""
    n = len(order)
    group = np.full(n, -1)
    for g, start in enumerate(order):  # the groups of linked stations
        if group[start] >= 0:
            continue
        stack = [int(start)]
        while stack:
            k = stack.pop()
            if group[k] < 0:
                group[k] = g
                stack.extend(neighbours[k])

    def repair(seq: np.ndarray) -> np.ndarray:
        left, out = list(seq), []
        visited, started = np.zeros(n, dtype=bool), set()
        while left:
            pos = next(
                p
                for p, k in enumerate(left)
                if group[k] not in started or any(visited[o] for o in neighbours[k])
            )
            k = left.pop(pos)
            out.append(k)
            visited[k] = True
            started.add(group[k])
        return np.array(out, dtype=order.dtype)

    tries = [repair(order), repair(order[::-1])]
    if d is None:
        return tries[0]
    length = [float(np.nan_to_num(d[t[:-1], t[1:]], posinf=1e9).sum()) for t in tries]
    return tries[int(np.argmin(length))]


# -- the route ----------------------------------------------------------------------------
def field_route(
    site: Site,
    scanner: Scanner,
    settings: PlanSettings,
    stations: pd.DataFrame,
    targets: pd.DataFrame,
    coverage: pd.DataFrame,
    links: pd.DataFrame,
) -> FieldRoute:
    """The visiting order of ``stations`` and the field time (see the module's text)."""
    preset = scanner.preset(settings.preset) if settings.preset else None
    rate = (preset and preset.rate_hz) or scanner.measurement_rate_hz or settings.scan_rate_hz
    route = FieldRoute(
        table=pd.DataFrame(columns=ROUTE_COLUMNS),
        rate_hz=float(rate),
        rate_assumed=not ((preset and preset.rate_hz) or scanner.measurement_rate_hz),
        preset=preset.name if preset else "",
        sector_scan=scanner.sector_scan,
    )
    if not len(stations):
        return route
    xy = stations[["x", "y"]].to_numpy(float)
    ids = stations["station_id"].astype(str).tolist()
    linked: dict[str, set[str]] = {}
    for a, b in zip(links["station_a"].astype(str), links["station_b"].astype(str), strict=True):
        linked.setdefault(a, set()).add(b)
        linked.setdefault(b, set()).add(a)
    # scans registered cloud to cloud are registered on site as they come
    route.on_site = "kind" in links and bool((links["kind"] == "cloud").any())
    g, order, pred, d = _visiting_order(site, settings, xy, ids, linked, route.on_site)
    order = _kit_order(
        order, d, targets, ids, settings.inventory, linked if route.on_site else None
    )
    legs, walk_m, notes = _walks(site, g, xy, order, pred)
    visit = {ids[k]: n for n, k in enumerate(order)}
    first_visit, last_visit, life = _target_visits(targets, visit)
    walk = (walk_m, notes, first_visit, last_visit, _standing(list(life.values()), len(order)))
    rows = _route_rows(
        scanner, settings, preset, route, stations, targets, coverage, order, linked, visit, walk
    )
    route.table = pd.DataFrame(rows, columns=ROUTE_COLUMNS)
    route.legs = legs
    route.kit = _kit(settings, targets, life, links, visit, [ids[k] for k in order])
    return route


def _visiting_order(
    site: Site,
    settings: PlanSettings,
    xy: np.ndarray,
    ids: list[str],
    linked: dict[str, set[str]],
    on_site: bool,
) -> tuple[Any, list[int], np.ndarray | None, np.ndarray]:
    """The walking graph, the visiting order (an open path, shortest walk; scans registered
    on site as they come each after one it links to), where the walks between all stations
    were found (a site of at most :data:`EXACT_MAX_STATIONS`) their predecessors, and the
    distances [m] the order was chosen on (walked, else straight)."""
    g = _walk_graph(site, xy, settings.clearance_m)
    exact = len(xy) <= EXACT_MAX_STATIONS
    pred = None
    if exact:
        w, pred = _shortest(g, np.arange(len(xy)))
        d = w[:, : len(xy)]
    else:  # a district: ordered on straight lines, each leg then walked
        d = np.hypot(*(xy[:, None, :] - xy[None, :, :]).transpose(2, 0, 1))
    order = _open_path_order(d)
    at = {sid: k for k, sid in enumerate(ids)}
    neighbours = [{at[o] for o in linked.get(i, ()) if o in at} for i in ids]
    if on_site:
        order = _registered_order(order, neighbours, d if exact else None)
    return g, order, pred, d


#: A visiting order that keeps more of the job within the kit may walk this share more than
#: the shortest found.
KIT_WALK_SLACK = 0.25
#: The kit-saving order is looked for up to this many stations (each pass tries the moves
#: of one station, up to n² orders), in at most this many passes (each lowers the targets
#: standing beyond the kit by one at least).
KIT_ORDER_MAX_STATIONS = 60
KIT_ORDER_PASSES = 20
#: ... and at most this many orders weighed in all (about 0.2 s on this machine: an edit by
#: hand is judged again with its route). A count, not a time: the same order on any machine.
KIT_ORDER_TRIES = 4000


def _kit_order(
    order: np.ndarray,
    d: np.ndarray,
    targets: pd.DataFrame,
    ids: list[str],
    inventory: tuple[TargetItem, ...],
    linked: dict[str, set[str]] | None,
) -> np.ndarray:
    """``order`` changed, where that helps, so that fewer targets stand at once than the
    crew owns of each item (``inventory``' counts; an item without one is not limited):
    one station at a time moved elsewhere in the order while that lowers the targets
    standing beyond the kit (:data:`KIT_ORDER_PASSES` moves, :data:`KIT_ORDER_TRIES`
    orders weighed at most), the walk (on ``d``
    [m]) kept within :data:`KIT_WALK_SLACK` of the shortest found and, where scans are
    registered on site (``linked``), every station that came after one it links to still
    doing so. A target stands from the first station that sees it to the last
    (every scan that sees it observes it in the registration's adjustment)."""
    owned = {i.name: i.count for i in inventory if i.count}
    n = len(order)
    if not owned or n < 3 or n > KIT_ORDER_MAX_STATIONS or not np.isfinite(d).all():
        return order
    at = {sid: k for k, sid in enumerate(ids)}
    limited = [
        (str(item), [at[s] for s in sids if s in at])
        for item, sids, kind in zip(
            targets["item"], targets["station_ids"], targets["type"], strict=True
        )
        if kind != "control" and item in owned
    ]
    limited = [(item, ks) for item, ks in limited if ks]
    if not limited:
        return order
    items = sorted({item for item, _ in limited})
    which = np.array([items.index(item) for item, _ in limited])
    flat = np.concatenate([ks for _, ks in limited])
    starts = np.cumsum([0] + [len(ks) for _, ks in limited[:-1]])
    cap = np.array([owned[i] for i in items])
    links = None if linked is None else [{at[o] for o in linked.get(i, ()) if o in at} for i in ids]

    def cost(o: np.ndarray) -> tuple[int, float]:
        pos = np.empty(n, dtype=np.int64)
        pos[o] = np.arange(n)
        p = pos[flat]
        spans = np.column_stack([np.minimum.reduceat(p, starts), np.maximum.reduceat(p, starts)])
        peak = np.array([_standing(spans[which == k], n).max() for k in range(len(items))])
        return int(np.maximum(peak - cap, 0).sum()), float(d[o[:-1], o[1:]].sum())

    best, (excess, walk) = np.asarray(order), cost(np.asarray(order))
    limit = walk * (1.0 + KIT_WALK_SLACK)
    alone = _unregistered(best, links) if links is not None else set()
    tries = 0
    for _ in range(KIT_ORDER_PASSES):  # each pass: the first move that lowers the excess
        if excess == 0 or tries >= KIT_ORDER_TRIES:
            break
        moves = ((i, j) for i in range(n) for j in range(n) if i != j)
        for i, j in moves:
            o = np.insert(np.delete(best, i), j, best[i])
            if links is not None and not _unregistered(o, links) <= alone:
                continue
            tries += 1
            if tries > KIT_ORDER_TRIES:
                break
            e, wk = cost(o)
            if e < excess and wk <= limit:
                best, excess, walk = o, e, wk
                break
        else:
            break  # no move lowers it
    return best


def _unregistered(order: np.ndarray, links: list[set[int]]) -> set[int]:
    """The stations of ``order`` but the first that come after none they link to (the
    first of a group of linked stations among them)."""
    seen = {int(order[0])}
    alone = set()
    for k in order[1:]:
        if links[k] and not links[k] & seen:
            alone.add(int(k))
        seen.add(int(k))
    return alone


def _walks(
    site: Site, g: Any, xy: np.ndarray, order: list[int], pred: np.ndarray | None
) -> tuple[list[np.ndarray], list[float], list[str]]:
    """Each leg of the visiting order walked round the buildings: its path, its length [m]
    and a note (a straight line where no way round was found, a no-go area crossed)."""
    legs: list[np.ndarray] = [np.empty((0, 2))]
    walk_m, notes = [0.0], [""]
    for a, b in itertools.pairwise(order):
        if pred is not None:
            row = pred[a]
        else:  # the way round is rarely more than a few times the straight line
            straight = float(np.hypot(*(xy[a] - xy[b])))
            row = _shortest(g, np.array([a]), limit=NO_GO_PENALTY * (straight + 50.0))[1][0]
        length, path = _leg(g, int(a), int(b), row)
        if path is None:  # no walk round: straight (through a building's passage, a door)
            path = xy[[a, b]]
            length = float(np.hypot(*(xy[a] - xy[b])))
            notes.append("no way round buildings found: straight line taken")
        elif any(shapely.linestrings(path).intersects(z.geometry) for z in site.no_go):
            notes.append("crosses a no-go area")
        else:
            notes.append("")
        walk_m.append(float(length))
        legs.append(path)
    return legs, walk_m, notes


def _target_visits(
    targets: pd.DataFrame, visit: dict[str, int]
) -> tuple[dict[int, list[str]], dict[int, list[str]], dict[str, tuple[int, int]]]:
    """The targets to set at each stop, to collect at each stop, and each target's span of
    stops: a target stands from the first station that scans it to the last (then
    collected), so the kit leap-frogs along the visiting order; a control point is a mark,
    not kit."""
    first_visit: dict[int, list[str]] = {}
    last_visit: dict[int, list[str]] = {}
    life: dict[str, tuple[int, int]] = {}
    for tid, sids, kind in zip(
        targets["target_id"], targets["station_ids"], targets["type"], strict=True
    ):
        seen_by = [visit[s] for s in sids if s in visit]
        if seen_by:
            first_visit.setdefault(min(seen_by), []).append(str(tid))
            if kind != "control":
                last_visit.setdefault(max(seen_by), []).append(str(tid))
                life[str(tid)] = (min(seen_by), max(seen_by))
    return first_visit, last_visit, life


def _scan_sector(
    sector: tuple[float, float, float] | None, sector_scan: bool
) -> tuple[float, float]:
    """Where a station's scan starts and how wide it is [°]: its view sector with a margin
    each side, or a full turn (no sector, one wider than 300°, a scanner that cannot)."""
    start, end, _ = sector or (0.0, 0.0, 0.0)
    width = min(360.0, (end - start) % 360.0 + 2 * SECTOR_MARGIN_DEG)
    if width > 300.0 or not sector_scan:
        return 0.0, 360.0
    return (start - SECTOR_MARGIN_DEG) % 360.0, width


def _route_rows(
    scanner: Scanner,
    settings: PlanSettings,
    preset: Preset | None,
    route: FieldRoute,
    stations: pd.DataFrame,
    targets: pd.DataFrame,
    coverage: pd.DataFrame,
    order: list[int],
    linked: dict[str, set[str]],
    visit: dict[str, int],
    walk: tuple,
) -> list[dict]:
    """One row of :data:`ROUTE_COLUMNS` per stop: the walk, the targets set and collected,
    the set-up, the scan (its sector, points and time: a full dome's time, the maker's
    where stated, else its points over the rate), the images, the session and the time
    elapsed."""
    walk_m, notes, first_visit, last_visit, standing = walk
    xy = stations[["x", "y"]].to_numpy(float)
    ids = stations["station_id"].astype(str).tolist()
    purposes = stations.get("purpose", pd.Series([""] * len(ids))).astype(str).tolist()
    step = resolve_step_mm(scanner, settings.step_mm_at_10m)
    lo, hi = scanner.vertical_fov_deg
    dome = float(scan_points(360.0, hi - lo, step))
    dome_s = preset.scan_s if preset and preset.scan_s else float(scan_time_s(dome, route.rate_hz))
    imaging_min = scanner.imaging_s / 60.0 if settings.imaging else 0.0
    sectors = view_sectors(stations, coverage, targets)
    spacing = coverage.groupby("station_id")["spacing_mm"].max()
    rows, session, used, elapsed = [], 1, 0.0, 0.0
    limit = settings.session_h * 60.0
    setup_min = settings.station_setup_min(scanner)
    for n, k in enumerate(order):
        sid = ids[k]
        start, width = _scan_sector(sectors.get(sid), scanner.sector_scan)
        points = float(scan_points(width, hi - lo, step))
        scanned = purposes[k] != "traverse"  # a total station's set-up: no scan
        points = points if scanned else 0.0
        scan_min = dome_s * points / dome / 60.0
        image_min = imaging_min if scanned else 0.0
        to_set = first_visit.get(n, [])
        to_collect = last_visit.get(n, [])
        walk_min = walk_m[n] / settings.walk_speed_m_s / 60.0
        t_min = settings.target_setup_min * len(to_set)
        c_min = settings.target_collect_min * len(to_collect)
        total = walk_min + t_min + setup_min + scan_min + image_min + c_min
        if used > 0 and used + total > limit:
            session, used = session + 1, 0.0
        used += total
        elapsed += total
        sp = float(spacing.get(sid, np.nan))
        rows.append(
            {
                "order": n + 1,
                "station_id": sid,
                "x": xy[k, 0],
                "y": xy[k, 1],
                "session": session,
                "walk_m": round(walk_m[n], 1),
                "walk_min": round(walk_min, 1),
                "targets_to_set": " ".join(to_set),
                "targets_min": round(t_min, 1),
                "targets_to_collect": " ".join(to_collect),
                "collect_min": round(c_min, 1),
                "targets_standing": int(standing[n]),
                "setup_min": setup_min,
                "sector_start_deg": round(start, 1),
                "sector_deg": round(width, 1),
                "preset": route.preset,
                "step_mm_at_10m": step,
                "scan_points_million": round(points / 1e6, 1),
                "scan_min": round(scan_min, 1),
                "imaging_min": round(image_min, 1),
                "station_min": round(total, 1),
                "elapsed_min": round(elapsed, 1),
                "max_spacing_mm": round(sp, 1) if np.isfinite(sp) else np.nan,
                "links_to": " ".join(sorted(linked.get(sid, ()))),
                "registers_to": " ".join(
                    o for o in sorted(linked.get(sid, ())) if o == "control" or visit.get(o, n) < n
                ),
                "walk_note": notes[n],
            }
        )
    return rows


def _standing(spans: Any, stops: int) -> np.ndarray:
    """How many targets stand at each of ``stops`` stops, each standing from its first
    stop to its last (``spans``, (first, last) pairs, both counted)."""
    spans = np.asarray(spans, dtype=np.int64).reshape(-1, 2)
    count = np.zeros(stops + 1, dtype=np.int64)
    np.add.at(count, spans[:, 0], 1)
    np.add.at(count, spans[:, 1] + 1, -1)
    return np.cumsum(count)[:stops]


def _kit(
    settings: PlanSettings,
    targets: pd.DataFrame,
    life: dict[str, tuple[int, int]],
    links: pd.DataFrame,
    visit: dict[str, int],
    visited: list[str],
) -> pd.DataFrame:
    """Per inventory item (:data:`KIT_COLUMNS`): owned, used by the plan, most standing at
    once and where (each target over its ``life``: the stops of the stations that see it),
    and most standing at once leap-frogged (each over its links' stations' stops)."""
    users: dict[str, set[int]] = {}
    by_target = links["target_ids"] if "target_ids" in links else [""] * len(links)
    for a, b, tids in zip(links["station_a"], links["station_b"], by_target, strict=True):
        for t in str(tids).split(";"):
            users.setdefault(t, set()).update(visit[s] for s in (a, b) if s in visit)
    items = {i.name: i for i in settings.inventory}
    rows = []
    for item, group in targets[targets["type"] != "control"].groupby("item", sort=True):
        tids = group["target_id"].astype(str)
        standing = _standing([life[t] for t in tids if t in life], len(visited))
        leap = _standing(
            [(min(users[t]), max(users[t])) for t in tids if users.get(t)], len(visited)
        )
        peak = int(max(standing, default=0))
        inv = items.get(str(item))
        rows.append(
            {
                "item": str(item),
                "type": str(group["type"].iloc[0]),
                "size_mm": float(group["size_mm"].iloc[0]),
                "owned": inv.count if inv is not None and inv.count else 0,
                "used": len(group),
                "most_at_once": peak,
                "at_station": visited[int(np.argmax(standing))] if peak else "",
                "leapfrog_at_once": int(max(leap, default=0)),
            }
        )
    return pd.DataFrame(rows, columns=KIT_COLUMNS)


def kit_words(k: Any) -> str:
    """One kit row (:data:`KIT_COLUMNS`, as a tuple or Series) and what it asks of the crew
    in words: within the kit, or exactly what to bring — to keep every scan's observation of
    the targets (the registration error as planned), or leap-frogging each target once its
    links' scans are made (fewer observations than the plan's registration error counts)."""
    head = f"{k.most_at_once} {k.item} stand at once (at {k.at_station})"
    if not k.owned:
        return f"{head}; no count given"
    if k.most_at_once <= k.owned:
        return f"{head}, the kit has {k.owned}"
    leap = (
        f"collected once its links' two scans are made, {k.leapfrog_at_once} would stand at "
        "once"
        + (
            f" (bring {k.leapfrog_at_once - k.owned} more)"
            if k.leapfrog_at_once > k.owned
            else " (within the kit)"
        )
        + ", with fewer observations than the registration error counts"
    )
    bring = f"{head}, the kit has {k.owned}: bring {k.most_at_once - k.owned} more"
    if k.leapfrog_at_once >= k.most_at_once:
        return bring
    return f"{bring} to keep every scan's sight of them (as planned); {leap}"
