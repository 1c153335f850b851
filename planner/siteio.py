"""Reading a site from GeoJSON, WKT or a CSV of vertices; the built-in default site.

Coordinates in a projected metric CRS are kept as given; longitude/latitude (a GeoJSON
without a CRS member, KML, a file labelled EPSG:4326, ``--crs EPSG:4326``) is projected to
its UTM zone.

* **GeoJSON** — a FeatureCollection, a Feature or a bare geometry. Properties: ``role``
  (``building`` — the default —, ``obstacle``, ``no-go``, ``boundary``), ``height`` (or
  ``height_m``) in metres, ``id`` (else the Feature's ``id`` member, else its index),
  ``plan`` (false: a building that only blocks the beam), ``kind``, ``name``; on a
  building, its own requirement (``max_xy_mm``, ``max_z_mm``, ``max_incidence_deg``,
  ``max_spacing_mm``, ``stations_per_sample``, ``class``, ``sample_spacing_m``: a zone
  covering it, :mod:`planner.zones`). A legacy ``crs`` member is kept and written back.
* **WKT** — one geometry per line, optionally followed by ``; key=value`` pairs with the
  same keys (``POLYGON ((...)); height=12; role=building; id=A``).
* **GeoPackage, Shapefile, KML/KMZ** — read through GDAL with ``pyogrio`` (its raw reader:
  WKB geometries and attribute arrays straight into the same features; geopandas would add
  a data-frame layer only to be unpacked again). Every layer is read; the role is the
  ``role`` attribute, else the layer's name (``buildings``, ``trees``, ``no-go``,
  ``boundary``, ``control``… :data:`LAYER_ROLES`), else building. Height: ``height``,
  ``height_m`` or OpenStreetMap's ``building:height`` ("12 m" is read as 12), else
  ``building:levels`` × the storey height, else a KML polygon extruded from the ground
  (its altitude). Id: ``id``, else the KML ``Name``, else ``name``. The CRS comes with the
  file (a shapefile's ``.prj``; KML is always longitude/latitude).
* **CSV** — one row per vertex, with a header: ``id, x, y`` and optionally ``ring`` (0 the
  outline, 1, 2, … holes), ``part`` (for MultiPolygons), ``height``, ``role``, ``plan``;
  vertices in ring order.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
from collections import defaultdict
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
import shapely
from shapely.errors import GEOSException, ShapelyError
from shapely.geometry import MultiPolygon, Polygon, shape
from shapely.geometry.base import BaseGeometry

from planner.crs import GEOJSON_DEFAULT
from planner.errors import InputError
from planner.materials import material_named
from planner.reading import MAX_FILE_BYTES, reading, user_file
from planner.site import (
    CROWN_BASE_SHARE,
    DEFAULT_CONTROL_RMS_MM,
    DEFAULT_CROWN_M,
    DEFAULT_NEAR_M,
    DEFAULT_PASSAGE_HEIGHT_M,
    DEFAULT_PASSAGE_WIDTH_M,
    FAR_HEIGHT_M,
    OVERLAP_TOLERANCE_M2,
    Area,
    Building,
    ControlPoint,
    Obstacle,
    Passage,
    Site,
    SiteLimits,
    repair_geometry,
    with_planned,
)
from planner.sitecheck import SiteNote, SiteProblem, SiteProblems, near_mask, resolve_overlaps
from planner.zones import ALIASES, ZONE_KEYS, Zone, zone_from_row

__all__ = [
    "default_site",
    "read_control",
    "read_outlines",
    "read_site",
    "site_from_features",
    "site_from_geojson",
]

ROLES = ("building", "obstacle", "no-go", "boundary", "control", "passage")
_ROLE_ALIASES = {
    "nogo": "no-go",
    "no_go": "no-go",
    "nogo-area": "no-go",
    "obstruction": "obstacle",
    "gateway": "passage",
    "building_passage": "passage",
    "building-passage": "passage",
}
#: OpenStreetMap keys of features that are not buildings (a way in an area's export).
_NOT_BUILDINGS = ("highway", "railway", "waterway", "barrier", "landuse", "natural", "amenity")
SUFFIXES = {
    ".geojson": "geojson",
    ".json": "geojson",
    ".wkt": "wkt",
    ".txt": "wkt",
    ".csv": "csv",
    ".gpkg": "GeoPackage",
    ".shp": "Shapefile",
    ".kml": "KML",
    ".kmz": "KMZ",
}
#: Formats read through GDAL (``pyogrio``): binary or XML, one or more layers each.
GIS_KINDS = ("GeoPackage", "Shapefile", "KML", "KMZ")
#: A layer named like this (lower case, "_" and " " as "-", a plural "s" dropped) gives its
#: features this role unless they carry their own ``role``.
LAYER_ROLES = {
    "building": "building",
    "house": "building",
    "obstacle": "obstacle",
    "tree": "obstacle",
    "wall": "obstacle",
    "no-go": "no-go",
    "nogo": "no-go",
    "road": "no-go",
    "street": "no-go",
    "boundary": "boundary",
    "site-boundary": "boundary",
    "control": "control",
    "control-point": "control",
    "passage": "passage",
    "gateway": "passage",
}
#: Storey height for a building known only by its number of storeys (``building:levels``,
#: as OpenStreetMap gives it) [m].
DEFAULT_STOREY_HEIGHT_M = 3.0


@dataclass
class Feature:
    """One parsed input feature before validation."""

    index: int
    geometry: BaseGeometry | None
    props: dict[str, Any]
    feature_id: Any = None

    @property
    def ident(self) -> str:
        for v in (self.props.get("id"), self.feature_id):
            if v is not None and str(v).strip():
                return str(v).strip()
        return str(self.index)

    def who(self) -> str:
        return f"feature {self.index} (id {self.ident!r})"


def _truthy(v: Any) -> bool:
    if isinstance(v, str):
        return v.strip().lower() not in ("false", "no", "0", "")
    return bool(v)


def site_from_features(
    features: Sequence[Feature],
    *,
    default_height_m: float | None = None,
    buildings: Sequence[str] | None = None,
    repair: bool = False,
    crs: str | None = None,
    name: str = "site",
    limits: SiteLimits | None = None,
    near_m: float = DEFAULT_NEAR_M,
    storey_height_m: float = DEFAULT_STOREY_HEIGHT_M,
    origin: str = "",
) -> Site:
    """Turn parsed features into a validated :class:`Site` (longitude/latitude projected to
    its UTM zone; a projected CRS label checked against the coordinates).

    Every problem is collected and reported at once (:mod:`planner.sitecheck`); problems far
    from the buildings to plan (``buildings``; all when None) are noted, not refused. A
    building without a height takes ``building:levels`` × ``storey_height_m``, else
    ``default_height_m``; ``repair`` mends outlines and overlapping buildings. What was
    done is in the site's ``notes``."""
    warnings: list[str] = []
    problems: list[SiteProblem] = []
    notes: list[SiteNote] = []
    _check_storey_height(storey_height_m)
    heights = [_height_of(f.props, f.geometry, storey_height_m) for f in features]  # KML: z
    crs = _to_metres(features, crs, warnings)
    blds: list[Building] = []
    heightless: list[tuple[int, Feature]] = []  # (index into blds, its feature)
    obstacles: list[Obstacle] = []
    no_go: list[Area] = []
    boundaries: list[BaseGeometry] = []
    control: list[ControlPoint] = []
    zones: list[Zone] = []
    passages: list[Passage] = []
    for f, (height, source) in zip(features, heights, strict=True):
        role = _role_of(f.props)
        if role is None:  # a road or a path of an area's export: not part of the site
            notes.append(SiteNote("other", (f.ident,), "dropped", _osm_kind(f.props)))
            continue
        if role not in ROLES:
            problems.append(
                SiteProblem(
                    "role",
                    (f.ident,),
                    f"{f.who()} has role {role!r}",
                    f"use one of {', '.join(ROLES)}",
                )
            )
            continue
        geom = f.geometry
        if geom is None:
            problems.append(
                SiteProblem(
                    "geometry",
                    (f.ident,),
                    f"{f.who()} has no geometry",
                    "remove it or draw its outline",
                )
            )
            continue
        if role == "control":
            control.append(_control_point(f))
            continue
        geom = shapely.force_2d(geom)
        if role == "obstacle" and _is_tree(f.props) and geom.geom_type == "Point":
            tree = _tree(f, geom, height)
            if isinstance(tree, SiteProblem):
                problems.append(tree)
            else:
                obstacles.append(tree)
            continue
        if role == "passage":
            passages.append(_passage(f, geom))
            continue
        polygonal = _polygonal(geom)  # anything else is the site's to refuse or leave out
        if repair and polygonal:
            repaired = repair_geometry(geom)
            if not repaired.equals(geom):
                x0, y0, x1, y1 = geom.bounds
                notes.append(
                    SiteNote(
                        "outline",
                        (f.ident,),
                        "repaired",
                        shapely.is_valid_reason(geom),
                        x=(x0 + x1) / 2,
                        y=(y0 + y1) / 2,
                    )
                )
            geom = repaired
        if role in ("building", "obstacle"):
            if source == "levels" and polygonal:
                notes.append(SiteNote("no-height", (f.ident,), "levels", f"{height:g} m"))
            if height is None:
                if default_height_m is not None and polygonal:
                    height = default_height_m
                    notes.append(
                        SiteNote("no-height", (f.ident,), "default", f"{default_height_m:g} m")
                    )
                elif role == "obstacle":
                    problems.append(_no_height(role, f))
                    continue
            if role == "building":
                zone = _building_zone(f)
                if zone is not None:
                    zones.append(zone)
                if height is None and polygonal:  # decided once it is known what is near
                    heightless.append((len(blds), f))
                blds.append(
                    Building(
                        f.ident,
                        geom,
                        height if height is not None else FAR_HEIGHT_M,
                        planned=_truthy(f.props.get("plan", True)),
                        name=str(f.props.get("name", "")),
                        material=material_named(f.props),
                    )
                )
            else:
                obstacles.append(
                    Obstacle(f.ident, geom, height, kind=str(f.props.get("kind", "obstacle")))
                )
        elif role == "no-go":
            no_go.append(Area(f.ident, geom))
        else:
            boundaries.append(geom)
    if len(boundaries) > 1:
        problems.append(
            SiteProblem("site", (), f"the file has {len(boundaries)} boundary features", "keep one")
        )
    if not blds:
        problems.append(
            SiteProblem(
                "site",
                (),
                "the file has no building footprint (a polygon with role 'building' or no role)",
            )
        )
        raise SiteProblems(problems, origin)
    blds = _without_parts(blds, [f for f in features if f.props.get("building:part")], notes)
    blds = with_planned(blds, buildings)
    if heightless:  # far from the planned buildings a height is immaterial: noted, not asked
        planned = [b.footprint for b in blds if b.planned and _polygonal(b.footprint)]
        near = near_mask(planned, [blds[i].footprint for i, _ in heightless], near_m)
        for (i, f), is_near in zip(heightless, near, strict=True):
            if is_near or blds[i].planned:
                problems.append(_no_height("building", f))
            else:
                notes.append(SiteNote("no-height", (f.ident,), "far", f"{FAR_HEIGHT_M:g} m"))
    if repair:
        good = [
            k
            for k, b in enumerate(blds)
            if isinstance(b.footprint, Polygon | MultiPolygon)
            and not b.footprint.is_empty
            and b.footprint.is_valid
        ]
        fixed, overlap_notes = resolve_overlaps(
            [blds[k].id for k in good], [blds[k].footprint for k in good], OVERLAP_TOLERANCE_M2
        )
        for k, geom in zip(good, fixed, strict=True):
            if geom is not blds[k].footprint:
                blds[k] = replace(blds[k], footprint=geom)
        notes += overlap_notes
    try:
        site = Site(
            buildings=blds,
            obstacles=obstacles,
            no_go=no_go,
            boundary=boundaries[0] if boundaries else None,
            crs=crs,
            name=name,
            warnings=warnings,
            limits=limits or SiteLimits(),
            control=control,
            zones=zones,
            notes=notes,
            near_m=near_m,
            passages=passages,
        )
    except SiteProblems as exc:
        problems += exc.problems
    if problems:
        raise SiteProblems(problems, origin)
    return site


