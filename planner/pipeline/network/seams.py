"""One registration network for a district: the blocks' networks tied across their seams.

Each block of a district is planned with its own registration network and datum
(:mod:`planner.pipeline.district.blocks`). Two neighbouring blocks are tied where a station of
one and a station of the other see three or more of the targets placed by either (a
**seam link**, with its covariance as any link: :func:`planner.registration_error.propagate`);
the seams form a tree from the block with the most stations (each block joined where its
accumulated error is smallest), and every station of a block then carries its block's
**frame error** — the error of the chain of seams and of each seam's station on the side
nearer the datum block (its block's own error there), added, carried to where the station
stands. The block's own registration errors are kept as they are, taken about the seam's
station on its side as about its own datum (a block's errors are of the same size about any
of its well-tied stations). Every sample's registration error, and whether it still
meets its requirement, follow; a block no seam reaches is not in the common frame and its
samples are not met (said, with the block).
"""

from __future__ import annotations

import heapq
from dataclasses import dataclass, replace

import numpy as np
import pandas as pd
import shapely

from planner.pipeline.evaluation.evaluate import Context
from planner.pipeline.geometry.facades import build_facades
from planner.pipeline.geometry.zoning import apply_zones
from planner.pipeline.network.targets import TargetCandidates, centre_rms, sights
from planner.registration_error import (
    Link,
    point_registration_variances,
    propagate,
    transport_pose_cov,
)
from planner.site import Site

__all__ = ["BlockFrame", "SeamLink", "root_block", "seam_links", "tie_blocks"]

#: Stations of two blocks this close may share targets [m].
SEAM_RADIUS_M = 60.0
#: Targets this close to a seam's stations are tried [m].
SEAM_TARGETS_M = 60.0


@dataclass(frozen=True)
class BlockFrame:
    """What the stitch keeps of a block's network: its stations' ids, scanner centres
    (K, 3) [m], pose covariances (K, 6, 6) and whether each is tied to the block's datum."""

    ids: list[str]
    xyz: np.ndarray
    pose_cov: np.ndarray
    tied: np.ndarray


@dataclass(frozen=True)
class SeamLink:
    """Station ``b`` (block ``block_b``) registered to station ``a`` (block ``block_a``)
    over the common targets ``target_ids``; ``cov`` is b's pose covariance relative to a
    (6 × 6, at b)."""

    block_a: int
    block_b: int
    a: int  # position in block_a's frame
    b: int
    target_ids: tuple[str, ...]
    cov: np.ndarray

    @property
    def rms_mm(self) -> float:
        return float(np.sqrt(np.trace(self.cov[:3, :3]) / 3.0))


def _targets(t: pd.DataFrame) -> TargetCandidates:
    """Placed targets as candidates (flat targets facing as placed)."""
    face = np.radians(t["facing_deg"].fillna(0.0).to_numpy(dtype=float))
    flat = (t["type"] == "flat").to_numpy()
    normal = np.where(flat[:, None], np.column_stack([np.sin(face), np.cos(face)]), 0.0)
    return TargetCandidates(
        xyz=t[["x", "y", "z"]].to_numpy(dtype=float),
        type=t["type"].to_numpy(dtype=object),
        normal=normal,
        facade=np.full(len(t), -1, dtype=np.int64),
        control_id=np.full(len(t), "", dtype=object),
        control_rms_mm=np.full(len(t), np.nan),
    )


def seam_links(
    site: Site,
    ctx_of,
    frames: list[BlockFrame],
    targets: list[pd.DataFrame],
) -> list[SeamLink]:
    """For every pair of blocks with stations within :data:`SEAM_RADIUS_M`, the best seam
    link (the smallest error) between a tied station of each, over targets either placed
    (with their placed sizes); none where no pair shares three. ``ctx_of(region)`` gives a
    :class:`Context` of the site within a region (for lines of sight)."""
    out = []
    for i in range(len(frames)):
        for j in range(i + 1, len(frames)):
            fi, fj = frames[i], frames[j]
            if not len(fi.ids) or not len(fj.ids):
                continue
            d = np.hypot(*(fi.xyz[:, None, :2] - fj.xyz[None, :, :2]).transpose(2, 0, 1))
            d = np.where(fi.tied[:, None] & fj.tied[None, :], d, np.inf)
            near_i = np.flatnonzero((d <= SEAM_RADIUS_M).any(axis=1))
            near_j = np.flatnonzero((d <= SEAM_RADIUS_M).any(axis=0))
            if not len(near_i) or not len(near_j):
                continue
            st_xyz = np.vstack([fi.xyz[near_i], fj.xyz[near_j]])
            both = pd.concat([targets[i], targets[j]], ignore_index=True)
            both = both[both["type"].isin(["flat", "sphere"])]
            close = np.hypot(
                *(both[["x", "y"]].to_numpy(float)[:, None] - st_xyz[None, :, :2]).transpose(
                    2, 0, 1
                )
            ).min(axis=1)
            both = both[close <= SEAM_TARGETS_M].reset_index(drop=True)
            if len(both) < 3:
                continue
            region = shapely.MultiPoint(
                np.vstack([st_xyz[:, :2], both[["x", "y"]].to_numpy(float)])
            ).buffer(5.0)
            link = _best_seam(ctx_of(region.convex_hull), both, fi, fj, near_i, near_j, i, j)
            if link is not None:
                out.append(link)
    return out


