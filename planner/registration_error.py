r"""Registration error: from each target's centre RMS to the RMS of every scanned point.

Voroshilov & Karachentsev note, after their eq. 2, that once the stations are tied into one
coordinate system m_x and m_y grow by the errors of the station coordinates and of the
joining (their m_xc, m_yc). This module computes those errors per station, and per point,
from the targets that tie the scans together. It goes beyond the paper; the model is the
planner's, checked by a Monte Carlo of the whole chain in ``tests/test_registration_error.py``.

**Target centres.** A target's fitted centre is uncertain by (per axis) σ_t² = σ_floor² +
(fit) + (systematic), with σ_r the ranging RMS and σ_l = S·m/ρ the lateral RMS of one point
at the target's distance S, d the point spacing there and n the points on the target
(:func:`points_on_target`):

* a **sphere** fitted with its known radius R, its visible cap sampled evenly in the
  projected disc: the fit's variance across the beam (the larger axis)
  (w_r σ_r² + 8/3 σ_l²) / n, and a bias toward the scanner
  b = (β_r σ_r² + 8/15 σ_l²) / R — noise moves points off the sphere's surface more often
  than onto it, and the fit follows them (the second-order error analysis of geometric
  fits of Al-Sharadqah & Chernov 2009, carried out here for a known radius);
  w_r = 4/3, β_r = 4/5 for a constant ranging noise, 32/15 and 3/2 when it grows as
  1/√cos θ with the incidence (:func:`planner.accuracy3d.incidence_ranging_rms_mm`). The
  bias is counted as an error per axis (it points along each station's own beam);
* a **flat** (checkerboard) target, its centre found by a plane fit and its edges: the
  fit (σ_r² + 2σ_l²) / n (σ_r² / cos θ with incidence-dependent ranging) and the sampling
  of its edges — an edge lies somewhere between two scan points, and scan lines square to
  the board cross it at the same phase, so averaging along the edge does not help:
  (d / cos θ)² / 12 per in-plane axis (d / cos θ the coarser spacing on the board),
  counted on every axis.

The floor stands for what the fit does not see (the printing or turning of the target,
centring): 0.5 mm unless given. A user figure replaces the model. Both are checked against
targets scanned point by point and fitted in ``tests/test_target_centres.py``.

**Pairwise registration.** Station j is registered to station i by least squares over
their common targets: unknowns the shift δs and the rotation δω of j (6 parameters; 4 —
δs and the rotation about the vertical δκ — for a levelled scanner, whose tilt its
compensator fixes to σ_τ independently at every station). For target t at X_t,

.. math::

    A_t = [\,I_3 \;\; -[X_t - s_j]_\times\,], \qquad
    \hat\theta_j = N^{-1}\sum_t A_t^\top W_t\,(e_{i,t} - e_{j,t} + \text{pose error of } i
    \text{ at } X_t),

with W_t = (σ_{i,t}² + σ_{j,t}²)⁻¹ I. Chaining along the network from the datum makes every
station's pose error a linear combination of the measurement errors of every target seen
(and of the stations' tilts): :func:`propagate` keeps those combinations, so a target used
by two links is counted once, correctly correlated, and the covariance of every station's
pose is exact to first order. Control targets with known coordinates (and their RMS) can
be the datum.

**The adjustment.** Registration software adjusts every target observation of every scan
together, not pair after pair. :func:`adjust` gives the pose covariances of that
simultaneous least-squares adjustment (targets and poses unknown, the datum fixed; a
levelled scanner's residual tilts as correlated noise): with the same observations it is
never worse than the chain, equal to it where each target serves one registration, and
better where a scan sees targets of more than its own links (loops). The plan is judged on
it; the chain of :func:`propagate` still chooses the links and reports each link's own
error.

**Points.** A point p scanned from station j moves by ``δs_j + δω_j × (p − s_j)``; its
registration RMS in the facade frame (:func:`point_registration_variances`) adds to the
scanner's m_x, m_y, m_z in quadrature.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from numba import njit
from numpy.typing import ArrayLike

from planner.accuracy3d import INCIDENCE_NOISE_EXPONENT, MIN_COS_INCIDENCE
from planner.errors import InputError
from planner.units import RHO_ARCSEC

__all__ = [
    "DEFAULT_FLOOR_MM",
    "Link",
    "NetworkError",
    "adjust",
    "datum_lean_mm",
    "datum_tilt_cov",
    "pair_registration_variances",
    "point_registration_variances",
    "points_on_target",
    "propagate",
    "scaled_condition",
    "target_centre_rms_mm",
    "transport_pose_cov",
]

#: What a centre fit does not see (printing, turning, centring) [mm], per axis.
DEFAULT_FLOOR_MM = 0.5
#: The sphere fit's weights of the ranging variance (module docstring): its variance across
#: the beam and its bias toward the scanner, for a constant ranging noise and for one
#: growing as 1/√cos θ with the incidence (:data:`~planner.accuracy3d.
#: INCIDENCE_NOISE_EXPONENT` = 1/2: the weights are integrals over the visible cap with that
#: exponent; ``tests/test_target_centres.py`` checks them against a simulation with it).
SPHERE_FIT_RANGING = {False: (4.0 / 3.0, 4.0 / 5.0), True: (32.0 / 15.0, 3.0 / 2.0)}
TARGET_TYPES = ("flat", "sphere", "cylinder")
#: The datum: station index meaning "the control network" (targets with known coordinates).
CONTROL = -1


def points_on_target(
    target_type: str, size_mm: np.ndarray, spacing_mm: np.ndarray, cos_incidence: np.ndarray
) -> np.ndarray:
    """Scan points on a target: a flat square of side a seen at incidence θ holds
    a²·cos θ / d², a sphere of diameter D shows a disc of π·D²/4 (d the point spacing at its
    distance). At least 1.

    Examples
    --------
    >>> float(points_on_target("flat", 100.0, 10.0, 1.0))
    100.0
    >>> round(float(points_on_target("sphere", 200.0, 20.0, 1.0)), 2)
    78.54
    """
    size = np.asarray(size_mm, dtype=float)
    d2 = np.square(np.asarray(spacing_mm, dtype=float))
    if target_type == "flat":
        n = size * size * np.clip(np.asarray(cos_incidence, dtype=float), 0.0, 1.0) / d2
    else:
        n = np.pi * size * size / 4.0 / d2
    return np.maximum(n, 1.0)


def target_centre_rms_mm(
    target_type: str,
    size_mm: np.ndarray,
    slope_distance_m: np.ndarray,
    cos_incidence: np.ndarray,
    range_rms_mm: np.ndarray,
    angle_rms_arcsec: float,
    spacing_mm: np.ndarray,
    *,
    floor_mm: float = DEFAULT_FLOOR_MM,
    incidence_noise: bool = False,
) -> np.ndarray:
    """Per-axis RMS [mm] of a target's fitted centre seen from one station (module
    docstring): the floor, the noise of the points on it averaged by the fit, and the
    sphere fit's bias or the sampling of a flat target's edges. ``incidence_noise``: the
    ranging noise grows as 1/√cos θ with the incidence (the 3-D model's term). A cylinder
    is taken as a sphere of its diameter.

    Examples
    --------
    A 200 mm sphere at 50 m, 4 mm ranging, 12.4″, 10 mm spacing (its bias 0.18 mm):

    >>> round(float(target_centre_rms_mm("sphere", 200.0, 50.0, 1.0, 4.0, 12.4, 10.0)), 3)
    0.652

    A 200 mm checkerboard there, square to the beam: the edges' sampling, 10 / √12 mm,
    dominates.

    >>> round(float(target_centre_rms_mm("flat", 200.0, 50.0, 1.0, 4.0, 12.4, 10.0)), 3)
    2.944
    """
    if target_type not in TARGET_TYPES:
        raise InputError(f"target type must be one of {', '.join(TARGET_TYPES)}")
    s = np.asarray(slope_distance_m, dtype=float)
    size = np.asarray(size_mm, dtype=float)
    cos_t = np.clip(np.asarray(cos_incidence, dtype=float), MIN_COS_INCIDENCE, 1.0)
    d = np.asarray(spacing_mm, dtype=float)
    lateral2 = np.square(s * 1000.0 * angle_rms_arcsec / RHO_ARCSEC)
    ranging2 = np.square(np.asarray(range_rms_mm, dtype=float))
    n = points_on_target(target_type, size, d, cos_t)
    if target_type == "flat":
        if incidence_noise:
            ranging2 = ranging2 / cos_t ** (2.0 * INCIDENCE_NOISE_EXPONENT)
        fit = (ranging2 + 2.0 * lateral2) / n
        systematic = np.square(d / cos_t) / 12.0
    else:
        w_fit, w_bias = SPHERE_FIT_RANGING[bool(incidence_noise)]
        fit = (w_fit * ranging2 + 8.0 / 3.0 * lateral2) / n
        systematic = np.square((w_bias * ranging2 + 8.0 / 15.0 * lateral2) / (size / 2.0))
    return np.sqrt(floor_mm**2 + fit + systematic)


@dataclass(frozen=True, eq=False)
class Link:
    """A registration of ``child`` to ``parent`` (a station index, or :data:`CONTROL`) over
    the common targets ``targets`` — or, cloud to cloud, over the surfaces both scans see:
    ``info`` is then the information (6 × 6, at the child's centre) the adjustment takes
    the link with: its surfaces' point-to-plane information
    (:func:`planner.cloud_registration.link_information`) with its start's prior, over the
    rehearsal's factor where the plan rehearsed it
    (:attr:`planner.pipeline.network.clouds.CloudLink.information`)."""

    parent: int
    child: int
    targets: tuple[int, ...]
    info: np.ndarray | None = None

    @property
    def kind(self) -> str:
        return "targets" if self.info is None else "cloud"


@dataclass
class NetworkError:
    """The propagated errors: every station's pose covariance (6 × 6; shift in mm, rotation
    in radians, about the station) and, per link, the child's pose covariance from that
    link alone."""

    pose_cov: np.ndarray  # (K, 6, 6)
    link_cov: dict[tuple[int, int], np.ndarray]  # (parent, child) -> 6 x 6
    tied: np.ndarray  # (K,) bool: reached from the datum


def _skew(v: np.ndarray) -> np.ndarray:
    """[v]×, the cross-product matrix, of a 3-vector or a stack of them (…, 3) → (…, 3, 3)."""
    v = np.asarray(v, dtype=float)
    out = np.zeros((*v.shape[:-1], 3, 3))
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    out[..., 0, 1], out[..., 0, 2] = -z, y
    out[..., 1, 0], out[..., 1, 2] = z, -x
    out[..., 2, 0], out[..., 2, 1] = -y, x
    return out


def propagate(
    station_xyz: np.ndarray,
    target_xyz: np.ndarray,
    target_rms_mm: dict[tuple[int, int], float],
    links: Sequence[Link],
    *,
    datum: int | None = 0,
    control_rms_mm: dict[int, float] | None = None,
    levelled: bool = False,
    tilt_rms_arcsec: float = 0.0,
) -> NetworkError:
    """Pose covariance of every station after pairwise registrations along ``links``.

    Parameters
    ----------
    station_xyz : (K, 3) scanner centres [m]; target_xyz : (T, 3) target centres [m].
    target_rms_mm : per (station, target) observation, the per-axis RMS of the centre [mm].
    links : the registrations, each child after its parent (a tree from the datum).
    datum : the station whose frame is the datum (error 0), or None with control targets.
    control_rms_mm : control targets (index → per-axis RMS of their known coordinates);
        links with ``parent = CONTROL`` register a station to them.
    levelled : 4-parameter registrations; every station's tilt is an independent error of
        ``tilt_rms_arcsec`` per axis. Otherwise (6 parameters) each registration takes out
        its station's own tilt, and ``tilt_rms_arcsec`` is the datum's: the network's
        vertical is the datum scan's, tilted from true vertical by that much per axis
        (:func:`datum_tilt_cov`).
    """
    k = len(station_xyz)
    control_rms_mm = control_rms_mm or {}
    # the noise sources: one 3-vector per observation, per control target, per tilt
    index: dict[tuple, int] = {}
    sigma: list[float] = []

    def source(key: tuple, rms: float, dims: int) -> int:
        if key not in index:
            index[key] = len(sigma)
            sigma.extend([rms] * dims)
        return index[key]

    for (st, t), rms in target_rms_mm.items():
        source(("obs", st, t), rms, 3)
    for t, rms in control_rms_mm.items():
        source(("control", t), rms, 3)
    tau = tilt_rms_arcsec / RHO_ARCSEC
    if levelled:
        for st in range(k):
            source(("tilt", st), tau, 2)
    elif datum is not None and tau > 0:
        source(("tilt", datum), tau, 2)
    params = 4 if levelled else 6
    for link in links:
        if link.info is not None:
            source(("cloud", link.parent, link.child), 1.0, params)
    m = len(sigma)
    pose = {} if datum is None else {datum: np.zeros((6, m))}
    if ("tilt", datum) in index:  # the datum's tilt moves its points, and (6 parameters)
        # every station registered to its frame
        pose[datum][3:5, index[("tilt", datum)] : index[("tilt", datum)] + 2] = np.eye(2)
    link_only: dict[tuple[int, int], np.ndarray] = {}
    for link in links:
        if link.parent != CONTROL and link.parent not in pose:
            raise InputError(f"link {link}: station {link.parent} is not tied yet; order links")
        j = link.child
        if link.info is not None:
            pose[j], link_only[(link.parent, j)] = _cloud_pose(
                link, pose[link.parent], station_xyz, index, m, levelled
            )
            continue
        sj = station_xyz[j]
        n_mat = np.zeros((params, params))
        rhs = np.zeros((params, m))
        rhs_link = np.zeros((params, m))
        for t in link.targets:
            x = target_xyz[t]
            lever = (x - sj) * 1000.0  # mm: a rotation [rad] × lever [mm] → mm
            a_full = np.hstack([np.eye(3), -_skew(lever)])
            a = a_full if not levelled else a_full[:, [0, 1, 2, 5]]
            c = np.zeros((3, m))  # (where the parent puts the target) − (where j measures it)
            if link.parent == CONTROL:
                rms_i = control_rms_mm[t]
                c[:, index[("control", t)] : index[("control", t)] + 3] += np.eye(3)
            else:
                i = link.parent
                rms_i = target_rms_mm[(i, t)]
                c[:, index[("obs", i, t)] : index[("obs", i, t)] + 3] += np.eye(3)
                lever_i = (x - station_xyz[i]) * 1000.0
                c += np.hstack([np.eye(3), -_skew(lever_i)]) @ pose[i]
            rms_j = target_rms_mm[(j, t)]
            c[:, index[("obs", j, t)] : index[("obs", j, t)] + 3] -= np.eye(3)
            if levelled:  # j's own tilt moves what j measures: −τ_j × lever
                cols = index[("tilt", j)]
                c[:, cols : cols + 2] -= (-_skew(lever))[:, :2]
            w = 1.0 / (rms_i**2 + rms_j**2)
            n_mat += w * a.T @ a
            rhs += w * a.T @ c
            c_link = c.copy()
            if link.parent != CONTROL:  # the link alone: without the parent's pose error
                c_link -= (
                    np.hstack([np.eye(3), -_skew((x - station_xyz[link.parent]) * 1000)])
                    @ pose[link.parent]
                )
            rhs_link += w * a.T @ c_link
        if scaled_condition(n_mat) > MAX_CONDITION:
            raise InputError(
                f"the targets of link {link.parent}→{link.child} do not fix the registration "
                "(fewer than 3, or all on one line)"
            )
        theta = np.linalg.solve(n_mat, rhs)
        theta_link = np.linalg.solve(n_mat, rhs_link)
        pose[j] = _expand(theta, levelled, index, j, m)
        link_only[(link.parent, link.child)] = _expand(theta_link, levelled, index, j, m)
    var = np.square(np.asarray(sigma))
    pose_cov = np.zeros((k, 6, 6))
    tied = np.zeros(k, dtype=bool)
    for st, lmat in pose.items():
        pose_cov[st] = (lmat * var) @ lmat.T
        tied[st] = True
    link_cov = {key: (lmat * var) @ lmat.T for key, lmat in link_only.items()}
    return NetworkError(pose_cov=pose_cov, link_cov=link_cov, tied=tied)


def adjust(
    station_xyz: np.ndarray,
    target_xyz: np.ndarray,
    target_rms_mm: dict[tuple[int, int], float],
    tied: np.ndarray,
    *,
    datum: int | None = 0,
    control_rms_mm: dict[int, float] | None = None,
    levelled: bool = False,
    tilt_rms_arcsec: float = 0.0,
    relative: Sequence[tuple[int, int, np.ndarray]] = (),
    tilt_readings: Mapping[int, float] | None = None,
    heights_mm: Mapping[int, float] | None = None,
) -> np.ndarray:
    """Pose covariance (K, 6, 6) of every station after one simultaneous least-squares
    adjustment of all the target observations: what registration software does with every
    target each scan sees, rather than registering pair after pair.

    ``relative`` adds the cloud-to-cloud links: each (parent i, child j, information J)
    an observation of j's pose relative to i's, ``q_j − T_ij q_i`` (T_ij carries i's pose
    error to j's centre), with the link's information J (6 × 6 at j's centre, shift in mm,
    rotation in rad: :attr:`planner.pipeline.network.clouds.CloudLink.information`) — the
    pose graph registration software adjusts its cloud-to-cloud links in (a bundle of the
    pairwise registrations). Levelled, the link observes the 4 estimated parameters, and
    the two stations' unestimated tilts move it as they move the link's estimate
    (:func:`planner.cloud_registration.link_covariance`).

    Unknowns: the pose error q_j of each station in ``tied`` (6 parameters; 4 — shift and the
    rotation about the vertical — for a levelled scanner) and the error x_t of every target
    observed. An observation of target t from station j gives the rows
    ``x_t − A_t q_j = e_jt (+ A_t,tilt ζ_j)`` with A_t = [I | −[X_t − s_j]×], weight
    1 / σ_jt²; a control target adds ``x_t = c_t`` with its own RMS; the datum station's
    shift and rotation are fixed (its tilt is not). With G the design matrix and N = GᵀWG,
    the estimate's error is N⁻¹GᵀW times the noise; its covariance N⁻¹ plus, for a levelled
    scanner, the part of the unestimated tilts ζ (σ_τ per axis, every station, the datum's
    too): M Σ_ζ Mᵀ with M = N⁻¹GᵀW A_tilt, the tilt itself then being the pose's rotation
    about x and y. With 6 parameters every station's own tilt is estimated away, but the
    datum's frame is held: the whole network turns with the datum's tilt about the datum
    (:func:`datum_tilt_cov`, independent of the target noise), which is added (Ghilani,
    *Adjustment Computations*, 6th ed., Wiley 2017, ch. 10 and 21: the covariance of
    adjusted unknowns; Triggs et al., "Bundle adjustment — a modern
    synthesis", LNCS 1883, 2000, https://doi.org/10.1007/3-540-44480-7_21: targets and poses
    adjusted together). Stations not in ``tied`` keep zero covariance; the observations of
    ``target_rms_mm`` must tie every station in ``tied`` (the pairwise links that
    :func:`propagate` follows do). Checked by a Monte Carlo of rigid registrations in
    ``tests/test_registration_error.py``.

    ``tilt_readings`` (6 parameters only; station → RMS [″] per axis): those scans' recorded
    tilts are observations of their rotation about x and y, ``ω_j,xy = ζ_j`` — the datum's
    among them, whose tilt is then an unknown of the adjustment, not a fixed lean: the
    network's vertical is held by all the readings (their combined error), not by the
    datum's alone. ``heights_mm`` (target → RMS [mm]): targets whose heights a level run
    measured, each an observation ``z_t + c = h_t`` with the run's unknown height offset c
    (a level run gives heights in its own datum); two or more hold the network's vertical
    too, so the datum's tilt is then an unknown with its own reading as prior (give it in
    ``tilt_readings``). The readings' and the heights' noise enter N like any observation's,
    so the covariance is N⁻¹. Checked by the virtual surveys in
    ``tests/test_tilt_readings.py``.
    """
    k = len(station_xyz)
    control_rms_mm = control_rms_mm or {}
    readings = bool(tilt_readings) and not levelled
    heights_mm = heights_mm or {}
    if heights_mm and not levelled and datum is not None and datum not in (tilt_readings or {}):
        raise InputError(
            "levelled heights hold the network's vertical only with the datum's tilt an "
            "unknown: give the datum's reading in tilt_readings"
        )
    par = [0, 1, 2, 5] if levelled else [0, 1, 2, 3, 4, 5]  # the pose parameters estimated
    # each station's estimated parameters: the datum's tilt alone when the readings hold it
    s_par = {j: par for j in range(k) if tied[j] and j != datum}
    if readings and datum is not None and tied[datum]:
        s_par[datum] = [3, 4]
    s_col, n_pose = {}, 0
    for j in sorted(s_par):
        s_col[j], n_pose = n_pose, n_pose + len(s_par[j])
    obs = [(j, t, r) for (j, t), r in target_rms_mm.items() if tied[j]]
    targets = sorted({t for _, t, _ in obs} | set(control_rms_mm))
    t_col = {t: n_pose + 3 * n for n, t in enumerate(targets)}
    levelled_seen = [t for t in heights_mm if t in t_col]
    n_unk = n_pose + 3 * len(targets) + (1 if levelled_seen else 0)  # the level run's offset
    n_mat = np.zeros((n_unk, n_unk))
    tilt_rhs = np.zeros((n_unk, 2 * k))  # GᵀW A_tilt: each station's tilt in the estimate
    for j, t, rms in obs:
        w = 1.0 / rms**2
        lever = (target_xyz[t] - station_xyz[j]) * 1000.0
        a_full = np.hstack([np.eye(3), -_skew(lever)])
        tc = t_col[t]
        n_mat[tc : tc + 3, tc : tc + 3] += w * np.eye(3)
        if j in s_col:
            a = a_full[:, s_par[j]]
            sc, ec = s_col[j], s_col[j] + a.shape[1]
            n_mat[sc:ec, sc:ec] += w * a.T @ a
            n_mat[sc:ec, tc : tc + 3] -= w * a.T
            n_mat[tc : tc + 3, sc:ec] -= w * a
        if levelled:  # the row x_t − A q_j carries A_tilt ζ_j on its right-hand side
            a_tilt = a_full[:, 3:5]
            tilt_rhs[tc : tc + 3, 2 * j : 2 * j + 2] += w * a_tilt
            if j in s_col:
                sc = s_col[j]
                tilt_rhs[sc : sc + len(par), 2 * j : 2 * j + 2] -= w * a_full[:, par].T @ a_tilt
    for t, rms in control_rms_mm.items():
        tc = t_col[t]
        n_mat[tc : tc + 3, tc : tc + 3] += np.eye(3) / rms**2
    if readings:  # the scans' readings of their own tilt
        for j, pj in s_par.items():
            if j not in tilt_readings:
                continue
            w_tilt = (RHO_ARCSEC / tilt_readings[j]) ** 2
            for r, p in enumerate(pj):
                if p in (3, 4):
                    n_mat[s_col[j] + r, s_col[j] + r] += w_tilt
    for t in levelled_seen:  # z_t + c = h_t: the target's z and the run's offset (last)
        w_h, z = 1.0 / heights_mm[t] ** 2, t_col[t] + 2
        n_mat[z, z] += w_h
        n_mat[z, -1] += w_h
        n_mat[-1, z] += w_h
        n_mat[-1, -1] += w_h
    for i, j, info in relative:
        _relative(n_mat, tilt_rhs, station_xyz, (i, j), info, s_col, s_par, levelled)
    pose_cov = np.zeros((k, 6, 6))
    tau2 = (tilt_rms_arcsec / RHO_ARCSEC) ** 2
    if n_unk:
        n_inv = np.linalg.inv(n_mat)
        cov_q = n_inv
        m = n_inv @ tilt_rhs  # (unknowns, 2K)
        if levelled:
            cov_q = n_inv + tau2 * m @ m.T
    else:  # nothing to adjust (one station): only the tilts
        cov_q, m = np.zeros((0, 0)), np.zeros((0, 2 * k))
    for j in range(k):
        if not tied[j]:
            continue
        # the pose error: estimated parameters and, levelled, the tilt ζ_j itself
        lin = np.zeros((6, n_unk))
        for r, p in enumerate(s_par.get(j, [])):
            lin[p, s_col[j] + r] = 1.0
        c = lin @ cov_q @ lin.T
        if levelled:
            cross = lin @ m[:, 2 * j : 2 * j + 2] * tau2  # Cov(estimate, ζ_j)
            c[:, 3:5] += cross
            c[3:5, :] += cross.T
            c[3:5, 3:5] += tau2 * np.eye(2)
        pose_cov[j] = c
    if not levelled and not readings and datum is not None:
        pose_cov[tied] += datum_tilt_cov(station_xyz[tied], station_xyz[datum], tilt_rms_arcsec)
    return pose_cov


def datum_lean_mm(distance_m: ArrayLike, tilt_rms_arcsec: float) -> np.ndarray:
    """RMS [mm] of the height error the datum's tilt (``tilt_rms_arcsec`` per axis) gives a
    point ``distance_m`` [m] from the datum, horizontally (:func:`datum_tilt_cov`).

    Examples
    --------
    >>> round(float(datum_lean_mm(50.0, 12.4)), 2)
    3.01
    """
    return np.asarray(distance_m, dtype=float) * 1000.0 * tilt_rms_arcsec / RHO_ARCSEC


def datum_tilt_cov(
    station_xyz: np.ndarray, datum_xyz: np.ndarray, tilt_rms_arcsec: float
) -> np.ndarray:
    """Pose covariance (K, 6, 6) the datum's tilt gives stations registered to its frame
    with 6 parameters: registration software holds the datum scan's frame, so the network's
    vertical is the datum scanner's axis, tilted from true vertical by ζ (σ =
    ``tilt_rms_arcsec`` about x and about y); every station turns with it about the datum —
    rotation ζ, shift ζ × (s − s_datum). Heights are against true vertical, so this is an
    error of every point, growing with its distance from the datum. (Voroshilov &
    Karachentsev's eq. 3–4 measure heights from the initial horizontal direction with RMS
    m_ν0 at distance S₀: for a network that direction is the datum's, at the point's
    distance from the datum.)

    Examples
    --------
    A station 100 m east of the datum, 12.4″ (60 µrad): 6 mm up or down.

    >>> c = datum_tilt_cov(np.array([[100.0, 0.0, 1.5]]), np.array([0.0, 0.0, 1.5]), 12.4)
    >>> round(float(np.sqrt(c[0, 2, 2])), 2)
    6.01
    """
    xyz = np.atleast_2d(np.asarray(station_xyz, dtype=float))
    jac = np.zeros((len(xyz), 6, 2))
    jac[:, 3:5, :] = np.eye(2)
    jac[:, 0:3, :] = -_skew((xyz - np.asarray(datum_xyz, dtype=float)) * 1000.0)[:, :, 0:2]
    tau2 = (tilt_rms_arcsec / RHO_ARCSEC) ** 2
    return tau2 * jac @ np.swapaxes(jac, 1, 2)


def _relative(n_mat, tilt_rhs, station_xyz, pair, info, s_col, s_par, levelled) -> None:
    """Add one cloud link's relative-pose observation (:func:`adjust`'s ``relative``) to the
    normal equations and, levelled, to the tilts' right-hand side (``s_col``, ``s_par``:
    each estimated station's first column and its parameters). In place."""
    i, j = pair
    par = [0, 1, 2, 5] if levelled else list(range(6))
    pick = np.eye(6)[par]  # the observed parameters
    t = np.eye(6)
    t[:3, 3:] = -_skew((station_xyz[j] - station_xyz[i]) * 1000.0)  # i's error at j
    w = info[np.ix_(par, par)]
    rows = {j: pick, i: -pick @ t}  # the observation's rows on each station's full pose
    tilts = {}
    if levelled:  # the unestimated tilts: the link's response to them, and i's at j
        m = -np.linalg.solve(w, info[np.ix_(par, [3, 4])])
        tilts = {j: m, i: pick @ t[:, 3:5] - m}
    g = {u: r[:, s_par[u]] for u, r in rows.items() if u in s_col}
    for u, gu in g.items():
        cu = slice(s_col[u], s_col[u] + gu.shape[1])
        for v, gv in g.items():
            n_mat[cu, s_col[v] : s_col[v] + gv.shape[1]] += gu.T @ w @ gv
        for st, a in tilts.items():
            tilt_rhs[cu, 2 * st : 2 * st + 2] += gu.T @ w @ a


