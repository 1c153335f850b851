"""The package's structure holds: layers, one source of truth, doctests that run, the report
showing exactly the plan ``plan`` makes, and a strict ``milp`` method."""

from __future__ import annotations

import inspect
from dataclasses import fields

import numpy as np
import pytest

from planner.pipeline.evaluation.evaluate import PairMetrics
from planner.pipeline.inputs.requirements import (
    CHECKS,
    PlanSettings,
    Requirements,
    requirements_and_settings,
)
from planner.pipeline.inputs.schema import METRIC_KEYS


# -- one table of requirement checks ------------------------------------------------------
def test_every_requirement_limit_has_exactly_one_check():
    limits = {c.limit for c in CHECKS}
    req_fields = {f.name for f in fields(Requirements)} - {
        "max_xy_mm",
        "stations_per_sample",
        "min_view_angle_deg",  # how redundant stations stand, not a limit on a sample
        "accuracy_class",
    }
    assert req_fields | {"max_x_mm", "max_y_mm"} == limits
    assert len({c.key for c in CHECKS}) == len(CHECKS)
    for c in CHECKS:
        assert c.metric in METRIC_KEYS, c
        assert c.metric in inspect.signature(PairMetrics).parameters or hasattr(
            PairMetrics, c.metric
        ), c


def test_the_table_drives_summary_and_reasons():
    from planner.pipeline.engine.planning import plan

    req = Requirements(max_xy_mm=5.0, max_z_mm=5.0, max_spacing_mm=0.5)  # 0.5 mm: unreachable
    p = plan(None, None, req, PlanSettings(sample_spacing_m=6, sample_height_step_m=5))
    assert "point spacing <= 0.5 mm" in p.summary()
    reasons = set(p.unmet["reason"])
    assert any(r.startswith("best achievable point spacing") for r in reasons), reasons
    assert not p.meets_all


def test_check_passes_and_ratio_in_both_senses():
    by = {c.key: c for c in CHECKS}
    v = np.array([1.0, 2.0, 3.0])
    assert by["m_x"].passes(v, 2.0).tolist() == [True, True, False]
    assert by["min_range"].passes(v, 2.0).tolist() == [False, True, True]
    assert by["m_x"].ratio(v, np.inf).tolist() == [0.0, 0.0, 0.0]
    assert by["min_range"].ratio(v, 2.0).tolist() == pytest.approx([2.0, 1.0, 2 / 3])


def test_options_not_given_leave_the_data_class_defaults():
    req, st = requirements_and_settings({"max_z_mm": None, "grid_m": None, "other": 3})
    assert req == Requirements() and st == PlanSettings()
    req, st = requirements_and_settings({"max_z_mm": 4.0, "grid_m": 3.0})
    assert req.max_z_mm == 4.0 and st.grid_m == 3.0
