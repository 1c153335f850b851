r"""Rehearse a plan: the point clouds its stations would give, before anyone goes out.

Every station of a plan is scanned on the computer: the scanner's angular grid (its
preset's step, thinned to a stated number of beams per station), every beam cast against
the plan's scene — buildings as their 3-D model or footprints, terrain, trees — and against
the plan's targets as geometry (a sphere of its diameter on its stand height; a
checkerboard of its size on its wall, four quadrants white and black), out to the
scanner's range. Each return is measured with the planner's error model:

* the slope distance with the ranging RMS of the returned signal (:mod:`planner.signal`):
  ``a + b·S`` on the datasheet's reference surface, grown as ``q^(−k)`` with the surface's
  reflectance (its building's material, :mod:`planner.materials`) and the incidence θ
  where the plan's model has that term, and no return beyond the reach on that surface;
  glass (a curtain wall, an LoD3 model's windows) returns nothing; a target's black
  quadrants range as the reference (as its centre's model assumes);
* the walls of footprint buildings carry the plan's parametric facade (its window share and
  reveal depth, :mod:`planner.cloud_registration`): one opening per bay and storey, a beam
  into it returning from the first jamb, head or sill it meets, or not at all (the glass) —
  the surfaces cloud-to-cloud registration ties scans along a wall with; a city model's
  walls are drawn as the model has them;
* the horizontal direction with ``m_β`` and the vertical angle with ``m_ν``;
* each scan's vertical axis tilted by its levelling residual (σ per axis: the compensator's
  figure, else ``m_ν``, the model's assumption) and turned to a random heading, so that the
  scan's own frame is not the site's (a scanner does not know north).

Each point keeps its predicted RMS — whatever the plan's model, the 3-D model's
``√(m_x² + m_y² + m_z²)`` of the point's own noise
(:func:`planner.accuracy3d.variances_3d` without the levelling, which moves the whole
scan: its pose carries it) — its incidence, the surface it hit and what kind of surface
that is. The intensity is the surface's reflectance
times ``cos θ`` (Lambert's law with the range corrected, as scanners' software reports
it; Kaasalainen et al. 2011, under :data:`SURFACE_REFLECTANCE`): the targets' white
(:data:`WHITE`) and black (:data:`BLACK`) quadrants stand out against the walls' material
(:data:`SURFACE_REFLECTANCE` where none is known), as registration software needs to find
them.

This is the planner's own simulation (beyond the papers), for looking at and registering in
the crew's software; its noise is the plan's model, so it rehearses the plan, it does not
check it. ``tests/test_rehearsal.py`` registers its clouds with an independent ICP.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from planner.accuracy3d import variances_3d
from planner.cloud_registration import (
    SILL_M,
    STOREY_M,
    WINDOW_HEIGHT_M,
    WINDOW_WIDTH_M,
    bay_width_m,
)
from planner.errors import InputError
from planner.materials import building_materials, reflectances, silent
from planner.mesh import triangle_normals
from planner.pipeline.engine.result import Plan
from planner.pipeline.evaluation.evaluate import Progress
from planner.pipeline.geometry.scene import TRIANGLE_KINDS, Scene

__all__ = [
    "DEFAULT_BEAMS_PER_STATION",
    "POINT_KINDS",
    "Rehearsal",
    "SimulatedScan",
    "estimate",
    "rehearse",
    "station_centres",
]

#: Beams cast per station unless asked otherwise: the preset's step is thinned to this
#: (a full-dome scan at 6 mm at 10 m is 40 million beams; the rehearsal is for looking and
#: registering, not for the final density) — said with the clouds.
DEFAULT_BEAMS_PER_STATION = 1_000_000
#: What a point lies on: the scene's triangle kinds, then the two target types.
POINT_KINDS = (*TRIANGLE_KINDS, "sphere", "checkerboard")
#: Reflectance of every surface of the scene where the material is not known: a mid grey
#: (weathered concrete and plaster lie about 0.3–0.6 in the near infrared; Kaasalainen et
#: al., "Analysis of incidence angle and distance effects on terrestrial laser scanner
#: intensity", Remote Sensing 3(10), 2011, https://doi.org/10.3390/rs3102207).
SURFACE_REFLECTANCE = 0.5
#: Reflectance of a sphere and of a checkerboard's white quadrants (matt white paint) and
#: of its black quadrants (matt black): the contrast registration software looks for.
WHITE = 0.9
BLACK = 0.05
#: A checkerboard stands this far in front of its wall [m] (its own thickness and fixing).
BOARD_STANDOFF_M = 0.005
#: Bytes per point of the files, for the size said before writing: an E57 scan's point
#: (three single-precision coordinates, an intensity, row and column, as pye57 writes them)
#: and a compressed LAS point (measured on the default site, benchmarks/RESULTS.md).
E57_BYTES_PER_POINT = 19
LAZ_BYTES_PER_POINT = 6
#: Seconds per beam cast and per point written (E57 and LAZ), for the time said before
#: (measured on the default site on two cores, benchmarks/RESULTS.md).
SECONDS_PER_BEAM = 1.4e-6
SECONDS_PER_POINT = 0.9e-6
_RHO = 180.0 * 3600.0 / np.pi  # arc-seconds per radian


@dataclass(frozen=True)
class SimulatedScan:
    """One station's simulated scan: points in the scanner's own frame and its pose.

    ``rotation`` turns the scanner's frame into the site's and ``position`` is its centre
    (site CRS) [m], so ``world = local @ rotation.T + position``.
    """

    station_id: str
    position: np.ndarray  # (3,) [m]
    rotation: np.ndarray  # (3, 3)
    local_xyz: np.ndarray  # (P, 3) [m], measured (with noise)
    intensity: np.ndarray  # (P,) 0–1
    rms_mm: np.ndarray  # (P,) predicted 3-D RMS of the point (scanner part) [mm]
    incidence_deg: np.ndarray  # (P,)
    surface: np.ndarray  # (P,) index into Rehearsal.surfaces
    kind: np.ndarray  # (P,) index into POINT_KINDS
    row: np.ndarray  # (P,) the beam's row of the scan grid (elevation)
    column: np.ndarray  # (P,) the beam's column (azimuth)
    beams: int  # beams cast

    @property
    def n_points(self) -> int:
        return len(self.local_xyz)

    @property
    def world_xyz(self) -> np.ndarray:
        """The points in the site's CRS [m]."""
        return self.local_xyz @ self.rotation.T + self.position


