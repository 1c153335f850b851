"""Setting out that a crew can follow: tape ties from two distinct physical corners (a corner
two buildings share is one corner, named once) whose tapes cross at a good angle, and the
stake-out file's heights — the ground's and the instrument's — real on a sloped 3-D site."""

from __future__ import annotations

import io
import re

import numpy as np
import pandas as pd
import pytest
from sites import E0, N0, rect

from planner.app.booklet import target_places
from planner.pipeline.documents.deliver import stakeout_csv
from planner.pipeline.documents.geojson import geojson
from planner.pipeline.field.setout import (
    GOOD_CROSSING_DEG,
    SAME_CORNER_M,
    Tie,
    _corners,
    corner_ties,
    ties_text,
)
from planner.pipeline.inputs.schema import STAKEOUT_COLUMNS
from planner.site import Building, Site


def _terrace(shift_m: float = 0.0) -> Site:
    """Two terraced houses built against each other: bub052 to the west, bub051 to the
    east (shifted east by ``shift_m``), sharing the corners of their party wall."""
    return Site(
        [
            Building("bub052", rect(0, 0, 12, 10), 9.0),
            Building("bub051", rect(12 + shift_m, 0, 24 + shift_m, 10), 9.0),
        ]
    )


def test_a_corner_two_buildings_share_is_one_corner_named_once():
    xy, names = _corners(_terrace())
    assert len(names) == 6  # 8 outline corners, the party wall's two ends shared
    shared = names.index("bub052 NE / bub051 NW corner")
    assert xy[shared] == pytest.approx([E0 + 12, N0 + 10], abs=1e-9)
    assert "bub052 SE / bub051 SW corner" in names
    assert sum("bub051 NW" in n for n in names) == 1
    # a few centimetres apart as drawn: still one corner, at their mean
    xy, names = _corners(_terrace(0.6 * SAME_CORNER_M))
    shared = names.index("bub052 NE / bub051 NW corner")
    assert xy[shared] == pytest.approx([E0 + 12 + 0.3 * SAME_CORNER_M, N0 + 10], abs=1e-9)
    # half a metre apart: two corners
    assert len(_corners(_terrace(0.5))[1]) == 8

    # a station 7 m north of the shared corner: one tie from it, the other from another
    # physical corner (before: the shared corner twice, 7.07 m at 8° from each name)
    (ties,) = corner_ties(_terrace(), np.array([[E0 + 13.0, N0 + 17.0]]))
    assert [t.corner for t in ties] == ["bub052 NE / bub051 NW corner", "bub051 NE corner"]
    assert ties[0].distance_m == pytest.approx(np.hypot(1.0, 7.0), abs=1e-9)  # m
    assert ties[0].bearing_deg == pytest.approx(np.degrees(np.arctan2(1.0, 7.0)), abs=1e-9)
    assert ties[1].distance_m == pytest.approx(np.hypot(11.0, 7.0), abs=1e-9)  # m, from (24, 10)
    assert np.hypot(ties[0].x - ties[1].x, ties[0].y - ties[1].y) == pytest.approx(12.0)  # m
    text = ties_text(ties)
    assert (
        text
        == "7.07 m at 8° from bub052 NE / bub051 NW corner; 13.04 m at 302° from bub051 NE corner"
    )
    assert text.count("bub051 NW") == 1 and "cross at" not in text


def test_the_two_ties_cross_at_a_good_angle():
    """The two nearest corners in sight are one wall's ends seen end-on (their tapes cross
    at 23°): the ties are the nearest pair crossing between 30° and 150°."""
    site = Site([Building("A", rect(0, 0, 10, 10), 9.0), Building("B", rect(30, 35, 40, 45), 9.0)])
    p = np.array([[E0 + 6.0, N0 + 41.0]])
    (near,) = corner_ties(site, p, n=3)  # the pair and the nearest other
    assert [t.corner for t in near] == ["B NW corner", "B SW corner", "A NE corner"]
    assert near[0].crossing_deg(near[1]) == pytest.approx(23.5, abs=0.1)  # deg: too shallow
    (ties,) = corner_ties(site, p)
    assert [t.corner for t in ties] == ["B NW corner", "A NE corner"]
    assert [t.distance_m for t in ties] == pytest.approx([np.hypot(24, 4), np.hypot(4, 31)])
    lo, hi = GOOD_CROSSING_DEG
    assert lo <= ties[0].crossing_deg(ties[1]) <= hi
    assert ties[0].crossing_deg(ties[1]) == pytest.approx(92.0, abs=0.5)  # deg
    # a point on the line of a long wall: no pair crosses well, the angle is said
    long = Site([Building("L", rect(0, 0, 40, 10), 9.0)])
    (poor,) = corner_ties(long, np.array([[E0 - 20.0, N0 + 10.5]]))
    assert [t.corner for t in poor] == ["L NW corner", "L SW corner"]
    assert poor[0].crossing_deg(poor[1]) == pytest.approx(26.3, abs=0.1)  # deg
    assert ties_text(poor).endswith("(the tapes cross at 26°: check it by the bearings)")


def test_one_corner_in_sight_is_said_once_and_none_is_said():
    one = Tie("bub051 NW / bub052 NE corner", E0, N0, 7.33, 92.0)
    text = ties_text([one])
    assert text.startswith("7.33 m at 92° from bub051 NW / bub052 NE corner, the only building")
    assert text.count("bub051 NW") == 1 and ";" not in text
    assert ties_text([]) == "no building corner in sight: set it out by its coordinates"


