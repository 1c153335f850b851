"""Registration error (planner.registration_error): a case worked out by hand, and a Monte
Carlo of the whole chain — noisy target measurements at every station, pairwise
least-squares registrations, chained from the datum — against the propagated covariance,
with negative controls that fail when the propagation is wrong."""

from __future__ import annotations

import numpy as np
import pytest
from virtual_survey import _procrustes, _rot_z, _rotvec

from planner.registration_error import (
    CONTROL,
    Link,
    adjust,
    pair_registration_variances,
    point_registration_variances,
    propagate,
    target_centre_rms_mm,
)
from planner.units import RHO_ARCSEC


def test_two_stations_three_targets_by_hand():
    """Station 1 at the centroid of three targets on an equilateral triangle of radius R in
    its horizontal plane, σ per axis at both stations: per axis var(δs) = 2σ²/3;
    var(ω_x) = var(ω_y) = 4σ²/(3R²), var(ω_z) = 2σ²/(3R²); a point h above the station
    moves along x by δs_x + ω_y·h."""
    r, sigma, h = 10.0, 1.0, 5.0  # m, mm, m
    ang = np.radians([0.0, 120.0, 240.0])
    targets = np.column_stack([r * np.cos(ang), r * np.sin(ang), np.zeros(3)]) + np.array(
        [50, 0, 0]
    )
    stations = np.array([[0.0, 0.0, 0.0], [50.0, 0.0, 0.0]])
    rms = {(k, t): sigma for k in range(2) for t in range(3)}
    net = propagate(stations, targets, rms, [Link(0, 1, (0, 1, 2))], datum=0)
    cov = net.pose_cov[1]
    r_mm = r * 1000
    assert np.diag(cov)[:3] == pytest.approx([2 * sigma**2 / 3] * 3, rel=1e-9)
    assert np.diag(cov)[3:] == pytest.approx(
        [4 * sigma**2 / (3 * r_mm**2)] * 2 + [2 * sigma**2 / (3 * r_mm**2)], rel=1e-9
    )
    vx, _, vz = point_registration_variances(
        cov[None],
        stations[1:2],
        np.array([[50.0, 0.0, h]]),
        np.array([[1.0, 0.0]]),
        np.array([[0.0, 1.0]]),
    )
    expected = 2 * sigma**2 / 3 + 4 * sigma**2 * (h * 1000) ** 2 / (3 * r_mm**2)
    assert vx[0] == pytest.approx(expected, rel=1e-9)  # mm²
    assert vz[0] == pytest.approx(2 * sigma**2 / 3, rel=1e-9)  # the rotation does not lift it
    assert net.pose_cov[0] == pytest.approx(np.zeros((6, 6)))  # the datum


def test_pair_and_point_variances_are_g_transposed_c_g():
    """Both layouts (every station with every point; each point with its own station) against
    the variance written out: along a unit vector u a point at lever r [mm] moves by
    g·(δs, δω) with g = (u, r × u), so its variance is gᵀ C g."""
    rng = np.random.default_rng(7)
    c, n = 6, 9
    a = rng.normal(size=(c, 6, 6))
    cov = a @ np.transpose(a, (0, 2, 1)) * np.array([1.0] * 3 + [1e-4] * 3)[:, None]
    cov = (cov + np.transpose(cov, (0, 2, 1))) / 2  # mm² and rad², symmetric
    stations = rng.uniform(0, 50, (c, 3)) + np.array([400_000.0, 5_600_000.0, 0.0])  # m
    points = rng.uniform(0, 50, (n, 3)) + np.array([400_000.0, 5_600_000.0, 0.0])
    along = np.array([0.6, 0.8])
    normal = np.array([0.8, -0.6])

    def written_out(j, i, u):
        r = (points[i] - stations[j]) * 1000.0
        g = np.concatenate([u, np.cross(r, u)])
        return g @ cov[j] @ g

    units = [np.append(along, 0.0), np.append(normal, 0.0), np.array([0.0, 0.0, 1.0])]
    want = np.array([[[written_out(j, i, u) for i in range(n)] for j in range(c)] for u in units])
    got = np.array(pair_registration_variances(cov, stations, points, along, normal))
    assert got == pytest.approx(want, rel=1e-9)  # mm²
    j = rng.integers(0, c, n)
    alongs, normals = np.tile(along, (n, 1)), np.tile(normal, (n, 1))
    one = np.array(point_registration_variances(cov[j], stations[j], points, alongs, normals))
    assert one == pytest.approx(want[:, j, np.arange(n)], rel=1e-9)  # mm²
    assert not np.allclose(want[0], want[1], rtol=1e-3)  # along and across differ here