#: A normal matrix this ill-conditioned (its diagonal scaled to one, so that shifts in mm and
#: rotations in radians compare) does not fix a registration.
MAX_CONDITION = 1e8


def scaled_condition(n_mats: np.ndarray) -> np.ndarray | float:
    """Condition number of symmetric normal matrices (…, p, p) with their diagonal scaled to
    one; inf where a diagonal element is not positive (a parameter nothing determines). One
    matrix (p, p) gives a scalar, a stack (…, p, p) an array.

    Examples
    --------
    >>> n = np.diag([1.0, 1e9])  # well posed, only in different units
    >>> float(np.linalg.cond(n)), round(float(scaled_condition(n)), 6)
    (1000000000.0, 1.0)
    """
    n_mats = np.asarray(n_mats, dtype=float)
    if n_mats.ndim == 2:  # one matrix, as the planner asks: the same steps, fewer calls
        diag = n_mats.diagonal()
        if not (diag.min() > 0 and np.isfinite(n_mats).all()):
            return np.float64(np.inf)
        d = 1.0 / np.sqrt(diag)
        w = np.abs(np.linalg.eigvalsh(n_mats * d[:, None] * d[None, :]))
        low = w.min()
        return w.max() / low if low > 0 else np.float64(np.inf)
    diag = np.diagonal(n_mats, axis1=-2, axis2=-1)
    fine = (diag > 0).all(axis=-1) & np.isfinite(n_mats).all(axis=(-2, -1))
    if not fine.all():  # (the usual case, every matrix fine, needs no masking)
        diag = np.where(fine[..., None], diag, 1.0)
        n_mats = np.where(fine[..., None, None], n_mats, np.eye(diag.shape[-1]))
    d = 1.0 / np.sqrt(diag)
    # symmetric: its eigenvalues' magnitudes are the singular values, and faster
    w = np.abs(np.linalg.eigvalsh(n_mats * d[..., :, None] * d[..., None, :]))
    with np.errstate(divide="ignore"):
        return np.where(fine, w.max(axis=-1) / w.min(axis=-1), np.inf)


