"""Reading 3-D city models into a :class:`~planner.site.Site`: CityJSON 1.0–2.0 (one file,
or a CityJSON Sequence ``.city.jsonl`` as 3DBAG serves its tiles) and CityGML 1.0, 2.0 and
3.0 buildings.

What is read:

* **buildings** — each ``Building`` with its ``BuildingPart``\\ s and installations becomes
  one :class:`~planner.site.Building` (its id the file's), carrying every surface of the
  level of detail chosen (``lod``: the finest the file gives, else the one asked for, e.g.
  ``"2"`` or ``"2.2"``) as a :class:`~planner.citymodel.Surface` of its semantic kind
  (walls, roofs, ground, eaves' undersides, windows, doors…; a surface without semantics
  is classed by its normal). Its footprint is the union of its ground surfaces (else of
  its lowest downward faces, else of its roofs), its base the lowest ground surface;
* **terrain** — ``TINRelief`` triangles (and mass points) become a
  :class:`~planner.terrain.TinTerrain`; a model without relief gets one through the
  buildings' ground surfaces (the ground they stand on);
* **vegetation and other structures** — ``SolitaryVegetationObject``, ``PlantCover``,
  bridges, city furniture, generic objects: obstacles with their own mesh (a tree given
  only by its height and crown diameter gets a crown of that size);
* **the CRS** — from the file (compound CRSs included: the horizontal part names the
  plan's coordinates, the vertical part its heights; longitude/latitude is projected to
  its UTM zone).

Every problem of the file is named with the object it is in and what is wrong
(:class:`~planner.errors.InputError`); a model with nothing to plan says so.
"""

from __future__ import annotations

import json
import math
import re
import xml.etree.ElementTree as ET
from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon

from planner.citymodel import SEMANTIC_KINDS, Surface, kind_by_normal
from planner.errors import InputError
from planner.materials import MATERIAL_KEYS, material_named
from planner.mesh import crown_triangles
from planner.reading import user_file
from planner.site import (
    CROWN_BASE_SHARE,
    DEFAULT_CROWN_M,
    DEFAULT_NEAR_M,
    Building,
    Obstacle,
    Site,
    SiteLimits,
    with_planned,
)
from planner.terrain import Terrain, TinTerrain

__all__ = [
    "MESH_SUFFIXES",
    "MODEL_SUFFIXES",
    "footprints_of",
    "is_city_model",
    "read_city_model",
    "site_from_citygml",
    "site_from_cityjson",
    "with_mesh",
]

#: File name endings read as a city model (a ``.json`` is one when its type says so).
MODEL_SUFFIXES = (".gml", ".xml", ".jsonl", ".citygml", ".ifc")
#: A city model larger than this is refused [bytes]: cut the tile to the job first.
MAX_MODEL_BYTES = 512_000_000

#: CityJSON object types read as obstacles with their own mesh (not planned).
OBSTACLE_TYPES = {
    "SolitaryVegetationObject": "tree",
    "PlantCover": "vegetation",
    "CityFurniture": "furniture",
    "GenericCityObject": "obstacle",
    "OtherConstruction": "obstacle",
    "Bridge": "bridge",
    "BridgePart": "bridge",
    "BridgeInstallation": "bridge",
    "BridgeConstructiveElement": "bridge",
}
#: Object types that belong to a building: their surfaces join it.
BUILDING_TYPES = ("Building", "BuildingPart")
INSTALLATION_TYPES = ("BuildingInstallation", "BuildingConstructiveElement")
#: Object types inside a building or on the ground that no beam from outside meets.
SKIPPED_TYPES = (
    "BuildingStorey",
    "BuildingRoom",
    "BuildingFurniture",
    "BuildingUnit",
    "LandUse",
    "Road",
    "Railway",
    "TransportSquare",
    "Waterway",
    "WaterBody",
    "Tunnel",
    "TunnelPart",
    "TunnelInstallation",
    "TunnelConstructiveElement",
    "TunnelHollowSpace",
    "TunnelFurniture",
    "CityObjectGroup",
)
#: What a model's surfaces of a kind mean for the plan, said with their count.
KIND_WORDS = {
    "window": "window surface(s) (glass) are not demanded: glass returns no point or a "
    "mirrored one",
    "door": "door surface(s) are demanded as wall is: a glazed door, an open one or a shop's "
    "roller shutter returns no point or another — mark such doors as windows in the model, "
    "or leave those samples out by a zone",
    "installation": "installation surface(s) (balconies, stairs, dormers, chimneys) are not "
    "demanded; they stand in the beams' way, shadowing the walls behind them",
}
#: Height below which a model's building is not one to scan: it only blocks the beam [m].
MIN_PLANNED_HEIGHT_M = 2.0


def is_city_model(path: Path) -> bool:
    """Whether the file is a city model (by its ending, or a ``.json`` whose type is
    CityJSON)."""
    name = path.name.lower()
    if name.endswith(MODEL_SUFFIXES):
        return True
    if name.endswith(".json"):
        with open(path, "rb") as fh:
            head = fh.read(4096).decode("utf-8", "replace")
        return re.search(r'"type"\s*:\s*"CityJSON"', head) is not None
    return False


# -- what the readers hand on -----------------------------------------------------------------
@dataclass
class _Object:
    """A city object as read: its polygons by level of detail, each ``(kind or None,
    rings)``; ``parent`` the object it belongs to."""

    id: str
    type: str
    parent: str | None = None
    name: str = ""
    attributes: dict[str, Any] = field(default_factory=dict)
    by_lod: dict[str, list[tuple[str | None, list[np.ndarray], str]]] = field(default_factory=dict)
    point: np.ndarray | None = None  # a tree's position when it has no geometry of its own

    def add(self, lod: str, kind: str | None, rings: list[np.ndarray], sid: str = "") -> None:
        self.by_lod.setdefault(lod, []).append((kind, rings, sid))


@dataclass
class _Model:
    """A parsed model: its objects, relief triangles and points, CRS label and the name of
    the file."""

    objects: list[_Object]
    relief: list[np.ndarray]
    relief_points: list[np.ndarray]
    crs: str | None
    origin: str


# -- LoD ----------------------------------------------------------------------------------------
#: A level of detail a user may ask for: CityGML's 0–4, CityJSON's refined 0.0–3.3.
LOD_PATTERN = re.compile(r"[0-4](\.[0-3])?")


def _lod_value(lod: str) -> float:
    try:
        return float(lod)
    except ValueError:
        return -1.0


