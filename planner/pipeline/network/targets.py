"""Where targets can go and what each station sees of them.

:func:`target_candidates`: flat targets on the planned facades at two heights (so that the
targets of a link spread in height too), spheres on stands on free ground, and the site's
control points. :func:`sights`: line of sight, range, the incidence on a flat target
(checkerboards: at most ``max_target_incidence_deg``), the size each target needs there —
the larger of Sossa's 2d / 4d and practice (points per quadrant, points on the sphere), with
the rule that sets it — and the RMS of its fitted centre
(:func:`planner.registration_error.target_centre_rms_mm`). :class:`SightCache` keeps what
each candidate position sees, computed once per position.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import shapely

from planner.pipeline.evaluation.evaluate import Context
from planner.pipeline.geometry.facades import SIGHT_OFFSET_M, FacadeSet, sample_flags
from planner.pipeline.network import clouds
from planner.registration_error import (
    target_centre_rms_mm,
)
from planner.spacing import point_spacing_mm
from planner.targets import chosen_sizes, size_rules

__all__ = [
    "SIGHT_CHUNK",
    "Sight",
    "SightCache",
    "TargetCandidates",
    "centre_rms",
    "item_sizes",
    "sights",
    "target_candidates",
    "target_sight_offset",
]


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


def item_sizes(
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
