"""The package's structure holds: layers, one source of truth, doctests that run, the report
showing exactly the plan ``plan`` makes, and a strict ``milp`` method."""

from __future__ import annotations

import json
import time

import numpy as np
import pytest
from sites import osm_like_export

from planner.pipeline.inputs.requirements import (
    PlanSettings,
    Requirements,
    field_specs,
)
from planner.siteio import read_site


def test_widgets_take_default_and_bounds_from_the_data_classes():
    from planner.app.dashboard import StationPlanner

    ui = StationPlanner()
    rq, ps = field_specs(Requirements), field_specs(PlanSettings)
    assert ui.max_gamma.value == rq["max_gamma_deg"].default == Requirements().max_gamma_deg
    assert ui.max_gamma.max == rq["max_gamma_deg"].hi == 89.0
    assert ui.per_sample.min == 1 and ui.per_sample.max == rq["stations_per_sample"].hi == 10
    assert ui.grid.value == PlanSettings().grid_m and ui.grid.min == ps["grid_m"].lo == 0.25
    assert ui.max_x.value == Requirements().max_x_mm


def test_dashboard_messages_name_its_own_controls(tmp_path):
    """One wording, two renderings: a message names ``--make-valid`` and ``--height H`` on
    the command line; the dashboard shows the same message with the labels of its own
    controls, and an option it has no control for as the command line's."""
    from planner.app.dashboard import StationPlanner
    from planner.app.widgets import error_html
    from planner.app.wording import SITE_LABELS, dashboard_labels, for_dashboard
    from planner.sitecheck import SiteProblems

    path = tmp_path / "export.geojson"
    path.write_text(json.dumps(osm_like_export()))
    with pytest.raises(SiteProblems) as caught:
        read_site(path, buildings=["main"])
    cli = str(caught.value)
    assert "(--height H)" in cli and "(repair=True, --make-valid)" in cli
    page = for_dashboard(cli)
    assert "--" not in page and "repair=True" not in page
    ui = StationPlanner()
    for flag, box in (("--make-valid", ui.make_valid), ("--height", ui.height)):
        assert box.description == SITE_LABELS[flag]
        assert f"the ‘{box.description}’ control" in page
    assert "<br>" in error_html(cli)  # one line per kind of problem
    for flag, label in dashboard_labels().items():
        assert for_dashboard(f"x ({flag})") == f"x (the ‘{label}’ control)"
    assert ui.grid.description.startswith(dashboard_labels()["--grid-m"])
    assert for_dashboard("raise it (--max-site-size-m)") == (
        "raise it (the command line's --max-site-size-m)"
    )


def test_the_dashboard_offers_the_chosen_scanners_settings():
    """The scanner setting follows the scanner (its presets by the maker's names, the usual
    one marked) and reaches the plan; imaging can be left out of the field time."""
    from planner.app.dashboard import StationPlanner

    ui = StationPlanner()
    assert ui.preset.disabled and ui.preset.label == "chosen by the plan"  # none to choose
    assert ui._inputs()[3].preset is None
    ui.scanner.value = "leica-rtc360"
    assert [v for _, v in ui.preset.options] == ["", "low", "medium", "high"]
    assert ("medium (usual)", "medium") in ui.preset.options
    ui.preset.value, ui.imaging.value = "low", False
    _site, _scanner, _req, settings = ui._inputs()
    assert settings.preset == "low" and settings.imaging is False


def _upload(ui, name: str, data: bytes) -> None:
    import datetime

    ui.upload.value = (
        {
            "name": name,
            "type": "",
            "size": len(data),
            "content": data,
            "last_modified": datetime.datetime(2026, 1, 1),
        },
    )


def _click_ground(m, x: float, y: float) -> None:
    """A click on the map's background as the browser sends it in a mode that wants the
    click's place (the catcher scatter's new point, x and y in one message)."""
    with m.catch.hold_trait_notifications():
        m.catch.x, m.catch.y = [x], [y]


