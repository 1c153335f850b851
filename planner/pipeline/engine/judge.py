"""The engine that judges a set of stations: their registration network built, every sample
judged on the scanner's error and the registration's (:class:`Judged`), stations added where
the registration keeps samples short, and the :class:`~planner.pipeline.engine.result.Plan` of a
round assembled (:func:`assemble`). The optimisation loop
(:func:`planner.pipeline.engine.planning.choose_stations`) and the edits by hand
(:mod:`planner.pipeline.engine.whatif`) both use it; :class:`Workbench` is what a plan was made
from.
"""

from __future__ import annotations

import copy
import math
import time
import weakref
from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd
import scipy.sparse as sp
import shapely

from planner.cloud_registration import relief_words
from planner.errors import InputError
from planner.materials import walls_words
from planner.pipeline.engine.ids import GivenIds, id_number
from planner.pipeline.engine.result import Plan, SolverReport
from planner.pipeline.engine.tables import (
    class_family,
    coverage_table,
    enclosed_messages,
    facade_summary,
    registration_messages,
    rename_stations,
    rename_targets,
    target_numbers,
    targets_and_links,
    unmet_messages,
    untied_places,
    zone_summary,
)
from planner.pipeline.evaluation.diagnosis import Diagnosis
from planner.pipeline.evaluation.evaluate import (
    Assignment,
    CandidateEvaluation,
    Context,
    Progress,
    Registration,
    assign_stations,
    evaluate_candidates,
)
from planner.pipeline.field.route import FieldRoute, field_route
from planner.pipeline.geometry.candidates import blocked_ground
from planner.pipeline.geometry.facades import FacadeSet
from planner.pipeline.geometry.zoning import ZoneTable
from planner.pipeline.inputs.clock import Clock
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.pipeline.inputs.schema import STATION_ID
from planner.pipeline.network.control import tie_groups, tie_messages, traverse_setups
from planner.pipeline.network.layout import Layout
from planner.pipeline.network.network import Network
from planner.pipeline.network.registration import build_network
from planner.pipeline.network.targets import SightCache, TargetCandidates
from planner.pipeline.optimise.cover import solve_cover
from planner.pipeline.optimise.spacing import close_pairs, merge_options
from planner.registration_error import datum_lean_mm
from planner.scanner import Scanner
from planner.site import Site

__all__ = [
    "Judged",
    "Round",
    "Workbench",
    "assemble",
    "copy_plan",
    "datum_round",
    "datum_station",
    "estimate_registration",
    "forget_workbench",
    "free_positions",
    "judge",
    "keep_workbench",
    "name_stations",
    "prune",
    "round_network",
    "stations_for",
    "workbench_of",
]


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
    #: the highest station and target numbers given so far: a station or target new to an
    #: edited plan takes the next one (a deleted one's id is not given again)
    last_station: int = 0
    last_target: int = 0

    def given(self, p: Plan) -> GivenIds:
        """The ids plan ``p`` (made from this workbench) gave, for a plan made from it."""
        return GivenIds.of(p.scan_stations, p.targets, self.last_station, self.last_target)

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


def blocked_at(wb: Workbench, xy: np.ndarray, clearance_m: float | None = None) -> np.ndarray:
    """Where a station cannot stand, per position of ``xy`` (k, 2) [m]: inside a building,
    obstacle or no-go area, or within the clearance (the settings', or ``clearance_m``)."""
    clear = wb.settings.clearance_m if clearance_m is None else clearance_m
    xy = np.asarray(xy, dtype=float).reshape(-1, 2)
    return shapely.contains_xy(blocked_ground(wb.site, clear), xy[:, 0], xy[:, 1])


