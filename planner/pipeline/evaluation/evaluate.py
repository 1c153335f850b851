"""Candidate × sample evaluation: sight geometry, line of sight, predicted RMS, requirements.

For every candidate station and facade sample: horizontal distance D, slope distance S,
deviation γ, tilt ν, line of sight (:mod:`planner.pipeline.geometry.visibility`), the scanner's
range and vertical field of view, m_x, m_y (eq. 2 of Voroshilov & Karachentsev, ranging RMS at the
measured slope distance S), m_z (eq. 4, S_0 = S) and the point spacing on the facade — each
through the science layer's array kernels. Whether a pair meets the requirements is decided
by the table :data:`~planner.pipeline.inputs.requirements.CHECKS`, against per-sample limits.

Vectorised per facade and chunked over candidates so memory stays bounded; no trigonometry
on the geometry (cos γ and sin ν come from dot products).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
import scipy.sparse as sp

from planner.accuracy import eq2_variances, eq4_variance
from planner.accuracy3d import footprint_mm, variances_3d
from planner.materials import reflectances
from planner.pipeline.geometry.candidates import GroundRegions
from planner.pipeline.geometry.facades import MERGE_OFFSET_M, SIGHT_OFFSET_M, FacadeSet
from planner.pipeline.geometry.scene import Scene
from planner.pipeline.geometry.visibility import (
    bridge_interval,
    clear_height,
    edges_in_box,
    edges_in_front,
    ends_ahead,
    own_edges,
    visible,
)
from planner.pipeline.geometry.zoning import SampleRequirements
from planner.pipeline.inputs.requirements import CHECKS, Check, PlanSettings, Requirements
from planner.pipeline.inputs.schema import METRIC_KEYS
from planner.polar import separated_directions
from planner.registration_error import pair_registration_variances
from planner.scanner import Scanner
from planner.site import Site
from planner.spacing import facade_spacing_kernel

__all__ = [
    "Assignment",
    "CandidateEvaluation",
    "Context",
    "PairMetrics",
    "Registration",
    "assign_stations",
    "best_achievable",
    "evaluate_candidates",
    "evaluate_stations",
]

Progress = Callable[[float, str], None]

#: Candidate × sample pairs evaluated at once: ~20 float arrays of this many stay in cache.
PAIR_CHUNK = 65_536

#: Clear heights kept between the evaluations of a plan (float64 values: 80 MB at most).
MAX_KEPT_CLEAR = 10_000_000


class ClearanceStore:
    """Lines of sight kept between the evaluations of a plan (clear heights, or the rays'
    answers), at most :data:`MAX_KEPT_CLEAR` values in all."""

    def __init__(self) -> None:
        self.kept: dict[tuple[int, bytes], Clearance | tuple[np.ndarray, np.ndarray]] = {}
        self.values = 0

    def keep(self, key: tuple[int, bytes], clearance, size: int) -> None:
        """Keep ``clearance`` (``size`` values) under ``key`` while the cap allows."""
        if self.values + size <= MAX_KEPT_CLEAR:
            self.kept[key] = clearance
            self.values += size


@dataclass(kw_only=True)
class Context:
    """Everything the evaluation needs, prepared once per plan."""

    site: Site
    facades: FacadeSet
    scanner: Scanner
    req: Requirements
    settings: PlanSettings
    reach_m: float
    scene: Scene  # every sight line is answered here
    edge_mask: list[np.ndarray]  # per facade: edges that can block its sight lines
    #: per facade: how far in front of it its rays end [m] (:data:`SIGHT_OFFSET_M`, and in
    #: front of the curved run of edges a merged facade stands for)
    ray_end_m: np.ndarray
    cols_of: list[np.ndarray]  # per facade: its columns
    samples_of: list[np.ndarray]  # per facade: its samples
    step_mm_at_10m: float
    limits: dict[str, np.ndarray]  # per check key: (N,) limit of every sample (±inf: none)
    stations_needed: np.ndarray  # (N,) stations (separate views) each sample needs
    #: (N,) each sample's material (:mod:`planner.materials`; "" none known) and its
    #: reflectance on the survey day (NaN: the scanner datasheet's reference surface)
    material: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=object))
    reflectance: np.ndarray = field(default_factory=lambda: np.zeros(0))
    #: clear heights of the candidate chunks evaluated on every sample of a facade, kept for
    #: the plan's next evaluation of all candidates (:meth:`clear_heights`); one store, with
    #: its count, shared by a context copied with other limits (the best-effort relaxation)
    _clear: ClearanceStore = field(default_factory=ClearanceStore, repr=False)

    @classmethod
    def build(
        cls,
        site: Site,
        facades: FacadeSet,
        scanner: Scanner,
        req: Requirements,
        settings: PlanSettings,
        reach: float,
        sample_req: SampleRequirements | None = None,
        scene: Scene | None = None,
    ) -> Context:
        """Everything the evaluation needs; ``sample_req`` the requirement of every sample
        (:func:`planner.pipeline.geometry.zoning.apply_zones`; default: ``req`` everywhere);
        ``scene`` the sight lines' (made for ``site`` with the settings' engine when not
        given)."""
        scene = scene or Scene(site, settings.sight_engine)
        masks, ahead = [], []
        for f in range(facades.n_facades):
            a, e = facades.start[f], facades.end[f]
            bbox = (
                min(a[0], e[0]) - reach,
                min(a[1], e[1]) - reach,
                max(a[0], e[0]) + reach,
                max(a[1], e[1]) + reach,
            )
            n = facades.normal[f]
            own = own_edges(scene.edges, a, n, e, MERGE_OFFSET_M)
            masks.append(np.flatnonzero(edges_in_front(scene.edges, a, n, bbox) & ~own))
            # a facade merged from a curved run of edges stands behind them: its rays end in
            # front of the run (a single edge: the facade itself, 0 m ahead)
            ahead.append(
                max(0.0, *(d.max(initial=0.0) for d in ends_ahead(scene.edges[own], a, n)))
            )
        sample_req = sample_req or SampleRequirements.uniform(req, len(facades.z))
        return cls(
            site=site,
            facades=facades,
            scanner=scanner,
            req=req,
            settings=settings,
            reach_m=reach,
            scene=scene,
            edge_mask=masks,
            ray_end_m=SIGHT_OFFSET_M + np.array(ahead, dtype=float),
            cols_of=facades.per_facade(facades.col_facade),
            samples_of=facades.per_facade(facades.facade),
            step_mm_at_10m=settings.scan_step_mm(scanner),
            limits=sample_req.limits,
            stations_needed=sample_req.stations,
            material=sample_req.material,
            reflectance=reflectances(
                sample_req.material, settings.material_table, settings.surface_condition
            ),
        )

    @property
    def edges(self) -> np.ndarray:
        """(M, 4) every blocking footprint edge (the scene's)."""
        return self.scene.edges

    @property
    def edge_heights(self) -> np.ndarray:
        """(M,) the top of each edge [m] (the scene's)."""
        return self.scene.edge_heights

    @property
    def bridges(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The floors over passages: edges, bottoms, tops (the scene's)."""
        return self.scene.bridges

    @cached_property
    def regions(self) -> GroundRegions:
        """The site's open ground in connected regions (closed courtyards apart)."""
        return GroundRegions(self.site)

    def station_z(self, xy: np.ndarray) -> np.ndarray:
        """Heights of scanner centres standing at ``xy`` (P, 2) [m]: the instrument height
        above the ground."""
        return self.scene.above_ground(xy, self.settings.instrument_height_m)

    def ahead(self, f: int, xy: np.ndarray, z: np.ndarray | None = None) -> np.ndarray:
        """Which scanner centres at ``xy`` (P, 2) (heights ``z``, default the stations')
        are in front of facade ``f``'s plane."""
        fac = self.facades
        rel = xy - fac.start[f]
        if not fac.tilted[f]:
            return rel @ fac.normal[f] > 0
        z = self.station_z(xy) if z is None else z
        n3 = fac.normal3[f]
        return rel @ n3[:2] + (z - fac.z0[f]) * n3[2] > 0

    def front_candidates(self, f: int, cand_xy: np.ndarray) -> np.ndarray:
        """Indices of candidates in front of facade ``f`` and within reach of it."""
        a, e = self.facades.start[f], self.facades.end[f]
        rel = cand_xy - a
        ahead = self.ahead(f, cand_xy)
        v = e - a
        t = np.clip(rel @ v / (v @ v), 0.0, 1.0)
        dist = np.hypot(*(rel - t[:, None] * v).T)
        return np.flatnonzero(ahead & (dist <= self.reach_m))

    def clear_heights(self, f: int, cand_xy: np.ndarray, keep: bool = False) -> Clearance:
        """Line of sight from ``cand_xy`` to facade ``f``'s columns: the (c, k) lowest
        visible height [m] (:func:`~planner.pipeline.geometry.visibility.clear_height`) and, where
        a passage's floors can be crossed, the heights they hide
        (:func:`~planner.pipeline.geometry.visibility.bridge_interval`). ``keep`` keeps it for the
        same facade and candidates again (while :data:`MAX_KEPT_CLEAR` values are kept)."""
        key = (f, cand_xy.tobytes())
        if key in self._clear.kept:
            return self._clear.kept[key]
        fac, cols = self.facades, self.cols_of[f]
        em = self.edge_mask[f]
        if len(em):
            lo_xy = np.minimum(cand_xy.min(axis=0), np.minimum(fac.start[f], fac.end[f]))
            hi_xy = np.maximum(cand_xy.max(axis=0), np.maximum(fac.start[f], fac.end[f]))
            em = em[edges_in_box(self.edges[em], (*lo_xy, *hi_xy))]
        target = fac.col_xy[cols] + SIGHT_OFFSET_M * fac.normal[f]
        c, k = len(cand_xy), len(cols)
        src, dst = np.repeat(cand_xy, k, axis=0), np.tile(target, (c, 1))
        hi = self.settings.instrument_height_m
        zc = clear_height(src, hi, dst, self.edges[em], self.edge_heights[em]).reshape(c, k)
        out = Clearance(zc)
        b_edges, bottoms, tops = self.bridges
        if len(b_edges):
            lo_xy = np.minimum(cand_xy.min(axis=0), np.minimum(fac.start[f], fac.end[f]))
            hi_xy = np.maximum(cand_xy.max(axis=0), np.maximum(fac.start[f], fac.end[f]))
            near = edges_in_box(b_edges, (*lo_xy, *hi_xy))
            if near.any():
                lo, up = bridge_interval(src, hi, dst, b_edges[near], bottoms[near], tops[near])
                out = Clearance(zc, lo.reshape(c, k), up.reshape(c, k))
        if keep:
            self._clear.keep(key, out, zc.size)
        return out

    def sees(
        self,
        f: int,
        cand_xy: np.ndarray,
        smp: np.ndarray,
        keep: bool = False,
        where: np.ndarray | None = None,
        cand_z: np.ndarray | None = None,
    ) -> np.ndarray:
        """(c, n) whether scanners standing at ``cand_xy`` see the samples ``smp`` of facade
        ``f`` (the scene's engine: per column on prisms, :meth:`clear_heights`; per sample
        by rays, ending :data:`SIGHT_OFFSET_M` in front of the wall, cast only for the pairs
        ``where`` (c, n) is True — in front, in range: the others read False; ``cand_z``
        the scanners' heights where known). ``keep`` keeps the answer for the same facade
        and candidates again."""
        fac = self.facades
        if self.scene.prisms:
            col_local = np.searchsorted(self.cols_of[f], fac.column[smp])
            return self.clear_heights(f, cand_xy, keep).sees(fac.z[smp], col_local)
        mine = self.samples_of[f]
        c, n = len(cand_xy), len(smp)
        pairs = np.ones((c, n), dtype=bool) if where is None else where
        key = (f, cand_xy.tobytes())
        kept = self._clear.kept.get(key)
        if kept is None:  # which pairs of the facade's samples are cast, and their answers
            kept = (np.zeros((c, len(mine)), dtype=bool), np.zeros((c, len(mine)), dtype=bool))
            if keep:
                self._clear.keep(key, kept, kept[0].size // 4 + 1)
        known, seen = kept
        cols = np.searchsorted(mine, smp)
        todo = pairs & ~known[:, cols]
        if todo.any():
            ci, si = np.nonzero(todo)
            zs = self.station_z(cand_xy) if cand_z is None else cand_z  # (per candidate)
            src = np.column_stack([cand_xy[ci], zs[ci]])
            dst = np.column_stack([fac.xy[smp[si]], fac.z[smp[si]]])
            seen[ci, cols[si]] = self.scene.seen(src, dst + self.ray_end_m[f] * fac.normal3[f])
            known[ci, cols[si]] = True
        return pairs & seen[:, cols]

    def pair_count(self, cand_xy: np.ndarray) -> int:
        """How many candidate × sample pairs the evaluation will compute (the work)."""
        return int(
            sum(
                len(self.front_candidates(f, cand_xy)) * len(self.samples_of[f])
                for f in range(self.facades.n_facades)
            )
        )

    def active_checks(self, smp: np.ndarray) -> list[tuple[Check, np.ndarray]]:
        """The checks with a limit at any of ``smp``, with those samples' limits (1, n)."""
        out = []
        for c in CHECKS:
            lim = self.limits[c.key][smp]
            if np.isfinite(lim).any():
                out.append((c, lim[None, :]))
        return out


@dataclass(frozen=True)
class Clearance:
    """Line of sight from c stations to the k columns of a facade: the lowest height seen
    (c, k) and, where a passage's floors can be crossed, the heights they hide ``[lo, up)``
    (:mod:`planner.pipeline.geometry.visibility`)."""

    zc: np.ndarray
    lo: np.ndarray | None = None
    up: np.ndarray | None = None

    def sees(self, z: np.ndarray, col: np.ndarray) -> np.ndarray:
        """(c, n): which of the samples at heights ``z`` in columns ``col`` are seen."""
        if self.lo is None:
            return visible(z, self.zc[:, col])
        return visible(z, self.zc[:, col], self.lo[:, col], self.up[:, col])


class PairMetrics:
    """Metrics of ``c`` candidates × ``n`` samples of one facade (arrays of shape (c, n)).

    The geometry and the variances are computed up front; the quantities the checks and the
    reports read (``m_x_mm``, ``gamma_deg``, ``spacing_mm``…) on first use.
    """

    def __init__(
        self,
        *,
        distance_m: np.ndarray,
        slope_distance_m: np.ndarray,
        cos_gamma: np.ndarray,
        sin_nu: np.ndarray,
        var_x: np.ndarray,
        var_y: np.ndarray,
        var_z: np.ndarray,
        view: np.ndarray,
        step_mm_at_10m: float,
        beam: Scanner | None = None,
        cos_incidence: np.ndarray | None = None,
        sight: Callable[[np.ndarray], np.ndarray] | None = None,
    ) -> None:
        self.distance_m = distance_m
        self.slope_distance_m = slope_distance_m
        self.cos_gamma = cos_gamma
        self.sin_nu = sin_nu
        self.var_x, self.var_y, self.var_z = var_x, var_y, var_z
        # sees the sample: in front, range, field of view and the line of sight — or, with
        # ``sight``, the line of sight asked of it when first needed (:meth:`seen_where`)
        self._view = view
        self._sight = sight
        self.step_mm_at_10m = step_mm_at_10m
        self.beam = beam  # the scanner whose beam footprint the model counts, if it does
        self.scanner_var = (var_x, var_y, var_z)
        self.reg_var = (0.0, 0.0, 0.0)
        self.untied = np.zeros((1, 1), dtype=bool)  # stations not tied to the datum
        if cos_incidence is not None:  # a sloping wall's: not cos γ · cos ν
            self.__dict__["cos_incidence"] = cos_incidence

    def add_registration(
        self,
        var_x: np.ndarray,
        var_y: np.ndarray,
        var_z: np.ndarray,
        *,
        untied: np.ndarray | None = None,
    ) -> None:
        """Add the registration's variances (c, n): m_x, m_y, m_z become the totals, the
        scanner's and the registration's parts stay readable. A station not tied to the
        datum (``untied``, (c, 1)) meets nothing; its registration part reads NaN. Call
        before reading the metrics."""
        if untied is not None:
            self.untied = untied
            var_x, var_y, var_z = (np.where(untied, 0.0, v) for v in (var_x, var_y, var_z))
        self.reg_var = (var_x, var_y, var_z)
        self.var_x = self.scanner_var[0] + var_x
        self.var_y = self.scanner_var[1] + var_y
        self.var_z = self.scanner_var[2] + var_z
        for name in ("m_x_mm", "m_y_mm", "m_z_mm"):
            self.__dict__.pop(name, None)

    @property
    def view(self) -> np.ndarray:
        """(c, n) whether each station sees each sample."""
        if self._sight is not None:
            self._view = self._view & self._sight(self._view)
            self._sight = None
        return self._view

    def seen_where(self, where: np.ndarray) -> np.ndarray:
        """``where`` & :attr:`view`, asking the line of sight of those pairs only (the
        pairs a check already rules out are not cast)."""
        if self._sight is None:
            return where & self._view
        where = where & self._view
        return where & self._sight(where)

    @property
    def scanner_m_x_mm(self) -> np.ndarray:
        return np.sqrt(self.scanner_var[0])

    @property
    def scanner_m_y_mm(self) -> np.ndarray:
        return np.sqrt(self.scanner_var[1])

    @property
    def scanner_m_z_mm(self) -> np.ndarray:
        return np.sqrt(self.scanner_var[2])

    @property
    def reg_m_x_mm(self) -> np.ndarray:
        reg = np.sqrt(np.broadcast_to(self.reg_var[0], self._view.shape))
        return np.where(self.untied, np.nan, reg)

    @property
    def reg_m_y_mm(self) -> np.ndarray:
        reg = np.sqrt(np.broadcast_to(self.reg_var[1], self._view.shape))
        return np.where(self.untied, np.nan, reg)

    @property
    def reg_m_z_mm(self) -> np.ndarray:
        reg = np.sqrt(np.broadcast_to(self.reg_var[2], self._view.shape))
        return np.where(self.untied, np.nan, reg)

    @cached_property
    def cos_incidence(self) -> np.ndarray:
        """cos θ = cos γ · cos ν, θ the 3-D incidence on the (vertical) facade (a sloping
        wall's is given by :func:`facade_pairs`)."""
        with np.errstate(divide="ignore", invalid="ignore"):
            cos_nu = np.where(
                self.slope_distance_m > 0, self.distance_m / self.slope_distance_m, 1.0
            )
        return self.cos_gamma * cos_nu

    @cached_property
    def incidence_deg(self) -> np.ndarray:
        return np.degrees(np.arccos(np.clip(self.cos_incidence, -1.0, 1.0)))

    @cached_property
    def m_x_mm(self) -> np.ndarray:
        return np.sqrt(self.var_x)

    @cached_property
    def m_y_mm(self) -> np.ndarray:
        return np.sqrt(self.var_y)

    @cached_property
    def m_z_mm(self) -> np.ndarray:
        return np.sqrt(self.var_z)

    @cached_property
    def gamma_deg(self) -> np.ndarray:
        return np.degrees(np.arccos(np.clip(self.cos_gamma, -1.0, 1.0)))

    @cached_property
    def nu_deg(self) -> np.ndarray:
        return np.degrees(np.arcsin(np.clip(self.sin_nu, -1.0, 1.0)))

    @cached_property
    def spacing_mm(self) -> np.ndarray:
        """The point spacing on the facade; where the model counts the beam's footprint,
        the larger of the spacing and the footprint (the finest detail resolved)."""
        spacing = facade_spacing_kernel(
            self.distance_m, self.slope_distance_m, self.cos_gamma, self.step_mm_at_10m
        )
        if self.beam is None:
            return spacing
        footprint = footprint_mm(self.slope_distance_m, self.beam, self.cos_incidence)
        return np.maximum(spacing, footprint)

    def value(self, metric: str) -> np.ndarray:
        return getattr(self, metric)


def _pair_variances(
    ctx: Context,
    d: np.ndarray,
    s: np.ndarray,
    cos_g: np.ndarray,
    sin_nu: np.ndarray,
    cos_theta: np.ndarray,
    reflectance: np.ndarray,
    own_level: bool,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, Scanner | None]:
    """The scanner's part of each pair's variances σ_x², σ_y², σ_z² [mm²] by the settings'
    model — eq. 2 and 4 of Voroshilov & Karachentsev, or the full 3-D propagation with its
    optional terms (:func:`planner.accuracy3d.variances_3d`) — and the scanner whose beam
    footprint the spacing check counts (None: not counted). The ranging RMS is the
    returned signal's (:meth:`Scanner.range_rms_on`): on the sample's ``reflectance`` (NaN:
    the datasheet's reference surface), at the 3-D incidence ``cos_theta`` where the 3-D
    model counts it. The station's own error is the registration's part, added after; the
    frame's tilt is counted here only where ``own_level`` or the settings say
    (:meth:`~planner.pipeline.inputs.requirements.PlanSettings.scan_tilt_rms_arcsec`)."""
    sc, st = ctx.scanner, ctx.settings
    m_s = sc.range_rms_on(s, reflectance, cos_theta if st.incidence_ranging else 1.0)
    no_station = (0.0, 0.0)  # the station's own error is the registration's part, below
    # the frame's tilt: here, or the registration's part
    tilt = sc.initial_tilt_rms_arcsec if own_level else st.scan_tilt_rms_arcsec(sc)
    beam = None
    if st.model == "paper":  # eq. 2 and 4 of Voroshilov & Karachentsev
        var_x, var_y = eq2_variances(d, cos_g * cos_g, m_s, sc.angle_rms_arcsec, no_station)
        var_z = eq4_variance(s, sin_nu * sin_nu, m_s, sc.tilt_rms_arcsec, s, tilt)
    else:  # the full 3-D propagation, with its optional terms
        var_x, var_y, var_z = variances_3d(
            s,
            cos_g,
            sin_nu,
            m_s,
            sc.angle_rms_arcsec,
            sc.tilt_rms_arcsec,
            tilt,
            no_station,
        )
        if st.beam_footprint and (sc.beam_divergence_mrad or sc.beam_exit_mm):
            beam = sc
    return var_x, var_y, var_z, beam


def facade_pairs(
    ctx: Context,
    f: int,
    cand_xy: np.ndarray,
    smp: np.ndarray | None = None,
    keep: bool = False,
    own_level: bool = False,
    cand_z: np.ndarray | None = None,
) -> PairMetrics:
    """Evaluate candidates ``cand_xy`` against the samples ``smp`` (default: all) of facade
    ``f``: geometry, visibility and the predicted variances (``keep``: keep the line of
    sight for the next evaluation, :meth:`Context.clear_heights`). ``own_level``: each
    candidate's scans carry its own levelling, as a scan on its own (or the datum) does —
    the stand-in for its frame's error before a registration network exists; otherwise the
    settings decide (:meth:`~planner.pipeline.inputs.requirements.PlanSettings
    .scan_tilt_rms_arcsec`)."""
    fac, sc = ctx.facades, ctx.scanner
    smp = ctx.samples_of[f] if smp is None else smp
    n = fac.normal[f]
    # sight geometry (station minus point horizontally; point minus scanner vertically)
    dx = cand_xy[:, 0:1] - fac.xy[smp, 0]
    dy = cand_xy[:, 1:2] - fac.xy[smp, 1]
    zs = ctx.station_z(cand_xy) if cand_z is None else cand_z  # the scanners' centres
    dz = fac.z[smp] - zs[:, None]
    d2 = dx * dx + dy * dy
    d = np.sqrt(d2)
    s = np.sqrt(d2 + dz * dz)
    cdot = dx * n[0] + dy * n[1]
    with np.errstate(divide="ignore", invalid="ignore"):
        cos_g = np.where(d > 0, cdot / d, 0.0)
        sin_nu = dz / s
    cos_inc = None
    front = cdot > 0
    if fac.tilted[f]:  # a sloping wall: in front of its plane, the incidence on it
        n3 = fac.normal3[f]
        towards = dx * n3[0] + dy * n3[1] - dz * n3[2]
        front = towards > 0
        with np.errstate(divide="ignore", invalid="ignore"):
            cos_inc = np.where(s > 0, towards / s, 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):  # the 3-D incidence
        cos_theta = cos_inc if cos_inc is not None else cos_g * np.where(s > 0, d / s, 1.0)
    rho = ctx.reflectance[smp][None, :] if len(ctx.reflectance) else np.nan
    # the reach on this surface at this incidence (the returned signal, planner.signal)
    reach = sc.max_range_on(rho, cos_theta if ctx.settings.incidence_ranging else 1.0)
    lo, up = np.sin(np.radians(sc.vertical_fov_deg))
    view = (
        front
        & (s >= sc.min_range_m)
        & (s <= reach)
        & (sin_nu >= lo - 1e-12)
        & (sin_nu <= up + 1e-12)
    )
    sight = None
    if ctx.scene.prisms:  # a clear height per column: every pair at once
        view &= ctx.sees(f, cand_xy, smp, keep, view)
    else:  # rays: cast when asked, for the pairs asked (:meth:`PairMetrics.seen_where`)

        def sight(where: np.ndarray) -> np.ndarray:
            return ctx.sees(f, cand_xy, smp, keep, where, zs)

    st = ctx.settings
    var_x, var_y, var_z, beam = _pair_variances(ctx, d, s, cos_g, sin_nu, cos_theta, rho, own_level)
    m = PairMetrics(
        distance_m=d,
        slope_distance_m=s,
        cos_gamma=cos_g,
        sin_nu=sin_nu,
        var_x=var_x,
        var_y=var_y,
        var_z=var_z,
        view=view,
        step_mm_at_10m=ctx.step_mm_at_10m,
        beam=beam,
        cos_incidence=cos_inc,
        sight=sight,
    )
    m_xc, m_yc = st.station_rms_pair
    if m_xc or m_yc:  # the paper's m_xc, m_yc given as a figure: the registration's part
        zero = np.zeros(view.shape)
        m.add_registration(zero + m_xc * m_xc, zero + m_yc * m_yc, zero)
    return m


def meets(ctx: Context, m: PairMetrics, smp: np.ndarray) -> np.ndarray:
    """Where a pair sees its sample and passes every check there (the table's rows); the
    line of sight is asked only of the pairs that pass the checks."""
    ok = np.ones(m._view.shape, dtype=bool)
    for check, limit in ctx.active_checks(smp):
        ok &= check.passes(m.value(check.metric), limit)
    return m.seen_where(ok)


def score(ctx: Context, m: PairMetrics, smp: np.ndarray) -> np.ndarray:
    """How far a pair is from meeting the requirements: the largest value / limit over the
    checks (<= 1 meets), inf where the station does not see the sample."""
    parts = [c.ratio(m.value(c.metric), lim) for c, lim in ctx.active_checks(smp)]
    out = np.maximum.reduce(parts) if parts else np.zeros(m.view.shape)
    return np.where(m.view, out, np.inf)


@dataclass
class CandidateEvaluation:
    """Which candidates meet every requirement at which sample, and how many see it."""

    ok: sp.csr_matrix  # (N samples, C candidates) bool
    n_view: np.ndarray  # (N,) candidates that see the sample (prisms; by rays: not counted)
    #: (N,) bool, every sample: an evaluation is never cut short (a plan is decided by work,
    #: not by the clock); the tables and the district's stitch still read it
    evaluated: np.ndarray


def evaluate_candidates(
    ctx: Context,
    cand_xy: np.ndarray,
    progress: Progress | None = None,
    registration: Registration | None = None,
    only: np.ndarray | None = None,
) -> CandidateEvaluation:
    """Evaluate every candidate against every facade sample (sparse result), on the scanner's
    error plus, when given, the registration's (one entry per candidate) — without it, each
    candidate with its own levelling (:func:`facade_pairs`' ``own_level``: the choice's
    stand-in for the frame's error until the network exists); ``only`` (N,) bool restricts
    it to some samples. Party-wall samples (never scanned) are not evaluated (none is met).
    Always whole: its size (samples × candidates) is refused before it starts where beyond
    the settings' ``max_pairs``."""
    fac = ctx.facades
    n_samples = len(fac.z)
    rows, cols = [], []
    n_view = np.zeros(n_samples, dtype=np.int64)
    wanted = ~fac.party_wall if only is None else only & ~fac.party_wall
    cand_z = ctx.station_z(cand_xy)  # every candidate's scanner, once
    for f in range(fac.n_facades):
        if progress:
            progress(f / fac.n_facades, f"evaluating facade {fac.facade_id[f]}")
        smp = ctx.samples_of[f][wanted[ctx.samples_of[f]]]
        if not len(smp):
            continue
        cand = ctx.front_candidates(f, cand_xy)
        if not len(cand):
            continue
        step = max(1, PAIR_CHUNK // len(smp))
        for lo in range(0, len(cand), step):
            ci = cand[lo : lo + step]
            m = facade_pairs(
                ctx, f, cand_xy[ci], smp, only is None, registration is None, cand_z[ci]
            )
            if registration is not None:
                add_registration(ctx, m, f, smp, registration, ci)
            r, c = np.nonzero(meets(ctx, m, smp) & ~m.untied)
            rows.append(smp[c])
            cols.append(ci[r])
            if ctx.scene.prisms:  # (by rays, the diagnosis counts them where it matters)
                n_view[smp] += m.view.sum(axis=0)
    if progress:
        progress(1.0, "evaluation done")
    r = np.concatenate(rows) if rows else np.empty(0, dtype=np.int64)
    c = np.concatenate(cols) if cols else np.empty(0, dtype=np.int64)
    ok = sp.csr_matrix((np.ones(len(r), dtype=bool), (r, c)), shape=(n_samples, len(cand_xy)))
    ok.sum_duplicates()
    return CandidateEvaluation(ok, n_view, np.ones(n_samples, dtype=bool))


def best_achievable(
    ctx: Context, cand_xy: np.ndarray, samples: np.ndarray
) -> dict[str, np.ndarray]:
    """For the given samples, the best value of each checked quantity over every candidate
    that sees them (each on its own, keyed by the check's key), and the best ``score``
    (largest value / limit, <= 1 meets). Arrays aligned with ``samples``; the worst value
    (±inf) where no candidate sees the sample. ``done`` says which samples were diagnosed
    (every one), ``n_view`` how many candidates see each."""
    fac = ctx.facades
    samples = np.asarray(samples)
    out = {c.key: np.full(len(samples), c.worst_value()) for c in CHECKS}
    out["score"] = np.full(len(samples), np.inf)
    out["done"] = np.ones(len(samples), dtype=bool)
    out["n_view"] = np.zeros(len(samples), dtype=np.int64)
    for f in np.unique(fac.facade[samples]):
        idx = np.flatnonzero(fac.facade[samples] == f)
        smp = samples[idx]
        cand = ctx.front_candidates(f, cand_xy)
        step = max(1, PAIR_CHUNK // len(smp))
        for lo in range(0, len(cand), step):
            # as the scanner-only evaluation judged it (each candidate with its own levelling)
            m = facade_pairs(ctx, int(f), cand_xy[cand[lo : lo + step]], smp, own_level=True)
            for c, _ in ctx.active_checks(smp):
                seen = np.where(m.view, m.value(c.metric), c.worst_value())
                best = c.best(seen, axis=0)
                prev = out[c.key][idx]
                out[c.key][idx] = (
                    np.minimum(prev, best) if c.sense == "max" else np.maximum(prev, best)
                )
            out["score"][idx] = np.minimum(out["score"][idx], score(ctx, m, smp).min(axis=0))
            out["n_view"][idx] += m.view.sum(axis=0)
    return out


@dataclass
class Assignment:
    """Each sample's assigned station — the best one meeting every requirement there, else
    the best one that sees it — and that station's metrics."""

    station: np.ndarray  # (N,) index into the stations, -1 where none sees the sample
    metrics: dict[str, np.ndarray]  # METRIC_KEYS, (N,) each, NaN where none is assigned
    n_meeting: np.ndarray  # (N,) stations meeting every requirement there (separate views)
    met_by_station: np.ndarray  # (K,) samples each station meets


@dataclass
class Registration:
    """The registration error to add to the scanner's: every station's pose covariance
    (K, 6, 6; shift mm, rotation rad), its scanner centre (K, 3) [m], and whether it is tied
    to the datum (an untied station's points are not in the common frame: infinite error)."""

    pose_cov: np.ndarray
    station_xyz: np.ndarray
    tied: np.ndarray


def add_registration(
    ctx: Context,
    m: PairMetrics,
    f: int,
    smp: np.ndarray,
    registration: Registration,
    stations: np.ndarray,
) -> None:
    """Add to the pairs ``m`` (stations × samples ``smp`` of facade ``f``) the registration
    error of ``stations`` (indices into ``registration``), in the facade's frame."""
    fac = ctx.facades
    pts = np.column_stack([fac.xy[smp], fac.z[smp]])
    along = (fac.end[f] - fac.start[f]) / np.hypot(*(fac.end[f] - fac.start[f]))
    rv = pair_registration_variances(
        registration.pose_cov[stations],
        registration.station_xyz[stations],
        pts,
        along,
        fac.normal[f],
    )
    m.add_registration(*rv, untied=~registration.tied[stations][:, None])


def _judged_facades(
    ctx: Context, station_xy: np.ndarray, registration: Registration | None
) -> Iterator[tuple[np.ndarray, np.ndarray, PairMetrics, np.ndarray]]:
    """Per facade, its samples, the stations in front of it (indices), their pairs' metrics
    (scanner plus, when given, registration) and where they meet the requirement."""
    fac = ctx.facades
    for f in range(fac.n_facades):
        smp = ctx.samples_of[f]
        ahead = np.flatnonzero(ctx.ahead(f, station_xy))
        if not len(ahead) or not len(smp):
            continue
        m = facade_pairs(ctx, f, station_xy[ahead])
        if registration is not None:
            add_registration(ctx, m, f, smp, registration, ahead)
        yield smp, ahead, m, meets(ctx, m, smp) & ~m.untied


def assign_stations(
    ctx: Context, station_xy: np.ndarray, registration: Registration | None = None
) -> Assignment:
    """Assign every sample a station (one facade at a time: memory grows with the samples,
    not samples × stations), judging the scanner's error plus, when given, the
    registration's at every pair."""
    fac = ctx.facades
    n, k = len(fac.z), len(station_xy)
    station = np.full(n, -1, dtype=np.int64)
    metrics = {key: np.full(n, np.nan) for key in METRIC_KEYS}
    n_meeting = np.zeros(n, dtype=np.int64)
    met_by = np.zeros(k, dtype=np.int64)
    for smp, ahead, m, ok in _judged_facades(ctx, station_xy, registration):
        sc = score(ctx, m, smp)
        rank = np.where(m.view, np.where(ok, sc, sc + 1e6), np.inf)
        best = np.argmin(rank, axis=0)
        has = np.isfinite(rank[best, np.arange(len(smp))])
        station[smp[has]] = ahead[best[has]]
        for key in METRIC_KEYS:
            metrics[key][smp[has]] = m.value(key)[best[has], np.flatnonzero(has)]
        n_meeting[smp] = _views(ctx, ok, station_xy[ahead], smp)
        met_by[ahead] += ok.sum(axis=1)
    return Assignment(station, metrics, n_meeting, met_by)


def meeting_pairs(
    ctx: Context, station_xy: np.ndarray, registration: Registration | None = None
) -> tuple[np.ndarray, np.ndarray, dict[str, np.ndarray]]:
    """Every (sample, station) pair where the station meets the sample's requirement on the
    scanner's error plus, when given, the registration's: sample and station indices and the
    pair's :data:`METRIC_KEYS` (one facade at a time, like :func:`assign_stations`)."""
    smp_out, st_out = [], []
    vals: dict[str, list[np.ndarray]] = {key: [] for key in METRIC_KEYS}
    for smp, ahead, m, ok in _judged_facades(ctx, station_xy, registration):
        r, c = np.nonzero(ok)
        smp_out.append(smp[c])
        st_out.append(ahead[r])
        for key in METRIC_KEYS:
            vals[key].append(m.value(key)[r, c])
    empty = np.empty(0, dtype=np.int64)
    return (
        np.concatenate(smp_out) if smp_out else empty,
        np.concatenate(st_out) if st_out else empty,
        {k: np.concatenate(v) if v else np.empty(0) for k, v in vals.items()},
    )


def _views(ctx: Context, ok: np.ndarray, station_xy: np.ndarray, smp: np.ndarray) -> np.ndarray:
    """Per sample, the stations meeting it that count as separate views: all of them where
    one is needed, else those at least ``min_view_angle_deg`` apart in direction (two
    stations side by side are one view)."""
    n_ok = ok.sum(axis=0)
    out = n_ok.copy()
    xy = ctx.facades.xy[smp]
    for i in np.flatnonzero((n_ok >= 2) & (ctx.stations_needed[smp] >= 2)):
        d = station_xy[ok[:, i]] - xy[i]
        az = np.degrees(np.arctan2(d[:, 1], d[:, 0]))
        out[i] = separated_directions(az, ctx.req.min_view_angle_deg)
    return out


def evaluate_stations(ctx: Context, station_xy: np.ndarray) -> dict[str, np.ndarray]:
    """Dense metrics of every sample × station: arrays of shape (N, K), NaN where the
    station is not in front of the facade — for a handful of stations (the memory grows
    with samples × stations; :func:`assign_stations` does not)."""
    fac = ctx.facades
    n, k = len(fac.z), len(station_xy)
    out = {key: np.full((n, k), np.nan) for key in (*METRIC_KEYS, "score")}
    out["view"] = np.zeros((n, k), dtype=bool)
    out["ok"] = np.zeros((n, k), dtype=bool)
    for f in range(fac.n_facades):
        smp = ctx.samples_of[f]
        ahead = np.flatnonzero(ctx.ahead(f, station_xy))
        if not len(ahead) or not len(smp):
            continue
        m = facade_pairs(ctx, f, station_xy[ahead])
        vals = {key: m.value(key) for key in METRIC_KEYS}
        vals["score"] = score(ctx, m, smp)
        vals["view"] = m.view
        vals["ok"] = meets(ctx, m, smp)
        ix = np.ix_(smp, ahead)
        for key, val in vals.items():
            out[key][ix] = val.T
    return out