def _pick_lod(available: Iterable[str], wanted: str | None) -> tuple[str | None, bool]:
    """The level of detail to read of an object: the finest of those matching ``wanted``
    ("2" matches "2", "2.0", "2.2"), else the finest there is; and whether it matched."""
    lods = sorted(available, key=_lod_value)
    if not lods:
        return None, True
    if wanted:
        match = [v for v in lods if v == wanted or v.split(".")[0] == wanted]
        if match:
            return match[-1], True
        return lods[-1], False
    return lods[-1], True


# -- CityJSON -------------------------------------------------------------------------------------
def _crs_of_cityjson(meta: Any) -> str | None:
    """The model's CRS as its metadata names it (a URL or URN; compound ones too)."""
    ref = meta.get("referenceSystem") if isinstance(meta, dict) else None
    return str(ref) if ref else None


class _CityJSONReader:
    """One CityJSON document (or the header of a sequence and its features)."""

    def __init__(self, header: dict[str, Any], origin: str) -> None:
        self.origin = origin
        version = str(header.get("version", ""))
        if not re.fullmatch(r"(1\.[01]|2\.0)(\.\d+)?", version):
            raise InputError(
                f"{origin}: CityJSON version {version or '(none)'!r}; versions 1.0, 1.1 and 2.0 "
                "are read — upgrade it with cjio (cjio FILE upgrade save OUT)"
            )
        t = header.get("transform")
        self.scale = np.ones(3)
        self.translate = np.zeros(3)
        if t is not None:
            try:
                self.scale = np.asarray(t["scale"], dtype=float).reshape(3)
                self.translate = np.asarray(t["translate"], dtype=float).reshape(3)
            except (KeyError, TypeError, ValueError):
                raise InputError(
                    f"{origin}: its 'transform' needs 'scale' and 'translate' of three numbers"
                ) from None
            if not (np.isfinite(self.scale).all() and np.isfinite(self.translate).all()):
                raise InputError(f"{origin}: its 'transform' has numbers that are not finite")
            if (self.scale <= 0).any():
                raise InputError(
                    f"{origin}: its 'transform' has the scale {self.scale.tolist()}; each "
                    "axis's scale must be above 0 (e.g. 0.001: millimetre integers)"
                )
        templates = header.get("geometry-templates") or {}
        self.templates = templates.get("templates") or []
        try:
            self.template_vertices = np.asarray(
                templates.get("vertices-templates") or np.empty((0, 3)), dtype=float
            ).reshape(-1, 3)
        except (TypeError, ValueError):
            raise InputError(
                f"{origin}: its template vertices must be triples of numbers"
            ) from None
        if not np.isfinite(self.template_vertices).all():
            raise InputError(f"{origin}: its template vertices are not all finite numbers")
        self.crs = _crs_of_cityjson(header.get("metadata"))
        self.objects: list[_Object] = []
        self.relief: list[np.ndarray] = []

    def vertices(self, raw: Any, where: str) -> np.ndarray:
        try:
            v = np.asarray(raw, dtype=float).reshape(-1, 3)
        except (TypeError, ValueError):
            raise InputError(
                f"{self.origin}: {where} 'vertices' must be triples of numbers"
            ) from None
        if not np.isfinite(v).all():
            raise InputError(f"{self.origin}: {where} has vertices that are not finite numbers")
        return _checked(v * self.scale + self.translate, f"{self.origin}: {where}")

    def read_objects(self, objs: Any, verts: np.ndarray) -> None:
        if not isinstance(objs, dict):
            raise InputError(f"{self.origin}: 'CityObjects' must be an object of city objects")
        for oid, o in objs.items():
            if not isinstance(o, dict) or "type" not in o:
                raise InputError(f"{self.origin}: city object {oid!r} has no 'type'")
            typ = str(o["type"])
            if typ in SKIPPED_TYPES or typ.startswith("+"):
                continue
            parents = o.get("parents") or []
            attrs = o.get("attributes") or {}
            obj = _Object(
                str(oid),
                typ,
                str(parents[0]) if parents else None,
                str(attrs.get("name", "")) if isinstance(attrs, dict) else "",
                attrs if isinstance(attrs, dict) else {},
            )
            for k, g in enumerate(o.get("geometry") or []):
                self._geometry(obj, g, verts, f"city object {oid!r}, geometry {k}")
            if typ == "TINRelief":
                for polys in obj.by_lod.values():
                    self.relief += [r[0] for _, r, _ in polys]
                continue
            self.objects.append(obj)

    def _geometry(self, obj: _Object, g: Any, verts: np.ndarray, where: str) -> None:
        if not isinstance(g, dict) or "type" not in g:
            raise InputError(f"{self.origin}: {where} has no 'type'")
        typ = g["type"]
        lod = str(g.get("lod", ""))
        try:
            if typ == "GeometryInstance":
                self._instance(obj, g, verts, where)
                return
            if typ in ("MultiPoint", "MultiLineString"):
                return
            surfaces = _surfaces_of(typ, g.get("boundaries"), g.get("semantics"), where)
        except (TypeError, KeyError, IndexError, ValueError, AttributeError) as exc:
            raise InputError(
                f"{self.origin}: {where} ({typ}) is malformed: {type(exc).__name__} {exc}"[:300]
            ) from None
        if surfaces is None:
            raise InputError(
                f"{self.origin}: {where} has the unknown geometry type {typ!r}; CityJSON's "
                "MultiSurface, CompositeSurface, Solid, MultiSolid, CompositeSolid and "
                "GeometryInstance are read"
            )
        for kind, rings in surfaces:
            obj.add(lod, kind, [_ring(verts, r, f"{self.origin}: {where}") for r in rings])

    def _instance(self, obj: _Object, g: dict, verts: np.ndarray, where: str) -> None:
        t = int(g["template"])
        if not 0 <= t < len(self.templates):
            raise InputError(f"{self.origin}: {where} uses template {t}, which does not exist")
        tpl = self.templates[t]
        m = np.asarray(g.get("transformationMatrix", np.eye(4).ravel()), dtype=float).reshape(4, 4)
        if not np.isfinite(m).all():
            raise InputError(f"{self.origin}: {where} has a transformation matrix of non-numbers")
        k = g["boundaries"][0]
        if isinstance(k, bool) or not isinstance(k, int) or not 0 <= k < len(verts):
            raise InputError(
                f"{self.origin}: {where}'s reference point is vertex {k!r}, which does not "
                f"exist (the file has {len(verts)})"
            )
        ref = verts[k]
        local = self.template_vertices
        with np.errstate(over="ignore", invalid="ignore"):
            moved = local @ m[:3, :3].T + m[:3, 3] + ref
        if not np.isfinite(moved).all():
            raise InputError(
                f"{self.origin}: {where}'s transformation matrix moves its template beyond any "
                "number (check the matrix)"
            )
        moved = _checked(moved, f"{self.origin}: {where}")
        lod = str(tpl.get("lod", ""))
        surfaces = _surfaces_of(tpl["type"], tpl.get("boundaries"), tpl.get("semantics"), where)
        if surfaces is None and tpl["type"] not in ("MultiPoint", "MultiLineString"):
            raise InputError(
                f"{self.origin}: {where} uses a template of unknown type {tpl['type']!r}"
            )
        for kind, rings in surfaces or []:
            obj.add(lod, kind, [_ring(moved, r, f"{self.origin}: {where}") for r in rings])
        if not surfaces:
            obj.point = ref


