"""3-D city models read (planner/cityio.py) and planned: the real samples shipped in
tests/data/citymodels (CityGML 2.0 and 3.0, a 3DBAG CityJSON Sequence), the synthetic
LoD2 town (planner/synthetic3d.py), the reader's refusals, and the facades of real walls."""

from __future__ import annotations

import collections
import copy
import json
from pathlib import Path

import numpy as np
import pytest
import shapely

from planner.cityio import read_city_model, site_from_cityjson
from planner.errors import InputError
from planner.pipeline.geometry.facades import build_facades
from planner.synthetic3d import lod2_town, write_model

DATA = Path(__file__).parent / "data" / "citymodels"
MUNICH = DATA / "munich_tum_entrance_lod2.citygml3.gml"
DELFT = DATA / "delft_3dbag.city.jsonl"
YOKOSUKA = DATA / "yokosuka_plateau_lod2.gml"


def _kinds(site):
    return collections.Counter(s.kind for b in site.buildings for s in b.surfaces)


def test_citygml3_munich_reads_its_walls_heights_and_compound_crs():
    site = read_city_model(MUNICH)
    (b,) = site.buildings
    assert b.id == "DEBY_LOD2_4959457"
    assert _kinds(site) == {"wall": 14, "roof": 2, "ground": 1}
    assert site.crs == "EPSG:25832"
    assert site.height_datum == "DHHN2016 height (EPSG:7837)"
    # the model's own attributes: HoeheGrund 515.042, HoeheDach 534.450
    assert b.base_z == pytest.approx(515.042, abs=0.01)  # m
    assert b.base_z + b.height_m == pytest.approx(534.45, abs=0.01)  # m
    assert b.footprint.area == pytest.approx(1229.6, abs=1.0)  # m²


def test_cityjson_sequence_3dbag_takes_each_buildings_finest_lod_from_its_part():
    site = read_city_model(DELFT)
    assert [b.id for b in site.buildings] == [
        "NL.IMBAG.Pand.0503100000012869",
        "NL.IMBAG.Pand.0503100000016459",
        "NL.IMBAG.Pand.0503100000005156",
    ]
    assert {s.lod for b in site.buildings for s in b.surfaces} == {"2.2"}
    # the building's own LoD 0 outline is not a surface of its LoD 2.2 model
    assert all(s.part.endswith("-0") for b in site.buildings for s in b.surfaces)
    assert (site.crs, site.height_datum) == ("EPSG:28992", "NAP height (EPSG:5709)")
    coarse = read_city_model(DELFT, lod="1.2")
    assert {s.lod for b in coarse.buildings for s in b.surfaces} == {"1.2"}
    assert sum(_kinds(coarse).values()) < sum(_kinds(site).values())
    missing = read_city_model(DELFT, lod="3")
    assert any("no LoD 3" in w for w in missing.warnings)


def test_citygml2_plateau_projects_latitude_longitude_and_keeps_building_parts():
    site = read_city_model(YOKOSUKA)
    assert site.crs == "EPSG:32654"  # UTM 54N, projected from JGD2011 latitude/longitude
    assert site.height_datum == "JGD2011 (vertical) height (EPSG:6695)"
    museum = next(b for b in site.buildings if b.id == "bldg_16418b2d-dc75-4731-ae04-90bbef1d66fe")
    assert len({s.part for s in museum.surfaces}) == 2  # its two BuildingParts
    # the museum is about 90 m × 60 m on the ground (a sanity check of the projection)
    x0, y0, x1, y1 = museum.footprint.bounds
    assert 50 < x1 - x0 < 150 and 30 < y1 - y0 < 150
    assert any("projected" in w for w in site.warnings)