def test_collinear_targets_do_not_fix_a_registration():
    stations = np.array([[0.0, 0.0, 0.0], [20.0, 0.0, 0.0]])
    targets = np.array([[10.0, 5.0, 1.0], [12.0, 5.0, 1.0], [14.0, 5.0, 1.0]])
    rms = {(k, t): 1.0 for k in range(2) for t in range(3)}
    with pytest.raises(Exception, match="do not fix the registration"):
        propagate(stations, targets, rms, [Link(0, 1, (0, 1, 2))])


def test_target_centre_rms_grows_with_distance_and_shrinks_with_size():
    near = target_centre_rms_mm("sphere", 200.0, 20.0, 1.0, 2.0, 10.0, 4.0)
    far = target_centre_rms_mm("sphere", 200.0, 80.0, 1.0, 2.0, 10.0, 16.0)
    bigger = target_centre_rms_mm("sphere", 400.0, 80.0, 1.0, 2.0, 10.0, 16.0)
    assert 0.5 < near < far and bigger < far
    # a checkerboard is as good as the sampling of its edges: d / √12, stretched by 1/cos θ
    flat = target_centre_rms_mm("flat", 100.0, 10.0, 1.0, 1.0, 5.0, 2.0, floor_mm=0.0)
    assert flat == pytest.approx(2.0 / np.sqrt(12), abs=0.01)  # mm
    oblique = target_centre_rms_mm("flat", 100.0, 10.0, 0.5, 1.0, 5.0, 2.0, floor_mm=0.0)
    assert oblique == pytest.approx(4.0 / np.sqrt(12), abs=0.02)  # mm


# -- Monte Carlo of the whole chain -------------------------------------------------------
def _rot_xy(tx, ty):
    """Tilts by ``tx`` about x, then ``ty`` about y (any shape): (…, 3, 3)."""
    cx, sx, cy, sy = np.cos(tx), np.sin(tx), np.cos(ty), np.sin(ty)
    rx, ry = np.zeros((*np.shape(tx), 3, 3)), np.zeros((*np.shape(ty), 3, 3))
    rx[..., 0, 0], rx[..., 1, 1], rx[..., 1, 2], rx[..., 2, 1], rx[..., 2, 2] = 1, cx, -sx, sx, cx
    ry[..., 0, 0], ry[..., 0, 2], ry[..., 1, 1], ry[..., 2, 0], ry[..., 2, 2] = cy, sy, 1, -sy, cy
    return rx @ ry


# four stations in a chain S0 → S1 → S2 and S1 → S3; targets in plan and at two heights,
# some shared by two links (their measurements correlate the links)
STATIONS = np.array([[0.0, 0.0, 1.5], [30.0, 5.0, 1.6], [55.0, -10.0, 1.4], [35.0, 35.0, 1.5]])
TARGETS = np.array(
    [
        [12.0, 8.0, 1.6],
        [15.0, -9.0, 3.2],
        [18.0, 14.0, 1.6],
        [20.0, -2.0, 3.0],
        [42.0, -6.0, 1.6],
        [44.0, 8.0, 3.1],
        [48.0, -18.0, 1.6],
        [26.0, 22.0, 1.6],
        [40.0, 22.0, 3.2],
        [32.0, 28.0, 1.7],
    ]
)
LINKS = [Link(0, 1, (0, 1, 2, 3)), Link(1, 2, (3, 4, 5, 6)), Link(1, 3, (2, 7, 8, 9))]
SAMPLES = {  # facade points scanned from each station (site frame)
    1: np.array([[30.0, 20.0, 12.0], [45.0, 5.0, 2.0]]),
    2: np.array([[60.0, 5.0, 14.0], [70.0, -10.0, 1.0]]),
    3: np.array([[35.0, 50.0, 10.0], [20.0, 40.0, 3.0]]),
}
TRIALS = 6000
#: relative tolerance on an RMS from TRIALS draws: 5 standard errors
REL_TOL = 5 / np.sqrt(2 * TRIALS)


