r"""The plan's own check of a cloud-to-cloud link: the two scans rehearsed and registered.

The link model (:mod:`planner.cloud_registration`) is a closed form near convergence; a
real registration also has to get there. So every cloud link a plan relies on is
rehearsed (:func:`rehearse_link`): the two set-ups' scans simulated in the plan's scene
(:mod:`planner.pipeline.geometry.beams`: the scanner's grid at the spacing the registration
thins the clouds to, cast only towards the surfaces the two scans share; the plan's noise
and the surfaces' own error, :class:`~planner.pipeline.geometry.beams.Floor`), the child
started where the scanner's pre-alignment or the operator's picking puts it
(:attr:`planner.scanner.Scanner.prealign`), and registered by a well-kept generalized ICP
(GICP: Segal, Haehnel & Thrun, "Generalized-ICP", Robotics: Science and Systems 2009,
https://doi.org/10.15607/RSS.2009.V.021) as the library ``small_gicp`` implements it
(Koide, "small_gicp: Efficient and parallel algorithms for point cloud registration",
Journal of Open Source Software 9(100), 6948, 2024, https://doi.org/10.21105/joss.06948)
— a registration the link model shares no code with.

What the check gives (:class:`LinkCheck`):

* the error of each trial (its own noise and start) at the child's centre, and the RMS
  over the trials that converged;
* the **basin**: the child started 3 σ of the start's error away along each horizontal
  axis and about the vertical (both ways), and where it does not come back from there, 2 σ
  and 1 σ (:data:`PROBE_LADDER`): the largest from which it comes back is the basin's edge
  in that direction, and the chance of a start beyond it (the normal distribution's two
  tails, summed over the directions) is the link's chance of failing, with the share of
  random starts that failed if that is larger. A link that fails more than
  :data:`MAX_FAILURE` of the time is not a link.

A trial *fails* when the registered child is more than :data:`FAIL_MM` off at its centre
or, by its rotation, at :data:`~planner.cloud_registration.LEVER_M`: a registration caught
in a wrong minimum, or left near its start along a direction its surfaces do not fix.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np
from scipy.spatial import cKDTree

from planner.cloud_registration import (
    LEVER_M,
    LINK_NEIGHBOURS,
    MAX_LINK_INCIDENCE_DEG,
    registration_spacing,
)
from planner.pipeline.geometry.beams import (
    Floor,
    Returns,
    World,
    cast,
    grid,
    measure,
    unit,
)
from planner.units import RHO_ARCSEC

__all__ = [
    "FAIL_MM",
    "MAX_FAILURE",
    "LinkCheck",
    "StartError",
    "rehearse_link",
]

#: A trial is a failure beyond this error [mm] at the child's centre or at the lever.
FAIL_MM = 10.0
#: A link failing more often than this is not a link (the issue's 1 %).
MAX_FAILURE = 0.01
#: The basin is probed this many standard deviations of the start's error away, along x,
#: along y and about the vertical, both ways; where the registration does not come back
#: from the first, from the next. A basin reaching 3 σ in all three directions leaves
#: 3 · P(|z| > 3) = 0.8 % of starts outside; one reaching only 2 σ in one, 4.6 %.
PROBE_SIGMAS = 3.0
PROBE_LADDER = (PROBE_SIGMAS, 2.0, 1.0)
PROBED = (0, 1, 5)
#: GICP's neighbours for each point's covariance (the library's default), its largest
#: correspondence distance [m] (for scans that start within decimetres) and its iterations
#: (half the library's 20: a start that has not come back in 10 has failed). One stage, on
#: purpose: refined coarse to fine (0.5, 0.25, 0.15 m) the rehearsal passed links that the
#: independent survey registered up to 6 × worse than the plan's error, and 28 samples of
#: the default site's cloud plan were marked met over their limits (benchmarks/RESULTS.md,
#: "cloud-survey", 2026-11-28); in one stage, none. (In one stage, points at the edges of
#: what two scans share find wrong partners within 0.5 m: such a link fails its rehearsal,
#: and the plan ties the station otherwise.)
NEIGHBOURS = 10
MAX_CORRESPONDENCE_M = 0.5
MAX_ITERATIONS = 10
#: GICP stops when an iteration moves the pose less than this [rad; m]: 2″ and 0.01 mm.
EPSILON = 1e-5
#: The grid is cast at the even spacing on the patch this far into their distances from the
#: scanner (nearer ones are thinned to it, farther ones are sampled coarser: a little
#: pessimistic there, and the check's cost stays that of the surfaces shared).
FAR_QUANTILE = 0.75
#: A thinned cloud is registered on at most this many of its points, drawn at random (as
#: CloudCompare's ICP samples at most 50 000 points of a cloud by default).
MAX_POINTS = 50_000
#: A beam direction is cast when it falls within this many patch half-widths of a patch
#: both scans share (the patches are cells of about 2 m).
PATCH_HALF_M = 1.5


@dataclass(frozen=True)
class StartError:
    """Where a registration starts: the RMS of the child's position per axis [mm] and of
    its heading and tilt about each horizontal axis [″] relative to the parent."""

    position_mm: float
    heading_arcsec: float
    tilt_arcsec: float

    def draw(self, rng: np.random.Generator) -> np.ndarray:
        """A random start (6,): shift [mm], rotation about x, y, z [rad]."""
        rad = np.array([self.tilt_arcsec, self.tilt_arcsec, self.heading_arcsec]) / RHO_ARCSEC
        return np.concatenate([rng.normal(0.0, self.position_mm, 3), rng.normal(0.0, rad)])

    def probe(self, direction: int, sign: float, sigmas: float) -> np.ndarray:
        """A start ``sigmas`` standard deviations off along one of :data:`PROBED` (0: x,
        1: y, 5: the heading), ``sign`` the side: (6,) shift [mm], rotation [rad]."""
        v = np.zeros(6)
        sd = self.heading_arcsec / RHO_ARCSEC if direction >= 3 else self.position_mm
        v[direction] = sign * sigmas * sd
        return v


@dataclass(frozen=True)
class LinkCheck:
    """What the rehearsal of one link found (module text)."""

    errors: np.ndarray  # (T, 6) each trial's error at the child's centre [mm, rad]
    failed: np.ndarray  # (T,) bool
    probes_failed: int  # of the basin's probes
    probes: int
    failure: float  # the chance the link fails (module text)
    points: tuple[int, int]  # points registered per trial (parent, child), after thinning

    @property
    def holds(self) -> bool:
        return self.failure <= MAX_FAILURE


def rehearse_link(
    world: World,
    parent_xyz: np.ndarray,
    child_xyz: np.ndarray,
    common_xyz: np.ndarray,
    start: StartError,
    *,
    spacing_mm: float,
    floor: tuple[float, float, float],
    trials: int = 3,
    seed: int = 0,
) -> LinkCheck:
    """Rehearse the registration of the scan at ``child_xyz`` to the one at ``parent_xyz``
    (scanner centres [m]) over the surfaces around ``common_xyz`` (P, 3) [m] that both see:
    ``trials`` draws of noise and start, and the basin's probes (module text). The clouds
    are thinned to ``spacing_mm`` (as registration software thins them); ``floor``: the
    surfaces' own error (plane and relief RMS [mm], cell [m])."""
    v_m = spacing_mm / 1000.0
    origin = np.asarray(parent_xyz, dtype=float)
    centre = np.asarray(child_xyz, dtype=float) - origin  # the child in the check's frame
    rets = [_cast_towards(world, np.asarray(s, float), common_xyz, v_m)
            for s in (parent_xyz, child_xyz)]  # fmt: skip
    rot = np.eye(3)
    errors, failed, sizes = [], [], (0, 0)
    probes_failed = n_probes = 0
    for t in range(trials):
        clouds = []
        for k, (pos, ret) in enumerate(zip((parent_xyz, child_xyz), rets, strict=True)):
            rng = np.random.default_rng([seed, t, k])
            fl = Floor(floor[0], floor[1], floor[2], scan_key=(seed * 1000 + t) * 2 + k + 1)
            m = measure(world, ret, np.asarray(pos, float), rot, rng, floor=fl)
            clouds.append(m.local_xyz + (np.asarray(pos, float) - origin))
        parent, child = (
            _prepared(_sampled(_thinned(c, v_m), (seed, t, k))) for k, c in enumerate(clouds)
        )
        sizes = (parent[0].size(), child[0].size())
        rng = np.random.default_rng([seed, t, 2])
        e = _register(parent, child, centre, start.draw(rng))
        errors.append(e)
        failed.append(_fails(e))
        if t == 0:  # the basin, on the first trial's clouds
            reach = []
            for direction in PROBED:
                r, n, bad = _basin(parent, child, centre, start, direction)
                reach.append(r)
                n_probes += n
                probes_failed += bad
    failed_arr = np.array(failed)
    # the chance of a start beyond the basin, summed over the directions probed
    basin = sum(_tail(r) for r in reach)
    failure = max(basin, float(failed_arr.mean()) if len(failed_arr) else 1.0)
    return LinkCheck(
        errors=np.array(errors).reshape(-1, 6),
        failed=failed_arr,
        probes_failed=int(probes_failed),
        probes=n_probes,
        failure=failure,
        points=sizes,
    )