#: A building part (OpenStreetMap's ``building:part``) this much inside a building's outline
#: is a piece of that building, not a building of its own.
PART_INSIDE = 0.9


def _without_parts(
    blds: list[Building], parts: list[Feature], notes: list[SiteNote]
) -> list[Building]:
    """The buildings without the OpenStreetMap building parts (``building:part`` and no
    ``building`` tag) that lie inside another building's outline: the outline already
    blocks the beam and carries the facades (each part left out is noted)."""
    ids = {f.ident for f in parts if not f.props.get("building")}
    if not ids:
        return blds
    whole = [b for b in blds if b.id not in ids and _polygonal(b.footprint)]
    tree = shapely.STRtree([b.footprint for b in whole])
    out = []
    for b in blds:
        if b.id in ids and _polygonal(b.footprint) and b.footprint.is_valid:
            hosts = [
                whole[j]
                for j in tree.query(b.footprint, predicate="intersects")
                if whole[j].footprint.is_valid
                and shapely.intersection(whole[j].footprint, b.footprint).area
                >= PART_INSIDE * b.footprint.area
            ]
            if hosts:
                notes.append(SiteNote("part", (b.id,), "dropped", f"a part of {hosts[0].id}"))
                continue
        out.append(b)
    return out


def _polygonal(geom: Any) -> bool:
    return isinstance(geom, Polygon | MultiPolygon) and not geom.is_empty


