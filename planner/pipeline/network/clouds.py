"""The surfaces the stations' scans share, and the cloud-to-cloud links over them.

The model is :mod:`planner.cloud_registration`; this module finds its patches on a site:

- **facade patches**: every facade sample is a patch of ``sample_spacing_m`` ×
  ``sample_height_step_m`` on its wall, seen by a station where the evaluation says so, its
  points those a registration uses (the scan step and the incidence, thinned to
  ``cloud_spacing_mm``: :func:`planner.cloud_registration.registration_points`), its
  noise across the wall the accuracy model's m_y
  (:func:`planner.pipeline.evaluation.evaluate.evaluate_stations`);
- **ground patches**: cells of :data:`GROUND_CELL_M` on open ground within
  :data:`GROUND_REACH_M` of a station that it sees over the buildings and a registration
  can use (not beyond the incidence a registration takes), its noise along the vertical
  from the ranging and the vertical angle at that elevation.

Obstacles other than buildings (trees, cars, street furniture) are not modelled: they add
overlap in practice, and move.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np
import scipy.sparse as sp
import shapely

from planner.cloud_registration import (
    FLOOR_CELL_M,
    GROUND_REACH_M,
    MAX_LINK_CONDITION,
    MIN_POINTS_ACROSS,
    WINDOW_HEIGHT_M,
    WINDOW_WIDTH_M,
    floor_units,
    link_covariance,
    link_information,
    link_strength,
    overlap_pct,
    patch_variance_mm2,
    plane_rows,
    registration_points,
    registration_spacing,
    relief_areas,
    reveal_visible,
    start_information,
    weakest_direction,
)
from planner.materials import roughness_mm
from planner.pipeline.evaluation.evaluate import Context, evaluate_stations
from planner.pipeline.geometry.beams import World
from planner.pipeline.network.linkcheck import LinkCheck, StartError, rehearse_link
from planner.pipeline.network.links import a_matrix
from planner.spacing import point_spacing_mm
from planner.units import RHO_ARCSEC

__all__ = [
    "GROUND_REACH_M",
    "CloudLink",
    "SurfaceCache",
    "Surfaces",
    "cloud_link",
    "overlap_matrix",
    "surfaces",
]

#: The surface kinds of a city model's openings (their reveals are the model's own walls).
OPENINGS = ("window", "door")
#: A relief patch with fewer points than this is not a plane to a scan.
MIN_RELIEF_POINTS = 3.0
#: What a reveal adds to the cloud floor, per opening [mm]: an ICP's local planes on a
#: reveal only a few point spacings deep are tilted by the noise across so few points, and
#: bias the shift along the wall. An independent point-to-plane ICP on simulated scans of a
#: wall with 150 mm reveals (tests/test_relief.py) found that bias 0.3–1.0 mm per link;
#: 1 mm per opening (1.4 mm with the cloud floor) predicts its RMS within ±25 %.
RELIEF_FLOOR_MM = 1.0
#: Ground cells [m].
GROUND_CELL_M = 2.0
#: A ground cell's sight line, cast as a ray, ends this far above the ground [m]: above the
#: terrain's triangles and the clearance the lines beside it keep.
GROUND_LIFT_M = 0.05


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
    """Scan ``child`` registered to scan ``parent`` over their common patches; ``check``
    the plan's rehearsal of it (:mod:`planner.pipeline.network.linkcheck`) where one was
    made, ``scale`` what that rehearsal multiplied the model's variance by (≥ 1)."""

    parent: int
    child: int
    info: np.ndarray  # (6, 6) point-to-plane information at the child's centre
    cov: np.ndarray  # (6, 6) the child's pose relative to the parent (levelled: with tilt)
    overlap_pct: float
    condition: float
    patches: int
    prior: np.ndarray = field(default_factory=lambda: np.zeros((6, 6)))  # the start's
    levelled: bool = False
    check: LinkCheck | None = None
    scale: float = 1.0

    @property
    def fixed(self) -> bool:
        return bool(np.isfinite(self.condition) and self.condition <= MAX_LINK_CONDITION)

    @property
    def holds(self) -> bool:
        """Its surfaces fix it and, where rehearsed, it does not fail too often."""
        return self.fixed and (self.check is None or self.check.holds)

    @property
    def information(self) -> np.ndarray:
        """The information (6, 6) the network takes the link with: its surfaces' and its
        start's, over the rehearsal's scale."""
        return (self.info + self.prior) / self.scale

    @property
    def weakest(self) -> str:
        """Its weakest direction in words: "free: …" where its surfaces leave one free (its
        start then holds it), else the largest error's."""
        if not self.fixed:
            return weakest_direction(link_covariance(self.info, levelled=self.levelled))
        return weakest_direction(self.cov)

    def checked(self, check: LinkCheck, probe_xyz: np.ndarray, centre: np.ndarray) -> CloudLink:
        """This link with its rehearsal ``check``: its variance scaled so that, along each
        axis at the child's facade points ``probe_xyz`` (P, 3) [m] about its centre
        ``centre`` [m], it is no smaller than the rehearsal's mean square over the trials
        that held (:func:`check_scale`)."""
        k2 = check_scale(self.cov, check, probe_xyz, centre)
        return replace(self, check=check, scale=k2, cov=self.cov * k2)


