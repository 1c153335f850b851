"""Units and angle conversions.

The unit rule of the whole package (stated once, here and in the README):

* geometry — distances and coordinates in **metres**, angles in **degrees**;
* errors (RMS) and target sizes in **millimetres**;
* angular RMS in **arc-seconds** (″).

Where an argument breaks the rule its name says so (``step_mm_at_10m``,
``angle_rms_urad``, ``measurement_rate_hz``).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike

#: Arc-seconds per radian, ρ = 180·3600/π = 206 264.806″. The papers round it to 206 265″;
#: the difference is 1 ppm and invisible at 0.1 mm.
RHO_ARCSEC: float = 180.0 * 3600.0 / math.pi


def urad_to_arcsec(urad: ArrayLike) -> np.ndarray | float:
    """Convert micro-radians to arc-seconds (60 µrad → 12.376″).

    Examples
    --------
    >>> round(urad_to_arcsec(60.0), 3)
    12.376
    """
    out = np.asarray(urad, dtype=float) * 1e-6 * RHO_ARCSEC
    return float(out) if out.ndim == 0 else out


def arcsec_to_urad(arcsec: ArrayLike) -> np.ndarray | float:
    """Convert arc-seconds to micro-radians (12.4″ → 60.12 µrad).

    Examples
    --------
    >>> round(arcsec_to_urad(12.4), 2)
    60.12
    """
    out = np.asarray(arcsec, dtype=float) / RHO_ARCSEC * 1e6
    return float(out) if out.ndim == 0 else out
