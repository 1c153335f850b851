"""Reading a BIM model (IFC) as a site: its buildings' shells as 3-D surfaces.

An IFC file (ISO 16739, the STEP physical file ``.ifc``) is what an architect or a
scan-to-BIM client hands over, and what research planners of laser scanning start from
(Noichl, Lichti & Borrmann, "Automating adaptive image generation for medium-scale scan
planning from building information models", Automation in Construction 161, 2024,
https://doi.org/10.1016/j.autcon.2024.105341). IfcOpenShell (https://ifcopenshell.org, the
optional extra ``tls-planner[ifc]``) reads it and turns every element's shape into
triangles in world coordinates (metres); this module classes them and hands them to the
city models' assembly (:mod:`planner.cityio`), so an IFC building is planned as a LoD3
model is:

* each ``IfcBuilding`` is a building; the elements contained in it (through its storeys)
  are its surfaces; elements of no building (an ``IfcSite``'s terrain, furniture outside)
  only block the beam;
* a window (``IfcWindow``) is glass (not demanded), a door (``IfcDoor``) a door, a roof
  (``IfcRoof``, a slab or covering of type ``ROOF``) roof where it faces up; spaces,
  openings, furniture and the building services are not surfaces at all;
* a face is the building's outside where the ground beside it, a little in front of it, is
  outside the building's outline; a face inside the outline (a wall's inner side, an inner
  wall) is ``interior``: no beam from outside reaches it, none is demanded;
* the model's georeferencing (IFC4's ``IfcMapConversion`` to an ``IfcProjectedCRS``) places
  it in its map CRS; without one it is read in its own local metres, and said.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import shapely

from planner.errors import InputError

__all__ = ["IFC_SUFFIXES", "read_ifc_model"]

#: File name endings read as IFC.
IFC_SUFFIXES = (".ifc",)
#: Element classes that are no surface of a building (inside, virtual or services).
SKIPPED_CLASSES = (
    "IfcSpace",
    "IfcOpeningElement",
    "IfcVirtualElement",
    "IfcFurnishingElement",
    "IfcDistributionElement",
    "IfcAnnotation",
    "IfcGrid",
    "IfcTransportElement",
)
#: A face is the building's outside where the ground this far in front of it is outside
#: the building's outline [m] (walls are 0.1–0.5 m thick: their inner side probes inside).
OUTSIDE_PROBE_M = 0.05
#: A model of more triangles than this is refused: simplify it or export the shell only.
MAX_IFC_TRIANGLES = 2_000_000


def _kind_of(element: Any) -> str | None:
    """The surface kind an element's faces take (None: skipped; "": by its normal)."""
    if any(element.is_a(c) for c in SKIPPED_CLASSES):
        return None
    if element.is_a("IfcWindow"):
        return "window"
    if element.is_a("IfcDoor"):
        return "door"
    predefined = str(getattr(element, "PredefinedType", "") or "")
    plate = element.is_a("IfcSlab") or element.is_a("IfcCovering")
    if element.is_a("IfcRoof") or (plate and predefined in ("ROOF", "ROOFING")):
        return "roof"
    return ""


def _building_of(element: Any) -> Any | None:
    """The ``IfcBuilding`` an element belongs to (through its container and the spatial
    decomposition), or None."""
    import ifcopenshell.util.element as ue

    node = ue.get_container(element) or ue.get_aggregate(element)
    for _ in range(64):  # (a cycle in a broken file ends here)
        if node is None or node.is_a("IfcBuilding"):
            return node
        node = ue.get_aggregate(node) or ue.get_container(node)
    return None


