"""Registration: targets that tie the scans together, and a connected station network.

Two stations are linked when at least three targets that both see can be placed, not
collinear, each big enough by Sossa's 2d / 4d rule at the farther of the two distances
(a flat target seen at incidence θ needs 2d / cos θ). Candidate targets are flat targets on
the planned facades and spheres on stands on free ground, both at ``target_height_m``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.csgraph import connected_components, minimum_spanning_tree

from planner.pipeline.evaluate import Context
from planner.pipeline.facades import PARTY_WALL_GAP_M, SIGHT_OFFSET_M, party_wall_mask
from planner.pipeline.visibility import clear_height, edges_in_box
from planner.spacing import point_spacing_mm
from planner.targets import SPACING_FACTOR, choose_target, target_size_kernel

__all__ = ["Network", "TargetCandidates", "connect", "target_candidates", "usability"]

#: Three targets whose second principal spread is below this are taken as collinear [m].
MIN_SPREAD_M = 0.5


@dataclass(kw_only=True)
class TargetCandidates:
    """Where targets could go: (T, 3) positions, type, and wall normal (zero for stands)."""

    xyz: np.ndarray
    type: np.ndarray  # "flat" or "sphere"
    normal: np.ndarray  # (T, 2)
    facade: np.ndarray  # (T,) facade index of a flat target, -1 for a stand


def target_candidates(ctx: Context, stand_xy: np.ndarray) -> TargetCandidates:
    """Flat targets along the planned facades and spheres on the given stand positions,
    for the target types the inventory holds."""
    fac, st = ctx.facades, ctx.settings
    types = {i.type for i in st.inventory}
    xyz, kind, nrm, owner, wall = [], [], [], [], []
    if "flat" in types:
        for f in range(fac.n_facades):
            z = min(st.target_height_m, fac.height_m[f] - 0.2)
            length = fac.length_m[f]
            n = max(1, round(length / st.target_spacing_m))
            for k in range(n):
                xy = fac.start[f] + (k + 0.5) / n * (fac.end[f] - fac.start[f])
                xyz.append([*xy, z])
                kind.append("flat")
                nrm.append(fac.normal[f])
                owner.append(fac.building_id[f])
                wall.append(f)
        if xyz:
            walls = np.array(xyz)
            probe = walls[:, :2] + PARTY_WALL_GAP_M * np.array(nrm)
            keep = ~party_wall_mask(ctx.site, np.array(owner, dtype=object), probe, walls[:, 2])
            xyz = [p for p, k in zip(xyz, keep, strict=True) if k]
            nrm = [p for p, k in zip(nrm, keep, strict=True) if k]
            kind = [p for p, k in zip(kind, keep, strict=True) if k]
            wall = [p for p, k in zip(wall, keep, strict=True) if k]
    if "sphere" in types:
        for xy in stand_xy:
            xyz.append([xy[0], xy[1], st.target_height_m])
            kind.append("sphere")
            nrm.append([0.0, 0.0])
            wall.append(-1)
    return TargetCandidates(
        xyz=np.array(xyz).reshape(-1, 3),
        type=np.array(kind, dtype=object),
        normal=np.array(nrm, dtype=float).reshape(-1, 2),
        facade=np.array(wall, dtype=np.int64),
    )


def usability(
    ctx: Context, tc: TargetCandidates, station_xy: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Which targets each station can use, and the size each would need there.

    Returns ``usable`` (T, K) bool and ``need_mm`` (T, K) minimum size [mm] (inf if unseen).
    A target is usable from a station when it is seen (line of sight, in front of its wall,
    within the scanner's range) and the inventory's largest item of its type is big enough.
    """
    sc, st = ctx.scanner, ctx.settings
    t, k = len(tc.xyz), len(station_xy)
    need = np.full((t, k), np.inf)
    if t == 0 or k == 0:
        return np.zeros((t, k), dtype=bool), need
    largest = {
        ty: max((i.size_mm for i in st.inventory if i.type == ty), default=0.0)
        for ty in ("flat", "sphere")
    }
    hi = st.instrument_height_m
    cos_max = np.cos(np.radians(st.max_target_incidence_deg))
    is_flat = tc.type == "flat"
    for j, sxy in enumerate(station_xy):
        rel = sxy - tc.xyz[:, :2]
        d = np.hypot(rel[:, 0], rel[:, 1])
        s = np.hypot(d, tc.xyz[:, 2] - hi)
        cdot = (rel * tc.normal).sum(axis=1)
        cand = (s >= sc.min_range_m) & (s <= sc.max_range_m)
        cand &= ~is_flat | (cdot > cos_max * s)  # in front, incidence within the limit
        idx = np.flatnonzero(cand)
        if not len(idx):
            continue
        reach = float(s[idx].max())
        e = ctx.edges
        near = edges_in_box(e, (sxy[0] - reach, sxy[1] - reach, sxy[0] + reach, sxy[1] + reach))
        end = tc.xyz[idx, :2] + SIGHT_OFFSET_M * tc.normal[idx]
        zc = clear_height(
            np.broadcast_to(sxy, (len(idx), 2)), hi, end, e[near], ctx.edge_heights[near]
        )
        seen = tc.xyz[idx, 2] >= zc - 1e-9
        idx = idx[seen]
        spacing = point_spacing_mm(s[idx], step_mm_at_10m=ctx.step_mm_at_10m)
        factor = np.array([SPACING_FACTOR[ty] for ty in tc.type[idx]], dtype=float)
        cos_incidence = np.where(is_flat[idx], cdot[idx] / s[idx], 1.0)
        need[idx, j] = target_size_kernel(factor, spacing, cos_incidence)
    big = np.array([largest[ty] for ty in tc.type])[:, None]
    return need <= big, need


