"""A virtual survey of a plan: the independent check of what the plan promises.

The plan is carried out on a computer, trial after trial, with nothing taken from the
planner's error model:

* every station is set up with a random heading and a random tilt of its vertical axis
  (σ per axis: the scanner's levelling figure, else its vertical-angle RMS m_ν — the
  planner's assumption for a scanner without a compensator), the datum's too;
* every target a station observes is scanned point by point: the scanner's angular grid
  (its step at 10 m, a random phase), each beam intersected with the sphere or the
  checkerboard, noise on the range (a + b·S, grown as 1/√cos θ with the incidence when the
  plan's model has that term) and on both angles; a sphere's centre fitted with its known
  radius (Gauss–Newton), a checkerboard's centre found by a plane fit and the colour
  changes along the scan lines; then a per-axis error for what a fit does not see (the
  planner's floor: printing, turning, centring);
* a target hidden behind another placed sphere or its stand is not observed;
* the stations are registered — one simultaneous adjustment of every observation with
  the datum's scan frame held (as registration software does), or pair by pair along the
  plan's links (weighted Procrustes) — 6 parameters, or 4 for a levelled scanner;
* every facade sample is measured from its assigned station with the same polar noise
  and carried into the registered frame; its error is taken along the facade, across it
  and in height, against true vertical;
* where the world is a 3-D model (``world_of(plan, model)``), each sample's beam is cast
  from its station against the model's own triangles (the survey's ray caster, not the
  planner's sight test): a beam that meets something before the sample, or nothing where
  the plan puts a wall, does not measure it — the sample is *unreached*, a false meet where
  the plan marks it met.

* a cloud-to-cloud link registers its child by an independent ICP on simulated scans
  (``tests/cloud_survey.py``: samples of the child's pose error, drawn one per trial); in
  one adjustment its relative pose is an observation weighted by the spread of those
  samples (the registration's own estimate of the link, not the planner's), pair by pair it
  carries the parent's registered pose to the child.

The frame error (tilt, targets, registration) is simulated ``trials`` times; the scanner's
point noise, which is independent of it, ``noise_trials`` times; their mean squares add.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numba import njit

from planner.pipeline.engine.judge import workbench_of

RHO = 180.0 * 3600.0 / np.pi  # arc-seconds per radian
STAND_RADIUS_M = 0.05  # the pole under a sphere


@dataclass(frozen=True)
class ScanModel:
    """How the scanner measures a point: ranging a + b·S [mm, ppm], both angles' RMS [″],
    its angular step (the spacing at 10 m [mm]) and whether the ranging noise grows as
    1/√cos θ with the incidence."""

    range_rms_mm: float
    range_ppm: float
    angle_rms_arcsec: float
    vertical_rms_arcsec: float
    step_mm_at_10m: float
    incidence_noise: bool

    @classmethod
    def of(cls, scanner, step_mm_at_10m: float, incidence_noise: bool) -> ScanModel:
        return cls(
            scanner.range_rms_mm,
            scanner.range_ppm,
            scanner.angle_rms_arcsec,
            scanner.tilt_rms_arcsec,
            step_mm_at_10m,
            incidence_noise,
        )


@dataclass
class World:
    """What the survey takes from a plan (network indices; metres, mm, arc-seconds)."""

    station_xyz: np.ndarray  # (K, 3)
    station_ids: list[str]
    target_xyz: np.ndarray  # (T, 3) every target candidate (indices of the observations)
    target_type: np.ndarray  # (T,) "flat", "sphere", "control"
    target_size_mm: dict[int, float]  # placed targets
    target_normal: np.ndarray  # (T, 2) a wall's outward normal
    obs: dict[tuple[int, int], float]  # (station, target) → the planner's centre RMS [mm]
    links: list[tuple[int, int, tuple[int, ...]]]  # (parent or -1, child, targets), in order
    datum: int | None
    control_rms_mm: dict[int, float]
    levelled: bool
    tilt_rms_arcsec: float
    scan: ScanModel
    floor_mm: float
    # the facade samples scanned (not on party walls, with a station)
    xyz: np.ndarray  # (N, 3)
    along: np.ndarray  # (N, 2)
    normal: np.ndarray  # (N, 2)
    station: np.ndarray  # (N,) network index
    promised: np.ndarray  # (N, 3) m_x, m_y, m_z [mm]
    promised_reg: np.ndarray  # (N, 3) the registration part [mm]
    limits: np.ndarray  # (N, 3)
    meets: np.ndarray  # (N,)
    sample_id: np.ndarray = field(default_factory=lambda: np.array([]))
    #: the true world, where it is a 3-D model: its triangles (T, 3, 3) [m]
    triangles: np.ndarray | None = None
    #: the cloud links (parent, child) and, once surveyed (tests/cloud_survey.py), samples
    #: (S, 6) of the child's pose error each: shift [mm], rotation [rad] at its centre
    cloud_errors: dict = field(default_factory=dict)

    @property
    def clouds(self) -> list[tuple[int, int]]:
        return [(i, j) for i, j, t in self.links if t is None]


def world_of(p, model=None) -> World:
    """The plan ``p`` (a :class:`planner.pipeline.engine.result.Plan` by targets) as a world to
    survey; ``model`` (a :class:`planner.site.Site` read from a city model): the world is
    that model, its surfaces and terrain the beams meet (a plan made on flat ground carried
    onto it: its heights above each building's base, its stations on the model's ground)."""
    net, sc, st = p.network, p.scanner, p.settings
    assert net is not None and net.error is not None, "the plan has no registration network"
    sxy = net.station_xyz[:, :2]
    ids = []
    for x, y in sxy:
        d = np.hypot(p.stations["x"] - x, p.stations["y"] - y)
        ids.append(str(p.stations["station_id"].iloc[int(np.argmin(d))]))
    index = {sid: j for j, sid in enumerate(ids)}
    tc = net.candidates
    size = {}
    for r in p.targets.itertuples():
        d = np.linalg.norm(tc.xyz - [r.x, r.y, r.z], axis=1)
        t = int(np.argmin(d))
        assert d[t] < 1e-6
        size[t] = float(r.size_mm) if np.isfinite(r.size_mm) else 200.0
    cov = p.coverage.reset_index(drop=True)
    limits = np.column_stack([workbench_of(p).ctx.limits[f"m_{k}"] for k in "xyz"])
    assert len(limits) == len(cov)
    keep = (~cov["party_wall"] & (cov["station_id"] != "")).to_numpy()
    cov, limits = cov[keep], limits[keep]
    fac = p.facades.set_index("facade_id").loc[cov["facade_id"]]
    along = np.column_stack([fac["x1"] - fac["x0"], fac["y1"] - fac["y0"]])
    along /= np.linalg.norm(along, axis=1)[:, None]
    normal = np.column_stack([along[:, 1], -along[:, 0]])
    links = [
        (lk.parent, lk.child, tuple(lk.targets) if lk.info is None else None) for lk in net.links
    ]
    station_xyz = net.station_xyz.copy()
    target_xyz = tc.xyz.copy()
    xyz = cov[["x", "y", "z"]].to_numpy()
    triangles = None
    if model is not None:
        triangles = _model_triangles(model)
        if not p.site.is_3d:  # heights above flat ground: onto the model's ground
            from planner.pipeline.geometry.audit import model_base

            xyz = xyz.copy()
            xyz[:, 2] += model_base(model, cov["building_id"].to_numpy(object), xyz[:, :2])
            station_xyz[:, 2] += _ground(model, station_xyz[:, :2])
            target_xyz[:, 2] += _ground(model, target_xyz[:, :2])
    return World(
        station_xyz=station_xyz,
        station_ids=ids,
        target_xyz=target_xyz,
        target_type=np.asarray(tc.type, dtype=object),
        target_size_mm=size,
        target_normal=tc.normal.copy(),
        obs=dict(net.centre_rms),
        links=links,
        datum=net.datum,
        control_rms_mm={
            int(t): float(tc.control_rms_mm[t]) for t in np.flatnonzero(tc.type == "control")
        },
        levelled=sc.is_levelled,
        tilt_rms_arcsec=sc.initial_tilt_rms_arcsec,
        # (written out, not PlanSettings.incidence_ranging: the survey also reads plans made
        # by the code before it, for benchmarks/virtual_survey_before.json)
        scan=ScanModel.of(
            sc, workbench_of(p).ctx.step_mm_at_10m, st.model == "3d" and st.incidence_noise
        ),
        floor_mm=st.target_floor_mm,
        xyz=xyz,
        along=along,
        normal=normal,
        station=cov["station_id"].map(index).to_numpy(),
        promised=cov[["m_x_mm", "m_y_mm", "m_z_mm"]].to_numpy(),
        promised_reg=cov[["reg_m_x_mm", "reg_m_y_mm", "reg_m_z_mm"]].to_numpy(),
        limits=limits,
        meets=cov["meets"].to_numpy(),
        sample_id=cov["sample_id"].to_numpy(),
        triangles=triangles,
    )


def _ground(model, xy: np.ndarray) -> np.ndarray:
    return model.terrain.ground_z(xy) if model.terrain is not None else np.zeros(len(xy))


def _model_triangles(model) -> np.ndarray:
    """The model's surfaces (not its virtual ones), trees and other structures and its
    terrain round the buildings, as triangles (T, 3, 3): the world the beams meet."""
    from planner.mesh import triangulate

    tri = [
        triangulate(s.rings)
        for b in model.buildings
        for s in b.surfaces
        if s.kind not in ("closure", "interior")
    ]
    tri += [o.mesh for o in model.obstacles if o.mesh is not None]
    if model.terrain is not None:
        pts = np.vstack([np.asarray(b.footprint.bounds).reshape(2, 2) for b in model.buildings])
        lo, hi = pts.min(axis=0) - 300.0, pts.max(axis=0) + 300.0
        tri.append(model.terrain.triangles((lo[0], lo[1], hi[0], hi[1])))
    return np.concatenate([t for t in tri if len(t)])


#: A beam meeting a surface this close to the sample measures it [m].
REACH_TOLERANCE_M = 0.05


def unreached(w: World) -> np.ndarray:
    """(N,) samples whose beam from their station, cast against the world's triangles,
    meets something more than :data:`REACH_TOLERANCE_M` before the sample, or nothing within
    that distance of it (no surface where the plan puts the wall). All False in a world
    without a model (the plan's own)."""
    out = np.zeros(len(w.xyz), dtype=bool)
    if w.triangles is None or not len(w.xyz):
        return out
    from embreex import mesh_construction, rtcore_scene

    origin = w.xyz.mean(axis=0)
    scene = rtcore_scene.EmbreeScene()
    mesh_construction.TriangleMesh(scene, (w.triangles - origin).astype(np.float32))
    src = w.station_xyz[w.station]
    ray = w.xyz - src
    dist = np.linalg.norm(ray, axis=1)
    res = scene.run(
        (src - origin).astype(np.float32),
        (ray / dist[:, None]).astype(np.float32),
        dists=(dist + 1.0).astype(np.float32),
        query="DISTANCE",
    )
    return np.abs(res - dist) > REACH_TOLERANCE_M


# -- rotations --------------------------------------------------------------------------------
def _rot_z(k: np.ndarray) -> np.ndarray:
    c, s = np.cos(k), np.sin(k)
    out = np.zeros((*np.shape(k), 3, 3))
    out[..., 0, 0], out[..., 0, 1], out[..., 1, 0], out[..., 1, 1] = c, -s, s, c
    out[..., 2, 2] = 1.0
    return out


def _rotvec(v: np.ndarray) -> np.ndarray:
    """Rotation matrices (…, 3, 3) of rotation vectors (…, 3) (Rodrigues)."""
    th = np.linalg.norm(v, axis=-1)[..., None, None]
    k = np.zeros((*v.shape[:-1], 3, 3))
    k[..., 0, 1], k[..., 0, 2] = -v[..., 2], v[..., 1]
    k[..., 1, 0], k[..., 1, 2] = v[..., 2], -v[..., 0]
    k[..., 2, 0], k[..., 2, 1] = -v[..., 1], v[..., 0]
    safe = np.where(th > 0, th, 1.0)
    eye = np.broadcast_to(np.eye(3), k.shape)
    return eye + np.sin(safe) / safe * k + (1 - np.cos(safe)) / safe**2 * (k @ k)


def _cross(v: np.ndarray) -> np.ndarray:
    out = np.zeros((*v.shape[:-1], 3, 3))
    out[..., 0, 1], out[..., 0, 2] = -v[..., 2], v[..., 1]
    out[..., 1, 0], out[..., 1, 2] = v[..., 2], -v[..., 0]
    out[..., 2, 0], out[..., 2, 1] = -v[..., 1], v[..., 0]
    return out


# -- the scanner ----------------------------------------------------------------------------
def _directions(az: np.ndarray, el: np.ndarray) -> np.ndarray:
    ce = np.cos(el)
    return np.stack([ce * np.cos(az), ce * np.sin(az), np.sin(el)], axis=-1)


def _measure(m: ScanModel, rng, beam_az, beam_el, rng_m, cos_inc) -> np.ndarray:
    """Points [m] as the scanner records them: the true range along the true beam, with
    noise on the range and on both angles."""
    s_rms = (m.range_rms_mm + m.range_ppm * 1e-3 * rng_m) / 1000.0
    if m.incidence_noise:
        s_rms = s_rms / np.sqrt(np.clip(cos_inc, 0.1, 1.0))
    a = beam_az + rng.normal(0.0, m.angle_rms_arcsec / RHO, beam_az.shape)
    e = beam_el + rng.normal(0.0, m.vertical_rms_arcsec / RHO, beam_el.shape)
    r = rng_m + rng.normal(0.0, 1.0, rng_m.shape) * s_rms
    return r[..., None] * _directions(a, e)


def _grid(m: ScanModel, rng, centre: np.ndarray, half_angle: float):
    """The scanner's beams round ``centre`` (trials, 3) in its own frame: a grid of its
    angular step with a random phase, wide enough for ``half_angle``. (T, A, E) angles."""
    az, el = _axes(m, rng, centre, half_angle)
    shape = (len(centre), az.shape[1], el.shape[1])
    return np.broadcast_to(az[:, :, None], shape), np.broadcast_to(el[:, None, :], shape)


def _axes(m: ScanModel, rng, centre: np.ndarray, half_angle: float):
    """The grid's azimuths (T, A) and elevations (T, E) [rad] (:func:`_grid`)."""
    step = m.step_mm_at_10m / 10_000.0  # rad
    dist = np.linalg.norm(centre, axis=-1)
    az_c = np.arctan2(centre[:, 1], centre[:, 0])
    el_c = np.arcsin(centre[:, 2] / dist)
    n_el = int(np.ceil(half_angle / step)) + 1
    n_az = int(np.ceil(half_angle / step / max(np.cos(el_c).min(), 0.2))) + 1
    ka = np.arange(-n_az, n_az + 1)
    ke = np.arange(-n_el, n_el + 1)
    t = len(centre)
    az = az_c[:, None] + (ka[None, :] + rng.random((t, 1))) * step
    el = el_c[:, None] + (ke[None, :] + rng.random((t, 1))) * step
    return az, el


#: Beams per chunk of trials (memory).
_CHUNK = 1_500_000


def sphere_centre(m: ScanModel, rng, c_local: np.ndarray, radius: float) -> np.ndarray:
    """A sphere scanned from the origin and its centre fitted with the known radius
    (Gauss–Newton from the true centre): (trials, 3) [m] in the scanner's frame. Compiled:
    a sphere near the scanner holds tens of thousands of points per scan."""
    phase = rng.random((len(c_local), 2))
    return _sphere_kernel(
        np.ascontiguousarray(c_local, dtype=float),
        float(radius),
        m.step_mm_at_10m / 10_000.0,
        phase,
        m.range_rms_mm / 1000.0,
        m.range_ppm * 1e-6,
        m.angle_rms_arcsec / RHO,
        m.vertical_rms_arcsec / RHO,
        m.incidence_noise,
        rng,
    )


@njit(cache=True)
def _sphere_kernel(centres, radius, step, phase, s_a, s_b, sd_az, sd_el, incidence, rng):
    out = np.empty_like(centres)
    for t in range(centres.shape[0]):
        cx, cy, cz = centres[t, 0], centres[t, 1], centres[t, 2]
        c2 = cx * cx + cy * cy + cz * cz
        dist = np.sqrt(c2)
        az_c, el_c = np.arctan2(cy, cx), np.arcsin(cz / dist)
        half = np.arcsin(min(radius / dist, 0.99))
        n_el = int(np.ceil(half / step)) + 1
        n_az = int(np.ceil(half / step / max(np.cos(el_c), 0.2))) + 1
        pts = np.empty(((2 * n_az + 1) * (2 * n_el + 1), 3))
        n = 0
        for ka in range(-n_az, n_az + 1):
            az = az_c + (ka + phase[t, 0]) * step
            for ke in range(-n_el, n_el + 1):
                el = el_c + (ke + phase[t, 1]) * step
                dx, dy, dz = np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)
                b = dx * cx + dy * cy + dz * cz
                disc = b * b - (c2 - radius * radius)
                if disc <= 0.0:
                    continue
                root = np.sqrt(disc)
                rng_m = b - root
                sd = s_a + s_b * rng_m
                if incidence:
                    sd /= np.sqrt(max(root / radius, 0.1))
                a2 = az + rng.standard_normal() * sd_az
                e2 = el + rng.standard_normal() * sd_el
                r2 = rng_m + rng.standard_normal() * sd
                pts[n, 0] = r2 * np.cos(e2) * np.cos(a2)
                pts[n, 1] = r2 * np.cos(e2) * np.sin(a2)
                pts[n, 2] = r2 * np.sin(e2)
                n += 1
        ex, ey, ez = cx, cy, cz
        for _ in range(4):  # Gauss–Newton on Σ (|p − c| − R)²
            nm = np.zeros((3, 3))
            g = np.zeros(3)
            for i in range(n):
                ux, uy, uz = pts[i, 0] - ex, pts[i, 1] - ey, pts[i, 2] - ez
                d = np.sqrt(ux * ux + uy * uy + uz * uz)
                ux, uy, uz = ux / d, uy / d, uz / d
                res = d - radius
                nm[0, 0] += ux * ux
                nm[0, 1] += ux * uy
                nm[0, 2] += ux * uz
                nm[1, 1] += uy * uy
                nm[1, 2] += uy * uz
                nm[2, 2] += uz * uz
                g[0] += ux * res
                g[1] += uy * res
                g[2] += uz * res
            step_c = _solve_symmetric_3(nm, g)
            ex, ey, ez = ex + step_c[0], ey + step_c[1], ez + step_c[2]
        out[t, 0], out[t, 1], out[t, 2] = ex, ey, ez
    return out


