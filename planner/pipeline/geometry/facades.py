"""Facades of the planned buildings, and the sample points on them.

Every exterior and interior (courtyard) ring edge of a planned building is a facade, after
merging consecutive edges that are nearly collinear (a facade digitised as many short
pieces). Facade frame: x along the facade, y along the outward normal, z up.
Samples sit at the centres of a grid of cells along the facade and up its height.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import shapely
import shapely.affinity

from planner.errors import InputError
from planner.pipeline.geometry.scene import Scene
from planner.site import Site

__all__ = [
    "FacadeSet",
    "build_facades",
    "check_sample_count",
    "estimate_samples",
    "in_opening",
    "keep_samples",
    "lower_roof_in_front",
    "on_facade",
    "party_wall_mask",
    "sample_flags",
]

#: A sample whose point, moved this far outward, lies in another building or obstacle
#: lower than the neighbour's height is on a party wall [m].
PARTY_WALL_GAP_M = 0.10
#: A sample whose point, moved this far outward, lies over a lower building faces that
#: building's roof: ground stations see it only over the roof's edge [m].
ROOF_PROBE_M = 0.5
#: A facade point moved this far into its building tells a passage's opening from wall [m].
OPENING_PROBE_M = 0.05
#: A facade leaning more than this from vertical is a sloping wall (no flat target on it)
#: [deg].
LEANING_DEG = 2.0
#: Sight lines end this far in front of the facade, so the wall itself is not crossed [m].
SIGHT_OFFSET_M = 0.02


@dataclass
class FacadeSet:
    """All facades and samples of a site, as flat arrays (index = position).

    A facade is a plane: drawn as a footprint's edge it is the vertical rectangle over it;
    from a city model, one wall surface (coplanar polygons of a building merged) at its
    real outline — a gable, a set-back storey, the sloping wall of a mansard. Its frame:
    x along it (``start`` → ``end``, horizontal), y its outward normal (``normal``, the
    horizontal part, unit; ``normal_z`` the vertical part of the 3-D unit normal, 0 for a
    vertical wall), z up. ``outline`` is its shape on its elevation: ``(u, h)`` with u the
    distance along it from ``start`` [m] and h the height above its building's base
    (``base_z``) [m].
    """

    # facades (F)
    building_id: np.ndarray  # str
    facade_id: np.ndarray  # str, "<building>-f<NN>"
    start: np.ndarray  # (F, 2) at the facade's foot
    end: np.ndarray  # (F, 2)
    normal: np.ndarray  # (F, 2) outward unit normal (its horizontal part, unit)
    height_m: np.ndarray  # (F,) from its foot to its top [m]
    courtyard: np.ndarray  # (F,) bool: on an interior ring
    # columns (C): one vertical line of samples on a facade
    col_facade: np.ndarray  # (C,) facade index
    col_xy: np.ndarray  # (C, 2) on the wall
    # samples (N)
    facade: np.ndarray  # (N,) facade index
    column: np.ndarray  # (N,) column index
    xy: np.ndarray  # (N, 2)
    z: np.ndarray  # (N,) height in the site's height system [m]
    sample_id: np.ndarray  # (N,) str, "<facade_id>-<col>-<row>"
    party_wall: np.ndarray  # (N,) bool
    # the facade in 3-D (F): its foot, its building's base, its tilt and its outline
    z0: np.ndarray | None = None  # (F,) height of its foot [m]
    base_z: np.ndarray | None = None  # (F,) its building's base [m]
    normal_z: np.ndarray | None = None  # (F,) vertical part of the 3-D unit normal
    outline: np.ndarray | None = None  # (F,) shapely Polygon on the elevation (u, h)

    def __post_init__(self) -> None:
        f = len(self.facade_id)
        if self.z0 is None:
            self.z0 = np.zeros(f)
        if self.base_z is None:
            self.base_z = self.z0.copy()
        if self.normal_z is None:
            self.normal_z = np.zeros(f)
        if self.outline is None:
            self.outline = np.array(
                [
                    shapely.box(0.0, z0 - b, float(L), z0 - b + h)
                    for L, h, z0, b in zip(
                        self.length_m, self.height_m, self.z0, self.base_z, strict=True
                    )
                ]
                + [None],
                dtype=object,
            )[:-1]

    @property
    def n_facades(self) -> int:
        return len(self.facade_id)

    def per_facade(self, of: np.ndarray) -> list[np.ndarray]:
        """Per facade, the indices of the items whose facade index ``of`` gives (its
        samples for :attr:`facade`, its columns for :attr:`col_facade`), ascending."""
        order = np.argsort(of, kind="stable")
        cuts = np.searchsorted(of[order], np.arange(self.n_facades + 1))
        return [order[cuts[f] : cuts[f + 1]] for f in range(self.n_facades)]

    @property
    def length_m(self) -> np.ndarray:
        return np.hypot(*(self.end - self.start).T) if len(self.start) else np.zeros(0)

    @property
    def normal3(self) -> np.ndarray:
        """(F, 3) the outward unit normals in 3-D."""
        c = np.sqrt(np.clip(1.0 - self.normal_z**2, 0.0, 1.0))
        return np.column_stack([self.normal * c[:, None], self.normal_z])

    @property
    def tilted(self) -> np.ndarray:
        """(F,) bool: the facade's plane is not exactly vertical (its geometry is computed
        in 3-D)."""
        return self.normal_z != 0.0

    @property
    def leaning(self) -> np.ndarray:
        """(F,) bool: the facade leans more than :data:`LEANING_DEG` (a mansard's sloping
        storey), not a vertical wall a model gives to its last millimetre."""
        return np.abs(self.normal_z) > np.sin(np.radians(LEANING_DEG))

    def place(self, f: np.ndarray, u: np.ndarray, h: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Points of facades ``f`` at ``u`` along them [m] and ``h`` above their building's
        base [m] (:func:`on_facade`)."""
        f = np.asarray(f, dtype=np.int64)
        return on_facade(
            self.start[f], self.end[f], self.normal_z[f], self.z0[f], self.base_z[f], u, h
        )

    def along_m(self, idx: np.ndarray | None = None) -> np.ndarray:
        """Each sample's distance along its facade from its start [m]."""
        idx = np.arange(len(self.z)) if idx is None else idx
        f = self.facade[idx]
        v = self.end[f] - self.start[f]
        return ((self.xy[idx] - self.start[f]) * v).sum(axis=1) / np.hypot(v[:, 0], v[:, 1])