def free_positions(
    wb: Workbench, xy: np.ndarray, what: str, clearance_m: float | None = None
) -> np.ndarray:
    """``xy`` [m] as a ``(k, 2)`` array, refused (InputError) where a station cannot stand
    (:func:`blocked_at`), saying what is in the way."""
    xy = np.asarray(xy, dtype=float).reshape(-1, 2)
    if not np.isfinite(xy).all():
        raise InputError(f"a {what} has no coordinates (x, y must be numbers)")
    clear = wb.settings.clearance_m if clearance_m is None else clearance_m
    bad = np.flatnonzero(blocked_at(wb, xy, clear))
    if len(bad):
        k = bad[0]
        raise InputError(
            f"the {what} at E {xy[k, 0]:.2f}, N {xy[k, 1]:.2f} stands "
            f"{what_blocks(wb.site, xy[k], clear)}; move it onto free ground"
        )
    return xy


def what_blocks(site: Site, xy: np.ndarray, clearance_m: float) -> str:
    """Why a station cannot stand at ``xy``, naming what is in the way."""
    point = shapely.Point(xy)
    names = {b.id: "building" for b in site.buildings} | {o.id: "obstacle" for o in site.obstacles}
    near = []
    for ident, geom, _h in site.blockers:
        if geom.contains(point):
            return f"inside {names.get(ident, 'building')} {ident}"
        near.append((geom.distance(point), ident))
    for a in site.no_go:
        if a.geometry.contains(point):
            return f"in the no-go area {a.id}"
    d, ident = min(near, default=(math.inf, ""))
    return (
        f"{d:.1f} m from {names.get(ident, 'building')} {ident} (the tripod keeps "
        f"{clearance_m:g} m clear)"
    )


def name_stations(n: int, visit: list[int], kept: dict[int, str], after: int | None) -> list[str]:
    """The ids of ``n`` stations (positions 0 … n-1) visited in the order ``visit``: a
    station in ``kept`` (position → id) keeps its id; the others are numbered in visiting
    order — S01 the first set-up, numbers a kept id holds skipped — or, given ``after`` (an
    edit by hand: no id is given twice), from ``after`` + 1 on.

    >>> name_stations(3, [2, 0, 1], {}, None)
    ['S02', 'S03', 'S01']
    >>> name_stations(3, [2, 0, 1], {1: "S01"}, None)
    ['S03', 'S01', 'S02']
    >>> name_stations(3, [0, 1, 2], {0: "S04", 2: "S01"}, after=7)
    ['S04', 'S08', 'S01']
    >>> name_stations(3, [0, 1, 2], {0: "S10", 1: "S11"}, after=9)
    ['S10', 'S11', 'S12']
    """
    taken = {id_number(s, "S") for s in kept.values()}
    ids: list[str | None] = [kept.get(k) for k in range(n)]
    number = after or 0
    for k in visit:
        if ids[k] is None:
            number += 1
            while number in taken:  # never an id a kept station holds
                number += 1
            ids[k] = STATION_ID.format(number)
    return [str(i) for i in ids]


