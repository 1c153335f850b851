"""Plans on the real building in 3-D: from a city model (synthetic LoD2 town, the shipped
real samples), on a terrain model, and a plan from footprints audited against the model
(planner/pipeline/geometry/audit.py) — the planner saying what a footprint plan gets wrong."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import shapely
from sites import assert_spaced

from planner.app.cli import main
from planner.cityio import read_city_model, site_from_cityjson
from planner.errors import InputError
from planner.pipeline.engine.planning import plan
from planner.pipeline.evaluation.evaluate import Context, facade_pairs
from planner.pipeline.geometry.audit import audit_plan, audit_summary
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.pipeline.inputs.resolved import reach_m
from planner.scanner import load_scanner
from planner.site import Building, Site, with_terrain
from planner.siteio import site_from_geojson
from planner.synthetic3d import footprints_geojson, lod2_town, write_model

DATA = Path(__file__).parent / "data" / "citymodels"
#: Coarse and quick: these tests are about the geometry, not the optimiser.
QUICK = PlanSettings(
    grid_m=3.0, sample_spacing_m=3.0, sample_height_step_m=3.0, time_limit_s=30, method="greedy"
)


@pytest.fixture(scope="module")
def town():
    model = lod2_town(4, seed=1)
    return model, site_from_cityjson(model)


@pytest.fixture(scope="module")
def model_plan(town):
    return plan(town[1], settings=QUICK)


def test_a_plan_from_the_model_promises_only_walls_it_sees(town, model_plan):
    p = model_plan
    table = audit_plan(p, town[1])
    assert len(table) == int(p.coverage["meets"].sum()) > 150
    assert (table["status"] == "seen").all()
    assert p.coverage["meets"].mean() > 0.9
    assert "Heights: DHHN2016 height (EPSG:7837)" in p.summary()
    assert "sight lines cast against 4 building(s) as their 3-D model" in p.summary()


def test_a_footprint_plan_audited_against_the_model_says_what_it_gets_wrong(town):
    model, site = town
    foot = site_from_geojson(footprints_geojson(model))
    p = plan(foot, settings=QUICK)
    summary = audit_summary(audit_plan(p, site)).set_index("building_id")
    whole = summary.loc["all"]
    assert whole["marked_met"] == int(p.coverage["meets"].sum())
    # walls promised above the eaves of pitched roofs and beside set-back storeys …
    assert whole["no wall_pct"] > 20
    # … and walls the real roofs, wings and balconies hide
    assert whole["hidden"] >= 5
    assert whole["seen"] + whole["hidden"] + whole["no wall"] == whole["marked_met"]


def test_stations_and_targets_stand_on_the_terrain(town, model_plan):
    site, p = town[1], model_plan
    xy = p.stations[["x", "y"]].to_numpy(float)
    assert p.stations["ground_z"].to_numpy() == pytest.approx(site.terrain.ground_z(xy), abs=1e-6)
    # the town's relief: 10 % across the street, about 500 m high
    assert np.ptp(p.stations["ground_z"]) > 1.0
    spheres = p.targets[p.targets["type"] == "sphere"]
    ground = site.terrain.ground_z(spheres[["x", "y"]].to_numpy(float))
    assert spheres["z"].to_numpy() == pytest.approx(ground + p.settings.target_height_m, abs=1e-3)


def test_a_sloping_walls_incidence_is_taken_in_3d(town):
    """A scanner level with the foot of a mansard's sloping storey, straight in front: the
    beam meets the wall at the wall's lean (18° from vertical), not square."""
    site = town[1]
    st = PlanSettings(sample_spacing_m=2.0, sample_height_step_m=2.0)
    sc = load_scanner(None or "leica-4mm-60urad")
    from planner.pipeline.geometry.facades import build_facades

    fac = build_facades(site, 2.0, 2.0)
    ctx = Context.build(site, fac, sc, Requirements(), st, reach_m(sc, Requirements(), st))
    f = int(np.flatnonzero(fac.leaning)[0])
    smp = ctx.samples_of[f][:1]
    n3 = fac.normal3[f]
    point = np.append(fac.xy[smp[0]], fac.z[smp[0]])
    # a station 20 m out along the horizontal normal, its centre at the point's height
    station = point[:2] + 20.0 * fac.normal[f]
    ground = site.terrain.ground_z(station[None, :])[0]
    m = facade_pairs(ctx, f, station[None, :], smp)
    beam = np.append(station, ground + st.instrument_height_m) - point
    expect = beam @ n3 / np.linalg.norm(beam)
    assert m.cos_incidence[0, 0] == pytest.approx(expect, abs=1e-9)
    # a vertical-wall formula would say cos γ · cos ν instead
    assert (
        abs(
            m.cos_incidence[0, 0]
            - m.cos_gamma[0, 0] * m.distance_m[0, 0] / m.slope_distance_m[0, 0]
        )
        > 0.05
    )


