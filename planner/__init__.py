"""tls-planner: plan terrestrial laser scanner (TLS) stations around buildings.

Unit rule (for the whole package, stated once):

* geometry: **metres** and **degrees**;
* errors (RMS) and target sizes: **millimetres**;
* angular RMS: **arc-seconds**;

an argument that breaks the rule says so in its name (``step_mm_at_10m``, ``range_ppm``).

Layers, each importing only the ones above it in this list:

1. formulas and data classes, flat in :mod:`planner` — :mod:`~planner.accuracy`
   (eq. 2 and 4), :mod:`~planner.polar`, :mod:`~planner.spacing`, :mod:`~planner.targets`,
   :mod:`~planner.scanner`, :mod:`~planner.site`, :mod:`~planner.siteio`,
   :mod:`~planner.calibration`, :mod:`~planner.reference` (the papers);
2. the planning pipeline, :mod:`planner.pipeline` — requirements, facades, candidates,
   visibility, evaluation, the optimiser, registration, :func:`plan` and :class:`Plan`;
3. the application, :mod:`planner.app` — command line, dashboards, reports, maps, figures;
   nothing below imports it, and it holds no science.

The names below are imported lazily (on first use), so ``import planner`` stays cheap.
"""

from __future__ import annotations

import importlib
from importlib.metadata import PackageNotFoundError
from importlib.metadata import version as _version
from typing import Any

try:  # one source: pyproject.toml's version, as installed
    __version__ = _version("tls-planner")
except PackageNotFoundError:  # run from a source tree that was never installed
    __version__ = "0.0.0+unknown"


#: Public name → the module that defines it (one place; ``__all__`` is derived from it).
_EXPORTS: dict[str, str] = {
    "DEFAULT_INVENTORY": "planner.targets",
    "DEFAULT_SCANNER": "planner.scanner",
    "RHO_ARCSEC": "planner.units",
    "Area": "planner.site",
    "Building": "planner.site",
    "InputError": "planner.errors",
    "Obstacle": "planner.site",
    "Plan": "planner.pipeline.engine.result",
    "PlanSettings": "planner.pipeline.inputs.requirements",
    "PlannerError": "planner.errors",
    "Requirements": "planner.pipeline.inputs.requirements",
    "Scanner": "planner.scanner",
    "Site": "planner.site",
    "TargetItem": "planner.targets",
    "arcsec_to_urad": "planner.units",
    "catalogue": "planner.scanner",
    "default_site": "planner.siteio",
    "deviation_angle_deg": "planner.polar",
    "facade_point_spacing_mm": "planner.spacing",
    "height_rms": "planner.accuracy",
    "load_scanner": "planner.scanner",
    "max_distance_m": "planner.accuracy",
    "max_target_distance_m": "planner.targets",
    "min_target_size_mm": "planner.targets",
    "plan": "planner.pipeline.district.groups",
    "planimetric_rms": "planner.accuracy",
    "point_spacing_mm": "planner.spacing",
    "polar_to_xyz": "planner.polar",
    "ranging_rms_mm": "planner.accuracy",
    "read_site": "planner.siteio",
    "recommend_targets": "planner.targets",
    "sight_geometry": "planner.polar",
    "tilt_deg": "planner.polar",
    "urad_to_arcsec": "planner.units",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'planner' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value  # later look-ups skip this function
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
