"""Planned control: stations that no common target ties to the others are tied by control
points coordinated from outside.

A group of stations the registration network does not reach (a courtyard behind a long
gateway, targets too small for the distances between the groups) is registered to three
**planned control points** — spheres on stands among its stations — coordinated in the
network's frame in one of two ways:

* **a total-station traverse** (the first choice): set-ups on open ground, each seeing the
  next (2.5-D line of sight at instrument height, under a gateway's floors too), from a
  tied station to one of the group's, legs of at most :data:`TRAVERSE_LEG_MAX_M`; the last
  set-up shoots the control points. Its error, per coordinate: the start station's pose
  error carried to the group, plus ``traverse_mm`` for every leg added in quadrature (an
  open traverse's legs err independently: σ√n — Ghilani & Wolf, *Elementary Surveying*,
  13th ed., Pearson 2012, ch. 3 (errors of a sum); the heading error a leg adds, a few
  arc-seconds, is left out beside the control points' own geometry), common to all the
  group's control points; each point's own shot adds :data:`CONTROL_SHOT_MM`.
* **GNSS** where no traverse reaches and the sky is open over the group (no obstruction
  above :data:`GNSS_MASK_DEG` in :data:`GNSS_OPEN_SHARE` of the directions): each point
  ``gnss_mm`` on its own, the frame tied to the network by GNSS points among its stations
  (``gnss_mm``/√3).

The group's stations are registered to their control points as a network of their own
(:func:`~planner.pipeline.network.registration.build_network`, the control as its datum), and the
datum error above is added to every one of their poses: what the group's samples are
judged on. A group neither reaches stays untied and its place is named.
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from planner.pipeline.evaluation.evaluate import Context, assign_stations
from planner.pipeline.geometry.visibility import clear_height
from planner.pipeline.inputs.schema import STATION_COLUMNS
from planner.pipeline.network.network import Network, control_messages
from planner.pipeline.network.registration import build_network
from planner.pipeline.network.targets import SightCache, TargetCandidates
from planner.registration_error import CONTROL, Link, transport_pose_cov

__all__ = [
    "CONTROL_SHOT_MM",
    "ControlTie",
    "sky_open",
    "tie_groups",
    "tie_messages",
    "traverse_path",
    "traverse_setups",
]

#: The longest traverse leg [m] (a total station's comfortable distance for a set-up).
TRAVERSE_LEG_MAX_M = 80.0
#: Traverse set-ups are searched on a grid this coarse (a subset of the candidates) [m] …
TRAVERSE_GRID_M = 6.0
#: … at most this many of them looked out from (each tests its sight lines to every set-up
#: within a leg), nearest the group first (A*): a count, not a time, so the same traverse is
#: found on any machine; where the search ends without one the group is tied otherwise
#: (GNSS) or said untied. (A gated 10-building block's courtyards, searched breadth first
#: and unbounded, took over ten minutes.)
TRAVERSE_MAX_SETUPS = 400
#: RMS per coordinate of a control point shot from a total-station set-up at up to 30 m
#: (1″ and 1 mm + 1.5 ppm: about 0.2 mm across and 1 mm along) [mm].
CONTROL_SHOT_MM = 1.0
#: GNSS needs the sky above this elevation clear …
GNSS_MASK_DEG = 30.0
#: … in at least this share of the directions round the point.
GNSS_OPEN_SHARE = 0.75
#: Control points are chosen among the spheres a group's station sees within this [m].
CONTROL_RADIUS_M = 30.0


@dataclass
class ControlTie:
    """How a group of stations is tied: ``kind`` "traverse" or "gnss", the group's stations
    (positions in the network), the traverse set-ups [m] from the tied station ``start`` to
    the group (none for GNSS), the planned control points (target candidate indices) and the
    datum error they carry, per coordinate [mm]."""

    kind: str
    stations: list[int]
    control: list[int]
    datum_rms_mm: float
    setups: np.ndarray = field(default_factory=lambda: np.empty((0, 2)))
    start: int = -1

    @property
    def legs(self) -> int:
        return max(0, len(self.setups) - 1)


def _sees(ctx: Context, a: np.ndarray, b: np.ndarray, height_m: float) -> np.ndarray:
    """Whether each of the points ``b`` (P, 2) is seen from ``a`` (2,) with both ends at
    ``height_m`` above the ground (a total station sighting a prism on a pole)."""
    if not len(b):
        return np.zeros(0, dtype=bool)
    src = np.column_stack(
        [np.broadcast_to(a, b.shape), ctx.scene.above_ground(a[None, :], height_m).repeat(len(b))]
    )
    dst = np.column_stack([b, ctx.scene.above_ground(b, height_m)])
    lo_xy, hi_xy = np.minimum(b.min(axis=0), a), np.maximum(b.max(axis=0), a)
    return ctx.scene.seen(src, dst, groups=(np.array([0, len(b)]), np.array([[*lo_xy, *hi_xy]])))


def traverse_path(
    ctx: Context,
    nodes: np.ndarray,
    starts: np.ndarray,
    ends: np.ndarray,
) -> list[int] | None:
    """The fewest legs from any of ``starts`` to any of ``ends`` (indices into ``nodes``,
    (N, 2) [m]) over legs of at most :data:`TRAVERSE_LEG_MAX_M` whose ends see each other:
    an A* search (the legs so far plus the legs the straight line to the nearest end needs
    at least), the line of sight tested as it goes, looking out from at most
    :data:`TRAVERSE_MAX_SETUPS` set-ups. None if none reaches within it."""
    hi = ctx.settings.instrument_height_m
    prev = np.full(len(nodes), -2, dtype=np.int64)
    prev[starts] = -1
    is_end = np.zeros(len(nodes), dtype=bool)
    is_end[ends] = True
    goal = nodes[np.asarray(ends, dtype=np.int64)]

    def to_goal(i: int) -> float:
        return float(np.min(np.hypot(*(goal - nodes[i]).T)))

    legs = np.zeros(len(nodes), dtype=np.int64)
    heap = [
        (math.ceil(to_goal(int(s)) / TRAVERSE_LEG_MAX_M), to_goal(int(s)), int(s)) for s in starts
    ]
    heapq.heapify(heap)
    looked = 0
    while heap:
        _, _, a = heapq.heappop(heap)
        if is_end[a]:
            path = [a]
            while prev[path[-1]] >= 0:
                path.append(int(prev[path[-1]]))
            return path[::-1]
        looked += 1
        if looked > TRAVERSE_MAX_SETUPS:
            return None
        free = np.flatnonzero(prev == -2)
        close = free[np.hypot(*(nodes[free] - nodes[a]).T) <= TRAVERSE_LEG_MAX_M]
        for b in close[_sees(ctx, nodes[a], nodes[close], hi)].tolist():
            prev[b], legs[b] = a, legs[a] + 1
            d = to_goal(b)
            heapq.heappush(heap, (int(legs[b]) + math.ceil(d / TRAVERSE_LEG_MAX_M), d, b))
    return None


def sky_open(ctx: Context, xy: np.ndarray, directions: int = 36, reach_m: float = 300.0) -> bool:
    """Whether GNSS can work at ``xy`` [m]: in :data:`GNSS_OPEN_SHARE` of ``directions``
    round it, nothing rises above :data:`GNSS_MASK_DEG` (buildings and obstacles, their
    heights over the instrument's)."""
    hi = ctx.settings.instrument_height_m
    az = np.radians(np.arange(directions) * 360.0 / directions)
    if not ctx.scene.prisms:  # a ray up at the mask's elevation in each direction
        z = ctx.scene.above_ground(np.asarray(xy, float)[None, :], hi)[0]
        el = np.radians(GNSS_MASK_DEG)
        vec = reach_m * np.column_stack(
            [np.cos(el) * np.sin(az), np.cos(el) * np.cos(az), np.full(directions, np.sin(el))]
        )
        org = np.broadcast_to([xy[0], xy[1], z], vec.shape)
        return bool((~ctx.scene.occluded(org, vec)).mean() >= GNSS_OPEN_SHARE)
    e, h = ctx.edges, ctx.edge_heights
    ends = np.column_stack([xy[0] + reach_m * np.sin(az), xy[1] + reach_m * np.cos(az)])
    # the lowest height seen at the ray's end is where the highest obstruction's angle points
    zc = clear_height(np.broadcast_to(xy, ends.shape), hi, ends, e, h)
    elevation = np.degrees(np.arctan2(np.maximum(zc - hi, 0.0), reach_m))
    return bool((elevation <= GNSS_MASK_DEG).mean() >= GNSS_OPEN_SHARE)


def _groups(ctx: Context, net: Network) -> list[list[int]]:
    """The untied stations by the open ground they stand in (positions in ``net``)."""
    untied = np.flatnonzero(~net.tied)
    region = ctx.regions.label(net.station_xyz[untied, :2])
    return [list(map(int, untied[region == r])) for r in np.unique(region)]


def _control_points(
    ctx: Context, seen: SightCache, cand: np.ndarray, station: int, rms_mm: float, name: str
) -> TargetCandidates | None:
    """Three planned control points among the spheres candidate ``station`` sees within
    :data:`CONTROL_RADIUS_M`, spread the most (the largest triangle); None if it sees fewer
    than three."""
    tc = seen.tc
    usable = seen.usable([station])[:, 0] & (tc.type == "sphere")
    d = np.hypot(*(tc.xyz[:, :2] - cand[station]).T)
    pick = np.flatnonzero(usable & (d <= CONTROL_RADIUS_M))
    if len(pick) < 3:
        return None
    pick = pick[np.argsort(d[pick])][:40]
    xy = tc.xyz[pick, :2]
    best, area = None, 0.0
    for i in range(len(pick)):
        for j in range(i + 1, len(pick)):
            cross = np.abs(
                (xy[j, 0] - xy[i, 0]) * (xy[:, 1] - xy[i, 1])
                - (xy[j, 1] - xy[i, 1]) * (xy[:, 0] - xy[i, 0])
            )
            k = int(np.argmax(cross))
            if cross[k] / 2.0 > area:
                best, area = (i, j, k), cross[k] / 2.0
    if best is None or area < 1.0:
        return None
    sel = pick[list(best)]
    return TargetCandidates(
        xyz=tc.xyz[sel].copy(),
        type=np.array(["control"] * 3, dtype=object),
        normal=np.zeros((3, 2)),
        facade=np.full(3, -1, dtype=np.int64),
        control_id=np.array([f"{name}{n + 1}" for n in range(3)], dtype=object),
        control_rms_mm=np.full(3, rms_mm),
    )


def tie_groups(
    ctx: Context,
    cand: np.ndarray,
    seen: SightCache,
    net: Network,
    goal_mm: float,
) -> Network:
    """``net`` with each group of untied stations tied by planned control where a traverse
    or GNSS can (the module's text); the planned points become control targets of the
    plan, the ties are in ``net.ties``."""
    if net.error is None or net.tied.all() or not net.tied.any():
        return net
    st = ctx.settings
    coarse = _coarse_nodes(cand, TRAVERSE_GRID_M)
    local = seen.fork(net.stations)  # the planned points stay out of the plan's cache
    n_group = 0
    for group in _groups(ctx, net):
        tied = np.flatnonzero(net.tied)
        nodes = np.vstack([cand[net.stations[tied]], cand[net.stations[group]], cand[coarse]])
        starts = np.arange(len(tied))
        ends = len(tied) + np.arange(len(group))
        path = traverse_path(ctx, nodes, starts, ends)
        if path is not None:
            kind, legs = "traverse", len(path) - 1
            anchor = group[int(path[-1] - len(tied))]
            start = int(tied[path[0]])
            datum_rms = st.traverse_mm * math.sqrt(legs)
            point_rms = CONTROL_SHOT_MM
            setups = nodes[path]
        elif sky_open(ctx, cand[net.stations[group[0]]]):
            kind, anchor, start, setups = "gnss", group[0], -1, np.empty((0, 2))
            datum_rms, point_rms = st.gnss_mm / math.sqrt(3.0), st.gnss_mm
        else:
            continue
        points = _control_points(
            ctx, local, cand, int(net.stations[anchor]), point_rms, f"C{n_group + 1}-"
        )
        if points is None:
            continue
        added = local.add_targets(points)
        local.by_hand[added] = False  # planned here, not placed by hand
        sub = _group_network(ctx, cand, local, net, group, goal_mm)
        if sub is None or not sub.tied.all():
            local.barred[added] = True  # not used after all
            continue
        n_group += 1
        tie = ControlTie(kind, group, list(map(int, added)), datum_rms, setups, start)
        _merge(net, sub, tie, local)
    return net


def _coarse_nodes(cand: np.ndarray, grid_m: float) -> np.ndarray:
    cells = np.floor(cand / grid_m + 1e-9).astype(np.int64)
    _, first = np.unique(cells, axis=0, return_index=True)
    return np.sort(first)


def _group_network(
    ctx: Context, cand: np.ndarray, seen: SightCache, net: Network, group: list[int], goal_mm
) -> Network | None:
    """The group's stations registered among themselves and to the control points."""
    chosen = net.stations[group]
    scanner_only = assign_stations(ctx, cand[chosen])
    fac = ctx.facades
    pts = np.column_stack([fac.xy, fac.z])
    probes = {j: pts[scanner_only.station == j] for j in range(len(chosen))}
    # the main network's spheres stand while the group is scanned, and hide what is behind
    sub = build_network(
        ctx, seen.tc, cand, chosen, probes, goal_mm=goal_mm, cache=seen, standing=net.targets
    )
    return sub if sub.datum is None and sub.error is not None else None


def _merge(net: Network, sub: Network, tie: ControlTie, seen: SightCache) -> None:
    """The group's registration put into ``net``: its stations tied with their poses in
    the control's frame plus the datum error (and, for a traverse, the start station's pose
    error carried to them), its links, targets and observations added."""
    pos = list(tie.stations)  # sub's station k is net's station pos[k]
    err = net.error
    extra = sub.stations[len(pos) :]  # linking stations the group's own network added
    if len(extra):
        base = len(net.stations)
        net.stations = np.concatenate([net.stations, extra])
        net.station_xyz = np.vstack([net.station_xyz, sub.station_xyz[len(pos) :]])
        err.pose_cov = np.concatenate([err.pose_cov, np.zeros((len(extra), 6, 6))])
        err.tied = np.concatenate([err.tied, np.zeros(len(extra), dtype=bool)])
        if net.overlap is not None:  # the linking stations' overlaps: the group's own
            grown = np.full((len(net.stations),) * 2, np.nan)
            grown[:base, :base] = net.overlap
            if sub.overlap is not None:
                at = np.asarray(pos + list(range(base, base + len(extra))))
                grown[np.ix_(at, at)] = sub.overlap[: len(at), : len(at)]
            net.overlap = grown
        net.n_link_stations += len(extra)
        pos += list(range(base, base + len(extra)))
        tie.stations = pos
    datum = np.zeros((6, 6))
    datum[:3, :3] = np.eye(3) * tie.datum_rms_mm**2
    for k, j in enumerate(pos):
        pose = sub.error.pose_cov[k] + datum
        if tie.start >= 0:
            pose = pose + transport_pose_cov(
                err.pose_cov[tie.start], net.station_xyz[tie.start], net.station_xyz[j]
            )
        err.pose_cov[j] = pose
        err.tied[j] = True

    def at(s: int) -> int:
        return s if s == CONTROL else pos[s]

    for lk in sub.links:
        net.links.append(Link(at(lk.parent), at(lk.child), lk.targets, lk.info))
        key = (lk.parent, lk.child)
        new = (at(lk.parent), at(lk.child))
        net.link_error_mm[new] = sub.link_error_mm.get(key, np.nan)
        net.link_sigma_mm[new] = sub.link_sigma_mm.get(key, np.nan)
        if key in sub.error.link_cov:
            err.link_cov[new] = sub.error.link_cov[key]
    for (j, t), rms in sub.centre_rms.items():
        net.centre_rms[(pos[j], t)] = rms
    net.targets = sorted(set(net.targets) | set(sub.targets))
    net.candidates = seen.tc
    net.sight = seen(net.stations)
    net.ties.append(tie)
    net.message = control_messages(net)


def setup_id(tie_no: int, k: int) -> str:
    """A traverse set-up's id: ``TR1-02`` is the second set-up of the first traverse."""
    return f"TR{tie_no}-{k + 1:02d}"


def traverse_setups(ties: list[ControlTie], settings, ground_z) -> pd.DataFrame:
    """The traverses' set-ups as rows of the stations table (purpose ``traverse``): where
    the crew sets up the total station, in order from the tied side (``ground_z``: the
    ground's height under points (P, 2))."""
    rows = []
    n = 0
    for tie in ties:
        if tie.kind != "traverse":
            continue
        n += 1
        for k, (x, y) in enumerate(tie.setups):
            rows.append(
                {
                    "station_id": setup_id(n, k),
                    "x": float(x),
                    "y": float(y),
                    "ground_z": float(ground_z(np.array([[x, y]]))[0]),
                    "instrument_height_m": settings.instrument_height_m,
                    "purpose": "traverse",
                    "samples_met": 0,
                }
            )
    return pd.DataFrame(rows, columns=[*STATION_COLUMNS, "samples_met"])


def tie_messages(
    ties: list[ControlTie], ids: list[str], tc: TargetCandidates, settings
) -> list[str]:
    """One line per group tied by planned control: how, from where, to which points, and
    the datum error it carries."""
    out = []
    n = 0
    for tie in ties:
        group = ", ".join(ids[j] for j in tie.stations if j < len(ids))
        points = ", ".join(str(tc.control_id[t]) for t in tie.control)
        if tie.kind == "traverse":
            n += 1
            how = (
                f"a total-station traverse of {tie.legs} leg(s) from {ids[tie.start]} "
                f"(set-ups {setup_id(n, 0)} to {setup_id(n, tie.legs)})"
            )
            rule = f"{settings.traverse_mm:g} mm per leg, --traverse-mm"
        else:
            how = "GNSS (the sky is open there)"
            rule = f"{settings.gnss_mm:g} mm a point, --gnss-mm"
        out.append(
            f"Registration: {group} tied by planned control: {how} coordinating control "
            f"points {points}; their datum ±{tie.datum_rms_mm:.1f} mm per coordinate "
            f"({rule}) is in every sample's registration error there."
        )
    return out