def _height_of(props: dict[str, Any], geom: BaseGeometry | None, storey_height_m: float):
    """A feature's height [m] and where it comes from: ``"given"`` — ``height`` or
    ``height_m`` (as given: a text that is not a height is refused later), else
    OpenStreetMap's ``building:height`` or ``est_height`` when they read as a number ("12 m"
    is 12); ``"levels"`` — ``building:levels`` (or ``levels``) × ``storey_height_m``;
    ``"extruded"`` — the altitude of a KML polygon extruded from the ground; else
    ``(None, "")``."""
    low = {k.lower(): k for k in props}
    for key in ("height", "height_m"):
        raw = props[low[key]] if key in low else None
        if raw is not None and not (isinstance(raw, str) and not raw.strip()):
            v = _number_in(raw) if isinstance(raw, str) else None
            return (v if v is not None else raw), "given"
    for key in ("building:height", "est_height"):
        v = _number_in(props[low[key]]) if key in low else None
        if v is not None:
            return v, "given"
    levels = next(
        (_number_in(props[low[k]]) for k in ("building:levels", "levels") if k in low), None
    )
    if levels is not None and levels > 0:
        return levels * storey_height_m, "levels"
    if (
        geom is not None
        and shapely.has_z(geom)
        and str(props.get("extrude", "0")) in ("1", "True", "true")
    ):
        z = shapely.get_coordinates(geom, include_z=True)[:, 2]
        if np.isfinite(z).all() and z.max() > 0:
            return float(z.max()), "extruded"
    return None, ""


def _check_storey_height(storey_height_m: float) -> None:
    from planner.ranges import RANGES

    RANGES["storey_height_m"].check(storey_height_m, "the storey height")


def _role_of(props: dict[str, Any]) -> str | None:
    """A feature's role: its ``role``; else, for OpenStreetMap tags, ``passage`` for a way
    through a building (``tunnel=building_passage``, a ``covered=yes`` highway) and None
    for a road, path or other feature that is not a building; else ``building``."""
    if "role" in props:
        role = str(props["role"]).strip().lower()
        return _ROLE_ALIASES.get(role, role)
    tags = {str(k).lower(): str(v).strip().lower() for k, v in props.items()}
    if tags.get("natural") == "tree":  # OpenStreetMap's tree: an obstacle with a crown
        return "obstacle"
    if tags.get("tunnel") == "building_passage" or (
        tags.get("covered") == "yes" and "highway" in tags
    ):
        return "passage"
    if (
        "building" not in tags
        and "building:part" not in tags
        and any(k in tags for k in _NOT_BUILDINGS)
    ):
        return None
    return "building"


def _osm_kind(props: dict[str, Any]) -> str:
    """What an OpenStreetMap feature left out is (``highway=footway``)."""
    for k in _NOT_BUILDINGS:
        if k in props:
            return f"{k}={props[k]}: not a building"
    return "not a building"


def _is_tree(props: dict[str, Any]) -> bool:
    return (
        str(props.get("natural", "")).lower() == "tree"
        or str(props.get("kind", "")).lower() == "tree"
    )


