"""Station planning: visibility, courtyards, grazing facades, infeasible requirements, the
optimiser on a case solved by hand, registration, and the consistency of every output row."""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np
import pandas as pd
import pytest
import shapely
from sites import E0, N0, courtyard_site, l_site, multipolygon_site, rect, square_site

from planner import (
    Scanner,
    facade_point_spacing_mm,
    height_rms,
    min_target_size_mm,
    planimetric_rms,
    point_spacing_mm,
    sight_geometry,
)
from planner.accuracy3d import point_rms_3d
from planner.pipeline.documents.export import coverage_csv
from planner.pipeline.engine.judge import workbench_of
from planner.pipeline.engine.planning import plan
from planner.pipeline.evaluation.evaluate import Context, evaluate_stations
from planner.pipeline.geometry.facades import build_facades
from planner.pipeline.geometry.visibility import SIGHT_CLEARANCE_M, clear_height
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.pipeline.inputs.resolved import reach_m
from planner.polar import incidence_deg
from planner.site import Building, ControlPoint, Obstacle, Site

PAPER = Scanner.from_name("leica-4mm-60urad")
LOOSE = Requirements(max_xy_mm=20.0, max_z_mm=20.0)


def views(site: Site, station_local_xy, req=LOOSE, settings=None, scanner=PAPER):
    """(samples × stations) dict of metrics for stations given in local coordinates."""
    settings = settings or PlanSettings(sample_spacing_m=1.0, sample_height_step_m=1.0)
    fac = build_facades(site, settings.sample_spacing_m, settings.sample_height_step_m)
    ctx = Context.build(site, fac, scanner, req, settings, reach_m(scanner, req, settings))
    st = np.array(station_local_xy, dtype=float) + np.array([E0, N0])
    return fac, evaluate_stations(ctx, st)


def test_self_occlusion_station_behind_the_building_sees_nothing_of_the_far_facade():
    site = square_site(20.0, 10.0)
    fac, m = views(site, [(10.0, -15.0)])
    north = fac.normal[fac.facade][:, 1] > 0.5
    south = fac.normal[fac.facade][:, 1] < -0.5
    assert not m["view"][north, 0].any()
    assert m["view"][south, 0].all()


def test_self_occlusion_by_the_buildings_own_wing():
    """Station at (40, 5), east of the L's long bar: on the wing's east facade (x = 10,
    y 10–30) the sight line to y = 12 runs through the bar, to y = 28 it clears the corner
    (30, 10)."""
    site = l_site(height=12.0)
    fac, m = views(site, [(40.0, 5.0)])
    on_wing = (np.abs(fac.xy[:, 0] - (E0 + 10)) < 1e-6) & (fac.normal[fac.facade][:, 0] > 0.5)
    low_y = on_wing & (fac.xy[:, 1] < N0 + 13)
    high_y = on_wing & (fac.xy[:, 1] > N0 + 27)
    assert low_y.any() and high_y.any()
    assert not m["view"][low_y, 0].any()
    assert m["view"][high_y, 0].all()


def test_occlusion_by_an_obstacle_tall_and_low():
    site = square_site(
        20.0,
        10.0,
        obstacles=[
            Obstacle("wall", rect(5, -10.1, 15, -9.9), 1.0, "wall"),
            Obstacle("shed", rect(-10, -12, 0, -8), 20.0, "shed"),
        ],
    )
    # the low wall halfway to the facade hides only the foot of the facade:
    # crossing its far edge at t = 10.1/20 ... z_clear = 1.5 + (1.0 + c - 1.5) / t, the wall
    # raised by the sight-line clearance c
    z = clear_height(
        np.array([[E0 + 10, N0 - 20]]),
        1.5,
        np.array([[E0 + 10, N0 + 0.02]]),
        np.array([[E0 + 5, N0 - 9.9, E0 + 15, N0 - 9.9]]),
        np.array([1.0]),
    )
    c = SIGHT_CLEARANCE_M
    assert z[0] == pytest.approx(1.5 - (0.5 - c) / ((20 - 9.9) / 20.02), abs=1e-9)  # m, 0.55
    fac, m = views(site, [(10.0, -20.0), (-6.0, -25.0)])
    col = (np.abs(fac.xy[:, 0] - (E0 + 10.5)) < 1e-6) & (np.abs(fac.xy[:, 1] - N0) < 1e-6)
    assert m["view"][col & (fac.z < 0.5), 0].sum() == 0  # z = 0.5 is hidden (0.55 clears)
    assert m["view"][col & (fac.z > 0.6), 0].all()
    # the 20 m shed hides the south-west corner from a station behind it, up to the top
    behind = (np.abs(fac.xy[:, 1] - N0) < 1e-6) & (fac.xy[:, 0] < E0 + 1.5)
    assert not m["view"][behind, 1].any()


