"""Targets within the kit: the crew's inventory as a constraint of the plan, not a remark.

A plan's targets stand, as planned, from the first scan that sees them to the last: the
registration's adjustment counts every scan's sight of a target
(:func:`planner.registration_error.adjust`). Where that is more of an item than the crew
owns (:attr:`planner.targets.TargetItem.count`), the targets of that item **leap-frog**: each
stands over a window of consecutive set-ups of the visiting order — from the first scan of
the links that use it to their last — and is then collected and set up again further on
(as another target); the adjustment counts its sightings within its window only, and the
plan is judged again on that (:func:`within_kit`). The route and the booklet then say where
each target goes up and comes down (the route's ``targets_set``/``targets_collected``), and
the plan says what the leap-frogging costs in samples met, or, where even leap-frogged the
kit cannot serve, what it would take.
"""

from __future__ import annotations

import copy
from dataclasses import replace
from typing import Any

import numpy as np

from planner.pipeline.engine.judge import Round, judge, round_network
from planner.pipeline.engine.result import Plan
from planner.pipeline.evaluation.evaluate import Context
from planner.pipeline.network.network import Network
from planner.pipeline.network.registration import readjusted
from planner.pipeline.network.targets import SightCache
from planner.registration_error import CONTROL

__all__ = ["leapfrogged", "over_kit", "within_kit"]


def over_kit(p: Plan) -> list[str]:
    """The inventory items of which more stand at once than the crew owns (kit rows with a
    count)."""
    kit = p.route.kit if p.route is not None else None
    if kit is None or not len(kit):
        return []
    over = kit[(kit["owned"] > 0) & (kit["most_at_once"] > kit["owned"])]
    return over["item"].astype(str).tolist()


def leapfrogged(net: Network, items: dict[int, str], limited: set[str], visit: list[int]) -> dict:
    """The network's observations with the targets of the ``limited`` items seen only
    within their windows (module text): ``items`` each target's item (network target
    index → name), ``visit`` each network station's position in the visiting order."""
    users: dict[int, set[int]] = {}
    for lk in net.links:
        for t in lk.targets:
            users.setdefault(t, set()).update(s for s in (lk.parent, lk.child) if s != CONTROL)
    window = {
        t: (min(visit[s] for s in who), max(visit[s] for s in who))
        for t, who in users.items()
        if who and items.get(t) in limited
    }
    return {
        (j, t): rms
        for (j, t), rms in net.centre_rms.items()
        if t not in window or window[t][0] <= visit[j] <= window[t][1]
    }


def within_kit(
    ctx: Context, cand: np.ndarray, seen: SightCache, r: Round, p: Plan, remake: Any
) -> tuple:
    """The round and plan within the crew's kit (module text) and what that took, in words:
    first the targets of every item over the kit leap-frogged over their links' windows;
    where that is not enough, the network laid out again as a leap-frogging traverse — links
    only between set-ups next to each other in the visiting order, each of at most half the
    smallest count of an item the plan runs short of, and at least 3 (a link needs three) —
    and its targets leap-frogged. Each is judged again and the plan
    made anew by ``remake(round)``; the first within the kit that meets as many samples is
    the plan. Where none does, the plan keeps its network and the words say what staying
    within the kit would cost in samples, or stand at once (the route's kit line says what
    to bring)."""
    limited = over_kit(p)
    if not limited or r.net is None or not len(r.net.links):
        return r, p, ""
    before = int(r.judged.n_met)
    items = ", ".join(limited)
    how = (
        "each target stands from the first to the last scan of the links that use it, then "
        "moves on, and the registration counts only those sightings"
    )
    again, q = _leapfrog(ctx, cand, r, p, remake, limited)
    if over_kit(q) or again.judged.n_met < before:  # a traverse along the visiting order
        owned = p.route.kit.set_index("item")["owned"]
        cap = max(3, int(min(owned[i] for i in limited)) // 2)
        chain = list(np.argsort(_visit_positions(q)))
        again = Round(cover=r.cover, added=r.added)
        again.net = round_network(
            ctx, cand, seen, r.net.stations, datum=r.net.datum_station, kit=(chain, cap)
        )
        how = (
            "the network is a traverse along the visiting order, each link on at most "
            f"{cap} targets set up between its two set-ups, then moved on"
        )
        if again.net is None or not len(again.net.links):
            return r, p, ""
        again.judged = judge(ctx, cand, again)
        again, q = _leapfrog(ctx, cand, again, remake(again), remake, limited)
        after = int(again.judged.n_met)
        if over_kit(q) or after < before:
            cost = (
                f"{_peak(q, limited)} would still stand at once"
                if over_kit(q)
                else f"{after} samples would be met instead of {before}"
            )
            return r, p, (
                f"Kit: no layout within the kit meeting as many samples was found for the "
                f"{items} — leap-frogged as a traverse along the visiting order, at most "
                f"{cap} targets a link, {cost}; the plan keeps its network (the field time "
                "says what to bring)."
            )  # fmt: skip
    words = (
        f"Kit: the {items} leap-frog to stay within the kit — {how}: "
        f"{int(again.judged.n_met)} samples met, as with every target standing from its "
        "first sight to its last."
    )
    return again, q, words


def _peak(p: Plan, limited: list[str]) -> int:
    kit = p.route.kit
    return int(kit.loc[kit["item"].isin(limited), "most_at_once"].max())


def _leapfrog(ctx: Context, cand: np.ndarray, r: Round, p: Plan, remake: Any, limited) -> tuple:
    """The round and plan with the ``limited`` items' targets seen only within their
    windows, judged again (the round and plan as they were if nothing changes, or where
    planned control ties groups of the network: their registrations are adjusted apart)."""
    net = r.net
    if net.ties:  # planned control ties groups registered apart: not adjusted again here
        return r, p
    seen = leapfrogged(net, _items(p, net), set(limited), _visit_positions(p))
    if len(seen) == len(net.centre_rms):
        return r, p
    other = copy.copy(net)
    other.centre_rms = seen
    if net.adjusted:  # the adjustment counts only the sightings within the windows
        inputs = dict(net.adjusted, target_rms_mm=seen)
        other.adjusted = inputs
        other.error = replace(net.error, pose_cov=readjusted(ctx, inputs, net.levelled))
    again = Round(cover=r.cover, added=r.added, net=other)
    again.judged = judge(ctx, cand, again)
    return again, remake(again)


def _visit_positions(p: Plan) -> list[int]:
    """Each network station's position in the plan's visiting order."""
    position = {sid: n for n, sid in enumerate(p.route.table["station_id"].astype(str))}
    return [position.get(sid, len(position)) for sid in p.network_ids()]


def _items(p: Plan, net: Network) -> dict[int, str]:
    """Each placed target's inventory item, by network target index (the targets table's
    ``item``, matched by position)."""
    xyz = net.candidates.xyz
    out = {}
    for r in p.targets.itertuples():
        if r.item:
            out[int(np.argmin(np.linalg.norm(xyz - [r.x, r.y, r.z], axis=1)))] = str(r.item)
    return out
