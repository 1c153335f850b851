"""Setting out on site in a crew's words: tape ties from building corners, where on a wall a
target goes, which walls a station scans.

A crew finds a station or a stand with a tape from two building corners it can see (the
classic "tie" of a setting-out sketch): two physical corners (one that two buildings share
is one corner, named with both), whose tapes cross at a good angle; and a wall target by its
building, its wall, its distance from the wall's end and its height above the ground. Grid
bearings (clockwise from the grid's north, degrees); distances in metres on the ground.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from itertools import combinations

import numpy as np
import pandas as pd
import shapely
from scipy.spatial import cKDTree

from planner.site import Site

__all__ = [
    "GOOD_CROSSING_DEG",
    "NEAR_CORNERS",
    "SAME_CORNER_M",
    "CornerTies",
    "Tie",
    "compass_word",
    "corner_ties",
    "ties_text",
    "wall_place",
    "walls_scanned",
]

_WORDS = ("north", "north-east", "east", "south-east", "south", "south-west", "west", "north-west")
_SHORT = ("N", "NE", "E", "SE", "S", "SW", "W", "NW")


def compass_word(azimuth_deg: float, short: bool = False) -> str:
    """An azimuth [deg, clockwise from north] as one of the 8 compass words.

    >>> compass_word(181.0), compass_word(300.0, short=True)
    ('south', 'NW')
    """
    k = int(((float(azimuth_deg) % 360.0) + 22.5) // 45) % 8
    return (_SHORT if short else _WORDS)[k]


def _azimuth(dx: float, dy: float) -> float:
    return float(np.degrees(np.arctan2(dx, dy)) % 360.0)


#: Corners of different buildings closer than this [m] are one physical corner (two
#: buildings built against each other share it): a tie names it once, with both buildings.
SAME_CORNER_M = 0.05
#: Two tapes fix a point well where they cross at an angle in this range [deg]: from
#: corners in nearly the same or the opposite direction the point slides along the tapes.
GOOD_CROSSING_DEG = (30.0, 150.0)
#: The nearest corners in sight that a station's or a target's two ties are chosen among.
NEAR_CORNERS = 5
#: Where no building corner is in sight: what the crew does instead.
NO_CORNER = "no building corner in sight: set it out by its coordinates"


@dataclass(frozen=True)
class Tie:
    """A tape tie: from ``corner`` (its name and position) ``distance_m`` along the grid
    bearing ``bearing_deg`` to the point."""

    corner: str
    x: float
    y: float
    distance_m: float
    bearing_deg: float

    def text(self) -> str:
        return f"{self.distance_m:.2f} m at {self.bearing_deg:.0f}° from {self.corner}"

    def crossing_deg(self, other: Tie) -> float:
        """The angle [deg, 0–180] at which this tape and ``other`` cross at the point they
        tie (the angle between their bearings)."""
        diff = abs(self.bearing_deg - other.bearing_deg) % 360.0
        return min(diff, 360.0 - diff)


def ties_text(ties: list[Tie]) -> str:
    """A point's ties in a crew's words: two tapes from two corners (and the angle they cross
    at where it is outside :data:`GOOD_CROSSING_DEG`: no better pair was in sight); the one
    corner in sight said as the only one (its bearing fixes the point); none, said so."""
    if not ties:
        return NO_CORNER
    if len(ties) == 1:
        return (
            f"{ties[0].text()}, the only building corner in sight (tape and bearing, or "
            "set it out by its coordinates)"
        )
    text = "; ".join(t.text() for t in ties)
    angle = ties[0].crossing_deg(ties[1])
    lo, hi = GOOD_CROSSING_DEG
    if not lo <= angle <= hi:
        text += f" (the tapes cross at {angle:.0f}°: check it by the bearings)"
    return text


def _building_corners(site: Site) -> tuple[np.ndarray, list[str], list[tuple[str, str]]]:
    """Every building's outline corners (vertices where the outline turns by more than
    10°): their positions, buildings and names, each as ("main NE", where): the building
    and the corner's compass side from its centre (the building's extent scaled to a
    square, so that a long building's end corners read NE, SE, SW, NW), and where a name two
    corners of a building would share, the corner's coordinates (" (E … N …)"; else "")."""
    xy, owners, names = [], [], []
    for b in site.buildings:
        x0, y0, x1, y1 = b.footprint.bounds
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        w, h = max(x1 - x0, 1e-9), max(y1 - y0, 1e-9)
        mine: list[tuple[np.ndarray, str]] = []
        for poly in getattr(b.footprint, "geoms", [b.footprint]):
            ring = np.asarray(poly.exterior.coords)[:-1, :2]
            n = len(ring)
            for k in range(n):
                a, p, c = ring[k - 1], ring[k], ring[(k + 1) % n]
                u, v = p - a, c - p
                turn = abs(np.degrees(np.arctan2(u[0] * v[1] - u[1] * v[0], u @ v)))
                if turn >= 10.0:
                    side = compass_word(_azimuth((p[0] - cx) / w, (p[1] - cy) / h), short=True)
                    mine.append((p, f"{b.id} {side}"))
        seen = Counter(name for _, name in mine)
        for p, name in mine:
            xy.append(p)
            owners.append(b.id)
            names.append((name, "" if seen[name] == 1 else f" (E {p[0]:.1f} N {p[1]:.1f})"))
    return np.array(xy, dtype=float).reshape(-1, 2), owners, names