def on_facade(
    start: np.ndarray,
    end: np.ndarray,
    normal_z: np.ndarray,
    z0: np.ndarray,
    base_z: np.ndarray,
    u: np.ndarray,
    h: np.ndarray,
) -> tuple[np.ndarray, np.ndarray]:
    """Points on facades (each given by its foot ``start`` → ``end`` (P, 2), the vertical
    part of its outward unit normal, its foot's height and its building's base (P,)) at
    ``u`` along them and ``h`` above the base [m]: their plan positions (P, 2) and heights
    (P,) [m] on the facade's plane — a sloping wall leans in or out with the height. The
    one mapping of a facade's elevation to the site (samples, targets, the 3-D walls of the
    files).

    >>> xy, z = on_facade(np.array([[0.0, 0.0]]), np.array([[10.0, 0.0]]), np.array([0.5]),
    ...                   np.array([3.0]), np.array([0.0]), np.array([4.0]), np.array([4.0]))
    >>> xy.round(3).tolist(), z.tolist()  # 1 m up a wall leaning 30° back: 0.577 m in
    ([[4.0, 0.577]], [4.0])
    """
    length = np.hypot(*(end - start).T).reshape(-1)
    along = (end - start) / np.maximum(length, 1e-12)[:, None]
    normal = np.column_stack([along[:, 1], -along[:, 0]])
    z = base_z + h
    c = np.sqrt(np.clip(1.0 - normal_z**2, 1e-12, 1.0))
    w = -normal_z * (z - z0) / c  # how far out of the foot's vertical the plane is
    return start + u[:, None] * along + w[:, None] * normal, z


