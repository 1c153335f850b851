"""Passages (gateways) through buildings: sight lines pass under the floors above them, the
sites say where they are in every format, the opening is not a wall, and a closed
perimeter block is one registration network through its gateway — without it, the
courtyard is named and nothing is spent on tying it."""

from __future__ import annotations

import json

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString, box
from sites import E0, N0, rect

from planner.pipeline.engine.planning import plan
from planner.pipeline.geometry.facades import build_facades
from planner.pipeline.geometry.scene import bridge_edges, footprint_edges
from planner.pipeline.geometry.visibility import bridge_interval, clear_height, visible
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.site import Building, Passage, Site
from planner.siteio import read_site
from planner.synthetic import town

#: A block 30 m deep and 20 m high with a gateway 4 m wide, 3.5 m high through it (x).
BLOCK = Building("blk", rect(0, 0, 30, 20), 20.0)
GATE = Passage("gate", rect(13, -1, 17, 21), 3.5)
HI = 1.5  # instrument height, m


def _blocked_3d(site: Site, a, b, z_b: float, steps: int = 4000) -> bool:
    """A sight line from (a, HI) to (b, z_b) tested point by point in 3-D: inside a
    footprint without its passage below the roof, or inside a passage between its clear
    height and the roof."""
    t = (np.arange(steps) + 0.5) / steps
    xy = np.asarray(a) + t[:, None] * (np.asarray(b) - np.asarray(a))
    z = HI + t * (z_b - HI)
    for _, geom, h in site.blockers:
        if (shapely.contains_xy(geom, xy[:, 0], xy[:, 1]) & (z < h)).any():
            return True
    for _, geom, lo, h in site.bridges:
        if (shapely.contains_xy(geom, xy[:, 0], xy[:, 1]) & (z >= lo) & (z < h)).any():
            return True
    return False


def _seen_2_5d(site: Site, a, b, z_b: float, bridges: bool = True) -> bool:
    e, h = footprint_edges(site)
    zc = clear_height(np.array([a]), HI, np.array([b]), e, h)
    lo = up = None
    if bridges:
        be, bottom, top = bridge_edges(site)
        lo, up = bridge_interval(np.array([a]), HI, np.array([b]), be, bottom, top)
    return bool(visible(np.array([z_b]), zc, lo, up)[0])


def test_sight_lines_through_a_gateway_agree_with_a_3d_test():
    """From the street through the gateway into the courtyard and up its far wall: the
    2.5-D test with the floors as a bridge agrees with a point-by-point 3-D test on 400
    random lines; without the bridge (the passage open to the sky) it does not."""
    site = Site([BLOCK], passages=[GATE])
    rng = np.random.default_rng(7)
    agree = disagree_open = 0
    for _ in range(400):
        a = (E0 + rng.uniform(12.0, 18.0), N0 + rng.uniform(-25.0, -2.0))  # the street
        b = (E0 + rng.uniform(10.0, 20.0), N0 + rng.uniform(22.0, 40.0))  # the courtyard
        z_b = rng.uniform(0.0, 25.0)
        truth = not _blocked_3d(site, a, b, z_b)
        agree += _seen_2_5d(site, a, b, z_b) == truth
        disagree_open += _seen_2_5d(site, a, b, z_b, bridges=False) != truth
    assert agree >= 398  # a line grazing an edge may fall either way
    assert disagree_open >= 40  # negative control: the floors above the gateway matter


def test_a_gateway_is_seen_through_low_and_over_the_roof_high():
    site = Site([BLOCK], passages=[GATE])
    street, court = (E0 + 15.0, N0 - 10.0), (E0 + 15.0, N0 + 30.0)
    assert _seen_2_5d(site, street, court, 1.0)  # under the floors
    assert not _seen_2_5d(site, street, court, 10.0)  # through the floors above: blocked
    assert _seen_2_5d(site, street, court, 80.0)  # over the roof: 1.5 + 18.5 × 40 / 10 = 75.5
    beside = (E0 + 5.0, N0 - 10.0), (E0 + 5.0, N0 + 30.0)  # not through the gateway
    assert not _seen_2_5d(site, *beside, 1.0)


def test_the_opening_is_not_a_wall_and_the_wall_above_it_is():
    plain = build_facades(Site([BLOCK]), 1.0, 1.0)
    gated = build_facades(Site([BLOCK], passages=[GATE]), 1.0, 1.0)
    south = np.isclose(gated.xy[:, 1], N0)
    in_gate = south & (gated.xy[:, 0] > E0 + 13) & (gated.xy[:, 0] < E0 + 17)
    assert gated.z[in_gate].min() >= 3.5  # nothing below the clear height in the opening
    gone = len(plain.z) - len(gated.z)
    assert gone == 2 * 4 * 3  # 4 columns × 3 rows (0.5, 1.5, 2.5 m) on each side
    north = np.isclose(gated.xy[:, 1], N0 + 20)
    assert not (north & (gated.z < 3.5) & (np.abs(gated.xy[:, 0] - E0 - 15) < 2)).any()