#: Coordinates beyond these are not on Earth in any metric CRS, nor at any building's
#: height [m] (a unit slip, a corrupt file).
MAX_XY_M = 1e8
MAX_Z_M = 1e5


def _checked(v: np.ndarray, where: str) -> np.ndarray:
    """Vertices (n, 3) [m] within :data:`MAX_XY_M` and :data:`MAX_Z_M`, else an error."""
    if len(v) and (np.abs(v[:, :2]).max() > MAX_XY_M or np.abs(v[:, 2]).max() > MAX_Z_M):
        raise InputError(
            f"{where} has coordinates beyond any site ({np.abs(v).max():.3g}); check the "
            "file's transform and units"
        )
    return v


def _ring(verts: np.ndarray, ring: Any, where: str) -> np.ndarray:
    """A ring's points from its vertex indices (each a whole number in the file's range)."""
    try:
        idx = np.asarray(ring, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InputError(f"{where} has a ring that is not a list of vertex indices") from None
    if not len(idx) or not np.all(idx == np.floor(idx)) or idx.min() < 0 or idx.max() >= len(verts):
        raise InputError(f"{where} refers to a vertex that does not exist")
    return verts[idx.astype(np.int64)]


def _semantic(sem: Any, value: Any) -> str | None:
    if value is None or not isinstance(sem, dict):
        return None
    surfaces = sem.get("surfaces") or []
    v = int(value)
    if not 0 <= v < len(surfaces) or not isinstance(surfaces[v], dict):
        raise IndexError(f"semantic surface {v} does not exist")
    return SEMANTIC_KINDS.get(str(surfaces[v].get("type", "")), "unknown")


def _surfaces_of(typ: str, b: Any, sem: Any, where: str) -> list[tuple[str | None, list]] | None:
    """Every surface of a CityJSON geometry as ``(kind or None, rings of vertex indices)``;
    only the exterior shell of a solid. None for an unknown type."""
    values = sem.get("values") if isinstance(sem, dict) else None

    def shell(surfs, vals):
        out = []
        for k, rings in enumerate(surfs):
            kind = _semantic(sem, vals[k]) if vals is not None else None
            out.append((kind, rings))
        return out

    if typ in ("MultiSurface", "CompositeSurface"):
        return shell(b, values)
    if typ == "Solid":
        return shell(b[0], values[0] if values is not None else None) if b else []
    if typ in ("MultiSolid", "CompositeSolid"):
        out = []
        for k, solid in enumerate(b):
            if solid:
                out += shell(solid[0], values[k][0] if values is not None else None)
        return out
    return None


def site_from_cityjson(text_or_obj: str | dict, origin: str = "CityJSON", **kwargs: Any) -> Site:
    """A site from a CityJSON document (text or parsed) or a CityJSON Sequence (text of
    one JSON object per line); ``kwargs`` as :func:`read_city_model`'s."""
    if isinstance(text_or_obj, dict):
        docs = [text_or_obj]
    else:
        docs = _json_documents(text_or_obj, origin)
    head = docs[0]
    if not isinstance(head, dict) or head.get("type") != "CityJSON":
        raise InputError(
            f"{origin}: a CityJSON file starts with an object of type 'CityJSON'; got "
            f"{head.get('type') if isinstance(head, dict) else type(head).__name__!r}"
        )
    reader = _CityJSONReader(head, origin)
    if head.get("CityObjects"):
        reader.read_objects(
            head["CityObjects"], reader.vertices(head.get("vertices", []), "its vertex list")
        )
    for n, doc in enumerate(docs[1:], start=2):
        if not isinstance(doc, dict) or doc.get("type") != "CityJSONFeature":
            raise InputError(f"{origin}, line {n}: expected a CityJSONFeature")
        where = f"feature {doc.get('id', n)!r}"
        reader.read_objects(doc.get("CityObjects"), reader.vertices(doc.get("vertices", []), where))
    model = _Model(reader.objects, reader.relief, [], reader.crs, origin)
    return _assemble(model, **kwargs)


def _json_documents(text: str, origin: str) -> list[Any]:
    """One JSON document, or (a CityJSON Sequence) one per non-empty line."""
    try:
        return [json.loads(text)]
    except json.JSONDecodeError as first:
        lines = [ln for ln in text.splitlines() if ln.strip()]
        if len(lines) < 2:
            raise InputError(
                f"{origin} is not valid JSON (line {first.lineno}: {first.msg})"
            ) from None
        out = []
        for n, ln in enumerate(lines, start=1):
            try:
                out.append(json.loads(ln))
            except json.JSONDecodeError as exc:
                raise InputError(f"{origin}, line {n}: not valid JSON ({exc.msg})") from None
        return out


# -- CityGML ---------------------------------------------------------------------------------------
def _local(tag: Any) -> str:
    return tag.rsplit("}", 1)[-1] if isinstance(tag, str) else ""


_XLINK = "{http://www.w3.org/1999/xlink}href"
_GML_IDS = ("{http://www.opengis.net/gml}id", "{http://www.opengis.net/gml/3.2}id")
_LOD = re.compile(r"lod(\d)")
#: CityGML element names of the objects read (others' polygons are skipped).
_GML_OBJECTS = (*BUILDING_TYPES, *INSTALLATION_TYPES, *OBSTACLE_TYPES, "TINRelief")
_GML_SKIPPED = {*SKIPPED_TYPES, "Room", "IntBuildingInstallation", "BuildingFurniture"}


def _gml_id(el: ET.Element) -> str:
    for key in _GML_IDS:
        if key in el.attrib:
            return el.attrib[key]
    return ""


def _numbers(text: str | None, where: str) -> np.ndarray:
    """The numbers of a coordinate list's text; an InputError naming the first word that is
    not one."""
    words = (text or "").replace(",", " ").split()
    try:
        return np.array(words, dtype=float)
    except ValueError:
        bad = next(w for w in words if not _is_number(w))
        raise InputError(f"{where}: a ring's coordinates hold {bad[:20]!r}, not a number") from None


def _is_number(word: str) -> bool:
    try:
        float(word)
    except ValueError:
        return False
    return True


def _pos_list(el: ET.Element, dim: int, where: str) -> np.ndarray:
    """The points of a ring (posList, pos elements or GML 2 coordinates), (n, 3)."""
    pl = next((c for c in el if _local(c.tag) == "posList"), None)
    if pl is not None:
        try:
            d = int(pl.attrib.get("srsDimension", dim))
        except ValueError:
            raise InputError(f"{where}: a posList's srsDimension is not a whole number") from None
        vals = _numbers(pl.text, where)
    else:
        pos = [c for c in el if _local(c.tag) == "pos"]
        if pos:
            rows = [_numbers(p.text, where) for p in pos]
            d = len(rows[0])
            if any(len(r) != d for r in rows):
                raise InputError(f"{where}: a ring's points have different dimensions")
            vals = np.concatenate(rows)
        else:
            co = next((c for c in el if _local(c.tag) == "coordinates"), None)
            if co is None or not co.text:
                raise InputError(f"{where}: a ring has no coordinates")
            tuples = [t.split(",") for t in co.text.split()]
            d = len(tuples[0])
            vals = _numbers(" ".join(v for t in tuples for v in t), where)
    if d != 3 or vals.size % 3:
        raise InputError(f"{where}: a ring's coordinates are not x y z triples (dimension {d})")
    pts = vals.reshape(-1, 3)
    if len(pts) < 3:
        raise InputError(
            f"{where}: a ring has {len(pts)} point(s); a polygon's ring needs at least three "
            "(an empty gml:posList?)"
        )
    if not np.isfinite(pts).all():
        raise InputError(f"{where}: a ring has coordinates that are not finite numbers")
    return _checked(pts, where)


class _GMLReader:
    """A CityGML document walked once: every polygon with its object, semantic kind and
    level of detail."""

    def __init__(self, root: ET.Element, origin: str) -> None:
        self.origin = origin
        self.objects: dict[str, _Object] = {}
        self.order: list[str] = []
        self.relief: list[np.ndarray] = []
        self.relief_points: list[np.ndarray] = []
        self.crs: str | None = None
        self.by_id: dict[str, tuple[str, str, list[np.ndarray], str | None]] = {}
        self.href_kind: dict[str, str] = {}
        self.dim = 3
        self._walk(root, None, None, "", None)
        # polygons given in a solid and named by a semantic surface through a link
        for pid, kind in self.href_kind.items():
            if pid in self.by_id:
                oid, lod, _, own = self.by_id[pid]
                if own is None:
                    self.objects[oid].by_lod[lod] = [
                        (kind if s == pid else k, r, s) for k, r, s in self.objects[oid].by_lod[lod]
                    ]

    def _walk(
        self, el: ET.Element, obj: str | None, kind: str | None, lod: str, opening: str | None
    ) -> None:
        name = _local(el.tag)
        if self.crs is None and "srsName" in el.attrib:
            self.crs = el.attrib["srsName"]
            self.dim = int(el.attrib.get("srsDimension", 3))
        if name in _GML_SKIPPED:
            return
        if name in _GML_OBJECTS:
            oid = _gml_id(el) or f"{name}-{len(self.objects) + 1}"
            if oid in self.objects:
                raise InputError(f"{self.origin}: two objects have the id {oid!r}")
            typ = name
            self.objects[oid] = _Object(oid, typ, obj, _gml_name(el), _gml_attributes(el))
            self.order.append(oid)
            obj, kind, lod = oid, ("installation" if name in INSTALLATION_TYPES else None), ""
        elif name in SEMANTIC_KINDS and obj is not None:
            kind = SEMANTIC_KINDS[name]
        m = _LOD.match(name)
        if m:
            lod = m.group(1)
        if name in ("Polygon", "Triangle", "PolygonPatch") and obj is not None:
            self._polygon(el, obj, kind, lod)
            return
        if (
            name in ("referencePoint",)
            and obj is not None
            and self.objects[obj].type in OBSTACLE_TYPES
        ):
            pos = next((c for c in el.iter() if _local(c.tag) == "pos"), None)
            if pos is not None and pos.text:
                self.objects[obj].point = np.array(pos.text.split(), dtype=float)[:3]
            return
        if name == "pos" and obj is not None and self.objects[obj].type == "TINRelief":
            self.relief_points.append(np.array(el.text.split(), dtype=float).reshape(-1, 3))
            return
        href = el.attrib.get(_XLINK)
        if href and kind is not None and href.startswith("#"):
            self.href_kind[href[1:]] = kind
        for child in el:
            self._walk(child, obj, kind, lod, opening)

    def _polygon(self, el: ET.Element, obj: str, kind: str | None, lod: str) -> None:
        where = f"{self.origin}: object {obj!r}"
        rings = []
        for part in el:
            pn = _local(part.tag)
            if pn in ("exterior", "interior", "outerBoundaryIs", "innerBoundaryIs"):
                ring = next((c for c in part if _local(c.tag) == "LinearRing"), None)
                if ring is None:
                    raise InputError(f"{where}: a polygon's {pn} has no LinearRing")
                pts = _pos_list(ring, self.dim, where)
                if pn in ("exterior", "outerBoundaryIs"):
                    rings.insert(0, pts)
                else:
                    rings.append(pts)
        if not rings:
            raise InputError(f"{where}: a polygon has no exterior ring")
        o = self.objects[obj]
        if o.type == "TINRelief":
            self.relief.append(rings[0])
            return
        pid = _gml_id(el)
        o.add(lod, kind, rings, pid)
        if pid:
            self.by_id[pid] = (obj, lod, rings, kind)


def _gml_name(el: ET.Element) -> str:
    for c in el:
        if _local(c.tag) == "name" and c.text:
            return c.text.strip()
    return ""


def _gml_attributes(el: ET.Element) -> dict[str, Any]:
    """The simple attributes the planner reads: a tree's height and crown, a building's wall
    material (CityGML 2.0 generic attributes named as :data:`MATERIAL_KEYS`)."""
    out: dict[str, Any] = {}
    for c in el:
        n = _local(c.tag)
        if n in ("height", "crownDiameter", "trunkDiameter", "measuredHeight") and c.text:
            try:
                out[n] = float(c.text)
            except ValueError:
                pass
        elif n in ("stringAttribute", "genericAttribute") and c.get("name") in MATERIAL_KEYS:
            value = next((v.text for v in c if _local(v.tag) == "value" and v.text), None)
            if value:
                out[c.get("name")] = value.strip()
    return out


def site_from_citygml(data: bytes, origin: str = "CityGML", **kwargs: Any) -> Site:
    """A site from a CityGML document's bytes; ``kwargs`` as :func:`read_city_model`'s."""
    try:
        root = ET.fromstring(data)
    except ET.ParseError as exc:
        raise InputError(f"{origin} is not well-formed XML ({exc})") from None
    if _local(root.tag) not in ("CityModel",):
        raise InputError(
            f"{origin}: a CityGML file's root is a CityModel; this one is {_local(root.tag)!r}"
        )
    r = _GMLReader(root, origin)
    objs = [r.objects[i] for i in r.order if r.objects[i].type != "TINRelief"]
    model = _Model(objs, r.relief, r.relief_points, r.crs, origin)
    return _assemble(model, **kwargs)


# -- the site -------------------------------------------------------------------------------------
def read_city_model(
    path: str | Path,
    *,
    lod: str | None = None,
    buildings: Sequence[str] | None = None,
    crs: str | None = None,
    limits: SiteLimits | None = None,
    near_m: float = DEFAULT_NEAR_M,
    terrain: Terrain | None = None,
) -> Site:
    """A :class:`Site` from a city model file (CityJSON ``.json``/``.city.json``, CityJSON
    Sequence ``.jsonl``, CityGML ``.gml``/``.xml``) or a BIM model (IFC ``.ifc``:
    :mod:`planner.ifcio`).

    Parameters
    ----------
    lod : str, optional
        The level of detail to read ("2", "2.2", "3"); default the finest each object has.
    buildings : list of str, optional
        Ids of the buildings to plan; the others only block the beam.
    crs : str, optional
        The CRS of the coordinates when the file names none (or to override it).
    terrain : Terrain, optional
        A terrain given by the user (a DTM): it wins over the model's relief.
    """
    if lod is not None:
        lod = str(lod).strip()
        if not LOD_PATTERN.fullmatch(lod):
            raise InputError(
                f"--lod must be a level of detail 0 to 4, e.g. 2 or 2.2 (CityJSON's refined "
                f"0.0–3.3); got {lod[:40]!r}"
            )
    p = user_file(path, "city model")
    size = p.stat().st_size
    if size == 0:
        raise InputError(f"{p.name} is empty; export the model again")
    if size > MAX_MODEL_BYTES:
        raise InputError(
            f"{p.name} is {size / 1e6:.0f} MB; cut the model to the job's surroundings first "
            "(cjio FILE subset --bbox …)"
        )
    kw = dict(lod=lod, buildings=buildings, crs=crs, limits=limits, near_m=near_m, terrain=terrain)
    from planner.reading import reading

    with reading(p.name, "IFC" if p.suffix.lower() == ".ifc" else "CityJSON or CityGML"):
        return _read_model(p, kw)


def _read_model(p: Path, kw: dict) -> Site:
    if p.suffix.lower() == ".ifc":  # a BIM model: its buildings' shells (planner.ifcio)
        from planner.ifcio import read_ifc_model

        objects, crs, notes = read_ifc_model(p, kw.get("crs"))
        site = _assemble(_Model(objects, [], [], crs, p.name), **{**kw, "crs": crs})
        site.warnings[:0] = notes
        return site
    raw = p.read_bytes()
    head = raw.lstrip(b"\xef\xbb\xbf \t\r\n")[:1]
    if head in (b"{", b"["):
        try:
            text = raw.decode("utf-8-sig")
        except UnicodeDecodeError:
            raise InputError(f"{p.name} is not UTF-8 text; save it as UTF-8 JSON") from None
        return site_from_cityjson(text, p.name, **kw)
    if head == b"<":
        return site_from_citygml(raw, p.name, **kw)
    raise InputError(f"{p.name} is neither CityJSON nor CityGML (it starts with neither {{ nor <)")


def _assemble(
    model: _Model,
    *,
    lod: str | None = None,
    buildings: Sequence[str] | None = None,
    crs: str | None = None,
    limits: SiteLimits | None = None,
    near_m: float = DEFAULT_NEAR_M,
    terrain: Terrain | None = None,
) -> Site:
    """The site of a parsed model: its buildings (parts and installations joined), the
    obstacles, the terrain, in a projected CRS."""
    from planner import crs as crs_

    origin = model.origin
    warnings: list[str] = []
    label = crs or model.crs
    horizontal, datum = crs_.split_model_crs(label) if label else (None, "")
    project = None
    if horizontal and crs_.is_geographic(horizontal):
        project, horizontal = _projection(model, horizontal, warnings)
    owner = _owners(model.objects)
    # one level of detail per building, with its parts and installations: the finest any of
    # them has (or the one asked for); a member without it (3DBAG's LoD 0 outline of a
    # building whose part holds the LoD 2.2 solid) adds nothing
    family: dict[str, set[str]] = {}
    for o in model.objects:
        if o.id in owner:
            family.setdefault(owner[o.id], set()).update(o.by_lod)
    family_lod = {top: _pick_lod(lods, lod) for top, lods in family.items()}
    per_building: dict[str, list[Surface]] = {}
    missing_lod: list[str] = []
    obstacles: list[Obstacle] = []
    names: dict[str, str] = {}
    materials: dict[str, str] = {}
    for o in model.objects:
        if o.type in BUILDING_TYPES and o.parent is None:
            names[o.id] = o.name
            materials[o.id] = material_named(o.attributes)
        top = owner.get(o.id)
        if top is not None:
            chosen, matched = family_lod[top]
            if not matched and o.id == top:
                missing_lod.append(o.id)
            if chosen not in o.by_lod:
                continue
        else:
            chosen, matched = _pick_lod(o.by_lod, lod)
        polys = o.by_lod.get(chosen, []) if chosen is not None else []
        if project is not None:
            polys = [(k, [project(r) for r in rings], s) for k, rings, s in polys]
        if o.type in OBSTACLE_TYPES:
            ob = _obstacle(o, polys, project)
            if ob is not None:
                obstacles.append(ob)
            continue
        if top is None:
            continue
        part = "" if o.id == top else o.id
        # an installation's surfaces (a balcony's slab and parapet, a chimney) are not
        # facade, whatever their semantics say
        fixed = "installation" if o.type in INSTALLATION_TYPES else None
        for kind, rings, sid in polys:
            per_building.setdefault(top, []).append(
                Surface(fixed or kind or "", tuple(rings), part, sid, chosen or "")
            )
    if missing_lod:
        warnings.append(
            f"{len(missing_lod)} object(s) have no LoD {lod}: their finest LoD was read "
            f"(e.g. {missing_lod[0]!r})"
        )
    unknown = sum(s.kind == "unknown" for group in per_building.values() for s in group)
    if unknown:
        warnings.append(
            f"{unknown} surface(s) of a semantic type the planner does not know were classed "
            "by their normal"
        )
    blds: list[Building] = []
    for bid, surfaces in per_building.items():
        b = _building(bid, names.get(bid, ""), surfaces, origin)
        if b is None:
            continue
        if materials.get(bid):
            b = replace(b, material=materials[bid])
        if b.height_m < MIN_PLANNED_HEIGHT_M:  # a shed, a garage: not scanned, but a building
            if b.height_m < (limits or SiteLimits()).min_building_height_m:
                obstacles.append(
                    Obstacle(b.id, b.footprint, b.height_m, "structure", mesh=_mesh(b))
                )
                continue
            b = replace(b, planned=False)
        blds.append(b)
    if not any(b.planned for b in blds):
        raise InputError(
            f"{origin} holds no building to plan (no Building with surfaces of at least "
            f"{MIN_PLANNED_HEIGHT_M:g} m); is it a terrain or vegetation model?"
        )
    if terrain is None:
        terrain = _model_terrain(model, blds, project)
    kinds = Counter(s.kind for b in blds for s in b.surfaces)
    warnings += [f"{kinds[k]} {words}" for k, words in KIND_WORDS.items() if kinds[k]]
    if not obstacles:
        warnings.append(
            f"{origin} holds buildings only — no trees, street furniture or other structures: "
            "sight lines are cast against its buildings alone; add what stands around them "
            "(an OpenStreetMap export, a survey of the street) with --surroundings FILE"
        )
    try:
        planned = with_planned(blds, buildings)
    except InputError as exc:
        raise InputError(f"{origin}: {exc}") from None
    site = Site(
        buildings=planned,
        obstacles=obstacles,
        crs=horizontal,
        name=Path(origin).name.split(".")[0],
        warnings=warnings,
        limits=limits or SiteLimits(),
        near_m=near_m,
        terrain=terrain,
        height_datum=datum,
    )
    if horizontal and project is None:
        crs_.check_projected(horizontal, np.array(site.buildings[0].footprint.centroid.coords))
    return site


def _projection(model: _Model, geographic: str, warnings: list[str]):
    """Longitude/latitude (in the CRS's own axis order) projected to its UTM zone: the
    function (n, 3) → (n, 3) and the UTM CRS."""
    from pyproj import CRS, Transformer

    from planner import crs as crs_

    src = CRS.from_user_input(geographic)
    to_lonlat = Transformer.from_crs(src, "OGC:CRS84")
    pts = next(
        (r for o in model.objects for p in o.by_lod.values() for _, rings, _ in p for r in rings),
        None,
    )
    if pts is None:
        raise InputError(f"{model.origin} holds no geometry")
    lon, lat = to_lonlat.transform(pts[0, 0], pts[0, 1])
    utm = crs_.utm_for(float(lon), float(lat))
    fwd = Transformer.from_crs(src, utm)

    def project(r: np.ndarray) -> np.ndarray:
        x, y = fwd.transform(r[:, 0], r[:, 1])
        return np.column_stack([x, y, r[:, 2]])

    warnings.append(
        f"longitude/latitude coordinates ({geographic}) projected to {crs_.name_of(utm)}: the "
        f"plan's coordinates are in {utm}"
    )
    return project, utm


def _owners(objects: list[_Object]) -> dict[str, str]:
    """Each building-like object's top building (parents followed up)."""
    by_id = {o.id: o for o in objects}
    out = {}
    for o in objects:
        if o.type not in (*BUILDING_TYPES, *INSTALLATION_TYPES):
            continue
        top, seen = o, set()
        while top.parent is not None and top.parent in by_id and top.parent not in seen:
            seen.add(top.id)
            top = by_id[top.parent]
        if top.type == "Building" or (top.type == "BuildingPart" and top.parent is None):
            out[o.id] = top.id
    return out


def _footprint_of(surfaces: list[Surface], base: float) -> Polygon | MultiPolygon:
    """The ground outline: the union of the ground surfaces' outlines, else of the lowest
    downward faces, else of the roofs."""
    for pick in (
        lambda s: s.kind == "ground",
        lambda s: s.normal[2] < -0.7 and s.z_range[0] - base <= 0.5,
        lambda s: s.kind == "roof" or s.normal[2] > 0.3,
    ):
        polys = []
        for s in surfaces:
            if pick(s):
                p = Polygon(s.rings[0][:, :2], [r[:, :2] for r in s.rings[1:] if len(r) >= 3])
                p = shapely.make_valid(p) if not p.is_valid else p
                polys += [
                    g for g in shapely.get_parts(p) if g.geom_type == "Polygon" and g.area > 1e-4
                ]
        if polys:
            u = shapely.union_all(polys, grid_size=0.001)
            parts = [g for g in shapely.get_parts(u) if g.geom_type == "Polygon" and g.area > 0.05]
            if parts:
                return parts[0] if len(parts) == 1 else MultiPolygon(parts)
    return Polygon()


def _building(bid: str, name: str, surfaces: list[Surface], origin: str) -> Building | None:
    """A building of a model from its surfaces (classed by their normal where the file
    gives no kind), its base the lowest ground surface (else its lowest point)."""
    good = _outward([s for s in surfaces if len(s.rings[0]) >= 3 and s.normal.any()])
    if not good:
        return None
    zmin = min(s.z_range[0] for s in good)
    grounds = [s.z_range[0] for s in good if s.kind == "ground"]
    base = min(grounds) if grounds else zmin
    classed = []
    for s in good:
        kind = s.kind
        if kind in ("", "unknown"):
            kind = kind_by_normal(float(s.normal[2]), s.z_range[0], base)
        classed.append(Surface(kind, s.rings, s.part, s.id, s.lod) if kind != s.kind else s)
    top = max(s.z_range[1] for s in classed)
    foot = _footprint_of(classed, base)
    if foot.is_empty:
        raise InputError(
            f"{origin}: building {bid!r} has no ground outline (no ground surface, no "
            "downward face, no roof to take it from)"
        )
    classed = _walls_outward(classed, foot)
    return Building(bid, foot, float(top - base), True, name, float(base), tuple(classed))


def _flipped(s: Surface) -> Surface:
    return Surface(s.kind, tuple(r[::-1] for r in s.rings), s.part, s.id, s.lod)


def _outward(surfaces: list[Surface]) -> list[Surface]:
    """The surfaces facing out of the building: all turned where the whole shell faces in
    (its signed volume negative: rings written clockwise seen from outside), and a roof
    facing down or a ground facing up turned on its own (the usual slips of real data)."""
    if not surfaces:
        return surfaces
    tri = np.concatenate([s.triangles for s in surfaces])
    if len(tri):
        c = tri.reshape(-1, 3).mean(axis=0)
        t = tri - c
        volume = float(np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])).sum()) / 6.0
        if volume < 0:
            surfaces = [_flipped(s) for s in surfaces]
    out = []
    for s in surfaces:
        nz = float(s.normal[2])
        if (s.kind == "roof" and nz < -0.1) or (s.kind == "ground" and nz > 0.1):
            s = _flipped(s)
        out.append(s)
    return out