def _map_conversion(model: Any) -> tuple[Any, str | None]:
    """The function placing the model's world coordinates (n, 3) in its map CRS (IFC4's
    ``IfcMapConversion``: E = E₀ + s(x cos θ − y sin θ), N = N₀ + s(x sin θ + y cos θ),
    H = H₀ + z; ISO 16739-1:2018, 8.18.3.7), and the CRS's name; ``(None, None)`` without."""
    try:
        conversions = model.by_type("IfcMapConversion")
    except RuntimeError:  # IFC2x3 has no such entity
        return None, None
    if not conversions:
        return None, None
    mc = conversions[0]
    e0, n0 = float(mc.Eastings or 0.0), float(mc.Northings or 0.0)
    h0 = float(mc.OrthogonalHeight or 0.0)
    a, o = float(mc.XAxisAbscissa or 1.0), float(mc.XAxisOrdinate or 0.0)
    s = float(mc.Scale or 1.0)
    if not all(math.isfinite(v) for v in (e0, n0, h0, a, o, s)) or s <= 0 or math.hypot(a, o) == 0:
        raise InputError("the IFC model's IfcMapConversion holds numbers that are not a placement")
    theta = math.atan2(o, a)
    c, sn = math.cos(theta), math.sin(theta)
    name = getattr(mc.TargetCRS, "Name", None) if mc.TargetCRS is not None else None

    def place(p: np.ndarray) -> np.ndarray:
        x, y, z = p[:, 0], p[:, 1], p[:, 2]
        return np.column_stack([e0 + s * (x * c - y * sn), n0 + s * (x * sn + y * c), h0 + z])

    return place, (str(name) if name else None)


def _shapes(model: Any, name: str) -> list[tuple[Any, np.ndarray]]:
    """Every element with a shape and its triangles (T, 3, 3) in world coordinates [m], in
    the order of their ids (the same on any machine)."""
    import ifcopenshell.geom

    settings = ifcopenshell.geom.settings()
    settings.set("use-world-coords", True)
    out: list[tuple[Any, np.ndarray]] = []
    total = 0
    it = ifcopenshell.geom.iterator(settings, model, 1)
    if not it.initialize():
        return out
    while True:
        shape = it.get()
        verts = np.asarray(shape.geometry.verts, dtype=float).reshape(-1, 3)
        faces = np.asarray(shape.geometry.faces, dtype=np.int64).reshape(-1, 3)
        total += len(faces)
        if total > MAX_IFC_TRIANGLES:
            raise InputError(
                f"{name} has more than {MAX_IFC_TRIANGLES:,} triangles; export the building's "
                "shell (walls, roofs, windows, doors) or simplify the model first"
            )
        if len(faces):
            out.append((model.by_id(shape.id), verts[faces]))
        if not it.next():
            break
    out.sort(key=lambda item: item[0].id())
    return out


#: A building whose slabs and roofs seen from above cover less than this share of the area
#: its walls enclose is read as walls alone: its outline is what they enclose.
SLABS_COVER = 0.5


def _outline(tri: np.ndarray) -> Any:
    """A building's outline: the union of its triangles seen from above — slabs and roofs
    give the area, walls seen edge on a strip each, a courtyard stays open; for a model of
    walls alone (slabs and roofs covering less than :data:`SLABS_COVER` of what the walls
    enclose), what they enclose."""
    flat = [shapely.Polygon(t[:, :2]) for t in tri]
    flat = [p for p in flat if p.is_valid and p.area > 1e-6]
    if not flat:
        return shapely.Polygon()
    union = shapely.union_all(flat, grid_size=0.001)
    filled = shapely.union_all(
        [shapely.Polygon(p.exterior) for p in shapely.get_parts(union) if p.geom_type == "Polygon"]
    )
    return union if union.area >= SLABS_COVER * filled.area else filled


def _ground(outline: Any, z: float) -> list[np.ndarray]:
    """The outline as ground triangles at height ``z`` [m], each facing down (the
    building's ground outline for the assembly)."""
    from planner.mesh import cap

    return [t[::-1] for t in cap(outline, z)]


