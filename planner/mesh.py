"""Planar polygons in 3-D and the triangles a ray engine casts against.

Pure geometry, vectorised where it counts: the plane of a polygon (Newell's normal), its
triangles (ear clipping of the polygon projected onto its plane, holes included, by the
``mapbox-earcut`` binding of Mapbox's earcut), footprints extruded to prisms, and the crowns
and trunks of trees. Coordinates are metres in the site's CRS and height system.

>>> square = np.array([[0, 0, 0], [4, 0, 0], [4, 0, 3], [0, 0, 3]], float)
>>> newell_normal(square).round(3).tolist()  # counter-clockwise seen from -y: faces -y
[0.0, -1.0, 0.0]
>>> triangulate([square]).shape
(2, 3, 3)
>>> float(triangle_areas(triangulate([square])).sum())
12.0
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

import mapbox_earcut
import numpy as np
import shapely

__all__ = [
    "cap",
    "clean_ring",
    "crown_triangles",
    "extrude",
    "newell_normal",
    "plane_axes",
    "triangle_areas",
    "triangle_normals",
    "triangulate",
]

#: Vertices of a ring closer than this are one vertex [m].
SAME_POINT_M = 1e-4


def clean_ring(ring: np.ndarray) -> np.ndarray:
    """``ring`` (n, 3) without its closing vertex and without repeated consecutive vertices.

    >>> clean_ring(np.array([[0, 0, 0], [1, 0, 0], [1, 0, 0], [1, 1, 0], [0, 0, 0]])).shape
    (3, 3)
    """
    r = np.asarray(ring, dtype=float).reshape(-1, 3)
    if len(r) > 1 and np.linalg.norm(r[-1] - r[0]) < SAME_POINT_M:
        r = r[:-1]
    if len(r) < 2:
        return r
    step = np.linalg.norm(np.diff(np.vstack([r, r[:1]]), axis=0), axis=1)
    return r[step >= SAME_POINT_M] if (step < SAME_POINT_M).any() else r


def newell_normal(ring: np.ndarray) -> np.ndarray:
    """The unit normal of a planar ring (n, 3) by Newell's method (the right-hand rule:
    counter-clockwise seen from the side it points to); zeros for a degenerate ring.
    Newell's method is exact for planar rings and the best-fitting normal of nearly planar
    ones (Sutherland, Sproull & Schumacker, "A characterization of ten hidden-surface
    algorithms", ACM Computing Surveys 6(1), 1974, https://doi.org/10.1145/356625.356626)."""
    r = np.asarray(ring, dtype=float)
    c = r - r.mean(axis=0)  # centred: no loss of digits to large coordinates
    nxt = np.roll(c, -1, axis=0)
    n = np.array(
        [
            np.sum((c[:, 1] - nxt[:, 1]) * (c[:, 2] + nxt[:, 2])),
            np.sum((c[:, 2] - nxt[:, 2]) * (c[:, 0] + nxt[:, 0])),
            np.sum((c[:, 0] - nxt[:, 0]) * (c[:, 1] + nxt[:, 1])),
        ]
    )
    length = np.linalg.norm(n)
    return n / length if length > 1e-12 else np.zeros(3)


def plane_axes(normal: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit axes spanning the plane of ``normal`` with ``(e1, e2, normal)`` right-handed:
    for a wall (a normal not near vertical) ``e1`` is horizontal, along the wall (the
    outward normal on its right, as the planner's facades run) and ``e2`` points up the
    wall; for a near-horizontal plane ``e1`` is east.

    >>> e1, e2 = plane_axes(np.array([0.0, -1.0, 0.0]))
    >>> e1.tolist(), e2.tolist()  # a wall facing south runs east
    ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0])
    """
    n = np.asarray(normal, dtype=float)
    horizontal = np.hypot(n[0], n[1])
    if horizontal > 1e-6:
        e1 = np.array([-n[1], n[0], 0.0]) / horizontal
    else:
        e1 = np.array([1.0, 0.0, 0.0])
    e2 = np.cross(n, e1)
    return e1 + 0.0, e2 / np.linalg.norm(e2) + 0.0  # (+ 0.0: no negative zeros)


#: A ring of more vertices than this is thinned before it is ear-clipped (ear clipping takes
#: time growing with the square of a ring's vertices where many lie in line: a wall drawn
#: with 500 000 vertices took minutes) …
THIN_ABOVE = 200
#: … dropping the vertices within this of the line through the ones kept (Douglas–Peucker
#: in the polygon's plane; every vertex kept is one of the ring's) [m].
THIN_TOLERANCE_M = 0.001


def thinned(uv: np.ndarray) -> np.ndarray:
    """The indices of the vertices of a ring ``uv`` (n, 2) kept by Douglas–Peucker within
    :data:`THIN_TOLERANCE_M` (all of them for a ring of :data:`THIN_ABOVE` or fewer), in
    order; at least three.

    >>> t = np.linspace(0.0, 1.0, 300, endpoint=False)
    >>> square = np.vstack([np.column_stack([t, 0 * t]), np.column_stack([1 + 0 * t, t]),
    ...                     np.column_stack([1 - t, 1 + 0 * t]), np.column_stack([0 * t, 1 - t])])
    >>> thinned(square).tolist()
    [0, 300, 600, 900]
    """
    if len(uv) <= THIN_ABOVE:
        return np.arange(len(uv))
    kept = shapely.get_coordinates(
        shapely.simplify(shapely.linearrings(uv), THIN_TOLERANCE_M, preserve_topology=False)
    )
    where = {tuple(p): k for k, p in enumerate(uv.tolist())}
    idx = sorted({where[tuple(p)] for p in kept.tolist() if tuple(p) in where})
    return np.asarray(idx) if len(idx) >= 3 else np.arange(len(uv))


def _in_plane(rings: Sequence[np.ndarray]) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """A planar polygon's rings cleaned (:func:`clean_ring`; holes of fewer than three
    vertices dropped) and each projected onto the polygon's plane (n, 2); both empty for a
    degenerate polygon."""
    clean = [clean_ring(r) for r in rings]
    if not clean or len(clean[0]) < 3:
        return [], []
    normal = newell_normal(clean[0])
    if not normal.any():
        return [], []
    clean = [clean[0], *(r for r in clean[1:] if len(r) >= 3)]
    e1, e2 = plane_axes(normal)
    origin = clean[0][0]
    return clean, [np.column_stack([(r - origin) @ e1, (r - origin) @ e2]) for r in clean]


def thin_rings(rings: Sequence[np.ndarray]) -> tuple[np.ndarray, ...]:
    """A planar polygon's rings, each of more than :data:`THIN_ABOVE` vertices thinned in
    the polygon's plane (:func:`thinned`: the vertices within a millimetre of the line
    through those kept dropped); the rings as they are where none is that long, or the
    polygon is degenerate. A wall drawn with 500 000 vertices in line keeps its four
    corners: every use of it (triangles, outlines, drawings) is as quick as for four."""
    if all(len(r) <= THIN_ABOVE for r in rings):
        return tuple(rings)
    clean, flat = _in_plane(rings)
    if not clean:
        return tuple(rings)
    return tuple(r[thinned(f)] for r, f in zip(clean, flat, strict=True))


def triangulate(rings: Sequence[np.ndarray]) -> np.ndarray:
    """Triangles (T, 3, 3) of a planar polygon given as rings (exterior first, then holes;
    each (n, 3), closed or not), projected onto its plane and ear-clipped; empty for a
    degenerate polygon. A ring of many vertices is thinned first (:func:`thinned`)."""
    clean, flat = _in_plane(rings)
    if not clean:
        return np.empty((0, 3, 3))
    keep = [thinned(f) for f in flat]
    pts = np.vstack([r[k] for r, k in zip(clean, keep, strict=True)])
    uv = np.vstack([f[k] for f, k in zip(flat, keep, strict=True)])
    ends = np.cumsum([len(k) for k in keep]).astype(np.uint32)
    idx = mapbox_earcut.triangulate_float64(uv, ends)
    return pts[idx.reshape(-1, 3)]


def triangle_normals(tri: np.ndarray) -> np.ndarray:
    """Unit normals (T, 3) of triangles (T, 3, 3), by the right-hand rule (zeros where a
    triangle is degenerate)."""
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return np.divide(n, length, out=np.zeros_like(n), where=length > 0)


def triangle_areas(tri: np.ndarray) -> np.ndarray:
    """Areas (T,) of triangles (T, 3, 3) [m²]."""
    return 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)


def cap(polygon, z: float) -> np.ndarray:
    """A footprint (shapely Polygon or MultiPolygon, holes included) as a flat face at
    height ``z`` [m]: triangles (T, 3, 3) facing up.

    >>> cap(shapely.box(0, 0, 2, 1), 5.0).shape
    (2, 3, 3)
    """
    out = [np.empty((0, 3, 3))]
    for poly in shapely.get_parts(shapely.orient_polygons(polygon)):
        rings = [np.asarray(r.coords)[:, :2] for r in [poly.exterior, *poly.interiors]]
        out.append(triangulate([np.column_stack([r, np.full(len(r), z)]) for r in rings]))
    return np.concatenate(out)


def extrude(polygon, z0: float, z1: float, *, top: bool = True, bottom: bool = True) -> np.ndarray:
    """A footprint (shapely Polygon or MultiPolygon, holes included) as a prism from height
    ``z0`` to ``z1`` [m]: triangles (T, 3, 3) of its walls, then where asked its top, then
    its bottom, every one facing out.

    >>> extrude(shapely.box(0, 0, 2, 1), 0.0, 3.0).shape  # 4 walls, top and bottom
    (12, 3, 3)
    """
    out = [np.empty((0, 3, 3))]
    for poly in shapely.get_parts(shapely.orient_polygons(polygon)):
        # exterior counter-clockwise, holes clockwise: outward is on each edge's right
        for ring in [poly.exterior, *poly.interiors]:
            xy = np.asarray(ring.coords)[:, :2]
            lo_a = np.column_stack([xy[:-1], np.full(len(xy) - 1, z0)])
            lo_b = np.column_stack([xy[1:], np.full(len(xy) - 1, z0)])
            hi_a, hi_b = lo_a.copy(), lo_b.copy()
            hi_a[:, 2] = hi_b[:, 2] = z1
            out.append(np.stack([lo_a, lo_b, hi_b], axis=1))
            out.append(np.stack([lo_a, hi_b, hi_a], axis=1))
    if top:
        out.append(cap(polygon, z1))
    if bottom:
        out.append(cap(polygon, z0)[:, ::-1])
    return np.concatenate(out)


def crown_triangles(
    xy: tuple[float, float], radius_m: float, z_lo: float, z_hi: float, *, sides: int = 8
) -> np.ndarray:
    """A tree's crown as a closed polyhedron (T, 3, 3): an ellipsoid of horizontal radius
    ``radius_m`` between heights ``z_lo`` and ``z_hi`` [m], in ``sides`` around and four
    bands up, its widest band inscribed in the crown's circle.

    >>> crown_triangles((0.0, 0.0), 3.0, 4.0, 10.0).shape
    (48, 3, 3)
    """
    az = np.linspace(0.0, 2.0 * np.pi, sides, endpoint=False)
    half = (z_hi - z_lo) / 2.0
    mid = z_lo + half
    bands = [np.array([[xy[0], xy[1], z_lo]])]
    for el in (-np.pi / 4, 0.0, np.pi / 4):
        r, z = radius_m * np.cos(el), mid + half * np.sin(el)
        bands.append(np.column_stack([xy[0] + r * np.cos(az), xy[1] + r * np.sin(az), [z] * sides]))
    bands.append(np.array([[xy[0], xy[1], z_hi]]))
    tri = []
    nxt = np.roll(np.arange(sides), -1)
    k = np.arange(sides)
    tri.append(np.stack([np.repeat(bands[0], sides, 0), bands[1][nxt], bands[1][k]], axis=1))
    for lo, hi in itertools.pairwise(bands[1:4]):
        tri.append(np.stack([lo[k], lo[nxt], hi[nxt]], axis=1))
        tri.append(np.stack([lo[k], hi[nxt], hi[k]], axis=1))
    tri.append(np.stack([bands[3][k], bands[3][nxt], np.repeat(bands[4], sides, 0)], axis=1))
    return np.concatenate(tri)