def assemble(
    wb: Workbench,
    r: Round,
    solver: SolverReport,
    messages: list[str],
    clock: Clock,
    *,
    progress: Progress | None = None,
    hand: np.ndarray | None = None,
    best_effort: np.ndarray | None = None,
    kept: dict[int, tuple[str, str]] | None = None,
    given: GivenIds | None = None,
) -> Plan:
    """The plan of the stations of round ``r`` (pool indices; those in ``hand`` placed by
    hand, those in ``best_effort`` for samples no position meets): coverage, targets, links,
    route, messages (the accuracy model's line, those given, then the network's and the
    unmet samples'; the list given is not changed).

    Station and target ids follow the visiting order (:func:`name_stations`); a station in
    ``kept`` (pool index → its id and purpose) keeps both. A plan made from an earlier one
    (``given``, its ids: :mod:`planner.pipeline.engine.ids`) keeps the earlier ids of the
    stations and targets that stand where they stood, and a new one takes a number never
    given (:attr:`Workbench.last_station`, :attr:`Workbench.last_target`)."""
    say = progress or (lambda _f, _m: None)
    ctx, st, ev, cand = wb.ctx, wb.settings, wb.evaluation, wb.pool
    net, assignment = r.net, r.judged.assignment
    kept = kept or {}
    messages = list(messages)
    say(0.93, "coverage of the chosen stations")
    t = time.perf_counter()
    station_idx = net.stations if net is not None else np.asarray(r.cover, dtype=np.int64)
    station_xy = cand[station_idx] if len(station_idx) else np.empty((0, 2))
    ids = [STATION_ID.format(i + 1) for i in range(len(station_idx))]  # until the order is known
    family = class_family(wb.req, wb.zones)
    grid = cand[: wb.n_grid]
    coverage = coverage_table(ctx, ev, wb.diagnosis, assignment, ids, net, wb.zone_ids, family)
    purpose = _purposes(r, station_idx, assignment.met_by_station, hand, best_effort, kept)
    stations = _station_table(ctx, st, station_idx, station_xy, ids, purpose, assignment, net)
    tc = net.candidates if net is not None else wb.tc  # with any planned control points
    targets, links = targets_and_links(ctx, tc, net, ids, coverage)
    clock.note("coverage", time.perf_counter() - t)
    say(0.97, "visiting order and field time")
    t = time.perf_counter()
    route = field_route(wb.site, wb.scanner, st, stations, targets, coverage, links)
    stations, coverage, targets, links, route, ids = _in_visiting_order(
        wb, station_idx, ids, kept, given, stations, coverage, targets, links, route
    )
    clock.note("route", time.perf_counter() - t)
    messages += _plan_messages(ctx, net, coverage, links, ids, tc, st)
    candidates = pd.DataFrame(
        {
            "x": grid[:, 0],
            "y": grid[:, 1],
            "samples_met": np.asarray(ev.ok[:, : wb.n_grid].sum(axis=0)).ravel(),
        }
    )
    solver = replace(
        solver,
        reach_m=wb.reach,
        candidates=wb.n_grid,
        samples=int((~wb.facades.party_wall).sum()),
        pairs=wb.pairs,
    )
    messages.insert(0, f"Accuracy model: {st.model_description()}.")
    messages.insert(1, _walls_message(wb))
    say(1.0, "plan ready")
    plan = Plan(
        site=wb.site,
        scanner=wb.scanner,
        requirements=wb.req,
        settings=st,
        stations=stations,
        targets=targets,
        coverage=coverage,
        facades=facade_summary(wb.facades, coverage),
        zones=zone_summary(wb.zones, coverage),
        links=links,
        candidates=candidates,
        network=net,
        route=route,
        solver=solver,
        messages=messages,
        timings_s=clock.timings(),
    )
    return keep_workbench(plan, wb)


def _walls_message(wb: Workbench) -> str:
    """What the plan took the walls to be: their materials on the survey day and, where
    scans are registered cloud to cloud, their relief."""
    st = wb.settings
    walls = walls_words(
        wb.ctx.material, st.material_table, st.surface_condition, wb.scanner.ref_reflectance
    )
    if st.registration_for(wb.scanner) != "targets" and st.computes_registration:
        walls += " " + relief_words(st.window_share, st.reveal_depth_m)
    return walls


