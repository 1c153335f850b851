"""Cloud-to-cloud and hybrid registration in the plan: the surfaces stations share, the
straight street the model must show free, and the plans of the default site in each mode."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from sites import E0, N0, rect, square_site
from sites import run_cli as _cli

from planner.pipeline.engine.judge import REGISTRATION_GOAL, workbench_of
from planner.pipeline.engine.planning import plan
from planner.pipeline.evaluation.evaluate import Context
from planner.pipeline.geometry.facades import build_facades
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.pipeline.network import clouds
from planner.pipeline.network.layout import Layout
from planner.scanner import Scanner, catalogue
from planner.site import Building, Site

SCANNER = Scanner.from_name("leica-4mm-60urad")


def _surfaces(site: Site, station_xy: np.ndarray, window_share: float = 0.0, **settings):
    """The patches the stations see (plain walls unless ``window_share`` is given)."""
    st = PlanSettings(registration="cloud", window_share=window_share, **settings)
    fac = build_facades(site, st.sample_spacing_m, st.sample_height_step_m)
    ctx = Context.build(site, fac, SCANNER, Requirements(), st, 120.0)
    return ctx, clouds.surfaces(ctx, np.asarray(station_xy, dtype=float) + np.array([E0, N0]))


def test_a_straight_street_leaves_the_shift_along_it_free_and_a_corner_fixes_it():
    """Two stations 20 m apart in front of a 120 m terrace (its south wall and the street):
    the link overlaps well but is free east-west (its start, the operator's picking, then
    holds it: 30 mm); two stations at its end that both see the end wall too are fixed — the
    terrace's far wall, seen from its end at a grazing incidence, is beyond the scanner's
    reach at that incidence (planner.signal) and adds nothing. The windows' 150 mm reveals
    tie the pair along the street only where the registration thins the clouds finely
    enough to see them as planes (20 mm), not at the default 100 mm."""
    site = Site([Building("row", rect(0, 0, 120, 12), 15.0)])
    ctx, surf = _surfaces(site, [[40, -8], [60, -8], [125, -6], [132, -12]])
    along = clouds.cloud_link(ctx, surf, 0, 1)
    assert along.overlap_pct > 40.0  # %
    assert not along.fixed and along.weakest == "free: shift 090°/270° (east-west)"
    assert np.sqrt(along.cov[0, 0]) == pytest.approx(30.0, abs=0.1)  # mm: where it started
    corner = clouds.cloud_link(ctx, surf, 2, 3)
    assert corner.fixed
    sd = np.sqrt(np.diag(corner.cov))
    assert sd[:3] == pytest.approx([0.30, 0.36, 0.14], abs=0.02)  # mm
    # with windows (the parametric facade): the reveals beyond both stations tie the pair
    # along the street on clouds thinned to 20 mm, not to 100 mm
    ctx, surf = _surfaces(site, [[40, -8], [60, -8]], window_share=0.25, cloud_spacing_mm=20.0)
    along = clouds.cloud_link(ctx, surf, 0, 1)
    assert along.fixed and np.sqrt(along.cov[0, 0]) < 1.0  # mm east-west
    ctx, surf = _surfaces(site, [[40, -8], [60, -8]], window_share=0.25)
    assert not clouds.cloud_link(ctx, surf, 0, 1).fixed


@pytest.mark.parametrize("pair", [[[20, 20], [15, 25]], [[38, -8], [34, -12]]])
def test_the_prediction_does_not_move_with_the_planners_sampling(pair):
    """A link between two set-ups at a corner of the L (its inner corner, its outer one)
    predicts the same error whether the planner cuts the walls into samples of 1, 2 or
    3 m: the points and the floor's cells of a patch both scale with its area."""
    from sites import l_site

    sd = []
    for m in (1.0, 2.0, 3.0):
        ctx, surf = _surfaces(l_site(), pair, sample_spacing_m=m, sample_height_step_m=m)
        link = clouds.cloud_link(ctx, surf, 0, 1)
        assert link.fixed
        sd.append(np.sqrt(np.diag(link.cov)[:3]))
    np.testing.assert_allclose(sd[0], sd[2], rtol=0.10)  # mm
    np.testing.assert_allclose(sd[1], sd[2], rtol=0.10)  # mm


