"""Scanner profiles: the catalogue, validation, and user profiles from files."""

from __future__ import annotations

import math

import numpy as np
import pytest

from planner import InputError, Scanner, catalogue, load_scanner
from planner.scanner import DEFAULT_SCANNER as DEFAULT
from planner.scanner import read_scanner_file

REQUIRED = [
    "leica-4mm-60urad",
    "leica-hds3000",
    "faro-focus3d-lab",
    "leica-hds3000-lab",
    "leica-p20-lab",
]


def test_catalogue_holds_every_seed_scanner_with_its_figures():
    cat = catalogue()
    assert set(REQUIRED) <= set(cat)
    paper = cat["leica-4mm-60urad"]
    assert (paper.range_rms_mm, paper.angle_rms_arcsec, paper.tilt_rms_arcsec) == (4.0, 12.4, 12.4)
    hds = cat["leica-hds3000"]
    assert hds.angle_rms_arcsec == pytest.approx(60e-6 * 206264.806, abs=1e-3)  # 6e-5 rad
    assert (hds.max_range_m, hds.measurement_rate_hz) == (134.0, 4000.0)
    assert hds.vertical_fov_deg[1] - hds.vertical_fov_deg[0] == 135.0  # 270° field, half-plane
    lab = {  # the Belgrade laboratory procedure, Table 3 (k = 1)
        "faro-focus3d-lab": (2.5, 1231.68, 59.31),
        "leica-hds3000-lab": (1.1, 606.89, 95.43),
        "leica-p20-lab": (1.7, 284.06, 52.49),
    }
    for name, (mm, h, v) in lab.items():
        s = cat[name]
        assert (s.range_rms_mm, s.angle_rms_arcsec, s.tilt_rms_arcsec) == (mm, h, v)
    for s in cat.values():  # cited as a published package would, not by an internal file
        assert any(w in s.source for w in ("Voroshilov", "Belgrade", "Liu", "datasheet"))
        assert "seed" not in (s.source + s.notes).lower()


def test_from_name_is_case_insensitive_and_unknown_lists_valid_names():
    assert Scanner.from_name(" Leica-P20-Lab ").name == "leica-p20-lab"
    with pytest.raises(InputError) as info:
        Scanner.from_name("leica-p2O-lab")
    msg = str(info.value)
    assert "Did you mean 'leica-p20-lab'" in msg
    for name in REQUIRED:
        assert name in msg


def test_constructor_of_the_public_api():
    sc = Scanner(
        name="mine",
        range_rms_mm=2.0,
        range_ppm=100.0,
        angle_rms_arcsec=12.4,
        vertical_angle_rms_arcsec=None,
        step_mm_at_10m=2.0,
        min_range_m=0.5,
        max_range_m=120.0,
    )
    assert sc.tilt_rms_arcsec == 12.4
    assert sc.range_rms_at(50.0) == pytest.approx(7.0)  # mm: 2 + 100 ppm of 50 m


@pytest.mark.parametrize(
    ("field", "value", "message"),
    [
        ("range_rms_mm", -1.0, "range_rms_mm must be >= 0.01 and <= 1000 [mm]"),
        ("range_rms_mm", 0.0, "range_rms_mm must be >= 0.01"),
        ("range_rms_mm", 1e-300, "range_rms_mm must be >= 0.01"),  # no division by ~0
        ("range_rms_mm", 1e308, "range_rms_mm must be >= 0.01 and <= 1000 [mm]"),
        ("angle_rms_arcsec", math.nan, "angle_rms_arcsec must be >= 0.01 and <= 3600"),
        ("measurement_rate_hz", 1e-300, "measurement_rate_hz must be >= 100"),
        ("vertical_angle_rms_arcsec", -2.0, "vertical_angle_rms_arcsec"),
        ("range_ppm", -5.0, "range_ppm must be >= 0 and <= 10000 [ppm]"),
        ("step_mm_at_10m", 0.0, "step_mm_at_10m"),
        ("min_range_m", 130.0, "min_range_m (130 m) must be smaller than max_range_m (120 m)"),
        ("max_range_m", math.inf, "max_range_m"),
        ("vertical_fov_deg", (30.0, -30.0), "-90 <= lowest < highest <= 90"),
        ("vertical_fov_deg", "wide", "two elevation angles"),
        ("range_rms_mm", "4", "must be a number [mm]"),
    ],
)
def test_invalid_figures_name_the_field_and_the_valid_range(field, value, message):
    kwargs = dict(name="bad", range_rms_mm=2.0, angle_rms_arcsec=10.0, max_range_m=120.0)
    kwargs[field] = value
    with pytest.raises(InputError) as info:
        Scanner(**kwargs)
    assert message in str(info.value)
    assert "'bad'" in str(info.value)