def _corners(site: Site) -> tuple[np.ndarray, list[str]]:
    """The site's physical corners and their names: the buildings' outline corners
    (:func:`_building_corners`), those closer than :data:`SAME_CORNER_M` one corner (two
    buildings built against each other share it) at their mean, named once with every
    building ("bub051 NW / bub052 NE corner"), in the buildings' order."""
    xy, owners, names = _building_corners(site)
    group = list(range(len(xy)))  # union–find: each corner's first corner of its group

    def root(k: int) -> int:
        while group[k] != k:
            k = group[k]
        return k

    pairs = sorted(cKDTree(xy).query_pairs(SAME_CORNER_M)) if len(xy) else []
    for a, b in pairs:
        ra, rb = root(a), root(b)
        group[max(ra, rb)] = min(ra, rb)
    members: dict[int, list[int]] = {}
    for k in range(len(xy)):
        members.setdefault(root(k), []).append(k)
    out_xy, out_names = [], []
    for ks in members.values():
        # each building once (two corners of one building closer than that: its first)
        first = [k for n, k in enumerate(ks) if owners[k] not in {owners[j] for j in ks[:n]}]
        if len(first) == 1:  # "main NE corner", "main S corner (E … N …)"
            out_names.append(f"{names[first[0]][0]} corner{names[first[0]][1]}")
        else:
            out_names.append(" / ".join(names[k][0] + names[k][1] for k in first) + " corner")
        out_xy.append(xy[ks].mean(axis=0))
    return np.array(out_xy, dtype=float).reshape(-1, 2), out_names


