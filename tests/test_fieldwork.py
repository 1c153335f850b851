"""Field logistics and the field booklet: scan time, the walking route (never through a
building), the schedule's sums and sessions, the booklet's pages."""

from __future__ import annotations

import itertools
import re

import numpy as np
import pandas as pd
import pytest
import shapely
from sites import E0, N0, rect, square_site

from planner.app.booklet import booklet_pdf, compass
from planner.fieldwork import scan_points, scan_time_s
from planner.pipeline.engine.planning import plan
from planner.pipeline.field.route import _open_path_order, field_route, walk_paths
from planner.pipeline.inputs.requirements import PlanSettings
from planner.scanner import load_scanner
from planner.site import Area, Building, Site
from planner.siteio import default_site


def test_scan_points_and_time_of_a_full_panorama():
    # δ = 2 mm / 10 m = 0.2 mrad: 2π/δ = 31 416 columns, (135° in rad)/δ = 11 781 rows
    assert scan_points(360.0, 135.0, 2.0) == 31_416 * 11_781
    assert scan_time_s(370_111_896, 1e6) == pytest.approx(370.1, abs=0.1)  # s
    # half the sector, half the points; twice the step, a quarter
    assert scan_points(180.0, 135.0, 2.0) == pytest.approx(scan_points(360, 135, 2) / 2, rel=1e-4)
    assert scan_points(360.0, 135.0, 4.0) == pytest.approx(scan_points(360, 135, 2) / 4, rel=1e-3)


def test_the_walk_goes_round_a_building():
    site = square_site(10.0)  # 10 × 10 m from (E0, N0)
    a, b = (E0 - 10, N0 + 5), (E0 + 20, N0 + 5)
    d = walk_paths(site, np.array([a, b]), clearance_m=1.0)
    # over the two north corners, kept about half a metre off: √(9.5² + 5.5²) to the first,
    # 11 m along the wall, the same down to b
    round_corner = 2 * np.hypot(9.5, 5.5) + 11.0
    assert d[0, 1] == pytest.approx(round_corner, abs=0.3)  # m
    assert d[0, 1] == pytest.approx(d[1, 0], abs=1e-9)  # m
    free = walk_paths(square_site(10.0), np.array([a, (E0 - 10, N0 + 25)]))
    assert free[0, 1] == pytest.approx(20.0, abs=1e-6)  # m: a free straight line


def test_no_go_area_is_crossed_only_when_nothing_else_reaches():
    street = Area("street", rect(-100, 20, 100, 26))
    site = Site([Building("b", rect(0, 0, 10, 10), 8.0)], no_go=[street])
    pts = np.array([(E0 + 5, N0 + 15), (E0 + 5, N0 + 35)])
    d = walk_paths(site, pts)
    assert np.isfinite(d[0, 1]) and d[0, 1] == pytest.approx(20.0, abs=0.01)  # m: crosses it
    gap = Site(
        [Building("b", rect(0, 0, 10, 10), 8.0)],
        no_go=[Area("w", rect(-100, 20, 0, 26)), Area("e", rect(12, 20, 100, 26))],
    )
    pts = np.array([(E0 + 20, N0 + 15), (E0 + 20, N0 + 35)])
    d = walk_paths(gap, pts)
    # round through the gap (x 0-12 m) rather than across the eastern half: to its corner
    # (11.5, 19.5), 7 m through, then on to the point
    detour = np.hypot(8.5, 4.5) + 7.0 + np.hypot(8.5, 8.5)
    assert d[0, 1] == pytest.approx(detour, abs=0.4)  # m


def test_open_path_order_is_optimal_on_small_instances():
    rng = np.random.default_rng(4)
    for _ in range(20):
        xy = rng.uniform(0, 100, (7, 2))
        d = np.hypot(*(xy[:, None] - xy[None]).transpose(2, 0, 1))
        order = _open_path_order(d)
        assert sorted(order) == list(range(7))
        length = d[order[:-1], order[1:]].sum()
        best = min(d[list(p[:-1]), list(p[1:])].sum() for p in itertools.permutations(range(7)))
        assert length <= best * 1.05 + 1e-9  # m: 2-opt from the best start, within 5 %


