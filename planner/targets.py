"""Registration target sizing: Sossa's 2d / 4d rule and a user's target inventory.

Reference: B. R. Sossa (2018), Table 2 (full citation in :data:`planner.reference.REFERENCES`;
explained in ``docs/science.md``). A target is usable at a distance
when it spans enough scan points to fit its surface unambiguously:

* flat (plane): 3 non-collinear points span d, plus one d for the beam missing the ideal
  spots → **2d**;
* sphere: 5 points on two scan lines span 3d, plus d → **4d**;
* cylinder: 9 points on three scan lines span 3d, plus d → **4d**;

where d = step_10m · D / 10 m is the point spacing (Table 1). A flat target seen at an
incidence θ from its normal has its points stretched by 1/cos θ along the tilt, so it needs
2d / cos θ (a departure from the paper, which treats targets square to the beam).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike

from planner._array import as_float_array, check_range, like_input
from planner.errors import InputError
from planner.ranges import RANGES
from planner.scanner import Scanner
from planner.spacing import point_spacing_mm, resolve_step_mm

__all__ = [
    "DEFAULT_INVENTORY",
    "SPACING_FACTOR",
    "TARGET_TYPES",
    "TargetItem",
    "choose_target",
    "chosen_sizes",
    "max_target_distance_m",
    "min_target_size_mm",
    "parse_inventory",
    "recommend_targets",
    "size_rules",
    "target_size_kernel",
]

#: The scan step Sossa's tables use [mm at 10 m].
SOSSA_STEP_MM_AT_10M = 2.0

#: Minimum target size in units of the point spacing d (Sossa, Table 2).
SPACING_FACTOR: dict[str, int] = {"flat": 2, "sphere": 4, "cylinder": 4}
TARGET_TYPES: tuple[str, ...] = tuple(SPACING_FACTOR)


def _check_type(target_type: str) -> str:
    t = str(target_type).strip().lower()
    if t not in SPACING_FACTOR:
        raise InputError(
            f"target type must be one of {', '.join(TARGET_TYPES)}; got {target_type!r}"
        )
    return t


def _cos_incidence(target_type: str, incidence_deg: ArrayLike) -> np.ndarray:
    inc = check_range(
        as_float_array(incidence_deg, "incidence_deg"),
        "incidence_deg",
        "deg",
        hi=90.0,
        absolute=True,
    )
    return np.cos(np.radians(inc)) if target_type == "flat" else np.ones_like(inc)


def target_size_kernel(
    factor: np.ndarray | float, spacing_mm: np.ndarray, cos_incidence: np.ndarray | float = 1.0
) -> np.ndarray:
    """The array kernel of the 2d / 4d rule (no validation; registration planning calls it):
    ``factor · d / cos θ`` [mm], ``factor`` from :data:`SPACING_FACTOR`, ``cos_incidence`` 1
    for spheres and cylinders. Infinite for a flat target seen edge-on."""
    with np.errstate(divide="ignore"):
        return factor * spacing_mm / np.where(cos_incidence > 0, cos_incidence, 0.0)


def min_target_size_mm(
    distance_m: ArrayLike,
    target_type: str,
    *,
    step_mm_at_10m: float | None = None,
    scanner: Scanner | None = None,
    incidence_deg: ArrayLike = 0.0,
) -> Any:
    """Minimum size [mm] of a ``flat`` (side), ``sphere`` or ``cylinder`` (diameter) target.

    ``2d`` for flat, ``4d`` for spheres and cylinders (Sossa, Table 2), d the point spacing
    at ``distance_m`` for the scan step (``step_mm_at_10m``, else the scanner's, else 2 mm —
    the paper's value). A flat target at ``incidence_deg`` from square-on needs 2d / cos θ.

    Examples
    --------
    >>> min_target_size_mm([50, 350], "sphere", step_mm_at_10m=2.0).tolist()
    [40.0, 280.0]
    """
    t = _check_type(target_type)
    step = resolve_step_mm(scanner, step_mm_at_10m, default=SOSSA_STEP_MM_AT_10M)
    d = np.asarray(point_spacing_mm(distance_m, step_mm_at_10m=step))
    size = target_size_kernel(SPACING_FACTOR[t], d, _cos_incidence(t, incidence_deg))
    return like_input(np.asarray(size, dtype=float), distance_m)


def max_target_distance_m(
    size_mm: ArrayLike,
    target_type: str,
    *,
    step_mm_at_10m: float | None = None,
    scanner: Scanner | None = None,
    incidence_deg: ArrayLike = 0.0,
) -> Any:
    """Largest distance [m] at which a target of ``size_mm`` still qualifies (inverse rule)."""
    t = _check_type(target_type)
    step = resolve_step_mm(scanner, step_mm_at_10m, default=SOSSA_STEP_MM_AT_10M)
    size = check_range(as_float_array(size_mm, "size_mm"), "size_mm", "mm", lo=0.0)
    dist = size * 10.0 * _cos_incidence(t, incidence_deg) / (SPACING_FACTOR[t] * step)
    return like_input(np.asarray(dist, dtype=float), size_mm)


#: Practice beside Sossa's minimum (the planner's defaults; PlanSettings can change them):
#: a printed checkerboard's centre is found from its four quadrants, each of which must
#: hold this many points …
MIN_POINTS_PER_QUADRANT = 4
#: … and it is not used beyond this incidence (FARO's guidance for targets in SCENE) [deg];
MAX_CHECKERBOARD_INCIDENCE_DEG = 45.0
#: a sphere's centre fit needs this many points on the visible cap.
MIN_POINTS_ON_SPHERE = 20


def size_rules(
    target_type: str,
    spacing_mm: np.ndarray,
    cos_incidence: np.ndarray,
    *,
    points_per_quadrant: float = MIN_POINTS_PER_QUADRANT,
    points_on_sphere: float = MIN_POINTS_ON_SPHERE,
) -> tuple[np.ndarray, np.ndarray]:
    """The minimum size [mm] a target needs and the rule that sets it (array kernel).

    The larger of Sossa's 2d / 4d (:func:`target_size_kernel`) and practice: a flat
    (checkerboard) target of side a seen at incidence θ puts (a/2)²·cos θ / d² points in a
    quadrant, so it needs ``a >= 2d·√(q / cos θ)``; a sphere of diameter D shows π·D²/4 / d²
    points, so it needs ``D >= 2d·√(p / π)``. Cylinders keep Sossa's rule. The rule is
    returned as text (``Sossa 2d``, ``4 points per quadrant``, ``20 points on the sphere``).

    Examples
    --------
    >>> need, rule = size_rules("flat", np.array([10.0, 10.0]), np.array([1.0, 0.1]))
    >>> need.round(1).tolist(), rule.tolist()
    ([40.0, 200.0], ['4 points per quadrant', 'Sossa 2d'])
    """
    t = _check_type(target_type)
    d = np.asarray(spacing_mm, dtype=float)
    cos_t = np.asarray(cos_incidence, dtype=float) * np.ones_like(d)
    sossa = target_size_kernel(SPACING_FACTOR[t], d, cos_t)
    sossa_rule = f"Sossa {SPACING_FACTOR[t]}d"
    if t == "flat":
        with np.errstate(divide="ignore", invalid="ignore"):
            practice = 2.0 * d * np.sqrt(points_per_quadrant / np.where(cos_t > 0, cos_t, 0.0))
        practice_rule = f"{points_per_quadrant:g} points per quadrant"
    elif t == "sphere":
        practice = 2.0 * d * np.sqrt(points_on_sphere / np.pi)
        practice_rule = f"{points_on_sphere:g} points on the sphere"
    else:
        return sossa, np.full(d.shape, sossa_rule, dtype=object)
    rule = np.where(practice > sossa, practice_rule, sossa_rule).astype(object)
    return np.maximum(sossa, practice), rule


@dataclass(frozen=True)
class TargetItem:
    """One kind of target a surveyor owns: a name, a type, its size [mm] and how many the
    crew has (``count``; None: as many as the plan needs, e.g. printed checkerboards)."""

    name: str
    type: str
    size_mm: float
    count: int | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "type", _check_type(self.type))
        size = RANGES["target_size_mm"].check(self.size_mm, f"target {self.name!r}: size_mm")
        object.__setattr__(self, "size_mm", size)
        if self.count is not None:
            if isinstance(self.count, bool) or int(self.count) != self.count or self.count < 1:
                raise InputError(
                    f"target {self.name!r}: count must be a whole number >= 1 (how many the "
                    f"crew has); got {self.count!r}"
                )
            object.__setattr__(self, "count", int(self.count))


#: A typical kit, sized by Sossa's practice (standard spheres 200 mm, sometimes 400 mm;
#: cylindrical site objects at most ~150 mm; flat surfaces of 70 mm side): six 200 mm
#: spheres and two 400 mm ones on their stands (an assumption: crews own a handful, and
#: the plan says what to bring where a job needs more standing at once), checkerboards
#: printed as needed and cylinders found on site (no count).
DEFAULT_INVENTORY: tuple[TargetItem, ...] = (
    TargetItem("flat-70", "flat", 70.0),
    TargetItem("sphere-200", "sphere", 200.0, 6),
    TargetItem("sphere-400", "sphere", 400.0, 2),
    TargetItem("cylinder-150", "cylinder", 150.0),
)


def as_inventory(
    items: Iterable[TargetItem | tuple[str, str, float]] | None,
) -> tuple[TargetItem, ...]:
    """An inventory from TargetItems or ``(name, type, size_mm)`` tuples; None → default."""
    if items is None:
        return DEFAULT_INVENTORY
    out = tuple(i if isinstance(i, TargetItem) else TargetItem(*i) for i in items)
    if not out:
        raise InputError("the target inventory is empty; list at least one (name, type, size_mm)")
    return out


def parse_inventory(text: str) -> tuple[TargetItem, ...]:
    """An inventory from text, one item per line: ``name, type, size_mm[, count]`` (``#``
    comments; without a count, as many as the plan needs).

    Examples
    --------
    >>> parse_inventory("sphere-200, sphere, 200, 12  # the usual ones")
    (TargetItem(name='sphere-200', type='sphere', size_mm=200.0, count=12),)
    """
    items = []
    for lineno, line in enumerate(str(text).splitlines(), start=1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        parts = [p.strip() for p in line.split(",")]
        if len(parts) not in (3, 4):
            raise InputError(
                f"inventory line {lineno} ({line!r}): write name, type, size in mm and, "
                "optionally, how many you have (e.g. sphere-200, sphere, 200, 12)"
            )
        try:
            size = float(parts[2])
        except ValueError:
            raise InputError(
                f"inventory line {lineno}: the size {parts[2]!r} is not a number of mm"
            ) from None
        count = None
        if len(parts) == 4 and parts[3]:
            try:
                count = int(parts[3])
            except ValueError:
                raise InputError(
                    f"inventory line {lineno}: the count {parts[3]!r} is not a whole number"
                ) from None
        items.append(TargetItem(parts[0], parts[1], size, count))
    return as_inventory(items)


def recommend_targets(
    distance_m: float,
    inventory: Sequence[TargetItem] | None = None,
    *,
    step_mm_at_10m: float | None = None,
    scanner: Scanner | None = None,
    incidence_deg: float = 0.0,
) -> pd.DataFrame:
    """Which inventory items qualify at ``distance_m``, and how far each one serves.

    Returns a DataFrame with columns ``name, type, size_mm, min_size_mm, qualifies,
    max_distance_m`` — one row per item, qualifying ones first, smallest first.
    """
    inv = as_inventory(inventory)
    rows = []
    for item in inv:
        kw = {"step_mm_at_10m": step_mm_at_10m, "scanner": scanner, "incidence_deg": incidence_deg}
        need = float(min_target_size_mm(distance_m, item.type, **kw))
        rows.append(
            {
                "name": item.name,
                "type": item.type,
                "size_mm": item.size_mm,
                "min_size_mm": need,
                "qualifies": item.size_mm >= need,
                "max_distance_m": float(max_target_distance_m(item.size_mm, item.type, **kw)),
            }
        )
    df = pd.DataFrame(rows)
    return df.sort_values(["qualifies", "size_mm"], ascending=[False, True], ignore_index=True)


def choose_target(
    min_size_mm: float, target_type: str, inventory: Sequence[TargetItem] | None = None
) -> TargetItem | None:
    """The smallest item of ``target_type`` at least ``min_size_mm`` big (the first listed of
    that size), or None."""
    t = _check_type(target_type)
    size = float(chosen_sizes(min_size_mm, t, inventory))
    return next((i for i in as_inventory(inventory) if i.type == t and i.size_mm == size), None)


def chosen_sizes(
    min_size_mm: ArrayLike, target_type: str, inventory: Sequence[TargetItem] | None = None
) -> np.ndarray:
    """The size [mm] of the smallest item of ``target_type`` at least as big as each of
    ``min_size_mm`` (NaN where none is big enough): the rule :func:`choose_target` picks its
    item by, for many sizes at once.

    Examples
    --------
    >>> chosen_sizes([150.0, 200.0, 300.0, 500.0], "sphere").tolist()
    [200.0, 200.0, 400.0, nan]
    """
    t = _check_type(target_type)
    sizes = np.sort([i.size_mm for i in as_inventory(inventory) if i.type == t])
    need = np.asarray(min_size_mm, dtype=float)
    if not len(sizes):
        return np.full(need.shape, np.nan)
    at = np.searchsorted(sizes, need, side="left")  # the first at least as big (NaN: none)
    return np.where(at < len(sizes), sizes[np.minimum(at, len(sizes) - 1)], np.nan)