def transport_pose_cov(
    pose_cov: np.ndarray, from_xyz: np.ndarray, to_xyz: np.ndarray
) -> np.ndarray:
    """A pose covariance (…, 6, 6; shift in mm about ``from_xyz``, rotation in rad) moved to
    a centre at ``to_xyz`` [m]: the shift there is ``δs + δω × (to − from)``.

    Examples
    --------
    >>> c = np.zeros((6, 6)); c[5, 5] = 1e-10  # 10 µrad about the vertical
    >>> moved = transport_pose_cov(c, np.zeros(3), np.array([100.0, 0, 0]))
    >>> round(float(np.sqrt(moved[1, 1])), 3)  # 10 µrad × 100 m = 1 mm across
    1.0
    """
    delta = (np.asarray(to_xyz, dtype=float) - np.asarray(from_xyz, dtype=float)) * 1000.0
    delta = np.broadcast_to(delta, (*np.shape(pose_cov)[:-2], 3))
    jac = np.zeros((*delta.shape[:-1], 6, 6))
    jac[..., :, :] = np.eye(6)
    jac[..., :3, 3:] = -_skew(delta)
    return jac @ pose_cov @ np.swapaxes(jac, -1, -2)


def _cloud_pose(
    link: Link, parent: np.ndarray, station_xyz: np.ndarray, index: dict, m: int, levelled: bool
) -> tuple[np.ndarray, np.ndarray]:
    """A cloud link's child pose as a combination of the noise sources, and the link's own
    part: the parent's pose carried to the child, plus the link's error (its covariance the
    inverse of its information, one source per parameter); levelled, plus the estimate's
    response to the relative tilt (ζ_j minus the parent's tilt), the tilt itself ζ_j
    (:func:`planner.cloud_registration.link_covariance`)."""
    i, j = link.parent, link.child
    par = [0, 1, 2, 5] if levelled else list(range(6))
    sub = link.info[np.ix_(par, par)]
    inv = np.linalg.inv(sub)
    chol = np.linalg.cholesky(0.5 * (inv + inv.T))
    jac = np.eye(6)
    jac[:3, 3:] = -_skew((station_xyz[j] - station_xyz[i]) * 1000.0)
    moved = jac @ parent
    c = index[("cloud", i, j)]
    noise = np.zeros((6, m))
    noise[np.ix_(par, range(c, c + len(par)))] = chol
    if not levelled:
        return moved + noise, noise
    tilt_j = np.zeros((2, m))
    tj = index[("tilt", j)]
    tilt_j[:, tj : tj + 2] = np.eye(2)
    tilt_i = np.zeros((2, m))
    ti = index[("tilt", i)]
    tilt_i[:, ti : ti + 2] = np.eye(2)
    resp = -inv @ link.info[np.ix_(par, [3, 4])]
    out, own = moved.copy(), np.zeros((6, m))
    out[par] += noise[par] + resp @ (tilt_j - moved[3:5])
    out[3:5] = tilt_j
    own[par] = noise[par] + resp @ (tilt_j - tilt_i)
    own[3:5] = tilt_j - tilt_i
    return out, own