#: How far beside a wall its two sides are probed for the building's inside [m].
SIDE_PROBE_M = 0.3


def _walls_outward(surfaces: list[Surface], foot) -> list[Surface]:
    """Each wall standing on the building's outline turned to face out where its normal
    points into the footprint (a wall whose rings a file wrote the wrong way round)."""
    walls = [k for k, s in enumerate(surfaces) if s.kind in ("wall", "door", "window")]
    if not walls:
        return surfaces
    n = np.array([surfaces[k].normal[:2] for k in walls])
    length = np.linalg.norm(n, axis=1)
    c = np.array([surfaces[k].rings[0].mean(axis=0)[:2] for k in walls])
    ok = length > 0.5
    u = n / np.where(ok, length, 1.0)[:, None]
    ahead = c + SIDE_PROBE_M * u
    behind = c - SIDE_PROBE_M * u
    inward = (
        ok
        & shapely.contains_xy(foot, ahead[:, 0], ahead[:, 1])
        & ~shapely.contains_xy(foot, behind[:, 0], behind[:, 1])
    )
    out = list(surfaces)
    for k, flip in zip(walls, inward, strict=True):
        if flip:
            out[k] = _flipped(out[k])
    return out


def _mesh(b: Building) -> np.ndarray:
    tri = [s.triangles for s in b.surfaces]
    return np.concatenate(tri) if tri else np.empty((0, 3, 3))


