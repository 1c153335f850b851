"""Every scan's recorded tilt as an observation of the adjustment
(:func:`planner.registration_error.adjust`, ``tilt_readings_rms_arcsec``), checked by a
virtual survey: rigid scans along a 150 m street, every scanner tilted at random (it is not
levelled), its tilt recorded with an error; the registration software adjusts every target
observation and every reading together, by least squares on the rigid model. The heights of
facade points against true vertical, over many surveys, match the model; the datum-only
model (the network keeps the first scan's vertical) is rejected by the same survey, and
matches a survey whose software uses the datum's reading alone.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from planner.pipeline.inputs.requirements import PlanSettings
from planner.registration_error import adjust
from planner.scanner import Scanner
from planner.units import RHO_ARCSEC

#: five stations along a 150 m street, 1.5 m instrument height [m]
STATIONS = np.array([[x, 0.0, 1.5] for x in (0.0, 35.0, 70.0, 105.0, 140.0)])
#: three targets between each pair of neighbours, spread across the street and in height
TARGETS = np.array(
    [
        [x + dx, dy, z]
        for x in (17.5, 52.5, 87.5, 122.5)
        for dx, dy, z in ((-6.0, 7.0, 1.2), (0.0, -8.0, 2.8), (6.0, 6.0, 0.6))
    ]
)
#: facade points each station scans: 12 m across the street, 2 and 12 m up [m]
POINTS = {
    j: np.array([[s[0] + 10.0, 12.0, 2.0], [s[0] - 10.0, 12.0, 12.0]])
    for j, s in enumerate(STATIONS)
}
SEEN_M = 40.0
TARGET_RMS_MM = 1.0
READING_ARCSEC = 60.0
TRIALS = 500


def _observations() -> list[tuple[int, int]]:
    return [
        (j, t)
        for j, s in enumerate(STATIONS)
        for t, x in enumerate(TARGETS)
        if np.linalg.norm(x - s) <= SEEN_M
    ]


def _survey(
    rng: np.random.Generator, readings: str, levels: dict[int, float] | None = None
) -> dict[int, np.ndarray]:
    """Height errors [mm] (trials, points) of every station's facade points after the
    software's adjustment. ``readings``: "every-scan" (every scan's reading observed) or
    "datum" (the datum's alone). ``levels``: targets whose heights a level run measured
    (target → RMS [mm]), in the run's own height datum (an unknown offset). Unknowns: every
    pose as a rotation vector and a shift (the datum's shift and heading held), every
    target, the run's offset; one Gauss–Newton step from the nominal poses, its Jacobian by
    finite differences of the rigid model."""
    levels = levels or {}
    lv = np.array(list(levels), dtype=int)
    lv_rms = np.array(list(levels.values()), dtype=float) / 1000.0  # m
    obs = _observations()
    k, n_t = len(STATIONS), len(TARGETS)
    heading = rng.uniform(0, 2 * np.pi, k)
    tau_true = rng.normal(0.0, 300.0 / RHO_ARCSEC, (TRIALS, k, 2))  # not levelled
    true_vec = np.concatenate([tau_true, np.zeros((TRIALS, k, 1))], -1)
    true_rot = _rot(true_vec) @ _rz(heading)  # a tilt in the world after the heading
    jj = np.array([j for j, _ in obs])
    tt = np.array([t for _, t in obs])
    local = np.einsum("nkji,nkj->nki", true_rot[:, jj], (TARGETS[tt] - STATIONS[jj])[None])
    local += rng.normal(0.0, TARGET_RMS_MM / 1000.0, local.shape)
    read = tau_true + rng.normal(0.0, READING_ARCSEC / RHO_ARCSEC, tau_true.shape)
    observed = range(k) if readings == "every-scan" else [0]
    run = TARGETS[lv, 2] + rng.normal(0.0, 0.05) + rng.normal(0.0, 1.0, (TRIALS, len(lv))) * lv_rms

    # unknowns: datum tilt (2), the other stations' (rotation 3, shift 3), targets (3 each)
    def unpack(u):
        vec = np.zeros((*u.shape[:-1], k, 3))
        shift = np.broadcast_to(STATIONS, (*u.shape[:-1], k, 3)).copy()
        vec[..., 0, :2] = u[..., :2]
        rest = u[..., 2 : 2 + 6 * (k - 1)].reshape(*u.shape[:-1], k - 1, 6)
        vec[..., 1:, :] += rest[..., :3]
        shift[..., 1:, :] += rest[..., 3:]
        xt = TARGETS + u[..., 2 + 6 * (k - 1) : -1].reshape(*u.shape[:-1], n_t, 3)
        return vec, shift, xt

    def residual(u, meas, reading, heights):
        vec, shift, xt = unpack(u)
        r_h = (xt[..., lv, 2] + u[..., -1:] - heights) / lv_rms
        rot = _rot(vec) @ _rz(heading)
        placed = np.einsum("...nij,...nj->...ni", rot[..., jj, :, :], meas) + shift[..., jj, :]
        r_t = (placed - xt[..., tt, :]) * (1000.0 / TARGET_RMS_MM)
        r_r = (vec[..., list(observed), :2] - reading[..., list(observed), :]) * (
            RHO_ARCSEC / READING_ARCSEC
        )
        parts = [r_t.reshape(*u.shape[:-1], -1), r_r.reshape(*u.shape[:-1], -1), r_h]
        return np.concatenate(parts, -1)

    n_u = 2 + 6 * (k - 1) + 3 * n_t + 1  # the last: the level run's offset
    nominal = np.einsum("kji,nkj->nki", _rz(heading)[jj], (TARGETS[tt] - STATIONS[jj])[None])[0]
    zero = np.zeros((k, 2))
    flat = TARGETS[lv, 2]
    r0 = residual(np.zeros(n_u), nominal, zero, flat)
    h = 1e-7
    jac = ((residual(h * np.eye(n_u), nominal, zero, flat) - r0) / h).T
    res = residual(np.zeros((TRIALS, n_u)), local, read, run)
    step = -np.linalg.lstsq(jac, res.T, rcond=None)[0]
    vec, shift, _ = unpack(step.T)
    est = _rot(vec) @ _rz(heading)
    out = {}
    for j, pts in POINTS.items():
        seen = np.einsum("nji,pj->npi", true_rot[:, j], pts - STATIONS[j])  # the scan's points
        placed = np.einsum("nij,npj->npi", est[:, j], seen) + shift[:, j, None, :]
        out[j] = (placed[..., 2] - pts[None, :, 2]) * 1000.0
    return out


def _rot(vec: np.ndarray) -> np.ndarray:
    """Rotation matrices (…, 3, 3) of rotation vectors (…, 3)."""
    return Rotation.from_rotvec(vec.reshape(-1, 3)).as_matrix().reshape(*vec.shape, 3)


def _rz(angle: np.ndarray) -> np.ndarray:
    return Rotation.from_rotvec(np.outer(angle, [0.0, 0.0, 1.0])).as_matrix()


def _predicted_z_mm(cov: np.ndarray) -> dict[int, np.ndarray]:
    out = {}
    for j, pts in POINTS.items():
        lever = (pts - STATIONS[j]) * 1000.0  # mm
        jac = np.zeros((len(pts), 6))
        jac[:, 2] = 1.0
        jac[:, 3], jac[:, 4] = lever[:, 1], -lever[:, 0]  # δz = δs_z + ω_x y − ω_y x
        out[j] = np.sqrt(np.einsum("pi,ij,pj->p", jac, cov[j], jac))
    return out


def _models() -> dict[str, dict[int, np.ndarray]]:
    rms = dict.fromkeys(_observations(), TARGET_RMS_MM)
    tied = np.ones(len(STATIONS), dtype=bool)
    kw = {"datum": 0, "tilt_rms_arcsec": READING_ARCSEC}
    every = adjust(
        STATIONS, TARGETS, rms, tied, tilt_readings=dict.fromkeys(range(5), READING_ARCSEC), **kw
    )
    datum = adjust(STATIONS, TARGETS, rms, tied, **kw)
    return {"every-scan": _predicted_z_mm(every), "datum": _predicted_z_mm(datum)}


@pytest.mark.parametrize("readings", ["every-scan", "datum"])
def test_the_network_leans_by_the_readings_the_software_uses(readings):
    """Heights [mm] of the street's facade points: the simulated surveys' RMS within the
    Monte Carlo's tolerance of the model of the readings the software used; the other
    model rejected at the far end of the street (negative control)."""
    sim = _survey(np.random.default_rng(52 if readings == "datum" else 53), readings)
    models = _models()
    tol = 4.0 / np.sqrt(2 * TRIALS)  # relative, about 4 sigma of an RMS from TRIALS draws
    other = "datum" if readings == "every-scan" else "every-scan"
    for j in POINTS:
        emp = np.sqrt(np.mean(np.square(sim[j]), axis=0))
        np.testing.assert_allclose(emp, models[readings][j], rtol=tol)
    far = np.sqrt(np.mean(np.square(sim[4]), axis=0))
    assert (np.abs(far / models[other][4] - 1) > 3 * tol).all()


def test_every_reading_holds_the_street_better_than_the_datums_alone():
    """At the far end of the street (140 m from the datum) the datum's reading alone
    (60″) leans heights by about 40 mm; five readings adjusted together by about half."""
    m = _models()
    lean = np.hypot(150.0, 12.0) * 1000 * READING_ARCSEC / RHO_ARCSEC  # mm
    assert lean < m["datum"][4][0] < 1.3 * lean  # the lean, and the chain's own error
    assert m["every-scan"][4][0] < 0.6 * m["datum"][4][0]


def test_the_settings_say_which_model_holds_the_vertical():
    """One rule (:meth:`PlanSettings.tilt_model`): a compensator's levelling, every scan's
    reading (a scanner that records one, adjusted together), else the datum's."""
    imu = Scanner(name="imu", range_rms_mm=1.0, angle_rms_arcsec=18.0, tilt_sensor_rms_arcsec=180.0)
    plain = Scanner(name="plain", range_rms_mm=1.0, angle_rms_arcsec=18.0)
    st = PlanSettings()
    assert st.tilt_model(imu) == "readings"
    assert st.tilt_model(plain) == "datum"
    assert st.tilt_model(imu.with_levelling(3.0)) == "compensator"
    assert PlanSettings(tilt_readings="datum").tilt_model(imu) == "datum"
    assert PlanSettings(registration_processing="pairwise").tilt_model(imu) == "datum"
    assert imu.datum_tilt_rms_arcsec == 180.0  # the datum's lean is its own reading's
    assert plain.datum_tilt_rms_arcsec == 18.0  # eq. 4's m_ν0 = m_ν


#: heights of a target at each end of the street and one in the middle (a total station's
#: trigonometric heights, 3 mm each: coarse enough that their error shows beside the chain's)
LEVELS = {0: 3.0, 7: 3.0, 11: 3.0}


def test_a_level_run_to_three_targets_holds_the_street_in_height():
    """The datum's reading alone (60″) and the heights of three targets along the street
    (3 mm each, in their own datum): heights within the Monte Carlo's tolerance of
    the model (:func:`adjust` with ``heights_mm``); the level run taken as error-free
    (negative control) promises less than the survey gives, and the street without the run
    leans by several times more."""
    rms = dict.fromkeys(_observations(), TARGET_RMS_MM)
    tied = np.ones(len(STATIONS), dtype=bool)
    kw = {"datum": 0, "tilt_rms_arcsec": READING_ARCSEC, "tilt_readings": {0: READING_ARCSEC}}
    levelled = _predicted_z_mm(adjust(STATIONS, TARGETS, rms, tied, heights_mm=LEVELS, **kw))
    exact = _predicted_z_mm(
        adjust(STATIONS, TARGETS, rms, tied, heights_mm=dict.fromkeys(LEVELS, 1e-3), **kw)
    )
    sim = _survey(np.random.default_rng(54), "datum", LEVELS)
    tol = 4.0 / np.sqrt(2 * TRIALS)
    for j in POINTS:
        emp = np.sqrt(np.mean(np.square(sim[j]), axis=0))
        np.testing.assert_allclose(emp, levelled[j], rtol=tol)
    far = np.sqrt(np.mean(np.square(sim[4]), axis=0))
    assert (far / exact[4] - 1 > 3 * tol).all()  # error-free control: rejected
    assert (_models()["datum"][4] > 3 * far).all()  # mm: the run's worth at the far end


def test_the_datums_reading_as_a_prior_is_the_datums_lean():
    """The datum's tilt as an unknown with its reading as prior (no other reading, no
    level run) is the datum-lean model exactly: one rule, two ways of writing it."""
    rms = dict.fromkeys(_observations(), TARGET_RMS_MM)
    tied = np.ones(len(STATIONS), dtype=bool)
    kw = {"datum": 0, "tilt_rms_arcsec": READING_ARCSEC}
    prior = adjust(STATIONS, TARGETS, rms, tied, tilt_readings={0: READING_ARCSEC}, **kw)
    plain = adjust(STATIONS, TARGETS, rms, tied, **kw)
    np.testing.assert_allclose(prior, plain, rtol=1e-6, atol=1e-9)
