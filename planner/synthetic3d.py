"""Synthetic LoD2 city models for tests and benchmarks: buildings shaped like real ones
(gable, hip and mansard roofs with eaves of 0.5–1 m, dormers, balconies, a set-back top
storey, a lower wing built against the main body), on a sloping terrain, with trees — as a
CityJSON 2.0 document with semantic surfaces, read by :mod:`planner.cityio` like any
model. The same seed gives the same model.

The same town drawn as footprints with their highest point (:func:`footprints_geojson`) is
what a plan made without the model sees: the comparison the planner's audit makes
(:func:`planner.pipeline.geometry.audit.audit_plan`).

>>> model = lod2_town(4, seed=1)
>>> sorted({o["type"] for o in model["CityObjects"].values()})
['Building', 'BuildingInstallation', 'BuildingPart', 'SolitaryVegetationObject', 'TINRelief']
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from planner.mesh import crown_triangles

__all__ = ["ROOFS", "TOWN_CRS", "footprints_geojson", "lod2_town", "write_model"]

#: The roof shapes of the generated buildings.
ROOFS = ("gable", "hip", "mansard", "flat")
#: The CRS of the generated models (ETRS89 / UTM 32N) and where they lie [m].
TOWN_CRS = "EPSG:25832"
ORIGIN = np.array([690_000.0, 5_336_000.0, 500.0])
#: Their CRS as CityJSON names it: ETRS89 / UTM 32N with DHHN2016 heights (an OGC compound).
REFERENCE_SYSTEM = (
    "https://www.opengis.net/def/crs-compound?1=https://www.opengis.net/def/crs/EPSG/0/25832"
    "&2=https://www.opengis.net/def/crs/EPSG/0/7837"
)

Ring = np.ndarray  # (n, 3)


@dataclass
class _Part:
    """A building part's surfaces as ``(semantic type, rings)``."""

    id: str
    type: str  # Building, BuildingPart, BuildingInstallation
    surfaces: list[tuple[str, list[Ring]]]
    parent: str | None = None


def _rect(x0: float, x1: float, y0: float, y1: float, z: float, up: bool) -> Ring:
    r = np.array([[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]], float)
    return r if up else r[::-1]


def _box(x0, x1, y0, y1, z0, z1, wall="WallSurface", top="RoofSurface", bottom="GroundSurface"):
    """A closed box's surfaces (outward, counter-clockwise seen from outside)."""
    out = [(bottom, [_rect(x0, x1, y0, y1, z0, False)]), (top, [_rect(x0, x1, y0, y1, z1, True)])]
    c = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    for (ax, ay), (bx, by) in zip(c, c[1:] + c[:1], strict=True):
        out.append((wall, [np.array([[ax, ay, z0], [bx, by, z0], [bx, by, z1], [ax, ay, z1]])]))
    return out


def _long_wall(hw: float, hd: float, z0: float, z1: float, sy: int) -> Ring:
    """The rectangular wall at ``y = sy·hd`` from ``z0`` to ``z1``, facing outward."""
    r = np.array([[-hw, sy * hd, z0], [hw, sy * hd, z0], [hw, sy * hd, z1], [-hw, sy * hd, z1]])
    return r if sy < 0 else r[::-1]


def _end_wall(hw: float, hd: float, z0: float, z1: float, sx: int) -> Ring:
    """The rectangular wall at ``x = sx·hw`` from ``z0`` to ``z1``, facing outward."""
    r = np.array([[sx * hw, -hd, z0], [sx * hw, hd, z0], [sx * hw, hd, z1], [sx * hw, -hd, z1]])
    return r if sx > 0 else r[::-1]