def test_the_overlap_counts_surface_not_points():
    """A station's ground next to it holds most of its points but not most of its surface:
    two stations 10 m apart along a wall overlap by more than half."""
    site = Site([Building("row", rect(0, 0, 120, 12), 15.0)])
    _, surf = _surfaces(site, [[40, -8], [50, -8]])
    ov = clouds.overlap_matrix(surf)
    assert ov[0, 1] == pytest.approx(ov[1, 0], abs=1e-9)  # % symmetric
    assert 50.0 < ov[0, 1] < 100.0  # %
    # the sparse overlap of the search for linking stations says the same, whether the
    # candidates come at once or a few at a time, whatever the threshold
    ctx, _ = _surfaces(site, [[40, -8]])
    xy = np.array([[40, -8], [50, -8], [70, -20], [130, -5]], dtype=float) + np.array([E0, N0])
    cache = clouds.SurfaceCache(ctx)
    dense = clouds.overlap_matrix(cache.take(np.arange(4), xy))
    assert 0.0 < dense[0, 2] < dense[0, 1]  # %
    for pct in (dense[0, 1] - 0.5, dense[0, 2] + 0.5, dense[0, 2] - 0.5, 10.0):
        np.testing.assert_array_equal(cache.overlapping(np.arange(4), xy, pct), dense >= pct)
        np.testing.assert_array_equal(
            cache.overlapping([3, 1], xy, pct), (dense >= pct)[[3, 1]][:, [3, 1]]
        )
    fresh = clouds.SurfaceCache(ctx)
    fresh.overlapping([0, 1], xy, 10.0)  # two first, then the others joining them
    np.testing.assert_array_equal(
        fresh.overlapping([2, 0, 3, 1], xy, 10.0), (dense >= 10.0)[[2, 0, 3, 1]][:, [2, 0, 3, 1]]
    )


@pytest.fixture(scope="module")
def modes():
    """The default site in each mode, its cloud links by the model alone (their rehearsal
    is tested in tests/test_linkcheck.py); "fine": cloud to cloud on clouds thinned to
    20 mm, "plain": plain walls."""
    model = {"link_check": "model"}
    out = {
        m: plan(settings=PlanSettings(registration=m, **model))
        for m in ("targets", "cloud", "hybrid")
    }
    out["fine"] = plan(settings=PlanSettings(registration="cloud", cloud_spacing_mm=20.0, **model))
    out["plain"] = plan(settings=PlanSettings(registration="cloud", window_share=0.0, **model))
    return out


def test_hybrid_meets_the_default_site_with_fewer_targets(modes):
    t, h = modes["targets"], modes["hybrid"]
    assert t.meets_all and h.meets_all
    assert len(h.targets) < len(t.targets)
    cloud = h.links[h.links["kind"] == "cloud"]
    assert len(cloud) >= 1
    assert (cloud["overlap_pct"] >= PlanSettings().min_overlap_pct).all()
    # a cloud link is kept where it is within the registration goal (0.3 × the 5 mm limit)
    goal = REGISTRATION_GOAL * 5.0
    assert (cloud["targets_placed"] == 0).all() and (cloud["link_rms_mm"] <= goal).all()  # mm
    assert any(m.startswith("Registration: hybrid") for m in h.messages)


def test_cloud_alone_on_plain_walls_says_which_stations_it_cannot_tie_and_why(modes):
    """Planned as plain planes (--window-share 0), the default building's walls are
    straight: most pairs of stations share one wall and the ground, which leave the shift
    along the wall free; the plan says so and how to fix it (no targets are placed). So do
    the walls with the parametric facade's reveals on clouds thinned to 100 mm (the reveals
    too shallow to be planes at that spacing); on clouds thinned to 20 mm the same site is
    one network meeting every sample, and the plan says what it assumed of the walls."""
    c = modes["plain"]
    assert len(c.targets) == 0
    assert (c.links["kind"] == "cloud").all()
    msg = next(m for m in c.messages if m.startswith("Registration: cloud to cloud"))
    assert "leave a direction free" in msg and "--registration hybrid" in msg
    assert not c.meets_all
    assert any("Cloud links count the walls as plain planes" in m for m in c.messages)
    assert not modes["cloud"].meets_all
    r = modes["fine"]
    assert r.meets_all and len(r.targets) == 0
    assert any("form one registration network" in m for m in r.messages)
    assert any("openings of 1.2 × 1.5 m on 25% of the wall, 150 mm deep" in m for m in r.messages)


def test_each_cloud_link_is_judged_by_its_own_error(modes):
    """Links into one station from different parents each have their own error at its facade
    points, whatever order they are asked in (a cache once kept the first one asked for every
    parent: the layout depended on the order of the search)."""

    c = modes["cloud"]
    wb, net = workbench_of(c), c.network
    stations = [int(s) for s in net.stations]
    lay = Layout(wb.ctx, wb.seen, wb.pool, stations, {}, goal_mm=1.0)
    checked = 0
    for child in range(lay.k):
        parents = [a for a in range(lay.k) if a != child and lay.cloud(a, child) is not None]
        for a in reversed(parents):  # the other order from the tree search's
            own = lay.error_at_probes(lay.cloud(a, child).cov, child)
            assert lay.link(a, child)[1] == pytest.approx(own, rel=1e-12)  # mm
        checked += len(parents) > 1
        errors = {round(lay.link(a, child)[1], 6) for a in parents}
        assert len(parents) < 2 or len(errors) > 1  # different parents, different errors
    assert checked >= 3


