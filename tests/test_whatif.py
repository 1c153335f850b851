"""What-if by hand (planner.pipeline.engine.whatif): stations moved, deleted, added or locked are
judged again as a plan is, from what the plan keeps."""

import copy

import numpy as np
import pytest

from planner.errors import InputError
from planner.pipeline.engine.judge import copy_plan, workbench_of
from planner.pipeline.engine.whatif import edit_targets, evaluate_stations, reoptimise


@pytest.fixture(scope="module")
def default_plan(default_plan):
    """The session's default plan, copied: the edits here add to a plan's workbench."""
    return copy_plan(default_plan)


def _xy(p):
    return p.stations[["x", "y"]].to_numpy()


def test_the_plans_own_stations_give_the_plans_coverage(default_plan):
    p = default_plan
    q = evaluate_stations(p, _xy(p))
    assert len(q.stations) == len(p.stations)
    # nothing moved: every station keeps its id and why it is there
    assert list(q.stations["station_id"]) == list(p.stations["station_id"])
    assert list(q.stations["purpose"]) == list(p.stations["purpose"])
    np.testing.assert_allclose(_xy(q), _xy(p), atol=1e-6)  # m
    assert (q.coverage["meets"] == p.coverage["meets"]).all()
    assert (q.coverage["station_id"] == p.coverage["station_id"]).all()
    for c in ("m_x_mm", "m_y_mm", "m_z_mm"):
        np.testing.assert_allclose(q.coverage[c], p.coverage[c], atol=0.01, equal_nan=True)  # mm
    assert "Stations edited by hand" in q.summary()


def test_a_plans_station_ids_follow_the_visiting_order(default_plan):
    """S01 is the first set-up, and the route, the stations, the coverage, the targets and
    the links name the same stations."""
    p = default_plan
    n = len(p.stations)
    assert list(p.route.table["station_id"]) == [f"S{k:02d}" for k in range(1, n + 1)]
    ids = set(p.stations["station_id"])
    assert set(p.coverage["station_id"]) - {""} <= ids
    assert {s for seen in p.targets["station_ids"] for s in seen} <= ids
    assert set(p.links["station_a"]) | set(p.links["station_b"]) <= ids | {"control"}
    named = p.coverage["reason"].str.findall(r"\bS\d\d\b").explode().dropna()
    assert set(named) <= ids  # the reasons name stations by the same ids


def test_deleting_a_station_loses_the_samples_only_it_meets(default_plan):
    p = default_plan
    # the station meeting most samples: without it some samples must go unmet
    k = int(p.stations["samples_met"].idxmax())
    gone = p.stations.loc[k, "station_id"]
    q = evaluate_stations(p, np.delete(_xy(p), k, axis=0))
    # the others keep their ids and purposes (a linking station may be added to tie them
    # again: it takes a number never given)
    before = p.stations.drop(index=k).set_index("station_id")["purpose"]
    after = q.stations.set_index("station_id")["purpose"]
    assert after.loc[before.index].tolist() == before.tolist()
    assert gone not in set(q.stations["station_id"])
    new = sorted(set(q.stations["station_id"]) - set(before.index))
    assert all(int(s[1:]) > len(p.stations) for s in new)
    assert 0 < len(q.unmet) < len(p.scanned)
    assert (q.unmet["reason"] != "").all()


def test_ids_stay_through_edits_and_a_deleted_id_is_not_given_again(default_plan):
    p = default_plan
    xy, ids = _xy(p).copy(), list(p.stations["station_id"])
    n = len(ids)
    k3, k5 = ids.index("S03"), ids.index("S05")
    xy[k5] += [1.0, 0.5]  # moved: keeps its id, placed by hand now
    keep = [k for k in range(n) if k != k3]  # S03 deleted
    free = xy[k3] + [-4.0, -6.0]  # beside the deleted S03
    q = evaluate_stations(p, np.vstack([xy[keep], free]), [ids[k] for k in keep] + [None])
    st = q.stations.set_index("station_id")
    assert "S03" not in st.index
    added = f"S{n + 1:02d}"
    assert st.loc[added, "purpose"] == "hand"
    assert st.loc[added, ["x", "y"]].to_numpy(float) == pytest.approx(free, abs=1e-6)  # m
    assert st.loc["S05", "purpose"] == "hand"
    assert st.loc["S05", ["x", "y"]].to_numpy(float) == pytest.approx(xy[k5], abs=1e-6)  # m
    unmoved = [s for s in ids if s not in ("S03", "S05")]
    assert (
        st.loc[unmoved, "purpose"].tolist()
        == p.stations.set_index("station_id").loc[unmoved, "purpose"].tolist()
    )
    # one more station: the next number, not the deleted S03
    more = free + np.array([6.0, -2.0])
    r = evaluate_stations(q, np.vstack([_xy(q), more]), [*q.stations["station_id"], None])
    assert f"S{n + 2:02d}" in set(r.stations["station_id"])
    assert "S03" not in set(r.stations["station_id"])