def _pitched(
    w: float, d: float, z0: float, eave: float, roof: str, pitch_deg: float, over: float, rng
):
    """Walls, roof and ground of a ``w`` × ``d`` body (x: −w/2…w/2, y: −d/2…d/2) with its
    base at ``z0`` and eaves at ``eave`` [m], the roof overhanging the walls by ``over``."""
    t = math.tan(math.radians(pitch_deg))
    hw, hd = w / 2, d / 2
    out: list[tuple[str, list[Ring]]] = [("GroundSurface", [_rect(-hw, hw, -hd, hd, z0, False)])]
    zo = eave - over * t  # the roof's edge, lower than the eaves by the overhang's drop
    if roof == "gable":  # ridge along x
        ridge = eave + hd * t
        for sx in (-1, 1):  # gable walls: pentagons
            pts = [
                [sx * hw, -hd, z0],
                [sx * hw, hd, z0],
                [sx * hw, hd, eave],
                [sx * hw, 0, ridge],
                [sx * hw, -hd, eave],
            ]
            r = np.array(pts, float)
            out.append(("WallSurface", [r if sx > 0 else r[::-1]]))
        for sy in (-1, 1):
            out.append(("WallSurface", [_long_wall(hw, hd, z0, eave, sy)]))
            ro = np.array(
                [
                    [-hw - over, sy * (hd + over), zo],
                    [hw + over, sy * (hd + over), zo],
                    [hw + over, 0, ridge],
                    [-hw - over, 0, ridge],
                ]
            )
            out.append(("RoofSurface", [ro if sy < 0 else ro[::-1]]))
        return out, ridge
    if roof == "hip":
        ridge = eave + hd * t
        inset = hd  # the hips rise at the same pitch: the ridge stops hd short of each end
        for sy in (-1, 1):
            out.append(("WallSurface", [_long_wall(hw, hd, z0, eave, sy)]))
            ro = np.array(
                [
                    [-hw - over, sy * (hd + over), zo],
                    [hw + over, sy * (hd + over), zo],
                    [hw - inset, 0, ridge],
                    [-hw + inset, 0, ridge],
                ]
            )
            out.append(("RoofSurface", [ro if sy < 0 else ro[::-1]]))
        for sx in (-1, 1):
            out.append(("WallSurface", [_end_wall(hw, hd, z0, eave, sx)]))
            ro = np.array(
                [
                    [sx * (hw + over), -hd - over, zo],
                    [sx * (hw + over), hd + over, zo],
                    [sx * (hw - inset), 0, ridge],
                ]
            )
            out.append(("RoofSurface", [ro if sx > 0 else ro[::-1]]))
        return out, ridge
    if roof == "mansard":  # a steep lower storey (its walls slope) under a gentle roof
        steep = 2.8  # height of the sloping storey [m]
        inset = steep / math.tan(math.radians(72.0))
        top = eave + steep
        ridge = top + (hd - inset) * math.tan(math.radians(20.0))
        for sy in (-1, 1):
            out.append(("WallSurface", [_long_wall(hw, hd, z0, eave, sy)]))
            s = np.array(
                [
                    [-hw, sy * hd, eave],
                    [hw, sy * hd, eave],
                    [hw - inset, sy * (hd - inset), top],
                    [-hw + inset, sy * (hd - inset), top],
                ]
            )
            out.append(("WallSurface", [s if sy < 0 else s[::-1]]))  # the sloping wall
            ro = np.array(
                [
                    [-hw + inset, sy * (hd - inset), top],
                    [hw - inset, sy * (hd - inset), top],
                    [hw - inset, 0, ridge],
                    [-hw + inset, 0, ridge],
                ]
            )
            out.append(("RoofSurface", [ro if sy < 0 else ro[::-1]]))
        for sx in (-1, 1):
            out.append(("WallSurface", [_end_wall(hw, hd, z0, eave, sx)]))
            s = np.array(
                [
                    [sx * hw, -hd, eave],
                    [sx * hw, hd, eave],
                    [sx * (hw - inset), hd - inset, top],
                    [sx * (hw - inset), -hd + inset, top],
                ]
            )
            out.append(("WallSurface", [s if sx > 0 else s[::-1]]))
            g = np.array(
                [
                    [sx * (hw - inset), -hd + inset, top],
                    [sx * (hw - inset), hd - inset, top],
                    [sx * (hw - inset), 0, ridge],
                ]
            )
            out.append(("WallSurface", [g if sx > 0 else g[::-1]]))
        return out, ridge
    raise ValueError(roof)


def _dormer(hd: float, eave: float, pitch_deg: float, x: float, width: float) -> list:
    """A gabled dormer on the +y roof slope of a gable roof, centred at ``x``."""
    t = math.tan(math.radians(pitch_deg))
    y0 = hd - 1.5  # its front wall stands 1.5 m in from the eaves
    z_foot = eave + (hd - y0) * t
    h = 1.6
    z_top = z_foot + h
    y_back = hd - 1.5 - (h / t)  # where its top meets the roof
    hw = width / 2
    front = np.array(
        [
            [x + hw, y0, z_foot],
            [x - hw, y0, z_foot],
            [x - hw, y0, z_top],
            [x, y0, z_top + 0.6],
            [x + hw, y0, z_top],
        ]
    )
    out = [("WallSurface", [front])]
    for sx in (-1, 1):  # the cheeks: triangles down to the roof
        c = np.array(
            [[x + sx * hw, y0, z_foot], [x + sx * hw, y_back, z_top], [x + sx * hw, y0, z_top]]
        )
        out.append(("WallSurface", [c if sx > 0 else c[::-1]]))
        ro = np.array(
            [
                [x + sx * hw, y0 + 0.3, z_top - 0.1],
                [x + sx * hw, y_back, z_top],
                [x, y_back, z_top + 0.6],
                [x, y0 + 0.3, z_top + 0.6],
            ]
        )
        out.append(("RoofSurface", [ro if sx < 0 else ro[::-1]]))
    return out