def test_open_path_order_of_a_district_is_a_short_permutation():
    """Thousands of stations (a district): fewer nearest-neighbour starts and 2-opt in
    windows, several reversals a pass. Every station once, and shorter than the nearest
    neighbour path from the first station alone (1.73 s and 122.9 km here, against 13.0 s
    and 126.5 km for 150 starts and one reversal a pass)."""
    rng = np.random.default_rng(0)
    xy = rng.uniform(0, 3000, (2640, 2))
    d = np.hypot(*(xy[:, None] - xy[None]).transpose(2, 0, 1))
    order = _open_path_order(d)
    assert sorted(order) == list(range(len(xy)))
    seen, nn = np.zeros(len(xy), bool), [0]
    seen[0] = True
    for _ in range(len(xy) - 1):
        nn.append(int(np.argmin(np.where(seen, np.inf, d[nn[-1]]))))
        seen[nn[-1]] = True
    length, greedy = d[order[:-1], order[1:]].sum(), d[nn[:-1], nn[1:]].sum()
    assert length < 0.95 * greedy  # m: 122.9 km against 135.4 km


def test_route_of_the_default_plan(default_plan):
    p = default_plan
    t = p.route.table
    assert sorted(t["station_id"]) == sorted(p.stations["station_id"])
    assert list(t["order"]) == list(range(1, len(t) + 1))
    # never through a building (or an obstacle)
    walls = shapely.union_all([b.footprint for b in p.site.buildings])
    for leg in p.route.legs[1:]:
        assert len(leg) >= 2
        assert not shapely.linestrings(leg).intersects(walls)
    # a leg's length is its polyline's, at least the straight distance between its stations
    xy = t[["x", "y"]].to_numpy()
    for n, leg in enumerate(p.route.legs[1:], start=1):
        length = np.hypot(*np.diff(leg, axis=0).T).sum()
        assert t["walk_m"].iloc[n] == pytest.approx(length, abs=0.05)  # m
        assert length >= np.hypot(*(xy[n] - xy[n - 1])) - 1e-6
    # every target set up once, before the first station that scans it
    placed = " ".join(t["targets_to_set"]).split()
    assert sorted(placed) == sorted(p.targets["target_id"])
    visit = dict(zip(t["station_id"], t["order"], strict=True))
    first = {
        tid: min(visit[s] for s in sids)
        for tid, sids in zip(p.targets["target_id"], p.targets["station_ids"], strict=True)
    }
    for r in t.itertuples():
        for tid in r.targets_to_set.split():
            assert first[tid] == r.order
    # the time adds up
    st = p.settings
    # … and collected once, after the last station that scans it: the kit leap-frogs
    collected = " ".join(t["targets_to_collect"]).split()
    kit = p.targets[p.targets["type"] != "control"]
    assert sorted(collected) == sorted(kit["target_id"])
    last = {
        tid: max(visit[s] for s in sids)
        for tid, sids in zip(kit["target_id"], kit["station_ids"], strict=True)
    }
    for r in t.itertuples():
        for tid in r.targets_to_collect.split():
            assert last[tid] == r.order
        standing = sum(first[k] <= r.order <= last[k] for k in last)
        assert r.targets_standing == standing
    assert p.route.kit["used"].sum() == len(kit)
    assert p.route.kit["most_at_once"].max() <= t["targets_standing"].max()
    parts = t[["walk_min", "targets_min", "collect_min", "setup_min", "scan_min", "imaging_min"]]
    assert np.allclose(t["station_min"], parts.sum(axis=1), atol=0.2)  # min (rounding)
    assert t["collect_min"].sum() == pytest.approx(st.target_collect_min * len(kit))  # min
    assert t["elapsed_min"].iloc[-1] == pytest.approx(p.route.total_min, abs=0.2)  # min
    assert (t["setup_min"] == st.setup_min).all()
    assert t["targets_min"].sum() == pytest.approx(st.target_setup_min * len(p.targets))  # min
    # the default scanner gives no measurement rate: the setting's, said so
    assert p.route.rate_assumed and p.route.rate_hz == st.scan_rate_hz
    assert "Field time:" in p.summary() and "assumed" in p.summary()


