"""A real export read in one run: every problem reported together, far problems noted and
let pass, overlapping buildings repaired pair by pair, heights from building:levels."""

from __future__ import annotations

import json

import pandas as pd
import pytest
import shapely
from sites import osm_like_export, rect, run_cli

from planner.pipeline.engine.planning import plan
from planner.pipeline.inputs.requirements import PlanSettings
from planner.site import FAR_HEIGHT_M, Building, Site
from planner.sitecheck import SiteProblems, notes_table, resolve_overlaps
from planner.siteio import read_site


@pytest.fixture
def export(tmp_path):
    path = tmp_path / "export.geojson"
    path.write_text(json.dumps(osm_like_export()))
    return path


def _kinds(exc: SiteProblems) -> dict[str, int]:
    out: dict[str, int] = {}
    for p in exc.problems:
        out[p.kind] = out.get(p.kind, 0) + 1
    return out


def test_every_problem_near_the_planned_buildings_is_reported_in_one_run(export):
    with pytest.raises(SiteProblems) as caught:
        read_site(export, buildings=["main"])
    exc = caught.value
    assert _kinds(exc) == {"no-height": 1, "outline": 1, "overlap": 2}
    text = str(exc)
    assert text.startswith("export.geojson: the site has 4 problems")
    for ident in ("way/1003", "way/1005", "'way/1001' and 'way/1002'", "'way/1003' and 'way/1004'"):
        assert ident in text
    assert "way/2" not in text and "way/3" not in text  # the far ones do not stop the plan
    assert "--make-valid" in text and "--height H" in text


def test_the_repair_and_a_default_height_read_it_and_say_what_they_did(export):
    site = read_site(export, buildings=["main"], repair=True, default_height_m=12.0)
    by_id = {b.id: b for b in site.buildings}
    notes = notes_table(site.notes)
    row = notes.set_index(["kind", "feature_ids", "action"])
    # heights: levels × 3 m, the default, "14 m" read as 14
    assert by_id["way/1001"].height_m == pytest.approx(12.0)  # 4 levels, m
    assert by_id["way/1004"].height_m == pytest.approx(9.0)  # 3 levels, m
    assert by_id["way/1003"].height_m == pytest.approx(12.0)  # the default, m
    assert by_id["way/1002"].height_m == pytest.approx(14.0)  # "14 m", m
    assert ("no-height", "way/1001", "levels") in row.index
    assert ("no-height", "way/1003", "default") in row.index
    # the shared wall digitised twice: snapped, so the two share the wall and no ground
    a, b = by_id["way/1001"].footprint, by_id["way/1002"].footprint
    assert a.intersection(b).area < 0.01  # m²
    assert a.boundary.intersection(b.boundary).length == pytest.approx(12.0, abs=0.01)  # m
    assert row.loc[("overlap", "way/1002;way/1001", "snapped"), "area_m2"] == pytest.approx(3.6)
    # the corner overlap clipped from the smaller building (96 m² less 8 m²)
    assert by_id["way/1004"].footprint.area == pytest.approx(88.0, abs=0.05)  # m²
    assert row.loc[("overlap", "way/1004;way/1003", "clipped"), "area_m2"] == pytest.approx(8.0)
    assert by_id["way/1005"].footprint.is_valid
    # far away: the pairs left, the unclosed way left out
    assert ("overlap", "way/2007;way/3002", "left") in row.index  # drawn twice
    assert ("geometry", "way/3004", "dropped") in row.index
    assert "way/3004" not in by_id
    # a building part inside its building: the outline stands for it
    assert ("part", "way/1006", "dropped") in row.index and "way/1006" not in by_id
    assert notes["x"].notna().sum() >= 6  # the pairs and outlines are located


def test_with_the_repair_alone_only_the_missing_height_is_left(export):
    with pytest.raises(SiteProblems) as caught:
        read_site(export, buildings=["main"], repair=True)
    assert _kinds(caught.value) == {"no-height": 1}
    assert "way/1003" in str(caught.value)


