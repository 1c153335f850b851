"""Candidate station positions: a grid over the free ground within reach of the facades."""

from __future__ import annotations

import math

import numpy as np
import shapely

from planner.errors import InputError
from planner.pipeline.geometry.facades import FacadeSet
from planner.site import Site

__all__ = ["MAX_GRID_POINTS", "GroundRegions", "blocked_ground", "candidate_grid"]

#: The candidate grid is refused beyond this many points (memory: 20 bytes each) [points].
MAX_GRID_POINTS = 50_000_000


def blocked_ground(site: Site, clearance_m: float) -> shapely.Geometry:
    """Where no station may stand: in or within ``clearance_m`` of a building or an
    obstacle, or in a no-go area."""
    blocked = [
        g.buffer(clearance_m, join_style="mitre") if clearance_m > 0 else g
        for _, g, _ in site.blockers
    ]
    blocked += [a.geometry for a in site.no_go]
    return shapely.union_all(blocked)


#: Gaps between buildings narrower than twice this are closed when the open ground is split
#: into regions: nobody walks, and no registration is made, through a digitising gap [m].
REGION_GAP_M = 0.25
#: The open ground is taken this far round the site [m]: beyond any station's reach.
REGION_MARGIN_M = 5000.0


class GroundRegions:
    """The open ground between the buildings and obstacles (without their passages) in its
    connected parts: a closed courtyard is a region of its own, a gateway (a passage)
    joins it to the street. Stations in different regions cannot be registered to each
    other by targets (no target is seen from both), nor walked between."""

    def __init__(self, site: Site) -> None:
        solid = shapely.union_all(
            [g.buffer(REGION_GAP_M, join_style="mitre") for _, g, _ in site.blockers]
        )
        x0, y0, x1, y1 = solid.bounds
        m = REGION_MARGIN_M
        ground = shapely.box(x0 - m, y0 - m, x1 + m, y1 + m).difference(solid)
        self.parts = [p for p in shapely.get_parts(ground) if not p.is_empty]
        self._tree = shapely.STRtree(self.parts)
        self._outer = shapely.box(x0 - m, y0 - m, x1 + m, y1 + m).exterior
        self._site = site

    def label(self, xy: np.ndarray) -> np.ndarray:
        """The region of each point (``(P, 2)`` [m]); -1 where none holds it (inside a
        building, or within :data:`REGION_GAP_M` of one)."""
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        out = np.full(len(xy), -1, dtype=np.int64)
        if not len(xy) or not self.parts:
            return out
        hit = self._tree.query(shapely.points(xy), predicate="intersects")
        out[hit[0]] = hit[1]
        return out

    def enclosed(self, region: int) -> bool:
        """Whether the region is closed all round by buildings (it does not reach the open
        ground round the site)."""
        return region >= 0 and not self.parts[region].intersects(self._outer)

    def enclosing(self, region: int) -> list[str]:
        """The buildings bordering a region (ids, sorted)."""
        if region < 0:
            return []
        edge = self.parts[region].buffer(2 * REGION_GAP_M)
        return sorted(b.id for b in self._site.buildings if b.footprint.intersects(edge))


def candidate_grid(
    site: Site, facades: FacadeSet, reach: float, grid_m: float, clearance_m: float
) -> np.ndarray:
    """Grid points (``(C, 2)``, aligned to multiples of ``grid_m``) on free ground within
    ``reach`` of a planned facade."""
    segs = shapely.linestrings(np.stack([facades.start, facades.end], axis=1))
    area = shapely.union_all(shapely.buffer(segs, reach))
    if site.boundary is not None:
        area = shapely.intersection(area, site.boundary)
    area = shapely.difference(area, blocked_ground(site, clearance_m))
    if area.is_empty:
        return np.empty((0, 2))
    xmin, ymin, xmax, ymax = area.bounds
    points = ((xmax - xmin) / grid_m + 1) * ((ymax - ymin) / grid_m + 1)
    if points > MAX_GRID_POINTS:
        raise InputError(
            f"the candidate grid would have {points:.3g} points ({grid_m:g} m over "
            f"{(xmax - xmin) / 1000:.1f} × {(ymax - ymin) / 1000:.1f} km); make the grid "
            f"coarser (--grid-m) or plan the site in parts"
        )
    xs = np.arange(math.floor(xmin / grid_m), math.ceil(xmax / grid_m) + 1) * grid_m
    ys = np.arange(math.floor(ymin / grid_m), math.ceil(ymax / grid_m) + 1) * grid_m
    gx, gy = np.meshgrid(xs, ys)
    gx, gy = gx.ravel(), gy.ravel()
    shapely.prepare(area)
    inside = shapely.contains_xy(area, gx, gy)
    return np.column_stack([gx[inside], gy[inside]])
