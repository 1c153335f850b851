"""The orchestrator: ``plan(site, scanner, requirements, settings) -> Plan``.

Steps: facades and samples → candidate stations → evaluation of every candidate × sample →
fewest stations (:mod:`~planner.pipeline.optimise.cover`) → registration network and targets
(:mod:`~planner.pipeline.network.registration`) → coverage by the chosen stations → per-facade
summary and unmet samples with the reason. The result type is
:class:`~planner.pipeline.engine.result.Plan`; its files are written by
:mod:`~planner.pipeline.documents.export`.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import numpy as np
import scipy.sparse as sp
import shapely

from planner.citymodel import LEVEL_ROOF_DEG, level_roof
from planner.errors import InputError
from planner.pipeline.engine.conditions import condition_words
from planner.pipeline.engine.ids import GivenIds, id_number
from planner.pipeline.engine.judge import (
    Round,
    Workbench,
    assemble,
    blocked_at,
    datum_round,
    estimate_registration,
    free_positions,
    judge,
    merge_close_stations,
    prune,
    round_network,
    stations_for,
    what_blocks,
)
from planner.pipeline.engine.kit import within_kit
from planner.pipeline.engine.levelrun import level_run, say_level_run, with_level_run
from planner.pipeline.engine.result import Plan, SolverReport
from planner.pipeline.engine.tables import budget_message, rehearsal_message
from planner.pipeline.evaluation.diagnosis import Diagnosis, diagnose
from planner.pipeline.evaluation.evaluate import (
    CandidateEvaluation,
    Context,
    Progress,
    Registration,
    evaluate_candidates,
)
from planner.pipeline.geometry.candidates import candidate_grid
from planner.pipeline.geometry.facades import (
    build_facades,
    check_sample_count,
    estimate_samples,
)
from planner.pipeline.geometry.scene import Scene
from planner.pipeline.geometry.zoning import apply_zones
from planner.pipeline.inputs.clock import Clock
from planner.pipeline.inputs.requirements import (
    CHECKS,
    PlanSettings,
    Requirements,
)
from planner.pipeline.inputs.resolved import expect, resolve
from planner.pipeline.network.targets import SightCache, target_candidates
from planner.pipeline.optimise.cover import CoverSolution, solve_cover, spread_views
from planner.pipeline.optimise.spacing import merge_close
from planner.scanner import DEFAULT_SCANNER, Scanner, load_scanner
from planner.site import Site
from planner.sitecheck import notes_summary

__all__ = ["choose_stations", "plan"]


#: Evaluation speed used to put a work estimate in minutes [pairs per second].
PAIRS_PER_S = 20e6
#: The optimiser's backstop (:mod:`planner.pipeline.optimise.cover`), in CPU seconds of
#: this process, is this share of ``time_limit_s`` for each search when the registration
#: network is still to be built and judged after it (else the whole) …
SOLVER_SHARE = 0.5
#: … and never under this, even where a plan inside a larger one (a district's block, a
#: job) has spent its part of the wall clock [s].
MIN_SOLVER_S = 0.5


def plan(
    site: Site | None = None,
    scanner: Scanner | str | None = None,
    requirements: Requirements | None = None,
    settings: PlanSettings | None = None,
    *,
    progress: Progress | None = None,
    locked: np.ndarray | None = None,
    deadline: float | None = None,
    given: GivenIds | None = None,
) -> Plan:
    """Plan the fewest stations meeting ``requirements`` around the planned buildings.

    Defaults: the built-in default site, the scanner of Voroshilov & Karachentsev's example
    (:data:`~planner.scanner.DEFAULT_SCANNER`), ``Requirements()`` and ``PlanSettings()``.
    ``locked`` — ``(k, 2)`` station positions [m] the surveyor fixed: they are kept, and the
    fewest others chosen around them. ``given`` — the ids of an earlier plan of the site
    (:meth:`GivenIds.of`): a station or target where one of its stood keeps that id, a new
    one takes a number it never gave. Infeasible requirements do not raise: the samples no
    candidate can satisfy come back with ``meets`` False and the reason (see
    :attr:`Plan.unmet`). The plan keeps what it was made from
    (:func:`~planner.pipeline.engine.judge.workbench_of`) for what-if edits
    (:mod:`planner.pipeline.engine.whatif`).

    This plans one job: :func:`planner.plan` (:func:`planner.pipeline.district.groups.plan`)
    plans buildings in groups far apart as separate jobs, each by this function.

    The plan is decided by work, not by the clock (:mod:`planner.pipeline.inputs.clock`):
    the same inputs give the same plan on any machine, however loaded. Only the optimiser's
    search for a smaller cover has a backstop, in this process's CPU seconds (a share of the
    settings' ``time_limit_s``), for problems too large for its work bounds; the messages
    then say so (``solver.cut_short``). ``deadline`` (a :func:`time.monotonic` time) is for
    a plan inside a larger schedule (a district's block): it caps that backstop too, and so
    makes the plan depend on the clock.
    """
    t0 = time.perf_counter()
    site, sc, req, st = plan_inputs(site, scanner, requirements, settings)
    clock = Clock(end=math.inf if deadline is None else deadline, started=t0)
    wb = _prepare(site, sc, req, st, progress or (lambda _f, _m: None))
    return choose_stations(wb, progress, locked=locked, clock=clock, given=given)


def plan_inputs(
    site: Site | None,
    scanner: Scanner | str | None,
    requirements: Requirements | None,
    settings: PlanSettings | None,
) -> tuple[Site, Scanner, Requirements, PlanSettings]:
    """A plan's inputs checked (a wrong type refused with what to pass) and defaulted: the
    built-in default site, the paper's scanner, ``Requirements()``, ``PlanSettings()``."""
    from planner.siteio import default_site

    expect(site, Site, "site", "read one with planner.read_site(path) or planner.default_site()")
    expect(requirements, Requirements, "requirements", "e.g. Requirements(max_xy_mm=4)")
    expect(settings, PlanSettings, "settings", "e.g. PlanSettings(grid_m=2)")
    if scanner is not None and not isinstance(scanner, Scanner | str | Path):
        raise InputError(
            f"scanner must be a Scanner, a catalogue name or a profile file; got "
            f"{type(scanner).__name__}"
        )
    return (
        site or default_site(),
        load_scanner(scanner or DEFAULT_SCANNER),
        requirements or Requirements(),
        settings or PlanSettings(),
    )


def _prepare(
    site: Site, sc: Scanner, req: Requirements, st: PlanSettings, say: Progress
) -> Workbench:
    """Samples, zones, search radius, candidate grid, target candidates (refusing work beyond
    the settings' limits with what to change)."""
    t0 = time.perf_counter()
    messages = [*site.warnings, *notes_summary(site.notes)]
    say(0.0, "sampling facades")
    n_est = estimate_samples(site, st.sample_spacing_m, st.sample_height_step_m)
    check_sample_count(n_est, st.sample_spacing_m, st.sample_height_step_m, st.max_samples)
    scene = Scene(site, st.sight_engine)
    fac = build_facades(
        site, st.sample_spacing_m, st.sample_height_step_m, scene=scene, roofs=st.demand_roofs
    )
    fac, sample_req, zones = apply_zones(
        site, fac, req, scene, st.material_table, st.default_material
    )
    if st.demand_roofs:
        level = [s for b in site.planned for s in b.surfaces if level_roof(s)]
        if level:
            messages.append(
                f"Roofs demanded: {len(level)} level roof surface(s) (within "
                f"{LEVEL_ROOF_DEG:g}° of level) are not sampled — no station on the ground sees "
                "them; plan them from an elevated station or the air"
            )
    if len(fac.z) > st.max_samples:
        raise InputError(
            f"with the zones' finer samples the facades need {len(fac.z):,} samples, more than "
            f"{st.max_samples:,.0f}; use coarser zone spacings or raise the limit (--max-samples)"
        )
    messages += zones.messages
    # the search radius, preset and step: the farthest any requirement (the site-wide one, a
    # zone's) reaches, the strictest spacing any asks
    inputs = resolve(sc, req, st, zones.requirements)
    st, reach = inputs.settings, inputs.reach_m
    cand = candidate_grid(site, fac, reach, st.grid_m, st.clearance_m)
    ctx = Context.build(site, fac, sc, req, st, reach, sample_req, scene)
    pairs = ctx.pair_count(cand)
    if pairs > st.max_pairs:
        raise InputError(
            f"the plan would evaluate {pairs:.3g} station × sample pairs (about "
            f"{pairs / PAIRS_PER_S / 60:.0f} min), more than {st.max_pairs:.3g}; use a coarser "
            "grid (--grid-m) or coarser samples, plan fewer buildings, or raise the limit "
            "(--max-pairs)"
        )
    say(
        0.02,
        f"work: {len(fac.z):,} samples × {len(cand):,} candidate stations "
        f"({pairs:.3g} pairs to evaluate)",
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
    locked_ids: list[str | None] | None = None,
    clock: Clock | None = None,
    given: GivenIds | None = None,
) -> Plan:
    """The fewest stations (with ``locked`` positions kept, each under its id in
    ``locked_ids`` where one is given) and their registration network, for what ``wb``
    holds, within the time budget of ``clock`` (default: the settings' from now).
    ``given``: the ids of the plan this one is made from (printed, scanned): stations and
    targets where that plan's stood keep their ids, a new one takes a number never given
    (:mod:`planner.pipeline.engine.ids`)."""
    ctx = wb.ctx
    fac = wb.facades
    say = progress or (lambda _f, _m: None)
    clock = Clock() if clock is None else clock
    clock.note("setup", wb.setup_s)
    forced, kept, not_kept = _locked(wb, locked, locked_ids, given)
    cand, seen = wb.pool, wb.seen
    # stations and registration chosen together (docs/science.md): the fewest stations by
    # the scanner's error, their network, every sample judged on the total; while the
    # registration keeps samples short, stations are added that meet them with the
    # registration error they would have (estimated from the network) and the network is
    # built and judged again; once none is short, the fewest stations are chosen again with
    # every candidate's estimated registration error, the network's backbone kept
    cut: list[str] = []  # what the clock stopped, in words (the optimiser's search only)
    ev = _evaluate(ctx, cand, say, clock)
    wb.evaluation = ev
    wb.diagnosis = diagnose(ctx, cand, ev, clock)
    sol = _optimise(ctx, cand, ev, say, clock, forced=forced, cut=cut)
    best_effort, relaxed_by = _best_effort(ctx, cand, sol.chosen, wb.diagnosis, clock)
    cover = np.union1d(sol.chosen, best_effort) if len(best_effort) else sol.chosen
    if len(best_effort):
        forced = np.union1d(forced, best_effort)
        say(0.8, f"best effort: {len(best_effort)} station(s) for what no position meets")
    r = Round(cover=cover, net=round_network(ctx, cand, seen, cover, clock))
    r.judged = judge(ctx, cand, r)
    r, rounds = _registration_rounds(ctx, cand, seen, r, forced, ev, clock, say, cut)
    r, rounds, untried, rehearsal = _last_rounds(
        ctx, cand, seen, r, forced, ev, clock, say, cut, rounds
    )
    n_locked = len(forced) - len(best_effort)
    messages = _choice_messages(wb, r, sol, cut, n_locked, len(best_effort), relaxed_by, rounds)
    if not_kept:
        messages.append(f"Not kept from the plan before: {'; '.join(not_kept)}.")
    if rehearsal:
        messages.append(rehearsal)
    solver = _solver_report(sol, rounds, cut, fac.party_wall, ev.evaluated)
    solver.spacing_untried = untried
    hand = np.setdiff1d(forced, best_effort)

    ids_before = (wb.last_station, wb.last_target)

    def remake(rr: Round) -> Plan:  # each try from the ids given before (one id each)
        wb.last_station, wb.last_target = ids_before
        return assemble(wb, rr, solver, messages, clock, progress=say, hand=hand,
                        best_effort=best_effort, kept=kept, given=given)  # fmt: skip

    if ctx.settings.height_control == "level":  # the datum's lean with the chain's error
        run = with_level_run(ctx, cand, r)
        if run is not None and run.judged.n_met > r.judged.n_met:
            r = run
    r, p = _within_the_kit(wb, r, remake, ids_before)
    say_level_run(p, level_run(ctx, cand, r), seen.tc.xyz)
    return _with_the_day(p)


def _within_the_kit(
    wb: Workbench, r: Round, remake: Callable[[Round], Plan], ids_before: tuple[int, int]
) -> tuple[Round, Plan]:
    """The round and plan within the crew's kit (:func:`~planner.pipeline.engine.kit.within_kit`,
    ``remake`` the plan's assembly), saying what that took; the ids the workbench has given
    are the plan's, not those of a layout tried for the kit and left (``ids_before``: the
    highest given before)."""
    r, p, kit = within_kit(wb.ctx, wb.pool, wb.seen, r, remake(r), remake)
    if kit:
        p.messages.append(kit)
    stations = (id_number(s, "S") or 0 for s in p.stations["station_id"])
    targets = (id_number(t, "T") or 0 for t in p.targets["target_id"])
    wb.last_station = max([ids_before[0], *stations])
    wb.last_target = max([ids_before[1], *targets])
    return r, p


def _with_the_day(p: Plan) -> Plan:
    """The plan, saying what the other survey day (dry or wet) would cost
    (:func:`~planner.pipeline.engine.conditions.condition_words`)."""
    day = condition_words(p)
    if day:
        p.messages.append(day)
    return p


def _locked(
    wb: Workbench,
    locked: np.ndarray | None,
    locked_ids: list[str | None] | None,
    given: GivenIds | None,
) -> tuple[np.ndarray, dict[int, tuple[str, str]], list[str]]:
    """The pool indices of the ``locked`` positions (refused where one cannot stand, but in
    a re-plan from an earlier plan, ``given``: there left out and said), the ids they keep
    (pool index → id and purpose "hand") and what was left out, in words."""
    forced = np.empty(0, dtype=np.int64)
    not_kept: list[str] = []
    if locked is not None and given is not None:  # a re-plan: the edits that can still stand
        locked, locked_ids, not_kept = _still_standing(wb, locked, locked_ids, given)
    if locked is not None and len(np.asarray(locked).reshape(-1, 2)):
        forced = wb.add_positions(free_positions(wb, locked, "locked station"))
    named = zip(forced, locked_ids, strict=True) if locked_ids is not None else []
    return forced, {int(i): (sid, "hand") for i, sid in named if sid}, not_kept


def _still_standing(
    wb: Workbench, locked: np.ndarray, locked_ids: list[str | None] | None, given: GivenIds
) -> tuple[np.ndarray, list[str | None] | None, list[str]]:
    """Of the ``locked`` positions kept from an earlier plan (``given`` its ids), those a
    station can still stand at (the site or the clearance may have changed: a zone, a
    passage, a no-go area drawn since), their ids, and each left out with why ("S07 in the
    no-go area street")."""
    xy = np.asarray(locked, dtype=float).reshape(-1, 2)
    ids = list(locked_ids) if locked_ids is not None else given.stations_at(xy)
    bad = blocked_at(wb, xy)
    said = [
        f"{ids[k] or f'the station at E {xy[k, 0]:.1f}, N {xy[k, 1]:.1f}'} "
        f"({what_blocks(wb.site, xy[k], wb.settings.clearance_m)})"
        for k in np.flatnonzero(bad)
    ]
    return xy[~bad], [i for i, b in zip(ids, bad, strict=True) if not b], said


def _last_rounds(
    ctx: Context,
    cand: np.ndarray,
    seen: SightCache,
    r: Round,
    forced: np.ndarray,
    ev: CandidateEvaluation,
    clock: Clock,
    say: Progress,
    cut: list[str],
    rounds: int,
) -> tuple[Round, int, int, str]:
    """After the registration rounds: redundant stations pruned, close ones merged, then the
    cloud links rehearsed (:func:`_rehearsed`). The round, the rounds in all, the pairs the
    spacing rule left untried and what the rehearsal found, in words ("" none)."""
    untried, words = 0, ""
    if ctx.settings.computes_registration and r.net is not None:
        r = prune(ctx, cand, seen, r, clock, keep=forced)
        r, untried = merge_close_stations(ctx, cand, seen, r, clock, keep=forced)
    if _rehearses(ctx, r):
        say(0.9, "registration: rehearsing the cloud links")
        r, more = _rehearsed(ctx, cand, seen, r, forced, ev, clock, say, cut)
        rounds += more
        made = {k: seen.clouds.checks[k] for k in seen.clouds.asked if k in seen.clouds.checks}
        words = rehearsal_message(r.net, made, ctx) if r.net is not None else ""
    return r, rounds, untried, words


def _rehearses(ctx: Context, r: Round) -> bool:
    """Whether the plan rehearses its cloud links (``link_check`` "rehearse", a network
    with cloud links to check)."""
    st = ctx.settings
    return bool(
        st.computes_registration
        and st.link_check == "rehearse"
        and r.net is not None
        and any(lk.info is not None for lk in r.net.links)
    )


def _rehearsed(
    ctx: Context,
    cand: np.ndarray,
    seen: SightCache,
    r: Round,
    forced: np.ndarray,
    ev: CandidateEvaluation,
    clock: Clock,
    say: Progress,
    cut: list[str],
) -> tuple[Round, int]:
    """The stations chosen, their network made again with every cloud link rehearsed
    (:mod:`planner.pipeline.network.linkcheck`: a link that fails is no link, one weaker
    than the model says is taken at the rehearsal's error) and judged; then, while the
    rehearsed registration keeps samples short, stations added for them (at most
    :data:`REHEARSED_ROUNDS` rounds, every new link rehearsed), redundant ones pruned. The
    round and its number of rounds. The rounds before were judged on the model's links, so
    none of them is compared with these. Every link of the network made is rehearsed,
    whatever the clock says."""
    seen.clouds.rehearsing, seen.clouds.asked = True, set()
    try:
        again = Round(cover=r.cover, added=r.added)
        again.net = round_network(ctx, cand, seen, r.net.stations, clock, r.net.datum_station)
        again.judged = judge(ctx, cand, again)
        again, rounds = _registration_rounds(
            ctx, cand, seen, again, forced, ev, clock, say, cut, limit=REHEARSED_ROUNDS
        )
        again = prune(ctx, cand, seen, again, clock, keep=forced)
    finally:
        seen.clouds.rehearsing = False
    return again, rounds + 1


def _registration_rounds(
    ctx: Context,
    cand: np.ndarray,
    seen: SightCache,
    r: Round,
    forced: np.ndarray,
    ev: CandidateEvaluation,
    clock: Clock,
    say: Progress,
    cut: list[str],
    limit: int | None = None,
) -> tuple[Round, int]:
    """Stations and registration chosen together (docs/science.md): while the registration
    keeps samples short, stations are added that meet them with the registration error they
    would have (estimated from the network) and the network is built and judged again (once,
    first, a datum nearer the middle is tried); once none is short, the fewest stations are
    chosen again with every candidate's estimated registration error, the network's
    backbone kept. The best round and the number of rounds; what the clock stopped of the
    optimiser's search, into ``cut``. ``limit``: at most that many rounds, each adding
    stations (none chosen again)."""
    st, cover = ctx.settings, r.cover
    best, rounds, adds, resolved, moved = r, 0, 0, limit is not None, limit is not None
    while st.computes_registration and rounds < (limit or MAX_REGISTRATION_ROUNDS):
        if r.net is None:
            break
        short = r.judged.short_by_registration
        if short.any() and not moved:  # once: a datum nearer the middle, kept if better
            moved = True
            trial = datum_round(ctx, cand, seen, r, clock, say)
            if trial is not None:  # else: as if untried
                rounds += 1
                r = trial
                best = r if r.judged.better_than(best.judged) else best
                continue
        more = np.empty(0, dtype=np.int64)
        if short.any() and (resolved or adds < ADD_ROUNDS):
            say(0.85, f"registration: {int(short.sum())} samples short; adding stations")
            more = stations_for(ctx, cand, r.net, short, clock)
        grown_from = r.net
        if len(more):
            adds += 1
            chosen = np.concatenate([r.net.stations, more])
            r = Round(cover=r.cover, added=np.union1d(r.added, more))
        elif not resolved and len(r.net.stations) > len(cover):
            say(0.9, "registration: choosing the fewest stations again")
            resolved = True
            backbone = np.union1d(r.net.backbone, forced)
            estimate = estimate_registration(ctx, r.net, cand)
            again = _evaluate(ctx, cand, say, clock, estimate=estimate)
            chosen = _optimise(
                ctx, cand, again, say, clock, backbone, scanner_ok=ev.ok, cut=cut
            ).chosen
            r = Round(cover=chosen)
        else:
            break
        rounds += 1
        keep = grown_from.datum_station if len(more) else None
        r.net = round_network(ctx, cand, seen, chosen, clock, keep)
        r.judged = judge(ctx, cand, r)
        if r.judged.better_than(best.judged):
            best = r
    return best, rounds


def _choice_messages(
    wb: Workbench,
    r: Round,
    sol: CoverSolution,
    cut: list[str],
    n_locked: int,
    n_best_effort: int,
    relaxed_by: float,
    rounds: int,
) -> list[str]:
    """The plan's messages so far (the workbench's), then what the budget cut, the
    stations locked, the best-effort ones and the stations the registration added."""
    st = wb.settings
    messages = list(wb.messages)
    if cut:
        messages.append(budget_message(st.time_limit_s, cut))
    if n_locked:
        messages.append(f"{n_locked} station(s) locked by hand; the others chosen around them.")
    if n_best_effort:
        messages.append(
            f"Best effort: {n_best_effort} station(s) added for the samples no position "
            f"meets, meeting them within {relaxed_by:.2f} × the "
            "limits (they stay unmet; see the best achievable values and what would meet them)."
        )
    if r.net is not None and len(r.net.stations) != sol.objective and st.computes_registration:
        messages.append(
            f"Stations: {sol.objective} meet the requirement by the scanner's error alone; "
            f"{len(r.net.stations)} with the registration error counted ({rounds} round(s) of "
            "adding stations and choosing again)."
        )
    return messages


def _solver_report(
    sol: CoverSolution, rounds: int, cut: list[str], party_wall: np.ndarray, evaluated: np.ndarray
) -> SolverReport:
    """How the covering stations were chosen, and what the budget cut short."""
    return SolverReport(
        method=sol.method,
        status=sol.status,
        objective=sol.objective,
        lower_bound=sol.lower_bound,
        gap=sol.gap,
        seconds=sol.seconds,
        greedy_objective=sol.greedy_objective,
        reductions=sol.details.get("reductions", ""),
        parts=sol.details.get("parts", 0),
        registration_rounds=rounds,
        cut_short=cut,
        samples_total=int((~party_wall).sum()),
        samples_evaluated=int((evaluated & ~party_wall).sum()),
    )


#: The samples no position meets are served, best effort, within this share of the smallest
#: uniform relaxation of the limits under which every one of them could be met.
BEST_EFFORT_SLACK = 1.02


def _best_effort(
    ctx: Context,
    cand: np.ndarray,
    chosen: np.ndarray,
    diagnosis: Diagnosis,
    clock: Clock,
) -> tuple[np.ndarray, float]:
    """Candidates (not among ``chosen``) for the samples no candidate meets, and the factor
    they meet them within: the smallest uniform relaxation of the limits under which every
    such sample seen could be met (the largest of their best achievable scores, value /
    limit, times :data:`BEST_EFFORT_SLACK`), the fewest candidates (greedy) meeting them
    under it — so that a requirement a little too strict gives the plan that comes closest,
    not zero stations. The samples stay unmet. None is spent on the samples beyond the
    ground's reach (:attr:`Diagnosis.elevated`): they need an elevated station."""
    none = np.empty(0, dtype=np.int64), 1.0
    if not len(diagnosis.samples):
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
    ok = evaluate_candidates(relaxed, cand, only=only).ok
    ok = sp.csr_matrix(ok[np.flatnonzero(only)])
    served = np.asarray(ok[:, chosen].sum(axis=1)).ravel() > 0 if len(chosen) else False
    demand = ((np.asarray(ok.sum(axis=1)).ravel() > 0) & ~served).astype(np.int64)
    if not demand.any():
        return none
    sol = solve_cover(ok, demand, _solver_time(ctx, clock), ctx.settings.method)
    return np.asarray(sol.chosen, dtype=np.int64), factor


#: How many times stations are added or chosen again for the registration error (each time
#: the network is built and judged again) …
MAX_REGISTRATION_ROUNDS = 4
#: Rounds of adding stations once the cloud links are rehearsed.
REHEARSED_ROUNDS = 1
#: … of which rounds of adding before the fewest are chosen again.
ADD_ROUNDS = 2


def _evaluate(
    ctx: Context,
    cand: np.ndarray,
    say: Progress,
    clock: Clock,
    estimate: Registration | None = None,
) -> CandidateEvaluation:
    """Every candidate against every sample on the scanner's error (plus the ``estimate`` of
    its registration error), whole."""
    with clock.timed("evaluate"):
        return evaluate_candidates(
            ctx, cand, progress=lambda f, m: say(0.05 + 0.6 * f, m), registration=estimate
        )


def _optimise(
    ctx: Context,
    cand: np.ndarray,
    ev: CandidateEvaluation,
    say: Progress,
    clock: Clock,
    forced: np.ndarray | None = None,
    scanner_ok: sp.csr_matrix | None = None,
    cut: list[str] | None = None,
) -> CoverSolution:
    """The fewest stations meeting the evaluation ``ev`` (with the redundant views spread);
    the ``forced`` candidates are taken and the fewest others added to them. Where the
    clock stopped the search before its work bounds, that is said into ``cut``. A sample the
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
    remaining = _solver_time(ctx, clock)
    if forced is None or not len(forced):
        sol = solve_cover(ok, demand, remaining, st.method)
    else:  # the others for what the forced stations leave
        free = np.ones(len(cand))
        free[forced] = 0.0
        left = np.maximum(0, demand - np.asarray(ok[:, forced].sum(axis=1)).ravel())
        sol = solve_cover(sp.csr_matrix((ok @ sp.diags(free)) > 0), left, remaining, st.method)
        sol.chosen = np.union1d(sol.chosen, forced)
        sol.objective = len(sol.chosen)
        if sol.lower_bound is not None:  # the bound of the others plus the forced ones
            sol.lower_bound = float(sol.lower_bound) + len(np.unique(forced))
            sol.gap = max(0.0, (sol.objective - sol.lower_bound) / max(sol.objective, 1))
    if sol.status == "time limit" and cut is not None:
        cut.append(
            f"the optimiser's search for fewer stations ({sol.objective}, at least "
            f"{sol.lower_bound:.0f}): a faster machine or a longer run may give fewer"
        )
    # one set-up per spot, before the views are spread (merging counts the stations that
    # meet a sample, not the directions they see it from)
    merged = merge_close(ok, demand, sol.chosen, cand[:, :2], st.station_spacing_m, forced)
    if merged.merged:  # one set-up per spot: never more stations, every demand still met
        sol.status += (
            f"; {len(merged.merged)} pair(s) closer than {st.station_spacing_m:g} m merged"
        )
        sol.chosen, sol.objective = merged.chosen, len(merged.chosen)
        if sol.lower_bound is not None:
            sol.gap = max(0.0, (sol.objective - sol.lower_bound) / max(sol.objective, 1))
    if (ctx.stations_needed > 1).any():
        spread = spread_views(ok, demand, sol.chosen, cand, fac.xy, req.min_view_angle_deg)
        if len(spread) > len(sol.chosen):  # the bound still holds; the gap is the spread's
            sol.status += f"; {len(spread) - len(sol.chosen)} added for separate views"
            sol.chosen, sol.objective = spread, len(spread)
            sol.gap = (sol.objective - sol.lower_bound) / sol.objective
    clock.note("optimise", time.perf_counter() - t)
    return sol


def _solver_time(ctx: Context, clock: Clock) -> float:
    """The optimiser's backstop [CPU s]: :data:`SOLVER_SHARE` of ``time_limit_s`` when the
    registration network is still to be built and judged (else all of it) — the same on
    any machine; where the plan has a wall-clock end (a district's block), that share of
    what is left of it, if less, and never under :data:`MIN_SOLVER_S`."""
    share = SOLVER_SHARE if ctx.settings.computes_registration else 1.0
    cpu = share * ctx.settings.time_limit_s
    return cpu if math.isinf(clock.end) else max(MIN_SOLVER_S, min(cpu, share * clock.left_s()))


def cover_demand(ctx: Context, n_ok: np.ndarray) -> np.ndarray:
    """How many of the chosen stations each sample needs, given how many candidates meet it
    (``n_ok``): the stations its requirement asks for, at most as many as meet it; none on a
    party wall."""
    return np.where(ctx.facades.party_wall, 0, np.minimum(ctx.stations_needed, n_ok))
