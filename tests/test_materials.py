"""Facade materials and the ranging model by returned signal (planner.materials,
planner.signal): the table, where a wall's material comes from, glass not demanded, the
survey day's condition, and a Monte Carlo of the ranging model against simulated returns."""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest
from sites import run_cli, square_site

from planner import plan
from planner.errors import InputError
from planner.materials import Material, material_table, read_material_file, reflectances
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.scanner import Scanner
from planner.signal import reach_exponent, relative_signal, signal_ranging_rms_mm
from planner.zones import parse_zone

RTC = "leica-rtc360"


def test_the_table_finds_a_material_by_name_or_osm_value_and_says_what_it_has():
    t = material_table()
    assert t.find("Brick").name == "brick"
    assert t.find("cement block").name == "concrete"  # OSM's cement_block
    assert t.find("curtain-wall").name == "glass"
    assert not t["glass"].returns and t["brick"].returns
    for m in t.values():  # wet is never brighter than dry
        assert m.wet_reflectance <= m.reflectance
    with pytest.raises(InputError, match=r"unknown material 'brik'.*did you mean brick\?"):
        t.find("brik")


def test_a_users_rows_are_added_and_replace_a_shipped_row(tmp_path):
    f = tmp_path / "mine.toml"
    f.write_text(
        '[[material]]\nname = "brick"\nreflectance = 0.55\n'
        '[[material]]\nname = "ceramic-tile"\nreflectance = 0.7\nwet_reflectance = 0.65\n'
        'aliases = ["tiles"]\n',
        encoding="utf-8",
    )
    t = material_table(read_material_file(f))
    assert t["brick"].reflectance == 0.55 and t["brick"].wet_reflectance == 0.55
    assert t.find("tiles").name == "ceramic-tile"
    bad = tmp_path / "bad.toml"
    bad.write_text('[[material]]\nname = "x"\nreflectance = 1.7\n', encoding="utf-8")
    with pytest.raises(InputError, match=r"reflectance must be > 0 and <= 1"):
        read_material_file(bad)
    bad.write_text('[[material]]\nname = "x"\nreflectivity = 0.3\n', encoding="utf-8")
    with pytest.raises(InputError, match="unknown keys reflectivity"):
        read_material_file(bad)


def test_the_signal_formulas():
    # 15 % brick square to the beam against an 80 % reference: q = 0.1875, m_S × 2.31
    q = relative_signal(0.15, 1.0, 0.8)
    assert q == pytest.approx(0.1875)
    assert signal_ranging_rms_mm(1.0, q) == pytest.approx(2.309, abs=0.001)  # mm
    assert relative_signal(float("nan"), 0.5, 0.8) == pytest.approx(0.5)  # reference surface
    # a datasheet's 800 m at 90 % and 400 m at 20 %: R ∝ q^0.46
    assert reach_exponent(800.0, 0.9, 400.0, 0.2) == pytest.approx(0.4608, abs=1e-4)
    sc = Scanner(
        name="v", range_rms_mm=3, angle_rms_arcsec=5, max_range_m=800.0,
        range_reflectance=0.9, dark_range_m=400.0, dark_reflectance=0.2,
    )  # fmt: skip
    assert sc.max_range_on(0.2) == pytest.approx(400.0)  # m: the datasheet's second figure
    assert sc.max_range_on(0.95) == pytest.approx(800.0)  # m: never beyond the stated reach
    with pytest.raises(InputError, match="go together"):
        Scanner(name="v", range_rms_mm=3, angle_rms_arcsec=5, dark_range_m=50.0)


