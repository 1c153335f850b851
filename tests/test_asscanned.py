"""planner.pipeline.survey.asscanned and the dashboard's "As scanned" tab: re-planning from the
stations as scanned, and the registration report compared with the plan."""

from __future__ import annotations

import datetime
import itertools

import numpy as np
import pandas as pd
import pytest
import scipy.sparse as sp
from scipy.optimize import Bounds, LinearConstraint, milp
from sites import run_cli as run

from planner.errors import InputError
from planner.pipeline.engine.judge import copy_plan, workbench_of
from planner.pipeline.engine.planning import cover_demand, plan
from planner.pipeline.inputs.requirements import PlanSettings
from planner.pipeline.survey.asscanned import (
    compare_links,
    pair_prediction,
    read_link_report,
    replan,
)
from planner.pipeline.survey.pointclouds import read_poses
from planner.scanner import Scanner
from planner.siteio import default_site


def _roles(p) -> tuple[str, str, str]:
    """The station to skip (the one meeting the most samples: something is left unmet),
    and two to move 3 m (the first two others in id order)."""
    busy = str(p.coverage.loc[p.coverage["meets"], "station_id"].value_counts().index[0])
    others = sorted(s for s in p.scan_stations["station_id"] if s != busy)
    return busy, others[0], others[1]


def _moved(p):
    skip, east, north = _roles(p)
    st = p.scan_stations[["station_id", "x", "y"]].copy()
    st = st[st["station_id"] != skip].copy()  # skipped
    st.loc[st["station_id"] == east, "x"] += 3.0  # m
    st.loc[st["station_id"] == north, "y"] += 3.0
    return st


def test_replan_proposes_the_fewest_extra_stations_for_what_is_left():
    """Two stations moved 3 m, one skipped: the extra covering stations are as few as an
    exact re-solve (scipy's MILP over the same evaluation) needs."""
    p = plan(settings=PlanSettings(registration_error=False))
    scanned = _moved(p)
    r = replan(p, scanned)
    status = r.stations.set_index("station_id")["status"]
    skip, east, north = _roles(p)
    assert status[skip] == "skipped" and status[east] == status[north] == "moved"
    assert (status == "as planned").sum() == len(p.scan_stations) - 3
    assert r.stations.set_index("station_id").loc[east, "moved_m"] == pytest.approx(3.0)
    wb = workbench_of(r.plan)  # the re-plan's (it works on a copy of the plan)
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
    p = copy_plan(default_plan)  # (a re-plan adds to the plan's workbench)
    scanned = p.scan_stations[["station_id", "x", "y"]]
    r = replan(p, scanned)
    assert r.extra.empty and (r.stations["status"] == "as planned").all()
    assert r.before[0] == r.before[1]


def test_the_link_report_is_read_under_its_own_names_and_compared(default_plan, tmp_path):
    a, b, pred = default_plan.links.iloc[0][["station_a", "station_b", "link_rms_mm"]]
    path = tmp_path / "report.csv"
    # a pair the plan does not link but a registration program's report holds (its scans
    # made one after the other): the plan's prediction for that pair registered directly
    links = default_plan.links
    linked = {frozenset(k) for k in zip(links.station_a, links.station_b, strict=True)}
    ids = default_plan.stations["station_id"].tolist()
    other = next(
        (x, y)
        for x, y in itertools.pairwise(ids)
        if frozenset((x, y)) not in linked and np.isfinite(pair_prediction(default_plan, x, y)[0])
    )
    path.write_text(
        f"From;To;Error (m);Overlap\n{b};{a};{3 * pred / 1000};40%\nS01;S99;0.001;5\n"
        f"{other[0]};{other[1]};0.0005;30\n"
    )
    rep = read_link_report(path)
    assert rep["error_mm"].iloc[0] == pytest.approx(3 * pred)  # mm
    check = compare_links(default_plan, rep)
    assert check["ratio"].iloc[0] == pytest.approx(3.0)
    assert check["planned"].tolist() == [True, False, False]
    assert check["verdict"].iloc[0] == "over twice the prediction: check this link"
    assert check["verdict"].iloc[1].startswith("no prediction")  # S99: no such scan
    assert check["predicted_mm"].iloc[2] == pytest.approx(pair_prediction(default_plan, *other)[0])
    assert check["ratio"].iloc[2] == pytest.approx(0.5 / check["predicted_mm"].iloc[2])
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


