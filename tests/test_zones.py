"""Requirements per building, facade and zone: reading them, applying them to the samples,
planning with them, and refusing every bad definition with a message."""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pandas as pd
import pytest
from sites import run_cli as _cli

from planner.pipeline.engine.planning import plan
from planner.pipeline.geometry.facades import build_facades
from planner.pipeline.geometry.zoning import along_m, apply_zones
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.siteio import default_site, site_from_geojson
from planner.zones import Zone, parse_zone, read_zones

ENTRANCE = (
    "id=entrance,facade=main-f00,from=4,to=10,z=0-6,max_xy_mm=4,max_z_mm=4,sample_spacing_m=0.5"
)


# -- reading ------------------------------------------------------------------------------
def test_a_zone_from_the_command_line_and_from_a_table_are_the_same(tmp_path):
    a = parse_zone(ENTRANCE)
    (tmp_path / "zones.csv").write_text(
        "id,facade_id,from_m,to_m,z_from_m,z_to_m,max_xy_mm,max_z_mm,sample_spacing_m\n"
        "entrance,main-f00,4,10,0,6,4,4,0.5\n"
    )
    (b,) = read_zones(tmp_path / "zones.csv")
    assert a == b
    assert a.along_m == (4.0, 10.0) and a.height_m == (0.0, 6.0)
    assert a.requirement == {"max_xy_mm": 4.0, "max_z_mm": 4.0}
    assert a.sample_spacing_m == a.sample_height_step_m == 0.5


def test_a_buildings_own_requirement_comes_from_its_properties():
    site = site_from_geojson(
        json.dumps(
            {
                "type": "FeatureCollection",
                "features": [
                    {
                        "type": "Feature",
                        "properties": {"id": "A", "height": 10, "class": "OGL3"},
                        "geometry": {
                            "type": "Polygon",
                            "coordinates": [
                                [
                                    [500000, 5400000],
                                    [500020, 5400000],
                                    [500020, 5400015],
                                    [500000, 5400015],
                                    [500000, 5400000],
                                ]
                            ],
                        },
                    }
                ],
            }
        )
    )
    (z,) = site.zones
    assert z.building_id == "A" and z.requirement == {"accuracy_class": "OGL3"}
    _fac, sreq, table = apply_zones(site, build_facades(site, 2.0, 2.0), Requirements())
    # every sample of the building takes the class's limit
    (zr,) = table.requirements
    np.testing.assert_allclose(sreq.limits["m_x"], zr.max_x_mm)
    assert zr.max_x_mm == 15.0 and zr.max_z_mm == 5.0  # OGL3 (position only): 15 mm
    assert (sreq.zone_ids == z.id).all()
    assert any("looser than the site-wide" in m for m in table.messages)


# -- applying -----------------------------------------------------------------------------
def test_finer_samples_appear_only_in_the_zone_and_take_its_limits():
    site = default_site()
    fac0 = build_facades(site, 2.0, 2.0)
    zone = parse_zone(ENTRANCE)
    fac, sreq, _ = apply_zones(replace(site, zones=[zone]), fac0, Requirements())
    inside = sreq.zone_ids == "entrance"
    f00 = fac.facade == list(fac.facade_id).index("main-f00")
    u = along_m(fac)
    # 6 m × 6 m at 0.5 m: 12 × 12 samples, at cell centres
    assert inside.sum() == 144
    np.testing.assert_allclose(np.unique(np.round(u[inside], 6)), 4.25 + 0.5 * np.arange(12))
    np.testing.assert_allclose(np.unique(np.round(fac.z[inside], 6)), 0.25 + 0.5 * np.arange(12))
    # elsewhere the coarse grid is untouched: the same samples, less those in the zone
    outside = ~inside
    in_zone0 = (
        (fac0.facade == list(fac0.facade_id).index("main-f00"))
        & (along_m(fac0) >= 4)
        & (along_m(fac0) <= 10)
        & (fac0.z <= 6)
    )
    assert set(fac.sample_id[outside]) == set(fac0.sample_id[~in_zone0])
    assert np.diff(np.unique(np.round(u[outside & f00], 6))).min() > 2.0  # 21 m / 10
    assert (sreq.limits["m_x"][inside] == 4.0).all() and (sreq.limits["m_x"][outside] == 5.0).all()
    assert (sreq.limits["m_z"][inside] == 4.0).all()


