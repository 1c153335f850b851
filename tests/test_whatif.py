"""What-if by hand (planner.pipeline.whatif): stations moved, deleted, added or locked are
judged again as a plan is, from what the plan keeps."""

import numpy as np
import pytest

from planner.errors import InputError
from planner.pipeline.planning import plan
from planner.pipeline.whatif import evaluate_stations, reoptimise


@pytest.fixture(scope="module")
def default_plan():
    return plan()


def _xy(p):
    return p.stations[["x", "y"]].to_numpy()


def test_the_plans_own_stations_give_the_plans_coverage(default_plan):
    p = default_plan
    q = evaluate_stations(p, _xy(p))
    assert len(q.stations) == len(p.stations)
    assert (q.stations["purpose"] == "hand").all()
    np.testing.assert_allclose(_xy(q), _xy(p), atol=1e-6)  # m
    assert (q.coverage["meets"] == p.coverage["meets"]).all()
    for c in ("m_x_mm", "m_y_mm", "m_z_mm"):
        np.testing.assert_allclose(q.coverage[c], p.coverage[c], atol=0.01, equal_nan=True)  # mm
    assert "placed by hand" in q.summary()


def test_deleting_a_station_loses_the_samples_only_it_meets(default_plan):
    p = default_plan
    # the station meeting most samples: without it some samples must go unmet
    k = int(p.stations["samples_met"].idxmax())
    q = evaluate_stations(p, np.delete(_xy(p), k, axis=0))
    assert len(q.stations) == len(p.stations) - 1
    assert 0 < len(q.unmet) < len(p.scanned)
    assert (q.unmet["reason"] != "").all()
    assert q.summary().count("placed by hand") == 2  # station line and message


def test_moving_a_station_changes_its_coverage(default_plan):
    p = default_plan
    xy = _xy(p)
    k = int(p.stations["samples_met"].idxmax())
    moved = xy.copy()
    moved[k] += [4.0, 0.0]
    q = evaluate_stations(p, moved)
    assert q.stations.loc[k, "x"] == pytest.approx(xy[k, 0] + 4.0, abs=1e-6)  # m
    sid = p.stations.loc[k, "station_id"]
    before = p.coverage[p.coverage["station_id"] == sid]
    after = q.coverage.set_index("sample_id").loc[before["sample_id"]]
    # the samples it served are now seen from 4 m further along: their errors change
    assert not np.allclose(after["m_x_mm"].to_numpy(), before["m_x_mm"].to_numpy(), atol=0.001)


def test_a_station_inside_a_building_is_refused_with_where(default_plan):
    centre = default_plan.site.planned[0].footprint.representative_point()
    with pytest.raises(InputError, match=r"inside a building.*move it onto free ground"):
        evaluate_stations(default_plan, [[centre.x, centre.y]])


def test_reoptimise_keeps_the_locked_station_and_covers_the_rest(default_plan):
    p = default_plan
    pin = _xy(p)[0] + [1.3, 0.7]  # off the 2 m grid: kept where the surveyor put it
    q = reoptimise(p, pin[None])
    hand = q.stations[q.stations["purpose"] == "hand"]
    assert len(hand) == 1
    assert hand[["x", "y"]].to_numpy()[0] == pytest.approx(pin, abs=1e-6)  # m
    assert q.meets_all
    assert "locked by hand" in q.summary()


def test_a_plan_without_its_workbench_says_so(default_plan):
    from dataclasses import replace

    with pytest.raises(InputError, match="plan the site again"):
        evaluate_stations(replace(default_plan, workbench=None), _xy(default_plan))
