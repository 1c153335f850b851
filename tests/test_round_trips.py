"""Round trips through the formula layer (pymap3d's habit): a function and its inverse give
back what went in, to a tolerance in physical units."""

from __future__ import annotations

import numpy as np
import pytest

from planner import Scanner, polar_to_xyz, sight_geometry
from planner.accuracy import height_rms, max_distance_m, planimetric_rms
from planner.accuracy3d import max_distance_3d_m, point_rms_3d

SCANNERS = ["leica-4mm-60urad", "leica-p50", "leica-rtc360", "riegl-vz-400i"]


@pytest.mark.parametrize("name", SCANNERS)
@pytest.mark.parametrize("limit", [3.0, 5.0, 8.0])
def test_the_distance_a_limit_holds_to_gives_back_the_limit(name, limit):
    """Eq. 2 / eq. 4 solved for the distance (max_distance_m), then evaluated there: the
    RMS is the limit (to 1 µm) wherever the limit is reachable; the same for the 3-D model."""
    sc = Scanner.from_name(name)
    angles = np.array([0.0, 30.0, 60.0])
    for comp, rms in (
        ("m_x", lambda d, a: planimetric_rms(d, a, sc)[0]),
        ("m_y", lambda d, a: planimetric_rms(d, a, sc)[1]),
        ("m_z", lambda d, a: height_rms(d, a, sc)),
    ):
        d = max_distance_m(limit, sc, comp, angles)
        ok = np.isfinite(d)
        assert ok.any()
        np.testing.assert_allclose(rms(d[ok], angles[ok]), limit, atol=1e-3)  # mm
    for comp, k in (("m_x", 0), ("m_y", 1), ("m_z", 2)):
        s = max_distance_3d_m(limit, sc, comp, 20.0, angles)
        ok = np.isfinite(s)
        if ok.any():
            got = point_rms_3d(s[ok], 20.0, angles[ok], sc)[k]
            np.testing.assert_allclose(got, limit, atol=1e-3)  # mm


@pytest.mark.parametrize("nu", [-40.0, 0.0, 25.0, 70.0])
@pytest.mark.parametrize("beta", [10.0, 95.0, 200.0])
def test_polar_to_xyz_and_sight_geometry_undo_each_other(nu, beta):
    """A point placed by eq. 1 (slope distance, horizontal angle, tilt) is seen from the
    station at that slope distance and tilt (to 1 nm, 1e-9°)."""
    station = np.array([500.0, 800.0, 12.0])
    s = 37.5
    p = polar_to_xyz(station, 15.0, beta, s, nu)
    g = sight_geometry(station, p, [1.0, 0.0])
    assert float(g.slope_distance_m) == pytest.approx(s, abs=1e-9)  # m
    assert float(g.nu_deg) == pytest.approx(nu, abs=1e-9)  # deg
    assert float(g.distance_m) == pytest.approx(s * np.cos(np.radians(nu)), abs=1e-9)  # m