def _balcony(face_y: float, x: float, z: float, width: float = 3.0, depth: float = 1.2) -> list:
    """A balcony on the wall at ``y = face_y`` (facing −y): a slab and its parapet."""
    slab = _box(
        x - width / 2,
        x + width / 2,
        face_y - depth,
        face_y,
        z,
        z + 0.2,
        "WallSurface",
        "OuterFloorSurface",
        "OuterCeilingSurface",
    )
    rail = _box(
        x - width / 2, x + width / 2, face_y - depth, face_y - depth + 0.1, z + 0.2, z + 1.1
    )
    return slab + rail


def _placed(surfaces: list, angle: float, at: np.ndarray) -> list:
    c, s = math.cos(angle), math.sin(angle)
    rot = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    return [(t, [r @ rot.T + at for r in rings]) for t, rings in surfaces]


def _terrain_z(xy: np.ndarray, slope: float, direction: float) -> np.ndarray:
    return slope * (xy[..., 0] * math.cos(direction) + xy[..., 1] * math.sin(direction))


def lod2_town(
    n_buildings: int = 6,
    seed: int = 0,
    *,
    slope: float = 0.10,
    trees: int | None = None,
    gap_m: tuple[float, float] = (8.0, 16.0),
) -> dict:
    """A CityJSON 2.0 document of ``n_buildings`` LoD2 buildings in two rows along a street,
    on terrain rising by ``slope`` (10 %: 1 m in 10) across it, with ``trees`` trees
    (default one per building) along the street. The roofs cycle through :data:`ROOFS`;
    pitched roofs overhang by 0.5–1 m, every other gable has two dormers, flat-roofed
    buildings carry a set-back top storey (a BuildingPart), every third building a lower
    wing built against it (a BuildingPart) and some balconies (installations)."""
    rng = np.random.default_rng(seed)
    parts: list[_Part] = []
    direction = math.radians(60.0)
    ends = [0.0, 4.0]  # where each row's last building ends along the street [m]
    for i in range(n_buildings):
        row = i % 2
        w, d = float(rng.uniform(10, 18)), float(rng.uniform(9, 13))
        wing_m = 6.5 if i % 3 == 2 else 0.0
        cx = ends[row] + float(rng.uniform(*gap_m)) + w / 2 + 1.0
        ends[row] = cx + w / 2 + wing_m + 1.0
        cy = -(d / 2 + 10.0) if row == 0 else d / 2 + 10.0  # a 20 m street between the rows
        angle = float(rng.uniform(-0.08, 0.08)) + (0.0 if row == 0 else math.pi)
        at2 = np.array([cx, cy])
        corners = np.array([[-w / 2, -d / 2], [w / 2, -d / 2], [w / 2, d / 2], [-w / 2, d / 2]])
        rot = np.array([[math.cos(angle), -math.sin(angle)], [math.sin(angle), math.cos(angle)]])
        base = float(_terrain_z(corners @ rot.T + at2, slope, direction).min())
        at = np.array([cx, cy, base])
        storeys = int(rng.integers(2, 5))
        eave = storeys * 3.0
        roof = ROOFS[i % len(ROOFS)]
        bid = f"B{i + 1:02d}"
        surfaces: list = []
        if roof == "flat":
            surfaces = _box(-w / 2, w / 2, -d / 2, d / 2, 0.0, eave)
            parts.append(_Part(bid, "Building", []))
            parts.append(_Part(f"{bid}-main", "BuildingPart", _placed(surfaces, angle, at), bid))
            top = [
                s
                for s in _box(-w / 2 + 2, w / 2 - 2, -d / 2 + 2, d / 2 - 2, eave, eave + 3.0)
                if s[0] != "GroundSurface"
            ]
            parts.append(_Part(f"{bid}-top", "BuildingPart", _placed(top, angle, at), bid))
        else:
            over = float(rng.uniform(0.5, 1.0))
            pitch = float(rng.uniform(35, 50)) if roof != "mansard" else 0.0
            surfaces, _ = _pitched(w, d, 0.0, eave, roof, pitch, over, rng)
            if roof == "gable" and i % 4 == 0:
                for dx in (-w / 4, w / 4):
                    surfaces += _dormer(d / 2, eave, pitch, dx, 1.8)
            parts.append(_Part(bid, "Building", _placed(surfaces, angle, at)))
        if i % 3 == 2:  # a lower wing against the +x gable
            ww, wd, wh = 6.0, d * 0.6, max(3.5, eave - 2.5)
            wing = [s for s in _box(w / 2, w / 2 + ww, -wd / 2, wd / 2, 0.0, wh)]
            parts.append(_Part(f"{bid}-wing", "BuildingPart", _placed(wing, angle, at), bid))
        if i % 2 == 1 and storeys >= 3:  # balconies on the street side (−y)
            for bx in (-w / 4, w / 4):
                parts.append(
                    _Part(
                        f"{bid}-balcony-{len(parts)}",
                        "BuildingInstallation",
                        _placed(_balcony(-d / 2, bx, 3.0), angle, at),
                        bid,
                    )
                )
    length = max(ends) + 20.0
    n_trees = n_buildings if trees is None else trees
    tree_objs = []
    for k in range(n_trees):
        tx = float(rng.uniform(5, length - 5))
        ty = float(rng.choice([-4.0, 4.0]))
        tz = float(_terrain_z(np.array([tx, ty]), slope, direction))
        h = float(rng.uniform(7, 13))
        crown = crown_triangles((tx, ty), float(rng.uniform(2, 3.5)), tz + 0.35 * h, tz + h)
        trunk = _placed(_box(-0.2, 0.2, -0.2, 0.2, 0.0, 0.35 * h), 0.0, np.array([tx, ty, tz]))
        tris = [("", [t]) for t in crown] + [("", r) for _, r in trunk]
        tree_objs.append((f"T{k + 1:02d}", tris, h))
    return _document(parts, tree_objs, _relief(length, slope, direction))