def test_replan_command_writes_the_new_plan_and_exit_2_on_bad_input(tmp_path, default_plan):
    st = tmp_path / "scanned.csv"
    pd.DataFrame({"station_id": ["S01"], "x": [690990.0], "y": [5335018.0]}).to_csv(st)
    out = tmp_path / "re"
    code, stdout, _ = run("replan", "--out", str(out), "--as-scanned", str(st), "-q")
    assert code in (0, 1), stdout
    table = pd.read_csv(out / "as_scanned.csv")
    skipped = len(default_plan.stations) - 1  # every planned station but the one scanned
    assert (table["status"] == "skipped").sum() == skipped and "Extra stations" in stdout
    bad = tmp_path / "x.e57"
    bad.write_bytes(b"not an e57")
    code, _, err = run("replan", "--out", str(tmp_path / "b"), "--as-scanned", str(bad), "-q")
    assert code == 2 and "not a readable E57" in err
    assert not (tmp_path / "b").exists()


def _upload(name: str, data: bytes) -> tuple[dict, ...]:
    return (
        {
            "name": name,
            "type": "text/csv",
            "size": len(data),
            "content": memoryview(data),
            "last_modified": datetime.datetime(2026, 1, 1),
        },
    )


def test_the_dashboard_replans_from_an_uploaded_csv_and_offers_the_extra_booklet():
    from planner.app.dashboard import StationPlanner

    ui = StationPlanner()
    ui.as_scanned.run()  # before any plan: said, nothing breaks
    assert "make a plan first" in ui.as_scanned.status.value
    ui.run()
    st = _moved(ui.plan)
    ui.as_scanned.poses.value = _upload("scanned.csv", st.to_csv(index=False).encode())
    ui.as_scanned.run().join()
    assert "Extra stations" in ui.as_scanned.status.value
    r = ui.as_scanned.last
    assert len(ui.plan.stations) == len(st) + len(r.extra)  # the map shows the new plan
    assert "booklet-extra-stations.pdf" in ui.as_scanned.booklet.value


def test_a_scan_where_no_station_can_stand_is_named(default_plan):
    p = copy_plan(default_plan)
    scanned = p.scan_stations[["station_id", "x", "y"]].copy()
    scanned.loc[scanned["station_id"] == "S03", ["x", "y"]] = (691010.0, 5335005.0)  # inside
    with pytest.raises(InputError, match=r"station S03 as scanned .* inside building main"):
        replan(p, scanned)


@pytest.mark.parametrize(
    ("argv", "said"),
    [
        (["rehearse", "--beams-per-station", "10"], "beams-per-station"),
        (["rehearse", "--seed", "-1"], "seed"),
        (["replan", "--as-scanned", "{tmp}/none.csv"], "no such file"),
        (["replan", "--as-scanned", "{tmp}/other.csv"], "is a station of this plan"),
        (["replan", "--as-scanned", "{tmp}/poses.las"], "an .e57 file"),
        (
            ["replan", "--as-scanned", "{tmp}/other.csv", "--link-report", "{tmp}/poses.txt"],
            "no column for",
        ),
    ],
)
def test_the_new_commands_refuse_bad_input_with_exit_2(tmp_path, argv, said):
    (tmp_path / "other.csv").write_text("station_id,x,y\nPillar A,690990,5335018\n")
    (tmp_path / "poses.txt").write_text("a b c\n")
    (tmp_path / "poses.las").write_bytes(b"LASF")
    out = tmp_path / "out"
    args = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    code, _, err = run(*args, "--out", str(out), "-q")
    assert code == 2, err
    assert said in err
    assert not out.exists()  # nothing written


