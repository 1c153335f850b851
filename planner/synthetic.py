"""Synthetic towns for tests and benchmarks: streets, perimeter blocks of terraced buildings
with shared (party) walls around courtyards, mixed heights, and the small irregularity of
real footprints.

The shipped data stays small; larger sites are generated, the same for the same seed.

Examples
--------
>>> site = town(10, seed=0)
>>> len(site.buildings)
10
>>> sorted({round(b.height_m) for b in site.buildings})[:2]
[10, 13]
"""

from __future__ import annotations

import json
from itertools import pairwise

import numpy as np
import shapely
from shapely.affinity import rotate, translate
from shapely.geometry import Polygon, box

from planner.site import Building, Passage, Site

__all__ = ["GATEWAYS", "TOWN_CRS", "densified", "scattered", "town", "town_geojson"]

#: How a block's courtyard opens to the street: ``open`` — a gap between the buildings
#: (the footprints show it); ``passage`` — a gateway through a building's ground floor, as
#: real perimeter blocks have (the footprints close the ring; a :class:`~planner.site.Passage`
#: marks it); ``closed`` — no way in (the gateway not marked).
GATEWAYS = ("open", "passage", "closed")
#: Clear height of the generated gateways [m].
GATEWAY_HEIGHT_M = 3.5

#: Where the generated towns lie (a UTM-like projected frame) [m], and the CRS their files
#: are written in.
ORIGIN_EN = (400_000.0, 5_600_000.0)
TOWN_CRS = "EPSG:32633"


def town(
    n_buildings: int,
    seed: int = 0,
    *,
    block_m: tuple[float, float] = (60.0, 45.0),
    street_m: float = 16.0,
    depth_m: tuple[float, float] = (10.0, 14.0),
    frontage_m: tuple[float, float] = (9.0, 22.0),
    storeys: tuple[int, int] = (3, 7),
    gateway_m: float = 5.0,
    jitter_m: float = 0.3,
    max_turn_deg: float = 4.0,
    gateways: str = "open",
    gateways_per_block: int = 1,
) -> Site:
    """A town of ``n_buildings`` terraced buildings in perimeter blocks.

    Blocks of ``block_m`` (width, depth) [m] stand on a square grid of streets
    ``street_m`` wide. Each block is a ring of buildings ``depth_m`` deep around its
    courtyard, cut into lots of ``frontage_m`` along the street; neighbouring lots share
    their party wall exactly. ``gateways_per_block`` sides (one, or two opposite) of each
    block have a gateway of ``gateway_m`` into the courtyard, as ``gateways`` says
    (:data:`GATEWAYS`: a gap, a passage under a building, or none). Heights are ``storeys``
    × 3.2 m plus up to a metre. The block's corners
    are moved by up to ``jitter_m`` and the block turned by up to ``max_turn_deg`` (real
    footprints are never a perfect grid); party walls stay shared.

    Blocks are filled in order (row by row, over a square of blocks) until the town holds
    ``n_buildings``; the last block may be partial (its lots in order round the block).
    """
    if n_buildings < 1:
        raise ValueError("n_buildings must be at least 1")
    if gateways not in GATEWAYS or gateways_per_block not in (1, 2):
        raise ValueError(f"gateways is one of {GATEWAYS}, gateways_per_block 1 or 2")
    rng = np.random.default_rng(seed)
    buildings: list[Building] = []
    passages: list[Passage] = []
    n_side = 1
    while n_side * n_side * 10 < n_buildings:  # a block holds about 10 buildings
        n_side += 1
    pitch = (block_m[0] + street_m, block_m[1] + street_m)
    block = 0
    while len(buildings) < n_buildings:
        row, col = divmod(block, n_side)
        x0, y0 = ORIGIN_EN[0] + col * pitch[0], ORIGIN_EN[1] + row * pitch[1]
        lots, gates = _block_lots(
            rng,
            x0,
            y0,
            block_m,
            depth_m,
            frontage_m,
            gateway_m,
            jitter_m,
            cut=gateways == "open",
            n_gates=gateways_per_block,
        )
        centre = (x0 + block_m[0] / 2, y0 + block_m[1] / 2)
        turn = float(rng.uniform(-max_turn_deg, max_turn_deg))
        mine = []
        for k, lot in enumerate(lots):
            if len(buildings) == n_buildings:
                break
            lot = rotate(lot, turn, origin=centre)
            height = int(rng.integers(storeys[0], storeys[1] + 1)) * 3.2 + rng.uniform(0, 1)
            mine.append(Building(f"b{block:03d}-{k:02d}", lot, round(float(height), 2)))
        buildings += mine
        if gateways == "passage":
            for g, gate in enumerate(gates):
                gate = rotate(gate, turn, origin=centre)
                if any(b.footprint.intersects(gate) for b in mine):
                    passages.append(Passage(f"g{block:03d}-{g}", gate, GATEWAY_HEIGHT_M))
        block += 1
    return Site(buildings, name=f"town-{n_buildings}-seed{seed}", passages=passages)


