"""GeoPackage, Shapefile and KML/KMZ sites through pyogrio: roles from layer names, heights
from attributes (OpenStreetMap's ``building:height`` and ``building:levels`` too), the CRS
from the file, longitude/latitude projected; broken files refused with a message."""

from __future__ import annotations

import numpy as np
import pyogrio.raw
import pytest
import shapely
from sites import run_cli as cli

from planner.crs import to_wgs84
from planner.errors import InputError
from planner.siteio import read_site

DEFAULT_CRS = "EPSG:25832"


def write(path, geoms, fields: dict, *, layer, crs=DEFAULT_CRS, driver="GPKG", append=False):
    names = list(fields)
    data = [
        np.asarray(fields[n], dtype=object if isinstance(fields[n][0], str) else None)
        for n in names
    ]
    gtype = geoms[0].geom_type + (" Z" if shapely.has_z(geoms[0]) else "")
    pyogrio.raw.write(
        str(path),
        shapely.to_wkb(geoms),
        data,
        fields=names,
        geometry_type=gtype,
        crs=crs,
        driver=driver,
        layer=layer,
        append=append,
    )
    return path


def box(x, y, w=20.0, h=10.0):
    return shapely.box(690_000 + x, 5_335_000 + y, 690_000 + x + w, 5_335_000 + y + h)


def test_geopackage_layers_give_roles_and_heights(tmp_path):
    path = tmp_path / "site.gpkg"
    write(
        path, [box(0, 0), box(40, 0)], {"height": [12.0, 9.5], "id": ["A", "B"]}, layer="Buildings"
    )
    write(path, [box(0, 30, 3, 3)], {"height": [8.0], "name": ["lime"]}, layer="trees", append=True)
    write(path, [box(-10, -20, 80, 6)], {"name": ["road"]}, layer="no_go", append=True)
    site = read_site(path)
    assert [(b.id, b.height_m) for b in site.buildings] == [("A", 12.0), ("B", 9.5)]
    assert [(o.id, o.height_m) for o in site.obstacles] == [("lime", 8.0)]
    assert [a.id for a in site.no_go] == ["road"]
    assert site.crs == DEFAULT_CRS
    assert site.buildings[0].footprint.equals(box(0, 0))  # coordinates kept, no shift


def test_openstreetmap_style_heights(tmp_path):
    path = tmp_path / "osm.gpkg"
    write(
        path,
        [box(0, 0), box(40, 0), box(80, 0)],
        {
            "building:height": ["12 m", "", ""],
            "building:levels": ["", "4", ""],
            "osm_id": ["w1", "w2", "w3"],
        },
        layer="buildings",
    )
    with pytest.raises(InputError, match="no height"):
        read_site(path)  # the third has neither: said, with the fix
    site = read_site(path, default_height_m=6.0, storey_height_m=3.5)
    assert [(b.id, b.height_m) for b in site.buildings] == [("w1", 12.0), ("w2", 14.0), ("w3", 6.0)]


def test_shapefile_with_its_prj_and_without_its_index(tmp_path):
    path = tmp_path / "blocks.shp"
    write(
        path,
        [box(0, 0), box(40, 0)],
        {"levels": [5, 2], "id": ["A", "B"]},
        layer="blocks",
        driver="ESRI Shapefile",
    )
    site = read_site(path)
    assert [(b.id, b.height_m) for b in site.buildings] == [("A", 15.0), ("B", 6.0)]
    assert site.crs == DEFAULT_CRS
    (tmp_path / "blocks.shx").unlink()
    (tmp_path / "blocks.dbf").unlink()
    with pytest.raises(InputError, match=r"blocks\.shp.*(\.shx|\.dbf)"):
        read_site(path)


def test_kml_in_longitude_latitude_is_projected(tmp_path):
    utm = [box(0, 0), box(40, 0, 10, 30)]

    def to_ll(a):
        return np.column_stack(to_wgs84(DEFAULT_CRS, a[:, 0], a[:, 1]))

    ll = [shapely.transform(g, to_ll) for g in utm]
    for suffix in ("kml", "kmz"):
        path = write(
            tmp_path / f"site.{suffix}",
            ll,
            {"Name": ["Town hall", "Annex"], "height": [15.0, 7.0]},
            layer="Buildings",
            crs="EPSG:4326",
            driver="LIBKML",
        )
        site = read_site(path)
        assert site.crs == "EPSG:32632"  # its UTM zone
        assert [b.id for b in site.buildings] == ["Town hall", "Annex"]
        # the same place: ETRS89 and WGS 84 UTM 32N agree within a metre; areas within 0.1 %
        for b, g in zip(site.buildings, utm, strict=True):
            assert b.footprint.area == pytest.approx(g.area, rel=1e-3)
            assert b.footprint.centroid.distance(g.centroid) < 1.0  # m
        assert any("projected to EPSG:32632" in w for w in site.warnings)


GOOGLE_EARTH_SHED = """<?xml version="1.0" encoding="UTF-8"?>
<kml xmlns="http://www.opengis.net/kml/2.2"><Document><name>drawn</name>
<Placemark><name>shed</name><Polygon><extrude>1</extrude>
<altitudeMode>relativeToGround</altitudeMode><outerBoundaryIs><LinearRing><coordinates>
9.0,48.0,11 9.0002,48.0,11 9.0002,48.0002,11 9.0,48.0002,11 9.0,48.0,11
</coordinates></LinearRing></outerBoundaryIs></Polygon></Placemark></Document></kml>
"""


def test_kml_extruded_polygon_gives_its_height(tmp_path):
    path = tmp_path / "drawn.kml"  # drawn in Google Earth: a polygon extruded from the ground
    path.write_text(GOOGLE_EARTH_SHED)
    site = read_site(path)
    assert [b.id for b in site.buildings] == ["shed"]
    assert site.buildings[0].height_m == pytest.approx(11.0, abs=1e-6)  # m
    assert site.buildings[0].footprint.area == pytest.approx(14.8 * 22.2, rel=0.01)  # m²


def test_layers_in_different_crs_are_refused(tmp_path):
    path = tmp_path / "mixed.gpkg"
    write(path, [box(0, 0)], {"height": [10.0]}, layer="a")
    write(path, [box(0, 0)], {"height": [10.0]}, layer="b", crs="EPSG:25833", append=True)
    with pytest.raises(InputError, match="different coordinate systems"):
        read_site(path)


def test_broken_gis_files_exit_2_with_a_message(tmp_path):
    bad = tmp_path / "bad.gpkg"
    bad.write_bytes(b"not a geopackage" * 64)
    code, _, err = cli("plan", str(bad), "--out", str(tmp_path / "p"), "-q")
    assert code == 2 and "bad.gpkg has the extension .gpkg but is not a GeoPackage" in err
    assert "Traceback" not in err and not (tmp_path / "p").exists()


def test_plan_from_a_geopackage(tmp_path):
    path = tmp_path / "site.gpkg"
    write(path, [box(0, 0)], {"height": [10.0], "id": ["A"]}, layer="buildings")
    out = tmp_path / "plan"
    code, stdout, err = cli(
        "plan",
        str(path),
        "--out",
        str(out),
        "-q",
        "--no-booklet",
        "--grid-m",
        "4",
        "--sample-spacing-m",
        "4",
        "--sample-height-step-m",
        "4",
    )
    assert code == 0, err
    assert "EPSG:25832" in stdout and (out / "plan.kml").exists()
