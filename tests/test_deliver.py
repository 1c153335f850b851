"""Coordinate systems in, field and CAD files out: longitude/latitude projected to UTM and
back to KML within a centimetre; DXF read back with ezdxf; the stake-out file; CRS labels
that contradict the coordinates refused."""

from __future__ import annotations

import io
import json
import xml.etree.ElementTree as ET
from dataclasses import replace

import ezdxf
import numpy as np
import pandas as pd
import pytest
import shapely
from sites import run_cli as cli

from planner.crs import to_wgs84
from planner.pipeline.documents.export import render
from planner.siteio import default_site

FAST = ["--grid-m", "4", "--sample-spacing-m", "4", "--sample-height-step-m", "4", "-q"]
KML = "{http://www.opengis.net/kml/2.2}"
M_PER_DEG_LAT = 111_320.0  # m per degree of latitude (enough for a 1 cm check)


def wkt_site(folder):
    """The default site's buildings as a WKT file (which carries no CRS)."""
    path = folder / "site.wkt"
    lines = [f"{b.footprint.wkt};id={b.id};height={b.height_m}" for b in default_site().buildings]
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.fixture(scope="module")
def lonlat_site(tmp_path_factory):
    """The default site's buildings in longitude/latitude, as GeoJSON without a CRS member
    (RFC 7946), the way OpenStreetMap exports come."""
    site = default_site()

    def to_ll(a):
        return np.column_stack(to_wgs84(site.crs, a[:, 0], a[:, 1]))

    feats = [
        {
            "type": "Feature",
            "geometry": json.loads(shapely.to_geojson(shapely.transform(b.footprint, to_ll))),
            "properties": {"id": b.id, "height": b.height_m, "plan": b.planned},
        }
        for b in site.buildings
    ]
    path = tmp_path_factory.mktemp("ll") / "osm.geojson"
    path.write_text(json.dumps({"type": "FeatureCollection", "features": feats}))
    return path, feats


@pytest.fixture(scope="module")
def lonlat_plan(lonlat_site, tmp_path_factory):
    path, _ = lonlat_site
    out = tmp_path_factory.mktemp("plan") / "p"
    code, stdout, err = cli("plan", str(path), *FAST, "--out", str(out))
    assert code in (0, 1), err
    return out, stdout


def test_lonlat_is_projected_to_its_utm_zone_and_said(lonlat_plan):
    out, stdout = lonlat_plan
    assert "Coordinates: EPSG:32632 (WGS 84 / UTM zone 32N)" in stdout
    assert "longitude/latitude coordinates (OGC:CRS84) projected to EPSG:32632" in stdout
    gj = json.loads((out / "plan.geojson").read_text())
    assert gj["crs"]["properties"]["name"] == "EPSG:32632"
    stations = pd.read_csv(out / "stations.csv")
    # UTM 32N eastings and northings of Munich, not degrees
    assert stations["x"].between(6.0e5, 7.5e5).all()
    assert stations["y"].between(5.2e6, 5.4e6).all()


def test_kml_lands_within_a_centimetre_of_the_input(lonlat_site, lonlat_plan):
    _, feats = lonlat_site
    out, _ = lonlat_plan
    root = ET.parse(out / "plan.kml").getroot()
    marks = {
        m.findtext(f"{KML}name"): m
        for folder in root.iter(f"{KML}Folder")
        if folder.findtext(f"{KML}name") == "building"
        for m in folder.iter(f"{KML}Placemark")
    }
    for f in feats:
        ring_in = np.asarray(f["geometry"]["coordinates"][0])
        text = marks[f["properties"]["id"]].find(f".//{KML}outerBoundaryIs//{KML}coordinates").text
        ring_out = np.array([[float(v) for v in c.split(",")[:2]] for c in text.split()])
        # same vertices (the planner may drop repeated ones; compare each input vertex with
        # the nearest output vertex)
        d_lon = (
            (ring_in[:, None, 0] - ring_out[None, :, 0])
            * M_PER_DEG_LAT
            * np.cos(np.radians(ring_in[:, None, 1]))
        )
        d_lat = (ring_in[:, None, 1] - ring_out[None, :, 1]) * M_PER_DEG_LAT
        nearest = np.sqrt(d_lon**2 + d_lat**2).min(axis=1)
        assert nearest.max() < 0.01  # m


