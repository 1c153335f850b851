"""Jobs of scattered buildings (:mod:`planner.pipeline.district.groups`): buildings far apart
planned as separate jobs, each with its own network, datum and route, in one run."""

from __future__ import annotations

import json

import numpy as np
import pytest

from planner import plan
from planner.pipeline.district.groups import jobs_budget_s, site_groups
from planner.pipeline.inputs.requirements import PlanSettings
from planner.site import Building, Site
from planner.synthetic import scattered, town_geojson
from tests.sites import E0, N0, rect, run_cli


def _three_groups() -> Site:
    """Two small buildings 12 m apart, one 400 m east, one 400 m north of them."""
    return Site(
        [
            Building("a", rect(E0, N0, E0 + 12, N0 + 8), 6.0),
            Building("b", rect(E0 + 24, N0, E0 + 34, N0 + 8), 6.0),
            Building("c", rect(E0 + 400, N0, E0 + 410, N0 + 8), 6.0),
            Building("d", rect(E0, N0 + 400, E0 + 10, N0 + 8 + 400), 6.0),
        ],
        name="three groups",
    )


def test_buildings_within_the_gap_are_one_group_and_far_ones_their_own():
    site = _three_groups()
    groups = site_groups(site, 50.0)
    assert [(g.key, g.buildings) for g in groups] == [
        ("G1", ("a", "b")),
        ("G2", ("c",)),
        ("G3", ("d",)),
    ]
    assert len(site_groups(site, 500.0)) == 1  # all within reach of one another
    assert len(site_groups(site, 5.0)) == 4  # a and b 12 m apart
    # the synthetic client's 49 buildings fall into the 12 groups it drew
    assert len(site_groups(scattered(49, 12, seed=0), 60.0)) == 12


@pytest.fixture(scope="module")
def jobs_and_one():
    site = _three_groups()
    return plan(site), plan(site, settings=PlanSettings(job_gap_m=0.0))


def test_each_group_is_a_job_with_its_own_network_and_route(jobs_and_one):
    """Three jobs: ids prefixed with the group, every sample met (each job its own datum),
    the route walks within a job and leaves the travel between jobs to the crew. One job
    over the same site (negative control: ``job_gap_m`` 0) cannot tie the groups 400 m
    apart: its far samples are not met, and it walks between them."""
    jobs, one = jobs_and_one
    ids = jobs.stations["station_id"].tolist()
    assert {i.split("-")[0] for i in ids} == {"G1", "G2", "G3"}
    assert jobs.solver.method == "jobs (3 groups)"
    assert any(m.startswith("Jobs: 3 groups of buildings far apart") for m in jobs.messages)
    assert jobs.scanned["meets"].all()
    t = jobs.route.table
    starts = t["station_id"].str.split("-").str[0].ne(t["station_id"].str.split("-").str[0].shift())
    assert (t.loc[starts, "walk_m"] == 0.0).all()  # m: no walk to a job's first station
    assert (t.loc[starts, "walk_note"].iloc[1:] != "").all()
    assert t["walk_m"].max() < 100.0  # m: every walk within a group
    # the jobs' routes run on: their sessions and elapsed time, their targets' ids prefixed
    assert t["session"].is_monotonic_increasing and t["elapsed_min"].is_monotonic_increasing
    named = " ".join(t["targets_to_set"]).split()
    assert named and all(i.split("-")[0] in {"G1", "G2", "G3"} for i in named)
    assert one.scanned["meets"].sum() < jobs.scanned["meets"].sum()
    assert one.route.table["walk_m"].max() > 300.0  # m: the one job walks across town


def test_the_command_says_the_jobs_and_their_time_before_it_plans(tmp_path):
    """``planner plan`` on a site of several groups: the jobs and the time they take are
    said first; the plan's files (the KML and the GeoJSON's route included) are written."""
    path = tmp_path / "site.geojson"
    site = scattered(4, 2, seed=3, spread_m=900.0)
    path.write_text(json.dumps(town_geojson(site)))
    code, out, err = run_cli("plan", str(path), "--out", str(tmp_path / "out"))
    assert code in (0, 1), err
    first = err.splitlines()[0]
    assert first.startswith("4 buildings in 2 groups far apart, planned as 2 jobs")
    assert first.endswith("--time-limit-s to change")
    assert (tmp_path / "out" / "plan.kml").exists()
    route = [
        f
        for f in json.loads((tmp_path / "out" / "plan.geojson").read_text())["features"]
        if f["properties"].get("layer") == "route"
    ]
    assert route and all(f["properties"]["walk_m"] < 200.0 for f in route)  # m
    assert "Jobs: 2 groups" in out


def test_the_time_budget_grows_with_the_jobs():
    """Each job's base and its samples' time: 12 jobs of 11 618 samples about 1.4 min."""
    assert jobs_budget_s([1000] * 12) == pytest.approx(12 * 3.0 + 12000 * 4e-3)  # s
    assert np.diff([jobs_budget_s([n]) for n in (100, 1000, 10000)]).min() > 0
