"""Point spacing of a scan: d(D) from the scan step (Sossa, Table 1), and on a facade.

Reference: B. R. Sossa, "Determination of optimal type and size of plane-based targets used
in terrestrial laser scanners calibration", Inzhenerna heodeziia 65 (2018), Table 1 (full
citation in :data:`planner.reference.REFERENCES`; explained in ``docs/science.md``).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from planner._array import as_float_array, check_range, like_input
from planner.errors import InputError
from planner.scanner import Scanner

__all__ = [
    "facade_point_spacing_mm",
    "facade_spacing_kernel",
    "point_spacing_mm",
    "resolve_step_mm",
]

#: Below this cosine a beam is taken as grazing: the spacing along it is infinite.
GRAZING_COS = 1e-12


def resolve_step_mm(
    scanner: Scanner | None, step_mm_at_10m: float | None, default: float | None = None
) -> float:
    """The scan step at 10 m [mm]: given explicitly, else the scanner's, else ``default``."""
    if step_mm_at_10m is None:
        if scanner is not None:
            return scanner.step_mm_at_10m
        if default is not None:
            return default
        raise InputError("give a scanner or step_mm_at_10m (the scan step at 10 m, in mm)")
    step = as_float_array(step_mm_at_10m, "step_mm_at_10m")
    if step.ndim != 0 or not np.isfinite(step) or step <= 0:
        raise InputError(f"step_mm_at_10m must be one number > 0 [mm]; got {step_mm_at_10m!r}")
    return float(step)


def point_spacing_mm(
    distance_m: ArrayLike, scanner: Scanner | None = None, *, step_mm_at_10m: float | None = None
) -> Any:
    """Spacing d of neighbouring points square to the beam [mm]: ``d = step_10m · D / 10 m``.

    Sossa, Table 1: with a 2 mm step at 10 m, d = 10 mm at 50 m … 70 mm at 350 m.

    Examples
    --------
    >>> point_spacing_mm([50, 350], step_mm_at_10m=2.0).tolist()
    [10.0, 70.0]
    """
    step = resolve_step_mm(scanner, step_mm_at_10m)
    d = check_range(as_float_array(distance_m, "distance_m"), "distance_m", "m", lo=0.0)
    return like_input(step * d / 10.0, distance_m)


def facade_point_spacing_mm(
    slope_distance_m: ArrayLike,
    gamma_deg: ArrayLike,
    nu_deg: ArrayLike,
    scanner: Scanner | None = None,
    *,
    step_mm_at_10m: float | None = None,
) -> Any:
    """Largest spacing of neighbouring points on a vertical facade [mm].

    A panoramic scanner steps both angles by δ = step_10m / 10 m. On a vertical facade the
    horizontal spacing is ``D·δ / cos γ`` (D = S·cos ν the horizontal distance, γ the
    deviation from the facade normal) and the vertical spacing ``S·δ / cos ν``; the larger
    is returned. Square to the facade (γ = ν = 0) it is Sossa's d(S). Grazing beams
    (|γ| or |ν| → 90°) give infinite spacing.
    """
    step = resolve_step_mm(scanner, step_mm_at_10m)
    s = check_range(
        as_float_array(slope_distance_m, "slope_distance_m"), "slope_distance_m", "m", lo=0.0
    )
    g = np.radians(
        check_range(
            as_float_array(gamma_deg, "gamma_deg"), "gamma_deg", "deg", hi=90.0, absolute=True
        )
    )
    nu = np.radians(
        check_range(as_float_array(nu_deg, "nu_deg"), "nu_deg", "deg", hi=90.0, absolute=True)
    )
    out = facade_spacing_kernel(s * np.cos(nu), s, np.cos(g), step)
    out = np.where(np.isnan(s) | np.isnan(g) | np.isnan(nu), np.nan, out)
    return like_input(out, slope_distance_m, gamma_deg, nu_deg)


def facade_spacing_kernel(
    distance_m: np.ndarray,
    slope_distance_m: np.ndarray,
    cos_gamma: np.ndarray,
    step_mm_at_10m: float,
) -> np.ndarray:
    """The array kernel of :func:`facade_point_spacing_mm` (no validation; the planner's hot
    path calls it): ``δ·max(D / cos γ, S² / D)`` [mm] with δ = step / 10 m, S²/D = S / cos ν.
    Infinite where the beam grazes the facade (cos γ or cos ν below :data:`GRAZING_COS`)."""
    delta = step_mm_at_10m / 10.0  # mm per metre of distance
    with np.errstate(divide="ignore", invalid="ignore"):
        horizontal = np.where(cos_gamma > GRAZING_COS, distance_m / cos_gamma, np.inf)
        vertical = np.where(
            distance_m > GRAZING_COS * slope_distance_m,
            slope_distance_m * slope_distance_m / distance_m,
            np.inf,
        )
    out = delta * np.maximum(horizontal, vertical)
    return np.where(slope_distance_m == 0.0, 0.0, out)  # at the scanner itself
