"""The surfaces of a 3-D building, and the rule of which of them a plan demands.

A city model (CityJSON, CityGML; :mod:`planner.cityio`) gives each building as planar
polygons in 3-D, each with its semantic type. The planner keeps them as :class:`Surface`
(kind, rings, the building part it belongs to) on the :class:`~planner.site.Building`;
the facades to scan are the wall surfaces as they are — gables, set-back storeys, the
sloping walls of a mansard — and the scene the beams are cast against is every surface.

The semantic types of CityGML 2.0 / 3.0 (Gröger, Kolbe, Nagel & Häfele, "OGC City
Geography Markup Language (CityGML) Encoding Standard 2.0", OGC 12-019, 2012;
Kolbe, Kutzner, Smyth, Nagel, Roensdorf & Heazel, "OGC City Geography Markup Language
(CityGML) 3.0 Conceptual Model", OGC 20-010, 2021) and CityJSON (Ledoux et al.,
"CityJSON: a compact and easy-to-use encoding of the CityGML data model", Open
Geospatial Data, Software and Standards 4, 2019, https://doi.org/10.1186/s40965-019-0064-0)
map to the kinds of :data:`SEMANTIC_KINDS`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from planner.mesh import newell_normal, thin_rings, triangle_areas, triangulate

__all__ = [
    "KINDS",
    "SEMANTIC_KINDS",
    "Surface",
    "demanded_kinds",
    "kind_by_normal",
    "level_roof",
]

#: The planner's surface kinds: what a beam meets and what a plan may demand.
KINDS = (
    "wall",
    "roof",
    "ground",
    "ceiling",  # the underside of an overhang (eaves, an arcade): OuterCeilingSurface
    "floor",  # a walkable top that is not roof (a terrace, a balcony): OuterFloorSurface
    "window",
    "door",
    "installation",  # balconies, dormer cheeks, chimneys given as installations
    "closure",  # virtual: closes a volume (an open carport's side); no beam stops on it
    "interior",  # inside the building: no beam from outside reaches it
)

#: CityGML / CityJSON semantic surface types → :data:`KINDS`.
SEMANTIC_KINDS = {
    "WallSurface": "wall",
    "RoofSurface": "roof",
    "GroundSurface": "ground",
    "OuterCeilingSurface": "ceiling",
    "OuterFloorSurface": "floor",
    "Window": "window",
    "WindowSurface": "window",
    "Door": "door",
    "DoorSurface": "door",
    "ClosureSurface": "closure",
    "InteriorWallSurface": "interior",
    "CeilingSurface": "interior",
    "FloorSurface": "interior",
    "BuildingInstallation": "installation",
    "BuildingConstructiveElement": "installation",
}

#: Kinds no beam stops on (left out of the scene).
SEETHROUGH = ("closure", "interior")


def demanded_kinds(roofs: bool = False) -> tuple[str, ...]:
    """The surface kinds whose points a plan demands — the rule, written once: walls and
    doors; roofs only when asked (they need an elevated station); never windows (glass
    returns no point or a mirrored one) nor what is not facade (ground, eaves' undersides,
    installations, closure and interior surfaces).

    >>> demanded_kinds()
    ('wall', 'door')
    >>> demanded_kinds(roofs=True)
    ('wall', 'door', 'roof')
    """
    return ("wall", "door", "roof") if roofs else ("wall", "door")


#: A roof within this of level is not sampled: no station on the ground sees it [deg].
LEVEL_ROOF_DEG = 1.0


def level_roof(surface: Surface) -> bool:
    """Whether ``surface`` is a level roof (within :data:`LEVEL_ROOF_DEG`)."""
    return surface.kind == "roof" and surface.normal[2] > np.cos(np.radians(LEVEL_ROOF_DEG))


#: A surface whose normal is within this of horizontal is a wall when its file does not say
#: [sin of the angle from horizontal]: sin 30° — a mansard's steep lower roof is a wall
#: only where the model says so.
WALL_NZ = 0.5


def kind_by_normal(normal_z: float, z_min: float, base_z: float) -> str:
    """The kind of an unclassified surface (a model without semantics, a plain mesh): a
    wall where its normal is near horizontal (:data:`WALL_NZ`), ground where it faces down
    at the building's base (within 0.5 m), the underside of an overhang where it faces down
    above it, else roof.

    >>> kind_by_normal(0.0, 3.0, 0.0), kind_by_normal(-1.0, 0.1, 0.0), kind_by_normal(0.7, 9.0, 0.0)
    ('wall', 'ground', 'roof')
    """
    if abs(normal_z) < WALL_NZ:
        return "wall"
    if normal_z < 0:
        return "ground" if z_min - base_z <= 0.5 else "ceiling"
    return "roof"


@dataclass(frozen=True, eq=False)
class Surface:
    """A planar polygon of a building: its ``kind`` (:data:`KINDS`), ``rings`` (exterior
    then holes, each (n, 3) [m], counter-clockwise seen from outside), the building part it
    belongs to (``part``, "" for the building itself) and its id in the file, if any."""

    kind: str
    rings: tuple[np.ndarray, ...]
    part: str = ""
    id: str = ""
    lod: str = field(default="", compare=False)

    def __post_init__(self) -> None:
        # a ring of very many vertices in line (a hostile or over-densified model) is kept
        # by its vertices that matter, within a millimetre (planner.mesh.thin_rings)
        object.__setattr__(self, "rings", thin_rings(self.rings))

    @cached_property
    def normal(self) -> np.ndarray:
        """The outward unit normal (3,) (Newell's, from the exterior ring)."""
        return newell_normal(self.rings[0])

    @cached_property
    def triangles(self) -> np.ndarray:
        """The polygon as triangles (T, 3, 3)."""
        return triangulate(self.rings)

    @property
    def area_m2(self) -> float:
        return float(triangle_areas(self.triangles).sum())

    @property
    def z_range(self) -> tuple[float, float]:
        z = self.rings[0][:, 2]
        return float(z.min()), float(z.max())
