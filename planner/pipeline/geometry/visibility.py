"""2.5-D line of sight: footprints with heights (buildings, obstacles) block the beam.

A sight line from a scanner centre ``(s, z_s)`` to a point above ``p`` is blocked by a
footprint of height H where it runs over the footprint below H. Since the line's height is
linear along it, checking where it crosses the footprint's edges is exact: at a crossing at
fraction t of the way, it is blocked if ``z_s + t·(z − z_s) < H``, i.e. if
``z < z_s + (H − z_s)/t``. So for a horizontal sight line the points above ``p`` are visible
from the height

    z_clear = max over crossed edges of ( z_s + (H − z_s)/t )

upwards — one number per (station, facade column), valid for every sample up the column.

A passage under a building (a gateway) leaves the floors above it as a *bridge*: a footprint
blocking only between its bottom (the passage's clear height) and its top. A crossing at
fraction t hides the heights ``z_s + (B − z_s)/t <= z < z_s + (H − z_s)/t``; a line through
a gateway crosses its two openings, and the heights hidden are those between the exit's
lower bound and the entry's upper one — below, the line passes under the floors; above,
over the roof. :func:`bridge_interval` gives that interval, the hull of every bridge
crossed (exact for one gateway, on the safe side for several).

The exact test counts a line passing a corner by a millimetre as clear; a scanner's beam is
millimetres to centimetres wide and the footprints are not known to the millimetre, and a
third-party ray-casting check on the extruded footprints found samples the 2.5-D test gave
as seen hidden by a corner or a roof edge by 1–2 mm. So every sight line keeps a clearance
of :data:`SIGHT_CLEARANCE_M`: each footprint edge is lengthened by it at both ends (a line
passing a corner closer than that is blocked) and raised by it (a crossing at fraction t
raises the clear height by ``clearance / t`` at the point); the floors over a passage are
thickened by it, below and above. ``clearance_m=0`` gives the exact geometry.

Targets set up on site are obstacles too: a sphere on its stand hides what lies behind it
from a station (a third-party ray-casting survey of planned networks found stations that
could not see a target of their link behind another target 2–12 m out).
:func:`stand_blocks` tests sight lines against spheres (radius plus the clearance) and the
stands below them (vertical poles of :data:`STAND_RADIUS_M` from the ground up to the
sphere).

The (sight line, edge) pairs are tested in a loop compiled with Numba (Lam, Pitrou &
Seibert, "Numba: a LLVM-based Python JIT compiler", LLVM-HPC 2015,
https://doi.org/10.1145/2833157.2833162): a plan tests millions of sight lines against a few
hundred edges each, and the loop skips a pair on its bounding boxes without the temporaries
a vectorised test needs (compiled once per machine and kept in the package's cache).
"""

from __future__ import annotations

import numpy as np
from numba import njit

__all__ = [
    "SIGHT_CLEARANCE_M",
    "STAND_RADIUS_M",
    "bridge_interval",
    "clear_height",
    "edges_in_box",
    "edges_in_front",
    "ends_ahead",
    "own_edges",
    "stand_blocks",
    "visible",
]

#: The clearance every sight line keeps from footprint edges, corners and roof edges [m]
#: (the module's text): about the radius of a survey scanner's beam at 50 m (0.3–0.5 mrad
#: divergence) and within the accuracy of building footprints.
SIGHT_CLEARANCE_M = 0.02

#: The stand below a sphere target, as an obstacle: a vertical pole of this radius [m] (a
#: tripod's head and tribrach; its legs spread below the heights sight lines to targets pass).
STAND_RADIUS_M = 0.05


def _kernel_array(a, dtype=np.float64) -> np.ndarray:
    """``a`` as the compiled kernels take it: C-ordered, of ``dtype``, and writable (a
    read-only array, as a broadcast height is, would make numba compile and load the kernel
    once more for that flag: three times as much to compile in a fresh clone)."""
    out = np.ascontiguousarray(a, dtype=dtype)
    return out if out.flags.writeable else out.copy()


