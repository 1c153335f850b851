"""District mode: a large site planned block by block on Dask, stitched into one plan.

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
neighbouring block, across the block edge — is removed (:func:`redundant_stations`).

**The bound stays honest.** A block's lower bound holds for the stations meeting *its*
samples; the plain sum of all blocks' bounds does not hold for the whole (a station on a
block edge may serve two blocks). Every candidate of the whole site that meets a sample of
a block is among that block's candidates, at the same grid position (the grid is anchored
to the CRS and the halo holds everything within the reach). Two bounds follow, and the
plan reports the larger:

* **Shared stations** (:func:`shared_prices`, :func:`block_cover`): each block's cover by
  the scanner's error, with every candidate priced 1 / (the number of blocks whose samples
  it meets). A cover of the whole site, restricted to the candidates meeting one block's
  samples, covers that block; summed over the blocks, these prices count each of its
  stations once. So the sum of the blocks' LP relaxations at these prices is a lower bound
  on the fewest stations of the whole (Lagrangian decomposition with the shared columns'
  costs split evenly; Guignard & Kim, "Lagrangean decomposition: a model yielding stronger
  Lagrangean bounds", Mathematical Programming 39, 1987,
  https://doi.org/10.1007/BF02592954; tested against the optimum of random instances).
* **Far apart**: each block says the farthest any candidate meets one of its samples (its
  **meeting reach**, :func:`meeting_reach`, at most the reach). Two blocks farther apart
  than the sum of their meeting reaches share no station, so the sum of the bounds of
  blocks pairwise that far apart is a bound (the largest such sum found, greedy).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
import pandas as pd
import scipy.sparse as sp
import shapely
from shapely.geometry import box

from planner.cloud_registration import weakest_direction
from planner.errors import InputError
from planner.pipeline.evaluate import Progress
from planner.pipeline.facades import check_sample_count, estimate_samples
from planner.pipeline.requirements import (
    DEFAULT_BLOCK_M,
    DISTRICT_SAMPLES,
    MAX_BLOCK_BUILDINGS,
    WORKER_MEMORY,
    PlanSettings,
    Requirements,
)
from planner.pipeline.result import Plan, SolverReport
from planner.pipeline.route import field_route
from planner.pipeline.schema import MEETING_COLUMNS, METRIC_KEYS
from planner.pipeline.tables import (
    DATUM_LEVELLING_FIX,
    REASON_DATA,
    budget_message,
    rename_stations,
    rename_targets,
)
from planner.ranges import RANGES
from planner.registration_error import datum_tilt_cov
from planner.scanner import Scanner
from planner.site import Site
from planner.sitecheck import notes_summary

__all__ = [
    "DEFAULT_BLOCK_M",
    "Block",
    "BlockCover",
    "block_cover",
    "block_region",
    "block_site",
    "meeting_table",
    "needs_district",
    "partition",
    "plan_district",
    "redundant_stations",
    "shared_prices",
]


#: Configuration of the local workers. Dask sets ``MALLOC_TRIM_THRESHOLD_`` for its workers
#: so that freed memory goes back to the system; setting it turns off glibc's dynamic mmap
#: threshold (``mallopt(3)``, M_MMAP_THRESHOLD), so every temporary array above 128 kB
#: is mapped and unmapped again, and a block's evaluation ran 2.5 times slower in a worker
#: than in one process (5.5 s against 14 s, benchmarks/RESULTS.md). Arrays up to 64 MB
#: come from the heap again.
#: The workers' statistical profiler (for Dask's dashboard, which the local cluster does
#: not serve) is off too.
WORKER_CONFIG = {
    "distributed.nanny.pre-spawn-environ.MALLOC_MMAP_THRESHOLD_": 64 * 2**20,
    "distributed.worker.profile.enabled": False,
}


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
    :data:`~planner.pipeline.requirements.DISTRICT_SAMPLES`)."""
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


