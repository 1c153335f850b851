r"""The full 3-D error model of a scanned point, beside eq. 2 and 4 of Voroshilov & Karachentsev.

A terrestrial laser scanner measures, for every point, a slope distance S, a horizontal
direction α and a vertical angle ν, on a vertical axis that its levelling leaves tilted by
a small τ = (τ_x, τ_y). In the scanner's frame the point is
``p = S·(cos ν cos α, cos ν sin α, sin ν)``; the complete Jacobian of that map gives, for
independent errors δS (RMS m_S), δα (m_β), δν (m_ν) and τ (σ_τ per axis),

.. math::

    \delta p = \delta S\,e_r + D\,\delta\alpha\,e_h + S\,\delta\nu\,e_v + \tau \times p

with D = S cos ν, e_r along the beam, e_h horizontal and square to it, e_v square to both.
Projected onto the facade frame (x along the facade, y along its outward normal, z up; γ the
deviation of the horizontal beam from the normal):

.. math::

    m_x^2 &= m_S^2\cos^2\!\nu\,\sin^2\!\gamma + (D m_\beta/\rho)^2\cos^2\!\gamma
             + (S m_\nu/\rho)^2\sin^2\!\nu\,\sin^2\!\gamma + (S \sin\nu\,\sigma_\tau/\rho)^2 \\
    m_y^2 &= m_S^2\cos^2\!\nu\,\cos^2\!\gamma + (D m_\beta/\rho)^2\sin^2\!\gamma
             + (S m_\nu/\rho)^2\sin^2\!\nu\,\cos^2\!\gamma + (S \sin\nu\,\sigma_\tau/\rho)^2 \\
    m_z^2 &= m_S^2\sin^2\!\nu + (S m_\nu/\rho)^2\cos^2\!\nu + (D\,\sigma_\tau/\rho)^2

At ν = 0 without tilt this is eq. 2 exactly. Where the beam is tilted, eq. 2 lets the
horizontal distance carry the whole ranging error (the 3-D model: m_S cos ν) and leaves out
the vertical angle's horizontal share (S m_ν sin ν) and the axis tilt's (S sin ν σ_τ, the
τ·tan ν of the horizontal direction). For m_z, eq. 4's third term (S_0 m_ν0 with S_0 = S)
is replaced by the tilt's D σ_τ. σ_τ is the scanner's compensator figure
(``levelling_rms_arcsec``), else m_ν — the paper's own assumption for m_ν0.

Two optional terms, each documented where it is defined:

* :func:`incidence_ranging_rms_mm` — ranging noise growing with the 3-D incidence θ;
* :func:`footprint_mm` — the beam's footprint, which bounds the detail a scan resolves.

The derivation is the planner's, not the paper's; ``tests/test_montecarlo.py`` checks it
against simulated polar measurements, with a negative control. ``docs/science.md`` explains
why it is the default for planning.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from planner._array import as_float_array, check_range, like_input
from planner.accuracy import MM_PER_M_PER_ARCSEC, station_rms_pair
from planner.errors import InputError
from planner.scanner import Scanner
from planner.signal import DEFAULT_RANGING_EXPONENT, MIN_COS_INCIDENCE, signal_ranging_rms_mm

__all__ = [
    "INCIDENCE_NOISE_EXPONENT",
    "MIN_COS_INCIDENCE",
    "footprint_mm",
    "incidence_ranging_rms_mm",
    "max_distance_3d_m",
    "point_rms_3d",
    "reach_bound_3d_m",
    "variances_3d",
]

#: Exponent k of the ranging noise's growth with incidence, m_S(θ) = m_S / cos^k θ: the
#: returned signal's ranging exponent (:data:`planner.signal.DEFAULT_RANGING_EXPONENT`) — the
#: power a diffusely reflecting surface returns falls with cos θ (Soudarissanane et al. 2009,
#: 2011), and the ranging noise grows with the inverse square root of the returned signal
#: (the intensity-based model of Wujanz et al. 2017), hence k = 1/2.
INCIDENCE_NOISE_EXPONENT = DEFAULT_RANGING_EXPONENT


def variances_3d(
    slope_distance_m: np.ndarray,
    cos_gamma: np.ndarray,
    sin_nu: np.ndarray,
    range_rms_mm: np.ndarray,
    angle_rms_arcsec: float,
    tilt_rms_arcsec: float,
    axis_tilt_rms_arcsec: float,
    station_var_mm2: tuple[float, float] = (0.0, 0.0),
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The 3-D model's m_x², m_y², m_z² [mm²] — the array kernel the planner's hot path calls
    (no validation). ``tilt_rms_arcsec`` is m_ν, ``axis_tilt_rms_arcsec`` σ_τ."""
    k = MM_PER_M_PER_ARCSEC
    cos2_g = cos_gamma * cos_gamma
    sin2_g = 1.0 - cos2_g
    sin2_nu = sin_nu * sin_nu
    cos2_nu = 1.0 - sin2_nu
    s2 = slope_distance_m * slope_distance_m
    ranging = np.square(range_rms_mm)
    horizontal = s2 * cos2_nu * (k * angle_rms_arcsec) ** 2  # (D m_β/ρ)²
    vertical = s2 * (k * tilt_rms_arcsec) ** 2  # (S m_ν/ρ)²
    tilt = s2 * (k * axis_tilt_rms_arcsec) ** 2  # (S σ_τ/ρ)²
    along = ranging * cos2_nu + vertical * sin2_nu  # the beam's share in the horizontal plane
    var_x = station_var_mm2[0] + along * sin2_g + horizontal * cos2_g + tilt * sin2_nu
    var_y = station_var_mm2[1] + along * cos2_g + horizontal * sin2_g + tilt * sin2_nu
    var_z = ranging * sin2_nu + vertical * cos2_nu + tilt * cos2_nu
    return var_x, var_y, var_z