def clear_height(
    src_xy: np.ndarray,
    src_z: np.ndarray | float,
    dst_xy: np.ndarray,
    edges: np.ndarray,
    heights: np.ndarray,
    clearance_m: float = SIGHT_CLEARANCE_M,
    groups: tuple[np.ndarray, np.ndarray] | None = None,
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
    clearance_m : float
        How far the line must pass from every edge, corner and roof edge [m] (the module's
        text; 0: the exact geometry).
    groups : (starts, boxes), optional
        The lines in G groups, group g being lines ``starts[g]:starts[g + 1]`` ((G + 1,)
        ints), each seen past only the edges whose bounding box overlaps its box
        ``boxes[g]`` = (xmin, ymin, xmax, ymax) ((G, 4); :func:`edges_in_box`): the lines of
        many scanner positions in one call, each position's edges within its reach. None:
        one group, every edge.
    """
    p = len(src_xy)
    out = np.full(p, -np.inf)
    if p == 0 or len(edges) == 0:
        return out
    if groups is None:
        starts, boxes = np.array([0, p]), np.array([[-np.inf, -np.inf, np.inf, np.inf]])
    else:
        starts, boxes = groups
        if len(starts) != len(boxes) + 1 or starts[0] != 0 or starts[-1] != p:
            raise ValueError(
                f"groups: {len(boxes)} boxes need {len(boxes) + 1} starts from 0 to the "
                f"{p} lines; got {len(starts)} from {starts[0]} to {starts[-1]}"
            )
    _clear_height_kernel(
        _kernel_array(src_xy, np.float64),
        _kernel_array(np.broadcast_to(np.asarray(src_z, dtype=np.float64), (p,))),
        _kernel_array(dst_xy, np.float64),
        _kernel_array(edges, np.float64),
        _kernel_array(heights, np.float64),
        float(clearance_m),
        _kernel_array(starts, np.int64),
        _kernel_array(boxes, np.float64),
        out,
    )
    return out


@njit(cache=True, nogil=True)
def _clear_height_kernel(src, zs, dst, edges, heights, pad, starts, boxes, out):  # pragma: no cover
    """Every (sight line, edge) pair whose boxes overlap, compiled (:func:`_crossing`),
    each edge lengthened and raised by ``pad``, a group's lines against the edges
    overlapping its box only; ``out`` holds ``-inf`` on entry."""
    m = edges.shape[0]
    ex_lo, ex_hi = np.empty(m), np.empty(m)  # each edge's box
    ey_lo, ey_hi = np.empty(m), np.empty(m)
    reach = _reach(edges, pad)
    for e in range(m):
        ex_lo[e], ex_hi[e] = min(edges[e, 0], edges[e, 2]), max(edges[e, 0], edges[e, 2])
        ey_lo[e], ey_hi[e] = min(edges[e, 1], edges[e, 3]), max(edges[e, 1], edges[e, 3])
    lo_x, hi_x = ex_lo - pad, ex_hi + pad  # and padded, for the lines
    lo_y, hi_y = ey_lo - pad, ey_hi + pad
    near = np.empty(m, dtype=np.int64)
    for g in range(boxes.shape[0]):
        if starts[g] == starts[g + 1]:
            continue  # no lines
        n_near = 0  # the edges in the group's box, as edges_in_box selects them
        for e in range(m):
            if (
                ex_hi[e] >= boxes[g, 0]
                and ex_lo[e] <= boxes[g, 2]
                and ey_hi[e] >= boxes[g, 1]
                and ey_lo[e] <= boxes[g, 3]
            ):
                near[n_near] = e
                n_near += 1
        for i in range(starts[g], starts[g + 1]):
            sx, sy, z0 = src[i, 0], src[i, 1], zs[i]
            rx, ry = dst[i, 0] - sx, dst[i, 1] - sy
            x_lo, x_hi = min(sx, dst[i, 0]), max(sx, dst[i, 0])
            y_lo, y_hi = min(sy, dst[i, 1]), max(sy, dst[i, 1])
            for q in range(n_near):
                e = near[q]
                if hi_x[e] < x_lo or lo_x[e] > x_hi or hi_y[e] < y_lo or lo_y[e] > y_hi:
                    continue
                t = _crossing(sx, sy, rx, ry, edges[e], reach[e])
                if t > 0.0:
                    out[i] = max(out[i], z0 + (heights[e] + pad - z0) / t)


@njit(cache=True, nogil=True)
def _reach(edges, pad):  # pragma: no cover - compiled
    """How far past its ends each edge reaches when lengthened by ``pad`` at both ends, as
    a fraction of its length (once per edge, not per sight line)."""
    out = np.zeros(edges.shape[0])
    if pad > 0.0:
        for e in range(edges.shape[0]):
            length = np.hypot(edges[e, 2] - edges[e, 0], edges[e, 3] - edges[e, 1])
            if length > 0.0:
                out[e] = pad / length
    return out


@njit(cache=True, nogil=True, inline="always")
def _crossing(sx, sy, rx, ry, edge, reach):  # pragma: no cover - compiled
    """Where the sight line from (sx, sy) along (rx, ry) crosses ``edge`` (x0, y0, x1, y1)
    lengthened at both ends by ``reach`` of its length (:func:`_reach`): the fraction
    ``t`` of the way when ``0 < t < 1`` and the crossing lies on it
    (``-reach <= u <= 1 + reach``); ``-1`` when it does not cross (parallel pairs do not)."""
    qx, qy = edge[2] - edge[0], edge[3] - edge[1]
    wx, wy = edge[0] - sx, edge[1] - sy
    den = rx * qy - ry * qx
    if den == 0.0:
        return -1.0
    t = (wx * qy - wy * qx) / den
    u = (wx * ry - wy * rx) / den
    if 1e-9 < t < 1.0 - 1e-9 and -reach <= u <= 1.0 + reach:
        return t
    return -1.0


def bridge_interval(
    src_xy: np.ndarray,
    src_z: np.ndarray | float,
    dst_xy: np.ndarray,
    edges: np.ndarray,
    bottoms: np.ndarray,
    tops: np.ndarray,
    clearance_m: float = SIGHT_CLEARANCE_M,
) -> tuple[np.ndarray, np.ndarray]:
    """The heights ``[lo, up)`` [m] above ``dst_xy`` that the floors over passages hide
    from each source (the module's text); ``lo = inf, up = -inf`` where none is crossed.
    ``edges`` are the bridges' ring edges, ``bottoms`` and ``tops`` their heights, each
    widened by ``clearance_m`` as :func:`clear_height` does."""
    p = len(src_xy)
    lo, up = np.full(p, np.inf), np.full(p, -np.inf)
    if p == 0 or len(edges) == 0:
        return lo, up
    _bridge_kernel(
        _kernel_array(src_xy, np.float64),
        _kernel_array(np.broadcast_to(np.asarray(src_z, dtype=np.float64), (p,))),
        _kernel_array(dst_xy, np.float64),
        _kernel_array(edges, np.float64),
        _kernel_array(bottoms, np.float64),
        _kernel_array(tops, np.float64),
        float(clearance_m),
        lo,
        up,
    )
    return lo, up


@njit(cache=True, nogil=True)
def _bridge_kernel(src, zs, dst, edges, bottoms, tops, pad, lo, up):  # pragma: no cover
    """Every (sight line, bridge edge) crossing, as in :func:`_clear_height_kernel`: the
    interval it hides widens ``[lo, up)``."""
    reach = _reach(edges, pad)
    for i in range(src.shape[0]):
        sx, sy, z0 = src[i, 0], src[i, 1], zs[i]
        rx, ry = dst[i, 0] - sx, dst[i, 1] - sy
        for e in range(edges.shape[0]):
            t = _crossing(sx, sy, rx, ry, edges[e], reach[e])
            if t > 0.0:
                lo[i] = min(lo[i], z0 + (bottoms[e] - pad - z0) / t)
                up[i] = max(up[i], z0 + (tops[e] + pad - z0) / t)


def visible(
    z: np.ndarray, zc: np.ndarray, lo: np.ndarray | None = None, up: np.ndarray | None = None
) -> np.ndarray:
    """Whether heights ``z`` are seen: at or above the clear height ``zc``
    (:func:`clear_height`) and not in a bridge's hidden interval ``[lo, up)``
    (:func:`bridge_interval`; none when not given). Broadcasts."""
    out = z >= zc - 1e-9
    if lo is not None:
        out &= ~((z >= lo) & (z < up))
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
    of the facade line (through ``point``, outward ``normal``) and overlapping ``bbox`` (a
    merged facade's own edges are in front of it too: :func:`own_edges`)."""
    d0, d1 = ends_ahead(edges, point, normal)
    return edges_in_box(edges, bbox) & (np.maximum(d0, d1) > 1e-6)


def own_edges(
    edges: np.ndarray, point: np.ndarray, normal: np.ndarray, end: np.ndarray, band_m: float
) -> np.ndarray:
    """Mask of the edges a facade from ``point`` to ``end`` (outward ``normal``) stands for:
    both ends within ``band_m`` in front of its line and within its length. A facade merged
    from nearly collinear edges (a curved wall drawn as many short edges,
    :func:`~planner.pipeline.geometry.facades.build_facades`) is sampled on its chord, up to
    ``band_m`` behind them: they are the facade itself, not a wall in front of it (so is any
    edge that close, e.g. an obstacle drawn against the wall: within a footprint's accuracy)."""
    d0, d1 = ends_ahead(edges, point, normal)
    along = np.asarray(end, dtype=float)[:2] - np.asarray(point, dtype=float)[:2]
    length = float(np.hypot(*along))
    if length == 0.0:
        return np.zeros(len(edges), dtype=bool)
    t = along / length
    u0 = (edges[:, 0] - point[0]) * t[0] + (edges[:, 1] - point[1]) * t[1]
    u1 = (edges[:, 2] - point[0]) * t[0] + (edges[:, 3] - point[1]) * t[1]
    tol = 1e-6
    return (
        (np.minimum(d0, d1) >= -tol)
        & (np.maximum(d0, d1) <= band_m + tol)
        & (np.minimum(u0, u1) >= -tol)
        & (np.maximum(u0, u1) <= length + tol)
    )


def ends_ahead(edges: np.ndarray, point: np.ndarray, normal: np.ndarray) -> tuple[np.ndarray, ...]:
    """How far each edge's two ends stand in front of the line through ``point`` [m]."""
    d0 = (edges[:, 0] - point[0]) * normal[0] + (edges[:, 1] - point[1]) * normal[1]
    d1 = (edges[:, 2] - point[0]) * normal[0] + (edges[:, 3] - point[1]) * normal[1]
    return d0, d1


def stand_blocks(
    src_xyz: np.ndarray,
    dst_xyz: np.ndarray,
    centre_xyz: np.ndarray,
    radius_m: np.ndarray | float,
    *,
    stand_radius_m: float = STAND_RADIUS_M,
    clearance_m: float = SIGHT_CLEARANCE_M,
) -> np.ndarray:
    """(N, M) mask: whether sight line n (``src_xyz`` → ``dst_xyz``, (N, 3) [m], heights in
    the site's height system) is blocked by sphere target m (centre ``centre_xyz`` (M, 3), radius
    ``radius_m``, one or (M,)) or its stand (module text). Only an obstacle between the
    ends blocks: one beside or behind the target or the station does not; the caller leaves
    a target out of its own line's obstacles."""
    ends = np.broadcast_arrays(
        np.asarray(src_xyz, float).reshape(-1, 3), np.asarray(dst_xyz, float).reshape(-1, 3)
    )
    src, dst = (_kernel_array(e) for e in ends)
    centre = _kernel_array(centre_xyz).reshape(-1, 3)
    radius = _kernel_array(np.broadcast_to(np.asarray(radius_m, dtype=float), len(centre)))
    out = np.empty((len(src), len(centre)), dtype=np.bool_)
    _stand_blocks_kernel(src, dst, centre, radius, float(stand_radius_m), float(clearance_m), out)
    return out


@njit(cache=True, nogil=True, error_model="numpy")
def _stand_blocks_kernel(src, dst, centre, radius, stand_r, clearance, out):  # pragma: no cover
    """:func:`stand_blocks`, compiled: each (line, sphere) pair in a loop, without the
    (N, M, 3) temporaries; the same products and sums in the same order as NumPy's."""
    for n in range(src.shape[0]):
        px, py, pz = src[n, 0], src[n, 1], src[n, 2]
        vx, vy, vz = dst[n, 0] - px, dst[n, 1] - py, dst[n, 2] - pz
        vv = vx * vx + vy * vy + vz * vz
        vh = vx * vx + vy * vy
        for m in range(centre.shape[0]):
            wx, wy, wz = centre[m, 0] - px, centre[m, 1] - py, centre[m, 2] - pz
            r = radius[m]
            # the sphere: the line's closest approach in 3-D
            t3 = (wx * vx + wy * vy + wz * vz) / vv
            ex, ey, ez = wx - t3 * vx, wy - t3 * vy, wz - t3 * vz
            d3 = np.sqrt(ex * ex + ey * ey + ez * ez)
            sphere = t3 > 0 and t3 < 1 and d3 < r + clearance
            # the stand: the closest approach seen from above, and the line's height there
            t2 = (wx * vx + wy * vy) / vh
            fx, fy = wx - t2 * vx, wy - t2 * vy
            d2 = np.sqrt(fx * fx + fy * fy)
            z = pz + t2 * vz
            stand = (
                t2 > 0 and t2 < 1 and d2 < stand_r + clearance and z < centre[m, 2] - r + clearance
            )
            out[n, m] = sphere or stand