def test_two_stations_on_one_spot_are_refused_naming_them(default_plan):
    p = default_plan
    xy, ids = _xy(p), list(p.stations["station_id"])
    with pytest.raises(InputError, match=rf"the new station would stand 0\.20 m from {ids[0]}"):
        evaluate_stations(p, np.vstack([xy, xy[0] + [0.2, 0.0]]), [*ids, None])


def test_moving_a_station_changes_its_coverage(default_plan):
    p = default_plan
    xy = _xy(p)
    k = int(p.stations["samples_met"].idxmax())
    moved = xy.copy()
    moved[k] += [4.0, 0.0]
    sid = p.stations.loc[k, "station_id"]
    q = evaluate_stations(p, moved, list(p.stations["station_id"]))
    row = q.stations.set_index("station_id").loc[sid]
    assert row["x"] == pytest.approx(xy[k, 0] + 4.0, abs=1e-6)  # m
    assert row["purpose"] == "hand"
    before = p.coverage[p.coverage["station_id"] == sid]
    after = q.coverage.set_index("sample_id").loc[before["sample_id"]]
    # the samples it served are now seen from 4 m further along: their errors change
    assert not np.allclose(after["m_x_mm"].to_numpy(), before["m_x_mm"].to_numpy(), atol=0.001)


def test_a_station_inside_a_building_is_refused_with_where(default_plan):
    b = default_plan.site.planned[0]
    centre = b.footprint.representative_point()
    with pytest.raises(InputError, match=rf"inside building {b.id}; move it onto free ground"):
        evaluate_stations(default_plan, [[centre.x, centre.y]])
    x0, y0, _, _ = b.footprint.bounds
    # beside the wall, within the tripod's clearance: how far, from what
    corner = [x0 - 0.4, y0 - 0.3]
    with pytest.raises(InputError, match=rf"stands 0\.5 m from building {b.id} \(the tripod"):
        evaluate_stations(default_plan, [corner])
    street = default_plan.site.no_go[0]
    inside = street.geometry.representative_point()
    with pytest.raises(InputError, match=f"in the no-go area {street.id}"):
        evaluate_stations(default_plan, [[inside.x, inside.y]])


def test_reoptimise_keeps_the_locked_station_and_covers_the_rest(default_plan):
    p = default_plan
    pin = _xy(p)[0] + [1.3, 0.7]  # off the 2 m grid: kept where the surveyor put it
    q = reoptimise(p, pin[None])
    hand = q.stations[q.stations["purpose"] == "hand"]
    assert len(hand) == 1
    assert hand[["x", "y"]].to_numpy()[0] == pytest.approx(pin, abs=1e-6)  # m
    assert q.meets_all
    assert "locked by hand" in q.summary()
    # ids stay: a station locked where it stands keeps its id, so does every station and
    # target where one of p's stood, and the others take numbers p never gave
    sid = p.stations["station_id"].iloc[0]
    r = reoptimise(p, _xy(p)[:1])
    locked = r.stations[r.stations["station_id"] == sid]
    assert locked[["x", "y"]].to_numpy()[0] == pytest.approx(_xy(p)[0], abs=1e-6)  # m
    _ids_stay(p, r)


def _number(ident: str) -> int:
    return int(ident[1:])


def _ids_stay(p, q) -> None:
    """Every station and target of ``q`` where one of ``p`` stood has its id; every other
    has a number above all of ``p``'s."""
    ours = q.targets[q.targets["type"] != "control"]
    for old_t, new_t, key, cols in (
        (p.stations, q.stations, "station_id", ["x", "y"]),
        (p.targets, ours, "target_id", ["x", "y", "z"]),
    ):
        old = {
            tuple(np.round(r, 3)): i
            for r, i in zip(old_t[cols].to_numpy(), old_t[key], strict=True)
        }
        top = max(_number(i) for i in old_t[key] if i[1:].isdigit())
        for r, i in zip(new_t[cols].to_numpy(), new_t[key], strict=True):
            was = old.get(tuple(np.round(r, 3)))
            if was is not None:
                assert i == was, f"{i} stands where {was} stood"
            else:
                assert _number(i) > top, f"{i} is new but its number was given before"