def _best_seam(ctx: Context, t: pd.DataFrame, fi, fj, near_i, near_j, i, j) -> SeamLink | None:
    tc = _targets(t)
    xy = np.vstack([fi.xyz[near_i, :2], fj.xyz[near_j, :2]])
    sight = sights(ctx, tc, xy)
    size = t["size_mm"].to_numpy(dtype=float)
    usable = sight.usable & (sight.need_mm <= np.nan_to_num(size, nan=np.inf)[:, None])
    rms = np.full(usable.shape, np.inf)
    for tt, k in zip(*np.nonzero(usable), strict=True):
        rms[tt, k] = centre_rms(ctx, tc, sight, int(tt), int(k), float(size[tt]))
    best = None
    n_i = len(near_i)
    for a in range(n_i):
        for b in range(len(near_j)):
            common = np.flatnonzero(usable[:, a] & usable[:, n_i + b])
            if len(common) < 3:
                continue
            xyz = np.vstack([fi.xyz[near_i[a]], fj.xyz[near_j[b]]])
            if not _spread(tc.xyz[common]):
                continue
            obs = {(0, int(c)): rms[c, a] for c in common}
            obs |= {(1, int(c)): rms[c, n_i + b] for c in common}
            err = propagate(
                xyz,
                tc.xyz,
                obs,
                [Link(0, 1, tuple(int(c) for c in common))],
                datum=0,
                levelled=ctx.scanner.is_levelled,
                # the seam's own error: its two stations' tilts, levelled; without a
                # compensator no datum's (the district's lean is added once, district/stitch.py)
                tilt_rms_arcsec=ctx.scanner.initial_tilt_rms_arcsec
                if ctx.scanner.is_levelled
                else 0.0,
            )
            if not err.tied.all():
                continue
            cov = err.pose_cov[1]
            key = float(np.trace(cov[:3, :3]))
            if best is None or key < best[0]:
                ids = tuple(str(t["target_id"].iloc[c]) for c in common)
                best = (key, SeamLink(i, j, int(near_i[a]), int(near_j[b]), ids, cov))
    return None if best is None else best[1]


def _spread(xyz: np.ndarray) -> bool:
    """Targets that fix a registration: three or more, not all on one line (1 m)."""
    if len(xyz) < 3:
        return False
    centred = xyz - xyz.mean(axis=0)
    return bool(np.linalg.svd(centred, compute_uv=False)[1] > 1.0)


def root_block(frames: list[BlockFrame]) -> int:
    """The block whose frame is the district's: the one with the most stations."""
    return int(np.argmax([len(f.ids) for f in frames]))


def tie_blocks(
    frames: list[BlockFrame], links: list[SeamLink], held: list[bool] | None = None
) -> tuple[list[np.ndarray | None], list[SeamLink]]:
    """The frame error of every block (a pose covariance (K, 6, 6) per station, added to
    its own) along the tree of seams from the block with the most stations (Dijkstra on
    the seams' variances); None for a block no seam reaches. And the seams used. A block
    whose vertical is ``held`` on its own (a level run, every scan's tilt reading) takes
    no tilt from the seams: its frame error keeps the shifts and the heading only."""
    held = held or [False] * len(frames)
    n = len(frames)
    if not n:
        return [], []
    root = root_block(frames)
    back = [  # each seam the other way: a registered to b, its covariance carried to a
        replace(
            s,
            block_a=s.block_b,
            block_b=s.block_a,
            a=s.b,
            b=s.a,
            cov=transport_pose_cov(s.cov, frames[s.block_b].xyz[s.b], frames[s.block_a].xyz[s.a]),
        )
        for s in links
    ]
    both = [*links, *back]
    cost = {root: 0.0}
    start = frames[root].xyz[0] if len(frames[root].ids) else np.zeros(3)
    frame: dict[int, tuple[np.ndarray, np.ndarray]] = {root: (np.zeros((6, 6)), start)}
    used: list[SeamLink] = []
    heap: list[tuple[float, int, int]] = []

    def push(k: int) -> None:
        for m, s in enumerate(both):
            if s.block_a == k and s.block_b not in cost:
                heapq.heappush(heap, (cost[k] + s.rms_mm**2, m, s.block_b))

    push(root)
    while heap:
        c, m, k = heapq.heappop(heap)
        if k in cost:
            continue
        s = both[m]
        fa, fb = frames[s.block_a], frames[k]
        cov_a, at_a = frame[s.block_a]
        xa, xb = fa.xyz[s.a], fb.xyz[s.b]
        at_station_a = transport_pose_cov(cov_a, at_a, xa) + fa.pose_cov[s.a]
        cov_b = transport_pose_cov(at_station_a, xa, xb) + s.cov
        if held[k]:  # its own vertical: the seams' tilts do not reach it
            cov_b = _without_tilt(cov_b)
        frame[k] = (cov_b, xb)
        cost[k] = c
        used.append(s)
        push(k)
    out: list[np.ndarray | None] = []
    for k, f in enumerate(frames):
        if k not in frame:
            out.append(None)
            continue
        cov, at = frame[k]
        out.append(transport_pose_cov(np.broadcast_to(cov, (len(f.ids), 6, 6)), at, f.xyz))
    return out, used


