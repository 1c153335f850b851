"""An independent point-to-plane ICP for the rehearsal's clouds (tests and benchmarks).

It shares no code with the planner's cloud-link model (``planner.cloud_registration``):
the parent's normals and local planes come from its own points (PCA of the 12 nearest;
neighbourhoods that are not planar are left out), each child point is matched to its
nearest parent point within a distance, the residual taken to that point's local plane,
correspondences beyond 4 robust standard deviations (0.1 mm at least) dropped (but while it
matches coarsely: then every match within its distance counts, as Open3D's ICP counts
them), and the 6 parameters (shift [mm], rotation [rad] about the child's centre) found
by Gauss–Newton.

:func:`link_errors` registers a rehearsed pair of scans trial after trial (each with its
own noise) and returns the estimated poses' errors; :func:`patches_of` keeps of each scan
what the link model counts: the walls, and the ground within reach of both stations.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from planner.pipeline.network.clouds import GROUND_REACH_M
from planner.pipeline.survey.rehearsal import POINT_KINDS, rehearse

NEIGHBOURS = 12
PLANAR = 0.02  # smallest eigenvalue over the sum: a planar neighbourhood
MATCH_M = 0.15
TRIM_FLOOR_M = 1e-4


def _skew(w: np.ndarray) -> np.ndarray:
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def icp(
    parent: np.ndarray,
    child: np.ndarray,
    centre: np.ndarray,
    iters: int = 8,
    coarse_m: float | None = None,
) -> np.ndarray:
    """The correction (6,) that registers the child: shift [mm], small rotation [rad]
    about ``centre``. ``coarse_m``: the first half of the iterations match within that
    distance [m] (coarse to fine), the rest within :data:`MATCH_M`."""
    tree = cKDTree(parent)
    _, nb = tree.query(parent, NEIGHBOURS)
    local = parent[nb] - parent[nb].mean(axis=1, keepdims=True)
    w, v = np.linalg.eigh(np.einsum("pki,pkj->pij", local, local))
    normal, planar = v[:, :, 0], w[:, 0] < PLANAR * w.sum(axis=1)
    plane_at = parent[nb].mean(axis=1)
    pose = np.zeros(6)  # shift [m], rotation [rad]
    for it in range(iters):
        match = coarse_m if coarse_m is not None and it < iters // 2 else MATCH_M
        moved = centre + (child - centre) @ (np.eye(3) + _skew(pose[3:])).T + pose[:3]
        d, j = tree.query(moved, distance_upper_bound=match)
        ok = np.isfinite(d)
        ok[ok] = planar[j[ok]]
        n, m = normal[j[ok]], moved[ok]
        res = np.einsum("ij,ij->i", m - plane_at[j[ok]], n)
        # fine: trimmed beyond 4 robust σ, never below TRIM_FLOOR_M (noise-free clouds:
        # rounding); coarse: every match within its distance (as Open3D's ICP)
        keep = np.abs(res) <= max(4 * 1.4826 * np.median(np.abs(res)), TRIM_FLOOR_M)
        if match > MATCH_M:
            keep[:] = True
        a = np.hstack([n, np.cross(m - centre, n)])[keep]
        pose += np.linalg.lstsq(a, -res[keep], rcond=None)[0]
    return np.concatenate([pose[:3] * 1000.0, pose[3:]])


def patches_of(scan, other_position: np.ndarray) -> np.ndarray:
    """Which of a scan's points the link model counts: walls, and the ground within
    :data:`GROUND_REACH_M` of both stations."""
    xy = scan.world_xyz[:, :2]
    wall = scan.kind == POINT_KINDS.index("wall")
    ground = scan.kind == POINT_KINDS.index("terrain")
    near = (np.hypot(*(xy - scan.position[:2]).T) <= GROUND_REACH_M) & (
        np.hypot(*(xy - other_position[:2]).T) <= GROUND_REACH_M
    )
    return wall | (ground & near)


def thin(points: np.ndarray, spacing_m: float) -> np.ndarray:
    """The cloud thinned to an even spacing, as registration software thins it: the mean of
    the points in each cube of ``spacing_m`` (none: ``spacing_m`` ≤ 1 mm)."""
    if spacing_m <= 0.001:
        return points
    cell = np.floor((points - points.min(axis=0)) / spacing_m).astype(np.int64)
    key = (cell[:, 0] << 42) | (cell[:, 1] << 21) | cell[:, 2]  # one integer per cube
    _, inverse, counts = np.unique(key, return_inverse=True, return_counts=True)
    sums = np.column_stack([np.bincount(inverse, weights=points[:, k]) for k in range(3)])
    return sums / counts[:, None]


def link_errors(plan, parent: str, child: str, trials: int, *, noise: bool = True) -> np.ndarray:
    """(trials, 6) errors of the child's pose registered to the parent's by :func:`icp`,
    each trial a new rehearsal of the two scans (seed 100 + trial) at the plan's step, the
    clouds thinned to the plan's registration spacing (:func:`thin`)."""
    out = np.empty((trials, 6))
    spacing = plan.settings.cloud_spacing_mm / 1000.0
    for k in range(trials):
        r = rehearse(
            plan, beams_per_station=10**8, seed=100 + k, stations=[parent, child], noise=noise
        )
        by = {s.station_id: s for s in r.scans}
        a, b = by[parent], by[child]
        pa, pb = patches_of(a, b.position), patches_of(b, a.position)
        out[k] = icp(thin(a.world_xyz[pa], spacing), thin(b.world_xyz[pb], spacing), b.position)
    return out