def _rms_table(seed: int = 3):
    rng = np.random.default_rng(seed)
    rms = {}
    for link in LINKS:
        for t in link.targets:
            for k in (link.parent, link.child):
                d = np.linalg.norm(TARGETS[t] - STATIONS[k])
                rms[(k, t)] = 0.6 + 0.02 * d + 0.3 * rng.random()  # mm, per axis
    return rms


def _scan(rms, nominal, tilted, tau, stations, targets, rng, trials):
    """``trials`` trials' true station frames (trials, K, 3, 3): the nominal headings
    ``nominal`` (K, 3, 3), tilted by a random ``tau`` [rad] per axis when ``tilted``; and
    every observation (station, target) of ``rms``, in its order — the target's centre
    measured once in the station's frame [m] with its RMS of noise — (trials, len(rms), 3).
    The draws are taken as one trial after another would take them: a trial's tilts (two
    per station), then each observation's noise."""
    keys = list(rms)
    k_of, t_of = (np.array(c) for c in zip(*keys, strict=True))
    n_tilt = 2 * len(nominal) if tilted else 0
    z = rng.standard_normal((trials, n_tilt + 3 * len(keys)))
    rot = np.broadcast_to(nominal, (trials, *nominal.shape))
    if tilted:
        tilt = tau * z[:, :n_tilt].reshape(trials, len(nominal), 2)
        rot = _rot_xy(tilt[..., 0], tilt[..., 1]) @ nominal
    sigma_m = np.array([rms[key] for key in keys]) / 1000
    noise = z[:, n_tilt:].reshape(trials, len(keys), 3) * sigma_m[:, None]
    meas = np.einsum("tnji,nj->tni", rot[:, k_of], targets[t_of] - stations[k_of]) + noise
    return rot, meas


def _carried(rot_hat, t_hat, true_rot, station, pts):
    """Errors [mm] (trials, points, 3) of points ``pts`` scanned from ``station`` in its
    true frames ``true_rot`` (trials, 3, 3) and placed with the estimated pose."""
    local = np.einsum("nji,pj->npi", true_rot, pts - station)
    placed = np.einsum("nij,npj->npi", rot_hat, local) + t_hat[:, None, :]
    return (placed - pts) * 1000


def _simulate_chain(
    rms,
    levelled,
    tilt_arcsec,
    rng,
    *,
    stations=STATIONS,
    targets=TARGETS,
    links=LINKS,
    samples=SAMPLES,
    datum=0,
    trials=TRIALS,
):
    """Errors [mm] of every sample point after the chained registrations: each station
    measures each of its targets once in its own (randomly turned) frame with the given
    noise, each link is a weighted least-squares rigid registration to its parent's
    estimate, and the sample points of each station are carried along (trials × …; all
    trials at once, the draws as one trial after another would take them)."""
    kappas = rng.uniform(0, 2 * np.pi, len(stations))
    nominal = _rot_z(kappas)
    tau = tilt_arcsec / RHO_ARCSEC
    true_rot, meas = _scan(rms, nominal, levelled, tau, stations, targets, rng, trials)
    at = {key: n for n, key in enumerate(rms)}
    # the datum's frame: its own (levelled: its nominal orientation, tilt unknown)
    est = {
        datum: (
            np.broadcast_to(nominal[datum], (trials, 3, 3)),
            np.tile(stations[datum], (trials, 1)),
        )
    }
    for link in links:
        i, j = link.parent, link.child
        ri, ti = est[i]
        mine = meas[:, [at[(i, t)] for t in link.targets]]  # (trials, m, 3)
        p = np.einsum("nij,nmj->nmi", ri, mine) + ti[:, None, :]
        q = meas[:, [at[(j, t)] for t in link.targets]]
        w = np.array([1 / (rms[(i, t)] ** 2 + rms[(j, t)] ** 2) for t in link.targets])
        est[j] = _procrustes(q, p, w, levelled)
    return {j: _carried(*est[j], true_rot[:, j], stations[j], pts) for j, pts in samples.items()}


