"""Registration planning: the targets that tie the scans together, the network of pairwise
registrations, and its error at every facade sample.

1. **Where targets can go** (:func:`target_candidates`): flat targets on the planned
   facades at two heights (so that the targets of a link spread in height too), spheres on
   stands on free ground, and the site's control points.
2. **What each station sees** (:func:`sights`): line of sight, range, the incidence on a
   flat target (checkerboards: at most ``max_target_incidence_deg``), the size each target
   needs there — the larger of Sossa's 2d / 4d and practice (points per quadrant, points on
   the sphere), with the rule that sets it — and the RMS of its fitted centre
   (:func:`planner.registration_error.target_centre_rms_mm`).
3. **Links** (:func:`_choose_link_targets`): for two stations, the common targets are
   chosen greedily to make the child's registration error at the facade points it serves
   smallest — not a fixed three, not by a spread rule: a thin triangle or targets all at
   one height show up as a large predicted error and are avoided — reusing targets already
   placed, up to ``max_targets_per_link``.
4. **The network** (:func:`build_network`): stations that cannot be linked get linking
   stations (searched along chains of candidates, as many hops as needed); the datum is
   the control network when three control points are seen, else the station that keeps the
   chain shortest in error; the registrations form a tree from it, each station joined
   where its accumulated error is smallest (the chain's error,
   :func:`planner.registration_error.propagate`, chooses it). The error the plan is judged
   on is that of the simultaneous adjustment of every placed target each station sees
   (:func:`planner.registration_error.adjust`), as registration software computes it.
"""

from __future__ import annotations

import heapq
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np
import scipy.sparse as sp
import shapely
from numba import njit
from scipy.cluster.hierarchy import DisjointSet
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree
from scipy.spatial.distance import cdist

from planner.cloud_registration import weakest_direction
from planner.pipeline import clouds
from planner.pipeline.clouds import CloudLink
from planner.pipeline.evaluate import Context, Registration
from planner.pipeline.facades import SIGHT_OFFSET_M, FacadeSet, sample_flags
from planner.pipeline.visibility import stand_blocks
from planner.registration_error import (
    CONTROL,
    MAX_CONDITION,
    Link,
    NetworkError,
    adjust,
    datum_lean_mm,
    propagate,
    scaled_condition,
    target_centre_rms_mm,
    transport_pose_cov,
)
from planner.scanner import Scanner
from planner.spacing import point_spacing_mm
from planner.targets import chosen_sizes, size_rules

__all__ = [
    "Network",
    "Sight",
    "TargetCandidates",
    "build_network",
    "control_messages",
    "sights",
    "target_candidates",
]

#: Linking stations are searched on a grid this coarse (a subset of the candidates) [m].
LINK_GRID_M = 4.0
#: A link stops taking targets once adding one improves its error by less than this.
MIN_GAIN = 0.03
#: The weak prior that lets the greedy target choice start from no targets (σ: 1 m, 0.6°).
_PRIOR = np.diag([1e-6] * 3 + [1e4] * 3)


@dataclass(kw_only=True)
class TargetCandidates:
    """Where targets could go: (T, 3) positions, type ("flat", "sphere", "control"), the
    wall's normal (zero elsewhere), the facade of a flat target (-1 elsewhere), and for
    control points their id and coordinate RMS [mm] (NaN elsewhere)."""

    xyz: np.ndarray
    type: np.ndarray
    normal: np.ndarray
    facade: np.ndarray
    control_id: np.ndarray
    control_rms_mm: np.ndarray

    @cached_property
    def is_control(self) -> np.ndarray:
        return self.type == "control"


def target_candidates(ctx: Context, stand_xy: np.ndarray) -> TargetCandidates:
    """Flat targets along the planned facades (at ``target_height_m`` and, where the wall
    is high enough, ``high_target_height_m``), spheres on the stand positions, for the types
    the inventory holds; and the site's control points."""
    fac, st = ctx.facades, ctx.settings
    types = {i.type for i in st.inventory}
    xyz, kind, nrm, wall = [], [], [], []
    if "flat" in types:
        heights = [st.target_height_m] + (
            [st.high_target_height_m] if st.high_target_height_m else []
        )
        for f in range(fac.n_facades):
            if fac.leaning[f]:  # no checkerboard on a sloping wall
                continue
            n = max(1, round(fac.length_m[f] / st.target_spacing_m))
            top = fac.z0[f] + fac.height_m[f]
            inner = _inner_outline(fac, f)
            for row, h in enumerate(heights):
                if h > fac.height_m[f] - 0.2 and row > 0:
                    continue
                frac = (np.arange(n) + 0.5 + 0.5 * row) / (n + 0.5 * row)  # the rows staggered
                foot = fac.start[f] + frac[:, None] * (fac.end[f] - fac.start[f])
                ground = ctx.scene.ground_z(foot + fac.normal[f])  # where the crew stands
                for k in range(n):
                    z = min(ground[k] + h, top - 0.2)
                    u, v = frac[k] * fac.length_m[f], z - fac.base_z[f]
                    if inner is not None and not inner.contains(shapely.Point(u, v)):
                        continue  # not on the wall: above a gable's slope, below a set-back
                    at = foot[k]
                    if fac.tilted[f]:  # a wall leaning a little: on its plane at that height
                        at = fac.place(np.array([f]), np.array([u]), np.array([v]))[0][0]
                    xyz.append([*at, z])
                    kind.append("flat")
                    nrm.append(fac.normal[f])
                    wall.append(f)
        if xyz:
            walls = np.array(xyz)
            wall_ok, party = sample_flags(
                ctx.site, fac, np.array(wall), walls[:, :2], walls[:, 2], ctx.scene
            )
            keep = wall_ok & ~party  # on a wall to scan, not in a gateway, not a party wall
            xyz = [p for p, k in zip(xyz, keep, strict=True) if k]
            nrm = [p for p, k in zip(nrm, keep, strict=True) if k]
            kind = [p for p, k in zip(kind, keep, strict=True) if k]
            wall = [p for p, k in zip(wall, keep, strict=True) if k]
    if "sphere" in types:
        stand_z = ctx.scene.above_ground(stand_xy, st.target_height_m)
        for xy, z in zip(stand_xy, stand_z, strict=True):
            xyz.append([xy[0], xy[1], z])
            kind.append("sphere")
            nrm.append([0.0, 0.0])
            wall.append(-1)
    ids, rms = [""] * len(xyz), [np.nan] * len(xyz)
    for c in ctx.site.control:
        xyz.append(list(c.xyz))
        kind.append("control")
        nrm.append([0.0, 0.0])
        wall.append(-1)
        ids.append(c.id)
        rms.append(c.rms_mm)
    return TargetCandidates(
        xyz=np.array(xyz, dtype=float).reshape(-1, 3),
        type=np.array(kind, dtype=object),
        normal=np.array(nrm, dtype=float).reshape(-1, 2),
        facade=np.array(wall, dtype=np.int64),
        control_id=np.array(ids, dtype=object),
        control_rms_mm=np.array(rms, dtype=float),
    )


def _inner_outline(fac: FacadeSet, f: int):
    """Where on facade ``f``'s elevation a flat target may go: a hand's breadth inside its
    outline (on a gable or a set-back storey's wall only where the wall is); None for a
    rectangle (a footprint's facade: anywhere on it)."""
    outline = fac.outline[f]
    if outline.equals(shapely.box(*outline.bounds)):
        return None
    return outline.buffer(-0.1)


@dataclass
class Sight:
    """What every station sees of every target, (T, K) arrays: usable, the size it needs
    there [mm] and the rule setting it, the centre's RMS with the largest item [mm]."""

    usable: np.ndarray
    need_mm: np.ndarray
    rule: np.ndarray
    slope_m: np.ndarray
    cos_incidence: np.ndarray
    spacing_mm: np.ndarray

    def take(self, cols: Sequence[int] | np.ndarray) -> Sight:
        cols = np.asarray(cols, dtype=np.int64)
        return Sight(*(getattr(self, f)[:, cols] for f in Sight.__dataclass_fields__))

    def put(self, used: int, other: Sight) -> Sight:
        """These sights' first ``used`` columns followed by ``other``'s (more stations, the
        same targets), in arrays with room to spare: a cache growing a batch of columns at
        a time is copied a logarithmic number of times, not at every batch."""
        need = used + other.usable.shape[1]
        fields = Sight.__dataclass_fields__
        out = Sight(*(_with_room(getattr(self, f), used, need) for f in fields))
        for f in fields:
            getattr(out, f)[:, used:need] = getattr(other, f)
        return out

    def stack(self, other: Sight) -> Sight:
        """The same stations' sights of other targets, as rows after these."""
        return Sight(
            *(
                np.concatenate([getattr(self, f), getattr(other, f)])
                for f in Sight.__dataclass_fields__
            )
        )


def _with_room(old: np.ndarray, used: int, need: int) -> np.ndarray:
    """``old`` if it has ``need`` columns, else its first ``used`` columns in an array with
    room to spare (twice the columns): a cache growing a batch of columns at a time is
    copied a logarithmic number of times, not at every batch."""
    if need <= old.shape[1]:
        return old
    new = np.empty((old.shape[0], max(need, 2 * old.shape[1])), dtype=old.dtype)
    new[:, :used] = old[:, :used]
    return new


def target_sight_offset(ctx: Context, tc: TargetCandidates) -> np.ndarray:
    """(T,) how far in front of its wall each target's sight lines end [m]: a flat target's
    facade's ray end (:attr:`Context.ray_end_m`: in front of the curved run of edges a
    merged facade stands for), :data:`SIGHT_OFFSET_M` for the others (their normal is 0)."""
    on_wall = tc.facade >= 0
    out = np.full(len(tc.facade), SIGHT_OFFSET_M)
    out[on_wall] = ctx.ray_end_m[tc.facade[on_wall]]
    return out