def _plane_fit_residual_rms(reflectance: float, incidence_deg: float, rng, signal: bool) -> float:
    """Scan a plane 20 m away at an incidence, each range the centroid of the photons of one
    return (Poisson in number, each photon's time of flight spread by the pulse), fit a
    plane and give the residuals' RMS [mm]. The photons per return on the reference surface
    square to the beam give the datasheet's ranging RMS; ``signal=False`` keeps that number
    whatever the surface (a constant noise: the negative control)."""
    sigma_mm, photons_ref, pulse_mm = 1.0, 400.0, 20.0  # 20 mm / √400 = 1 mm
    ref = 0.8
    th = np.radians(incidence_deg)
    n_mean = photons_ref * (reflectance * np.cos(th) / ref if signal else 1.0)
    assert pulse_mm / np.sqrt(photons_ref) == sigma_mm
    # beams across a 1 m × 1 m patch of the plane, whose normal leans θ from the beam
    u, v = np.meshgrid(np.linspace(-0.5, 0.5, 60), np.linspace(-0.5, 0.5, 60))
    normal = np.array([np.sin(th), 0.0, -np.cos(th)])  # towards the scanner at the origin
    centre = np.array([0.0, 0.0, 20.0])
    e1, e2 = np.array([np.cos(th), 0.0, np.sin(th)]), np.array([0.0, 1.0, 0.0])
    pts = centre + u.reshape(-1, 1) * e1 + v.reshape(-1, 1) * e2
    beam = pts / np.linalg.norm(pts, axis=1, keepdims=True)
    n = np.maximum(rng.poisson(n_mean, len(pts)), 1)
    # the centroid of n photons' arrival times: mean of n normal spreads
    centroid = rng.normal(0.0, pulse_mm, n.sum())
    err_mm = np.add.reduceat(centroid, np.r_[0, np.cumsum(n)[:-1]]) / n
    noisy = pts + beam * (err_mm / 1000.0)[:, None]
    c = noisy.mean(axis=0)
    _, _, vt = np.linalg.svd(noisy - c, full_matrices=False)
    assert abs(vt[2] @ normal) > 0.999  # the plane found is the plane scanned
    return float(np.sqrt(np.mean(((noisy - c) @ vt[2]) ** 2)) * 1000.0)


@pytest.mark.parametrize("reflectance", [0.15, 0.4, 0.75])
@pytest.mark.parametrize("incidence_deg", [0.0, 45.0, 70.0])
def test_plane_fit_residuals_of_simulated_returns_agree_with_the_signal_model(
    reflectance, incidence_deg
):
    """Monte Carlo: the residuals of a plane fitted to simulated returns are the model's
    ranging RMS on that surface at that incidence, projected on the normal (m_S(q)·cos θ),
    within ±20 % — for three reflectances at three incidences. A constant noise (the
    datasheet's m_S everywhere, as scan simulators draw it) misses the dark and the slanting
    surfaces by more (negative control)."""
    rng = np.random.default_rng(7)
    sc = Scanner(name="mc", range_rms_mm=1.0, angle_rms_arcsec=1.0, reference_reflectance=0.8)
    cos_t = np.cos(np.radians(incidence_deg))
    predicted = float(sc.range_rms_on(20.0, reflectance, cos_t)) * cos_t
    found = _plane_fit_residual_rms(reflectance, incidence_deg, rng, signal=True)
    assert found == pytest.approx(predicted, rel=0.20)  # mm
    constant = float(sc.range_rms_at(20.0)) * cos_t  # what a constant-noise model predicts
    if reflectance < 0.5 or incidence_deg > 60:
        assert abs(found / constant - 1) > 0.20  # the constant model fails here
    control = _plane_fit_residual_rms(reflectance, incidence_deg, rng, signal=False)
    assert control == pytest.approx(constant, rel=0.20)  # the simulation sees the difference


def _plan(site, **kw):
    """An RTC360 plan held to 50 mm in height: this file is about ranging, and the IMU's
    180″ tilt readings lean an untied network by tens of millimetres over a site
    (tests/test_tilt_readings.py)."""
    return plan(site, RTC, Requirements(max_z_mm=50.0), settings=PlanSettings(**kw))