def _plan_block(
    site: Site,
    scanner: Scanner,
    req: Requirements,
    settings: PlanSettings,
    region: shapely.Geometry | None = None,
    share_s: float = math.inf,
    until_epoch: float = math.inf,
) -> tuple[Plan, pd.DataFrame, BlockCover]:
    """One block's plan (a Dask task), its :func:`meeting_table` (within ``region``, the
    block's box grown by its halo) and its :func:`block_cover`; its network and workbench
    stay on the worker. Its timings say the worker process's peak memory so far [MB]
    (``worker_peak_mb``). The plan takes at most ``share_s`` seconds and ends by
    ``until_epoch`` (a :func:`time.time` time: the worker may be another machine)."""
    import resource

    from planner.pipeline.planning import plan

    now = time.monotonic()
    deadline = min(now + share_s, now + (until_epoch - time.time()))
    p = plan(site, scanner, req, settings, deadline=deadline)
    table = meeting_table(p, region)
    p.solver.meeting_reach_m = meeting_reach(p)
    cover = block_cover(p)
    keep_frame(p)
    p.network = p.workbench = None
    p.timings_s["worker_peak_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return p, table, cover


@dataclass(frozen=True)
class KeptNetwork:
    """A block's registration network as the stitch needs it, kept when the network itself
    is dropped (:func:`keep_frame`): scanner centres (K, 3) [m], pose covariances about the
    datum without its lean, which are tied, the datum whose tilt leans them (None: none
    does) and which carry that lean, and the network's message."""

    xyz: np.ndarray
    pose_cov: np.ndarray
    tied: np.ndarray
    datum: np.ndarray | None
    leans: np.ndarray
    message: str


def keep_frame(p: Plan) -> None:
    """What the stitch ties a block's network to its neighbours' with
    (:mod:`planner.pipeline.seams`), kept in the block's plan before its network and
    workbench are dropped: every station's scanner centre, pose covariance about the block's
    datum (without the lean of the datum's tilt: in the district's frame only one datum's
    tilt counts), whether it is tied, where the datum whose tilt leans the block stands
    (None: a levelled scanner, control, or no network) and which stations carry that lean
    (:attr:`Plan.block_frame`); and every sample's m limits (hidden coverage columns)."""
    net = p.network
    k = len(net.stations) if net is not None else 0
    xyz = net.station_xyz.copy() if k else np.empty((0, 3))
    pose = net.error.pose_cov.copy() if k and net.error is not None else np.zeros((k, 6, 6))
    tied = net.tied.copy() if k else np.zeros(0, dtype=bool)
    datum = net.leaning_datum(p.scanner) if k else None
    leans = net.leans(p.scanner) if k else np.zeros(0, dtype=bool)
    if datum is not None:
        datum = datum.copy()
        pose[leans] -= datum_tilt_cov(xyz[leans], datum, p.scanner.initial_tilt_rms_arcsec)
    p.block_frame = KeptNetwork(xyz, pose, tied, datum, leans, net.message if net else "")
    limits = p.workbench.ctx.limits
    for c in "xyz":  # for judging each sample again in the district's frame
        p.coverage[f"_lim_m_{c}"] = limits[f"m_{c}"]


def _shown(planned: tuple[Plan, pd.DataFrame, BlockCover]) -> tuple:
    """What the stitch needs of a planned block: its plan, its meeting table and where its
    cover's candidates stand (the cover itself stays on the worker)."""
    p, table, cover = planned
    return p, table, cover.xy


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
    from planner.pipeline.planning import cover_demand

    wb = p.workbench
    if wb is None or wb.evaluation is None:
        return BlockCover(np.empty((0, 2)), sp.csr_matrix((0, 0), dtype=bool), np.empty(0))
    ok = wb.evaluation.ok.tocsr()
    demand = cover_demand(wb.ctx, np.asarray(ok.sum(axis=1)).ravel())
    rows = ok[demand > 0].tocsc()
    cols = np.flatnonzero(np.diff(rows.indptr) > 0)
    return BlockCover(wb.pool[cols].copy(), rows[:, cols].tocsr(), demand[demand > 0])


def shared_prices(xys: list[np.ndarray]) -> list[np.ndarray]:
    """Each block's cover candidates (standing at ``xys[k]``) priced 1 / (the number of
    blocks whose covers hold the same grid position, to the millimetre)."""
    sizes = [len(xy) for xy in xys]
    if not sum(sizes):
        return [np.empty(0) for _ in xys]
    keys = np.round(np.concatenate(xys) * 1000.0).astype(np.int64)
    _, where, count = np.unique(keys, axis=0, return_inverse=True, return_counts=True)
    return np.split(1.0 / count[where.ravel()], np.cumsum(sizes)[:-1])


#: Time for the LP relaxation of one block's cover at shared prices [s].
SHARED_BOUND_S = 20.0


def _cover(planned: tuple[Plan, pd.DataFrame, BlockCover]) -> BlockCover:
    return planned[2]


#: The share of a district's time budget kept for stitching the blocks, the bound and the
#: route after the blocks are planned — or, where longer, the stitch's estimated time: about
#: this long per facade sample of the site [s] (measured on a 40-building town of 10 526
#: samples by the estimate, blocks of 80 m: 0.4–2.9 s, by how much the blocks planned), and
#: closing a local cluster (about 1 s).
STITCH_SHARE = 0.15
STITCH_S_PER_SAMPLE = 2e-4
CLOSE_CLUSTER_S = 1.0


def _shared_bound(cover: BlockCover, price: np.ndarray, time_limit_s: float) -> float:
    """The LP relaxation of a block's cover with its candidates at ``price`` (a Dask task,
    on the worker holding the cover); 0 (still a bound) when not solved in time."""
    from planner.pipeline.optimise import lp_bound

    return lp_bound(cover.a, cover.demand, price, time_limit_s)


def _gather_bound(bounds: list, deadline: float) -> tuple[float, str]:
    """The sum of the blocks' bounds, waited for until ``deadline``; 0 and why when a
    worker died or the time ran out."""
    from dask.distributed import wait
    from distributed.scheduler import KilledWorker

    try:
        done = wait(bounds, timeout=max(0.1, deadline - time.monotonic()))
    except TimeoutError:
        for f in bounds:
            f.cancel()
        return 0.0, "the time budget ran out"
    if len(done.not_done):
        return 0.0, "the time budget ran out"
    try:
        return float(sum(f.result() for f in bounds)), ""
    except KilledWorker:
        return 0.0, "a worker died while solving it"


def meeting_reach(p: Plan, rows_per_chunk: int = 2000) -> float:
    """The farthest a candidate meets one of the plan's samples in its first evaluation (by
    the scanner's error), horizontally [m]; the plan's reach when it was not kept."""
    wb = p.workbench
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
    from planner.pipeline.evaluate import Context, meeting_pairs
    from planner.pipeline.facades import build_facades

    wb, st = p.workbench, p.settings
    xy = p.stations[["x", "y"]].to_numpy(dtype=float)
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
        contexts.append(
            (Context.build(around, fac, p.scanner, p.requirements, st, wb.reach), False)
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
                    "station_id": p.stations["station_id"].to_numpy()[k],
                    "own": own,
                    "needed": c.stations_needed[smp] if own else np.nan,
                    **metrics,
                }
            )
        )
    return pd.concat(parts, ignore_index=True)[columns]


