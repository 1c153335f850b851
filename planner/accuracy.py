"""Predicted RMS of a scanned point: eq. 2 (m_x, m_y) and eq. 4 (m_z) of Voroshilov & Karachentsev.

Reference: A. P. Voroshilov, Yu. A. Karachentsev, "Choice of station location at surface
laser scanning of buildings and constructions" (full citation in
:data:`planner.reference.REFERENCES`; the model is explained in ``docs/science.md``).

Facade frame: **x along the facade, y along its outward normal, z up**. The beam's horizontal
angle β is measured from the x axis, so a beam square to the facade has β = 90°. The
**deviation angle** γ = 90° − β is the angle between the beam and the facade normal; its sign
does not matter (the formulas hold cos² and sin²).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from planner._array import as_float_array, check_range, like_input
from planner.errors import InputError
from planner.scanner import Scanner
from planner.units import RHO_ARCSEC

__all__ = [
    "eq2_variances",
    "eq4_variance",
    "height_rms",
    "max_distance_m",
    "planimetric_rms",
    "ranging_rms_mm",
    "reach_bound_m",
]

MM_PER_M_PER_ARCSEC = 1000.0 / RHO_ARCSEC  # lateral mm per metre of distance per arc-second


def eq2_variances(
    distance_m: np.ndarray,
    cos2_gamma: np.ndarray,
    range_rms_mm: np.ndarray,
    angle_rms_arcsec: float,
    station_var_mm2: tuple[float, float] = (0.0, 0.0),
) -> tuple[np.ndarray, np.ndarray]:
    """Eq. 2 of Voroshilov & Karachentsev as variances [mm²], from cos²γ — the array kernel
    the planner's hot path calls (no validation).

    ``m_x² = m_xc² + m_S²·sin²γ + (D·m_β/ρ)²·cos²γ`` and
    ``m_y² = m_yc² + m_S²·cos²γ + (D·m_β/ρ)²·sin²γ`` (cos β = sin γ).
    """
    ang2 = np.square(distance_m * (MM_PER_M_PER_ARCSEC * angle_rms_arcsec))
    ms2 = np.square(range_rms_mm)
    sin2 = 1.0 - cos2_gamma
    var_x = station_var_mm2[0] + ms2 * sin2 + ang2 * cos2_gamma
    var_y = station_var_mm2[1] + ms2 * cos2_gamma + ang2 * sin2
    return var_x, var_y


def eq4_variance(
    slope_distance_m: np.ndarray,
    sin2_nu: np.ndarray,
    range_rms_mm: np.ndarray,
    tilt_rms_arcsec: float,
    initial_distance_m: np.ndarray,
    initial_tilt_rms_arcsec: float,
) -> np.ndarray:
    """Eq. 4 of Voroshilov & Karachentsev as a variance [mm²], from sin²ν — the array kernel
    the planner's hot path calls (no validation).

    ``m_z² = m_S²·sin²ν + (S·m_ν/ρ)²·cos²ν + (S_0·m_ν0/ρ)²``.
    """
    k = MM_PER_M_PER_ARCSEC
    return (
        np.square(range_rms_mm) * sin2_nu
        + np.square(slope_distance_m * (k * tilt_rms_arcsec)) * (1.0 - sin2_nu)
        + np.square(initial_distance_m * (k * initial_tilt_rms_arcsec))
    )


def ranging_rms_mm(distance_m: ArrayLike, scanner: Scanner) -> Any:
    """Ranging RMS ``m_S = a + b·D`` [mm] of ``scanner`` at ``distance_m`` [m].

    Datasheets quote the ranging accuracy as ``a`` [mm] plus ``b`` [ppm] of the distance
    (e.g. ±(2 mm + 100 ppm·L) in Xia et al. 2020); b = 0 gives a constant m_S.

    Examples
    --------
    >>> from planner import Scanner
    >>> sc = Scanner(name="x", range_rms_mm=2.0, range_ppm=100.0, angle_rms_arcsec=10.0)
    >>> ranging_rms_mm([0, 10, 30], sc).tolist()
    [2.0, 3.0, 5.0]
    >>> ranging_rms_mm(float("nan"), sc)
    nan
    """
    d = check_range(as_float_array(distance_m, "distance_m"), "distance_m", "m", lo=0.0)
    return like_input(scanner.range_rms_at(d), distance_m)


def station_rms_pair(station_rms_mm: Any) -> tuple[float, float]:
    """``(m_xc, m_yc)`` [mm] from one number (both equal) or a pair."""
    arr = as_float_array(station_rms_mm, "station_rms_mm")
    if arr.ndim == 0:
        arr = np.array([arr, arr])
    if arr.shape != (2,) or np.isnan(arr).any():
        raise InputError(
            "station_rms_mm must be one number (m_xc = m_yc) or a pair (m_xc, m_yc) [mm], "
            f"not NaN; got {station_rms_mm!r}"
        )
    check_range(arr, "station_rms_mm", "mm", lo=0.0)
    return float(arr[0]), float(arr[1])


def planimetric_rms(
    distance_m: ArrayLike,
    gamma_deg: ArrayLike,
    scanner: Scanner,
    station_rms_mm: float | tuple[float, float] = 0.0,
    *,
    ranging_distance_m: ArrayLike | None = None,
) -> tuple[Any, Any]:
    r"""RMS ``m_x``, ``m_y`` [mm] of a point in the facade frame — eq. 2 of Voroshilov &
    Karachentsev.

    .. math::

        m_x^2 = m_{xc}^2 + m_S^2\cos^2\beta + (D/\rho)^2 \sin^2\beta\, m_\beta^2 \\
        m_y^2 = m_{yc}^2 + m_S^2\sin^2\beta + (D/\rho)^2 \cos^2\beta\, m_\beta^2

    with β = 90° − γ, so cos β = sin γ and sin β = cos γ (``docs/science.md``).

    Parameters
    ----------
    distance_m : array_like
        Horizontal distance D from station to point [m], >= 0.
    gamma_deg : array_like
        Deviation γ of the beam from the facade normal [deg], -90 <= γ <= 90.
    scanner : Scanner
        Gives ``m_S`` (``a + b·D``) and ``m_β`` (``angle_rms_arcsec``).
    station_rms_mm : float or (float, float), default 0
        RMS ``m_xc``, ``m_yc`` of the station coordinates, which also absorb the
        registration of several scans into one system [mm].
    ranging_distance_m : array_like, optional
        Distance at which ``m_S = a + b·D`` is evaluated [m]; the slope distance S is the
        one actually measured. Default D, as eq. 2 treats the measured distance as horizontal.
        Irrelevant for a constant m_S (b = 0).

    Returns
    -------
    m_x, m_y : float, ndarray or Series
        Broadcast over the inputs; NaN in, NaN out.

    Notes
    -----
    The paper's Table 1 prints, in the column m_y at γ = 60°, values this formula does not
    give (e.g. 4.1 mm at 120 m where eq. 2 gives 6.6 mm): they equal
    cos γ·√(m_S² + (D·m_β/ρ)²), i.e. cos²γ used in place of sin²γ in the angular term.
    The formula is implemented as printed in eq. 2; ``tests/test_paper_tables.py`` records
    the misprint.

    Examples
    --------
    >>> from planner import Scanner
    >>> sc = Scanner.from_name("leica-4mm-60urad")
    >>> [round(v, 2) for v in planimetric_rms(100.0, 0.0, sc)]
    [6.01, 4.0]
    >>> planimetric_rms([10.0, float("nan")], 30.0, sc)[0].round(2).tolist()
    [2.07, nan]
    """
    d = check_range(as_float_array(distance_m, "distance_m"), "distance_m", "m", lo=0.0)
    g = check_range(
        as_float_array(gamma_deg, "gamma_deg"), "gamma_deg", "deg", hi=90.0, absolute=True
    )
    m_xc, m_yc = station_rms_pair(station_rms_mm)
    s_for_range = d if ranging_distance_m is None else ranging_distance_m
    m_s = np.asarray(ranging_rms_mm(s_for_range, scanner))
    cos2_gamma = np.cos(np.radians(g)) ** 2
    var_x, var_y = eq2_variances(d, cos2_gamma, m_s, scanner.angle_rms_arcsec, (m_xc**2, m_yc**2))
    m_x, m_y = np.sqrt(var_x), np.sqrt(var_y)
    return like_input(m_x, distance_m, gamma_deg), like_input(m_y, distance_m, gamma_deg)


def height_rms(
    slope_distance_m: ArrayLike,
    nu_deg: ArrayLike,
    scanner: Scanner,
    *,
    initial_distance_m: ArrayLike | None = None,
    initial_tilt_rms_arcsec: float | None = None,
) -> Any:
    r"""RMS ``m_z`` [mm] of the height of a scanned point — eq. 4 of Voroshilov & Karachentsev.

    .. math::

        m_z^2 = m_S^2\sin^2\nu + (S/\rho)^2\cos^2\nu\, m_\nu^2 + (S_0/\rho)^2 m_{\nu_0}^2

    derived from eq. 3, ``z = z_0 + S·sin ν − S_0·sin ν_0``, with ``m_z0 = 0`` and ν_0 = 0.

    Parameters
    ----------
    slope_distance_m : array_like
        Slope distance S from the scanner to the point [m], >= 0.
    nu_deg : array_like
        Tilt (elevation) ν of the beam [deg], -90 <= ν <= 90.
    scanner : Scanner
        Gives ``m_S`` (``a + b·S``) and ``m_ν`` (``tilt_rms_arcsec``).
    initial_distance_m : array_like, optional
        S_0, the distance at which the initial (horizontal) direction is fixed [m].
        Default S, as in the paper's Table 2.
    initial_tilt_rms_arcsec : float, optional
        m_ν0, the RMS of the initial direction [″]. Default
        :attr:`Scanner.initial_tilt_rms_arcsec`: the levelling figure of a compensated
        scanner, else m_ν as in Table 2.

    Returns
    -------
    m_z : float, ndarray or Series

    Examples
    --------
    >>> from planner import Scanner
    >>> sc = Scanner.from_name("leica-4mm-60urad")
    >>> round(height_rms(50.0, 90.0, sc), 2)  # Table 2 prints 5.0
    5.0
    """
    s = check_range(
        as_float_array(slope_distance_m, "slope_distance_m"), "slope_distance_m", "m", lo=0.0
    )
    nu = check_range(as_float_array(nu_deg, "nu_deg"), "nu_deg", "deg", hi=90.0, absolute=True)
    s0 = (
        s
        if initial_distance_m is None
        else check_range(
            as_float_array(initial_distance_m, "initial_distance_m"),
            "initial_distance_m",
            "m",
            lo=0.0,
        )
    )
    m_nu = scanner.tilt_rms_arcsec
    if initial_tilt_rms_arcsec is None:
        m_nu0 = scanner.initial_tilt_rms_arcsec
    else:
        m_nu0 = float(
            check_range(
                as_float_array(initial_tilt_rms_arcsec, "initial_tilt_rms_arcsec"),
                "initial_tilt_rms_arcsec",
                "arc-seconds",
                lo=0.0,
            )
        )
    sin2_nu = np.sin(np.radians(nu)) ** 2
    m_z = np.sqrt(eq4_variance(s, sin2_nu, scanner.range_rms_at(s), m_nu, s0, m_nu0))
    return like_input(m_z, slope_distance_m, nu_deg)


def max_distance_m(
    limit_mm: float,
    scanner: Scanner,
    component: str,
    angle_deg: ArrayLike,
    *,
    station_rms_mm: float | tuple[float, float] = 0.0,
) -> Any:
    r"""Largest distance [m] at which ``component`` stays within ``limit_mm`` — eq. 2 or 4
    solved for the distance.

    ``component`` is ``"m_x"`` or ``"m_y"`` (eq. 2, at deviation ``angle_deg`` = γ, the
    horizontal distance D returned, ranging at D) or ``"m_z"`` (eq. 4 with S_0 = S, at tilt
    ``angle_deg`` = ν, the slope distance S returned). Every term of both equations grows
    with the distance, so the requirement holds from 0 up to the returned distance, found
    as the positive root of :math:`A d^2 + B d + C = 0` (the ranging RMS a + b·d makes it a
    quadratic). ``inf`` where the requirement holds at every distance, NaN where it fails
    even at 0 m (the ranging RMS or the station RMS alone exceed it).

    Examples
    --------
    >>> from planner import Scanner
    >>> sc = Scanner.from_name("leica-4mm-60urad")
    >>> round(max_distance_m(5.0, sc, "m_x", 0.0), 1)  # 5 mm = D·12.4″/ρ
    83.2
    >>> max_distance_m(3.0, sc, "m_y", 0.0)  # m_S = 4 mm > 3 mm at any distance
    nan
    """
    limit = float(check_range(as_float_array(limit_mm, "limit_mm"), "limit_mm", "mm", lo=0.0))
    ang = np.radians(
        check_range(
            as_float_array(angle_deg, "angle_deg"), "angle_deg", "deg", hi=90.0, absolute=True
        )
    )
    a, b = scanner.range_rms_mm, scanner.range_ppm * 1e-3  # mm, mm per m
    k = MM_PER_M_PER_ARCSEC
    if component in ("m_x", "m_y"):
        m_xc, m_yc = station_rms_pair(station_rms_mm)
        station2 = (m_xc if component == "m_x" else m_yc) ** 2
        cos2 = np.cos(ang) ** 2
        range_w, angle_w = (1.0 - cos2, cos2) if component == "m_x" else (cos2, 1.0 - cos2)
        angle_term = (k * scanner.angle_rms_arcsec) ** 2 * angle_w
    elif component == "m_z":
        station2 = 0.0
        sin2 = np.sin(ang) ** 2
        range_w = sin2
        angle_term = k**2 * (
            scanner.tilt_rms_arcsec**2 * (1.0 - sin2) + scanner.initial_tilt_rms_arcsec**2
        )
    else:
        raise InputError(f"component must be 'm_x', 'm_y' or 'm_z'; got {component!r}")
    qa = b * b * range_w + angle_term
    qb = 2.0 * a * b * range_w
    qc = a * a * range_w + station2 - limit * limit
    with np.errstate(divide="ignore", invalid="ignore"):
        disc = np.sqrt(np.maximum(qb * qb - 4.0 * qa * qc, 0.0))
        root = np.where(qa > 0, (-qb + disc) / (2.0 * qa), np.where(qb > 0, -qc / qb, np.inf))
    out = np.where((qc > 1e-12) | np.isnan(qa + qc), np.nan, root)  # NaN in, NaN out
    return like_input(np.asarray(out, dtype=float), angle_deg)


def reach_bound_m(
    scanner: Scanner,
    max_x_mm: float,
    max_y_mm: float,
    max_z_mm: float,
    station_rms_mm: tuple[float, float] = (0.0, 0.0),
    initial_tilt_rms_arcsec: float | None = None,
) -> float:
    """A distance [m] beyond which no point can meet all three limits, whatever γ and ν.

    From eq. 2, ``m_x² + m_y² = m_xc² + m_yc² + m_S² + (D·m_β/ρ)²`` whatever γ, so
    ``D <= ρ/m_β · √(T_x² + T_y² − m_xc² − m_yc² − a²)``; from eq. 4 with S_0 = S,
    ``m_z >= S·m_ν0/ρ``, so ``S <= ρ·T_z/m_ν0``. The smaller of the two (a search radius
    for candidate stations: S >= D). m_ν0: ``initial_tilt_rms_arcsec``, default the
    scanner's (0 where a plan's registration part carries the tilt: no bound from eq. 4).

    Examples
    --------
    >>> sc = Scanner.from_name("leica-4mm-60urad")
    >>> round(reach_bound_m(sc, 5.0, 5.0, 5.0), 1)
    83.2
    """
    budget = max_x_mm**2 + max_y_mm**2 - sum(v * v for v in station_rms_mm)
    budget -= scanner.range_rms_mm**2
    d_xy = math.sqrt(max(budget, 0.0)) / (MM_PER_M_PER_ARCSEC * scanner.angle_rms_arcsec)
    m_nu0 = (
        scanner.initial_tilt_rms_arcsec
        if initial_tilt_rms_arcsec is None
        else initial_tilt_rms_arcsec
    )
    d_z = max_z_mm / (MM_PER_M_PER_ARCSEC * m_nu0) if m_nu0 > 0 else math.inf
    return min(d_xy, d_z)