def _purposes(
    r: Round,
    station_idx: np.ndarray,
    met_by_station: np.ndarray,
    hand: np.ndarray | None,
    best_effort: np.ndarray | None,
    kept: dict[int, tuple[str, str]],
) -> np.ndarray:
    """Each station's purpose (:data:`~planner.pipeline.inputs.schema.STATION_PURPOSES`)."""
    net = r.net
    hand = hand if hand is not None else []
    purpose = np.select(
        [
            np.isin(station_idx, hand),
            np.isin(station_idx, best_effort if best_effort is not None else []),
            np.isin(station_idx, r.cover),
            np.isin(station_idx, r.added),
        ],
        ["hand", "best-effort", "cover", "registration"],
        "link",
    )
    # a covering station no sample is assigned to any more is there for the network — if
    # another scan is registered to it (one in an untied courtyard links nothing: it stays
    # a covering station whose samples the registration cannot carry, and is said so)
    links_others = np.zeros(len(station_idx), dtype=bool)
    if net is not None:  # a link's parent, or a planned traverse's start
        parents = [lk.parent for lk in net.links] + [t.start for t in net.ties]
        links_others[[k for k in parents if 0 <= k < len(station_idx)]] = True
    idle = (purpose == "cover") & (np.asarray(met_by_station) == 0)
    purpose[idle & links_others] = "link"
    for k, i in enumerate(station_idx.tolist()):
        if i in kept and not np.isin(i, hand):
            purpose[k] = kept[i][1]
    return purpose


def _station_table(
    ctx: Context,
    st: PlanSettings,
    station_idx: np.ndarray,
    station_xy: np.ndarray,
    ids: list[str],
    purpose: np.ndarray,
    assignment: Assignment,
    net: Network | None,
) -> pd.DataFrame:
    """The stations table (:data:`~planner.pipeline.inputs.schema.STATION_COLUMNS`, and the
    samples each meets), with a planned traverse's set-ups."""
    stations = pd.DataFrame(
        {
            "station_id": ids,
            "x": station_xy[:, 0],
            "y": station_xy[:, 1],
            "ground_z": ctx.scene.ground_z(station_xy),
            "instrument_height_m": st.instrument_height_m,
            "purpose": purpose,
            "samples_met": assignment.met_by_station,
        }
    )
    setups = traverse_setups(net.ties if net is not None else [], st, ctx.scene.ground_z)
    if len(setups):
        stations = pd.concat([stations, setups], ignore_index=True)
    return stations


def _in_visiting_order(
    wb: Workbench,
    station_idx: np.ndarray,
    ids: list[str],
    kept: dict[int, tuple[str, str]],
    given: GivenIds | None,
    stations: pd.DataFrame,
    coverage: pd.DataFrame,
    targets: pd.DataFrame,
    links: pd.DataFrame,
    route: FieldRoute,
) -> tuple[pd.DataFrame, pd.DataFrame, pd.DataFrame, pd.DataFrame, FieldRoute, list[str]]:
    """Stations and targets named in the visiting order (:func:`name_stations`,
    :func:`~planner.pipeline.engine.tables.target_numbers`) in every table and the route,
    those ``kept`` or standing where the ``given`` ids' stood keeping theirs; the
    workbench's highest numbers raised (never lowered: no id given twice). ``ids``: the
    stations' ids until now, by their place in ``station_idx``."""
    at = {sid: k for k, sid in enumerate(ids)}
    visit = [at[sid] for sid in route.table["station_id"] if sid in at]
    named = {k: kept[i][0] for k, i in enumerate(station_idx.tolist()) if i in kept}
    target_kept: dict[str, str] = {}
    if given is not None:
        taken = set(named.values())
        for k, sid in enumerate(given.stations_at(wb.pool[station_idx])):
            if sid is not None and k not in named and sid not in taken:
                named[k] = sid
                taken.add(sid)
        ours = targets[targets["type"] != "control"]
        places = given.targets_at(ours[["x", "y", "z"]].to_numpy(float))
        target_kept = {t: g for t, g in zip(ours["target_id"], places, strict=True) if g}
    last = (wb.last_station, wb.last_target)
    if given is not None:
        last = (max(last[0], given.last_station), max(last[1], given.last_target))
    names = name_stations(len(ids), visit, named, last[0] if given is not None else None)
    mapping = dict(zip(ids, names, strict=True))
    stations, coverage, targets, links = rename_stations(
        mapping, stations, coverage, targets, links
    )
    ids = names
    place = {mapping[sid]: n for n, sid in enumerate(route.table["station_id"]) if sid in mapping}
    renumbered = target_numbers(targets, place, target_kept, last[1] if given is not None else 0)
    targets, links = rename_targets(renumbered, targets, links)
    route = route.renamed(mapping, renumbered)
    wb.last_station = max([last[0], *(id_number(s, "S") or 0 for s in ids)])
    wb.last_target = max([last[1], *(id_number(t, "T") or 0 for t in renumbered.values())])
    return stations, coverage, targets, links, route, ids