def test_overlapping_zones_take_the_strictest_and_a_looser_zone_is_said():
    site = default_site()
    zones = [
        parse_zone("id=A,facade=main-f00,from=0,to=10,max_xy_mm=4"),
        parse_zone("id=B,facade=main-f00,from=6,to=21,max_xy_mm=3,max_gamma_deg=80"),
        parse_zone("id=loose,facade=main-f04,max_z_mm=8"),
    ]
    fac, sreq, table = apply_zones(
        replace(site, zones=zones), build_facades(site, 2.0, 2.0), Requirements()
    )
    u = along_m(fac)
    f00 = fac.facade == list(fac.facade_id).index("main-f00")
    both = f00 & (u >= 6) & (u <= 10)
    only_a = f00 & (u < 6)
    assert (sreq.limits["m_x"][both] == 3.0).all() and (sreq.limits["m_x"][only_a] == 4.0).all()
    assert (sreq.limits["gamma"][both] == 75.0).all()  # A's (the site's 75°) is stricter
    assert all(z == "A;B" for z in sreq.zone_ids[both])
    f04 = fac.facade == list(fac.facade_id).index("main-f04")
    assert (sreq.limits["m_z"][f04] == 8.0).all()
    said = " ".join(table.messages)
    assert "loose" in said and "looser than the site-wide" in said and "B" in said


# -- planning -----------------------------------------------------------------------------
def test_a_stricter_entrance_adds_what_it_needs_and_no_more_than_the_strict_site():
    """Scanner's error alone (the optimiser's count is proven optimal): the default site,
    the same with a 4 mm entrance zone, and the whole site at 4 mm."""
    st = PlanSettings(registration_error=False)
    site = default_site()
    base = plan(site, settings=st)
    zoned = plan(replace(site, zones=[parse_zone(ENTRANCE)]), settings=st)
    strict = plan(site, requirements=Requirements(max_xy_mm=4, max_z_mm=4), settings=st)
    for p in (base, zoned, strict):
        assert p.solver.status == "optimal"
    assert base.solver.objective <= zoned.solver.objective <= strict.solver.objective
    assert zoned.solver.objective < strict.solver.objective
    cov = zoned.scanned
    zone = cov[cov["zone"] == "entrance"]
    assert len(zone) == 144 and zone["meets"].all()
    assert (zone[["m_x_mm", "m_y_mm", "m_z_mm"]] <= 4.0 + 1e-9).all().all()
    assert (zoned.zones["unmet"] == 0).all()


def test_samples_in_a_zone_are_judged_by_its_limits_with_registration():
    p = plan(replace(default_site(), zones=[parse_zone(ENTRANCE)]))
    cov = p.scanned
    zone = cov["zone"] == "entrance"
    for c in "xyz":
        assert (cov.loc[zone & cov["meets"], f"m_{c}_mm"] <= 4.0 + 1e-9).all()
        assert (cov.loc[~zone & cov["meets"], f"m_{c}_mm"] <= 5.0 + 1e-9).all()
    # some samples outside the zone are between 4 and 5 mm: judged by the site's limit
    assert (
        (cov.loc[~zone, ["m_x_mm", "m_y_mm", "m_z_mm"]].max(axis=1) > 4.0) & cov.loc[~zone, "meets"]
    ).any()
    assert "Zone entrance" in p.summary()


def test_cli_zone_and_zone_table_give_the_zone_file(tmp_path):
    code, _out, err = _cli("plan", "--zone", ENTRANCE, "--out", str(tmp_path / "p"), "-q")
    assert code == 0, err
    zones = pd.read_csv(tmp_path / "p" / "zones.csv")
    assert list(zones["zone_id"]) == ["entrance"] and zones.loc[0, "met"] == 144
    facades = pd.read_csv(tmp_path / "p" / "facades.csv")
    assert facades.set_index("facade_id").loc["main-f00", "zones"] == "entrance"