def _write_dtm(path: Path, slope: float, crs: str = "EPSG:25832") -> None:
    import rasterio
    from rasterio.transform import from_origin

    x0, y0, cell = 689_900.0, 5_336_100.0, 1.0
    cols, rows = 300, 300
    xs = x0 + (np.arange(cols) + 0.5) * cell
    z = 400.0 + slope * (xs - x0)
    grid = np.tile(z, (rows, 1)).astype("float32")
    with rasterio.open(
        path,
        "w",
        driver="GTiff",
        height=rows,
        width=cols,
        count=1,
        dtype="float32",
        crs=crs,
        transform=from_origin(x0, y0, cell, cell),
        nodata=-9999.0,
    ) as dst:
        dst.write(grid, 1)


def _box_site() -> Site:
    b = Building("B", shapely.box(690_000.0, 5_335_950.0, 690_020.0, 5_335_962.0), 9.0)
    return Site([b], crs="EPSG:25832")


def test_a_terrain_model_carries_stations_and_buries_the_uphill_walls_foot(tmp_path):
    dtm = tmp_path / "dtm.tif"
    _write_dtm(dtm, slope=0.10)
    site = with_terrain(_box_site(), str(dtm))
    b = site.buildings[0]
    # the building stands on its lowest ground: x = 690 000 m, 10 m into a 10 % slope
    assert b.base_z == pytest.approx(400.0 + 0.10 * 100.0, abs=0.06)  # m
    p = plan(site, settings=QUICK)
    xy = p.stations[["x", "y"]].to_numpy(float)
    assert p.stations["ground_z"].to_numpy() == pytest.approx(
        400.0 + 0.10 * (xy[:, 0] - 689_900.0), abs=0.06
    )
    # the east wall's foot is 2 m below the ground in front of it: no samples there
    cov, fac = p.coverage, p.facades.set_index("facade_id")
    east = fac.index[(fac["x0"] > 690_019) & (fac["x1"] > 690_019)][0]
    west = fac.index[(fac["x0"] < 690_001) & (fac["x1"] < 690_001)][0]
    low = lambda fid: cov.loc[cov["facade_id"] == fid, "z"].min() - b.base_z  # noqa: E731
    assert low(west) == pytest.approx(1.5, abs=0.01)  # the first row, 1.5 m up
    assert low(east) > 2.0
    assert "Heights: the heights of the terrain model dtm.tif" in p.summary()


def test_a_terrain_model_in_another_crs_or_not_a_geotiff_is_refused(tmp_path):
    dtm = tmp_path / "dtm.tif"
    _write_dtm(dtm, slope=0.1, crs="EPSG:32632")
    with pytest.raises(InputError, match="reproject the terrain model"):
        with_terrain(_box_site(), str(dtm))
    fake = tmp_path / "fake.tif"
    fake.write_text("<VRTDataset/>")
    with pytest.raises(InputError, match="cannot read it as a GeoTIFF"):
        with_terrain(_box_site(), str(fake))
    elsewhere = Site(
        [Building("far", shapely.box(700_000.0, 5_336_000.0, 700_010.0, 5_336_010.0), 9.0)]
    )
    _write_dtm(dtm, slope=0.1)
    with pytest.raises(InputError, match="does not cover the site"):
        with_terrain(elsewhere, str(dtm))


