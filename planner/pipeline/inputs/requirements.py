"""What the client needs (:class:`Requirements`), how the planner works (:class:`PlanSettings`),
and the one table of requirement checks (:data:`CHECKS`).

One source of truth:

* every default, unit, bound and label of a requirement or a setting is written once, in
  the fields below (their ``metadata``); the command line, the dashboard and the report
  read them from here (:func:`field_specs`);
* every requirement that judges a facade sample is one row of :data:`CHECKS`; the
  evaluation (which candidate meets which sample), the "best achievable" diagnosis, the
  reasons, the summary, the report and the dashboard all read that table. Adding a
  requirement means adding its limit field here and its row to :data:`CHECKS` (and the
  metric, if the evaluation does not compute it yet).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass, field, fields, replace
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from planner.accuracy import station_rms_pair
from planner.classes import class_limits, parse_class
from planner.cloud_registration import (
    DEFAULT_CLOUD_FLOOR_MM,
    DEFAULT_CLOUD_SPACING_MM,
    DEFAULT_MIN_OVERLAP_PCT,
    DEFAULT_REVEAL_DEPTH_M,
    DEFAULT_WINDOW_SHARE,
)
from planner.errors import InputError
from planner.materials import CONDITIONS, Material, MaterialTable, material_table
from planner.ranges import Range, check_number
from planner.targets import DEFAULT_INVENTORY, TargetItem, as_inventory

if TYPE_CHECKING:
    from planner.scanner import Scanner

__all__ = [
    "CHECKS",
    "DEFAULT_STATION_SPACING_M",
    "GENERIC_SETUP_MIN",
    "Check",
    "FieldSpec",
    "PlanSettings",
    "Requirements",
    "field_specs",
    "requirements_and_settings",
]


# -- field metadata -----------------------------------------------------------------------
def _spec(
    default: Any,
    unit: str,
    label: str,
    *,
    lo: float | None = 0.0,
    hi: float | None = None,
    open_lo: bool = True,
    optional: bool = False,
    step: float = 1.0,
    help: str = "",
    group: str = "",
) -> Any:
    """A dataclass field carrying its unit, valid range, label and group (read by
    validation, the command line and the widgets)."""
    meta = {
        "group": group,
        "unit": unit,
        "label": label,
        "lo": lo,
        "hi": hi,
        "open_lo": open_lo,
        "optional": optional,
        "step": step,
        "help": help,
    }
    return field(default=default, metadata=meta)


@dataclass(frozen=True)
class FieldSpec:
    """A requirement or setting as the user interfaces show it."""

    name: str
    default: Any
    unit: str
    label: str
    lo: float | None
    hi: float | None
    open_lo: bool
    optional: bool
    step: float
    help: str
    group: str = ""

    @property
    def flag(self) -> str:
        """The command-line option: ``max_z_mm`` → ``--max-z-mm``."""
        return "--" + self.name.replace("_", "-")

    @functools.cached_property
    def range(self) -> Range:
        """The values it may take (:class:`planner.ranges.Range`)."""
        return Range(self.lo, self.hi, self.unit, self.open_lo)

    def rule(self) -> str:
        """The valid range in words, e.g. ``> 0 and <= 89``."""
        return self.range.rule()


@functools.cache
def field_specs(cls: type) -> dict[str, FieldSpec]:
    """The fields of :class:`Requirements` or :class:`PlanSettings` that carry a spec (one
    dictionary per class, made once: read it, do not change it)."""
    out = {}
    for f in fields(cls):
        if "unit" in f.metadata:
            out[f.name] = FieldSpec(name=f.name, default=f.default, **f.metadata)
    return out


def _number(value: Any, spec: FieldSpec) -> float | None:
    if value is None and spec.optional:
        return None
    return check_number(value, spec.name, spec.range)


def _validate_numbers(obj: Any, skip: tuple[str, ...] = ()) -> None:
    for name, spec in field_specs(type(obj)).items():
        if name not in skip:
            object.__setattr__(obj, name, _number(getattr(obj, name), spec))


# -- requirements -------------------------------------------------------------------------
@dataclass(frozen=True, kw_only=True)
class Requirements:
    """Accuracy and coverage the plan must meet at every facade sample.

    Parameters
    ----------
    max_xy_mm : float or (float, float), default 5
        Largest m_x and m_y in the facade frame [mm] (one value for both, or a pair).
    max_z_mm : float, default 5
        Largest m_z [mm].
    max_gamma_deg : float, default 75
        Largest deviation γ of the beam from the facade normal, measured in plan [deg];
        grazing beams give sparse, noisy points. At most 89.
    max_incidence_deg : float, optional
        Largest 3-D incidence θ, the angle between the beam and the facade normal in space
        (cos θ = cos γ · cos ν, so θ ≥ γ) [deg]. At most 89.
    max_spacing_mm : float, optional
        Largest point spacing on the facade [mm] at the scan step in use.
    min_range_m, max_range_m : float, optional
        Slope-distance window [m]; by default the scanner's.
    stations_per_sample : int, default 1
        How many stations must each meet every requirement at a sample.
    min_view_angle_deg : float, default 30
        With two or more stations per sample, the smallest angle between their views of it
        (in plan, seen from the sample) for them to count as separate views.
    accuracy_class : str, optional
        A contract's accuracy class (``OGL4/OGH3``, ``LOA40``; :mod:`planner.classes`),
        which sets ``max_xy_mm`` and/or ``max_z_mm``.
    """

    max_xy_mm: float | tuple[float, float] = _spec(
        5.0,
        "mm",
        "largest m_x, m_y",
        step=0.5,
        help="largest m_x and m_y in the facade frame",
        hi=1000.0,
        lo=0.01,
        open_lo=False,
    )
    max_z_mm: float = _spec(
        5.0,
        "mm",
        "largest m_z",
        step=0.5,
        help="largest height RMS m_z",
        hi=1000.0,
        lo=0.01,
        open_lo=False,
    )
    max_gamma_deg: float = _spec(
        75.0,
        "deg",
        "largest deviation γ",
        hi=89.0,
        step=5.0,
        help="largest deviation of the beam from the facade normal, in plan",
    )
    max_spacing_mm: float | None = _spec(
        None,
        "mm",
        "largest point spacing",
        optional=True,
        help="largest point spacing on the facade at the scan step in use",
        hi=10000.0,
        lo=0.1,
        open_lo=False,
    )
    min_range_m: float | None = _spec(
        None,
        "m",
        "shortest distance",
        open_lo=False,
        optional=True,
        help="shortest slope distance station to point (default: the scanner's)",
        hi=10000.0,
    )
    max_incidence_deg: float | None = _spec(
        None,
        "deg",
        "largest incidence θ",
        hi=89.0,
        optional=True,
        step=5.0,
        help="largest 3-D angle between the beam and the facade normal (cos θ = cos γ·cos ν)",
    )
    max_range_m: float | None = _spec(
        None,
        "m",
        "longest distance",
        optional=True,
        step=5.0,
        help="longest slope distance station to point (default: the scanner's)",
        hi=10000.0,
        lo=0.1,
        open_lo=False,
    )
    stations_per_sample: int = _spec(
        1,
        "stations",
        "stations per sample",
        lo=1,
        hi=10,
        open_lo=False,
        help="how many stations must each meet every requirement at a sample",
    )
    min_view_angle_deg: float = _spec(
        30.0,
        "deg",
        "smallest angle between views",
        open_lo=False,
        hi=150.0,
        step=5.0,
        help="with 2 or more stations per sample: the smallest angle (in plan, seen from the "
        "sample) between the stations counted, so that they see it from different directions",
    )
    accuracy_class: str | None = None

    def __post_init__(self) -> None:
        if self.accuracy_class is not None:
            self._apply_class()
        xy = self.max_xy_mm
        pair = tuple(xy) if isinstance(xy, tuple | list) else (xy, xy)
        if len(pair) != 2:
            raise InputError(f"max_xy_mm must be one number or a pair (m_x, m_y) [mm]; got {xy!r}")
        spec = field_specs(Requirements)["max_xy_mm"]
        pair = tuple(_number(v, spec) for v in pair)
        object.__setattr__(self, "max_xy_mm", pair if pair[0] != pair[1] else pair[0])
        k = self.stations_per_sample
        if isinstance(k, bool) or not isinstance(k, int | np.integer) or not 1 <= k <= 10:
            raise InputError(f"stations_per_sample must be a whole number from 1 to 10; got {k!r}")
        object.__setattr__(self, "stations_per_sample", int(k))
        _validate_numbers(self, skip=("max_xy_mm", "stations_per_sample"))
        lo, hi = self.min_range_m, self.max_range_m
        if lo is not None and hi is not None and lo >= hi:
            raise InputError(f"min_range_m ({lo:g} m) must be smaller than max_range_m ({hi:g} m)")

    def _apply_class(self) -> None:
        """Set the limits the accuracy class implies; a different explicit limit for the
        same quantity is a conflict (give one or the other)."""
        names = "/".join(c.name for c in parse_class(self.accuracy_class))
        object.__setattr__(self, "accuracy_class", names)
        for key, value in class_limits(names).items():
            given, default = getattr(self, key), field_specs(Requirements)[key].default
            if given != default and given != value:
                raise InputError(
                    f"{key}={given!r} conflicts with the accuracy class {names} ({value:g} mm); "
                    "give the class or the limit, not both"
                )
            object.__setattr__(self, key, value)

    @property
    def max_x_mm(self) -> float:
        xy = self.max_xy_mm
        return xy[0] if isinstance(xy, tuple) else xy

    @property
    def max_y_mm(self) -> float:
        xy = self.max_xy_mm
        return xy[1] if isinstance(xy, tuple) else xy

    def with_overrides(self, overrides: Mapping[str, Any]) -> Requirements:
        """This requirement with some fields replaced (a zone's, :mod:`planner.zones`). A
        class in ``overrides`` sets what it covers, the other limits stay these; explicit
        limits in ``overrides`` replace this requirement's class."""
        base = {f.name: getattr(self, f.name) for f in fields(self)}
        if overrides.get("accuracy_class"):
            specs = field_specs(Requirements)
            for key in class_limits(overrides["accuracy_class"]):
                base[key] = specs[key].default
        elif "max_xy_mm" in overrides or "max_z_mm" in overrides:
            base["accuracy_class"] = None
        base.update(overrides)
        return Requirements(**base)

    def active_checks(self) -> list[tuple[Check, float]]:
        """The checks this requirement sets, with their limits (unset limits left out)."""
        return [(c, c.limit_of(self)) for c in CHECKS if c.limit_of(self) is not None]

    def describe(self) -> str:
        """The requirement in one line: ``m_x <= 5 mm, m_y <= 5 mm, …``."""
        text = ", ".join(c.text(limit) for c, limit in self.active_checks())
        k = self.stations_per_sample
        text += f", {k} stations per sample" if k > 1 else ""
        return f"class {self.accuracy_class}: {text}" if self.accuracy_class else text


# -- the table of checks ------------------------------------------------------------------
@dataclass(frozen=True)
class Check:
    """One requirement judged at every sample: ``metric`` compared with ``limit``.

    ``metric`` names a per-pair quantity of the evaluation (``m_x_mm``, ``gamma_deg``…),
    ``limit`` the attribute of :class:`Requirements` holding the limit, ``sense`` whether
    the value must stay below (``"max"``) or above (``"min"``) it.
    """

    key: str
    label: str
    unit: str
    metric: str
    limit: str
    sense: Literal["max", "min"]

    #: Relative slack of the comparison, so a value equal to its limit meets it.
    TOLERANCE = 1e-9

    def limit_of(self, req: Requirements) -> float | None:
        return getattr(req, self.limit)

    def no_limit(self) -> float:
        """The limit meaning "not required" in arrays: +inf for a maximum, -inf for a minimum."""
        return math.inf if self.sense == "max" else -math.inf

    def passes(self, value: np.ndarray, limit: np.ndarray | float) -> np.ndarray:
        """Where ``value`` meets ``limit`` (arrays broadcast; an infinite limit always passes)."""
        if self.sense == "max":
            return value <= limit * (1.0 + self.TOLERANCE)
        return value >= limit * (1.0 - self.TOLERANCE)

    def ratio(self, value: np.ndarray, limit: np.ndarray | float) -> np.ndarray:
        """How far ``value`` is from ``limit``: <= 1 meets (value/limit, or limit/value for a
        minimum); 0 where there is no limit."""
        with np.errstate(divide="ignore", invalid="ignore"):
            r = value / limit if self.sense == "max" else limit / value
        return np.where(np.isfinite(limit), r, 0.0)

    def best(self, values: np.ndarray, axis: int = 0) -> np.ndarray:
        """The best value along ``axis`` (the smallest for a maximum, the largest for a
        minimum); values that do not count must be given as the worst (±inf)."""
        return values.min(axis=axis) if self.sense == "max" else values.max(axis=axis)

    def worst_value(self) -> float:
        return math.inf if self.sense == "max" else -math.inf

    def text(self, limit: float) -> str:
        """``m_x <= 5 mm``."""
        op = "<=" if self.sense == "max" else ">="
        return f"{self.label} {op} {limit:g} {self.unit}".replace(" °", "°")

    def shortfall(self, best: float, limit: float) -> str:
        """``best achievable m_x 5.3 mm > 5 mm``."""
        op = ">" if self.sense == "max" else "<"
        return f"best achievable {self.label} {best:.1f} {self.unit} {op} {limit:g} {self.unit}"


#: Every requirement judged at a sample (one row each; see the module docstring).
CHECKS: tuple[Check, ...] = (
    Check("m_x", "m_x", "mm", "m_x_mm", "max_x_mm", "max"),
    Check("m_y", "m_y", "mm", "m_y_mm", "max_y_mm", "max"),
    Check("m_z", "m_z", "mm", "m_z_mm", "max_z_mm", "max"),
    Check("gamma", "γ", "°", "gamma_deg", "max_gamma_deg", "max"),
    Check("incidence", "θ", "°", "incidence_deg", "max_incidence_deg", "max"),
    Check("spacing", "point spacing", "mm", "spacing_mm", "max_spacing_mm", "max"),
    Check("min_range", "distance", "m", "slope_distance_m", "min_range_m", "min"),
    Check("max_range", "distance", "m", "slope_distance_m", "max_range_m", "max"),
)


# -- settings -----------------------------------------------------------------------------
METHODS = ("auto", "milp", "greedy")
#: How sight lines are answered (:class:`planner.pipeline.geometry.scene.Scene`): ``auto`` — the
#: compiled prism test where the site is footprints on flat ground, else rays cast on the
#: scene's triangles; or either by name.
SIGHT_ENGINES = ("auto", "rays", "prisms")
#: The accuracy models: eq. 2 and 4 of Voroshilov & Karachentsev, or the full 3-D propagation.
MODELS = ("3d", "paper")
#: How the scans are registered: ``auto`` takes the scanner profile's usual workflow
#: (targets when it names none).
REGISTRATION_MODES = ("auto", "targets", "cloud", "hybrid")
#: How the registration software computes the registration the plan promises, in words
#: (the command line's help, the dashboard's tooltips, the summary and the report).
REGISTRATION_PROCESSING = {
    "adjustment": "the scans registered in one adjustment (every scan's targets and surfaces "
    "at once, as a registration program's network or bundle adjustment does)",
    "pairwise": "each scan registered on its own to the one before it along the plan's links "
    "(pair by pair)",
}
#: How the plan checks each cloud-to-cloud link it relies on, in words.
LINK_CHECKS = {
    "rehearse": "each link's two scans rehearsed and registered by a generalized ICP "
    "(small_gicp) from the scanner's pre-alignment: the larger of the model's error and the "
    "rehearsal's is the link's, and a link that fails more than 1 % of the time is not a link",
    "model": "the link model alone (quicker; its closed form assumes the registration converges)",
}
#: Height control the plan may add where the network leans with its datum scan, in words.
HEIGHT_CONTROL = {
    "level": "a level run to some placed targets where the datum's lean would take samples "
    "over the height limit",
    "always": "a level run wherever the network leans, even where the lean keeps no sample "
    "short (a district's blocks do, their frames joined over hundreds of metres)",
    "none": "no height control planned (the plan says what a level run would buy)",
}
#: Which scans' recorded tilts hold the network's vertical (a scanner without a compensator
#: that records its tilt, :attr:`~planner.scanner.Scanner.tilt_sensor_rms_arcsec`), in words.
TILT_READINGS = {
    "every-scan": "every scan's recorded tilt an observation of the adjustment (as registration "
    "software that uses the scanner's inclination does)",
    "datum": "the first (datum) scan's tilt alone; every other scan's tilt taken out by its "
    "registration",
}


#: Side of a district block [m] (:mod:`planner.pipeline.district.blocks`): a few city blocks, a
#: task of seconds to a minute.
#: Least distance between two set-ups [m]: from practice, two set-ups closer than about
#: five metres are to a crew one spot scanned twice (the second a tripod's few paces away).
DEFAULT_STATION_SPACING_M = 5.0
#: Set-up time per station [min] of a scanner whose profile gives none: a tripod set up,
#: levelled and taken down, as the field-time examples of this package have assumed.
GENERIC_SETUP_MIN = 5.0
DEFAULT_BLOCK_M = 250.0
#: A block holding more planned buildings than this is split into quadrants (again while
#: needed). Measured on the synthetic town (benchmarks/RESULTS.md, district section): a
#: block of 100 terraced buildings outgrew a 2 GB worker; one of 27 took 72 s (46 s of it
#: the registration of 85 stations, whose chain then carried 5.8 mm of m_z); blocks of 10–11
#: take 20–26 s and keep their registration chains short.
MAX_BLOCK_BUILDINGS = 12
#: ``--district auto`` plans block by block when the facades need more samples than this
#: (a work estimate, :func:`planner.pipeline.geometry.facades.estimate_samples`), not because the
#: buildings happen to straddle a block line: the 50-building town (11 201 samples) takes
#: about 45 s in one process and 16 s on two workers (benchmarks/RESULTS.md), while a city
#: block of 10 buildings (about 2 000 samples) plans as one registration network best.
DISTRICT_SAMPLES = 8000
#: Memory of each local Dask worker: blocks of up to MAX_BLOCK_BUILDINGS planned buildings
#: peaked at 551 MB per worker on the 1000-building town with 2 workers, 727 MB with one
#: (each worker also holds its blocks' covers until the district's bound is computed;
#: benchmarks/RESULTS.md).
WORKER_MEMORY = "2GB"


#: The groups of :class:`PlanSettings`' fields (key → title), in the order the command line's
#: help and the dashboard's "More settings" show them; each field names its group.
SETTING_GROUPS = {
    "sampling": "Samples, candidate stations and the scan",
    "model": "Accuracy model",
    "registration": "Registration and targets",
    "field": "Field work and documents",
    "solver": "Optimiser, time budget and work limits",
}


def setting_groups() -> dict[str, list[str]]:
    """The names of :class:`PlanSettings`' fields by group (:data:`SETTING_GROUPS`' keys),
    in their order.

    >>> setting_groups()["solver"]
    ['method', 'time_limit_s', 'max_samples', 'job_gap_m', 'max_pairs']
    """
    out: dict[str, list[str]] = {g: [] for g in SETTING_GROUPS}
    for f in fields(PlanSettings):
        out[f.metadata["group"]].append(f.name)
    return out


@dataclass(frozen=True, kw_only=True)
class PlanSettings:
    """How the planner samples the site, models the errors, registers the scans, schedules
    the field work and solves (sensible defaults for a building). The fields come in the
    groups of :data:`SETTING_GROUPS` (:func:`setting_groups`); the command line's help and
    the dashboard's "More settings" show them so.

    Samples, candidate stations and the scan
    ----------------------------------------
    grid_m : float, default 2
        Spacing of candidate stations [m], >= 0.25.
    station_spacing_m : float, default 5
        The least distance between two set-ups a crew keeps [m]
        (:data:`DEFAULT_STATION_SPACING_M`): chosen stations closer are merged into one
        where one set-up meets what both do (:mod:`planner.pipeline.optimise.spacing`),
        else kept and the plan says why; 0 merges nothing.
    clearance_m : float, default 1
        Free space kept around buildings and obstacles for the tripod [m].
    sample_spacing_m, sample_height_step_m : float, default 2
        Facade sample spacing along the facade and up its height [m].
    instrument_height_m : float, default 1.5
        Scanner centre above the ground [m].
    step_mm_at_10m : float, optional
        Scan step in use [mm at 10 m]; default the scanner's.
    preset : str or None, default None
        The scanner's resolution / quality setting (the maker's name, from the catalogue's
        presets). None: the coarsest whose point spacing meets ``max_spacing_mm`` straight
        on at the search radius, else the scanner's default setting
        (:meth:`PlanSettings.for_scanner` decides it once). A ``step_mm_at_10m`` given wins.
    demand_roofs : bool, default False
        Demand the roofs of buildings from a 3-D model too (they need an elevated
        station); walls and doors are always demanded, windows never
        (:func:`planner.citymodel.demanded_kinds`).
    sight_engine : "auto", "rays" or "prisms", default "auto"
        How sight lines are answered (:data:`SIGHT_ENGINES`).

    Accuracy model
    --------------
    model : "3d" or "paper", default "3d"
        ``3d``: the full 3-D propagation (:mod:`planner.accuracy3d`); ``paper``: eq. 2 and
        4 of Voroshilov & Karachentsev as printed. ``docs/science.md`` says why 3-D is the
        default.
    incidence_noise, beam_footprint : bool, default True
        The 3-D model's optional terms: ranging noise growing with the 3-D incidence, and
        the beam's footprint bounding the detail a scan resolves (in the spacing check).
    surface_condition : "dry" or "wet", default "dry"
        The survey day: wet porous materials return a weaker signal (noisier ranging, a
        shorter reach; :mod:`planner.materials`, :mod:`planner.signal`).
    materials : tuple of Material, default ()
        The user's rows added to the material table (``--materials FILE``).
    default_material : str or None, default None
        The material of walls no source names; None: the scanner datasheet's reference
        surface (the figures as published).

    Registration and targets
    ------------------------
    registration : "auto", "targets", "cloud" or "hybrid", default "auto"
        How the scans are registered: by common targets; cloud to cloud (ICP on the
        surfaces two scans share, :mod:`planner.cloud_registration`); or hybrid (cloud links,
        targets only where a link is weak). ``auto``: the scanner profile's workflow, else
        targets.
    registration_processing : "adjustment" or "pairwise", default "adjustment"
        What the promise assumes of the registration software: every scan's targets and
        surfaces adjusted together (a registration program's network or bundle adjustment),
        or each scan registered on its own to the one before it along the plan's links
        (errors add up along the chain; the plan then judges, and adds stations, by that).
    tilt_readings : "every-scan" or "datum", default "every-scan"
        Which recorded tilts hold the network's vertical, for a scanner that records one
        with every scan and has no compensator (:meth:`tilt_model`): all of them, as
        registration software that uses the inclination does in its adjustment, or the
        datum scan's alone (software that ignores the readings, or pairwise processing).
    height_control : "level", "always" or "none", default "level"
        Where the network leans — with its datum scan, or with its scans' tilt readings
        combined (:meth:`tilt_model` "datum" or "readings") — and the lean would take
        samples over the height limit, plan a level run to some of the placed targets
        (:mod:`planner.pipeline.network.height`); "always": wherever the network leans
        (a district plans its blocks so); "none": plan none (the plan still says what one
        would buy).
    level_rms_mm : float, default 1.0
        RMS of each levelled target's height [mm].
    registration_error : bool, default True
        Judge every sample by the scanner's error plus the registration's, propagated from
        the targets (:mod:`planner.registration_error`). A ``station_rms_mm`` given
        replaces the computed registration error by the paper's fixed m_xc, m_yc.
    station_rms_mm : float or (float, float), default 0
        Station / registration RMS m_xc, m_yc added to eq. 2 [mm].
    inventory : targets the surveyor owns (default: Sossa's practice).
    target_height_m : float, default 1.6
        Height of targets on stands and on walls [m].
    high_target_height_m, min_points_per_quadrant, min_points_on_sphere, target_rms_mm,
    target_floor_mm, max_targets_per_link
        Target planning: a second row of wall targets, the practice sizing rules, the
        centre RMS (a figure of your own, or the model with its floor), the most targets a
        link takes.
    target_spacing_m : float, default 6
        Spacing of candidate target positions along facades and on free ground [m].
    max_target_incidence_deg : float, default 45
        Beyond this incidence a flat target is not used.
    window_share, reveal_depth_m : float, default 0.25 and 0.15
        The walls' relief as cloud-to-cloud registration sees it: the share of a wall in
        windows and doors and how deep they sit (:mod:`planner.cloud_registration`, the
        parametric facade); ``window_share=0`` plans the walls plain.
    min_overlap_pct, cloud_floor_mm : float, default 20 and 1
        A cloud link needs this overlap (as registration software counts it); what a
        surface's plane fit does not see, per 2 m cell and scan.
    cloud_spacing_mm : float, default 100
        The even spacing registration software thins the clouds to before a cloud-to-cloud
        registration [mm] (:data:`planner.cloud_registration.DEFAULT_CLOUD_SPACING_MM`).
    link_check : "rehearse" or "model", default "rehearse"
        How the plan checks each cloud link it relies on (:data:`LINK_CHECKS`;
        :mod:`planner.pipeline.network.linkcheck`).
    traverse_mm, gnss_mm : float, default 2 and 15
        The accuracy of planned control (:mod:`planner.pipeline.network.control`), per coordinate
        [mm]: what one leg of a total-station traverse adds, and a GNSS (network RTK) point.

    Field work and documents
    ------------------------
    setup_min : float or None
        Field time to set up, level and take down the scanner at a station [min]; None:
        the scanner profile's figure (:attr:`Scanner.setup_min`, its source in the
        catalogue), else :data:`GENERIC_SETUP_MIN`. Decided once, by :meth:`for_scanner`.
    target_setup_min, target_collect_min : float, default 2 and 1
        Field time to place a target and to collect it once the last station that uses it
        is scanned [min] (targets leap-frog along the visiting order within the
        inventory's counts).
    walk_speed_m_s : float, default 0.8
        Walking speed between stations, carrying the kit [m/s].
    session_h : float, default 4
        Longest field session [h]; the visiting order is split into sessions.
    scan_rate_hz : float, default 500 000
        Measurement rate [points/s] for scan times when the scanner's profile gives none.
    imaging : bool, default True
        Whether each station also takes its images (HDR panorama); the field time counts the
        scanner's ``imaging_s`` for it.
    drawing_scale : int, default 500
        The drawing (DXF) is made for the scale 1 : ``drawing_scale``: its lettering 2.5 mm
        and its symbols 3 mm on paper at that scale.

    Optimiser, time budget and work limits
    --------------------------------------
    method : "auto", "milp" or "greedy"
        ``auto``: the integer program where the bounds do not prove a cover optimal, its
        best cover within the work bounds; ``milp``: an error unless proven optimal;
        ``greedy``: greedy set cover only.
    time_limit_s : float, default 60
        The optimiser's backstop: each search for a smaller cover stops after half of it
        (all of it without registration) in this process's CPU seconds, where its work
        bounds (iterations, nodes) have not ended it first — the plan then says so. The
        rest of a plan (evaluation, diagnosis, network, registration rounds, documents) is
        decided by work and never cut: the same inputs give the same plan on any machine.
        The district mode schedules its blocks within it on the wall clock. A site of
        several jobs (``job_gap_m``) planned from the command line without one takes the
        jobs' estimated time (:func:`planner.pipeline.district.groups.jobs_budget_s`).
    job_gap_m : float or None, default None
        Planned buildings farther apart than this [m] (not joined through others) are
        separate jobs (:mod:`planner.pipeline.district.groups`): each its own network,
        datum and route. None: the search radius; 0: one job.
    max_samples, max_pairs : float, default 1 000 000 and 10⁹
        The work the planner accepts before it starts: facade samples, and candidate ×
        sample evaluations (about 20 million a second). Beyond them the plan is refused with
        the estimate; raise them explicitly for a site that needs it.
    """

    # -- samples, candidate stations and the scan (SETTING_GROUPS['sampling'])
    grid_m: float = _spec(
        2.0,
        "m",
        "candidate grid",
        lo=0.25,
        open_lo=False,
        step=0.5,
        help="candidate grid spacing",
        group="sampling",
        hi=1000.0,
    )
    station_spacing_m: float = _spec(
        DEFAULT_STATION_SPACING_M,
        "m",
        "station spacing",
        open_lo=False,
        step=0.5,
        help="least distance between two set-ups: chosen stations closer are merged where one "
        "set-up meets what both do, else the plan says why (0: never merged)",
        group="sampling",
        hi=1000.0,
    )
    clearance_m: float = _spec(
        1.0,
        "m",
        "clearance",
        open_lo=False,
        step=0.5,
        help="free space kept around buildings and obstacles for the tripod",
        group="sampling",
        hi=100.0,
    )
    sample_spacing_m: float = _spec(
        2.0,
        "m",
        "sample spacing along",
        step=0.5,
        help="facade sample spacing along the facade",
        group="sampling",
        hi=1000.0,
        lo=0.01,
        open_lo=False,
    )
    sample_height_step_m: float = _spec(
        2.0,
        "m",
        "sample spacing up",
        step=0.5,
        help="facade sample spacing up the facade",
        group="sampling",
        hi=1000.0,
        lo=0.01,
        open_lo=False,
    )
    instrument_height_m: float = _spec(
        1.5,
        "m",
        "instrument height",
        step=0.1,
        help="scanner centre above the ground",
        group="sampling",
        hi=100.0,
        lo=0.1,
        open_lo=False,
    )
    step_mm_at_10m: float | None = _spec(
        None,
        "mm",
        "scan step at 10 m",
        optional=True,
        step=0.5,
        help="scan step in use at 10 m (default: the scanner's)",
        group="sampling",
        hi=1000.0,
        lo=0.01,
        open_lo=False,
    )
    preset: str | None = field(default=None, metadata={"group": "sampling"})
    demand_roofs: bool = field(default=False, metadata={"group": "sampling"})
    sight_engine: str = field(default="auto", metadata={"group": "sampling"})
    # -- accuracy model (SETTING_GROUPS['model'])
    model: str = field(default="3d", metadata={"group": "model"})
    incidence_noise: bool = field(default=True, metadata={"group": "model"})
    beam_footprint: bool = field(default=True, metadata={"group": "model"})
    surface_condition: str = field(default="dry", metadata={"group": "model"})
    materials: tuple[Material, ...] = field(default=(), metadata={"group": "model"})
    default_material: str | None = field(default=None, metadata={"group": "model"})
    # -- registration and targets (SETTING_GROUPS['registration'])
    registration: str = field(default="auto", metadata={"group": "registration"})
    registration_processing: str = field(default="adjustment", metadata={"group": "registration"})
    tilt_readings: str = field(default="every-scan", metadata={"group": "registration"})
    height_control: str = field(default="level", metadata={"group": "registration"})
    level_rms_mm: float = _spec(
        1.0,
        "mm",
        "levelled height RMS",
        open_lo=False,
        lo=0.01,
        step=0.1,
        help="RMS of a target's height by the planned level run (default: a digital level's "
        "run over the site and reading the target's centre above the staff's mark)",
        group="registration",
        hi=1000.0,
    )
    registration_error: bool = field(default=True, metadata={"group": "registration"})
    station_rms_mm: float | tuple[float, float] = _spec(
        0.0,
        "mm",
        "station RMS m_xc, m_yc",
        open_lo=False,
        step=0.5,
        help="a fixed station / registration RMS m_xc, m_yc (the paper's) in place of the "
        "registration error computed from the targets; 0: computed",
        group="registration",
        hi=1000.0,
    )
    inventory: tuple[TargetItem, ...] = field(
        metadata={"group": "registration"}, default=DEFAULT_INVENTORY
    )
    target_height_m: float = _spec(
        1.6,
        "m",
        "target height",
        step=0.1,
        help="height of targets on stands and on walls",
        group="registration",
        hi=100.0,
        lo=0.01,
        open_lo=False,
    )
    high_target_height_m: float | None = _spec(
        3.0,
        "m",
        "second wall target height",
        optional=True,
        step=0.5,
        help="height of a second row of wall targets, so that a link's targets spread in height",
        group="registration",
        hi=100.0,
        lo=0.01,
        open_lo=False,
    )
    target_spacing_m: float = _spec(
        6.0,
        "m",
        "target spacing",
        step=1.0,
        help="spacing of candidate target positions along facades and on free ground",
        group="registration",
        hi=1000.0,
        lo=0.1,
        open_lo=False,
    )
    max_target_incidence_deg: float = _spec(
        45.0,
        "deg",
        "largest target incidence",
        hi=89.0,
        step=5.0,
        help="beyond this incidence a flat (checkerboard) target is not used (FARO's guidance "
        "for targets in SCENE: 45°)",
        group="registration",
    )
    min_points_per_quadrant: float = _spec(
        4,
        "points",
        "points per checkerboard quadrant",
        step=1,
        help="each quadrant of a flat target must hold this many scan points",
        group="registration",
        hi=1000000.0,
    )
    min_points_on_sphere: float = _spec(
        20,
        "points",
        "points on a sphere",
        step=1,
        help="a sphere's visible cap must hold this many scan points for its centre fit",
        group="registration",
        hi=1000000.0,
    )
    target_rms_mm: float | None = _spec(
        None,
        "mm",
        "target centre RMS",
        optional=True,
        step=0.1,
        help="your figure for a target centre's RMS per axis (default: the model)",
        group="registration",
        hi=1000.0,
        lo=0.001,
        open_lo=False,
    )
    target_floor_mm: float = _spec(
        0.5,
        "mm",
        "target centre floor",
        open_lo=False,
        step=0.1,
        help="what a centre fit does not see (printing, turning, centring), per axis",
        group="registration",
        hi=1000.0,
    )
    max_targets_per_link: float = _spec(
        6,
        "targets",
        "most targets per link",
        lo=3,
        open_lo=False,
        hi=20,
        step=1,
        help="the most common targets a registration of two stations takes",
        group="registration",
    )
    min_overlap_pct: float = _spec(
        DEFAULT_MIN_OVERLAP_PCT,
        "%",
        "least cloud overlap",
        hi=100.0,
        step=5.0,
        help="the overlap a cloud-to-cloud link needs, as registration software counts it "
        "(Autodesk ReCap asks more than 20 %)",
        group="registration",
    )
    window_share: float = _spec(
        DEFAULT_WINDOW_SHARE,
        "",
        "window share of the walls",
        open_lo=False,
        step=0.05,
        help="share of a wall's area in windows and doors, whose reveals give cloud-to-cloud "
        "registration surfaces along the wall; 0: plain walls (a curtain wall, a blank "
        "gable)",
        group="registration",
        hi=0.9,
    )
    reveal_depth_m: float = _spec(
        DEFAULT_REVEAL_DEPTH_M,
        "m",
        "window reveal depth",
        open_lo=False,
        step=0.05,
        help="how far windows and doors sit behind the wall's face",
        group="registration",
        hi=2.0,
    )
    cloud_spacing_mm: float = _spec(
        DEFAULT_CLOUD_SPACING_MM,
        "mm",
        "cloud registration spacing",
        lo=1.0,
        open_lo=False,
        step=10.0,
        help="the even spacing the registration software thins the clouds to before a "
        "cloud-to-cloud registration (a finer spacing uses shallower relief; the plan's "
        "check of its links takes longer)",
        group="registration",
        hi=1000.0,
    )
    link_check: str = field(default="rehearse", metadata={"group": "registration"})
    cloud_floor_mm: float = _spec(
        DEFAULT_CLOUD_FLOOR_MM,
        "mm",
        "cloud patch floor",
        open_lo=False,
        step=0.5,
        help="what the plane fit of a 2 m surface patch does not see (roughness, edges, "
        "calibration), per scan",
        group="registration",
        hi=1000.0,
    )
    traverse_mm: float = _spec(
        2.0,
        "mm",
        "traverse, per leg",
        step=0.5,
        help="RMS per coordinate that one leg of a total-station traverse adds to planned "
        "control (a 1\u2033 instrument over legs up to 80 m)",
        group="registration",
        hi=1000.0,
        lo=0.001,
        open_lo=False,
    )
    gnss_mm: float = _spec(
        15.0,
        "mm",
        "GNSS point",
        step=1.0,
        help="RMS per coordinate of a planned control point fixed by GNSS (network RTK)",
        group="registration",
        hi=10000.0,
        lo=0.001,
        open_lo=False,
    )
    # -- field work and documents (SETTING_GROUPS['field'])
    setup_min: float | None = _spec(
        None,
        "min",
        "set-up per station",
        step=1.0,
        optional=True,
        help="field time to set up, level and take down the scanner at a station (empty: "
        f"the scanner profile's figure, else {GENERIC_SETUP_MIN:g} min)",
        group="field",
        hi=1440.0,
        lo=0.01,
        open_lo=False,
    )
    target_setup_min: float = _spec(
        2.0,
        "min",
        "set-up per target",
        open_lo=False,
        step=0.5,
        help="field time to place one target (stand or wall) before the first scan that sees it",
        group="field",
        hi=1440.0,
    )
    target_collect_min: float = _spec(
        1.0,
        "min",
        "collecting per target",
        open_lo=False,
        step=0.5,
        help="field time to collect one target once the last station that uses it is scanned",
        group="field",
        hi=1440.0,
    )
    walk_speed_m_s: float = _spec(
        0.8,
        "m/s",
        "walking speed",
        step=0.1,
        help="walking speed carrying the kit",
        group="field",
        hi=50.0,
        lo=0.01,
        open_lo=False,
    )
    session_h: float = _spec(
        4.0,
        "h",
        "session length",
        step=0.5,
        help="longest field session (a battery set, half a day); the route is split into these",
        group="field",
        hi=168.0,
        lo=0.01,
        open_lo=False,
    )
    scan_rate_hz: float = _spec(
        500_000.0,
        "points/s",
        "measurement rate if unknown",
        step=50_000.0,
        help="measurement rate for the scan time when the scanner profile gives none",
        group="field",
        hi=100000000.0,
        lo=100.0,
        open_lo=False,
    )
    imaging: bool = field(default=True, metadata={"group": "field"})
    drawing_scale: int = _spec(
        500,
        "1:N",
        "drawing scale",
        lo=1,
        open_lo=False,
        step=50,
        help="the drawing's scale 1:N (plan.dxf): lettering 2.5 mm and symbols 3 mm on paper",
        group="field",
        hi=1000000.0,
    )
    # -- optimiser, time budget and work limits (SETTING_GROUPS['solver'])
    method: str = field(default="auto", metadata={"group": "solver"})
    time_limit_s: float = _spec(
        60.0,
        "s",
        "time limit",
        step=5.0,
        help="the optimiser's backstop: each search for fewer stations stops after half of "
        "it in CPU seconds, where its work bounds have not ended it first (said in the "
        "plan); the rest of the plan is decided by work, the same on any machine",
        group="solver",
        hi=604800.0,
    )
    max_samples: float = _spec(
        1_000_000,
        "samples",
        "most facade samples",
        step=100_000,
        help="refuse a site that needs more facade samples than this (raise it explicitly)",
        group="solver",
        hi=1000000000.0,
    )
    job_gap_m: float | None = _spec(
        None,
        "m",
        "gap between jobs",
        lo=0.0,
        open_lo=False,
        optional=True,
        step=10.0,
        help="planned buildings farther apart than this are separate jobs, each with its own "
        "network, datum and route (default: the search radius, the farthest a station "
        "serves; 0: one job)",
        group="solver",
        hi=1000000.0,
    )
    max_pairs: float = _spec(
        1e9,
        "pairs",
        "most candidate × sample pairs",
        step=1e8,
        help="refuse a plan that needs more station × sample evaluations than this (about "
        "20 million a second)",
        group="solver",
        hi=10000000000000.0,
    )

    def __post_init__(self) -> None:
        spec = field_specs(PlanSettings)["station_rms_mm"]
        for value in station_rms_pair(self.station_rms_mm):
            _number(value, spec)
        _validate_numbers(self, skip=("station_rms_mm",))
        object.__setattr__(self, "inventory", as_inventory(self.inventory))
        if self.method not in METHODS:
            raise InputError(f"method must be one of {', '.join(METHODS)}; got {self.method!r}")
        if self.model not in MODELS:
            raise InputError(f"model must be one of {', '.join(MODELS)}; got {self.model!r}")
        if self.registration not in REGISTRATION_MODES:
            raise InputError(
                f"registration must be one of {', '.join(REGISTRATION_MODES)}; "
                f"got {self.registration!r}"
            )
        if self.registration_processing not in REGISTRATION_PROCESSING:
            raise InputError(
                "registration processing must be one of "
                f"{', '.join(REGISTRATION_PROCESSING)}; got {self.registration_processing!r}"
            )
        if self.link_check not in LINK_CHECKS:
            raise InputError(
                f"link check must be one of {', '.join(LINK_CHECKS)}; got {self.link_check!r}"
            )
        if self.height_control not in HEIGHT_CONTROL:
            raise InputError(
                f"height control must be one of {', '.join(HEIGHT_CONTROL)}; "
                f"got {self.height_control!r}"
            )
        if self.tilt_readings not in TILT_READINGS:
            raise InputError(
                f"tilt readings must be one of {', '.join(TILT_READINGS)}; "
                f"got {self.tilt_readings!r}"
            )
        if self.preset is not None and (not isinstance(self.preset, str) or not self.preset):
            raise InputError(f"preset must be a setting's name; got {self.preset!r}")
        if self.surface_condition not in CONDITIONS:
            raise InputError(
                f"surface condition must be one of {', '.join(CONDITIONS)}; "
                f"got {self.surface_condition!r}"
            )
        object.__setattr__(self, "materials", tuple(self.materials))
        if not all(isinstance(m, Material) for m in self.materials):
            raise InputError("materials must be planner.materials.Material rows")
        if self.default_material is not None:
            self.material_table.find(self.default_material, "the default material")
        if self.sight_engine not in SIGHT_ENGINES:
            raise InputError(
                f"sight engine must be one of {', '.join(SIGHT_ENGINES)}; got {self.sight_engine!r}"
            )
        for name in (
            "incidence_noise",
            "beam_footprint",
            "registration_error",
            "imaging",
            "demand_roofs",
        ):
            if not isinstance(getattr(self, name), bool):
                raise InputError(f"{name} must be True or False; got {getattr(self, name)!r}")

    @property
    def material_table(self) -> MaterialTable:
        """The material table the plan uses: the shipped one with the user's rows."""
        return material_table(self.materials)

    def model_description(self) -> str:
        """Which model makes the accuracy figures, in words (every output states it)."""
        if self.model == "paper":
            return "eq. 2 and 4 of Voroshilov & Karachentsev (the paper's model)"
        terms = [
            t
            for t, on in (
                ("incidence-dependent ranging", self.incidence_noise),
                ("beam footprint", self.beam_footprint),
            )
            if on
        ]
        return "full 3-D propagation" + (f" with {' and '.join(terms)}" if terms else "")

    def scan_step_mm(self, scanner: Scanner) -> float:
        """The scan step [mm at 10 m] the plan uses with ``scanner``: the one given or
        decided (:meth:`for_scanner`), else the profile's own."""
        return float(self.step_mm_at_10m or scanner.step_mm_at_10m)

    def for_scanner(
        self, scanner: Scanner, max_spacing_mm: float | None, reach: float
    ) -> PlanSettings:
        """These settings with the scan step and preset the plan uses with ``scanner``,
        decided once: a ``step_mm_at_10m`` given stands (with the ``preset`` given, where
        its step is that one, else the scanner's preset of that step, if any); a ``preset``
        given gives its step; else, of the scanner's presets, the coarsest whose spacing
        step·D/10 m at the search radius ``reach`` [m] stays within ``max_spacing_mm`` (the
        strictest spacing required anywhere), or without one the scanner's usual setting. A
        scanner without presets plans at its profile's step."""
        if self.setup_min is None:
            return replace(self, setup_min=self.station_setup_min(scanner)).for_scanner(
                scanner, max_spacing_mm, reach
            )
        if self.step_mm_at_10m is not None:
            same = [
                p for p in scanner.presets if abs(p.step_mm_at_10m - self.step_mm_at_10m) < 0.05
            ]
            named = [p for p in same if self.preset and p.name == self.preset]
            return replace(self, preset=(named or same)[0].name if same else None)
        if self.preset is not None:
            chosen = scanner.preset(self.preset)
        else:
            limit = None if max_spacing_mm is None else max_spacing_mm * 10.0 / max(reach, 1e-9)
            chosen = scanner.choose_preset(limit)
        if chosen is None:
            return self
        return replace(self, preset=chosen.name, step_mm_at_10m=chosen.step_mm_at_10m)

    def station_setup_min(self, scanner: Scanner) -> float:
        """The set-up time per station [min]: the setting, else the scanner profile's
        figure, else :data:`GENERIC_SETUP_MIN`. The one place this default is decided."""
        if self.setup_min is not None:
            return self.setup_min
        return scanner.setup_min if scanner.setup_min is not None else GENERIC_SETUP_MIN

    def registration_for(self, scanner: Scanner) -> str:
        """How the scans are registered with ``scanner``: the setting, or (``auto``) the
        profile's usual workflow, else targets. The one place this default is decided."""
        if self.registration != "auto":
            return self.registration
        return scanner.registration or "targets"

    @property
    def station_rms_pair(self) -> tuple[float, float]:
        """``(m_xc, m_yc)`` [mm]."""
        return station_rms_pair(self.station_rms_mm)

    @property
    def computes_registration(self) -> bool:
        """Whether samples are judged with the registration error computed from targets
        (on, and no fixed ``station_rms_mm`` given in its place)."""
        return self.registration_error and self.station_rms_pair == (0.0, 0.0)

    @property
    def incidence_ranging(self) -> bool:
        """Whether the ranging noise grows with the incidence (the 3-D model's term), for
        facade points and target points alike."""
        return self.model == "3d" and self.incidence_noise

    def tilt_model(self, scanner: Scanner) -> str:
        """How the network's vertical is held — the one place this is decided:

        - ``"compensator"``: a levelled scanner; every scan's compensator fixes its own tilt
          (4-parameter registrations, each scan's residual tilt independent);
        - ``"readings"``: the scanner records its tilt with every scan
          (:attr:`~planner.scanner.Scanner.tilt_sensor_rms_arcsec`), the software uses the
          readings (``tilt_readings`` every-scan) and adjusts every scan together: each
          reading is an observation, so the network leans by their combined error
          (:func:`planner.registration_error.adjust`);
        - ``"datum"``: 6-parameter registrations take out every scan's tilt but the datum
          scan's, whose vertical the whole network keeps
          (:func:`planner.registration_error.datum_tilt_cov`, σ
          :attr:`~planner.scanner.Scanner.datum_tilt_rms_arcsec`)."""
        if scanner.is_levelled:
            return "compensator"
        if (
            scanner.tilt_sensor_rms_arcsec is not None
            and self.tilt_readings == "every-scan"
            and self.registration_processing == "adjustment"
        ):
            return "readings"
        return "datum"

    def scan_tilt_rms_arcsec(self, scanner: Scanner) -> float:
        """The tilt of the scanner's vertical axis counted in every point's scanner part
        [″] — the 3-D model's σ_τ, eq. 4's m_ν0. Heights are against true vertical. Where
        the registration error is computed, the registration part carries each scan's
        frame, its tilt included (a levelled scanner's own residual tilt; else, each scan
        registered with 6 parameters, the datum's tilt, which turns the whole network:
        :func:`planner.registration_error.datum_tilt_cov`), so the scanner part counts
        none; otherwise every scan stands levelled on its own, to the profile's m_ν0
        (:attr:`Scanner.initial_tilt_rms_arcsec`). The one place this is decided."""
        return 0.0 if self.computes_registration else scanner.initial_tilt_rms_arcsec


def requirements_and_settings(
    options: Mapping[str, Any],
) -> tuple[Requirements, PlanSettings]:
    """:class:`Requirements` and :class:`PlanSettings` from a flat mapping of options (the
    command line's, the dashboard's, the report's): keys are field names, a value of None
    means "not given" so the data class default applies. Other keys are ignored."""
    req_names = {f.name for f in fields(Requirements)}
    set_names = {f.name for f in fields(PlanSettings)}
    given = {k: v for k, v in options.items() if v is not None}
    req = Requirements(**{k: v for k, v in given.items() if k in req_names})
    settings = PlanSettings(**{k: v for k, v in given.items() if k in set_names})
    return req, settings