def _triple(points: np.ndarray, prefer: np.ndarray) -> np.ndarray | None:
    """Three well-spread points (indices), preferring ``prefer`` ones; None if all collinear."""
    if len(points) < 3:
        return None
    centred = points - points.mean(axis=0)
    if np.linalg.svd(centred, compute_uv=False)[1] < MIN_SPREAD_M * np.sqrt(len(points)) / 2:
        return None
    pool = np.argsort(~prefer, kind="stable")  # preferred first
    first = pool[0]
    dist = np.linalg.norm(points - points[first], axis=1) - 1e3 * (~prefer)
    second = int(np.argmax(np.where(np.arange(len(points)) == first, -np.inf, dist)))
    line = points[second] - points[first]
    rel = points - points[first]
    area = np.linalg.norm(np.cross(rel, line), axis=1) - 1e3 * (~prefer)  # 3-D points
    area[[first, second]] = -np.inf
    third = int(np.argmax(area))
    tri = np.array([first, second, third])
    a, b, c = points[tri]
    if np.linalg.norm(np.cross(b - a, c - a)) / 2 < MIN_SPREAD_M**2:
        return None
    return tri


def link_matrix(usable: np.ndarray, xyz: np.ndarray) -> np.ndarray:
    """(K, K) number of common usable targets, zeroed where they are collinear or < 3."""
    u = sp.csr_matrix(usable.astype(np.int32))
    common = (u.T @ u).toarray()
    np.fill_diagonal(common, 0)
    out = np.where(common >= 3, common, 0)
    for i, j in zip(*np.nonzero(np.triu(out)), strict=True):
        both = usable[:, i] & usable[:, j]
        if _triple(xyz[both], np.zeros(both.sum(), dtype=bool)) is None:
            out[i, j] = out[j, i] = 0
    return out


@dataclass(kw_only=True)
class Network:
    """The registration network over the chosen stations."""

    stations: np.ndarray  # candidate indices, cover stations first then linking ones
    n_link_stations: int
    links: list[tuple[int, int, int]]  # (station position a, b, common targets), all links
    tree: list[tuple[int, int]]  # the links the targets are chosen for
    targets: list[int]  # chosen target candidate indices
    target_links: dict[int, list[tuple[int, int]]]
    n_components: int
    message: str
    usable: np.ndarray  # (T, K) target usable from each of ``stations``
    need_mm: np.ndarray  # (T, K) minimum target size there [mm]


#: Linking stations are searched on a grid this coarse (a subset of the candidates) [m].
LINK_GRID_M = 4.0


def _coarse(cand_xy: np.ndarray, grid_m: float) -> np.ndarray:
    """Indices of the candidates on a ``grid_m`` lattice (candidates lie on a finer one)."""
    cells = np.floor(cand_xy / grid_m + 1e-9).astype(np.int64)
    _, first = np.unique(cells, axis=0, return_index=True)
    return np.sort(first)