def sights(ctx: Context, tc: TargetCandidates, station_xy: np.ndarray) -> Sight:
    """Which targets each station can use (seen: line of sight, range; a flat target in
    front of its wall within ``max_target_incidence_deg``; an inventory item big enough).

    The ranges, incidences and lines of sight are computed :data:`SIGHT_CHUNK` stations at
    a time (each station's lines against the edges within its reach), and the spacing and
    sizes once for every pair seen."""
    sc, st = ctx.scanner, ctx.settings
    t, k = len(tc.xyz), len(station_xy)
    shape = (t, k)
    need = np.full(shape, np.inf)
    rule = np.full(shape, "", dtype=object)
    slope = np.full(shape, np.nan)
    cos_inc = np.ones(shape)
    spacing = np.full(shape, np.nan)
    if t == 0 or k == 0:
        return Sight(np.zeros(shape, dtype=bool), need, rule, slope, cos_inc, spacing)
    largest = {
        ty: max((i.size_mm for i in st.inventory if i.type == ty), default=0.0)
        for ty in ("flat", "sphere", "cylinder")
    }
    largest["control"] = np.inf  # a control point is a mark that is there: no size to choose
    cos_max = np.cos(np.radians(st.max_target_incidence_deg))
    of_type = {ty: tc.type == ty for ty in ("flat", "sphere", "control")}
    is_flat = of_type["flat"]
    xy, z = tc.xyz[:, :2], tc.xyz[:, 2]
    ends = xy + target_sight_offset(ctx, tc)[:, None] * tc.normal  # where the sight lines end
    none = np.zeros(0, dtype=np.int64)
    seen_t, seen_j, seen_s, seen_cdot = [none], [none], [none.astype(float)], [none.astype(float)]
    station_z = ctx.station_z(station_xy)
    for c0 in range(0, k, SIGHT_CHUNK):
        chunk = station_xy[c0 : c0 + SIGHT_CHUNK]
        chunk_z = station_z[c0 : c0 + SIGHT_CHUNK]
        rel = chunk[:, None, :] - xy[None, :, :]  # (C, T, 2)
        s_all = np.hypot(np.hypot(rel[..., 0], rel[..., 1]), z - chunk_z[:, None])
        cdot_all = (rel * tc.normal).sum(axis=-1)
        cand_all = (s_all >= sc.min_range_m) & (s_all <= sc.max_range_m)
        cand_all &= ~is_flat | (cdot_all > cos_max * s_all)
        at, idx = np.nonzero(cand_all)  # the sight lines, station by station
        if not len(idx):
            continue
        s = s_all[at, idx]
        # each station's lines against the edges within its farthest line's reach
        reach = np.where(cand_all, s_all, -np.inf).max(axis=1)
        boxes = np.column_stack([chunk - reach[:, None], chunk + reach[:, None]])
        starts = np.searchsorted(at, np.arange(len(chunk) + 1))
        src = np.column_stack([chunk[at], chunk_z[at]])
        dst = np.column_stack([ends[idx], z[idx]])
        keep = ctx.scene.seen(src, dst, groups=(starts, boxes))
        seen_t.append(idx[keep])
        seen_j.append(c0 + at[keep])
        seen_s.append(s[keep])
        seen_cdot.append(cdot_all[at[keep], idx[keep]])
    tt, jj = np.concatenate(seen_t), np.concatenate(seen_j)
    s, cdot = np.concatenate(seen_s), np.concatenate(seen_cdot)
    sp = point_spacing_mm(s, step_mm_at_10m=ctx.step_mm_at_10m)
    ci = np.where(is_flat[tt], cdot / s, 1.0)
    slope[tt, jj], cos_inc[tt, jj], spacing[tt, jj] = s, ci, sp
    for ty in ("flat", "sphere"):
        sel = of_type[ty][tt]
        if sel.any():
            n_, r_ = size_rules(
                ty,
                sp[sel],
                ci[sel],
                points_per_quadrant=st.min_points_per_quadrant,
                points_on_sphere=st.min_points_on_sphere,
            )
            need[tt[sel], jj[sel]], rule[tt[sel], jj[sel]] = n_, r_
    ctl = of_type["control"][tt]
    need[tt[ctl], jj[ctl]], rule[tt[ctl], jj[ctl]] = 0.0, "control point"
    big = np.array([largest[ty] for ty in tc.type])[:, None]
    return Sight(np.isfinite(need) & (need <= big), need, rule, slope, cos_inc, spacing)


#: :func:`sights` computes ranges and incidences this many stations at a time.
SIGHT_CHUNK = 64


class SightCache:
    """What the candidates see of the targets, computed once per candidate for a plan (the
    registration is built again every round)."""

    def __init__(self, ctx: Context, tc: TargetCandidates, cand_xy: np.ndarray) -> None:
        self.ctx, self.tc, self.cand_xy = ctx, tc, cand_xy
        self.column: dict[int, int] = {}
        self.sight: Sight | None = None
        #: targets the surveyor ruled out (no station may use them) and placed by hand
        #: (preferred by every link that can use them)
        self.barred = np.zeros(len(tc.xyz), dtype=bool)
        self.by_hand = np.zeros(len(tc.xyz), dtype=bool)
        self._clouds: clouds.SurfaceCache | None = None
        #: link choices and centre RMS by candidate index, kept between the rounds of a plan
        #: (for one goal and state of the targets: see :meth:`memo_for`)
        self._memo_key: tuple | None = None
        self._memo: dict = {}
        #: which targets the candidates searched for linking stations can use, by candidate
        #: (:meth:`usable`: the one field such a search needs, a bit per pair, not six
        #: arrays of the candidates' sights)
        self._searched: dict[int, int] = {}
        self._searched_usable = np.zeros((len(tc.xyz), 0), dtype=bool)

    def memo_for(self, goal_mm: float) -> dict:
        """The table of link choices and centre RMS valid for ``goal_mm`` and the targets as
        they stand (added, barred, placed by hand); a new table when either changed."""
        key = (goal_mm, len(self.tc.xyz), self.barred.tobytes(), self.by_hand.tobytes())
        if key != self._memo_key:
            self._memo_key, self._memo = key, {}
        return self._memo

    @property
    def clouds(self) -> clouds.SurfaceCache:
        """The patches each candidate sees and the cloud links between candidates (made
        when first asked: only cloud-to-cloud and hybrid registration use them)."""
        if self._clouds is None:
            self._clouds = clouds.SurfaceCache(self.ctx)
        return self._clouds

    def fork(self, keep: Sequence[int] | np.ndarray) -> SightCache:
        """A cache of its own holding these sights of candidates ``keep`` (others computed
        when asked): targets added to it (planned control) stay out of this one."""
        keep = [int(i) for i in dict.fromkeys(keep)]
        out = SightCache(self.ctx, self.tc, self.cand_xy)
        cols = self._columns(keep)
        out.sight = self.sight.take(cols) if self.sight is not None else None
        out.column = {i: n for n, i in enumerate(keep)}
        out.barred, out.by_hand = self.barred.copy(), self.by_hand.copy()
        out._clouds = self._clouds  # the patches do not depend on the targets
        return out

    def add_targets(self, more: TargetCandidates) -> np.ndarray:
        """Append target candidates (placed by hand); the sights of every station seen so
        far are extended to them. Their indices."""
        first = len(self.tc.xyz)
        self.tc = TargetCandidates(
            **{
                f: np.concatenate([getattr(self.tc, f), getattr(more, f)])
                for f in TargetCandidates.__dataclass_fields__
            }
        )
        if self.sight is not None:
            cols = sorted(self.column, key=self.column.__getitem__)
            self.sight = self.sight.take(np.arange(len(cols))).stack(
                sights(self.ctx, more, self.cand_xy[cols])
            )
        self.barred = np.concatenate([self.barred, np.zeros(len(more.xyz), dtype=bool)])
        self.by_hand = np.concatenate([self.by_hand, np.ones(len(more.xyz), dtype=bool)])
        self._searched, self._searched_usable = {}, np.zeros((len(self.tc.xyz), 0), dtype=bool)
        return np.arange(first, len(self.tc.xyz))

    def __call__(self, idx: Sequence[int] | np.ndarray) -> Sight:
        """The sights of candidates ``idx``, in that order."""
        cols = self._columns(idx)
        if self.sight is None:
            return sights(self.ctx, self.tc, self.cand_xy[:0])
        out = self.sight.take(cols)  # a copy
        out.usable[self.barred] = False
        return out

    def usable(self, idx: Sequence[int] | np.ndarray) -> np.ndarray:
        """(T, len(idx)) which targets candidates ``idx`` can use: the one field of
        :meth:`__call__` a search over many candidates needs. Candidates whose sights are
        not kept are computed and only this field is kept of them."""
        idx = [int(i) for i in idx]
        new = [i for i in dict.fromkeys(idx) if i not in self.column and i not in self._searched]
        if new:
            fresh = sights(self.ctx, self.tc, self.cand_xy[new]).usable
            base = len(self._searched)
            self._searched_usable = _with_room(self._searched_usable, base, base + len(new))
            self._searched_usable[:, base : base + len(new)] = fresh
            self._searched.update({i: base + n for n, i in enumerate(new)})
        out = np.empty((len(self.tc.xyz), len(idx)), dtype=bool)
        kept = np.array([i in self.column for i in idx], dtype=bool)
        at = np.array(idx, dtype=np.int64)
        if kept.any():
            out[:, kept] = self.sight.usable[:, [self.column[i] for i in at[kept]]]
        if not kept.all():
            out[:, ~kept] = self._searched_usable[:, [self._searched[i] for i in at[~kept]]]
        out[self.barred] = False
        return out

    def _columns(self, idx: Sequence[int] | np.ndarray) -> list[int]:
        """The cache's columns of candidates ``idx``, computing the sights of new ones."""
        idx = [int(i) for i in idx]
        new = [i for i in dict.fromkeys(idx) if i not in self.column]
        if new:
            fresh = sights(self.ctx, self.tc, self.cand_xy[new])
            base = len(self.column)
            self.sight = fresh if self.sight is None else self.sight.put(base, fresh)
            self.column.update({i: base + n for n, i in enumerate(new)})
        return [self.column[i] for i in idx]


