"""What-if by hand: the surveyor moves, adds, deletes or locks stations, and the plan is
judged again — coverage, accuracy with the registration error, targets and links — without
planning from scratch.

Both functions work on a plan made in this process
(:func:`~planner.pipeline.engine.judge.workbench_of` holds what it was made from: samples, candidate
grid, target candidates and what each position sees of them, so that a re-evaluation only computes
what changed):

* :func:`evaluate_stations` — exactly these stations (no optimiser), judged as a plan is;
* :func:`edit_targets` — the same stations, targets ruled out, moved or added by hand;
* :func:`reoptimise` — keep the locked stations and choose the fewest others around them.

Target edits stay with the plan's workbench: a target ruled out stays out, and one placed by
hand stays offered, for every later edit and re-optimisation of that plan.
"""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np

from planner.errors import InputError
from planner.pipeline.engine.ids import GivenIds, ids_at
from planner.pipeline.engine.judge import (
    Round,
    Workbench,
    assemble,
    free_positions,
    judge,
    round_network,
    workbench_of,
)
from planner.pipeline.engine.planning import choose_stations
from planner.pipeline.engine.result import Plan, SolverReport
from planner.pipeline.evaluation.evaluate import Progress
from planner.pipeline.inputs.clock import Clock
from planner.pipeline.network.targets import TargetCandidates

__all__ = [
    "edit_targets",
    "evaluate_stations",
    "reoptimise",
    "user_edits",
]


def _workbench(p: Plan) -> Workbench:
    wb = workbench_of(p)
    if wb is None:
        raise InputError(
            "this plan keeps nothing to edit (a district plan, or one read back from its "
            "files); plan the site again in this session to move stations by hand"
        )
    return wb


def evaluate_stations(
    p: Plan, xy: np.ndarray, ids: list[str | None] | tuple[str | None, ...] | None = None
) -> Plan:
    """The plan with stations exactly at ``xy`` (``(k, 2)`` [m], site CRS): the registration
    network built for them, every sample judged on scanner ⊕ registration, targets, links and
    the route. A position inside a building, obstacle or no-go area is an
    :class:`~planner.errors.InputError` saying which. The registration network may add a
    station where it needs one to tie the others (its purpose is "link").

    ``ids`` names the station each position was (``None`` for one added; an id the plan
    does not have is kept, as for a station added on site); without it a position the plan
    already has a station at is that station. A station keeps its id
    through edits, and its purpose where it has not moved; one moved or added is "hand", and
    an added station takes the next number never given (a deleted station's id is not given
    again)."""
    t0 = time.perf_counter()
    wb = _workbench(p)
    xy = np.asarray(xy, dtype=float).reshape(-1, 2)
    scans = p.scan_stations
    old_xy = scans[["x", "y"]].to_numpy(dtype=float)
    by_id = dict(zip(scans["station_id"], range(len(scans)), strict=True))
    if ids is None:
        ids = _ids_at(p, xy)
    if len(ids) != len(xy):
        raise InputError(f"{len(ids)} station ids for {len(xy)} positions: give one per position")
    # a traverse's set-ups are the total station's: planned again with the network, not here
    traverse = set(p.stations["station_id"]) - set(scans["station_id"])
    keep = [sid not in traverse for sid in ids]
    xy, ids = xy[keep], [sid for sid, k in zip(ids, keep, strict=True) if k]
    xy = free_positions(wb, xy, "station")
    _apart(xy, ids)
    idx = wb.add_positions(xy)
    kept, hand = {}, []
    for i, sid, q in zip(idx.tolist(), ids, xy, strict=True):
        j = by_id.get(sid) if sid else None
        if j is None:
            hand.append(i)
            if sid:  # an id the plan does not have (a station added on site): it keeps it
                kept[i] = (str(sid), "hand")
            continue
        moved = bool(np.abs(old_xy[j] - q).max() >= 1e-3)
        kept[i] = (str(sid), "hand" if moved else str(scans["purpose"].iloc[j]))
        if moved:
            hand.append(i)
    message = f"Stations edited by hand: {len(xy)} judged again."
    return _judged(p, wb, idx, np.array(hand, dtype=np.int64), message, t0, kept)


#: Two stations closer than this [m] are one set-up twice: an edit that does it is refused.
MIN_STATION_SEPARATION_M = 0.5


def one_setup_twice(xy: np.ndarray) -> tuple[int, int, float] | None:
    """The closest two of the positions ``xy`` (k, 2) [m] where they stand closer than
    :data:`MIN_STATION_SEPARATION_M` (one set-up twice): their indices and distance [m];
    None where no two do."""
    xy = np.asarray(xy, dtype=float).reshape(-1, 2)
    if len(xy) < 2:
        return None
    d = np.hypot(*(xy[:, None, :] - xy[None, :, :]).transpose(2, 0, 1))
    d[np.tri(len(xy), dtype=bool)] = np.inf
    a, b = np.unravel_index(int(np.argmin(d)), d.shape)
    return (int(a), int(b), float(d[a, b])) if d[a, b] < MIN_STATION_SEPARATION_M else None