#: How long a scheduler named by --scheduler is waited for before the plan says it cannot
#: be reached [s]: Dask's own connection timeout, and the deadline for the whole
#: connection (a peer that accepts but never answers as a scheduler: an HTTP server, a
#: silent port) at three times that.
SCHEDULER_TIMEOUT_S = 5.0
#: The address schemes of Dask's communication layers a planner can connect over.
SCHEDULER_SCHEMES = ("tcp", "tls", "ws", "wss")


def scheduler_address(text: str) -> str:
    """A Dask scheduler's address as ``SCHEME://HOST:PORT`` (:data:`SCHEDULER_SCHEMES`), or
    InputError saying what is wrong with it — before anything is connected to."""
    from urllib.parse import urlsplit

    example = "e.g. tcp://10.0.0.5:8786"
    if not isinstance(text, str) or "://" not in text:
        raise InputError(f"a scheduler's address is SCHEME://HOST:PORT ({example}); got {text!r}")
    try:
        parts = urlsplit(text)
        port = parts.port
    except ValueError as exc:
        raise InputError(
            f"the scheduler address {text[:80]!r} is malformed ({exc}); {example}"
        ) from None
    scheme = text.split("://", 1)[0]
    if scheme not in SCHEDULER_SCHEMES:
        raise InputError(
            f"the scheduler address {text[:80]!r} uses {scheme[:20] + '://'!r}; a plan connects "
            f"over {', '.join(s + '://' for s in SCHEDULER_SCHEMES)} ({example})"
        )
    host = parts.hostname or ""
    if not host or len(host) > 253 or port is None or not 1 <= port <= 65535:
        raise InputError(
            f"the scheduler address {text[:80]!r} needs a host (at most 253 characters) and a "
            f"port from 1 to 65535 ({example})"
        )
    if parts.path.strip("/") or parts.query or parts.fragment or "@" in parts.netloc:
        raise InputError(
            f"the scheduler address {text[:80]!r} has more than SCHEME://HOST:PORT ({example})"
        )
    return text


def connect(address: str, timeout_s: float | None = None) -> Any:
    """A Dask client of the scheduler at ``address``, or InputError within ``3 × timeout_s``
    seconds (default :data:`SCHEDULER_TIMEOUT_S`): the connection runs in a daemon thread,
    so a peer that accepts and never answers cannot hold the plan (the thread is left to
    end with the process)."""
    import threading

    from dask.distributed import Client

    timeout_s = SCHEDULER_TIMEOUT_S if timeout_s is None else timeout_s
    scheduler_address(address)
    got: dict[str, Any] = {}

    def attempt() -> None:
        try:
            got["client"] = Client(address, timeout=timeout_s)
        except Exception as exc:  # every failure to connect is about the address given
            got["error"] = exc

    thread = threading.Thread(target=attempt, name="scheduler-connect", daemon=True)
    thread.start()
    thread.join(3 * timeout_s)
    fix = "start one (dask scheduler) or leave --scheduler out for a local cluster"
    if "client" in got:
        return got["client"]
    if "error" in got:
        exc = got["error"]
        why = f"{type(exc).__name__}: {str(exc).splitlines()[0][:160] if str(exc) else ''}"
        if isinstance(exc, OSError | TimeoutError):
            raise InputError(f"cannot reach a Dask scheduler at {address[:80]!r} ({why}); {fix}")
        raise InputError(
            f"cannot use {address[:80]!r} as a Dask scheduler ({why}): what answers there is "
            f"not one, or the address needs a setting this one lacks (tls:// needs Dask's TLS "
            f"configuration); {fix}"
        )
    raise InputError(
        f"nothing answered as a Dask scheduler at {address[:80]!r} within "
        f"{3 * timeout_s:.0f} s; {fix}"
    )


