"""Polar measurement geometry: eq. 1 of Voroshilov & Karachentsev, and D, S, γ, ν from coordinates.

Coordinates are metres in any right-handed frame with z up (a projected CRS plus height).
Arrays broadcast: points as ``(..., 3)``, horizontal vectors as ``(..., 2)``.
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from planner._array import as_float_array, check_range, like_input
from planner.errors import InputError

__all__ = [
    "SightGeometry",
    "deviation_angle_deg",
    "horizontal_distance_m",
    "incidence_deg",
    "polar_to_xyz",
    "separated_directions",
    "sight_geometry",
    "slope_distance_m",
    "tilt_deg",
]


def _xyz(a: ArrayLike, name: str, dim: int) -> np.ndarray:
    arr = as_float_array(a, name)
    if arr.ndim == 0 or arr.shape[-1] != dim:
        raise InputError(
            f"{name} must have {dim} coordinates in its last axis; got shape {arr.shape}"
        )
    return arr


def polar_to_xyz(
    station_xyz: ArrayLike,
    alpha0_deg: ArrayLike,
    beta_deg: ArrayLike,
    slope_distance_m: ArrayLike,
    nu_deg: ArrayLike,
    instrument_height_m: ArrayLike = 0.0,
) -> np.ndarray:
    """Point coordinates from one station's polar measurement — eq. 1 of Voroshilov & Karachentsev.

    ``x = x_c + D·cos(α0 + β)``, ``y = y_c + D·sin(α0 + β)``, ``z = z_c + S·sin ν + i_c``
    with ``D = S·cos ν``. Angles are counted from the x axis towards y (the paper's
    convention), α0 the direction of the scanner's initial direction, β the horizontal angle.

    Returns an array of shape ``(..., 3)``.
    """
    st = _xyz(station_xyz, "station_xyz", 3)
    a = np.radians(as_float_array(alpha0_deg, "alpha0_deg") + as_float_array(beta_deg, "beta_deg"))
    s = as_float_array(slope_distance_m, "slope_distance_m")
    nu = np.radians(as_float_array(nu_deg, "nu_deg"))
    d = s * np.cos(nu)
    ic = as_float_array(instrument_height_m, "instrument_height_m")
    x = st[..., 0] + d * np.cos(a)
    y = st[..., 1] + d * np.sin(a)
    z = st[..., 2] + s * np.sin(nu) + ic
    return np.stack(np.broadcast_arrays(x, y, z), axis=-1)


#: :func:`slope_distance_m` holds cos ν at least this, so a vertical beam gives a finite S.
MIN_COS_TILT = 1e-9


def slope_distance_m(distance_m: ArrayLike, nu_deg: ArrayLike) -> Any:
    """Slope distance S [m] from the horizontal distance D [m] and the tilt ν [deg]:
    ``D = S·cos ν`` of eq. 1 (Voroshilov & Karachentsev) solved for S, ``S = D / cos ν``
    (cos ν held at :data:`MIN_COS_TILT` at least). ``inf`` and NaN distances pass through.

    Examples
    --------
    >>> slope_distance_m([10.0, 10.0, float("inf")], [0.0, 60.0, 30.0]).round(6).tolist()
    [10.0, 20.0, inf]
    """
    d = as_float_array(distance_m, "distance_m")
    nu = check_range(as_float_array(nu_deg, "nu_deg"), "nu_deg", "deg", hi=90.0, absolute=True)
    return like_input(d / np.maximum(np.cos(np.radians(nu)), MIN_COS_TILT), distance_m, nu_deg)


def horizontal_distance_m(slope_distance_m: ArrayLike, nu_deg: ArrayLike) -> Any:
    """Horizontal distance D [m] of a beam of slope distance S [m] and tilt ν [deg]:
    ``D = S·cos ν`` (eq. 1 of Voroshilov & Karachentsev); the inverse of
    :func:`slope_distance_m` (below ν = 90°).

    Examples
    --------
    >>> horizontal_distance_m([10.0, 20.0], [0.0, 60.0]).round(6).tolist()
    [10.0, 10.0]
    """
    s = as_float_array(slope_distance_m, "slope_distance_m")
    nu = check_range(as_float_array(nu_deg, "nu_deg"), "nu_deg", "deg", hi=90.0, absolute=True)
    return like_input(s * np.cos(np.radians(nu)), slope_distance_m, nu_deg)


def deviation_angle_deg(
    station_xy: ArrayLike, point_xy: ArrayLike, normal_xy: ArrayLike
) -> np.ndarray:
    """Deviation γ [deg] of the horizontal beam from the facade's outward normal.

    The angle between the horizontal vector point → station and the outward normal, in
    [0°, 180°]: 0° square to the facade, 90° grazing, > 90° the facade seen from behind.
    NaN where the station stands right above the point (no horizontal direction).
    """
    st = _xyz(station_xy, "station_xy", 2)[..., :2]
    pt = _xyz(point_xy, "point_xy", 2)[..., :2]
    n = _xyz(normal_xy, "normal_xy", 2)
    v = st - pt
    vn = np.hypot(v[..., 0], v[..., 1])
    nn = np.hypot(n[..., 0], n[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        cos_g = (v[..., 0] * n[..., 0] + v[..., 1] * n[..., 1]) / (vn * nn)
    cos_g = np.where(vn > 0, np.clip(cos_g, -1.0, 1.0), np.nan)
    return np.degrees(np.arccos(cos_g))


def tilt_deg(station_xyz: ArrayLike, point_xyz: ArrayLike) -> np.ndarray:
    """Tilt (elevation) ν [deg] of the beam from the scanner centre to the point, in [-90, 90]."""
    st = _xyz(station_xyz, "station_xyz", 3)
    pt = _xyz(point_xyz, "point_xyz", 3)
    d = np.hypot(pt[..., 0] - st[..., 0], pt[..., 1] - st[..., 1])
    return np.degrees(np.arctan2(pt[..., 2] - st[..., 2], d))


def incidence_deg(gamma_deg: ArrayLike, nu_deg: ArrayLike) -> np.ndarray:
    """3-D incidence θ [deg] of a beam on a vertical wall: ``cos θ = cos γ · cos ν``.

    γ is measured in plan (the deviation from the wall's normal in the horizontal plane)
    and ν is the beam's tilt; the angle between the beam and the wall's normal is larger
    than either as soon as both are non-zero.

    Examples
    --------
    >>> incidence_deg([0, 60, 60], [0, 0, 45]).round(2).tolist()
    [0.0, 60.0, 69.3]
    """
    g = np.radians(as_float_array(gamma_deg, "gamma_deg"))
    nu = np.radians(as_float_array(nu_deg, "nu_deg"))
    return np.degrees(np.arccos(np.clip(np.cos(g) * np.cos(nu), -1.0, 1.0)))


class SightGeometry(NamedTuple):
    """Horizontal distance D [m], slope distance S [m], deviation γ [deg] and tilt ν [deg]."""

    distance_m: np.ndarray
    slope_distance_m: np.ndarray
    gamma_deg: np.ndarray
    nu_deg: np.ndarray


def sight_geometry(
    station_xyz: ArrayLike, point_xyz: ArrayLike, normal_xy: ArrayLike
) -> SightGeometry:
    """D, S, γ, ν of the beam from a scanner centre to a facade point (all broadcast).

    ``station_xyz`` is the scanner centre (ground + instrument height), ``point_xyz`` the
    point on the facade, ``normal_xy`` the facade's horizontal outward normal.
    """
    st = _xyz(station_xyz, "station_xyz", 3)
    pt = _xyz(point_xyz, "point_xyz", 3)
    dx = pt[..., 0] - st[..., 0]
    dy = pt[..., 1] - st[..., 1]
    dz = pt[..., 2] - st[..., 2]
    d = np.hypot(dx, dy)
    s = np.sqrt(d * d + dz * dz)
    return SightGeometry(
        d, s, deviation_angle_deg(st[..., :2], pt[..., :2], normal_xy), tilt_deg(st, pt)
    )


def separated_directions(azimuths_deg: ArrayLike, min_angle_deg: float) -> int:
    """The most directions among ``azimuths_deg`` that are pairwise at least
    ``min_angle_deg`` apart on the circle: how many truly different views of a point its
    stations give (two stations side by side are one view). Greedy from each start, which
    is exact for points on a circle.

    Examples
    --------
    >>> separated_directions([0, 5, 90], 30), separated_directions([0, 10, 350], 30)
    (2, 1)
    """
    a = np.sort(np.mod(np.asarray(azimuths_deg, dtype=float).ravel(), 360.0))
    best = min(len(a), 1)
    for start in range(len(a)):
        count, last = 1, a[start]
        for step in range(1, len(a)):
            v = a[(start + step) % len(a)] + (360.0 if start + step >= len(a) else 0.0)
            if v - last >= min_angle_deg and (a[start] + 360.0) - v >= min_angle_deg:
                count, last = count + 1, v
        best = max(best, count)
    return best
