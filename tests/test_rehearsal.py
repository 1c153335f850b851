"""planner.pipeline.rehearsal, .pointclouds, .helios and .asscanned: the survey rehearsed
as point clouds, and re-planned from what was scanned."""

from __future__ import annotations

import laspy
import numpy as np
import pandas as pd
import pytest
import scipy.sparse as sp
from scipy.optimize import Bounds, LinearConstraint, milp
from sites import run_cli as run

from planner.errors import InputError
from planner.pipeline.asscanned import compare_links, read_link_report, replan
from planner.pipeline.helios import check_survey, helios_files, read_survey
from planner.pipeline.planning import cover_demand, plan
from planner.pipeline.pointclouds import (
    e57_bytes,
    laz_bytes,
    legend_csv,
    read_e57_scans,
    read_poses,
)
from planner.pipeline.rehearsal import POINT_KINDS, estimate, rehearse
from planner.pipeline.requirements import PlanSettings
from planner.pipeline.scene import Scene

BEAMS = 20_000  # a coarse grid: every check here holds at any density
RHO = 206_264.806


@pytest.fixture(scope="module")
def default_plan():
    return plan()


@pytest.fixture(scope="module")
def rehearsal(default_plan):
    return rehearse(default_plan, beams_per_station=BEAMS, seed=3)


def test_every_station_is_scanned_with_walls_ground_and_targets(default_plan, rehearsal):
    assert [s.station_id for s in rehearsal.scans] == [f"S{k:02d}" for k in range(1, 11)]
    kinds = np.concatenate([s.kind for s in rehearsal.scans])
    seen = {POINT_KINDS[k] for k in np.unique(kinds)}
    assert {"wall", "terrain", "sphere"} <= seen
    for s in rehearsal.scans:
        d = np.linalg.norm(s.local_xyz, axis=1)
        sc = default_plan.scanner
        assert d.min() >= sc.min_range_m - 0.05 and d.max() <= sc.max_range_m + 0.05  # m
        # the station stands where the plan puts it, the instrument height above the ground
        row = default_plan.stations.set_index("station_id").loc[s.station_id]
        assert s.position == pytest.approx([row.x, row.y, 1.5], abs=1e-9)  # m
    assert rehearsal.notes and "Thinned" in rehearsal.notes[0]


def test_the_noise_is_the_predicted_rms_and_a_noise_free_scan_fails_the_check(default_plan):
    """Same seed, same beams: the noisy points against the exact ones. The mean square of
    their 3-D differences is the mean of the predicted rms_mm² (±10 %); without noise it is
    zero — the check can fail."""

    def ratio(noise: bool) -> float:
        exact = rehearse(default_plan, beams_per_station=BEAMS, seed=5, noise=False)
        other = rehearse(default_plan, beams_per_station=BEAMS, seed=5, noise=noise)
        err, pred = [], []
        for a, b in zip(exact.scans, other.scans, strict=True):
            walls = a.kind == POINT_KINDS.index("wall")
            err.append(np.linalg.norm(b.local_xyz[walls] - a.local_xyz[walls], axis=1) * 1e3)
            pred.append(b.rms_mm[walls].astype(float))
        e, p = np.concatenate(err), np.concatenate(pred)
        return float(np.sqrt(np.mean(e**2) / np.mean(p**2)))

    assert ratio(True) == pytest.approx(1.0, abs=0.1)
    assert ratio(False) < 0.01  # negative control


def test_e57_round_trip_keeps_poses_and_point_counts(rehearsal, tmp_path):
    path = tmp_path / "scans.e57"
    path.write_bytes(e57_bytes(rehearsal))
    back = read_e57_scans(path)
    assert [b["name"] for b in back] == [s.station_id for s in rehearsal.scans]
    for b, s in zip(back, rehearsal.scans, strict=True):
        assert np.abs(b["translation"] - s.position).max() < 1e-4  # m: 0.1 mm
        turn = b["rotation"].T @ s.rotation  # the residual rotation
        angle = np.arccos(np.clip((np.trace(turn) - 1) / 2, -1, 1)) * RHO
        assert angle < 1.0  # arc-second
        assert len(b["xyz"]) == s.n_points
        # single precision about the scanner: a few micrometres at 100 m
        assert np.abs(b["xyz"] - s.local_xyz).max() < 2e-5  # m
    poses = read_poses(path)
    assert poses["station_id"].tolist() == [s.station_id for s in rehearsal.scans]


