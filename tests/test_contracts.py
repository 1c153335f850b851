"""One contract over every family of formula functions (shapely's ``test_predicates.py``
habit): a scalar in gives a scalar out, a list or an array gives an array of its shape, a
pandas Series gives a Series on the same index, and NaN passes through as NaN — the same for
every function, so a new one joins by a line in :data:`FORMULAS`."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from planner import Scanner
from planner.accuracy import height_rms, max_distance_m, planimetric_rms, ranging_rms_mm
from planner.accuracy3d import (
    footprint_mm,
    incidence_ranging_rms_mm,
    max_distance_3d_m,
    point_rms_3d,
)
from planner.polar import horizontal_distance_m, slope_distance_m
from planner.spacing import facade_point_spacing_mm, point_spacing_mm
from planner.targets import max_target_distance_m, min_target_size_mm

SC = Scanner.from_name("leica-p50")

#: (name, the function of one array argument — the others fixed — and a valid value of it;
#: for a function of several outputs, which one).
FORMULAS = [
    ("planimetric_rms m_x", lambda v: planimetric_rms(v, 30.0, SC)[0], 40.0),
    ("planimetric_rms m_y", lambda v: planimetric_rms(40.0, v, SC)[1], 30.0),
    ("height_rms", lambda v: height_rms(v, 20.0, SC), 40.0),
    ("ranging_rms_mm", lambda v: ranging_rms_mm(v, SC), 40.0),
    ("max_distance_m", lambda v: max_distance_m(5.0, SC, "m_x", v), 30.0),
    ("point_rms_3d m_z", lambda v: point_rms_3d(v, 30.0, 20.0, SC)[2], 40.0),
    ("incidence_ranging_rms_mm", lambda v: incidence_ranging_rms_mm(2.0, v), 0.5),
    ("footprint_mm", lambda v: footprint_mm(v, Scanner.from_name("leica-rtc360")), 40.0),
    ("max_distance_3d_m", lambda v: max_distance_3d_m(5.0, SC, "m_y", 30.0, v), 20.0),
    ("slope_distance_m", lambda v: slope_distance_m(v, 30.0), 40.0),
    ("horizontal_distance_m", lambda v: horizontal_distance_m(v, 30.0), 40.0),
    ("point_spacing_mm", lambda v: point_spacing_mm(v, step_mm_at_10m=2.0), 40.0),
    (
        "facade_point_spacing_mm",
        lambda v: facade_point_spacing_mm(v, 30.0, 10.0, step_mm_at_10m=2.0),
        40.0,
    ),
    ("min_target_size_mm", lambda v: min_target_size_mm(v, "sphere"), 40.0),
    ("max_target_distance_m", lambda v: max_target_distance_m(v, "sphere"), 200.0),
]
IDS = [f[0] for f in FORMULAS]


@pytest.mark.parametrize(("name", "f", "v"), FORMULAS, ids=IDS)
def test_a_scalar_gives_a_scalar(name, f, v):
    out = f(v)
    assert np.ndim(out) == 0 and isinstance(float(out), float) and math.isfinite(float(out))


@pytest.mark.parametrize(("name", "f", "v"), FORMULAS, ids=IDS)
def test_an_array_gives_an_array_of_its_shape_element_by_element(name, f, v):
    values = np.array([[v, 0.9 * v, 1.1 * v], [0.5 * v, v, 0.8 * v]])
    out = np.asarray(f(values))
    assert out.shape == values.shape
    for idx in np.ndindex(values.shape):  # the same as one value at a time
        assert out[idx] == pytest.approx(float(f(float(values[idx]))), rel=1e-12, abs=1e-12)
    assert np.asarray(f([v, v])).shape == (2,)


@pytest.mark.parametrize(("name", "f", "v"), FORMULAS, ids=IDS)
def test_a_series_keeps_its_index(name, f, v):
    s = pd.Series([v, 0.9 * v], index=["a", "b"])
    out = f(s)
    assert isinstance(out, pd.Series) and list(out.index) == ["a", "b"]
    assert out["a"] == pytest.approx(float(f(v)), rel=1e-12)


@pytest.mark.parametrize(("name", "f", "v"), FORMULAS, ids=IDS)
def test_nan_passes_through(name, f, v):
    out = np.asarray(f(np.array([v, np.nan])), dtype=float)
    assert math.isfinite(out[0]) and math.isnan(out[1])