def plan_district(
    site: Site,
    scanner: Scanner,
    requirements: Requirements | None = None,
    settings: PlanSettings | None = None,
    *,
    block_m: float = DEFAULT_BLOCK_M,
    scheduler: str | None = None,
    workers: int = 2,
    memory_limit: str = WORKER_MEMORY,
    progress: Progress | None = None,
    deadline: float | None = None,
) -> Plan:
    """Plan a district block by block on Dask (see the module's text) and stitch one plan.

    Parameters
    ----------
    block_m : float
        Side of a block [m].
    scheduler : str, optional
        Address of an existing Dask scheduler (``tcp://host:8786``); default: a
        ``LocalCluster`` of ``workers`` processes with ``memory_limit`` each, closed after.
    deadline : float, optional
        When the whole plan must be done (a :func:`time.monotonic` time; default: now plus
        the settings' ``time_limit_s``). The blocks share the time before
        :data:`STITCH_SHARE` of it is left, each by its size; a block whose share runs out
        is planned in part (its plan says what was cut), the bound is given up when the
        time is out, and the plan says what the budget cut short.
    """
    from planner.pipeline.planning import reach_m

    req = requirements or Requirements()
    st = settings or PlanSettings()
    say = progress or (lambda _f, _m: None)
    t0 = time.perf_counter()
    if deadline is None:
        deadline = time.monotonic() + st.time_limit_s
    blocks = partition(site, block_m)
    halo = reach_m(scanner, req, st)
    spacing = [req.max_spacing_mm, *(z.requirement.get("max_spacing_mm") for z in site.zones)]
    spacing = [float(v) for v in spacing if v]  # the strictest anywhere: one step for all blocks
    st = st.for_scanner(scanner, min(spacing, default=None), halo)
    RANGES["workers"].check(workers, "the number of workers")
    memory_bytes(memory_limit)
    sites = [block_site(site, b, halo) for b in blocks]
    # each block's samples, refused here as a block's plan would refuse them (before a
    # cluster is started for nothing); the largest blocks go first (below)
    work = [estimate_samples(s, st.sample_spacing_m, st.sample_height_step_m) for s in sites]
    check_sample_count(
        max(work, default=0), st.sample_spacing_m, st.sample_height_step_m, st.max_samples
    )
    say(0.0, f"{len(blocks)} block(s) of {block_m:g} m, halo {halo:.0f} m")
    from dask.distributed import Client, as_completed
    from distributed.scheduler import KilledWorker

    cluster = None
    if scheduler:
        client = connect(scheduler)
    else:
        cluster = local_cluster(workers, memory_limit)
        client = Client(cluster)
    # the workers import the planner now, before the blocks' shares of the time are counted:
    # a share is for planning, not for a worker's start (about 3 s on a loaded machine)
    client.run(_import_planner)
    # the time budget: the blocks share what is left before the stitch's share; a block is
    # given its share when a worker takes it (as many in flight as the cluster has threads),
    # so that a block finishing early leaves its time to the ones after it
    left = max(0.0, deadline - time.monotonic())
    stitching = STITCH_S_PER_SAMPLE * estimate_samples(
        site, st.sample_spacing_m, st.sample_height_step_m
    ) + (CLOSE_CLUSTER_S if cluster is not None else 0.0)
    until = time.monotonic() + left - min(left, max(STITCH_SHARE * left, stitching))
    slots = max(1, sum(client.nthreads().values()))
    # the largest blocks first (by their samples), so that the last ones to finish are small
    # and no worker idles long while another plans a large block at the end
    queue = sorted(range(len(blocks)), key=lambda k: -work[k])
    in_flight: dict[int, float] = {}  # block → when its share ends
    covers: list = [None] * len(blocks)
    futures: dict = {}
    pending = as_completed()

    def submit_next() -> None:
        k = queue.pop(0)
        now = time.monotonic()
        busy = sum(max(0.0, end - now) for end in in_flight.values())  # the others' time
        pool = slots * max(0.0, until - now) - busy
        share = max(0.0, pool) * work[k] / max(1, sum(work[j] for j in [k, *queue]))
        share = min(share, max(0.0, until - now))
        in_flight[k] = now + share
        f = client.submit(
            _plan_block,
            sites[k],
            scanner,
            req,
            st,
            block_region(blocks[k], halo),
            share,
            time.time() + (until - now),
            priority=work[k],
            pure=False,
        )
        # the plans and tables come here; the covers stay on the workers for the bound
        covers[k] = client.submit(_cover, f, priority=work[k])
        shown = client.submit(_shown, f, priority=work[k])
        futures[shown] = k
        pending.add(shown)

    try:
        while queue and len(in_flight) < slots:
            submit_next()
        plans: list[Plan | None] = [None] * len(blocks)
        tables: list[pd.DataFrame | None] = [None] * len(blocks)
        xys: list[np.ndarray] = [np.empty((0, 2))] * len(blocks)
        for done, fut in enumerate(pending, start=1):
            k = futures[fut]
            in_flight.pop(k, None)
            if queue:
                submit_next()
            try:
                plans[k], tables[k], xys[k] = fut.result()
            except KilledWorker:
                limit = "the cluster's limit" if scheduler else memory_limit
                n = len(blocks[k].buildings)
                raise InputError(
                    f"the worker planning block {blocks[k].key} ({n} building"
                    f"{'s' * (n != 1)}) died, most often because the block needed more "
                    f"memory than a worker has ({limit}); no plan was written. Plan with "
                    f"smaller blocks (--block-m {block_m / 2:g}) or give the workers more memory"
                    + ("" if scheduler else " (--worker-memory)")
                ) from None
            say(0.93 * done / len(blocks), f"block {done} of {len(blocks)} planned")
        # the workers bound the fewest stations while the blocks are stitched here
        say(0.93, "stitching the blocks (and bounding the fewest stations)")
        t = time.perf_counter()
        prices = shared_prices(xys)
        lp_s = min(SHARED_BOUND_S, max(0.0, deadline - time.monotonic()))
        bounds = [
            client.submit(_shared_bound, c, q, lp_s) for c, q in zip(covers, prices, strict=True)
        ]
        covers.clear()  # the bounds hold them now
        out = stitch(site, scanner, req, st, blocks, plans, halo, tables)
        stitched = time.perf_counter()
        shared, why = _gather_bound(bounds, deadline)
        if why:  # the plan stands; its bound is the far-apart blocks' alone
            out.messages.append(
                f"The bound on shared stations was not computed ({why}); the bound given is "
                "that of the blocks far apart."
            )
        out.solver = replace(
            out.solver, **_bound_fields(out.solver.objective, out.solver.far_bound, shared)
        )
        out.timings_s["stitch_s"] = stitched - t
        out.timings_s["bound_wait_s"] = time.perf_counter() - stitched
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    out.timings_s["total"] = time.perf_counter() - t0
    say(1.0, "plan ready")
    return out


