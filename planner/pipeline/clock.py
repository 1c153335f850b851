"""A plan's time budget and where its time went, as one object.

Every stage of a plan (evaluation, diagnosis, optimiser, registration rounds, documents)
shares the settings' ``time_limit_s``. A :class:`Clock` holds the deadline and the seconds
each stage took; the stages are handed the clock instead of a deadline and a dictionary of
timings each. A clock without a deadline (:meth:`Clock.unbounded`) serves the edits by
hand, which are never cut short.
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
    """The deadline of a piece of work (a :func:`time.monotonic` time; ``math.inf``: none),
    when it started (:func:`time.perf_counter`) and the seconds spent per stage."""

    deadline: float = math.inf
    started: float = field(default_factory=time.perf_counter)
    spent_s: dict[str, float] = field(default_factory=dict)

    @classmethod
    def budget(
        cls, limit_s: float, *, deadline: float | None = None, started: float | None = None
    ) -> Clock:
        """A clock running out ``limit_s`` from now, or at ``deadline`` where one is given
        (a plan inside a larger one: a district block, the command's own budget).

        >>> Clock.budget(60.0).left_s() > 59.0
        True
        """
        end = time.monotonic() + limit_s if deadline is None else deadline
        return cls(deadline=end, started=time.perf_counter() if started is None else started)

    @classmethod
    def unbounded(cls) -> Clock:
        """A clock with no deadline (edits by hand are judged whole)."""
        return cls()

    def left_s(self) -> float:
        """Seconds left before the deadline (never negative)."""
        return max(0.0, self.deadline - time.monotonic())

    @property
    def over(self) -> bool:
        """Whether the deadline has passed."""
        return time.monotonic() > self.deadline

    def share(self, fraction: float) -> float:
        """The deadline of a stage that may take ``fraction`` of the time left.

        >>> c = Clock.budget(100.0)
        >>> 49.0 < c.share(0.5) - time.monotonic() <= 50.0
        True
        """
        now = time.monotonic()
        return min(self.deadline, now + fraction * max(0.0, self.deadline - now))

    def sooner(self, seconds: float) -> Clock:
        """This clock running out ``seconds`` earlier, its timings shared: for work that
        must leave time for what follows it whatever the clock says.

        >>> c = Clock.budget(10.0)
        >>> round(c.deadline - c.sooner(2.0).deadline, 6), c.sooner(2.0).spent_s is c.spent_s
        (2.0, True)
        """
        return Clock(deadline=self.deadline - seconds, started=self.started, spent_s=self.spent_s)

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
