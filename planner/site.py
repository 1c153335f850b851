"""The site: buildings to plan, obstacles, no-go areas, boundary — validated before any work.

Geometry is shapely 2, in the user's projected metric CRS (metres), kept as given: results
are written back in the same coordinates. Heights are metres in the site's height system
(:attr:`Site.height_datum`): above the flat ground at height 0 for a site drawn as
footprints, the model's (or the terrain model's) vertical datum for a 3-D city model or a
site given a terrain (:attr:`Site.terrain`). A building drawn as a footprint stands on its
``base_z`` (None: the lowest ground under it) and is ``height_m`` high; a building from a
3-D model also carries its surfaces (:class:`~planner.citymodel.Surface`).
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon
from shapely.geometry.base import BaseGeometry

from planner.citymodel import Surface
from planner.errors import InputError
from planner.ranges import RANGES
from planner.sitecheck import CLIP_SHARE, SiteNote, SiteProblem, SiteProblems, near_mask
from planner.terrain import Terrain
from planner.text import printable
from planner.zones import Zone

__all__ = [
    "Area",
    "Building",
    "ControlPoint",
    "Obstacle",
    "Passage",
    "Site",
    "SiteLimits",
    "repair_geometry",
    "with_terrain",
]

Polygonal = Polygon | MultiPolygon

#: Overlaps smaller than this are taken as touching (digitising noise) [m²].
OVERLAP_TOLERANCE_M2 = 0.01
#: Consecutive vertices closer than this make a zero-length edge [m].
ZERO_EDGE_M = 1e-3
#: A ring with more vertices than this is thinned (:meth:`Site._thinned`): no building's
#: outline drawn for a survey needs more (a 200 m round tower at 0.3 m edges has 2 100).
DENSE_RING_VERTICES = 5000
#: How far a thinned outline may move from the one given [m].
THIN_TOLERANCE_M = 0.01


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
    """A building: footprint (holes are courtyards) and height [m] above its base.

    ``planned`` buildings get their facades scanned; the others only block the beam.
    ``base_z`` is the height of its ground [m] in the site's height system (None: the
    lowest ground under it — 0 on flat ground); ``surfaces`` its 3-D surfaces where a city
    model gives them (then the facades are its walls as they are, and the footprint its
    ground outline), else it is the footprint extruded to ``height_m``. ``material``: what
    its walls are made of, as its source names it (:mod:`planner.materials`; "" unknown).
    """

    id: str
    footprint: Polygonal
    height_m: float
    planned: bool = True
    name: str = ""
    base_z: float | None = None
    surfaces: tuple[Surface, ...] = field(default=(), compare=False, repr=False)
    material: str = ""

    @property
    def is_3d(self) -> bool:
        """Whether the building has 3-D surfaces (from a city model)."""
        return bool(self.surfaces)

    @property
    def top_z(self) -> float:
        """The building's highest point [m] in the site's height system."""
        return (self.base_z or 0.0) + self.height_m


@dataclass(frozen=True)
class Obstacle:
    """Something that blocks the beam and where no station stands: a wall, a tree, a shed.

    Drawn as an outline with a height, it blocks as a prism from the ground up; a tree with
    a ``crown_base_m`` (> 0) as a trunk up to it and a crown above it; one from a city model
    as its own ``mesh`` (T, 3, 3) [m], the outline being where no station stands.
    """

    id: str
    geometry: Polygonal
    height_m: float
    kind: str = "obstacle"
    crown_base_m: float = 0.0
    mesh: np.ndarray | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class Area:
    """A no-go area where no station may stand (a road, water)."""

    id: str
    geometry: Polygonal


#: Clear height of a passage whose file gives none [m]: a gateway for carts and cars.
DEFAULT_PASSAGE_HEIGHT_M = 3.0
#: Width of a passage drawn as a line [m].
DEFAULT_PASSAGE_WIDTH_M = 3.0


@dataclass(frozen=True)
class Passage:
    """A way through a building at ground level — a gateway into a courtyard, which
    footprints alone do not show (OpenStreetMap: ``tunnel=building_passage``). Below
    ``clear_height_m`` the building is open there: sight lines pass under the floors above,
    stations and targets may stand in it (clear of its walls), the walk goes through, and
    the openings are not facade to scan."""

    id: str
    geometry: Polygonal
    clear_height_m: float = DEFAULT_PASSAGE_HEIGHT_M

    @classmethod
    def along(
        cls,
        id: str,
        line: BaseGeometry,
        width_m: float = DEFAULT_PASSAGE_WIDTH_M,
        clear_height_m: float = DEFAULT_PASSAGE_HEIGHT_M,
    ) -> Passage:
        """A passage drawn as a line through the building, ``width_m`` wide (square ends:
        it stops where the line does).

        >>> Passage.along("G1", shapely.LineString([(0, 0), (10, 0)]), 4.0).geometry.bounds
        (0.0, -2.0, 10.0, 2.0)
        """
        geom = line.buffer(width_m / 2.0, cap_style="flat", join_style="mitre")
        return cls(id, geom, clear_height_m)


#: A tree given without its crown's diameter has a crown this wide [m], starting at this
#: share of its height (the site file's trees and a city model's).
DEFAULT_CROWN_M = 5.0
CROWN_BASE_SHARE = 0.35

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
        rms = RANGES["control_rms_mm"].check(rms, f"control point {self.id!r}: rms_mm")
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


def _usable(geom: Any) -> bool:
    return isinstance(geom, Polygon | MultiPolygon) and not geom.is_empty


def _polygonal_part(geom: BaseGeometry) -> Polygonal:
    """The polygons of an overlay's result (lines and points where outlines touch go)."""
    polys = [g for g in shapely.get_parts(geom) if isinstance(g, Polygon) and not g.is_empty]
    if not polys:
        return Polygon()
    return polys[0] if len(polys) == 1 else MultiPolygon(polys)