def _import_planner() -> None:
    import planner.pipeline.planning  # noqa: F401


def memory_bytes(text: str) -> int:
    """A worker's memory (``"2GB"``, ``"1.5 GiB"``) in bytes, or an input error."""
    from dask.utils import parse_bytes

    try:
        size = parse_bytes(text)
    except (ValueError, TypeError):
        size = 0
    if size < 256 * 2**20:
        raise InputError(
            f"worker memory {text!r} is not a size of at least 256 MB; give e.g. 2GB or 3.5GiB"
        )
    return size


def local_cluster(workers: int, memory_limit: str):
    """A ``LocalCluster`` of ``workers`` single-threaded processes, each with
    ``memory_limit``, their allocator set by :data:`WORKER_CONFIG`. Its own log lines are
    kept off the terminal: a worker that dies reaches the user as the planner's message
    naming the block, and closing the cluster can log a heartbeat error with a traceback
    that means nothing (dask/distributed issue 7105; seen after a 1000-building plan)."""
    import logging

    import dask
    from dask.distributed import LocalCluster

    with dask.config.set(WORKER_CONFIG):
        return LocalCluster(
            n_workers=workers,
            threads_per_worker=1,
            processes=True,
            memory_limit=memory_limit,
            dashboard_address=None,
            silence_logs=logging.CRITICAL,
        )


def _honest_bound(blocks: list[Block], plans: list[Plan], reach: float) -> float:
    """The largest sum of block bounds over blocks pairwise farther apart than the sum of
    their meeting reaches (the ``reach`` where a block does not say its own; greedy, by
    bound), never below the largest single block's."""
    bounds = [float(p.solver.lower_bound or 0.0) for p in plans]
    meet = [min(reach, _meeting_reach(p, reach)) for p in plans]
    chosen: list[int] = []
    for k in np.argsort(bounds)[::-1]:
        if all(
            blocks[k].footprint.distance(blocks[j].footprint) > meet[k] + meet[j] for j in chosen
        ):
            chosen.append(int(k))
    return max(sum(bounds[k] for k in chosen), max(bounds, default=0.0))


def _network_message(p: Plan) -> str:
    """What a block's registration network says of itself (kept when the network is
    dropped for the trip back from the worker)."""
    if p.block_frame is not None:
        return p.block_frame.message
    return p.network.message if p.network is not None else ""


def _meeting_reach(p: Plan, reach: float) -> float:
    """How far a block plan's stations meet samples [m] (the reach where it kept none)."""
    m = p.solver.meeting_reach_m
    return float(reach if m is None else m)


def _bound_fields(objective: int, far: float, shared: float) -> dict[str, float]:
    """The plan's bound — the larger of the far-apart blocks' (``far``) and the blocks'
    covers at shared prices (``shared``), rounded up — and its gap."""
    bound = max(far, float(math.ceil(shared - 1e-6)))
    gap = 0.0 if objective == 0 else max(0.0, (objective - bound) / objective)
    return {"lower_bound": bound, "gap": gap, "shared_bound": shared}


