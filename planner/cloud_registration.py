r"""Cloud-to-cloud registration: the error of registering two scans by their common surfaces.

Most crews register scans cloud to cloud (Leica Cyclone REGISTER 360, FARO SCENE, Trimble
RealWorks, Autodesk ReCap) rather than by targets. Voroshilov & Karachentsev count "the
overlap zones of neighbouring scans" among what a station choice must weigh, without a
model of it; this module is the planner's model, beyond the paper, checked by a Monte
Carlo of simulated scans registered by an independent point-to-plane ICP in
``tests/test_cloud_registration.py``.

**Patches.** The surfaces two stations both see are cut into small patches (a facade
sample's cell, a ground cell), each a plane through ``p`` with unit normal ``n``. A
registration does not use the scans as they are: registration software thins them to an
even spacing first (:data:`DEFAULT_CLOUD_SPACING_MM`) and fits each point's local plane to
its nearest neighbours (:data:`LINK_NEIGHBOURS`). So station j's points on a patch are
those of its scan step at that range, spread along the beam by the incidence and thinned
to the even spacing (:func:`registration_spacing`, :func:`registration_points`); a patch
counts only where those neighbourhoods span the surface in two directions — at grazing
incidence the points lie in lines whose neighbourhoods are lines, not planes — and the
incidence is at most :data:`MAX_LINK_INCIDENCE_DEG`. Each point has RMS ``σ_j`` along the
normal (the accuracy model's error across the surface), so the patch's position along its
normal in scan j is known to

.. math::

    v_j = \sigma_j^2 / n_j + \sigma_\mathrm{floor}^2 / u ,

the floor being the surface's own error in one scan that no number of points averages away
(roughness, edges, ranging biases with incidence and material, the scanner's calibration):
1 mm unless given, independent from one cell of :data:`FLOOR_CELL_M` to the next, so a
patch of area A holds ``u = A / FLOOR_CELL_M²`` of them (:func:`patch_variance_mm2`,
:func:`floor_units`). The prediction so does not depend on how finely the planner cuts the
walls into samples: halving a patch halves both its points and its floor's cells.

**Point-to-plane normal equations.** Registering scan j to scan i moves j's points by
``δs + δω × r`` (r = p − s_j); a patch's point-to-plane residual changes by
``a·(δs, δω)`` with ``a = (n, r × n)`` (:func:`plane_rows`). Near convergence the
point-to-plane estimate (Chen & Medioni 1992; Rusinkiewicz & Levoy, "Efficient variants of
the ICP algorithm", 3DIM 2001, https://doi.org/10.1109/IM.2001.924423) has the
information matrix

.. math::

    J = \sum_k \frac{a_k a_k^\top}{v_{i,k} + v_{j,k}}

and covariance ``J⁻¹`` — the closed form of Censi, "An accurate closed-form estimate of
ICP's covariance", ICRA 2007 (https://doi.org/10.1109/ROBOT.2007.363961) for
point-to-plane residuals with independent noise (:func:`link_information`,
:func:`link_covariance`). Its eigenvectors are the directions the surfaces fix; a
direction no surface constrains (along a straight street with one facade and the ground)
has an eigenvalue near zero (Gelfand, Ikemoto, Rusinkiewicz & Levoy, "Geometrically stable
sampling for the ICP algorithm", 3DIM 2003, https://doi.org/10.1109/IM.2003.1240258):
:func:`link_strength`.

A levelled scanner (a compensator) estimates 4 parameters, the shift and the rotation about
the vertical; the two stations' residual tilts ζ (σ_τ per axis each) are not estimated,
so the relative tilt ``Δζ`` is an error of the link and biases the 4 estimated parameters
by ``−J₄₄⁻¹ J₄τ Δζ`` (the same treatment as the target registrations of
:mod:`planner.registration_error`).

**Relief.** A real wall is not a plane: the reveals of its windows and doors, its sills,
lintels, balconies and downpipes have surfaces whose normals run along it, and it is on
these that point-to-plane ICP fixes the shift along a wall two scans share (a plain wall
and the ground leave that shift free). Where the model has them (an LoD3 model's reveals
are walls of their own) they are patches like any other. Otherwise the planner uses a
stated **parametric facade** (:func:`relief_areas`): windows of :data:`WINDOW_WIDTH_M` ×
:data:`WINDOW_HEIGHT_M` over a share of the wall (``window_share``, default
:data:`DEFAULT_WINDOW_SHARE`: European housing stock has window-to-wall ratios of about
15–35 %), set :data:`DEFAULT_REVEAL_DEPTH_M` behind its face. Each facade patch then
carries three relief patches: the two jambs (normals ±along the wall) and the head
(normal down). A scan sees a jamb only from the side it faces, to the depth the
opening's width lets it see (:func:`reveal_visible`); it counts only where that depth holds
:data:`MIN_POINTS_ACROSS` rows of the thinned cloud, less the row along its edge with the
wall, whose neighbourhoods straddle the two faces. So two scans share a jamb only where
both stand on the same side of it — a pair in front of one long wall is tied along it by
the windows beyond both, not by those between them — and a reveal shallower than a few
registration spacings ties nothing. Sills (normal up) are seen only from above and are left
out; a plain wall
(``window_share=0``, a curtain wall, a blank gable) gets no relief. The relief adds no
overlap (registration software counts overlap on the wall's own surface). A reveal's floor
is per opening (:data:`planner.pipeline.network.clouds.RELIEF_FLOOR_MM`: a reveal only a
few point spacings deep tilts its local planes).

**Overlap.** Registration software reports a link's overlap as the share of a scan that
lies on surfaces the other scan also holds, counted on clouds thinned to an even spacing —
by surface area, not by raw points (which crowd near the scanner); :func:`overlap_pct`
takes the smaller of the two shares, on the patches the registration can use (the
planned facades, and the ground near the stations seen at no more than
:data:`MAX_LINK_INCIDENCE_DEG`).

**Where it starts.** An ICP converges from where the scans are pre-aligned (the scanner's
own tracking, or the operator's picking: :attr:`planner.scanner.Scanner.start_error`) and
stays there along a direction its surfaces do not fix: the start's error is the link's
prior (:func:`start_information`). Whether it gets there at all — the basin — is what the
plan's rehearsal of each link checks (:mod:`planner.pipeline.network.linkcheck`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from planner.units import RHO_ARCSEC

__all__ = [
    "DEFAULT_CLOUD_FLOOR_MM",
    "DEFAULT_CLOUD_SPACING_MM",
    "DEFAULT_MIN_OVERLAP_PCT",
    "DEFAULT_REVEAL_DEPTH_M",
    "DEFAULT_WINDOW_SHARE",
    "FLOOR_CELL_M",
    "GROUND_REACH_M",
    "LINK_NEIGHBOURS",
    "MAX_LINK_INCIDENCE_DEG",
    "MIN_POINTS_ACROSS",
    "SILL_M",
    "STOREY_M",
    "WINDOW_HEIGHT_M",
    "WINDOW_WIDTH_M",
    "bay_width_m",
    "floor_units",
    "link_covariance",
    "link_information",
    "link_strength",
    "overlap_pct",
    "patch_variance_mm2",
    "plane_rows",
    "registration_points",
    "registration_spacing",
    "relief_areas",
    "relief_words",
    "reveal_visible",
    "start_information",
    "weakest_direction",
]

#: What a patch's plane fit does not see (roughness, edges, calibration) [mm], per cell of
#: :data:`FLOOR_CELL_M` and scan.
DEFAULT_CLOUD_FLOOR_MM = 1.0
#: The floor is independent from one cell of this side to the next [m].
FLOOR_CELL_M = 2.0
#: The even spacing registration software thins the clouds to before a cloud-to-cloud
#: registration [mm]. CloudCompare's ICP samples at most 50 000 points of a cloud by
#: default (CloudCompare user manual, "Fine registration (ICP)": its random sampling
#: limit); over the 500–1 000 m² two neighbouring scans of buildings share, that is a
#: spacing of 10–14 cm. Cyclone REGISTER 360 and SCENE state none; 100 mm is assumed
#: (``--cloud-spacing-mm``: a finer spacing uses shallower relief, and its check is longer).
DEFAULT_CLOUD_SPACING_MM = 100.0
#: How far from a station its ground counts for a link [m] (nearer, the ground is seen
#: steeply enough to be a plane to a registration; farther, a few sparse lines).
GROUND_REACH_M = 25.0
#: A patch seen at a larger incidence gives a registration nothing [°].
MAX_LINK_INCIDENCE_DEG = 85.0
#: The neighbours of a point's local plane (small_gicp's default, 10): a patch whose
#: thinned points lie in lines farther apart than a neighbourhood reaches gives lines, not
#: planes.
LINK_NEIGHBOURS = 10
#: Rows of points across the depth of a reveal it shows it needs to be a plane to a
#: registration (the row at its edge with the wall is not one).
MIN_POINTS_ACROSS = 2.0
#: The overlap registration software asks of a cloud-to-cloud link [%] (Autodesk ReCap's
#: registration report: balance above 20 %).
DEFAULT_MIN_OVERLAP_PCT = 20.0
#: The parametric facade (module docstring): the share of a wall in openings, how deep they
#: sit [m], and an opening's size [m]. The share is an assumption of a typical residential
#: or office facade (window-to-wall ratios of 15–35 %; Goia, "Search for the optimal
#: window-to-wall ratio in office buildings in different European climates", Solar Energy
#: 132, 467–492, 2016, https://doi.org/10.1016/j.solener.2016.03.031, finds 30–45 % best for
#: offices); the depth that of a window set in a masonry wall's reveal.
DEFAULT_WINDOW_SHARE = 0.25
DEFAULT_REVEAL_DEPTH_M = 0.15
WINDOW_WIDTH_M = 1.2
WINDOW_HEIGHT_M = 1.5
#: The openings' layout where one is drawn (the rehearsal's walls): one per bay and storey,
#: the sill this far above the storey's floor [m].
STOREY_M = 3.0
SILL_M = 0.9


def bay_width_m(window_share: float) -> float:
    """The bay [m] that gives one opening per bay and storey ``window_share`` of the wall.

    >>> bay_width_m(0.25)
    2.4
    """
    return WINDOW_WIDTH_M * WINDOW_HEIGHT_M / window_share / STOREY_M


#: Lever at which a rotation's error is compared with a shift's [m] (weakest direction).
LEVER_M = 10.0


def plane_rows(point_xyz: np.ndarray, normal_xyz: np.ndarray, centre_xyz: np.ndarray) -> np.ndarray:
    """Rows ``a = (n, r × n)`` (P, 6) of patches through ``point_xyz`` (P, 3) [m] with unit
    normals ``normal_xyz`` (P, 3), for a scan centred at ``centre_xyz`` (3,) [m]: the
    point-to-plane residual's change with the scan's shift [mm] and rotation [rad]
    (r in mm).

    Examples
    --------
    A wall facing the scanner 10 m north, its normal pointing back south:

    >>> a = plane_rows(np.array([[0.0, 10.0, 1.5]]), np.array([[0.0, -1.0, 0.0]]), np.zeros(3))
    >>> [round(float(v), 1) + 0.0 for v in a[0]]  # a shift north, a tilt about x (1.5 m)
    [0.0, -1.0, 0.0, 1500.0, 0.0, 0.0]
    """
    n = np.asarray(normal_xyz, dtype=float)
    r = (np.asarray(point_xyz, dtype=float) - np.asarray(centre_xyz, dtype=float)) * 1000.0
    return np.concatenate([n, np.cross(r, n)], axis=-1)


def relief_areas(area_m2: float, window_share: float, reveal_depth_m: float) -> tuple[float, float]:
    """The relief of a facade patch of ``area_m2`` on the parametric facade (module
    docstring): the area of its jambs facing each way along the wall, and of its heads [m²].
    A share s of the wall in openings of w × h, d deep, gives s/(w·h) openings per m², each
    with two jambs of h·d and a head of w·d.

    Examples
    --------
    >>> [round(a, 4) for a in relief_areas(4.0, 0.25, 0.15)]  # a 2 m × 2 m patch
    [0.125, 0.1]
    """
    openings = area_m2 * window_share / (WINDOW_WIDTH_M * WINDOW_HEIGHT_M)
    return openings * WINDOW_HEIGHT_M * reveal_depth_m, openings * WINDOW_WIDTH_M * reveal_depth_m


def relief_words(window_share: float, reveal_depth_m: float) -> str:
    """The relief the cloud links count, in words (every cloud or hybrid plan says it).

    >>> relief_words(0.25, 0.15)[:60]
    'Cloud links count the walls’ relief as a parametric facade: '
    """
    if window_share <= 0 or reveal_depth_m <= 0:
        return "Cloud links count the walls as plain planes (no relief: --window-share 0)."
    return (
        "Cloud links count the walls’ relief as a parametric facade: openings of "
        f"{WINDOW_WIDTH_M:g} × {WINDOW_HEIGHT_M:g} m on {window_share:.0%} of the wall, "
        f"{reveal_depth_m * 1000:.0f} mm deep (--window-share, --reveal-depth-m; 0 for plain "
        "walls: a curtain wall, a blank gable), except on buildings whose model draws its "
        "openings (LoD3)."
    )


def reveal_visible(
    tan_side: np.ndarray, reveal_depth_m: float, width_m: float | np.ndarray
) -> np.ndarray:
    """The share of a jamb a scan sees into an opening of ``width_m`` set ``reveal_depth_m``
    deep, from a direction ``tan_side`` (tan of its angle from the wall's normal, towards
    the jamb's side): ``min(1, w / (d·tan))`` — the near edge hides the rest at grazing
    angles.

    >>> reveal_visible(np.array([0.5, 8.0, 16.0]), 0.15, 1.2).tolist()
    [1.0, 1.0, 0.5]
    """
    with np.errstate(divide="ignore"):
        return np.minimum(1.0, width_m / (reveal_depth_m * np.abs(tan_side)))


def registration_spacing(
    spacing_mm: ArrayLike, cos_incidence: ArrayLike, even_mm: float
) -> tuple[np.ndarray, np.ndarray]:
    """The spacing [mm] of a scan's points on a surface as a registration uses them, along
    the beam's trace and across it: the scan's spacing square to the beam ``spacing_mm``,
    stretched along the trace by 1 / cos θ, and never finer than the even spacing the
    software thins to (``even_mm``).

    >>> [float(v) for v in registration_spacing(20.0, 0.1, 100.0)]
    [200.0, 100.0]
    """
    d = np.asarray(spacing_mm, dtype=float)
    cos = np.clip(np.asarray(cos_incidence, dtype=float), 1e-9, 1.0)
    return np.maximum(d / cos, even_mm), np.maximum(d, even_mm)


def registration_points(
    area_m2: ArrayLike, cos_incidence: ArrayLike, spacing_mm: ArrayLike, even_mm: float
) -> np.ndarray:
    """The points a registration uses on a patch of ``area_m2`` seen at incidence θ with the
    scan's spacing ``spacing_mm`` square to the beam, thinned to ``even_mm`` (module
    docstring): ``A / (along · across)``, at least 1 — and 0 where θ exceeds
    :data:`MAX_LINK_INCIDENCE_DEG` or the points lie in lines farther apart than their
    neighbourhoods reach (along > K / π × across, K the neighbours).

    Examples
    --------
    A 2 m × 2 m patch: square to the beam, at 80° with a fine scan, at 80° with a coarse one.

    >>> registration_points(4.0, [1.0, 0.17, 0.17], [10.0, 10.0, 60.0], 100.0).round(1).tolist()
    [400.0, 400.0, 0.0]
    """
    cos = np.asarray(cos_incidence, dtype=float)
    along, across = registration_spacing(spacing_mm, cos, even_mm)
    pts = np.maximum(np.asarray(area_m2, dtype=float) * 1e6 / (along * across), 1.0)
    usable = (cos >= np.cos(np.radians(MAX_LINK_INCIDENCE_DEG))) & (
        along <= LINK_NEIGHBOURS / np.pi * across
    )
    return np.where(usable, pts, 0.0)


def floor_units(area_m2: ArrayLike) -> np.ndarray:
    """How many independent cells of the floor (:data:`FLOOR_CELL_M`) a patch of
    ``area_m2`` holds.

    >>> float(floor_units(1.0))
    0.25
    """
    return np.asarray(area_m2, dtype=float) / FLOOR_CELL_M**2


def patch_variance_mm2(
    normal_rms_mm: ArrayLike,
    n_points: ArrayLike,
    floor_mm: float | np.ndarray = DEFAULT_CLOUD_FLOOR_MM,
    units: ArrayLike = 1.0,
) -> np.ndarray:
    """Variance [mm²] of a patch's position along its normal in one scan: ``σ²/n`` of its
    points plus its floor's ``floor² / u`` over its ``units`` independent cells.

    Examples
    --------
    >>> float(patch_variance_mm2(3.0, 9.0, 1.0))
    2.0
    >>> float(patch_variance_mm2(3.0, 9.0, 1.0, units=4.0))
    1.25
    """
    sigma = np.asarray(normal_rms_mm, dtype=float)
    floor2 = np.square(floor_mm) / np.asarray(units, dtype=float)
    return np.square(sigma) / np.asarray(n_points, dtype=float) + floor2


def start_information(start_error: tuple[float, float, float]) -> np.ndarray:
    """The prior (6, 6) a link's start puts on its estimate (mm, rad): the inverse of the
    pre-alignment's variance per parameter, ``start_error`` = (position per axis [mm],
    heading [″], tilt per axis [″]) (:attr:`planner.scanner.Scanner.start_error`).

    >>> [f"{v:.3g}" for v in np.diag(start_information((30.0, 360.0, 20.0)))]
    ['0.00111', '0.00111', '0.00111', '1.06e+08', '1.06e+08', '3.28e+05']
    """
    pos, head, tilt = start_error
    rad = np.array([tilt, tilt, head]) / RHO_ARCSEC
    return np.diag(np.concatenate([np.full(3, 1.0 / pos**2), 1.0 / rad**2]))


def link_information(
    rows: np.ndarray, var_parent_mm2: np.ndarray, var_child_mm2: np.ndarray
) -> np.ndarray:
    """The point-to-plane information matrix J (6, 6) of a link over its common patches:
    ``Σ a aᵀ / (v_i + v_j)`` (module docstring); rows from :func:`plane_rows` at the child.

    Examples
    --------
    One wall (normal y) and the ground: the shift along the wall (x) is not fixed.

    >>> pts = np.array([[-5.0, 10, 1], [5, 10, 1], [0, 10, 4], [-3, 3, 0], [3, 3, 0], [0, 6, 0]])
    >>> nrm = np.array([[0, -1.0, 0]] * 3 + [[0, 0, 1.0]] * 3)
    >>> j = link_information(plane_rows(pts, nrm, np.array([0, 0, 1.5])), 1.0, 1.0)
    >>> float(j[0, 0])  # nothing constrains x
    0.0
    """
    a = np.asarray(rows, dtype=float)
    w = 1.0 / (np.broadcast_to(var_parent_mm2, len(a)) + np.broadcast_to(var_child_mm2, len(a)))
    return (a * w[:, None]).T @ a


#: Estimated pose parameters: all six, or (levelled) the shift and the rotation about z.
_LEVELLED = [0, 1, 2, 5]
_TILT = [3, 4]


def link_covariance(
    info: np.ndarray, *, levelled: bool = False, tilt_rms_arcsec: float = 0.0
) -> np.ndarray:
    """The child's pose covariance relative to the parent (6, 6; shift in mm, rotation in
    rad) from the link's information matrix; inf on the diagonal where the surfaces leave
    a parameter free. Levelled: the 4 parameters estimated, the relative tilt of the two
    stations (σ_τ each, per axis) an error of the link (module docstring).

    Examples
    --------
    >>> c = link_covariance(np.diag([1.0, 1, 1, 1e6, 1e6, 1e6]))
    >>> round(float(np.sqrt(c[0, 0])), 3)
    1.0
    """
    info = np.asarray(info, dtype=float)
    par = _LEVELLED if levelled else list(range(6))
    sub = info[np.ix_(par, par)]
    cov = np.zeros((6, 6))
    if not np.isfinite(_condition(sub)):
        cov[par, par] = np.inf
        return cov
    inv = np.linalg.pinv(sub, hermitian=True)
    cov[np.ix_(par, par)] = inv
    if levelled:
        tau2 = 2.0 * (tilt_rms_arcsec / RHO_ARCSEC) ** 2  # two stations' tilts
        m = -inv @ info[np.ix_(par, _TILT)]  # the estimate's response to Δζ
        cov[np.ix_(par, par)] += tau2 * m @ m.T
        cov[np.ix_(par, _TILT)] = tau2 * m
        cov[np.ix_(_TILT, par)] = tau2 * m.T
        cov[np.ix_(_TILT, _TILT)] = tau2 * np.eye(2)
    return cov


#: A scaled information matrix this ill-conditioned leaves a direction free.
MAX_LINK_CONDITION = 1e8


def _condition(info: np.ndarray) -> float:
    diag = np.diag(info)
    if (diag <= 0).any() or not np.isfinite(info).all():
        return np.inf
    d = 1.0 / np.sqrt(diag)
    w = np.abs(np.linalg.eigvalsh(info * d[:, None] * d[None, :]))
    return float(w.max() / w.min()) if w.min() > 0 else np.inf


def link_strength(info: np.ndarray, *, levelled: bool = False) -> tuple[float, float]:
    """The condition number of the estimated parameters' information (diagonal scaled to
    one, so that mm and rad compare; inf when a parameter is free) and its smallest
    eigenvalue [1/mm², a rotation taken at :data:`LEVER_M`].

    Examples
    --------
    >>> link_strength(np.diag([1.0, 1, 1, 1e8, 1e8, 0]))[0]
    inf
    """
    info = np.asarray(info, dtype=float)
    par = _LEVELLED if levelled else list(range(6))
    sub = info[np.ix_(par, par)]
    scale = np.array([1.0 if p < 3 else 1.0 / (LEVER_M * 1000.0) for p in par])
    smallest = float(np.linalg.eigvalsh(sub * scale[:, None] * scale[None, :]).min())
    return _condition(sub), max(smallest, 0.0)


def weakest_direction(cov: np.ndarray) -> str:
    """The direction a link's error is largest in, in words: a shift (bearing from grid
    north, or up/down) or a rotation (about the vertical, or a tilt), comparing a rotation
    at :data:`LEVER_M`.

    Examples
    --------
    >>> weakest_direction(np.diag([1.0, 9.0, 1.0, 0, 0, 0]))
    'shift 000°/180° (north-south), 3.0 mm'
    >>> weakest_direction(np.diag([np.inf, 1.0, 1.0, 0, 0, 0]))
    'free: shift 090°/270° (east-west)'
    """
    cov = np.asarray(cov, dtype=float)
    diag = np.diag(cov)
    if not np.isfinite(diag).all():
        free = int(np.flatnonzero(~np.isfinite(diag))[0])
        return "free: " + _name(free, np.eye(3)[free] if free < 3 else None)
    shift = cov[:3, :3]
    w, v = np.linalg.eigh(shift)
    rot = np.sqrt(np.maximum(diag[3:], 0.0)) * LEVER_M * 1000.0  # mm at the lever
    if rot.max() > np.sqrt(max(w[-1], 0.0)):
        k = 3 + int(np.argmax(rot))
        return f"{_name(k, None)}, {rot.max():.1f} mm at {LEVER_M:g} m"
    return f"{_name(0, v[:, -1])}, {np.sqrt(w[-1]):.1f} mm"


def _name(k: int, vec: np.ndarray | None) -> str:
    if k >= 3:
        return "rotation about the vertical" if k == 5 else "tilt"
    if abs(vec[2]) > np.hypot(vec[0], vec[1]):
        return "shift up-down"
    bearing = float(np.degrees(np.arctan2(vec[0], vec[1]))) % 180.0
    names = ["north-south", "northeast-southwest", "east-west", "southeast-northwest"]
    name = names[int(((bearing + 22.5) % 180) // 45)]
    return f"shift {bearing:03.0f}°/{bearing + 180:03.0f}° ({name})"


def overlap_pct(
    common_parent: ArrayLike,
    total_parent: ArrayLike,
    common_child: ArrayLike,
    total_child: ArrayLike,
) -> np.ndarray:
    """A link's overlap [%]: the smaller share of either scan's surface (area, or points on
    an even spacing) that both hold (module docstring); 0 for a scan that holds nothing.
    Broadcasts (every pair of stations at once).

    Examples
    --------
    >>> float(overlap_pct(300, 1000, 300, 600))
    30.0
    """
    shares = []
    for c, t in ((common_parent, total_parent), (common_child, total_child)):
        c, t = np.asarray(c, dtype=float), np.asarray(t, dtype=float)
        out = np.zeros(np.broadcast_shapes(c.shape, t.shape))
        shares.append(np.divide(c, t, out=out, where=t > 0))  # 0 where t is not
    return 100.0 * np.minimum(*shares)