def centre_rms(
    ctx: Context,
    tc: TargetCandidates,
    sight: Sight,
    t: int | np.ndarray,
    j: int,
    size_mm: float | np.ndarray,
) -> float | np.ndarray:
    """RMS [mm] per axis of target ``t``'s centre measured from station column ``j`` with an
    item of ``size_mm`` (the user's figure when ``target_rms_mm`` is set); ``t`` and
    ``size_mm`` arrays of targets and their items: an array, computed type by type."""
    st, sc = ctx.settings, ctx.scanner
    ts = np.atleast_1d(np.asarray(t, dtype=np.int64))
    size = np.broadcast_to(np.asarray(size_mm, dtype=float), ts.shape)
    if st.target_rms_mm is not None:
        out = np.full(ts.shape, float(st.target_rms_mm))
    else:
        out = np.empty(ts.shape)
        types = tc.type[ts]
        for ty in dict.fromkeys(types.tolist()):
            one = types == ty
            at = ts[one]
            s = sight.slope_m[at, j]
            out[one] = target_centre_rms_mm(
                "sphere" if ty == "control" else ty,
                size[one],
                s,
                sight.cos_incidence[at, j],
                sc.range_rms_at(s),
                sc.angle_rms_arcsec,
                sight.spacing_mm[at, j],
                floor_mm=st.target_floor_mm,
                incidence_noise=st.incidence_ranging,
            )
    return float(out[0]) if np.ndim(t) == 0 else out


def _item_sizes(
    ctx: Context, tc: TargetCandidates, targets: np.ndarray, need_mm: np.ndarray
) -> np.ndarray:
    """:func:`~planner.targets.chosen_sizes` of each target's type; 200 [mm] for a control
    point, measured as a sphere-sized mark."""
    out = np.full(len(targets), 200.0)
    types = tc.type[targets]
    for ty in dict.fromkeys(types.tolist()):
        if ty != "control":
            one = types == ty
            out[one] = chosen_sizes(need_mm[one], ty, ctx.settings.inventory)
    return out


def _a_matrix(lever_mm: np.ndarray, levelled: bool) -> np.ndarray:
    """(…, 3, p) design rows of a target at ``lever_mm`` from the child station."""
    x, y, z = lever_mm[..., 0], lever_mm[..., 1], lever_mm[..., 2]
    a = np.zeros((*lever_mm.shape[:-1], 3, 6))
    a[..., 0, 0] = a[..., 1, 1] = a[..., 2, 2] = 1.0  # the shift
    a[..., 0, 4], a[..., 0, 5] = z, -y  # the small rotation's lever
    a[..., 1, 3], a[..., 1, 5] = -z, x
    a[..., 2, 3], a[..., 2, 4] = y, -x
    return a[..., [0, 1, 2, 5]] if levelled else a