def test_sessions_split_the_day():
    site = default_site()
    p = plan(site, settings=PlanSettings(session_h=0.5))
    t = p.route.table
    assert p.route.sessions > 1
    for _, rows in t.groupby("session"):
        assert rows["station_min"].sum() <= 30.0 + 1e-6 or len(rows) == 1  # min
    assert list(t["session"]) == sorted(t["session"])


@pytest.mark.booklet
def test_booklet_has_the_overview_and_a_page_per_station(default_plan):
    pdf = booklet_pdf(default_plan)
    assert pdf.startswith(b"%PDF")
    pages = re.findall(rb"/Type\s*/Page\b(?!s)", pdf)
    assert len(pages) == 1 + len(default_plan.stations)
    assert b"CreationDate" not in pdf
    small = plan(square_site())  # the same plan, the same bytes (a plan of a few pages)
    assert booklet_pdf(small) == booklet_pdf(small)


def test_compass_points():
    assert [compass(a) for a in (0, 44, 46, 180, 225, 359)] == [
        "N (0°)",
        "NE (44°)",
        "NE (46°)",
        "S (180°)",
        "SW (225°)",
        "N (359°)",
    ]


def test_a_station_in_a_closed_courtyard_is_still_routed():
    court = shapely.Polygon(
        rect(0, 0, 40, 40).exterior.coords, [rect(10, 10, 30, 30).exterior.coords]
    )
    site = Site([Building("c", court, 10.0)])
    pts = np.array([(E0 + 20, N0 + 20), (E0 - 10, N0 + 20)])
    assert np.isinf(walk_paths(site, pts)[0, 1])  # no way round
    stations = pd.DataFrame({"station_id": ["S01", "S02"], "x": pts[:, 0], "y": pts[:, 1]})
    empty = pd.DataFrame(
        columns=[
            *["target_id", "x", "y", "type", "item", "size_mm", "station_ids"],
            *["station_a", "station_b", "spacing_mm"],
        ]
    )
    coverage = pd.DataFrame(
        {"station_id": ["S01", "S02"], "x": pts[:, 0] + 5, "y": pts[:, 1], "spacing_mm": 4.0}
    )
    p50 = load_scanner("leica-p50")
    r = field_route(site, p50, PlanSettings(), stations, empty, coverage, empty)
    assert list(r.table["walk_note"]) == ["", "no way round buildings found: straight line taken"]
    assert r.table["walk_m"].iloc[1] == pytest.approx(30.0, abs=1e-6)  # m, straight
    assert not r.rate_assumed and r.rate_hz == p50.measurement_rate_hz


# -- the scanner's settings (presets) --------------------------------------------------------
PRESET_SCANNERS = [
    "leica-rtc360",
    "leica-p50",
    "leica-blk360",
    "faro-focus-premium",
    "zf-imager-5016",
]


@pytest.mark.parametrize("name", PRESET_SCANNERS)
def test_each_preset_times_the_scans_by_its_step_rate_and_sector(default_plan, name):
    """Every setting of a scanner: the dome's points at its step over its rate, shared out
    by the station's sector where the scanner can scan one (the full dome where it cannot),
    then its images."""
    from dataclasses import replace

    p, sc = default_plan, load_scanner(name)
    lo, hi = sc.vertical_fov_deg
    for pr in sc.presets:
        st = replace(p.settings, preset=pr.name).for_scanner(sc, None, 100.0)
        assert st.step_mm_at_10m == pr.step_mm_at_10m
        t = field_route(p.site, sc, st, p.stations, p.targets, p.coverage, p.links).table
        rate = pr.rate_hz or sc.measurement_rate_hz
        dome_min = scan_points(360.0, hi - lo, pr.step_mm_at_10m) / rate / 60.0
        share = scan_points(t["sector_deg"].to_numpy(), hi - lo, pr.step_mm_at_10m) / (
            scan_points(360.0, hi - lo, pr.step_mm_at_10m)
        )
        assert t["scan_min"].to_numpy() == pytest.approx(dome_min * share, abs=0.051)  # min
        assert (t["preset"] == pr.name).all()
        assert t["imaging_min"].to_numpy() == pytest.approx(sc.imaging_s / 60.0, abs=0.051)
        if not sc.sector_scan:
            assert (t["sector_deg"] == 360.0).all()
    if sc.sector_scan:
        assert (t["sector_deg"] < 360.0).any()  # the default plan has stations facing a side


