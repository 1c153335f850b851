"""District mode on Dask (:func:`plan_district`): the blocks
(:mod:`~planner.pipeline.district.blocks`) planned as tasks on a ``LocalCluster`` or an
existing cluster's scheduler, the largest first, each given its share of the time budget
when a worker takes it; then stitched (:mod:`~planner.pipeline.district.stitch`) while the
workers compute the bound at shared prices (:mod:`~planner.pipeline.district.bounds`).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import pandas as pd

from planner.errors import InputError
from planner.pipeline.district.blocks import (
    Block,
    KeptNetwork,
    block_region,
    block_site,
    cover_of,
    for_stitch,
    partition,
    plan_block,
)
from planner.pipeline.district.bounds import (
    SHARED_BOUND_S,
    bound_fields,
    gather_bound,
    shared_bound,
    shared_prices,
)
from planner.pipeline.district.stitch import stitch
from planner.pipeline.engine.result import Plan
from planner.pipeline.evaluation.evaluate import Progress
from planner.pipeline.geometry.facades import check_sample_count, estimate_samples
from planner.pipeline.inputs.requirements import (
    DEFAULT_BLOCK_M,
    WORKER_MEMORY,
    PlanSettings,
    Requirements,
)
from planner.pipeline.inputs.resolved import resolve, zone_requirements
from planner.ranges import RANGES
from planner.scanner import Scanner
from planner.site import Site

__all__ = [
    "SCHEDULER_SCHEMES",
    "SCHEDULER_TIMEOUT_S",
    "WORKER_CONFIG",
    "connect",
    "local_cluster",
    "memory_bytes",
    "plan_district",
    "scheduler_address",
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
        When the bound on shared stations is given up (a :func:`time.monotonic` time;
        default: now plus the settings' ``time_limit_s``; said in the plan). The blocks
        themselves are planned by work, not by the clock: the same district plan on any
        machine, however loaded — only its bound may be given up on a slow one.
    """
    req = requirements or Requirements()
    st = settings or PlanSettings()
    say = progress or (lambda _f, _m: None)
    t0 = time.perf_counter()
    if deadline is None:
        deadline = time.monotonic() + st.time_limit_s
    RANGES["workers"].check(workers, "the number of workers")
    memory_bytes(memory_limit)
    blocks, sites, work, halo, st = _blocks(site, scanner, req, st, block_m)
    say(0.0, f"{len(blocks)} block(s) of {block_m:g} m, halo {halo:.0f} m")
    from dask.distributed import Client

    cluster = None
    if scheduler:
        client = connect(scheduler)
    else:
        cluster = local_cluster(workers, memory_limit)
        client = Client(cluster)
    try:
        # the workers import the planner now, before the blocks' shares of the time are
        # counted: a share is for planning, not for a worker's start (about 3 s loaded)
        client.run(_import_planner)
        job = _BlockJobs(client, blocks, sites, work, scanner, req, st, halo)
        plans, tables, xys, frames = job.run(
            say, lambda k: _worker_died(blocks[k], scheduler, memory_limit, block_m)
        )
        # the workers bound the fewest stations while the blocks are stitched here
        say(0.93, "stitching the blocks (and bounding the fewest stations)")
        t = time.perf_counter()
        prices = shared_prices(xys)
        lp_s = min(SHARED_BOUND_S, max(0.0, deadline - time.monotonic()))
        bounds = [
            client.submit(shared_bound, c, q, lp_s) for c, q in zip(job.covers, prices, strict=True)
        ]
        job.covers.clear()  # the bounds hold them now
        out = stitch(site, scanner, req, st, blocks, plans, halo, tables, frames)
        stitched = time.perf_counter()
        shared, why = gather_bound(bounds, deadline)
        if why:  # the plan stands; its bound is the far-apart blocks' alone
            out.messages.append(
                f"The bound on shared stations was not computed ({why}); the bound given is "
                "that of the blocks far apart."
            )
        out.solver = replace(
            out.solver, **bound_fields(out.solver.objective, out.solver.far_bound, shared)
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


def _blocks(
    site: Site, scanner: Scanner, req: Requirements, st: PlanSettings, block_m: float
) -> tuple[list[Block], list[Site], list[int], float, PlanSettings]:
    """The blocks, each block's site (its halo's buildings with it) and samples, the halo
    [m] and the settings resolved. The halo is the farthest any requirement reaches (the
    site-wide one, every zone's), and the strictest spacing anywhere chooses one step for
    all blocks. A block with more samples than the settings allow is refused here, as its
    plan would refuse it, before a cluster is started for nothing."""
    blocks = partition(site, block_m)
    inputs = resolve(scanner, req, st, zone_requirements(site, req))
    halo, st = inputs.reach_m, inputs.settings
    sites = [block_site(site, b, halo) for b in blocks]
    work = [estimate_samples(s, st.sample_spacing_m, st.sample_height_step_m) for s in sites]
    check_sample_count(
        max(work, default=0), st.sample_spacing_m, st.sample_height_step_m, st.max_samples
    )
    return blocks, sites, work, halo, st


def _worker_died(block: Block, scheduler: str | None, memory_limit: str, block_m: float) -> str:
    """What to say when the worker planning ``block`` died."""
    limit = "the cluster's limit" if scheduler else memory_limit
    n = len(block.buildings)
    return (
        f"the worker planning block {block.key} ({n} building{'s' * (n != 1)}) died, most "
        f"often because the block needed more memory than a worker has ({limit}); no plan "
        f"was written. Plan with smaller blocks (--block-m {block_m / 2:g}) or give the "
        "workers more memory" + ("" if scheduler else " (--worker-memory)")
    )


@dataclass
class _BlockJobs:
    """The blocks' plans as Dask tasks: the largest blocks first (by their samples), so that
    the last ones to finish are small and no worker idles long while another plans a large
    block at the end; as many in flight as the cluster has threads. The time budget: the
    blocks share what is left before ``until``; a block is given its share when a worker
    takes it, so that a block finishing early leaves its time to the ones after it."""

    client: Any
    blocks: list[Block]
    sites: list[Site]
    work: list[int]
    scanner: Scanner
    req: Requirements
    st: PlanSettings
    halo: float
    covers: list = field(default_factory=list)  # each block's cover, kept on the workers
    queue: list[int] = field(default_factory=list)  # the blocks not yet handed out
    in_flight: dict[int, float] = field(default_factory=dict)  # block → when it was handed out
    futures: dict = field(default_factory=dict)  # each block's result → the block
    pending: Any = None  # the results in the order they come (dask's as_completed)

    def run(
        self, say: Progress, died: Callable[[int], str]
    ) -> tuple[list[Plan], list[pd.DataFrame], list[np.ndarray], list[KeptNetwork]]:
        """Every block's plan, meeting table, cover candidates' positions and frame, in
        block order; a worker dying is an InputError (``died(k)`` says what to say)."""
        from dask.distributed import as_completed
        from distributed.scheduler import KilledWorker

        n = len(self.blocks)
        self.queue = sorted(range(n), key=lambda k: -self.work[k])
        self.in_flight, self.futures, self.pending = {}, {}, as_completed()
        self.covers = [None] * n
        slots = max(1, sum(self.client.nthreads().values()))
        while self.queue and len(self.in_flight) < slots:
            self._submit_next(slots)
        out: list[list] = [[None] * n, [None] * n, [np.empty((0, 2))] * n, [None] * n]
        for done, fut in enumerate(self.pending, start=1):
            k = self.futures[fut]
            self.in_flight.pop(k, None)
            if self.queue:
                self._submit_next(slots)
            try:
                for part, value in zip(out, fut.result(), strict=True):
                    part[k] = value
            except KilledWorker:
                raise InputError(died(k)) from None
            say(0.93 * done / n, f"block {done} of {n} planned")
        plans, tables, xys, frames = out
        return plans, tables, xys, frames

    def _submit_next(self, slots: int) -> None:
        k = self.queue.pop(0)
        work = self.work
        self.in_flight[k] = time.monotonic()
        f = self.client.submit(
            plan_block,
            self.sites[k],
            self.scanner,
            self.req,
            self.st,
            block_region(self.blocks[k], self.halo),
            priority=work[k],
            pure=False,
        )
        # the plans and tables come here; the covers stay on the workers for the bound
        self.covers[k] = self.client.submit(cover_of, f, priority=work[k])
        shown = self.client.submit(for_stitch, f, priority=work[k])
        self.futures[shown] = k
        self.pending.add(shown)


def _import_planner() -> None:
    import planner.pipeline.engine.planning  # noqa: F401


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