COURTYARD_SETTINGS = PlanSettings(grid_m=2.0, sample_spacing_m=3.0, sample_height_step_m=3.0)


def test_a_closed_courtyard_is_scanned_from_inside_but_cannot_be_tied_without_control():
    site = courtyard_site(court=20.0, height=9.0)
    p = plan(site, PAPER, Requirements(max_xy_mm=6, max_z_mm=6), COURTYARD_SETTINGS)
    hole = shapely.Polygon(site.buildings[0].footprint.interiors[0])
    inside = shapely.contains_xy(hole, p.stations["x"], p.stations["y"])
    assert inside.sum() >= 1 and (~inside).sum() >= 1
    court = p.facades[p.facades["courtyard"]]
    assert len(court) == 4 and all(court["stations"].str.len() > 0)
    # no target is seen from inside and outside: the courtyard's samples are not met, and
    # the plan says why and what to do
    assert not p.meets_all
    inner = p.coverage[p.coverage["facade_id"].isin(court["facade_id"])]
    assert (~inner["meets"]).all()
    assert (
        inner["reason"]
        .str.contains(
            r"stands in the courtyard enclosed by court, which no registration reaches: mark its "
            "gateway"
        )
        .all()
    )
    assert inner["reg_m_x_mm"].isna().all()
    assert any("cannot be tied" in m and "--control" in m for m in p.messages)
    # no station is added inside for the registration error: none could be tied there
    assert not (inside & (p.stations["purpose"] == "registration")).any()


def test_control_points_tie_a_closed_courtyard_to_the_site_network():
    court = courtyard_site(court=20.0, height=9.0)
    # four control points in the courtyard (brought in by a traverse), three outside
    marks = [
        (11, 11, 1.0),
        (29, 12, 3.0),
        (28, 29, 2.0),
        (12, 28, 4.0),
        (-8, -8, 1),
        (48, -6, 2),
        (-6, 48, 3),
    ]
    control = [
        ControlPoint(f"C{i}", (E0 + x, N0 + y, z), 1.0) for i, (x, y, z) in enumerate(marks, 1)
    ]
    site = replace(court, control=control)
    p = plan(site, PAPER, Requirements(max_xy_mm=6, max_z_mm=6), COURTYARD_SETTINGS)
    assert p.meets_all
    assert p.links["station_a"].eq("control").any()
    assert any("tied to the site network through" in m for m in p.messages)
    cov = p.coverage[~p.coverage["party_wall"]]
    # the control points' own 1 mm RMS reaches every sample: none is registered better
    assert (cov[["reg_m_x_mm", "reg_m_y_mm", "reg_m_z_mm"]].max(axis=1) > 0.5).all()
    used = p.targets[p.targets["type"] == "control"]
    assert set(used["target_id"]) <= {c.id for c in control} and len(used) >= 3


def test_too_small_courtyard_is_reported_unmet_with_the_reason():
    site = courtyard_site(court=1.5, height=9.0)
    p = plan(
        site,
        PAPER,
        Requirements(max_xy_mm=6, max_z_mm=6),
        PlanSettings(sample_spacing_m=3.0, sample_height_step_m=3.0),
    )
    court_ids = set(p.facades.loc[p.facades["courtyard"], "facade_id"])
    unmet = p.unmet
    inner = unmet[unmet["facade_id"].isin(court_ids)]
    assert set(inner["facade_id"]) == court_ids
    assert (
        inner["reason"]
        == "no ground station sees it: it needs an elevated station (a lift or a mast)"
    ).all()
    assert (inner["elevated_station"] == "above the ground").all()
    assert any("do not meet the requirements" in m for m in p.messages)
    assert unmet["facade_id"].isin(court_ids).all()  # the outer walls are met