def _plan_messages(
    ctx: Context,
    net: Network | None,
    coverage: pd.DataFrame,
    links: pd.DataFrame,
    ids: list[str],
    tc: TargetCandidates,
    st: PlanSettings,
) -> list[str]:
    """The network's messages (untied places, ties, the registration's share) and the unmet
    samples'."""
    messages: list[str] = []
    if net is not None:
        messages.append(f"Registration: {net.message}.")
        messages.extend(enclosed_messages(untied_places(ctx, net), ids))
        messages.extend(tie_messages(net.ties, ids, tc, st))
        messages.extend(registration_messages(coverage, links, st))
    unmet = coverage[~coverage["meets"] & ~coverage["party_wall"]]
    if len(unmet):
        messages.extend(unmet_messages(unmet))
    return messages


#: Each plan's workbench, kept beside the plan (a plain result) for as long as the plan lives.
_BENCHES: weakref.WeakKeyDictionary[Plan, Workbench] = weakref.WeakKeyDictionary()


def keep_workbench(p: Plan, wb: Workbench) -> Plan:
    """Keep ``wb`` beside ``p`` (for :func:`workbench_of`) and return ``p``. Nothing of it is
    saved or sent with the plan to another process."""
    _BENCHES[p] = wb
    return p


def workbench_of(p: Plan) -> Workbench | None:
    """What ``p`` was made from, for what-if edits — None for a plan made elsewhere (another
    process, a district's stitch) or read back from files."""
    return _BENCHES.get(p)


def forget_workbench(p: Plan) -> None:
    """Let ``p``'s workbench go (a district block's, once its frame is kept: the worker
    keeps the light plan until the stitch, not what it was made from)."""
    _BENCHES.pop(p, None)


def copy_plan(p: Plan) -> Plan:
    """A deep copy of ``p`` with a deep copy of its workbench beside it: what-if edits of the
    copy leave ``p`` and its workbench as they were."""
    q, wb = copy.deepcopy((p, workbench_of(p)))
    return keep_workbench(q, wb) if wb is not None else q


@dataclass
class Judged:
    """A round's stations judged on the total error against the client's limits."""

    assignment: Assignment
    n_met: int
    n_stations: int
    short_by_registration: np.ndarray  # (N,) met by the scanner's error alone, not the total
    met: np.ndarray | None = None  # (N,) the samples met (None: none judged)

    def better_than(self, other: Judged) -> bool:
        """More samples met; as many with fewer stations."""
        return (self.n_met, -self.n_stations) > (other.n_met, -other.n_stations)


@dataclass
class Round:
    """Stations tried: those the optimiser chose (``cover``), those added for the
    registration error (``added``), their network and its judgement."""

    cover: np.ndarray
    added: np.ndarray = field(default_factory=lambda: np.empty(0, dtype=np.int64))
    net: Network | None = None
    judged: Judged | None = None


def serving_probes(ctx: Context, station: np.ndarray, k: int) -> dict[int, np.ndarray]:
    """Each of ``k`` stations' probe points (P, 3) [m]: the facade samples it serves best by
    the scanner's error (``station``: each sample's, -1 none), where its links' errors are
    judged."""
    fac = ctx.facades
    pts = np.column_stack([fac.xy, fac.z])
    return {j: pts[station == j] for j in range(k)}


