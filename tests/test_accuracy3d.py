"""The full 3-D model (planner.accuracy3d) and the accuracy classes (planner.classes): fixed
values worked out by hand, limits, inversions, and the classes' tables."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from planner import InputError, Requirements, Scanner, planimetric_rms
from planner.accuracy3d import (
    footprint_mm,
    incidence_ranging_rms_mm,
    max_distance_3d_m,
    point_rms_3d,
)
from planner.classes import CLASSES, achieved_class, class_limits, parse_class
from planner.polar import incidence_deg

K = 1000 / 206264.80624709636  # mm per m per arc-second


@pytest.fixture(scope="module")
def levelled():
    return Scanner(name="lev", range_rms_mm=1.0, angle_rms_arcsec=8.0, levelling_rms_arcsec=1.5)


def test_at_zero_tilt_without_axis_tilt_the_3d_model_is_eq2(paper_scanner):
    flat = Scanner(name="flat", range_rms_mm=4.0, angle_rms_arcsec=12.4, levelling_rms_arcsec=1e-9)
    for d, g in [(10.0, 0.0), (50.0, 30.0), (120.0, 60.0)]:
        m_x, m_y, _ = point_rms_3d(d, g, 0.0, flat)
        e_x, e_y = planimetric_rms(d, g, paper_scanner)
        assert m_x == pytest.approx(e_x, abs=1e-9) and m_y == pytest.approx(e_y, abs=1e-9)


def test_the_issues_worked_example_by_hand(levelled):
    """1 mm / 8″ at S = 40 m, ν = 60°, γ = 0 (1.5″ compensator), term by term."""
    s, nu = 40.0, np.radians(60.0)
    ranging = (1.0 * np.cos(nu)) ** 2  # 0.25 mm²
    vertical = (s * 8.0 * K * np.sin(nu)) ** 2  # 1.8056 mm²
    tilt = (s * np.sin(nu) * 1.5 * K) ** 2
    m_x, m_y, m_z = point_rms_3d(40.0, 0.0, 60.0, levelled)
    assert m_y == pytest.approx(np.sqrt(ranging + vertical + tilt), abs=1e-9)  # mm
    assert m_y == pytest.approx(1.456, abs=0.001)  # mm, against eq. 2's 1.00 mm
    assert m_x == pytest.approx(np.sqrt((s * np.cos(nu) * 8 * K) ** 2 + tilt), abs=1e-9)
    d = s * np.cos(nu)
    assert m_z == pytest.approx(
        np.sqrt(np.sin(nu) ** 2 + (s * 8 * K * np.cos(nu)) ** 2 + (d * 1.5 * K) ** 2), abs=1e-9
    )


def test_incidence_and_footprint_terms():
    assert incidence_deg(60.0, 45.0) == pytest.approx(69.295, abs=1e-3)  # deg
    assert incidence_ranging_rms_mm(2.0, 0.25) == pytest.approx(4.0)  # mm: 2 / √0.25
    assert incidence_ranging_rms_mm(2.0, 0.0) == pytest.approx(2.0 / np.sqrt(0.1))
    sc = Scanner(
        name="b", range_rms_mm=1, angle_rms_arcsec=5, beam_divergence_mrad=0.3, beam_exit_mm=2.0
    )
    assert footprint_mm(100.0, sc, 0.5) == pytest.approx((2.0 + 30.0) / 0.5)  # mm
    bare = Scanner(name="n", range_rms_mm=1, angle_rms_arcsec=5)
    assert footprint_mm(100.0, bare) == 0.0


@pytest.mark.parametrize("component", ["m_x", "m_y", "m_z"])
@pytest.mark.parametrize(("gamma", "nu"), [(0.0, 0.0), (30.0, 45.0), (60.0, 20.0)])
def test_max_distance_3d_inverts_the_model(paper_scanner, component, gamma, nu):
    for noise in (False, True):
        reach = float(
            max_distance_3d_m(5.0, paper_scanner, component, gamma, nu, incidence_noise=noise)
        )
        if not np.isfinite(reach):
            continue
        values = dict(
            zip(
                ("m_x", "m_y", "m_z"),
                point_rms_3d(reach, gamma, nu, paper_scanner, incidence_noise=noise),
                strict=True,
            )
        )
        assert values[component] == pytest.approx(5.0, abs=1e-6)  # mm, at the limit


def test_planning_reports_theta_and_bounds_it(default_plan):
    from planner.pipeline.engine.planning import plan

    free = default_plan
    theta = free.scanned["incidence_deg"]
    assert (theta >= free.scanned["gamma_deg"] - 1e-9).all()
    assert theta.max() > 60.0  # steep beams exist on the default plan …
    bounded = plan(requirements=Requirements(max_incidence_deg=60.0))
    met = bounded.scanned[bounded.scanned["meets"]]
    assert (met["incidence_deg"] <= 60.0 + 1e-9).all()  # … and the bound holds where met
    assert "θ <= 60°" in bounded.summary()


# -- accuracy classes ---------------------------------------------------------------------
def test_din_classes_as_tabulated():
    assert [CLASSES[f"OGL{i}"].upper_mm for i in range(6)] == [1000, 150, 50, 15, 5, 0.5]
    assert [CLASSES[f"OGH{i}"].upper_mm for i in range(6)] == [500, 50, 20, 5, 2, 0.5]
    assert CLASSES["OGL3"].lower_mm == 5 and CLASSES["OGH3"].lower_mm == 2


def test_loa_is_converted_from_95_percent():
    assert [CLASSES[f"LOA{i}0"].upper_mm for i in (2, 3, 4, 5)] == [50, 15, 5, 1]
    assert class_limits("LOA40") == {"max_xy_mm": 2.5, "max_z_mm": 2.5}  # mm: 5 mm / 2
    assert class_limits("OGL4/OGH3") == {"max_xy_mm": 5.0, "max_z_mm": 5.0}
    assert class_limits("OGH2") == {"max_z_mm": 20.0}


@pytest.mark.parametrize(
    ("spec", "message"),
    [
        ("OGL9", "unknown accuracy class"),
        ("OGL4/OGL3", "overlapping classes"),
        ("LOA40/OGH3", "overlapping classes"),
        ("LOA10", "no upper bound"),
        ("", "empty"),
    ],
)
def test_bad_classes(spec, message):
    with pytest.raises(InputError, match=message):
        parse_class(spec)


def test_requirements_from_a_class_and_conflicts():
    req = Requirements(accuracy_class="ogl4/ogh3")
    assert (req.max_x_mm, req.max_z_mm, req.accuracy_class) == (5.0, 5.0, "OGL4/OGH3")
    assert Requirements(accuracy_class="OGH2", max_xy_mm=3.0).max_xy_mm == 3.0  # other quantity
    with pytest.raises(InputError, match="conflicts with the accuracy class"):
        Requirements(accuracy_class="LOA40", max_z_mm=3.0)


def test_the_class_each_point_achieves():
    got = achieved_class(
        np.array([0.4, 3.0, 12.0, np.nan]),
        np.array([0.3, 4.9, 1.0, 1.0]),
        np.array([0.4, 1.9, 30.0, 1.0]),
        "DIN",
    )
    assert got.tolist() == ["OGL5/OGH5", "OGL4/OGH4", "OGL3/OGH1", ""]
    loa = achieved_class(np.array([0.4, 2.4]), np.array([0.4, 2.0]), np.array([0.4, 2.6]), "LOA")
    assert loa.tolist() == ["LOA50", "LOA30"]


def test_a_plan_to_a_class_reports_the_class_per_sample(tmp_path):
    from sites import run_cli as run

    code, out, err = run("plan", "--class", "OGL4/OGH3", "--out", str(tmp_path / "p"), "-q")
    assert code in (0, 1), err
    assert "class OGL4/OGH3" in out
    cov = pd.read_csv(tmp_path / "p" / "coverage.csv")
    met = cov[cov["meets"]]
    assert len(met) and met["class_achieved"].str.match(r"OGL[45]/OGH[345]$").all()