def test_no_station_is_proposed_on_a_roof_whose_height_was_made_up():
    """The same wall above the annex's roof, the annex's 7 m now a height the site assumed
    (the file gave none): the plan does not build on it — no elevated station on that roof
    is proposed, and the reason says the height is assumed and asks for it."""
    from dataclasses import replace

    from planner.pipeline.engine.explain import suggestions
    from planner.sitecheck import SiteNote
    from planner.siteio import default_site

    site = default_site()
    site = replace(site, notes=[*site.notes, SiteNote("no-height", ("annex",), "default", "7 m")])
    assert site.assumed_heights == {"annex"}
    p = plan(site, "trimble-x7", settings=PlanSettings(registration_error=False))
    unmet = p.unmet
    assert set(unmet["facade_id"]) == {"main-f09"} and (unmet["elevated_station"] == "").all()
    assert unmet["reason"].str.contains("over 'annex', whose height is assumed").all()
    assert not any("roof of annex" in h for h in suggestions(p))


def test_a_wall_above_a_lower_neighbours_roof_needs_an_elevated_station():
    """The default site's east wall above the annex's 7 m roof (12 m deep): the samples
    at 8.4 m are seen from the ground only over the roof's edge, steeply; with the X7, each
    scan levelled on its own (the registration not counted), none is met (best m_z 5.2 mm).
    They need a station on the annex's roof: no best-effort ground station is spent on them
    (two were), and no longer-range scanner is offered."""
    from planner.pipeline.engine.explain import explain_unmet, suggestions
    from planner.siteio import default_site

    p = plan(default_site(), "trimble-x7", settings=PlanSettings(registration_error=False))
    unmet = p.unmet
    assert set(unmet["facade_id"]) == {"main-f09"}
    assert unmet["z"].to_numpy() == pytest.approx(8.44, abs=0.01)  # m
    assert (unmet["elevated_station"] == "roof of annex").all()
    assert unmet["reason"].str.endswith("it needs an elevated station (e.g. on that roof)").all()
    assert not (p.stations["purpose"] == "best-effort").any()
    assert not any(m.startswith("Best effort:") for m in p.messages)
    table = explain_unmet(p)
    assert table["quantity"].tolist() == ["needs an elevated station"]
    hints = suggestions(p)
    assert hints[0].startswith("an elevated station on the roof of annex for 3 sample(s)")
    assert not any("a scanner that keeps these limits farther out" in h for h in hints)
    # a sample in the open, not above a roof, is not marked
    assert (p.coverage.loc[p.coverage["meets"], "elevated_station"] == "").all()


def test_facade_reachable_only_at_grazing_angles():
    """A 40 m facade facing a 1.5 m alley: with a 1 m clearance no station fits in the alley,
    so the middle of the facade is seen only from the alley's ends, at grazing angles."""
    a = Building("A", rect(0, 0, 40, 10), 6.0)
    b = Building("B", rect(0, 11.5, 40, 21.5), 6.0, planned=False)
    site = Site([a, b])
    settings = PlanSettings(sample_spacing_m=4.0, sample_height_step_m=3.0)
    strict = plan(site, PAPER, Requirements(max_xy_mm=10, max_z_mm=10, max_gamma_deg=60), settings)
    alley = strict.coverage[(strict.coverage["y"] == N0 + 10) & ~strict.coverage["party_wall"]]
    middle = alley[(alley["x"] > E0 + 10) & (alley["x"] < E0 + 30)]
    assert not middle["meets"].any()
    best_gamma = middle["reason"].str.extract(r"best achievable γ ([\d.]+)")[0].astype(float)
    assert (best_gamma > 60).all() and (best_gamma < 90).all()
    lax = plan(site, PAPER, Requirements(max_xy_mm=10, max_z_mm=10, max_gamma_deg=88), settings)
    alley_lax = lax.coverage[(lax.coverage["y"] == N0 + 10)]
    assert alley_lax["meets"].sum() > alley["meets"].sum()
    assert (alley_lax.loc[alley_lax["meets"], "gamma_deg"] > 60).any()


