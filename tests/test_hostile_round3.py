"""Hostile input, round three (issue 71): the 3-D readers, the terrain, the materials table
and the re-plan's files. Each case is a file or an option a user could give, with the promise
it checks: exit 2 naming the fault (never a traceback, never exit 3), no silent drop, no
silent unit, no live formula in a file the planner writes."""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pytest
from sites import run_cli

E, N = 691000.0, 5335000.0


def _cube(x0: float, y0: float, size: float = 10.0, h: float = 8.0) -> tuple[list, list]:
    """A building's vertices and the boundaries of its solid (a box)."""
    v = [
        [x0, y0, 0], [x0 + size, y0, 0], [x0 + size, y0 + size, 0], [x0, y0 + size, 0],
        [x0, y0, h], [x0 + size, y0, h], [x0 + size, y0 + size, h], [x0, y0 + size, h],
    ]  # fmt: skip
    faces = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    return v, [[[f] for f in faces]]


def _cityjson(tmp: Path, *, instance: dict | None = None, transform: dict | None = None) -> Path:
    verts, solid = _cube(E, N)
    doc = {
        "type": "CityJSON",
        "version": "1.1",
        "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/25832"},
        "CityObjects": {
            "b1": {
                "type": "Building",
                "geometry": [{"type": "Solid", "lod": "2", "boundaries": solid}],
            }
        },
        "vertices": verts,
    }
    if transform is not None:
        doc["transform"] = transform
    if instance is not None:
        doc["geometry-templates"] = {
            "templates": [{"type": "MultiSurface", "lod": "1", "boundaries": [[[0, 1, 2]]]}],
            "vertices-templates": [[0, 0, 0], [1, 0, 0], [0, 1, 3]],
        }
        doc["CityObjects"]["t1"] = {"type": "SolitaryVegetationObject", "geometry": [instance]}
    path = tmp / "model.city.json"
    path.write_text(json.dumps(doc))
    return path


def _plan(*argv: str, tmp: Path) -> tuple[int, str]:
    code, _out, err = run_cli("plan", *argv, "--out", str(tmp / "out"), "-q")
    assert "Traceback" not in err
    return code, err


@pytest.mark.parametrize(
    ("instance", "said"),
    [
        # a reference vertex of −1 would wrap to the last vertex: a tree on a roof corner
        ({"type": "GeometryInstance", "template": 0, "boundaries": [-1],
          "transformationMatrix": list(np.eye(4).ravel())}, "vertex -1, which does not exist"),
        ({"type": "GeometryInstance", "template": 0, "boundaries": [99],
          "transformationMatrix": list(np.eye(4).ravel())}, "vertex 99, which does not exist"),
        # a matrix that sends the template beyond any number: no object dropped in silence
        ({"type": "GeometryInstance", "template": 0, "boundaries": [0],
          "transformationMatrix": [1e308] * 16}, "transformation matrix"),
    ],
)  # fmt: skip
def test_a_cityjson_instance_that_points_nowhere_is_refused(tmp_path, instance, said):
    code, err = _plan(str(_cityjson(tmp_path, instance=instance)), tmp=tmp_path)
    assert code == 2 and said in err


def test_a_cityjson_transform_with_a_zero_scale_is_named(tmp_path):
    bad = {"scale": [0.0, 0.001, 0.001], "translate": [0.0, 0.0, 0.0]}
    code, err = _plan(str(_cityjson(tmp_path, transform=bad)), tmp=tmp_path)
    assert code == 2 and "'transform' has the scale" in err


def test_a_citygml_wall_with_an_empty_pos_list_is_refused_not_dropped(tmp_path):
    """A real CityGML model (Yokosuka, PLATEAU) with one ring's coordinates emptied: before,
    the wall was dropped without a word (3 facades for 4)."""
    text = (Path(__file__).parent / "data/citymodels/yokosuka_plateau_lod2.gml").read_text()
    start = text.index("<gml:posList")
    head = text.index(">", start) + 1
    path = tmp_path / "town.gml"
    path.write_text(text[:head] + text[text.index("</gml:posList>", head) :])
    code, err = _plan(str(path), tmp=tmp_path)
    assert code == 2 and "a ring has 0 point(s)" in err


