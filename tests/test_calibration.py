"""Calibration → profile: synthetic data with known parameters, the seeds' numbers, bad input."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from sites import run_cli as run

from planner import InputError, Scanner
from planner.calibration import (
    _rotation,
    axis_errors,
    baseline_calibration,
    helmert6,
    lab_test,
    profile_from_calibration,
    simulate_axes,
    simulate_baseline,
    simulate_lab,
    six_segment_constant,
)
from planner.units import RHO_ARCSEC


def test_helmert_recovers_rotation_and_translation_within_their_standard_errors():
    rng = np.random.default_rng(11)
    ref = rng.uniform([-4, -3, 0], [4, 3, 3.3], (40, 3))
    rot = _rotation(*np.radians([0.5, -1.2, 37.0]))
    t = np.array([100.0, 200.0, 5.0])
    scan = (ref - t) @ rot + rng.normal(0, 0.0005, ref.shape)  # 0.5 mm per coordinate
    h = helmert6(ref, scan)
    np.testing.assert_allclose(
        h.translation_m, t, atol=3 * max(h.std_errors["tx_mm"], h.std_errors["tz_mm"]) / 1000 + 0.01
    )
    # angles: within 3 standard errors (″)
    for got, want, se in zip(
        h.angles_deg,
        [0.5, -1.2, 37.0],
        [h.std_errors["omega_arcsec"], h.std_errors["phi_arcsec"], h.std_errors["kappa_arcsec"]],
        strict=True,
    ):
        assert abs(got - want) * 3600 < 3 * se
    assert h.sigma0_mm == pytest.approx(0.5, rel=0.15)  # mm
    # the transformation maps the scan onto the reference to the noise level
    assert np.abs(h.residuals[["dx_mm", "dy_mm", "dz_mm"]].to_numpy()).max() < 5 * 0.5


def test_m_r_of_pure_noise_is_the_noise_sigma():
    """Scanner coordinates = exact transformation + N(0, σ) per coordinate: a pair's distance
    difference then has variance 2σ² (less the 6 of 3n degrees of freedom the fit takes)."""
    rng = np.random.default_rng(7)
    n, sigma = 150, 0.8  # targets, mm
    ref = rng.uniform([-4.6, -3.5, 0], [4.6, 3.5, 3.3], (n, 3))
    scan = ref + rng.normal(0, sigma / 1000, ref.shape)
    ids = [str(i) for i in range(n)]
    t = lab_test(
        pd.DataFrame({"id": ids, "x": ref[:, 0], "y": ref[:, 1], "z": ref[:, 2]}),
        pd.DataFrame({"id": ids, "x": scan[:, 0], "y": scan[:, 1], "z": scan[:, 2]}),
    )
    expected = sigma * np.sqrt(2 * (1 - 6 / (3 * n)))
    # 3n = 450 coordinate errors: the RMS has a relative standard error of about 3.3 %
    assert t.m_r["distance_mm"] == pytest.approx(expected, rel=0.10)
    assert t.M_r["distance_mm"] == pytest.approx(2 * t.m_r["distance_mm"])
    # significant pairs of pure noise: about the 5 % tail of a normal at k = 2
    assert 0.02 < t.pairs["significant_distance"].mean() < 0.08


def test_lab_test_reproduces_the_inflated_angular_figures_of_short_lab_distances():
    """The Belgrade procedure found 284–1232″ horizontal m_r in a 9.3 × 7 × 3.3 m lab. A scanner
    with only 20″ angular noise simulated in such a room gives the same magnitude: target pairs
    nearly above one another have tiny horizontal separations, and φ = arctan(ΔX/ΔY) blows
    up."""
    ref, scan = simulate_lab(angle_rms_arcsec=20.0, range_rms_mm=1.5)
    t = lab_test(ref, scan)
    assert t.m_r["horizontal_arcsec"] > 10 * 20.0
    assert t.warnings and "inflated" in t.warnings[0]
    assert len(t.pairs) == 60 * 59 // 2
    xy = ref.set_index("id")[["x", "y"]]
    worst = t.pairs.loc[t.pairs["d_horizontal_arcsec"].abs().idxmax()]
    horizontal_m = np.hypot(*(xy.loc[worst["target_a"]] - xy.loc[worst["target_b"]]))
    assert horizontal_m < 0.5 and worst["significant_horizontal"]  # nearly above one another


def test_lab_network_check_and_pairs_option():
    ref, scan = simulate_lab(n_targets=12)
    t = lab_test(
        ref, scan, pairs="first", reference_precision_mm=0.7, declared_target_precision_mm=2.0
    )
    assert len(t.pairs) == 11 and set(t.pairs["target_a"]) == {"1"}
    # the Belgrade procedure's network check: 0.7 mm against 2 mm — a third is 0.67 mm, so
    # 0.7 passes only as the paper rounds
    assert "NOT good enough" in t.network and "0.67 mm" in t.network
    ok = lab_test(ref.assign(sigma_mm=0.5), scan, declared_target_precision_mm=2.0)
    assert ok.network.startswith("reference network good enough: point precision 0.5 mm")


def test_baseline_recovers_k_and_R_within_their_standard_errors():
    data = simulate_baseline(k_mm=3.9, scale_ppm=-30.0, noise_mm=1.0)  # Liu & Zhang's HDS3000
    r = baseline_calibration(data)
    assert abs(r.k_mm - 3.9) < 3 * r.k_se_mm
    assert abs(r.scale_ppm - (-30.0)) < 3 * r.scale_se_ppm
    assert r.residual_rms_mm == pytest.approx(1.0, rel=0.3)
    assert r.n == 21  # N(N+1)/2 distances for N = 6 segments


def test_six_segment_constant_is_unbiased_by_scale():
    for scale in (0.0, 50.0):
        data = simulate_baseline(k_mm=-1.5, scale_ppm=scale, noise_mm=0.5, seed=9)
        r = six_segment_constant(
            data.rename(columns={"measured_m": "distance_m"})[["from", "to", "distance_m"]]
        )
        assert abs(r.k_mm - (-1.5)) < 3 * r.k_se_mm
        assert r.k_se_mm < 0.5
        np.testing.assert_allclose(r.segments_m.to_numpy(), [5, 10, 20, 30, 40, 50], atol=0.004)


def test_axis_errors_recover_c_and_i():
    data = simulate_axes(
        c_deg=0.0075, i_deg=0.0461, noise_arcsec=2.0, alphas_deg=np.linspace(-35, 65, 24)
    )
    r = axis_errors(data)
    assert abs(r.c_deg - 0.0075) < 3 * r.c_se_deg
    assert abs(r.i_deg - 0.0461) < 3 * r.i_se_deg
    assert r.orientation_deg == pytest.approx(12.5, abs=0.01)
    assert r.residual_rms_arcsec == pytest.approx(2.0, rel=0.4)


BELGRADE_TABLES = {  # Table 3 (k = 1) and Table 4 (k = 2): distance [mm], φ [″], θ [″]
    "FARO Focus3D": ((2.5, 1231.68, 59.31), (5.0, 2463.36, 118.62)),
    "Leica HDS3000": ((1.1, 606.89, 95.43), (2.3, 1213.77, 190.85)),
    "Leica ScanStation P20": ((1.7, 284.06, 52.49), (3.4, 568.13, 104.97)),
}


@pytest.mark.parametrize("scanner", BELGRADE_TABLES)
def test_belgrade_expanded_uncertainties_are_twice_the_standard_ones(scanner):
    """M_r = 2·m_r (Belgrade procedure, eq. 8) within the rounding of the printed figures: a
    printed m_r is ±half a unit of its last digit, so 2·m_r is ±one unit; plus half a unit for M_r.
    (HDS3000: 2 × 1.1 = 2.2 but 2.3 printed — the unrounded m_r was 1.15 mm.)"""
    m, big = BELGRADE_TABLES[scanner]
    for value, expanded, unit in zip(m, big, (0.1, 0.01, 0.01), strict=True):
        assert abs(expanded - 2 * value) <= unit + unit / 2 + 1e-9


def test_liu_zhang_six_segment_table_cannot_be_recomputed_and_is_inconsistent():
    """Liu & Zhang, Table 1: the total station's mean distances from point 1 and the 'distances
    corrected by the additive constant' C = −1.5 mm. Only 6 of the 21 observed distances are
    printed, so the adjustment cannot be redone; and the printed corrections are +1.8 … +3.8 mm,
    not the constant −1.5 mm: they are adjusted values, not D + C."""
    measured = np.array([4.7834, 9.8965, 20.0045, 30.0019, 40.0055, 50.0067])
    corrected = np.array([4.78717, 9.8995, 20.0063, 30.0057, 40.0092, 50.0088])
    corrections_mm = (corrected - measured) * 1000
    np.testing.assert_allclose(corrections_mm, [3.77, 3.0, 1.8, 3.8, 3.7, 2.1], atol=0.01)
    assert np.ptp(corrections_mm) > 1.9  # not one constant
    assert (corrections_mm > 0).all()  # the opposite sign of C = −1.5 mm
    # what can be checked: N = 6 segments give N(N+1)/2 = 21 combinations, as the paper says
    assert len(simulate_baseline()) == 21
    # and its HDS3000 scale −0.00003016 is the "−30 ppm" it states
    assert -0.00003016 * 1e6 == pytest.approx(-30.16) and round(-30.16) == -30


def test_profile_from_calibration_round_trip_and_use_by_the_planner(tmp_path):
    ref, scan = simulate_lab()
    lab = lab_test(ref, scan)
    base = Scanner.from_name("leica-p20-lab")
    bl = baseline_calibration(simulate_baseline())
    sc, notes = profile_from_calibration(
        "my-p20",
        base=base,
        lab=lab,
        baseline=bl,
        range_from="baseline",
        angles_from=None,
        include_scale=True,
    )
    assert sc.range_rms_mm == pytest.approx(bl.residual_rms_mm)
    assert sc.range_ppm == pytest.approx(abs(bl.scale_ppm))
    assert sc.angle_rms_arcsec == base.angle_rms_arcsec  # kept: the user chose so
    path = sc.save(tmp_path / "my-p20.toml")
    back = Scanner.from_file(path)
    assert back.extra["calibration"]["baseline"]["n"] == 21
    assert back.extra["calibration"]["lab"]["pairs"] == len(lab.pairs)
    assert any("correct distances by k" in n for n in notes)
    code, out, _ = run("accuracy", "--scanner", str(path), "--distances", "10", "--angles", "0")
    assert code == 0 and "my-p20" in out
    with_angles, notes2 = profile_from_calibration("lab-angles", lab=lab, angles_from="lab")
    assert with_angles.angle_rms_arcsec == pytest.approx(lab.m_r["horizontal_arcsec"])
    assert any("inflated" in n for n in notes2)


def write(tmp_path, name, df):
    p = tmp_path / name
    df.to_csv(p, index=False)
    return p


def test_installed_profile_is_found_by_name(tmp_path, monkeypatch):
    monkeypatch.setenv("TLS_PLANNER_PROFILES", str(tmp_path / "profiles"))
    a = write(tmp_path, "axes.csv", simulate_axes())
    code, out, err = run("calibrate", "axes", str(a), "--install", "--name", "site-scanner")
    assert code == 0, err
    assert (tmp_path / "profiles" / "site-scanner.toml").is_file()
    assert Scanner.from_name("site-scanner").extra["calibration"]["angles_from"] == "axes"
    code, out, _ = run("accuracy", "--scanner", "site-scanner", "--distances", "10")
    assert code == 0 and "site-scanner" in out
    code, _, err = run("calibrate", "axes", str(a), "--install")
    assert code == 2 and "--install needs a profile name" in err


def test_calibrate_cli_writes_a_profile(tmp_path):
    ref, scan = simulate_lab()
    r, s = write(tmp_path, "ref.csv", ref), write(tmp_path, "scan.csv", scan)
    prof = tmp_path / "p.toml"
    code, out, err = run(
        "calibrate",
        "lab",
        str(r),
        str(s),
        "--profile-out",
        str(prof),
        "--declared-precision-mm",
        "2",
        "--reference-precision-mm",
        "0.5",
    )
    assert code == 0, err
    assert "Helmert" in out and "M_r (k=2)" in out and "warning:" in out
    assert "reference network good enough" in out
    assert Scanner.from_file(prof).range_rms_mm == pytest.approx(
        lab_test(ref, scan).m_r["distance_mm"]
    )
    b = write(tmp_path, "baseline.csv", simulate_baseline()[["measured_m", "reference_m"]])
    code, out, _ = run("calibrate", "baseline", str(b), "--profile-out", str(tmp_path / "b.toml"))
    assert code == 0 and "k = +" in out and "R = " in out
    six = write(
        tmp_path,
        "six.csv",
        simulate_baseline().rename(columns={"measured_m": "distance_m"})[
            ["from", "to", "distance_m"]
        ],
    )
    code, out, _ = run("calibrate", "baseline", str(six))
    assert code == 0 and "Six-segment" in out
    a = write(tmp_path, "axes.csv", simulate_axes())
    code, out, _ = run("calibrate", "axes", str(a), "--profile-out", str(tmp_path / "a.toml"))
    assert code == 0 and "collimation c" in out


@pytest.mark.parametrize(
    ("mutate", "message"),
    [
        (
            lambda r, s: (r, s.assign(id=s["id"].replace({"1": "99"}))),
            "only in the reference: 1; only in the scan: 99",
        ),
        (lambda r, s: (r.head(2), s.head(2)), "needs at least 3 common targets"),
        (
            lambda r, s: (
                r.assign(x=np.arange(len(r)) * 1.0, y=0.0, z=0.0),
                s.assign(x=np.arange(len(s)) * 1.0, y=0.0, z=0.0),
            ),
            "collinear",
        ),
        (
            lambda r, s: (r.assign(z=r["z"].where(r.index != 3, np.nan)), s),
            "column 'z' has a missing or non-numeric value in row 4",
        ),
        (lambda r, s: (r.drop(columns="z"), s), "lacks the column(s) z"),
        (lambda r, s: (pd.concat([r, r.head(1)]), s), "appears twice"),
    ],
)
def test_bad_lab_input_exits_2_with_the_problem_named(tmp_path, mutate, message):
    ref, scan = simulate_lab(n_targets=10)
    ref, scan = mutate(ref, scan)
    r, s = write(tmp_path, "ref.csv", ref), write(tmp_path, "scan.csv", scan)
    code, out, err = run(
        "calibrate", "lab", str(r), str(s), "--profile-out", str(tmp_path / "x.toml")
    )
    assert "Helmert" not in out  # nothing reported for bad input
    assert code == 2
    assert message in err and "Traceback" not in err
    assert not (tmp_path / "x.toml").exists()


def test_bad_baseline_and_axes_input(tmp_path):
    few = write(
        tmp_path, "few.csv", pd.DataFrame({"measured_m": [10.0, 20.0], "reference_m": [10.0, 20.0]})
    )
    code, _, err = run("calibrate", "baseline", str(few))
    assert code == 2 and "at least 3 distances" in err
    flat = write(tmp_path, "flat.csv", simulate_axes(alphas_deg=[10.0] * 6))
    code, _, err = run("calibrate", "axes", str(flat))
    assert code == 2 and "too alike to separate c from i" in err
    with pytest.raises(InputError, match="does not exist"):
        baseline_calibration(tmp_path / "nope.csv")
    assert RHO_ARCSEC > 0


def test_signal_calibration_recovers_the_exponent_and_a_constant_noise_gives_none(tmp_path):
    """Planes of 10, 50 and 99 % at four incidences (the shipped example, k = 0.55, m_0 =
    0.8 mm): the fit recovers both within a few standard errors; planes scanned with one
    noise whatever the signal give k ≈ 0 (negative control: the fit can tell)."""
    from planner.app.calibration_plots import example_path
    from planner.calibration import signal_calibration, simulate_signal

    example = example_path("signal.csv")
    r = signal_calibration(example)
    assert r.k == pytest.approx(0.55, abs=4 * r.k_se + 0.01)
    assert r.m0_mm == pytest.approx(0.8, abs=0.03)  # mm
    flat = signal_calibration(simulate_signal(m0_mm=1.0, k=0.0, seed=11))
    assert abs(flat.k) < 0.03
    with pytest.raises(InputError, match="spans a factor"):
        signal_calibration(simulate_signal(reflectances=(0.8,), incidences_deg=(0.0, 10.0)))
    code, _, err = run(
        "calibrate", "signal", str(example), "--range-from", "signal",
        "--profile-out", str(tmp_path / "mine.toml"),
    )  # fmt: skip
    assert code == 0, err
    sc = Scanner.from_file(tmp_path / "mine.toml")
    assert sc.ranging_exponent == pytest.approx(r.k, abs=1e-3)
    assert sc.range_rms_mm == pytest.approx(r.m0_mm, abs=1e-3)  # mm
    # the profile plans with it: dark brick ranges (0.8 / 0.15)^k noisier than the reference
    assert float(sc.range_rms_on(10.0, 0.15)) == pytest.approx(
        r.m0_mm * (0.8 / 0.15) ** r.k, rel=1e-6
    )
    bad = tmp_path / "bad.csv"
    bad.write_text("reflectance,incidence_deg,residual_rms_mm\n50,0,1.0\n", encoding="utf-8")
    code, _, err = run("calibrate", "signal", str(bad))
    assert code == 2 and "fraction" in err