def test_the_site_is_drawn_before_it_is_planned_and_buildings_are_picked_on_it(tmp_path):
    """An uploaded site is drawn on the map at once, its buildings' ids on it, nothing
    planned yet; a building clicked in "Pick buildings" mode (its id mark or anywhere on its
    outline) plans it or leaves it out (the list of buildings follows, and the plan on screen
    is marked out of date)."""
    from planner.app.dashboard import MAP_TAB, StationPlanner
    from planner.synthetic import town, town_geojson

    ui = StationPlanner()
    ui.run()
    assert ui.plan is not None
    site = town(3, seed=0)
    _upload(ui, "town.geojson", json.dumps(town_geojson(site)).encode())
    m = ui.map
    ids = [b.id for b in site.buildings]
    assert m._pick_ids == ids  # drawn at once, before any plan
    assert sorted(m.building_labels.text) == sorted(ids)  # three apart: every id shown
    assert len(m.stations.x) == 0 and "The site: " in m.status.value
    assert ui.tabs.selected_index == MAP_TAB
    m.mode.value = "pick"
    one, two = (site.buildings[k].footprint.representative_point() for k in (1, 2))
    _click_ground(m, one.x, one.y)  # anywhere on the building
    assert ui.buildings.value == ids[1]
    assert "Out of date" in ui.stale.value
    _click_ground(m, two.x, two.y)
    assert ui.buildings.value == f"{ids[1]}, {ids[2]}"
    _click_ground(m, one.x, one.y)  # picked again: left out
    assert ui.buildings.value == ids[2]
    _click_ground(m, two.x + 500.0, two.y)  # nothing there: said where clicked
    assert list(m.notice.text) == ["no building here"] and ui.buildings.value == ids[2]
    m.mode.value = "move"
    _click_ground(m, one.x, one.y)  # outside "Pick buildings" a click picks nothing
    assert ui.buildings.value == ids[2]
    # the map holds no plan for this site: an edit is refused, saying why, not made on the
    # previous site's plan
    m.mode.value = "add"
    with m.stations.hold_trait_notifications():
        m.stations.x, m.stations.y = [one.x + 30.0], [one.y]
    assert "no plan on the map" in m.status.value and len(m.stations.x) == 0
    m._reoptimise_locked()
    assert "no plan on the map" in m.status.value and ui.plan.site.buildings[0].id == "main"


def test_a_facade_is_picked_on_the_map_and_its_range_dragged_along_the_wall():
    """In "Pick a facade" mode a click next to a wall picks it for a zone (the zone editor
    follows), the range's ends dragged on the map set the editor's range (projected onto
    the wall, to the decimetre), the zone added is drawn along its wall, and the plan is out
    of date."""
    from planner.app.dashboard import StationPlanner

    ui = StationPlanner()
    ui.run()
    m = ui.map
    m.mode.value = "facade"
    ids, a, b = m._facades
    k = ids.index("main-f02")
    length = float(np.hypot(*(b[k] - a[k])))
    u = (b[k] - a[k]) / length
    normal = np.array([u[1], -u[0]])
    click = a[k] + 0.5 * length * u + 1.5 * normal  # 1.5 m off the wall's middle
    _click_ground(m, *click)
    assert ui.zone_editor.facade.value == "main-f02"
    assert ui.zone_editor.along.value == pytest.approx((0.0, round(length, 1)), abs=0.05)  # m
    assert m.mode.value == "range"  # the range's ends to drag next
    assert m.handles.visible and m.handles.enable_move and len(m.handles.x) == 2
    ends = np.column_stack([m.handles.x, m.handles.y])
    # drag the first end 4 m along the wall and 2 m off it: it lands on the wall at 4 m
    moved = ends[0] + 4.0 * u + 2.0 * normal
    with m.handles.hold_trait_notifications():
        m.handles.x, m.handles.y = [moved[0], ends[1, 0]], [moved[1], ends[1, 1]]
    m._handle_dragged({})
    assert ui.zone_editor.along.value == pytest.approx((4.0, round(length, 1)), abs=0.05)  # m
    line = np.column_stack([np.ravel(m.facade_line.x), np.ravel(m.facade_line.y)])
    assert np.hypot(*(line[0] - (a[k] + 4.0 * u))) == pytest.approx(0.0, abs=0.01)  # m
    ui.zone_editor.add_zone()
    zone = ui.zone_editor.zones[-1]
    assert zone.facade_id == "main-f02" and zone.along_m == pytest.approx((4.0, length), abs=0.05)
    drawn = np.column_stack([np.ravel(m.zone_lines.x), np.ravel(m.zone_lines.y)])
    assert np.hypot(*(drawn[0] - (a[k] + 4.0 * u))) == pytest.approx(0.0, abs=0.01)  # m
    assert "Out of date" in ui.stale.value
    m.mode.value = "facade"
    far = a[k] + 40.0 * normal  # nowhere near a wall: refused where clicked
    _click_ground(m, *far)
    assert list(m.notice.text) == ["click on a wall"]
    ui.buildings.value = "main"  # the site drawn again: the facade and its ranges stay
    assert ui.zone_editor.facade.value == "main-f02"
    assert ui.zone_editor.along.value == pytest.approx((4.0, length), abs=0.05)  # m


