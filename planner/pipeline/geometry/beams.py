r"""A scanner's beams cast into the scene and measured: the simulated scan's core.

A station's scan is simulated in two steps, so that one cast serves many draws of noise:

1. :func:`cast` — every beam of a grid (azimuths and elevations in the scanner's own frame,
   turned into the site's by the scan's pose) meets the first thing in its way: the
   scene's triangles (buildings as their 3-D model or footprints, terrain, trees), flat
   ground at 0 where the site has no terrain, the plan's targets as geometry (a sphere on
   its stand height, a checkerboard on its wall) and the parametric facade's openings cut
   into footprint walls (:class:`Reveals`); what returns is kept within the scanner's
   range and the reach on that surface (:mod:`planner.signal`), glass returning nothing.
   The true returns: :class:`Returns`.
2. :func:`measure` — each return measured with the planner's error model: the slope
   distance with the ranging RMS of the returned signal, both angles with their RMS; and,
   where asked, the surfaces' own systematic error (:class:`Floor`): what a plane fit
   does not see (ranging biases with incidence and material, the scanner's calibration),
   an offset along the surface's normal, the same over a cell of the surface in one scan
   and independent between scans and cells — the error the cloud-to-cloud link model
   counts as its floor (:mod:`planner.cloud_registration`).

The rehearsal (:mod:`planner.pipeline.survey.rehearsal`) and the plan's own check of its
cloud links (:mod:`planner.pipeline.network.linkcheck`) both simulate scans here.
"""

from __future__ import annotations

from dataclasses import dataclass

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
from planner.materials import building_materials, reflectances, silent
from planner.mesh import triangle_normals
from planner.pipeline.geometry.scene import TRIANGLE_KINDS, Scene
from planner.pipeline.inputs.requirements import PlanSettings
from planner.scanner import Scanner
from planner.site import Site

__all__ = [
    "BLACK",
    "POINT_KINDS",
    "SURFACE_REFLECTANCE",
    "WHITE",
    "Floor",
    "Measured",
    "Returns",
    "Reveals",
    "Targets",
    "World",
    "cast",
    "grid",
    "measure",
    "rotation",
    "unit",
]

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
_RHO = 180.0 * 3600.0 / np.pi  # arc-seconds per radian