def stitch(
    site: Site,
    scanner: Scanner,
    req: Requirements,
    st: PlanSettings,
    blocks: list[Block],
    plans: list[Plan],
    reach: float,
    tables: list[pd.DataFrame] | None = None,
) -> Plan:
    """One plan from the blocks' plans: ids prefixed with the block key (control points keep
    theirs), the stations a neighbouring block makes redundant removed (given the blocks'
    :func:`meeting_table`), an honest bound (the far-apart blocks'; :func:`plan_district`
    raises it to the blocks' covers at shared prices where that is larger), a message per
    block, one route."""
    stations, targets, coverage, facades, links, zones, cands = [], [], [], [], [], [], []
    messages = [
        *site.warnings,
        *notes_summary(site.notes),
        f"District: {len(blocks)} blocks planned on Dask, halo {reach:.0f} m.",
    ]
    control = {c.id for c in site.control}
    for b, p in zip(blocks, plans, strict=True):
        sid = {s: f"{b.key}-{s}" for s in p.stations["station_id"]}
        tid = {t: f"{b.key}-{t}" for t in p.targets["target_id"] if t not in control}
        st_b, cov_b, tg_b, lk_b = rename_stations(sid, p.stations, p.coverage, p.targets, p.links)
        tg_b, lk_b = rename_targets(tid, tg_b, lk_b)
        stations.append(st_b)
        targets.append(tg_b)
        coverage.append(cov_b.drop(columns=[REASON_DATA], errors="ignore"))
        facades.append(p.facades)
        links.append(lk_b)
        zones.append(p.zones)
        cands.append(p.candidates)
        net = _network_message(p)
        messages.append(
            f"Block {b.key} ({len(b.buildings)} buildings): {len(p.stations)} stations, "
            f"{p.solver.status}, bound {p.solver.lower_bound}"
            + (f"; Registration: {net}." if net else "")
        )
    targets_df = _merge_control(pd.concat(targets, ignore_index=True))
    stations_df = pd.concat(stations, ignore_index=True)
    coverage_df = pd.concat(coverage, ignore_index=True)
    links_df = pd.concat(links, ignore_index=True)
    objective = int(sum(p.solver.objective for p in plans))
    removed: list[str] = []
    if tables is not None:
        meeting = pd.concat(
            [
                t.assign(station_id=f"{b.key}-" + t["station_id"].astype(str))
                for b, t in zip(blocks, tables, strict=True)
            ],
            ignore_index=True,
        )
        removed = redundant_stations(stations_df, coverage_df, links_df, meeting)
        if removed:
            stations_df, coverage_df, links_df, targets_df = _without(
                removed, stations_df, coverage_df, links_df, targets_df, meeting
            )
            objective -= len(removed)
            messages.append(
                f"{len(removed)} station(s) on block edges removed as redundant: every sample "
                "they met is met from another station, some of a neighbouring block (those "
                "samples are in that block's frame)."
            )
    cut = _cut_short(blocks, plans)
    if cut:
        messages.append(budget_message(st.time_limit_s, cut))
    far = _honest_bound(blocks, plans, reach)
    statuses = {p.solver.status for p in plans}
    solver = SolverReport(
        method=f"district ({len(blocks)} blocks)",
        status=statuses.pop() if len(statuses) == 1 else "mixed: " + ", ".join(sorted(statuses)),
        objective=objective,
        **_bound_fields(objective, far, 0.0),
        far_bound=far,
        seconds=max(float(p.solver.seconds) for p in plans),
        greedy_objective=sum(int(p.solver.greedy_objective or 0) for p in plans),
        parts=sum(int(p.solver.parts) for p in plans),
        reach_m=reach,
        meeting_reach_m=max(_meeting_reach(p, reach) for p in plans),
        candidates=sum(int(p.solver.candidates) for p in plans),
        samples=sum(int(p.solver.samples) for p in plans),
        pairs=sum(int(p.solver.pairs) for p in plans),
        registration_rounds=max(int(p.solver.registration_rounds) for p in plans),
        blocks=len(blocks),
        block_bound_sum=float(sum(p.solver.lower_bound or 0 for p in plans)),
        redundant_removed=len(removed),
        cut_short=cut,
    )
    coverage_df, links_df, seam_notes = _tie_seams(
        site, scanner, req, st, blocks, plans, reach, coverage_df, links_df, facades, removed
    )
    messages += seam_notes
    coverage_df = coverage_df.drop(columns=[f"_lim_m_{c}" for c in "xyz"], errors="ignore")
    route = field_route(site, scanner, st, stations_df, targets_df, coverage_df, links_df)
    messages.insert(0, f"Accuracy model: {st.model_description()}.")
    return Plan(
        site=site,
        scanner=scanner,
        requirements=req,
        settings=st,
        stations=stations_df,
        targets=targets_df,
        coverage=coverage_df,
        facades=pd.concat(facades, ignore_index=True),
        zones=pd.concat(zones, ignore_index=True),
        links=links_df,
        candidates=pd.concat(cands, ignore_index=True),
        network=None,
        route=route,
        solver=solver,
        messages=messages,
        timings_s={
            "blocks_s": float(sum(p.timings_s.get("total", 0.0) for p in plans)),
            "worker_peak_mb": max(p.timings_s.get("worker_peak_mb", 0.0) for p in plans),
        },
    )


