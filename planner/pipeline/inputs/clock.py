"""A plan's time budget and where its time went, as one object.

A plan is decided by work, not by the clock: the evaluation, the diagnosis, the
registration network and its rounds run whole, each bounded by counts (samples ×
candidates, rounds, pairs tried), so the same inputs give the same plan on an idle desktop
and on a loaded laptop. The settings' ``time_limit_s`` only stops the optimiser's search
for a smaller cover (itself bounded by iterations and nodes, :mod:`planner.pipeline.optimise.cover`)
on a machine too slow for those bounds; the plan then says it may differ from a longer run.

A :class:`Clock` holds that end (read by the optimiser alone, :meth:`Clock.left_s`) and
the seconds each stage took; the stages are handed the clock instead of a dictionary of
timings each. A clock without an end (:meth:`Clock.unbounded`) serves the edits by hand.
"""

from __future__ import annotations

import math
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field

__all__ = ["Clock"]


@dataclass
class Clock:
    """The end of a piece of work's time (a :func:`time.monotonic` time; ``math.inf``:
    none), when it started (:func:`time.perf_counter`) and the seconds spent per stage."""

    end: float = math.inf
    started: float = field(default_factory=time.perf_counter)
    spent_s: dict[str, float] = field(default_factory=dict)

    @classmethod
    def unbounded(cls) -> Clock:
        """A clock with no deadline (edits by hand are judged whole)."""
        return cls()

    def left_s(self) -> float:
        """Seconds left before the end (never negative; infinite without one): a plan
        inside a larger schedule caps its optimiser's backstop by it — nothing else of a plan
        reads it.

        >>> Clock(end=time.monotonic() + 60.0).left_s() > 59.0
        True
        """
        return max(0.0, self.end - time.monotonic())

    def note(self, stage: str, seconds: float) -> None:
        """Count ``seconds`` to ``stage`` (a stage may run several times)."""
        self.spent_s[stage] = self.spent_s.get(stage, 0.0) + seconds

    @contextmanager
    def timed(self, stage: str) -> Iterator[None]:
        """Count the time the ``with`` block takes to ``stage``.

        >>> c = Clock.unbounded()
        >>> with c.timed("route"):
        ...     pass
        >>> list(c.spent_s)
        ['route']
        """
        t = time.perf_counter()
        try:
            yield
        finally:
            self.note(stage, time.perf_counter() - t)

    def timings(self) -> dict[str, float]:
        """The seconds per stage and ``total`` since the clock started."""
        return {**self.spent_s, "total": time.perf_counter() - self.started}
