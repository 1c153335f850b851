"""What the client needs (:class:`Requirements`) and how the planner works
(:class:`PlanSettings`)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from planner.accuracy import station_rms_pair
from planner.errors import InputError
from planner.targets import DEFAULT_INVENTORY, TargetItem, as_inventory

__all__ = ["PlanSettings", "Requirements"]


def _positive(
    value: Any,
    name: str,
    unit: str,
    *,
    allow_none: bool = False,
    lo: float = 0.0,
    hi: float | None = None,
    open_lo: bool = True,
) -> float | None:
    if value is None and allow_none:
        return None
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a number [{unit}]; got {value!r}") from None
    bad = not math.isfinite(v) or (v <= lo if open_lo else v < lo) or (hi is not None and v > hi)
    if bad:
        rule = f"{'>' if open_lo else '>='} {lo:g}" + (f" and <= {hi:g}" if hi is not None else "")
        raise InputError(f"{name} must be {rule} [{unit}]; got {value!r}")
    return v


@dataclass(frozen=True)
class Requirements:
    """Accuracy and coverage the plan must meet at every facade sample.

    Parameters
    ----------
    max_xy_mm : float or (float, float)
        Largest m_x and m_y in the facade frame [mm] (one value for both, or a pair).
    max_z_mm : float
        Largest m_z [mm].
    max_gamma_deg : float, default 75
        Largest deviation of the beam from the facade normal [deg]; grazing beams give
        sparse, noisy points. At most 89.
    max_spacing_mm : float, optional
        Largest point spacing on the facade [mm] at the scan step in use.
    min_range_m, max_range_m : float, optional
        Distance window [m]; by default the scanner's.
    stations_per_sample : int, default 1
        How many stations must each meet every requirement at a sample.
    """

    max_xy_mm: float | tuple[float, float] = 5.0
    max_z_mm: float = 5.0
    max_gamma_deg: float = 75.0
    max_spacing_mm: float | None = None
    min_range_m: float | None = None
    max_range_m: float | None = None
    stations_per_sample: int = 1

    def __post_init__(self) -> None:
        xy = self.max_xy_mm
        pair = tuple(xy) if isinstance(xy, tuple | list) else (xy, xy)
        if len(pair) != 2:
            raise InputError(f"max_xy_mm must be one number or a pair (m_x, m_y) [mm]; got {xy!r}")
        pair = tuple(_positive(v, "max_xy_mm", "mm") for v in pair)
        object.__setattr__(self, "max_xy_mm", pair if pair[0] != pair[1] else pair[0])
        object.__setattr__(self, "max_z_mm", _positive(self.max_z_mm, "max_z_mm", "mm"))
        object.__setattr__(
            self, "max_gamma_deg", _positive(self.max_gamma_deg, "max_gamma_deg", "deg", hi=89.0)
        )
        object.__setattr__(
            self,
            "max_spacing_mm",
            _positive(self.max_spacing_mm, "max_spacing_mm", "mm", allow_none=True),
        )
        lo = _positive(self.min_range_m, "min_range_m", "m", allow_none=True, open_lo=False)
        hi = _positive(self.max_range_m, "max_range_m", "m", allow_none=True)
        if lo is not None and hi is not None and lo >= hi:
            raise InputError(f"min_range_m ({lo:g} m) must be smaller than max_range_m ({hi:g} m)")
        object.__setattr__(self, "min_range_m", lo)
        object.__setattr__(self, "max_range_m", hi)
        k = self.stations_per_sample
        if isinstance(k, bool) or not isinstance(k, int) or not 1 <= k <= 10:
            raise InputError(f"stations_per_sample must be a whole number from 1 to 10; got {k!r}")

    @property
    def max_x_mm(self) -> float:
        xy = self.max_xy_mm
        return xy[0] if isinstance(xy, tuple) else xy

    @property
    def max_y_mm(self) -> float:
        xy = self.max_xy_mm
        return xy[1] if isinstance(xy, tuple) else xy


@dataclass(frozen=True)
class PlanSettings:
    """How the planner samples the site and solves (sensible defaults for a building).

    Parameters
    ----------
    grid_m : float, default 2
        Spacing of candidate stations [m].
    clearance_m : float, default 1
        Free space kept around buildings and obstacles for the tripod [m].
    sample_spacing_m, sample_height_step_m : float, default 2
        Facade sample spacing along the facade and up its height [m].
    instrument_height_m : float, default 1.5
        Scanner centre above the ground [m].
    station_rms_mm : float or (float, float), default 0
        Station / registration RMS m_xc, m_yc added to eq. 2 [mm].
    step_mm_at_10m : float, optional
        Scan step in use [mm at 10 m]; default the scanner's.
    inventory : targets the surveyor owns (default: Sossa's practice).
    target_height_m : float, default 1.6
        Height of targets on stands and on walls [m].
    target_spacing_m : float, default 6
        Spacing of candidate target positions along facades and on free ground [m].
    max_target_incidence_deg : float, default 60
        Beyond this incidence a flat target is not used.
    time_limit_s : float, default 20
        Time limit of the integer program; greedy set cover is the fallback.
    method : "auto", "milp" or "greedy"
    """

    grid_m: float = 2.0
    clearance_m: float = 1.0
    sample_spacing_m: float = 2.0
    sample_height_step_m: float = 2.0
    instrument_height_m: float = 1.5
    station_rms_mm: float | tuple[float, float] = 0.0
    step_mm_at_10m: float | None = None
    inventory: tuple[TargetItem, ...] = field(default=DEFAULT_INVENTORY)
    target_height_m: float = 1.6
    target_spacing_m: float = 6.0
    max_target_incidence_deg: float = 60.0
    time_limit_s: float = 20.0
    method: str = "auto"

    def __post_init__(self) -> None:
        for name, unit in (
            ("grid_m", "m"),
            ("sample_spacing_m", "m"),
            ("sample_height_step_m", "m"),
            ("instrument_height_m", "m"),
            ("target_height_m", "m"),
            ("target_spacing_m", "m"),
            ("time_limit_s", "s"),
        ):
            object.__setattr__(self, name, _positive(getattr(self, name), name, unit))
        object.__setattr__(
            self, "clearance_m", _positive(self.clearance_m, "clearance_m", "m", open_lo=False)
        )
        object.__setattr__(
            self,
            "step_mm_at_10m",
            _positive(self.step_mm_at_10m, "step_mm_at_10m", "mm", allow_none=True),
        )
        object.__setattr__(
            self,
            "max_target_incidence_deg",
            _positive(self.max_target_incidence_deg, "max_target_incidence_deg", "deg", hi=89.0),
        )
        station_rms_pair(self.station_rms_mm)
        object.__setattr__(self, "inventory", as_inventory(self.inventory))
        if self.method not in ("auto", "milp", "greedy"):
            raise InputError(f"method must be 'auto', 'milp' or 'greedy'; got {self.method!r}")
        if self.grid_m < 0.25:
            raise InputError(
                f"grid_m must be >= 0.25 m (got {self.grid_m:g}); finer grids only cost time"
            )