def _obstacle(o: _Object, polys: list, project) -> Obstacle | None:
    """A tree, a bridge or another structure with its own mesh; a tree given only by a
    point and its height gets a crown of its size."""
    from planner.mesh import triangulate

    kind = OBSTACLE_TYPES[o.type]
    tri = [triangulate(rings) for _, rings, _ in polys]
    tri = [t for t in tri if len(t)]
    if tri:
        mesh = np.concatenate(tri)
    elif o.point is not None and kind == "tree":
        p = o.point if project is None else project(o.point[None, :])[0]
        h = float(o.attributes.get("height", 0) or 0)
        if not h > 0:
            return None
        crown = float(o.attributes.get("crownDiameter", 0) or 0) or DEFAULT_CROWN_M
        mesh = crown_triangles((p[0], p[1]), crown / 2, p[2] + CROWN_BASE_SHARE * h, p[2] + h)
    else:
        return None
    pts = mesh.reshape(-1, 3)
    lo, hi = float(pts[:, 2].min()), float(pts[:, 2].max())
    low = pts[pts[:, 2] <= lo + 1.0]
    where = shapely.MultiPoint(low[:, :2]).convex_hull.buffer(0.2, quad_segs=2)
    if kind == "tree":  # where the trunk stands; the crown is overhead
        where = shapely.Point(low[:, :2].mean(axis=0)).buffer(0.4, quad_segs=2)
    where = shapely.remove_repeated_points(where, 0.005)
    return Obstacle(o.id, where, max(hi - lo, 0.1), kind, mesh=mesh)


