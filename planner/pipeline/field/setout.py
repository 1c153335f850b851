"""Setting out on site in a crew's words: tape ties from building corners, where on a wall a
target goes, which walls a station scans.

A crew finds a station or a stand with a tape from two building corners it can see (the
classic "tie" of a setting-out sketch), and a wall target by its building, its wall, its
distance from the wall's end and its height. Grid bearings (clockwise from the grid's
north, degrees); distances in metres on the ground.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

import numpy as np
import pandas as pd
import shapely
from scipy.spatial import cKDTree

from planner.site import Site

__all__ = ["CornerTies", "Tie", "compass_word", "corner_ties", "wall_place", "walls_scanned"]

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


def _corners(site: Site) -> tuple[np.ndarray, list[str]]:
    """Every building's outline corners (vertices where the outline turns by more than
    10°), named by building and their compass side from its centre (the building's extent
    scaled to a square, so that a long building's end corners read NE, SE, SW, NW); a name
    two corners would share gets the corner's coordinates."""
    xy, names = [], []
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
                    mine.append((p, f"{b.id} {side} corner"))
        seen = Counter(name for _, name in mine)
        for p, name in mine:
            if seen[name] > 1:
                name += f" (E {p[0]:.1f} N {p[1]:.1f})"
            xy.append(p)
            names.append(name)
    return np.array(xy, dtype=float).reshape(-1, 2), names


class CornerTies:
    """The tape ties of a site, its corners found once (for every station and target of a
    booklet, not once a page): call it with points for each point's nearest corners in
    plain sight."""

    def __init__(self, site: Site) -> None:
        self.corners, self.names = _corners(site)
        self._tree = cKDTree(self.corners) if len(self.corners) else None
        self._walls = shapely.union_all([b.footprint for b in site.buildings]).buffer(-0.01)
        shapely.prepare(self._walls)

    def __call__(self, points: np.ndarray, n: int = 2) -> list[list[Tie]]:
        """For each point (``(k, 2)`` [m]), the ``n`` nearest building corners in plain sight
        of it (the line to the corner crosses no building), as tape ties; fewer where fewer
        are in sight."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        if self._tree is None:
            return [[] for _ in points]
        out = []
        for p in points:
            ties: list[Tie] = []
            k_near = min(len(self.corners), 8 * n)
            while True:  # the nearest few first; all of them where those are out of sight
                d, near = (np.atleast_1d(a) for a in self._tree.query(p, k=k_near))
                order = np.lexsort((near, d))  # nearest first, equals in the corners' order
                for dk, k in zip(d[order], near[order], strict=True):
                    if len(ties) == n:
                        break
                    c = self.corners[k]
                    if dk < 0.01 or self._walls.intersects(shapely.LineString([c, p])):
                        continue
                    ties.append(Tie(self.names[k], *c, float(dk), _azimuth(*(p - c))))
                if len(ties) == n or k_near == len(self.corners):
                    break
                ties, k_near = [], len(self.corners)
            out.append(ties)
        return out


def corner_ties(site: Site, points: np.ndarray, n: int = 2) -> list[list[Tie]]:
    """:class:`CornerTies` of ``site`` at ``points`` (for one call; a booklet keeps one)."""
    return CornerTies(site)(points, n)


def wall_place(facade: pd.Series, x: float, y: float, z: float) -> str:
    """Where a wall target goes, as a crew looks for it: its building, its wall (by the way
    it faces), the distance from the wall's end nearer the west (or the south, on a wall
    running north–south) and its height, e.g. "building main, north wall, 4.2 m from its
    west end, 3.0 m high"."""
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
