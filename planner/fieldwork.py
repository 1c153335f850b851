"""Field time of a scan: points in a scan window, scan time at a measurement rate.

A panoramic scanner steps its two axes by the same angle δ; a scan step of ``s`` mm at 10 m
is δ = s / 10 000 rad (the point spacing square to the beam, :mod:`planner.spacing`). A scan
window of ``w`` degrees across and ``v`` degrees up and down holds ⌈w/δ⌉·⌈v/δ⌉ points and
takes that over the measurement rate (points per second). This is the manufacturers' own
rule behind their resolution tables (e.g. "6.3 mm at 10 m, 360° × 300°: 44 M points");
overheads (the compensator check, photographs) are the station's set-up time, not modelled
here.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from planner._array import as_float_array, check_range, like_input

__all__ = ["scan_points", "scan_time_s", "step_rad"]


def step_rad(step_mm_at_10m: ArrayLike) -> Any:
    """The angular step δ [rad] of a scan step given as point spacing at 10 m [mm].

    >>> round(step_rad(2.0), 6)
    0.0002
    """
    s = check_range(
        as_float_array(step_mm_at_10m, "step_mm_at_10m"),
        "step_mm_at_10m",
        "mm",
        lo=0.0,
        lo_inclusive=False,
    )
    return like_input(s / 10_000.0, step_mm_at_10m)


def scan_points(
    horizontal_deg: ArrayLike, vertical_deg: ArrayLike, step_mm_at_10m: ArrayLike
) -> Any:
    """Points in a scan window ``horizontal_deg`` × ``vertical_deg`` at a scan step.

    >>> int(scan_points(360.0, 135.0, 2.0))  # 31 416 columns × 11 781 rows
    370111896
    """
    w = np.radians(
        check_range(
            as_float_array(horizontal_deg, "horizontal_deg"), "horizontal_deg", "deg", lo=0, hi=360
        )
    )
    v = np.radians(
        check_range(
            as_float_array(vertical_deg, "vertical_deg"), "vertical_deg", "deg", lo=0, hi=360
        )
    )
    d = step_rad(np.asarray(step_mm_at_10m, dtype=float))
    out = np.ceil(w / d - 1e-9) * np.ceil(v / d - 1e-9)
    return like_input(out, horizontal_deg, vertical_deg, step_mm_at_10m)


def scan_time_s(points: ArrayLike, measurement_rate_hz: ArrayLike) -> Any:
    """Seconds to measure ``points`` at ``measurement_rate_hz`` points per second.

    >>> round(scan_time_s(370_111_896, 1_000_000.0))
    370
    """
    n = check_range(as_float_array(points, "points"), "points", "points", lo=0.0)
    rate = check_range(
        as_float_array(measurement_rate_hz, "measurement_rate_hz"),
        "measurement_rate_hz",
        "points/s",
        lo=0.0,
        lo_inclusive=False,
    )
    return like_input(n / rate, points, measurement_rate_hz)
