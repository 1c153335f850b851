r"""The returned signal: how a surface's reflectance and the beam's incidence set the ranging
noise and the reach of a scanner.

A scanner's datasheet states its ranging RMS ``m_S = a + b·D`` and its reach on a bright
reference surface (``reference_reflectance``, e.g. 80–90 %) square to the beam. A real
facade returns less: for a diffusely reflecting (Lambertian) surface the returned power is

.. math::

    P \propto \frac{\rho \cos\theta}{R^2}

(the laser range equation for an extended target; Jelalian, "Laser Radar Systems", Artech
House, 1992; Soudarissanane, Lindenbergh, Menenti & Teunissen, "Scanning geometry:
influencing factor on the quality of terrestrial laser scanning points", ISPRS J.
Photogramm. Remote Sens. 66(4), 389–399, 2011, https://doi.org/10.1016/j.isprsjprs.2011.01.005).

**Ranging noise.** Wujanz, Burger, Mettenleiter & Neitzel ("An intensity-based stochastic
model for terrestrial laser scanners", ISPRS J. Photogramm. Remote Sens. 125, 146–155,
2017, https://doi.org/10.1016/j.isprsjprs.2016.12.006) showed the ranging precision of a
phase scanner is a power law of the raw intensity, ``σ = c · I^(−k)``, and Wujanz et al.
(2018, "Determination of intensity-based stochastic models for terrestrial laser scanners
utilising 3D-point clouds", Sensors 18(7), 2187, https://doi.org/10.3390/s18072187) that
the same holds for pulsed scanners. The R² of the signal is already in the datasheet's
``a + b·D`` (stated on the reference surface at every distance), so what a surface changes
is the ratio of its signal to the reference's at the same distance,
``q = ρ cos θ / ρ_ref`` (:func:`relative_signal`), and

.. math::

    m_S(\rho, \theta, D) = (a + b D) \cdot q^{-k}

(:func:`signal_ranging_rms_mm`). k = ½ is the shot-noise limit — the timing of a return
made of N photons is known to 1/√N — and the planner's default; the lab calibration fits k
from plane residuals at several reflectances (Schmitz, Holst, Medic, Lichti & Kuhlmann,
"How to efficiently determine the range precision of 3D terrestrial laser scanners",
Sensors 19(6), 1466, 2019, https://doi.org/10.3390/s19061466), and a profile may carry it.

**Reach.** A return is detected while its power is above the receiver's threshold, so the
farthest range on a surface of signal ratio q' (to the surface the datasheet's reach is
stated on) is ``R_max · q'^p`` with p = ½ from the range equation
(:func:`signal_reach_m`); a datasheet stating its reach at two reflectances (e.g. 90 % and
18 %) gives p itself (:func:`reach_exponent`). The stated reach is never exceeded (it is
also the limit of the range's ambiguity interval or the instrument's setting).

Where the planner knows no material, the surface is the datasheet's reference (q = 1 at
square incidence): the figures as published.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from planner._array import like_input

__all__ = [
    "DEFAULT_RANGE_EXPONENT",
    "DEFAULT_RANGING_EXPONENT",
    "DEFAULT_REFERENCE_REFLECTANCE",
    "MIN_COS_INCIDENCE",
    "MIN_SIGNAL",
    "reach_exponent",
    "relative_signal",
    "signal_ranging_rms_mm",
    "signal_reach_m",
]

#: The reflectance a datasheet's ranging figures hold on where the profile does not say:
#: makers state them on bright, diffuse targets (80–90 %) [0–1].
DEFAULT_REFERENCE_REFLECTANCE = 0.8
#: Exponent k of the ranging noise's growth as the signal falls, m_S ∝ q^(−k): the shot-noise
#: limit (module docstring).
DEFAULT_RANGING_EXPONENT = 0.5
#: Exponent p of the reach's fall with the signal, R_max ∝ q^p: the range equation for an
#: extended diffuse target (module docstring).
DEFAULT_RANGE_EXPONENT = 0.5
#: Below this cos θ (θ ≈ 84°) the incidence is held: the surface is not scanned usefully.
MIN_COS_INCIDENCE = 0.1
#: The weakest signal ratio the formulas take (a 1 % reflectance square to the beam against
#: the reference): below it the ranging noise is held, not grown without bound.
MIN_SIGNAL = 0.01


def relative_signal(
    reflectance: ArrayLike,
    cos_incidence: ArrayLike = 1.0,
    reference_reflectance: float = DEFAULT_REFERENCE_REFLECTANCE,
) -> Any:
    """The signal ratio ``q = ρ cos θ / ρ_ref`` of a surface to the reference surface at the
    same distance (module docstring); NaN reflectance (no material known) is the reference
    itself; cos θ held at :data:`MIN_COS_INCIDENCE`, q at :data:`MIN_SIGNAL` or more.

    Examples
    --------
    >>> relative_signal([0.8, 0.2, float("nan")], 0.5).round(3).tolist()
    [0.5, 0.125, 0.5]
    """
    rho = np.asarray(reflectance, dtype=float)
    rho = np.where(np.isnan(rho), reference_reflectance, rho)
    cos_t = np.clip(np.asarray(cos_incidence, dtype=float), MIN_COS_INCIDENCE, 1.0)
    q = np.maximum(rho * cos_t / reference_reflectance, MIN_SIGNAL)
    return like_input(q, reflectance, cos_incidence)


def signal_ranging_rms_mm(
    range_rms_mm: ArrayLike, signal: ArrayLike, exponent: float = DEFAULT_RANGING_EXPONENT
) -> Any:
    """Ranging RMS [mm] on a surface of signal ratio ``signal`` (:func:`relative_signal`):
    ``m_S · q^(−k)`` (module docstring; Wujanz et al. 2017, 2018).

    Examples
    --------
    Dark brick (15 %) square to the beam against an 80 % reference, and plaster at 60°:

    >>> signal_ranging_rms_mm(1.0, relative_signal([0.15, 0.75], [1.0, 0.5])).round(2).tolist()
    [2.31, 1.46]
    """
    m_s = np.asarray(range_rms_mm, dtype=float)
    q = np.maximum(np.asarray(signal, dtype=float), MIN_SIGNAL)
    return like_input(m_s * q**-exponent, range_rms_mm, signal)


def reach_exponent(
    range_a_m: float, reflectance_a: float, range_b_m: float, reflectance_b: float
) -> float:
    """Exponent p of ``R_max ∝ q^p`` from a datasheet's reach at two reflectances.

    Examples
    --------
    A scanner reaching 350 m at 90 % and 165 m at 20 %:

    >>> round(reach_exponent(350.0, 0.9, 165.0, 0.2), 3)
    0.5
    """
    return math.log(range_a_m / range_b_m) / math.log(reflectance_a / reflectance_b)


def signal_reach_m(
    max_range_m: float, signal: ArrayLike, exponent: float = DEFAULT_RANGE_EXPONENT
) -> Any:
    """The farthest range [m] on a surface whose signal ratio to the surface the reach is
    stated on is ``signal``: ``R_max · min(q, 1)^p`` (module docstring: never beyond the
    stated reach).

    Examples
    --------
    >>> signal_reach_m(120.0, [1.0, 0.25, 2.0]).tolist()
    [120.0, 60.0, 120.0]
    """
    q = np.clip(np.asarray(signal, dtype=float), MIN_SIGNAL, 1.0)
    return like_input(max_range_m * q**exponent, signal)