def test_kml_stations_and_targets_match_the_tables(lonlat_plan):
    out, _ = lonlat_plan
    stations = pd.read_csv(out / "stations.csv").set_index("station_id")
    root = ET.parse(out / "plan.kml").getroot()
    found = {}
    for folder in root.iter(f"{KML}Folder"):
        if folder.findtext(f"{KML}name") != "station":
            continue
        for m in folder.iter(f"{KML}Placemark"):
            lon, lat = (float(v) for v in m.findtext(f".//{KML}coordinates").split(",")[:2])
            found[m.findtext(f"{KML}name")] = (lon, lat)
    assert set(found) == set(stations.index)
    lon, lat = to_wgs84("EPSG:32632", stations["x"].to_numpy(), stations["y"].to_numpy())
    for sid, lo, la in zip(stations.index, lon, lat, strict=True):
        assert found[sid][0] == pytest.approx(lo, abs=1e-8)  # deg ≈ 1 mm
        assert found[sid][1] == pytest.approx(la, abs=1e-8)


def test_dxf_has_every_station_and_target_with_attributes(lonlat_plan):
    out, _ = lonlat_plan
    doc = ezdxf.readfile(out / "plan.dxf")
    msp = doc.modelspace()
    stations = pd.read_csv(out / "stations.csv").set_index("station_id")
    targets = pd.read_csv(out / "targets.csv").set_index("target_id")
    got_st, got_tg = {}, {}
    for ref in msp.query("INSERT"):
        attribs = {a.dxf.tag: a.dxf.text for a in ref.attribs}
        if ref.dxf.name == "STATION":
            assert ref.dxf.layer == "STATIONS"
            got_st[attribs["ID"]] = (ref.dxf.insert, attribs)
        elif ref.dxf.name in ("TARGET-FLAT", "TARGET-SPHERE", "CONTROL"):
            assert ref.dxf.layer == "TARGETS"
            got_tg[attribs["ID"]] = (ref.dxf.insert, attribs)
            assert ref.dxf.name == {"flat": "TARGET-FLAT", "sphere": "TARGET-SPHERE"}.get(
                attribs["TYPE"], "CONTROL"
            )
    assert set(got_st) == set(stations.index) and set(got_tg) == set(targets.index)
    for sid, (ins, attribs) in got_st.items():
        assert ins.x == pytest.approx(stations.at[sid, "x"], abs=0.001)  # m, real coordinates
        assert ins.y == pytest.approx(stations.at[sid, "y"], abs=0.001)
        assert float(attribs["HEIGHT"]) == pytest.approx(stations.at[sid, "instrument_height_m"])
    for tid, (ins, attribs) in got_tg.items():
        assert (ins.x, ins.y, ins.z) == pytest.approx(
            tuple(targets.loc[tid, ["x", "y", "z"]]), abs=0.001
        )
        assert attribs["TYPE"] == targets.at[tid, "type"]
        assert float(attribs["SIZE_MM"]) == pytest.approx(targets.at[tid, "size_mm"], abs=0.5)
    layers = {e.dxf.layer for e in msp}
    assert {"BUILDINGS", "STATIONS", "TARGETS", "LINKS", "VIEW-SECTORS", "PLAN-INFO"} <= layers
    info = " ".join(e.dxf.text for e in msp.query("TEXT"))
    assert "EPSG:32632" in info


def _symbol(doc, name: str) -> tuple[str, int]:
    """A block's outline: the kind of entity and its vertex count (a circle: 0)."""
    (outline,) = [e for e in doc.blocks[name] if e.dxftype() in ("LWPOLYLINE", "CIRCLE")]
    return outline.dxftype(), len(outline) if outline.dxftype() == "LWPOLYLINE" else 0