def test_ids_stay_through_locks_hand_stations_and_re_optimising(default_plan):
    """Delete one station and add one by hand, lock two, re-optimise: the locked and the
    hand-placed keep their ids and places, nothing of the plan is renumbered, a deleted id
    is never given again."""
    p = default_plan
    xy = _xy(p)
    gone = p.stations["station_id"].iloc[-1]
    added = xy[0] + [0.0, 9.0]
    q = evaluate_stations(p, np.vstack([xy[:-1], added]))  # one deleted, one added
    _ids_stay(p, q)
    assert gone not in set(q.stations["station_id"])
    hand_id = q.stations[q.stations["purpose"] == "hand"]["station_id"].iloc[0]
    assert _number(hand_id) > max(_number(s) for s in p.stations["station_id"])
    r = reoptimise(q, xy[[1, 2]])
    _ids_stay(q, r)
    kept = r.stations.set_index("station_id")
    for sid, pos in [(p.stations["station_id"].iloc[1], xy[1]), (hand_id, added)]:
        assert kept.loc[sid, ["x", "y"]].to_numpy(float) == pytest.approx(pos, abs=1e-6)  # m
    assert gone not in set(r.stations["station_id"])  # a deleted id is never given again


def test_a_station_added_by_hand_on_one_spot_is_said_not_moved(default_plan):
    """A station added by hand 3 m from a planned one: kept where the surveyor put it, and
    the summary names the pair closer than the crew's spacing and why it stays."""
    from sites import assert_spaced

    p = default_plan
    xy = np.vstack([_xy(p), _xy(p)[0] + [3.0, 0.0]])
    q = evaluate_stations(p, xy)
    assert len(q.stations) == len(p.stations) + 1
    assert_spaced(q)
    line = q.spacing_summary()
    assert "1 pair(s) closer than 5 m" in line and "3.0 m (placed by hand)" in line


def test_a_plan_without_its_workbench_says_so(default_plan):

    with pytest.raises(InputError, match="plan the site again"):
        evaluate_stations(copy.copy(default_plan), _xy(default_plan))


# -- targets by hand (they change the plan's workbench: a plan of their own) ----------------
BY_HAND = "Targets placed or moved by hand in this plan's edits:"


@pytest.fixture
def own_plan(default_plan):
    return copy_plan(default_plan)


def _has(targets, xyz) -> bool:
    return bool((np.abs(targets[["x", "y", "z"]].to_numpy(dtype=float) - xyz) < 1e-6).all(1).any())


def test_a_target_ruled_out_is_never_used_again(own_plan):
    p = own_plan
    gone = p.targets.set_index("target_id").loc[["T01", "T02"], ["x", "y", "z"]].to_numpy()
    q = edit_targets(p, remove=["T01", "T02"])
    assert not any(_has(q.targets, xyz) for xyz in gone)
    assert len(q.stations) == len(p.stations)
    np.testing.assert_allclose(_xy(q), _xy(p), atol=1e-6)  # m: the stations stay
    assert q.meets_all  # the network found other targets
    assert "Targets edited by hand: 2 ruled out." in q.messages
    # … and it stays out when the rest is optimised again
    r = reoptimise(q, np.empty((0, 2)))
    assert not any(_has(r.targets, xyz) for xyz in gone)


def test_a_moved_flat_target_slides_along_its_wall_and_is_used(own_plan):
    p = own_plan
    flat = p.targets[p.targets["type"] == "flat"].iloc[0]
    q = edit_targets(p, move={flat["target_id"]: (flat["x"] + 1.5, flat["y"] + 3.0)})
    assert not _has(q.targets, flat[["x", "y", "z"]].to_numpy(dtype=float))
    # the default site's first target is on a wall along E: it moves 1.5 m along it,
    # not the 3 m off it
    wall = workbench_of(p).ctx.facades
    f = int(workbench_of(p).tc.facade[workbench_of(p).seen.by_hand][0])
    a, b = wall.start[f], wall.end[f]
    new = q.targets[q.targets["facade_id"] == flat["facade_id"]][["x", "y", "z"]].to_numpy(float)
    moved = new[np.argmin(np.abs(new[:, 0] - (flat["x"] + 1.5)) + np.abs(new[:, 1] - flat["y"]))]
    d, v = b - a, moved[:2] - a
    cross = (d[0] * v[1] - d[1] * v[0]) / np.linalg.norm(d)
    assert abs(cross) < 1e-6  # m: on the wall's line
    assert moved[2] == pytest.approx(flat["z"], abs=1e-9)  # m: at its height
    assert (
        "Targets placed or moved by hand in this plan's edits: 1 of 1 used by the registration."
        in q.messages
    )


def test_a_sphere_added_by_hand_is_preferred_where_it_can_serve(own_plan):
    p = own_plan
    st = p.stations.set_index("station_id")[["x", "y"]]
    link = p.links.iloc[0]  # a third of the way along the first link: both its stations see it
    a, b = st.loc[link["station_a"]].to_numpy(float), st.loc[link["station_b"]].to_numpy(float)
    xy = a + (b - a) / 3 + 0.7
    q = edit_targets(p, add_xy=xy[None])
    z = workbench_of(p).settings.target_height_m
    assert _has(q.targets, np.array([*xy, z]))
    assert (
        "Targets placed or moved by hand in this plan's edits: 1 of 1 used by the registration."
        in q.messages
    )
    # negative control: a stand far outside every station's view serves nothing
    far = edit_targets(q, add_xy=np.array([[a[0] + 2000.0, a[1]]]))
    assert not _has(far.targets, np.array([a[0] + 2000.0, a[1], z]))
    assert (
        "Targets placed or moved by hand in this plan's edits: 1 of 2 used by the registration"
        in " ".join(far.messages)
    )


