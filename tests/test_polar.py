"""Geometry helpers: eq. 1, the deviation angle, the tilt, and facade point spacing."""

from __future__ import annotations

import numpy as np
import pytest

from planner import (
    InputError,
    deviation_angle_deg,
    facade_point_spacing_mm,
    polar_to_xyz,
    sight_geometry,
    tilt_deg,
)


def test_eq1_polar_to_xyz():
    xyz = polar_to_xyz([100.0, 200.0, 50.0], 30.0, 60.0, 20.0, 30.0, instrument_height_m=1.5)
    d = 20 * np.cos(np.radians(30))
    np.testing.assert_allclose(xyz, [100.0, 200.0 + d, 50.0 + 10.0 + 1.5], atol=1e-12)  # m


def test_deviation_angle_cases():
    normal = [0.0, 1.0]  # facade along x, outward normal +y
    assert deviation_angle_deg([0, 10], [0, 0], normal) == pytest.approx(0.0)
    assert deviation_angle_deg([10, 10], [0, 0], normal) == pytest.approx(45.0)
    assert deviation_angle_deg([-10, 10], [0, 0], normal) == pytest.approx(45.0)  # unsigned
    assert deviation_angle_deg([10, 0], [0, 0], normal) == pytest.approx(90.0)  # grazing
    assert deviation_angle_deg([0, -10], [0, 0], normal) == pytest.approx(180.0)  # behind
    assert np.isnan(deviation_angle_deg([0, 0], [0, 0], normal))  # right above the point
    # broadcasting: many stations, one point
    got = deviation_angle_deg(np.array([[0, 5], [5, 5], [5, 0]]), [0, 0], normal)
    np.testing.assert_allclose(got, [0, 45, 90], atol=1e-12)


def test_tilt_and_sight_geometry():
    assert tilt_deg([0, 0, 1.5], [10, 0, 11.5]) == pytest.approx(45.0)
    g = sight_geometry([0, 0, 1.5], [3, 4, 13.5], [0, -1])
    assert g.distance_m == pytest.approx(5.0)
    assert g.slope_distance_m == pytest.approx(13.0)
    assert g.nu_deg == pytest.approx(np.degrees(np.arctan2(12, 5)))
    assert g.gamma_deg == pytest.approx(np.degrees(np.arctan2(3, 4)))  # in front: normal -y
    with pytest.raises(InputError, match="3 coordinates"):
        sight_geometry([0, 0], [1, 1, 1], [0, 1])


def test_facade_point_spacing():
    # square on: Sossa's d(S) = 2 mm · 20 m / 10 m
    assert facade_point_spacing_mm(20.0, 0.0, 0.0, step_mm_at_10m=2.0) == pytest.approx(4.0)
    # oblique horizontally: D·δ/cos γ with D = S
    assert facade_point_spacing_mm(20.0, 60.0, 0.0, step_mm_at_10m=2.0) == pytest.approx(8.0)
    # steep: S·δ/cos ν beats D·δ/cos γ
    s, nu = 20.0, 60.0
    assert facade_point_spacing_mm(s, 30.0, nu, step_mm_at_10m=2.0) == pytest.approx(8.0)
    assert facade_point_spacing_mm(10.0, 90.0, 0.0, step_mm_at_10m=2.0) == np.inf
    assert np.isnan(facade_point_spacing_mm(np.nan, 0.0, 0.0, step_mm_at_10m=2.0))


@pytest.mark.parametrize("nu", [-89.0, -30.0, 0.0, 45.0, 89.0])
def test_slope_and_horizontal_distance_round_trip(nu):
    """D = S·cos ν and S = D / cos ν undo each other (to 1 nm), for arrays and scalars; and
    they agree with the polar coordinates of eq. 1 (the point's horizontal offset)."""
    from planner.polar import horizontal_distance_m, slope_distance_m

    s = np.array([0.5, 12.0, 250.0])
    d = horizontal_distance_m(s, nu)
    np.testing.assert_allclose(slope_distance_m(d, nu), s, atol=1e-9)  # m
    assert horizontal_distance_m(12.0, nu) == pytest.approx(float(d[1]), abs=1e-12)
    p = polar_to_xyz([0.0, 0.0, 0.0], 0.0, 30.0, 12.0, nu)
    assert np.hypot(p[0], p[1]) == pytest.approx(float(d[1]), abs=1e-9)  # m
