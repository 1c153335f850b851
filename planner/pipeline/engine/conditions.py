"""The plan on another survey day: the same stations judged with the walls' reflectance of
a wet (or dry) day (:mod:`planner.materials`), so the plan can say what rain would cost —
"with wet walls, 110 of the samples met need a nearer station"."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from planner.materials import reflectances
from planner.pipeline.engine.judge import Round, judge, workbench_of
from planner.pipeline.engine.result import Plan

__all__ = ["condition_sensitivity", "condition_words"]


def condition_sensitivity(p: Plan, condition: str) -> tuple[int, int] | None:
    """The plan's stations and registration judged on a survey day of ``condition``
    (:data:`planner.materials.CONDITIONS`: porous walls darker when wet): the samples met
    then and the samples met as planned — e.g. "with wet walls, 37 more samples need a
    nearer station". None where the plan keeps no workbench or no wall's material changes
    with the day (no material known: the datasheet's reference surface has no wet figure).
    The registration is the plan's (its cloud links' patches are not judged again)."""
    wb = workbench_of(p)
    if wb is None or p.network is None:
        return None
    ctx = wb.ctx
    other = reflectances(ctx.material, ctx.settings.material_table, condition)
    if np.array_equal(other, ctx.reflectance, equal_nan=True):
        return None
    day = replace(ctx, reflectance=other)
    judged = judge(day, wb.pool, Round(cover=p.network.stations, net=p.network))
    return judged.n_met, int(p.coverage["meets"].sum())


def condition_words(p: Plan) -> str | None:
    """The plan's survey day and what the other would cost, in words (None where no wall's
    material changes with the day)."""
    day = p.settings.surface_condition
    other = "dry" if day == "wet" else "wet"
    found = condition_sensitivity(p, other)
    if found is None:
        return None
    then, now = found
    if other == "wet":
        lost = now - then
        ctx = workbench_of(p).ctx
        wet = reflectances(ctx.material, p.settings.material_table, "wet")
        known = np.isfinite(wet) & (ctx.reflectance > 0)
        darker = 1.0 - float(np.median(wet[known] / ctx.reflectance[known]))
        return (
            f"Survey day: dry. With wet walls (their materials {darker:.0%} darker) the same "
            f"stations meet {then} of the {now} samples met dry"
            + (f": {lost} would need a nearer station." if lost > 0 else ": none lost.")
            + " Plan with --surface-condition wet to survey after rain."
        )
    more = f"{then - now} more than wet" if then > now else "as many as wet"
    return f"Survey day: wet. On a dry day the same stations meet {then} samples ({more})."