def _basin(parent, child, centre: np.ndarray, start: StartError, direction: int) -> tuple:
    """How far the basin reaches along ``direction`` (in σ of the start's error): the largest
    of :data:`PROBE_LADDER` from which the registration comes back on both sides (0: not
    even from the smallest); and the probes made, and how many failed."""
    made = bad = 0
    for sigmas in PROBE_LADDER:
        ok = True
        for sign in (1.0, -1.0):
            made += 1
            if _fails(_register(parent, child, centre, start.probe(direction, sign, sigmas))):
                bad += 1
                ok = False
                break
        if ok:
            return sigmas, made, bad
    return 0.0, made, bad


def _tail(k: float) -> float:
    """The chance a normal variable lies more than k σ from its mean (both tails)."""
    return math.erfc(k / math.sqrt(2.0))


def _fails(e: np.ndarray) -> bool:
    return bool(
        np.linalg.norm(e[:3]) > FAIL_MM or np.linalg.norm(e[3:]) * LEVER_M * 1000.0 > FAIL_MM
    )


def _cast_towards(world: World, pos: np.ndarray, common_xyz: np.ndarray, v_m: float):
    """The returns of the beams from ``pos`` on the patches ``common_xyz``: a grid at the
    spacing ``v_m`` at :data:`FAR_QUANTILE` of their distances (never finer than the
    scanner's own step), only its beams that point within :data:`PATCH_HALF_M` of a patch,
    and of their returns those that land within it where the grid's points form a plane,
    one per cell of half the spacing."""
    sc, st = world.scanner, world.settings
    rel = np.asarray(common_xyz, dtype=float) - pos
    dist = np.linalg.norm(rel, axis=1)
    far = float(np.quantile(dist, FAR_QUANTILE)) if len(dist) else 10.0
    step = max(st.scan_step_mm(sc) / 1e4, v_m / max(far, 1.0))
    az, el = grid(step, sc.vertical_fov_deg)
    # a raster of directions (0.25°) marked around each patch
    cell = np.radians(0.25)
    n_az, n_el = int(np.ceil(2 * np.pi / cell)), int(np.ceil(np.pi / cell))
    mark = np.zeros((n_el, n_az), dtype=bool)
    p_az = np.arctan2(rel[:, 1], rel[:, 0]) % (2 * np.pi)
    p_el = np.arcsin(np.clip(rel[:, 2] / np.maximum(dist, 1e-9), -1.0, 1.0))
    half = np.arctan2(PATCH_HALF_M, np.maximum(dist, 1e-3)) + step
    for a, e, h in zip(p_az, p_el, half, strict=True):
        e0, e1 = int((e - h + np.pi / 2) / cell), int((e + h + np.pi / 2) / cell) + 1
        w = h / max(np.cos(min(abs(e) + h, np.radians(89.0))), 1e-3)
        a0, a1 = int((a - w) / cell), int((a + w) / cell) + 1
        cols = np.arange(a0, a1) % n_az
        mark[max(e0, 0) : min(e1, n_el), cols] = True
    col, row = np.meshgrid(np.arange(len(az)), np.arange(len(el)))
    col, row = col.ravel(), row.ravel()
    ai = (az[col] / cell).astype(np.int64) % n_az
    ei = np.clip(((el[row] + np.pi / 2) / cell).astype(np.int64), 0, n_el - 1)
    keep = mark[ei, ai]
    ret = cast(world, pos, np.eye(3), az, el, col[keep], row[keep])
    # only what lies on the shared surfaces (the directions also hold what is behind them)
    hit = pos + ret.dist[:, None] * unit(ret.az, ret.el)
    near = cKDTree(common_xyz).query(hit, distance_upper_bound=PATCH_HALF_M)[0] <= PATCH_HALF_M
    # where the check's grid, coarser than the scanner's own step, leaves lines of points
    # (grazing, or beyond the incidence a registration takes), the scanner's thinned scan
    # leaves a plane: left out
    along, across = registration_spacing(step * 1000.0 * ret.dist, ret.cos, v_m * 1000.0)
    planar = (along <= LINK_NEIGHBOURS / np.pi * across) & (
        ret.cos >= np.cos(np.radians(MAX_LINK_INCIDENCE_DEG))
    )
    near &= planar
    # one return per cell of half the even spacing: the thinning keeps no more (and the
    # noise of the returns a registration averages in a cell is below the floor's)
    cell = np.floor((hit[near] - pos) / (v_m / 2.0)).astype(np.int64) + (1 << 20)
    key = (cell[:, 0] << 42) | (cell[:, 1] << 21) | cell[:, 2]  # cells within ±10⁶ of pos
    _, first = np.unique(key, return_index=True)
    return _take(ret, np.flatnonzero(near)[np.sort(first)])