def test_a_passage_is_drawn_across_a_building_and_planned_with():
    """In "Draw a passage" mode two clicks across a building make a gateway of the width
    and clear height given; the site drawn (and planned next) has it, the plan on screen is
    kept, dimmed, out of date; a passage through no building is refused where clicked,
    saying why."""
    from planner.app.dashboard import StationPlanner

    ui = StationPlanner()
    ui.run()
    m = ui.map
    n_stations = len(m.stations.x)
    m.mode.value = "passage"
    m.passage_width.value, m.passage_height.value = 4.0, 3.5
    x0, y0, _x1, _y1 = next(b for b in ui.plan.site.buildings if b.id == "main").footprint.bounds
    _click_ground(m, x0 + 5.0, y0 - 1.0)  # south of main's south wing
    assert "other side" in next(iter(m.notice.text))
    _click_ground(m, x0 + 5.0, y0 + 9.0)  # into its courtyard
    (gate,) = ui.drawn_passages
    assert gate.clear_height_m == 3.5 and gate.geometry.area == pytest.approx(40.0, rel=1e-6)
    assert "Out of date" in ui.stale.value
    assert len(m.stations.x) == n_stations and list(m.stations.opacities) == [0.3]
    site, _sc, _req, _st = ui._inputs()
    assert [p.id for p in site.passages] == ["drawn-1"]
    _click_ground(m, x0 - 60.0, y0 - 60.0)  # two clicks on open ground
    _click_ground(m, x0 - 50.0, y0 - 60.0)
    assert len(ui.drawn_passages) == 1
    assert "No passage drawn" in m.status.value and "does not pass through" in m.status.value
    assert next(iter(m.notice.text)).startswith("no passage: ")
    # an edit by hand of the out-of-date plan: judged, still dimmed, the passage still drawn
    xy = np.column_stack([m.stations.x, m.stations.y])
    xy[0] += 1.0
    ui.evaluate_by_hand(xy, list(m._ids))
    assert "judged again" in m.status.value and list(m.stations.opacities) == [0.3]
    assert "Out of date" in ui.stale.value and np.isfinite(np.ravel(m.passages.x)).any()
    m.clear_passages.click()
    assert ui.drawn_passages == [] and ui._inputs()[0].passages == []
    # passages drawn on one site are dropped when another is chosen, and it is said
    _click_ground(m, x0 + 5.0, y0 - 1.0)
    _click_ground(m, x0 + 5.0, y0 + 9.0)
    assert len(ui.drawn_passages) == 1
    ui.site_source.value = "Upload a file"
    assert ui.drawn_passages == [] and "dropped" in m.status.value


def test_an_upload_that_cannot_be_planned_is_drawn_with_its_problems_marked():
    """A file whose buildings lack heights and overlap is drawn at once as far as it can be
    read, the features that stop the plan outlined in red and crossed where they are (their
    problem on hover), and the error says what is wrong; a file that cannot be read at all
    leaves an empty map saying why."""
    from planner.app.dashboard import StationPlanner

    def square(x, y, s):
        return [[[x, y], [x + s, y], [x + s, y + s], [x, y + s], [x, y]]]

    crs = {"type": "name", "properties": {"name": "EPSG:25832"}}
    feats = [
        {"type": "Feature", "properties": {"id": "A", "height": 10},
         "geometry": {"type": "Polygon", "coordinates": square(500000, 5500000, 20)}},
        {"type": "Feature", "properties": {"id": "B"},
         "geometry": {"type": "Polygon", "coordinates": square(500040, 5500000, 20)}},
    ]  # fmt: skip
    ui = StationPlanner()
    _upload(ui, "site.geojson", json.dumps(
        {"type": "FeatureCollection", "crs": crs, "features": feats}
    ).encode())  # fmt: skip
    m = ui.map
    assert m._pick_ids == ["A", "B"]  # drawn, as far as it can be
    assert "cannot be planned" in m.status.value and "B" in m.status.value
    assert list(m.marked.names) and "height" in m.marked.names[0]
    assert np.nanmin(np.ravel(m.problems.x)) == pytest.approx(500040.0, abs=0.01)  # B: m
    # overlapping buildings (no site can be made of them): the outlines as drawn
    feats.append(
        {"type": "Feature", "properties": {"id": "C", "height": 8},
         "geometry": {"type": "Polygon", "coordinates": square(500005, 5500005, 20)}}
    )  # fmt: skip
    _upload(ui, "overlap.geojson", json.dumps(
        {"type": "FeatureCollection", "crs": crs, "features": feats}
    ).encode())  # fmt: skip
    assert m._pick_ids == ["A", "B", "C"] and "cannot be planned" in m.status.value
    names = sorted(str(n) for n in m.marked.names)  # each feature named, its problem on hover
    assert len(names) == 3 and "'A' and 'C' overlap" in names[-1] and "no height" in names[0]
    _upload(ui, "broken.geojson", b"{ not json")
    assert m._pick_ids == [] and "cannot be drawn" in m.status.value
    assert list(m.building_labels.text) == []  # nothing of the previous drawing left


