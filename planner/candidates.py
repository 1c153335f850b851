"""Candidate station positions: a grid over the free ground within reach of the facades."""

from __future__ import annotations

import math

import numpy as np
import shapely

from planner.facades import FacadeSet
from planner.requirements import Requirements
from planner.scanner import Scanner
from planner.site import Site
from planner.units import RHO_ARCSEC

__all__ = ["blocked_ground", "candidate_grid", "reach_m"]

#: Below this, the accuracy bound is not used to shrink the search: even an infeasible
#: requirement gets candidates close by, so the plan can say what is achievable [m].
MIN_SEARCH_RADIUS_M = 25.0


def reach_m(scanner: Scanner, req: Requirements, station_rms_mm: tuple[float, float]) -> float:
    """Largest horizontal distance [m] at which a station can meet the requirements.

    From eq. 2, ``m_x² + m_y² = m_xc² + m_yc² + m_S² + (D·m_β/ρ)²`` whatever γ, so
    ``D <= ρ/m_β · √(T_x² + T_y² − m_xc² − m_yc² − a²)``; from eq. 4 with S_0 = S,
    ``m_z >= S·m_ν0/ρ``, so ``S <= ρ·T_z/m_ν0``. Also the scanner's and the requirement's
    maximum range. Never below :data:`MIN_SEARCH_RADIUS_M` (within the range limits).
    """
    budget = req.max_x_mm**2 + req.max_y_mm**2 - sum(v * v for v in station_rms_mm)
    budget -= scanner.range_rms_mm**2
    d_xy = RHO_ARCSEC / scanner.angle_rms_arcsec * math.sqrt(max(budget, 0.0)) / 1000.0
    m_nu0 = scanner.levelling_rms_arcsec or scanner.tilt_rms_arcsec
    d_z = RHO_ARCSEC * req.max_z_mm / m_nu0 / 1000.0
    limit = min(scanner.max_range_m, req.max_range_m or math.inf)
    return min(limit, max(min(d_xy, d_z), MIN_SEARCH_RADIUS_M))


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
    xs = np.arange(math.floor(xmin / grid_m), math.ceil(xmax / grid_m) + 1) * grid_m
    ys = np.arange(math.floor(ymin / grid_m), math.ceil(ymax / grid_m) + 1) * grid_m
    gx, gy = np.meshgrid(xs, ys)
    gx, gy = gx.ravel(), gy.ravel()
    shapely.prepare(area)
    inside = shapely.contains_xy(area, gx, gy)
    return np.column_stack([gx[inside], gy[inside]])
