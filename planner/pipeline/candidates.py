"""Candidate station positions: a grid over the free ground within reach of the facades."""

from __future__ import annotations

import math

import numpy as np
import shapely

from planner.errors import InputError
from planner.pipeline.facades import FacadeSet
from planner.site import Site

__all__ = ["MAX_GRID_POINTS", "blocked_ground", "candidate_grid"]

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