#: Consecutive footprint edges turning less than this are one facade [deg] …
MERGE_ANGLE_DEG = 10.0
#: … while every vertex between stays within this of the facade's chord [m].
MERGE_OFFSET_M = 0.10


def _merge_ring(xy: np.ndarray, max_turn_deg: float, max_offset_m: float) -> list[tuple[int, int]]:
    """Runs ``(i, j)`` of vertex indices of a closed ring (no repeated last point) forming
    straight facades: consecutive edges turning less than ``max_turn_deg`` and with every
    vertex within ``max_offset_m`` of the chord are merged."""
    n = len(xy)
    d = np.roll(xy, -1, axis=0) - xy
    ang = np.arctan2(d[:, 1], d[:, 0])
    turn = np.abs((np.diff(np.append(ang, ang[0])) + np.pi) % (2 * np.pi) - np.pi)  # at vertex i+1
    corners = np.flatnonzero(np.degrees(np.roll(turn, 1)) >= max_turn_deg)
    start = int(corners[0]) if corners.size else 0
    order = [(start + k) % n for k in range(n + 1)]
    runs = []
    i = 0
    while i < n:
        j = i + 1
        while j < n:
            a, b = xy[order[i]], xy[order[j + 1]]
            chord = b - a
            length = np.hypot(*chord)
            pts = xy[[order[k] for k in range(i + 1, j + 1)]]
            rel = pts - a
            off = np.abs(chord[0] * rel[:, 1] - chord[1] * rel[:, 0]) / max(length, 1e-12)
            t1 = np.degrees(
                abs(
                    np.angle(
                        complex(*(xy[order[j + 1]] - xy[order[j]]))
                        / complex(*(xy[order[i + 1]] - xy[order[i]]))
                    )
                )
            )
            if off.max() <= max_offset_m and t1 < max_turn_deg:
                j += 1
            else:
                break
        runs.append((order[i], order[j]))
        i = j
    return runs


def estimate_samples(site: Site, sample_spacing_m: float, sample_height_step_m: float) -> int:
    """About how many samples :func:`build_facades` will make (before making them): every
    ring edge of a planned building, its length over the spacing, times its rows."""
    total = 0.0
    for b in site.planned:
        rows = max(1.0, round(b.height_m / sample_height_step_m))
        for poly in shapely.get_parts(b.footprint):
            for ring in [poly.exterior, *poly.interiors]:
                edges = len(ring.coords) - 1
                total += (ring.length / sample_spacing_m + edges) * rows
    return int(total)


def check_sample_count(
    n_est: int, sample_spacing_m: float, sample_height_step_m: float, max_samples: float
) -> None:
    """Refuse facades that would need more than ``max_samples`` samples (``n_est``, from
    :func:`estimate_samples`), before any is made, saying what to change."""
    if n_est > max_samples:
        raise InputError(
            f"the facades would need about {n_est:,} samples at {sample_spacing_m:g} m × "
            f"{sample_height_step_m:g} m, more than {max_samples:,.0f}; use coarser "
            "samples (--sample-spacing-m, --sample-height-step-m), plan fewer buildings, or "
            "raise the limit (--max-samples)"
        )