def _relief(length: float, slope: float, direction: float) -> list[Ring]:
    """The terrain as triangles of a 5 m grid over the town and 150 m around."""
    xs = np.arange(-150.0, length + 150.0 + 1e-9, 5.0)
    ys = np.arange(-150.0, 150.0 + 1e-9, 5.0)
    gx, gy = np.meshgrid(xs, ys)
    z = _terrain_z(np.stack([gx, gy], axis=-1), slope, direction)
    p = np.stack([gx, gy, z], axis=-1)
    a, b, c, d = (
        p[:-1, :-1].reshape(-1, 3),
        p[:-1, 1:].reshape(-1, 3),
        p[1:, 1:].reshape(-1, 3),
        p[1:, :-1].reshape(-1, 3),
    )
    return [t for t in np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)])]


def _document(parts: list[_Part], trees: list, relief: list[Ring]) -> dict:
    """The CityJSON document (vertices shared, quantised to millimetres)."""
    verts: dict[tuple[int, int, int], int] = {}
    scale = 0.001

    def vid(p: np.ndarray) -> int:
        key = tuple(round(v / scale) for v in (p + ORIGIN).tolist())
        if key not in verts:
            verts[key] = len(verts)
        return verts[key]

    def multisurface(surfaces: list, lod: str) -> dict:
        bounds, values, types = [], [], []
        for typ, rings in surfaces:
            bounds.append([[vid(q) for q in r] for r in rings])
            if typ:
                if typ not in types:
                    types.append(typ)
                values.append(types.index(typ))
            else:
                values.append(None)
        g = {"type": "MultiSurface", "lod": lod, "boundaries": bounds}
        if types:
            g["semantics"] = {"surfaces": [{"type": t} for t in types], "values": values}
        return g

    objs: dict[str, dict] = {}
    for p in parts:
        o: dict = {
            "type": p.type,
            "geometry": [multisurface(p.surfaces, "2.2")] if p.surfaces else [],
        }
        if p.parent:
            o["parents"] = [p.parent]
            objs[p.parent].setdefault("children", []).append(p.id)
        objs[p.id] = o
    for tid, tris, h in trees:
        objs[tid] = {
            "type": "SolitaryVegetationObject",
            "attributes": {"height": round(h, 2)},
            "geometry": [multisurface(tris, "2")],
        }
    objs["terrain"] = {
        "type": "TINRelief",
        "geometry": [
            {
                "type": "CompositeSurface",
                "lod": "1",
                "boundaries": [[[vid(q) for q in t]] for t in relief],
            }
        ],
    }
    v = np.array(list(verts), dtype=np.int64)
    origin = v.min(axis=0)
    return {
        "type": "CityJSON",
        "version": "2.0",
        "transform": {"scale": [scale] * 3, "translate": (origin * scale).tolist()},
        "metadata": {"referenceSystem": REFERENCE_SYSTEM, "title": "synthetic LoD2 town"},
        "CityObjects": objs,
        "vertices": (v - origin).tolist(),
    }


def write_model(model: dict, path: str | Path) -> Path:
    """Write a model (:func:`lod2_town`) as a CityJSON file."""
    p = Path(path)
    p.write_text(json.dumps(model, separators=(",", ":")), encoding="utf-8")
    return p


def footprints_geojson(model: dict) -> dict:
    """The model's buildings as footprints with their highest point, as a GeoJSON site
    (:func:`planner.cityio.footprints_of`)."""
    from planner.cityio import footprints_of, site_from_cityjson

    return footprints_of(site_from_cityjson(model))