@pytest.mark.parametrize("lod", ["nan", "-1", "1e308", "2;rm -rf /", "5"])
def test_a_level_of_detail_that_is_none_is_refused(tmp_path, lod):
    code, err = _plan(str(_cityjson(tmp_path)), "--lod", lod, tmp=tmp_path)
    assert code == 2 and "--lod must be a level of detail 0 to 4" in err


def test_a_mesh_on_a_city_model_is_refused_not_put_over_its_walls(tmp_path):
    mesh = tmp_path / "m.obj"
    mesh.write_text(f"v {E} {N} 0\nv {E + 5} {N} 0\nv {E} {N + 5} 5\nf 1 2 3\n")
    code, err = _plan(str(_cityjson(tmp_path)), "--mesh", str(mesh), tmp=tmp_path)
    assert code == 2 and "already have theirs" in err


def test_a_terrain_whose_heights_are_in_feet_is_refused_naming_the_unit(tmp_path):
    import pyproj
    import rasterio
    from rasterio.crs import CRS
    from rasterio.transform import from_origin

    path = tmp_path / "dtm.tif"
    crs = CRS.from_wkt(pyproj.CRS("EPSG:25832+6360").to_wkt())  # ETRS89 / UTM 32N + ftUS
    raster = {"height": 40, "width": 40, "count": 1, "dtype": "float32", "crs": crs}
    where = from_origin(E - 200, N + 200, 10, 10)
    with rasterio.open(path, "w", driver="GTiff", transform=where, **raster) as d:
        d.write(np.full((1, 40, 40), 328.0, dtype="float32"))
    ring = [[E, N], [E + 20, N], [E + 20, N + 15], [E, N + 15], [E, N]]
    feature = {
        "type": "Feature",
        "properties": {"id": "a", "height": 10},
        "geometry": {"type": "Polygon", "coordinates": [ring]},
    }
    crs_member = {"type": "name", "properties": {"name": "EPSG:25832"}}
    site = tmp_path / "site.geojson"
    site.write_text(
        json.dumps({"type": "FeatureCollection", "crs": crs_member, "features": [feature]})
    )
    code, err = _plan(str(site), "--terrain", str(path), tmp=tmp_path)
    assert code == 2 and "US survey foot" in err


@pytest.mark.parametrize(
    ("toml", "said"),
    [
        ('[[material]]\nname = "x"\nreflectance = 0.5\naliases = 5\n', "aliases must be a list"),
        (
            '[[material]]\nname = "x"\nreflectance = 0.5\nlabel = { a = 1 }\n',
            "label must be a text",
        ),
        ("a = " + "[" * 3000 + "]" * 3000 + "\n", "nested too deeply"),
    ],
)
def test_a_materials_table_that_is_not_one_is_refused(tmp_path, toml, said):
    path = tmp_path / "mat.toml"
    path.write_text(toml)
    code, err = _plan("--materials", str(path), tmp=tmp_path)
    assert code == 2 and said in err


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no named pipes here")
def test_a_pipe_or_a_folder_given_as_a_file_is_said_as_such_and_never_opened(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)  # opening it would wait for a writer for ever
    code, err = _plan(str(fifo), tmp=tmp_path)
    assert code == 2 and "is a pipe, not a file" in err
    code, err = _plan("--zones", str(tmp_path), tmp=tmp_path)
    assert code == 2 and "is a folder, not a file" in err