def test_the_plan_and_audit_commands_on_a_city_model(tmp_path, capsys):
    model = lod2_town(1, seed=2)
    path = write_model(model, tmp_path / "town.city.json")
    foot = tmp_path / "town.geojson"
    foot.write_text(json.dumps(footprints_geojson(model)))
    quick = [
        "--grid-m",
        "3",
        "--sample-spacing-m",
        "3",
        "--sample-height-step-m",
        "3",
        "--method",
        "greedy",
        "-q",
    ]
    assert main(["plan", str(path), *quick, "--out", str(tmp_path / "model")]) in (0, 1)
    assert "Heights: DHHN2016 height" in (tmp_path / "model" / "summary.txt").read_text()
    stations = pd.read_csv(tmp_path / "model" / "stations.csv")
    assert stations["ground_z"].between(480, 520).all()
    assert "WALLS-3D" in (tmp_path / "model" / "plan.dxf").read_text()
    assert main(["plan", str(foot), *quick, "--out", str(tmp_path / "foot")]) in (0, 1)
    capsys.readouterr()
    assert main(["audit", str(path), "--plan", str(tmp_path / "foot")]) == 0
    out = capsys.readouterr().out
    assert "no wall" in out and "all" in out
    table = pd.read_csv(tmp_path / "foot" / "audit.csv")
    assert set(table["status"]) <= {"seen", "hidden", "no wall"}
    assert (table["status"] == "no wall").mean() > 0.2
    # --lod on footprints, --terrain on the default site: said, exit 2
    assert main(["plan", str(foot), "--lod", "2", "--out", str(tmp_path / "x")]) == 2
    assert "level of detail" in capsys.readouterr().err
    assert main(["plan", "--terrain", "dtm.tif", "--out", str(tmp_path / "y")]) == 2


@pytest.mark.parametrize(
    "name, buildings, spacing_m",
    [
        ("delft_3dbag.city.jsonl", ["NL.IMBAG.Pand.0503100000005156"], 3.0),  # not the sheds
        ("munich_tum_entrance_lod2.citygml3.gml", None, 5.0),
    ],
)
def test_a_real_model_planned_end_to_end_promises_only_walls_it_sees(name, buildings, spacing_m):
    """A real model planned with a scanner that levels itself (the P50): most of its
    samples met, and every one marked met is on a wall of the model that its station
    sees."""
    site = read_city_model(DATA / name, buildings=buildings)
    p = plan(
        site, "leica-p50", settings=replace(QUICK, sample_spacing_m=4.0, sample_height_step_m=4.0)
    )
    table = audit_plan(p, site)
    assert len(table) > 0.8 * len(p.scanned) > 20
    assert (table["status"] == "seen").all()


def test_the_files_carry_the_walls_and_points_in_3d(town, model_plan):
    """plan.geojson: each wall of the model as a 3-D polygon on the model's wall, stations
    at their scanner centres; plan.dxf: the walls as 3-D polylines, the stations at their
    heights; plan.kml: heights above the ground."""
    import io
    import xml.etree.ElementTree as ET

    import ezdxf

    from planner.pipeline.documents.export import render

    p = model_plan
    files = render(p)
    feats = json.loads(files["plan.geojson"])["features"]
    walls = [f for f in feats if f["properties"]["layer"] == "wall"]
    assert len(walls) == len(p.facades)
    surfaces = [s for b in town[1].buildings for s in b.surfaces if s.kind == "wall"]
    planes = np.array([[*s.normal, -s.normal @ s.rings[0][0]] for s in surfaces])
    for w in walls[:10]:
        ring = np.asarray(w["geometry"]["coordinates"][0])
        assert ring.shape[1] == 3
        dist = np.abs(ring @ planes[:, :3].T + planes[:, 3]).min(axis=1)
        assert dist.max() < 0.06  # m: on a wall of the model (planes merged within 5 cm)
    st = [f for f in feats if f["properties"]["layer"] == "station"]
    for f in st:
        z = f["geometry"]["coordinates"][2]
        assert z == pytest.approx(f["properties"]["ground_z"] + 1.5, abs=1e-3)  # m
    doc = ezdxf.read(io.StringIO(files["plan.dxf"]))
    msp = doc.modelspace()
    assert len(msp.query('POLYLINE[layer=="WALLS-3D"]')) == len(p.facades)
    inserts = msp.query('INSERT[name=="STATION"]')
    assert sorted(round(i.dxf.insert.z, 3) for i in inserts) == sorted(
        round(f["geometry"]["coordinates"][2], 3) for f in st
    )
    kml = ET.fromstring(files["plan.kml"])
    ns = {"k": "http://www.opengis.net/kml/2.2"}
    folders = kml.iterfind(".//k:Folder", ns)
    stations = next(f for f in folders if f.find("k:name", ns).text == "station")
    heights = [float(c.text.split(",")[2]) for c in stations.iterfind(".//k:coordinates", ns)]
    assert heights == pytest.approx([1.5] * len(st), abs=1e-3)  # m above the ground