def _classed(kind: str, tri: np.ndarray, outline: Any) -> list[tuple[str, np.ndarray]]:
    """Each triangle with its kind: ``interior`` where a point a little in front of it (in
    plan) lies inside the building's outline, else ``kind`` — but a window's or door's
    frame top or bottom is classed by its normal — and ``floor`` for an upward face of an
    element that is not roof (a slab's top)."""
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    length = np.linalg.norm(n, axis=1)
    good = length > 1e-12
    n = n[good] / length[good, None]
    tri = tri[good]
    centre = tri.mean(axis=1)
    horizontal = np.hypot(n[:, 0], n[:, 1])
    probe = centre[:, :2] + OUTSIDE_PROBE_M * n[:, :2] / np.maximum(horizontal, 1e-9)[:, None]
    inside = (horizontal > 0.5) & shapely.contains_xy(outline, probe[:, 0], probe[:, 1])
    out = []
    for t, nz, inner in zip(tri, n[:, 2], inside, strict=True):
        k = "" if kind in ("window", "door") and abs(nz) > 0.5 else kind  # a frame's top
        if inner:
            out.append(("interior", t))
        elif k == "" and nz > 0.5:
            out.append(("floor", t))  # a slab's top: a walkable top, not roof (unless one)
        else:
            out.append((k, t))
    return out


def read_ifc_model(path: Path, crs: str | None = None) -> tuple[list, str | None, list[str]]:
    """The buildings of an IFC file as city objects for :func:`planner.cityio.assemble`
    (one ``Building`` per ``IfcBuilding``, each face a surface with its kind), the model's
    CRS (``crs`` wins) and what was noted."""
    from planner.cityio import _Object

    try:
        import ifcopenshell
    except ImportError:
        raise InputError(
            f"{path.name}: reading IFC needs IfcOpenShell — install the planner's IFC extra "
            "(pip install 'tls-planner[ifc]'), or export the model as CityGML or a mesh"
        ) from None
    try:
        model = ifcopenshell.open(str(path))
    except Exception as exc:  # IfcOpenShell raises its own errors for a broken file
        raise InputError(
            f"{path.name}: not an IFC model IfcOpenShell reads ({type(exc).__name__}: "
            f"{str(exc)[:200]})"
        ) from None
    notes: list[str] = []
    place, model_crs = _map_conversion(model)
    if place is None:
        notes.append(
            f"{path.name}: the IFC model has no georeferencing (IfcMapConversion): read in its "
            "own local metres — give the site's CRS and place it in a georeferenced export"
        )
    per_building: dict[Any, list[tuple[str, np.ndarray]]] = {}
    loose: list[np.ndarray] = []
    for element, tri in _shapes(model, path.name):
        kind = _kind_of(element)
        if kind is None:
            continue
        tri = place(tri.reshape(-1, 3)).reshape(-1, 3, 3) if place is not None else tri
        if not np.isfinite(tri).all():
            raise InputError(f"{path.name}: element {element.GlobalId} has no finite shape")
        b = _building_of(element)
        if b is None:
            loose.append(tri)
            continue
        per_building.setdefault(b, []).append((kind, tri))
    objects = []
    for b, parts in per_building.items():
        everything = np.concatenate([t for _, t in parts])
        outline = _outline(everything)
        o = _Object(str(b.GlobalId), "Building", name=str(b.Name or ""))
        for kind, tri in parts:
            for k, t in _classed(kind, tri, outline):
                o.add("3", k or None, [t])
        for t in _ground(outline, float(everything[:, :, 2].min())):
            o.add("3", "ground", [t])
        objects.append(o)
    if loose:
        o = _Object("ifc-site-elements", "GenericCityObject")
        for t in np.concatenate(loose):
            o.add("3", None, [t])
        objects.append(o)
    if not per_building:
        raise InputError(
            f"{path.name}: no element of the IFC model belongs to an IfcBuilding (walls, "
            "roofs, windows contained in its storeys); is it a site or infrastructure model?"
        )
    return objects, crs or model_crs, notes