def test_las_carries_the_points_and_their_attributes(rehearsal, tmp_path):
    path = tmp_path / "scans.laz"
    path.write_bytes(laz_bytes(rehearsal))
    las = laspy.read(path)
    xyz = np.concatenate([s.world_xyz for s in rehearsal.scans])
    assert las.header.point_count == rehearsal.n_points
    assert np.abs(np.column_stack([las.x, las.y, las.z]) - xyz).max() < 1e-4  # m
    rms = np.concatenate([s.rms_mm for s in rehearsal.scans])
    assert np.asarray(las.rms_mm) == pytest.approx(rms, abs=1e-4)  # mm
    inc = np.concatenate([s.incidence_deg for s in rehearsal.scans])
    assert np.asarray(las.incidence_deg) == pytest.approx(inc, abs=1e-3)  # deg
    first = rehearsal.scans[0]
    assert (np.asarray(las.point_source_id)[: first.n_points] == 1).all()
    targets = np.isin(np.asarray(las.classification), [64, 65])
    assert targets.sum() == sum(
        np.isin(s.kind, [POINT_KINDS.index("sphere"), POINT_KINDS.index("checkerboard")]).sum()
        for s in rehearsal.scans
    )
    legend = pd.read_csv(pd.io.common.StringIO(legend_csv(rehearsal)))
    assert legend.query("attribute == 'point_source_id'")["means"].tolist()[0] == "S01"


def test_targets_are_geometry_spheres_on_their_centres_boards_in_two_colours(default_plan):
    exact = rehearse(default_plan, beams_per_station=200_000, seed=2, noise=False)
    t = default_plan.targets.set_index("target_id")
    n_sphere, boards = 0, []
    for s in exact.scans:
        on = s.kind == POINT_KINDS.index("sphere")
        for k in np.unique(s.surface[on]):
            row = t.loc[exact.surfaces[k]]
            c = np.array([row.x, row.y, row.z])  # z above flat ground at 0
            r = np.linalg.norm(s.world_xyz[on & (s.surface == k)] - c, axis=1)
            assert r * 1e3 == pytest.approx(np.full(len(r), row.size_mm / 2), abs=0.01)  # mm
            n_sphere += 1
        boards.append(s.intensity[s.kind == POINT_KINDS.index("checkerboard")])
    assert n_sphere >= 10
    shades = np.unique(np.round(np.concatenate(boards) > 0.3))
    assert shades.tolist() == [0.0, 1.0]  # white and black quadrants both seen


def test_the_size_said_before_is_the_size_made(default_plan, rehearsal):
    size = estimate(default_plan, BEAMS)
    assert size["points"] == pytest.approx(rehearsal.n_points, rel=0.2)


def test_helios_survey_is_valid_and_reads_back(default_plan):
    scene = Scene(default_plan.site, "rays")
    files = helios_files(default_plan, scene)
    assert check_survey(files) == []
    broken = dict(files, **{"helios_scene.xml": files["helios_scene.xml"].replace(b"obj", b"ob")})
    assert check_survey(broken)  # a reference that does not resolve is found
    del broken["helios_scanner.xml"]
    assert "helios_scanner.xml is missing" in check_survey(broken)


def test_helios_legs_are_the_stations(default_plan, tmp_path):
    scene = Scene(default_plan.site, "rays")
    files = helios_files(default_plan, scene)
    (tmp_path / "s.xml").write_bytes(files["helios_survey.xml"])
    legs = read_survey(tmp_path / "s.xml")
    st = default_plan.scan_stations.set_index("station_id")
    assert len(legs) == len(st)
    for leg in legs:
        row = st.loc[leg["station_id"]]
        assert leg["xyz"][:2] + scene.origin[:2] == pytest.approx([row.x, row.y], abs=1e-4)
    obj = files["helios_scene.obj"].decode().splitlines()
    assert sum(1 for line in obj if line.startswith("f ")) == scene.n_triangles + 2  # +ground


def _moved(p):
    st = p.scan_stations[["station_id", "x", "y"]].copy()
    st = st[st["station_id"] != "S05"].copy()  # skipped
    st.loc[st["station_id"] == "S02", "x"] += 3.0  # m
    st.loc[st["station_id"] == "S09", "y"] += 3.0
    return st