def network_layout(p: Plan) -> Layout | None:
    """The layout the plan's network was chosen from (its stations, each probed where it
    serves, the plan's goal for a link), to ask what any pair of its scans would give
    registered directly; None for a plan without its workbench or network."""
    wb, net = workbench_of(p), p.network
    if wb is None or net is None:
        return None
    ctx = wb.ctx
    stations = [int(s) for s in net.stations]
    served = assign_stations(ctx, wb.pool[stations]).station
    return Layout(
        ctx,
        wb.seen,
        wb.pool,
        stations,
        serving_probes(ctx, served, len(stations)),
        goal_mm=REGISTRATION_GOAL * tightest_mm(ctx),
    )


def round_network(
    ctx: Context,
    cand: np.ndarray,
    seen: SightCache,
    chosen: np.ndarray,
    clock: Clock | None = None,
    datum: int | None = None,
    kit: tuple = (None, None),
) -> Network | None:
    """The registration network of the stations ``chosen`` (candidate indices), each
    probed at the facade points it serves best by the scanner's error, built whole (the
    ``clock`` only counts its time). ``kit``: a
    leap-frogging kit's chain and cap
    (:func:`~planner.pipeline.network.registration.build_network`)."""
    if not len(chosen):
        return None
    clock = Clock.unbounded() if clock is None else clock
    t = time.perf_counter()
    fac = ctx.facades
    scanner_only = assign_stations(ctx, cand[chosen])
    probes = serving_probes(ctx, scanner_only.station, len(chosen))
    tightest = tightest_mm(ctx)
    # the height error each sample leaves the registration (its limit ⊕ the scanner's part)
    has = (scanner_only.station >= 0) & ~fac.party_wall
    m_z = scanner_only.metrics["m_z_mm"][has]
    room = np.sqrt(np.maximum(np.square(ctx.limits["m_z"][has]) - np.square(m_z), 0.0))
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
        height_room=(fac.xy[has], room),
        chain=kit[0],
        cap=kit[1],
    )
    if not net.tied.all() and net.tied.any():  # groups no target reaches: planned control
        net = tie_groups(ctx, cand, seen, net, REGISTRATION_GOAL * tightest)
    clock.note("registration", time.perf_counter() - t)
    if net.datum is not None and seen.tc.is_control.any() and not net.ties:
        # control points given but no station sees three of them: a station that does,
        # nearest the others, ties the network to the site's control (else it is said)
        tie = _control_station(seen, cand, chosen)
        if tie is not None and tie not in chosen:
            return round_network(ctx, cand, seen, np.append(chosen, tie), clock)
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


def prune(
    ctx: Context,
    cand: np.ndarray,
    seen: SightCache,
    r: Round,
    clock: Clock,
    keep: np.ndarray | None = None,
) -> Round:
    """Drop stations the final judgement gives no sample and no other station is registered
    to (chosen for an estimate the exact network did not bear out), one at a time, each kept
    out only if no sample is lost; the ``keep`` candidates (locked by hand) are never dropped.
    Each station is tried once (a network built and judged per try: in cloud mode each try
    may rehearse new links, and retrying every idle station after each drop took minutes)."""
    keep = np.empty(0, dtype=np.int64) if keep is None else keep
    tried: set[int] = set()  # candidates whose dropping lost samples
    while True:  # each pass drops one station or ends
        served = np.bincount(
            r.judged.assignment.station[r.judged.assignment.station >= 0],
            minlength=len(r.net.stations),
        )
        parents = {lk.parent for lk in r.net.links}
        idle = [
            k
            for k in np.flatnonzero(served == 0)
            if k not in parents
            and r.net.stations[k] not in keep
            and int(r.net.stations[k]) not in tried
        ]
        for k in idle:
            tried.add(int(r.net.stations[k]))
            chosen = np.delete(r.net.stations, k)
            trial = Round(cover=np.setdiff1d(r.cover, r.net.stations[k]), added=r.added)
            trial.net = round_network(ctx, cand, seen, chosen, clock, r.net.datum_station)
            if trial.net is None:
                continue
            trial.judged = judge(ctx, cand, trial)
            if trial.judged.n_met >= r.judged.n_met:
                r = trial
                break
        else:
            return r