def test_infeasible_tolerance_does_not_crash_and_says_what_is_achievable():
    p = plan(
        square_site(),
        PAPER,
        Requirements(max_xy_mm=0.5, max_z_mm=5),
        PlanSettings(sample_spacing_m=4.0, sample_height_step_m=5.0, model="paper"),
    )
    assert not p.meets_all
    assert len(p.unmet) == len(p.coverage)
    # best effort, not zero stations: the plan that comes closest, said as such
    assert len(p.stations) > 0
    assert any(m.startswith("Best effort:") for m in p.messages)
    n_best = int(
        p.messages[[m.startswith("Best effort:") for m in p.messages].index(True)].split()[2]
    )
    assert (p.stations["purpose"] == "best-effort").sum() == n_best  # marked as such
    assert "best effort, for samples no position meets" in p.summary()
    # best achievable m_y with m_S = 4 mm: 4·cos 75° = 1.04 mm at the grazing limit
    assert p.unmet["reason"].str.contains(r"best achievable m_y 1\.0 mm > 0\.5 mm").all()
    assert p.solver.status == "nothing to cover"
    # the map says so: grey positions, no colour bar scaled on nothing (it ran -0.1..0.1)
    from planner.app.maps import plot_plan_map

    fig = plot_plan_map(p)
    assert len(fig.axes) == 1
    names = fig.legends[0].get_texts() if fig.legends else fig.axes[0].get_legend().get_texts()
    names = [t.get_text() for t in names]
    assert "candidate position (none meets a sample as asked)" in names
    assert "station (best effort, for samples no position meets)" in names
    assert not any("covering" in n or "to cover" in n for n in names)


def test_party_wall_is_reported_not_demanded():
    a = Building("A", rect(0, 0, 20, 10), 12.0)
    b = Building("B", rect(20, 0, 30, 10), 6.0, planned=False)
    p = plan(
        Site([a, b]),
        PAPER,
        Requirements(max_xy_mm=6, max_z_mm=6),
        PlanSettings(sample_spacing_m=2.0, sample_height_step_m=2.0),
    )
    east = p.coverage[p.coverage["x"] == E0 + 20]
    assert east.loc[east["z"] < 6, "party_wall"].all()
    assert not east.loc[east["z"] > 6, "party_wall"].any()  # above the neighbour's roof
    assert p.meets_all
    assert int(p.facades["party_wall_samples"].sum()) == int(east["party_wall"].sum()) == 15
    csv = coverage_csv(p)
    party_ids = east.loc[east["party_wall"], "sample_id"]
    assert not any(f",{sid}," in csv for sid in party_ids)  # party rows are not in the CSV
    assert sum(f",{sid}," in csv for sid in east.loc[~east["party_wall"], "sample_id"]) == 15


def test_party_walls_are_not_evaluated():
    """A party wall is never scanned: the evaluation skips it (none of its samples met)."""
    from planner.pipeline.evaluation.evaluate import evaluate_candidates

    a = Building("A", rect(0, 0, 20, 10), 12.0)
    b = Building("B", rect(20, 0, 30, 10), 6.0, planned=False)
    st = PlanSettings(sample_spacing_m=2.0, sample_height_step_m=2.0)
    site, req = Site([a, b]), Requirements(max_xy_mm=6, max_z_mm=6)
    fac = build_facades(site, st.sample_spacing_m, st.sample_height_step_m)
    ctx = Context.build(site, fac, PAPER, req, st, reach_m(PAPER, req, st))
    party = ctx.facades.party_wall
    assert party.sum() == 15
    cand = np.array([[E0 + 40.0, N0 + 5.0], [E0 + 10.0, N0 - 15.0]])
    ev = evaluate_candidates(ctx, cand)
    assert ev.evaluated.all()
    assert ev.ok[np.flatnonzero(party)].nnz == 0  # east of A: the party wall is not met
    assert ev.ok[np.flatnonzero(~party & (ctx.facades.xy[:, 0] == E0 + 20))].nnz > 0


