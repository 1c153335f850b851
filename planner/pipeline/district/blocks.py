"""District mode's blocks: a large site cut into blocks, each planned as its own site.

The planned buildings are partitioned into square blocks (by footprint centroid). Each block
is planned as its own site: its buildings planned, and every building, obstacle, no-go area
and control point within a **halo** of the block's reach around it kept — so that stations
near a block edge, and occluders across it, are seen exactly as in the whole site (the
candidate grid is anchored to the CRS, so a block's candidates are the whole site's). The
blocks run as tasks on ``dask.distributed``: a ``LocalCluster`` by default, or an existing
cluster's scheduler. Their plans are stitched: ids prefixed with the block's key, each
block's registration network said per block, one route through all stations. Each block
also judges its stations on the buildings of its halo (:func:`meeting_table`), and a
covering station whose every met sample another station still meets — one of a
neighbouring block, across the block edge — is removed
(:func:`~planner.pipeline.district.stitch.redundant_stations`).

Scheduling the blocks: :mod:`~planner.pipeline.district.schedule`; the bound on the fewest
stations: :mod:`~planner.pipeline.district.bounds`; the stitch:
:mod:`~planner.pipeline.district.stitch`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
import pandas as pd
import scipy.sparse as sp
import shapely
from shapely.geometry import box

from planner.pipeline.engine.judge import forget_workbench, workbench_of
from planner.pipeline.engine.result import Plan
from planner.pipeline.geometry.facades import estimate_samples
from planner.pipeline.inputs.requirements import (
    DEFAULT_BLOCK_M,
    DISTRICT_SAMPLES,
    MAX_BLOCK_BUILDINGS,
    PlanSettings,
    Requirements,
)
from planner.pipeline.inputs.schema import MEETING_COLUMNS, METRIC_KEYS
from planner.ranges import RANGES
from planner.registration_error import datum_tilt_cov
from planner.scanner import Scanner
from planner.site import Site

__all__ = [
    "Block",
    "BlockCover",
    "KeptNetwork",
    "block_cover",
    "block_region",
    "block_site",
    "keep_frame",
    "meeting_reach",
    "meeting_table",
    "needs_district",
    "partition",
]


@dataclass(frozen=True)
class Block:
    """One block of a district: its key (``K03``) and the planned buildings in it."""

    key: str
    buildings: tuple[str, ...]
    footprint: shapely.Geometry  # the union of its planned footprints


def partition(
    site: Site, block_m: float = DEFAULT_BLOCK_M, max_buildings: int = MAX_BLOCK_BUILDINGS
) -> list[Block]:
    """The planned buildings in square blocks of ``block_m`` (by footprint centroid), in
    row order from the south-west; a block with more than ``max_buildings`` is split into
    quadrants, again while needed (down to 20 m), so that every block fits a worker."""
    RANGES["block_m"].check(block_m, "the block size")
    cells: dict[tuple[float, float, float], list] = {}  # (south, west, side) → buildings

    def place(buildings: list, south: float, west: float, side: float) -> None:
        if len(buildings) <= max_buildings or side / 2 < 20.0:
            cells[(south, west, side)] = buildings
            return
        half = side / 2
        parts: dict[tuple[int, int], list] = {}
        for b in buildings:
            c = b.footprint.centroid
            parts.setdefault((int(c.y >= south + half), int(c.x >= west + half)), []).append(b)
        for (i, j), bs in parts.items():
            place(bs, south + i * half, west + j * half, half)

    grid: dict[tuple[int, int], list] = {}
    for b in site.planned:
        c = b.footprint.centroid
        grid.setdefault((math.floor(c.y / block_m), math.floor(c.x / block_m)), []).append(b)
    for (row, col), bs in grid.items():
        place(bs, row * block_m, col * block_m, block_m)
    out = []
    for n, key in enumerate(sorted(cells), start=1):
        bs = cells[key]
        out.append(
            Block(
                f"K{n:0{max(2, len(str(len(cells))))}d}",
                tuple(b.id for b in bs),
                shapely.union_all([b.footprint for b in bs]),
            )
        )
    return out


def needs_district(site: Site, settings: PlanSettings) -> bool:
    """Whether the site is too much work for one process (more samples than
    :data:`~planner.pipeline.inputs.requirements.DISTRICT_SAMPLES`)."""
    n = estimate_samples(site, settings.sample_spacing_m, settings.sample_height_step_m)
    return n > DISTRICT_SAMPLES


def block_region(block: Block, halo_m: float) -> shapely.Geometry:
    """The block's box grown by ``halo_m``: what its site holds (convex)."""
    return box(*block.footprint.bounds).buffer(halo_m)