def _model_terrain(model: _Model, blds: list[Building], project) -> Terrain | None:
    """The model's relief, else the ground the buildings stand on (their ground surfaces'
    points); None when neither says more than one height."""
    if model.relief or model.relief_points:
        tri = [r[:3] for r in model.relief if len(r) >= 3]
        faces = np.array(tri) if tri else None
        pts = [f.reshape(-1, 3) for f in tri] + list(model.relief_points)
        allp = np.vstack(pts)
        if project is not None:
            allp = project(allp)
            faces = None
        return TinTerrain(allp, "the model's relief (TINRelief)", faces)
    pts = [s.rings[0] for b in blds for s in b.surfaces if s.kind == "ground"]
    if not pts:  # no ground surfaces: the outlines at the buildings' bases
        for b in blds:
            xy = shapely.get_coordinates(b.footprint)
            pts.append(np.column_stack([xy, np.full(len(xy), b.base_z)]))
    allp = np.vstack(pts)
    if np.ptp(allp[:, 2]) < 0.05 and math.isclose(float(allp[0, 2]), 0.0, abs_tol=0.05):
        return None
    return TinTerrain(
        allp, "ground of the model's buildings (no relief in the model)", measured=False
    )


def footprints_of(site: Site) -> dict:
    """A model's buildings as a surveyor without the model draws them — each building's
    ground outline with the height of its highest point above its base — as a GeoJSON site
    in the model's CRS (the comparison :mod:`planner.pipeline.geometry.audit` makes)."""
    feats = [
        {
            "type": "Feature",
            "properties": {"id": b.id, "height": round(b.height_m, 2), "plan": b.planned},
            "geometry": json.loads(shapely.to_geojson(b.footprint)),
        }
        for b in site.buildings
    ]
    out: dict[str, Any] = {"type": "FeatureCollection", "features": feats}
    if site.crs:
        code = site.crs.split(":")[-1]
        out["crs"] = {"type": "name", "properties": {"name": f"urn:ogc:def:crs:EPSG::{code}"}}
    return out