def test_imaging_off_takes_the_images_out_of_the_field_time(default_plan):
    from dataclasses import replace

    p, sc = default_plan, load_scanner("leica-rtc360")
    st = p.settings.for_scanner(sc, None, 100.0)
    on = field_route(p.site, sc, st, p.stations, p.targets, p.coverage, p.links)
    off = field_route(
        p.site, sc, replace(st, imaging=False), p.stations, p.targets, p.coverage, p.links
    )
    assert on.total_min - off.total_min == pytest.approx(
        len(p.stations) * sc.imaging_s / 60.0, abs=0.2
    )  # min
    assert (off.table["imaging_min"] == 0).all()
    assert "imaging" in on.summary() and "imaging" not in off.summary()
    assert "full dome: the scanner cannot scan a sector" in on.summary()


def test_each_scanner_sets_up_in_its_own_time(default_plan):
    """The set-up per station is the profile's (RTC360 2 min, P50 5 min), a profile without
    one the generic 5 min, and a time the user gives stands for every scanner."""
    from dataclasses import replace

    from planner.pipeline.inputs.requirements import GENERIC_SETUP_MIN

    p = default_plan
    blank = replace(p.settings, setup_min=None)
    for name, want in [("leica-rtc360", 2.0), ("leica-p50", 5.0), ("leica-hds3000", 5.0)]:
        sc = load_scanner(name)
        st = blank.for_scanner(sc, None, 100.0)
        assert st.setup_min == pytest.approx(want, abs=1e-9)  # min
        t = field_route(p.site, sc, st, p.stations, p.targets, p.coverage, p.links).table
        assert (t["setup_min"] == want).all()
    assert load_scanner("leica-hds3000").setup_min is None
    assert blank.station_setup_min(load_scanner("leica-hds3000")) == GENERIC_SETUP_MIN
    mine = replace(blank, setup_min=7.5).for_scanner(load_scanner("leica-rtc360"), None, 100.0)
    assert mine.setup_min == 7.5  # min: the user's figure stands
    # every field profile says where its set-up time comes from
    for name in ("leica-rtc360", "leica-p50", "leica-blk360", "faro-focus-premium"):
        sc = load_scanner(name)
        assert sc.setup_min is not None and "Set-up" in sc.notes


@pytest.mark.parametrize(("name", "stated_s"), [("leica-rtc360", 120.0), ("leica-blk360", 180.0)])
def test_a_full_dome_with_images_keeps_within_the_makers_stated_time(name, stated_s):
    """The datasheets state a full-dome scan with its HDR images at the usual setting in
    under 2 min (RTC360) and 3 min (BLK360, first generation): the computed scan and the
    imaging time assumed stay within it."""
    sc = load_scanner(name)
    pr = sc.preset(None)
    lo, hi = sc.vertical_fov_deg
    scan_s = scan_time_s(scan_points(360.0, hi - lo, pr.step_mm_at_10m), sc.measurement_rate_hz)
    assert scan_s + sc.imaging_s <= stated_s


def test_the_plan_picks_the_coarsest_setting_the_spacing_allows():
    """No spacing required: the scanner's usual setting; a spacing required at the search
    radius: the coarsest setting meeting it; a step given: that step (and its setting's
    name)."""
    from planner.pipeline.inputs.requirements import Requirements
    from planner.pipeline.inputs.resolved import reach_m

    sc = load_scanner("leica-rtc360")
    st = PlanSettings()
    req = Requirements()
    reach = reach_m(sc, req, st)
    assert st.for_scanner(sc, None, reach).preset == "medium"
    for spacing_at_reach, want in ((12.5, "low"), (6.5, "medium"), (4.0, "high"), (1.0, "high")):
        chosen = st.for_scanner(sc, spacing_at_reach * reach / 10.0, reach)
        assert chosen.preset == want
        assert chosen.step_mm_at_10m == sc.preset(want).step_mm_at_10m
    given = PlanSettings(step_mm_at_10m=3.0).for_scanner(sc, None, reach)
    assert (given.preset, given.step_mm_at_10m) == ("high", 3.0)
    own = PlanSettings(step_mm_at_10m=4.0).for_scanner(sc, None, reach)
    assert (own.preset, own.step_mm_at_10m) == (None, 4.0)
    p = plan(default_site(), sc, Requirements(max_spacing_mm=13.0 * reach / 10.0))
    assert p.settings.preset == "low"
    assert (p.route.table["step_mm_at_10m"] == 12.0).all()
    assert "setting 'low'" in p.route.summary()