def _tie_seams(
    site: Site,
    scanner: Scanner,
    req: Requirements,
    st: PlanSettings,
    blocks: list[Block],
    plans: list[Plan],
    reach: float,
    coverage: pd.DataFrame,
    links: pd.DataFrame,
    facades: list[pd.DataFrame],
    removed: list[str],
) -> tuple[pd.DataFrame, pd.DataFrame, list[str]]:
    """The blocks' networks tied into one across their seams (:mod:`planner.pipeline.seams`):
    every sample judged again with its block's frame error; the seams as links; what was
    tied and what could not be, said."""
    from planner.pipeline import seams

    if len(blocks) < 2 or not st.computes_registration or "_lim_m_x" not in coverage:
        return coverage, links, []
    frames, targets, datums, leaning = [], [], [], []
    gone = set(removed)
    for b, p in zip(blocks, plans, strict=True):
        fr = p.block_frame
        xyz, pose, tied, datum, leans = fr.xyz, fr.pose_cov, fr.tied, fr.datum, fr.leans
        ids = [f"{b.key}-{s}" for s in p.stations["station_id"][: len(xyz)]]
        keep = np.array([i not in gone for i in ids], dtype=bool)
        datums.append(datum)
        leaning.append(np.asarray(leans, dtype=bool)[keep])
        frames.append(
            seams.BlockFrame(
                [i for i, k in zip(ids, keep, strict=True) if k],
                np.asarray(xyz)[keep],
                np.asarray(pose)[keep],
                np.asarray(tied, dtype=bool)[keep],
            )
        )
        t = p.targets.copy()
        t["target_id"] = [f"{b.key}-{x}" for x in t["target_id"]]
        targets.append(t)
    ctx_of = seams.context_of(site, scanner, req, st, reach)
    found = seams.seam_links(site, ctx_of, frames, targets)
    extra, used = seams.tie_blocks(frames, found)
    # one datum's tilt leans the district's frame: the root block's, in place of each
    # block's own (a scanner without a compensator)
    root = seams.root_block(frames)
    lean = datums[root]
    tau = scanner.initial_tilt_rms_arcsec
    per_station, xyz = {}, {}
    for f, e, own, leans in zip(frames, extra, datums, leaning, strict=True):
        if e is not None:
            e = e.copy()
            if lean is not None:  # (a levelled scanner's frames do not lean)
                e[leans] += datum_tilt_cov(f.xyz[leans], lean, tau)
            if own is not None:
                e[leans] -= datum_tilt_cov(f.xyz[leans], own, tau)
            per_station |= dict(zip(f.ids, e, strict=True))
        xyz |= dict(zip(f.ids, f.xyz, strict=True))
    limits = coverage[[f"_lim_m_{c}" for c in "xyz"]].to_numpy(dtype=float)
    facade_df = pd.concat(facades, ignore_index=True)
    coverage, over = seams.add_frame_errors(coverage, facade_df, per_station, xyz, limits)
    n_lost, n_height = int(over.any(axis=1).sum()), int(over[:, 2].sum())
    notes = []
    lost = [b.key for b, e, f in zip(blocks, extra, frames, strict=True) if e is None and f.ids]
    for b, e, f in zip(blocks, extra, frames, strict=True):
        if e is None and f.ids:
            coverage = seams.untied_blocks(coverage, set(f.ids), b.key)
    rows = [
        {
            "station_a": frames[s.block_a].ids[s.a],
            "station_b": frames[s.block_b].ids[s.b],
            "common_targets": len(s.target_ids),
            "targets_placed": len(s.target_ids),
            "target_ids": ";".join(s.target_ids),
            "link_rms_mm": s.rms_mm,
            "dilution": np.nan,
            "station_b_rms_mm": np.nan,
            "kind": "targets",  # a seam: the common targets of two blocks' stations
            "overlap_pct": np.nan,
            "weakest_direction": weakest_direction(s.cov),
        }
        for s in used
    ]
    if rows:
        links = pd.concat([links, pd.DataFrame(rows, columns=links.columns)], ignore_index=True)
    tied = len(blocks) - len(lost)
    worst = max((s.rms_mm for s in used), default=0.0)
    notes.append(
        f"District network: {tied} of {len(blocks)} blocks tied into one frame across "
        f"{len(used)} seam(s) (common targets of neighbouring blocks' stations; worst seam "
        f"{worst:.1f} mm), every sample judged with its block's frame error"
        + (
            f"; {', '.join(lost)} could not be tied (no station shares three targets with a "
            "neighbouring block's): their samples are not in the common frame"
            if lost
            else ""
        )
        + "."
    )
    if n_lost:
        notes.append(
            f"District network: {n_lost} sample(s) met within their block exceed a limit in "
            "the common frame, with the seams' error added"
            + (
                f"; {n_height} of them in height, where the frame leans about the datum "
                f"station of block {blocks[root].key} (its levelling, {tau:g}″ RMS, carried "
                f"to every block): {DATUM_LEVELLING_FIX}"
                if lean is not None and n_height
                else ""
            )
            + "."
        )
    return coverage, links, notes


def _cut_short(blocks: list[Block], plans: list[Plan]) -> list[str]:
    """What the time budget cut short in the blocks, each kind once with the blocks it
    happened in (the evaluation with the samples left out over all blocks)."""
    kinds: dict[str, list[str]] = {}
    for b, p in zip(blocks, plans, strict=True):
        for what in p.solver.cut_short:
            kinds.setdefault(what.split(" (")[0], []).append(b.key)
    out = []
    for what, keys in kinds.items():
        shown = ", ".join(keys[:6]) + (f" and {len(keys) - 6} more" if len(keys) > 6 else "")
        if what == "the evaluation":
            total = sum(int(p.solver.samples_total) for p in plans)
            done = sum(int(p.solver.samples_evaluated) for p in plans)
            what = f"the evaluation ({done} of {total} samples; the plan covers those)"
        out.append(f"{what} in {len(keys)} of {len(blocks)} blocks ({shown})")
    return out