def _predicted(net, j):
    pts = SAMPLES[j]
    n = len(pts)
    along = np.tile([1.0, 0.0], (n, 1))
    normal = np.tile([0.0, 1.0], (n, 1))
    return point_registration_variances(
        np.repeat(net.pose_cov[j][None], n, axis=0),
        np.repeat(STATIONS[j][None], n, axis=0),
        pts,
        along,
        normal,
    )


@pytest.mark.parametrize(("levelled", "tilt"), [(False, 0.0), (True, 3.0)])
def test_chained_registration_matches_a_monte_carlo(levelled, tilt):
    rms = _rms_table()
    net = propagate(STATIONS, TARGETS, rms, LINKS, datum=0, levelled=levelled, tilt_rms_arcsec=tilt)
    sim = _simulate_chain(rms, levelled, tilt, np.random.default_rng(17 + levelled))
    worst = 0.0
    for j in SAMPLES:
        pred = np.sqrt(np.column_stack(_predicted(net, j)))  # (points, 3) RMS [mm]
        emp = np.sqrt(np.mean(np.square(sim[j]), axis=0))  # (points, 3)
        worst = max(worst, float(np.max(np.abs(emp / pred - 1))))
        np.testing.assert_allclose(emp, pred, rtol=REL_TOL)
    assert worst < REL_TOL


def test_negative_control_fails():
    """A wrong propagation — the links' shared targets taken as independent (the
    covariances of consecutive links simply added) — is rejected by the same Monte Carlo."""
    rms = _rms_table()
    sim = _simulate_chain(rms, False, 0.0, np.random.default_rng(5))
    net = propagate(STATIONS, TARGETS, rms, LINKS, datum=0)
    # (a) independent links: every station's covariance = the sum of its links' own
    link_only = {child: net.link_cov[(p, child)] for (p, child) in net.link_cov}
    summed = net.pose_cov.copy()
    summed[1] = link_only[1]
    summed[2] = link_only[1] + link_only[2]
    summed[3] = link_only[1] + link_only[3]
    wrong = type(net)(pose_cov=summed, link_cov=net.link_cov, tied=net.tied)
    misses = []
    for j in (2, 3):
        emp = np.sqrt(np.mean(np.square(sim[j]), axis=0))
        bad = np.sqrt(np.column_stack(_predicted(wrong, j)))
        misses.append(float(np.max(np.abs(emp / bad - 1))))
    assert max(misses) > 4 * REL_TOL, misses


def test_control_targets_are_a_datum():
    """Registered to three control points of 1 mm, a station's shift is known to ~1 mm
    whatever station is first; with 10 mm control points it is worse."""
    stations = np.array([[0.0, 0.0, 1.5]])
    targets = np.array([[10.0, 0.0, 1.5], [-5.0, 9.0, 3.0], [-5.0, -9.0, 1.5]])
    rms = {(0, t): 0.5 for t in range(3)}
    good = propagate(
        stations,
        targets,
        rms,
        [Link(CONTROL, 0, (0, 1, 2))],
        datum=None,
        control_rms_mm=dict.fromkeys(range(3), 1.0),
    )
    poor = propagate(
        stations,
        targets,
        rms,
        [Link(CONTROL, 0, (0, 1, 2))],
        datum=None,
        control_rms_mm=dict.fromkeys(range(3), 10.0),
    )
    shift_good = np.sqrt(np.diag(good.pose_cov[0])[:3])
    assert np.all(shift_good < 1.2) and np.all(shift_good > 0.5)  # mm
    assert np.all(np.sqrt(np.diag(poor.pose_cov[0])[:3]) > 5 * shift_good)
    assert good.tied.all()