def test_a_context_copied_with_other_limits_shares_one_count_of_the_kept_clear_heights():
    """The best-effort relaxation copies the plan's context with other limits; the clear
    heights both keep are one store with one count, so the cap (MAX_KEPT_CLEAR) holds for
    the plan, not once per copy."""
    from dataclasses import replace

    from planner.pipeline.evaluation import evaluate as ev_mod

    a = Building("A", rect(0, 0, 20, 10), 12.0)
    st = PlanSettings(sample_spacing_m=2.0, sample_height_step_m=2.0)
    site, req = Site([a]), Requirements(max_xy_mm=6, max_z_mm=6)
    fac = build_facades(site, st.sample_spacing_m, st.sample_height_step_m)
    ctx = Context.build(site, fac, PAPER, req, st, reach_m(PAPER, req, st))
    relaxed = replace(ctx, limits={k: v * 2 for k, v in ctx.limits.items()})
    cand = np.array([[E0 + 10.0, N0 - 15.0], [E0 + 5.0, N0 - 10.0]])
    ctx.clear_heights(0, cand, keep=True)
    relaxed.clear_heights(1, cand, keep=True)
    assert relaxed._clear is ctx._clear
    cols = len(ctx.cols_of[0]) + len(ctx.cols_of[1])
    assert ctx._clear.values == 2 * cols  # both counted once, in one place
    store = ev_mod.ClearanceStore()
    store.values = ev_mod.MAX_KEPT_CLEAR - 1
    store.keep((0, b""), ctx.clear_heights(0, cand), 2)
    assert not store.kept  # over the cap: not kept


def test_many_short_edges_and_multipolygons():
    tower = Site([Building("tower", shapely.Point(E0, N0).buffer(10.0, quad_segs=16), 20.0)])
    fac = build_facades(tower)
    assert 16 <= fac.n_facades <= 64
    centre = np.array([E0, N0])
    mid = (fac.start + fac.end) / 2
    assert ((mid - centre) * fac.normal).sum(axis=1).min() > 0  # all outward
    p = plan(
        multipolygon_site(),
        PAPER,
        Requirements(max_xy_mm=6, max_z_mm=6),
        PlanSettings(sample_spacing_m=3.0, sample_height_step_m=4.0),
    )
    assert p.meets_all and len(p.facades) == 8


def _normals(p):
    f = p.facades.set_index("facade_id")
    v = np.column_stack([f["x1"] - f["x0"], f["y1"] - f["y0"]])
    return pd.DataFrame(
        np.column_stack([v[:, 1], -v[:, 0]]) / np.hypot(*v.T)[:, None],
        index=f.index,
        columns=["nx", "ny"],
    )


@pytest.fixture(scope="module")
def rich_plan():
    """The default site with a ppm scanner and station RMS, so every term of eq. 2/4 acts."""
    sc = Scanner(
        name="ppm",
        range_rms_mm=2.0,
        range_ppm=100.0,
        angle_rms_arcsec=10.0,
        vertical_angle_rms_arcsec=14.0,
        max_range_m=150.0,
    )
    return plan(
        None,
        sc,
        Requirements(max_xy_mm=(4.0, 4.5), max_z_mm=4.0, max_gamma_deg=70, max_spacing_mm=12.0),
        PlanSettings(station_rms_mm=(1.0, 1.5), sample_spacing_m=3.0, sample_height_step_m=3.0),
    )


def test_coverage_rows_recomputed_from_coordinates_with_the_science_layer(rich_plan):
    p = rich_plan
    cov = p.coverage[p.coverage["station_id"] != ""].join(_normals(p), on="facade_id")
    st = p.stations.set_index("station_id").loc[cov["station_id"]]
    g = sight_geometry(
        np.column_stack([st["x"], st["y"], st["instrument_height_m"]]),
        cov[["x", "y", "z"]].to_numpy(),
        cov[["nx", "ny"]].to_numpy(),
    )
    assert p.settings.model == "3d" and p.settings.incidence_noise
    m_x, m_y, m_z = point_rms_3d(
        g.slope_distance_m,
        g.gamma_deg,
        g.nu_deg,
        p.scanner,
        station_rms_mm=(1.0, 1.5),
        incidence_noise=True,
    )
    np.testing.assert_allclose(
        cov["incidence_deg"], incidence_deg(g.gamma_deg, g.nu_deg), atol=1e-6
    )  # deg
    np.testing.assert_allclose(cov["distance_m"], g.distance_m, atol=1e-9)  # m
    np.testing.assert_allclose(cov["slope_distance_m"], g.slope_distance_m, atol=1e-9)  # m
    np.testing.assert_allclose(cov["gamma_deg"], g.gamma_deg, atol=1e-6)  # deg
    np.testing.assert_allclose(cov["nu_deg"], g.nu_deg, atol=1e-6)  # deg
    np.testing.assert_allclose(cov["m_x_mm"], m_x, atol=1e-9)  # mm
    np.testing.assert_allclose(cov["m_y_mm"], m_y, atol=1e-9)  # mm
    np.testing.assert_allclose(cov["m_z_mm"], m_z, atol=1e-9)  # mm
    spacing = facade_point_spacing_mm(g.slope_distance_m, g.gamma_deg, g.nu_deg, p.scanner)
    np.testing.assert_allclose(cov["spacing_mm"], spacing, rtol=1e-9)  # mm
    assert len(cov) > 100