def _sampled(points: np.ndarray, seed: tuple) -> np.ndarray:
    """At most :data:`MAX_POINTS` of a thinned cloud, drawn at random (seeded)."""
    if len(points) <= MAX_POINTS:
        return points
    pick = np.random.default_rng(seed).choice(len(points), MAX_POINTS, replace=False)
    return points[np.sort(pick)]


def _take(ret: Returns, keep: np.ndarray) -> Returns:
    """The returns ``keep`` selects."""
    return Returns(**{
        f.name: getattr(ret, f.name)[keep] if f.name != "beams" else ret.beams
        for f in fields(Returns)
    })  # fmt: skip


def _thinned(points: np.ndarray, v_m: float) -> np.ndarray:
    """The cloud thinned to the even spacing ``v_m`` (the mean of each cube's points)."""
    import small_gicp

    return small_gicp.voxelgrid_sampling(
        small_gicp.PointCloud(np.ascontiguousarray(points, dtype=float)), v_m, num_threads=1
    ).points()[:, :3]


def _prepared(points: np.ndarray):
    """A thinned cloud with its points' covariances and its k-d tree (GICP's)."""
    import small_gicp

    cloud = small_gicp.PointCloud(np.ascontiguousarray(points, dtype=float))
    tree = small_gicp.KdTree(cloud, num_threads=1)
    small_gicp.estimate_covariances(cloud, tree, num_neighbors=NEIGHBOURS, num_threads=1)
    return cloud, tree