def check_scale(
    cov: np.ndarray, check: LinkCheck, probe_xyz: np.ndarray, centre: np.ndarray
) -> float:
    """The factor (≥ 1) on a link's variance that makes it, along x, y and z at the points
    ``probe_xyz`` (P, 3) [m], no smaller than the rehearsal's mean square there: the
    largest of the three axes' pooled ratios (rehearsed over predicted, over the trials that
    held and the points); 1 where every trial failed (the link is not one anyway)."""
    ok = check.errors[~check.failed]
    if not len(ok) or not np.isfinite(cov).all():
        return 1.0
    g = a_matrix((np.atleast_2d(probe_xyz) - centre) * 1000.0, levelled=False)  # (P, 3, 6)
    predicted = np.einsum("pij,jk,pik->i", g, cov, g)  # (3,) summed over the points
    rehearsed = np.einsum("pij,tj->tpi", g, ok)  # (T, P, 3)
    seen = np.square(rehearsed).sum(axis=(0, 1)) / len(ok)
    ratio = np.divide(seen, predicted, out=np.zeros(3), where=predicted > 0)
    return float(max(1.0, ratio.max()))


def surfaces(ctx: Context, station_xy: np.ndarray) -> Surfaces:
    """The facade and ground patches the stations at ``station_xy`` (K, 2) see (module
    docstring)."""
    return SurfaceCache(ctx).take(np.arange(len(station_xy)), np.asarray(station_xy, float))