def test_the_paper_model_reproduces_eq2_and_eq4_row_by_row():
    sc = Scanner(name="ppm", range_rms_mm=2.0, range_ppm=100.0, angle_rms_arcsec=10.0)
    p = plan(
        square_site(),
        sc,
        Requirements(max_xy_mm=4.0, max_z_mm=4.0),
        PlanSettings(model="paper", station_rms_mm=(1.0, 1.5), sample_spacing_m=3.0),
    )
    cov = p.coverage[p.coverage["station_id"] != ""].join(_normals(p), on="facade_id")
    st = p.stations.set_index("station_id").loc[cov["station_id"]]
    g = sight_geometry(
        np.column_stack([st["x"], st["y"], st["instrument_height_m"]]),
        cov[["x", "y", "z"]].to_numpy(),
        cov[["nx", "ny"]].to_numpy(),
    )
    m_x, m_y = planimetric_rms(
        g.distance_m, g.gamma_deg, sc, (1.0, 1.5), ranging_distance_m=g.slope_distance_m
    )
    np.testing.assert_allclose(cov["m_x_mm"], m_x, atol=1e-9)  # mm
    np.testing.assert_allclose(cov["m_y_mm"], m_y, atol=1e-9)  # mm
    np.testing.assert_allclose(
        cov["m_z_mm"], height_rms(g.slope_distance_m, g.nu_deg, sc), atol=1e-9
    )  # mm
    assert (cov["model"] == "paper").all() and len(cov) > 20


def test_target_sizes_recomputed_with_the_science_layer(rich_plan):
    """Every target's minimum size is the larger of Sossa's 2d / 4d rule (2d / cos θ for a
    flat target on its wall) and practice — 4 points in each checkerboard quadrant
    ((a/2)²·cos θ / d² >= 4), 20 points on a sphere's visible disc (π·D²/4 / d² >= 20) — at
    the most demanding of its stations, recomputed from the coordinates; each target names
    the rule; no checkerboard is used beyond 45° incidence."""
    p = rich_plan
    st = p.stations.set_index("station_id")
    assert len(p.targets) >= 3
    for r in p.targets.itertuples():
        need = []
        for sid in r.station_ids:
            dx, dy = st.loc[sid, "x"] - r.x, st.loc[sid, "y"] - r.y
            s = float(np.hypot(np.hypot(dx, dy), r.z - st.loc[sid, "instrument_height_m"]))
            theta = 0.0
            if r.type == "flat":
                nx, ny = np.sin(np.radians(r.facing_deg)), np.cos(np.radians(r.facing_deg))
                theta = float(np.degrees(np.arccos((dx * nx + dy * ny) / s)))
                assert theta <= 45.0 + 1e-9
            sossa = min_target_size_mm(s, r.type, scanner=p.scanner, incidence_deg=theta)
            d = float(point_spacing_mm(s, scanner=p.scanner))
            if r.type == "flat":
                practice = 2 * d * np.sqrt(4 / np.cos(np.radians(theta)))
            else:
                practice = 2 * d * np.sqrt(20 / np.pi)
            need.append((max(sossa, practice), "points" if practice > sossa else "Sossa"))
        size, rule = max(need)
        assert r.min_size_mm == pytest.approx(size, abs=1e-6)  # mm
        assert rule in r.sized_by
        assert r.size_mm >= r.min_size_mm