def build_facades(
    site: Site,
    sample_spacing_m: float = 2.0,
    sample_height_step_m: float = 2.0,
    *,
    merge_angle_deg: float = MERGE_ANGLE_DEG,
    merge_offset_m: float = MERGE_OFFSET_M,
    scene: Scene | None = None,
    roofs: bool = False,
) -> FacadeSet:
    """Facades and samples of the planned buildings of ``site``.

    A building drawn as a footprint: every ring edge (nearly collinear edges merged) is a
    facade from the building's base to its top. A facade of length L gets
    ``max(1, round(L / sample_spacing_m))`` columns at the centres of equal cells and
    ``max(1, round(H / sample_height_step_m))`` rows, also at cell centres.

    A building from a city model: every plane of its demanded surfaces
    (:func:`planner.citymodel.demanded_kinds`: walls, doors; roofs where ``roofs``) is a
    facade, its polygons merged; its samples are the centres of the same grid of cells
    over its outline that fall on it (a cell too small for its centre, as the tip of a
    gable: its outline's own point).

    Party-wall samples (against a neighbour, below its height; in 3-D: just outside the
    wall is inside another building or part) are flagged, not dropped. Samples below the
    ground (a wall on a slope) and in a passage's opening are dropped: there is no wall to
    scan. The line-of-sight scene (:class:`~planner.pipeline.geometry.scene.Scene`) is made here
    when a 3-D site needs one and none is given.
    """
    flat = [b for b in site.planned if not b.surfaces]
    fac = _footprint_facades(
        site, flat, sample_spacing_m, sample_height_step_m, merge_angle_deg, merge_offset_m
    )
    model = [b for b in site.planned if b.surfaces]
    if model or site.is_3d:
        if scene is None:
            scene = Scene(site)
        if model:
            fac = _joined(
                fac, _model_facades(model, scene, sample_spacing_m, sample_height_step_m, roofs)
            )
    wall, party = sample_flags(site, fac, fac.facade, fac.xy, fac.z, scene)
    fac.party_wall = party
    return fac if wall.all() else keep_samples(fac, wall)


def _footprint_facades(
    site: Site,
    buildings: list,
    sample_spacing_m: float,
    sample_height_step_m: float,
    merge_angle_deg: float,
    merge_offset_m: float,
) -> FacadeSet:
    """The facades of buildings drawn as footprints (:func:`build_facades`)."""
    f_b, f_id, f_a, f_e, f_n, f_h, f_c, f_z = [], [], [], [], [], [], [], []
    for b in buildings:
        k = 0
        for poly in shapely.get_parts(shapely.orient_polygons(b.footprint)):
            rings = [(poly.exterior, False)] + [(r, True) for r in poly.interiors]
            for ring, is_court in rings:
                xy = np.asarray(ring.coords)[:-1, :2]
                for i, j in _merge_ring(xy, merge_angle_deg, merge_offset_m):
                    a, e = xy[i], xy[j]
                    v = e - a
                    length = float(np.hypot(*v))
                    f_b.append(b.id)
                    f_id.append(f"{b.id}-f{k:02d}")
                    f_a.append(a)
                    f_e.append(e)
                    f_n.append(np.array([v[1], -v[0]]) / length)
                    f_h.append(b.height_m)
                    f_c.append(is_court)
                    f_z.append(float(b.base_z or 0.0))
                    k += 1
    start = np.array(f_a, dtype=float).reshape(-1, 2)
    end = np.array(f_e, dtype=float).reshape(-1, 2)
    normal = np.array(f_n, dtype=float).reshape(-1, 2)
    height = np.array(f_h, dtype=float)
    base = np.array(f_z, dtype=float)
    lengths = np.hypot(*(end - start).T)
    n_cols = np.maximum(1, np.round(lengths / sample_spacing_m)).astype(int)
    n_rows = np.maximum(1, np.round(height / sample_height_step_m)).astype(int)
    col_f = np.repeat(np.arange(len(f_id)), n_cols)
    first_col = np.concatenate([[0], np.cumsum(n_cols)[:-1]]).astype(int)
    k_in_f = np.arange(col_f.size) - first_col[col_f]
    frac = (k_in_f + 0.5) / n_cols[col_f]
    col_xy = start[col_f] + frac[:, None] * (end - start)[col_f]
    # samples: every column × its facade's rows, but none in a passage's opening
    rows_per_col = n_rows[col_f]
    s_col = np.repeat(np.arange(col_f.size), rows_per_col)
    first_row = np.concatenate([[0], np.cumsum(rows_per_col)[:-1]]).astype(int)
    r_in_c = np.arange(s_col.size) - first_row[s_col]
    s_f = col_f[s_col]
    s_z = base[s_f] + (r_in_c + 0.5) / n_rows[s_f] * height[s_f]
    s_xy = col_xy[s_col].reshape(-1, 2)
    fid = np.array(f_id, dtype=object)
    sample_id = np.array(
        [f"{fid[f]}-{c:03d}-{r:02d}" for f, c, r in zip(s_f, k_in_f[s_col], r_in_c, strict=True)],
        dtype=object,
    )
    return FacadeSet(
        building_id=np.array(f_b, dtype=object),
        facade_id=fid,
        start=start,
        end=end,
        normal=normal,
        height_m=height,
        courtyard=np.array(f_c, dtype=bool),
        col_facade=col_f,
        col_xy=col_xy.reshape(-1, 2),
        facade=s_f,
        column=s_col,
        xy=s_xy,
        z=s_z,
        sample_id=sample_id,
        party_wall=np.zeros(len(s_z), dtype=bool),
        z0=base.copy(),
        base_z=base,
    )


