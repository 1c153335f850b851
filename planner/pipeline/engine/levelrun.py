"""What a level run buys the plan (:func:`level_run`), in words (:func:`say_level_run`).

Where the plan levelled targets (:mod:`planner.pipeline.network.height`) the network is
judged again without their heights, to say how many samples the run meets; where height
control is off (``--height-control none``) and the network leans (with its datum, or with
its scans' tilt readings combined), it is judged with the run it would take, and the plan
says what that would buy, in its messages and in the reasons of the samples it would
meet.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, replace

import numpy as np
import pandas as pd

from planner.pipeline.engine.judge import Round, judge
from planner.pipeline.engine.result import Plan
from planner.pipeline.engine.tables import DATUM_LEVELLING_FIX
from planner.pipeline.evaluation.evaluate import Context
from planner.pipeline.inputs.schema import id_key
from planner.pipeline.network.height import levelled_targets
from planner.pipeline.network.registration import readjusted

__all__ = ["LevelRun", "level_run", "say_level_run", "with_level_run"]


@dataclass
class LevelRun:
    """A level run and what it buys: its targets (candidate index → height RMS [mm]),
    whether the plan made it (else it is proposed), and the samples met with and without."""

    targets: dict[int, float]
    planned: bool
    met_with: np.ndarray
    met_without: np.ndarray

    @property
    def gain(self) -> int:
        return int(self.met_with.sum() - self.met_without.sum())


def level_run(ctx: Context, cand: np.ndarray, r: Round) -> LevelRun | None:
    """The plan's level run judged against none, or the run the plan would take (height
    control off) judged against none; None where there is nothing to say."""
    net = r.net
    if net is None or not net.adjusted or r.judged is None or r.judged.met is None:
        return None
    if net.ties:  # planned control (a traverse, GNSS) ties and holds this network
        return None
    if net.levelled:
        without = _with_heights(ctx, cand, r, {})
        return LevelRun(net.levelled, True, r.judged.met, without.judged.met)
    if ctx.settings.height_control != "none":  # planned where needed: none was
        return None
    run = with_level_run(ctx, cand, r)
    return None if run is None else LevelRun(run.net.levelled, False, run.judged.met, r.judged.met)


def with_level_run(ctx: Context, cand: np.ndarray, r: Round) -> Round | None:
    """The round ``r`` with the level run its network would take (the targets it placed,
    :func:`~planner.pipeline.network.height.levelled_targets` forced), judged; None where
    the network takes none (it does not lean, it is tied by control, it has too few
    targets). The lean counted with the chain: the run the datum's lean alone did not call
    for may still meet what the two together keep short (a 10-building block: 6.7 of a
    12.5 mm registration error was the datum's lean, 394 samples short in m_z)."""
    net = r.net
    if net is None or not net.adjusted or net.ties or net.levelled or r.judged is None:
        return None
    placed = sorted(int(t) for t in net.targets)  # as the network placed them
    heights = levelled_targets(
        ctx, net.station_xyz, net.datum, net.candidates.xyz, placed, force=True
    )
    return _with_heights(ctx, cand, r, heights) if heights else None


def _with_heights(ctx: Context, cand: np.ndarray, r: Round, heights: dict) -> Round:
    """The round with its network readjusted with the levelled ``heights`` (none: without
    the run it has), judged."""
    other = copy.copy(r.net)
    other.error = replace(r.net.error, pose_cov=readjusted(ctx, r.net.adjusted, heights))
    other.levelled = heights
    out = Round(cover=r.cover, added=r.added, net=other)
    out.judged = judge(ctx, cand, out)
    return out


def say_level_run(p: Plan, run: LevelRun | None, xyz: np.ndarray) -> None:
    """The plan's message on its level run (``xyz``: the target candidates' centres, to
    find the run's targets among the plan's); where the run is proposed, the reasons of the
    samples it would meet name it in place of the general fix. In place."""
    if run is None or (not run.planned and run.gain <= 0):
        return
    ids = _target_ids(p.targets, xyz[list(run.targets)])
    rms = max(run.targets.values())
    what = (
        f"a level run to {len(ids)} target(s), {', '.join(ids)} (each height to {rms:g} mm in "
        "the run's own datum"
        + ("; targets.csv 'height_by', stake-out code -LVL)" if run.planned else ")")
    )
    if run.planned:
        p.messages.append(
            f"Height control: {what} holds the network's vertical: {run.gain} more sample(s) "
            "met than without it."
        )
        return
    p.messages.append(
        f"Height control (not planned: --height-control none): {what} would meet "
        f"{run.gain} more sample(s); --height-control level plans it."
    )
    fix = (
        f"levelling {', '.join(ids[:6])}{' …' if len(ids) > 6 else ''} by a level run: "
        f"{run.gain} more sample(s) met (--height-control level)"
    )
    gained = run.met_with & ~run.met_without
    reason = p.coverage["reason"].to_numpy(dtype=object)
    reason[gained] = [str(t).replace(DATUM_LEVELLING_FIX, fix) for t in reason[gained]]
    p.coverage["reason"] = reason


def _target_ids(targets: pd.DataFrame, xyz: np.ndarray) -> list[str]:
    """The ids of the plan's targets at ``xyz`` (within a millimetre), in id order."""
    at = targets[["x", "y", "z"]].to_numpy(float)
    ids = []
    for x in xyz:
        d = np.linalg.norm(at - x, axis=1)
        if len(d) and d.min() < 1e-3:
            ids.append(str(targets["target_id"].iloc[int(np.argmin(d))]))
    return sorted(ids, key=id_key)