def test_model_facades_follow_the_walls_real_outline():
    """The Munich building's walls: every sample lies on a wall polygon of the model (within
    a millimetre of its plane), and a wall's samples stay inside its outline."""
    site = read_city_model(MUNICH)
    fac = build_facades(site, 2.0, 2.0)
    walls = [s for s in site.buildings[0].surfaces if s.kind == "wall"]
    pts = np.column_stack([fac.xy, fac.z])
    planes = np.array([[*s.normal, -s.normal @ s.rings[0][0]] for s in walls])
    dist = np.abs(pts @ planes[:, :3].T + planes[:, 3])
    assert dist.min(axis=1).max() < 1e-3  # m
    assert len(fac.z) > 500
    for f in range(fac.n_facades):
        mine = fac.facade == f
        u = fac.along_m(np.flatnonzero(mine))
        h = fac.z[mine] - fac.base_z[f]
        assert shapely.contains_xy(fac.outline[f].buffer(1e-6), u, h).all()


def _gable_model() -> dict:
    return lod2_town(1, seed=0, trees=0)  # one gable-roofed building


def test_a_gable_walls_samples_stop_at_its_roof_line():
    site = site_from_cityjson(_gable_model())
    fac = build_facades(site, 1.0, 1.0)
    (b,) = site.buildings
    eave = min(s.z_range[1] for s in b.surfaces if s.kind == "wall")
    above = fac.z > eave + 0.01
    walls_above = np.unique(fac.facade[above])
    # above the eaves: the two gables (from the ground up) and the dormers (above the roof)
    gables = [f for f in walls_above if fac.z0[f] < eave]
    assert len(gables) == 2
    assert all(fac.z0[f] > eave for f in walls_above if f not in gables)
    # under the ridge line: each sample above the eaves is within its wall's outline
    for f in walls_above:
        i = np.flatnonzero(fac.facade == f)
        u, h = fac.along_m(i), fac.z[i] - fac.base_z[f]
        assert shapely.contains_xy(fac.outline[f], u, h).all()


def test_sloping_mansard_walls_and_party_walls_between_parts():
    """The town's mansard has sloping walls (their normals lean up) and its lower wing's
    wall against the main body is a party wall, not demanded."""
    site = site_from_cityjson(lod2_town(3, seed=0, trees=0))
    fac = build_facades(site, 2.0, 2.0)
    mansard = fac.building_id == "B03"
    tilted = mansard & fac.leaning
    assert tilted.sum() == 4  # the four sloping walls
    assert fac.normal_z[tilted] == pytest.approx(np.cos(np.radians(72.0)), abs=1e-3)
    wing = {s.part for b in site.buildings for s in b.surfaces if s.part.endswith("-wing")}
    assert wing == {"B03-wing"}
    party = fac.party_wall & (fac.building_id[fac.facade] == "B03")
    assert party.sum() >= 10
    # the party samples are on the two walls where the wing meets the body: facing ±x
    nx = np.abs(fac.normal[fac.facade[party], 0])
    assert (nx > 0.99).all()


def test_cityjson_written_and_read_again_gives_the_same_site(tmp_path):
    model = lod2_town(3, seed=4)
    path = write_model(model, tmp_path / "town.city.json")
    a, b = site_from_cityjson(model), read_city_model(path)
    assert [x.id for x in a.buildings] == [x.id for x in b.buildings]
    assert [x.height_m for x in a.buildings] == pytest.approx([x.height_m for x in b.buildings])
    assert a.terrain.source == "the model's relief (TINRelief)"
    # the relief rises 10 % across the street: the ground 20 m apart differs by up to 2 m
    g = a.terrain.ground_z(np.array([[690010.0, 5335990.0], [690010.0, 5336010.0]]))
    assert abs(g[1] - g[0]) == pytest.approx(20 * 0.10 * np.sin(np.radians(60)), abs=0.02)  # m