class SurfaceCache:
    """What each candidate position sees of the patches, computed once per candidate for a
    plan, and the cloud links between candidates (by candidate index). Ground cells lie on
    one grid for the whole plan, so a candidate's patches do not depend on the others."""

    def __init__(self, ctx: Context) -> None:
        self.ctx = ctx
        fac = ctx.facades
        self._xyz = [np.column_stack([fac.xy, fac.z])]
        self._normal = [fac.normal3[fac.facade]]
        self._area = [
            np.full(len(fac.z), ctx.settings.sample_spacing_m * ctx.settings.sample_height_step_m)
        ]
        self._n = len(fac.z)
        # the parametric facade's relief (planner.cloud_registration): three patches per
        # facade sample, its two jambs and its head, numbered after the samples
        st = ctx.settings
        area = st.sample_spacing_m * st.sample_height_step_m
        jamb, head = relief_areas(area, st.window_share, st.reveal_depth_m)
        self._relief_area = np.array([jamb, jamb, head])
        # the openings of a sample's patch: each reveal's floor is its own
        self._openings = area * st.window_share / (WINDOW_WIDTH_M * WINDOW_HEIGHT_M)
        # a city model that draws its openings (LoD3: windows, doors) has its reveals as
        # walls of their own: no parametric relief on its buildings
        drawn = [b.id for b in ctx.site.planned if any(s.kind in OPENINGS for s in b.surfaces)]
        self._parametric = ~np.isin(fac.building_id[fac.facade], drawn)
        if jamb > 0:
            n = len(fac.z)
            wall = np.column_stack([fac.normal[fac.facade], np.zeros(n)])
            along = np.column_stack([-wall[:, 1], wall[:, 0], np.zeros(n)])
            down = np.tile([0.0, 0.0, -1.0], (n, 1))
            self._relief_normal = np.stack([along, -along, down], axis=1)  # (N, 3, 3)
            inside = self._xyz[0] - 0.5 * st.reveal_depth_m * wall
            self._xyz.append(np.repeat(inside, 3, axis=0))
            self._normal.append(self._relief_normal.reshape(-1, 3))
            self._area.append(np.zeros(3 * n))  # relief adds no overlap
            self._n += 3 * n
        # the ground cells met so far (:data:`_CELL_KEY`), sorted, and their patch indices
        self._cell_keys = np.empty(0, dtype=np.int64)
        self._cell_ids = np.empty(0, dtype=np.int64)
        self._solid = shapely.union_all([g for _, g, _ in ctx.site.blockers])
        self.columns: dict[int, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}
        # each facade sample's wall class (:meth:`wall_axes`), and each candidate's as bits
        n = fac.normal[fac.facade]
        deg = np.degrees(np.arctan2(n[:, 1], n[:, 0])) % 180.0
        self._axis = (np.floor((deg + 22.5) / 45.0) % 4).astype(np.int64)
        self._axes: dict[int, int] = {}
        self.links: dict[tuple[int, int], CloudLink] = {}
        #: whether the networks made from here on rehearse their cloud links (once the
        #: plan's stations are chosen), the rehearsals (by candidate indices), and the
        #: world they are cast in
        self.rehearsing = False
        self.checks: dict[tuple[int, int], LinkCheck] = {}
        #: the pairs :meth:`check` was asked for since the plan began rehearsing (a cache
        #: kept between plans holds other plans' rehearsals too)
        self.asked: set[tuple[int, int]] = set()
        self._world: World | None = None
        # the surface every pair of candidates seen by :meth:`overlap` holds in common [m²]
        self._row: dict[int, int] = {}
        self._common = np.zeros((0, 0), dtype=np.float32)
        self._total = np.zeros(0)
        # which pairs of those overlap by ``_over_pct`` or more (:meth:`overlapping`)
        self._over = np.zeros((0, 0), dtype=bool)
        self._over_pct = math.nan

    def take(self, idx: np.ndarray, cand_xy: np.ndarray) -> Surfaces:
        """The patches candidates ``idx`` (positions ``cand_xy[idx]``) see, as :class:`Surfaces`
        over the patches any of them sees."""
        idx = np.asarray(idx, dtype=np.int64)
        self._compute(idx, cand_xy)
        cols = [self.columns[int(i)] for i in idx]
        used = _sorted_union([c[0] for c in cols])
        xyz, normal, area = (a[used] for a in self._table())
        points = np.zeros((len(used), len(idx)))
        var = np.full((len(used), len(idx)), np.inf)
        for j, (ids, pts, v) in enumerate(cols):
            rows = np.searchsorted(used, ids)
            points[rows, j], var[rows, j] = pts, v
        return Surfaces(
            xyz=xyz,
            normal=normal,
            points=points,
            var_mm2=var,
            area_m2=area,
            station_xyz=np.column_stack([cand_xy[idx], self.ctx.station_z(cand_xy[idx])]),
        )

    def link(self, parent: int, child: int, cand_xy: np.ndarray) -> CloudLink:
        """The cloud-to-cloud registration of candidate ``child`` to candidate ``parent``, as
        the link model gives it (its rehearsal, where made, is kept in :attr:`checks`)."""
        if (parent, child) not in self.links:
            pair = self.take(np.array([parent, child]), cand_xy)
            self.links[(parent, child)] = cloud_link(self.ctx, pair, 0, 1)
        return self.links[(parent, child)]

    def check(self, parent: int, child: int, cand_xy: np.ndarray) -> LinkCheck | None:
        """Rehearse the link of candidate ``child`` to ``parent`` (once for a plan:
        :func:`~planner.pipeline.network.linkcheck.rehearse_link`, from the scanner's
        pre-alignment, over the patches both see); None where the link model already says
        its surfaces do not fix it."""
        key = (parent, child)
        cl = self.link(parent, child, cand_xy)
        self.asked.add(key)
        if key in self.checks or not cl.fixed:
            return self.checks.get(key)
        ctx = self.ctx
        st = ctx.settings
        if self._world is None:
            self._world = World.of(ctx.site, ctx.scanner, st, ctx.scene)
        pair = self.take(np.array([parent, child]), cand_xy)
        both = (pair.points[:, 0] > 0) & (pair.points[:, 1] > 0)
        self.checks[key] = rehearse_link(
            self._world,
            pair.station_xyz[0],
            pair.station_xyz[1],
            pair.xyz[both],
            StartError(*ctx.scanner.start_error),
            spacing_mm=st.cloud_spacing_mm,
            floor=(st.cloud_floor_mm, float(np.hypot(st.cloud_floor_mm, RELIEF_FLOOR_MM)),
                   FLOOR_CELL_M),
            seed=int(parent) * 100_003 + int(child),
        )  # fmt: skip
        return self.checks[key]

    def overlapping(self, idx: np.ndarray, cand_xy: np.ndarray, min_pct: float) -> np.ndarray:
        """(K, K) whether the scans of candidates ``idx`` overlap by ``min_pct`` [%] or more
        (the overlap of :func:`overlap_matrix`), for the searches for linking stations over
        many candidates. The surface every pair holds in common is kept for the plan (sparse
        products for the candidates not seen yet), and so is the answer: each pair's overlap
        is computed once, with the same operands as over the whole matrix."""
        idx = np.asarray(idx, dtype=np.int64)
        self._compute(idx, cand_xy)
        new = [int(i) for i in dict.fromkeys(idx.tolist()) if i not in self._row]
        if new:
            area = self._table()[2]
            every = [*self._row, *new]
            seen = self._seen_matrix(every)  # (N, P)
            fresh = (seen[len(self._row) :] @ sp.diags(area) @ seen.T).toarray()
            n = len(self._row)
            common = np.zeros((len(every), len(every)), dtype=np.float32)
            common[:n, :n] = self._common
            common[n:, :] = fresh
            common[:n, n:] = fresh[:, :n].T
            self._common = common
            self._total = np.concatenate([self._total, seen[n:] @ area])
            self._row.update({c: n + k for k, c in enumerate(new)})
        if new or min_pct != self._over_pct:
            old = len(self._over) if min_pct == self._over_pct else 0
            over = np.zeros(self._common.shape, dtype=bool)
            over[:old, :old] = self._over[:old, :old]
            c, t = self._common, self._total
            # the new rows against every column, then the old rows against the new columns
            over[old:] = _overlaps(c[old:], t[old:, None], c[:, old:].T, t[None, :], min_pct)
            over[:old, old:] = _overlaps(
                c[:old, old:], t[:old, None], c[old:, :old].T, t[None, old:], min_pct
            )
            self._over, self._over_pct = over, min_pct
        rows = np.array([self._row[int(i)] for i in idx], dtype=np.int64)
        return self._over[np.ix_(rows, rows)]

    def wall_axes(self, idx: np.ndarray, cand_xy: np.ndarray) -> np.ndarray:
        """(K,) which of four 45° classes of wall direction (normals modulo 180°) each
        candidate sees, as bits: two scans whose common walls fall in one class share no two
        walls that are not parallel — with the ground they leave a shift free."""
        idx = np.asarray(idx, dtype=np.int64)
        self._compute(idx, cand_xy)
        return np.array([self._axes[int(i)] for i in idx], dtype=np.int64)

    def _seen_matrix(self, idx: list[int]) -> sp.csr_matrix:
        """(len(idx), P) which patches candidates ``idx`` see."""
        cols = [self.columns[i][0] for i in idx]
        which = np.repeat(np.arange(len(idx)), [len(c) for c in cols])
        rows = np.concatenate(cols) if cols else np.empty(0, np.int64)
        return sp.csr_matrix((np.ones(len(rows)), (which, rows)), shape=(len(idx), self._n))

    def _table(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Every patch's centre, normal and area, joined once after new ones came."""
        if len(self._xyz) > 1:
            self._xyz, self._normal, self._area = (
                [np.concatenate(a)] for a in (self._xyz, self._normal, self._area)
            )
        return self._xyz[0], self._normal[0], self._area[0]

    def _compute(self, idx: np.ndarray, cand_xy: np.ndarray) -> None:
        """The patches of the candidates ``idx`` not seen yet."""
        new = [int(i) for i in dict.fromkeys(np.asarray(idx).tolist()) if i not in self.columns]
        if not new:
            return
        ctx, sc, st = self.ctx, self.ctx.scanner, self.ctx.settings
        station_xy = cand_xy[new]
        station_z = ctx.station_z(station_xy)
        f_points, f_var = _facade_patches(ctx, station_xy, self._parametric)
        for j, (c, sxy) in enumerate(zip(new, station_xy, strict=True)):
            f_ids = np.flatnonzero(f_points[:, j] > 0)
            g_xy = self._cells_near(sxy)
            g_z = ctx.scene.ground_z(g_xy)
            height = station_z[j] - g_z  # the scanner's height over each cell
            d = np.hypot(*(g_xy - sxy).T)
            s = np.hypot(d, height)
            near = s >= sc.min_range_m
            g_xy, g_z, s, height = g_xy[near], g_z[near], s[near], height[near]
            src = np.column_stack(
                [np.broadcast_to(sxy, g_xy.shape), np.full(len(g_xy), station_z[j])]
            )
            box = (
                np.array([0, len(g_xy)]),
                np.array([[*(sxy - GROUND_REACH_M), *(sxy + GROUND_REACH_M)]]),
            )
            # a cell's sight line ends on the ground: just above it where rays answer (the
            # terrain's own triangles would block a line ending on them)
            lift = 0.0 if ctx.scene.prisms else GROUND_LIFT_M
            open_ = ctx.scene.seen(src, np.column_stack([g_xy, g_z + lift]), groups=box)
            g_xy, s, height = g_xy[open_], s[open_], height[open_]
            sin_e = height / s
            # the beam meets the ground at θ = 90° − elevation
            m_s = sc.range_rms_on(s, np.nan, sin_e if st.incidence_ranging else 1.0)
            sigma2 = (m_s * sin_e) ** 2 + (
                s * 1000.0 * sc.tilt_rms_arcsec / RHO_ARCSEC * np.sqrt(1.0 - sin_e**2)
            ) ** 2
            g_pts = registration_points(
                GROUND_CELL_M**2,
                sin_e,
                point_spacing_mm(s, step_mm_at_10m=ctx.step_mm_at_10m),
                st.cloud_spacing_mm,
            )
            use = g_pts > 0  # grazing ground gives a registration nothing
            g_xy, g_pts, sigma2 = g_xy[use], g_pts[use], sigma2[use]
            g_ids = self._ground_ids(g_xy)
            r_ids, r_pts, r_var = self._relief(f_ids, np.array([*sxy, station_z[j]]))
            walls = np.unique(self._axis[f_ids])
            if len(r_ids):  # a wall's reveals run along it: its square class too
                on = (r_ids - len(ctx.facades.z)) // 3  # the samples whose reveals it sees
                walls = np.union1d(walls, (self._axis[on] + 2) % 4)
            self._axes[c] = int(np.bitwise_or.reduce(1 << walls, initial=0))
            self.columns[c] = (
                np.concatenate([f_ids, r_ids, g_ids]),
                np.concatenate([f_points[f_ids, j], r_pts, g_pts]),
                np.concatenate(
                    [
                        f_var[f_ids, j],
                        r_var,
                        patch_variance_mm2(
                            np.sqrt(sigma2), g_pts, st.cloud_floor_mm, floor_units(GROUND_CELL_M**2)
                        ),
                    ]
                ),
            )

    def _relief(
        self, f_ids: np.ndarray, station: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The relief patches (ids, points, variance along their normals [mm²]) a station at
        ``station`` (3,) sees on the facade samples ``f_ids`` it sees: a jamb from the side it
        faces and to the depth the opening lets it see, the head from below
        (:mod:`planner.cloud_registration`)."""
        f_ids = f_ids[self._parametric[f_ids]]
        if not self._relief_area[0] or not len(f_ids):
            empty = np.empty(0)
            return empty.astype(np.int64), empty, empty
        ctx, sc, st = self.ctx, self.ctx.scanner, self.ctx.settings
        fac = ctx.facades
        v = station - self._xyz_of(f_ids)  # (K, 3) towards the scanner [m]
        s = np.linalg.norm(v, axis=1)
        normals = self._relief_normal[f_ids]  # (K, 3, 3)
        cos = np.einsum("kd,krd->kr", v, normals) / s[:, None]
        front = np.maximum(np.einsum("kd,kd->k", v[:, :2], fac.normal[fac.facade[f_ids]]), 1e-9)
        # the openings' width hides a jamb, their height a head, at grazing angles
        widths = np.array([WINDOW_WIDTH_M, WINDOW_WIDTH_M, WINDOW_HEIGHT_M])
        seen = reveal_visible(np.abs(cos) * (s / front)[:, None], st.reveal_depth_m, widths)
        spacing = point_spacing_mm(s, step_mm_at_10m=ctx.step_mm_at_10m)
        cos_c = np.clip(cos, 0.0, 1.0)
        # the thinned cloud on a reveal: its rows across the depth it shows, the row along
        # its edge with the wall (whose neighbourhoods straddle two faces) giving no plane
        # (planner.cloud_registration)
        along, across = registration_spacing(spacing[:, None], cos_c, st.cloud_spacing_mm)
        rows = seen * st.reveal_depth_m * 1000.0 / along
        usable = np.clip((rows - 1.0) / np.maximum(rows, 1e-9), 0.0, 1.0)
        pts = self._relief_area * seen * usable * 1e6 / (along * across)
        rho = ctx.reflectance[f_ids] if len(ctx.reflectance) else np.nan
        signal_cos = np.maximum(cos_c, 1e-3) if st.incidence_ranging else 1.0
        m_s = sc.range_rms_on(s[:, None], np.reshape(rho, (-1, 1)), signal_cos)
        # across the beam: the horizontal angle on a jamb, the vertical one on a head
        angles = np.array([sc.angle_rms_arcsec, sc.angle_rms_arcsec, sc.tilt_rms_arcsec])
        lateral = s[:, None] * 1000.0 * angles / RHO_ARCSEC  # mm
        sigma2 = np.square(m_s * cos_c) + np.square(lateral) * (1.0 - cos_c**2)
        ok = (rows >= MIN_POINTS_ACROSS) & (pts >= MIN_RELIEF_POINTS)
        ids = len(fac.z) + 3 * f_ids[:, None] + np.arange(3)
        floor = np.hypot(st.cloud_floor_mm, RELIEF_FLOOR_MM)
        openings = np.broadcast_to(self._openings, pts.shape)[ok]  # the floor's units
        var = patch_variance_mm2(np.sqrt(sigma2[ok]), pts[ok], floor, openings)
        return ids[ok], pts[ok], var

    def _xyz_of(self, f_ids: np.ndarray) -> np.ndarray:
        """Centres of facade samples ``f_ids`` (3-D) [m]."""
        fac = self.ctx.facades
        return np.column_stack([fac.xy[f_ids], fac.z[f_ids]])

    def _cells_near(self, sxy: np.ndarray) -> np.ndarray:
        """Centres of the grid's ground cells within reach of ``sxy`` outside buildings."""
        lo = np.floor((sxy - GROUND_REACH_M) / GROUND_CELL_M)
        hi = np.ceil((sxy + GROUND_REACH_M) / GROUND_CELL_M)
        gx, gy = np.meshgrid(np.arange(lo[0], hi[0]), np.arange(lo[1], hi[1]))
        xy = (np.column_stack([gx.ravel(), gy.ravel()]) + 0.5) * GROUND_CELL_M
        xy = xy[np.hypot(*(xy - sxy).T) <= GROUND_REACH_M]
        if not self._solid.is_empty and len(xy):
            xy = xy[~shapely.contains_xy(self._solid, xy[:, 0], xy[:, 1])]
        return xy

    def _ground_ids(self, g_xy: np.ndarray) -> np.ndarray:
        """Patch indices of ground cells (centres ``g_xy``), new cells appended."""
        cells = np.floor(g_xy / GROUND_CELL_M).astype(np.int64).reshape(-1, 2)
        keys = cells[:, 0] * _CELL_KEY + cells[:, 1]  # one integer per cell
        at = np.searchsorted(self._cell_keys, keys)
        known = at < len(self._cell_keys)
        known[known] = self._cell_keys[at[known]] == keys[known]
        if not known.all():  # new cells, numbered in the order they first come
            _, first = np.unique(keys[~known], return_index=True)
            fresh = cells[~known][np.sort(first)]
            centres = (fresh + 0.5) * GROUND_CELL_M
            self._xyz.append(np.column_stack([centres, np.zeros(len(fresh))]))
            self._normal.append(np.tile([0.0, 0.0, 1.0], (len(fresh), 1)))
            self._area.append(np.full(len(fresh), GROUND_CELL_M**2))
            ids = np.concatenate([self._cell_ids, self._n + np.arange(len(fresh))])
            every = np.concatenate([self._cell_keys, fresh[:, 0] * _CELL_KEY + fresh[:, 1]])
            order = np.argsort(every, kind="stable")
            self._cell_keys, self._cell_ids = every[order], ids[order]
            self._n += len(fresh)
            at = np.searchsorted(self._cell_keys, keys)
        return self._cell_ids[at]


def _overlaps(common_parent, total_parent, common_child, total_child, min_pct) -> np.ndarray:
    """Whether :func:`~planner.cloud_registration.overlap_pct` of the surfaces in common (kept
    as float32, taken exactly as float64) reaches ``min_pct``."""
    parent, child = common_parent.astype(float), common_child.astype(float)
    return overlap_pct(parent, total_parent, child, total_child) >= min_pct


#: A ground cell (i, j) as one integer, i·_CELL_KEY + j: distinct for |j| < _CELL_KEY / 2,
#: and within int64 for |i| < 2³¹ (cells of 2 m: coordinates within ±4 000 000 km).
_CELL_KEY = 1 << 32


def _sorted_union(ids: list[np.ndarray]) -> np.ndarray:
    """The patch indices in any of ``ids`` (each without repeats), sorted: ``np.unique`` of
    them joined, by a sort (NumPy's hashing ``unique`` is slower on these)."""
    if not ids:
        return np.empty(0, dtype=np.int64)
    joined = np.sort(np.concatenate(ids))
    first = np.ones(len(joined), dtype=bool)
    first[1:] = joined[1:] != joined[:-1]
    return joined[first]


def _facade_patches(
    ctx: Context, station_xy: np.ndarray, parametric: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """(N, K) scan points on every facade patch from each station (0: not seen) and the
    variance of the patch's position across its wall [mm²] (infinite where not seen)."""
    st = ctx.settings
    dense = evaluate_stations(ctx, station_xy)
    view = dense["view"] & np.isfinite(dense["scanner_m_y_mm"])
    slope = np.where(view, dense["slope_distance_m"], 1.0)
    cos_inc = np.where(view, np.cos(np.radians(np.nan_to_num(dense["incidence_deg"]))), 0.0)
    # the parametric facade's openings return nothing from their glass
    area = st.sample_spacing_m * st.sample_height_step_m
    area = area * np.where(parametric, 1.0 - st.window_share, 1.0)[:, None]
    spacing = point_spacing_mm(slope, step_mm_at_10m=ctx.step_mm_at_10m)
    points = registration_points(area, cos_inc, spacing, st.cloud_spacing_mm)
    points = np.where(view, points, 0.0)
    # the floor: what a plane fit does not see, and the wall's own roughness (its material)
    floor = np.hypot(st.cloud_floor_mm, roughness_mm(ctx.material, st.material_table))[:, None]
    var = patch_variance_mm2(
        np.nan_to_num(dense["scanner_m_y_mm"], nan=1.0),
        np.maximum(points, 1.0),
        floor,
        floor_units(area),
    )
    return points, np.where(points > 0, var, np.inf)


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
    seen_p, seen_c = surf.points[:, parent] > 0, surf.points[:, child] > 0
    both = np.flatnonzero(seen_p & seen_c)
    rows = plane_rows(surf.xyz[both], surf.normal[both], surf.station_xyz[child])
    info = link_information(rows, surf.var_mm2[both, parent], surf.var_mm2[both, child])
    sc = ctx.scanner
    levelled = sc.is_levelled
    prior = start_information(sc.start_error)
    cov = link_covariance(
        # a link relative to its parent: the two stations' tilts levelled, none without a
        # compensator (6 parameters take them out; the datum's lean is the network's); the
        # registration starts from the pre-alignment, and stays there where the surfaces
        # fix nothing (planner.cloud_registration)
        info + prior,
        levelled=levelled,
        tilt_rms_arcsec=sc.initial_tilt_rms_arcsec if levelled else 0.0,
    )
    area = surf.area_m2
    common = area[both].sum()
    ov = overlap_pct(common, area[seen_p].sum(), common, area[seen_c].sum())
    return CloudLink(
        parent=parent,
        child=child,
        info=info,
        cov=cov,
        overlap_pct=float(ov),
        condition=link_strength(info, levelled=levelled)[0],
        patches=len(both),
        prior=prior,
        levelled=levelled,
    )