#: A model facade's samples keep this far inside its outline [m]: a cell centre on the
#: outline's edge is on the wall's edge (the eaves, a corner), where a beam may miss it.
EDGE_MARGIN_M = 0.05
#: Polygons of a building whose normals differ by less than this and whose planes are
#: this close are one facade [deg, m].
COPLANAR_DEG = 3.0
COPLANAR_M = 0.05


def _planes(surfaces: list) -> list[list]:
    """The surfaces grouped by plane: normals within :data:`COPLANAR_DEG` and each one's
    centre within :data:`COPLANAR_M` of the group's plane (through its first surface's
    centre; measured there, not from the CRS's origin, where a thousandth of a degree is
    metres)."""
    groups: list[tuple[np.ndarray, np.ndarray, list]] = []
    cos_max = np.cos(np.radians(COPLANAR_DEG))
    for s in surfaces:
        n = s.normal
        c = s.rings[0].mean(axis=0)
        for gn, gc, members in groups:
            if gn @ n >= cos_max and abs(gn @ (c - gc)) <= COPLANAR_M:
                members.append(s)
                break
        else:
            groups.append((n, c, [s]))
    return [m for _, _, m in groups]


def _model_facades(
    buildings: list, scene: Scene, spacing: float, step: float, roofs: bool
) -> FacadeSet:
    """The facades of buildings from a city model (:func:`build_facades`)."""
    from planner.citymodel import demanded_kinds, level_roof

    wanted = demanded_kinds(roofs)
    rows: list[dict] = []
    for b in buildings:
        k = 0
        base = float(b.base_z or 0.0)
        demanded = [s for s in b.surfaces if s.kind in wanted and not level_roof(s)]
        for members in _planes(demanded):
            area = np.array([m.area_m2 for m in members])
            n3 = (np.array([m.normal for m in members]) * area[:, None]).sum(axis=0)
            n3 /= np.linalg.norm(n3)
            horizontal = np.hypot(n3[0], n3[1])
            nh = n3[:2] / horizontal if horizontal > 1e-6 else np.array([0.0, -1.0])
            along = np.array([-nh[1], nh[0]])
            pts = np.vstack([m.rings[0] for m in members])
            p0 = pts[np.argmin(pts[:, 2])]
            outline, planes = [], []  # each member on the elevation, and its own plane
            for m in members:
                rings = [
                    np.column_stack([(r[:, :2] - p0[:2]) @ along, r[:, 2] - base]) for r in m.rings
                ]
                poly = shapely.Polygon(rings[0], [r for r in rings[1:] if len(r) >= 3])
                parts = [
                    g
                    for g in shapely.get_parts(shapely.make_valid(poly))
                    if g.geom_type == "Polygon"
                ]
                outline += parts
                planes += [(g, m.normal, m.rings[0].mean(axis=0)) for g in parts]
            merged = shapely.union_all(outline, grid_size=0.001)
            for piece in shapely.get_parts(merged):
                if piece.geom_type != "Polygon" or piece.area < 0.01:
                    continue
                u0, h0, u1, h1 = piece.bounds
                shifted = shapely.affinity.translate(piece, -u0, 0.0)
                foot_xy = p0[:2] + u0 * along
                # the foot: where the (maybe sloping) plane meets the piece's lowest height
                w = -n3[2] * ((base + h0) - p0[2]) / max(horizontal, 1e-6)
                foot_xy = foot_xy + w * nh
                rows.append(
                    dict(
                        building=b.id,
                        id=f"{b.id}-f{k:02d}",
                        start=foot_xy,
                        end=foot_xy + (u1 - u0) * along,
                        normal=nh,
                        normal_z=float(n3[2]) if abs(n3[2]) > 1e-9 else 0.0,
                        z0=base + h0,
                        base=base,
                        height=h1 - h0,
                        outline=shifted,
                        planes=[
                            (shapely.affinity.translate(g, -u0, 0.0), n, c) for g, n, c in planes
                        ],
                    )
                )
                k += 1
    return _sampled(rows, spacing, step)


