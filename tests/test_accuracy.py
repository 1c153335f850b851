"""The formula layer: values, input types, broadcasting, NaN, and documented errors."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from planner import (
    InputError,
    Scanner,
    arcsec_to_urad,
    height_rms,
    planimetric_rms,
    ranging_rms_mm,
    urad_to_arcsec,
)
from planner.units import RHO_ARCSEC


def test_normal_case_terms_do_not_cross(paper_scanner):
    """γ = 0: m_S does not reach m_x and m_β does not reach m_y (Voroshilov & Karachentsev, §2)."""
    m_x, m_y = planimetric_rms(100.0, 0.0, paper_scanner)
    assert m_x == pytest.approx(100_000 / RHO_ARCSEC * 12.4, abs=1e-6)  # mm, angular only
    assert m_y == pytest.approx(4.0, abs=1e-12)  # mm, ranging only


def test_gamma_sign_does_not_matter(paper_scanner):
    a = planimetric_rms([20, 80], [35, 35], paper_scanner)
    b = planimetric_rms([20, 80], [-35, -35], paper_scanner)
    np.testing.assert_allclose(a, b, rtol=0, atol=0)


def test_station_rms_one_number_or_pair(paper_scanner):
    m_x0, m_y0 = planimetric_rms(50, 30, paper_scanner)
    m_x1, m_y1 = planimetric_rms(50, 30, paper_scanner, station_rms_mm=3.0)
    assert m_x1 == pytest.approx(np.hypot(m_x0, 3.0), abs=1e-12)  # mm
    assert m_y1 == pytest.approx(np.hypot(m_y0, 3.0), abs=1e-12)  # mm
    m_x2, m_y2 = planimetric_rms(50, 30, paper_scanner, station_rms_mm=(1.0, 2.0))
    assert m_x2 == pytest.approx(np.hypot(m_x0, 1.0), abs=1e-12)  # mm
    assert m_y2 == pytest.approx(np.hypot(m_y0, 2.0), abs=1e-12)  # mm


def test_ranging_a_plus_b_d(ppm_scanner):
    # ±(2 mm + 100 ppm): 100 ppm of 10 m is 1 mm
    np.testing.assert_allclose(ranging_rms_mm([0, 10, 20, 30], ppm_scanner), [2.0, 3.0, 4.0, 5.0])
    _, m_y = planimetric_rms(30.0, 0.0, ppm_scanner)
    assert m_y == pytest.approx(5.0, abs=1e-12)  # mm: m_S at D = 30 m
    _, m_y_slope = planimetric_rms(30.0, 0.0, ppm_scanner, ranging_distance_m=40.0)
    assert m_y_slope == pytest.approx(6.0, abs=1e-12)  # mm: m_S at S = 40 m
    assert height_rms(30.0, 90.0, ppm_scanner) == pytest.approx(
        np.hypot(5.0, 30_000 / RHO_ARCSEC * 20.0), abs=1e-9
    )


def test_height_rms_uses_vertical_angle_and_overrides(ppm_scanner):
    s, nu = 40.0, 25.0
    k = s * 1000 / RHO_ARCSEC
    m_s = 6.0  # mm: 2 mm + 100 ppm of 40 m
    c, sn = np.cos(np.radians(nu)), np.sin(np.radians(nu))
    full = np.sqrt((m_s * sn) ** 2 + (k * c * 20.0) ** 2 + (k * 20.0) ** 2)
    assert height_rms(s, nu, ppm_scanner) == pytest.approx(full, abs=1e-9)
    # a compensated scanner: S_0 = 10 m, m_ν0 = 1.5″
    k0 = 10.0 * 1000 / RHO_ARCSEC
    comp = np.sqrt((m_s * sn) ** 2 + (k * c * 20.0) ** 2 + (k0 * 1.5) ** 2)
    got = height_rms(s, nu, ppm_scanner, initial_distance_m=10.0, initial_tilt_rms_arcsec=1.5)
    assert got == pytest.approx(comp, abs=1e-9)
    levelled = Scanner(
        name="lev",
        range_rms_mm=2.0,
        range_ppm=100.0,
        angle_rms_arcsec=12.4,
        vertical_angle_rms_arcsec=20.0,
        levelling_rms_arcsec=1.5,
    )
    got2 = height_rms(s, nu, levelled, initial_distance_m=10.0)
    assert got2 == pytest.approx(comp, abs=1e-9)


def test_scalar_list_array_series_give_the_same_numbers(paper_scanner):
    d = [10.0, 55.0, 120.0]
    g = [0.0, 30.0, 60.0]
    from_list = planimetric_rms(d, g, paper_scanner)
    from_array = planimetric_rms(np.array(d), np.array(g), paper_scanner)
    from_series = planimetric_rms(
        pd.Series(d, index=list("abc")), pd.Series(g, index=list("abc")), paper_scanner
    )
    for i in range(3):
        scalar = planimetric_rms(d[i], g[i], paper_scanner)
        assert isinstance(scalar[0], float)
        for k in range(2):
            assert from_list[k][i] == scalar[k]
            assert from_array[k][i] == scalar[k]
            assert from_series[k].iloc[i] == scalar[k]
    assert list(from_series[0].index) == ["a", "b", "c"]
    hz = [height_rms(s, 30.0, paper_scanner) for s in d]
    np.testing.assert_array_equal(height_rms(d, 30.0, paper_scanner), hz)


def test_broadcasting_makes_a_table(paper_scanner):
    m_x, m_y = planimetric_rms(
        np.array([10, 20, 30.0])[:, None], np.array([0, 30.0]), paper_scanner
    )
    assert m_x.shape == m_y.shape == (3, 2)
    assert height_rms(np.arange(1, 7.0).reshape(2, 3), 45.0, paper_scanner).shape == (2, 3)


def test_nan_passes_through(paper_scanner):
    m_x, m_y = planimetric_rms([10.0, np.nan], [np.nan, 30.0], paper_scanner)
    assert np.isnan(m_x).all() and np.isnan(m_y).all()
    assert np.isnan(height_rms(np.nan, 10.0, paper_scanner))


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda s: planimetric_rms(-1.0, 0.0, s), "distance_m must satisfy distance_m >= 0"),
        (lambda s: planimetric_rms([1.0, -3.0], 0.0, s), "index (1,)"),
        (lambda s: planimetric_rms(10.0, 95.0, s), "-90 <= gamma_deg <= 90"),
        (lambda s: planimetric_rms(np.inf, 0.0, s), "distance_m"),
        (lambda s: planimetric_rms("ten", 0.0, s), "not the text 'ten'"),
        (lambda s: planimetric_rms(10.0, 0.0, s, station_rms_mm=-1), "station_rms_mm"),
        (lambda s: planimetric_rms(10.0, 0.0, s, station_rms_mm=(1, 2, 3)), "or a pair"),
        (lambda s: height_rms(10.0, -91.0, s), "-90 <= nu_deg <= 90"),
        (lambda s: height_rms(-5.0, 0.0, s), "slope_distance_m >= 0"),
        (lambda s: height_rms(5.0, 0.0, s, initial_tilt_rms_arcsec=-1.0), "initial_tilt_rms"),
    ],
)
def test_bad_input_raises_input_error_naming_the_argument(paper_scanner, call, message):
    with pytest.raises(InputError) as info:
        call(paper_scanner)
    assert message in str(info.value)
    assert isinstance(info.value, ValueError)  # InputError is also a ValueError


def test_angle_conversions_round_trip():
    assert urad_to_arcsec(60.0) == pytest.approx(12.376, abs=5e-4)  # ″, the paper's 12.4
    assert arcsec_to_urad(urad_to_arcsec(123.4)) == pytest.approx(123.4, abs=1e-12)
    np.testing.assert_allclose(urad_to_arcsec([0, 4.8481368]), [0, 1.0], atol=1e-7)