@pytest.mark.parametrize("suffix", [".obj", ".glb"])
def test_a_plain_mesh_gives_the_footprints_their_3d_shape(tmp_path, suffix):
    """The buildings of a model written as a plain mesh in local coordinates (OBJ z-up,
    glTF y-up, as an IFC export comes), given to the same town's footprints with the
    offset: the buildings take their shape, and the plan promises only walls the model
    shows."""
    import trimesh

    from planner.cityio import footprints_of, with_mesh

    model = site_from_cityjson(lod2_town(2, seed=1, slope=0.0, trees=0))
    tri = np.concatenate([s.triangles for b in model.buildings for s in b.surfaces])
    offset = np.array([690_000.0, 5_336_000.0, 500.0])
    v = (tri - offset).reshape(-1, 3)
    if suffix == ".glb":
        v = np.column_stack([v[:, 0], v[:, 2], -v[:, 1]])  # glTF: y up
    path = tmp_path / f"town{suffix}"
    trimesh.Trimesh(v, np.arange(len(v)).reshape(-1, 3), process=False).export(path)
    site = with_mesh(site_from_geojson(footprints_of(model)), path, offset=tuple(offset))
    for b, m in zip(site.buildings, model.buildings, strict=True):
        assert b.base_z == pytest.approx(m.base_z, abs=1e-3)  # m
        assert b.height_m == pytest.approx(m.height_m, abs=1e-3)  # m
    p = plan(site, settings=QUICK)
    table = audit_plan(p, model)
    assert len(table) > 0.9 * len(p.scanned)
    assert (table["status"] == "seen").all()
    with pytest.raises(InputError, match="none of its triangles is near a building"):
        with_mesh(site_from_geojson(footprints_of(model)), path)  # the offset forgotten


def test_ground_patches_are_seen_on_a_terrain(town):
    """Cloud-to-cloud registration counts the ground a scan holds: on a terrain the ground
    cells round a station are seen (the lines end just above the terrain's triangles)."""
    from planner.pipeline.geometry.facades import build_facades
    from planner.pipeline.network.clouds import SurfaceCache

    site = town[1]
    st = PlanSettings()
    sc = load_scanner("leica-4mm-60urad")
    ctx = Context.build(site, build_facades(site), sc, Requirements(), st, 60.0)
    cache = SurfaceCache(ctx)
    station = np.array([[690_030.0, 5_336_000.0]])  # in the street
    cache._compute(np.array([0]), station)
    ids = cache.columns[0][0]
    ground = ids[ids >= len(ctx.facades.z)]
    assert len(ground) > 100  # of the about 490 cells within 25 m, outside the buildings


def test_a_plan_of_another_site_is_not_audited_as_all_wallless(town, default_plan):
    from planner.pipeline.geometry.audit import audit

    p = default_plan
    with pytest.raises(InputError, match="not on the model's buildings"):
        audit(town[1], p.coverage, p.facades, p.stations)


def test_a_district_block_of_a_model_keeps_its_terrain_and_heights(town):
    """District mode plans a model block by block: each block's site (and a seam's context)
    stands on the model's terrain, in its heights (before, a block stood on flat ground at
    0 m under buildings 500 m up, and saw nothing)."""
    from planner.pipeline.district.blocks import Block, block_site
    from planner.pipeline.network.seams import context_of

    site = town[1]
    b = site.buildings[0]
    block = block_site(site, Block("K01", (b.id,), b.footprint), 30.0)
    assert block.terrain is site.terrain and block.height_datum == site.height_datum
    assert [x.id for x in block.planned] == [b.id]
    sc = load_scanner("leica-4mm-60urad")
    ctx = context_of(site, sc, Requirements(), PlanSettings(), 60.0)(b.footprint.buffer(5))
    xy = np.array([[690_030.0, 5_336_000.0]])
    assert ctx.station_z(xy)[0] == pytest.approx(site.terrain.ground_z(xy)[0] + 1.5)


def test_the_model_plans_stations_keep_the_crews_spacing(model_plan):
    assert_spaced(model_plan)
