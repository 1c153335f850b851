"""Cloud-to-cloud link model (planner.cloud_registration) against a Monte Carlo: two scans
of planar surfaces simulated point by point (range noise along the beam, angular noise
across it, a per-scan offset of every patch for the floor), the second registered to the
first by a point-to-plane ICP written here (nearest neighbours, normals by PCA, Gauss-Newton
from a perturbed start) that shares no code with the prediction."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from planner.cloud_registration import (
    link_covariance,
    link_information,
    link_strength,
    overlap_pct,
    patch_variance_mm2,
    plane_rows,
    weakest_direction,
)
from planner.units import RHO_ARCSEC

RANGE_MM, ANGLE_ARCSEC, FLOOR_MM = 2.0, 10.0, 1.0
PATCH_M, GRID = 2.0, 6  # patches 2 m square, 6 × 6 points from each scan
PARENT = np.array([0.0, 0.0, 1.5])
CHILD = np.array([6.0, 2.0, 1.5])


def _patches(walls: bool = True, cross_wall: bool = True, ground: bool = True):
    """Patch centres, normals and in-plane axes: a long wall north (y = 12 m, facing south),
    a cross wall east (x = 15 m, facing west), the ground between (kept 1 m off the walls)."""
    out = []
    if walls:
        for x in np.arange(-9.0, 14.0, PATCH_M + 0.5):
            for z in (1.5, 4.0, 6.5):
                out.append(((x, 12.0, z), (0, -1.0, 0), (1.0, 0, 0), (0, 0, 1.0)))
    if cross_wall:
        for y in np.arange(-4.0, 11.0, PATCH_M + 0.5):
            for z in (1.5, 4.0, 6.5):
                out.append(((15.0, y, z), (-1.0, 0, 0), (0, 1.0, 0), (0, 0, 1.0)))
    if ground:
        for x in np.arange(-6.0, 13.0, PATCH_M + 0.5):
            for y in np.arange(-4.0, 10.5, PATCH_M + 0.5):
                out.append(((x, y, 0.0), (0, 0, 1.0), (1.0, 0, 0), (0, 1.0, 0)))
    c, n, u, v = (np.array(a, dtype=float) for a in zip(*out, strict=True))
    return c, n, u, v


def _normal_rms(c: np.ndarray, n: np.ndarray, station: np.ndarray) -> np.ndarray:
    """RMS of one point along the patch normal [mm]: range noise along the beam, angular
    noise across it, projected."""
    beam = c - station
    dist = np.linalg.norm(beam, axis=1)
    cos = np.abs((beam / dist[:, None] * n).sum(axis=1))
    lateral = dist * 1000.0 * ANGLE_ARCSEC / RHO_ARCSEC
    return np.sqrt((RANGE_MM * cos) ** 2 + lateral**2 * (1.0 - cos**2))


def predicted(
    patches, *, levelled: bool = False, tau_arcsec: float = 0.0, floor_mm: float = FLOOR_MM
) -> np.ndarray:
    c, n, _, _ = patches
    v_parent = patch_variance_mm2(_normal_rms(c, n, PARENT), GRID * GRID, floor_mm)
    v_child = patch_variance_mm2(_normal_rms(c, n, CHILD), GRID * GRID, floor_mm)
    info = link_information(plane_rows(c, n, CHILD), v_parent, v_child)
    return link_covariance(info, levelled=levelled, tilt_rms_arcsec=tau_arcsec)


def _scan(patches, station, rng, tilt=(0.0, 0.0)) -> np.ndarray:
    """One scan's points [m]: every patch's grid, the noise of each point, the patch's
    offset, and (levelled) the station's residual tilt about its centre."""
    c, n, u, v = patches
    t = (np.arange(GRID) + 0.5) / GRID - 0.5
    a, b = np.meshgrid(t * PATCH_M, t * PATCH_M)
    pts = (
        c[:, None, :]
        + a.ravel()[None, :, None] * u[:, None]
        + b.ravel()[None, :, None] * v[:, None]
    )
    pts += n[:, None, :] * rng.normal(0, FLOOR_MM / 1000.0, (len(c), 1, 1))
    pts = pts.reshape(-1, 3)
    beam = pts - station
    dist = np.linalg.norm(beam, axis=1, keepdims=True)
    unit = beam / dist
    # two directions across the beam
    e1 = np.cross(unit, [0.0, 0.0, 1.0])
    e1 /= np.linalg.norm(e1, axis=1, keepdims=True)
    e2 = np.cross(unit, e1)
    lat = dist * ANGLE_ARCSEC / RHO_ARCSEC
    pts = (
        pts
        + unit * rng.normal(0, RANGE_MM / 1000.0, dist.shape)
        + e1 * lat * rng.normal(size=dist.shape)
        + e2 * lat * rng.normal(size=dist.shape)
    )
    rot = _rotation(np.array([tilt[0], tilt[1], 0.0]))
    return (pts - station) @ rot.T + station