def test_every_meets_row_really_meets_the_requirements(rich_plan):
    p = rich_plan
    req = p.requirements
    met = p.coverage[p.coverage["meets"]]
    assert len(met) > 0.9 * (~p.coverage["party_wall"]).sum()
    assert (met["m_x_mm"] <= 4.0 + 1e-9).all() and (met["m_y_mm"] <= 4.5 + 1e-9).all()
    assert (met["m_z_mm"] <= 4.0 + 1e-9).all()
    assert (met["gamma_deg"] <= req.max_gamma_deg + 1e-9).all()
    assert (met["spacing_mm"] <= 12.0 + 1e-9).all()
    assert (met["slope_distance_m"] <= p.scanner.max_range_m).all()
    # and the CSV says the same to its printed precision
    from io import StringIO

    csv = pd.read_csv(StringIO(coverage_csv(p)))
    assert list(csv.columns) == [
        "building_id",
        "facade_id",
        "sample_id",
        "x",
        "y",
        "z",
        "station_id",
        "distance_m",
        "slope_distance_m",
        "gamma_deg",
        "nu_deg",
        "incidence_deg",
        "m_x_mm",
        "m_y_mm",
        "m_z_mm",
        "meets",
        "model",
        "scanner_m_x_mm",
        "scanner_m_y_mm",
        "scanner_m_z_mm",
        "reg_m_x_mm",
        "reg_m_y_mm",
        "reg_m_z_mm",
        "spacing_mm",
        "reason",
        "elevated_station",
        "zone",
        "material",
    ]
    assert (csv.loc[csv["meets"], "m_x_mm"] <= 4.0 + 0.0005).all()
    # the totals are the scanner's and the registration's parts added in quadrature
    for c in "xyz":
        total = np.hypot(met[f"scanner_m_{c}_mm"], met[f"reg_m_{c}_mm"])
        np.testing.assert_allclose(met[f"m_{c}_mm"], total, atol=1e-9)  # mm
    assert (met[["reg_m_x_mm", "reg_m_y_mm", "reg_m_z_mm"]].max(axis=1) > 0.1).mean() > 0.5


def test_optimiser_finds_the_minimum_worked_out_by_hand():
    """A 20 × 20 m square, 3 m high, one row of samples at the instrument height (ν = 0,
    S = D), samples every 2 m (x = 1, 3, …, 19 on each facade), γ <= 30°, range <= 12 m.

    * A station sees a facade only within 30° of its normal. Seeing two adjacent facades
      would need γ_A + γ_B = 90° at the corner, so with γ <= 30° each station serves at most
      one facade.
    * A station at distance p from a facade serves the stretch |x − x_s| <= min(p·tan 30°,
      √(12² − p²)); the widest is at p = 12·cos 30° = 10.4 m: ±12·sin 30° = ±6 m, 12 m.
    * The samples of one facade span 18 m (x = 1 … 19) > 12 m: one station is not enough;
      two at x_s ≈ 6 and 14 (12 m each) are.
    So the minimum is 4 facades × 2 = 8 stations.
    """
    site = square_site(20.0, 3.0)
    req = Requirements(max_xy_mm=50, max_z_mm=50, max_gamma_deg=30, max_range_m=12.0)
    settings = PlanSettings(grid_m=0.5, sample_spacing_m=2.0, sample_height_step_m=3.0)
    p = plan(site, PAPER, req, settings)
    assert p.meets_all
    # proven optimal: by HiGHS, or by greedy meeting the packing bound (8 samples, one near
    # the middle of each half-facade, share no candidate)
    assert p.solver.status.startswith("optimal")
    assert p.solver.objective == 8 and p.solver.lower_bound == 8 and p.solver.gap == 0.0
    assert p.solver.greedy_objective >= 8
    assert (p.stations["purpose"] == "cover").sum() == 8
    greedy = plan(
        site,
        PAPER,
        req,
        PlanSettings(grid_m=0.5, sample_spacing_m=2.0, sample_height_step_m=3.0, method="greedy"),
    )
    assert greedy.solver.method == "greedy" and greedy.meets_all