def test_bad_target_edits_say_what_is_wrong(own_plan):
    p = own_plan
    with pytest.raises(InputError, match="no target 'T99'"):
        edit_targets(p, remove=["T99"])
    b = p.site.planned[0].footprint.representative_point()
    with pytest.raises(InputError, match="stands inside building"):
        edit_targets(p, add_xy=np.array([[b.x, b.y]]))


def test_the_plan_says_which_registration_processing_its_promise_assumes(default_plan):
    """The registration error is that of one adjustment of every scan; the summary (and so
    the booklet and the report, which print it) says so, and that pairwise registration
    along the links can do worse."""
    from planner.app.report import ReportContent
    from planner.pipeline.engine.tables import PROCESSING_WORDS

    summary = default_plan.summary()
    line = next(m for m in summary.splitlines() if m.startswith("Registration error: worst"))
    assert line.endswith(PROCESSING_WORDS["adjustment"])
    assert "one adjustment" in line and "pair by pair" in line
    text = str(ReportContent(default_plan).assumptions().data)
    assert "pair by pair along the links" in text and "20 mm from their edges" in text


def test_one_id_everywhere_in_the_files_and_targets_numbered_as_they_are_set_up(default_plan):
    """The stations' ids are the same in every file a crew or the office reads, listed in
    order; targets are T01, T02 … in the order they are first set up."""
    import io
    import re

    import ezdxf
    import pandas as pd

    from planner.pipeline.documents.export import render

    p = default_plan
    files = render(p)
    n = len(p.stations)
    ids = [f"S{k:02d}" for k in range(1, n + 1)]
    assert pd.read_csv(io.StringIO(files["stations.csv"]))["station_id"].tolist() == ids
    assert pd.read_csv(io.StringIO(files["route.csv"]))["station_id"].tolist() == ids
    stake = pd.read_csv(io.StringIO(files["stakeout.csv"]))
    assert stake.loc[stake["code"] == "STN", "point_id"].tolist() == ids
    doc = ezdxf.read(io.StringIO(files["plan.dxf"]))
    drawn = [
        a.dxf.text
        for ref in doc.modelspace().query("INSERT[name=='STATION']")
        for a in ref.attribs
        if a.dxf.tag == "ID"
    ]
    assert sorted(drawn) == ids
    assert set(ids) <= set(re.findall(r"<name>(S\d\d)</name>", files["plan.kml"]))
    set_up = " ".join(
        pd.read_csv(io.StringIO(files["route.csv"]), keep_default_na=False)["targets_to_set"]
    ).split()
    flat = [t for t in set_up if t.startswith("T")]
    assert flat == [f"T{k:02d}" for k in range(1, len(flat) + 1)]
    targets = pd.read_csv(io.StringIO(files["targets.csv"]))
    assert targets["target_id"].tolist()[: len(flat)] == flat


def test_a_re_plan_keeps_the_edits_that_can_still_stand_and_says_the_others(default_plan):
    """The site planned again after a no-go area was drawn over a locked station: the other
    locked station keeps its id and place, the blocked one is left out and said (its id and
    what is in the way), and the new stations take numbers never given."""
    from dataclasses import replace

    import shapely

    from planner.pipeline.engine.planning import plan
    from planner.pipeline.engine.whatif import user_edits
    from planner.site import Area

    p = default_plan
    xy, ids = _xy(p), list(p.stations["station_id"])
    given, keep = user_edits(p, xy[:2])
    assert len(keep) == 2 and given.last_station >= max(_number(s) for s in ids)
    road = Area("road", shapely.Point(xy[0]).buffer(3.0))
    site = replace(p.site, no_go=[*p.site.no_go, road])
    q = plan(site, p.scanner, p.requirements, p.settings, locked=keep, given=given)
    st = q.stations.set_index("station_id")
    assert st.loc[ids[1], ["x", "y"]].to_numpy(float) == pytest.approx(xy[1], abs=1e-6)  # m
    assert ids[0] not in st.index or np.hypot(*(st.loc[ids[0], ["x", "y"]] - xy[0])) < 1e-3
    said = [m for m in q.messages if m.startswith("Not kept from the plan before")]
    assert said == [f"Not kept from the plan before: {ids[0]} (in the no-go area road)."]
    _ids_stay(p, q)