def test_the_replans_files_refused_and_written_as_the_others(tmp_path):
    """An empty table of scans, a report's error of 1e308 mm or −3 mm: exit 2 naming the row;
    a scan a crew named as a formula lands inert in as_scanned.csv."""
    empty = tmp_path / "empty.csv"
    empty.write_text("")
    code, _, err = run_cli("replan", "--as-scanned", str(empty), "--out", str(tmp_path / "a"), "-q")
    assert code == 2 and "empty" in err and "Traceback" not in err
    scans = tmp_path / "scans.csv"
    scans.write_text('station_id,x,y\nS01,691020,5335050\n=HYPERLINK("x"),691030,5335050\n')
    for error in ("1e308", "-3"):
        report = tmp_path / "report.csv"
        report.write_text(f"From,To,Error\nS01,S02,{error}\n")
        code, _, err = run_cli(
            "replan", "--as-scanned", str(scans), "--link-report", str(report),
            "--out", str(tmp_path / "b"), "-q",
        )  # fmt: skip
        assert code == 2 and "row 2's error [mm]" in err
    code, _, err = run_cli("replan", "--as-scanned", str(scans), "--out", str(tmp_path / "c"), "-q")
    assert code in (0, 1), err
    text = (tmp_path / "c" / "as_scanned.csv").read_text()
    assert "'=HYPERLINK" in text and '\n"=HYPERLINK' not in text and "\n=HYPERLINK" not in text


def _densified_box(per_edge: int, w: float = 30.0, d: float = 20.0, h: float = 12.0) -> dict:
    """A CityJSON box building whose walls, ground and roof are drawn with ``per_edge``
    vertices along each footprint edge (all in line): 8 × ``per_edge`` vertices."""
    corners = [(0.0, 0.0), (w, 0.0), (w, d), (0.0, d)]
    t = np.linspace(0.0, 1.0, per_edge, endpoint=False)
    ring = np.vstack(
        [
            np.column_stack([x0 + (x1 - x0) * t, y0 + (y1 - y0) * t])
            for (x0, y0), (x1, y1) in zip(corners, corners[1:] + corners[:1], strict=True)
        ]
    )
    m = len(ring)
    verts = [[x, y, 0.0] for x, y in ring] + [[x, y, h] for x, y in ring]
    walls = []
    for k in range(4):
        edge = [(k * per_edge + j) % m for j in range(per_edge + 1)]
        walls.append([edge + [m + i for i in edge[::-1]]])
    bottom, top = list(range(m))[::-1], [m + i for i in range(m)]
    return {
        "type": "CityJSON",
        "version": "2.0",
        "transform": {"scale": [1.0, 1.0, 1.0], "translate": [500000.0, 5400000.0, 100.0]},
        "CityObjects": {
            "B1": {
                "type": "Building",
                "geometry": [
                    {
                        "type": "Solid",
                        "lod": "2",
                        "boundaries": [[*walls, [bottom], [top]]],
                        "semantics": {
                            "surfaces": [
                                {"type": "WallSurface"},
                                {"type": "GroundSurface"},
                                {"type": "RoofSurface"},
                            ],
                            "values": [[0, 0, 0, 0, 1, 2]],
                        },
                    }
                ],
            }
        },
        "vertices": verts,
    }


def test_a_building_drawn_with_many_vertices_in_line_reads_as_its_corners():
    """A building of 40 000 vertices, every one of its walls' edges densified in line (the
    hostile round's 500 000-vertex building took 262 s, 210 s of it ear-clipping and the
    DXF 3-D outlines of every vertex): each surface keeps its corners (within a
    millimetre), so the walls, their areas and the plan are those of the plain box."""
    from planner.cityio import site_from_cityjson

    dense = site_from_cityjson(_densified_box(5000))
    plain = site_from_cityjson(_densified_box(1))
    (a,), (b,) = dense.planned, plain.planned
    assert [len(s.rings[0]) for s in a.surfaces] == [len(s.rings[0]) for s in b.surfaces]
    assert max(len(s.rings[0]) for s in a.surfaces) == 4
    area = {s.kind: 0.0 for s in b.surfaces}
    for s in a.surfaces:
        area[s.kind] += s.area_m2
    for s in b.surfaces:
        area[s.kind] -= s.area_m2
    assert all(v == pytest.approx(0.0, abs=1e-6) for v in area.values())  # m²
