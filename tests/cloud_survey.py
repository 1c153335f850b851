"""The cloud-to-cloud links of a plan surveyed independently: their errors as an ICP the
planner does not use finds them (tests and benchmarks).

For each cloud link of a plan, the two set-ups' scans are simulated in the plan's scene
(:mod:`planner.pipeline.geometry.beams`: the scene's ray caster and the plan's noise — the
world the survey scans, as the rehearsal draws it; the surfaces' own error per 2 m cell
included) and registered by the point-to-plane ICP of ``tests/icp.py`` (its own normals,
matching, trimming and Gauss–Newton; coarse to fine: correspondences within 0.5 m, then
0.15 m), from a start drawn from the scanner's pre-alignment error, on the clouds thinned
to the plan's registration spacing (``tests/icp.thin``), returns beyond 85° of incidence left
out, and so are returns whose neighbours lie on a line (the survey scans at 25 mm at 10 m
for its cost: there its points on grazing ground lie in lines a metre apart, where the
scanner's own step, thinned by the registration, leaves a plane). Nothing of the planner's
link model, its rehearsal (small_gicp) or its network adjustment is used: the errors found
(the child's pose at its centre, per sample) go to the virtual survey
(``tests/virtual_survey.py``), which registers the network with them.
"""

from __future__ import annotations

import numpy as np
from icp import icp, thin

from planner.pipeline.engine.judge import workbench_of
from planner.pipeline.geometry.beams import POINT_KINDS, Floor, World, cast, grid, measure
from planner.pipeline.network.clouds import GROUND_REACH_M

#: The survey's scans: the step at 10 m [mm] (the registration thins them to its spacing;
#: a surface beyond 40 m is sampled coarser than 100 mm).
STEP_MM_AT_10M = 25.0
#: The walls a registration of two scans has to go on: within this of both stations [m].
WALL_REACH_M = 60.0
#: A return whose neighbours (10, as the ICP's local planes) lie on a line is left out.
NEIGHBOURS = 10
#: Returns seen at a larger incidence than 85° are left out (:meth:`Scans.points`).
COS_GRAZING = float(np.cos(np.radians(85.0)))
RHO = 180.0 * 3600.0 / np.pi


def _rotvec(w: np.ndarray) -> np.ndarray:
    th = float(np.linalg.norm(w))
    if th == 0:
        return np.eye(3)
    k = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]) / th
    return np.eye(3) + np.sin(th) * k + (1 - np.cos(th)) * k @ k


class Scans:
    """Every scanning station of a plan cast once into its scene (true returns), measured
    anew for each sample."""

    def __init__(self, plan, step_mm_at_10m: float = STEP_MM_AT_10M) -> None:
        ctx = workbench_of(plan).ctx
        self.plan, self.ctx = plan, ctx
        self.world = World.of(ctx.site, ctx.scanner, ctx.settings, ctx.scene)
        az, el = grid(step_mm_at_10m / 1e4, ctx.scanner.vertical_fov_deg)
        col, row = np.meshgrid(np.arange(len(az)), np.arange(len(el)))
        self._beams = (az, el, col.ravel(), row.ravel())
        st = plan.scan_stations.set_index("station_id")
        self.xyz = {
            sid: np.array([r.x, r.y, r.ground_z + r.instrument_height_m])
            for sid, r in st.iterrows()
        }
        self._returns: dict[str, object] = {}

    def returns(self, sid: str):
        if sid not in self._returns:
            self._returns[sid] = cast(self.world, self.xyz[sid], np.eye(3), *self._beams)
        return self._returns[sid]

    def points(self, sid: str, seed: int) -> tuple[np.ndarray, np.ndarray]:
        """One measured scan (world frame [m]) of station ``sid`` with its own noise and
        surfaces' error, and which of its points lie on the ground."""
        st = self.ctx.settings
        ret = self.returns(sid)
        fl = Floor(st.cloud_floor_mm, float(np.hypot(st.cloud_floor_mm, 1.0)), 2.0, seed)
        m = measure(
            self.world, ret, self.xyz[sid], np.eye(3), np.random.default_rng(seed), floor=fl
        )
        ground = np.isin(ret.kind, [POINT_KINDS.index("ground"), POINT_KINDS.index("terrain")])
        building = np.isin(ret.kind, [POINT_KINDS.index("wall"), POINT_KINDS.index("roof")])
        # where the survey's coarse step leaves lines of points (grazing, or beyond 85°), the
        # scanner's own step, thinned by the registration, leaves a plane: left out
        spacing = STEP_MM_AT_10M / 10_000.0 * ret.dist  # m, square to the beam
        v = st.cloud_spacing_mm / 1000.0
        along = np.maximum(spacing / np.maximum(ret.cos, 1e-9), v)
        lines = along > NEIGHBOURS / np.pi * np.maximum(spacing, v)
        keep = (ground | building) & (ret.cos >= COS_GRAZING) & ~lines
        pts = m.local_xyz + self.xyz[sid]
        return pts[keep], ground[keep]