def test_profile_file_round_trip(tmp_path):
    sc = Scanner(
        name="my-p20",
        range_rms_mm=1.2,
        range_ppm=10.0,
        angle_rms_arcsec=8.0,
        vertical_angle_rms_arcsec=8.5,
        levelling_rms_arcsec=1.5,
        source="calibrated 2026",
        notes='a "quoted" note',
        extra={"calibration": {"k_mm": 0.4}},
    )
    path = sc.save(tmp_path / "p20.toml")
    back = Scanner.from_file(path)
    assert back == sc
    assert back.extra == {"calibration": {"k_mm": 0.4}}
    assert load_scanner(str(path)) == sc
    assert load_scanner(path) == sc


def test_file_with_several_profiles_and_bad_files(tmp_path):
    two = tmp_path / "two.toml"
    two.write_text(
        Scanner.from_name("leica-hds3000").to_toml() + Scanner.from_name("leica-p20-lab").to_toml()
    )
    assert len(read_scanner_file(two)) == 2
    assert Scanner.from_file(two, name="leica-p20-lab").range_rms_mm == 1.7
    with pytest.raises(InputError, match="holds 2 scanner profiles"):
        Scanner.from_file(two)
    with pytest.raises(InputError, match="has no scanner 'x'"):
        Scanner.from_file(two, name="x")
    broken = tmp_path / "broken.toml"
    broken.write_text("[[scanner]\nname = ")
    with pytest.raises(InputError, match="is not valid TOML"):
        Scanner.from_file(broken)
    partial = tmp_path / "partial.toml"
    partial.write_text('[[scanner]]\nname = "p"\nrange_rms_mm = 2.0\n')
    with pytest.raises(InputError, match="lacks angle_rms_arcsec"):
        Scanner.from_file(partial)
    with pytest.raises(InputError, match="does not exist"):
        Scanner.from_file(tmp_path / "missing.toml")
    binary = tmp_path / "bin.toml"
    binary.write_bytes(b"\xff\xfe\x00bad")
    with pytest.raises(InputError, match="not a UTF-8 text file"):
        Scanner.from_file(binary)


TODAYS = [
    "leica-rtc360",
    "leica-p50",
    "leica-blk360",
    "faro-focus-premium",
    "trimble-x7",
    "zf-imager-5016",
    "riegl-vz-400i",
]


@pytest.mark.parametrize("name", TODAYS)
def test_todays_scanners_reproduce_their_datasheets_3d_point_accuracy(name):
    """Each profile's ranging and angles, combined as √(m_S² + 2·(D·m/ρ)²), give the 3-D
    point accuracy its datasheet publishes within 25 % — a check of the transcription and
    of the assumptions its notes state."""
    s = catalogue()[name]
    assert "datasheet" in s.source and s.notes
    for distance, published in s.extra.get("datasheet_3d_accuracy_mm", []):
        lateral = distance * 1000 / 206264.806
        model = np.sqrt(
            float(s.range_rms_at(distance)) ** 2
            + (lateral * s.angle_rms_arcsec) ** 2
            + (lateral * s.tilt_rms_arcsec) ** 2
        )
        assert model == pytest.approx(published, rel=0.25), (distance, published, model)


def test_levelled_scanners_and_beam_figures():
    cat = catalogue()
    assert cat["leica-p50"].is_levelled and cat["leica-p50"].levelling_rms_arcsec == 1.5
    assert not cat["leica-rtc360"].is_levelled and not cat[DEFAULT].is_levelled
    assert cat["faro-focus-premium"].beam_divergence_mrad == 0.3


def test_presets_the_profiles_step_is_the_default_settings_and_they_round_trip(tmp_path):
    """A catalogue scanner with presets: its profile's step is its default setting's, every
    setting named once, coarsest first in the file; a profile with presets written and read
    back is the same profile."""
    with_presets = [s for s in catalogue().values() if s.presets]
    assert {s.name for s in with_presets} >= {"leica-rtc360", "leica-p50", "faro-focus-premium"}
    for s in with_presets:
        assert s.preset(None).step_mm_at_10m == s.step_mm_at_10m
        steps = [p.step_mm_at_10m for p in s.presets]
        assert steps == sorted(steps, reverse=True)
        path = tmp_path / f"{s.name}.toml"
        s.save(path)
        assert Scanner.from_file(path) == s
    rtc = load_scanner("leica-rtc360")
    assert [p.step_mm_at_10m for p in rtc.presets] == [12.0, 6.0, 3.0]  # mm, the datasheet's
    assert not rtc.sector_scan and load_scanner("leica-p50").sector_scan


def test_a_bad_preset_says_what_the_scanner_has():
    rtc = load_scanner("leica-rtc360")
    with pytest.raises(InputError, match=r"no preset 'ultra'; its presets: low, medium, high"):
        rtc.preset("ultra")
    with pytest.raises(InputError, match=r"unknown key\(s\) speed"):
        Scanner.from_dict(
            {
                "name": "x",
                "range_rms_mm": 1,
                "angle_rms_arcsec": 10,
                "preset": [{"name": "a", "step_mm_at_10m": 5, "speed": 3}],
            }
        )
    with pytest.raises(InputError, match="default_preset 'b' is not one of its presets"):
        Scanner(
            name="x",
            range_rms_mm=1,
            angle_rms_arcsec=10,
            presets=({"name": "a", "step_mm_at_10m": 5},),
            default_preset="b",
        )