def _rotation(w: np.ndarray) -> np.ndarray:
    """Rotation matrix of a small rotation vector w [rad] (Rodrigues)."""
    th = np.linalg.norm(w)
    if th < 1e-15:
        return np.eye(3)
    k = w / th
    kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(th) * kx + (1 - np.cos(th)) * kx @ kx


def icp(parent: np.ndarray, child: np.ndarray, start: np.ndarray, free: list[int]) -> np.ndarray:
    """Point-to-plane ICP of ``child`` onto ``parent``: the pose (shift [mm], rotation
    [rad] about the child's centre) that brings the child's points onto the parent's local
    planes, the ``free`` parameters estimated from ``start``."""
    tree = cKDTree(parent)
    _, nb = tree.query(parent, k=10)
    local = parent[nb] - parent[nb].mean(axis=1, keepdims=True)
    _, vecs = np.linalg.eigh(np.einsum("pki,pkj->pij", local, local))
    normals = vecs[:, :, 0]  # smallest spread: the plane's normal
    centres = parent[nb].mean(axis=1)
    pose = start.astype(float).copy()
    for _ in range(6):
        moved = (child - CHILD) @ _rotation(pose[3:]).T + CHILD + pose[:3] / 1000.0
        _, j = tree.query(moved)
        nrm, ctr = normals[j], centres[j]
        res = ((moved - ctr) * nrm).sum(axis=1) * 1000.0  # mm
        lever = (moved - CHILD) * 1000.0
        jac = np.hstack([nrm, np.cross(lever, nrm)])[:, free]
        step = np.linalg.lstsq(jac, -res, rcond=None)[0]
        pose[free] += step
    return pose


def monte_carlo(patches, trials: int, *, tau_arcsec: float = 0.0, seed: int = 7) -> np.ndarray:
    """Estimated child poses' errors (trials, 6): shift [mm], rotation [rad]."""
    rng = np.random.default_rng(seed)
    levelled = tau_arcsec > 0
    free = [0, 1, 2, 5] if levelled else list(range(6))
    tau = tau_arcsec / RHO_ARCSEC
    out = np.empty((trials, 6))
    for k in range(trials):
        ti, tj = rng.normal(0, tau, 2), rng.normal(0, tau, 2)
        parent = _scan(patches, PARENT, rng, ti)
        child = _scan(patches, CHILD, rng, tj)
        start = np.zeros(6)
        start[free] = np.concatenate([rng.normal(0, 20.0, 3), rng.normal(0, 5e-4, len(free) - 3)])
        est = icp(parent, child, start, free)
        # the child's error relative to the parent: its tilts left as they are (levelled)
        est[[3, 4]] = est[[3, 4]] + (tj - ti) if levelled else est[[3, 4]]
        out[k] = est
    return out


TRIALS = 120


@pytest.fixture(scope="module")
def corner():
    patches = _patches()
    return patches, monte_carlo(patches, TRIALS)


def test_a_corner_link_agrees_with_the_icp_monte_carlo_per_axis(corner):
    patches, runs = corner
    cov = predicted(patches)
    sim = runs.std(axis=0)
    pred = np.sqrt(np.diag(cov))
    # shifts [mm] and rotations [rad]: every axis within 25 %
    assert sim / pred == pytest.approx(np.ones(6), abs=0.25)
    assert pred[:3] == pytest.approx([0.36, 0.32, 0.24], abs=0.02)  # mm