def test_replan_proposes_the_fewest_extra_stations_for_what_is_left():
    """Two stations moved 3 m, one skipped: the extra covering stations are as few as an
    exact re-solve (scipy's MILP over the same evaluation) needs."""
    p = plan(settings=PlanSettings(registration_error=False))
    scanned = _moved(p)
    r = replan(p, scanned)
    status = r.stations.set_index("station_id")["status"]
    assert status["S05"] == "skipped" and status["S02"] == "moved" and status["S01"] == "as planned"
    assert r.stations.set_index("station_id").loc["S02", "moved_m"] == pytest.approx(3.0)
    wb = p.workbench
    ok = wb.evaluation.ok
    forced = wb.add_positions(scanned[["x", "y"]].to_numpy())
    demand = cover_demand(wb.ctx, np.asarray(ok.sum(axis=1)).ravel())
    left = np.maximum(0, demand - np.asarray(ok[:, forced].sum(axis=1)).ravel())
    rows = left > 0
    free = np.setdiff1d(np.arange(ok.shape[1]), forced)
    a = sp.csr_matrix(ok[rows][:, free], dtype=float)
    best = milp(
        np.ones(len(free)),
        constraints=LinearConstraint(a, lb=left[rows]),
        integrality=np.ones(len(free)),
        bounds=Bounds(0, 1),
    )
    assert best.success
    covering = r.extra["reason"].str.contains("left unmet")
    assert covering.sum() == round(best.fun) > 0
    # the others tie the scans made into one network again (S05, skipped, was a link)
    assert r.extra.loc[~covering, "reason"].str.contains("into the registration network").all()
    assert r.plan.meets_all
    # ids: the scans keep theirs, the extra stations take numbers never given
    assert set(r.extra["station_id"]).isdisjoint(p.stations["station_id"])


def test_nothing_changed_means_nothing_extra(default_plan):
    scanned = default_plan.scan_stations[["station_id", "x", "y"]]
    r = replan(default_plan, scanned)
    assert r.extra.empty and (r.stations["status"] == "as planned").all()
    assert r.before[0] == r.before[1]


def test_the_link_report_is_read_under_its_own_names_and_compared(default_plan, tmp_path):
    a, b, pred = default_plan.links.iloc[0][["station_a", "station_b", "link_rms_mm"]]
    path = tmp_path / "report.csv"
    path.write_text(f"From;To;Error (m);Overlap\n{b};{a};{3 * pred / 1000};40%\nS01;S99;0.001;5\n")
    rep = read_link_report(path)
    assert rep["error_mm"].iloc[0] == pytest.approx(3 * pred)  # mm
    check = compare_links(default_plan, rep)
    assert check["ratio"].iloc[0] == pytest.approx(3.0)
    assert check["verdict"].tolist() == [
        "over twice the prediction: check this link",
        "not a link of the plan",
    ]
    assert check["reported_overlap_pct"].iloc[0] == 40


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("station_id,x\nS01,3\n", "missing y"),
        ("station_id,x,y\nS01,a,3\n", "row 2"),
        ("station_id,x,y\nS01,1,2\nS01,5,6\n", "given twice"),
    ],
)
def test_bad_station_files_are_refused(tmp_path, text, said):
    path = tmp_path / "st.csv"
    path.write_text(text)
    with pytest.raises(InputError, match=said):
        read_poses(path)


def test_replan_command_writes_the_new_plan_and_exit_2_on_bad_input(tmp_path):
    st = tmp_path / "scanned.csv"
    pd.DataFrame({"station_id": ["S01"], "x": [690990.0], "y": [5335018.0]}).to_csv(st)
    out = tmp_path / "re"
    code, stdout, _ = run("replan", "--out", str(out), "--as-scanned", str(st), "-q")
    assert code in (0, 1), stdout
    table = pd.read_csv(out / "as_scanned.csv")
    assert (table["status"] == "skipped").sum() == 9 and "Extra stations" in stdout
    bad = tmp_path / "x.e57"
    bad.write_bytes(b"not an e57")
    code, _, err = run("replan", "--out", str(tmp_path / "b"), "--as-scanned", str(bad), "-q")
    assert code == 2 and "not a readable E57" in err
    assert not (tmp_path / "b").exists()