#: Plain meshes read with ``trimesh`` (an IFC model exported as a mesh, a photogrammetric
#: model): Wavefront OBJ, PLY, glTF / GLB, STL, OFF.
MESH_SUFFIXES = (".obj", ".ply", ".gltf", ".glb", ".stl", ".off")
#: A mesh triangle whose centre lies this close to a building's footprint is that
#: building's (its eaves reach beyond the walls) [m].
MESH_REACH_M = 1.5
#: A mesh of more triangles than this is refused: decimate it first.
MAX_MESH_TRIANGLES = 2_000_000


def with_mesh(
    site: Site,
    path: str | Path,
    *,
    offset: tuple[float, float, float] = (0.0, 0.0, 0.0),
    up: str | None = None,
) -> Site:
    """``site`` (buildings drawn as footprints, with their ids) given the 3-D shape of a
    plain mesh: each triangle whose centre lies within :data:`MESH_REACH_M` of a building's
    footprint becomes a surface of that building (a wall, roof, ground or eave's underside
    by its normal: :func:`planner.citymodel.kind_by_normal`), the others a structure that
    blocks the beam. The mesh is in the site's CRS once ``offset`` (x, y, z [m]) is added;
    ``up`` is its up axis, ``z`` (default) or ``y`` (glTF's, its default). Without a terrain
    the site stands on the ground the mesh's buildings stand on."""

    p = user_file(path, "mesh file")
    drawn = [b.id for b in site.buildings if b.is_3d]
    if drawn:
        raise InputError(
            f"--mesh gives footprints their 3-D shape; the site's buildings already have theirs "
            f"(a city model: {', '.join(drawn[:3])}{' …' if len(drawn) > 3 else ''}) — plan the "
            "model as it is, or give the mesh with the buildings' footprints"
        )
    off = np.asarray(offset, dtype=float).ravel()
    if off.shape != (3,) or not np.isfinite(off).all():
        raise InputError(f"the mesh's offset is three numbers E,N,H [m]; got {offset!r}")
    if p.suffix.lower() not in MESH_SUFFIXES:
        raise InputError(f"{p.name}: a mesh is read from {', '.join(MESH_SUFFIXES)}")
    from planner.reading import reading

    with reading(p.name, "mesh"):
        return _with_mesh(site, p, off, up)


