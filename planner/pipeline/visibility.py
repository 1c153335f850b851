"""2.5-D line of sight: footprints with heights (buildings, obstacles) block the beam.

A sight line from a scanner centre ``(s, z_s)`` to a point above ``p`` is blocked by a
footprint of height H where it runs over the footprint below H. Since the line's height is
linear along it, checking where it crosses the footprint's edges is exact: at a crossing at
fraction t of the way, it is blocked if ``z_s + t·(z − z_s) < H``, i.e. if
``z < z_s + (H − z_s)/t``. So for a horizontal sight line the points above ``p`` are visible
from the height

    z_clear = max over crossed edges of ( z_s + (H − z_s)/t )

upwards — one number per (station, facade column), valid for every sample up the column.
"""

from __future__ import annotations

import numpy as np

__all__ = ["clear_height", "edges_in_box", "edges_in_front"]

#: Upper bound on (sight lines × edges) handled at once, to bound memory (~10 arrays of it).
MAX_ELEMENTS = 2_000_000


def clear_height(
    src_xy: np.ndarray,
    src_z: np.ndarray | float,
    dst_xy: np.ndarray,
    edges: np.ndarray,
    heights: np.ndarray,
) -> np.ndarray:
    """Lowest height [m] above ``dst_xy`` visible from each source; ``-inf`` if unobstructed.

    Parameters
    ----------
    src_xy, dst_xy : (P, 2) arrays
        Ends of P horizontal sight lines (scanner position, facade column / target).
    src_z : float or (P,) array
        Height of the scanner centre [m].
    edges : (M, 4) array
        Blocking footprint edges ``x0, y0, x1, y1``.
    heights : (M,) array
        Height of the footprint each edge belongs to [m].
    """
    p = len(src_xy)
    out = np.full(p, -np.inf)
    if p == 0 or len(edges) == 0:
        return out
    zs = np.broadcast_to(np.asarray(src_z, dtype=float), (p,))
    ax, ay = edges[:, 0], edges[:, 1]
    qx, qy = edges[:, 2] - ax, edges[:, 3] - ay
    step = max(1, MAX_ELEMENTS // len(edges))
    for lo in range(0, p, step):
        hi = min(p, lo + step)
        sx, sy = src_xy[lo:hi, 0:1], src_xy[lo:hi, 1:2]
        rx, ry = dst_xy[lo:hi, 0:1] - sx, dst_xy[lo:hi, 1:2] - sy
        den = rx * qy - ry * qx
        wx, wy = ax - sx, ay - sy
        with np.errstate(divide="ignore", invalid="ignore"):
            inv = 1.0 / den
            t = (wx * qy - wy * qx) * inv
            u = (wx * ry - wy * rx) * inv
            hit = (t > 1e-9) & (t < 1.0 - 1e-9) & (u >= 0.0) & (u <= 1.0)
            z0 = zs[lo:hi, None]
            need = np.where(hit, z0 + (heights - z0) / t, -np.inf)
        out[lo:hi] = need.max(axis=1)
    return out


def edges_in_box(edges: np.ndarray, bbox: tuple[float, float, float, float]) -> np.ndarray:
    """Mask of edges ``(M, 4)`` whose bounding box overlaps ``bbox`` = (xmin, ymin, xmax, ymax)."""
    xmin, ymin, xmax, ymax = bbox
    return (
        (np.maximum(edges[:, 0], edges[:, 2]) >= xmin)
        & (np.minimum(edges[:, 0], edges[:, 2]) <= xmax)
        & (np.maximum(edges[:, 1], edges[:, 3]) >= ymin)
        & (np.minimum(edges[:, 1], edges[:, 3]) <= ymax)
    )


def edges_in_front(
    edges: np.ndarray,
    point: np.ndarray,
    normal: np.ndarray,
    bbox: tuple[float, float, float, float],
) -> np.ndarray:
    """Mask of edges that can block a sight line ending on a facade: an end strictly in front
    of the facade line (through ``point``, outward ``normal``) and overlapping ``bbox``."""
    d0 = (edges[:, 0] - point[0]) * normal[0] + (edges[:, 1] - point[1]) * normal[1]
    d1 = (edges[:, 2] - point[0]) * normal[0] + (edges[:, 3] - point[1]) * normal[1]
    return edges_in_box(edges, bbox) & (np.maximum(d0, d1) > 1e-6)