def scattered(
    n_buildings: int = 49,
    n_groups: int = 12,
    seed: int = 0,
    *,
    spread_m: float = 3000.0,
    apart_m: float = 300.0,
    lot_m: float = 40.0,
    storeys: tuple[int, int] = (2, 6),
) -> Site:
    """One client's ``n_buildings`` free-standing buildings across a town, in ``n_groups``
    groups (a school's buildings, a yard, a lone house) at least ``apart_m`` apart inside a
    square of ``spread_m`` [m]: every group holds at least one building, the rest are shared
    out at random. A group's buildings stand on lots of ``lot_m`` in a row-by-row square,
    each 10–30 m by 8–20 m, turned by up to 20°, ``storeys`` × 3.2 m high plus up to a
    metre.
    """
    if n_groups < 1 or n_buildings < n_groups:
        raise ValueError("n_groups must be at least 1 and at most n_buildings")
    rng = np.random.default_rng(seed)
    centres: list[np.ndarray] = []
    while len(centres) < n_groups:  # dart throwing: groups at least apart_m apart
        c = rng.uniform(0.0, spread_m, size=2)
        if all(np.hypot(*(c - o)) >= apart_m + 2 * lot_m for o in centres):
            centres.append(c)
    sizes = np.ones(n_groups, dtype=int)
    np.add.at(sizes, rng.integers(0, n_groups, n_buildings - n_groups), 1)
    buildings: list[Building] = []
    for g, (centre, size) in enumerate(zip(centres, sizes, strict=True)):
        side = int(np.ceil(np.sqrt(size)))
        for k in range(size):
            row, col = divmod(k, side)
            x = ORIGIN_EN[0] + centre[0] + (col - (side - 1) / 2) * lot_m
            y = ORIGIN_EN[1] + centre[1] + (row - (side - 1) / 2) * lot_m
            w, d = rng.uniform(10.0, 30.0), rng.uniform(8.0, 20.0)
            fp = rotate(box(x - w / 2, y - d / 2, x + w / 2, y + d / 2), rng.uniform(-20, 20))
            height = int(rng.integers(storeys[0], storeys[1] + 1)) * 3.2 + rng.uniform(0, 1)
            fp = shapely.set_precision(fp, 0.01)
            buildings.append(Building(f"g{g:02d}-{k:02d}", fp, round(float(height), 2)))
    return Site(buildings, name=f"scattered-{n_buildings}-seed{seed}")


#: Slivers narrower than this (left by the gateway) are not buildings [m].
MIN_LOT_WIDTH_M = 4.0


def _narrowest_m(poly: Polygon) -> float:
    """The short side of the polygon's smallest enclosing rectangle [m]."""
    xy = np.asarray(shapely.oriented_envelope(poly).exterior.coords)[:3]
    return float(min(np.hypot(*(xy[1] - xy[0])), np.hypot(*(xy[2] - xy[1]))))