def incidence_ranging_rms_mm(
    range_rms_mm: ArrayLike, cos_incidence: ArrayLike, exponent: float = INCIDENCE_NOISE_EXPONENT
) -> Any:
    """Ranging RMS [mm] at the 3-D incidence θ: ``m_S / cos^k θ`` (k =
    :data:`INCIDENCE_NOISE_EXPONENT`), cos θ held at :data:`MIN_COS_INCIDENCE`.

    Soudarissanane et al. (2009, 2011) show the incidence dominating a point's precision
    beyond about 60°; this is the smooth form of that growth (a departure from the
    datasheets, which state m_S square to the surface).

    Examples
    --------
    >>> incidence_ranging_rms_mm(2.0, [1.0, 0.5, 0.0]).round(3).tolist()
    [2.0, 2.828, 6.325]
    """
    cos_t = np.clip(np.asarray(cos_incidence, dtype=float), MIN_COS_INCIDENCE, 1.0)
    m_s = signal_ranging_rms_mm(np.asarray(range_rms_mm, dtype=float), cos_t, exponent)
    return like_input(np.asarray(m_s), range_rms_mm, cos_incidence)


def footprint_mm(
    slope_distance_m: ArrayLike, scanner: Scanner, cos_incidence: ArrayLike = 1.0
) -> Any:
    """Length [mm] of the beam's footprint on a surface at incidence θ: the beam diameter
    ``beam_exit_mm + S·beam_divergence_mrad`` stretched by 1/cos θ; 0 for a scanner
    without beam figures. A scan resolves no detail finer than its footprint (Lichti &
    Jamtsho 2006, the effective angular resolution), so the planner compares the larger of
    the point spacing and the footprint with a spacing requirement.

    Examples
    --------
    >>> sc = Scanner(name="x", range_rms_mm=1, angle_rms_arcsec=10, beam_exit_mm=2.0,
    ...              beam_divergence_mrad=0.3)
    >>> footprint_mm([10.0, 50.0], sc).round(2).tolist()
    [5.0, 17.0]
    """
    s = np.asarray(slope_distance_m, dtype=float)
    if scanner.beam_divergence_mrad is None and scanner.beam_exit_mm is None:
        return like_input(np.where(np.isnan(s), np.nan, 0.0), slope_distance_m)
    width = (scanner.beam_exit_mm or 0.0) + s * (scanner.beam_divergence_mrad or 0.0)
    cos_t = np.clip(np.asarray(cos_incidence, dtype=float), MIN_COS_INCIDENCE, 1.0)
    return like_input(width / cos_t, slope_distance_m)