@dataclass(frozen=True)
class Rehearsal:
    """The simulated scans of a plan and how they were made."""

    scans: list[SimulatedScan]
    surfaces: list[str]  # ids of what was hit: buildings, obstacles, "terrain", targets
    step_mm_at_10m: float  # the grid's step as cast
    preset_step_mm_at_10m: float  # the plan's step
    seed: int
    crs: str | None = None
    notes: list[str] = field(default_factory=list)

    @property
    def n_points(self) -> int:
        return sum(s.n_points for s in self.scans)

    def legend(self) -> pd.DataFrame:
        """What each index of the clouds' ``surface`` attribute stands for."""
        return pd.DataFrame({"surface": range(len(self.surfaces)), "id": self.surfaces})


def grid_step_mm_at_10m(plan: Plan, beams_per_station: int) -> float:
    """The step [mm at 10 m] the rehearsal casts at: the plan's preset step, thinned so a
    full-dome scan over the scanner's vertical field is at most ``beams_per_station``."""
    if beams_per_station < 1000:
        raise InputError(
            f"beams per station must be at least 1000 (got {beams_per_station}); the "
            f"default is {DEFAULT_BEAMS_PER_STATION}"
        )
    lo, hi = plan.scanner.vertical_fov_deg
    preset = plan.settings.scan_step_mm(plan.scanner)
    step = preset / 1e4  # rad
    beams = 2 * np.pi * np.radians(hi - lo) / step**2
    if beams > beams_per_station:
        step *= np.sqrt(beams / beams_per_station)
    return step * 1e4