def test_stations_per_sample():
    settings = PlanSettings(sample_spacing_m=4.0, sample_height_step_m=5.0)
    one = plan(square_site(), PAPER, Requirements(max_xy_mm=6, max_z_mm=6), settings)
    two = plan(
        square_site(), PAPER, Requirements(max_xy_mm=6, max_z_mm=6, stations_per_sample=2), settings
    )
    assert two.meets_all
    assert (two.coverage["stations_meeting"] >= 2).all()
    assert two.solver.objective > one.solver.objective


def test_registration_targets_tie_the_default_plan(rich_plan, default_plan):
    p = default_plan
    assert p.meets_all and any("form one registration network" in m for m in p.messages)
    t = p.targets
    assert len(t) >= 3
    assert (t["size_mm"] >= t["min_size_mm"]).all()
    assert t["station_ids"].map(len).min() >= 2
    assert set(t["type"]) <= {"flat", "sphere"}
    # every station takes part in at least one link with three targets placed
    linked = set(
        p.links.loc[p.links["targets_placed"] >= 3, ["station_a", "station_b"]].to_numpy().ravel()
    )
    assert linked == set(p.stations["station_id"])
    # a flat target's minimum size is at least 2d at its farthest station (incidence only adds)
    st = p.stations.set_index("station_id")
    for r in t[t["type"] == "flat"].itertuples():
        s_max = max(
            np.hypot(np.hypot(st.loc[s, "x"] - r.x, st.loc[s, "y"] - r.y), r.z - 1.5)
            for s in r.station_ids
        )
        assert r.min_size_mm >= 2 * p.scanner.step_mm_at_10m * s_max / 10 - 1e-9


@pytest.mark.parametrize("registration", [True, False])
def test_the_optimisers_backstop_is_a_share_of_the_budget_whatever_the_clock(
    monkeypatch, registration
):
    """The optimiser's backstop is CPU seconds, a share of --time-limit-s: half of it for
    each search when the registration is still to be built, else all of it — the same
    whatever the wall clock has spent (here: a clock racing an hour a look)."""
    import planner.pipeline.engine.planning as planning

    limits = []
    real = planning.solve_cover

    def spy(ok, demand, time_limit_s, method):
        if method != "greedy":  # a greedy cover takes no time limit
            limits.append(time_limit_s)
        return real(ok, demand, time_limit_s, method)

    monkeypatch.setattr(planning, "solve_cover", spy)
    real_clock, looks = time.monotonic, [0]

    def racing() -> float:
        looks[0] += 1
        return real_clock() + 3600.0 * looks[0]

    monkeypatch.setattr(time, "monotonic", racing)
    budget = 40.0  # s
    settings = PlanSettings(time_limit_s=budget, registration_error=registration)
    plan(square_site(20.0, 10.0), PAPER, Requirements(max_xy_mm=6, max_z_mm=6), settings)
    share = 0.5 if registration else 1.0
    assert limits and all(s == pytest.approx(share * budget, abs=1e-9) for s in limits)  # s


def test_what_a_plan_says_of_hopeless_samples_does_not_depend_on_the_optimisers_time(
    monkeypatch,
):
    """The diagnosis of the samples no position meets (their best achievable values, which
    the reasons print) is whole: an optimiser slow beyond the whole budget does not cut it
    short (it did: the reasons then changed under load)."""
    import planner.pipeline.engine.planning as planning

    args = (None, None, Requirements(max_xy_mm=5, max_z_mm=2), PlanSettings(time_limit_s=2))
    calm = workbench_of(plan(*args))
    real = planning.solve_cover

    def slow(ok, demand, time_limit_s, method):  # the machine loaded: the time all gone
        time.sleep(2.05)
        return real(ok, demand, time_limit_s, method)

    monkeypatch.setattr(planning, "solve_cover", slow)
    hurried = workbench_of(plan(*args))
    assert calm.evaluation.evaluated.all() and hurried.evaluation.evaluated.all()
    a, b = calm.diagnosis, hurried.diagnosis
    assert len(a.samples) > 10 and np.array_equal(a.samples, b.samples)
    assert a.best["done"].all() and b.best["done"].all()
    for key in a.best:
        np.testing.assert_array_equal(a.best[key], b.best[key])