def test_a_station_added_on_site_keeps_its_name_and_is_not_proposed_again(default_plan):
    scanned = default_plan.scan_stations[["station_id", "x", "y"]].copy()
    scanned.loc[len(scanned)] = ("S40", 691050.0, 5334950.0)  # m: a set-up the plan lacks
    n = len(default_plan.stations)
    r = replan(default_plan, scanned)
    status = r.stations.set_index("station_id")["status"]
    assert status["S40"] == "added on site"
    assert r.extra.empty  # nothing was left: no extra station, S40 not renamed
    assert "S40" in set(r.plan.stations["station_id"])
    assert len(default_plan.stations) == n  # the plan given is not changed


def test_scan_names_are_matched_as_a_crew_writes_them_and_a_semicolon_csv_is_read(
    default_plan, tmp_path
):
    rows = default_plan.scan_stations[["station_id", "x", "y"]]
    lines = ["Name;E;N;H"] + [
        f"{sid.lower().replace('s0', 's')};{str(x).replace('.', ',')};{y};1,5"
        for sid, x, y in rows.itertuples(index=False)
    ]
    (tmp_path / "st.csv").write_text("\n".join(lines))
    scanned = read_poses(tmp_path / "st.csv")
    assert scanned["x"].iloc[0] == pytest.approx(rows["x"].iloc[0])  # m
    r = replan(default_plan, scanned)
    assert (r.stations["status"] == "as planned").all()
    assert r.stations["scan_name"].iloc[0] == rows["station_id"].iloc[0].lower().replace("s0", "s")


@pytest.mark.parametrize(
    ("xy", "said"),
    [((0.0, 0.0), "same position"), ((500000.0, 5000000.0), "not in the site's CRS")],
)
def test_poses_that_are_not_the_stations_are_refused(default_plan, xy, said):
    scanned = default_plan.scan_stations[["station_id", "x", "y"]].copy()
    if said == "same position":
        scanned[["x", "y"]] = xy
    else:
        scanned.loc[scanned.index[0], ["x", "y"]] = xy
    with pytest.raises(InputError, match=said):
        replan(default_plan, scanned)


def test_a_link_report_without_an_error_is_said_so(default_plan, tmp_path):
    a, b = default_plan.links.iloc[0][["station_a", "station_b"]]
    (tmp_path / "r.csv").write_text(f"from,to,Error [mm]\n{a},{b},\n")
    check = compare_links(default_plan, read_link_report(tmp_path / "r.csv"))
    assert check["verdict"].tolist() == ["no error given"]


@pytest.mark.booklet
@pytest.mark.booklet
def test_the_extra_stations_booklet_has_their_pages(default_plan, monkeypatch):
    import planner.app.booklet as bk

    drawn = []
    monkeypatch.setattr(bk, "_overview", lambda p: bk.Figure())
    monkeypatch.setattr(
        bk,
        "_station_page",
        lambda p, n, *a: drawn.append(bk._route(p).iloc[n]["station_id"]) or bk.Figure(),
    )
    bk.booklet_pdf(default_plan, only={"S07", "S03"})
    assert sorted(drawn) == ["S03", "S07"]


def test_replan_checks_it_starts_from_the_plan_the_crew_followed(default_plan, tmp_path):
    from planner.pipeline.survey.asscanned import check_same_plan

    folder = tmp_path / "plan"
    folder.mkdir()
    default_plan.stations.to_csv(folder / "stations.csv", index=False)
    check_same_plan(default_plan, folder)  # the same plan: no complaint
    moved = default_plan.stations.copy()
    moved.loc[moved["station_id"] == "S04", "x"] += 0.01  # m
    moved.to_csv(folder / "stations.csv", index=False)
    with pytest.raises(InputError, match="stations S04 differ"):
        check_same_plan(default_plan, folder)


def test_a_tripod_set_up_nearer_a_wall_than_the_plans_clearance_is_taken(default_plan):
    scanned = default_plan.scan_stations[["station_id", "x", "y"]].copy()
    # S01 set up 0.5 m west of the building's west wall (x = 691000; the plan keeps 1 m)
    scanned.loc[scanned["station_id"] == "S01", ["x", "y"]] = (690999.5, 5335018.0)
    r = replan(default_plan, scanned)
    assert r.stations.set_index("station_id").loc["S01", "status"] == "moved"
    assert r.plan.settings.clearance_m == default_plan.settings.clearance_m  # m: as planned