def point_rms_3d(
    slope_distance_m: ArrayLike,
    gamma_deg: ArrayLike,
    nu_deg: ArrayLike,
    scanner: Scanner,
    *,
    station_rms_mm: float | tuple[float, float] = 0.0,
    incidence_noise: bool = False,
    axis_tilt_rms_arcsec: float | None = None,
) -> tuple[Any, Any, Any]:
    """m_x, m_y, m_z [mm] of a point on a vertical facade by the full 3-D model (module
    docstring), the ranging RMS a + b·S at the slope distance and, with
    ``incidence_noise``, grown with the 3-D incidence (:func:`incidence_ranging_rms_mm`).
    σ_τ, the tilt of the vertical axis: ``axis_tilt_rms_arcsec``, default the scanner's
    m_ν0 (a scan levelled on its own; a plan whose registration part carries the frame's
    tilt counts 0 here, :meth:`planner.pipeline.inputs.requirements.PlanSettings
    .scan_tilt_rms_arcsec`).

    Examples
    --------
    A beam square to the wall in plan (γ = 0) but tilted by ν = 60°, at S = 40 m, from a
    1 mm / 8″ scanner with a 1.5″ compensator: eq. 2 gives m_y = m_S = 1.00 mm; the range
    error's horizontal share is only 0.5 mm, but the vertical angle adds 1.34 mm:

    >>> sc = Scanner(name="x", range_rms_mm=1.0, angle_rms_arcsec=8.0, levelling_rms_arcsec=1.5)
    >>> [round(float(v), 2) for v in point_rms_3d(40.0, 0.0, 60.0, sc)]  # m_x, m_y, m_z
    [0.82, 1.46, 1.17]
    """
    s = check_range(
        as_float_array(slope_distance_m, "slope_distance_m"), "slope_distance_m", "m", lo=0.0
    )
    g = check_range(
        as_float_array(gamma_deg, "gamma_deg"), "gamma_deg", "deg", hi=90.0, absolute=True
    )
    nu = check_range(as_float_array(nu_deg, "nu_deg"), "nu_deg", "deg", hi=90.0, absolute=True)
    m_xc, m_yc = station_rms_pair(station_rms_mm)
    cos_g, sin_nu = np.cos(np.radians(g)), np.sin(np.radians(nu))
    m_s = scanner.range_rms_at(s)
    if incidence_noise:
        m_s = incidence_ranging_rms_mm(m_s, cos_g * np.cos(np.radians(nu)))
    vx, vy, vz = variances_3d(
        s,
        cos_g,
        sin_nu,
        m_s,
        scanner.angle_rms_arcsec,
        scanner.tilt_rms_arcsec,
        scanner.initial_tilt_rms_arcsec if axis_tilt_rms_arcsec is None else axis_tilt_rms_arcsec,
        (m_xc * m_xc, m_yc * m_yc),
    )
    inputs = (slope_distance_m, gamma_deg, nu_deg)
    return tuple(like_input(np.sqrt(v), *inputs) for v in (vx, vy, vz))


def reach_bound_3d_m(
    scanner: Scanner,
    max_x_mm: float,
    max_y_mm: float,
    station_rms_mm: tuple[float, float] = (0.0, 0.0),
    axis_tilt_rms_arcsec: float | None = None,
) -> float:
    """A slope distance [m] beyond which no point meets both horizontal limits under the
    3-D model, whatever γ and ν: ``m_x² + m_y² >= (S/ρ)²·min(m_β², m_ν² + 2σ_τ²)``
    (the horizontal angle's share at ν = 0, the vertical angle's and the tilt's at
    ν = 90°; ranging only adds). σ_τ: ``axis_tilt_rms_arcsec``, default the scanner's
    m_ν0 (0 where a plan's registration part carries the tilt).

    Examples
    --------
    >>> sc = Scanner.from_name("leica-4mm-60urad")
    >>> round(reach_bound_3d_m(sc, 5.0, 5.0), 1)
    117.6
    """
    budget = max_x_mm**2 + max_y_mm**2 - sum(v * v for v in station_rms_mm)
    tau = scanner.initial_tilt_rms_arcsec if axis_tilt_rms_arcsec is None else axis_tilt_rms_arcsec
    floor = min(scanner.angle_rms_arcsec**2, scanner.tilt_rms_arcsec**2 + 2.0 * tau**2)
    return float(np.sqrt(max(budget, 0.0) / floor) / MM_PER_M_PER_ARCSEC)


