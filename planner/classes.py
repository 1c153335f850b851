"""Accuracy classes clients write into contracts, as requirements on m_x, m_y and m_z.

* **DIN 18710-1** (Ingenieurvermessung) classes of object points, position ``OGL0``–``OGL5``
  and height ``OGH0``–``OGH5``, each a range of the standard deviation of the coordinates
  (sX, sY) or of the height (sH). The table below follows the classification "after DIN
  18710-1" of the German federal surveying guidelines (Baufachliche Richtlinien Vermessung,
  BFR Vermessung, section 2.2, https://bfrvermessung.de). The planner applies a position
  class to m_x and m_y (the facade frame's coordinates) and a height class to m_z.
* **USIBD Level of Accuracy** (U.S. Institute of Building Documentation, LOA Specification
  Guide C120, version 3.0, 2019): ``LOA10``–``LOA50``, ranges of the measured accuracy
  stated at the 95 % confidence level (2σ). The planner converts to a standard deviation
  by dividing by 2 (for a one-dimensional normal error 95 % is 1.96σ: dividing by 2 is the
  safe side by 2 %) and applies it to m_x, m_y and m_z alike.

The point-density levels of the GSA BIM Guide 03 (3D imaging) are not included: the
project could not verify their figures against the guide.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planner.errors import InputError

__all__ = [
    "CLASSES",
    "AccuracyClass",
    "achieved_class",
    "class_limits",
    "parse_class",
]

BFR = (
    "DIN 18710-1 classes as tabulated in the Baufachliche Richtlinien Vermessung (BFR "
    "Vermessung), section 2.2, https://bfrvermessung.de"
)
USIBD = (
    "USIBD Level of Accuracy (LOA) Specification Guide C120, version 3.0 (2019), "
    "U.S. Institute of Building Documentation; ranges at 95 % (2σ)"
)


@dataclass(frozen=True)
class AccuracyClass:
    """One class: the range (lower, upper] of an error figure [mm] and what it applies to.

    ``coverage_factor`` is k of the stated figure (1: a standard deviation; 2: a 2σ
    range); ``sigma_max_mm`` the largest standard deviation the class allows.
    """

    name: str
    family: str  # "DIN" or "LOA"
    applies_to: str  # "position" (m_x, m_y), "height" (m_z) or "point" (all three)
    lower_mm: float
    upper_mm: float | None  # None: no upper bound (the coarsest class)
    coverage_factor: float
    source: str

    @property
    def sigma_max_mm(self) -> float | None:
        return None if self.upper_mm is None else self.upper_mm / self.coverage_factor

    def describe(self) -> str:
        """``OGL4: 0.5 < σ ≤ 5 mm (position)`` / ``LOA40: 1–5 mm at 95 % → σ ≤ 2.5 mm``."""
        if self.family == "LOA":
            top = f"{self.upper_mm:g} mm" if self.upper_mm else "open"
            conv = f" → σ ≤ {self.sigma_max_mm:g} mm" if self.upper_mm else ""
            return f"{self.name}: {self.lower_mm:g}–{top} at 95 % (2σ){conv} (m_x, m_y, m_z)"
        what = "m_x, m_y" if self.applies_to == "position" else "m_z"
        top = f"≤ {self.upper_mm:g} mm" if self.upper_mm else ""
        return f"{self.name}: {self.lower_mm:g} < σ {top} ({what})".replace("  ", " ")


def _din(prefix: str, applies: str, bounds: list[tuple[float, float | None]]) -> list:
    return [
        AccuracyClass(f"{prefix}{i}", "DIN", applies, lo, hi, 1.0, BFR)
        for i, (lo, hi) in enumerate(bounds)
    ]


#: Every class by name. DIN: σ ranges [mm]; LOA: 2σ ranges [mm].
CLASSES: dict[str, AccuracyClass] = {
    c.name: c
    for c in [
        *_din(
            "OGL",
            "position",
            [(150, 1000), (50, 150), (15, 50), (5, 15), (0.5, 5), (0, 0.5)],
        ),
        *_din("OGH", "height", [(50, 500), (20, 50), (5, 20), (2, 5), (0.5, 2), (0, 0.5)]),
        AccuracyClass("LOA10", "LOA", "point", 50, None, 2.0, USIBD),
        AccuracyClass("LOA20", "LOA", "point", 15, 50, 2.0, USIBD),
        AccuracyClass("LOA30", "LOA", "point", 5, 15, 2.0, USIBD),
        AccuracyClass("LOA40", "LOA", "point", 1, 5, 2.0, USIBD),
        AccuracyClass("LOA50", "LOA", "point", 0, 1, 2.0, USIBD),
    ]
}


def parse_class(spec: str) -> list[AccuracyClass]:
    """The classes named in ``spec``: ``OGL4``, ``OGH3``, ``OGL4/OGH3`` or ``LOA40``.

    Examples
    --------
    >>> [c.name for c in parse_class("ogl4/OGH3")]
    ['OGL4', 'OGH3']
    """
    names = [p.strip().upper() for p in str(spec).replace("+", "/").split("/") if p.strip()]
    if not names:
        raise InputError("an accuracy class is empty; e.g. OGL4/OGH3 or LOA40")
    unknown = [n for n in names if n not in CLASSES]
    if unknown:
        raise InputError(
            f"unknown accuracy class {', '.join(unknown)}; the classes are "
            f"{', '.join(CLASSES)} (DIN 18710-1 position OGL / height OGH, USIBD LOA)"
        )
    out = [CLASSES[n] for n in names]
    applies = [c.applies_to for c in out]
    if len(set(applies)) != len(applies) or ("point" in applies and len(out) > 1):
        raise InputError(
            f"{spec!r} names overlapping classes; give at most one position class and one "
            "height class (OGL4/OGH3), or one LOA class"
        )
    if any(c.upper_mm is None for c in out):
        raise InputError(
            f"{spec!r}: {', '.join(c.name for c in out if c.upper_mm is None)} has no upper "
            "bound to plan for; give the limits in mm instead (--max-xy-mm, --max-z-mm)"
        )
    return out


def class_limits(spec: str) -> dict[str, float]:
    """The requirement limits [mm] a class sets: ``max_xy_mm`` and/or ``max_z_mm``.

    Examples
    --------
    >>> class_limits("OGL4/OGH3")
    {'max_xy_mm': 5.0, 'max_z_mm': 5.0}
    >>> class_limits("LOA40")
    {'max_xy_mm': 2.5, 'max_z_mm': 2.5}
    """
    out: dict[str, float] = {}
    for c in parse_class(spec):
        if c.applies_to in ("position", "point"):
            out["max_xy_mm"] = float(c.sigma_max_mm)
        if c.applies_to in ("height", "point"):
            out["max_z_mm"] = float(c.sigma_max_mm)
    return out


def achieved_class(
    m_x_mm: np.ndarray, m_y_mm: np.ndarray, m_z_mm: np.ndarray, family: str
) -> np.ndarray:
    """The best class of ``family`` ("DIN" or "LOA") each point achieves, as text
    (``OGL4/OGH3``; ``LOA40``); "" where the figures are NaN.

    Examples
    --------
    >>> achieved_class(np.array([3.0]), np.array([4.0]), np.array([1.5]), "DIN").tolist()
    ['OGL4/OGH4']
    >>> achieved_class(np.array([3.0]), np.array([4.0]), np.array([1.5]), "LOA").tolist()
    ['LOA30']
    """

    def best(values: np.ndarray, classes: list[AccuracyClass]) -> np.ndarray:
        names = np.full(values.shape, "", dtype=object)
        for c in sorted(classes, key=lambda c: -(c.upper_mm or np.inf)):  # coarse → fine
            limit = np.inf if c.upper_mm is None else c.sigma_max_mm
            names = np.where(values <= limit * (1 + 1e-9), c.name, names)
        return np.where(np.isnan(values), "", names)

    xy = np.maximum(np.asarray(m_x_mm, float), np.asarray(m_y_mm, float))  # NaN stays NaN
    z = np.asarray(m_z_mm, float)
    if family == "LOA":
        return best(np.maximum(xy, z), [c for c in CLASSES.values() if c.family == "LOA"])
    pos = best(xy, [c for c in CLASSES.values() if c.applies_to == "position"])
    hgt = best(z, [c for c in CLASSES.values() if c.applies_to == "height"])
    joined = np.char.add(np.char.add(pos.astype(str), "/"), hgt.astype(str))
    return np.where((pos == "") | (hgt == ""), "", joined).astype(object)