BAD_ZONES = [
    ("facade=main-f00,from=4,to=40,max_xy_mm=4", "which is 21.00 m long"),
    ("facade=main-f00,z=20-30,max_xy_mm=4", "above facade main-f00"),
    ("facade=main-f00,z=0-30,max_xy_mm=4", "above facade main-f00"),
    ("facade=main-f99,max_xy_mm=4", "has no facade 'main-f99'"),
    ("facade=nowhere-f00,max_xy_mm=4", "not a building"),
    ("facade=main-f00,mx_xy_mm=4", "did you mean 'max_xy_mm'"),
    ("facade=main-f00,max_xy_mm=four", "max_xy_mm must be a number"),
    ("facade=main-f00,max_xy_mm=-1", "max_xy_mm must be >= 0.01"),
    ("max_xy_mm=4", "give a building_id or a facade_id"),
    ("facade=main-f00,building=main,max_xy_mm=4", "one of them"),
    ("facade=main-f00,from=10,to=4,max_xy_mm=4", "must run from a number >= 0 to a larger one"),
    ("facade=main-f00,from=4,max_xy_mm=4", "give both ends"),
    ("facade=main-f00,elevation=POLYGON((0 0, 30 0, 30 5, 0 0)),max_xy_mm=4", "not within facade"),
    ("facade=main-f00,elevation=POLYGON((0 0,,max_xy_mm=4", "not WKT"),
    ("facade=main-f00,from=4,to=6", "sets no requirement"),
    ("facade=main-f00,class=OGL9", "unknown accuracy class"),
    ("facade=main-f00,class=OGL4,max_xy_mm=2", "conflicts with the accuracy class"),
    ("facade=main-f00,stations_per_sample=0", "stations_per_sample"),
    ("facade=main-f00,stations_per_sample=1.5", "whole number"),
    ("facade=main-f00,from=4,to=4.1,z=0-0.1,max_xy_mm=4", "holds no facade sample"),
    ("facade=main-f00,max_xy_mm=4,sample_spacing_m=0.001", "sample_spacing_m must be from"),
    ("facade main-f00", "is not key=value"),
    ("building=house,from=1,to=2,max_xy_mm=4", "needs a facade_id"),
]


@pytest.mark.parametrize(("spec", "message"), BAD_ZONES)
def test_every_bad_zone_is_refused_with_exit_2_and_a_message(tmp_path, spec, message):
    code, out, err = _cli(
        "plan", "--buildings", "main", "--zone", spec, "--out", str(tmp_path / "p"), "-q"
    )
    assert code == 2, (out, err)
    assert message in err and "Traceback" not in err
    assert not (tmp_path / "p").exists()


@pytest.mark.parametrize(
    ("table", "message"),
    [
        ("id,facade_id,max_xy_mm\nA,main-f00,4\nA,main-f01,4\n", "appears twice"),
        ("id,facade_id,max_xy_mm,colour\nA,main-f00,4,red\n", "unknown key 'colour'"),
        ("id,facade_id,max_xy_mm\n", "has no zones"),
        ("id,facade_id,max_xy_mm\nA,main-f00,4,9\n", "more cells than the header"),
    ],
)
def test_bad_zone_tables_are_refused(tmp_path, table, message):
    path = tmp_path / "zones.csv"
    path.write_text(table)
    code, _, err = _cli("plan", "--zones", str(path), "--out", str(tmp_path / "p"), "-q")
    assert code == 2 and message in err, err


def test_a_zone_on_a_building_not_planned_is_ignored_and_said(tmp_path):
    code, out, err = _cli(
        "plan", "--zone", "building=house,max_xy_mm=4", "--out", str(tmp_path / "p"), "-q"
    )
    assert code == 0, err
    assert "Zone 'zone1' is on building 'house', which is not planned: ignored" in out


def test_a_zone_is_a_value_object():
    z = Zone(id="z", facade_id="main-f00", along_m=(1, 2), requirement={"max_z_mm": 3})
    assert z.along_m == (1.0, 2.0) and z.is_part and "1–2 m along" in z.describe()


def test_the_dashboard_adds_a_zone_without_files():
    from planner.app.dashboard import StationPlanner

    d = StationPlanner()
    z = d.zone_editor
    assert "main-f00" in z.facade.options and z.along.max == 21.0 and z.height.max == 15.0
    z.facade.value = "main-f00"
    z.along.value, z.height.value = (4.0, 10.0), (0.0, 6.0)
    z.max_xy.value, z.max_z.value, z.spacing.value = 4.0, 4.0, 0.5
    z.add_zone()
    assert "main-f00, 4–10 m along, 0–6 m high" in z.listing.value
    d.run()
    assert d.error.value == ""
    assert list(d.plan.zones["zone_id"]) == ["Z1"] and d.plan.zones.loc[0, "samples"] == 144
    assert d.stale.value == ""
    z.facade.value = "main-f00"
    z.along.value = (0.0, 0.05)
    z.height.value = (14.9, 15.0)
    z.spacing.value = 0.0
    z.add_zone()
    assert "Out of date" in d.stale.value  # a zone added dates the plan on screen
    d.run()  # a zone too small to hold a sample: a message, never a traceback
    assert "holds no facade sample" in d.error.value