def _sampled(rows: list[dict], spacing: float, step: float) -> FacadeSet:
    """Facades from their rows (:func:`_model_facades`) with their samples: the centres of
    a grid of cells over each outline that fall on it."""
    f_n = len(rows)
    fac = FacadeSet(
        building_id=np.array([r["building"] for r in rows], dtype=object),
        facade_id=np.array([r["id"] for r in rows], dtype=object),
        start=np.array([r["start"] for r in rows], dtype=float).reshape(-1, 2),
        end=np.array([r["end"] for r in rows], dtype=float).reshape(-1, 2),
        normal=np.array([r["normal"] for r in rows], dtype=float).reshape(-1, 2),
        height_m=np.array([r["height"] for r in rows], dtype=float),
        courtyard=np.zeros(f_n, dtype=bool),
        col_facade=np.empty(0, dtype=np.int64),
        col_xy=np.empty((0, 2)),
        facade=np.empty(0, dtype=np.int64),
        column=np.empty(0, dtype=np.int64),
        xy=np.empty((0, 2)),
        z=np.empty(0),
        sample_id=np.empty(0, dtype=object),
        party_wall=np.empty(0, dtype=bool),
        z0=np.array([r["z0"] for r in rows], dtype=float),
        base_z=np.array([r["base"] for r in rows], dtype=float),
        normal_z=np.array([r["normal_z"] for r in rows], dtype=float),
        outline=np.array([r["outline"] for r in rows] + [None], dtype=object)[:-1],
    )
    col_f, col_u, s_f, s_col, s_u, s_h, ids = [], [], [], [], [], [], []
    for f, r in enumerate(rows):
        shape = r["outline"]
        u1, h0, h1 = float(fac.length_m[f]), r["z0"] - r["base"], r["z0"] - r["base"] + r["height"]
        nc = max(1, round(u1 / spacing))
        # rows a step apart along the plane (a roof's slope rises less per step than a wall)
        rise = step * max(float(np.sqrt(1.0 - r["normal_z"] ** 2)), 0.02)
        nr = max(1, round((h1 - h0) / rise))
        uu = (np.arange(nc) + 0.5) * u1 / nc
        hh = h0 + (np.arange(nr) + 0.5) * (h1 - h0) / nr
        gu, gh = np.meshgrid(uu, hh, indexing="ij")
        ci, ri = np.meshgrid(np.arange(nc), np.arange(nr), indexing="ij")
        inner = shape.buffer(-EDGE_MARGIN_M)  # not on an edge, where the wall may not be
        on = shapely.contains_xy(inner, gu.ravel(), gh.ravel())
        pu, ph, pc, pr = gu.ravel()[on], gh.ravel()[on], ci.ravel()[on], ri.ravel()[on]
        for piece in shapely.get_parts(shape):  # a piece no cell centre falls on
            if not shapely.contains_xy(piece, pu, ph).any():
                core = piece.buffer(-EDGE_MARGIN_M)
                p = (core if not core.is_empty else piece).representative_point()
                pu, ph = np.append(pu, p.x), np.append(ph, p.y)
                pc = np.append(pc, min(int(p.x / (u1 / nc)), nc - 1))
                pr = np.append(pr, nr)
        cols = np.unique(pc)
        first = len(col_f)
        col_f += [f] * len(cols)
        col_u += [(c + 0.5) * u1 / nc for c in cols]
        s_f.append(np.full(len(pu), f))
        s_col.append(first + np.searchsorted(cols, pc))
        s_u.append(pu)
        s_h.append(ph)
        ids += [f"{r['id']}-{c:03d}-{q:02d}" for c, q in zip(pc, pr, strict=True)]
    if not rows:
        return fac
    fac.col_facade = np.array(col_f, dtype=np.int64)
    fac.col_xy = fac.place(
        fac.col_facade, np.array(col_u), fac.z0[fac.col_facade] - fac.base_z[fac.col_facade]
    )[0]
    fac.facade = np.concatenate(s_f).astype(np.int64)
    fac.column = np.concatenate(s_col).astype(np.int64)
    u, h = np.concatenate(s_u), np.concatenate(s_h)
    fac.xy, fac.z = fac.place(fac.facade, u, h)
    _onto_members(fac, rows, u, h)
    fac.sample_id = np.array(ids, dtype=object)
    fac.party_wall = np.zeros(len(fac.z), dtype=bool)
    return fac