def _with_mesh(site: Site, p: Path, off: np.ndarray, up: str | None) -> Site:
    import trimesh

    up = up or ("y" if p.suffix.lower() in (".gltf", ".glb") else "z")
    if up not in ("y", "z"):
        raise InputError(f"the mesh's up axis is y or z; got {up!r}")
    try:
        mesh = trimesh.load(p, force="mesh", process=False)
    except Exception as exc:  # trimesh raises what its loaders raise
        raise InputError(
            f"{p.name}: cannot read it as a mesh ({type(exc).__name__}: {exc})"[:300]
        ) from None
    faces = np.asarray(getattr(mesh, "faces", np.empty((0, 3))))
    verts = np.asarray(getattr(mesh, "vertices", np.empty((0, 3))), dtype=float)
    if not len(faces):
        raise InputError(f"{p.name} holds no triangles")
    if len(faces) > MAX_MESH_TRIANGLES:
        raise InputError(
            f"{p.name} has {len(faces):,} triangles, more than {MAX_MESH_TRIANGLES:,}; "
            "decimate it first"
        )
    if up == "y":
        verts = np.column_stack([verts[:, 0], -verts[:, 2], verts[:, 1]])
    if not np.isfinite(verts).all():
        raise InputError(f"{p.name} has coordinates that are not finite numbers")
    if len(faces) and (faces.min() < 0 or faces.max() >= len(verts)):
        raise InputError(f"{p.name}: a face refers to a vertex that does not exist")
    tri = verts[faces] + off
    _checked(tri.reshape(-1, 3), p.name)
    centre = tri.mean(axis=1)
    foot = [b.footprint for b in site.buildings]
    tree = shapely.STRtree([g.buffer(MESH_REACH_M) for g in foot])
    hit = tree.query(shapely.points(centre[:, :2]), predicate="intersects")
    owner = np.full(len(tri), -1)
    dist = np.full(len(tri), np.inf)
    for k, j in hit.T:  # the nearest footprint where several reach
        d = foot[j].distance(shapely.Point(centre[k, :2]))
        if d < dist[k]:
            owner[k], dist[k] = j, d
    if not (owner >= 0).any():
        raise InputError(
            f"{p.name}: none of its triangles is near a building of the site; is it in the "
            "site's CRS (give --mesh-offset E,N,H for a mesh in local coordinates)?"
        )
    buildings = []
    for j, b in enumerate(site.buildings):
        mine = tri[owner == j]
        if not len(mine):
            buildings.append(b)
            continue
        base = float(mine[:, :, 2].min())
        surfaces = []
        for t in mine:
            n = np.cross(t[1] - t[0], t[2] - t[0])
            length = np.linalg.norm(n)
            if length < 1e-9:
                continue
            kind = kind_by_normal(float(n[2] / length), float(t[:, 2].min()), base)
            surfaces.append(Surface(kind, (t,)))
        top = float(mine[:, :, 2].max())
        buildings.append(replace(b, base_z=base, height_m=top - base, surfaces=tuple(surfaces)))
    rest = tri[owner < 0]
    obstacles = list(site.obstacles)
    if len(rest):
        low = rest.reshape(-1, 3)
        where = shapely.MultiPoint(low[:, :2]).convex_hull.buffer(0.2, quad_segs=2)
        obstacles.append(
            Obstacle(
                "mesh-structures", where, float(np.ptp(low[:, 2])) + 0.1, "structure", mesh=rest
            )
        )
    terrain = site.terrain
    if terrain is None:  # the ground the mesh's buildings stand on (their ground faces)
        terrain = _model_terrain(
            _Model([], [], [], None, p.name), [b for b in buildings if b.surfaces], None
        )
    return replace(
        site,
        buildings=buildings,
        obstacles=obstacles,
        terrain=terrain,
        warnings=list(site.warnings),
    )
