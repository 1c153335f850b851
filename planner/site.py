"""The site: buildings to plan, obstacles, no-go areas, boundary — validated before any work.

Geometry is shapely 2, in the user's projected metric CRS (metres), kept as given: results
are written back in the same coordinates. Heights are metres above the (flat) ground.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field, replace

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon
from shapely.geometry.base import BaseGeometry

from planner.errors import InputError
from planner.zones import Zone

__all__ = [
    "Area",
    "Building",
    "ControlPoint",
    "Obstacle",
    "Site",
    "SiteLimits",
    "repair_geometry",
]

Polygonal = Polygon | MultiPolygon

#: Overlaps smaller than this are taken as touching (digitising noise) [m²].
OVERLAP_TOLERANCE_M2 = 0.01
#: Consecutive vertices closer than this make a zero-length edge [m].
ZERO_EDGE_M = 1e-3


@dataclass(frozen=True, kw_only=True)
class SiteLimits:
    """What a real site can hold; a site beyond these is refused before any work (most often
    a unit slip: millimetres for metres, degrees for metres). Raise them explicitly for a
    site that really is that large (``--max-building-height-m``, ``--max-site-size-m``).

    Parameters
    ----------
    max_building_height_m : float, default 1000
        The tallest building of the world is 828 m.
    min_building_height_m : float, default 1
        Anything lower is not a building to scan (give it as an obstacle).
    max_building_size_m : float, default 2000
        Largest extent of one footprint (the longest buildings are about 1.5 km).
    max_site_size_m : float, default 50 000
        Largest extent of the whole site.
    """

    max_building_height_m: float = 1000.0
    min_building_height_m: float = 1.0
    max_building_size_m: float = 2000.0
    max_site_size_m: float = 50_000.0

    def __post_init__(self) -> None:
        for name in (
            "max_building_height_m",
            "min_building_height_m",
            "max_building_size_m",
            "max_site_size_m",
        ):
            v = getattr(self, name)
            if (
                isinstance(v, bool)
                or not isinstance(v, int | float)
                or not math.isfinite(v)
                or v <= 0
            ):
                raise InputError(f"{name} must be a number > 0 [m]; got {v!r}")


#: Projected coordinates beyond this are not on Earth in any metric CRS [m].
MAX_COORDINATE_M = 1e8


@dataclass(frozen=True)
class Building:
    """A building: footprint (holes are courtyards) and height [m] above the ground.

    ``planned`` buildings get their facades scanned; the others only block the beam.
    """

    id: str
    footprint: Polygonal
    height_m: float
    planned: bool = True
    name: str = ""


@dataclass(frozen=True)
class Obstacle:
    """Something that blocks the beam and where no station stands: a wall, a tree, a shed."""

    id: str
    geometry: Polygonal
    height_m: float
    kind: str = "obstacle"


@dataclass(frozen=True)
class Area:
    """A no-go area where no station may stand (a road, water)."""

    id: str
    geometry: Polygonal


#: A control point farther than this from every building is not on the site [m].
MAX_CONTROL_DISTANCE_M = 1000.0
#: The RMS of a control point's coordinates when the file does not give one [mm].
DEFAULT_CONTROL_RMS_MM = 2.0


@dataclass(frozen=True)
class ControlPoint:
    """A target with known coordinates (a site network's point): x, y, z [m] in the site's
    CRS and height system, and the RMS of those coordinates [mm] per axis. Stations that see
    three of them are registered to the site network (georeferencing)."""

    id: str
    xyz: tuple[float, float, float]
    rms_mm: float = DEFAULT_CONTROL_RMS_MM

    def __post_init__(self) -> None:
        try:
            xyz = tuple(float(v) for v in self.xyz)
            rms = float(self.rms_mm)
        except (TypeError, ValueError):
            raise InputError(
                f"control point {self.id!r} needs three coordinates and an RMS [m, mm]; got "
                f"{self.xyz!r}, {self.rms_mm!r}"
            ) from None
        if len(xyz) != 3 or not all(math.isfinite(v) for v in xyz):
            raise InputError(
                f"control point {self.id!r} needs finite x, y, z [m] (the height too); "
                f"got {self.xyz!r}"
            )
        if not math.isfinite(rms) or rms <= 0 or rms > 100:
            raise InputError(
                f"control point {self.id!r}: rms_mm must be > 0 and <= 100 [mm]; "
                f"got {self.rms_mm!r}"
            )
        object.__setattr__(self, "xyz", xyz)
        object.__setattr__(self, "rms_mm", rms)


def repair_geometry(geom: BaseGeometry) -> BaseGeometry:
    """The explicit repair offered for bad polygons: drop repeated vertices, then make_valid.

    Only the polygonal part of the result is kept. Never applied silently.
    """
    fixed = shapely.make_valid(shapely.remove_repeated_points(geom, ZERO_EDGE_M))
    polys = [g for g in shapely.get_parts(fixed) if isinstance(g, Polygon) and not g.is_empty]
    if not polys:
        return Polygon()
    return polys[0] if len(polys) == 1 else MultiPolygon(polys)


def _where(what: str, ident: str) -> str:
    return f"{what} {ident!r}"


def _check_kind(geom: BaseGeometry, who: str) -> None:
    if geom is not None and not isinstance(geom, BaseGeometry):
        raise InputError(
            f"{who} has a {type(geom).__name__} where a shapely Polygon is expected "
            "(e.g. shapely.box(x0, y0, x1, y1) or shapely.Polygon([(x, y), ...]))"
        )
    if geom is None or geom.is_empty:
        raise InputError(f"{who} has an empty geometry; remove the feature or draw its outline")
    if not isinstance(geom, Polygon | MultiPolygon):
        hint = (
            " (buffer a wall line by half its thickness)" if geom.geom_type == "LineString" else ""
        )
        raise InputError(f"{who} is a {geom.geom_type}; it must be a Polygon or MultiPolygon{hint}")
    coords = shapely.get_coordinates(geom)
    if not np.isfinite(coords).all():
        raise InputError(f"{who} has coordinates that are not finite numbers (NaN or infinity)")


def _check_shape(geom: BaseGeometry, who: str) -> None:
    for ring in _rings(geom):
        xy = np.asarray(ring.coords)[:, :2]
        step = np.hypot(*np.diff(xy, axis=0).T)
        bad = np.flatnonzero(step < ZERO_EDGE_M)
        if bad.size:
            x, y = xy[bad[0]]
            raise InputError(
                f"{who} has a zero-length edge (a repeated vertex) at ({x:.3f}, {y:.3f}); "
                "remove the duplicate vertex, or repair the geometry explicitly "
                "(repair=True, --make-valid)"
            )
    if not geom.is_valid:
        reason = shapely.is_valid_reason(geom)
        raise InputError(
            f"{who} is not a valid polygon: {reason}; fix the outline in your CAD/GIS, or repair "
            "it explicitly with make_valid (repair=True, --make-valid)"
        )


def _rings(geom: Polygonal) -> Iterable:
    for poly in shapely.get_parts(geom):
        yield poly.exterior
        yield from poly.interiors


def _check_height(h: float, who: str, lo: float, hi: float) -> float:
    """A height [m] in (0, hi], at least ``lo``; a bool or a text that is not a number is
    refused (``true`` is not a height)."""
    if isinstance(h, bool):
        raise InputError(f"{who} has height {h!r}; give the height in metres as a number")
    try:
        v = float(h)
    except (TypeError, ValueError):
        raise InputError(f"{who} has height {h!r}; give the height in metres as a number") from None
    if not math.isfinite(v) or v <= 0:
        raise InputError(f"{who} has height {h!r}; it must be a number > 0 [m]")
    if v > hi:
        raise InputError(
            f"{who} has height {v:g} m, higher than any building ({hi:g} m); check the unit "
            "(heights are metres), or raise the limit if it is real (--max-building-height-m)"
        )
    if v < lo:
        raise InputError(
            f"{who} has height {v:g} m, lower than a building to scan ({lo:g} m); check the "
            "unit (heights are metres), or give it as an obstacle (role obstacle)"
        )
    return v


def _check_extent(
    geoms: Sequence[tuple[BaseGeometry, str]], buildings: Sequence[Building], limits: SiteLimits
) -> None:
    """Coordinates on Earth, footprints and the site no larger than a real one."""
    for geom, who in geoms:
        x0, y0, x1, y1 = geom.bounds
        if max(abs(x0), abs(y0), abs(x1), abs(y1)) > MAX_COORDINATE_M:
            raise InputError(
                f"{who} has coordinates of {max(abs(x0), abs(y0), abs(x1), abs(y1)):.3g}, "
                "beyond any projected CRS in metres; check the file's coordinates and CRS"
            )
    for b in buildings:
        x0, y0, x1, y1 = b.footprint.bounds
        if max(x1 - x0, y1 - y0) > limits.max_building_size_m:
            raise InputError(
                f"building {b.id!r} is {max(x1 - x0, y1 - y0):.0f} m across, larger than a real "
                f"building ({limits.max_building_size_m:g} m); check the unit (coordinates are "
                "metres), or raise the limit if it is real (--max-building-size-m)"
            )
    bounds = np.array([g.bounds for g, _ in geoms])
    size = max(bounds[:, 2].max() - bounds[:, 0].min(), bounds[:, 3].max() - bounds[:, 1].min())
    if size > limits.max_site_size_m:
        raise InputError(
            f"the site is {size / 1000:.1f} km across, more than {limits.max_site_size_m:g} m; "
            "check the coordinates, plan it in parts, or raise the limit (--max-site-size-m)"
        )


def _looks_like_degrees(geoms: Sequence[BaseGeometry]) -> bool:
    """Lon/lat degrees: all coordinates in range and every outline smaller than 1 cm."""
    coords = shapely.get_coordinates(list(geoms))
    if not len(coords):
        return False
    in_range = (np.abs(coords[:, 0]) <= 180).all() and (np.abs(coords[:, 1]) <= 90).all()
    if not in_range:
        return False
    sizes = [max(g.bounds[2] - g.bounds[0], g.bounds[3] - g.bounds[1]) for g in geoms]
    return max(sizes) < 0.01


@dataclass
class Site:
    """Buildings (planned or not), obstacles, no-go areas and an optional boundary.

    Construction validates everything and raises :class:`InputError` naming the feature
    and the fix: empty or invalid polygons, zero-length edges, bad heights, coordinates that
    look like longitude/latitude, duplicate ids, obstacles overlapping buildings, buildings
    overlapping each other, no building to plan, a boundary that does not hold them.
    """

    buildings: list[Building]
    obstacles: list[Obstacle] = field(default_factory=list)
    no_go: list[Area] = field(default_factory=list)
    boundary: Polygonal | None = None
    crs: str | None = None
    name: str = "site"
    warnings: list[str] = field(default_factory=list)
    limits: SiteLimits = field(default_factory=SiteLimits)
    control: list[ControlPoint] = field(default_factory=list)
    zones: list[Zone] = field(default_factory=list)

    def __post_init__(self) -> None:
        for name, kind in (
            ("buildings", Building),
            ("obstacles", Obstacle),
            ("no_go", Area),
            ("control", ControlPoint),
            ("zones", Zone),
        ):
            items = getattr(self, name)
            if isinstance(items, str | bytes) or not hasattr(items, "__iter__"):
                raise InputError(
                    f"Site {name} must be a list of {kind.__name__}; got {items!r}"[:160]
                )
            bad = [i for i in items if not isinstance(i, kind)]
            if bad:
                raise InputError(
                    f"Site {name} must hold {kind.__name__} objects; got "
                    f"{type(bad[0]).__name__} {bad[0]!r}"[:200]
                )
        self.buildings = list(self.buildings)
        self.control = list(self.control)
        ids = [c.id for c in self.control]
        if len(set(ids)) != len(ids):
            raise InputError("control point ids must be unique; one appears twice")
        self.obstacles = list(self.obstacles)
        self.no_go = list(self.no_go)
        seen: set[str] = set()
        named = [(b.footprint, _where("building", b.id)) for b in self.buildings]
        named += [(o.geometry, _where(o.kind, o.id)) for o in self.obstacles]
        named += [(a.geometry, _where("no-go area", a.id)) for a in self.no_go]
        if self.boundary is not None:
            named.append((self.boundary, "the site boundary"))
        for geom, who in named:
            _check_kind(geom, who)
        _check_extent(named, self.buildings, self.limits)
        lim = self.limits
        for b in self.buildings:
            if b.id in seen:
                raise InputError(f"building {b.id!r} appears twice; building ids must be unique")
            seen.add(b.id)
            h = _check_height(
                b.height_m,
                _where("building", b.id),
                lim.min_building_height_m,
                lim.max_building_height_m,
            )
            object.__setattr__(b, "height_m", h)
        for o in self.obstacles:
            h = _check_height(o.height_m, _where(o.kind, o.id), 0.0, lim.max_building_height_m)
            object.__setattr__(o, "height_m", h)
        everything = [b.footprint for b in self.buildings] + [o.geometry for o in self.obstacles]
        if _looks_like_degrees(everything):
            raise InputError(
                "the coordinates look like longitude/latitude degrees (every outline is smaller "
                "than 0.01 units); say so with --crs EPSG:4326 (they are then projected to their "
                "UTM zone), or reproject the file to a projected CRS"
            )
        for geom, who in named:
            _check_shape(geom, who)
        if not any(b.planned for b in self.buildings):
            raise InputError(
                "the site has no building to plan; add a building footprint with role "
                "'building', or choose buildings to plan (--buildings ID,ID)"
            )
        self._check_overlaps()
        self._check_control()
        self._check_zones()

    def _check_zones(self) -> None:
        """Zone ids unique; each on a building of the site (a facade id names its building:
        ``<building>-f<NN>``)."""
        self.zones = list(self.zones)
        ids = [z.id for z in self.zones]
        dup = sorted({i for i in ids if ids.count(i) > 1})
        if dup:
            raise InputError(f"zone id {dup[0]!r} appears twice; zone ids must be unique")
        known = {b.id for b in self.buildings}
        for z in self.zones:
            bid = z.building_id or (z.facade_id or "").rsplit("-f", 1)[0]
            if bid not in known:
                where = z.building_id or z.facade_id
                raise InputError(
                    f"zone {z.id!r} is on {where!r}, which is not a building (or a facade "
                    f"<building>-f<NN>) of the site; buildings: {', '.join(sorted(known)[:20])}"
                )

    def _check_control(self) -> None:
        """Control points must be on the site: not inside a building, not kilometres away
        (most often another CRS or swapped x, y)."""
        if not self.control:
            return
        foot = shapely.union_all([b.footprint for b in self.buildings])
        for c in self.control:
            p = shapely.Point(c.xyz[:2])
            d = float(foot.distance(p))
            if d > MAX_CONTROL_DISTANCE_M:
                raise InputError(
                    f"control point {c.id!r} is {d:,.0f} m from the nearest building; control "
                    "points must be given in the site's CRS (is it another CRS, or are x and "
                    "y swapped?)"
                )
            inside = [b.id for b in self.buildings if b.footprint.buffer(-0.05).contains(p)]
            if inside:
                raise InputError(
                    f"control point {c.id!r} is inside building {inside[0]!r}; a scanner "
                    "must see it: give the point where it stands on open ground or on a wall"
                )

    def _check_overlaps(self) -> None:
        foot = [b.footprint for b in self.buildings]
        tree = shapely.STRtree(foot)
        pairs = tree.query(foot, predicate="intersects")
        for i, j in pairs.T:
            if i < j:
                area = shapely.intersection(foot[i], foot[j]).area
                if area > OVERLAP_TOLERANCE_M2:
                    a, b = self.buildings[i].id, self.buildings[j].id
                    raise InputError(
                        f"buildings {a!r} and {b!r} overlap by {area:.2f} m²; buildings may "
                        "share walls but not ground: fix the outlines or remove the duplicate"
                    )
        if self.obstacles:
            obs = [o.geometry for o in self.obstacles]
            for i, j in tree.query(obs, predicate="intersects").T:
                area = shapely.intersection(obs[i], foot[j]).area
                if area > OVERLAP_TOLERANCE_M2:
                    o, b = self.obstacles[i], self.buildings[j]
                    raise InputError(
                        f"{o.kind} {o.id!r} overlaps building {b.id!r} by {area:.2f} m²; "
                        "clip the obstacle to the building's outline, or make it part of "
                        "the building"
                    )
        if self.boundary is not None:
            for b in self.planned:
                if not shapely.covers(self.boundary.buffer(1e-6), b.footprint):
                    raise InputError(
                        f"building {b.id!r} is not inside the site boundary; enlarge the "
                        "boundary or leave the building out of the plan"
                    )

    # -- views ----------------------------------------------------------------------------
    @property
    def planned(self) -> list[Building]:
        """The buildings whose facades are to be scanned."""
        return [b for b in self.buildings if b.planned]

    @property
    def blockers(self) -> list[tuple[str, Polygonal, float]]:
        """Everything that blocks the beam: ``(id, polygon, height_m)`` of every building
        (planned or not) and every obstacle."""
        out = [(b.id, b.footprint, b.height_m) for b in self.buildings]
        out += [(o.id, o.geometry, o.height_m) for o in self.obstacles]
        return out

    def select(self, building_ids: Sequence[str] | None) -> Site:
        """The same site planning only ``building_ids`` (the others act as obstacles)."""
        if building_ids is None:
            return self
        wanted = [str(i) for i in building_ids]
        known = {b.id for b in self.buildings}
        missing = [i for i in wanted if i not in known]
        if missing:
            shown = ", ".join(sorted(known)[:20]) + (" …" if len(known) > 20 else "")
            raise InputError(
                f"no building with id {', '.join(map(repr, missing))}; ids are: {shown}"
            )
        chosen = set(wanted)
        return replace(
            self,
            buildings=[replace(b, planned=b.id in chosen) for b in self.buildings],
            warnings=list(self.warnings),
        )