@pytest.mark.parametrize("scale", [500, 200])
def test_dxf_speaks_the_maps_symbols_at_the_drawing_scale(tmp_path, scale, default_plan):
    """The drawing's conventions: the maps' symbols (station ▲, flat target ■, sphere ●,
    control ▼); the lettering 2.5 mm on paper at 1:scale; buildings labelled with id and
    height; the header's extents around the drawing; the view sectors' layer off."""
    base = default_plan
    p = replace(base, settings=replace(base.settings, drawing_scale=scale))  # (the DXF's own)
    doc = ezdxf.read(io.StringIO(render(p)["plan.dxf"]))
    msp = doc.modelspace()
    assert _symbol(doc, "STATION") == ("LWPOLYLINE", 3)
    assert _symbol(doc, "TARGET-FLAT") == ("LWPOLYLINE", 4)
    assert _symbol(doc, "TARGET-SPHERE") == ("CIRCLE", 0)
    up = [v[1] for v in doc.blocks["STATION"].query("LWPOLYLINE")[0].get_points("xy")]
    down = [v[1] for v in doc.blocks["CONTROL"].query("LWPOLYLINE")[0].get_points("xy")]
    assert up[0] == max(up) and down[0] == min(down)  # ▲ and ▼
    m_per_mm = scale / 1000
    for ref in msp.query("INSERT"):
        assert ref.dxf.xscale == pytest.approx(m_per_mm)
        shown = [a for a in ref.attribs if not a.is_invisible]
        assert [a.dxf.tag for a in shown] == ["ID"]
        assert shown[0].dxf.height == pytest.approx(2.5 * m_per_mm)  # m (an ATTRIB is in the world)
    labels = {e.dxf.text: e for e in msp.query("TEXT[layer=='BUILDING-LABELS']")}
    for b in p.site.buildings:
        text = f"{b.id} {b.height_m:.1f} m"
        assert text in labels
        assert labels[text].dxf.height == pytest.approx(2.5 * m_per_mm)  # m
    lo, hi = doc.header["$EXTMIN"], doc.header["$EXTMAX"]
    xy = p.stations[["x", "y"]].to_numpy()
    assert lo[0] <= xy[:, 0].min() and hi[0] >= xy[:, 0].max()
    assert lo[1] <= xy[:, 1].min() and hi[1] >= xy[:, 1].max()
    assert hi[0] - lo[0] < 1000  # m: the extents are the drawing's, not the 1e20 default
    assert doc.layers.get("VIEW-SECTORS").is_off()
    assert not doc.layers.get("STATIONS").is_off()


def test_the_dxf_opens_on_the_planned_area_not_the_whole_model(default_plan):
    """A city model's tile holds buildings kilometres from those planned (a 9 × 10 km
    sample opened on dots): they are drawn, but the drawing's extents are the plan's —
    its stations, targets, planned buildings — within a few symbols' margin."""
    import copy

    from planner.site import Building, Site

    p = copy.deepcopy(default_plan)
    far = Building("far-away", shapely.box(0, 0, 10, 10), 9.0, planned=False)
    x0, y0 = p.stations["x"].min() + 5000.0, p.stations["y"].min() + 7000.0  # m
    far = Building(
        "far-away", shapely.affinity.translate(far.footprint, x0, y0), 9.0, planned=False
    )
    p.site = Site([*p.site.buildings, far], crs=p.site.crs, name=p.site.name)
    doc = ezdxf.read(io.StringIO(render(p)["plan.dxf"]))
    assert any("far-away" in e.dxf.text for e in doc.modelspace().query("TEXT"))  # drawn
    lo, hi = doc.header["$EXTMIN"], doc.header["$EXTMAX"]
    xy = p.stations[["x", "y"]].to_numpy()
    assert hi[0] - lo[0] < (np.ptp(xy[:, 0]) + 300.0)  # m: not the 5 km to the far building
    assert hi[1] - lo[1] < (np.ptp(xy[:, 1]) + 300.0)  # m


def test_stakeout_file_lists_stations_and_targets(lonlat_plan):
    out, _ = lonlat_plan
    so = pd.read_csv(out / "stakeout.csv")
    assert list(so.columns) == [
        "point_id",
        "easting",
        "northing",
        "height",
        "code",
        "ground_z",
        "above_ground_m",
        "height_from",
    ]
    stations = pd.read_csv(out / "stations.csv")
    targets = pd.read_csv(out / "targets.csv")
    assert len(so) == len(stations) + len(targets)
    st = so[so["code"] == "STN"].set_index("point_id")
    for r in stations.itertuples():
        assert st.at[r.station_id, "easting"] == pytest.approx(r.x, abs=0.001)
        assert st.at[r.station_id, "northing"] == pytest.approx(r.y, abs=0.001)
    assert set(so.loc[so["code"] != "STN", "code"]) <= {"TGT-SPHERE", "TGT-FLAT", "CTL"}


