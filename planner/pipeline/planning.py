"""The orchestrator: ``plan(site, scanner, requirements, settings) -> Plan``.

Steps: facades and samples → candidate stations → evaluation of every candidate × sample →
fewest stations (:mod:`~planner.pipeline.optimise`) → registration network and targets
(:mod:`~planner.pipeline.registration`) → coverage by the chosen stations → per-facade
summary and unmet samples with the reason. The result type is
:class:`~planner.pipeline.result.Plan`; its files are written by
:mod:`~planner.pipeline.export`.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import scipy.sparse as sp
import shapely

from planner.accuracy import reach_bound_m
from planner.accuracy3d import reach_bound_3d_m
from planner.errors import InputError
from planner.pipeline.candidates import blocked_ground, candidate_grid
from planner.pipeline.control import tie_groups, tie_messages, traverse_setups
from planner.pipeline.evaluate import (
    METRIC_KEYS,
    Assignment,
    CandidateEvaluation,
    Context,
    Registration,
    assign_stations,
    best_achievable,
    evaluate_candidates,
)
from planner.pipeline.facades import (
    FacadeSet,
    build_facades,
    estimate_samples,
    lower_roof_in_front,
)
from planner.pipeline.optimise import CoverSolution, solve_cover, spread_views
from planner.pipeline.registration import (
    Network,
    SightCache,
    TargetCandidates,
    build_network,
    target_candidates,
)
from planner.pipeline.requirements import (
    CHECKS,
    REGISTRATION_PROCESSING,
    PlanSettings,
    Requirements,
)
from planner.pipeline.result import LINK_COLUMNS, TARGET_COLUMNS, ZONE_COLUMNS, Plan
from planner.pipeline.route import field_route
from planner.pipeline.zones import ZoneTable, apply_zones
from planner.registration_error import CONTROL, Link, datum_lean_mm
from planner.scanner import DEFAULT_SCANNER, Scanner, load_scanner
from planner.site import Site
from planner.sitecheck import notes_summary
from planner.targets import choose_target

__all__ = ["Workbench", "assemble", "choose_stations", "plan"]

Progress = Callable[[float, str], None]

#: Candidate stations farther than this from a facade are not searched [m] (the accuracy
#: bound usually stops well before).
MIN_SEARCH_RADIUS_M = 25.0
#: Evaluation speed used to put a work estimate in minutes [pairs per second].
PAIRS_PER_S = 20e6
#: The optimiser always gets at least this long, even when the evaluation used the budget
#: (greedy set cover takes well under it) [s].
MIN_SOLVER_S = 0.5
#: The share of the time left that the optimiser may take when the registration network is
#: still to be built and judged after it (its rounds need the rest of the budget).
SOLVER_SHARE = 0.5
#: The share of the plan's budget the first evaluation of every candidate may take: a site
#: too large for its budget is evaluated in part, and the optimiser and the registration
#: still get their time.
EVALUATION_SHARE = 0.6


def reach_m(scanner: Scanner, req: Requirements, settings: PlanSettings | None = None) -> float:
    """Search radius for candidate stations [m]: the distance beyond which no station can
    meet the requirements under the settings' model (:func:`planner.accuracy.reach_bound_m`,
    :func:`planner.accuracy3d.reach_bound_3d_m`), within the scanner's and the requirement's
    range, and never below :data:`MIN_SEARCH_RADIUS_M` — so that even an infeasible
    requirement gets candidates close by and the plan can say what is achievable."""
    st = PlanSettings() if settings is None else settings
    _expect(st, PlanSettings, "settings", "PlanSettings(...)")
    tilt = st.scan_tilt_rms_arcsec(scanner)
    if st.model == "paper":
        bound = reach_bound_m(
            scanner, req.max_x_mm, req.max_y_mm, req.max_z_mm, st.station_rms_pair, tilt
        )
    else:
        bound = reach_bound_3d_m(scanner, req.max_x_mm, req.max_y_mm, st.station_rms_pair, tilt)
    limit = min(scanner.max_range_m, req.max_range_m or np.inf)
    return float(min(limit, max(bound, MIN_SEARCH_RADIUS_M)))


def plan(
    site: Site | None = None,
    scanner: Scanner | str | None = None,
    requirements: Requirements | None = None,
    settings: PlanSettings | None = None,
    *,
    progress: Progress | None = None,
    locked: np.ndarray | None = None,
    deadline: float | None = None,
) -> Plan:
    """Plan the fewest stations meeting ``requirements`` around the planned buildings.

    Defaults: the built-in default site, the scanner of Voroshilov & Karachentsev's example
    (:data:`~planner.scanner.DEFAULT_SCANNER`), ``Requirements()`` and ``PlanSettings()``.
    ``locked`` — ``(k, 2)`` station positions [m] the surveyor fixed: they are kept, and the
    fewest others chosen around them. Infeasible requirements do not raise: the samples no
    candidate can satisfy come back with ``meets`` False and the reason (see
    :attr:`Plan.unmet`). The plan keeps what it was made from (:attr:`Plan.workbench`) for
    what-if edits (:mod:`planner.pipeline.whatif`).

    The plan ends by ``deadline`` (a :func:`time.monotonic` time; default: now plus the
    settings' ``time_limit_s``): when it comes, the best plan so far is made, and its
    messages say what the budget cut short (``solver["cut_short"]``).
    """
    from planner.siteio import default_site

    t0 = time.perf_counter()
    _expect(site, Site, "site", "read one with planner.read_site(path) or planner.default_site()")
    _expect(requirements, Requirements, "requirements", "e.g. Requirements(max_xy_mm=4)")
    _expect(settings, PlanSettings, "settings", "e.g. PlanSettings(grid_m=2)")
    if scanner is not None and not isinstance(scanner, Scanner | str | Path):
        raise InputError(
            f"scanner must be a Scanner, a catalogue name or a profile file; got "
            f"{type(scanner).__name__}"
        )
    st = settings or PlanSettings()
    if deadline is None:
        deadline = time.monotonic() + st.time_limit_s
    wb = _prepare(
        site or default_site(),
        load_scanner(scanner or DEFAULT_SCANNER),
        requirements or Requirements(),
        st,
        progress or (lambda _f, _m: None),
    )
    return choose_stations(wb, progress, locked=locked, deadline=deadline, t0=t0)


@dataclass
class Workbench:
    """What a plan is made from, kept for what-if edits: the facade samples and their
    requirements, the candidate grid, the target candidates and what each position sees of
    them (computed once per position). ``pool`` is the candidate grid followed by every
    position a surveyor put a station at (appended, never removed, so that the sight cache's
    indices stay valid). Not saved with the plan and not sent between processes."""

    site: Site
    scanner: Scanner
    req: Requirements
    settings: PlanSettings
    facades: FacadeSet
    zones: ZoneTable
    zone_ids: np.ndarray  # (N,) the zones each sample is in ('' none)
    ctx: Context
    seen: SightCache
    reach: float
    n_grid: int
    pairs: float
    messages: list[str]
    setup_s: float
    evaluation: CandidateEvaluation | None = None  # the last full evaluation of the grid
    diagnosis: Diagnosis | None = None  # what no candidate of that evaluation meets, and why

    @property
    def pool(self) -> np.ndarray:
        return self.seen.cand_xy

    @property
    def tc(self) -> TargetCandidates:
        """The target candidates (with those placed by hand)."""
        return self.seen.tc

    def add_positions(self, xy: np.ndarray) -> np.ndarray:
        """Pool indices of the positions ``xy`` [m] (appended when new, to the millimetre)."""
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        pool = self.seen.cand_xy
        idx = np.empty(len(xy), dtype=np.int64)
        for k, p in enumerate(xy):
            same = np.flatnonzero(np.all(np.abs(pool - p) < 1e-3, axis=1))
            if len(same):
                idx[k] = same[0]
            else:
                pool = np.vstack([pool, p])
                idx[k] = len(pool) - 1
        self.seen.cand_xy = pool
        return idx


def _prepare(
    site: Site, sc: Scanner, req: Requirements, st: PlanSettings, say: Progress
) -> Workbench:
    """Samples, zones, search radius, candidate grid, target candidates (refusing work beyond
    the settings' limits with what to change)."""
    t0 = time.perf_counter()
    messages = [*site.warnings, *notes_summary(site.notes)]
    say(0.0, "sampling facades")
    n_est = estimate_samples(site, st.sample_spacing_m, st.sample_height_step_m)
    if n_est > st.max_samples:
        raise InputError(
            f"the facades would need about {n_est:,} samples at {st.sample_spacing_m:g} m × "
            f"{st.sample_height_step_m:g} m, more than {st.max_samples:,.0f}; use coarser "
            "samples (--sample-spacing-m, --sample-height-step-m), plan fewer buildings, or "
            "raise the limit (--max-samples)"
        )
    fac = build_facades(site, st.sample_spacing_m, st.sample_height_step_m)
    fac, sample_req, zones = apply_zones(site, fac, req)
    if len(fac.z) > st.max_samples:
        raise InputError(
            f"with the zones' finer samples the facades need {len(fac.z):,} samples, more than "
            f"{st.max_samples:,.0f}; use coarser zone spacings or raise the limit (--max-samples)"
        )
    messages += zones.messages
    # the search radius: the farthest any requirement (the site-wide one, a zone's) reaches
    reach = max(reach_m(sc, r, st) for r in [req, *zones.requirements])
    cand = candidate_grid(site, fac, reach, st.grid_m, st.clearance_m)
    ctx = Context.build(site, fac, sc, req, st, reach, sample_req)
    pairs = ctx.pair_count(cand)
    if pairs > st.max_pairs:
        raise InputError(
            f"the plan would evaluate {pairs:.3g} station × sample pairs (about "
            f"{pairs / PAIRS_PER_S / 60:.0f} min), more than {st.max_pairs:.3g}; use a coarser "
            "grid (--grid-m) or coarser samples, plan fewer buildings, or raise the limit "
            "(--max-pairs)"
        )
    if len(cand) == 0:
        messages.append(
            "no free ground for a station within reach of the facades "
            f"({reach:.0f} m, clearance {st.clearance_m:g} m)"
        )
    stand_xy = candidate_grid(site, fac, min(reach, 40.0), st.target_spacing_m, st.clearance_m)
    if site.passages and len(cand):  # a gateway's stand sees both sides: one every grid step
        through = shapely.union_all([g.geometry for g in site.passages])
        stand_xy = np.vstack([stand_xy, cand[shapely.contains_xy(through, cand[:, 0], cand[:, 1])]])
    tc = target_candidates(ctx, stand_xy)
    return Workbench(
        site=site,
        scanner=sc,
        req=req,
        settings=st,
        facades=fac,
        zones=zones,
        zone_ids=sample_req.zone_ids,
        ctx=ctx,
        seen=SightCache(ctx, tc, cand),
        reach=reach,
        n_grid=len(cand),
        pairs=pairs,
        messages=messages,
        setup_s=time.perf_counter() - t0,
    )


def choose_stations(
    wb: Workbench,
    progress: Progress | None = None,
    *,
    locked: np.ndarray | None = None,
    deadline: float | None = None,
    t0: float | None = None,
) -> Plan:
    """The fewest stations (with ``locked`` positions kept) and their registration network,
    for what ``wb`` holds; the plan's time budget runs from ``deadline``."""
    t0 = time.perf_counter() if t0 is None else t0
    ctx, st = wb.ctx, wb.settings
    fac = wb.facades
    say = progress or (lambda _f, _m: None)
    deadline = time.monotonic() + st.time_limit_s if deadline is None else deadline
    timings: dict[str, float] = {"setup": wb.setup_s}
    forced = np.empty(0, dtype=np.int64)
    if locked is not None and len(np.asarray(locked).reshape(-1, 2)):
        forced = wb.add_positions(_free_positions(wb, locked, "locked station"))
    cand, seen = wb.pool, wb.seen
    # stations and registration chosen together (docs/science.md): the fewest stations by
    # the scanner's error, their network, every sample judged on the total; while the
    # registration keeps samples short, stations are added that meet them with the
    # registration error they would have (estimated from the network) and the network is
    # built and judged again; once none is short, the fewest stations are chosen again with
    # every candidate's estimated registration error, the network's backbone kept
    cut: list[str] = []  # what the time budget cut short, in words
    now = time.monotonic()
    evaluated_by = now + EVALUATION_SHARE * max(0.0, deadline - now)
    ev = _evaluate(ctx, cand, say, min(deadline, evaluated_by), timings)
    if not ev.evaluated.all():
        cut.append(
            f"the evaluation ({int(ev.evaluated.sum())} of {len(fac.z)} samples; the plan "
            "covers those)"
        )
    wb.evaluation = ev
    # the diagnosis before the optimiser: the optimiser takes a share of the time left, and
    # what it leaves must not decide what the plan says of the samples no position meets
    wb.diagnosis = _diagnose(ctx, cand, ev, deadline, timings)
    if len(wb.diagnosis.samples) and not np.all(wb.diagnosis.best["done"]):
        cut.append("the diagnosis of the samples no position meets")
    sol = _optimise(ctx, cand, ev, say, deadline, timings, forced=forced)
    if len(wb.diagnosis.samples) and time.monotonic() > deadline:
        cut.append("the best-effort stations for the samples no position meets")
    best_effort, relaxed_by = _best_effort(ctx, cand, sol.chosen, wb.diagnosis, deadline)
    if len(best_effort):
        sol.chosen = np.union1d(sol.chosen, best_effort)
        forced = np.union1d(forced, best_effort)
        say(0.8, f"best effort: {len(best_effort)} station(s) for what no position meets")
    r = _Round(cover=sol.chosen, net=_network(ctx, cand, seen, sol.chosen, timings, deadline))
    r.judged = _judge(ctx, cand, r)
    best, rounds, adds, resolved, moved = r, 0, 0, False, False
    while st.computes_registration and rounds < MAX_REGISTRATION_ROUNDS:
        if r.net is None:
            break
        if time.monotonic() > deadline:
            if r.judged.short_by_registration.any() or not resolved:
                cut.append(f"the registration rounds (after {rounds})")
            break
        short = r.judged.short_by_registration
        if short.any() and not moved:  # once: a datum nearer the middle, kept if better
            moved = True
            middle = _datum_station(ctx, cand, r)
            if middle is not None:
                say(0.85, "registration: a datum station nearer the middle of the site")
                trial = _Round(cover=r.cover, added=np.union1d(r.added, [middle]))
                chosen = np.concatenate([r.net.stations, [middle]])
                trial.net = _network(ctx, cand, seen, chosen, timings, deadline)
                trial.judged = _judge(ctx, cand, trial)
                gain = trial.judged.n_met - r.judged.n_met
                if gain > DATUM_SHARE * (~ctx.facades.party_wall).sum():  # else: as if untried
                    rounds += 1
                    r = trial
                    best = r if r.judged.better_than(best.judged) else best
                    continue
        more = np.empty(0, dtype=np.int64)
        if short.any() and (resolved or adds < ADD_ROUNDS):
            say(0.85, f"registration: {int(short.sum())} samples short; adding stations")
            more = _stations_for(ctx, cand, r.net, short, deadline, timings)
        grown_from = r.net
        if len(more):
            adds += 1
            chosen = np.concatenate([r.net.stations, more])
            r = _Round(cover=r.cover, added=np.union1d(r.added, more))
        elif not resolved and len(r.net.stations) > len(sol.chosen):
            say(0.9, "registration: choosing the fewest stations again")
            resolved = True
            backbone = np.union1d(r.net.backbone, forced)
            estimate = _estimate(ctx, r.net, cand)
            _, again = _choose(
                ctx, cand, say, deadline, timings, estimate, forced=backbone, scanner_ok=ev.ok
            )
            chosen = again.chosen
            r = _Round(cover=chosen)
        else:
            break
        rounds += 1
        keep = grown_from.datum_station if len(more) else None
        r.net = _network(ctx, cand, seen, chosen, timings, deadline, keep)
        r.judged = _judge(ctx, cand, r)
        if r.judged.better_than(best.judged):
            best = r
    r = best
    if st.computes_registration and r.net is not None:
        r = _prune(ctx, cand, seen, r, deadline, timings, keep=forced)
    if any(n.cut_short for n in (r.net,) if n is not None):
        cut.append("the search for linking stations")
    messages = list(wb.messages)
    if cut:
        messages.append(budget_message(st.time_limit_s, cut))
    n_locked = len(forced) - len(best_effort)
    if n_locked:
        messages.append(f"{n_locked} station(s) locked by hand; the others chosen around them.")
    if len(best_effort):
        messages.append(
            f"Best effort: {len(best_effort)} station(s) added for the samples no position "
            f"meets, meeting them within {relaxed_by:.2f} × the "
            "limits (they stay unmet; see the best achievable values and what would meet them)."
        )
    solver = {
        "method": sol.method,
        "status": sol.status,
        "objective": sol.objective,
        "lower_bound": sol.lower_bound,
        "gap": sol.gap,
        "seconds": sol.seconds,
        "greedy_objective": sol.greedy_objective,
        "reductions": sol.details.get("reductions", ""),
        "parts": sol.details.get("parts", 0),
        "registration_rounds": rounds,
        "cut_short": cut,
        "samples_total": len(fac.z),
        "samples_evaluated": int(ev.evaluated.sum()),
    }
    if r.net is not None and len(r.net.stations) != sol.objective and st.computes_registration:
        messages.append(
            f"Stations: {sol.objective} meet the requirement by the scanner's error alone; "
            f"{len(r.net.stations)} with the registration error counted ({rounds} round(s) of "
            "adding stations and choosing again)."
        )
    hand = np.setdiff1d(forced, best_effort)
    return assemble(
        wb, r, solver, messages, timings, t0, progress=say, hand=hand, best_effort=best_effort
    )


#: The samples no position meets are served, best effort, within this share of the smallest
#: uniform relaxation of the limits under which every one of them could be met.
BEST_EFFORT_SLACK = 1.02


@dataclass
class Diagnosis:
    """The best achievable value of every check at the samples no candidate meets
    (:func:`~planner.pipeline.evaluate.best_achievable`), computed once per evaluation: the
    best-effort stations and the reasons of the plan and of every edit by hand read it."""

    samples: np.ndarray  # (M,) sorted sample indices
    best: dict[str, np.ndarray]  # per check key, "score" and "done": (M,) each
    n_view: np.ndarray  # (M,) candidates that see each
    roof: np.ndarray  # (M,) the lower building whose roof each faces ("" none)

    @property
    def elevated(self) -> np.ndarray:
        """(M,) bool: beyond the ground's reach — no ground candidate sees the sample, or it
        faces a lower neighbour's roof (seen from the ground only over the roof's edge): a
        station on that roof, a lift or a mast would serve it; none is spent on it here."""
        return (self.n_view == 0) | (self.roof != "")

    def at(self, sample: int) -> tuple[int, dict[str, float], str] | None:
        """(candidates seeing it, best values, the roof it faces) of ``sample``; None where
        not diagnosed."""
        j = int(np.searchsorted(self.samples, sample))
        if j == len(self.samples) or self.samples[j] != sample or not self.best["done"][j]:
            return None
        best = {key: float(v[j]) for key, v in self.best.items()}
        return int(self.n_view[j]), best, str(self.roof[j])


def _diagnose(
    ctx: Context,
    cand: np.ndarray,
    ev: CandidateEvaluation,
    deadline: float,
    timings: dict[str, float],
) -> Diagnosis:
    """Diagnose the demanded, evaluated samples fewer candidates meet than they need."""
    t = time.perf_counter()
    n_ok = np.asarray(ev.ok.sum(axis=1)).ravel()
    hopeless = np.flatnonzero(~ctx.facades.party_wall & (n_ok < ctx.stations_needed) & ev.evaluated)
    best = best_achievable(ctx, cand, hopeless, deadline) if len(hopeless) else {"done": []}
    roof = lower_roof_in_front(ctx.site, ctx.facades, hopeless)
    timings["diagnosis"] = time.perf_counter() - t
    return Diagnosis(hopeless, best, ev.n_view[hopeless], roof)


def _best_effort(
    ctx: Context,
    cand: np.ndarray,
    chosen: np.ndarray,
    diagnosis: Diagnosis,
    deadline: float,
) -> tuple[np.ndarray, float]:
    """Candidates (not among ``chosen``) for the samples no candidate meets, and the factor
    they meet them within: the smallest uniform relaxation of the limits under which every
    such sample seen could be met (the largest of their best achievable scores, value /
    limit, times :data:`BEST_EFFORT_SLACK`), the fewest candidates (greedy) meeting them
    under it — so that a requirement a little too strict gives the plan that comes closest,
    not zero stations. The samples stay unmet. None is spent on the samples beyond the
    ground's reach (:attr:`Diagnosis.elevated`): they need an elevated station."""
    none = np.empty(0, dtype=np.int64), 1.0
    if not len(diagnosis.samples) or time.monotonic() > deadline:
        return none
    best = diagnosis.best
    good = best["done"] & np.isfinite(best["score"]) & ~diagnosis.elevated
    if not good.any():
        return none
    factor = float(best["score"][good].max()) * BEST_EFFORT_SLACK
    limits = {
        c.key: ctx.limits[c.key] * factor if c.sense == "max" else ctx.limits[c.key] / factor
        for c in CHECKS
    }
    relaxed = replace(ctx, limits=limits, stations_needed=np.ones_like(ctx.stations_needed))
    only = np.zeros(len(ctx.facades.z), dtype=bool)
    only[diagnosis.samples[good]] = True
    ok = evaluate_candidates(relaxed, cand, deadline=deadline, only=only).ok
    ok = sp.csr_matrix(ok[np.flatnonzero(only)])
    served = np.asarray(ok[:, chosen].sum(axis=1)).ravel() > 0 if len(chosen) else False
    demand = ((np.asarray(ok.sum(axis=1)).ravel() > 0) & ~served).astype(np.int64)
    if not demand.any():
        return none
    sol = solve_cover(ok, demand, _solver_time(ctx, deadline), ctx.settings.method)
    return np.asarray(sol.chosen, dtype=np.int64), factor


def _free_positions(wb: Workbench, xy: np.ndarray, what: str) -> np.ndarray:
    """``xy`` [m] as a ``(k, 2)`` array, refused (InputError) where a station cannot stand:
    inside a building, obstacle or no-go area, or within the clearance of one."""
    xy = np.asarray(xy, dtype=float).reshape(-1, 2)
    if not np.isfinite(xy).all():
        raise InputError(f"a {what} has no coordinates (x, y must be numbers)")
    blocked = blocked_ground(wb.site, wb.settings.clearance_m)
    bad = np.flatnonzero(shapely.contains_xy(blocked, xy[:, 0], xy[:, 1]))
    if len(bad):
        k = bad[0]
        raise InputError(
            f"the {what} at E {xy[k, 0]:.2f}, N {xy[k, 1]:.2f} stands inside a building, "
            f"obstacle or no-go area (or within {wb.settings.clearance_m:g} m of one); move it "
            "onto free ground"
        )
    return xy


def assemble(
    wb: Workbench,
    r: _Round,
    solver: dict[str, Any],
    messages: list[str],
    timings: dict[str, float],
    t0: float,
    *,
    progress: Progress | None = None,
    hand: np.ndarray | None = None,
    best_effort: np.ndarray | None = None,
) -> Plan:
    """The plan of the stations of round ``r`` (pool indices; those in ``hand`` placed by
    hand, those in ``best_effort`` for samples no position meets): coverage, targets, links,
    route, messages."""
    say = progress or (lambda _f, _m: None)
    ctx, st, ev, cand = wb.ctx, wb.settings, wb.evaluation, wb.pool
    net, assignment = r.net, r.judged.assignment
    say(0.93, "coverage of the chosen stations")
    t = time.perf_counter()
    station_idx = net.stations if net is not None else np.asarray(r.cover, dtype=np.int64)
    station_xy = cand[station_idx] if len(station_idx) else np.empty((0, 2))
    ids = [f"S{i + 1:02d}" for i in range(len(station_idx))]
    family = _class_family(wb.req, wb.zones)
    grid = cand[: wb.n_grid]
    coverage = _coverage(ctx, ev, wb.diagnosis, assignment, ids, net, wb.zone_ids, family)
    purpose = np.select(
        [
            np.isin(station_idx, hand if hand is not None else []),
            np.isin(station_idx, best_effort if best_effort is not None else []),
            np.isin(station_idx, r.cover),
            np.isin(station_idx, r.added),
        ],
        ["hand", "best-effort", "cover", "registration"],
        "link",
    )
    stations = pd.DataFrame(
        {
            "station_id": ids,
            "x": station_xy[:, 0],
            "y": station_xy[:, 1],
            "instrument_height_m": st.instrument_height_m,
            "purpose": purpose,
            "samples_met": assignment.met_by_station,
        }
    )
    ties = net.ties if net is not None else []
    setups = traverse_setups(ties, st)
    if len(setups):
        stations = pd.concat([stations, setups], ignore_index=True)
    tc = net.candidates if net is not None else wb.tc  # with any planned control points
    targets, links = _targets_and_links(ctx, tc, net, ids, coverage)
    timings["coverage"] = time.perf_counter() - t
    say(0.97, "visiting order and field time")
    t = time.perf_counter()
    route = field_route(wb.site, wb.scanner, st, stations, targets, coverage, links)
    timings["route"] = time.perf_counter() - t
    if net is not None:
        messages.append(f"Registration: {net.message}.")
        messages.extend(_enclosed_messages(untied_places(ctx, net), ids))
        messages.extend(tie_messages(ties, ids, tc, st))
        messages.extend(_registration_messages(coverage, links, st))
    unmet = coverage[~coverage["meets"] & ~coverage["party_wall"]]
    if len(unmet):
        messages.extend(_unmet_messages(unmet))
    candidates = pd.DataFrame(
        {
            "x": grid[:, 0],
            "y": grid[:, 1],
            "samples_met": np.asarray(ev.ok[:, : wb.n_grid].sum(axis=0)).ravel(),
        }
    )
    solver = {
        **solver,
        "reach_m": wb.reach,
        "candidates": wb.n_grid,
        "samples": int((~wb.facades.party_wall).sum()),
        "pairs": wb.pairs,
    }
    messages.insert(0, f"Accuracy model: {st.model_description()}.")
    timings["total"] = time.perf_counter() - t0
    say(1.0, "plan ready")
    return Plan(
        site=wb.site,
        scanner=wb.scanner,
        requirements=wb.req,
        settings=st,
        stations=stations,
        targets=targets,
        coverage=coverage,
        facades=_facade_summary(wb.facades, coverage),
        zones=_zone_summary(wb.zones, coverage),
        links=links,
        candidates=candidates,
        network=net,
        route=route,
        solver=solver,
        messages=messages,
        timings_s=timings,
        workbench=wb,
    )


#: How many times stations are added or chosen again for the registration error (each time
#: the network is built and judged again) …
MAX_REGISTRATION_ROUNDS = 4
#: … of which rounds of adding before the fewest are chosen again.
ADD_ROUNDS = 2


@dataclass
class _Judged:
    """A round's stations judged on the total error against the client's limits."""

    assignment: Assignment
    n_met: int
    n_stations: int
    short_by_registration: np.ndarray  # (N,) met by the scanner's error alone, not the total

    def better_than(self, other: _Judged) -> bool:
        """More samples met; as many with fewer stations."""
        return (self.n_met, -self.n_stations) > (other.n_met, -other.n_stations)


@dataclass
class _Round:
    """Stations tried: those the optimiser chose (``cover``), those added for the
    registration error (``added``), their network and its judgement."""

    cover: np.ndarray
    added: np.ndarray = field(default_factory=lambda: np.empty(0, dtype=np.int64))
    net: Network | None = None
    judged: _Judged | None = None


def _choose(
    ctx: Context,
    cand: np.ndarray,
    say: Progress,
    deadline: float,
    timings: dict[str, float],
    estimate: Registration | None = None,
    forced: np.ndarray | None = None,
    scanner_ok: sp.csr_matrix | None = None,
) -> tuple[CandidateEvaluation, CoverSolution]:
    """Evaluate every candidate (:func:`_evaluate`) and choose the fewest stations
    (:func:`_optimise`)."""
    ev = _evaluate(ctx, cand, say, deadline, timings, estimate)
    return ev, _optimise(ctx, cand, ev, say, deadline, timings, forced, scanner_ok)


def _evaluate(
    ctx: Context,
    cand: np.ndarray,
    say: Progress,
    deadline: float,
    timings: dict[str, float],
    estimate: Registration | None = None,
) -> CandidateEvaluation:
    """Every candidate against every sample on the scanner's error (plus the ``estimate`` of
    its registration error), until ``deadline``."""
    t = time.perf_counter()
    ev = evaluate_candidates(
        ctx,
        cand,
        progress=lambda f, m: say(0.05 + 0.6 * f, m),
        deadline=deadline,
        registration=estimate,
    )
    timings["evaluate"] = timings.get("evaluate", 0.0) + time.perf_counter() - t
    return ev


def _optimise(
    ctx: Context,
    cand: np.ndarray,
    ev: CandidateEvaluation,
    say: Progress,
    deadline: float,
    timings: dict[str, float],
    forced: np.ndarray | None = None,
    scanner_ok: sp.csr_matrix | None = None,
) -> CoverSolution:
    """The fewest stations meeting the evaluation ``ev`` (with the redundant views spread);
    the ``forced`` candidates are taken and the fewest others added to them. A sample the
    evaluation leaves fewer candidates than the ``scanner_ok`` (the evaluation on the
    scanner's error alone) would give it is covered on ``scanner_ok``: by stations it is
    met from by the scanner's error, where the exact network may still meet it — not by
    whichever station happens to be nearest."""
    fac, req, st = ctx.facades, ctx.req, ctx.settings
    say(0.7, "choosing the fewest stations")
    t = time.perf_counter()
    ok = ev.ok
    n_ok = np.asarray(ok.sum(axis=1)).ravel()
    if scanner_ok is not None:
        n_scanner = np.asarray(scanner_ok.sum(axis=1)).ravel()
        lost = n_ok < np.minimum(ctx.stations_needed, n_scanner)
        if lost.any():
            mixed = ok.multiply(~lost[:, None]) + scanner_ok.multiply(lost[:, None])
            ok = sp.csr_matrix(mixed > 0)
            n_ok = np.where(lost, n_scanner, n_ok)
    demand = cover_demand(ctx, n_ok)
    remaining = _solver_time(ctx, deadline)
    if forced is None or not len(forced):
        sol = solve_cover(ok, demand, remaining, st.method)
    else:  # the others for what the forced stations leave
        free = np.ones(len(cand))
        free[forced] = 0.0
        left = np.maximum(0, demand - np.asarray(ok[:, forced].sum(axis=1)).ravel())
        sol = solve_cover(sp.csr_matrix((ok @ sp.diags(free)) > 0), left, remaining, st.method)
        sol.chosen = np.union1d(sol.chosen, forced)
        sol.objective = len(sol.chosen)
    if (ctx.stations_needed > 1).any():
        spread = spread_views(ok, demand, sol.chosen, cand, fac.xy, req.min_view_angle_deg)
        if len(spread) > len(sol.chosen):  # the bound still holds; the gap is the spread's
            sol.status += f"; {len(spread) - len(sol.chosen)} added for separate views"
            sol.chosen, sol.objective = spread, len(spread)
            sol.gap = (sol.objective - sol.lower_bound) / sol.objective
    timings["optimise"] = timings.get("optimise", 0.0) + time.perf_counter() - t
    return sol


def _solver_time(ctx: Context, deadline: float) -> float:
    """The optimiser's time limit [s]: what is left of the plan's budget, or its
    :data:`SOLVER_SHARE` when the registration network is still to be built and judged;
    never under :data:`MIN_SOLVER_S`."""
    share = SOLVER_SHARE if ctx.settings.computes_registration else 1.0
    return max(MIN_SOLVER_S, share * (deadline - time.monotonic()))


def cover_demand(ctx: Context, n_ok: np.ndarray) -> np.ndarray:
    """How many of the chosen stations each sample needs, given how many candidates meet it
    (``n_ok``): the stations its requirement asks for, at most as many as meet it; none on a
    party wall."""
    return np.where(ctx.facades.party_wall, 0, np.minimum(ctx.stations_needed, n_ok))


def _network(
    ctx: Context,
    cand: np.ndarray,
    seen: SightCache,
    chosen: np.ndarray,
    timings: dict[str, float],
    deadline: float = math.inf,
    datum: int | None = None,
) -> Network | None:
    """The registration network of the stations ``chosen`` (candidate indices), each
    probed at the facade points it serves best by the scanner's error; after ``deadline``
    without looking for linking stations."""
    if not len(chosen):
        return None
    t = time.perf_counter()
    fac = ctx.facades
    scanner_only = assign_stations(ctx, cand[chosen])
    pts = np.column_stack([fac.xy, fac.z])
    probes = {j: pts[scanner_only.station == j] for j in range(len(chosen))}
    tightest = _tightest_mm(ctx)
    net = build_network(
        ctx,
        seen.tc,
        cand,
        np.asarray(chosen, dtype=np.int64),
        probes,
        goal_mm=REGISTRATION_GOAL * tightest,
        weak_mm=WEAK_LINK * tightest,
        cache=seen,
        datum=datum,
        deadline=deadline,
    )
    if not net.tied.all() and net.tied.any():  # groups no target reaches: planned control
        net = tie_groups(ctx, cand, seen, net, REGISTRATION_GOAL * tightest, deadline)
    timings["registration"] = timings.get("registration", 0.0) + time.perf_counter() - t
    if net.datum is not None and seen.tc.is_control.any() and not net.ties:
        # control points given but no station sees three of them: a station that does,
        # nearest the others, ties the network to the site's control (else it is said)
        tie = _control_station(seen, cand, chosen)
        if tie is not None and tie not in chosen:
            return _network(ctx, cand, seen, np.append(chosen, tie), timings, deadline)
    return net


#: Candidates looked at for a station that sees the control points (the nearest to them).
CONTROL_POOL = 400


def _control_station(seen: SightCache, cand: np.ndarray, chosen: np.ndarray) -> int | None:
    """The candidate seeing at least three control points that stands nearest the chosen
    stations (None if no candidate near the control points sees three)."""
    ctl = seen.tc.xyz[seen.tc.is_control, :2]
    near = np.min(np.linalg.norm(cand[:, None, :] - ctl[None], axis=2), axis=1)
    pool = np.argsort(near)[:CONTROL_POOL]
    usable = seen(pool).usable[seen.tc.is_control]
    sees = pool[usable.sum(axis=0) >= 3]
    if not len(sees):
        return None
    gap = np.min(np.linalg.norm(cand[sees, None, :] - cand[chosen][None], axis=2), axis=1)
    return int(sees[np.argmin(gap)])


def _prune(
    ctx: Context,
    cand: np.ndarray,
    seen: SightCache,
    r: _Round,
    deadline: float,
    timings: dict[str, float],
    keep: np.ndarray | None = None,
) -> _Round:
    """Drop stations the final judgement gives no sample and no other station is registered
    to (chosen for an estimate the exact network did not bear out), one at a time, each kept
    out only if no sample is lost; the ``keep`` candidates (locked by hand) are never dropped."""
    keep = np.empty(0, dtype=np.int64) if keep is None else keep
    while time.monotonic() < deadline:
        served = np.bincount(
            r.judged.assignment.station[r.judged.assignment.station >= 0],
            minlength=len(r.net.stations),
        )
        parents = {lk.parent for lk in r.net.links}
        idle = [
            k
            for k in np.flatnonzero(served == 0)
            if k not in parents and r.net.stations[k] not in keep
        ]
        for k in idle:
            chosen = np.delete(r.net.stations, k)
            trial = _Round(cover=np.setdiff1d(r.cover, r.net.stations[k]), added=r.added)
            trial.net = _network(ctx, cand, seen, chosen, timings, deadline, r.net.datum_station)
            if trial.net is None:
                continue
            trial.judged = _judge(ctx, cand, trial)
            if trial.judged.n_met >= r.judged.n_met:
                r = trial
                break
        else:
            return r
    return r


def _stations_for(
    ctx: Context,
    cand: np.ndarray,
    net: Network,
    short: np.ndarray,
    deadline: float,
    timings: dict[str, float],
) -> np.ndarray:
    """Candidates to add so that the ``short`` samples meet the total: each candidate judged
    with the registration error it would have in ``net`` (:meth:`Network.estimate`), the
    one meeting the most short samples first (greedy), until all are met or none helps."""
    t = time.perf_counter()
    estimate = _estimate(ctx, net, cand)
    if estimate is None:
        return np.empty(0, dtype=np.int64)
    ev = evaluate_candidates(ctx, cand, deadline=deadline, registration=estimate, only=short)
    keep = np.ones(len(cand))
    keep[net.stations] = 0.0  # the network's own stations do not meet them already
    ok = sp.csr_matrix((ev.ok[np.flatnonzero(short)] @ sp.diags(keep)) > 0)
    demand = np.minimum(1, np.asarray(ok.sum(axis=1)).ravel())
    sol = solve_cover(ok, demand, 0.0, "greedy")
    timings["evaluate"] += time.perf_counter() - t
    return np.asarray(sol.chosen, dtype=np.int64)


def _datum_station(ctx: Context, cand: np.ndarray, r: _Round) -> int | None:
    """A new station for the datum, where the lean of the datum's levelling (a scanner
    without a compensator, :func:`planner.registration_error.datum_tilt_cov`) keeps many
    samples short in m_z (:data:`DATUM_SHARE`): the candidate (where a tied station's
    ground reaches) with which the fewest samples stay short — each judged on its m_z with
    the lean about that candidate in place of the present datum's, the rest of its
    registration error kept — if fewer than now; else None. The network's layout then
    chooses its datum with the new station among the others."""
    net = r.net
    lean_at = net.leaning_datum(ctx.scanner) if net is not None else None
    if lean_at is None:
        return None
    a = r.judged.assignment
    tau = ctx.scanner.initial_tilt_rms_arcsec
    xy = ctx.facades.xy
    has = (a.station >= 0) & ~ctx.facades.party_wall & np.isfinite(a.metrics["m_z_mm"])
    if not has.any():
        return None
    xy = xy[has]
    lean_now = datum_lean_mm(np.hypot(*(xy - lean_at[:2]).T), tau)
    rest = np.square(a.metrics["m_z_mm"][has]) - np.square(lean_now)  # all but the lean
    budget = np.square(ctx.limits["m_z"][has]) - rest
    per_m2 = float(datum_lean_mm(1.0, tau)) ** 2

    def short(at: np.ndarray) -> np.ndarray:  # samples short with the datum at each of at
        far2 = ((xy[None, :, :] - at[:, None, :]) ** 2).sum(axis=2)
        return (per_m2 * far2 > budget[None, :] * (1 + 1e-9)).sum(axis=1)

    now = int(short(lean_at[None, :2])[0])
    if now <= DATUM_SHARE * has.sum():  # a few: stations added near them serve better
        return None
    region = ctx.regions.label(cand)
    tied = np.unique(region[net.stations[net.tied]])
    pool = np.flatnonzero(np.isin(region, tied[tied >= 0]))
    pool = np.setdiff1d(pool, net.stations)
    pool = pool[:: max(1, len(pool) // DATUM_POOL)]  # an even thinning of the grid
    if not len(pool):
        return None
    counts = np.concatenate([short(cand[pool[k : k + 256]]) for k in range(0, len(pool), 256)])
    best = int(np.argmin(counts))
    return int(pool[best]) if counts[best] < now else None


#: The datum station is looked for among at most about this many candidates.
DATUM_POOL = 2000
#: A datum station is tried where the lean keeps more than this share of the samples short
#: (the default site's plan: 1 %, better served by stations added near them; a ten-building
#: block: 35 %, met by one datum station in the middle), and kept where it meets more than
#: this share more.
DATUM_SHARE = 0.05


def _estimate(ctx: Context, net: Network, cand: np.ndarray) -> Registration | None:
    """The registration error every candidate would have in ``net``
    (:meth:`Network.estimate`), none for a candidate that could not be tied: one standing
    in open ground no tied station stands in (a closed courtyard) — no station is chosen
    for the registration error where it cannot be tied."""
    est = net.estimate(cand, ctx.settings.instrument_height_m)
    if est is None:
        return None
    region = ctx.regions.label(cand)
    tied_regions = np.unique(region[net.stations[net.tied]])
    est.tied = est.tied & np.isin(region, tied_regions[tied_regions >= 0])
    return est


#: A link's own error is brought below this share of the tightest limit (where targets can):
#: in quadrature it then adds under 5 % to an error at the limit.
REGISTRATION_GOAL = 0.3
#: A link whose own error exceeds this share of the tightest limit is too weak: linking
#: stations are sought to make a detour round it (kept where the worst error drops).
WEAK_LINK = 0.5


def _judge(ctx: Context, cand: np.ndarray, r: _Round) -> _Judged:
    """Assign every sample its station and judge it on the total error (scanner ⊕
    registration); which samples only the registration keeps from meeting the limits."""
    fac, st = ctx.facades, ctx.settings
    n = len(fac.z)
    if r.net is None:
        a = assign_stations(ctx, np.empty((0, 2)))
        return _Judged(a, 0, 0, np.zeros(n, dtype=bool))
    station_xy = cand[r.net.stations]
    registration = None
    if st.computes_registration:
        registration = r.net.registration()
    a = assign_stations(ctx, station_xy, registration)
    demanded = ~fac.party_wall
    met = (a.n_meeting >= ctx.stations_needed) & demanded
    scanner_ok = np.ones(n, dtype=bool)
    for c in "xyz":
        v = a.metrics[f"scanner_m_{c}_mm"]
        scanner_ok &= np.isfinite(v) & (v <= ctx.limits[f"m_{c}"] * (1 + 1e-9))
    return _Judged(a, int(met.sum()), len(station_xy), demanded & ~met & scanner_ok)


def budget_message(time_limit_s: float, cut: list[str]) -> str:
    """What the time budget cut short, as the plan says it."""
    return (
        f"Time budget: the {time_limit_s:g} s ran out; cut short: {'; '.join(cut)}. The plan "
        "is the best found in the time; raise --time-limit-s for the whole of it."
    )


def _expect(value: object, kind: type, name: str, hint: str) -> None:
    """The Python API's boundary: a wrong type is an InputError saying what to pass."""
    if value is not None and not isinstance(value, kind):
        raise InputError(
            f"{name} must be a planner.{kind.__name__} ({hint}); got {type(value).__name__}"
            + (f" {value!r}"[:80] if isinstance(value, str | Path) else "")
        )


def _reason(
    ctx: Context, sample: int, n_view: int, best: dict[str, float], n_meet: int, roof: str = ""
) -> str:
    """Why no station meets ``sample``, in words: each check the best candidate fails; where
    the ground cannot reach it, that it needs an elevated station (on ``roof``'s roof)."""
    if n_view == 0 and roof:
        return (
            f"no ground station sees it over the roof of {roof!r}: it needs an elevated "
            "station (e.g. on that roof)"
        )
    if n_view == 0:
        return "no ground station sees it: it needs an elevated station (a lift or a mast)"
    why = _unmet_checks(ctx, sample, best, n_meet)
    if roof:
        return (
            f"{why} from the ground, seen only over the roof of {roof!r}: it needs an "
            "elevated station (e.g. on that roof)"
        )
    return why


def _unmet_checks(ctx: Context, sample: int, best: dict[str, float], n_meet: int) -> str:
    """Each check the best candidate fails at ``sample``, in words."""
    k = int(ctx.stations_needed[sample])
    if 0 < n_meet < k:
        return f"only {n_meet} station position(s) meet every requirement here; {k} required"
    parts = []
    for c in CHECKS:
        limit = float(ctx.limits[c.key][sample])
        if np.isfinite(limit) and not c.passes(np.float64(best[c.key]), limit):
            parts.append(c.shortfall(best[c.key], limit))
    if parts:
        return "; ".join(parts)
    if best["score"] <= 1.0 and ctx.settings.computes_registration:
        return (
            "the registration error leaves too little: the best station meets it by the "
            f"scanner's error alone ({best['score']:.2f} × the limits), none with the "
            "registration error of the network added"
        )
    each = [
        f"{c.label} {best[c.key]:.1f} {c.unit} (limit {float(ctx.limits[c.key][sample]):g})"
        for c in CHECKS[:3]
        if np.isfinite(ctx.limits[c.key][sample])
    ]
    return (
        "no single station meets every requirement at once: each alone is achievable (best "
        + ", ".join(each)
        + f"), together at best {best['score']:.2f} × the limits"
    )


def _coverage(
    ctx: Context,
    ev: CandidateEvaluation,
    diagnosis: Diagnosis,
    assignment: Assignment,
    ids: list[str],
    net: Network | None = None,
    zone_ids: np.ndarray | None = None,
    class_family: str | None = None,
) -> pd.DataFrame:
    """One row per sample: its station, the metrics there, whether it meets its
    requirement, and why not."""
    fac = ctx.facades
    ctx_zone_ids = zone_ids if zone_ids is not None else np.full(len(fac.z), "", dtype=object)
    n = len(fac.z)
    k_req = ctx.stations_needed
    n_ok_cand = np.asarray(ev.ok.sum(axis=1)).ravel()
    picked, n_meeting = assignment.metrics, assignment.n_meeting
    names = np.array([*ids, ""], dtype=object)
    station = names[assignment.station]  # -1 picks the "" at the end
    demanded = ~fac.party_wall
    meets = (n_meeting >= k_req) & demanded
    reason = np.full(n, "", dtype=object)
    candidates_meet = ~meets & demanded & (n_ok_cand >= k_req)
    untied = np.zeros(n, dtype=bool)
    places = untied_places(ctx, net)
    if net is not None and net.error is not None and len(ids) > 1:
        has = assignment.station >= 0
        untied[has] = ~net.error.tied[assignment.station[has]]
    lean_at = net.leaning_datum(ctx.scanner) if net is not None else None
    datum = None if lean_at is None else (ids[net.datum], lean_at[:2])
    for i in np.flatnonzero(candidates_meet):
        place = places.get(int(assignment.station[i]), "") if untied[i] else ""
        reason[i] = _short_reason(
            ctx, i, picked, station[i], untied[i], n_meeting[i], k_req[i], place, datum
        )
    elevated = np.full(n, "", dtype=object)
    for i in np.flatnonzero(~meets & demanded & (n_ok_cand < k_req) & ev.evaluated):
        found = diagnosis.at(int(i))
        if found is None:
            reason[i] = "no station meets it (not diagnosed further: the time limit ran out)"
            continue
        n_view, best, roof = found
        reason[i] = _reason(ctx, int(i), n_view, best, int(n_ok_cand[i]), roof)
        if n_view == 0 or roof:
            elevated[i] = f"roof of {roof}" if roof else "above the ground"
    reason[~meets & demanded & ~ev.evaluated] = "not evaluated: the time budget ran out"
    reason[fac.party_wall] = "party wall (against a neighbour): not scanned"
    extra = {}
    if class_family:  # the class each sample achieves, beside pass/fail
        from planner.classes import achieved_class

        extra["class_achieved"] = achieved_class(
            picked["m_x_mm"], picked["m_y_mm"], picked["m_z_mm"], class_family
        )
    shown = [k for k in METRIC_KEYS if k != "spacing_mm" and not k.startswith(("scanner", "reg"))]
    return pd.DataFrame(
        {
            "building_id": fac.building_id[fac.facade],
            "facade_id": fac.facade_id[fac.facade],
            "sample_id": fac.sample_id,
            "x": fac.xy[:, 0],
            "y": fac.xy[:, 1],
            "z": fac.z,
            "station_id": station,
            **{k: picked[k] for k in shown},
            "meets": meets,
            "model": ctx.settings.model,
            **{k: picked[k] for k in METRIC_KEYS if k.startswith(("scanner", "reg"))},
            "spacing_mm": picked["spacing_mm"],
            "stations_meeting": n_meeting,
            "party_wall": fac.party_wall,
            "reason": reason,
            "elevated_station": elevated,
            "zone": ctx_zone_ids,
            **extra,
        }
    )


def _short_reason(
    ctx: Context,
    i: int,
    picked: dict[str, np.ndarray],
    station: str,
    untied: bool,
    n_meeting: int,
    k_req: int,
    place: str = "",
    datum: tuple[str, np.ndarray] | None = None,
) -> str:
    """Why a sample some candidate could meet is not met by the chosen stations (``place``:
    where an untied station stands, :func:`untied_places`; ``datum``: the datum station's id
    and position, whose levelling leans the network of a scanner without a compensator)."""
    if untied and place:
        return (
            f"its station {station} stands in {place}, which no registration reaches: "
            f"{ENCLOSED_FIX}"
        )
    if untied:
        return f"its station {station} cannot be tied to the registration network"
    worst = None
    for c in "xyz":
        total, scanner = picked[f"m_{c}_mm"][i], picked[f"scanner_m_{c}_mm"][i]
        reg = picked[f"reg_m_{c}_mm"][i]
        limit = float(ctx.limits[f"m_{c}"][i])
        if np.isfinite(limit) and scanner <= limit < total and np.isfinite(reg):
            if worst is None or total / limit > worst[0]:
                worst = (total / limit, c, scanner, reg, total, limit)
    if worst is not None:
        _, c, scanner, reg, total, limit = worst
        text = (
            f"the registration error takes it over: m_{c} {scanner:.1f} mm from the scanner "
            f"⊕ {reg:.1f} mm registration (station {station}) = {total:.1f} mm > {limit:g} mm"
        )
        if datum is not None and c == "z":
            far = float(np.hypot(*(ctx.facades.xy[i] - datum[1])))
            m_nu0 = ctx.scanner.initial_tilt_rms_arcsec
            lean = float(datum_lean_mm(far, m_nu0))
            if lean >= 0.5 * reg:
                text += (
                    f"; {lean:.1f} mm of it is the levelling of the datum {datum[0]} "
                    f"({m_nu0:g}″ at {far:.0f} m): {DATUM_LEVELLING_FIX}"
                )
        return text
    if k_req > 1:
        return (
            f"the chosen stations give {n_meeting} of the {k_req} views required (views "
            f"{ctx.req.min_view_angle_deg:g}° apart in direction)"
        )
    return "the chosen stations do not cover this sample"


#: What keeps heights true far from the datum of a scanner without a compensator.
DATUM_LEVELLING_FIX = (
    "level that scan better (a scanner with a compensator: its levelling figure in the "
    "profile, levelling_rms_arcsec) or tie the heights to control points (--control)"
)

#: What ties a closed courtyard's stations to the others.
ENCLOSED_FIX = (
    "mark its gateway (a feature with role passage, or OpenStreetMap's "
    "tunnel=building_passage) or give control points (--control)"
)


def untied_places(ctx: Context, net: Network | None) -> dict[int, str]:
    """Where the stations not tied to the network stand, in words, by their position in
    ``net``: "the courtyard enclosed by A, B, C" for a closed courtyard (open ground no
    other station's region reaches, :class:`~planner.pipeline.candidates.GroundRegions`)."""
    if net is None or net.error is None or len(net.stations) <= 1:
        return {}
    untied = np.flatnonzero(~net.error.tied)
    out = {}
    for k, r in zip(untied, ctx.regions.label(net.station_xyz[untied, :2]), strict=True):
        if ctx.regions.enclosed(int(r)):
            blds = ctx.regions.enclosing(int(r))
            more = f" and {len(blds) - 6} more" if len(blds) > 6 else ""
            out[int(k)] = f"the courtyard enclosed by {', '.join(blds[:6])}{more}"
    return out


def _enclosed_messages(places: dict[int, str], ids: list[str]) -> list[str]:
    """One line per closed courtyard whose stations cannot be tied."""
    by_place: dict[str, list[str]] = {}
    for k, place in places.items():
        by_place.setdefault(place, []).append(ids[k])
    return [
        f"Registration: {place[0].upper()}{place[1:]} (station(s) {', '.join(sorted(st))}) "
        f"cannot be tied to the others — no station outside sees its targets: {ENCLOSED_FIX}. "
        "No station is added there for the registration error."
        for place, st in by_place.items()
    ]


def _tightest_mm(ctx: Context) -> float:
    """The tightest accuracy limit of any sample [mm]."""
    lims = np.concatenate([ctx.limits[k] for k in ("m_x", "m_y", "m_z")])
    lims = lims[np.isfinite(lims)]
    return float(lims.min()) if len(lims) else 5.0


def _class_family(req: Requirements, zones: ZoneTable) -> str | None:
    """The family of the accuracy class asked for (site-wide or in a zone), if any."""
    from planner.classes import parse_class

    for r in [req, *zones.requirements]:
        if r.accuracy_class:
            return parse_class(r.accuracy_class)[0].family
    return None


def _zone_summary(zones: ZoneTable, cov: pd.DataFrame) -> pd.DataFrame:
    """Each zone: where, its requirement, its sampling, and whether it is met."""
    rows = []
    for z, r, mask in zip(zones.zones, zones.requirements, zones.masks, strict=True):
        scanned = mask & ~cov["party_wall"].to_numpy()
        met = int(cov["meets"].to_numpy()[scanned].sum())
        rows.append(
            {
                "zone_id": z.id,
                "where": z.describe(),
                "requirement": r.describe(),
                "sample_spacing_m": z.sample_spacing_m,
                "samples": int(scanned.sum()),
                "met": met,
                "unmet": int(scanned.sum()) - met,
            }
        )
    return pd.DataFrame(rows, columns=ZONE_COLUMNS)


def _facade_summary(fac: FacadeSet, cov: pd.DataFrame) -> pd.DataFrame:
    scanned = cov[~cov["party_wall"]]
    by = scanned.groupby("facade_id", sort=False)
    stats = pd.DataFrame(
        {
            "met": by["meets"].sum(),
            "unmet": by["meets"].size() - by["meets"].sum(),
            "worst_m_x_mm": by["m_x_mm"].max(),
            "worst_m_y_mm": by["m_y_mm"].max(),
            "worst_m_z_mm": by["m_z_mm"].max(),
            "stations": by["station_id"].agg(lambda s: ";".join(sorted(v for v in set(s) if v))),
        }
    )
    zones_on = cov.groupby("facade_id", sort=False)["zone"].agg(
        lambda s: ";".join(sorted({z for v in s if v for z in v.split(";")}))
    )
    allby = cov.groupby("facade_id", sort=False)
    out = pd.DataFrame(
        {
            "building_id": fac.building_id,
            "facade_id": fac.facade_id,
            "x0": fac.start[:, 0],
            "y0": fac.start[:, 1],
            "x1": fac.end[:, 0],
            "y1": fac.end[:, 1],
            "length_m": fac.length_m,
            "height_m": fac.height_m,
            "courtyard": fac.courtyard.astype(bool),
        }
    )
    out["samples"] = out["facade_id"].map(allby.size()).fillna(0).astype(int)
    out["party_wall_samples"] = (
        out["facade_id"].map(allby["party_wall"].sum()).fillna(0).astype(int)
    )
    stats = stats.reindex(out["facade_id"])
    for col in ("met", "unmet"):
        out[col] = stats[col].fillna(0).astype(int).to_numpy()
    for col in ("worst_m_x_mm", "worst_m_y_mm", "worst_m_z_mm"):
        out[col] = stats[col].to_numpy(dtype=float)
    out["stations"] = stats["stations"].fillna("").to_numpy(dtype=object)
    out["zones"] = out["facade_id"].map(zones_on).fillna("").to_numpy(dtype=object)
    return out


def _targets_and_links(
    ctx: Context,
    tc: TargetCandidates,
    net: Network | None,
    ids: list[str],
    coverage: pd.DataFrame,
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """The target list (where, which type, how big and by which rule, which stations use
    it) and the per-link report (targets in common, placed, the link's own predicted error
    and the registration error the child station ends with)."""
    if net is None or not len(ids):
        return pd.DataFrame(columns=TARGET_COLUMNS), pd.DataFrame(columns=LINK_COLUMNS)
    fac, st = ctx.facades, ctx.settings
    sight = net.sight
    users: dict[int, set[int]] = {}
    for lk in net.links:
        for t in lk.targets:
            users.setdefault(t, set()).add(lk.child)
            if lk.parent != CONTROL:
                users[t].add(lk.parent)
    rows = []
    tid: dict[int, str] = {}
    for t in net.targets:
        who = sorted(users.get(t, ()))
        control = tc.type[t] == "control"
        if control:
            size, item = float("nan"), ""
            seen_by = np.array(who, dtype=int)
        else:
            need_users = sight.need_mm[t, who]
            chosen = choose_target(float(need_users.max()), tc.type[t], st.inventory)
            size = chosen.size_mm if chosen else float("nan")
            item = chosen.name if chosen else ""
            seen_by = np.flatnonzero(sight.usable[t] & (sight.need_mm[t] <= size))
        far = who[int(np.argmax(sight.need_mm[t, who]))] if who else 0
        f = int(tc.facade[t])
        nx, ny = tc.normal[t]
        label = (
            tc.control_id[t]
            if control
            else f"T{len([x for x in tid.values() if x.startswith('T')]) + 1:02d}"
        )
        tid[t] = label
        rows.append(
            {
                "target_id": label,
                "x": tc.xyz[t, 0],
                "y": tc.xyz[t, 1],
                "z": tc.xyz[t, 2],
                "type": tc.type[t],
                "min_size_mm": float(sight.need_mm[t, seen_by].max()) if len(seen_by) else np.nan,
                "size_mm": size,
                "sized_by": sight.rule[t, far],
                "station_ids": [ids[s] for s in seen_by],
                "item": item,
                "facade_id": fac.facade_id[f] if f >= 0 else "",
                # which way a wall target faces: azimuth of its normal, clockwise from grid north
                "facing_deg": float(np.degrees(np.arctan2(nx, ny)) % 360.0) if f >= 0 else np.nan,
                "centre_rms_mm": max(
                    (net.centre_rms.get((j, t), np.nan) for j in who), default=np.nan
                ),
            }
        )
    targets = pd.DataFrame(rows, columns=TARGET_COLUMNS)
    worst_at = coverage.groupby("station_id")[["reg_m_x_mm", "reg_m_y_mm", "reg_m_z_mm"]].max()
    links = pd.DataFrame(
        [
            {
                "station_a": "control" if lk.parent == CONTROL else ids[lk.parent],
                "station_b": ids[lk.child],
                "common_targets": _common_count(net, tc, lk),
                "targets_placed": len(lk.targets),
                "target_ids": ";".join(tid[t] for t in lk.targets),
                "link_rms_mm": net.link_error_mm.get((lk.parent, lk.child), np.nan),
                "dilution": net.link_error_mm.get((lk.parent, lk.child), np.nan)
                / net.link_sigma_mm.get((lk.parent, lk.child), np.nan),
                "station_b_rms_mm": float(worst_at.loc[ids[lk.child]].max())
                if ids[lk.child] in worst_at.index
                else np.nan,
                **_link_kind(net, lk),
            }
            for lk in net.links
        ],
        columns=LINK_COLUMNS,
    )
    return targets, links


def _link_kind(net: Network, lk: Link) -> dict:
    """How a link registers (targets or cloud), the overlap of its two scans [%] (where the
    surfaces were modelled) and the direction its own error is largest in."""
    ov = net.overlap
    overlap = float(ov[lk.parent, lk.child]) if ov is not None and lk.parent != CONTROL else np.nan
    return {
        "kind": lk.kind,
        "overlap_pct": overlap,
        "weakest_direction": net.weakest.get((lk.parent, lk.child), ""),
    }


def _common_count(net: Network, tc: TargetCandidates, lk: Link) -> int:
    usable = net.sight.usable
    if lk.parent == CONTROL:
        return int((usable[:, lk.child] & tc.is_control).sum())
    return int((usable[:, lk.parent] & usable[:, lk.child] & ~tc.is_control).sum())


#: What the predicted registration error assumes of the registration software, per
#: ``registration_processing`` (said in the summary, the report and the booklet through the
#: summary's message).
PROCESSING_WORDS = {
    "adjustment": f"It assumes {REGISTRATION_PROCESSING['adjustment']}; registered pair by "
    "pair along the links instead, the errors add up along the chain and can exceed it (plan "
    "for that with --registration-processing pairwise).",
    "pairwise": f"It assumes {REGISTRATION_PROCESSING['pairwise']}: the errors add up along "
    "the chain; one adjustment of every scan's targets and surfaces together does at least "
    "as well.",
}


def _registration_messages(
    coverage: pd.DataFrame, links: pd.DataFrame, st: PlanSettings
) -> list[str]:
    """The worst predicted registration error and where; the weakest link."""
    if not st.computes_registration:
        if st.station_rms_pair != (0.0, 0.0):
            return [f"Registration error: the fixed station RMS {st.station_rms_mm} mm (as given)."]
        return ["Registration error: not counted (--no-registration-error)."]
    cov = coverage[~coverage["party_wall"] & (coverage["station_id"] != "")]
    if cov.empty:
        return []
    parts = cov[["reg_m_x_mm", "reg_m_y_mm", "reg_m_z_mm"]]
    worst = parts.max(axis=1)
    if not np.isfinite(worst).any():
        return []
    i = worst.idxmax()
    row = cov.loc[i]
    out = [
        f"Registration error: worst {worst[i]:.1f} mm (m_{parts.loc[i].idxmax().split('_')[2]}) at "
        f"{row['sample_id']} scanned from {row['station_id']}; median {worst.median():.1f} mm. "
        + PROCESSING_WORDS[st.registration_processing]
    ]
    if len(links):
        weak = links.loc[links["link_rms_mm"].idxmax()]
        how = (
            f"cloud to cloud, {weak['overlap_pct']:.0f} % overlap"
            if weak["kind"] == "cloud"
            else f"{weak['targets_placed']} targets of {weak['common_targets']} in common"
        )
        dilution = f", dilution {weak['dilution']:.1f}" if weak["kind"] != "cloud" else ""
        out.append(
            f"Weakest link: {weak['station_a']} → {weak['station_b']}, {how}, "
            f"{weak['link_rms_mm']:.1f} mm on its own ({weak['weakest_direction']}{dilution})."
        )
    return out


#: Facades the summary lists with their unmet samples (the rest: coverage.csv).
UNMET_FACADES_SHOWN = 12


def _unmet_messages(unmet: pd.DataFrame) -> list[str]:
    """The unmet samples by facade, the most unmet first (at most
    :data:`UNMET_FACADES_SHOWN`), each with its most frequent reason."""
    out = [f"{len(unmet)} sample(s) do not meet the requirements:"]
    groups = sorted(
        unmet.groupby(["building_id", "facade_id"], sort=True), key=lambda kv: -len(kv[1])
    )
    for (bid, fid), g in groups[:UNMET_FACADES_SHOWN]:
        reasons = g["reason"].value_counts()
        out.append(
            f"  facade {fid} (building {bid}): {len(g)} sample(s), "
            f"z {g['z'].min():.1f}–{g['z'].max():.1f} m"
            f" — {reasons.index[0]}"
            + (f" (and {len(reasons) - 1} other reason(s))" if len(reasons) > 1 else "")
        )
    if len(groups) > UNMET_FACADES_SHOWN:
        rest = sum(len(g) for _, g in groups[UNMET_FACADES_SHOWN:])
        out.append(
            f"  … and {rest} sample(s) on {len(groups) - UNMET_FACADES_SHOWN} other facade(s) "
            "(coverage.csv)"
        )
    return out