def _block_lots(
    rng: np.random.Generator,
    x0: float,
    y0: float,
    block_m: tuple[float, float],
    depth_m: tuple[float, float],
    frontage_m: tuple[float, float],
    gateway_m: float,
    jitter_m: float,
    *,
    cut: bool = True,
    n_gates: int = 1,
) -> tuple[list[Polygon], list[Polygon]]:
    """The lots of one block: four strips along the streets (each taking one corner, turning
    counter-clockwise), cut square to the street into lots, trimmed to the block's jittered
    outline; a gateway through the middle of one strip (or two opposite ones), cut out of
    the lots when ``cut``. Neighbouring lots share their cut. The lots and the gateways
    (reaching a metre past the block on both sides)."""
    w, d = block_m
    depth = float(rng.uniform(*depth_m))
    corners = np.array([(0, 0), (w, 0), (w, d), (0, d)], dtype=float)
    corners += rng.uniform(-jitter_m, jitter_m, size=corners.shape)
    outer = Polygon(corners + np.array([x0, y0]))
    m = 2.0  # the strips reach past the outline, which trims them
    # (start, end) along the strip and the strip's box as a function of (a, b)
    strips = [
        (0.0, w - depth, lambda a, b: (a, -m, b, depth)),  # south, with the SW corner
        (0.0, d - depth, lambda a, b: (w - depth, a, w + m, b)),  # east, SE corner
        (depth, w, lambda a, b: (a, d - depth, b, d + m)),  # north, NE corner
        (depth, d, lambda a, b: (-m, a, depth, b)),  # west, NW corner
    ]
    gate_side = int(rng.integers(0, 4))
    gate_sides = {gate_side, (gate_side + 2) % 4} if n_gates == 2 else {gate_side}
    lots, gates = [], []
    for side, (lo, hi, strip) in enumerate(strips):
        cuts = [lo]
        while hi - cuts[-1] > frontage_m[1]:
            cuts.append(cuts[-1] + float(rng.uniform(*frontage_m)))
        cuts.append(hi)
        if len(cuts) > 2 and cuts[-1] - cuts[-2] < frontage_m[0]:
            del cuts[-2]
        gate = None
        if side in gate_sides:
            mid = (lo + hi) / 2
            gate = translate(box(*strip(mid - gateway_m / 2, mid + gateway_m / 2)), x0, y0)
            gates.append(_through(gate, side))
        for a, b in pairwise(cuts):
            x_a, y_a, x_b, y_b = strip(a, b)
            lot = box(x0 + x_a, y0 + y_a, x0 + x_b, y0 + y_b).intersection(outer)
            if gate is not None and cut:
                lot = lot.difference(gate)
            for part in getattr(lot, "geoms", [lot]):
                if isinstance(part, Polygon) and _narrowest_m(part) >= MIN_LOT_WIDTH_M:
                    lots.append(shapely.set_precision(part, 0.01))
    return lots, gates


def _through(gate: Polygon, side: int) -> Polygon:
    """A gateway's box made to reach a metre into the courtyard (its strip's box ends at the
    courtyard side; a passage drawn through the whole building is what a map shows)."""
    x0, y0, x1, y1 = gate.bounds
    grow = {0: (0, 0, 0, 1), 1: (-1, 0, 0, 0), 2: (0, -1, 0, 0), 3: (0, 0, 1, 0)}[side]
    return box(x0 + grow[0], y0 + grow[1], x1 + grow[2], y1 + grow[3])


def town_geojson(site: Site) -> dict:
    """A generated town as a GeoJSON FeatureCollection the site readers take (in
    :data:`TOWN_CRS`): its buildings with their heights and its passages (role passage,
    their clear height) — for tests and benchmarks that plan it from a file."""

    def feature(props: dict, geom) -> dict:
        return {
            "type": "Feature",
            "properties": props,
            "geometry": json.loads(shapely.to_geojson(geom)),
        }

    feats = [feature({"id": b.id, "height": b.height_m}, b.footprint) for b in site.buildings]
    feats += [
        feature({"id": g.id, "role": "passage", "height": g.clear_height_m}, g.geometry)
        for g in site.passages
    ]
    crs = {"type": "name", "properties": {"name": TOWN_CRS}}
    return {"type": "FeatureCollection", "crs": crs, "features": feats}


def densified(corners: np.ndarray, per_edge: int) -> np.ndarray:
    """A closed outline through ``corners`` (K, 2) [m] drawn as ``per_edge`` equal edges
    along each side, as a traced or densified footprint is: (K × per_edge, 2) vertices, the
    ring not closed (corners in the order given; corners that cross give a bow-tie).

    >>> densified(np.array([[0, 0], [4, 0], [4, 2], [0, 2]]), 2).tolist()[:3]
    [[0.0, 0.0], [2.0, 0.0], [4.0, 0.0]]
    """
    a = np.asarray(corners, dtype=float)
    t = np.linspace(0.0, 1.0, per_edge, endpoint=False)[:, None]
    return np.vstack([p + t * (q - p) for p, q in zip(a, np.roll(a, -1, axis=0), strict=True)])