def _without_tilt(cov: np.ndarray) -> np.ndarray:
    """A pose covariance with the rotations about x and y (the tilt) taken out."""
    out = cov.copy()
    out[..., 3:5, :] = 0.0
    out[..., :, 3:5] = 0.0
    return out


def add_frame_errors(
    coverage: pd.DataFrame,
    facades: pd.DataFrame,
    extra: dict[str, np.ndarray],
    xyz: dict[str, np.ndarray],
    limits: np.ndarray,
) -> tuple[pd.DataFrame, np.ndarray]:
    """``coverage`` with every sample's registration error grown by its station's frame
    error (``extra``: station id → 6 × 6 pose covariance; ``xyz`` its scanner centre):
    the totals again, and a sample that met its m_x, m_y, m_z limits (``limits`` (N, 3))
    no longer meeting them unmet, with the reason. Also which samples were lost so, by
    the limit each exceeds now ((N, 3): m_x, m_y, m_z)."""
    cov = coverage.copy()
    over = np.zeros((len(cov), 3), dtype=bool)
    has = cov["station_id"].isin(list(extra)).to_numpy() & cov["station_id"].ne("").to_numpy()
    if not has.any():
        return cov, over
    rows = np.flatnonzero(has)
    sid = cov["station_id"].to_numpy()[rows]
    pose = np.stack([extra[s] for s in sid])
    st_xyz = np.stack([xyz[s] for s in sid])
    fac = facades.set_index("facade_id")
    f = cov["facade_id"].to_numpy()[rows]
    a = fac.loc[f, ["x0", "y0"]].to_numpy(float)
    e = fac.loc[f, ["x1", "y1"]].to_numpy(float)
    along = (e - a) / np.linalg.norm(e - a, axis=1)[:, None]
    normal = np.column_stack([along[:, 1], -along[:, 0]])
    pts = cov[["x", "y", "z"]].to_numpy(float)[rows]
    more = point_registration_variances(pose, st_xyz, pts, along, normal)
    was = cov["meets"].to_numpy().copy()
    for k, (c, v) in enumerate(zip("xyz", more, strict=True)):
        # (v takes a block's own datum lean out again where the district's replaces it:
        # never more than the sample had, so below zero only by rounding)
        reg = np.sqrt(np.maximum(cov[f"reg_m_{c}_mm"].to_numpy()[rows] ** 2 + v, 0.0))
        total = np.hypot(cov[f"scanner_m_{c}_mm"].to_numpy()[rows], reg)
        cov.loc[cov.index[rows], f"reg_m_{c}_mm"] = reg
        cov.loc[cov.index[rows], f"m_{c}_mm"] = total
        over[rows, k] = total > limits[rows, k] * (1 + 1e-9)
    over &= was.astype(bool)[:, None]
    lost = over.any(axis=1)
    cov.loc[lost, "meets"] = False
    cov.loc[lost, "reason"] = (
        "the registration error takes it over once its block is tied to the district's "
        "network (the seams' error added)"
    )
    return cov, over


def untied_blocks(coverage: pd.DataFrame, stations: set[str], block: str) -> pd.DataFrame:
    """``coverage`` with the samples scanned from ``stations`` (a block no seam reaches)
    unmet: they are not in the district's frame."""
    cov = coverage
    mine = cov["station_id"].isin(stations) & cov["meets"]
    cov.loc[mine, "meets"] = False
    cov.loc[mine, "reason"] = (
        f"its block {block} cannot be tied to the district's network: no station of it "
        "shares three targets with a neighbouring block's"
    )
    return cov


def context_of(site: Site, scanner, req, settings, reach: float):
    """A function giving a :class:`Context` of ``site`` within a region (lines of sight for
    a seam: its buildings planned only for the context's sake)."""

    def make(region: shapely.Geometry) -> Context:
        bs = [replace(b, planned=True) for b in site.buildings if b.footprint.intersects(region)]
        if not bs:
            bs = [
                replace(
                    min(site.buildings, key=lambda b: b.footprint.distance(region)), planned=True
                )
            ]
        sub = Site(
            bs,
            obstacles=[o for o in site.obstacles if o.geometry.intersects(region)],
            passages=site.passages_through(bs),
            crs=site.crs,
            limits=site.limits,
            near_m=site.near_m,
            terrain=site.terrain,
            height_datum=site.height_datum,
        )
        fac = build_facades(sub, 10.0, 10.0)
        fac, smp_req, _ = apply_zones(
            replace(sub, zones=[]), fac, req, None, settings.material_table,
            settings.default_material,
        )  # fmt: skip
        return Context.build(sub, fac, scanner, req, settings, reach, smp_req)

    return make