def link_errors(scans: Scans, parent: str, child: str, samples: int, seed: int = 0) -> np.ndarray:
    """(samples, 6) the child's pose error [mm, rad at its centre] registered to the parent
    by the independent ICP from a start drawn from the scanner's pre-alignment (module
    text): each sample its own noise and start."""
    pos_mm, head_arcsec, tilt_arcsec = scans.ctx.scanner.start_error
    spacing = scans.ctx.settings.cloud_spacing_mm / 1000.0
    a, b = scans.xyz[parent], scans.xyz[child]
    out = np.empty((samples, 6))
    for s in range(samples):
        base = (seed * 1000 + s) * 2
        pa, pb = (
            _shared(*scans.points(parent, base + 1), a, b),
            _shared(*scans.points(child, base + 2), a, b),
        )
        rng = np.random.default_rng([seed, s, 7])
        w = np.array([*rng.normal(0, tilt_arcsec, 2), rng.normal(0, head_arcsec)]) / RHO
        shift = rng.normal(0.0, pos_mm / 1000.0, 3)
        moved = (thin(pb, spacing) - b) @ _rotvec(w).T + b + shift
        origin = a  # the ICP in a frame about the parent (numbers of metres, not of 10⁶)
        est = icp(thin(pa, spacing) - origin, moved - origin, b - origin, iters=24, coarse_m=0.5)
        # the registered pose's error: the start's, corrected by the ICP's estimate
        r_est = _rotvec(est[3:])
        total_rot = r_est @ _rotvec(w)
        total_shift = r_est @ shift + est[:3] / 1000.0
        skew = total_rot - total_rot.T
        out[s] = [*(total_shift * 1000.0), skew[2, 1] / 2, skew[0, 2] / 2, skew[1, 0] / 2]
    return out


def _shared(pts: np.ndarray, ground: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """What a registration of the pair has to go on: the buildings within
    :data:`WALL_REACH_M` of both stations and the ground within
    :data:`~planner.pipeline.network.clouds.GROUND_REACH_M` of both."""
    da = np.hypot(*(pts[:, :2] - a[:2]).T)
    db = np.hypot(*(pts[:, :2] - b[:2]).T)
    reach = np.where(ground, GROUND_REACH_M, WALL_REACH_M)
    return pts[(da <= reach) & (db <= reach)]


def surveyed(world, plan, samples: int, seed: int = 0):
    """The virtual survey's world (``tests/virtual_survey.world_of``) with its cloud links'
    errors surveyed (:func:`link_errors`, ``samples`` each)."""
    scans = Scans(plan)
    for i, j in world.clouds:
        a, b = world.station_ids[i], world.station_ids[j]
        world.cloud_errors[(i, j)] = link_errors(scans, a, b, samples, seed)
    return world