#: Merging stations closer than the crew's spacing tries at most this many close pairs
#: per station of the network (each pair tried with its network built and judged): a plan
#: of many close pairs (best-effort stations for what no position meets) would otherwise
#: spend minutes here. A count, not a time: the same pairs are tried on any machine.
MERGE_PAIRS_PER_STATION = 1.0
#: A close pair is tried as each of its two stations and the best one candidate between.
MERGE_TRIALS = 3


def merge_close_stations(
    ctx: Context,
    cand: np.ndarray,
    seen: SightCache,
    r: Round,
    clock: Clock,
    keep: np.ndarray | None = None,
) -> tuple[Round, int]:
    """One set-up per spot (:mod:`planner.pipeline.optimise.spacing`) for the network's
    stations: each pair closer than the crew's spacing, closest first, tried as one station
    — the first of the pair kept, or the second, or the free candidate nearest their middle
    the spacing away from every other station — with its network built and judged; taken
    where the network has fewer stations, every sample met before is met and no more
    groups need planned control (a traverse, GNSS) to be tied. The ``keep`` candidates
    (locked by hand) are never moved; a pair no trial merges stays (the plan says why). At
    most :data:`MERGE_PAIRS_PER_STATION` pairs per station are tried; the round and how many
    close pairs were left untried."""
    spacing = ctx.settings.station_spacing_m
    fixed = set(np.asarray(keep if keep is not None else [], dtype=np.int64).tolist())
    most = 0 if r.net is None else max(1, int(MERGE_PAIRS_PER_STATION * len(r.net.stations)))
    tried: set[tuple[int, int]] = set()
    while r.net is not None and spacing > 0:
        st = r.net.stations
        pairs = [
            (int(st[i]), int(st[j]))
            for i, j in close_pairs(cand[st, :2], spacing)
            if (int(st[i]), int(st[j])) not in tried and not {int(st[i]), int(st[j])} <= fixed
        ]
        if not pairs or len(tried) >= most:
            return r, len(pairs)
        a, b = pairs[0]
        tried.add((a, b))
        rest = st[(st != a) & (st != b)]
        datum = r.net.datum_station if r.net.datum_station not in (a, b) else None
        for one in merge_options(cand[:, :2], rest, a, b, spacing, fixed)[:MERGE_TRIALS]:
            trial = Round(cover=_swap(r.cover, a, b, one), added=_swap(r.added, a, b, one))
            trial.net = round_network(ctx, cand, seen, np.append(rest, one), clock, datum)
            if trial.net is None:
                continue
            trial.judged = judge(ctx, cand, trial)
            kept = r.judged.met is None or not (r.judged.met & ~trial.judged.met).any()
            if (
                len(trial.net.stations) < len(st)
                and kept
                and len(trial.net.ties) <= len(r.net.ties)
            ):
                r = trial
                break
    return r, 0


def _swap(idx: np.ndarray, a: int, b: int, one: int) -> np.ndarray:
    """``idx`` with ``a`` and ``b`` replaced by ``one`` where either was in it."""
    if not np.isin([a, b], idx).any():
        return idx
    return np.union1d(np.setdiff1d(idx, [a, b]), [one])


def stations_for(
    ctx: Context,
    cand: np.ndarray,
    net: Network,
    short: np.ndarray,
    clock: Clock,
) -> np.ndarray:
    """Candidates to add so that the ``short`` samples meet the total: each candidate judged
    with the registration error it would have in ``net`` (:meth:`Network.estimate`), the
    one meeting the most short samples first (greedy), until all are met or none helps."""
    t = time.perf_counter()
    estimate = estimate_registration(ctx, net, cand)
    if estimate is None:
        return np.empty(0, dtype=np.int64)
    ev = evaluate_candidates(ctx, cand, registration=estimate, only=short)
    keep = np.ones(len(cand))
    keep[net.stations] = 0.0  # the network's own stations do not meet them already
    ok = sp.csr_matrix((ev.ok[np.flatnonzero(short)] @ sp.diags(keep)) > 0)
    demand = np.minimum(1, np.asarray(ok.sum(axis=1)).ravel())
    sol = solve_cover(ok, demand, 0.0, "greedy")
    clock.note("evaluate", time.perf_counter() - t)
    return np.asarray(sol.chosen, dtype=np.int64)