@njit(cache=True)
def _solve_symmetric_3(a, b):
    """x with a x = b for a symmetric 3 × 3 ``a`` (its upper triangle read), by Cramer's
    rule: np.linalg.solve would compile numba's LAPACK bindings (7 of the kernel's 11 s of
    compiling in a fresh clone)."""
    a00, a01, a02, a11, a12, a22 = a[0, 0], a[0, 1], a[0, 2], a[1, 1], a[1, 2], a[2, 2]
    c00 = a11 * a22 - a12 * a12  # the cofactors (symmetric)
    c01 = a02 * a12 - a01 * a22
    c02 = a01 * a12 - a02 * a11
    c11 = a00 * a22 - a02 * a02
    c12 = a01 * a02 - a00 * a12
    c22 = a00 * a11 - a01 * a01
    det = a00 * c00 + a01 * c01 + a02 * c02
    x = np.empty(3)
    x[0] = (c00 * b[0] + c01 * b[1] + c02 * b[2]) / det
    x[1] = (c01 * b[0] + c11 * b[1] + c12 * b[2]) / det
    x[2] = (c02 * b[0] + c12 * b[1] + c22 * b[2]) / det
    return x


def board_centre(
    m: ScanModel, rng, c_local: np.ndarray, n_local: np.ndarray, up_local: np.ndarray, size: float
) -> np.ndarray:
    """A checkerboard (side ``size`` [m], normal ``n_local``, its edges level and plumb)
    scanned from the origin; its centre found by a plane fit and the colour changes along
    the scan lines (the midpoint of each pair of neighbouring points of different colour):
    (trials, 3) [m] in the scanner's frame."""
    out = np.empty_like(c_local)
    half = float(np.arctan(size / np.sqrt(2) / np.linalg.norm(c_local, axis=-1).min()))
    az, el = _grid(m, rng, c_local[:1], half)
    per = max(1, _CHUNK // az[0].size)
    for lo in range(0, len(c_local), per):
        c, nrm, up = c_local[lo : lo + per], n_local[lo : lo + per], up_local[lo : lo + per]
        ax = np.cross(up, nrm)  # along the board, level
        az, el = _grid(m, rng, c, half)
        d = _directions(az, el)
        dn = np.einsum("taek,tk->tae", d, nrm)
        rng_m = (c * nrm).sum(-1)[:, None, None] / np.where(dn < 0, dn, -1.0)
        p = rng_m[..., None] * d - c[:, None, None, :]
        pu = np.einsum("taek,tk->tae", p, ax)
        pv = np.einsum("taek,tk->tae", p, up)
        hit = (dn < 0) & (np.abs(pu) <= size / 2) & (np.abs(pv) <= size / 2)
        colour = np.sign(pu) * np.sign(pv)
        pts = _measure(m, rng, az, el, np.where(hit, rng_m, 1.0), -dn)
        mask = hit.astype(float)
        cnt = mask.sum(axis=(1, 2))
        mean = np.einsum("taek,tae->tk", pts, mask) / cnt[:, None]
        q = (pts - mean[:, None, None, :]) * mask[..., None]
        scatter = np.einsum("taei,taej->tij", q, q)
        _, vec = np.linalg.eigh(scatter)
        n_fit = vec[..., 0] * np.sign((vec[..., 0] * nrm).sum(-1))[:, None]
        z = np.array([0.0, 0.0, 1.0])
        u_fit = np.cross(z, n_fit)
        u_fit /= np.linalg.norm(u_fit, axis=-1)[:, None]
        u_fit *= np.sign((u_fit * ax).sum(-1))[:, None]
        v_fit = np.cross(n_fit, u_fit)
        rel = pts - mean[:, None, None, :]
        fu = np.einsum("taek,tk->tae", rel, u_fit)
        fv = np.einsum("taek,tk->tae", rel, v_fit)

        u0 = _edge(fu, hit, colour, 1)  # along a row (one elevation) the colour changes at u = 0
        v0 = _edge(fv, hit, colour, 2)  # along a profile (one azimuth) at v = 0
        out[lo : lo + per] = mean + u0[:, None] * u_fit + v0[:, None] * v_fit
    return out


def _edge(coord, hit, colour, axis):
    """Where the colour changes along ``axis`` of the grid: the mean midpoint of every pair
    of neighbouring points on the board of different colour (T,)."""
    a = np.moveaxis(coord, axis, -1)
    h = np.moveaxis(hit, axis, -1)
    col = np.moveaxis(colour, axis, -1)
    pair = h[..., 1:] & h[..., :-1] & (col[..., 1:] != col[..., :-1])
    mid = 0.5 * (a[..., 1:] + a[..., :-1])
    return (mid * pair).sum(axis=(1, 2)) / np.maximum(pair.sum(axis=(1, 2)), 1)


# -- occlusion by the spheres set up -----------------------------------------------------------
def hidden(w: World, clearance_m: float = 0.0) -> set[tuple[int, int]]:
    """Observations whose sight line passes through another placed sphere or its stand."""
    spheres = [t for t in w.target_size_mm if w.target_type[t] == "sphere"]
    out = set()
    for j, t in w.obs:
        a, b = w.station_xyz[j], w.target_xyz[t]
        for o in spheres:
            if o == t:
                continue
            c, r = w.target_xyz[o], w.target_size_mm[o] / 2000.0 + clearance_m
            ab = b - a
            u = np.clip(np.dot(c - a, ab) / np.dot(ab, ab), 0.0, 1.0)
            if np.linalg.norm(a + u * ab - c) < r and 0.0 < u < 1.0:
                out.add((j, t))
                break
            # the stand: a vertical pole from the ground to the sphere
            s = np.linspace(0.0, 1.0, 400)
            line = a + s[:, None] * ab
            near = np.hypot(line[:, 0] - c[0], line[:, 1] - c[1]) < STAND_RADIUS_M + clearance_m
            if (near & (line[:, 2] < c[2] - r) & (s > 0.01) & (s < 0.99)).any():
                out.add((j, t))
                break
    return out


# -- the survey -----------------------------------------------------------------------------
@dataclass
class Result:
    world: World
    frame_ms: np.ndarray  # (N, 3) mean square of the frame error [mm²]
    frame_se: np.ndarray  # (N, 3) its standard error
    noise_ms: np.ndarray  # (N, 3) mean square of the point noise [mm²]
    noise_se: np.ndarray  # (N, 3) its standard error
    hidden: set
    untied: np.ndarray  # (K,) bool: stations the survey could not register
    unreached: np.ndarray | None = None  # (N,) bool: beams that do not reach the sample

    @property
    def rms(self) -> np.ndarray:
        return np.sqrt(self.frame_ms + self.noise_ms)

    @property
    def rms_se(self) -> np.ndarray:
        """Standard error of :attr:`rms` (both simulations')."""
        return np.hypot(self.frame_se, self.noise_se) / (2.0 * np.maximum(self.rms, 1e-9))

    def false_meets(self, sigmas: float = 3.0) -> np.ndarray:
        """Samples the plan marks met whose simulated RMS exceeds a limit by more than
        ``sigmas`` standard errors of the simulation (0: any excess)."""
        w = self.world
        over = self.rms - w.limits > sigmas * self.rms_se + 1e-9
        lost = self.untied[w.station]
        if self.unreached is not None:
            lost = lost | self.unreached
        return w.meets & (over.any(axis=1) | lost)

    def ratios(self) -> np.ndarray:
        """(N, 3) simulated over promised RMS (total), at the samples marked met."""
        w = self.world
        return self.rms[w.meets] / w.promised[w.meets]

    def frame_ratios(self) -> np.ndarray:
        """(N, 3) simulated over promised registration RMS, at the samples marked met."""
        w = self.world
        ok = w.meets & (w.promised_reg > 0).all(axis=1)
        return np.sqrt(self.frame_ms[ok]) / w.promised_reg[ok]


def survey(
    w: World,
    *,
    trials: int = 200,
    noise_trials: int = 20_000,
    seed: int = 0,
    tilt: bool = True,
    target_points: bool = True,
    occlusion: bool = True,
    processing: str = "adjustment",
) -> Result:
    """Survey the world ``w`` (module docstring). ``tilt``: the stations' axes tilted (the
    datum's included); ``target_points``: targets scanned point by point (else each
    centre measured with the planner's RMS); ``occlusion``: targets hidden by placed
    spheres are not observed; ``processing``: ``adjustment`` or ``pairwise``."""
    rng = np.random.default_rng(seed)
    k = len(w.station_xyz)
    heading = rng.uniform(0, 2 * np.pi, k)
    tau = (w.tilt_rms_arcsec / RHO) if tilt else 0.0
    tilt_v = np.zeros((trials, k, 3))
    tilt_v[..., :2] = rng.normal(0.0, tau, (trials, k, 2))
    true_rot = _rotvec(tilt_v) @ _rot_z(heading)  # (T, K, 3, 3): local → world
    nominal = _rot_z(heading)
    hid = hidden(w) if occlusion else set()
    obs = {key: rms for key, rms in w.obs.items() if key not in hid}
    # every observation: the centre measured in the station's frame
    meas = {}
    for (j, t), rms in obs.items():
        c_local = np.einsum("tji,j->ti", true_rot[:, j], w.target_xyz[t] - w.station_xyz[j])
        ty = w.target_type[t]
        if not target_points or ty == "control":
            centre = c_local + rng.normal(0.0, rms / 1000.0, c_local.shape)
        else:
            size = w.target_size_mm[t] / 1000.0
            if ty == "sphere":
                centre = sphere_centre(w.scan, rng, c_local, size / 2)
            else:
                n3 = np.array([*w.target_normal[t], 0.0])
                n_local = np.einsum("tji,j->ti", true_rot[:, j], n3)
                up_local = np.einsum("tji,j->ti", true_rot[:, j], np.array([0.0, 0.0, 1.0]))
                centre = board_centre(w.scan, rng, c_local, n_local, up_local, size)
            centre = centre + rng.normal(0.0, w.floor_mm / 1000.0, centre.shape)
        meas[(j, t)] = centre
    control = {t: rng.normal(0.0, r / 1000.0, (trials, 3)) for t, r in w.control_rms_mm.items()}
    clouds = _cloud_draws(w, rng, trials, tilt_v)
    if processing == "adjustment":
        rot, pos, tied = _adjust(w, obs, meas, nominal, control, trials, clouds)
    else:
        rot, pos, tied = _pairwise(w, obs, meas, nominal, control, trials, clouds)
    # the frame error at every sample: the true local point carried by the estimated pose
    j = w.station
    local = np.einsum("tnji,nj->tni", true_rot[:, j], w.xyz - w.station_xyz[j])
    est = np.einsum("tnij,tnj->tni", rot[:, j], local) + pos[:, j]
    err = (est - w.xyz) * 1000.0  # (T, N, 3) mm
    comp = _facade(err, w)
    frame_ms = np.mean(comp**2, axis=0)
    frame_se = np.std(comp**2, axis=0) / np.sqrt(trials)
    noise_ms, noise_se = _point_noise(w, rng, noise_trials)
    frame_ms[~tied[j]] = np.inf
    return Result(w, frame_ms, frame_se, noise_ms, noise_se, hid, ~tied, unreached(w))


def _facade(err: np.ndarray, w: World) -> np.ndarray:
    return np.stack(
        [
            np.einsum("tni,ni->tn", err[..., :2], w.along),
            np.einsum("tni,ni->tn", err[..., :2], w.normal),
            err[..., 2],
        ],
        axis=-1,
    )


def _point_noise(w: World, rng, trials: int) -> tuple[np.ndarray, np.ndarray]:
    """Mean square [mm²] of each sample's polar noise from its station, in the facade frame,
    and its standard error."""
    rel = w.xyz - w.station_xyz[w.station]
    dist = np.linalg.norm(rel, axis=1)
    az = np.arctan2(rel[:, 1], rel[:, 0])
    el = np.arcsin(rel[:, 2] / dist)
    cos_g = np.abs((-rel[:, :2] * w.normal).sum(1)) / np.hypot(rel[:, 0], rel[:, 1])
    cos_inc = cos_g * np.cos(el)
    out = np.zeros((len(dist), 3))
    out2 = np.zeros((len(dist), 3))
    per = max(1, 2_000_000 // max(len(dist), 1))
    done = 0
    while done < trials:
        t = min(per, trials - done)
        shape = (t, len(dist))
        pts = _measure(
            w.scan,
            rng,
            np.broadcast_to(az, shape),
            np.broadcast_to(el, shape),
            np.broadcast_to(dist, shape),
            np.broadcast_to(cos_inc, shape),
        )
        sq = _facade((pts - rel) * 1000.0, w) ** 2
        out += sq.sum(axis=0)
        out2 += (sq * sq).sum(axis=0)
        done += t
    mean = out / trials
    return mean, np.sqrt(np.maximum(out2 / trials - mean * mean, 0.0) / trials)


def _cloud_draws(w: World, rng, trials: int, tilt_v: np.ndarray) -> dict:
    """Per cloud link (i, j): the relative pose each trial's registration measures, as the
    deviation of j's pose from the nominal carried from i's (T, 6) [m, rad]: the truth
    (both stations' tilts; the positions are true) plus one of the link's surveyed errors."""
    out = {}
    for i, j in w.clouds:
        e = w.cloud_errors[(i, j)]
        pick = e[rng.integers(0, len(e), trials)]
        lever = w.station_xyz[j] - w.station_xyz[i]
        truth = np.concatenate([-np.cross(tilt_v[:, i], lever), tilt_v[:, j] - tilt_v[:, i]], 1)
        out[(i, j)] = truth + np.concatenate([pick[:, :3] / 1000.0, pick[:, 3:]], axis=1)
    return out


def _cloud_rows(w: World, clouds: dict, scol: dict, n_unk: int):
    """The cloud links' relative-pose rows of the adjustment, whitened by each link's own
    spread (the inverse covariance of its surveyed errors): rows (6·L, n_unk), right-hand
    sides (T, 6·L)."""
    rows, rhs = [], []
    for (i, j), d in clouds.items():
        e = w.cloud_errors[(i, j)]
        e = np.concatenate([e[:, :3] / 1000.0, e[:, 3:]], axis=1)
        cov = e.T @ e / len(e) + np.diag([1e-10] * 3 + [1e-12] * 3)  # m², rad²
        white = np.linalg.cholesky(np.linalg.inv(cov)).T
        a = np.zeros((6, n_unk))
        t = np.eye(6)
        t[:3, 3:] = -_cross(w.station_xyz[j] - w.station_xyz[i])
        if j in scol:
            a[:, scol[j] : scol[j] + 6] += np.eye(6)
        if i in scol:
            a[:, scol[i] : scol[i] + 6] -= t
        rows.append(white @ a)
        rhs.append(d @ white.T)
    return rows, rhs


def _adjust(w: World, obs, meas, nominal, control, trials, clouds=None):
    """One simultaneous least-squares adjustment of every observation (a Gauss–Newton step
    from the nominal poses and the true target positions, exact to first order): the
    datum's frame held, each other station 6 parameters (4 levelled), every target 3; the
    control points observed with their RMS (``control``: the error of their given
    coordinates per trial [m]). Returns rotations, positions (T, K, …), tied."""
    k = len(w.station_xyz)
    rot = np.broadcast_to(nominal, (trials, k, 3, 3)).copy()
    pos = np.broadcast_to(w.station_xyz, (trials, k, 3)).copy()
    tied = _reached(w, obs)
    free = [j for j in range(k) if tied[j] and j != w.datum]
    npar = 4 if w.levelled else 6
    targets = sorted({t for (j, t) in obs if tied[j]} | set(w.control_rms_mm))
    tcol = {t: len(free) * npar + 3 * n for n, t in enumerate(targets)}
    scol = {j: npar * n for n, j in enumerate(free)}
    n_unk = len(free) * npar + 3 * len(targets)
    rows, rhs, wts = [], [], []
    for (j, t), rms in obs.items():
        if not tied[j]:
            continue
        a = np.zeros((3, n_unk))
        a[:, tcol[t] : tcol[t] + 3] = -np.eye(3)
        lever = w.target_xyz[t] - w.station_xyz[j]
        if j in scol:
            full = np.hstack([np.eye(3), -_cross(lever)])  # ∂(R m + s)/∂(δs, δω)
            a[:, scol[j] : scol[j] + npar] = full[:, [0, 1, 2, 5]] if w.levelled else full
        # residual: where the nominal pose puts the measured centre, minus the true centre
        r = np.einsum("ij,tj->ti", nominal[j], meas[(j, t)]) + w.station_xyz[j] - w.target_xyz[t]
        rows.append(a)
        rhs.append(-r)
        wts.append(np.full(3, 1.0 / (rms / 1000.0) ** 2))
    for t, rms in w.control_rms_mm.items():
        a = np.zeros((3, n_unk))
        a[:, tcol[t] : tcol[t] + 3] = np.eye(3)
        rows.append(a)
        rhs.append(control[t])
        wts.append(np.full(3, 1.0 / (rms / 1000.0) ** 2))
    if clouds:
        assert not w.levelled, "the survey registers cloud links with 6 parameters"
        c_rows, c_rhs = _cloud_rows(w, clouds, scol, n_unk)
        rows += c_rows
        rhs += c_rhs
        wts += [np.ones(6)] * len(c_rows)
    if not n_unk or not rows:
        return rot, pos, tied
    a = np.concatenate(rows)
    b = np.concatenate(rhs, axis=1)  # (T, rows)
    wv = np.concatenate(wts)
    n = a.T @ (wv[:, None] * a)
    x = np.linalg.solve(n, (a.T * wv) @ b.T).T  # (T, n_unk)
    for j in free:
        p = x[:, scol[j] : scol[j] + npar]
        shift, omega = p[:, :3], np.zeros((trials, 3))
        if w.levelled:
            omega[:, 2] = p[:, 3]
        else:
            omega = p[:, 3:6]
        rot[:, j] = _rotvec(omega) @ nominal[j]
        pos[:, j] = w.station_xyz[j] + shift
    return rot, pos, tied


def _reached(w: World, obs) -> np.ndarray:
    """Stations the observations tie to the datum (three common targets along a chain, or
    a cloud link)."""
    k = len(w.station_xyz)
    seen: dict[int, set[int]] = {}
    for j, t in obs:
        seen.setdefault(j, set()).add(t)
    tied = np.zeros(k, dtype=bool)
    known: set[int] = set(w.control_rms_mm)
    if w.datum is not None:
        tied[w.datum] = True
        known |= seen.get(w.datum, set())
    grew = True
    while grew:
        grew = False
        for j in range(k):
            by_cloud = any(tied[i] for i, c in w.clouds if c == j) or any(
                tied[c] for c, i in w.clouds if i == j
            )
            if not tied[j] and (len(seen.get(j, set()) & known) >= 3 or by_cloud):
                tied[j] = True
                known |= seen.get(j, set())
                grew = True
    return tied


def _pairwise(w: World, obs, meas, nominal, control, trials, clouds=None):
    """Each link of the plan registered on its own, child to parent, in tree order:
    weighted Procrustes of the child's measured centres onto the parent's registered ones
    (6 parameters; levelled: the shift and the rotation about the vertical); a cloud link
    carries the parent's registered pose to the child with its measured relative pose."""
    k = len(w.station_xyz)
    rot = np.broadcast_to(nominal, (trials, k, 3, 3)).copy()
    pos = np.broadcast_to(w.station_xyz, (trials, k, 3)).copy()
    tied = np.zeros(k, dtype=bool)
    if w.datum is not None:
        tied[w.datum] = True
    for parent, child, targets in w.links:
        if targets is None:  # cloud to cloud
            if not tied[parent]:
                continue
            # the parent's registered pose, as a deviation from its nominal one
            d = rot[:, parent] @ np.swapaxes(nominal[parent], -1, -2)[None]
            w_i = 0.5 * np.stack(
                [d[:, 2, 1] - d[:, 1, 2], d[:, 0, 2] - d[:, 2, 0], d[:, 1, 0] - d[:, 0, 1]], 1
            )
            s_i = pos[:, parent] - w.station_xyz[parent]
            lever = w.station_xyz[child] - w.station_xyz[parent]
            rel = clouds[(parent, child)]
            s_j = s_i + np.cross(w_i, lever) + rel[:, :3]
            rot[:, child] = _rotvec(w_i + rel[:, 3:]) @ nominal[child]
            pos[:, child] = w.station_xyz[child] + s_j
            tied[child] = True
            continue
        use = [t for t in targets if (child, t) in obs and (parent == -1 or (parent, t) in obs)]
        if len(use) < 3 or (parent != -1 and not tied[parent]):
            continue
        if parent == -1:
            ref = np.stack([w.target_xyz[t] + control[t] for t in use], axis=1)
            wt = np.array([1 / (w.control_rms_mm[t] ** 2 + obs[(child, t)] ** 2) for t in use])
        else:
            ref = np.stack(
                [
                    np.einsum("tij,tj->ti", rot[:, parent], meas[(parent, t)]) + pos[:, parent]
                    for t in use
                ],
                axis=1,
            )
            wt = np.array([1 / (obs[(parent, t)] ** 2 + obs[(child, t)] ** 2) for t in use])
        q = np.stack([meas[(child, t)] for t in use], axis=1)  # (T, n, 3) child's frame
        rot[:, child], pos[:, child] = _procrustes(q, ref, wt, w.levelled)
        tied[child] = True
    return rot, pos, tied


def _procrustes(q, p, wt, levelled):
    """R, t (per trial) minimising Σ w‖R q + t − p‖²; levelled: R = R_z(κ), only κ and t
    estimated."""
    wn = wt / wt.sum()
    qc = np.einsum("n,tni->ti", wn, q)
    pc = np.einsum("n,tni->ti", wn, p)
    a, b = q - qc[:, None], p - pc[:, None]
    if levelled:
        # q is in the (untilted, unturned) scanner frame: R = R_z(κ)
        cross = np.einsum("n,tn->t", wn, a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0])
        dot = np.einsum("n,tn->t", wn, a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1])
        r = _rot_z(np.arctan2(cross, dot))
    else:
        h = np.einsum("n,tni,tnj->tij", wn, a, b)
        u, _, vt = np.linalg.svd(h)
        d = np.sign(np.linalg.det(np.swapaxes(vt, 1, 2) @ np.swapaxes(u, 1, 2)))
        fix = np.broadcast_to(np.eye(3), h.shape).copy()
        fix[:, 2, 2] = d
        r = np.swapaxes(vt, 1, 2) @ fix @ np.swapaxes(u, 1, 2)
    return r, pc - np.einsum("tij,tj->ti", r, qc)


def report(res: Result) -> dict:
    """The numbers a closing note gives: samples simulated and marked met, false meets (any
    excess, and beyond 3 standard errors), and the ratio simulated / promised at the median
    and the 95th percentile per axis (total and registration part)."""
    w = res.world
    r, f = res.ratios(), res.frame_ratios()
    fin = np.isfinite(r).all(axis=1)
    return {
        "samples": len(w.meets),
        "met": int(w.meets.sum()),
        "false_meets_any": int(res.false_meets(0.0).sum()),
        "false_meets_3se": int(res.false_meets(3.0).sum()),
        "hidden": len(res.hidden),
        "untied": int(res.untied.sum()),
        "unreached": int(res.unreached.sum()) if res.unreached is not None else 0,
        "unreached_met": int((res.unreached & w.meets).sum()) if res.unreached is not None else 0,
        "median": np.median(r[fin], axis=0).round(3).tolist(),
        "p95": np.percentile(r[fin], 95, axis=0).round(3).tolist(),
        "reg_median": np.median(f[np.isfinite(f).all(1)], axis=0).round(3).tolist(),
        "reg_p95": np.percentile(f[np.isfinite(f).all(1)], 95, axis=0).round(3).tolist(),
    }