@pytest.mark.parametrize(
    "mutate, words",
    [
        (lambda m: m.update(version="0.9"), "version '0.9'"),
        (
            lambda m: m["CityObjects"]["B01"]["geometry"][0]["boundaries"][0][0].append(10**9),
            "vertex that does not exist",
        ),
        (
            lambda m: m["CityObjects"]["B01"]["geometry"][0].update(type="Sphere"),
            "unknown geometry type 'Sphere'",
        ),
        (lambda m: m["CityObjects"]["B01"].pop("type"), "city object 'B01' has no 'type'"),
        (
            lambda m: m.update(
                CityObjects={k: v for k, v in m["CityObjects"].items() if k == "terrain"}
            ),
            "holds no building to plan",
        ),
        (
            lambda m: m["CityObjects"]["B01"]["geometry"][0]["semantics"]["values"].__setitem__(
                0, 99
            ),
            "malformed",
        ),
    ],
)
def test_a_malformed_cityjson_is_refused_naming_the_object(mutate, words):
    model = copy.deepcopy(_gable_model())
    mutate(model)
    with pytest.raises(InputError, match=words):
        site_from_cityjson(json.loads(json.dumps(model)), "bad.city.json")


@pytest.mark.parametrize(
    "text, words",
    [
        (b"<CityModel><unclosed>", "not well-formed XML"),
        (b"<?xml version='1.0'?><FeatureCollection/>", "root is a CityModel"),
        (b"hello", "neither CityJSON nor CityGML"),
        (b"", "is empty"),
    ],
)
def test_a_malformed_citygml_is_refused(tmp_path, text, words):
    p = tmp_path / "bad.gml"
    p.write_bytes(text)
    with pytest.raises(InputError, match=words):
        read_city_model(p)


def test_the_buildings_to_plan_are_picked_by_id():
    model = lod2_town(2, seed=0, trees=0)
    site = site_from_cityjson(model, buildings=["B02"])
    assert [b.id for b in site.planned] == ["B02"]
    with pytest.raises(InputError, match="no building with id 'B99'"):
        site_from_cityjson(model, buildings=["B99"])


def test_roofs_are_facades_only_on_request():
    """Walls only by default; with ``roofs`` the pitched roofs join as sloping facades
    (their normals up), sampled on their outlines; windows never (the rule written once)."""
    from planner.citymodel import demanded_kinds

    site = site_from_cityjson(_gable_model())
    walls = build_facades(site, 2.0, 2.0)
    both = build_facades(site, 2.0, 2.0, roofs=True)
    assert both.n_facades > walls.n_facades
    roofs = np.flatnonzero(both.normal_z > 0.5)
    assert len(roofs) >= 2 and not (walls.normal_z > 0.5).any()
    # the main roof's two slopes, each sampled over its outline
    assert all((both.facade == f).sum() >= 3 for f in roofs[:2])
    assert "window" not in demanded_kinds(True) and "roof" not in demanded_kinds()


@pytest.mark.parametrize("which", ["every ring", "one wall"])
def test_rings_written_the_wrong_way_round_are_turned_out(which):
    """Real files carry rings written clockwise seen from outside, for a whole building or
    a polygon here and there: the facades face out all the same."""
    model = _gable_model()
    good = build_facades(site_from_cityjson(copy.deepcopy(model)), 2.0, 2.0)
    geometry = model["CityObjects"]["B01"]["geometry"][0]
    if which == "every ring":
        geometry["boundaries"] = [[r[::-1] for r in surf] for surf in geometry["boundaries"]]
    else:
        kinds = geometry["semantics"]["surfaces"]
        wall = next(
            k
            for k, v in enumerate(geometry["semantics"]["values"])
            if v is not None and kinds[v]["type"] == "WallSurface"
        )
        geometry["boundaries"][wall] = [r[::-1] for r in geometry["boundaries"][wall]]
    turned = build_facades(site_from_cityjson(model), 2.0, 2.0)
    assert turned.n_facades == good.n_facades and len(turned.z) == len(good.z)
    assert turned.normal == pytest.approx(good.normal, abs=1e-9)