def _expand(theta: np.ndarray, levelled: bool, index: dict, j: int, m: int) -> np.ndarray:
    """A station's pose error (6 rows: shift, rotation) from the fitted parameters."""
    if not levelled:
        return theta
    out = np.zeros((6, m))
    out[0:3] = theta[0:3]
    out[5] = theta[3]
    cols = index[("tilt", j)]
    out[3:5, cols : cols + 2] = np.eye(2)  # the compensator's residual tilt of station j
    return out


def point_registration_variances(
    pose_cov: np.ndarray,
    station_xyz: np.ndarray,
    point_xyz: np.ndarray,
    along_xy: np.ndarray,
    normal_xy: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Registration variance [mm²] of points in their facade frames.

    ``pose_cov`` (P, 6, 6) is the pose covariance of the station each point was scanned
    from (``station_xyz`` (P, 3)); ``along_xy``, ``normal_xy`` (P, 2) the facade's unit
    vectors. The point moves by ``δs + δω × (p − s)`` (see
    :func:`pair_registration_variances` for the quadratic this is).
    """
    var = _lever_variances(pose_cov, station_xyz, point_xyz, along_xy, normal_xy, paired=True)
    return var[0, 0], var[1, 0], var[2, 0]


def pair_registration_variances(
    pose_cov: np.ndarray,
    station_xyz: np.ndarray,
    point_xyz: np.ndarray,
    along_xy: np.ndarray,
    normal_xy: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Registration variance [mm²] of ``n`` points of one facade (its unit vectors
    ``along_xy``, ``normal_xy``) scanned from each of ``c`` stations: arrays (c, n).

    Along a unit vector u the point moves by ``gᵀ·(δs, δω)`` with ``g = (u, r × u)``
    (r = p − s in mm), so its variance is ``gᵀ C g``. With ``r × u = Kᵀ r`` (K the cross
    product matrix of u) that is ``b + M r`` for b = (u, 0) and M = (0; Kᵀ), and the
    variance the quadratic ``bᵀCb + 2 (MᵀCb)·r + rᵀ (MᵀCM) r`` in the lever, its
    coefficients once per station.
    """
    var = _lever_variances(pose_cov, station_xyz, point_xyz, along_xy, normal_xy, paired=False)
    return var[0], var[1], var[2]


def _lever_variances(
    pose_cov: np.ndarray,
    station_xyz: np.ndarray,
    point_xyz: np.ndarray,
    along_xy: np.ndarray,
    normal_xy: np.ndarray,
    paired: bool,
) -> np.ndarray:
    """The variances [mm²] along, across and in height: (3, S, n) for every one of the S
    stations with every one of the n points, or (``paired``) (3, 1, S) for station i with
    point i."""
    s = len(pose_cov)
    out = np.empty((3, 1, s) if paired else (3, s, len(point_xyz)))
    _lever_quadratics(
        _variance_coefficients(np.asarray(pose_cov, dtype=float), along_xy, normal_xy),
        np.ascontiguousarray(station_xyz, dtype=float),
        np.ascontiguousarray(point_xyz, dtype=float),
        paired,
        out,
    )
    return out


def _variance_coefficients(
    pose_cov: np.ndarray, along_xy: np.ndarray, normal_xy: np.ndarray
) -> np.ndarray:
    """(3, S, 10) the variance along the facade, across it and in height as quadratics in
    the lever r [mm], per pose covariance (S, 6, 6): ``bᵀCb``, ``2 MᵀCb`` (x, y, z) and
    ``MᵀCM`` (xx, yy, zz, then xy, xz, yz doubled) — :func:`pair_registration_variances`.
    The facade's unit vectors are one (2,) or one per pose (S, 2)."""
    s = len(pose_cov)
    flat = np.zeros((s, 3))
    out = np.empty((3, s, 10))
    for k, u2 in enumerate((along_xy, normal_xy, None)):
        u = flat.copy()
        if u2 is None:
            u[:, 2] = 1.0
        else:
            u[:, :2] = u2
        b = np.concatenate([u, flat], axis=1)  # (S, 6)
        m = np.concatenate([np.zeros((s, 3, 3)), np.swapaxes(_skew(u), 1, 2)], axis=1)
        mt = np.swapaxes(m, 1, 2)  # (S, 3, 6): r × u = Kᵀ r, the rows of δω
        cb = (pose_cov @ b[:, :, None])[..., 0]  # (S, 6)
        c2 = mt @ pose_cov @ m  # (S, 3, 3)
        out[k, :, 0] = (b * cb).sum(axis=1)
        out[k, :, 1:4] = 2.0 * (mt @ cb[:, :, None])[..., 0]
        out[k, :, 4:7] = np.diagonal(c2, axis1=1, axis2=2)
        out[k, :, 7] = 2.0 * c2[:, 0, 1]
        out[k, :, 8] = 2.0 * c2[:, 0, 2]
        out[k, :, 9] = 2.0 * c2[:, 1, 2]
    return out


@njit(cache=True, nogil=True)
def _lever_quadratics(coef, station_xyz, point_xyz, paired, out):  # pragma: no cover
    """Evaluate the quadratics ``coef`` (3, S, 10) of :func:`_variance_coefficients` at the
    levers r = (point − station)·1000 [mm]: every station with every point into ``out``
    (3, S, n), or (``paired``) station i with point i only into ``out`` (3, 1, S)."""
    for k in range(coef.shape[0]):
        for j in range(coef.shape[1]):
            a = coef[k, j]
            first, last = (j, j + 1) if paired else (0, point_xyz.shape[0])
            for i in range(first, last):
                x = (point_xyz[i, 0] - station_xyz[j, 0]) * 1000.0
                y = (point_xyz[i, 1] - station_xyz[j, 1]) * 1000.0
                z = (point_xyz[i, 2] - station_xyz[j, 2]) * 1000.0
                v = a[0] + a[1] * x + a[2] * y + a[3] * z
                v += a[4] * x * x + a[5] * y * y + a[6] * z * z
                v += a[7] * x * y + a[8] * x * z + a[9] * y * z
                if paired:
                    out[k, 0, j] = v
                else:
                    out[k, j, i] = v