# -- the whole chain of a real plan ---------------------------------------------------------
def test_the_default_plans_registration_error_matches_a_monte_carlo_of_its_network(
    default_plan,
):
    """The default site's plan, its network as planned (stations, targets, every station's
    observation of every placed target it sees, with its centre RMS), simulated end to end
    and adjusted together, every station's axis tilted (the datum's too); the empirical
    error of every facade sample scanned from a registered station, along the facade, across it
    and in height, against the registration RMS the coverage reports. Negative control:
    the same network without its rotations' lever arms (shift errors only) misses."""
    p = default_plan
    net = p.network
    assert net is not None and net.datum is not None and len(net.links) >= 3
    ids = list(p.stations["station_id"])
    cov = p.scanned[p.scanned["station_id"] != ""]
    fac = p.facades.set_index("facade_id")
    rows = {j: cov[cov["station_id"] == sid] for j, sid in enumerate(ids) if j != net.datum}
    rows = {j: r.iloc[:: max(1, len(r) // 12)] for j, r in rows.items() if len(r)}
    samples = {j: r[["x", "y", "z"]].to_numpy() for j, r in rows.items()}
    trials = 3000
    sim = _simulate_adjustment(
        net.centre_rms,
        False,
        p.scanner.initial_tilt_rms_arcsec,  # every station tilted, the datum's too
        np.random.default_rng(11),
        stations=net.station_xyz,
        targets=net.candidates.xyz,
        samples=samples,
        datum=net.datum,
        trials=trials,
        tilted=True,
    )
    tol = 5 / np.sqrt(2 * trials)
    worst, shift_only = 0.0, 0.0
    for j, r in rows.items():
        f = fac.loc[r["facade_id"]]
        along = np.column_stack([f["x1"] - f["x0"], f["y1"] - f["y0"]])
        along /= np.linalg.norm(along, axis=1)[:, None]
        normal = np.column_stack([along[:, 1], -along[:, 0]])
        e = sim[j]  # (trials, points, 3) [mm]
        emp = np.sqrt(
            np.column_stack(
                [
                    np.mean(np.einsum("tpi,pi->tp", e[..., :2], along) ** 2, axis=0),
                    np.mean(np.einsum("tpi,pi->tp", e[..., :2], normal) ** 2, axis=0),
                    np.mean(e[..., 2] ** 2, axis=0),
                ]
            )
        )
        pred = r[["reg_m_x_mm", "reg_m_y_mm", "reg_m_z_mm"]].to_numpy()
        worst = max(worst, float(np.max(np.abs(emp / pred - 1))))
        shifts = np.sqrt(np.diag(net.error.pose_cov[j])[:3])
        shift_only = max(shift_only, float(np.max(emp[:, 2] / shifts[2] - 1)))
    assert worst < tol, worst
    assert shift_only > 4 * tol  # the rotations matter: ignoring them is rejected


# -- the simultaneous adjustment --------------------------------------------------------
#: every target a station sees within this range is observed (loops beyond the tree) [m]
SEEN_M = 36.0


def _observed_rms(seed: int = 4) -> dict[tuple[int, int], float]:
    rng = np.random.default_rng(seed)
    rms = {}
    for k, s in enumerate(STATIONS):
        for t, x in enumerate(TARGETS):
            d = np.linalg.norm(x - s)
            if d <= SEEN_M or any(k in (lk.parent, lk.child) and t in lk.targets for lk in LINKS):
                rms[(k, t)] = 0.6 + 0.02 * d + 0.3 * rng.random()  # mm, per axis
    return rms


def _simulate_adjustment(
    rms,
    levelled,
    tilt_arcsec,
    rng,
    *,
    stations=STATIONS,
    targets=TARGETS,
    samples=SAMPLES,
    datum=0,
    trials=TRIALS,
    tilted=None,
):
    """Errors [mm] of every sample point after one joint least-squares adjustment of all
    the observations ``rms`` ((station, target) → RMS): rigid station frames (random
    heading, and a random tilt when levelled or ``tilted``), noisy target centres, the datum
    held at its nominal frame (untilted: heights against true vertical); the adjustment is
    a Gauss-Newton step from the nominal poses with a finite-difference Jacobian of the
    rigid model (nothing shared with the covariance formula). Returns {station: (trials,
    points, 3)}; all trials at once, the draws as one trial after another would take them."""
    tilted = levelled if tilted is None else tilted
    keys = list(rms)
    seen = sorted({t for _, t in keys})
    col = {t: n for n, t in enumerate(seen)}
    k_of = np.array([k for k, _ in keys])
    t_col = np.array([col[t] for _, t in keys])
    kappas = rng.uniform(0, 2 * np.pi, len(stations))
    nominal = _rot_z(kappas)
    w = np.repeat([1.0 / rms[key] ** 2 for key in keys], 3)
    free = [j for j in range(len(stations)) if j != datum]
    n_rot = 1 if levelled else 3
    size = 3 + n_rot

    def unpack(u):
        """Poses {station: (R, t)} and target centres of unknowns u (…, n_u)."""
        lead = u.shape[:-1]
        poses = {
            datum: (
                np.broadcast_to(nominal[datum], (*lead, 3, 3)),
                np.broadcast_to(stations[datum], (*lead, 3)),
            )
        }
        for n, j in enumerate(free):
            rot = u[..., n * size : n * size + n_rot]
            vec = np.concatenate([np.zeros((*lead, 2)), rot], -1) if levelled else rot
            poses[j] = (
                _rotvec(vec) @ nominal[j],
                stations[j] + u[..., n * size + n_rot : (n + 1) * size],
            )
        return poses, targets[seen] + u[..., len(free) * size :].reshape(*lead, -1, 3)

    def residual(u, meas):
        """(…, 3 · observations): each observation placed with its station's pose, less
        its target's centre."""
        poses, xt = unpack(u)
        rot = np.stack([poses[k][0] for k in range(len(stations))], -3)[..., k_of, :, :]
        shift = np.stack([poses[k][1] for k in range(len(stations))], -2)[..., k_of, :]
        placed = np.einsum("...nij,...nj->...ni", rot, meas) + shift
        return (placed - xt[..., t_col, :]).reshape(*u.shape[:-1], -1)

    n_u = len(free) * size + 3 * len(seen)
    exact = np.einsum("nji,nj->ni", nominal[k_of], targets[[t for _, t in keys]] - stations[k_of])
    r0 = residual(np.zeros(n_u), exact)
    h = 1e-7
    jac = ((residual(h * np.eye(n_u), exact) - r0) / h).T
    normal = jac.T @ (w[:, None] * jac)
    tau = tilt_arcsec / RHO_ARCSEC
    true_rot, meas = _scan(rms, nominal, tilted, tau, stations, targets, rng, trials)
    res = residual(np.zeros((trials, n_u)), meas)
    steps = -np.linalg.solve(normal, jac.T @ (w[:, None] * res.T)).T
    poses, _ = unpack(steps)
    return {j: _carried(*poses[j], true_rot[:, j], stations[j], pts) for j, pts in samples.items()}


@pytest.mark.parametrize(("levelled", "tilt"), [(False, 0.0), (True, 3.0)])
def test_simultaneous_adjustment_matches_a_monte_carlo(levelled, tilt):
    """Every target each station sees (loops beyond the tree), adjusted together: the
    predicted RMS of every sample point matches the Monte Carlo; the chain of pairwise
    registrations over the same network predicts more (negative control: the chain's
    prediction is rejected as a model of the joint adjustment)."""
    rms = _observed_rms()
    assert len(rms) > sum(2 * len(lk.targets) for lk in LINKS)  # more than the tree's
    cov = adjust(
        STATIONS, TARGETS, rms, np.ones(4, bool), datum=0, levelled=levelled, tilt_rms_arcsec=tilt
    )
    sim = _simulate_adjustment(rms, levelled, tilt, np.random.default_rng(23 + levelled))
    chain = propagate(
        STATIONS, TARGETS, rms, LINKS, datum=0, levelled=levelled, tilt_rms_arcsec=tilt
    )
    net = type(chain)(pose_cov=cov, link_cov={}, tied=chain.tied)
    misses = []
    for j in SAMPLES:
        emp = np.sqrt(np.mean(np.square(sim[j]), axis=0))
        np.testing.assert_allclose(emp, np.sqrt(np.column_stack(_predicted(net, j))), rtol=REL_TOL)
        chained = np.sqrt(np.column_stack(_predicted(chain, j)))
        assert (chained >= emp * (1 - REL_TOL)).all()  # the chain never promises more
        misses.append(float(np.max(chained / emp - 1)))
    assert max(misses) > 4 * REL_TOL, misses


def test_the_datum_tilt_turns_the_network_and_each_stations_own_is_registered_away():
    """Without a compensator (6-parameter registrations) every station's axis is tilted
    (12.4″ per axis, the datum's too): a registration takes out each station's own tilt,
    but the datum's frame is held, so the whole network leans with the datum's tilt and
    heights (against true vertical) err in proportion to the distance from the datum. The
    adjustment's covariance with the datum's tilt matches the Monte Carlo at every sample
    (the datum's own included); the former model — the datum exact, each station's own
    tilt counted at its points — is rejected by it (negative control)."""
    tilt = 12.4
    rms = _observed_rms()
    samples = {**SAMPLES, 0: np.array([[-20.0, 10.0, 8.0], [10.0, -25.0, 2.0]])}
    cov = adjust(STATIONS, TARGETS, rms, np.ones(4, bool), datum=0, tilt_rms_arcsec=tilt)
    sim = _simulate_adjustment(
        rms, False, tilt, np.random.default_rng(29), samples=samples, tilted=True
    )
    assert np.sqrt(cov[0, 3, 3]) * RHO_ARCSEC == pytest.approx(tilt)  # the datum's tilt itself
    no_tilt = adjust(STATIONS, TARGETS, rms, np.ones(4, bool), datum=0)
    tau2 = (tilt / RHO_ARCSEC) ** 2
    misses = []
    for j, pts in samples.items():
        n = len(pts)
        along, normal = np.tile([1.0, 0.0], (n, 1)), np.tile([0.0, 1.0], (n, 1))

        def rms_of(c, j=j, pts=pts, n=n, along=along, normal=normal):
            var = point_registration_variances(
                np.repeat(c[j][None], n, axis=0),
                np.repeat(STATIONS[j][None], n, axis=0),
                pts,
                along,
                normal,
            )
            return np.column_stack(var)

        emp = np.sqrt(np.mean(np.square(sim[j]), axis=0))
        np.testing.assert_allclose(emp, np.sqrt(rms_of(cov)), rtol=REL_TOL)
        # the former model: no datum tilt, each station's own tilt at its points (the
        # 3-D model's σ_τ terms, S·sin ν·σ_τ across and D·σ_τ in height)
        rel = (pts - STATIONS[j]) * 1000.0
        own = tau2 * np.column_stack(
            [rel[:, 2] ** 2, rel[:, 2] ** 2, rel[:, 0] ** 2 + rel[:, 1] ** 2]
        )
        former = np.sqrt(rms_of(no_tilt) + own)
        misses.append(float(np.max(np.abs(emp / former - 1))))
    assert max(misses) > 4 * REL_TOL, misses


@pytest.mark.parametrize(("levelled", "control"), [(False, False), (True, False), (False, True)])
def test_adjustment_of_a_tree_is_the_chain(levelled, control):
    """Where each target serves one registration only, adjusting everything together is
    the chain of pairwise registrations: the same covariance to rounding — from a datum
    station, or from control points (targets 0–2 with known coordinates)."""
    first = Link(CONTROL, 0, (0, 1, 2)) if control else Link(0, 1, (0, 1, 2))
    second = Link(0, 1, (3, 4, 5, 6)) if control else Link(1, 2, (3, 4, 5, 6))
    links = [first, second, Link(1, 3, (7, 8, 9))]
    rms = {
        (k, t): 0.7 + 0.01 * t + 0.05 * k
        for lk in links
        for t in lk.targets
        for k in (lk.parent, lk.child)
        if k != CONTROL
    }
    ctl = {0: 1.5, 1: 2.0, 2: 1.0} if control else None
    kw = {
        "datum": None if control else 0,
        "control_rms_mm": ctl,
        "levelled": levelled,
        "tilt_rms_arcsec": 3.0,
    }
    chain = propagate(STATIONS, TARGETS, rms, links, **kw)
    assert chain.tied[[0, 1, 3]].all() and chain.pose_cov[3].trace() > 0
    np.testing.assert_allclose(
        adjust(STATIONS, TARGETS, rms, chain.tied, **kw), chain.pose_cov, rtol=1e-9, atol=1e-18
    )


@pytest.mark.parametrize("levelled", [False, True])
def test_one_scan_alone_keeps_its_own_levelling(levelled):
    """One station, nothing to register: its frame is still tilted from true vertical by
    its levelling (the scanner part of a plan that computes the registration counts no
    tilt, so the registration part must), whether or not a compensator levels it."""
    station, no_targets = np.array([[0.0, 0.0, 1.5]]), np.zeros((0, 3))
    kw = {"datum": 0, "levelled": levelled, "tilt_rms_arcsec": 12.4}
    cov = adjust(station, no_targets, {}, np.ones(1, bool), **kw)
    tilt = np.sqrt(np.diag(cov[0])[3:5]) * RHO_ARCSEC
    np.testing.assert_allclose(tilt, 12.4, rtol=1e-9)  # ″ about x and about y
    np.testing.assert_allclose(
        propagate(station, no_targets, {}, [], **kw).pose_cov, cov, rtol=1e-12, atol=0
    )


def test_the_compiled_probe_errors_are_those_of_the_inverse():
    """The link chooser's errors at its probe points, compiled (a Cholesky factor and forward
    substitution), against rᵀ N⁻¹ r with NumPy's inverse; a matrix that is not positive
    definite gives NaN; the scaled condition of one matrix is that of a stack, bit for bit."""
    from planner.pipeline.network.links import _probe_errors
    from planner.registration_error import scaled_condition

    rng = np.random.default_rng(3)
    for p in (4, 6):
        a = rng.normal(size=(30, 9, p)) * np.array([1.0, 1.0, 1.0, 1e3, 1e3, 1e3])[:p]
        n_mats = np.einsum("bip,biq->bpq", a, a) + np.eye(p) * 1e-6
        rows = rng.normal(size=(48, p)) * 1e4
        want = np.sqrt(((rows @ np.linalg.inv(n_mats)) * rows).sum(axis=-1).max(axis=1))
        np.testing.assert_allclose(_probe_errors(n_mats, rows), want, rtol=1e-10)
        stack = scaled_condition(n_mats)
        one = np.array([scaled_condition(m) for m in n_mats])
        np.testing.assert_array_equal(one, stack)
    singular = np.zeros((1, 6, 6))
    assert np.isnan(_probe_errors(singular, rows))
    assert scaled_condition(singular[0]) == np.inf == scaled_condition(singular)[0]