def _apart(xy: np.ndarray, ids) -> None:
    """An :class:`~planner.errors.InputError` naming the stations two positions put on top
    of each other."""
    pair = one_setup_twice(xy)
    if pair is not None:
        a, b, d = pair
        names = [ids[k] or "the new station" for k in (a, b)]
        raise InputError(
            f"{names[1]} would stand {d:.2f} m from {names[0]} (closer than "
            f"{MIN_STATION_SEPARATION_M:g} m: one set-up twice); put it elsewhere"
        )


def _ids_at(p: Plan, xy: np.ndarray) -> list[str | None]:
    """The id of the plan's station at each position (to the millimetre; each id once, a
    scanning station before a traverse set-up on the same spot), None where it has none."""
    order = p.stations.sort_values("purpose", key=lambda s: s.eq("traverse"), kind="stable")
    return ids_at(order[["x", "y"]].to_numpy(float), order["station_id"].astype(str).tolist(), xy)


def _judged(
    p: Plan,
    wb: Workbench,
    idx: np.ndarray,
    hand: np.ndarray,
    message: str,
    t0: float,
    kept: dict[int, tuple[str, str]] | None = None,
) -> Plan:
    """The plan of the stations ``idx`` (pool indices; ``hand`` placed by hand; ``kept``
    those that keep their id and purpose), their network built and every sample judged."""
    clock = Clock(started=t0)  # (an edit is judged whole: no deadline)
    r = Round(cover=idx)
    datum = p.network.datum_station if p.network is not None else None  # kept where it stays
    datum = datum if datum is not None and datum in set(np.asarray(idx).tolist()) else None
    r.net = round_network(wb.ctx, wb.pool, wb.seen, idx, clock, datum) if len(idx) else None
    r.judged = judge(wb.ctx, wb.pool, r)
    bound = p.solver.lower_bound
    n = len(r.net.stations) if r.net is not None else 0
    solver = SolverReport(
        method="hand placement",
        status="stations placed by hand",
        objective=n,
        lower_bound=bound,
        gap=None if bound is None or n == 0 else max(0.0, (n - bound) / n),
    )
    messages = [*wb.messages, message]
    given = wb.given(p)
    return assemble(wb, r, solver, messages, clock, hand=hand, kept=kept, given=given)


def _target_index(wb: Workbench, p: Plan, target_id: str) -> int:
    """The target candidate of the plan's target ``target_id`` (found by its position)."""
    row = p.targets[p.targets["target_id"] == target_id]
    if row.empty:
        known = ", ".join(p.targets["target_id"]) or "none"
        raise InputError(f"the plan has no target {target_id!r} (its targets: {known})")
    xyz = row[["x", "y", "z"]].to_numpy(dtype=float)[0]
    same = np.flatnonzero(np.all(np.abs(wb.tc.xyz - xyz) < 1e-6, axis=1))
    return int(same[0])


def edit_targets(
    p: Plan,
    *,
    remove: tuple[str, ...] | list[str] = (),
    move: dict[str, tuple[float, float]] | None = None,
    add_xy: np.ndarray | None = None,
) -> Plan:
    """The plan's stations kept and its targets edited by hand, the network built again and
    every sample judged on scanner ⊕ registration.

    ``remove`` (target ids) are ruled out: no link may use them (a wall that takes no
    target, a stand that cannot go there). ``move`` (target id → E, N [m]) rules the old
    place out and offers the new one: a flat target slides along its own wall at its
    height, a sphere stands where it is put. ``add_xy`` (``(k, 2)`` [m]) offers spheres on
    stands there. Targets placed by hand are preferred by every link that can use them
    (the network still chooses: a target no pair of stations sees is not used, and the
    plan says how many of them are). A control point cannot move (it is a surveyed mark);
    it can be ruled out.
    """
    t0 = time.perf_counter()
    wb = _workbench(p)
    n_added = edit_candidates(p, remove=remove, move=move, add_xy=add_xy)
    scans = p.scan_stations
    idx = wb.add_positions(scans[["x", "y"]].to_numpy(dtype=float))
    kept = {
        i: (str(sid), str(pu))
        for i, sid, pu in zip(idx.tolist(), scans["station_id"], scans["purpose"], strict=True)
    }
    hand = idx[(scans["purpose"] == "hand").to_numpy()]
    done = [f"{len(remove)} ruled out"] if remove else []
    done += [f"{len(move)} moved"] if move else []
    done += [f"{n_added} added"] if n_added else []
    q = _judged(p, wb, idx, hand, f"Targets edited by hand: {', '.join(done)}.", t0, kept)
    q.solver = replace(p.solver, objective=q.solver.objective)
    mine = int(wb.seen.by_hand.sum())
    if mine:
        used = q.network.targets if q.network is not None else []
        n_used = int(wb.seen.by_hand[used].sum())
        q.messages.append(
            "Targets placed or moved by hand in this plan's edits: "
            f"{n_used} of {mine} used by the registration"
            + ("" if n_used == mine else " (the others no pair of stations needs or sees)")
            + "."
        )
    return q