def _onto_members(fac: FacadeSet, rows: list[dict], u: np.ndarray, h: np.ndarray) -> None:
    """Each sample moved along its facade's normal onto the plane of the model's polygon it
    lies on (the polygons merged into a facade are coplanar only within
    :data:`COPLANAR_M`): every sample is on a surface of the model."""
    n3 = fac.normal3
    for f, r in enumerate(rows):
        mine = np.flatnonzero(fac.facade == f)
        if len(r["planes"]) < 2 or not len(mine):
            continue
        for shape, normal, centre in r["planes"]:
            on = mine[shapely.contains_xy(shape, u[mine], h[mine])]
            if not len(on):
                continue
            p = np.column_stack([fac.xy[on], fac.z[on]])
            t = ((centre - p) @ normal) / (n3[f] @ normal)
            moved = p + t[:, None] * n3[f]
            fac.xy[on], fac.z[on] = moved[:, :2], moved[:, 2]


def _joined(a: FacadeSet, b: FacadeSet) -> FacadeSet:
    """The facades of ``a`` then of ``b`` (indices of ``b`` shifted)."""
    fa, ca = a.n_facades, len(a.col_facade)
    per_facade = (
        "building_id",
        "facade_id",
        "start",
        "end",
        "normal",
        "height_m",
        "courtyard",
        "z0",
        "base_z",
        "normal_z",
        "outline",
    )
    out = {k: np.concatenate([getattr(a, k), getattr(b, k)]) for k in per_facade}
    out["col_facade"] = np.concatenate([a.col_facade, b.col_facade + fa])
    out["col_xy"] = np.vstack([a.col_xy, b.col_xy])
    out["facade"] = np.concatenate([a.facade, b.facade + fa])
    out["column"] = np.concatenate([a.column, b.column + ca])
    for k in ("xy", "z", "sample_id", "party_wall"):
        out[k] = np.concatenate([getattr(a, k), getattr(b, k)])
    return FacadeSet(**out)