def _tree(f: Feature, point: BaseGeometry, height: float | None) -> Obstacle | SiteProblem:
    """A tree given as a point (OpenStreetMap's ``natural=tree`` with ``height`` and
    ``diameter_crown``, or ``crown_diameter_m`` and ``crown_base_m``): an obstacle with a
    trunk and a crown, its outline the crown's circle."""
    if height is None:
        return _no_height("obstacle", f)
    crown = DEFAULT_CROWN_M
    for key in ("crown_diameter_m", "diameter_crown", "crown_diameter"):
        v = _number_in(f.props.get(key)) if key in f.props else None
        if v is not None:
            crown = v
            break
    if not (0.5 <= crown <= 60.0):
        return SiteProblem(
            "tree",
            (f.ident,),
            f"{f.who()} has a crown {crown:g} m across",
            "give the crown's diameter in metres (0.5 to 60)",
        )
    base = _number_in(f.props.get("crown_base_m")) if "crown_base_m" in f.props else None
    base = CROWN_BASE_SHARE * height if base is None else base
    if not (0.0 < base < height):
        return SiteProblem(
            "tree",
            (f.ident,),
            f"{f.who()}: its crown starts at {base:g} m, not below its top ({height:g} m)",
            "give crown_base_m between 0 and the tree's height",
        )
    circle = point.buffer(crown / 2.0, quad_segs=4)
    return Obstacle(f.ident, circle, float(height), "tree", crown_base_m=float(base))


def _passage(f: Feature, geom: BaseGeometry) -> Passage:
    """A passage from its feature: a polygon as drawn, a line widened to its ``width``
    (default :data:`~planner.site.DEFAULT_PASSAGE_WIDTH_M`); its clear height from
    ``clear_height_m``, OpenStreetMap's ``maxheight`` or ``height`` (default
    :data:`~planner.site.DEFAULT_PASSAGE_HEIGHT_M`)."""
    low = {k.lower(): k for k in f.props}
    clear = DEFAULT_PASSAGE_HEIGHT_M
    for key in ("clear_height_m", "maxheight", "height"):
        v = _number_in(f.props[low[key]]) if key in low else None
        if v is not None:
            clear = v
            break
    if geom.geom_type in ("LineString", "MultiLineString"):
        width = _number_in(f.props[low["width"]]) if "width" in low else None
        width = width if width and width > 0 else DEFAULT_PASSAGE_WIDTH_M
        return Passage.along(f.ident, geom, width, clear)
    return Passage(f.ident, geom, clear)


def _no_height(role: str, f: Feature) -> SiteProblem:
    return SiteProblem(
        "no-height",
        (f.ident,),
        f"{role} {f.who()} has no height",
        "add a 'height' (or 'building:levels') property in metres, or give a default height "
        "(--height H)",
    )


def _building_zone(f: Feature) -> Zone | None:
    """A building's own requirement from its properties (``max_xy_mm``, ``max_z_mm``,
    ``class``, ``sample_spacing_m``…), as a zone covering the building; None if it has none."""
    keys = {k: v for k, v in f.props.items() if ALIASES.get(k, k) in ZONE_KEYS}
    for k in ("sample_spacing_m", "sample_height_step_m"):
        if k in f.props:
            keys[k] = f.props[k]
    if not keys:
        return None
    return zone_from_row({"building_id": f.ident, **keys}, f"{f.ident} (building)")


def _control_point(f: Feature) -> ControlPoint:
    """A control point from a Point feature: z from its third coordinate or a ``z``
    property, ``rms_mm`` from its properties."""
    geom = f.geometry
    if geom.geom_type != "Point":
        raise InputError(f"control {f.who()} is a {geom.geom_type}; a control point is a Point")
    z = geom.z if geom.has_z else f.props.get("z", f.props.get("height"))
    if z is None:
        raise InputError(
            f"control {f.who()} has no height: give the point three coordinates or a 'z' "
            "property [m]"
        )
    rms = f.props.get("rms_mm", DEFAULT_CONTROL_RMS_MM)
    return ControlPoint(f.ident, (geom.x, geom.y, z), rms)


def read_control(path: str | Path) -> list[ControlPoint]:
    """Control points from a CSV file: ``id, x, y, z`` [m] and optionally ``rms_mm``."""
    p = user_file(path, "control point file")
    with reading(p.name, "csv"):
        rows = list(csv.DictReader(io.StringIO(p.read_text(encoding="utf-8-sig"))))
        if not rows:
            raise InputError(f"{p.name} has no control points (header id,x,y,z[,rms_mm])")
        out = []
        for lineno, row in enumerate(rows, start=2):
            low = {str(k).strip().lower(): v for k, v in row.items() if k is not None}
            missing = [c for c in ("id", "x", "y", "z") if not (low.get(c) or "").strip()]
            if missing:
                raise InputError(f"{p.name} line {lineno}: missing {', '.join(missing)}")
            rms = (
                float(low["rms_mm"])
                if (low.get("rms_mm") or "").strip()
                else DEFAULT_CONTROL_RMS_MM
            )
            out.append(
                ControlPoint(
                    low["id"].strip(),
                    (float(low["x"]), float(low["y"]), float(low["z"])),
                    rms,
                )
            )
        return out


def _to_metres(features: Sequence[Feature], crs: str | None, warnings: list[str]) -> str | None:
    """Project longitude/latitude features (in place) to their UTM zone and return the CRS
    the site is in; check a projected CRS label against the coordinates."""
    from planner import crs as crs_

    xy = _coordinates(features)
    if not crs or not len(xy):
        return crs
    if not crs_.is_geographic(crs):
        crs_.check_projected(crs, xy)
        return crs
    if not _in_degree_range(xy):  # a label that contradicts the coordinates: never written back
        raise InputError(
            f"the file says its coordinates are longitude/latitude ({crs}) but they are not "
            f"(e.g. {xy[0, 0]:.3f}, {xy[0, 1]:.3f}); fix the file's CRS label or its coordinates"
        )
    lon, lat = xy.mean(axis=0)
    utm = crs_.utm_for(float(lon), float(lat))
    forward = crs_.wgs84_to(utm)

    def project(a: np.ndarray) -> np.ndarray:
        return np.column_stack(forward(a[:, 0], a[:, 1]))

    for f in features:
        if f.geometry is not None:
            f.geometry = shapely.transform(f.geometry, project)  # z (control points) kept
    warnings.append(
        f"longitude/latitude coordinates ({crs}) projected to {crs_.name_of(utm)}: the "
        f"plan's coordinates are in {utm} (plan.kml in longitude/latitude)"
    )
    return utm