def _geojson(tmp_path, features, crs="EPSG:25832"):
    path = tmp_path / "site.geojson"
    path.write_text(
        json.dumps(
            {
                "type": "FeatureCollection",
                "crs": {"type": "name", "properties": {"name": crs}},
                "features": features,
            }
        )
    )
    return path


def _feature(geom, **props):
    return {"type": "Feature", "properties": props, "geometry": shapely.geometry.mapping(geom)}


@pytest.mark.parametrize(
    ("props", "width", "clear"),
    [
        ({"role": "passage", "width": 4, "height": 3.2}, 4.0, 3.2),
        ({"role": "gateway"}, 3.0, 3.0),  # the defaults
        ({"tunnel": "building_passage", "highway": "service", "maxheight": "3.8 m"}, 3.0, 3.8),
        ({"covered": "yes", "highway": "footway", "width": "2.5"}, 2.5, 3.0),
    ],
    ids=["role", "defaults", "osm building_passage", "osm covered highway"],
)
def test_passages_are_read_from_a_line_with_its_width_and_clear_height(
    tmp_path, props, width, clear
):
    line = LineString([(E0 + 15, N0 - 3), (E0 + 15, N0 + 23)])
    path = _geojson(
        tmp_path, [_feature(BLOCK.footprint, id="blk", height=20), _feature(line, id="g", **props)]
    )
    site = read_site(path)
    (g,) = site.passages
    assert g.clear_height_m == pytest.approx(clear)  # m
    assert g.geometry.area == pytest.approx(width * 26.0, rel=1e-6)  # m²
    assert [b.id for b in site.buildings] == ["blk"]


def test_a_gis_layer_named_gateways_holds_passages(tmp_path):
    from test_gdalio import write

    path = tmp_path / "site.gpkg"
    write(path, [BLOCK.footprint], {"height": [20.0]}, layer="buildings", crs="EPSG:25832")
    line = LineString([(E0 + 15, N0 - 3), (E0 + 15, N0 + 23)])
    write(path, [line], {"maxheight": ["3.4"]}, layer="gateways", crs="EPSG:25832", append=True)
    site = read_site(path)
    assert len(site.passages) == 1 and site.passages[0].clear_height_m == pytest.approx(3.4)


def test_a_passage_is_checked_with_the_rest(tmp_path):
    from planner.sitecheck import SiteProblems

    nowhere = _feature(box(E0 + 100, N0, E0 + 104, N0 + 5), id="g", role="passage")
    too_high = _feature(GATE.geometry, id="h", role="passage", height=25)
    path = _geojson(tmp_path, [_feature(BLOCK.footprint, id="blk", height=20), nowhere, too_high])
    with pytest.raises(SiteProblems) as caught:
        read_site(path)
    text = str(caught.value)
    assert "passage 'g' does not pass through any building" in text
    assert "passage 'h' is 25 m high, as high as building 'blk'" in text


SETTINGS = PlanSettings(time_limit_s=300, grid_m=3, sample_spacing_m=3, sample_height_step_m=3)
REQ = Requirements(max_xy_mm=6, max_z_mm=8)


@pytest.fixture(scope="module")
def gated_and_closed():
    return {
        g: plan(town(10, seed=1, gateways=g), "leica-4mm-60urad", REQ, SETTINGS)
        for g in ("passage", "closed")
    }


def test_a_perimeter_block_with_a_gateway_is_one_network(gated_and_closed):
    """A closed ring of ten terraced buildings entered through one gateway: every station
    tied, every sample some station meets by the scanner met with the registration."""
    p = gated_and_closed["passage"]
    assert p.network is not None and p.network.tied.all()
    cov = p.scanned
    assert cov["meets"].mean() >= 0.98
    gate = p.site.passages[0].geometry.buffer(3.0)
    # the registration goes through the gateway: targets stand in it or just beside it
    assert shapely.contains_xy(gate, p.targets["x"], p.targets["y"]).any()


def test_without_its_gateway_the_courtyard_is_named_and_nothing_is_spent_on_it(
    gated_and_closed,
):
    gated, closed = gated_and_closed["passage"], gated_and_closed["closed"]
    assert not closed.network.tied.all()
    named = [m for m in closed.messages if "The courtyard enclosed by b000-" in m]
    assert len(named) == 1 and "mark its gateway" in named[0]
    inside = closed.unmet["reason"].str.contains("stands in the courtyard enclosed by")
    assert inside.sum() >= 150
    assert closed.scanned["meets"].sum() < gated.scanned["meets"].sum() - 150
    # no station in the courtyard was added for the registration error
    from planner.pipeline.geometry.candidates import GroundRegions

    regions = GroundRegions(closed.site)
    where = regions.label(closed.stations[["x", "y"]].to_numpy())
    court = [regions.enclosed(int(r)) for r in where]
    assert any(court)
    assert not (np.array(court) & (closed.stations["purpose"] == "registration")).any()
    # the covering stations in the untied courtyard still say they cover: they link nothing
    # (they were relabelled "link", and the summary counted them "to link the network")
    in_court = np.array(court)
    assert (closed.stations["purpose"][in_court] == "cover").all()