class CornerTies:
    """The tape ties of a site, its corners found once (for every station and target of a
    booklet, not once a page): call it with points for each point's ties from two distinct
    physical corners in plain sight, crossing well."""

    def __init__(self, site: Site) -> None:
        self.corners, self.names = _corners(site)
        self._tree = cKDTree(self.corners) if len(self.corners) else None
        # shrunk by the corners' tolerance: a corner two buildings share (their mean) stands
        # clear of both, and a tape grazing a wall by less than that is not hidden by it
        walls = shapely.union_all([b.footprint for b in site.buildings])
        self._walls = walls.buffer(-SAME_CORNER_M)
        shapely.prepare(self._walls)

    def __call__(self, points: np.ndarray, n: int = 2) -> list[list[Tie]]:
        """For each point (``(k, 2)`` [m]), ``n`` tape ties from distinct building corners
        in plain sight of it (the line to the corner crosses no building), nearest first;
        fewer where fewer are in sight.

        Two tapes fix a point where their circles cross; crossing at a shallow angle (from
        corners in nearly the same or the opposite direction) a centimetre on a tape moves
        the point along the other by 1/sin of the angle (4 cm at 15°, 11 cm at 5°, against
        1 cm at 90°), and where they nearly touch the crew cannot tell where they cross.
        So the two ties are the pair of the
        :data:`NEAR_CORNERS` nearest corners in sight whose tapes cross within
        :data:`GOOD_CROSSING_DEG`, the shortest tapes together; where no pair does, the pair
        whose tapes' lengths over the sine of their angle (what the crossing's error grows
        with) is least, and :func:`ties_text` says the angle. Further ties (``n`` > 2): the
        nearest others."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        if self._tree is None:
            return [[] for _ in points]
        return [_pick(self._in_sight(p, n), n) for p in points]

    def _in_sight(self, p: np.ndarray, n: int) -> list[Tie]:
        """The :data:`NEAR_CORNERS` (at least ``n``) corners nearest ``p`` in plain sight as
        ties, nearest first (equals in the corners' order); fewer where fewer are in sight.
        The nearest few are looked at first, more only while fewer than ``n`` are in sight."""
        want = max(n, NEAR_CORNERS)
        k_near = min(len(self.corners), 8 * want)
        while True:
            d, near = (np.atleast_1d(a) for a in self._tree.query(p, k=k_near))
            order = np.lexsort((near, d))  # nearest first, equals in the corners' order
            ties: list[Tie] = []
            for dk, k in zip(d[order], near[order], strict=True):
                c = self.corners[k]
                if dk < 0.01 or self._walls.intersects(shapely.LineString([c, p])):
                    continue
                ties.append(Tie(self.names[k], *c, float(dk), _azimuth(*(p - c))))
                if len(ties) == want:
                    return ties
            if len(ties) >= n or k_near == len(self.corners):
                return ties
            k_near = min(len(self.corners), 4 * k_near)


def _pick(ties: list[Tie], n: int) -> list[Tie]:
    """``n`` of a point's ties in sight (nearest first): the pair crossing well with the
    shortest tapes together (else the one whose crossing errs least), then the nearest
    others; nearest first (see :meth:`CornerTies.__call__`)."""
    if n < 2 or len(ties) < 3:
        return ties[:n]
    lo, hi = GOOD_CROSSING_DEG
    pairs = list(combinations(range(len(ties)), 2))
    angle = {(i, j): ties[i].crossing_deg(ties[j]) for i, j in pairs}
    good = [ij for ij in pairs if lo <= angle[ij] <= hi]
    tape = {ij: ties[ij[0]].distance_m + ties[ij[1]].distance_m for ij in pairs}
    if good:
        best = min(good, key=lambda ij: (tape[ij], ij))
    else:  # the smallest error of the crossing: the tapes' lengths over the angle's sine
        best = min(pairs, key=lambda ij: (tape[ij] / max(np.sin(np.radians(angle[ij])), 1e-9), ij))
    rest = [k for k in range(len(ties)) if k not in best][: n - 2]
    return [ties[k] for k in sorted([*best, *rest])]


def corner_ties(site: Site, points: np.ndarray, n: int = 2) -> list[list[Tie]]:
    """:class:`CornerTies` of ``site`` at ``points`` (for one call; a booklet keeps one)."""
    return CornerTies(site)(points, n)


def wall_place(facade: pd.Series, x: float, y: float, z: float) -> str:
    """Where a wall target goes, as a crew looks for it: its building, its wall (by the way
    it faces), the distance from the wall's end nearer the west (or the south, on a wall
    running north–south) and its height ``z`` above the ground, e.g. "building main, north
    wall, 4.2 m from its west end, 3.0 m high"."""
    a = np.array([facade["x0"], facade["y0"]], dtype=float)
    b = np.array([facade["x1"], facade["y1"]], dtype=float)
    along = b - a
    facing = _azimuth(along[1], -along[0])  # outward: the ring runs anticlockwise
    east_west = abs(along[0]) >= abs(along[1])
    start = a if (a[0] < b[0] if east_west else a[1] < b[1]) else b
    end_word = "west" if east_west else "south"
    dist = float(np.hypot(x - start[0], y - start[1]))
    return (
        f"building {facade['building_id']}, {compass_word(facing)} wall, {dist:.1f} m from its "
        f"{end_word} end, {z:.1f} m high"
    )


def walls_scanned(coverage: pd.DataFrame, facades: pd.DataFrame, station_id: str) -> str:
    """The walls a station scans (the samples assigned to it), in words: "main north wall
    (20 points), annex east wall (8 points)"; most points first."""
    mine = coverage[(coverage["station_id"] == station_id) & ~coverage["party_wall"]]
    if mine.empty:
        return "none (it ties the others together)"
    fac = facades.set_index("facade_id")
    named = []
    for fid, count in mine["facade_id"].value_counts().items():
        f = fac.loc[fid]
        facing = _azimuth(f["y1"] - f["y0"], -(f["x1"] - f["x0"]))
        named.append((f"{f['building_id']} {compass_word(facing)} wall", fid, count))
    names = [n for n, _, _ in named]
    return ", ".join(  # two walls of one building facing one way: told apart by their ids
        f"{n} ({fid}, {c} points)" if names.count(n) > 1 else f"{n} ({c} points)"
        for n, fid, c in named
    )
