"""What-if by hand: the surveyor moves, adds, deletes or locks stations, and the plan is
judged again — coverage, accuracy with the registration error, targets and links — without
planning from scratch.

Both functions work on a plan made in this process (:attr:`Plan.workbench` holds what it was
made from: samples, candidate grid, target candidates and what each position sees of them,
so that a re-evaluation only computes what changed):

* :func:`evaluate_stations` — exactly these stations (no optimiser), judged as a plan is;
* :func:`reoptimise` — keep the locked stations and choose the fewest others around them.
"""

from __future__ import annotations

import time

import numpy as np

from planner.errors import InputError
from planner.pipeline.planning import (
    Progress,
    Workbench,
    _free_positions,
    _judge,
    _network,
    _Round,
    assemble,
    choose_stations,
)
from planner.pipeline.result import Plan

__all__ = ["evaluate_stations", "reoptimise"]


def _workbench(p: Plan) -> Workbench:
    if p.workbench is None:
        raise InputError(
            "this plan keeps nothing to edit (a district plan, or one read back from its "
            "files); plan the site again in this session to move stations by hand"
        )
    return p.workbench


def evaluate_stations(p: Plan, xy: np.ndarray) -> Plan:
    """The plan with stations exactly at ``xy`` (``(k, 2)`` [m], site CRS): the registration
    network built for them, every sample judged on scanner ⊕ registration, targets, links and
    the route; their purpose is "hand". A position inside a
    building, obstacle or no-go area is an :class:`~planner.errors.InputError` saying which.
    The registration network may add a station where it needs one to tie the others (its
    purpose is "link")."""
    t0 = time.perf_counter()
    wb = _workbench(p)
    xy = _free_positions(wb, xy, "station")
    idx = wb.add_positions(xy)
    timings: dict[str, float] = {"setup": 0.0}
    r = _Round(cover=idx)
    r.net = _network(wb.ctx, wb.pool, wb.seen, idx, timings) if len(idx) else None
    r.judged = _judge(wb.ctx, wb.pool, r)
    bound = p.solver.get("lower_bound")
    n = len(r.net.stations) if r.net is not None else 0
    solver = {
        "method": "hand placement",
        "status": "stations placed by hand",
        "objective": n,
        "lower_bound": bound,
        "gap": None if bound is None or n == 0 else max(0.0, (n - bound) / n),
        "seconds": 0.0,
        "greedy_objective": None,
        "reductions": "",
        "parts": 0,
        "registration_rounds": 0,
    }
    messages = [*wb.messages, f"Stations placed by hand: {len(idx)}."]
    return assemble(wb, r, solver, messages, timings, t0, hand=idx)


def reoptimise(p: Plan, locked_xy: np.ndarray, progress: Progress | None = None) -> Plan:
    """A new plan keeping the stations at ``locked_xy`` (``(k, 2)`` [m]) and choosing the
    fewest others around them, with the registration rounds of a full plan (the settings'
    time budget)."""
    return choose_stations(_workbench(p), progress, locked=locked_xy)