def test_the_status_line_ends_on_the_runs_last_line():
    """The elapsed-time tick never reaches the page after a background run's last line: the
    kernel sends each thread's widget updates in the order they are made, and a tick being
    sent as the run ended stayed on screen as "planning… N s" over a finished run (a
    browser test waited for "done" in vain). Here each tick's send takes 0.6 s, and the run
    is cancelled and ends while one is being sent; Cancel after the end changes nothing."""
    import threading
    import time

    from planner.app.dashboard import StationPlanner

    ui = StationPlanner()
    sent: list[str] = []
    sending = threading.Event()  # a tick is being sent
    send = ui.status.send_state

    def slow_send(key=None):
        text = ui.status.value
        if "planning…" in text:
            sending.set()
            time.sleep(0.6)
        sent.append(text)
        send(key)

    ui.status.send_state = slow_send

    def cancelled(progress):
        assert sending.wait(30)
        ui.cancel()
        progress(0.5, "halfway")  # where Cancel takes effect

    worker = ui.start(cancelled)
    worker.join(60)
    assert not worker.is_alive()
    time.sleep(1.0)  # a tick left running would have written by now
    assert any("planning…" in t for t in sent) and any("cancelling…" in t for t in sent)
    assert sent[-1].startswith("<i>cancelled after"), sent[-3:]
    assert not any(t.name == "planner" for t in threading.enumerate())
    ui.cancel()  # after the run: its last line stays
    assert ui.status.value == sent[-1] and "cancelled after" in sent[-1]


def test_an_input_changed_while_a_plan_is_made_marks_it_out_of_date():
    """An input changed while a background run works (its inputs were read at the start)
    marks what it leaves on screen out of date: the plan it made, or the previous plan
    when it is cancelled; a run with no change leaves no mark."""
    import time

    from planner.app.dashboard import StationPlanner

    ui = StationPlanner()
    ui.run()
    base = ui.plan

    def made(progress):
        time.sleep(0.5)
        progress(0.5, "halfway")  # where Cancel takes effect
        return base

    def done(worker):
        worker.join(60)
        assert not worker.is_alive()

    done(ui.start(made))
    assert ui.stale.value == ""
    worker = ui.start(made)
    ui.max_x.value = 4.5  # [mm]
    done(worker)
    assert "Out of date" in ui.stale.value and "done" in ui.status.value
    done(ui.start(made))  # made again from the inputs on screen
    assert ui.stale.value == ""
    worker = ui.start(made)
    ui.max_y.value = 4.5  # [mm]
    ui.cancel()
    done(worker)
    assert "cancelled" in ui.status.value and ui.plan is not None
    assert "Out of date" in ui.stale.value


def test_ids_stay_through_a_hand_station_locks_re_optimising_and_a_re_plan_with_a_zone():
    """The crew's ids stay: a station added by hand takes a number never given, two locked
    stations and the hand one keep their ids and places through "Re-optimise around the
    locked" and through a full re-plan after a zone is added (a passage or a setting alike:
    the same site planned again), and no id is given to two places."""
    from planner.app.dashboard import StationPlanner

    ui = StationPlanner()
    ui.run()
    m = ui.map
    xy = np.column_stack([m.stations.x, m.stations.y])
    ids = list(m._ids)
    added = xy[0] + [0.0, 9.0]  # m: free ground beside the first station
    ui.evaluate_by_hand(np.vstack([xy, added]), [*ids, None])
    by_place = dict(
        zip(
            map(tuple, np.round(ui.plan.stations[["x", "y"]].to_numpy(), 3)),
            ui.plan.stations["station_id"],
            strict=True,
        )
    )
    hand = by_place[tuple(np.round(added, 3))]
    assert int(hand[1:]) > max(int(s[1:]) for s in ids)  # a number never given
    for k in (1, 2):  # lock two of the planned stations
        m.locked[list(m._ids).index(ids[k])] = True
    m._reoptimise_locked()
    while ui._worker is not None:  # re-optimised in the background
        time.sleep(0.05)
    keep = {ids[1]: xy[1], ids[2]: xy[2], hand: added}

    def kept_in(p):
        st = p.stations.set_index("station_id")
        for sid, pos in keep.items():
            assert st.loc[sid, ["x", "y"]].to_numpy(float) == pytest.approx(pos, abs=1e-6)  # m
        assert p.stations["station_id"].is_unique and p.targets["target_id"].is_unique

    kept_in(ui.plan)
    ui.zone_editor.facade.value = "main-f02"
    ui.zone_editor.add_zone()
    assert "Out of date" in ui.stale.value
    ui.run()  # the same site planned again, with the zone
    kept_in(ui.plan)
    assert not ui.stale.value
    kit = ui.inventory.value
    ui.inventory.value = "not an inventory"
    ui.run()  # an error on the way: no plan on screen
    assert ui.plan is None
    ui.inventory.value = kit
    ui.run()  # the edits and ids are still the site's
    kept_in(ui.plan)


