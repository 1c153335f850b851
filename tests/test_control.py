"""Planned control: a group no common target ties is tied by control points coordinated by
a total-station traverse (through a gateway) or by GNSS where the sky is open; the datum
error they carry is checked by a Monte Carlo of the traverse and the registration, with a
negative control (the control taken as error-free)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd
import pytest
import shapely
from sites import courtyard_site, poly, rect

from planner.pipeline.engine.planning import plan
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.pipeline.network.control import CONTROL_SHOT_MM
from planner.registration_error import CONTROL, Link, propagate, transport_pose_cov
from planner.site import Building, Passage, Site
from planner.targets import parse_inventory

#: Spheres of 60 mm only: too small to be shared over the courtyard wing, so the courtyard
#: behind its 1.6 m gateway is not tied by common targets.
SMALL = PlanSettings(
    time_limit_s=300,
    sample_spacing_m=3,
    sample_height_step_m=3,
    inventory=parse_inventory("s, sphere, 60"),
)


@pytest.fixture(scope="module")
def gated():
    site = replace(
        courtyard_site(court=20.0, height=12.0),
        passages=[Passage("gate", rect(19.2, -1, 20.8, 11), 3.0)],
    )
    return plan(site, "leica-4mm-60urad", Requirements(max_xy_mm=6, max_z_mm=6), SMALL)


def test_a_courtyard_behind_a_narrow_gateway_is_tied_by_a_traverse(gated):
    p = gated
    (tie,) = p.network.ties
    assert tie.kind == "traverse" and tie.legs >= 1
    assert p.network.tied.all() and p.meets_all
    # the traverse runs through the gateway: one of its legs crosses it
    legs = shapely.linestrings(np.stack([tie.setups[:-1], tie.setups[1:]], axis=1))
    assert shapely.intersects(legs, p.site.passages[0].geometry).any()
    # its set-ups are stations to set up (no scan), its control points targets to set out
    tr = p.stations[p.stations["purpose"] == "traverse"]
    assert len(tr) == tie.legs + 1 and tr["station_id"].str.startswith("TR1-").all()
    route = p.route.table.set_index("station_id")
    assert (route.loc[tr["station_id"], "scan_min"] == 0).all()
    ctl = p.targets[p.targets["type"] == "control"]
    assert sorted(ctl["target_id"]) == ["C1-1", "C1-2", "C1-3"]
    stake = pd.read_csv(pd.io.common.StringIO(_stakeout(p)))
    assert (stake["code"] == "TRV").sum() == len(tr) and (stake["code"] == "CTL").sum() == 3
    msg = [m for m in p.messages if "tied by planned control" in m]
    assert len(msg) == 1 and "a total-station traverse of" in msg[0]
    assert f"±{tie.datum_rms_mm:.1f} mm per coordinate" in msg[0]
    assert tie.datum_rms_mm == pytest.approx(2.0 * np.sqrt(tie.legs))  # mm: 2 mm a leg


def test_stations_edited_by_hand_on_a_plan_with_a_traverse(gated):
    """Every station of the plan given back as it is (the traverse's set-ups too, two of
    which stand on scanner stations): the scanner stations are judged again under their
    ids and purposes, the traverse is planned again with the network, not taken for
    stations placed by hand."""
    from planner.pipeline.engine.whatif import evaluate_stations

    p = gated
    q = evaluate_stations(p, p.stations[["x", "y"]].to_numpy(), list(p.stations["station_id"]))
    before = p.scan_stations.set_index("station_id")["purpose"]
    after = q.scan_stations.set_index("station_id")["purpose"]
    assert after.loc[before.index].tolist() == before.tolist()
    assert (q.stations["purpose"] == "traverse").sum() == (
        p.stations["purpose"] == "traverse"
    ).sum()
    assert (q.stations["purpose"] != "hand").all()
    q2 = evaluate_stations(p, p.stations[["x", "y"]].to_numpy())  # by position alone
    assert sorted(q2.scan_stations["station_id"]) == sorted(before.index)


def _stakeout(p) -> str:
    from planner.pipeline.documents.deliver import stakeout_csv

    return stakeout_csv(p)


def test_the_planned_control_datum_matches_a_monte_carlo(gated):
    """Simulated as it happens: the start station's pose error (its frame carries the
    traverse), each leg's error, each control point's shot, the group station's noisy
    target centres; the station registered to its control points by a rigid fit. The
    RMS at its facade points agrees with the predicted registration error per axis;
    negative control: predicted with the control error-free, it does not."""
    p, net = gated, gated.network
    (tie,) = net.ties
    link = next(lk for lk in net.links if lk.parent == CONTROL and lk.child in tie.stations)
    j, ts = link.child, list(link.targets)
    xj = net.station_xyz[j]
    xs = net.station_xyz[tie.start]
    ctl = net.candidates.xyz[ts]
    sig_c = np.array([net.centre_rms[(j, t)] for t in ts])
    # the planner's parts: the fit to the control points, the datum, the start carried over
    fit = propagate(
        xj[None],
        ctl,
        {(0, k): s for k, s in enumerate(sig_c)},
        [Link(CONTROL, 0, tuple(range(len(ts))))],
        datum=None,
        control_rms_mm=dict.fromkeys(range(len(ts)), CONTROL_SHOT_MM),
    ).pose_cov[0]
    datum = np.zeros((6, 6))
    datum[:3, :3] = np.eye(3) * tie.datum_rms_mm**2
    start = transport_pose_cov(net.error.pose_cov[tie.start], xs, xj)
    predicted, negative = fit + datum + start, fit
    # the simulation
    rng = np.random.default_rng(11)
    n, legs = 4000, tie.legs
    s_pose = rng.multivariate_normal(np.zeros(6), net.error.pose_cov[tie.start], size=n)
    walk = rng.normal(0.0, 2.0, size=(n, legs, 3)).sum(axis=1)  # traverse_mm per leg
    lever = (ctl - xs) * 1000.0  # mm
    err_ctl = (
        s_pose[:, None, :3]
        + np.cross(s_pose[:, None, 3:], lever[None])
        + walk[:, None, :]
        + rng.normal(0.0, CONTROL_SHOT_MM, size=(n, len(ts), 3))
    )
    obs = rng.normal(0.0, 1.0, size=(n, len(ts), 3)) * sig_c[None, :, None]
    # the rigid fit, linearised: the station's pose error from control - observation misfit
    rel = (ctl - xj) * 1000.0
    a = np.zeros((len(ts) * 3, 6))
    for k, r in enumerate(rel):
        a[3 * k : 3 * k + 3, :3] = np.eye(3)
        a[3 * k : 3 * k + 3, 3:] = -np.array([[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])
    w = np.repeat(1.0 / (sig_c**2 + CONTROL_SHOT_MM**2), 3)
    solve = np.linalg.solve(a.T @ (w[:, None] * a), a.T * w)
    pose = (err_ctl - obs).reshape(n, -1) @ solve.T  # (n, 6)
    pts = p.scanned.loc[p.scanned["station_id"] == p.stations["station_id"][j]]
    pts = pts[["x", "y", "z"]].to_numpy()[:: max(1, len(pts) // 20)]
    for q in pts:
        lv = (q - xj) * 1000.0
        g = np.hstack(
            [np.eye(3), -np.array([[0, -lv[2], lv[1]], [lv[2], 0, -lv[0]], [-lv[1], lv[0], 0]])]
        )
        sim = np.sqrt(((pose @ g.T) ** 2).mean(axis=0))
        want = np.sqrt(np.diag(g @ predicted @ g.T))
        bad = np.sqrt(np.diag(g @ negative @ g.T))
        assert sim == pytest.approx(want, rel=0.1)  # per axis, mm
        assert (sim / bad).max() > 1.5  # the control is not error-free
    # the planner's own prediction for the station (its group adjusted together) is this
    # composition or a little better, never better than the datum alone
    planner_shift = np.sqrt(np.diag(net.error.pose_cov[j])[:3])
    assert np.all(planner_shift <= np.sqrt(np.diag(predicted)[:3]) * 1.01)
    assert np.all(planner_shift >= tie.datum_rms_mm * 0.99)


def test_gnss_ties_a_closed_courtyard_open_to_the_sky():
    """A low ring of buildings round a wide yard: no gateway, but the sky is open inside
    (the roofs rise 5° above the instrument): GNSS control ties it, carrying its 15 mm."""
    outer = [(0, 0), (100, 0), (100, 100), (0, 100)]
    hole = [(10, 10), (10, 90), (90, 90), (90, 10)]
    site = Site([Building("ring", poly(outer, [hole]), 6.0)])
    st = PlanSettings(time_limit_s=300, sample_spacing_m=6, sample_height_step_m=3, grid_m=4)
    p = plan(site, "leica-4mm-60urad", Requirements(max_xy_mm=20, max_z_mm=20), st)
    kinds = [t.kind for t in p.network.ties]
    assert kinds == ["gnss"]
    assert p.network.tied.all()
    (tie,) = p.network.ties
    assert tie.datum_rms_mm == pytest.approx(15.0 / np.sqrt(3.0))  # mm
    assert any("GNSS (the sky is open there)" in m for m in p.messages)
    inside = p.scanned[
        p.scanned["facade_id"].isin(p.facades.loc[p.facades["courtyard"], "facade_id"])
    ]
    assert (inside["reg_m_x_mm"] > tie.datum_rms_mm * 0.99).all()  # the datum is in it


def test_a_groups_linking_stations_carry_their_overlaps():
    """A group tied by planned control whose own network adds a linking station: the
    network's overlap matrix grows with it (a hybrid plan of this eight-building town ended
    in IndexError writing its links table)."""
    from planner.pipeline.engine.planning import plan as plan_one
    from planner.synthetic import town

    p = plan_one(town(8, seed=2), settings=PlanSettings(registration="hybrid", grid_m=3.0))
    net = p.network  # (the kit's trial network was the one tied by control)
    assert net.overlap.shape == (len(net.stations), len(net.stations))
    assert len(p.links) == len(net.links)
    assert int(p.scanned["meets"].sum()) > 0.95 * len(p.scanned)
