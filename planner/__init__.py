"""tls-planner: plan terrestrial laser scanner (TLS) stations around buildings.

Unit rule (for the whole package, stated once):

* geometry: **metres** and **degrees**;
* errors (RMS) and target sizes: **millimetres**;
* angular RMS: **arc-seconds**;

an argument that breaks the rule says so in its name (``step_mm_at_10m``, ``range_ppm``).

Layers: formula functions (:mod:`planner.accuracy`, :mod:`planner.spacing`,
:mod:`planner.targets`, :mod:`planner.polar`) → data classes (:class:`Scanner`) →
orchestration (:func:`plan`, in :mod:`planner.planning`); the command line
(:mod:`planner.cli`), notebooks and reports hold no science.
"""

from planner.accuracy import height_rms, planimetric_rms, ranging_rms_mm
from planner.errors import InputError, PlannerError
from planner.planning import Plan, plan
from planner.polar import deviation_angle_deg, polar_to_xyz, sight_geometry, tilt_deg
from planner.requirements import PlanSettings, Requirements
from planner.scanner import Scanner, catalogue, load_scanner
from planner.site import Area, Building, Obstacle, Site
from planner.siteio import default_site, read_site
from planner.spacing import facade_point_spacing_mm, point_spacing_mm
from planner.targets import (
    DEFAULT_INVENTORY,
    TargetItem,
    max_target_distance_m,
    min_target_size_mm,
    recommend_targets,
)
from planner.units import RHO_ARCSEC, arcsec_to_urad, urad_to_arcsec

__version__ = "0.1.0"

__all__ = [
    "DEFAULT_INVENTORY",
    "RHO_ARCSEC",
    "Area",
    "Building",
    "InputError",
    "Obstacle",
    "Plan",
    "PlanSettings",
    "PlannerError",
    "Requirements",
    "Scanner",
    "Site",
    "TargetItem",
    "arcsec_to_urad",
    "catalogue",
    "default_site",
    "deviation_angle_deg",
    "facade_point_spacing_mm",
    "height_rms",
    "load_scanner",
    "max_target_distance_m",
    "min_target_size_mm",
    "plan",
    "planimetric_rms",
    "point_spacing_mm",
    "polar_to_xyz",
    "ranging_rms_mm",
    "read_site",
    "recommend_targets",
    "sight_geometry",
    "tilt_deg",
    "urad_to_arcsec",
]