def _free_id(ident: str, taken: dict[str, bool]) -> str:
    """``ident`` with the first suffix ``-2``, ``-3``… not yet taken."""
    k = 2
    while f"{ident}-{k}" in taken:
        k += 1
    return f"{ident}-{k}"


#: The fix offered for an outline that is not a valid polygon.
OUTLINE_FIX = (
    "fix the outline in your CAD/GIS, or repair it explicitly with make_valid (repair=True, "
    "--make-valid)"
)


def _kind_problem(geom: BaseGeometry, who: str, ident: str) -> SiteProblem | None:
    """A geometry that is not a usable polygon (None, empty, another type, NaN)."""
    if geom is not None and not isinstance(geom, BaseGeometry):
        return SiteProblem(
            "geometry",
            (ident,),
            f"{who} has a {type(geom).__name__} where a shapely Polygon is expected",
            "e.g. shapely.box(x0, y0, x1, y1) or shapely.Polygon([(x, y), ...])",
        )
    if geom is None or geom.is_empty:
        return SiteProblem(
            "geometry", (ident,), f"{who} has an empty geometry", "remove it or draw its outline"
        )
    if not isinstance(geom, Polygon | MultiPolygon):
        hint = "buffer a wall line by half its thickness" if geom.geom_type == "LineString" else ""
        return SiteProblem(
            "geometry", (ident,), f"{who} is a {geom.geom_type}; it must be a Polygon", hint
        )
    if not np.isfinite(shapely.get_coordinates(geom)).all():
        return SiteProblem(
            "geometry",
            (ident,),
            f"{who} has coordinates that are not finite numbers (NaN or infinity)",
            "fix its coordinates",
        )
    return None


def _shape_problem(geom: BaseGeometry, who: str, ident: str) -> SiteProblem | None:
    """A zero-length edge (a repeated vertex) or an invalid polygon."""
    for ring in _rings(geom):
        xy = np.asarray(ring.coords)[:, :2]
        step = np.hypot(*np.diff(xy, axis=0).T)
        bad = np.flatnonzero(step < ZERO_EDGE_M)
        if bad.size:
            x, y = xy[bad[0]]
            return SiteProblem(
                "edge",
                (ident,),
                f"{who} has a zero-length edge (a repeated vertex) at ({x:.3f}, {y:.3f})",
                "remove the duplicate vertex, or repair the geometry explicitly "
                "(repair=True, --make-valid)",
            )
    if not geom.is_valid:
        return SiteProblem(
            "outline",
            (ident,),
            f"{who} is not a valid polygon: {shapely.is_valid_reason(geom)}",
            OUTLINE_FIX,
        )
    return None


def _rings(geom: Polygonal) -> Iterable:
    for poly in shapely.get_parts(geom):
        yield poly.exterior
        yield from poly.interiors