def sample_flags(
    site: Site,
    fac: FacadeSet,
    s_f: np.ndarray,
    xy: np.ndarray,
    z: np.ndarray,
    scene: Scene | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """For points ``xy``, ``z`` on facades ``s_f`` (samples, a zone's finer samples, flat
    targets): whether each is wall to scan and whether it is on a party wall — the one
    place these rules are written:

    * not wall: in a passage's opening (below its clear height above the building's base),
      or below the ground in front of it (a wall on a slope is partly buried);
    * party wall: for a building drawn as a footprint, its point moved
      :data:`PARTY_WALL_GAP_M` out lies in another building or obstacle at least as high
      (:func:`party_wall_mask`); for a 3-D building, that point is inside another building
      or part (:meth:`~planner.pipeline.geometry.scene.Scene.inside`: the first building surface
      straight below it is that one's ground face)."""
    wall = ~in_opening(site, xy - OPENING_PROBE_M * fac.normal[s_f], z - fac.base_z[s_f])
    model = np.isin(fac.building_id[s_f], [b.id for b in site.planned if b.surfaces])
    party = np.zeros(len(z), dtype=bool)
    drawn = ~model
    if drawn.any():
        party[drawn] = party_wall_mask(
            site,
            fac.building_id[s_f[drawn]],
            xy[drawn] + PARTY_WALL_GAP_M * fac.normal[s_f[drawn]],
            z[drawn],
        )
    if site.is_3d:
        if scene is None:
            scene = Scene(site)
        probe = np.column_stack([xy, z]) + PARTY_WALL_GAP_M * fac.normal3[s_f]
        wall &= z >= scene.ground_z(probe[:, :2]) - 1e-6
        if model.any():
            party[model] = scene.inside(probe[model]) != ""
    return wall, party


def keep_samples(fac: FacadeSet, keep: np.ndarray) -> FacadeSet:
    """``fac`` with only the samples ``keep`` (N,) bool (facades and columns kept)."""
    return replace(
        fac,
        facade=fac.facade[keep],
        column=fac.column[keep],
        xy=fac.xy[keep],
        z=fac.z[keep],
        sample_id=fac.sample_id[keep],
        party_wall=fac.party_wall[keep],
    )


def party_wall_mask(
    site: Site, owner: np.ndarray, probe_xy: np.ndarray, z: np.ndarray
) -> np.ndarray:
    """Points on a wall of building ``owner`` whose probe point (just outside the wall) lies
    in another building or obstacle at least as high as the point: a party wall there."""
    out = np.zeros(len(z), dtype=bool)
    blockers = site.blockers
    geoms = [g for _, g, _ in blockers]
    tree = shapely.STRtree(geoms)
    pts = shapely.points(probe_xy)
    for k, j in tree.query(pts, predicate="intersects").T:
        bid, _, h = blockers[j]
        if bid != owner[k] and z[k] <= h:
            out[k] = True
    return out


def lower_roof_in_front(site: Site, fac: FacadeSet, samples: np.ndarray) -> np.ndarray:
    """For each of ``samples`` (indices), the id of the lower building whose roof it faces
    (its point moved :data:`ROOF_PROBE_M` outward lies in that building's footprint, which is
    lower than the point), else ``""``: a wall above a neighbour's roof, which a station on
    that roof sees square and close, and the ground only over the roof's edge."""
    out = np.full(len(samples), "", dtype=object)
    if not len(samples):
        return out
    f = fac.facade[samples]
    probe = fac.xy[samples] + ROOF_PROBE_M * fac.normal[f]
    z = fac.z[samples]
    owner = fac.building_id[f]
    blds = site.buildings
    tree = shapely.STRtree([b.footprint for b in blds])
    best = np.full(len(samples), -np.inf)
    for k, j in tree.query(shapely.points(probe), predicate="intersects").T:
        b = blds[j]
        if b.id != owner[k] and b.top_z < z[k] and b.top_z > best[k]:
            out[k], best[k] = b.id, b.top_z
    return out


def in_opening(site: Site, probe_xy: np.ndarray, h: np.ndarray) -> np.ndarray:
    """Points (a wall's point moved :data:`OPENING_PROBE_M` into the building, ``h`` [m]
    above its building's base) in a passage below its clear height: the opening of a
    gateway, where there is no wall."""
    out = np.zeros(len(h), dtype=bool)
    if not site.passages or not len(h):
        return out
    geoms = [p.geometry for p in site.passages]
    tree = shapely.STRtree(geoms)
    for k, j in tree.query(shapely.points(probe_xy), predicate="intersects").T:
        if h[k] < site.passages[j].clear_height_m:
            out[k] = True
    return out