def block_site(site: Site, block: Block, halo_m: float) -> Site:
    """The site of one block: its buildings planned; everything within ``halo_m`` of them
    kept (other buildings only block the beam), a passage with the buildings it passes
    through (the end of one reaching into the halo from a building left out is ground)."""
    region = block_region(block, halo_m)
    mine = set(block.buildings)
    buildings = [
        replace(b, planned=b.id in mine)
        for b in site.buildings
        if b.id in mine or b.footprint.intersects(region)
    ]
    return Site(
        buildings,
        obstacles=[o for o in site.obstacles if o.geometry.intersects(region)],
        no_go=[a for a in site.no_go if a.geometry.intersects(region)],
        passages=site.passages_through(buildings),
        boundary=site.boundary,
        crs=site.crs,
        name=f"{site.name} {block.key}",
        limits=site.limits,
        near_m=site.near_m,
        terrain=site.terrain,
        height_datum=site.height_datum,
        control=[c for c in site.control if region.contains(shapely.Point(c.x, c.y))],
        zones=[
            z
            for z in site.zones
            if (z.building_id in mine)
            or (z.facade_id is not None and z.facade_id.rsplit("-f", 1)[0] in mine)
        ],
    )


def plan_block(
    site: Site,
    scanner: Scanner,
    req: Requirements,
    settings: PlanSettings,
    region: shapely.Geometry | None = None,
) -> tuple[Plan, pd.DataFrame, BlockCover, KeptNetwork]:
    """One block's plan (a Dask task), its :func:`meeting_table` (within ``region``, the
    block's box grown by its halo), its :func:`block_cover` and its network's frame
    (:func:`keep_frame`); its network and workbench stay on the worker. Its timings say the worker
    process's peak memory so far [MB] (``worker_peak_mb``). The block is planned by work,
    not by the clock (:func:`planner.pipeline.engine.planning.plan`): the same on any worker,
    however loaded."""
    import resource

    from planner.pipeline.engine.planning import plan

    if settings.height_control == "level":  # the district's frame spans all the blocks
        settings = replace(settings, height_control="always")
    p = plan(site, scanner, req, settings)
    table = meeting_table(p, region)
    p.solver.meeting_reach_m = meeting_reach(p)
    cover = block_cover(p)
    frame = keep_frame(p)
    p.network = None
    forget_workbench(p)  # the worker keeps the plan until the stitch, not its machinery
    p.timings_s["worker_peak_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return p, table, cover, frame


@dataclass(frozen=True)
class KeptNetwork:
    """A block's registration network as the stitch needs it, kept when the network itself
    is dropped (:func:`keep_frame`): scanner centres (K, 3) [m], pose covariances about the
    datum without its lean, which are tied, the datum whose tilt leans them (None: none
    does) and which carry that lean, the network's message, and every sample's limits on
    m_x, m_y, m_z (N, 3) [mm] in the order of the block's coverage."""

    xyz: np.ndarray
    pose_cov: np.ndarray
    tied: np.ndarray
    datum: np.ndarray | None
    leans: np.ndarray
    message: str
    limits: np.ndarray
    #: the block's own vertical is held absolutely (a level run, or every scan's tilt
    #: reading): the seams carry no tilt into it (:func:`~planner.pipeline.network.seams.
    #: tie_blocks`)
    held: bool = False


def keep_frame(p: Plan) -> KeptNetwork:
    """What the stitch ties a block's network to its neighbours' with
    (:mod:`planner.pipeline.network.seams`), taken from the block's plan before its network and
    workbench are dropped: every station's scanner centre, pose covariance about the block's
    datum (without the lean of the datum's tilt: in the district's frame only one datum's
    tilt counts), whether it is tied, where the datum whose tilt leans the block stands
    (None: a levelled scanner, control, or no network) and which stations carry that lean;
    and every sample's m limits, for judging it again in the district's frame."""
    net = p.network
    k = len(net.stations) if net is not None else 0
    xyz = net.station_xyz.copy() if k else np.empty((0, 3))
    pose = net.error.pose_cov.copy() if k and net.error is not None else np.zeros((k, 6, 6))
    tied = net.tied.copy() if k else np.zeros(0, dtype=bool)
    datum = net.leaning_datum() if k else None
    leans = net.leans() if k else np.zeros(0, dtype=bool)
    if datum is not None:
        datum = datum.copy()
        pose[leans] -= datum_tilt_cov(xyz[leans], datum, p.scanner.datum_tilt_rms_arcsec)
    limits = workbench_of(p).ctx.limits
    lim = np.column_stack([limits[f"m_{c}"] for c in "xyz"]).astype(float)
    held = bool(k) and (bool(net.levelled) or net.tilt_model == "readings")
    return KeptNetwork(xyz, pose, tied, datum, leans, net.message if net else "", lim, held)


def for_stitch(planned: tuple[Plan, pd.DataFrame, BlockCover, KeptNetwork]) -> tuple:
    """What the stitch needs of a planned block: its plan, its meeting table, where its
    cover's candidates stand (the cover itself stays on the worker) and its frame."""
    p, table, cover, frame = planned
    return p, table, cover.xy, frame


@dataclass(frozen=True)
class BlockCover:
    """A block's cover by the scanner's error (its first evaluation): its samples needing a
    station as rows (``demand`` stations each), the candidates meeting any of them as
    columns, standing at ``xy`` [m] on the grid the whole site shares."""

    xy: np.ndarray
    a: sp.csr_matrix
    demand: np.ndarray


def block_cover(p: Plan) -> BlockCover:
    """The cover problem of the plan's first choice of stations (empty when it was not
    kept)."""
    from planner.pipeline.engine.planning import cover_demand

    wb = workbench_of(p)
    if wb is None or wb.evaluation is None:
        return BlockCover(np.empty((0, 2)), sp.csr_matrix((0, 0), dtype=bool), np.empty(0))
    ok = wb.evaluation.ok.tocsr()
    demand = cover_demand(wb.ctx, np.asarray(ok.sum(axis=1)).ravel())
    rows = ok[demand > 0].tocsc()
    cols = np.flatnonzero(np.diff(rows.indptr) > 0)
    return BlockCover(wb.pool[cols].copy(), rows[:, cols].tocsr(), demand[demand > 0])


def cover_of(planned: tuple[Plan, pd.DataFrame, BlockCover, KeptNetwork]) -> BlockCover:
    return planned[2]


def meeting_reach(p: Plan, rows_per_chunk: int = 2000) -> float:
    """The farthest a candidate meets one of the plan's samples in its first evaluation (by
    the scanner's error), horizontally [m]; the plan's reach when it was not kept."""
    wb = workbench_of(p)
    if wb is None or wb.evaluation is None:
        return float(p.solver.reach_m)
    ok, xy, pool = wb.evaluation.ok.tocsr(), wb.facades.xy, wb.pool
    farthest = 0.0
    for start in range(0, ok.shape[0], rows_per_chunk):
        part = ok[start : start + rows_per_chunk].tocoo()
        if part.nnz:
            d = xy[start + part.row] - pool[part.col]
            farthest = max(farthest, float(np.sqrt((d**2).sum(axis=1)).max()))
    return farthest


def meeting_table(p: Plan, region: shapely.Geometry | None = None) -> pd.DataFrame:
    """Which of a block plan's stations meet which samples — of its own buildings and of the
    others within reach (its halo's, planned by other blocks) — on the scanner's error plus
    the block's registration, with the pair's metrics: what the stitch needs to find the
    stations a neighbouring block makes redundant. A halo building is judged on the site's
    requirement (``needed`` NaN: its zones, if any, belong to its own block), and only at
    samples inside ``region`` (:func:`block_region`): a sight line between two points in it
    can only be blocked by buildings the block's site holds."""
    from planner.pipeline.evaluation.evaluate import Context, meeting_pairs
    from planner.pipeline.geometry.facades import build_facades
    from planner.pipeline.geometry.zoning import apply_zones

    wb, st = workbench_of(p), p.settings
    scans = p.scan_stations  # the network's stations (a traverse's set-ups scan nothing)
    xy = scans[["x", "y"]].to_numpy(dtype=float)
    reg = p.network.registration() if p.network is not None else None
    columns = MEETING_COLUMNS + list(METRIC_KEYS)
    if not len(xy):
        return pd.DataFrame(columns=columns)
    stations = shapely.MultiPoint(xy)
    halo = [
        replace(b, planned=not b.planned)
        for b in wb.site.buildings
        if b.planned or b.footprint.distance(stations) <= wb.reach
    ]
    contexts = [(wb.ctx, True)]
    if any(b.planned for b in halo):
        around = replace(wb.site, buildings=halo, passages=wb.site.passages_through(halo), zones=[])
        fac = build_facades(around, st.sample_spacing_m, st.sample_height_step_m)
        # their walls' materials (glass not demanded), as the block's own are
        fac, smp_req, _ = apply_zones(
            around, fac, p.requirements, None, st.material_table, st.default_material
        )
        contexts.append(
            (Context.build(around, fac, p.scanner, p.requirements, st, wb.reach, smp_req), False)
        )
    parts = []
    for c, own in contexts:
        smp, k, metrics = meeting_pairs(c, xy, reg)
        f = c.facades
        if not own and region is not None:
            inside = shapely.contains_xy(region, f.xy[smp, 0], f.xy[smp, 1])
            smp, k, metrics = smp[inside], k[inside], {n: v[inside] for n, v in metrics.items()}
        parts.append(
            pd.DataFrame(
                {
                    "facade_id": f.facade_id[f.facade[smp]],
                    "sample_id": f.sample_id[smp],
                    "x": f.xy[smp, 0],
                    "y": f.xy[smp, 1],
                    "z": f.z[smp],
                    "station_id": scans["station_id"].to_numpy()[k],
                    "own": own,
                    "needed": c.stations_needed[smp] if own else np.nan,
                    **metrics,
                }
            )
        )
    return pd.concat(parts, ignore_index=True)[columns]