def edit_candidates(
    p: Plan,
    *,
    remove: tuple[str, ...] | list[str] = (),
    move: dict[str, tuple[float, float]] | None = None,
    add_xy: np.ndarray | None = None,
) -> int:
    """:func:`edit_targets`' edits made to the target candidates of ``p``'s workbench,
    without judging the plan again (the caller judges): the old places barred, the new
    ones offered as placed by hand. Returns the number of spheres added."""
    wb = _workbench(p)
    tc, st, fac = wb.tc, wb.settings, wb.ctx.facades
    out = [_target_index(wb, p, t) for t in remove]
    n_added = 0
    rows: list[tuple[list[float], str, list[float], int]] = []  # xyz, type, normal, facade
    for target_id, (e, n) in (move or {}).items():
        t = _target_index(wb, p, target_id)
        if tc.type[t] == "control":
            raise InputError(
                f"{target_id} is a control point, a surveyed mark: it cannot move (rule it "
                "out instead, and add a sphere where you want one)"
            )
        out.append(t)
        if tc.type[t] == "flat":  # along its own wall, at its height
            f = int(tc.facade[t])
            a, b = fac.start[f], fac.end[f]
            u = float(np.clip(np.dot([e, n] - a, b - a) / np.dot(b - a, b - a), 0.02, 0.98))
            rows.append(([*(a + u * (b - a)), tc.xyz[t, 2]], "flat", list(tc.normal[t]), f))
        else:
            (xy,) = free_positions(wb, [e, n], f"target stand of {target_id}")
            rows.append(([*xy, st.target_height_m], str(tc.type[t]), [0.0, 0.0], -1))
    if add_xy is not None and len(np.asarray(add_xy).reshape(-1, 2)):
        if not any(i.type == "sphere" for i in st.inventory):
            raise InputError(
                "a target placed by hand stands on a tripod as a sphere, and your inventory "
                "holds no sphere; add one to the inventory (e.g. 'S145, sphere, 145')"
            )
        for xy in free_positions(wb, add_xy, "target stand"):
            rows.append(([*xy, st.target_height_m], "sphere", [0.0, 0.0], -1))
            n_added += 1
    wb.seen.barred[out] = True
    if rows:
        wb.seen.add_targets(
            TargetCandidates(
                xyz=np.array([r[0] for r in rows], dtype=float),
                type=np.array([r[1] for r in rows], dtype=object),
                normal=np.array([r[2] for r in rows], dtype=float),
                facade=np.array([r[3] for r in rows], dtype=np.int64),
                control_id=np.array([""] * len(rows), dtype=object),
                control_rms_mm=np.full(len(rows), np.nan),
            )
        )
    return n_added


def reoptimise(p: Plan, locked_xy: np.ndarray, progress: Progress | None = None) -> Plan:
    """A new plan keeping the stations at ``locked_xy`` (``(k, 2)`` [m]) and those placed by
    hand (:func:`user_edits`), and choosing the fewest others around them, with the
    registration rounds of a full plan (the settings' time budget). Ids stay
    (:mod:`planner.pipeline.engine.ids`): the kept stations keep theirs, and so does every
    station or target the new plan has where ``p`` had one; a new one takes a number never
    given."""
    wb = _workbench(p)
    given, keep = user_edits(p, locked_xy)
    return choose_stations(wb, progress, locked=keep, locked_ids=_ids_at(p, keep), given=given)


def user_edits(p: Plan, locked_xy: np.ndarray | None = None) -> tuple[GivenIds, np.ndarray]:
    """What a plan made from ``p`` keeps of the surveyor's work: the ids ``p`` gave (with the
    numbers its workbench ever gave) and the positions ``(k, 2)`` [m] to keep — the stations
    locked (``locked_xy``) and those placed by hand (purpose "hand"), each once."""
    wb = workbench_of(p)
    given = wb.given(p) if wb is not None else GivenIds.of(p.scan_stations, p.targets)
    scans = p.scan_stations
    hand = scans[scans["purpose"] == "hand"][["x", "y"]].to_numpy(float)
    locked = np.empty((0, 2)) if locked_xy is None else np.asarray(locked_xy, float)
    keep = np.vstack([locked.reshape(-1, 2), hand])
    return given, keep[np.sort(np.unique(np.round(keep, 3), axis=0, return_index=True)[1])]