def _grid(step_rad: float, fov_deg: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Azimuths and elevations [rad] of the scan grid (columns, rows)."""
    n_az = max(int(np.ceil(2 * np.pi / step_rad)), 8)
    az = np.arange(n_az) * (2 * np.pi / n_az)
    lo, hi = np.radians(fov_deg)
    el = lo + np.arange(int(np.floor((hi - lo) / step_rad)) + 1) * step_rad
    return az, el


def _unit(az: np.ndarray, el: np.ndarray) -> np.ndarray:
    return np.stack([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)], axis=-1)


def _rotation(heading: float, tilt_x: float, tilt_y: float) -> np.ndarray:
    """Scanner frame → site frame: turned by ``heading`` about the vertical, then its axis
    tilted by small rotations about x and y [rad]."""
    c, s = np.cos(heading), np.sin(heading)
    rz = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    cx, sx, cy, sy = np.cos(tilt_x), np.sin(tilt_x), np.cos(tilt_y), np.sin(tilt_y)
    rx = np.array([[1.0, 0.0, 0.0], [0.0, cx, -sx], [0.0, sx, cx]])
    ry = np.array([[cy, 0.0, sy], [0.0, 1.0, 0.0], [-sy, 0.0, cy]])
    return rx @ ry @ rz


@dataclass(frozen=True)
class _Targets:
    """The plan's targets as geometry: spheres (centre, radius) and boards (centre, normal,
    half side), with their index into the surfaces list."""

    sphere_c: np.ndarray
    sphere_r: np.ndarray
    sphere_id: np.ndarray
    board_c: np.ndarray
    board_n: np.ndarray
    board_h: np.ndarray
    board_id: np.ndarray

    @classmethod
    def of(cls, plan: Plan, first_id: int) -> _Targets:
        t = plan.targets
        kinds = t["type"].astype(str).to_numpy() if len(t) else np.empty(0, str)
        xyz = t[["x", "y", "z"]].to_numpy(dtype=float) if len(t) else np.empty((0, 3))
        size_m = t["size_mm"].to_numpy(dtype=float) / 1000.0 if len(t) else np.empty(0)
        ids = first_id + np.arange(len(t))
        sph = kinds == "sphere"
        flat = kinds == "flat"
        az = np.radians(t["facing_deg"].to_numpy(dtype=float)[flat]) if len(t) else np.empty(0)
        normal = np.column_stack([np.sin(az), np.cos(az), np.zeros(len(az))])
        return cls(
            sphere_c=xyz[sph],
            sphere_r=size_m[sph] / 2,
            sphere_id=ids[sph],
            board_c=xyz[flat] + BOARD_STANDOFF_M * normal,
            board_n=normal,
            board_h=size_m[flat] / 2,
            board_id=ids[flat],
        )

    def hit(self, o: np.ndarray, d: np.ndarray, dist: np.ndarray):
        """Where beams from the point ``o`` (3,) along unit ``d`` meet a target nearer
        than ``dist``: the distance, the target's surface index, kind, normal and
        reflectance (−1 where none)."""
        n = len(d)
        best = dist.copy()
        who = np.full(n, -1)
        kind = np.full(n, -1)
        normal = np.zeros((n, 3))
        refl = np.zeros(n)
        for c, r, sid in zip(self.sphere_c, self.sphere_r, self.sphere_id, strict=True):
            oc = o - c
            b = d @ oc
            disc = b * b - (oc @ oc - r * r)
            near = disc > 0
            t = np.where(near, -b - np.sqrt(np.where(near, disc, 0.0)), np.inf)
            take = (t > 0) & (t < best)
            best[take] = t[take]
            who[take], kind[take], refl[take] = sid, POINT_KINDS.index("sphere"), WHITE
            normal[take] = (o - c) + t[take, None] * d[take]
            normal[take] /= r
        up = np.array([0.0, 0.0, 1.0])
        for c, nrm, h, sid in zip(
            self.board_c, self.board_n, self.board_h, self.board_id, strict=True
        ):
            dn = d @ nrm
            facing = dn < -1e-9
            t = np.where(facing, ((c - o) @ nrm) / np.where(facing, dn, 1.0), np.inf)
            p = (o - c) + np.where(facing, t, 0.0)[:, None] * d
            along = np.cross(nrm, up)
            u, v = p @ along, p[:, 2]
            take = (t > 0) & (t < best) & (np.abs(u) <= h) & (np.abs(v) <= h)
            best[take] = t[take]
            who[take], kind[take] = sid, POINT_KINDS.index("checkerboard")
            refl[take] = np.where(u[take] * v[take] > 0, WHITE, BLACK)
            normal[take] = nrm
        return best, who, kind, normal, refl


def station_centres(plan: Plan) -> tuple[list[str], np.ndarray]:
    """The scanning stations in the order of their ids (S01, S02 … S10), and their scanner
    centres [m]."""
    st = plan.scan_stations
    name = st["station_id"].astype(str)
    st = st.iloc[np.lexsort((name.to_numpy(), name.str.len().to_numpy()))]
    xyz = np.column_stack(
        [
            st["x"].to_numpy(dtype=float),
            st["y"].to_numpy(dtype=float),
            (st["ground_z"] + st["instrument_height_m"]).to_numpy(dtype=float),
        ]
    )
    return st["station_id"].astype(str).tolist(), xyz


def estimate(
    plan: Plan, beams_per_station: int = DEFAULT_BEAMS_PER_STATION, scene: Scene | None = None
) -> dict[str, float]:
    """The rehearsal's size before it is made: points, E57 and LAZ bytes and seconds (a
    pilot scan of every station at a coarse grid counts the share of beams that return)."""
    scene = scene or Scene(plan.site, "rays")
    step = grid_step_mm_at_10m(plan, beams_per_station)
    pilot = rehearse(plan, beams_per_station=4000, scene=scene, seed=0)
    share = pilot.n_points / max(sum(s.beams for s in pilot.scans), 1)
    az, el = _grid(step / 1e4, plan.scanner.vertical_fov_deg)
    beams = len(az) * len(el) * len(pilot.scans)
    points = share * beams
    return {
        "stations": float(len(pilot.scans)),
        "beams": float(beams),
        "points": points,
        "step_mm_at_10m": step,
        "e57_bytes": points * E57_BYTES_PER_POINT,
        "laz_bytes": points * LAZ_BYTES_PER_POINT,
        "seconds": beams * SECONDS_PER_BEAM + points * SECONDS_PER_POINT,
    }


@dataclass(frozen=True)
class _Reveals:
    """The parametric facade's openings (:mod:`planner.cloud_registration`) cut into the
    scene's walls of footprint buildings: a beam meeting a wall inside an opening goes on
    into its reveal and returns from the first jamb, head or sill it meets, or not at all
    (the glass at its back). Per wall triangle: its outward normal and along-wall axis
    (horizontal), the openings' first column and row and their counts (a wall of a building
    whose model draws its openings, or none planned, has none)."""

    along: np.ndarray  # (T, 3)
    start_u: np.ndarray  # (T,) the first bay's start along the wall [m]
    bays: np.ndarray  # (T,) int
    base_z: np.ndarray  # (T,) the wall's foot [m]
    storeys: np.ndarray  # (T,) int
    bay_m: float
    depth_m: float

    @classmethod
    def of(cls, plan: Plan, tri: np.ndarray, normals: np.ndarray, owner: np.ndarray,
           kind: np.ndarray, owner_ids: list[str]) -> _Reveals:  # fmt: skip
        st = plan.settings
        n = len(tri)
        along = np.column_stack([-normals[:, 1], normals[:, 0], np.zeros(n)])
        norm = np.linalg.norm(along, axis=1, keepdims=True)
        along = np.divide(along, norm, out=np.zeros_like(along), where=norm > 1e-9)
        footprint = {b.id for b in plan.site.buildings if not b.is_3d}
        walls = (kind == TRIANGLE_KINDS.index("wall")) & (np.abs(normals[:, 2]) < 0.05)
        walls &= np.isin(np.asarray(owner_ids, dtype=object)[owner], list(footprint))
        u = np.einsum("tvd,td->tv", tri, along)
        length, height = u.max(axis=1) - u.min(axis=1), np.ptp(tri[:, :, 2], axis=1)
        bay = bay_width_m(max(st.window_share, 1e-9))
        on = walls & (st.window_share > 0) & (st.reveal_depth_m > 0)
        bays = np.where(on, np.floor(length / bay), 0).astype(np.int64)
        storeys = np.where(on, np.floor(height / STOREY_M), 0).astype(np.int64)
        start = u.min(axis=1) + (length - bays * bay) / 2.0
        return cls(along, start, bays, tri[:, :, 2].min(axis=1), storeys, bay, st.reveal_depth_m)

    def enter(
        self, pos: np.ndarray, d: np.ndarray, dist: np.ndarray, tri_idx: np.ndarray,
        normals: np.ndarray,
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:  # fmt: skip
        """The beams from ``pos`` along ``d`` that hit wall triangles ``tri_idx`` at
        ``dist``, taken into the openings: the new distances, which beams hit a reveal and
        its normal there, and which beams were lost in the glass."""
        dist = dist.copy()
        hit_reveal = np.zeros(len(d), dtype=bool)
        normal = np.zeros((len(d), 3))
        glass = np.zeros(len(d), dtype=bool)
        i = np.flatnonzero((tri_idx >= 0) & np.isfinite(dist))
        i = i[self.bays[tri_idx[i]] > 0]
        if not len(i):
            return dist, hit_reveal, normal, glass
        ti = tri_idx[i]
        p = pos + dist[i, None] * d[i]
        ax = self.along[ti]
        u = np.einsum("kd,kd->k", p, ax) - self.start_u[ti]
        h = p[:, 2] - self.base_z[ti]
        k, s = np.floor(u / self.bay_m), np.floor(h / STOREY_M)
        x0 = k * self.bay_m + (self.bay_m - WINDOW_WIDTH_M) / 2.0
        z0 = s * STOREY_M + SILL_M
        inside = (k >= 0) & (k < self.bays[ti]) & (s >= 0) & (s < self.storeys[ti])
        inside &= (u > x0) & (u < x0 + WINDOW_WIDTH_M) & (h > z0) & (h < z0 + WINDOW_HEIGHT_M)
        i, ti, u, h, x0, z0, ax = (a[inside] for a in (i, ti, u, h, x0, z0, ax))
        if not len(i):
            return dist, hit_reveal, normal, glass
        di = d[i]
        inward = -np.einsum("kd,kd->k", di, normals[ti])  # > 0: the beam goes into the wall
        du, dz = np.einsum("kd,kd->k", di, ax), di[:, 2]
        with np.errstate(divide="ignore", invalid="ignore"):
            back = self.depth_m / inward
            tu = np.where(du > 0, (x0 + WINDOW_WIDTH_M - u) / du, (x0 - u) / du)
            tz = np.where(dz > 0, (z0 + WINDOW_HEIGHT_M - h) / dz, (z0 - h) / dz)
        tu, tz = np.where(tu > 0, tu, np.inf), np.where(tz > 0, tz, np.inf)
        first = np.minimum(tu, tz)
        wall = first < back
        dist[i[wall]] += first[wall]
        glass[i[~wall]] = True
        jamb = wall & (tu <= tz)
        normal[i[jamb]] = -np.sign(du[jamb])[:, None] * ax[jamb]
        other = wall & ~jamb
        normal[i[other], 2] = -np.sign(dz[other])
        hit_reveal[i[wall]] = True
        return dist, hit_reveal, normal, glass


def _scan(
    plan: Plan,
    scene: Scene,
    targets: _Targets,
    sid: str,
    pos: np.ndarray,
    rot: np.ndarray,
    rng: np.random.Generator,
    grid: tuple,
    mesh: tuple,
    noise: bool,
) -> SimulatedScan:
    """One station's simulated scan: the grid's beams (``grid``: azimuths, elevations, each
    beam's column and row and direction in the scanner's frame) turned by ``rot`` and cast
    from ``pos`` against the scene, the targets and (no terrain) flat ground at 0; the
    returns within the scanner's range with the plan's noise drawn from ``rng``. ``mesh``:
    the scene's triangle normals, owners, kinds and the flat ground's surface number."""
    sc, st = plan.scanner, plan.settings
    az, el, col, row, local_dir = grid
    normals, owner, tri_kind, ground_id, owner_rho, silent_tri, reveals = mesh
    d = local_dir @ rot.T
    o = np.broadcast_to(pos, d.shape)
    dist, t_idx = scene.first_hit(o, d, sc.max_range_m)
    if plan.site.terrain is None:  # flat ground at 0 all round (the scene has none)
        down = (d[:, 2] < -1e-9) & (t_idx < 0)
        dist[down] = -pos[2] / d[down, 2]
    dist, hit_t, hit_kind, t_normal, refl = targets.hit(pos, d, dist)
    # into the walls' openings (the parametric facade): a reveal, or the glass
    wall_hit = np.where((hit_t < 0) & (t_idx >= 0), t_idx, -1)
    dist, in_reveal, reveal_normal, in_glass = reveals.enter(pos, d, dist, wall_hit, normals)
    keep = np.isfinite(dist) & (dist >= sc.min_range_m) & (dist <= sc.max_range_m) & ~in_glass
    tri = np.maximum(t_idx, 0)
    ground = keep & (hit_t < 0) & (t_idx < 0)  # the flat ground
    t_normal[ground] = (0.0, 0.0, 1.0)
    hit_t[ground], hit_kind[ground] = ground_id, POINT_KINDS.index("terrain")
    refl[ground] = SURFACE_REFLECTANCE
    on_mesh = (hit_t < 0) & (t_idx >= 0)
    n = np.where(on_mesh[:, None], normals[tri], t_normal)
    n[in_reveal] = reveal_normal[in_reveal]
    cos_t = np.abs(np.einsum("ij,ij->i", n, d))
    # the surface's reflectance (a target's paint; NaN: the datasheet's reference surface):
    # glass returns nothing, a dark wall ranges noisier and not as far (planner.signal)
    target = (hit_t >= 0) & ~ground
    rho = np.where(on_mesh, owner_rho[owner[tri]], np.nan)
    rho[target] = np.maximum(refl[target], sc.ref_reflectance)  # black ranges as the reference
    signal_cos = cos_t if st.incidence_ranging else 1.0
    with np.errstate(invalid="ignore"):
        keep &= ~(on_mesh & silent_tri[tri]) & (dist <= sc.max_range_on(rho, signal_cos))
    on_mesh &= keep
    surface = np.where(on_mesh, owner[tri], hit_t)
    kind = np.where(on_mesh, tri_kind[tri], hit_kind)
    reflectance = np.where(target, refl, np.where(np.isnan(rho), SURFACE_REFLECTANCE, rho))
    s, a, e, c = dist[keep], az[col[keep]], el[row[keep]], cos_t[keep]
    m_s = sc.range_rms_on(s, rho[keep], c if st.incidence_ranging else 1.0)
    # the point's own noise; the scan's levelling is its frame's error (the pose)
    var = variances_3d(
        s, np.ones_like(s), np.sin(e), m_s, sc.angle_rms_arcsec, sc.tilt_rms_arcsec, 0.0
    )
    draws = rng.normal(0.0, 1.0, (3, len(s))) * noise
    s = s + draws[0] * m_s / 1000.0
    a = a + draws[1] * sc.angle_rms_arcsec / _RHO
    e = e + draws[2] * sc.tilt_rms_arcsec / _RHO
    return SimulatedScan(
        station_id=sid,
        position=pos.copy(),
        rotation=rot,
        local_xyz=s[:, None] * _unit(a, e),
        intensity=(reflectance[keep] * c).astype(np.float32),
        rms_mm=np.sqrt(sum(var)).astype(np.float32),
        incidence_deg=np.degrees(np.arccos(np.clip(c, 0.0, 1.0))).astype(np.float32),
        surface=surface[keep].astype(np.int64),
        kind=kind[keep].astype(np.int64),
        row=row[keep],
        column=col[keep],
        beams=len(d),
    )


def _owner_materials(plan: Plan, owner_ids: list[str]) -> tuple[np.ndarray, np.ndarray]:
    """Each scene owner's reflectance on the survey day (NaN: no material known) and whether
    it returns no point: a building's material as the plan takes it
    (:func:`planner.materials.building_materials`: its own, else the plan's default; a
    zone's material is not drawn in the rehearsal); an obstacle's none."""
    st = plan.settings
    own, _ = building_materials(plan.site.buildings, st.material_table, st.default_material)
    names = np.array([own.get(str(oid), "") for oid in owner_ids], dtype=object)
    table = st.material_table
    return reflectances(names, table, st.surface_condition), silent(names, table)


def rehearse(
    plan: Plan,
    *,
    beams_per_station: int = DEFAULT_BEAMS_PER_STATION,
    seed: int = 1,
    scene: Scene | None = None,
    noise: bool = True,
    stations: list[str] | None = None,
    progress: Progress | None = None,
) -> Rehearsal:
    """Every scanning station's simulated scan (module text), or ``stations``' (ids) alone
    (each scan's heading, tilt and noise the same either way). ``noise=False``: the points
    exactly on the surfaces (a control for checks of the noise)."""
    say = progress or (lambda _f, _m: None)
    scene = scene or Scene(plan.site, "rays")
    sc, st = plan.scanner, plan.settings
    tri, owner, tri_kind, owner_ids = scene.mesh
    normals = triangle_normals(tri) if len(tri) else np.zeros((0, 3))
    surfaces = [*owner_ids, *plan.targets["target_id"].astype(str).tolist()]
    if plan.site.terrain is None:
        surfaces.append("ground")
    targets = _Targets.of(plan, len(owner_ids))
    owner_rho, silent_owner = _owner_materials(plan, owner_ids)
    silent_tri = silent_owner[owner] | (tri_kind == TRIANGLE_KINDS.index("window"))
    reveals = _Reveals.of(plan, tri, normals, owner, tri_kind, owner_ids)
    step = grid_step_mm_at_10m(plan, beams_per_station)
    az, el = _grid(step / 1e4, sc.vertical_fov_deg)
    col, row = np.meshgrid(np.arange(len(az)), np.arange(len(el)))
    col, row = col.ravel(), row.ravel()
    local_dir = _unit(az[col], el[row])
    tau = sc.datum_tilt_rms_arcsec / _RHO  # a scan stands tilted by what levels it
    ids, xyz = station_centres(plan)
    scans = []
    for k, (sid, pos) in enumerate(zip(ids, xyz, strict=True)):
        # each scan its own stream of random numbers (seed, station): the same scan whichever
        # others are simulated with it
        rng = np.random.default_rng([seed, k])
        heading, tilt = rng.uniform(0, 2 * np.pi), rng.normal(0.0, tau, 2)
        if stations is not None and sid not in stations:
            continue
        say(k / max(len(ids), 1), f"simulated scan of {sid} ({k + 1} of {len(ids)})")
        rot = _rotation(heading, *tilt)
        grid = (az, el, col, row, local_dir)
        mesh = (normals, owner, tri_kind, len(surfaces) - 1, owner_rho, silent_tri, reveals)
        scans.append(_scan(plan, scene, targets, sid, pos, rot, rng, grid, mesh, noise))
    say(1.0, "simulated scans done")
    preset = st.scan_step_mm(sc)
    notes = []
    if step > preset * 1.001:
        notes.append(
            f"Thinned: beams cast every {step:.1f} mm at 10 m instead of the preset's "
            f"{preset:.1f} mm ({beams_per_station:,} beams per station at most); the clouds "
            "are for looking and registering, not the final density."
        )
    return Rehearsal(
        scans=scans,
        surfaces=surfaces,
        step_mm_at_10m=step,
        preset_step_mm_at_10m=preset,
        seed=seed,
        crs=plan.site.crs,
        notes=notes,
    )