def test_the_scanner_profile_names_its_workflow():
    assert catalogue()["leica-rtc360"].registration == "hybrid"
    st = PlanSettings()
    assert st.registration_for(catalogue()["leica-rtc360"]) == "hybrid"
    assert st.registration_for(SCANNER) == "targets"
    assert (
        PlanSettings(registration="cloud").registration_for(catalogue()["leica-rtc360"]) == "cloud"
    )


def test_the_command_line_takes_the_mode_and_refuses_a_wrong_one(tmp_path):
    code, _, err = _cli("plan", "--registration", "icp", "--out", str(tmp_path / "x"), "-q")
    assert code == 2 and "--registration" in err
    fast = ["--grid-m", "4", "--sample-spacing-m", "4", "--sample-height-step-m", "4", "-q"]
    code, _, _ = _cli(
        "plan", "--registration", "hybrid", "--out", str(tmp_path / "p"), "--no-booklet", *fast
    )
    assert code in (0, 1)
    links = pd.read_csv(tmp_path / "p" / "links.csv")
    assert set(links["kind"]) <= {"cloud", "targets"}
    assert "hybrid" in (tmp_path / "p" / "summary.txt").read_text()


def _corner_network(min_overlap_pct: float):
    """The cloud-to-cloud network of two stations 6 m and 62 m out along the diagonal off
    one corner of a 40 m square building: both see its two walls there, but their scans
    overlap by a third only (the ground near each is the other's blind spot)."""
    from planner.pipeline.engine.judge import round_network
    from planner.pipeline.engine.planning import _prepare

    st = PlanSettings(registration="cloud", min_overlap_pct=min_overlap_pct)
    wb = _prepare(square_site(40.0, 12.0), SCANNER, Requirements(), st, lambda *_: None)
    cand = wb.pool
    ends = [
        int(np.argmin(np.hypot(*(cand - np.array([E0 + x, N0 + y])).T)))
        for x, y in ((-6.0, -6.0), (-62.0, -62.0))
    ]
    return round_network(wb.ctx, cand, wb.seen, np.array(ends))


def test_scans_that_overlap_too_little_are_chained_by_linking_stations_cloud_to_cloud():
    """Linking stations are found by overlap and strength (not by targets) where scans are
    registered cloud to cloud; the negative control asks an overlap no pair of scans has
    (100 %): then nothing links, and the plan says the stations cannot be tied."""
    net = _corner_network(50.0)
    assert net.overlap[0, 1] < 50.0  # % the two alone cannot be linked
    assert net.error.tied.all()
    assert net.n_link_stations >= 1 and not net.targets
    assert all(lk.info is not None for lk in net.links)  # every link cloud to cloud
    ov = net.overlap
    for lk in net.links:
        assert ov[lk.parent, lk.child] >= 50.0  # %
        assert net.clouds[(lk.parent, lk.child)].fixed
    never = _corner_network(100.0)
    assert never.n_link_stations == 0 and not never.links
    assert "cannot be tied" in never.message


def test_a_cloud_to_cloud_plan_scans_in_an_order_that_registers_each_scan_on_arrival(modes):
    """Every scan after the first comes after one it is linked to (a group's first scan
    excepted), and the route and booklet name it."""
    h = modes["hybrid"]
    t = h.route.table
    assert t["registers_to"].iloc[0] == ""
    assert (t["registers_to"].iloc[1:] != "").all()
    order = {s: n for n, s in enumerate(t["station_id"])}
    for sid, earlier in zip(t["station_id"], t["registers_to"], strict=True):
        for o in earlier.split():
            assert order[o] < order[sid]
    assert "Scan order: every scan is registered to one scanned before it." in h.route.summary()


def test_the_registered_order_moves_only_what_it_must():
    from planner.pipeline.field.route import _registered_order

    # a chain 0-1-2-3 visited 0, 2, 1, 3: station 2 waits for 1; 4 stands alone
    nb = [{1}, {0, 2}, {1, 3}, {2}, set()]
    order = _registered_order(np.array([0, 2, 4, 1, 3]), nb, None)
    assert order.tolist() == [0, 4, 1, 2, 3]
    assert _registered_order(np.array([0, 1, 2, 3, 4]), nb, None).tolist() == [0, 1, 2, 3, 4]


def test_candidates_that_see_no_patch_have_an_empty_union():
    """Scans that hold no patch (a candidate hemmed in) make surfaces of no patch, not an
    error."""
    from planner.pipeline.network.clouds import _sorted_union

    empty = np.empty(0, dtype=np.int64)
    assert _sorted_union([]).tolist() == _sorted_union([empty, empty]).tolist() == []
    assert _sorted_union([np.array([5, 2]), empty, np.array([2, 9])]).tolist() == [2, 5, 9]