def _probe_errors(n_mats: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """Largest per-axis RMS [mm] of the child's error at the probe points, for a stack of
    positive-definite normal matrices (B, p, p) of its registration (the link alone; their
    lower triangles are read); ``rows`` (3P, p) the probes' design rows. NaN for a matrix
    that is not positive definite. Whether a matrix fixes the registration is for the caller
    to judge (:func:`_well_posed`). The same numbers as rᵀ·inv(N)·r to rounding (a test:
    1e-10 relative; they differ in the last bits, about 1e-14), not bit for bit."""
    out = np.empty(len(n_mats))
    _probe_errors_kernel(np.ascontiguousarray(n_mats), np.ascontiguousarray(rows), out)
    return out


@njit(cache=True, nogil=True)
def _probe_errors_kernel(n_mats, rows, out):  # pragma: no cover - compiled
    """:func:`_probe_errors` compiled, matrix by matrix: N = L·Lᵀ (Cholesky), each probe
    row's variance rᵀN⁻¹r = |L⁻¹r|² by forward substitution, the largest, its root. NaN
    for a matrix that is not positive definite."""
    p = n_mats.shape[1]
    low = np.empty((p, p))
    z = np.empty(p)
    for b in range(n_mats.shape[0]):
        ok = True
        for i in range(p):
            for k in range(i + 1):
                acc = n_mats[b, i, k]
                for m in range(k):
                    acc -= low[i, m] * low[k, m]
                if i == k:
                    if not acc > 0.0:
                        ok = False
                        break
                    low[i, i] = np.sqrt(acc)
                else:
                    low[i, k] = acc / low[k, k]
            if not ok:
                break
        if not ok:
            out[b] = np.nan
            continue
        worst = 0.0
        for r in range(rows.shape[0]):
            var = 0.0
            for i in range(p):
                acc = rows[r, i]
                for m in range(i):
                    acc -= low[i, m] * z[m]
                z[i] = acc / low[i, i]
                var += z[i] * z[i]
            worst = max(worst, var)
        out[b] = np.sqrt(worst)


def _well_posed(n_mats: np.ndarray, order: np.ndarray) -> int | None:
    """The first of ``order`` (indices into the stack ``n_mats``) whose matrix fixes a
    registration (:func:`~planner.registration_error.scaled_condition`), or None. One
    matrix at a time: the greedy choice needs only its best trial's, and that is nearly
    always the first."""
    for i in order:
        if scaled_condition(n_mats[i]) < MAX_CONDITION:
            return int(i)
    return None


#: The facade points a link's error is judged at: the farthest from the station and a
#: spread of the rest (the error grows with the lever arm, so these bound it).
MAX_PROBES = 16


def _probes(points: np.ndarray, station: np.ndarray) -> np.ndarray:
    if len(points) <= MAX_PROBES:
        return points
    d = np.linalg.norm(points - station, axis=1)
    far = np.argsort(d)[-MAX_PROBES // 2 :]
    spread = np.linspace(0, len(points) - 1, MAX_PROBES // 2).astype(int)
    return points[np.unique(np.concatenate([far, spread]))]


#: How much below the error with every common target a link's bound is taken, so that the
#: arithmetic's rounding (the matrices differ only in the order they are summed where a link
#: takes them all) can never lift the bound over the link's own error.
BOUND_MARGIN = 1e-3


def _all_targets_error(
    common: np.ndarray,
    xyz: np.ndarray,
    sigma2: np.ndarray,
    child_xyz: np.ndarray,
    probes: np.ndarray,
    levelled: bool,
) -> float:
    """A lower bound [mm] of the error :func:`_choose_link_targets` gives a link over
    ``common``: the error with every one of them. The targets a link chooses are some of
    ``common``, and a target more only adds to the normal matrix (N_all ⪰ N_chosen, so
    each probe's variance with N_all is the smaller); 0 where every common target together
    does not fix the registration (that bound says nothing)."""
    a = _a_matrix((xyz[common] - child_xyz) * 1000.0, levelled)
    n_mat = np.einsum("cip,ciq->pq", a / sigma2[:, None, None], a)
    if scaled_condition(n_mat) >= MAX_CONDITION:
        return 0.0
    g = _a_matrix((probes - child_xyz) * 1000.0, levelled)
    error = float(_probe_errors(n_mat[None], g.reshape(-1, g.shape[-1]))[0])
    return error * (1.0 - BOUND_MARGIN)


def _choose_link_targets(
    common: np.ndarray,
    xyz: np.ndarray,
    sigma2: np.ndarray,
    child_xyz: np.ndarray,
    probes: np.ndarray,
    reused: np.ndarray,
    levelled: bool,
    max_targets: int,
    goal_mm: float,
    must: np.ndarray | None = None,
) -> tuple[list[int], float]:
    """Greedy choice among ``common`` targets (σ_i² + σ_j² per target in ``sigma2``):
    each step adds the target that lowers the child's predicted error at ``probes`` (the
    points :meth:`_Layout.probes_of` picks) most (a target already placed, flagged in
    ``reused``, wins within :data:`MIN_GAIN`), until three are chosen and the
    goal is met, adding no longer helps, or ``max_targets`` are chosen. Targets flagged in
    ``must`` (placed by the surveyor) come first, whatever they add. Returns the targets
    and the link's error [mm] (inf if they cannot fix the registration)."""
    prior = _PRIOR if not levelled else _PRIOR[np.ix_([0, 1, 2, 5], [0, 1, 2, 5])]
    a = _a_matrix((xyz[common] - child_xyz) * 1000.0, levelled)  # (C, 3, p)
    contrib = np.einsum("cip,ciq->cpq", a, a) / sigma2[:, None, None]
    g = _a_matrix((probes - child_xyz) * 1000.0, levelled)
    rows = g.reshape(-1, g.shape[-1])  # (3P, p): the probes' design rows
    chosen = [] if must is None else [int(c) for c in np.flatnonzero(must[common])]
    chosen = chosen[: int(max_targets)]
    n_mat = contrib[chosen].sum(axis=0) if chosen else np.zeros(prior.shape)
    error = np.inf
    if chosen and scaled_condition(n_mat + prior) < MAX_CONDITION:
        error = float(_probe_errors((n_mat + prior)[None], rows)[0])
    free = np.ones(len(common), dtype=bool)
    free[chosen] = False
    while len(chosen) < max_targets:
        left = np.flatnonzero(free)
        if not len(left) or (len(chosen) >= 3 and error <= goal_mm):
            break  # three chosen and the goal met: whatever a trial gave, the loop ends here
        mats = n_mat + contrib[left] + prior
        trial = _probe_errors(mats, rows)
        order = np.argsort(trial, kind="stable")
        best = _well_posed(mats, order)
        new_error = np.inf if best is None else float(trial[best])
        best = 0 if best is None else best
        if np.isfinite(new_error) and reused[left].any():
            r = _well_posed(mats, order[reused[left][order]])
            if r is not None and trial[r] <= new_error * (1 + MIN_GAIN):
                best, new_error = r, float(trial[r])
        if len(chosen) >= 3 and new_error > error * (1 - MIN_GAIN):
            break
        chosen.append(int(left[best]))
        free[left[best]] = False
        n_mat = n_mat + contrib[left[best]]
        error = new_error
    if len(chosen) < 3 or scaled_condition(n_mat) > MAX_CONDITION:
        return [], np.inf
    return [int(common[c]) for c in chosen], float(_probe_errors(n_mat[None], rows)[0])


@dataclass(kw_only=True)
class Network:
    """The registration network over the chosen stations."""

    stations: np.ndarray  # candidate indices: cover stations first, then linking ones
    n_link_stations: int
    links: list[Link]  # the registrations (a tree from the datum), parent first
    link_error_mm: dict[tuple[int, int], float]  # the link alone, at the child's points
    link_sigma_mm: dict[tuple[int, int], float]  # RMS of one target's centre difference
    linkable: list[tuple[int, int, int]]  # every pair with >= 3 common targets (a, b, count)
    targets: list[int]  # target candidate indices placed
    datum: int | None  # a station position, or None for the control network
    error: NetworkError | None  # pose covariances
    n_groups: int
    message: str
    sight: Sight  # of ``stations``
    candidates: TargetCandidates  # where targets could go; ``targets`` index them
    station_xyz: np.ndarray  # (K, 3) scanner centres [m]
    #: every observation adjusted: (station, target) → centre RMS [mm] per axis
    centre_rms: dict[tuple[int, int], float] = field(default_factory=dict)
    #: the time budget ran out before linking stations were looked for
    cut_short: bool = False
    #: groups tied by planned control (:mod:`planner.pipeline.control`)
    ties: list = field(default_factory=list)
    #: how the scans are registered: targets, cloud or hybrid
    mode: str = "targets"
    #: the cloud links used, by (parent, child)
    clouds: dict = field(default_factory=dict)
    #: each link's weakest direction, in words, at its child's facade points
    weakest: dict = field(default_factory=dict)
    #: (K, K) overlap of the stations' scans [%] (None: targets only)
    overlap: np.ndarray | None = None

    @property
    def tied(self) -> np.ndarray:
        if self.error is None:
            return np.zeros(len(self.stations), dtype=bool)
        return self.error.tied

    def registration(self) -> Registration | None:
        """The registration error of the network's stations (exact), for :func:`judging
        <planner.pipeline.evaluate.assign_stations>` a plan."""
        if self.error is None:
            return None
        return Registration(
            pose_cov=self.error.pose_cov,
            station_xyz=self.station_xyz,
            tied=self.error.tied | (len(self.stations) == 1),
        )

    def leaning_datum(self, scanner: Scanner) -> np.ndarray | None:
        """Where the datum whose tilt leans the whole network stands (x, y, z): a scanner
        without a compensator registered to a station datum
        (:func:`~planner.registration_error.datum_tilt_cov`); None where a compensator
        levels every scan or control points fix the vertical."""
        if scanner.is_levelled or self.datum is None or self.error is None:
            return None
        return self.station_xyz[self.datum]

    def leans(self, scanner: Scanner) -> np.ndarray:
        """(K,) the stations whose pose carries the datum's lean: tied to the datum (also
        through a traverse from a tied station), not by planned GNSS control of their own."""
        if self.leaning_datum(scanner) is None:
            return np.zeros(len(self.stations), dtype=bool)
        out = self.tied.copy()
        for tie in self.ties:
            if tie.start < 0:
                out[list(tie.stations)] = False
        return out

    @property
    def datum_station(self) -> int | None:
        """The datum as a candidate index (None: the control network, or no datum)."""
        return None if self.datum is None else int(self.stations[self.datum])

    @property
    def backbone(self) -> np.ndarray:
        """The stations others are registered to (candidate indices): the network's frame,
        which a new choice of stations keeps."""
        parents = {lk.parent for lk in self.links if lk.parent != CONTROL}
        return self.stations[sorted(parents)] if parents else self.stations[:0]

    def estimate(self, cand_xy: np.ndarray, cand_z: np.ndarray) -> Registration | None:
        """The registration error every candidate would have if it joined this network, for
        choosing stations with their registration in view: a station of the network keeps
        its own; another candidate gets the pose error of the nearest tied station, carried
        to where it stands, plus the error of one of this network's better links (its lower
        quartile). An estimate, on the hopeful side: the chosen stations' network is then
        built and judged exactly, and stations are added again where it falls short, while
        a pessimistic estimate (the median link, once targets hide each other) could rule
        out every candidate and leave the samples short."""
        if self.error is None or not self.error.tied.any():
            return None
        tied = np.flatnonzero(self.error.tied)
        net_xyz = self.station_xyz
        xyz = np.column_stack([cand_xy, cand_z])
        _, nearest = cKDTree(net_xyz[tied, :2]).query(cand_xy)
        j = tied[nearest]
        pose = transport_pose_cov(self.error.pose_cov[j], net_xyz[j], xyz)
        links = list(self.error.link_cov.values())
        if links:
            size = [np.trace(c[:3, :3]) for c in links]
            pose += links[int(np.argsort(size)[len(size) // 4])]
        own = self.stations[self.error.tied]
        pose[own] = self.error.pose_cov[self.error.tied]
        return Registration(pose_cov=pose, station_xyz=xyz, tied=np.ones(len(xyz), dtype=bool))


def _coarse(cand_xy: np.ndarray, grid_m: float) -> np.ndarray:
    cells = np.floor(cand_xy / grid_m + 1e-9).astype(np.int64)
    _, first = np.unique(cells, axis=0, return_index=True)
    return np.sort(first)


def _linkable(sight: Sight, tc: TargetCandidates, a: int, b: int) -> np.ndarray:
    """Targets (not control points) both stations can use."""
    both = sight.usable[:, a] & sight.usable[:, b] & ~tc.is_control
    return np.flatnonzero(both)


def _components(k: int, edges: Sequence[tuple[int, int]]) -> np.ndarray:
    """The group (0, 1, …, by each group's lowest station) of each of ``k`` stations joined
    by ``edges`` (scipy's connected components)."""
    pairs = np.asarray(list(edges), dtype=np.int64).reshape(-1, 2)
    graph = sp.coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(k, k))
    return connected_components(graph, directed=False)[1]


#: Common targets closer than this to one line do not fix a registration [m].
MIN_SPREAD_M = 0.3


def _spread(points: np.ndarray) -> bool:
    """Whether three or more target positions (n, 3) are not all on one line."""
    if len(points) < 3:
        return False
    sv = np.linalg.svd(points - points.mean(axis=0), compute_uv=False)
    return bool(sv[1] > MIN_SPREAD_M)


def _strong(sight: Sight, tc: TargetCandidates, a: int, b: int, xyz: np.ndarray) -> bool:
    """Whether two stations share three or more targets that fix a registration."""
    return _spread(xyz[_linkable(sight, tc, a, b)])


def _bridge_pool(ctx: Context, cand_xy: np.ndarray, stations: list[int]) -> np.ndarray:
    """Candidates a linking station is looked for among: a coarse grid of them (not the
    stations themselves) within :data:`BRIDGE_RADIUS_M` of a station."""
    pool = _coarse(cand_xy, max(LINK_GRID_M, ctx.settings.grid_m))
    pool = pool[~np.isin(pool, stations)]
    near = np.hypot(*(cand_xy[pool, None, :] - cand_xy[None, stations, :]).transpose(2, 0, 1))
    return pool[near.min(axis=1) <= BRIDGE_RADIUS_M]


class _PoolHops:
    """Which pool candidates could register to which (P × P), a row made only when the
    search reaches that candidate (``hops[rows]``, (len(rows), P)): a chain is mostly one
    candidate beside the stations, so most rows are never asked. ``strike`` rules a hop out
    both ways (in the rows kept: ``make_rows`` returns new arrays, never views)."""

    def __init__(self, n: int, make_rows: Callable[[np.ndarray], np.ndarray]) -> None:
        self.n, self._make = n, make_rows
        self._rows: dict[int, np.ndarray] = {}

    def __len__(self) -> int:
        return self.n

    def __getitem__(self, rows: np.ndarray) -> np.ndarray:
        at = np.asarray(rows, dtype=np.int64).tolist()
        new = [i for i in dict.fromkeys(at) if i not in self._rows]
        if not self._rows and len(new) > self.n / 2:  # most of them: all at once
            new = list(range(self.n))
        if new:
            self._rows.update(zip(new, self._make(np.array(new, dtype=np.int64)), strict=True))
        return np.stack([self._rows[i] for i in at]) if at else np.zeros((0, self.n), bool)

    def strike(self, a: int, b: int) -> None:
        self[np.array([a, b])]  # made, then edited
        self._rows[a][b] = self._rows[b][a] = False


@dataclass
class _Hops:
    """Which pool candidates could register to which (``adj``, P × P, made as asked) and to
    which stations (``to_st``, P × K) — a necessary condition, cheap for every pair — and
    ``ok(i, j, to_station)``, the full check of one hop. ``cut``: the deadline left pool
    out."""

    pool: np.ndarray
    adj: Callable[[np.ndarray], np.ndarray]  # pool positions (F,) → their rows (F, P)
    to_st: np.ndarray
    ok: Callable[[int, int, bool], bool]
    cut: bool = False


def _target_hops(seen: SightCache, pool: np.ndarray, sight: Sight, deadline: float) -> _Hops | None:
    """Hops by targets: three common targets, checked not to lie on one line."""
    tc = seen.tc
    parts = []  # the pool's sights, a chunk at a time while the time lasts
    for k in range(0, len(pool), BRIDGE_CHUNK):
        if time.monotonic() > deadline:
            break
        parts.append(seen.usable(pool[k : k + BRIDGE_CHUNK]))
    cut = sum(p.shape[1] for p in parts) < len(pool)
    if not parts:
        return None
    pool = pool[: sum(p.shape[1] for p in parts)]
    u_pool = np.hstack(parts) & ~tc.is_control[:, None]
    u_st = sight.usable & ~tc.is_control[:, None]
    rows = u_pool.any(axis=1)  # the targets no pool candidate sees count for no hop
    pool_seen = u_pool[rows].astype(np.float32)
    to_st = (pool_seen.T @ u_st[rows].astype(np.float32)) >= 3

    def adj(at: np.ndarray) -> np.ndarray:  # three common targets, exact in float32 < 2**24
        if len(at) == len(pool):  # every row: the symmetric product, half the work
            return ((pool_seen.T @ pool_seen) >= 3)[at]
        return (pool_seen[:, at].T @ pool_seen) >= 3

    def ok(i: int, j: int, to_station: bool) -> bool:
        other = u_st[:, j] if to_station else u_pool[:, j]
        return _spread(tc.xyz[u_pool[:, i] & other])

    return _Hops(pool, adj, to_st, ok, cut)


#: The number of bits set in each 4-bit number.
_BITS = np.array([bin(v).count("1") for v in range(16)])


def _cloud_hops(
    ctx: Context, seen: SightCache, stations: list[int], pool: np.ndarray
) -> _Hops | None:
    """Hops cloud to cloud: scans overlapping by the settings' minimum, checked to fix
    every direction (:attr:`~planner.pipeline.clouds.CloudLink.fixed`)."""
    k = len(stations)
    every = np.concatenate([stations, pool]).astype(np.int64)
    over = seen.clouds.overlapping(every, seen.cand_xy, ctx.settings.min_overlap_pct)
    axes = seen.clouds.wall_axes(every, seen.cand_xy)
    over &= _BITS[axes[:, None] & axes[None, :]] >= 2  # two walls in common, not parallel
    np.fill_diagonal(over, False)

    def ok(i: int, j: int, to_station: bool) -> bool:
        parent = stations[j] if to_station else int(pool[j])
        return seen.clouds.link(parent, int(pool[i]), seen.cand_xy).fixed

    among = over[k:, k:]
    return _Hops(pool, lambda at: among[at], over[k:, :k], ok)


def _hops(
    ctx: Context,
    seen: SightCache,
    cand_xy: np.ndarray,
    stations: list[int],
    lay: _Layout,
    deadline: float,
) -> _Hops | None:
    """The hops a linking station can make in the layout's registration mode: by targets,
    cloud to cloud, or (hybrid) either. None: no pool, or the deadline left none of it."""
    pool = _bridge_pool(ctx, cand_xy, stations)
    if not len(pool):
        return None
    by_targets = None if lay.mode == "cloud" else _target_hops(seen, pool, lay.sight, deadline)
    if lay.mode == "targets" or (by_targets is None and lay.mode == "hybrid"):
        return by_targets
    pool = pool if by_targets is None else by_targets.pool
    by_clouds = _cloud_hops(ctx, seen, stations, pool)
    if by_targets is None:
        return by_clouds
    t_ok, c_ok = by_targets.ok, by_clouds.ok
    t_adj, c_adj = by_targets.adj, by_clouds.adj
    return _Hops(
        pool,
        lambda at: t_adj(at) | c_adj(at),
        by_targets.to_st | by_clouds.to_st,
        lambda i, j, to_station: t_ok(i, j, to_station) or c_ok(i, j, to_station),
        by_targets.cut,
    )


def _bridges(hops: _Hops, groups: np.ndarray, deadline: float = math.inf) -> tuple[list[int], bool]:
    """The fewest linking candidates that chain every group of stations into one: a
    breadth-first search over the pool's hops, from one group to the nearest other,
    repeated until one group is left, none can be reached or ``deadline`` passes. A chain
    found is checked hop by hop (:attr:`_Hops.ok`) and a hop that fails is struck off
    before searching again. Also whether the deadline cut the search short."""
    adj, to_st, cut = _PoolHops(len(hops.pool), hops.adj), hops.to_st.copy(), hops.cut
    added: list[int] = []
    groups = groups.copy()
    for _ in range(MAX_BRIDGE_SEARCHES):
        if groups.max() == 0:
            break
        if time.monotonic() > deadline:
            cut = True
            break
        chain = _bfs_chain(adj, to_st, groups)
        if chain is None:
            break
        # check the chain's hops: group 0 → chain[-1] → … → chain[0] → another group
        bad = False
        for a, b in zip(chain[1:], chain[:-1], strict=True):
            if not hops.ok(a, b, False):
                adj.strike(a, b)
                bad = True
        for end, mine in ((chain[-1], groups == 0), (chain[0], groups > 0)):
            for s in np.flatnonzero(to_st[end] & mine):
                if not hops.ok(end, int(s), True):
                    to_st[end, s] = False
                    bad = True
        if bad:
            continue
        added += [int(hops.pool[i]) for i in chain]
        # the reached group joins group 0
        hit = {int(g) for i in chain for g in groups[to_st[i] & (groups > 0)]}
        groups = np.where(np.isin(groups, list(hit)), 0, groups)
        groups = np.unique(groups, return_inverse=True)[1]
    return added, cut


#: Linking stations are searched this close to the stations they link [m].
BRIDGE_RADIUS_M = 60.0
#: The bridge search computes its candidates' sights this many at a time (the time budget
#: is checked between chunks).
BRIDGE_CHUNK = 512
#: How many chains the bridge search tries (each failing hop struck off) before giving up.
MAX_BRIDGE_SEARCHES = 200


def _bfs_chain(
    adj: np.ndarray | _PoolHops, hop: np.ndarray, groups: np.ndarray
) -> list[int] | None:
    """Shortest chain of pool candidates from group 0 to any other group (pool indices,
    the one touching the other group first), or None; ``adj`` (P, P; rows are read only
    for the candidates reached) and ``hop`` (P, K): the hops among the pool and from the
    pool to the stations.

    Breadth-first, a level at a time on the boolean hop matrix; within a level the order is
    that of a plain queue (by parent, then index), so the chain found is the queue's."""
    frontier = np.flatnonzero(hop[:, groups == 0].any(axis=1))
    goal = hop[:, groups > 0].any(axis=1)
    prev = np.full(len(adj), -2)  # -2: not reached; -1: a start
    prev[frontier] = -1
    while len(frontier):
        hit = frontier[goal[frontier]]
        if len(hit):
            i, chain = int(hit[0]), []
            while i != -1:
                chain.append(i)
                i = int(prev[i])
            return chain
        reach = adj[frontier]  # (F, P)
        new = np.flatnonzero(reach.any(axis=0) & (prev == -2))
        if not len(new):
            return None
        first = reach[:, new].argmax(axis=0)  # the earliest parent in queue order
        prev[new] = frontier[first]
        frontier = new[np.lexsort((new, first))]
    return None


class _Layout:
    """Stations, what they see, which pairs can be linked, and the best tree of
    registrations over them (datum and links, the accumulated error at each station)."""

    def __init__(
        self,
        ctx: Context,
        seen: SightCache,
        cand_xy: np.ndarray,
        stations: list[int],
        probes: dict[int, np.ndarray],
        goal_mm: float,
        datum: int | None = None,
        deadline: float = math.inf,
    ) -> None:
        tc, st = seen.tc, ctx.settings
        self.ctx, self.tc, self.goal_mm, self.seen = ctx, tc, goal_mm, seen
        self.by_hand = seen.by_hand if seen.by_hand.any() else None
        self.stations = stations
        self.probes = probes
        self.sight = seen(stations)
        k = self.k = len(stations)
        self.station_xyz = np.column_stack([cand_xy[stations], ctx.station_z(cand_xy[stations])])
        self.mode = st.registration_for(ctx.scanner)
        self._cloud_errors: dict[tuple[int, int], float] = {}
        self.surf = self.overlap = None
        pairs = set()
        if self.mode != "cloud":
            pairs |= {
                (a, b)
                for a in range(k)
                for b in range(a + 1, k)
                if _strong(self.sight, tc, a, b, tc.xyz)
            }
        if self.mode != "targets" and k > 1:
            self.surf = seen.clouds.take(np.array(stations), cand_xy)
            self.overlap = clouds.overlap_matrix(self.surf)
            pairs |= {
                (a, b)
                for a, b in zip(
                    *np.nonzero(np.triu(self.overlap >= st.min_overlap_pct, 1)), strict=True
                )
                if self.cloud(int(a), int(b)) is not None
            }
        self.pairs = sorted((int(a), int(b)) for a, b in pairs)
        # by candidate index (CONTROL for the control network), shared by the layouts of a
        # plan: a link depends on its two stations and the child's facade points only
        self._memo = seen.memo_for(goal_mm)
        self._links: dict[tuple[int, int], tuple[list[int], float]] = {}
        self._bounds: dict[tuple[int, int], float] = {}  # of :meth:`bound`
        self._sigma2 = np.full((k, len(tc.xyz)), np.nan)  # σ² of :meth:`sigma`, as asked
        self._judged_at: dict[int, np.ndarray] = {}  # of :meth:`probes_of`, as asked
        # the datum: the control network if any station sees three control points, else the
        # station from which the tree of registrations accumulates the least error
        # (Dijkstra on the links' variances; with 6 parameters, plus the datum's tilt at
        # each station's facade points), the choice keeping the worst station best
        roots: list[int] = []
        if tc.is_control.any():
            seen_ctl = any(np.isfinite(self.link(CONTROL, j)[1]) for j in range(k))
            roots = [CONTROL] if seen_ctl else []
        kept = not roots and datum in stations  # kept from the network this one grows from
        if kept:
            roots = [stations.index(datum)]
        best = self._best_tree(roots or range(k), deadline)
        if kept and best is not None and len(best[3]) < k:  # it does not reach them all
            free = self._best_tree(range(k), deadline)
            best = free if len(free[3]) > len(best[3]) else best
        self.datum, self.tree, self.cost = best[1:] if best else (None, [], {})
        self.worst_var = max(self.cost.values()) if self.cost else np.inf

    def _best_tree(self, roots: Sequence[int], deadline: float = math.inf) -> tuple | None:
        """(key, root, tree, cost) of the root whose tree reaches the most stations, then
        keeps the worst station's error smallest — with 6 parameters, its variance plus the
        datum's lean at its facade points (:meth:`datum_tilt_var`); ties go to the lowest
        root. The most central root is tried first, and others only while half of the time
        left before ``deadline`` remains (the links and the layout after it need the rest). Once a
        root's tree reaches every station, another root's search stops at the first station
        worse than that tree's worst: it cannot win (and none of its links is made)."""
        roots = list(roots)
        if len(roots) > 1:
            first = _central(self.station_xyz[roots])  # a position in roots
            roots = [roots[first], *roots[:first], *roots[first + 1 :]]
        best = None
        now = time.monotonic()
        stop = now + ROOT_SEARCH_SHARE * (deadline - now) if math.isfinite(deadline) else deadline
        for n, root in enumerate(roots):
            if n and time.monotonic() > stop:
                break
            tilt = self.datum_tilt_var(root)
            beaten = best[0][1] if best is not None and best[0][0] == -self.k else np.inf
            grown = _tree(root, self.k, self.pairs, self.link, self.bound, (tilt, beaten))
            if grown is None:
                continue
            tree, cost = grown
            worst = max((c + tilt[j] for j, c in cost.items()), default=np.inf)
            key = (-len(cost), worst, root)  # ties: the first root
            if best is None or key < best[0]:
                best = (key, root, tree, cost)
        return best

    def datum_tilt_var(self, root: int) -> np.ndarray:
        """(K,) the largest height variance [mm²] the datum's tilt gives each station's
        facade points with ``root`` as the datum (none for a levelled scanner, whose
        stations keep their own tilt, or for the control network):
        :func:`~planner.registration_error.datum_tilt_cov`."""
        sc = self.ctx.scanner
        if root == CONTROL or sc.is_levelled:
            return np.zeros(self.k)
        xy, starts = self._probe_xy
        far = np.maximum.reduceat(np.hypot(*(xy - self.station_xyz[root, :2]).T), starts)
        return np.square(datum_lean_mm(far, sc.initial_tilt_rms_arcsec))

    @cached_property
    def _probe_xy(self) -> tuple[np.ndarray, np.ndarray]:
        """Every station's facade points (:meth:`probe`) in plan, one after another, and
        where each station's begin (for :meth:`datum_tilt_var`, asked for every root)."""
        pts = [self.probe(j)[:, :2] for j in range(self.k)]
        starts = np.cumsum([0, *(len(p) for p in pts[:-1])])
        return np.concatenate(pts), starts

    def sigma(self, j: int, t: int) -> float:
        """Centre RMS of target t from station j with the largest item it could need."""
        return self._sigmas(j, [t])[0]

    def _sigmas(self, j: int, targets: list[int]) -> list[float]:
        """:meth:`sigma` of each of ``targets``, kept in the plan's memo; those not yet in
        it computed together (:func:`centre_rms` of many)."""
        keys = [("rms", self.stations[j], t) for t in targets]
        new = [n for n, key in enumerate(keys) if key not in self._memo]
        if new:
            at = np.array([targets[n] for n in new], dtype=np.int64)
            size = _item_sizes(self.ctx, self.tc, at, self.sight.need_mm[at, j])
            rms = centre_rms(self.ctx, self.tc, self.sight, at, j, size)
            self._memo.update(zip([keys[n] for n in new], rms.tolist(), strict=True))
        return [self._memo[key] for key in keys]

    def sigma2(self, j: int, targets: np.ndarray) -> np.ndarray:
        """:meth:`sigma` squared for each of ``targets`` from station j (kept by station: a
        station's targets are asked again by each of its links)."""
        row = self._sigma2[j]
        todo = targets[np.isnan(row[targets])].tolist()
        for t, sigma in zip(todo, self._sigmas(j, todo), strict=True):
            row[t] = sigma**2
        return row[targets]

    def probe(self, j: int) -> np.ndarray:
        """The facade points station j serves (a linking station: its targets' spread)."""
        pts = self.probes.get(j)
        if pts is None or not len(pts):
            seen = np.flatnonzero(self.sight.usable[:, j])
            if not len(seen):
                return self.station_xyz[j : j + 1] + np.array([[1.0, 0.0, 0.0]])
            pts = self.tc.xyz[seen]
        return pts

    def probes_of(self, j: int) -> np.ndarray:
        """The points a link's error at station j is judged at (:func:`_probes` of
        :meth:`probe`), made once for the layout."""
        if j not in self._judged_at:
            self._judged_at[j] = _probes(self.probe(j), self.station_xyz[j])
        return self._judged_at[j]

    def cloud(self, i: int, j: int) -> CloudLink | None:
        """The cloud-to-cloud registration of j to i, if their scans overlap enough and their
        common surfaces fix it (None otherwise)."""
        if self.surf is None or i == CONTROL:
            return None
        cl = self.seen.clouds.link(self.stations[i], self.stations[j], self.seen.cand_xy)
        ok = cl.fixed and cl.overlap_pct >= self.ctx.settings.min_overlap_pct
        return cl if ok else None

    def link(
        self, i: int, j: int, placed: set[int] | None = None, stands: _Stands | None = None
    ) -> tuple[list[int], float]:
        """Targets and error of registering j to i (i may be CONTROL); cached unless
        ``placed`` (targets already set up, preferred) is given; ``stands``: the spheres set
        up and the sight lines in use, which rule out targets hidden or hiding. Cloud to
        cloud (no targets): the cloud link; hybrid: the cloud link unless it is weaker than
        the goal and the targets do better."""
        cl = self.cloud(i, j)
        if cl is not None or self.mode == "cloud":
            err = self._cloud_error(cl, i, j) if cl is not None else np.inf
            if self.mode == "cloud" or err <= self.goal_mm:
                return [], err
            by_targets = self._target_link(i, j, placed, stands)
            return by_targets if by_targets[1] < err else ([], err)
        return self._target_link(i, j, placed, stands)

    def bound(self, i: int, j: int) -> float:
        """A lower bound [mm] of :meth:`link`'s error of j to i, cheap where the link is not
        yet known: the error with every common target (:func:`_all_targets_error`). A link
        known, cloud to cloud, or to the control network: its own error."""
        key = (i, j)
        if key not in self._bounds:
            cached = key in self._links or (i != CONTROL and self._shared_key(i, j) in self._memo)
            if cached or i == CONTROL or self.mode == "cloud" or self.cloud(i, j) is not None:
                self._bounds[key] = self.link(i, j)[1]
            else:  # kept for the plan's layouts, as the links are (:meth:`_shared_key`)
                common = _linkable(self.sight, self.tc, i, j)
                shared = ("bound", *self._shared_key(i, j), common.tobytes())
                if shared not in self._memo:
                    self._memo[shared] = (
                        _all_targets_error(
                            common,
                            self.tc.xyz,
                            self.sigma2(i, common) + self.sigma2(j, common),
                            self.station_xyz[j],
                            self.probes_of(j),
                            self.ctx.scanner.is_levelled,
                        )
                        if len(common) >= 3
                        else np.inf
                    )
                self._bounds[key] = self._memo[shared]
        return self._bounds[key]

    def _shared_key(self, i: int, j: int) -> tuple:
        """The key of the link of j to i in the memo the plan's layouts share."""
        st_i = self.stations[i] if i != CONTROL else CONTROL
        return (st_i, self.stations[j], self.probes_of(j).tobytes())

    def _cloud_error(self, cl: CloudLink, i: int, j: int) -> float:
        """The cloud link of j to i: its own error at j's facade points [mm] (kept per
        link; ``cl.parent`` is a position in the pair it was computed from, not i)."""
        if (i, j) not in self._cloud_errors:
            self._cloud_errors[(i, j)] = self.error_at_probes(cl.cov, j)
        return self._cloud_errors[(i, j)]

    def error_at_probes(self, cov: np.ndarray, j: int) -> float:
        """The largest RMS [mm] a pose covariance ``cov`` (at station j) gives the facade
        points j serves, along any axis; inf where the covariance leaves a direction free."""
        if not np.isfinite(np.diag(cov)).all():
            return np.inf
        pts = self.probes_of(j)
        g = _a_matrix((pts - self.station_xyz[j]) * 1000.0, levelled=False)
        return float(np.sqrt(np.einsum("nij,jk,nik->ni", g, cov, g).max()))

    def _target_link(
        self, i: int, j: int, placed: set[int] | None = None, stands: _Stands | None = None
    ) -> tuple[list[int], float]:
        key = (i, j)
        if placed is None and key in self._links:
            return self._links[key]
        probe = self.probes_of(j)
        shared = self._shared_key(i, j)
        if placed is None and shared in self._memo:
            self._links[key] = self._memo[shared]
            return self._links[key]
        tc = self.tc
        if i == CONTROL:
            common = np.flatnonzero(self.sight.usable[:, j] & tc.is_control)
        else:
            common = _linkable(self.sight, tc, i, j)
        if stands is not None:
            common = common[~stands.hidden((i, j), common)]
        if i == CONTROL:
            s2 = np.array([tc.control_rms_mm[t] ** 2 + self.sigma(j, t) ** 2 for t in common])
        else:
            s2 = self.sigma2(i, common) + self.sigma2(j, common)
        out: tuple[list[int], float] = ([], np.inf)
        free = np.ones(len(common), dtype=bool)
        while free.sum() >= 3:
            out = self._choose(i, j, common[free], s2[free], probe, placed or set())
            hiding = stands.among((i, j), out[0]) if stands is not None else []
            if not hiding:  # no sphere of the choice hides another of it
                break
            free &= ~np.isin(common, hiding)
            out = ([], np.inf)
        if placed is None:
            self._links[key] = self._memo[shared] = out
        return out

    def _choose(
        self,
        i: int,
        j: int,
        common: np.ndarray,
        s2: np.ndarray,
        probe: np.ndarray,
        placed: set[int],
    ) -> tuple[list[int], float]:
        """:func:`_choose_link_targets` for the link of j to i over ``common`` (``s2`` their
        variances), kept for the plan's layouts: the choice depends on the two stations, the
        targets offered, which of them are placed and the points it is judged at only (the
        rest is the memo's key: :meth:`SightCache.memo_for`)."""
        reused = np.isin(common, list(placed))
        key = (
            "choose",
            self.stations[i] if i != CONTROL else CONTROL,
            self.stations[j],
            probe.tobytes(),
            common.tobytes(),
            reused.tobytes(),
        )
        if key not in self._memo:
            self._memo[key] = _choose_link_targets(
                common,
                self.tc.xyz,
                s2,
                self.station_xyz[j],
                probe,
                reused,
                self.ctx.scanner.is_levelled,
                self.ctx.settings.max_targets_per_link,
                self.goal_mm,
                self.by_hand,
            )
        targets, error = self._memo[key]
        return list(targets), error

    def weak_groups(self, weak_mm: float) -> np.ndarray:
        """Groups of stations joined by links whose own error is at most ``weak_mm``. Only
        what the groups need is made: the links already known first (the tree's), then a
        pair only while its stations are in different groups, and a link only where its
        bound is within ``weak_mm``."""
        joined = DisjointSet(range(self.k))
        ok = []
        known = sorted(
            self.pairs, key=lambda ab: ab not in self._links and ab[::-1] not in self._links
        )
        for a, b in known:
            if joined.connected(a, b):
                continue
            ways = ((a, b), (b, a)) if (b, a) not in self._links else ((b, a), (a, b))
            if any(self.bound(i, j) <= weak_mm and self.link(i, j)[1] <= weak_mm for i, j in ways):
                joined.merge(a, b)
                ok.append((a, b))
        return _components(self.k, ok)


#: A link whose targets the spheres of earlier links hide is registered to another station
#: instead if that link's error is within this factor of its own (or within the goal); else
#: it keeps its targets, and the network's message says to set such spheres up only after
#: those scans (which ones is not yet named: the field booklet's set-up order is to come).
HIDDEN_DETOUR = 1.5


class _Stands:
    """The sphere targets set up so far, as obstacles to the other targets' sight lines
    (:func:`~planner.pipeline.visibility.stand_blocks`; each as big as the largest sphere of
    the inventory, the size a later user may still need), and the sight lines in use, which
    a further sphere must not hide."""

    def __init__(self, ctx: Context, tc: TargetCandidates, station_xyz: np.ndarray) -> None:
        sizes = [i.size_mm for i in ctx.settings.inventory if i.type == "sphere"]
        self.radius_m = max(sizes, default=0.0) / 2000.0
        self.tc, self.station_xyz = tc, station_xyz
        self.end = tc.xyz.copy()
        # where target sights end (:func:`sights`)
        self.end[:, :2] += target_sight_offset(ctx, tc)[:, None] * tc.normal
        self.spheres: list[int] = []
        self.lines: set[tuple[int, int]] = set()  # (station column, target)

    def _blocks(self, src: np.ndarray, dst: np.ndarray, own: np.ndarray) -> np.ndarray:
        """Whether the spheres set up hide each sight line (``own``: its target)."""
        block = stand_blocks(src, dst, self.tc.xyz[self.spheres], self.radius_m)
        return (block & (own[:, None] != np.array(self.spheres)[None, :])).any(axis=1)

    def hidden(self, stations: Sequence[int], targets: np.ndarray) -> np.ndarray:
        """Mask over ``targets``: hidden from one of ``stations`` (columns; CONTROL
        skipped) by a sphere set up, or a sphere that would hide a sight line in use."""
        out = np.zeros(len(targets), dtype=bool)
        own = [j for j in stations if j != CONTROL]
        if not len(targets):
            return out
        if self.spheres and own:
            src = np.repeat(self.station_xyz[own], len(targets), axis=0)
            tt = np.tile(targets, len(own))
            out |= self._blocks(src, self.end[tt], tt).reshape(len(own), -1).any(axis=0)
        new = (self.tc.type[targets] == "sphere") & ~np.isin(targets, self.spheres)
        if self.lines and new.any():
            lines = sorted(self.lines)
            src = self.station_xyz[[j for j, _ in lines]]
            dst = self.end[[t for _, t in lines]]
            hides = stand_blocks(src, dst, self.tc.xyz[targets[new]], self.radius_m)
            out[new] |= hides.any(axis=0)
        return out

    def among(self, stations: Sequence[int], targets: Sequence[int]) -> list[int]:
        """The spheres not yet set up among ``targets`` that hide another of them from one
        of ``stations`` (columns; CONTROL skipped)."""
        own = [j for j in stations if j != CONTROL]
        targets = np.asarray(targets, dtype=np.int64)
        new = targets[(self.tc.type[targets] == "sphere") & ~np.isin(targets, self.spheres)]
        if not len(new) or not own:
            return []
        src = np.repeat(self.station_xyz[own], len(targets), axis=0)
        tt = np.tile(targets, len(own))
        block = stand_blocks(src, self.end[tt], self.tc.xyz[new], self.radius_m)
        block &= tt[:, None] != new[None, :]
        return [int(u) for u in new[block.any(axis=0)]]

    def hide(self, sight: Sight, targets: Sequence[int]) -> Sight:
        """``sight`` (a copy) with those of ``targets`` the spheres set up hide from a
        station not usable from it (a link's own sight lines kept: the few a link can only
        have behind another's sphere, which the network's message tells)."""
        usable = sight.usable.copy()
        rows = np.asarray(sorted(targets), dtype=np.int64)
        tt, jj = np.nonzero(usable[rows])
        tt = rows[tt]
        if self.spheres and len(tt):
            hidden = self._blocks(self.station_xyz[jj], self.end[tt], tt)
            hidden &= [(j, t) not in self.lines for j, t in zip(jj, tt, strict=True)]
            usable[tt[hidden], jj[hidden]] = False
        return replace(sight, usable=usable)

    def set_up(self, stations: Sequence[int], targets: Sequence[int]) -> None:
        """Targets now in use, seen from ``stations`` (columns; CONTROL skipped)."""
        for t in targets:
            if self.tc.type[t] == "sphere" and t not in self.spheres:
                self.spheres.append(int(t))
            self.lines |= {(int(j), int(t)) for j in stations if j != CONTROL}


def build_network(
    ctx: Context,
    tc: TargetCandidates,
    cand_xy: np.ndarray,
    chosen: np.ndarray,
    probes: dict[int, np.ndarray],
    *,
    goal_mm: float,
    weak_mm: float = np.inf,
    cache: SightCache | None = None,
    datum: int | None = None,
    deadline: float = math.inf,
) -> Network:
    """Link the chosen stations into one registration network (module docstring).

    ``probes`` maps a position in ``chosen`` to the facade points it serves (P, 3) [m]; a
    linking station without points is probed at its own targets' spread. A link whose own
    error exceeds ``weak_mm`` is strengthened, where linking stations can, by a detour
    that makes the worst station's error smaller. ``cache`` keeps the candidates' sights
    between calls. ``datum`` (a candidate index) keeps the datum of the network this one
    grows from, when it is among the stations. After ``deadline`` (a
    :func:`time.monotonic` time) no linking stations are looked for (``cut_short``).
    """
    levelled = ctx.scanner.is_levelled
    seen = cache if cache is not None else SightCache(ctx, tc, cand_xy)
    stations = [int(c) for c in chosen]
    n_cover = len(stations)
    lay = _Layout(ctx, seen, cand_xy, stations, probes, goal_mm, datum, deadline)
    groups = _components(lay.k, lay.pairs)
    cut_short = False
    if groups.max() > 0:  # stations neither targets nor clouds tie: linking stations
        hops = _hops(ctx, seen, cand_xy, stations, lay, deadline)
        extra, cut_short = _bridges(hops, groups, deadline) if hops else ([], True)
        if extra:
            lay = _Layout(ctx, seen, cand_xy, stations + extra, probes, goal_mm, datum, deadline)
    weak = np.zeros(1)
    if np.isfinite(weak_mm) and lay.k > 1 and time.monotonic() <= deadline:
        weak = lay.weak_groups(weak_mm)
    if weak.max() > 0:  # too weak: a detour, if it helps
        hops = _hops(ctx, seen, cand_xy, lay.stations, lay, deadline)
        extra, _ = _bridges(hops, weak, deadline) if hops else ([], True)
        if extra:
            trial = _Layout(
                ctx, seen, cand_xy, lay.stations + extra, probes, goal_mm, datum, deadline
            )
            if len(trial.cost) >= len(lay.cost) and trial.worst_var < 0.8 * lay.worst_var:
                lay = trial
    stations, sight, station_xyz, datum = lay.stations, lay.sight, lay.station_xyz, lay.datum
    k, xyz = lay.k, tc.xyz
    # the links in tree order, each preferring the targets already set up (those the surveyor
    # placed by hand are taken first by every link that sees them: _choose_link_targets)
    placed: set[int] = set()
    links: list[Link] = []
    link_error: dict[tuple[int, int], float] = {}
    stands = _Stands(ctx, tc, station_xyz)
    tied = [] if datum is None or datum == CONTROL else [datum]
    paired = set(lay.pairs)
    behind = 0  # links that can only use a target another link's sphere hides
    for parent, child in lay.tree:
        targets, err = lay.link(parent, child, placed, stands)
        cl = lay.cloud(parent, child)
        if not targets and cl is not None:  # cloud to cloud
            links.append(Link(parent, child, (), cl.info))
            link_error[(parent, child)] = err
            tied.append(child)
            continue
        if not targets:  # the targets set up hide this link's: register it to another
            bound = max(lay.goal_mm, HIDDEN_DETOUR * lay.link(parent, child)[1])
            others = [(i, lay.link(i, child, placed, stands)) for i in tied if i != parent]
            others = [
                (e, i, t)
                for i, (t, e) in others
                if t and e <= bound and (min(i, child), max(i, child)) in paired
            ]
            if others:
                err, parent, targets = min(others)
        if not targets:  # no good other either: targets that do not hide one another
            targets, err = lay.link(parent, child, placed, _Stands(ctx, tc, station_xyz))
            behind += 1  # behind a sphere of another link: the message says so
        if not targets:
            targets, err = lay.link(parent, child)
        links.append(Link(parent, child, tuple(targets)))
        link_error[(parent, child)] = err
        placed.update(targets)
        stands.set_up((parent, child), targets)
        tied.append(child)
    sight = stands.hide(sight, placed)  # the spheres set up hide some targets from some stations
    # the final sizes: each placed target gets the smallest item that serves every station
    # using it, and the centre RMS with that item
    users: dict[int, set[int]] = {}
    for lk in links:
        for t in lk.targets:
            users.setdefault(t, set()).add(lk.child)
            if lk.parent != CONTROL:
                users[t].add(lk.parent)
    final_rms: dict[tuple[int, int], float] = {}  # the links' observations
    observed: dict[tuple[int, int], float] = {}  # and every other station's that sees one
    for t, who in users.items():
        need = max(float(sight.need_mm[t, j]) for j in who)
        size = float(_item_sizes(ctx, tc, np.array([t]), np.array([need]))[0])
        for j in who:
            final_rms[(j, t)] = observed[(j, t)] = centre_rms(ctx, tc, sight, t, j, size)
        if tc.type[t] == "control":
            continue  # a control point is observed by the stations its links tie to it
        for j in map(int, np.flatnonzero(sight.usable[t] & (sight.need_mm[t] <= size))):
            if (j, t) not in observed:
                observed[(j, t)] = centre_rms(ctx, tc, sight, t, j, size)
    control_rms = {int(t): float(tc.control_rms_mm[t]) for t in np.flatnonzero(tc.is_control)}
    link_sigma: dict[tuple[int, int], float] = {}
    error = None
    if links or datum is not None:
        error = propagate(
            station_xyz,
            xyz,
            final_rms,
            links,
            datum=None if datum == CONTROL else datum,
            control_rms_mm=control_rms,
            levelled=levelled,
            tilt_rms_arcsec=ctx.scanner.initial_tilt_rms_arcsec,
        )
    if error is not None and ctx.settings.registration_processing == "adjustment":
        # the registration as it is computed: every target each scan sees, adjusted together
        # (pairwise: each scan registered to its parent on the link's targets, the chain's)
        error.pose_cov = adjust(
            station_xyz,
            xyz,
            observed,
            error.tied,
            datum=None if datum == CONTROL else datum,
            control_rms_mm={t: r for t, r in control_rms.items() if t in users},
            levelled=levelled,
            tilt_rms_arcsec=ctx.scanner.initial_tilt_rms_arcsec,
            planes=_planes(lay.surf),
        )
    if error is not None:
        # each link's own error with the final sizes, at the facade points of its child; and
        # the RMS of one target's centre difference in it (its dilution's denominator)
        for lk in links:
            if lk.info is not None:
                continue  # a cloud link's own error is known (Layout.link)
            key = (lk.parent, lk.child)
            link_error[key] = lay.error_at_probes(error.link_cov[key], lk.child)
            s2 = [
                (control_rms[t] if lk.parent == CONTROL else final_rms[(lk.parent, t)]) ** 2
                + final_rms[(lk.child, t)] ** 2
                for t in lk.targets
            ]
            link_sigma[(lk.parent, lk.child)] = float(np.sqrt(np.mean(s2)))
    weakest = {}  # each link's weakest direction at the middle of its child's facade points
    for lk in links:
        key = (lk.parent, lk.child)
        cov = lay.cloud(*key).cov if lk.info is not None else None
        if cov is None and error is not None and key in error.link_cov:
            cov = error.link_cov[key]
        if cov is not None and np.isfinite(np.diag(cov)).all():
            mid = lay.probe(lk.child).mean(axis=0)
            cov = transport_pose_cov(cov, station_xyz[lk.child], mid)
        weakest[key] = weakest_direction(cov) if cov is not None else ""
    n_groups = int(_components(k, lay.pairs).max() + 1) if k else 0
    untied = int((~error.tied).sum()) if error is not None else k
    message = _message(k, k - n_cover, datum, untied, n_groups, tc, links, lay.mode)
    if behind:
        message += (
            f"; {behind} link(s) use a target behind another link's sphere (set that sphere "
            "up only after those scans)"
        )
    linkable = [(a, b, len(_linkable(sight, tc, a, b))) for a, b in lay.pairs]
    return Network(
        stations=np.array(stations, dtype=np.int64),
        n_link_stations=k - n_cover,
        links=links,
        link_error_mm=link_error,
        link_sigma_mm=link_sigma,
        linkable=linkable,
        targets=sorted(placed),
        datum=None if datum == CONTROL else datum,
        error=error,
        n_groups=n_groups,
        message=message,
        sight=sight,
        candidates=tc,
        station_xyz=station_xyz,
        centre_rms=observed,
        cut_short=cut_short,
        mode=lay.mode,
        weakest=weakest,
        clouds={
            (lk.parent, lk.child): lay.cloud(lk.parent, lk.child)
            for lk in links
            if lk.info is not None
        },
        overlap=lay.overlap,
    )


def _planes(surf: clouds.Surfaces | None) -> tuple | None:
    """The patches as the adjustment takes them (:func:`planner.registration_error.adjust`)."""
    if surf is None:
        return None
    p, j = np.nonzero(surf.seen)
    var = dict(
        zip(zip(j.tolist(), p.tolist(), strict=True), surf.var_mm2[p, j].tolist(), strict=True)
    )
    return surf.xyz, surf.normal, var


#: The share of the time left that the search for the network's datum (its best root) may
#: take; the rest is for the links and the layout after it.
ROOT_SEARCH_SHARE = 0.5


def _central(xyz: np.ndarray) -> int:
    """The station nearest all others (the smallest farthest distance): the datum a
    network grows from when there is no time to grow one from every station."""
    return int(np.argmin(cdist(xyz[:, :2], xyz[:, :2]).max(axis=1)))


def _tree(
    root: int,
    k: int,
    pairs: Sequence[tuple[int, int]],
    link,
    bound=None,
    beaten: tuple[np.ndarray, float] | None = None,
) -> tuple[list, dict] | None:
    """Registrations from ``root`` reaching every station it can, each joined where its
    accumulated error variance is smallest (Dijkstra); and that variance per station.

    ``bound(i, j)``, a lower bound of ``link(i, j)``'s error, makes a link only when the
    search reaches it: a link waits in the queue at its bound, and is made, and queued again
    at its own error, when it comes first. The bound never passes the error, so the links
    come out of the queue in the same order, and the tree is the same, as with every link
    made at once (ties: the lower station, then the lower parent).

    ``beaten`` (extra, worst): None as soon as a station's variance plus its extra must pass
    worst (the caller has a tree that reaches every station and is better): the station just
    reached, or any not yet reached, whose variance can only be larger."""
    neighbours: dict[int, list[int]] = {i: [] for i in range(k)}
    for a, b in pairs:
        neighbours[a].append(b)
        neighbours[b].append(a)
    # (variance, station, parent, made: the link's own error, not its bound)
    if root == CONTROL:
        start = [(link(CONTROL, j)[1] ** 2, j, CONTROL, True) for j in range(k)]
        heap = [s for s in start if np.isfinite(s[0])]
    else:
        heap = [(0.0, root, None, True)]
    cost: dict[int, float] = {}
    heapq.heapify(heap)
    tree = []
    left = np.ones(k, dtype=bool)  # not yet reached
    while heap:
        c, node, parent, made = heapq.heappop(heap)
        if node in cost:
            continue
        if not made:  # the link waited at its bound and comes first: make it
            err = link(parent, node)[1]
            if np.isfinite(err):
                heapq.heappush(heap, (cost[parent] + err**2, node, parent, True))
            continue
        cost[node] = c
        if beaten is not None and c + beaten[0][left].max() > beaten[1]:
            return None
        left[node] = False
        if parent is not None:
            tree.append((parent, node))
        for nb in neighbours[node]:
            if nb not in cost:
                err = link(node, nb)[1] if bound is None else bound(node, nb)
                if np.isfinite(err):
                    heapq.heappush(heap, (c + err**2, nb, node, bound is None))
    return tree, cost


def control_messages(net: Network) -> str:
    """The network's message again, after planned control tied some of its groups."""
    k = len(net.stations)
    untied = int((~net.tied).sum())
    tied_by = sum(len(t.stations) for t in net.ties)
    head = _message(
        k, net.n_link_stations, net.datum, untied, net.n_groups, net.candidates, net.links, net.mode
    )
    if tied_by and untied == 0:
        head = f"{MODE_WORDS[net.mode]} — the {k} stations form one registration network"
    if tied_by:
        head += f" ({tied_by} of them through planned control)"
    return head


#: How each registration mode is said in the summary.
MODE_WORDS = {
    "targets": "by targets",
    "cloud": "cloud to cloud",
    "hybrid": "hybrid (cloud to cloud, targets where a link is weak)",
}


def _message(k, n_link, datum, untied, n_groups, tc, links, mode="targets") -> str:
    return f"{MODE_WORDS[mode]}{_counts(links, mode)} — " + _network_words(
        k, n_link, datum, untied, n_groups, tc, links, mode
    )


def _counts(links, mode) -> str:
    if mode == "targets" or not links:
        return ""
    n_cloud = sum(lk.info is not None for lk in links)
    return f": {n_cloud} cloud link(s), {len(links) - n_cloud} by targets"


def _network_words(k, n_link, datum, untied, n_groups, tc, links, mode) -> str:
    if k <= 1 and not tc.is_control.any():
        return "one station: no registration needed"
    added = f" after adding {n_link} linking station{'s' if n_link != 1 else ''}" if n_link else ""
    if datum == CONTROL:
        n_ctl = len({t for lk in links if lk.parent == CONTROL for t in lk.targets})
        head = f"tied to the site network through {n_ctl} control points"
    else:
        head = f"the {k} stations form one registration network"
    if untied == 0:
        return head + added
    if mode == "cloud":
        return (
            f"{untied} of the {k} stations cannot be tied to the others cloud to cloud (in "
            f"{n_groups} groups: the surfaces they share with the others overlap too little or "
            "leave a direction free, as one straight wall and the ground leave the shift along "
            "the wall); add targets where the clouds are weak (--registration hybrid), move "
            "or add a station that sees a cross wall or a corner, or tie them by control"
        )
    by = "common targets or surfaces" if mode == "hybrid" else "common targets"
    return (
        f"{untied} of the {k} stations cannot be tied to the others by {by} "
        f"(even{added or ' without linking stations'}, in {n_groups} groups); tie them by a "
        "traverse, by control points coordinated with a total station (--control), or add "
        "a station by hand"
    )