def test_problems_only_far_from_the_planned_buildings_are_notes(export):
    data = osm_like_export()
    near_problems = ("way/1002", "way/1003", "way/1004", "way/1005")
    data["features"] = [f for f in data["features"] if f.get("id") not in near_problems]
    export.write_text(json.dumps(data))
    site = read_site(export, buildings=["main"])
    notes = notes_table(site.notes)
    far = notes[notes["action"] == "far"]
    assert set(far.loc[far["kind"] == "no-height", "feature_ids"]) == {
        f"way/2{k:03d}" for k in range(20)
    }
    heights = {b.id: b.height_m for b in site.buildings}
    assert heights["way/2000"] == FAR_HEIGHT_M
    assert heights["way/2020"] == pytest.approx(6.0)  # 2 levels × 3 m
    assert set(notes.loc[notes["kind"] == "outline", "feature_ids"]) == {
        "way/2003",
        "way/2014",
        "way/2027",
    }
    assert all(site_b.footprint.is_valid for site_b in site.buildings)
    assert set(notes.loc[notes["action"] == "left", "feature_ids"]) >= {"way/2007;way/3002"}


def test_a_building_drawn_twice_near_the_plan_is_left_to_the_user(tmp_path):
    feats = [
        {"type": "Feature", "properties": {"id": i, "height": 10}, "geometry": g}
        for i, g in (
            ("A", shapely.geometry.mapping(rect(0, 0, 20, 10))),
            ("B", shapely.geometry.mapping(rect(30, 0, 45, 10))),
            ("B2", shapely.geometry.mapping(rect(30, 0, 45, 10.2))),
        )
    ]
    path = tmp_path / "twice.geojson"
    path.write_text(
        json.dumps(
            {
                "type": "FeatureCollection",
                "crs": {"type": "name", "properties": {"name": "EPSG:25832"}},
                "features": feats,
            }
        )
    )
    with pytest.raises(SiteProblems, match=r"'B' and 'B2' overlap by 150.00 m² \(100 %"):
        read_site(path, buildings=["A"], repair=True)


def test_snapping_a_shared_wall_makes_it_a_party_wall():
    """Two terraced houses whose shared wall was digitised twice (a 0.3 m overlap): after
    the repair the wall is a party wall, as it is when the wall is drawn once."""
    exact = [Building("W", rect(0, 0, 10, 10), 9.0), Building("E", rect(10, 0, 20, 10), 9.0)]
    sloppy = [rect(0, 0, 10, 10), rect(9.7, 0, 20, 10.05)]
    fixed, notes = resolve_overlaps(["W", "E"], sloppy, 0.01)
    assert [n.action for n in notes] == ["snapped"]
    repaired = [Building("W", fixed[0], 9.0), Building("E", fixed[1], 9.0)]
    st = PlanSettings(registration_error=False, time_limit_s=30)
    party = [
        int(plan(Site(b), settings=st).coverage["party_wall"].sum()) for b in (exact, repaired)
    ]
    assert party[0] > 0
    assert party[1] == party[0]


def test_the_plan_writes_the_repair_table_and_counts_in_the_summary(export, tmp_path):
    out = tmp_path / "plan"
    code, _stdout, err = run_cli(
        "plan",
        str(export),
        "--buildings",
        "main",
        "--make-valid",
        "--height",
        "12",
        "--no-booklet",
        "-q",
        "--out",
        str(out),
    )
    assert code in (0, 1), err
    table = pd.read_csv(out / "site_repairs.csv", keep_default_na=False)
    site = read_site(export, buildings=["main"], repair=True, default_height_m=12.0)
    assert len(table) == len(site.notes) >= 30
    summary = (out / "summary.txt").read_text()
    assert "has no height" not in summary
    site_lines = [line for line in summary.splitlines() if line.startswith("Site: ")]
    assert 5 <= len(site_lines) <= 8
    assert any(line.startswith("Site: 21 buildings without a height") for line in site_lines)
    assert "Site: 1 overlapping pair along a shared wall, snapped" in summary