def grid(step_rad: float, fov_deg: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Azimuths and elevations [rad] of a scan grid (columns, rows).

    >>> az, el = grid(np.radians(10.0), (-45.0, 90.0))
    >>> len(az), len(el), round(float(np.degrees(el[-1])), 1)
    (36, 14, 85.0)
    """
    n_az = max(int(np.ceil(2 * np.pi / step_rad)), 8)
    az = np.arange(n_az) * (2 * np.pi / n_az)
    lo, hi = np.radians(fov_deg)
    el = lo + np.arange(int(np.floor((hi - lo) / step_rad)) + 1) * step_rad
    return az, el


def unit(az: np.ndarray, el: np.ndarray) -> np.ndarray:
    """Unit vectors (…, 3) of azimuths and elevations [rad] (x at azimuth 0, z up)."""
    return np.stack([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)], axis=-1)


def rotation(heading: float, tilt_x: float, tilt_y: float) -> np.ndarray:
    """Scanner frame → site frame: turned by ``heading`` about the vertical, then its axis
    tilted by small rotations about x and y [rad]."""
    c, s = np.cos(heading), np.sin(heading)
    rz = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    cx, sx, cy, sy = np.cos(tilt_x), np.sin(tilt_x), np.cos(tilt_y), np.sin(tilt_y)
    rx = np.array([[1.0, 0.0, 0.0], [0.0, cx, -sx], [0.0, sx, cx]])
    ry = np.array([[cy, 0.0, sy], [0.0, 1.0, 0.0], [-sy, 0.0, cy]])
    return rx @ ry @ rz


@dataclass(frozen=True)
class Targets:
    """Targets as geometry: spheres (centre, radius) and boards (centre, normal, half
    side), with their index into the world's surfaces."""

    sphere_c: np.ndarray
    sphere_r: np.ndarray
    sphere_id: np.ndarray
    board_c: np.ndarray
    board_n: np.ndarray
    board_h: np.ndarray
    board_id: np.ndarray

    @classmethod
    def of(cls, t: pd.DataFrame | None, first_id: int) -> Targets:
        """A plan's targets table (``x, y, z, type, size_mm, facing_deg``; None: none)."""
        if t is None or not len(t):
            t = pd.DataFrame(columns=["x", "y", "z", "type", "size_mm", "facing_deg"])
        kinds = t["type"].astype(str).to_numpy()
        xyz = t[["x", "y", "z"]].to_numpy(dtype=float).reshape(-1, 3)
        size_m = t["size_mm"].to_numpy(dtype=float) / 1000.0
        ids = first_id + np.arange(len(t))
        sph = kinds == "sphere"
        flat = kinds == "flat"
        az = np.radians(t["facing_deg"].to_numpy(dtype=float)[flat])
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


@dataclass(frozen=True)
class Reveals:
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
    def of(cls, site: Site, settings: PlanSettings, tri: np.ndarray, normals: np.ndarray,
           owner: np.ndarray, kind: np.ndarray, owner_ids: list[str]) -> Reveals:  # fmt: skip
        st = settings
        n = len(tri)
        along = np.column_stack([-normals[:, 1], normals[:, 0], np.zeros(n)])
        norm = np.linalg.norm(along, axis=1, keepdims=True)
        along = np.divide(along, norm, out=np.zeros_like(along), where=norm > 1e-9)
        footprint = {b.id for b in site.buildings if not b.is_3d}
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


@dataclass(frozen=True)
class World:
    """Everything a beam meets, prepared once for a plan: the scene's triangles with their
    normals, owners, kinds and materials, the walls' openings and the targets; the surfaces
    a point can lie on (the scene's owners, then the targets, then flat ground where the
    site has no terrain)."""

    site: Site
    scanner: Scanner
    settings: PlanSettings
    scene: Scene
    normals: np.ndarray  # (T, 3)
    owner: np.ndarray  # (T,) index into the surfaces
    tri_kind: np.ndarray  # (T,) index into TRIANGLE_KINDS
    owner_rho: np.ndarray  # (owners,) reflectance on the survey day (NaN: reference)
    silent_tri: np.ndarray  # (T,) returns nothing (glass)
    reveals: Reveals
    targets: Targets
    surfaces: list[str]

    @classmethod
    def of(
        cls,
        site: Site,
        scanner: Scanner,
        settings: PlanSettings,
        scene: Scene | None = None,
        targets: pd.DataFrame | None = None,
    ) -> World:
        """The world of a plan's site (``scene``: its ray scene, made when not given;
        ``targets``: the plan's targets table, None for none)."""
        scene = scene if scene is not None and scene.engine == "rays" else Scene(site, "rays")
        tri, owner, tri_kind, owner_ids = scene.mesh
        normals = triangle_normals(tri) if len(tri) else np.zeros((0, 3))
        ids = [] if targets is None else targets["target_id"].astype(str).tolist()
        surfaces = [*owner_ids, *ids]
        if site.terrain is None:
            surfaces.append("ground")
        owner_rho, silent_owner = _owner_materials(site, settings, owner_ids)
        silent_tri = silent_owner[owner] | (tri_kind == TRIANGLE_KINDS.index("window"))
        return cls(
            site=site,
            scanner=scanner,
            settings=settings,
            scene=scene,
            normals=normals,
            owner=owner,
            tri_kind=tri_kind,
            owner_rho=owner_rho,
            silent_tri=silent_tri,
            reveals=Reveals.of(site, settings, tri, normals, owner, tri_kind, owner_ids),
            targets=Targets.of(targets, len(owner_ids)),
            surfaces=surfaces,
        )


def _owner_materials(
    site: Site, settings: PlanSettings, owner_ids: list[str]
) -> tuple[np.ndarray, np.ndarray]:
    """Each scene owner's reflectance on the survey day (NaN: no material known) and whether
    it returns no point: a building's material as the plan takes it
    (:func:`planner.materials.building_materials`: its own, else the plan's default; a
    zone's material is not drawn); an obstacle's none."""
    st = settings
    own, _ = building_materials(site.buildings, st.material_table, st.default_material)
    names = np.array([own.get(str(oid), "") for oid in owner_ids], dtype=object)
    table = st.material_table
    return reflectances(names, table, st.surface_condition), silent(names, table)


@dataclass(frozen=True)
class Returns:
    """The beams of one scan that returned, before noise (R returns of ``beams`` cast)."""

    dist: np.ndarray  # (R,) slope distance [m]
    az: np.ndarray  # (R,) azimuth in the scanner's frame [rad]
    el: np.ndarray  # (R,) elevation in the scanner's frame [rad]
    cos: np.ndarray  # (R,) cosine of the incidence
    rho: np.ndarray  # (R,) reflectance for the ranging (NaN: the reference surface)
    reflectance: np.ndarray  # (R,) the surface's reflectance, for the intensity
    normal: np.ndarray  # (R, 3) the surface's unit normal (site frame)
    surface: np.ndarray  # (R,) index into World.surfaces
    kind: np.ndarray  # (R,) index into POINT_KINDS
    relief: np.ndarray  # (R,) on a reveal of the parametric facade
    row: np.ndarray  # (R,) the beam's row of the grid
    column: np.ndarray  # (R,) the beam's column
    beams: int


def cast(
    world: World,
    pos: np.ndarray,
    rot: np.ndarray,
    az: np.ndarray,
    el: np.ndarray,
    col: np.ndarray,
    row: np.ndarray,
) -> Returns:
    """The beams at azimuths ``az[col]`` and elevations ``el[row]`` of a scanner at ``pos``
    turned by ``rot`` (its frame → the site's), cast against the world (module text)."""
    sc, st = world.scanner, world.settings
    d = unit(az[col], el[row]) @ rot.T
    o = np.broadcast_to(pos, d.shape)
    dist, t_idx = world.scene.first_hit(o, d, sc.max_range_m)
    flat_ground = world.site.terrain is None
    if flat_ground:  # flat ground at 0 all round (the scene has none)
        down = (d[:, 2] < -1e-9) & (t_idx < 0)
        dist[down] = -pos[2] / d[down, 2]
    dist, hit_t, hit_kind, t_normal, refl = world.targets.hit(pos, d, dist)
    # into the walls' openings (the parametric facade): a reveal, or the glass
    wall_hit = np.where((hit_t < 0) & (t_idx >= 0), t_idx, -1)
    dist, in_reveal, reveal_normal, in_glass = world.reveals.enter(
        pos, d, dist, wall_hit, world.normals
    )
    keep = np.isfinite(dist) & (dist >= sc.min_range_m) & (dist <= sc.max_range_m) & ~in_glass
    tri = np.maximum(t_idx, 0)
    ground = keep & (hit_t < 0) & (t_idx < 0)  # the flat ground
    t_normal[ground] = (0.0, 0.0, 1.0)
    hit_t[ground], hit_kind[ground] = len(world.surfaces) - 1, POINT_KINDS.index("terrain")
    refl[ground] = SURFACE_REFLECTANCE
    on_mesh = (hit_t < 0) & (t_idx >= 0)
    n = np.where(on_mesh[:, None], world.normals[tri], t_normal)
    n[in_reveal] = reveal_normal[in_reveal]
    cos_t = np.abs(np.einsum("ij,ij->i", n, d))
    # the surface's reflectance (a target's paint; NaN: the datasheet's reference surface):
    # glass returns nothing, a dark wall ranges noisier and not as far (planner.signal)
    target = (hit_t >= 0) & ~ground
    rho = np.where(on_mesh, world.owner_rho[world.owner[tri]], np.nan)
    rho[target] = np.maximum(refl[target], sc.ref_reflectance)  # black ranges as the reference
    signal_cos = cos_t if st.incidence_ranging else 1.0
    with np.errstate(invalid="ignore"):
        keep &= ~(on_mesh & world.silent_tri[tri]) & (dist <= sc.max_range_on(rho, signal_cos))
    on_mesh &= keep
    surface = np.where(on_mesh, world.owner[tri], hit_t)
    kind = np.where(on_mesh, world.tri_kind[tri], hit_kind)
    reflectance = np.where(target, refl, np.where(np.isnan(rho), SURFACE_REFLECTANCE, rho))
    # the normal as the beam sees it (towards the scanner)
    n = np.where((np.einsum("ij,ij->i", n, d) > 0)[:, None], -n, n)
    return Returns(
        dist=dist[keep],
        az=az[col[keep]],
        el=el[row[keep]],
        cos=cos_t[keep],
        rho=rho[keep],
        reflectance=reflectance[keep],
        normal=n[keep],
        surface=surface[keep].astype(np.int64),
        kind=kind[keep].astype(np.int64),
        relief=in_reveal[keep],
        row=row[keep],
        column=col[keep],
        beams=len(d),
    )


@dataclass(frozen=True)
class Floor:
    """The surfaces' own systematic error in one scan (module text): an offset along the
    surface's normal, N(0, ``plane_mm``) on a plane surface and N(0, ``relief_mm``) on a
    reveal, the same within a cell of ``cell_m`` (in the site's frame, per class of normal
    direction) and independent between cells and between scans (``scan_key``)."""

    plane_mm: float
    relief_mm: float
    cell_m: float
    scan_key: int

    def offsets_mm(self, xyz: np.ndarray, normal: np.ndarray, relief: np.ndarray) -> np.ndarray:
        """The offset [mm] of points at ``xyz`` (P, 3) [m] on surfaces of ``normal``."""
        cell = np.floor(xyz / self.cell_m).astype(np.int64)
        axis = np.argmax(np.abs(normal), axis=1)  # the face: ±x, ±y, ±z
        face = 2 * axis + (normal[np.arange(len(normal)), axis] > 0)
        key = np.full(len(xyz), _mix(np.uint64(self.scan_key)))
        for v in (cell[:, 0], cell[:, 1], cell[:, 2], face):
            key = _mix(key ^ v.astype(np.uint64))
        u1 = (_mix(key) >> np.uint64(11)).astype(float) / 2.0**53
        u2 = (_mix(key ^ np.uint64(0xD1B54A32D192ED03)) >> np.uint64(11)).astype(float) / 2.0**53
        z = np.sqrt(-2.0 * np.log(np.maximum(u1, 1e-300))) * np.cos(2.0 * np.pi * u2)
        return z * np.where(relief, self.relief_mm, self.plane_mm)


def _mix(x: np.ndarray) -> np.ndarray:
    """SplitMix64's finaliser (Steele, Lea & Flood, "Fast splittable pseudorandom number
    generators", OOPSLA 2014, https://doi.org/10.1145/2660193.2660195): one random 64-bit
    word per key, the same key always the same word."""
    with np.errstate(over="ignore"):
        x = np.asarray(x, dtype=np.uint64)
        x = (x ^ (x >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
        x = (x ^ (x >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
        return x ^ (x >> np.uint64(31))


@dataclass(frozen=True)
class Measured:
    """A scan's returns as measured: points in the scanner's frame and their predicted
    RMS (the scanner part, :func:`planner.accuracy3d.variances_3d` without the levelling)."""

    local_xyz: np.ndarray  # (R, 3) [m]
    rms_mm: np.ndarray  # (R,)


def measure(
    world: World,
    ret: Returns,
    pos: np.ndarray,
    rot: np.ndarray,
    rng: np.random.Generator,
    *,
    noise: bool = True,
    floor: Floor | None = None,
) -> Measured:
    """The returns ``ret`` of a scanner at ``pos`` turned by ``rot`` measured with the
    planner's error model, the noise drawn from ``rng`` (module text); ``noise=False``: the
    points exactly on the surfaces; ``floor``: the surfaces' own error added."""
    sc, st = world.scanner, world.settings
    s = ret.dist
    m_s = sc.range_rms_on(s, ret.rho, ret.cos if st.incidence_ranging else 1.0)
    var = variances_3d(
        s, np.ones_like(s), np.sin(ret.el), m_s, sc.angle_rms_arcsec, sc.tilt_rms_arcsec, 0.0
    )
    draws = rng.normal(0.0, 1.0, (3, len(s))) * noise
    s_m = s + draws[0] * m_s / 1000.0
    a = ret.az + draws[1] * sc.angle_rms_arcsec / _RHO
    e = ret.el + draws[2] * sc.tilt_rms_arcsec / _RHO
    local = s_m[:, None] * unit(a, e)
    if floor is not None and len(s):
        true_xyz = (s[:, None] * unit(ret.az, ret.el)) @ rot.T + pos
        off = floor.offsets_mm(true_xyz, ret.normal, ret.relief) / 1000.0
        local = local + off[:, None] * (ret.normal @ rot)  # the normal in the scanner's frame
    return Measured(local_xyz=local, rms_mm=np.sqrt(sum(var)).astype(np.float32))
