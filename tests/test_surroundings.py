"""A model's surroundings from a second file (issues 68, 70): a city or BIM model that
holds only its buildings says so, and ``--surroundings`` adds the neighbours, trees and
no-go areas around it (never planned; one of the model's own buildings left out, said)."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest
import shapely
from ifc_models import E0, N0, town_hall
from sites import run_cli

from planner.cityio import read_city_model
from planner.errors import InputError
from planner.siteio import with_surroundings


def _around(path, crs: str | None = "EPSG:25832"):
    """A neighbour 10 m south of the hall, the hall itself again (from another source), a
    tree and a no-go street west of it."""
    features = [
        {
            "type": "Feature",
            "properties": {"id": "neighbour", "height": 12.0},
            "geometry": shapely.geometry.mapping(shapely.box(E0 - 5, N0 - 30, E0 + 20, N0 - 12)),
        },
        {
            "type": "Feature",
            "properties": {"id": "hall-from-osm", "height": 8.0},
            "geometry": shapely.geometry.mapping(shapely.box(E0, N0 + 2, E0 + 12, N0 + 14)),
        },
        {
            "type": "Feature",
            "properties": {"id": "lime", "role": "obstacle", "natural": "tree", "height": 9.0},
            "geometry": {"type": "Point", "coordinates": [E0 + 30.0, N0 - 5.0]},
        },
        {
            "type": "Feature",
            "properties": {"id": "street", "role": "no-go"},
            "geometry": shapely.geometry.mapping(shapely.box(E0 - 40, N0 - 40, E0 - 20, N0 + 60)),
        },
    ]
    doc = {"type": "FeatureCollection", "features": features}
    if crs:
        doc["crs"] = {"type": "name", "properties": {"name": crs}}
    path.write_text(json.dumps(doc))
    return path


@pytest.fixture(scope="module")
def hall(tmp_path_factory):
    return town_hall(tmp_path_factory.mktemp("ifc") / "town-hall.ifc")


def test_a_model_of_buildings_alone_says_its_surroundings_are_missing(hall):
    site = read_city_model(hall)
    assert any("holds buildings only" in w and "--surroundings" in w for w in site.warnings)


def test_the_surroundings_block_and_keep_out_but_are_never_planned(hall, tmp_path):
    site = read_city_model(hall)
    out = with_surroundings(site, _around(tmp_path / "around.geojson"))
    ids = {b.id: b for b in out.buildings}
    assert "neighbour" in ids and not ids["neighbour"].planned
    assert "hall-from-osm" not in ids  # the model's own building, from another source
    assert [b.id for b in out.planned] == [b.id for b in site.planned]
    assert [o.id for o in out.obstacles] == ["lime"]
    assert [a.id for a in out.no_go] == ["street"]
    words = out.warnings[-1]
    assert "1 building(s) (not planned), 1 tree(s) or obstacle(s), 1 no-go area(s)" in words
    assert "1 of its buildings are the site's own, left out" in words


def test_the_command_plans_around_the_surroundings(hall, tmp_path):
    around = _around(tmp_path / "around.geojson")
    out = tmp_path / "plan"
    code, stdout, err = run_cli(
        "plan", str(hall), "--surroundings", str(around), "--out", str(out), "-q"
    )
    assert code in (0, 1), err
    assert "Surroundings from around.geojson" in stdout
    st = pd.read_csv(out / "stations.csv")
    street = shapely.box(E0 - 40, N0 - 40, E0 - 20, N0 + 60)
    neighbour = shapely.box(E0 - 5, N0 - 30, E0 + 20, N0 - 12)
    pts = shapely.points(st[["x", "y"]].to_numpy(float))
    assert not shapely.contains(street, pts).any()
    assert not shapely.contains(neighbour, pts).any()
    assert np.isfinite(st[["x", "y"]].to_numpy(float)).all()


def test_surroundings_in_another_crs_are_refused(hall, tmp_path):
    site = read_city_model(hall)
    with pytest.raises(InputError, match="give the surroundings in the site's CRS"):
        with_surroundings(site, _around(tmp_path / "utm33.geojson", crs="EPSG:25833"))
