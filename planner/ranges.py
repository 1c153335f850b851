"""The physical range of every number a user gives, and the one check of it.

A number from a file, a widget or the command line is checked once, where it is read,
against its :class:`Range`: finite, within what the quantity can physically be. A value
outside (``1e308`` mm, ``1e-300`` points a second, a port of 70 000) is an
:class:`~planner.errors.InputError` naming the quantity, its unit and its range — never an
overflow or a division by zero deep in the model. The requirements' and settings' ranges
live with their fields (:mod:`planner.pipeline.inputs.requirements`); the scanner profile's, the
command line's and the server's are in :data:`RANGES`.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from planner.errors import InputError

__all__ = ["RANGES", "Range", "argument", "check_number"]


@dataclass(frozen=True)
class Range:
    """The values a quantity may take: ``lo`` (excluded when ``open_lo``) to ``hi``
    (included), in ``unit``; ``integer`` for a count."""

    lo: float | None
    hi: float | None
    unit: str
    open_lo: bool = False
    integer: bool = False

    def rule(self) -> str:
        """The range in words, e.g. ``> 0 and <= 89``."""
        parts = []
        if self.lo is not None:
            parts.append(f"{'>' if self.open_lo else '>='} {self.lo:g}")
        if self.hi is not None:
            parts.append(f"<= {self.hi:g}")
        return " and ".join(parts) or "any finite number"

    def check(self, value: Any, what: str) -> float:
        """``value`` as a float (an int for a count) if it is in range, else InputError."""
        return check_number(value, what, self)


def check_number(value: Any, what: str, rng: Range) -> Any:
    """The one check of a user's number: a real number (not a bool or text), finite, whole
    for a count, within ``rng``; the message names ``what``, the range and the unit."""
    kind = "a whole number" if rng.integer else "a number"

    def refused() -> InputError:
        return InputError(f"{what} must be {kind} [{rng.unit}] ({rng.rule()}); got {value!r}"[:300])

    plain = type(value) is float or type(value) is int  # the usual case, checked first
    if not plain and (isinstance(value, bool | str | bytes) or np.ndim(value) != 0):
        raise refused()
    try:
        v = float(value)
    except OverflowError:  # an integer beyond any float: out of every range
        v = math.inf if value > 0 else -math.inf
    except (TypeError, ValueError):
        raise refused() from None
    bad = not math.isfinite(v) or (rng.integer and v != round(v))
    if rng.lo is not None:
        bad |= v <= rng.lo if rng.open_lo else v < rng.lo
    if rng.hi is not None:
        bad |= v > rng.hi
    if bad:
        whole = "a whole number " if rng.integer else ""
        raise InputError(f"{what} must be {whole}{rng.rule()} [{rng.unit}]; got {value!r}"[:300])
    return int(v) if rng.integer else v


def argument(name: str) -> Callable[[str], Any]:
    """An argparse ``type=`` that reads a number and checks it against ``RANGES[name]``."""
    rng = RANGES[name]

    def parse(text: str) -> Any:
        try:
            value: Any = int(text) if rng.integer else float(text)
        except ValueError:
            kind = "a whole number" if rng.integer else "a number"
            raise argparse.ArgumentTypeError(
                f"expected {kind} ({rng.rule()}) [{rng.unit}]; got {text!r}"
            ) from None
        try:
            return check_number(value, "the value", rng)
        except InputError as exc:
            raise argparse.ArgumentTypeError(str(exc).removeprefix("the value ")) from None

    parse.__name__ = name  # argparse names the type in its messages
    return parse


#: Ranges of the numbers given outside the requirements and settings: a scanner profile's
#: figures (its datasheet), the command line's options and the dashboard server's.
RANGES: dict[str, Range] = {
    # scanner profile (the best datasheets give 0.1 mm, 1″; the worst 100 mm, 1000″)
    "range_rms_mm": Range(0.01, 1000.0, "mm"),
    "range_ppm": Range(0.0, 10_000.0, "ppm"),
    "angle_rms_arcsec": Range(0.01, 3600.0, "arc-seconds"),
    "levelling_rms_arcsec": Range(0.0, 3600.0, "arc-seconds", open_lo=True),  # ~0: ideal
    "step_mm_at_10m": Range(0.01, 1000.0, "mm"),
    "max_range_m": Range(0.5, 10_000.0, "m"),
    "min_range_m": Range(0.0, 1000.0, "m"),
    "measurement_rate_hz": Range(100.0, 1e8, "points/s"),
    "beam_divergence_mrad": Range(0.001, 100.0, "mrad"),
    "beam_exit_mm": Range(0.01, 1000.0, "mm"),
    "imaging_s": Range(0.0, 86_400.0, "s"),
    "setup_min": Range(0.0, 1440.0, "min", open_lo=True),
    "start_position_mm": Range(0.0, 10_000.0, "mm", open_lo=True),
    "start_heading_arcsec": Range(0.0, 648_000.0, "arc-seconds", open_lo=True),
    "scan_s": Range(1.0, 86_400.0, "s"),
    "reflectance": Range(0.0, 1.0, "fraction of 1", open_lo=True),  # a surface's, 0–1
    "ranging_exponent": Range(0.0, 3.0, ""),  # k of m_S ∝ q^(−k); 0: no signal dependence
    # targets and control points (the largest spheres and boards are 450 mm; a control
    # network's point is known to better than a decimetre, not better than 10 µm)
    "target_size_mm": Range(1.0, 2000.0, "mm"),
    "control_rms_mm": Range(0.01, 100.0, "mm"),
    # command line
    "distance_m": Range(0.0, 10_000.0, "m", open_lo=True),
    "angle_deg": Range(-90.0, 90.0, "deg"),
    "height_m": Range(0.0, 1000.0, "m", open_lo=True),
    "storey_height_m": Range(0.0, 20.0, "m", open_lo=True),
    "site_limit_m": Range(0.0, 1e7, "m", open_lo=True),
    "offset_m": Range(-1e8, 1e8, "m"),
    "rms_mm": Range(0.0, 1000.0, "mm"),
    "block_m": Range(20.0, 100_000.0, "m"),
    "workers": Range(1, 256, "processes", integer=True),
    "coverage_factor": Range(0.0, 10.0, "", open_lo=True),
    "beams_per_station": Range(1000, 100_000_000, "beams", integer=True),
    "seed": Range(0, 2**32 - 1, "", integer=True),
    # dashboard server
    "port": Range(1, 65_535, "TCP port", integer=True),
    "kernel_idle_s": Range(1.0, 1e7, "s"),
}
