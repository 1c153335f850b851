"""What no candidate meets, and why: the best achievable value of every check at those
samples (:func:`diagnose`), read by the best-effort stations, the unmet reasons of the plan
and every edit by hand."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planner.pipeline.evaluation.evaluate import CandidateEvaluation, Context, best_achievable
from planner.pipeline.geometry.facades import lower_roof_in_front
from planner.pipeline.inputs.clock import Clock

__all__ = ["Diagnosis", "diagnose"]


@dataclass
class Diagnosis:
    """The best achievable value of every check at the samples no candidate meets
    (:func:`~planner.pipeline.evaluation.evaluate.best_achievable`), computed once per evaluation:
    the best-effort stations and the reasons of the plan and of every edit by hand read it."""

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


def diagnose(ctx: Context, cand: np.ndarray, ev: CandidateEvaluation, clock: Clock) -> Diagnosis:
    """Diagnose the demanded, evaluated samples fewer candidates meet than they need."""
    with clock.timed("diagnosis"):
        n_ok = np.asarray(ev.ok.sum(axis=1)).ravel()
        demanded = ~ctx.facades.party_wall & ev.evaluated
        hopeless = np.flatnonzero(demanded & (n_ok < ctx.stations_needed))
        best = best_achievable(ctx, cand, hopeless) if len(hopeless) else {"done": []}
        roof = lower_roof_in_front(ctx.site, ctx.facades, hopeless)
    n_view = ev.n_view[hopeless]
    if len(hopeless) and not ctx.scene.prisms:  # the evaluation did not count them by rays
        n_view = np.where(best["done"], best["n_view"], n_view)
    return Diagnosis(hopeless, best, n_view, roof)
