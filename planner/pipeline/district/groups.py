"""Jobs of scattered buildings: one client's buildings across a town planned as separate jobs.

A site whose planned buildings fall into **groups** farther apart than a station reaches
(:func:`site_groups`: buildings within the gap of one another, directly or through others,
are one group) is not one survey: a crew scans each group on its own day or hour, on its own
datum, and drives between them. Registering them into one network would need a chain of
stations across the empty town between; the plan would call their samples untied. So each
group is planned as its own job — its own stations, targets, registration network and datum,
its own route — in its share of the time budget, and the jobs are joined into one plan
(:func:`jobs_plan`; ids prefixed with the group's key, ``G03-S02``): the travel between
groups is left to the crew, and tying the groups into one frame (GNSS control points,
``--control``) is for the user to ask.

The default time budget scales with the work (:func:`jobs_budget_s`), said before the plan
starts; ``--time-limit-s`` given stands.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np
import shapely
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from planner.pipeline.district.blocks import Block, block_site
from planner.pipeline.district.stitch import stitch
from planner.pipeline.engine import planning
from planner.pipeline.engine.result import Plan
from planner.pipeline.evaluation.evaluate import Progress
from planner.pipeline.geometry.facades import estimate_samples
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.pipeline.inputs.resolved import resolve, zone_requirements
from planner.scanner import Scanner
from planner.site import Site

__all__ = [
    "job_groups",
    "job_sites",
    "jobs_budget_s",
    "jobs_plan",
    "jobs_words",
    "plan",
    "site_groups",
]

#: A job's time on top of its samples' [s] (reading, candidates, network, route) …
JOB_BASE_S = 3.0
#: … and per sample [s]: the 49 buildings of :func:`planner.synthetic.scattered` (12 jobs,
#: 11 618 samples) planned in 49 s on this project's 2-core machine, a 50-building town
#: (11 201 samples, one job) in about 50 s (benchmarks/RESULTS.md), the default site (968)
#: in 2 s; the estimate leaves room for a slower machine.
JOB_S_PER_SAMPLE = 4e-3


def plan(
    site: Site | None = None,
    scanner: Scanner | str | None = None,
    requirements: Requirements | None = None,
    settings: PlanSettings | None = None,
    *,
    progress: Progress | None = None,
    locked: np.ndarray | None = None,
    deadline: float | None = None,
    given: planning.GivenIds | None = None,
) -> Plan:
    """Plan the fewest stations meeting ``requirements`` around the planned buildings — as
    :func:`planner.pipeline.engine.planning.plan` does (its parameters), but planned
    buildings in groups far apart (:func:`job_groups`) are planned as separate jobs, each
    with its own network, datum and route, joined into one plan (:func:`jobs_plan`); with
    ``locked`` or ``given`` (edits of one plan) the site is planned as one job."""
    site, sc, req, st = planning.plan_inputs(site, scanner, requirements, settings)
    groups, halo = job_groups(site, sc, req, st) if locked is None and given is None else ([], 0)
    if len(groups) < 2:
        return planning.plan(
            site, sc, req, st, progress=progress, locked=locked, deadline=deadline, given=given
        )
    return jobs_plan(
        site,
        sc,
        req,
        st,
        groups,
        halo,
        lambda s, until, say: planning.plan(s, sc, req, st, progress=say, deadline=until),
        deadline=deadline,
        progress=progress,
    )


def site_groups(site: Site, gap_m: float) -> list[Block]:
    """The planned buildings in groups: two buildings whose footprints come within
    ``gap_m`` [m] of each other are in one group, and so are the groups they join. Keys
    ``G1``… (``G01``… from ten groups), in order of the groups' south-west corners (rows
    from the south).

    >>> from shapely.geometry import box
    >>> from planner.site import Building
    >>> s = Site([Building("a", box(0, 0, 10, 10), 9.0), Building("b", box(20, 0, 30, 10), 9.0),
    ...           Building("c", box(500, 0, 510, 10), 9.0)])
    >>> [(g.key, g.buildings) for g in site_groups(s, 50.0)]
    [('G1', ('a', 'b')), ('G2', ('c',))]
    """
    planned = list(site.planned)
    if not planned:
        return []
    geoms = np.array([b.footprint for b in planned])
    tree = shapely.STRtree(geoms)
    a, b = tree.query(geoms, predicate="dwithin", distance=gap_m)
    n = len(planned)
    _, label = connected_components(coo_matrix((np.ones(len(a)), (a, b)), shape=(n, n)))
    parts = [np.flatnonzero(label == g) for g in range(label.max() + 1)]
    corner = [shapely.union_all(geoms[p]).bounds for p in parts]
    order = sorted(range(len(parts)), key=lambda g: (round(corner[g][1]), corner[g][0]))
    width = len(str(len(parts)))
    return [
        Block(
            f"G{n:0{width}d}",
            tuple(planned[i].id for i in parts[g]),
            shapely.union_all(geoms[parts[g]]),
        )
        for n, g in enumerate(order, start=1)
    ]


def jobs_budget_s(samples: list[int]) -> float:
    """The time the jobs of ``samples`` (each group's) take together, about [s]: each its
    base and its samples' time (:data:`JOB_BASE_S`, :data:`JOB_S_PER_SAMPLE`)."""
    return float(sum(JOB_BASE_S + JOB_S_PER_SAMPLE * n for n in samples))


def job_sites(
    site: Site, groups: list[Block], halo_m: float, st: PlanSettings
) -> tuple[list[Site], list[float]]:
    """Each job's site (its group planned, its halo kept) and its estimated time [s]
    (:func:`jobs_budget_s` of its samples)."""
    sites = [block_site(site, g, halo_m) for g in groups]
    step = (st.sample_spacing_m, st.sample_height_step_m)
    return sites, [jobs_budget_s([estimate_samples(s, *step)]) for s in sites]


def jobs_words(site: Site, groups: list[Block], budget_s: float, given: bool) -> str:
    """What is about to happen, said before the plan starts."""
    n = len(site.planned)
    minutes = budget_s / 60.0
    about = f"about {minutes:.0f} min" if minutes >= 1.5 else f"about {budget_s:.0f} s"
    return (
        f"{n} buildings in {len(groups)} groups far apart, planned as "
        f"{len(groups)} jobs (each its own network, datum and route): "
        + (
            f"{about} in the time given (--time-limit-s)"
            if given
            else f"{about}; --time-limit-s to change"
        )
    )


def job_groups(
    site: Site, scanner: Scanner, req: Requirements, st: PlanSettings
) -> tuple[list[Block], float]:
    """The site's jobs (:func:`site_groups` at the settings' ``job_gap_m``, else the search
    radius; one job at 0) and the halo each job's site keeps [m]: the search radius."""
    reach = resolve(scanner, req, st, zone_requirements(site, req)).reach_m
    gap = reach if st.job_gap_m is None else st.job_gap_m
    if gap <= 0 or len(site.planned) < 2:
        return [], reach
    return site_groups(site, gap), reach


def jobs_plan(
    site: Site,
    scanner: Scanner,
    req: Requirements,
    st: PlanSettings,
    groups: list[Block],
    halo_m: float,
    plan_one: Callable[[Site, float, Progress], Plan],
    *,
    deadline: float | None = None,
    progress: Progress | None = None,
) -> Plan:
    """Each group planned as its own job by ``plan_one(site, deadline, progress)``, one
    after another — where a ``deadline`` is given, each by its share of the time left (its
    share of the estimated work, :func:`jobs_budget_s`; else none: each job decided by work
    alone, :func:`planner.pipeline.engine.planning.plan`) — and the jobs joined into one plan
    (:func:`~planner.pipeline.district.stitch.stitch`: ids prefixed with the group's key,
    each job's network and route its own)."""
    say = progress or (lambda _f, _m: None)
    t0 = time.perf_counter()
    sites, work = job_sites(site, groups, halo_m, st)
    plans: list[Plan] = []
    for k, (g, s) in enumerate(zip(groups, sites, strict=True)):
        done, total = sum(work[:k]), sum(work)
        until = None
        if deadline is not None:
            left = max(0.0, deadline - time.monotonic())
            until = time.monotonic() + left * work[k] / max(total - done, 1e-9)
        lo, span = done / total, work[k] / total

        def inner(
            f: float,
            message: str,
            lo: float = lo,
            span: float = span,
            key: str = g.key,
            n: int = k + 1,
        ) -> None:
            say(lo + span * f, f"{key} (job {n} of {len(groups)}): {message}")

        plans.append(plan_one(s, until, inner))
    out = stitch(site, scanner, req, st, groups, plans, halo_m, jobs=True)
    out.timings_s["total"] = time.perf_counter() - t0
    say(1.0, "plan ready")
    return out