# -- setting out and the kit -------------------------------------------------------------------
def test_tape_ties_and_wall_places_in_a_crews_words():
    from planner.pipeline.field.setout import corner_ties, wall_place

    site = Site([Building("A", rect(0, 0, 20, 10), 12.0)])
    (ties,) = corner_ties(site, np.array([[E0 + 23.0, N0 - 4.0]]))
    # not the NE corner, the second nearest: its tape would cross the first at 25°
    assert [t.corner for t in ties] == ["A SE corner", "A SW corner"]
    assert ties[1].distance_m == pytest.approx(np.hypot(23.0, 4.0), abs=1e-9)  # m
    assert ties[0].distance_m == pytest.approx(5.0, abs=1e-9)  # m: 3-4-5 from (20, 0)
    assert ties[0].bearing_deg == pytest.approx(143.13, abs=0.01)  # deg, grid
    assert "5.00 m at 143° from A SE corner" == ties[0].text()
    # a corner behind the building is not a tie: the tape would cross it
    (behind,) = corner_ties(site, np.array([[E0 + 10.0, N0 - 3.0]]))
    assert {t.corner for t in behind} == {"A SW corner", "A SE corner"}
    south = pd.Series({"building_id": "A", "x0": E0, "y0": N0, "x1": E0 + 20, "y1": N0})
    assert (
        wall_place(south, E0 + 4.2, N0, 3.0)
        == "building A, south wall, 4.2 m from its west end, 3.0 m high"
    )
    east = pd.Series({"building_id": "A", "x0": E0 + 20, "y0": N0, "x1": E0 + 20, "y1": N0 + 10})
    assert wall_place(east, E0 + 20, N0 + 7.5, 1.6).startswith(
        "building A, east wall, 7.5 m from its south end"
    )


def test_a_kit_short_of_targets_is_said_with_what_to_bring():
    from planner.targets import parse_inventory

    inv = parse_inventory("flat-70, flat, 70\nsphere-200, sphere, 200, 3\nsphere-400, sphere, 400")
    p = plan(default_site(), settings=PlanSettings(inventory=inv))
    kit = p.route.kit.set_index("item")
    assert kit.loc["sphere-200", "owned"] == 3
    peak = int(kit.loc["sphere-200", "most_at_once"])
    assert peak > 3
    t = p.route.table.set_index("station_id")
    where = kit.loc["sphere-200", "at_station"]
    assert t.loc[where, "targets_standing"] >= peak
    assert (
        f"Kit: {peak} sphere-200 stand at once (at {where}), the kit has 3: bring {peak - 3} more"
        in p.summary()
    )
    # leap-frogged (each collected once its links' two scans are made) never more stand
    assert (p.route.kit["leapfrog_at_once"] <= p.route.kit["most_at_once"]).all()


def test_the_default_kit_is_six_spheres_and_the_plan_keeps_within_it_or_says_what_to_bring(
    default_plan,
):
    """The default inventory is a kit a crew owns (six 200 mm spheres, two 400 mm, printed
    checkerboards): every item the plan uses stands within its count, or the summary and the
    booklet's kit list say how many more to bring."""
    from planner.app.booklet import kit_list
    from planner.pipeline.field.route import kit_words
    from planner.targets import DEFAULT_INVENTORY

    counts = {i.name: i.count for i in DEFAULT_INVENTORY}
    assert counts["sphere-200"] == 6 and counts["sphere-400"] == 2 and counts["flat-70"] is None
    p = default_plan
    for k in p.route.kit.itertuples():
        words = kit_words(k)
        assert words in kit_list(p)
        if k.owned and k.most_at_once > k.owned:
            assert f"bring {k.most_at_once - k.owned} more" in words
            assert f"Kit: {words}." in p.summary()
        elif k.owned:
            assert words.endswith(f"the kit has {k.owned}") and "bring" not in words
        else:
            assert words.endswith("no count given")