def _height_problem(h: float, who: str, ident: str, lo: float, hi: float) -> SiteProblem | str:
    """A height [m] in (0, hi], at least ``lo``, as a float; or the problem (a bool or a
    text that is not a number is refused: ``true`` is not a height)."""
    number = "give the height in metres as a number"
    if isinstance(h, bool):
        return SiteProblem("height", (ident,), f"{who} has height {h!r}", number)
    try:
        v = float(h)
    except (TypeError, ValueError):
        return SiteProblem("height", (ident,), f"{who} has height {h!r}", number)
    if not math.isfinite(v) or v <= 0:
        return SiteProblem(
            "height", (ident,), f"{who} has height {h!r}", "it must be a number > 0 [m]"
        )
    if v > hi:
        return SiteProblem(
            "height",
            (ident,),
            f"{who} has height {v:g} m, higher than any building ({hi:g} m)",
            "check the unit (heights are metres), or raise the limit if it is real "
            "(--max-building-height-m)",
        )
    if v < lo:
        return SiteProblem(
            "height",
            (ident,),
            f"{who} has height {v:g} m, lower than a building to scan ({lo:g} m)",
            "check the unit (heights are metres), or give it as an obstacle (role obstacle)",
        )
    return v


def _largest_coordinate(geom: BaseGeometry) -> float:
    x0, y0, x1, y1 = geom.bounds
    return max(abs(x0), abs(y0), abs(x1), abs(y1))


def _beyond_any_crs(geom: BaseGeometry) -> bool:
    return _largest_coordinate(geom) > MAX_COORDINATE_M


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


#: Problems in features farther than this from every building to plan do not stop the plan
#: (:mod:`planner.sitecheck`) [m]; the plan command sets it to its search radius.
DEFAULT_NEAR_M = 150.0
#: Height given to a building far from the planned ones whose height is missing or not a
#: building's: it blocks no sight line the plan needs [m].
FAR_HEIGHT_M = 10.0


def _printable_ids(items: Iterable[Any]) -> list[Any]:
    """The features with their ids and names as :func:`planner.text.printable` shows them
    (a control character in an id is escaped once here, so every output shows the same id)."""
    out = []
    for item in items:
        names = {
            k: printable(v)
            for k in ("id", "name", "building_id", "facade_id")
            if isinstance(v := getattr(item, k, None), str) and printable(v) != v
        }
        out.append(replace(item, **names) if names else item)
    return out