def _coordinates(features: Sequence[Feature]) -> np.ndarray:
    """Every vertex of the features' geometries, (N, 2)."""
    geoms = [f.geometry for f in features if f.geometry is not None]
    return shapely.get_coordinates(geoms) if geoms else np.empty((0, 2))


def _in_degree_range(xy: np.ndarray) -> bool:
    """Every vertex a possible longitude/latitude (and there is one)."""
    return bool(len(xy)) and bool(
        (np.abs(xy[:, 0]) <= 180).all() and (np.abs(xy[:, 1]) <= 90).all()
    )


# -- GeoJSON ------------------------------------------------------------------------------
def _geojson_features(obj: Any, origin: str) -> tuple[list[Feature], str | None]:
    if not isinstance(obj, dict) or "type" not in obj:
        raise InputError(f"{origin} is JSON but not GeoJSON (no 'type' member)")
    crs = None
    if isinstance(obj.get("crs"), dict):
        crs = str(obj["crs"].get("properties", {}).get("name") or "") or None
    kind = obj["type"]
    if kind == "FeatureCollection":
        raw = obj.get("features")
        if not isinstance(raw, list):
            raise InputError(f"{origin}: a FeatureCollection needs a 'features' list")
    elif kind == "Feature":
        raw = [obj]
    elif kind in (
        "Polygon",
        "MultiPolygon",
        "GeometryCollection",
        "Point",
        "LineString",
        "MultiPoint",
        "MultiLineString",
    ):
        raw = [{"type": "Feature", "geometry": obj, "properties": {}}]
    else:
        raise InputError(f"{origin}: unknown GeoJSON type {kind!r}")
    out = []
    for i, feat in enumerate(raw):
        if not isinstance(feat, dict) or feat.get("type") != "Feature":
            raise InputError(f"{origin}: item {i} of 'features' is not a GeoJSON Feature")
        props = feat.get("properties") or {}
        if not isinstance(props, dict):
            raise InputError(
                f"{origin}: feature {i} has 'properties' of type {type(props).__name__}; it "
                'must be an object of key: value pairs (e.g. {"height": 12})'
            )
        gj = feat.get("geometry")
        try:
            geom = shape(gj) if gj else None
        except (
            ShapelyError,
            GEOSException,
            ValueError,
            TypeError,
            KeyError,
            AttributeError,
            IndexError,
        ) as exc:
            raise InputError(f"{origin}: feature {i} has a malformed geometry ({exc})") from None
        out.append(Feature(i, geom, dict(props), feat.get("id")))
    return out, crs


def site_from_geojson(obj: dict | str, **kwargs: Any) -> Site:
    """A site from a GeoJSON object (or its text)."""
    origin = kwargs.pop("origin", "the GeoJSON")
    with reading(origin, "geojson"):
        if isinstance(obj, str):
            try:
                obj = json.loads(obj)
            except json.JSONDecodeError as exc:
                raise InputError(f"the text is not valid JSON: {exc}") from None
        features, crs = _geojson_features(obj, origin)
        crs = _geojson_crs(features, kwargs.pop("crs", None) or crs)
        return site_from_features(features, crs=crs, origin=origin, **kwargs)


def _geojson_crs(features: Sequence[Feature], crs: str | None) -> str | None:
    """A GeoJSON's CRS: the one given or labelled, else longitude/latitude where every
    vertex could be (RFC 7946: GeoJSON without a CRS is longitude/latitude)."""
    if crs is None and _in_degree_range(_coordinates(features)):
        return GEOJSON_DEFAULT
    return crs