def test_a_dark_or_wet_wall_ranges_noisier_and_the_plan_says_what_rain_costs():
    from planner.pipeline.engine.conditions import condition_sensitivity

    site = square_site(30.0, 12.0)
    bright = _plan(site, default_material="plaster")
    dark = _plan(site, default_material="brick-dark")
    wet = _plan(site, default_material="brick-dark", surface_condition="wet")
    assert (bright.coverage["material"] == "plaster").all()
    median = [float(p.scanned["scanner_m_y_mm"].median()) for p in (bright, dark, wet)]
    assert median[0] < median[1] < median[2]  # mm: plaster, dark brick, dark brick wet
    # the ranging part on dark brick is (0.75/0.15)^½ = 2.24× plaster's at one geometry
    rho = reflectances(np.array(["plaster", "brick-dark"], dtype=object), material_table())
    sc = Scanner.from_name(RTC)
    ratio = sc.range_rms_on(20.0, rho[1]) / sc.range_rms_on(20.0, rho[0])
    assert float(ratio) == pytest.approx(np.sqrt(0.75 / 0.15), abs=0.001)
    # the dry plan's stations after rain: samples lost, and said; the wet plan holds dry
    then, now = condition_sensitivity(dark, "wet")
    assert then < now == int(dark.coverage["meets"].sum())
    assert any(f"meet {then} of the {now} samples met dry" in m for m in dark.messages)
    assert condition_sensitivity(wet, "dry") == (now, now)
    assert condition_sensitivity(_plan(site), "wet") is None  # no material: nothing to say
    assert any(m.startswith("Walls (dry day): dark brick / clinker 15%") for m in dark.messages)


def test_glass_is_not_demanded_and_said_and_a_zone_names_a_materials_part():
    site = square_site(30.0, 12.0)
    site = replace(
        site,
        zones=[
            parse_zone("facade=sq-f00,material=glass", "curtain"),
            parse_zone("facade=sq-f01,z=0-3,material=granite", "plinth"),
        ],
    )
    p = _plan(site)
    cov = p.coverage
    assert not (cov["facade_id"] == "sq-f00").any()  # the curtain wall: no samples
    plinth = cov[cov["facade_id"] == "sq-f01"]
    assert set(plinth["material"]) == {"granite", ""}
    assert (plinth.loc[plinth["material"] == "granite", "z"] <= 3.0 + 1e-9).all()  # m
    facades = p.facades.set_index("facade_id")
    assert facades.loc["sq-f01", "materials"] == "granite"  # facades.csv and plan.geojson
    assert facades.loc["sq-f02", "materials"] == ""
    said = [m for m in p.messages if m.startswith("Not demanded")]
    assert said and "glass" in said[0] and "sq-f00" in said[0]


def test_a_site_files_building_material_is_read_and_an_unknown_one_said(tmp_path):
    from planner.siteio import read_site

    def feature(i, mat, x0):
        ring = [[x0, 0], [x0 + 20, 0], [x0 + 20, 15], [x0, 15], [x0, 0]]
        props = {"id": f"b{i}", "height": 10, "building:material": mat}
        return {"type": "Feature", "properties": props,
                "geometry": {"type": "Polygon", "coordinates": [ring]}}  # fmt: skip

    doc = {"type": "FeatureCollection", "crs": {"type": "name", "properties": {
        "name": "urn:ogc:def:crs:EPSG::25832"}},
        "features": [feature(1, "brick", 500000), feature(2, "plastic", 500040)]}  # fmt: skip
    for f in doc["features"]:  # in the UTM zone's area
        f["geometry"]["coordinates"] = [[[x, y + 5_400_000] for x, y in r]
                                        for r in f["geometry"]["coordinates"]]  # fmt: skip
    f = tmp_path / "site.geojson"
    f.write_text(json.dumps(doc), encoding="utf-8")
    site = read_site(f)
    assert {b.id: b.material for b in site.buildings} == {"b1": "brick", "b2": "plastic"}
    p = _plan(site)
    by = p.coverage.groupby("building_id")["material"].agg(set)
    assert by["b1"] == {"brick"} and by["b2"] == {""}
    assert any("'plastic' (b2)" in m and "--materials" in m for m in p.messages)


