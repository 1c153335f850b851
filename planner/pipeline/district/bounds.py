"""Bounds on the fewest stations of a district planned in blocks.

**The bound stays honest.** A block's lower bound holds for the stations meeting *its*
samples; the plain sum of all blocks' bounds does not hold for the whole (a station on a
block edge may serve two blocks). Every candidate of the whole site that meets a sample of
a block is among that block's candidates, at the same grid position (the grid is anchored
to the CRS and the halo holds everything within the reach). Two bounds follow, and the
plan reports the larger:

* **Shared stations** (:func:`shared_prices`,
:func:`~planner.pipeline.district.blocks.block_cover`): each block's cover by
  the scanner's error, with every candidate priced 1 / (the number of blocks whose samples
  it meets). A cover of the whole site, restricted to the candidates meeting one block's
  samples, covers that block; summed over the blocks, these prices count each of its
  stations once. So the sum of the blocks' LP relaxations at these prices is a lower bound
  on the fewest stations of the whole (Lagrangian decomposition with the shared columns'
  costs split evenly; Guignard & Kim, "Lagrangean decomposition: a model yielding stronger
  Lagrangean bounds", Mathematical Programming 39, 1987,
  https://doi.org/10.1007/BF02592954; tested against the optimum of random instances).
* **Far apart**: each block says the farthest any candidate meets one of its samples (its
  **meeting reach**, :func:`~planner.pipeline.district.blocks.meeting_reach`, at most the reach).
  Two blocks farther apart than the sum of their meeting reaches share no station, so the sum of the
  bounds of blocks pairwise that far apart is a bound (the largest such sum found, greedy).
"""

from __future__ import annotations

import math
import time

import numpy as np

from planner.pipeline.district.blocks import Block, BlockCover
from planner.pipeline.engine.result import Plan

__all__ = ["SHARED_BOUND_S", "shared_prices"]


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


def shared_bound(cover: BlockCover, price: np.ndarray, time_limit_s: float) -> float:
    """The LP relaxation of a block's cover with its candidates at ``price`` (a Dask task,
    on the worker holding the cover); 0 (still a bound) when not solved in time."""
    from planner.pipeline.optimise.cover import lp_bound

    return lp_bound(cover.a, cover.demand, price, time_limit_s)


def gather_bound(bounds: list, deadline: float) -> tuple[float, str]:
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


def honest_bound(blocks: list[Block], plans: list[Plan], reach: float) -> float:
    """The largest sum of block bounds over blocks pairwise farther apart than the sum of
    their meeting reaches (the ``reach`` where a block does not say its own; greedy, by
    bound), never below the largest single block's."""
    bounds = [float(p.solver.lower_bound or 0.0) for p in plans]
    meet = [min(reach, capped_meeting_reach(p, reach)) for p in plans]
    chosen: list[int] = []
    for k in np.argsort(bounds)[::-1]:
        if all(
            blocks[k].footprint.distance(blocks[j].footprint) > meet[k] + meet[j] for j in chosen
        ):
            chosen.append(int(k))
    return max(sum(bounds[k] for k in chosen), max(bounds, default=0.0))


def capped_meeting_reach(p: Plan, reach: float) -> float:
    """How far a block plan's stations meet samples [m] (the reach where it kept none)."""
    m = p.solver.meeting_reach_m
    return float(reach if m is None else m)


def bound_fields(objective: int, far: float, shared: float) -> dict[str, float]:
    """The plan's bound — the larger of the far-apart blocks' (``far``) and the blocks'
    covers at shared prices (``shared``), rounded up — and its gap."""
    bound = max(far, float(math.ceil(shared - 1e-6)))
    gap = 0.0 if objective == 0 else max(0.0, (objective - bound) / objective)
    return {"lower_bound": bound, "gap": gap, "shared_bound": shared}
