"""Site input: the three readers, the default site, and every bad input caught before work."""

from __future__ import annotations

import json

import pytest
import shapely
from shapely.geometry import Point, box
from sites import E0, N0, rect

from planner import InputError
from planner.site import Building, Obstacle, Site
from planner.sitecheck import notes_summary
from planner.siteio import default_site, read_site


def fc(*features, crs="EPSG:25832"):
    out = {"type": "FeatureCollection", "features": list(features)}
    if crs:
        out["crs"] = {"type": "name", "properties": {"name": crs}}
    return out


def feat(geom, **props):
    return {"type": "Feature", "geometry": shapely.geometry.mapping(geom), "properties": props}


def write(tmp_path, name, text):
    p = tmp_path / name
    p.write_text(text if isinstance(text, str) else json.dumps(text))
    return p


def test_default_site_is_realistic():
    s = default_site()
    assert [b.id for b in s.planned] == ["main"]
    main = s.planned[0]
    assert main.height_m == 15.0
    assert main.footprint.area == pytest.approx(48 * 34 - 22 * 14 - 6 * 10)  # C-shaped block
    assert not shapely.equals(main.footprint, main.footprint.convex_hull)  # non-convex
    assert {o.kind for o in s.obstacles} == {"tree"}
    assert [a.id for a in s.no_go] == ["street"]
    assert s.boundary is not None and s.crs.endswith("25832")
    # the annex shares the east wall (a party wall), the house stands 12 m west
    annex = next(b for b in s.buildings if b.id == "annex")
    assert main.footprint.touches(annex.footprint) and not annex.planned


def test_geojson_wkt_and_csv_give_the_same_site(tmp_path):
    foot = rect(0, 0, 20, 10)
    gj = write(
        tmp_path,
        "a.geojson",
        fc(feat(foot, id="B1", height=9.0), feat(rect(30, 0, 32, 2), role="obstacle", height=3)),
    )
    wkt = write(
        tmp_path,
        "a.wkt",
        f"{foot.wkt}; id=B1; height=9\n{rect(30, 0, 32, 2).wkt}; role=obstacle; height=3\n",
    )
    rows = ["id,x,y,height,role"]
    rows += [f"B1,{x},{y},9," for x, y in list(foot.exterior.coords)[:-1]]
    rows += [f"O1,{x},{y},3,obstacle" for x, y in list(rect(30, 0, 32, 2).exterior.coords)[:-1]]
    csv = write(tmp_path, "a.csv", "\n".join(rows) + "\n")
    sites = [read_site(p) for p in (gj, wkt, csv)]
    for s in sites:
        assert [b.id for b in s.buildings] == ["B1"]
        assert s.buildings[0].height_m == 9.0
        assert shapely.equals(s.buildings[0].footprint, foot)
        assert len(s.obstacles) == 1 and s.obstacles[0].height_m == 3.0
    assert sites[0].crs == "EPSG:25832"


def test_csv_with_holes_and_parts(tmp_path):
    rows = ["id,part,ring,x,y,height"]
    rows += [f"C,0,0,{E0 + x},{N0 + y},10" for x, y in [(0, 0), (30, 0), (30, 30), (0, 30)]]
    rows += [f"C,0,1,{E0 + x},{N0 + y},10" for x, y in [(10, 10), (10, 20), (20, 20), (20, 10)]]
    rows += [f"C,1,0,{E0 + x},{N0 + y},10" for x, y in [(50, 0), (60, 0), (60, 10), (50, 10)]]
    s = read_site(write(tmp_path, "c.csv", "\n".join(rows)))
    geom = s.buildings[0].footprint
    assert geom.geom_type == "MultiPolygon" and geom.area == pytest.approx(900 - 100 + 100)


def test_feature_index_is_the_id_when_none_is_given(tmp_path):
    s = read_site(
        write(
            tmp_path,
            "x.geojson",
            fc(feat(rect(0, 0, 5, 5), height=3), feat(rect(10, 0, 15, 5), height=4)),
        )
    )
    assert [b.id for b in s.buildings] == ["0", "1"]


def test_selection_makes_the_others_obstacles(tmp_path):
    feats = [feat(rect(25 * i, 0, 25 * i + 20, 10), id=f"b{i}", height=8) for i in range(200)]
    p = write(tmp_path, "city.geojson", fc(*feats))
    s = read_site(p, buildings=["b7", "b8"])
    assert [b.id for b in s.planned] == ["b7", "b8"]
    assert len(s.blockers) == 200
    with pytest.raises(InputError, match="no building with id 'b999'; ids are: b0, b1"):
        read_site(p, buildings=["b999"])


def test_missing_height_uses_the_default_with_a_warning(tmp_path):
    p = write(tmp_path, "h.geojson", fc(feat(rect(0, 0, 5, 5), id="A")))
    with pytest.raises(
        InputError,
        match=r"has no height; add a 'height' \(or 'building:levels'\) property .* \(--height H\)",
    ):
        read_site(p)
    s = read_site(p, default_height_m=11.0)
    assert s.buildings[0].height_m == 11.0
    assert [(n.kind, n.ids, n.action) for n in s.notes] == [("no-height", ("A",), "default")]
    assert notes_summary(s.notes) == [
        "Site: 1 building without a height given the default height 11 m (A; each in "
        "site_repairs.csv)."
    ]


BOWTIE = shapely.Polygon([(E0, N0), (E0 + 10, N0 + 10), (E0 + 10, N0), (E0, N0 + 10)])