def test_leaving_the_floor_or_the_ground_out_of_the_prediction_disagrees(corner):
    """Negative controls: the same scans predicted without the patches' floor (every axis
    too optimistic), and without the ground's patches (two walls leave the height free)."""
    patches, runs = corner
    sim = runs.std(axis=0)
    no_floor = sim / np.sqrt(np.diag(predicted(patches, floor_mm=0.0)))
    assert no_floor.min() > 1.5
    c, n, u, v = patches
    walls = n[:, 2] == 0
    cov = predicted((c[walls], n[walls], u[walls], v[walls]))
    assert np.isinf(cov[2, 2]) and sim[2] == pytest.approx(0.24, abs=0.05)  # mm


def test_a_levelled_scanners_link_agrees_with_the_monte_carlo():
    patches = _patches()
    tau = 3.0  # arc-seconds per axis, each station
    runs = monte_carlo(patches, TRIALS, tau_arcsec=tau, seed=11)
    cov = predicted(patches, levelled=True, tau_arcsec=tau)
    sim, pred = runs.std(axis=0), np.sqrt(np.diag(cov))
    assert sim / pred == pytest.approx(np.ones(6), abs=0.25)


def test_a_straight_street_is_free_along_the_street():
    """One facade and the ground: the model says the link slides along the wall, which the
    ICP confirms (it does not take out its start's error there); a cross wall fixes it."""
    street = _patches(cross_wall=False)
    c, n, _, _ = street
    v = patch_variance_mm2(_normal_rms(c, n, CHILD), GRID * GRID, FLOOR_MM)
    info = link_information(plane_rows(c, n, CHILD), v, v)
    cond, smallest = link_strength(info)
    assert cond == np.inf and smallest == pytest.approx(0.0, abs=1e-9)
    cov = link_covariance(info)
    assert weakest_direction(cov) == "free: shift 090°/270° (east-west)"
    runs = monte_carlo(street, 20, seed=3)
    assert runs[:, 0].std() > 10.0  # mm: the start's 20 mm spread is not taken out
    corner_info = link_information(*_corner_rows())
    assert link_strength(corner_info)[0] < 1e4


def _corner_rows():
    c, n, _, _ = _patches()
    v = patch_variance_mm2(_normal_rms(c, n, CHILD), GRID * GRID, FLOOR_MM)
    return plane_rows(c, n, CHILD), v, v


def test_overlap_is_the_smaller_share():
    assert overlap_pct(50, 100, 50, 400) == pytest.approx(12.5, abs=1e-9)  # %
    assert overlap_pct(0, 0, 10, 10) == pytest.approx(0.0, abs=1e-9)  # %


@pytest.mark.parametrize("levelled", [False, True])
def test_one_link_adjusted_as_a_relative_pose_is_the_link(levelled):
    """The network's simultaneous adjustment of one cloud link's relative pose (the pose
    graph registration software adjusts) equals the pairwise link (the child's pose
    covariance, the datum its parent), levelled or not."""
    from planner.registration_error import Link, adjust, propagate

    c, n, _, _ = _patches()
    tau = 3.0 if levelled else 0.0
    vp = patch_variance_mm2(_normal_rms(c, n, PARENT), GRID * GRID, FLOOR_MM)
    vc = patch_variance_mm2(_normal_rms(c, n, CHILD), GRID * GRID, FLOOR_MM)
    info = link_information(plane_rows(c, n, CHILD), vp, vc)
    xyz = np.array([PARENT, CHILD])
    kw = {"levelled": levelled, "tilt_rms_arcsec": tau}
    chain = propagate(xyz, np.empty((0, 3)), {}, [Link(0, 1, (), info)], datum=0, **kw)
    adjusted = adjust(xyz, np.empty((0, 3)), {}, chain.tied, datum=0, relative=[(0, 1, info)], **kw)
    sd_adj, sd_chain = np.sqrt(np.diag(adjusted[1])), np.sqrt(np.diag(chain.pose_cov[1]))
    assert sd_adj == pytest.approx(sd_chain, rel=1e-6)
    sd_link = np.sqrt(np.diag(link_covariance(info, levelled=levelled, tilt_rms_arcsec=tau)))
    if not levelled:  # the datum is the parent: the child's pose is the link's
        assert sd_chain == pytest.approx(sd_link, rel=1e-6)
    else:  # its tilt is its own (τ), the link's the two stations' (τ√2)
        assert sd_chain[3:5] == pytest.approx(sd_link[3:5] / np.sqrt(2), rel=1e-6)
        assert sd_chain[5] == pytest.approx(sd_link[5], rel=1e-6)