# -- WKT ----------------------------------------------------------------------------------
def _wkt_features(text: str, origin: str) -> list[Feature]:
    out = []
    for lineno, line in enumerate(text.splitlines(), start=1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        wkt, *pairs = line.split(";")
        try:
            geom = shapely.from_wkt(wkt.strip())
        except (ShapelyError, GEOSException) as exc:
            raise InputError(
                f"{origin} line {lineno} is not WKT ({str(exc).splitlines()[0]})"
            ) from None
        props: dict[str, Any] = {}
        for pair in pairs:
            if not pair.strip():
                continue
            if "=" not in pair:
                raise InputError(
                    f"{origin} line {lineno}: expected key=value after ';', got {pair.strip()!r}"
                )
            k, v = pair.split("=", 1)
            props[k.strip().lower()] = v.strip()
        parts = [geom]
        if geom is not None and geom.geom_type == "GeometryCollection":
            parts = list(shapely.get_parts(geom))
        for part in parts:
            out.append(Feature(len(out), part, dict(props)))
    if not out:
        raise InputError(f"{origin} holds no WKT geometry")
    return out


# -- CSV ----------------------------------------------------------------------------------
_CSV_ALIASES = {
    "id": ("id", "building_id", "feature_id", "name"),
    "x": ("x", "easting", "e"),
    "y": ("y", "northing", "n"),
}


def _csv_features(text: str, origin: str) -> list[Feature]:
    try:
        dialect = csv.Sniffer().sniff(text[:4096], delimiters=",;\t")
    except csv.Error:
        dialect = csv.excel
    reader = csv.DictReader(io.StringIO(text), dialect=dialect)
    header = [h.strip().lower() for h in (reader.fieldnames or [])]
    cols: dict[str, str] = {}
    for key, names in _CSV_ALIASES.items():
        for original, low in zip(reader.fieldnames or [], header, strict=True):
            if low in names:
                cols[key] = original
                break
    missing = [k for k in ("id", "x", "y") if k not in cols]
    if missing:
        raise InputError(
            f"{origin}: a vertex CSV needs the columns id, x, y (optional ring, part, height, "
            f"role, plan); missing {', '.join(missing)} (header: {', '.join(header) or 'none'})"
        )
    lowmap = {original: low for original, low in zip(reader.fieldnames or [], header, strict=True)}
    rings: dict[str, dict[tuple[int, int], list[tuple[float, float]]]] = defaultdict(
        lambda: defaultdict(list)
    )
    props: dict[str, dict[str, Any]] = {}
    order: list[str] = []
    optional = {
        k: _col(lowmap, k)
        for k in ("part", "ring", "height", "height_m", "role", "plan", "kind", "name")
    }
    for rowno, row in enumerate(reader, start=2):
        ident = (row.get(cols["id"]) or "").strip()
        if not ident:
            raise InputError(f"{origin} line {rowno}: empty id")
        try:
            x = float(row[cols["x"]])
            y = float(row[cols["y"]])
            if not (math.isfinite(x) and math.isfinite(y)):
                raise ValueError
            part = int(float(row.get(optional["part"]) or 0)) if optional["part"] else 0
            ring = int(float(row.get(optional["ring"]) or 0)) if optional["ring"] else 0
        except (TypeError, ValueError):
            raise InputError(
                f"{origin} line {rowno}: x, y (and ring, part) must be finite numbers; got "
                f"{row.get(cols['x'])!r}, {row.get(cols['y'])!r}"
            ) from None
        if ident not in props:
            order.append(ident)
            props[ident] = {"id": ident}
        for key in ("height", "height_m", "role", "plan", "kind", "name"):
            c = optional[key]
            value = (row.get(c) or "").strip() if c else ""
            if not value:
                continue
            known = props[ident].get(key)
            if known is not None and known != value:
                raise InputError(
                    f"{origin} line {rowno}: id {ident!r} has {key} {value!r} here but "
                    f"{known!r} on an earlier vertex; one feature has one {key} — give it "
                    "the same on every vertex (or only on the first)"
                )
            props[ident][key] = value
        rings[ident][(part, ring)].append((x, y))
    out = []
    for ident in order:
        polys = []
        parts = sorted({p for p, _ in rings[ident]})
        for p in parts:
            shell = rings[ident].get((p, 0))
            if not shell or len(shell) < 3:
                raise InputError(
                    f"{origin}: id {ident!r} part {p} needs an outline (ring 0) of >= 3 vertices"
                )
            holes = [v for (pp, r), v in sorted(rings[ident].items()) if pp == p and r > 0]
            polys.append(Polygon(shell, holes))
        geom = polys[0] if len(polys) == 1 else MultiPolygon(polys)
        out.append(Feature(len(out), geom, props[ident]))
    if not out:
        raise InputError(f"{origin} has a header but no vertices")
    return out


def _col(lowmap: dict[str, str], key: str) -> str | None:
    for original, low in lowmap.items():
        if low == key:
            return original
    return None


# -- files --------------------------------------------------------------------------------
def _sniff(text: str) -> str:
    head = text.lstrip()[:200].upper()
    if head.startswith("{") or head.startswith("["):
        return "geojson"
    if head.split("(")[0].strip().split(" ")[0] in (
        "POLYGON",
        "MULTIPOLYGON",
        "GEOMETRYCOLLECTION",
        "POINT",
        "LINESTRING",
        "#",
    ):
        return "wkt"
    return "csv"


def read_site(
    path: str | Path,
    *,
    default_height_m: float | None = None,
    buildings: Sequence[str] | None = None,
    repair: bool = False,
    limits: SiteLimits | None = None,
    crs: str | None = None,
    storey_height_m: float = DEFAULT_STOREY_HEIGHT_M,
    near_m: float = DEFAULT_NEAR_M,
    lod: str | None = None,
) -> Site:
    """Read a site file (``.geojson``/``.json``, ``.wkt``/``.txt``, ``.csv``, ``.gpkg``,
    ``.shp``, ``.kml`` or ``.kmz``) or a 3-D city model (CityJSON ``.json``/``.city.json``,
    a CityJSON Sequence ``.jsonl``, CityGML ``.gml``/``.xml``:
    :func:`planner.cityio.read_city_model`).

    Parameters
    ----------
    default_height_m : float, optional
        Height for buildings and obstacles that have none, nor ``building:levels`` (noted).
    buildings : list of str, optional
        Ids of the buildings to plan; all others only block the beam.
    repair : bool
        Apply the explicit repair: outlines (repeated vertices, ``make_valid``) and
        overlapping buildings (:func:`planner.sitecheck.resolve_overlaps`), each noted.
    crs : str, optional
        The CRS of the coordinates (e.g. ``EPSG:25832``, ``EPSG:4326``), overriding the file's
        own label; longitude/latitude is projected to its UTM zone. GeoJSON without a label in
        the degree range is longitude/latitude (RFC 7946).
    storey_height_m : float, default 3
        Height of a storey, for buildings known by ``building:levels`` only.
    near_m : float, default :data:`planner.site.DEFAULT_NEAR_M`
        Problems in features farther than this from every building to plan do not stop
        the reading: such features are repaired, given a height or left out, and noted
        (the ``plan`` command passes its search radius).
    lod : str, optional
        A city model's level of detail ("2", "2.2"; default the finest); only for models.

    Every problem of the file is reported at once (:class:`planner.sitecheck.SiteProblems`).
    """
    from planner.cityio import is_city_model, read_city_model

    if isinstance(path, str | os.PathLike) and Path(path).is_file() and is_city_model(Path(path)):
        return read_city_model(
            path, lod=lod, buildings=buildings, crs=crs, limits=limits, near_m=near_m
        )
    try:
        features, file_crs = _file_features(path, crs)  # (a path: checked there)
    except _CityJSON as model:  # its type found only once parsed
        from planner.cityio import site_from_cityjson

        name = Path(path).name
        with reading(name, "CityJSON"):
            return site_from_cityjson(
                model.obj, name, lod=lod, buildings=buildings, crs=crs, limits=limits, near_m=near_m
            )
    if lod:
        raise InputError(
            f"{Path(path).name}: --lod chooses a city model's level of detail; this is a site "
            "of footprints"
        )
    p = Path(path)
    return site_from_features(
        features,
        default_height_m=default_height_m,
        buildings=buildings,
        repair=repair,
        name=p.stem,
        limits=limits,
        crs=file_crs,
        storey_height_m=storey_height_m,
        near_m=near_m,
        origin=p.name,
    )


class _CityJSON(Exception):
    """A ``.json`` site file that is a CityJSON document (its parsed object)."""

    def __init__(self, obj: dict) -> None:
        super().__init__("a CityJSON document")
        self.obj = obj


def read_outlines(path: str | Path, crs: str | None = None) -> list[tuple[str, str, BaseGeometry]]:
    """The outlines of a site file as drawn, not validated: ``(id, role, geometry)`` of
    every feature with a geometry, in metres (longitude/latitude projected as
    :func:`read_site` does). For a drawing of a site that cannot be planned: its problems
    shown where they are. A file that cannot be read at all raises as :func:`read_site`; a
    city model gives its buildings' ground outlines."""
    from planner.cityio import is_city_model

    p = Path(path)
    try:
        if p.is_file() and is_city_model(p):
            raise _CityJSON({})
        features, file_crs = _file_features(path, crs)
    except _CityJSON:
        site = read_site(path, crs=crs)
        return [(b.id, "building", b.footprint) for b in site.buildings]
    _to_metres(features, file_crs, [])
    return [
        (f.ident, _role_of(f.props) or "building", f.geometry)
        for f in features
        if f.geometry is not None and not f.geometry.is_empty
    ]


def _file_features(path: Any, crs: str | None) -> tuple[list[Feature], str | None]:
    """The features of a site file, parsed but not validated, and their CRS (``crs`` given
    wins over the file's label; GeoJSON without one in the degree range is
    longitude/latitude, RFC 7946)."""
    if not isinstance(path, str | os.PathLike):
        raise InputError(f"a site file is named by a path; got {type(path).__name__} {path!r}")
    p = user_file(path, "site file")
    if p.stat().st_size == 0:
        raise InputError(f"{p.name} is empty; export the site again")
    kind = SUFFIXES.get(p.suffix.lower())
    if kind is None:
        raise InputError(
            f"{p.name}: unknown file type {p.suffix!r}; use .geojson/.json, .wkt/.txt, .csv, "
            ".gpkg, .shp, .kml or .kmz"
        )
    if p.stat().st_size > MAX_FILE_BYTES:
        raise InputError(
            f"{p.name} is {p.stat().st_size / 1e6:.0f} MB; a site file of more than "
            f"{MAX_FILE_BYTES / 1e6:.0f} MB is not a site — split it, or plan parts of it"
        )
    if kind in GIS_KINDS:
        with reading(p.name, kind):
            features, file_crs = _gis_features(p, kind)
        return features, crs or file_crs
    raw = p.read_bytes()
    if b"\x00" in raw[:4096]:
        raise InputError(f"{p.name} is a binary file, not {kind.upper()} text")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise InputError(f"{p.name} is not UTF-8 text; save it as UTF-8 {kind.upper()}") from None
    found = _sniff(text)
    if found != kind and not (kind == "csv" and found == "csv"):
        raise InputError(
            f"{p.name} has the extension {p.suffix} but its content looks like {found.upper()}; "
            f"rename it to a {found} file or export it again as {kind.upper()}"
        )
    with reading(p.name, kind):
        if kind == "geojson":
            try:
                obj = json.loads(text)
            except json.JSONDecodeError as exc:
                raise InputError(
                    f"{p.name} is not valid JSON (line {exc.lineno}: {exc.msg})"
                ) from None
            if isinstance(obj, dict) and obj.get("type") == "CityJSON":
                raise _CityJSON(obj)  # a city model named .json (read_site reads it so)
            features, file_crs = _geojson_features(obj, p.name)
            return features, _geojson_crs(features, crs or file_crs)
        parse: Callable[[str, str], list[Feature]] = (
            _wkt_features if kind == "wkt" else _csv_features
        )
        return parse(text, p.name), crs


# -- GeoPackage, Shapefile, KML/KMZ (GDAL through pyogrio) -----------------------------------
def _gis_features(p: Path, kind: str) -> tuple[list[Feature], str | None]:
    """Every layer's features, with roles, heights and ids mapped (see the module's text),
    and the file's CRS. Read by the extension's own GDAL driver only (:mod:`planner.gdalio`)."""
    from planner import gdalio

    names = gdalio.layers(p, kind)
    features: list[Feature] = []
    crs_seen: dict[str, str] = {}
    for layer in names:
        meta, _, wkb, values = gdalio.read_layer(p, kind, layer)
        if len(wkb) == 0:
            continue
        if meta.get("crs"):
            crs_seen[str(layer)] = str(meta["crs"])
        layer_role = _layer_role(str(layer))
        names = [str(n) for n in meta["fields"]]
        for i, blob in enumerate(wkb):
            props = {n: _plain(v[i]) for n, v in zip(names, values, strict=True)}
            props = {k: v for k, v in props.items() if v is not None}
            geom = shapely.from_wkb(blob) if blob is not None else None
            _map_gis_props(props, kind, layer_role)
            features.append(Feature(len(features), geom, props))
    if not features:
        raise InputError(f"{p.name} holds no features; export the buildings into it")
    if len(set(crs_seen.values())) > 1:
        listed = ", ".join(f"{k}: {v}" for k, v in crs_seen.items())
        raise InputError(
            f"{p.name}: its layers are in different coordinate systems ({listed}); export "
            "them in one"
        )
    return features, next(iter(crs_seen.values()), None)


def _layer_role(name: str) -> str | None:
    key = name.strip().lower().replace("_", "-").replace(" ", "-")
    for k in (key, key[:-1] if key.endswith("s") else key):
        if k in LAYER_ROLES:
            return LAYER_ROLES[k]
    return None


def _plain(v: Any) -> Any:
    """An attribute value as plain Python (None for GDAL's nulls, NaN, NaT)."""
    if v is None:
        return None
    if isinstance(v, np.generic):
        v = v.item()
    if isinstance(v, float) and not math.isfinite(v):
        return None
    if isinstance(v, str) and v in ("", "NaT"):
        return None
    if not isinstance(v, str | int | float | bool):
        return None if str(v) == "NaT" else str(v)
    return v


def _number_in(text: Any) -> float | None:
    """The number in an attribute such as ``12``, ``"12.5"`` or ``"12 m"`` (OpenStreetMap)."""
    if isinstance(text, bool):
        return None
    if isinstance(text, int | float):
        return float(text)
    head = str(text).strip().lower().removesuffix("m").strip().replace(",", ".")
    try:
        return float(head)
    except ValueError:
        return None


def _map_gis_props(props: dict[str, Any], kind: str, layer_role: str | None) -> None:
    """Roles and ids of a GIS feature in the keys the site reader knows (heights:
    :func:`_height_of`, as for every format)."""
    low = {k.lower(): k for k in props}
    if "role" not in props and "role" in low:
        props["role"] = props[low["role"]]
    if "role" not in props and layer_role:
        props["role"] = layer_role
    if kind in ("KML", "KMZ") and props.get("Name"):
        props["id"] = props["Name"]  # LIBKML's own "id" is the layer and a counter
    elif "id" not in props:
        for key in ("name", "osm_id", "fid"):
            if key in low:
                props["id"] = props[low[key]]
                break


def default_site(buildings: Sequence[str] | None = None, limits: SiteLimits | None = None) -> Site:
    """The built-in default site (``planner/data/default_site.geojson``).

    A courtyard block 'main' (48 × 34 m, 15 m high; courtyard 22 × 14 m reached through a
    6 m gateway in the south wing) with a lower annex 'annex' built against its east wall
    (a party wall), a neighbouring house 'house' 12 m to the west, a lime tree in front of
    the south facade, a street as a no-go area, and the survey boundary, in ETRS89 / UTM 32N
    metres. Only 'main' is planned; the others block the beam.
    """
    text = resources.files("planner.data").joinpath("default_site.geojson").read_text("utf-8")
    return site_from_geojson(
        text,
        origin="default_site.geojson",
        buildings=buildings,
        name="default site",
        limits=limits,
    )


#: A building of the surroundings that covers this share of a site's building (or is
#: covered by it) is that building from another source: left out, and said.
SAME_BUILDING_SHARE = 0.5


def with_surroundings(
    site: Site,
    path: str | Path,
    *,
    crs: str | None = None,
    default_height_m: float | None = None,
) -> Site:
    """``site`` with what stands around it from a second file in the same CRS (a site file:
    footprints with heights, trees, obstacles, no-go areas — e.g. an OpenStreetMap export
    beside a city model that holds only its buildings): its buildings block the beam but
    are not planned, its trees and obstacles block it, its no-go areas keep stations out.
    A building of the file that is one of the site's (covering half of it or more) is left
    out, and said; everything else is checked as a site file is
    (:func:`site_from_features`, with the site's buildings beside it)."""
    from planner import crs as crs_

    p = user_file(path, "surroundings file")
    with reading(p.name, "surroundings"):
        features, file_crs = _file_features(p, crs)
    if site.crs and file_crs:
        if crs_.split_model_crs(site.crs)[0] != crs_.split_model_crs(file_crs)[0]:
            raise InputError(
                f"{p.name} is in {crs_.name_of(file_crs)}, the site in "
                f"{crs_.name_of(site.crs)}; give the surroundings in the site's CRS"
            )
    ours = [b.footprint for b in site.buildings]
    tree = shapely.STRtree(ours)
    kept, same = [], []
    for f in features:
        role = _role_of(f.props)
        g = f.geometry
        if role == "building" and g is not None and _polygonal(g):
            hits = tree.query(g, predicate="intersects")
            cover = [
                shapely.area(shapely.intersection(g, ours[j]))
                / max(min(g.area, ours[j].area), 1e-9)
                for j in hits
            ]
            if cover and max(cover) >= SAME_BUILDING_SHARE:
                same.append(f.ident)
                continue
        f.props = {**f.props, "plan": False}
        kept.append(f)
    taken = {b.id for b in site.buildings}
    for f in kept:  # an id the site already gives is the surroundings' own
        if f.ident in taken:
            f.props = {**f.props, "id": f"surroundings:{f.ident}"}
    mine = [
        Feature(-1 - k, b.footprint, {"id": b.id, "height": b.height_m, "role": "building"})
        for k, b in enumerate(site.buildings)
    ]
    around = site_from_features(
        [*mine, *kept],
        default_height_m=default_height_m,
        crs=file_crs or site.crs,
        name=site.name,
        limits=site.limits,
        near_m=site.near_m,
        origin=p.name,
    )
    new = [b for b in around.buildings if b.id not in taken]
    words = (
        f"Surroundings from {p.name}: {len(new)} building(s) (not planned), "
        f"{len(around.obstacles)} tree(s) or obstacle(s), {len(around.no_go)} no-go area(s)"
        + (f"; {len(same)} of its buildings are the site's own, left out" if same else "")
    )
    return replace(
        site,
        buildings=[*site.buildings, *new],
        obstacles=[*site.obstacles, *around.obstacles],
        no_go=[*site.no_go, *around.no_go],
        warnings=[*site.warnings, words],
    )
