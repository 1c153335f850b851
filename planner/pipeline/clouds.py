"""The surfaces the stations' scans share, and the cloud-to-cloud links over them.

The model is :mod:`planner.cloud_registration`; this module finds its patches on a site:

- **facade patches**: every facade sample is a patch of ``sample_spacing_m`` ×
  ``sample_height_step_m`` on its wall, seen by a station where the evaluation says so, its
  points from the scan step and the incidence, its noise across the wall the accuracy
  model's m_y (:func:`planner.pipeline.evaluate.evaluate_stations`);
- **ground patches**: cells of :data:`GROUND_CELL_M` on open ground within
  :data:`GROUND_REACH_M` of a station that it sees over the buildings, its noise along the
  vertical from the ranging and the vertical angle at that elevation.

Obstacles other than buildings (trees, cars, street furniture) are not modelled: they add
overlap in practice, and move.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely

from planner.cloud_registration import (
    MAX_LINK_CONDITION,
    link_covariance,
    link_information,
    link_strength,
    overlap_pct,
    patch_points,
    patch_variance_mm2,
    plane_rows,
    weakest_direction,
)
from planner.pipeline.evaluate import Context, evaluate_stations
from planner.pipeline.visibility import clear_height, edges_in_box
from planner.spacing import point_spacing_mm
from planner.units import RHO_ARCSEC

__all__ = ["CloudLink", "Surfaces", "cloud_link", "overlap_matrix", "surfaces"]

#: Ground cells [m] and how far from a station its ground counts [m].
GROUND_CELL_M = 2.0
GROUND_REACH_M = 25.0


@dataclass(frozen=True)
class Surfaces:
    """Patches (P) and what K stations make of them."""

    xyz: np.ndarray  # (P, 3) patch centres [m]
    normal: np.ndarray  # (P, 3) unit normals
    points: np.ndarray  # (P, K) scan points on each patch (0: not seen)
    var_mm2: np.ndarray  # (P, K) variance of the patch's position along its normal [mm²]
    area_m2: np.ndarray  # (P,)
    station_xyz: np.ndarray  # (K, 3)

    @property
    def seen(self) -> np.ndarray:
        return self.points > 0


@dataclass(frozen=True)
class CloudLink:
    """Scan ``child`` registered to scan ``parent`` over their common patches."""

    parent: int
    child: int
    info: np.ndarray  # (6, 6) point-to-plane information at the child's centre
    cov: np.ndarray  # (6, 6) the child's pose relative to the parent (levelled: with tilt)
    overlap_pct: float
    condition: float
    patches: int

    @property
    def fixed(self) -> bool:
        return bool(np.isfinite(self.condition) and self.condition <= MAX_LINK_CONDITION)

    @property
    def weakest(self) -> str:
        return weakest_direction(self.cov)


def surfaces(ctx: Context, station_xy: np.ndarray) -> Surfaces:
    """The facade and ground patches the stations at ``station_xy`` (K, 2) see (module
    docstring)."""
    sc, st, fac = ctx.scanner, ctx.settings, ctx.facades
    k = len(station_xy)
    hi = st.instrument_height_m
    dense = evaluate_stations(ctx, station_xy)
    view = dense["view"] & np.isfinite(dense["scanner_m_y_mm"])
    area = st.sample_spacing_m * st.sample_height_step_m
    slope = np.where(view, dense["slope_distance_m"], 1.0)
    cos_inc = np.where(view, np.cos(np.radians(np.nan_to_num(dense["incidence_deg"]))), 0.0)
    f_points = np.where(
        view,
        patch_points(area, cos_inc, point_spacing_mm(slope, step_mm_at_10m=ctx.step_mm_at_10m)),
        0.0,
    )
    f_var = patch_variance_mm2(
        np.nan_to_num(dense["scanner_m_y_mm"], nan=1.0),
        np.maximum(f_points, 1.0),
        st.cloud_floor_mm,
    )
    f_xyz = np.column_stack([fac.xy, fac.z])
    f_normal = np.column_stack([fac.normal[fac.facade], np.zeros(len(fac.z))])
    g_xy = _ground_cells(ctx, station_xy)
    g_points = np.zeros((len(g_xy), k))
    g_var = np.full((len(g_xy), k), np.inf)
    for j, sxy in enumerate(station_xy):
        d = np.hypot(*(g_xy - sxy).T)
        s = np.hypot(d, hi)
        near = np.flatnonzero((d <= GROUND_REACH_M) & (s >= sc.min_range_m))
        if not len(near):
            continue
        e = ctx.edges
        box = edges_in_box(e, (*(sxy - GROUND_REACH_M), *(sxy + GROUND_REACH_M)))
        zc = clear_height(
            np.broadcast_to(sxy, (len(near), 2)), hi, g_xy[near], e[box], ctx.edge_heights[box]
        )
        near = near[zc <= 0.0]
        s_n = s[near]
        sin_e = hi / s_n
        sigma2 = (sc.range_rms_at(s_n) * sin_e) ** 2 + (
            s_n * 1000.0 * sc.tilt_rms_arcsec / RHO_ARCSEC * np.sqrt(1.0 - sin_e**2)
        ) ** 2
        pts = patch_points(
            GROUND_CELL_M**2, sin_e, point_spacing_mm(s_n, step_mm_at_10m=ctx.step_mm_at_10m)
        )
        g_points[near, j] = pts
        g_var[near, j] = patch_variance_mm2(np.sqrt(sigma2), pts, st.cloud_floor_mm)
    keep = (g_points > 0).any(axis=1)
    return Surfaces(
        xyz=np.vstack([f_xyz, np.column_stack([g_xy[keep], np.zeros(keep.sum())])]),
        normal=np.vstack([f_normal, np.tile([0.0, 0.0, 1.0], (keep.sum(), 1))]),
        points=np.vstack([f_points, g_points[keep]]),
        var_mm2=np.vstack([np.where(view, f_var, np.inf), g_var[keep]]),
        area_m2=np.concatenate([np.full(len(f_xyz), area), np.full(keep.sum(), GROUND_CELL_M**2)]),
        station_xyz=np.column_stack([station_xy, np.full(k, hi)]),
    )


def _ground_cells(ctx: Context, station_xy: np.ndarray) -> np.ndarray:
    """Centres of ground cells within reach of a station and outside the buildings."""
    if not len(station_xy):
        return np.empty((0, 2))
    lo = station_xy.min(axis=0) - GROUND_REACH_M
    hi = station_xy.max(axis=0) + GROUND_REACH_M
    xs = np.arange(lo[0], hi[0], GROUND_CELL_M) + GROUND_CELL_M / 2
    ys = np.arange(lo[1], hi[1], GROUND_CELL_M) + GROUND_CELL_M / 2
    gx, gy = np.meshgrid(xs, ys)
    xy = np.column_stack([gx.ravel(), gy.ravel()])
    near = np.zeros(len(xy), dtype=bool)
    for sxy in station_xy:
        near |= np.hypot(*(xy - sxy).T) <= GROUND_REACH_M
    xy = xy[near]
    solid = [g for _, g, _ in ctx.site.blockers]
    if solid and len(xy):
        xy = xy[~shapely.contains_xy(shapely.union_all(solid), xy[:, 0], xy[:, 1])]
    return xy


def overlap_matrix(surf: Surfaces) -> np.ndarray:
    """(K, K) overlap [%] of every pair of stations: the smaller share of either scan's
    surface that the other scan also holds (:func:`planner.cloud_registration.overlap_pct`;
    by area, as registration software counts it on clouds thinned to an even spacing)."""
    seen = surf.seen.astype(float)
    area = seen * surf.area_m2[:, None]
    total = area.sum(axis=0)
    common = area.T @ seen  # [a, b]: the surface both a and b see
    return overlap_pct(common, total[:, None], common.T, total[None, :])


def cloud_link(ctx: Context, surf: Surfaces, parent: int, child: int) -> CloudLink:
    """The cloud-to-cloud registration of scan ``child`` to scan ``parent``."""
    both = np.flatnonzero(surf.seen[:, parent] & surf.seen[:, child])
    rows = plane_rows(surf.xyz[both], surf.normal[both], surf.station_xyz[child])
    info = link_information(rows, surf.var_mm2[both, parent], surf.var_mm2[both, child])
    sc = ctx.scanner
    levelled = sc.is_levelled
    cov = link_covariance(
        info, levelled=levelled, tilt_rms_arcsec=sc.initial_tilt_rms_arcsec if levelled else 0.0
    )
    area = surf.area_m2
    common = area[both].sum()
    ov = overlap_pct(
        common, area[surf.seen[:, parent]].sum(), common, area[surf.seen[:, child]].sum()
    )
    return CloudLink(
        parent=parent,
        child=child,
        info=info,
        cov=cov,
        overlap_pct=float(ov),
        condition=link_strength(info, levelled=levelled)[0],
        patches=len(both),
    )