@dataclass
class Site:
    """Buildings (planned or not), obstacles, no-go areas and an optional boundary.

    Construction validates everything and raises :class:`~planner.sitecheck.SiteProblems`
    (an :class:`InputError`) naming every problem at once, each feature and the fix: empty
    or invalid polygons, zero-length edges, bad heights, coordinates that look like
    longitude/latitude, duplicate ids, obstacles overlapping buildings, buildings
    overlapping each other, no building to plan, a boundary that does not hold them.
    A problem only in features farther than ``near_m`` from every planned building cannot
    change the plan: the feature is repaired (make_valid), given a height, renamed or left
    out, and that is noted in ``notes`` (:class:`~planner.sitecheck.SiteNote`) instead.

    ``terrain`` (:class:`~planner.terrain.Terrain`) gives the ground's heights (None: flat
    ground at 0); ``height_datum`` says in words what the heights are measured from (the
    model's or the terrain's vertical datum). A building without a ``base_z`` stands on
    the lowest ground under its footprint.
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
    notes: list[SiteNote] = field(default_factory=list)
    near_m: float = DEFAULT_NEAR_M
    passages: list[Passage] = field(default_factory=list)
    terrain: Terrain | None = None
    height_datum: str = ""

    def __post_init__(self) -> None:
        for name, kind in (
            ("buildings", Building),
            ("obstacles", Obstacle),
            ("no_go", Area),
            ("control", ControlPoint),
            ("zones", Zone),
            ("notes", SiteNote),
            ("passages", Passage),
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
        if not (isinstance(self.near_m, int | float) and self.near_m >= 0):
            raise InputError(f"near_m must be a distance >= 0 [m]; got {self.near_m!r}")
        self.buildings = _printable_ids(self.buildings)
        self.control = _printable_ids(self.control)
        self.obstacles = _printable_ids(self.obstacles)
        self.no_go = _printable_ids(self.no_go)
        self.notes = list(self.notes)
        self.passages = _printable_ids(self.passages)
        self.zones = _printable_ids(self.zones)
        self.name = printable(str(self.name))
        problems: list[SiteProblem] = []
        any_planned = any(b.planned for b in self.buildings)
        self._check_features(problems)
        if problems and problems[-1].kind == "site":  # degrees: nothing else is meaningful
            raise SiteProblems(problems[-1:])
        if not any_planned:
            problems.append(
                SiteProblem(
                    "site",
                    (),
                    "the site has no building to plan",
                    "add a building footprint with role 'building', or choose buildings to "
                    "plan (--buildings ID,ID)",
                )
            )
        self._check_overlaps(problems)
        problems += self._check_control()
        problems += self._check_zones()
        problems += self._check_passages()
        if problems:
            raise SiteProblems(problems)
        self._settle_bases()

    def _settle_bases(self) -> None:
        """Every building's ``base_z``: given, else the lowest ground under its outline
        (0 on flat ground)."""
        for b in self.buildings:
            z = self.ground_under(b.footprint) if b.base_z is None else b.base_z
            object.__setattr__(b, "base_z", float(z))

    @property
    def height_system(self) -> str:
        """What the heights of the plan are measured from, in words."""
        if self.height_datum:
            return self.height_datum
        if self.terrain is not None:
            return f"the heights of the {self.terrain.source}"
        return "metres above the ground (flat ground at height 0)"

    @property
    def is_3d(self) -> bool:
        """Whether the site is more than footprints on flat ground: 3-D buildings, a
        terrain, trees with crowns or obstacles given as meshes."""
        return (
            self.terrain is not None
            or any(b.surfaces for b in self.buildings)
            or any(o.mesh is not None or o.crown_base_m > 0 for o in self.obstacles)
        )

    # -- validation ---------------------------------------------------------------------------
    def _note(self, note: SiteNote) -> None:
        if all(n.key != note.key for n in self.notes):
            self.notes.append(note)

    def _height(
        self, h: float | SiteProblem, ident: str, is_near: bool, problems: list[SiteProblem]
    ) -> float | None:
        """A checked height (:func:`_height_problem`); a problem of a feature near the
        planned buildings is collected (None), a far one's noted and
        :data:`FAR_HEIGHT_M` taken."""
        if not isinstance(h, SiteProblem):
            return h
        if is_near:
            problems.append(h)
            return None
        self._note(SiteNote("height", (ident,), "far", f"{h.text}; {FAR_HEIGHT_M:g} m taken"))
        return FAR_HEIGHT_M

    def _near(self, geoms: Sequence[BaseGeometry | None]) -> np.ndarray:
        planned = [b.footprint for b in self.buildings if b.planned and _usable(b.footprint)]
        return near_mask(planned, geoms, self.near_m)

    def _thinned(self, item: Any, attr: str) -> Any:
        """``item`` with its outline thinned where a ring has more than
        :data:`DENSE_RING_VERTICES` vertices: vertices within :data:`THIN_TOLERANCE_M` of
        the simplified line dropped (Douglas & Peucker, "Algorithms for the reduction of the
        number of points required to represent a digitized line or its caricature", The
        Canadian Cartographer 10(2), 1973, https://doi.org/10.3138/FM57-6770-U75U-7727), and
        noted. A densified or traced outline otherwise makes a facade of every millimetre
        edge, and the plan's time and files grow with them."""
        geom = getattr(item, attr)
        counts = [len(r.coords) for r in _rings(geom)]
        if max(counts, default=0) <= DENSE_RING_VERTICES:
            return item
        thin = shapely.simplify(geom, THIN_TOLERANCE_M, preserve_topology=True)
        if not _usable(thin) or not thin.is_valid:
            return item  # the shape checks say what is wrong with it
        after = sum(len(r.coords) for r in _rings(thin))
        self._note(
            SiteNote(
                "outline",
                (item.id,),
                "thinned",
                f"{sum(counts):,} vertices to {after:,}, within {100 * THIN_TOLERANCE_M:g} cm",
            )
        )
        return replace(item, **{attr: thin})

    def _check_features(self, problems: list[SiteProblem]) -> None:
        """Every feature on its own: geometry, extent, id, height, outline. A problem far
        from the planned buildings is repaired (or the feature left out) and noted."""
        lim = self.limits
        b_near = self._near([b.footprint for b in self.buildings]) | np.array(
            [b.planned for b in self.buildings], dtype=bool
        )
        o_near = self._near([o.geometry for o in self.obstacles])
        a_near = self._near([a.geometry for a in self.no_go])

        def keep(items: list, near: np.ndarray, what: Callable[[Any], str], geom_of, ident_of):
            """The items whose geometry is usable; far ones that are not are noted and left."""
            out, flags = [], []
            for item, is_near in zip(items, near, strict=True):
                who, ident, geom = what(item), ident_of(item), geom_of(item)
                p = _kind_problem(geom, who, ident)
                if p is None and _beyond_any_crs(geom):
                    p = SiteProblem(
                        "extent",
                        (ident,),
                        f"{who} has coordinates of {_largest_coordinate(geom):.3g}, beyond any "
                        "projected CRS in metres",
                        "check the file's coordinates and CRS",
                    )
                    problems.append(p)  # the whole file is in another unit or CRS
                    continue
                if p is not None and is_near:
                    problems.append(p)
                    continue
                if p is not None:
                    self._note(SiteNote("geometry", (ident,), "dropped", p.text))
                    continue
                out.append(item)
                flags.append(bool(is_near))
            return out, np.array(flags, dtype=bool)

        self.buildings, b_near = keep(
            self.buildings,
            b_near,
            lambda b: _where("building", b.id),
            lambda b: b.footprint,
            lambda b: b.id,
        )
        self.obstacles, o_near = keep(
            self.obstacles,
            o_near,
            lambda o: _where(o.kind, o.id),
            lambda o: o.geometry,
            lambda o: o.id,
        )
        self.no_go, a_near = keep(
            self.no_go,
            a_near,
            lambda a: _where("no-go area", a.id),
            lambda a: a.geometry,
            lambda a: a.id,
        )
        if self.boundary is not None:
            p = _kind_problem(self.boundary, "the site boundary", "boundary")
            if p is not None:
                problems.append(p)
                self.boundary = None
        self.buildings = [self._thinned(b, "footprint") for b in self.buildings]
        self.obstacles = [self._thinned(o, "geometry") for o in self.obstacles]
        self.no_go = [self._thinned(a, "geometry") for a in self.no_go]
        everything = [b.footprint for b in self.buildings] + [o.geometry for o in self.obstacles]
        if everything and _looks_like_degrees(everything):
            problems.append(
                SiteProblem(
                    "site",
                    (),
                    "the coordinates look like longitude/latitude degrees (every outline is "
                    "smaller than 0.01 units)",
                    "say so with --crs EPSG:4326 (they are then projected to their UTM zone), "
                    "or reproject the file to a projected CRS",
                )
            )
            return
        # building size, ids, heights
        kept, near_kept = [], []
        seen: dict[str, bool] = {}
        for b, is_near in zip(self.buildings, b_near, strict=True):
            x0, y0, x1, y1 = b.footprint.bounds
            size = max(x1 - x0, y1 - y0)
            if size > lim.max_building_size_m:
                text = (
                    f"building {b.id!r} is {size:.0f} m across, larger than a real building "
                    f"({lim.max_building_size_m:g} m)"
                )
                if is_near:
                    problems.append(
                        SiteProblem(
                            "extent",
                            (b.id,),
                            text,
                            "check the unit (coordinates are metres), or raise the limit if "
                            "it is real (--max-building-size-m)",
                        )
                    )
                else:
                    self._note(SiteNote("extent", (b.id,), "dropped", text))
                continue
            if b.id in seen:
                if is_near or seen[b.id]:
                    problems.append(
                        SiteProblem(
                            "id",
                            (b.id,),
                            f"building {b.id!r} appears twice",
                            "building ids must be unique",
                        )
                    )
                    continue
                new_id = _free_id(b.id, seen)
                self._note(SiteNote("id", (b.id,), "renamed", f"the second {b.id!r} is {new_id!r}"))
                b = replace(b, id=new_id)
            seen[b.id] = bool(is_near)
            h = self._height(
                _height_problem(
                    b.height_m,
                    _where("building", b.id),
                    b.id,
                    lim.min_building_height_m,
                    lim.max_building_height_m,
                ),
                b.id,
                is_near,
                problems,
            )
            if h is None:
                continue
            object.__setattr__(b, "height_m", h)
            kept.append(b)
            near_kept.append(is_near)
        self.buildings = kept
        for o, is_near in zip(self.obstacles, o_near, strict=True):
            h = self._height(
                _height_problem(
                    o.height_m, _where(o.kind, o.id), o.id, 0.0, lim.max_building_height_m
                ),
                o.id,
                is_near,
                problems,
            )
            if h is None:
                continue
            object.__setattr__(o, "height_m", h)
        # outlines: far ones repaired
        for items, near, attr, label in (
            (self.buildings, near_kept, "footprint", lambda b: _where("building", b.id)),
            (self.obstacles, o_near, "geometry", lambda o: _where(o.kind, o.id)),
            (self.no_go, a_near, "geometry", lambda a: _where("no-go area", a.id)),
        ):
            for k, (item, is_near) in enumerate(zip(items, near, strict=True)):
                geom = getattr(item, attr)
                p = _shape_problem(geom, label(item), item.id)
                if p is None:
                    continue
                if is_near:
                    problems.append(p)
                    continue
                fixed = repair_geometry(geom)
                self._note(SiteNote(p.kind, (item.id,), "far", p.text))
                items[k] = self._thinned(replace(item, **{attr: fixed}), attr)  # valid now
        empty = [b.id for b in self.buildings if b.footprint.is_empty]
        self.buildings = [b for b in self.buildings if not b.footprint.is_empty]
        self.obstacles = [o for o in self.obstacles if not o.geometry.is_empty]
        self.no_go = [a for a in self.no_go if not a.geometry.is_empty]
        for i in empty:
            self._note(SiteNote("geometry", (i,), "dropped", "nothing was left of it"))
        if self.boundary is not None:
            p = _shape_problem(self.boundary, "the site boundary", "boundary")
            if p is not None:
                problems.append(p)
        named = [(b.footprint, b.id) for b in self.buildings]
        named += [(o.geometry, o.id) for o in self.obstacles]
        if self.boundary is not None:
            named.append((self.boundary, "boundary"))
        if named:
            bounds = np.array([g.bounds for g, _ in named])
            size = max(
                bounds[:, 2].max() - bounds[:, 0].min(), bounds[:, 3].max() - bounds[:, 1].min()
            )
            if size > lim.max_site_size_m:
                problems.append(
                    SiteProblem(
                        "extent",
                        (),
                        f"the site is {size / 1000:.1f} km across, more than "
                        f"{lim.max_site_size_m:g} m",
                        "check the coordinates, plan it in parts, or raise the limit "
                        "(--max-site-size-m)",
                    )
                )

    def _check_passages(self) -> list[SiteProblem]:
        """A passage is a valid polygon through a building, lower than the building."""
        out = []
        lim = self.limits
        for p in self.passages:
            who = _where("passage", p.id)
            bad = _kind_problem(p.geometry, who, p.id) or _shape_problem(p.geometry, who, p.id)
            if bad is not None:
                out.append(replace(bad, kind="passage"))
                continue
            h = _height_problem(p.clear_height_m, who, p.id, 0.0, lim.max_building_height_m)
            if isinstance(h, SiteProblem):
                out.append(replace(h, kind="passage"))
                continue
            object.__setattr__(p, "clear_height_m", h)
            through = [b for b in self.buildings if b.footprint.intersects(p.geometry)]
            if not through:
                out.append(
                    SiteProblem(
                        "passage",
                        (p.id,),
                        f"{who} does not pass through any building",
                        "draw it through the building whose ground floor it crosses",
                    )
                )
            for b in through:
                if h >= b.height_m:
                    out.append(
                        SiteProblem(
                            "passage",
                            (p.id, b.id),
                            f"{who} is {h:g} m high, as high as building {b.id!r} "
                            f"({b.height_m:g} m)",
                            "give its clear height (the gateway's, not the building's)",
                        )
                    )
        return out

    def _check_zones(self) -> list[SiteProblem]:
        """Zone ids unique; each on a building of the site (a facade id names its building:
        ``<building>-f<NN>``)."""
        self.zones = list(self.zones)
        out = []
        for dup in sorted(i for i, k in Counter(z.id for z in self.zones).items() if k > 1):
            out.append(
                SiteProblem(
                    "zone", (dup,), f"zone id {dup!r} appears twice", "zone ids must be unique"
                )
            )
        known = {b.id for b in self.buildings}
        for z in self.zones:
            bid = z.building_id or (z.facade_id or "").rsplit("-f", 1)[0]
            if bid not in known:
                where = z.building_id or z.facade_id
                out.append(
                    SiteProblem(
                        "zone",
                        (z.id,),
                        f"zone {z.id!r} is on {where!r}, which is not a building (or a facade "
                        "<building>-f<NN>) of the site",
                        f"buildings: {', '.join(sorted(known)[:20])}",
                    )
                )
        return out

    def _check_control(self) -> list[SiteProblem]:
        """Control points must be on the site: not inside a building, not kilometres away
        (most often another CRS or swapped x, y); their ids unique."""
        if not self.control:
            return []
        out = []
        ids = [c.id for c in self.control]
        if len(set(ids)) != len(ids):
            out.append(
                SiteProblem("control", (), "control point ids must be unique; one appears twice")
            )
        if not self.buildings:
            return out
        foot = shapely.union_all([b.footprint for b in self.buildings])
        for c in self.control:
            p = shapely.Point(c.xyz[:2])
            d = float(foot.distance(p))
            if d > MAX_CONTROL_DISTANCE_M:
                out.append(
                    SiteProblem(
                        "control",
                        (c.id,),
                        f"control point {c.id!r} is {d:,.0f} m from the nearest building",
                        "control points must be given in the site's CRS (is it another CRS, or "
                        "are x and y swapped?)",
                    )
                )
                continue
            inside = [b.id for b in self.buildings if b.footprint.buffer(-0.05).contains(p)]
            if inside:
                out.append(
                    SiteProblem(
                        "control",
                        (c.id,),
                        f"control point {c.id!r} is inside building {inside[0]!r}",
                        "a scanner must see it: give the point where it stands on open ground "
                        "or on a wall",
                    )
                )
        return out

    def _check_overlaps(self, problems: list[SiteProblem]) -> None:
        """Buildings may share walls but not ground; obstacles may not stand in buildings;
        the planned buildings inside the boundary. Far pairs are noted and left."""
        valid = [b for b in self.buildings if b.footprint.is_valid]  # the others are said
        if not valid:
            return
        foot = [b.footprint for b in valid]
        near = self._near(foot)
        tree = shapely.STRtree(foot)
        pairs = tree.query(foot, predicate="intersects")
        for i, j in pairs.T:
            if i < j:
                inter = shapely.intersection(foot[i], foot[j])
                area = inter.area
                if area > OVERLAP_TOLERANCE_M2:
                    a, b = valid[i].id, valid[j].id
                    c = inter.representative_point()
                    # two buildings of a 3-D model: their outlines only keep stations off
                    models = bool(valid[i].surfaces) and bool(valid[j].surfaces)
                    if (near[i] or near[j]) and not models:
                        share = 100 * area / min(foot[i].area, foot[j].area)
                        problems.append(
                            SiteProblem(
                                "overlap",
                                (a, b),
                                f"buildings {a!r} and {b!r} overlap by {area:.2f} m² "
                                f"({share:.0f} % of the smaller) at ({c.x:.1f}, {c.y:.1f})",
                                "buildings may share walls but not ground: fix the outlines, "
                                "remove a building drawn twice, or let the repair snap shared "
                                f"walls and clip overlaps up to {100 * CLIP_SHARE:.0f} % of the "
                                "smaller building (--make-valid)",
                            )
                        )
                    else:
                        self._note(
                            SiteNote(
                                "overlap",
                                (a, b),
                                "left",
                                "far from the planned buildings",
                                float(area),
                                c.x,
                                c.y,
                            )
                        )
        # (an obstacle from a model's mesh is where stations keep off; it may reach over a roof)
        obstacles = [o for o in self.obstacles if o.geometry.is_valid and o.mesh is None]
        if obstacles:
            obs = [o.geometry for o in obstacles]
            o_near = self._near(obs)
            for i, j in tree.query(obs, predicate="intersects").T:
                area = shapely.intersection(obs[i], foot[j]).area
                if area > OVERLAP_TOLERANCE_M2:
                    o, b = obstacles[i], valid[j]
                    if o_near[i] or near[j]:
                        problems.append(
                            SiteProblem(
                                "obstacle-overlap",
                                (o.id, b.id),
                                f"{o.kind} {o.id!r} overlaps building {b.id!r} by {area:.2f} m²",
                                "clip the obstacle to the building's outline, or make it part "
                                "of the building",
                            )
                        )
                    else:
                        self._note(
                            SiteNote("obstacle-overlap", (o.id, b.id), "left", "", float(area))
                        )
        if self.boundary is not None and self.boundary.is_valid:
            for b in valid:
                if b.planned and not shapely.covers(self.boundary.buffer(1e-6), b.footprint):
                    problems.append(
                        SiteProblem(
                            "boundary",
                            (b.id,),
                            f"building {b.id!r} is not inside the site boundary",
                            "enlarge the boundary or leave the building out of the plan",
                        )
                    )

    # -- views ----------------------------------------------------------------------------
    @property
    def assumed_heights(self) -> set[str]:
        """The ids of the buildings whose height the file did not give and the site assumed
        (a default height, or one for a building far from the planned ones): no plan builds
        on such a height (a station on that roof)."""
        return {
            i
            for n in self.notes
            if n.kind == "no-height" and n.action in ("default", "far")
            for i in n.ids
        }

    def ground_z(self, xy: np.ndarray) -> np.ndarray:
        """Height of the ground [m] under each point ``xy`` (P, 2) in the site's height
        system: its terrain's, 0 on flat ground. The one place this rule is written."""
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        return np.zeros(len(xy)) if self.terrain is None else self.terrain.ground_z(xy)

    @property
    def planned(self) -> list[Building]:
        """The buildings whose facades are to be scanned."""
        return [b for b in self.buildings if b.planned]

    @property
    def blockers(self) -> list[tuple[str, Polygonal, float]]:
        """Everything that blocks the beam from the ground up: ``(id, polygon, top)`` of
        every building (planned or not; without its passages) and every obstacle, ``top``
        its highest point [m] in the site's height system (its height on flat ground)."""
        cut = shapely.union_all([p.geometry for p in self.passages]) if self.passages else None
        out = []
        for b in self.buildings:
            g = b.footprint
            if cut is not None and g.intersects(cut):
                g = _polygonal_part(g.difference(cut))
            out.append((b.id, g, b.top_z))
        out += [
            (o.id, o.geometry, self.ground_under(o.geometry) + o.height_m) for o in self.obstacles
        ]
        return out

    def ground_under(self, geom: BaseGeometry) -> float:
        """The lowest ground [m] under an outline (0 on flat ground)."""
        if self.terrain is None:
            return 0.0
        ring = shapely.segmentize(geom.boundary if geom.area else geom, 2.0)
        return float(self.terrain.ground_z(shapely.get_coordinates(ring)).min())

    @property
    def bridges(self) -> list[tuple[str, Polygonal, float, float]]:
        """The floors above the passages: ``(building id, polygon, bottom, top)`` [m] — a
        sight line crossing one between its bottom (the passage's clear height) and top
        (the building's height) is blocked."""
        out = []
        for p in self.passages:
            for b in self.buildings:
                if b.footprint.intersects(p.geometry):
                    part = _polygonal_part(b.footprint.intersection(p.geometry))
                    if not part.is_empty:
                        out.append((b.id, part, b.base_z + p.clear_height_m, b.top_z))
        return out

    def passages_through(self, buildings: Sequence[Building]) -> list[Passage]:
        """The passages through any of ``buildings``: those a part of the site holding only
        these buildings keeps (one whose building is left out would pass through nothing:
        where it reaches beyond its walls it is open ground)."""
        return [
            p
            for p in self.passages
            if any(b.footprint.intersects(p.geometry) for b in buildings)  # as the check
        ]

    def select(self, building_ids: Sequence[str] | None) -> Site:
        """The same site planning only ``building_ids`` (the others act as obstacles)."""
        if building_ids is None:
            return self
        return replace(
            self,
            buildings=with_planned(self.buildings, building_ids),
            warnings=list(self.warnings),
        )


def with_terrain(site: Site, path: str) -> Site:
    """``site`` standing on the terrain model (GeoTIFF) at ``path``, cut to the site and
    300 m around (:func:`planner.terrain.read_terrain`): its footprint buildings' bases
    settled on it again, its heights in the terrain's vertical datum."""
    from planner import crs as crs_
    from planner.terrain import read_terrain

    geoms = [b.footprint for b in site.buildings] + [o.geometry for o in site.obstacles]
    x0, y0, x1, y1 = shapely.union_all(geoms).bounds
    m = 300.0
    terrain, t_crs = read_terrain(path, (x0 - m, y0 - m, x1 + m, y1 + m))
    if site.crs and t_crs:
        same = crs_.split_model_crs(site.crs)[0] == crs_.split_model_crs(t_crs)[0]
        if not same:
            raise InputError(
                f"the terrain model is in {crs_.name_of(t_crs)}, the site in "
                f"{crs_.name_of(site.crs)}; reproject the terrain model (gdalwarp -t_srs …)"
            )
    lo, hi = terrain.z_range
    if hi - lo > 3000:
        raise InputError(
            f"the terrain model's heights span {lo:g}–{hi:g} m over the site; check its units"
        )
    buildings = [b if b.surfaces else replace(b, base_z=None) for b in site.buildings]
    warnings = list(site.warnings)
    gx = terrain.x0 + np.array([0, terrain.z.shape[1] - 1]) * terrain.dx
    gy = terrain.y0 + np.array([0, terrain.z.shape[0] - 1]) * terrain.dy
    if gx.min() > x0 or gx.max() < x1 or gy.min() > y0 or gy.max() < y1:
        warnings.append(
            f"the {terrain.source} does not cover every building: beyond its edge the edge's "
            "heights are taken"
        )
    return replace(site, buildings=buildings, terrain=terrain, warnings=warnings)


def with_planned(buildings: Sequence[Building], ids: Sequence[str] | None) -> list[Building]:
    """The buildings with those of ``ids`` planned and the others not (as they are when
    None); an unknown id is refused, naming the known ones."""
    if ids is None:
        return list(buildings)
    wanted = [str(i) for i in ids]
    known = {b.id for b in buildings}
    missing = [i for i in wanted if i not in known]
    if missing:
        shown = ", ".join(sorted(known)[:20]) + (" …" if len(known) > 20 else "")
        raise InputError(f"no building with id {', '.join(map(repr, missing))}; ids are: {shown}")
    chosen = set(wanted)
    return [replace(b, planned=b.id in chosen) for b in buildings]