def test_site_without_crs_has_no_kml_and_says_so(tmp_path):
    csv = wkt_site(tmp_path)
    code, stdout, err = cli(
        "plan", str(csv), *FAST, "--no-registration-error", "--out", str(tmp_path / "p")
    )
    assert code in (0, 1), err
    assert "Coordinates: no CRS given" in stdout
    assert not (tmp_path / "p" / "plan.kml").exists()
    assert (tmp_path / "p" / "plan.dxf").exists()
    # named on the command line: the outputs carry it, and the KML is written
    code, stdout, err = cli(
        "plan",
        str(csv),
        "--crs",
        "EPSG:25832",
        *FAST,
        "--no-registration-error",
        "--out",
        str(tmp_path / "q"),
    )
    assert code in (0, 1), err
    assert "Coordinates: EPSG:25832 (ETRS89 / UTM zone 32N)" in stdout
    assert (tmp_path / "q" / "plan.kml").exists()


@pytest.mark.parametrize(
    ("crs", "message"),
    [
        ("EPSG:4326", "longitude/latitude"),  # projected metres labelled as degrees
        ("EPSG:2193", "not in the area of EPSG:2193"),  # New Zealand's grid for a German site
        ("EPSG:999999", "unknown CRS"),
        ("nonsense", "unknown CRS"),
    ],
)
def test_a_crs_that_contradicts_the_coordinates_is_refused(tmp_path, crs, message):
    csv = wkt_site(tmp_path)
    out = tmp_path / "p"
    code, _, err = cli("plan", str(csv), "--crs", crs, *FAST, "--out", str(out))
    assert code == 2 and message in err, err
    assert "Traceback" not in err and not out.exists()


def test_the_geojson_carries_every_column_of_the_stations_links_and_targets(default_plan):
    """plan.geojson writes each station, link and target with the columns of its table (the
    one column list): a cloud link is told from a target link (kind, overlap, weakest
    direction) and a flat target keeps its wall — in the GeoJSON, and so in the KML and the
    DXF made from it (the target block's FACADE)."""
    from planner.pipeline.inputs.schema import LINK_COLUMNS, TARGET_COLUMNS

    files = render(default_plan)
    feats = json.loads(files["plan.geojson"])["features"]
    links = [f["properties"] for f in feats if f["properties"]["layer"] == "link"]
    targets = [f["properties"] for f in feats if f["properties"]["layer"] == "target"]
    table = pd.read_csv(io.StringIO(files["links.csv"]), keep_default_na=False)
    assert len(links) == len(table) > 0
    for props, row in zip(links, table.to_dict("records"), strict=True):
        assert set(LINK_COLUMNS) <= set(props)
        assert (
            props["kind"] == row["kind"] and props["weakest_direction"] == row["weakest_direction"]
        )
    assert all(set(TARGET_COLUMNS) - {"x", "y", "z"} <= set(t) for t in targets)
    flat = [t for t in targets if t["type"] == "flat"]
    assert flat and all(t["facade_id"] for t in flat)
    doc = ezdxf.read(io.StringIO(files["plan.dxf"]))
    walls = {
        ref.get_attrib_text("FACADE")
        for ref in doc.modelspace().query("INSERT")
        if ref.dxf.name == "TARGET-FLAT"
    }
    assert walls == {t["facade_id"] for t in flat}


@pytest.mark.parametrize(
    ("scanner", "words"), [(None, "6 parameters per scan"), ("leica-p50", "4 parameters per scan")]
)
def test_the_files_say_how_the_registration_was_planned(scanner, words, default_plan):
    """summary.txt and plan.geojson say whether each scan is registered with 4 parameters
    (a levelled scanner) or 6, and what the promise assumes of the registration software."""
    import planner

    p = (
        default_plan
        if scanner is None
        else planner.plan(
            scanner=scanner, settings=planner.PlanSettings(time_limit_s=30, sample_spacing_m=4)
        )
    )
    files = render(p)
    model = json.loads(files["plan.geojson"])["registration_model"]
    from planner.pipeline.inputs.requirements import REGISTRATION_PROCESSING

    assert model.startswith(words) and model.endswith(REGISTRATION_PROCESSING["adjustment"])
    assert f"Registration model: {p.registration_model()}." in files["summary.txt"]
    assert model.startswith(p.registration_model())