def test_the_command_line_takes_materials_and_refuses_a_bad_one(tmp_path):
    out = tmp_path / "out"
    code, _, err = run_cli("plan", "--default-material", "brik", "--out", str(out))
    assert code == 2 and "did you mean brick" in err and "Traceback" not in err
    assert not out.exists()
    mats = tmp_path / "m.toml"
    mats.write_text('[[material]]\nname = "brik"\nreflectance = 0.3\n', encoding="utf-8")
    code, _, err = run_cli(
        "plan", "--materials", str(mats), "--default-material", "brik",
        "--surface-condition", "wet", "--scanner", RTC, "--time-limit-s", "20",
        "--out", str(out),
    )  # fmt: skip
    assert code in (0, 1), err
    import pandas as pd

    cov = pd.read_csv(out / "coverage.csv", keep_default_na=False)
    assert set(cov["material"]) == {"brik"}


def test_the_rehearsal_returns_nothing_from_glass():
    from planner.pipeline.survey.rehearsal import POINT_KINDS, rehearse

    site = square_site(20.0, 10.0)
    glass = replace(site, buildings=[replace(site.buildings[0], material="glass")])
    p = _plan(site)
    walls = POINT_KINDS.index("wall")
    seen = rehearse(p, beams_per_station=100_000, noise=False, stations=["S01"])
    assert (seen.scans[0].kind == walls).sum() > 100
    p_glass = replace(p, site=glass)
    none = rehearse(p_glass, beams_per_station=100_000, noise=False, stations=["S01"])
    assert (none.scans[0].kind == walls).sum() == 0


def test_a_material_row_refuses_what_cannot_be():
    with pytest.raises(InputError, match="returns must be true or false"):
        Material("x", 0.3, 0.2, returns="no")
    with pytest.raises(InputError, match="wet_reflectance"):
        Material("x", 0.3, 0.0)


def test_the_most_specific_zone_names_the_material_and_no_material_is_the_reference():
    from planner.materials import material_table as table
    from planner.pipeline.geometry.facades import build_facades
    from planner.pipeline.geometry.zoning import apply_zones
    from planner.pipeline.inputs.requirements import Requirements

    site = square_site(30.0, 12.0)
    site = replace(
        site,
        buildings=[replace(site.buildings[0], material="brick")],
        zones=[  # a plinth on the whole building, under a facade in sandstone
            parse_zone("building=sq,z=0-3,material=granite", "plinth"),
            parse_zone("facade=sq-f01,material=sandstone", "face"),
        ],
    )
    fac = build_facades(site, 2.0, 2.0)
    fac, req, _ = apply_zones(site, fac, Requirements(), None, table())
    on = fac.facade_id[fac.facade] == "sq-f01"
    low = fac.z - fac.base_z[fac.facade] <= 3.0
    assert set(req.material[on & low]) == {"granite"}  # the part of a facade wins
    assert set(req.material[on & ~low]) == {"sandstone"}
    assert set(req.material[~on & ~low]) == {"brick"}
    # a wall of no material is the reference surface, whatever surface the reach is stated on
    hds = Scanner.from_name("leica-hds3000")  # 134 m at 18 %
    assert float(hds.max_range_on(float("nan"))) == pytest.approx(134.0)  # m
    assert float(hds.max_range_on(0.1)) == pytest.approx(134.0 * (0.1 / 0.18) ** 0.5)  # m


def test_a_calibrated_profile_keeps_its_bases_reach():
    from planner.calibration import profile_from_calibration, signal_calibration, simulate_signal

    r = signal_calibration(simulate_signal(reference_reflectance=0.9), 0.9)
    base = Scanner.from_name("leica-hds3000")
    kept, _ = profile_from_calibration("mine", base=base, signal=r)
    assert kept.range_reflectance == 0.18 and kept.reference_reflectance is None
    assert kept.ranging_exponent == pytest.approx(0.5, abs=0.02)
    own, _ = profile_from_calibration("mine", base=base, signal=r, range_from="signal")
    assert own.reference_reflectance == 0.9 and own.range_rms_mm == pytest.approx(1.0, abs=0.02)
