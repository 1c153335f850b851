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

from planner.errors import InputError
from planner.pipeline.engine.result import Plan
from planner.pipeline.evaluation.evaluate import Progress
from planner.pipeline.geometry.beams import (
    POINT_KINDS,
    World,
    cast,
    grid,
    measure,
    rotation,
)
from planner.pipeline.geometry.scene import Scene
from planner.units import RHO_ARCSEC

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
#: Bytes per point of the files, for the size said before writing: an E57 scan's point
#: (three single-precision coordinates, an intensity, row and column, as pye57 writes them)
#: and a compressed LAS point (measured on the default site, benchmarks/RESULTS.md).
E57_BYTES_PER_POINT = 19
LAZ_BYTES_PER_POINT = 6
#: Seconds per beam cast and per point written (E57 and LAZ), for the time said before
#: (measured on the default site on two cores, benchmarks/RESULTS.md).
SECONDS_PER_BEAM = 1.4e-6
SECONDS_PER_POINT = 0.9e-6


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
    az, el = grid(step / 1e4, plan.scanner.vertical_fov_deg)
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


def _scan(world: World, sid: str, pos: np.ndarray, rot: np.ndarray,
          rng: np.random.Generator, beams: tuple, noise: bool) -> SimulatedScan:  # fmt: skip
    """One station's simulated scan: the grid's ``beams`` (azimuths, elevations, each
    beam's column and row) cast from ``pos`` turned by ``rot`` into the world
    (:func:`~planner.pipeline.geometry.beams.cast`) and measured with the plan's noise drawn
    from ``rng`` (:func:`~planner.pipeline.geometry.beams.measure`)."""
    ret = cast(world, pos, rot, *beams)
    m = measure(world, ret, pos, rot, rng, noise=noise)
    return SimulatedScan(
        station_id=sid,
        position=pos.copy(),
        rotation=rot,
        local_xyz=m.local_xyz,
        intensity=(ret.reflectance * ret.cos).astype(np.float32),
        rms_mm=m.rms_mm,
        incidence_deg=np.degrees(np.arccos(np.clip(ret.cos, 0.0, 1.0))).astype(np.float32),
        surface=ret.surface,
        kind=ret.kind,
        row=ret.row,
        column=ret.column,
        beams=ret.beams,
    )


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
    sc, st = plan.scanner, plan.settings
    world = World.of(plan.site, sc, st, scene, plan.targets)
    step = grid_step_mm_at_10m(plan, beams_per_station)
    az, el = grid(step / 1e4, sc.vertical_fov_deg)
    col, row = np.meshgrid(np.arange(len(az)), np.arange(len(el)))
    beams = (az, el, col.ravel(), row.ravel())
    tau = sc.datum_tilt_rms_arcsec / RHO_ARCSEC  # a scan stands tilted by what levels it
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
        scans.append(_scan(world, sid, pos, rotation(heading, *tilt), rng, beams, noise))
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
        surfaces=world.surfaces,
        step_mm_at_10m=step,
        preset_step_mm_at_10m=preset,
        seed=seed,
        crs=plan.site.crs,
        notes=notes,
    )