def datum_station(ctx: Context, cand: np.ndarray, r: Round) -> int | None:
    """A new station for the datum, where the lean of the datum's levelling (a scanner
    without a compensator, :func:`planner.registration_error.datum_tilt_cov`) keeps many
    samples short in m_z (:data:`DATUM_SHARE`): the candidate (where a tied station's
    ground reaches) with which the fewest samples stay short — each judged on its m_z with
    the lean about that candidate in place of the present datum's, the rest of its
    registration error kept — if fewer than now; else None. The network's layout then
    chooses its datum with the new station among the others."""
    net = r.net
    lean_at = net.leaning_datum() if net is not None else None
    if lean_at is None:
        return None
    a = r.judged.assignment
    tau = ctx.scanner.datum_tilt_rms_arcsec
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


def datum_round(
    ctx: Context,
    cand: np.ndarray,
    seen: SightCache,
    r: Round,
    clock: Clock,
    say: Progress,
) -> Round | None:
    """Round ``r`` with a datum station nearer the middle (:func:`datum_station`), its
    network built and judged, where that meets more than :data:`DATUM_SHARE` of the samples
    more; else None (the round as it was)."""
    middle = datum_station(ctx, cand, r)
    if middle is None:
        return None
    say(0.85, "registration: a datum station nearer the middle of the site")
    trial = Round(cover=r.cover, added=np.union1d(r.added, [middle]))
    chosen = np.concatenate([r.net.stations, [middle]])
    trial.net = round_network(ctx, cand, seen, chosen, clock)
    trial.judged = judge(ctx, cand, trial)
    gain = trial.judged.n_met - r.judged.n_met
    return trial if gain > DATUM_SHARE * (~ctx.facades.party_wall).sum() else None


#: The datum station is looked for among at most about this many candidates.
DATUM_POOL = 2000


#: A datum station is tried where the lean keeps more than this share of the samples short
#: (the default site's plan: 1 %, better served by stations added near them; a ten-building
#: block: 35 %, met by one datum station in the middle), and kept where it meets more than
#: this share more.
DATUM_SHARE = 0.05


def estimate_registration(ctx: Context, net: Network, cand: np.ndarray) -> Registration | None:
    """The registration error every candidate would have in ``net``
    (:meth:`Network.estimate`), none for a candidate that could not be tied: one standing
    in open ground no tied station stands in (a closed courtyard) — no station is chosen
    for the registration error where it cannot be tied."""
    est = net.estimate(cand, ctx.station_z(cand))
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


def judge(ctx: Context, cand: np.ndarray, r: Round) -> Judged:
    """Assign every sample its station and judge it on the total error (scanner ⊕
    registration); which samples only the registration keeps from meeting the limits."""
    fac, st = ctx.facades, ctx.settings
    n = len(fac.z)
    if r.net is None:
        a = assign_stations(ctx, np.empty((0, 2)))
        return Judged(a, 0, 0, np.zeros(n, dtype=bool))
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
    return Judged(a, int(met.sum()), len(station_xy), demanded & ~met & scanner_ok, met)


def tightest_mm(ctx: Context) -> float:
    """The tightest accuracy limit of any sample [mm]."""
    lims = np.concatenate([ctx.limits[k] for k in ("m_x", "m_y", "m_z")])
    lims = lims[np.isfinite(lims)]
    return float(lims.min()) if len(lims) else 5.0