def connect(ctx: Context, tc: TargetCandidates, cand_xy: np.ndarray, chosen: np.ndarray) -> Network:
    """Link the chosen stations; add the fewest linking stations found if they are not
    connected; choose three targets per link of a spanning tree, reusing targets."""
    stations = list(int(c) for c in chosen)
    usable, need = usability(ctx, tc, cand_xy[stations])
    links = link_matrix(usable, tc.xyz)
    n_comp, labels = connected_components(sp.csr_matrix(links > 0), directed=False)
    added = 0
    if n_comp > 1 and len(tc.xyz):
        pool = _coarse(cand_xy, max(LINK_GRID_M, ctx.settings.grid_m))
        all_usable, all_need = usability(ctx, tc, cand_xy[pool])
        taken = set(np.flatnonzero(np.isin(pool, stations)).tolist())
        while n_comp > 1:
            best = _best_bridge(all_usable, usable, labels, n_comp, tc.xyz, taken)
            if best is None:
                break
            for c in best:
                stations.append(int(pool[c]))
                taken.add(c)
                usable = np.column_stack([usable, all_usable[:, c]])
                need = np.column_stack([need, all_need[:, c]])
                added += 1
            links = link_matrix(usable, tc.xyz)
            n_comp, labels = connected_components(sp.csr_matrix(links > 0), directed=False)
    # spanning forest, heaviest links (most common targets) first
    weight = np.where(links > 0, 1.0 / np.maximum(links, 1), 0.0)
    tree = minimum_spanning_tree(sp.csr_matrix(np.triu(weight)))
    tree_links = [(int(min(a, b)), int(max(a, b))) for a, b in zip(*tree.nonzero(), strict=True)]
    chosen_targets: list[int] = []
    target_links: dict[int, list[tuple[int, int]]] = {}
    for a, b in tree_links:
        both = np.flatnonzero(usable[:, a] & usable[:, b])
        prefer = np.isin(both, chosen_targets)
        tri = _triple(tc.xyz[both], prefer)
        if tri is None:
            continue
        for t in both[tri]:
            t = int(t)
            if t not in target_links:
                chosen_targets.append(t)
                target_links[t] = []
            target_links[t].append((a, b))
    all_links = [
        (int(a), int(b), int(links[a, b])) for a, b in zip(*np.nonzero(np.triu(links)), strict=True)
    ]
    if len(stations) <= 1:
        msg = "one station: no registration needed"
    elif n_comp == 1:
        msg = f"the {len(stations)} stations form one registration network"
        if added:
            msg += f" after adding {added} linking station{'s' if added > 1 else ''}"
    else:
        msg = (
            f"the stations fall into {n_comp} groups that no common targets can tie together "
            f"(even with {added} linking stations added); tie them by a traverse or by targets "
            "coordinated with a total station"
        )
    return Network(
        stations=np.array(stations),
        n_link_stations=added,
        links=all_links,
        tree=tree_links,
        targets=chosen_targets,
        target_links=target_links,
        n_components=n_comp,
        message=msg,
        usable=usable,
        need_mm=need,
    )


def _best_bridge(
    all_usable: np.ndarray,
    usable: np.ndarray,
    labels: np.ndarray,
    n_comp: int,
    xyz: np.ndarray,
    taken: set[int],
) -> list[int] | None:
    """One candidate linking the most components, else two linked candidates bridging two."""
    u_all = sp.csc_matrix(all_usable.astype(np.int32))
    u_st = sp.csc_matrix(usable.astype(np.int32))
    common = (u_all.T @ u_st).toarray()  # (C, K)
    reach = np.zeros((all_usable.shape[1], n_comp), dtype=bool)
    for comp in range(n_comp):
        members = np.flatnonzero(labels == comp)
        for k in members:
            hits = np.flatnonzero(common[:, k] >= 3)
            for c in hits:
                if not reach[c, comp]:
                    both = all_usable[:, c] & usable[:, k]
                    if _triple(xyz[both], np.zeros(both.sum(), dtype=bool)) is not None:
                        reach[c, comp] = True
    reach[list(taken)] = False
    n_reached = reach.sum(axis=1)
    if n_reached.max(initial=0) >= 2:
        return [int(np.argmax(n_reached))]
    # two candidates: c1 reaches component A, c2 another, and c1 and c2 are linked
    for comp in range(n_comp):
        ca = np.flatnonzero(reach[:, comp])
        cb = np.flatnonzero(reach.any(axis=1) & ~reach[:, comp])
        if not len(ca) or not len(cb):
            continue
        cc = (u_all[:, ca].T @ u_all[:, cb]).toarray()
        order = np.argsort(-cc, axis=None)
        for flat in order[:200]:
            i, j = np.unravel_index(flat, cc.shape)
            if cc[i, j] < 3:
                break
            both = all_usable[:, ca[i]] & all_usable[:, cb[j]]
            if _triple(xyz[both], np.zeros(both.sum(), dtype=bool)) is not None:
                return [int(ca[i]), int(cb[j])]
    return None


def target_table_rows(ctx: Context, tc: TargetCandidates, net: Network) -> list[dict]:
    """Rows of the target list: position, type, the wall it goes on and which way it faces,
    the minimum size for every station listed (Sossa's rule at the farthest) and the
    inventory item chosen, and the stations that use it."""
    usable, need = net.usable, net.need_mm
    fac = ctx.facades
    rows = []
    for t in net.targets:
        users = sorted({s for link in net.target_links[t] for s in link})
        item = choose_target(float(need[t, users].max()), tc.type[t], ctx.settings.inventory)
        size = item.size_mm if item else float("nan")
        seen_by = np.flatnonzero(usable[t] & (need[t] <= size))
        f = int(tc.facade[t])
        nx, ny = tc.normal[t]
        rows.append(
            {
                "t": t,
                "x": tc.xyz[t, 0],
                "y": tc.xyz[t, 1],
                "z": tc.xyz[t, 2],
                "type": tc.type[t],
                "min_size_mm": float(need[t, seen_by].max()),
                "size_mm": size,
                "item": item.name if item else "",
                "stations": seen_by,
                "facade_id": fac.facade_id[f] if f >= 0 else "",
                # which way a wall target faces: azimuth of its normal, clockwise from grid north
                "facing_deg": float(np.degrees(np.arctan2(nx, ny)) % 360.0) if f >= 0 else np.nan,
            }
        )
    return rows