def _register(parent, child, centre: np.ndarray, start: np.ndarray) -> np.ndarray:
    """The child registered to the parent from the pose error ``start`` (6,: mm, rad about
    the child's centre): the registered pose's error (6,) at the child's centre."""
    import small_gicp

    t = small_gicp.align(
        parent[0],
        child[0],
        parent[1],
        init_T_target_source=_pose(start, centre),
        registration_type="GICP",
        max_correspondence_distance=MAX_CORRESPONDENCE_M,
        num_threads=1,
        max_iterations=MAX_ITERATIONS,
        rotation_epsilon=EPSILON,
        translation_epsilon=EPSILON,
    ).T_target_source
    shift = (t[:3, :3] @ centre + t[:3, 3] - centre) * 1000.0
    w = t[:3, :3] - t[:3, :3].T
    return np.concatenate([shift, [w[2, 1] / 2.0, w[0, 2] / 2.0, w[1, 0] / 2.0]])


def _pose(e: np.ndarray, centre: np.ndarray) -> np.ndarray:
    """A 4 × 4 transform: rotation ``e[3:]`` [rad] about ``centre`` [m], then shift
    ``e[:3]`` [mm]."""
    w = e[3:]
    angle = float(np.linalg.norm(w))
    k = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
    if angle > 0:
        kn = k / angle
        r = np.eye(3) + math.sin(angle) * kn + (1 - math.cos(angle)) * kn @ kn
    else:
        r = np.eye(3)
    out = np.eye(4)
    out[:3, :3] = r
    out[:3, 3] = centre - r @ centre + e[:3] / 1000.0
    return out