def max_distance_3d_m(
    limit_mm: float,
    scanner: Scanner,
    component: str,
    gamma_deg: ArrayLike,
    nu_deg: ArrayLike,
    *,
    incidence_noise: bool = False,
) -> Any:
    """Largest slope distance [m] at which ``component`` (``"m_x"``, ``"m_y"``, ``"m_z"``)
    stays within ``limit_mm`` under the 3-D model, for a beam at deviation γ and tilt ν.

    At fixed angles every term grows with S (the ranging RMS as a + b·S, the angular terms
    as S), so the variance is a quadratic A·S² + B·S + C and the answer its positive root;
    ``inf`` where the limit holds at every distance, NaN where it fails even at 0 m.
    The 3-D counterpart of :func:`planner.accuracy.max_distance_m`.

    Examples
    --------
    >>> sc = Scanner.from_name("leica-4mm-60urad")
    >>> round(float(max_distance_3d_m(5.0, sc, "m_x", 0.0, 0.0)), 1)  # ν = 0: eq. 2's 83.2 m
    83.2
    >>> round(float(max_distance_3d_m(5.0, sc, "m_y", 0.0, 60.0)), 1)  # eq. 2: no limit
    62.2
    """
    limit = float(check_range(as_float_array(limit_mm, "limit_mm"), "limit_mm", "mm", lo=0.0))
    g = np.radians(
        check_range(
            as_float_array(gamma_deg, "gamma_deg"), "gamma_deg", "deg", hi=90.0, absolute=True
        )
    )
    nu = np.radians(
        check_range(as_float_array(nu_deg, "nu_deg"), "nu_deg", "deg", hi=90.0, absolute=True)
    )
    c2g, s2g, c2n, s2n = np.cos(g) ** 2, np.sin(g) ** 2, np.cos(nu) ** 2, np.sin(nu) ** 2
    k2 = MM_PER_M_PER_ARCSEC**2
    mb2, mn2 = scanner.angle_rms_arcsec**2, scanner.tilt_rms_arcsec**2
    t2 = scanner.initial_tilt_rms_arcsec**2
    if component == "m_x":
        w_range, w_angle = c2n * s2g, mb2 * c2n * c2g + mn2 * s2n * s2g + t2 * s2n
    elif component == "m_y":
        w_range, w_angle = c2n * c2g, mb2 * c2n * s2g + mn2 * s2n * c2g + t2 * s2n
    elif component == "m_z":
        w_range, w_angle = s2n, mn2 * c2n + t2 * c2n
    else:
        raise InputError(f"component must be 'm_x', 'm_y' or 'm_z'; got {component!r}")
    if incidence_noise:
        cos_t = np.clip(np.cos(g) * np.cos(nu), MIN_COS_INCIDENCE, 1.0)
        w_range = w_range / cos_t ** (2 * INCIDENCE_NOISE_EXPONENT)
    a, b = scanner.range_rms_mm, scanner.range_ppm * 1e-3
    qa = b * b * w_range + k2 * w_angle
    qb = 2.0 * a * b * w_range
    qc = a * a * w_range - limit * limit
    with np.errstate(divide="ignore", invalid="ignore"):
        disc = np.sqrt(np.maximum(qb * qb - 4.0 * qa * qc, 0.0))
        root = np.where(qa > 0, (-qb + disc) / (2.0 * qa), np.where(qb > 0, -qc / qb, np.inf))
    out = np.where((qc > 1e-12) | np.isnan(qa + qc), np.nan, root)  # NaN in, NaN out
    return like_input(np.asarray(out, dtype=float), gamma_deg, nu_deg)