@pytest.mark.parametrize(
    ("features", "message"),
    [
        (
            [feat(BOWTIE, id="bow", height=5)],
            r"building 'bow' is not a valid polygon: Self-intersection\[500005 5400005\]",
        ),
        (
            [{"type": "Feature", "geometry": None, "properties": {"id": "e", "height": 3}}],
            "has no geometry",
        ),
        ([feat(shapely.Polygon(), id="e", height=3)], "'e' has an empty geometry"),
        ([feat(rect(0, 0, 5, 5), id="z", height=0)], "'z' has height 0; it must be a number > 0"),
        ([feat(rect(0, 0, 5, 5), id="n", height="tall")], "give the height in metres as a number"),
        (
            [
                feat(
                    shapely.Polygon([(E0, N0), (E0 + 5, N0), (E0 + 5, N0), (E0 + 5, N0 + 5)]),
                    id="d",
                    height=3,
                )
            ],
            r"'d' has a zero-length edge \(a repeated vertex\) at \(500005.000, 5400000.000\)",
        ),
        (
            [
                feat(rect(0, 0, 10, 10), id="B", height=9),
                feat(rect(8, 8, 12, 12), role="obstacle", height=5, id="t"),
            ],
            "obstacle 't' overlaps building 'B' by 4.00 m²; clip the obstacle",
        ),
        (
            [
                feat(rect(0, 0, 10, 10), id="A", height=9),
                feat(rect(5, 0, 15, 10), id="B", height=9),
            ],
            "buildings 'A' and 'B' overlap by 50.00 m²",
        ),
        (
            [feat(rect(0, 0, 10, 10), id="A", height=9, role="roof")],
            "has role 'roof' — use one of building",
        ),
        ([feat(rect(0, 0, 10, 10), role="obstacle", height=3)], "no building footprint"),
        (
            [feat(shapely.LineString([(E0, N0), (E0 + 9, N0)]), id="w", height=2)],
            "is a LineString; it must be a Polygon",
        ),
        (
            [feat(rect(0, 0, 10, 10), id="A", height=9), feat(rect(20, 0, 40, 5), role="boundary")],
            "building 'A' is not inside the site boundary",
        ),
    ],
)
def test_bad_input_names_the_feature_and_the_fix(tmp_path, features, message):
    p = write(tmp_path, "bad.geojson", fc(*features))
    with pytest.raises(InputError, match=message):
        read_site(p)


def test_degrees_are_longitude_latitude_in_geojson_and_said_elsewhere(tmp_path):
    """GeoJSON without a CRS in the degree range is longitude/latitude (RFC 7946): projected
    to its UTM zone (about 15 m × 22 m here); WKT in degrees needs --crs, and the message
    says so."""
    p = write(
        tmp_path, "ll.geojson", fc(feat(box(11.57, 48.13, 11.5702, 48.1302), height=9), crs=None)
    )
    s = read_site(p)
    assert s.crs == "EPSG:32632"
    # 0.0002° × 0.0002° at 48.13° N: 14.86 m × 22.26 m (rotated by the grid convergence)
    assert s.buildings[0].footprint.area == pytest.approx(14.86 * 22.26, rel=0.005)  # m²
    w = write(
        tmp_path,
        "ll.wkt",
        "POLYGON ((11.57 48.13, 11.5702 48.13, 11.5702 48.1302, "
        "11.57 48.1302, 11.57 48.13));height=9\n",
    )
    with pytest.raises(InputError, match=r"look like longitude/latitude.*--crs EPSG:4326"):
        read_site(w)
    assert read_site(w, crs="EPSG:4326").crs == "EPSG:32632"


def test_make_valid_is_an_explicit_option(tmp_path):
    p = write(tmp_path, "bow.geojson", fc(feat(BOWTIE, id="bow", height=5)))
    with pytest.raises(InputError, match="make_valid"):
        read_site(p)
    s = read_site(p, repair=True)
    assert s.buildings[0].footprint.is_valid
    assert s.buildings[0].footprint.area == pytest.approx(50.0)
    assert [(n.kind, n.ids, n.action) for n in s.notes] == [("outline", ("bow",), "repaired")]


@pytest.mark.parametrize(
    ("name", "content", "message"),
    [
        ("a.geojson", "id,x,y\n1,2,3\n", "content looks like CSV"),
        ("a.csv", '{"type": "FeatureCollection", "features": []}', "content looks like GEOJSON"),
        ("a.wkt", "POLYGON ((0 0, 1 0, 1", "line 1 is not WKT"),
        ("a.geojson", '{"type": "FeatureCollection", "features": [', "is not valid JSON"),
        ("a.geojson", '{"features": []}', "not GeoJSON"),
        ("a.shp", "whatever", "has the extension .shp but is not a Shapefile"),
        ("a.csv", "name,easting\nx,1\n", "needs the columns id, x, y"),
    ],
)
def test_a_file_that_is_not_what_its_extension_says(tmp_path, name, content, message):
    with pytest.raises(InputError, match=message):
        read_site(write(tmp_path, name, content))


def test_binary_and_missing_files(tmp_path):
    b = tmp_path / "x.csv"
    b.write_bytes(b"\x00\x01\x02PK")
    with pytest.raises(InputError, match="is a binary file"):
        read_site(b)
    with pytest.raises(InputError, match="does not exist"):
        read_site(tmp_path / "nope.geojson")


def test_site_in_code_validates_too():
    with pytest.raises(InputError, match="has no building to plan"):
        Site([Building("a", rect(0, 0, 5, 5), 5, planned=False)])
    with pytest.raises(InputError, match="appears twice"):
        Site([Building("a", rect(0, 0, 5, 5), 5), Building("a", rect(9, 0, 14, 5), 5)])
    with pytest.raises(InputError, match="tree 't' has height -1"):
        Site(
            [Building("a", rect(0, 0, 5, 5), 5)],
            [Obstacle("t", Point(E0 + 9, N0).buffer(1), -1, "tree")],
        )
