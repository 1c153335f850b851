"""Facades of the planned buildings, and the sample points on them.

Every exterior and interior (courtyard) ring edge of a planned building is a facade, after
merging consecutive edges that are nearly collinear (a facade digitised as many short
pieces). Facade frame: x along the facade, y along the outward normal, z up.
Samples sit at the centres of a grid of cells along the facade and up its height.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely

from planner.errors import InputError
from planner.site import Site

__all__ = [
    "FacadeSet",
    "bridge_edges",
    "build_facades",
    "check_sample_count",
    "estimate_samples",
    "footprint_edges",
    "in_opening",
    "lower_roof_in_front",
    "party_wall_mask",
]

#: A sample whose point, moved this far outward, lies in another building or obstacle
#: lower than the neighbour's height is on a party wall [m].
PARTY_WALL_GAP_M = 0.10
#: A sample whose point, moved this far outward, lies over a lower building faces that
#: building's roof: ground stations see it only over the roof's edge [m].
ROOF_PROBE_M = 0.5
#: A facade point moved this far into its building tells a passage's opening from wall [m].
OPENING_PROBE_M = 0.05
#: Sight lines end this far in front of the facade, so the wall itself is not crossed [m].
SIGHT_OFFSET_M = 0.02


@dataclass
class FacadeSet:
    """All facades and samples of a site, as flat arrays (index = position)."""

    # facades (F)
    building_id: np.ndarray  # str
    facade_id: np.ndarray  # str, "<building>-f<NN>"
    start: np.ndarray  # (F, 2)
    end: np.ndarray  # (F, 2)
    normal: np.ndarray  # (F, 2) outward unit normal
    height_m: np.ndarray  # (F,)
    courtyard: np.ndarray  # (F,) bool: on an interior ring
    # columns (C): one vertical line of samples on a facade
    col_facade: np.ndarray  # (C,) facade index
    col_xy: np.ndarray  # (C, 2) on the wall
    # samples (N)
    facade: np.ndarray  # (N,) facade index
    column: np.ndarray  # (N,) column index
    xy: np.ndarray  # (N, 2)
    z: np.ndarray  # (N,) height above ground [m]
    sample_id: np.ndarray  # (N,) str, "<facade_id>-<col>-<row>"
    party_wall: np.ndarray  # (N,) bool

    @property
    def n_facades(self) -> int:
        return len(self.facade_id)

    @property
    def length_m(self) -> np.ndarray:
        return np.hypot(*(self.end - self.start).T)


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
    merge_angle_deg: float = 10.0,
    merge_offset_m: float = 0.10,
) -> FacadeSet:
    """Facades and samples of the planned buildings of ``site``.

    A facade of length L gets ``max(1, round(L / sample_spacing_m))`` columns at the centres
    of equal cells; a building of height H gets ``max(1, round(H / sample_height_step_m))``
    rows, also at cell centres. Party-wall samples (against a neighbour, below its height)
    are flagged, not dropped.
    """
    f_b, f_id, f_a, f_e, f_n, f_h, f_c = [], [], [], [], [], [], []
    for b in site.planned:
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
                    k += 1
    start, end, normal = np.array(f_a), np.array(f_e), np.array(f_n)
    height = np.array(f_h, dtype=float)
    lengths = np.hypot(*(end - start).T)
    n_cols = np.maximum(1, np.round(lengths / sample_spacing_m)).astype(int)
    n_rows = np.maximum(1, np.round(height / sample_height_step_m)).astype(int)
    col_f = np.repeat(np.arange(len(f_id)), n_cols)
    first_col = np.concatenate([[0], np.cumsum(n_cols)[:-1]])
    k_in_f = np.arange(col_f.size) - first_col[col_f]
    frac = (k_in_f + 0.5) / n_cols[col_f]
    col_xy = start[col_f] + frac[:, None] * (end - start)[col_f]
    # samples: every column × its facade's rows, but none in a passage's opening
    rows_per_col = n_rows[col_f]
    s_col = np.repeat(np.arange(col_f.size), rows_per_col)
    first_row = np.concatenate([[0], np.cumsum(rows_per_col)[:-1]])
    r_in_c = np.arange(s_col.size) - first_row[s_col]
    s_f = col_f[s_col]
    s_z = (r_in_c + 0.5) / n_rows[s_f] * height[s_f]
    s_xy = col_xy[s_col]
    wall = ~in_opening(site, s_xy - OPENING_PROBE_M * normal[s_f], s_z)
    s_col, r_in_c, s_f, s_z, s_xy = s_col[wall], r_in_c[wall], s_f[wall], s_z[wall], s_xy[wall]
    fid = np.array(f_id, dtype=object)
    sample_id = np.array(
        [f"{fid[f]}-{c:03d}-{r:02d}" for f, c, r in zip(s_f, k_in_f[s_col], r_in_c, strict=True)],
        dtype=object,
    )
    party = party_wall_mask(
        site, np.array(f_b, dtype=object)[s_f], s_xy + PARTY_WALL_GAP_M * normal[s_f], s_z
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
        col_xy=col_xy,
        facade=s_f,
        column=s_col,
        xy=s_xy,
        z=s_z,
        sample_id=sample_id,
        party_wall=party,
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
        if b.id != owner[k] and b.height_m < z[k] and b.height_m > best[k]:
            out[k], best[k] = b.id, b.height_m
    return out


def in_opening(site: Site, probe_xy: np.ndarray, z: np.ndarray) -> np.ndarray:
    """Points (a wall's point moved :data:`OPENING_PROBE_M` into the building) in a
    passage below its clear height: the opening of a gateway, where there is no wall."""
    out = np.zeros(len(z), dtype=bool)
    if not site.passages or not len(z):
        return out
    geoms = [p.geometry for p in site.passages]
    tree = shapely.STRtree(geoms)
    for k, j in tree.query(shapely.points(probe_xy), predicate="intersects").T:
        if z[k] < site.passages[j].clear_height_m:
            out[k] = True
    return out


def bridge_edges(site: Site) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Every ring edge of the floors above the passages (:attr:`Site.bridges`): ``(M, 4)``
    as x0, y0, x1, y1, with the bottom and top of the floors [m]."""
    segs, bottoms, tops = [np.empty((0, 4))], [np.empty(0)], [np.empty(0)]
    for _, geom, bottom, top in site.bridges:
        e = _ring_edges(geom)
        segs.append(e)
        bottoms.append(np.full(len(e), bottom))
        tops.append(np.full(len(e), top))
    return np.vstack(segs), np.concatenate(bottoms), np.concatenate(tops)


def _ring_edges(geom) -> np.ndarray:
    """Every ring edge of a polygon or multipolygon, ``(M, 4)`` as x0, y0, x1, y1."""
    segs = [np.empty((0, 4))]
    for poly in shapely.get_parts(geom):
        for ring in [poly.exterior, *poly.interiors]:
            xy = np.asarray(ring.coords)[:, :2]
            segs.append(np.hstack([xy[:-1], xy[1:]]))
    return np.vstack(segs)


def footprint_edges(site: Site) -> tuple[np.ndarray, np.ndarray]:
    """Every ring edge of every blocker: ``(M, 4)`` as x0, y0, x1, y1, and its height."""
    segs, heights = [np.empty((0, 4))], [np.empty(0)]
    for _, geom, h in site.blockers:
        e = _ring_edges(geom)
        segs.append(e)
        heights.append(np.full(len(e), h))
    return np.vstack(segs), np.concatenate(heights)
