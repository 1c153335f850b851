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

#: Upper bound on (sight line, edge) pairs handled at once, to bound memory (~10 arrays of it).
MAX_ELEMENTS = 2_000_000

#: Side of the square cells [m] that group sight lines by where they start and end: a group
#: is tested only against the edges near the segment between its two cells' centres.
CELL_M = 8.0


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
    line, edge = _near_pairs(src_xy, dst_xy, edges)
    for lo in range(0, len(line), MAX_ELEMENTS):
        li, ei = line[lo : lo + MAX_ELEMENTS], edge[lo : lo + MAX_ELEMENTS]
        sx, sy = src_xy[li, 0], src_xy[li, 1]
        rx, ry = dst_xy[li, 0] - sx, dst_xy[li, 1] - sy
        e = edges[ei]
        qx, qy = e[:, 2] - e[:, 0], e[:, 3] - e[:, 1]
        wx, wy = e[:, 0] - sx, e[:, 1] - sy
        den = rx * qy - ry * qx
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (wx * qy - wy * qx) / den
            u = (wx * ry - wy * rx) / den
            hit = (t > 1e-9) & (t < 1.0 - 1e-9) & (u >= 0.0) & (u <= 1.0)
            z0 = zs[li[hit]]
            np.maximum.at(out, li[hit], z0 + (heights[ei[hit]] - z0) / t[hit])
    return out


def _near_pairs(
    src_xy: np.ndarray, dst_xy: np.ndarray, edges: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """(line, edge) index pairs, by line, that can cross: the lines grouped by the cells
    (:data:`CELL_M`) of their two ends; a group's lines lie within the cell's half diagonal
    ``r`` of the segment between the cells' centres, so an edge farther than that from it —
    outside its box grown by ``r``, or wholly on one side of its strip of half-width ``r`` —
    crosses none of them."""
    cells = np.floor(np.column_stack([src_xy, dst_xy]) / CELL_M).astype(np.int64)
    cells -= cells.min(axis=0)
    span = cells.max(axis=0) + 1
    key = ((cells[:, 0] * span[1] + cells[:, 1]) * span[2] + cells[:, 2]) * span[3] + cells[:, 3]
    first_line, group = np.unique(key, return_index=True, return_inverse=True)[1:]
    ends = (np.floor(np.column_stack([src_xy, dst_xy])[first_line] / CELL_M) + 0.5) * CELL_M
    a, b = ends[:, 0:2], ends[:, 2:4]
    r = CELL_M * np.sqrt(0.5) + 1e-6
    lo, hi = np.minimum(a, b) - r, np.maximum(a, b) + r
    near = (
        (np.maximum(edges[:, 0], edges[:, 2]) >= lo[:, 0:1])
        & (np.minimum(edges[:, 0], edges[:, 2]) <= hi[:, 0:1])
        & (np.maximum(edges[:, 1], edges[:, 3]) >= lo[:, 1:2])
        & (np.minimum(edges[:, 1], edges[:, 3]) <= hi[:, 1:2])
    )
    d = b - a
    length = np.hypot(d[:, 0], d[:, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        nx, ny = -d[:, 1:2] / length[:, None], d[:, 0:1] / length[:, None]
    side0 = (edges[:, 0] - a[:, 0:1]) * nx + (edges[:, 1] - a[:, 1:2]) * ny
    side1 = (edges[:, 2] - a[:, 0:1]) * nx + (edges[:, 3] - a[:, 1:2]) * ny
    apart = ((side0 > r) & (side1 > r)) | ((side0 < -r) & (side1 < -r))
    near &= ~apart | (length[:, None] == 0)
    g_of, e_of = np.nonzero(near)  # by group
    count = np.bincount(g_of, minlength=len(a))
    first = np.concatenate([[0], np.cumsum(count)[:-1]])
    n = count[group]  # edges per line
    line = np.repeat(np.arange(len(group)), n)
    within = np.arange(len(line)) - np.repeat(np.cumsum(n) - n, n)
    return line, e_of[np.repeat(first[group], n) + within]


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