def test_the_crews_kit_is_remembered_for_the_next_session():
    """The kit planned with is the next dashboard's (kept beside the user's profiles); a
    kit file that no longer reads is ignored for the default kit."""
    from planner.app.dashboard import StationPlanner
    from planner.app.widgets import inventory_text, kit_file

    kit_file().unlink(missing_ok=True)
    ui = StationPlanner()
    assert ui.inventory.value == inventory_text()  # nothing remembered: the default kit
    mine = "sphere-145, sphere, 145, 8\nflat-70, flat, 70"
    try:
        ui.inventory.value = mine
        ui._inputs()
        assert StationPlanner().inventory.value == mine
        kit_file().write_text("not, an, inventory, line, at all")
        assert StationPlanner().inventory.value == inventory_text()
    finally:
        kit_file().unlink(missing_ok=True)


def test_control_points_and_the_scanners_levelling_are_given_in_the_dashboard():
    """The dashboard's control-point file and levelling figure reach the plan: the points
    as the site's control (a bad file said, not used), the figure as the scanner's
    compensator; the datum's levelling hint names these controls, not command-line flags."""
    import datetime

    from planner.app.dashboard import StationPlanner
    from planner.app.wording import for_dashboard
    from planner.pipeline.engine.tables import DATUM_LEVELLING_FIX

    ui = StationPlanner()
    text = "id,x,y,z\nC1,690995,5334990,0.2\nC2,691060,5334990,0.3\nC3,691030,5335060,0.1\n"

    def choose(data: bytes) -> None:
        ui.control_upload.value = (
            {
                "name": "control.csv",
                "type": "",
                "size": len(data),
                "content": data,
                "last_modified": datetime.datetime(2026, 1, 1),
            },
        )

    choose(b"id,x,y\nC1,1,2\n")
    assert "missing z" in ui.control_name.value
    assert ui._inputs()[0].control == []
    choose(text.encode())
    assert "3 control point(s)" in ui.control_name.value
    site, sc, _req, _st = ui._inputs()
    assert [c.id for c in site.control] == ["C1", "C2", "C3"]
    assert site.control[1].xyz[2] == pytest.approx(0.3)  # m
    assert not sc.is_levelled  # the default scanner has no compensator
    ui.levelling.value = 3.0
    sc = ui._inputs()[1]
    assert sc.is_levelled and sc.levelling_rms_arcsec == 3.0  # ″
    words = for_dashboard(DATUM_LEVELLING_FIX)
    assert "Scanner levelling" in words and "Control CSV" in words and "--" not in words


def test_ids_start_at_s01_until_a_plan_is_handed_out_or_edited():
    """Planned again with another scanner before anything went out: ids from S01 again;
    once the plan's files are made (downloads, report, booklet), the next plan of the same
    site keeps them and numbers its new stations after them."""
    from planner.app.dashboard import StationPlanner

    ui = StationPlanner()
    ui.run()
    ui.scanner.value = "leica-rtc360"
    ui.run()
    ids = sorted(ui.plan.stations["station_id"])
    assert ids[0] == "S01" and len(ids) == len(set(ids))
    ui._plan_files()  # the files made: the ids are out
    out = ui.plan.stations.set_index("station_id")[["x", "y"]]
    ui.scanner.value = "leica-p50"
    ui.run()
    new = ui.plan.stations.set_index("station_id")[["x", "y"]]
    for sid, (x, y) in new.iterrows():
        if sid in out.index:
            assert out.loc[sid].to_numpy() == pytest.approx([x, y], abs=1e-3)  # m: where it was
        else:
            assert int(sid[1:]) > max(int(s[1:]) for s in out.index)