def test_a_station_page_says_where_everything_goes(default_plan):
    """The page of a station: tape ties to it, every target it scans on its map, each
    target to set up with where it goes in words and a column for notes, what to collect,
    the walls it scans; the overview lists the kit."""
    from matplotlib.table import Table
    from matplotlib.text import Text

    from planner.app import booklet as bk
    from planner.pipeline.field.route import view_sectors

    p = default_plan
    sectors = view_sectors(p.stations, p.coverage, p.targets)
    t = p.route.table
    n = int(np.argmax(t["targets_to_set"].str.len()))
    fig = bk._station_page(p, n, sectors)
    cells = [c.get_text() for tb in fig.findobj(Table) for c in tb.get_celld().values()]
    words = " ".join([*(x.get_text() for x in fig.findobj(Text)), *(c.get_text() for c in cells)])
    sid = t["station_id"].iloc[n]
    assert re.search(r"Set out \(tape\).*\d+\.\d\d m at \d+° from \w+ \w+ corner", words, re.S)
    assert "Walls it scans" in words and "wall (" in words
    assert "notes" in words and "Collect after it" in words
    for tid in t["targets_to_set"].iloc[n].split():
        assert tid in words
    flat = p.targets[
        (p.targets["type"] == "flat") & p.targets["station_ids"].map(lambda s: sid in s)
    ]
    if len(flat):
        assert re.search(
            r"building \w+, \w+(-\w+)? wall, \d+\.\d m from its (west|south) end", words
        )
    (ax,) = [a for a in fig.axes if a.get_xlabel().startswith("Easting")]
    x0, x1, y0, y1 = *ax.get_xlim(), *ax.get_ylim()
    seen = p.targets[p.targets["station_ids"].map(lambda s: sid in s)]
    assert seen["x"].between(x0, x1).all() and seen["y"].between(y0, y1).all()  # all on it
    overview = " ".join(x.get_text() for x in bk._overview(p).findobj(Text))
    assert "Kit to pack:" in overview and "stand at once" in overview


def test_the_visiting_order_keeps_the_targets_standing_within_the_kit():
    """Two targets, one sphere owned: visited S1 S2 S3 S4 both stand at S2 and S3; the
    order S1 S3 S2 S4 (no longer to walk) has one standing at a time. A kit with no count
    leaves the shortest order alone."""
    from planner.pipeline.field.route import _kit_order
    from planner.targets import TargetItem

    ids = ["S1", "S2", "S3", "S4"]
    d = np.ones((4, 4)) - np.eye(4)  # m: every walk the same
    targets = pd.DataFrame(
        {
            "target_id": ["T1", "T2"],
            "type": ["sphere", "sphere"],
            "item": ["s", "s"],
            "station_ids": [["S1", "S3"], ["S2", "S4"]],
        }
    )
    one = (TargetItem("s", "sphere", 200.0, 1),)
    order = _kit_order(np.arange(4), d, targets, ids, one, None)
    assert [ids[k] for k in order] == ["S1", "S3", "S2", "S4"]
    many = (TargetItem("s", "sphere", 200.0),)
    assert _kit_order(np.arange(4), d, targets, ids, many, None).tolist() == [0, 1, 2, 3]
    # scans registered on site: S3 links only to S4, so it may not come before S4 is scanned
    linked = {"S1": {"S2"}, "S2": {"S1", "S4"}, "S4": {"S2", "S3"}, "S3": {"S4"}}
    order = _kit_order(np.array([0, 1, 3, 2]), d, targets, ids, one, linked)
    seen = {ids[order[0]]}
    for k in order[1:]:
        assert linked[ids[k]] & seen
        seen.add(ids[k])
