"""The plan's inputs resolved once (:func:`resolve`): the search radius, the scanner's preset
and scan step, and how the scans are registered — decided in one place from the scanner,
the requirements (the site-wide one and the zones') and the settings, and taken as one
value (:class:`Inputs`) by the command line, the dashboard, :func:`~planner.plan` and the
district's blocks.

>>> from planner.scanner import DEFAULT_SCANNER, Scanner
>>> r = resolve(Scanner.from_name(DEFAULT_SCANNER))
>>> round(r.reach_m, 1), r.registration, r.parameters
(117.6, 'targets', 6)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from planner.accuracy import reach_bound_m
from planner.accuracy3d import reach_bound_3d_m
from planner.errors import InputError
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.scanner import Scanner
from planner.site import Site
from planner.zones import Zone

__all__ = [
    "MIN_SEARCH_RADIUS_M",
    "Inputs",
    "expect",
    "reach_m",
    "resolve",
    "zone_requirement",
    "zone_requirements",
]

#: Candidate stations farther than this from a facade are not searched [m] (the accuracy
#: bound usually stops well before).
MIN_SEARCH_RADIUS_M = 25.0


def expect(value: object, kind: type, name: str, hint: str) -> None:
    """The Python API's boundary: a wrong type is an InputError saying what to pass."""
    if value is not None and not isinstance(value, kind):
        raise InputError(
            f"{name} must be a planner.{kind.__name__} ({hint}); got {type(value).__name__}"
            + (f" {value!r}"[:80] if isinstance(value, str | Path) else "")
        )


def reach_m(scanner: Scanner, req: Requirements, settings: PlanSettings | None = None) -> float:
    """Search radius for candidate stations [m] for one requirement: the distance beyond
    which no station can meet it under the settings' model
    (:func:`planner.accuracy.reach_bound_m`, :func:`planner.accuracy3d.reach_bound_3d_m`),
    within the scanner's and the requirement's range, and never below
    :data:`MIN_SEARCH_RADIUS_M` — so that even an infeasible requirement gets candidates
    close by and the plan can say what is achievable."""
    st = PlanSettings() if settings is None else settings
    expect(st, PlanSettings, "settings", "PlanSettings(...)")
    tilt = st.scan_tilt_rms_arcsec(scanner)
    if st.model == "paper":
        bound = reach_bound_m(
            scanner, req.max_x_mm, req.max_y_mm, req.max_z_mm, st.station_rms_pair, tilt
        )
    else:
        bound = reach_bound_3d_m(scanner, req.max_x_mm, req.max_y_mm, st.station_rms_pair, tilt)
    limit = min(scanner.max_range_m, req.max_range_m or np.inf)
    return float(min(limit, max(bound, MIN_SEARCH_RADIUS_M)))


def zone_requirement(zone: Zone, req: Requirements) -> Requirements:
    """The requirement inside ``zone``: the site-wide ``req`` with the zone's own values
    (refused with the zone's id where they break the requirement's rules)."""
    try:
        return req.with_overrides(zone.requirement)
    except InputError as exc:
        raise InputError(f"zone {zone.id!r}: {exc}") from None


def zone_requirements(site: Site, req: Requirements) -> list[Requirements]:
    """The requirement of every zone of ``site`` (:func:`zone_requirement`)."""
    return [zone_requirement(z, req) for z in site.zones]


@dataclass(frozen=True)
class Inputs:
    """What a plan is made with, resolved (:func:`resolve`).

    Attributes
    ----------
    scanner : Scanner
    requirements : Requirements
        The site-wide requirement.
    settings : PlanSettings
        The settings with the scan step and preset decided
        (:meth:`~planner.pipeline.inputs.requirements.PlanSettings.for_scanner`).
    reach_m : float
        The search radius [m]: the farthest any requirement (the site-wide one, a zone's)
        lets a station stand from a facade.
    registration : str
        How the scans are registered: "targets", "cloud" or "hybrid"
        (:meth:`~planner.pipeline.inputs.requirements.PlanSettings.registration_for`).
    parameters : int
        The parameters of each scan's registration: 4 (x, y, z and the rotation about the
        vertical) for a scanner whose compensator levels each scan, else 6.
    """

    scanner: Scanner
    requirements: Requirements
    settings: PlanSettings
    reach_m: float
    registration: str
    parameters: int


def resolve(
    scanner: Scanner,
    requirements: Requirements | None = None,
    settings: PlanSettings | None = None,
    zones: Sequence[Requirements] = (),
) -> Inputs:
    """The plan's inputs resolved once (module docstring). ``zones``: the zones'
    requirements (:meth:`Requirements.with_overrides` of the site-wide one); the search
    radius is the farthest any of them reaches, and the preset is chosen for the strictest
    spacing any of them asks. Settings already resolved come back the same."""
    req = Requirements() if requirements is None else requirements
    st = PlanSettings() if settings is None else settings
    expect(req, Requirements, "requirements", "e.g. Requirements(max_xy_mm=4)")
    expect(st, PlanSettings, "settings", "e.g. PlanSettings(grid_m=2)")
    every = list({id(r): r for r in [req, *zones]}.values())
    reach = max(reach_m(scanner, r, st) for r in every)
    spacing = [r.max_spacing_mm for r in every if r.max_spacing_mm]
    st = st.for_scanner(scanner, min(spacing, default=None), reach)
    return Inputs(
        scanner=scanner,
        requirements=req,
        settings=st,
        reach_m=reach,
        registration=st.registration_for(scanner),
        parameters=4 if scanner.is_levelled else 6,
    )
