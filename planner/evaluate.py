"""Candidate × sample evaluation: sight geometry, line of sight, predicted RMS, requirements.

For every candidate station and facade sample: horizontal distance D, slope distance S,
deviation γ, tilt ν, line of sight (:mod:`planner.visibility`), the scanner's range and
vertical field of view, m_x, m_y (eq. 2, ranging RMS at the measured slope distance S),
m_z (eq. 4, S_0 = S) and the point spacing on the facade. Vectorised per facade and chunked
over candidates so memory stays bounded; no trigonometry on the hot path (cos²γ, sin²ν
come from dot products).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from planner.accuracy import eq2_variances, eq4_variance, station_rms_pair
from planner.facades import SIGHT_OFFSET_M, FacadeSet, footprint_edges
from planner.requirements import PlanSettings, Requirements
from planner.scanner import Scanner
from planner.site import Site
from planner.visibility import clear_height, edges_in_box, edges_in_front

__all__ = ["Context", "PairMetrics", "evaluate_candidates", "evaluate_stations"]

Progress = Callable[[float, str], None]

#: Per-pair quantities reported for chosen stations (besides ``score``, ``view``, ``ok``).
METRIC_KEYS = (
    "distance_m",
    "slope_distance_m",
    "gamma_deg",
    "nu_deg",
    "m_x_mm",
    "m_y_mm",
    "m_z_mm",
    "spacing_mm",
)

#: Candidate × sample pairs evaluated at once: ~20 float arrays of this many stay in cache.
PAIR_CHUNK = 65_536


@dataclass
class Context:
    """Everything the evaluation needs, prepared once per plan."""

    site: Site
    facades: FacadeSet
    scanner: Scanner
    req: Requirements
    settings: PlanSettings
    reach_m: float
    edges: np.ndarray
    edge_heights: np.ndarray
    edge_mask: list[np.ndarray]  # per facade: edges that can block its sight lines
    cols_of: list[np.ndarray]
    samples_of: list[np.ndarray]
    step_mm_at_10m: float

    @classmethod
    def build(
        cls,
        site: Site,
        facades: FacadeSet,
        scanner: Scanner,
        req: Requirements,
        settings: PlanSettings,
        reach: float,
    ) -> Context:
        edges, heights = footprint_edges(site)
        masks, cols_of, samples_of = [], [], []
        col_order = np.argsort(facades.col_facade, kind="stable")
        smp_order = np.argsort(facades.facade, kind="stable")
        col_bounds = np.searchsorted(
            facades.col_facade[col_order], np.arange(facades.n_facades + 1)
        )
        smp_bounds = np.searchsorted(facades.facade[smp_order], np.arange(facades.n_facades + 1))
        for f in range(facades.n_facades):
            a, e = facades.start[f], facades.end[f]
            bbox = (
                min(a[0], e[0]) - reach,
                min(a[1], e[1]) - reach,
                max(a[0], e[0]) + reach,
                max(a[1], e[1]) + reach,
            )
            masks.append(np.flatnonzero(edges_in_front(edges, a, facades.normal[f], bbox)))
            cols_of.append(col_order[col_bounds[f] : col_bounds[f + 1]])
            samples_of.append(smp_order[smp_bounds[f] : smp_bounds[f + 1]])
        step = settings.step_mm_at_10m or scanner.step_mm_at_10m
        return cls(
            site,
            facades,
            scanner,
            req,
            settings,
            reach,
            edges,
            heights,
            masks,
            cols_of,
            samples_of,
            step,
        )

    def front_candidates(self, f: int, cand_xy: np.ndarray) -> np.ndarray:
        """Indices of candidates in front of facade ``f`` and within reach of it."""
        a, e, n = self.facades.start[f], self.facades.end[f], self.facades.normal[f]
        rel = cand_xy - a
        ahead = rel @ n > 0
        v = e - a
        t = np.clip(rel @ v / (v @ v), 0.0, 1.0)
        dist = np.hypot(*(rel - t[:, None] * v).T)
        return np.flatnonzero(ahead & (dist <= self.reach_m))


@dataclass
class PairMetrics:
    """Metrics of ``c`` candidates × ``n`` samples of one facade (arrays of shape (c, n))."""

    distance_m: np.ndarray
    slope_distance_m: np.ndarray
    cos_gamma: np.ndarray
    sin_nu: np.ndarray
    var_x: np.ndarray
    var_y: np.ndarray
    var_z: np.ndarray
    spacing_mm: np.ndarray
    view: np.ndarray  # sees the sample: in front, line of sight, range, field of view
    ok: np.ndarray  # view and every requirement


def facade_pairs(
    ctx: Context, f: int, cand_xy: np.ndarray, smp: np.ndarray | None = None, *, full: bool = True
) -> PairMetrics:
    """Evaluate candidates ``cand_xy`` against the samples ``smp`` (default: all) of facade
    ``f``. ``full=False`` skips what only reports need (point spacing without a spacing
    requirement)."""
    fac, sc, req = ctx.facades, ctx.scanner, ctx.req
    hi = ctx.settings.instrument_height_m
    cols = ctx.cols_of[f]
    smp = ctx.samples_of[f] if smp is None else smp
    n = fac.normal[f]
    c, k = len(cand_xy), len(cols)
    # line of sight, once per (candidate, column), against the edges that can lie between
    em = ctx.edge_mask[f]
    if len(em):
        lo_xy = np.minimum(cand_xy.min(axis=0), np.minimum(fac.start[f], fac.end[f]))
        hi_xy = np.maximum(cand_xy.max(axis=0), np.maximum(fac.start[f], fac.end[f]))
        em = em[edges_in_box(ctx.edges[em], (*lo_xy, *hi_xy))]
    target = fac.col_xy[cols] + SIGHT_OFFSET_M * n
    zc = clear_height(
        np.repeat(cand_xy, k, axis=0),
        hi,
        np.tile(target, (c, 1)),
        ctx.edges[em],
        ctx.edge_heights[em],
    ).reshape(c, k)
    col_local = np.searchsorted(cols, fac.column[smp])
    # sight geometry (station minus point horizontally; point minus scanner vertically)
    dx = cand_xy[:, 0:1] - fac.xy[smp, 0]
    dy = cand_xy[:, 1:2] - fac.xy[smp, 1]
    dz = fac.z[smp] - hi
    d2 = dx * dx + dy * dy
    d = np.sqrt(d2)
    s2 = d2 + dz * dz
    s = np.sqrt(s2)
    cdot = dx * n[0] + dy * n[1]
    with np.errstate(divide="ignore", invalid="ignore"):
        cos_g = np.where(d > 0, cdot / d, 0.0)
        sin_nu = dz / s
    lo, up = np.sin(np.radians(sc.vertical_fov_deg))
    view = (
        (cdot > 0)
        & (fac.z[smp] >= zc[:, col_local] - 1e-9)
        & (s >= sc.min_range_m)
        & (s <= sc.max_range_m)
        & (sin_nu >= lo - 1e-12)
        & (sin_nu <= up + 1e-12)
    )
    m_s = sc.range_rms_mm + sc.range_ppm * 1e-3 * s if sc.range_ppm else sc.range_rms_mm
    st = station_rms_pair(ctx.settings.station_rms_mm)
    cos2 = cos_g * cos_g
    var_x, var_y = eq2_variances(d, cos2, m_s, sc.angle_rms_arcsec, (st[0] ** 2, st[1] ** 2))
    m_nu0 = sc.levelling_rms_arcsec or sc.tilt_rms_arcsec
    var_z = eq4_variance(s, sin_nu * sin_nu, m_s, sc.tilt_rms_arcsec, s, m_nu0)
    delta = ctx.step_mm_at_10m / 10.0  # mm per metre of distance
    with np.errstate(divide="ignore", invalid="ignore"):
        spacing = delta * np.maximum(
            np.where(cdot > 0, d2 / cdot, np.inf), np.where(d > 0, s2 / d, np.inf)
        )
    cos_gmax = np.cos(np.radians(req.max_gamma_deg))
    ok = (
        view
        & (var_x <= req.max_x_mm**2 * (1 + 1e-12))
        & (var_y <= req.max_y_mm**2 * (1 + 1e-12))
        & (var_z <= req.max_z_mm**2 * (1 + 1e-12))
        & (cos_g >= cos_gmax - 1e-12)
    )
    if req.max_spacing_mm is not None:
        ok &= spacing <= req.max_spacing_mm
    if req.min_range_m is not None:
        ok &= s >= req.min_range_m
    if req.max_range_m is not None:
        ok &= s <= req.max_range_m
    return PairMetrics(d, s, cos_g, sin_nu, var_x, var_y, var_z, spacing, view, ok)


def score(ctx: Context, m: PairMetrics) -> np.ndarray:
    """How far a pair is from meeting the requirements: max of value / limit (<= 1 meets),
    inf where the station does not see the sample."""
    req = ctx.req
    with np.errstate(invalid="ignore"):
        gamma = np.degrees(np.arccos(np.clip(m.cos_gamma, -1, 1)))
    parts = [
        np.sqrt(m.var_x) / req.max_x_mm,
        np.sqrt(m.var_y) / req.max_y_mm,
        np.sqrt(m.var_z) / req.max_z_mm,
        gamma / req.max_gamma_deg,
    ]
    if req.max_spacing_mm is not None:
        parts.append(m.spacing_mm / req.max_spacing_mm)
    if req.min_range_m is not None:
        parts.append(req.min_range_m / m.slope_distance_m)
    if req.max_range_m is not None:
        parts.append(m.slope_distance_m / req.max_range_m)
    out = np.maximum.reduce(parts)
    return np.where(m.view, out, np.inf)


@dataclass
class CandidateEvaluation:
    """Which candidates meet every requirement at which sample, and how many see it."""

    ok: sp.csr_matrix  # (N samples, C candidates) bool
    n_view: np.ndarray  # (N,) candidates that see the sample


def evaluate_candidates(
    ctx: Context, cand_xy: np.ndarray, progress: Progress | None = None
) -> CandidateEvaluation:
    """Evaluate every candidate against every facade sample (sparse result)."""
    fac = ctx.facades
    n_samples = len(fac.z)
    rows, cols = [], []
    n_view = np.zeros(n_samples, dtype=np.int64)
    for f in range(fac.n_facades):
        if progress:
            progress(f / fac.n_facades, f"evaluating facade {fac.facade_id[f]}")
        smp = ctx.samples_of[f]
        cand = ctx.front_candidates(f, cand_xy)
        if not len(cand) or not len(smp):
            continue
        step = max(1, PAIR_CHUNK // len(smp))
        for lo in range(0, len(cand), step):
            ci = cand[lo : lo + step]
            m = facade_pairs(ctx, f, cand_xy[ci], full=False)
            r, c = np.nonzero(m.ok)
            rows.append(smp[c])
            cols.append(ci[r])
            n_view[smp] += m.view.sum(axis=0)
    if progress:
        progress(1.0, "evaluation done")
    r = np.concatenate(rows) if rows else np.empty(0, dtype=np.int64)
    c = np.concatenate(cols) if cols else np.empty(0, dtype=np.int64)
    ok = sp.csr_matrix((np.ones(len(r), dtype=bool), (r, c)), shape=(n_samples, len(cand_xy)))
    ok.sum_duplicates()
    return CandidateEvaluation(ok, n_view)


def _blocks(xy: np.ndarray, per_block: int) -> np.ndarray:
    """An order of the points by square blocks of about ``per_block`` points each."""
    if len(xy) <= per_block:
        return np.arange(len(xy))
    span = np.ptp(xy, axis=0).max() + 1e-9
    side = span * np.sqrt(per_block / len(xy))
    cell = np.floor((xy - xy.min(axis=0)) / side).astype(np.int64)
    return np.lexsort((xy[:, 0], xy[:, 1], cell[:, 0], cell[:, 1]))


BEST_KEYS = ("m_x_mm", "m_y_mm", "m_z_mm", "gamma_deg", "spacing_mm", "score")


def best_achievable(
    ctx: Context, cand_xy: np.ndarray, samples: np.ndarray
) -> dict[str, np.ndarray]:
    """For the given samples, the best value of each quantity over every candidate that sees
    them (each minimised on its own), and the best ``score`` (max of value / limit, <= 1
    meets). Arrays aligned with ``samples``; inf where no candidate sees the sample."""
    fac = ctx.facades
    out = {k: np.full(len(samples), np.inf) for k in BEST_KEYS}
    samples = np.asarray(samples)
    for f in np.unique(fac.facade[samples]):
        idx = np.flatnonzero(fac.facade[samples] == f)
        smp = samples[idx]
        cand = ctx.front_candidates(f, cand_xy)
        step = max(1, PAIR_CHUNK // len(smp))
        for lo in range(0, len(cand), step):
            m = facade_pairs(ctx, int(f), cand_xy[cand[lo : lo + step]], smp)
            cos_best = np.where(m.view, m.cos_gamma, -np.inf).max(axis=0)
            with np.errstate(invalid="ignore"):
                gamma = np.where(
                    np.isfinite(cos_best), np.degrees(np.arccos(np.clip(cos_best, -1, 1))), np.inf
                )
            vals = {
                "m_x_mm": np.sqrt(np.where(m.view, m.var_x, np.inf).min(axis=0)),
                "m_y_mm": np.sqrt(np.where(m.view, m.var_y, np.inf).min(axis=0)),
                "m_z_mm": np.sqrt(np.where(m.view, m.var_z, np.inf).min(axis=0)),
                "gamma_deg": gamma,
                "spacing_mm": np.where(m.view, m.spacing_mm, np.inf).min(axis=0),
                "score": score(ctx, m).min(axis=0),
            }
            for key, v in vals.items():
                out[key][idx] = np.minimum(out[key][idx], v)
    return out


def evaluate_stations(ctx: Context, station_xy: np.ndarray) -> dict[str, np.ndarray]:
    """Dense metrics of every sample × station: arrays of shape (N, K), NaN where the
    station is not in front of the facade or out of reach of the evaluation."""
    fac = ctx.facades
    n, k = len(fac.z), len(station_xy)
    out = {key: np.full((n, k), np.nan) for key in (*METRIC_KEYS, "score")}
    out["view"] = np.zeros((n, k), dtype=bool)
    out["ok"] = np.zeros((n, k), dtype=bool)
    for f in range(fac.n_facades):
        smp = ctx.samples_of[f]
        a, nrm = fac.start[f], fac.normal[f]
        ahead = np.flatnonzero((station_xy - a) @ nrm > 0)
        if not len(ahead) or not len(smp):
            continue
        m = facade_pairs(ctx, f, station_xy[ahead])
        with np.errstate(invalid="ignore"):
            gamma = np.degrees(np.arccos(np.clip(m.cos_gamma, -1, 1)))
        vals = {
            "distance_m": m.distance_m,
            "slope_distance_m": m.slope_distance_m,
            "gamma_deg": gamma,
            "nu_deg": np.degrees(np.arcsin(np.clip(m.sin_nu, -1, 1))),
            "m_x_mm": np.sqrt(m.var_x),
            "m_y_mm": np.sqrt(m.var_y),
            "m_z_mm": np.sqrt(m.var_z),
            "spacing_mm": m.spacing_mm,
            "score": score(ctx, m),
            "view": m.view,
            "ok": m.ok,
        }
        ix = np.ix_(smp, ahead)
        for key, val in vals.items():
            out[key][ix] = val.T
    return out
