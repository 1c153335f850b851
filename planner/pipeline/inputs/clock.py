"""A plan's time budget and where its time went, as one object.

Every stage of a plan (evaluation, diagnosis, optimiser, registration rounds, documents)
shares the settings' ``time_limit_s``. A :class:`Clock` holds the deadline and the seconds
each stage took; the stages are handed the clock instead of a deadline and a dictionary of
timings each. A clock without a deadline (:meth:`Clock.unbounded`) serves the edits by
hand, which are never cut short.

Work that must run after a stage whatever the clock says (the last judgement, the tables,
the files) is reserved at its measured cost on an idle machine, stretched by the *pace*
this process gets: wall seconds per second of its CPU time. On a machine whose cores are
shared with other work everything takes that much longer, and a fixed reserve would let the
plan overrun its budget by as much.
"""

from __future__ import annotations

import math
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field

__all__ = ["Clock", "pace"]

#: The pace (wall seconds per CPU second) a reserve is stretched by at most.
MAX_PACE = 3.0
#: A pace is measured over at least this long [s]; over less it is taken as 1.
MIN_PACE_WINDOW_S = 0.3


def pace(wall_s: float, cpu_s: float) -> float:
    """How many times longer work takes now than with a core to itself: ``wall_s`` over the
    ``cpu_s`` this process had in that time, within 1 … :data:`MAX_PACE` (1 for a window
    shorter than :data:`MIN_PACE_WINDOW_S`, or where threads gave it more CPU than wall).

    >>> pace(3.0, 2.0), pace(3.0, 4.0), pace(0.1, 0.01), pace(10.0, 0.0)
    (1.5, 1.0, 1.0, 3.0)
    """
    if wall_s < MIN_PACE_WINDOW_S:
        return 1.0
    return min(MAX_PACE, max(1.0, wall_s / cpu_s)) if cpu_s > 0 else MAX_PACE


@dataclass
class Clock:
    """The end of a piece of work's time (a :func:`time.monotonic` time; ``math.inf``:
    none), when it started (:func:`time.perf_counter`, and :func:`time.process_time`), the
    seconds it keeps at the end for what must follow it (:meth:`sooner`), and the seconds
    spent per stage."""

    end: float = math.inf
    started: float = field(default_factory=time.perf_counter)
    spent_s: dict[str, float] = field(default_factory=dict)
    reserve_s: float = 0.0
    cpu_started: float = field(default_factory=time.process_time)

    @property
    def deadline(self) -> float:
        """When this clock's work must stop (a :func:`time.monotonic` time): the end, less
        the reserve stretched by the pace so far (:meth:`pace`)."""
        return self.end - self.reserve_s * self.pace() if self.reserve_s else self.end

    def pace(self) -> float:
        """This process's pace since the clock started (:func:`pace`)."""
        wall = time.perf_counter() - self.started
        return pace(wall, time.process_time() - self.cpu_started)

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
        return cls(end=end, started=time.perf_counter() if started is None else started)

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
        now, deadline = time.monotonic(), self.deadline  # (the pace read once)
        return min(deadline, now + fraction * max(0.0, deadline - now))

    def sooner(self, seconds: float) -> Clock:
        """This clock running out ``seconds`` earlier — on an idle machine; as many times
        more as the pace is slower (:meth:`pace`) — its timings shared: for work that must
        leave time for what follows it whatever the clock says.

        >>> c = Clock.budget(10.0)
        >>> round(c.deadline - c.sooner(2.0).deadline, 6), c.sooner(2.0).spent_s is c.spent_s
        (2.0, True)
        """
        return Clock(
            end=self.end,
            started=self.started,
            spent_s=self.spent_s,
            reserve_s=self.reserve_s + seconds,
            cpu_started=self.cpu_started,
        )

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