def test_the_stakeout_file_of_a_flat_site_has_the_instrument_height(default_plan):
    p = default_plan
    so = pd.read_csv(io.StringIO(stakeout_csv(p))).set_index("point_id")
    assert list(so.reset_index().columns) == STAKEOUT_COLUMNS
    assert not so.isna().any().any()
    st = p.stations.set_index("station_id")
    stn = so.loc[st.index]
    assert (stn["height"] == 0.0).all() and (stn["ground_z"] == 0.0).all()  # flat ground
    assert stn["above_ground_m"].to_numpy() == pytest.approx(st["instrument_height_m"], abs=5e-4)
    assert (stn["above_ground_m"] > 1.0).all()  # m: not 0.000
    tg = p.targets.set_index("target_id")
    assert so.loc[tg.index, "above_ground_m"].to_numpy() == pytest.approx(tg["z"], abs=5e-4)


@pytest.fixture(scope="module")
def sloped_plan():
    """A plan of a synthetic LoD2 town on terrain rising 10 % across its street."""
    from planner.cityio import site_from_cityjson
    from planner.pipeline.engine.planning import plan
    from planner.pipeline.inputs.requirements import PlanSettings
    from planner.synthetic3d import lod2_town

    quick = PlanSettings(
        grid_m=3.0, sample_spacing_m=3.0, sample_height_step_m=3.0, time_limit_s=30, method="greedy"
    )
    return plan(site_from_cityjson(lod2_town(4, seed=1)), settings=quick)


def test_the_stakeout_file_of_a_sloped_site_has_real_heights(sloped_plan):
    p = sloped_plan
    so = pd.read_csv(io.StringIO(stakeout_csv(p))).set_index("point_id")
    assert list(so.reset_index().columns) == STAKEOUT_COLUMNS
    assert not so.isna().any().any()
    st = p.stations.set_index("station_id")
    stn = so.loc[st.index]
    terrain = p.site.terrain.ground_z(st[["x", "y"]].to_numpy(float))
    assert stn["ground_z"].to_numpy() == pytest.approx(terrain, abs=5e-4)  # m
    assert stn["ground_z"].to_numpy() == pytest.approx(st["ground_z"], abs=5e-4)
    assert stn["height"].to_numpy() == pytest.approx(st["ground_z"], abs=5e-4)  # the mark
    assert stn["ground_z"].min() > 400.0 and np.ptp(stn["ground_z"]) > 1.0  # m: a slope
    assert stn["above_ground_m"].to_numpy() == pytest.approx(st["instrument_height_m"], abs=5e-4)
    assert (stn["above_ground_m"] > 1.0).all()
    tg = p.targets.set_index("target_id")
    tgt = so.loc[tg.index]
    under = p.site.terrain.ground_z(tg[["x", "y"]].to_numpy(float))
    assert tgt["height"].to_numpy() == pytest.approx(tg["z"], abs=5e-4)
    assert tgt["ground_z"].to_numpy() == pytest.approx(under, abs=5e-4)
    assert tgt["above_ground_m"].to_numpy() == pytest.approx(tg["z"] - under, abs=1e-3)
    spheres = tg["type"] == "sphere"
    assert spheres.any()
    assert tgt.loc[spheres, "above_ground_m"].to_numpy() == pytest.approx(
        p.settings.target_height_m, abs=1e-3
    )
    # the GeoJSON says the same: a station at its scanner's centre, its ground beside it
    for f in geojson(p)["features"]:
        if f["properties"]["layer"] == "station":
            r = so.loc[f["properties"]["station_id"]]
            assert f["properties"]["ground_z"] == pytest.approx(r["ground_z"], abs=1e-3)
            assert f["geometry"]["coordinates"][2] == pytest.approx(
                r["ground_z"] + r["above_ground_m"], abs=1e-3
            )
    # and the booklet gives a stand's height above the ground, not in the height system
    places = target_places(p, list(tg.index[spheres]))
    highs = [float(re.search(r"stand, (\d+\.\d) m high", w).group(1)) for w in places]
    assert highs == pytest.approx([p.settings.target_height_m] * len(highs), abs=0.051)


def test_heights_from_an_assumed_ground_are_given_to_the_decimetre_and_said():
    """A city model with no relief: the ground is assumed from under its buildings (joined
    across the streets), so the stake-out's heights are given to 0.1 m and say so — not to
    the millimetre from an assumption (two stations 70 m apart both "at 462.874 m")."""
    from planner.cityio import site_from_cityjson
    from planner.pipeline.engine.planning import plan
    from planner.pipeline.inputs.requirements import PlanSettings
    from planner.synthetic3d import lod2_town

    model = lod2_town(2, seed=0)
    model["CityObjects"] = {
        k: o for k, o in model["CityObjects"].items() if o["type"] != "TINRelief"
    }
    site = site_from_cityjson(model)
    assert site.terrain is not None and not site.terrain.measured
    quick = PlanSettings(grid_m=3.0, sample_spacing_m=3.0, sample_height_step_m=3.0)
    so = pd.read_csv(io.StringIO(stakeout_csv(plan(site, settings=quick))))
    assert so["height_from"].str.startswith("assumed: ground of the model's buildings").all()
    assert np.allclose(so["height"], so["height"].round(1), atol=1e-9)  # m: to 0.1 m
    assert np.allclose(so["ground_z"], so["ground_z"].round(1), atol=1e-9)