def test_field_exports_are_read_as_a_crew_gives_them(default_plan, tmp_path):
    """A BOM (Excel's CSV UTF-8), Point ID / Easting (m) headers, an empty spreadsheet row,
    scans named Scan 001…; a link report in cm with units in its cells and Scan A / Scan B."""
    rows = default_plan.scan_stations[["station_id", "x", "y"]]
    body = "\r\n".join(
        f"Scan {sid[1:].zfill(3)},{x},{y},1.5" for sid, x, y in rows.itertuples(index=False)
    )
    (tmp_path / "st.csv").write_bytes(
        ("\ufeffPoint ID,Easting (m),Northing (m),H\r\n" + body + "\r\n,,,\r\n").encode()
    )
    scanned = read_poses(tmp_path / "st.csv")
    assert len(scanned) == len(rows)
    r = replan(default_plan, scanned)
    assert (r.stations["status"] == "as planned").all()
    a, b, pred = default_plan.links.iloc[0][["station_a", "station_b", "link_rms_mm"]]
    line = f"scan {a[1:]};{b.lower()};{pred / 10:.6f} cm"
    (tmp_path / "r.csv").write_bytes(f"\ufeffScan A;Scan B;Deviation (cm)\n{line}\n".encode())
    check = compare_links(default_plan, read_link_report(tmp_path / "r.csv"))
    assert check["ratio"].iloc[0] == pytest.approx(1.0, abs=1e-3)
    (tmp_path / "bad.csv").write_text(f"from,to,error\n{a},{b},abc\n")
    with pytest.raises(InputError, match="'abc' is not a number"):
        read_link_report(tmp_path / "bad.csv")


def test_scans_of_another_plan_and_a_target_typed_far_off_are_refused(default_plan):
    scanned = default_plan.scan_stations[["station_id", "x", "y"]].copy()
    with pytest.raises(InputError, match="not the plan the crew followed"):
        replan(default_plan, scanned.assign(x=scanned["x"] + 40.0))  # m
    t = default_plan.targets[["target_id", "x", "y"]].copy()
    t.loc[t.index[0], "x"] -= 1000.0  # m: a digit typed wrong
    with pytest.raises(InputError, match="a typing error"):
        replan(default_plan, scanned, targets_placed=t)


@pytest.mark.parametrize("missing", [0, 1])
def test_a_missing_target_keeps_the_targets_that_stood_and_the_scans_made(tmp_path, missing):
    """The RTC360 on the default site, every scan made as planned but one sphere of a
    target link never set up (the first link's, or the second's): the re-plan keeps every
    sphere that stood under its id, ties the scans by what is there (the spheres that stood,
    the clouds, an extra set-up where nothing else can) with at most two extra set-ups, and
    meets what the plan met; the command writes the extra stations' booklet."""
    p = plan(default_site(), Scanner.from_name("leica-rtc360"))
    by_targets = p.links[p.links["kind"] == "targets"]
    gone = str(by_targets["target_ids"].iloc[missing].split(";")[0])
    placed = p.targets[p.targets["target_id"] != gone][["target_id", "x", "y"]]
    scanned = p.scan_stations[["station_id", "x", "y"]]
    r = replan(p, scanned, targets_placed=placed)
    kept = set(r.plan.targets["target_id"].astype(str))
    assert gone not in kept and kept <= set(placed["target_id"].astype(str))
    assert len(r.extra) <= 2
    assert r.plan.scanned["meets"].sum() >= p.scanned["meets"].sum()
    st, tg = tmp_path / "scanned.csv", tmp_path / "placed.csv"
    scanned.to_csv(st, index=False)
    placed.to_csv(tg, index=False)
    out = tmp_path / "re"
    code, _, err = run(
        "replan", "--scanner", "leica-rtc360", "--out", str(out), "--as-scanned", str(st),
        "--targets-placed", str(tg), "--booklet", "-q",
    )  # fmt: skip
    assert code in (0, 1), err
    assert (out / "booklet.pdf").exists() == bool(len(r.extra))