def redundant_stations(
    stations: pd.DataFrame, coverage: pd.DataFrame, links: pd.DataFrame, meeting: pd.DataFrame
) -> list[str]:
    """Covering (or linking) stations whose every met sample stays met without them (ids),
    fewest samples first, each checked against those already removed. Only a station no
    other is registered to and no unmet sample is scanned from (its best achievable values
    are those of its station) can go, and only samples needing one station are served from
    elsewhere; a sample of another block counts where that block's stations meet it on the
    same point (to the millimetre) and it lies in no zone (a zone's requirement is its own
    block's)."""
    pairs = _counting_pairs(coverage, meeting)  # only the samples met now must stay met
    multi = set(pairs.loc[pairs["own"] & (pairs["needed"] > 1), "station_id"])
    parents = set(links["station_a"])
    unmet = set(coverage.loc[~coverage["meets"] & ~coverage["party_wall"], "station_id"])
    movable = stations[(stations["purpose"] == "cover") | (stations["purpose"] == "link")][
        "station_id"
    ]
    movable = [s for s in movable if s not in parents | multi | unmet]
    by_sample: dict[tuple, set[str]] = {}
    by_station: dict[str, list[tuple]] = {}
    samples = zip(pairs["facade_id"], pairs["sample_id"], strict=True)
    for smp, s in zip(samples, pairs["station_id"], strict=True):
        by_sample.setdefault(smp, set()).add(s)
        by_station.setdefault(s, []).append(smp)
    removed: list[str] = []
    for s in sorted(movable, key=lambda s: len(by_station.get(s, []))):
        gone = {*removed, s}
        if all(by_sample[smp] - gone for smp in by_station.get(s, [])):
            removed.append(s)
    return removed


def _counting_pairs(coverage: pd.DataFrame, meeting: pd.DataFrame) -> pd.DataFrame:
    """The rows of the meeting table that count for the samples met now: a block's own, and
    another block's where it is the same point (to the millimetre) outside zones."""
    key = ["facade_id", "sample_id"]
    met = coverage.loc[coverage["meets"] & ~coverage["party_wall"], [*key, "x", "y", "z", "zone"]]
    rows = meeting.merge(met, on=key, suffixes=("", "_c"))
    same = rows[["x", "y", "z"]].to_numpy() - rows[["x_c", "y_c", "z_c"]].to_numpy()
    counts = rows["own"] | ((np.abs(same).max(axis=1) < 1e-3) & (rows["zone"] == ""))
    return rows.loc[counts, meeting.columns]


def _without(
    removed: list[str],
    stations: pd.DataFrame,
    coverage: pd.DataFrame,
    links: pd.DataFrame,
    targets: pd.DataFrame,
    meeting: pd.DataFrame,
) -> tuple[pd.DataFrame, pd.DataFrame, pd.DataFrame, pd.DataFrame]:
    """The plan's tables without the ``removed`` stations: their samples served by the
    remaining station meeting them (:func:`_counting_pairs`) with the smallest largest RMS
    (its metrics taken over) and counted again, their links gone, and the targets no link
    uses any more."""

    gone = set(removed)
    key = ["facade_id", "sample_id"]
    cov = coverage.copy()
    left = _counting_pairs(coverage, meeting)
    left = left[~left["station_id"].isin(gone)]
    left = left.assign(worst=left[["m_x_mm", "m_y_mm", "m_z_mm"]].max(axis=1))
    best = left.sort_values("worst").drop_duplicates(key).set_index(key)
    counts = left.groupby(key)["station_id"].nunique()
    idx = cov.set_index(key).index
    moved = cov["station_id"].isin(gone).to_numpy()
    take = best.reindex(idx[moved])
    cov.loc[moved, "station_id"] = take["station_id"].to_numpy()
    for k in METRIC_KEYS:  # as floats: an empty block's table makes the concatenation objects
        if k in cov.columns:
            cov.loc[moved, k] = pd.to_numeric(take[k], errors="coerce").to_numpy(dtype=float)
    met = cov["meets"].to_numpy()
    cov.loc[met, "stations_meeting"] = counts.reindex(idx[met]).fillna(0).astype(int).to_numpy()
    links = links[~links["station_b"].isin(gone)].reset_index(drop=True)
    used = {t for ids in links["target_ids"] for t in str(ids).split(";") if t}
    targets = targets[targets["target_id"].isin(used) | (targets["type"] == "control")].copy()
    targets["station_ids"] = targets["station_ids"].map(
        lambda ids: [s for s in ids if s not in gone]
    )
    stations = stations[~stations["station_id"].isin(gone)].reset_index(drop=True)
    return stations, cov, links, targets.reset_index(drop=True)


def _merge_control(t: pd.DataFrame) -> pd.DataFrame:
    """A control point seen from stations of several blocks: one row, every station."""
    ctl = t[t["type"] == "control"]
    if ctl.empty or not ctl["target_id"].duplicated().any():
        return t
    merged = ctl.groupby("target_id", sort=False).agg(
        {c: "first" for c in t.columns if c not in ("target_id", "station_ids")}
        | {"station_ids": lambda s: sorted({x for ids in s for x in ids})}
    )
    merged = merged.reset_index()[t.columns]
    return pd.concat([t[t["type"] != "control"], merged], ignore_index=True)
