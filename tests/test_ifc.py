"""An IFC model read directly (issue 68): its building's shell in its map CRS, windows not
demanded, doors said, inner faces never demanded, and bad files refused with exit 2."""

from __future__ import annotations

import builtins
from collections import Counter

import numpy as np
import pandas as pd
import pytest
import shapely
from ifc_models import E0, H0, N0, TURN_DEG, town_hall
from sites import run_cli

from planner.cityio import read_city_model
from planner.errors import InputError


@pytest.fixture(scope="module")
def hall(tmp_path_factory):
    return town_hall(tmp_path_factory.mktemp("ifc") / "town-hall.ifc")


def test_the_building_stands_in_its_map_crs_with_its_outline_and_height(hall):
    """The model's IfcMapConversion places it: the 20 × 12 m outline turned 30° about
    (E0, N0), its base at H0, 8.3 m high (walls and the roof slab); EPSG:25832."""
    site = read_city_model(hall)
    assert site.crs == "EPSG:25832"
    (b,) = site.planned
    assert b.name == "Town hall"
    assert b.base_z == pytest.approx(H0, abs=1e-6)  # m
    assert b.height_m == pytest.approx(8.3, abs=1e-6)  # m
    t = np.radians(TURN_DEG)
    corners = np.array([[0, 0], [20, 0], [20, 12], [0, 12]], dtype=float)
    placed = np.column_stack(
        [
            E0 + corners[:, 0] * np.cos(t) - corners[:, 1] * np.sin(t),
            N0 + corners[:, 0] * np.sin(t) + corners[:, 1] * np.cos(t),
        ]
    )
    expected = shapely.Polygon(placed)
    # the window and door stand 0.05 m proud of the south wall: 0.15 m² more
    assert b.footprint.area == pytest.approx(240.15, abs=0.01)  # m²
    assert b.footprint.symmetric_difference(expected).area < 0.2  # m²


def test_windows_doors_and_inner_faces_are_classed_and_said(hall):
    site = read_city_model(hall)
    (b,) = site.planned
    kinds = Counter(s.kind for s in b.surfaces)
    assert kinds["window"] >= 2 and kinds["door"] >= 2 and kinds["interior"] >= 8
    assert kinds["roof"] >= 2
    said = " ".join(site.warnings)
    assert "window surface(s) (glass) are not demanded" in said
    assert "door surface(s) are demanded as wall is" in said
    # every wall face left demanded is on the outline, facing out of it
    outline = b.footprint
    for s in b.surfaces:
        if s.kind == "wall":
            c = s.rings[0].mean(axis=0)[:2]
            n = s.normal[:2] / np.linalg.norm(s.normal[:2])
            assert not outline.contains(shapely.Point(c + 0.2 * n))
            assert outline.buffer(0.01).contains(shapely.Point(c))
        if s.kind == "interior":  # a wall's inner side: the ground in front is inside
            c = s.rings[0].mean(axis=0)[:2]
            n = s.normal[:2] / max(np.linalg.norm(s.normal[:2]), 1e-9)
            assert outline.contains(shapely.Point(c + 0.05 * n))


def test_an_ifc_model_plans_from_the_command_line_and_no_sample_is_inside(hall, tmp_path):
    out = tmp_path / "plan"
    code, stdout, err = run_cli("plan", str(hall), "--out", str(out), "-q")
    assert code in (0, 1), err
    assert "EPSG:25832" in stdout
    cov = pd.read_csv(out / "coverage.csv", keep_default_na=False)
    site = read_city_model(hall)
    (b,) = site.planned
    assert len(cov) > 50
    # every sample on the building's outline (none on an inner face), within 5 cm
    ring = b.footprint.exterior
    d = shapely.distance(ring, shapely.points(cov[["x", "y"]].to_numpy(float)))
    assert float(np.max(d)) < 0.06  # m
    assert cov["meets"].astype(str).eq("True").mean() > 0.9


def test_a_model_without_georeferencing_is_read_in_local_metres_and_said(tmp_path):
    site = read_city_model(town_hall(tmp_path / "local.ifc", georeferenced=False))
    assert site.crs is None
    assert any("no georeferencing (IfcMapConversion)" in w for w in site.warnings)
    (b,) = site.planned
    assert b.footprint.bounds == pytest.approx((0.0, -0.05, 20.0, 12.0), abs=1e-6)  # m


def test_a_broken_or_empty_ifc_is_refused_with_exit_2(tmp_path):
    bad = tmp_path / "bad.ifc"
    bad.write_text("ISO-10303-21;\nHEADER;\nthis is not a STEP file\n")
    code, _stdout, err = run_cli("plan", str(bad), "--out", str(tmp_path / "o"), "-q")
    assert code == 2 and "bad.ifc" in err and "Traceback" not in err
    import ifcopenshell.api as api

    f = api.run("project.create_file", version="IFC4")
    api.run("root.create_entity", f, ifc_class="IfcProject", name="P")
    empty = tmp_path / "empty.ifc"
    f.write(str(empty))
    code, _stdout, err = run_cli("plan", str(empty), "--out", str(tmp_path / "o2"), "-q")
    assert code == 2 and "no element of the IFC model belongs to an IfcBuilding" in err


def test_without_ifcopenshell_the_message_says_what_to_install(hall, monkeypatch):
    real = builtins.__import__

    def no_ifc(name, *args, **kwargs):
        if name == "ifcopenshell" or name.startswith("ifcopenshell."):
            raise ImportError(name)
        return real(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_ifc)
    with pytest.raises(InputError, match=r"tls-planner\[ifc\]"):
        read_city_model(hall)
