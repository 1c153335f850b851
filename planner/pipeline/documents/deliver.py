"""Field and CAD deliverables of a plan: DXF (``ezdxf``), KML (WGS 84) and a stake-out file.

All three are drawn from the plan's GeoJSON features
(:func:`planner.pipeline.documents.export.geojson`), so every output shows the same stations,
targets, links and unmet samples at the same coordinates: real coordinates in the site's CRS, no
local shift (KML: longitude/latitude).
"""

from __future__ import annotations

import contextlib
import io
import math
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from typing import Any

import numpy as np
import pandas as pd
import shapely

from planner.crs import to_wgs84
from planner.pipeline.documents.geojson import geojson, geometry_json
from planner.pipeline.engine.result import Plan
from planner.pipeline.field.route import view_sectors
from planner.pipeline.inputs.schema import (
    STAKEOUT_COLUMNS,
    SYMBOLS,
    in_id_order,
    to_csv,
)

__all__ = ["DXF_LAYERS", "dxf_text", "kml_text", "stakeout_csv"]

#: DXF layer of each GeoJSON layer, with its AutoCAD colour index (and the label layers).
DXF_LAYERS = {
    "building": ("BUILDINGS", 7),
    "building-label": ("BUILDING-LABELS", 7),
    "obstacle": ("OBSTACLES", 3),
    "no-go": ("NO-GO", 1),
    "passage": ("PASSAGES", 2),
    "boundary": ("BOUNDARY", 8),
    "facade": ("FACADES", 9),
    "wall": ("WALLS-3D", 9),
    "station": ("STATIONS", 5),
    "target": ("TARGETS", 6),
    "link": ("LINKS", 4),
    "unmet": ("UNMET", 1),
    "sector": ("VIEW-SECTORS", 140),
    "route": ("ROUTE", 30),
    "info": ("PLAN-INFO", 7),
}
#: The attributes of a target's block (the ID shown, the others hidden).
TARGET_TAGS = ("ID", "TYPE", "SIZE_MM", "FACADE", "FACING_DEG")
#: Layers off when the drawing opens (there to switch on: they swamp a plan on screen).
DXF_LAYERS_OFF = ("VIEW-SECTORS",)
#: Text height and symbol size on paper [mm] at the drawing scale: a station's ID reads as
#: 2.5 mm lettering (ISO 3098), its symbol 3 mm across.
TEXT_MM = 2.5
SYMBOL_MM = 3.0
#: A dash of the dashed layers on paper [mm].
LINE_DASH_MM = 5.0
#: Linetype of a layer, where not continuous.
DXF_LINETYPES = {"ROUTE": "DASHED", "LINKS": "DASHDOT", "PASSAGES": "DASHED"}


def _features(p: Plan) -> list[dict]:
    return geojson(p)["features"]


def _rings(geom: dict) -> list[list[list[float]]]:
    """Every ring or line of a GeoJSON geometry (polygons: exterior and holes)."""
    kind, c = geom["type"], geom["coordinates"]
    if kind == "Polygon":
        return c
    if kind == "MultiPolygon":
        return [ring for poly in c for ring in poly]
    if kind == "LineString":
        return [c]
    if kind == "MultiLineString":
        return c
    return []


def _sector_points(x, y, start, end, radius, step_deg=5.0) -> list[tuple[float, float]]:
    span = (end - start) % 360.0
    n = max(2, math.ceil(span / step_deg) + 1)
    az = np.radians(start + np.linspace(0.0, span, n))
    arc = [(x + radius * math.sin(a), y + radius * math.cos(a)) for a in az]
    return [(x, y), *arc, (x, y)]


def _symbol(block: Any, shape: str, size: float) -> None:
    """Draw a map symbol (:data:`~planner.pipeline.inputs.schema.SYMBOLS`) ``size`` across,
    centred on the block's origin, with a point at the exact position."""
    h = size / 2
    if shape == "circle":
        block.add_circle((0, 0), h)
    elif shape == "square":
        block.add_lwpolyline([(-h, -h), (h, -h), (h, h), (-h, h)], close=True)
    else:  # an equilateral triangle, point up or down
        k = 1.0 if shape == "triangle-up" else -1.0
        block.add_lwpolyline(
            [(0, k * h), (-0.866 * h, -k * h / 2), (0.866 * h, -k * h / 2)], close=True
        )
    block.add_point((0, 0))


def dxf_text(p: Plan) -> str:
    """The plan as a DXF drawing (R2010, metres) in the site's coordinates, for the drawing
    scale 1:``p.settings.drawing_scale``: a layer per kind (:data:`DXF_LAYERS`, view sectors
    off); stations and targets as blocks in the maps' symbols (station ▲, flat target ■,
    sphere ●, control ▼) with attributes, the ID shown at 2.5 mm on paper, the rest (station:
    HEIGHT, PURPOSE; target: TYPE, SIZE_MM, FACADE, FACING_DEG) carried but hidden;
    buildings labelled with their id and height; links, unmet samples, view sectors, route;
    the CRS, scanner and requirement on PLAN-INFO; the header's extents set (zoom extents)."""
    import ezdxf  # heavy: only when a DXF is written

    doc, paper = _dxf_document(ezdxf, p.settings.drawing_scale)
    msp = doc.modelspace()
    drawn = [  # the points placed of what the plan is about (the extents: see _framed)
        placed
        for f in _features(p)
        if len(placed := _draw_feature(msp, f, paper)) and _framed(f["properties"])
    ]
    drawn += _draw_site_and_sectors(msp, p, paper)
    _frame(msp, p, drawn, paper)
    stream = io.StringIO()
    with _same_bytes(ezdxf):  # … and its header dates when it is written
        doc.write(stream)
    return stream.getvalue()


def _dxf_document(ezdxf: Any, drawing_scale: float) -> tuple[Any, float]:
    """A new DXF document (metres) with the plan's layers, linetype scale and symbol blocks
    (drawn in paper millimetres, inserted at the scale); and the metres on the ground per
    millimetre on paper."""
    with _same_bytes(ezdxf):  # ezdxf stamps its metadata when the document is made
        doc = ezdxf.new("R2010", setup=True)
    doc.units = ezdxf.units.M
    for name, colour in DXF_LAYERS.values():
        layer = doc.layers.add(name, color=colour, linetype=DXF_LINETYPES.get(name, "Continuous"))
        if name in DXF_LAYERS_OFF:
            layer.off()
    paper = drawing_scale / 1000.0  # metres on the ground per mm on paper
    # ezdxf's DASHED is 1.27 units of dash and 0.254 of gap: 5 mm dashes on paper
    doc.header["$LTSCALE"] = paper * LINE_DASH_MM / 1.27
    for name, shape, tags in (
        ("STATION", SYMBOLS["station"], ("ID", "HEIGHT", "PURPOSE")),
        ("TARGET-FLAT", SYMBOLS["flat"], TARGET_TAGS),
        ("TARGET-SPHERE", SYMBOLS["sphere"], TARGET_TAGS),
        ("CONTROL", SYMBOLS["control"], TARGET_TAGS),
    ):
        block = doc.blocks.new(name)  # drawn in paper millimetres, inserted at the scale
        size = SYMBOL_MM if name in ("STATION", "CONTROL") else 0.7 * SYMBOL_MM
        _symbol(block, shape, size)
        for n, tag in enumerate(tags):
            block.add_attdef(
                tag,
                (0.6 * SYMBOL_MM, 0.2 * TEXT_MM - 1.2 * TEXT_MM * n),
                dxfattribs={"height": TEXT_MM, "flags": 0 if tag == "ID" else 1},
            )
    return doc, paper


def _draw_feature(msp: Any, f: dict, paper: float) -> np.ndarray:
    """One GeoJSON feature of the plan into the model space, on its layer: stations and
    targets as blocks with attributes, walls as 3-D outlines, the rest as points and
    polylines. The points it placed (for the drawing's extents)."""
    scaled = {"xscale": paper, "yscale": paper, "zscale": paper}
    props, geom = f["properties"], f["geometry"]
    layer = DXF_LAYERS[props["layer"]][0]
    placed = shapely.get_coordinates(shapely.geometry.shape(geom))
    if props["layer"] == "station":  # at the scanner's centre where heights are known
        x, y, *z = geom["coordinates"]
        at = (x, y, z[0] if z else 0.0)
        ref = msp.add_blockref("STATION", at, dxfattribs={"layer": layer, **scaled})
        ref.add_auto_attribs(
            {
                "ID": props["station_id"],
                "HEIGHT": f"{props['instrument_height_m']:.3f}",
                "PURPOSE": props["purpose"],
            }
        )
    elif props["layer"] == "target":
        x, y, z = geom["coordinates"]
        name = {"flat": "TARGET-FLAT", "control": "CONTROL"}.get(props["type"], "TARGET-SPHERE")
        ref = msp.add_blockref(name, (x, y, z), dxfattribs={"layer": layer, **scaled})
        ref.add_auto_attribs(
            {
                "ID": props["target_id"],
                "TYPE": props["type"],
                "SIZE_MM": "" if props.get("size_mm") is None else f"{props['size_mm']:g}",
                "FACADE": props.get("facade_id") or "",
                "FACING_DEG": ""
                if props.get("facing_deg") is None
                else f"{props['facing_deg']:.0f}",
            }
        )
    elif geom["type"] == "Point":
        msp.add_point(tuple(geom["coordinates"]), dxfattribs={"layer": layer})
    elif props["layer"] == "wall":  # a wall of a 3-D building, at its outline in 3-D
        for ring in _rings(geom):
            msp.add_polyline3d([tuple(c) for c in ring], close=True, dxfattribs={"layer": layer})
    else:
        closed = geom["type"] in ("Polygon", "MultiPolygon")
        for ring in _rings(geom):
            msp.add_lwpolyline(
                [tuple(c[:2]) for c in ring], close=closed, dxfattribs={"layer": layer}
            )
    return placed


def _draw_site_and_sectors(msp: Any, p: Plan, paper: float) -> list[np.ndarray]:
    """The buildings' labels (id and height), the site's boundary and the stations' view
    sectors; the points they placed that frame the drawing (the planned buildings' labels,
    the sectors: see :data:`FRAMED_LAYERS`)."""
    from ezdxf.enums import TextEntityAlignment

    drawn: list[np.ndarray] = []
    for b in p.site.buildings:
        at = b.footprint.representative_point()
        height = (
            "no height"
            if b.height_m is None or not math.isfinite(b.height_m)
            else (f"{b.height_m:.1f} m")
        )
        msp.add_text(
            f"{b.id} {height}",
            height=TEXT_MM * paper,
            dxfattribs={"layer": "BUILDING-LABELS"},
        ).set_placement((at.x, at.y), align=TextEntityAlignment.MIDDLE_CENTER)
        if b.planned:
            drawn.append(np.array([[at.x, at.y]]))
    if p.site.boundary is not None:
        for ring in _rings(geometry_json(p.site.boundary)):
            msp.add_lwpolyline([tuple(c[:2]) for c in ring], dxfattribs={"layer": "BOUNDARY"})
    st = p.stations.set_index("station_id")
    for sid, (start, end, radius) in view_sectors(p.stations, p.coverage, p.targets).items():
        pts = _sector_points(st.at[sid, "x"], st.at[sid, "y"], start, end, radius)
        msp.add_lwpolyline(pts, close=True, dxfattribs={"layer": "VIEW-SECTORS"})
        drawn.append(np.asarray(pts, dtype=float)[:, :2])
    return drawn


#: Layers the drawing opens on (its extents): what the plan is about. The site's context —
#: buildings not planned, obstacles, no-go areas, passages, the boundary — is drawn but
#: does not widen the view (a city model's tile of 9 × 10 km opened on dots).
FRAMED_LAYERS = ("facade", "wall", "station", "target", "link", "unmet", "route")


def _framed(props: dict) -> bool:
    """Whether a feature sets the drawing's extents: a planned building, or a layer of
    :data:`FRAMED_LAYERS`."""
    layer = props.get("layer")
    return layer in FRAMED_LAYERS or (layer == "building" and bool(props.get("planned")))


def _frame(msp: Any, p: Plan, drawn: list[np.ndarray], paper: float) -> None:
    """The plan's information below all of it, and the header's extents (zoom extents
    works) from the points placed, a symbol's size round them and the information's line
    (a letter about 0.8 of its height wide), the drawing opened on them."""
    from ezdxf import zoom
    from ezdxf.enums import TextEntityAlignment

    xy = np.vstack([d[:, :2] for d in drawn if len(d)] or [np.array(_lower_left(p))[None]])
    (x0, y0), (x1, y1) = xy.min(axis=0), xy.max(axis=0)
    info, height = _info(p), TEXT_MM * paper  # the plan's information below all of it
    y_info = y0 - 2.0 * height
    msp.add_text(info, height=height, dxfattribs={"layer": "PLAN-INFO"}).set_placement(
        (x0, y_info), align=TextEntityAlignment.LEFT
    )
    # the header's extents (zoom extents works) from the points placed, a symbol's size
    # round them and the information's line (a letter about 0.8 of its height wide), and
    # the drawing opened on them
    margin = SYMBOL_MM * paper
    lo = (float(x0 - margin), float(y_info - margin), 0.0)
    hi = (float(max(x1, x0 + 0.8 * height * len(info)) + margin), float(y1 + margin), 0.0)
    msp.dxf.extmin, msp.dxf.extmax = lo, hi  # (written to the header's $EXTMIN, $EXTMAX)
    zoom.center(msp, ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2), (hi[0] - lo[0], hi[1] - lo[1]))


@contextlib.contextmanager
def _same_bytes(ezdxf: Any) -> Iterator[None]:
    """ezdxf's fixed creation metadata and dates: the same plan, the same DXF bytes."""
    saved = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        yield
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = saved


def _lower_left(p: Plan) -> tuple[float, float]:
    xy = shapely.get_coordinates([b.footprint for b in p.site.buildings])
    return float(xy[:, 0].min()), float(xy[:, 1].min())


def _info(p: Plan) -> str:
    crs = p.site.crs or "no CRS given (local metres)"
    return (
        f"tls-planner plan of {p.site.name}; coordinates: {crs}; scanner {p.scanner.name}; "
        f"required {p.requirements.describe()}"
    )


def _wgs84(p: Plan, coords: np.ndarray) -> np.ndarray:
    lon, lat = to_wgs84(p.site.crs, coords[:, 0], coords[:, 1])
    return np.column_stack([lon, lat])


def _kml_coords(lonlat: np.ndarray, z: np.ndarray | None = None) -> str:
    z = np.zeros(len(lonlat)) if z is None else z
    return " ".join(f"{lo:.9f},{la:.9f},{h:.3f}" for (lo, la), h in zip(lonlat, z, strict=True))


def kml_text(p: Plan) -> str | None:
    """Buildings, stations, targets and links for Google Earth and phones, in WGS 84
    longitude/latitude (KML 2.2, OGC 07-147r2). None when the site has no CRS."""
    if not p.site.crs:
        return None
    ns = "http://www.opengis.net/kml/2.2"
    kml = ET.Element("kml", xmlns=ns)
    doc = ET.SubElement(kml, "Document")
    ET.SubElement(doc, "name").text = f"tls-planner plan: {p.site.name}"
    ET.SubElement(doc, "description").text = _info(p)
    folders: dict[str, ET.Element] = {}
    for f in _features(p):
        props, geom = f["properties"], f["geometry"]
        layer = props["layer"]
        if layer not in (
            "building",
            "obstacle",
            "no-go",
            "passage",
            "station",
            "target",
            "link",
            "route",
        ):
            continue
        if layer not in folders:
            folders[layer] = ET.SubElement(doc, "Folder")
            ET.SubElement(folders[layer], "name").text = layer
        mark = ET.SubElement(folders[layer], "Placemark")
        ident = next((props[k] for k in props if k.endswith("_id") and props[k]), layer)
        if layer == "route":
            ident = f"{props['order']}: {props['station_a']} → {props['station_b']}"
        elif layer == "link":
            ident = f"{props['station_a']} → {props['station_b']}"
        ET.SubElement(mark, "name").text = str(ident)
        data = ET.SubElement(mark, "ExtendedData")
        for k, v in props.items():
            if v is None or k == "layer":
                continue
            item = ET.SubElement(data, "Data", name=k)
            ET.SubElement(item, "value").text = str(v)
        _kml_geometry(p, mark, geom, props.get("ground_z"))
    ET.indent(kml)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(kml, encoding="unicode") + "\n"


def _kml_geometry(p: Plan, parent: ET.Element, geom: dict, ground_z: float | None = None) -> None:
    """A GeoJSON geometry as KML, points at their height above the ground (``ground_z``:
    the ground's height under a point in the site's height system, where it is not 0)."""
    kind, c = geom["type"], geom["coordinates"]
    if kind == "Point":
        xyz = np.asarray([c], dtype=float)
        pt = ET.SubElement(parent, "Point")
        z = xyz[:, 2] - (ground_z or 0.0) if xyz.shape[1] > 2 else None
        if z is not None:
            ET.SubElement(pt, "altitudeMode").text = "relativeToGround"
        ET.SubElement(pt, "coordinates").text = _kml_coords(_wgs84(p, xyz), z)
        return
    if kind in ("Polygon", "MultiPolygon"):
        polys = [c] if kind == "Polygon" else c
        multi = ET.SubElement(parent, "MultiGeometry") if len(polys) > 1 else parent
        for poly in polys:
            el = ET.SubElement(multi, "Polygon")
            for n, ring in enumerate(poly):
                bound = ET.SubElement(el, "outerBoundaryIs" if n == 0 else "innerBoundaryIs")
                lr = ET.SubElement(ET.SubElement(bound, "LinearRing"), "coordinates")
                lr.text = _kml_coords(_wgs84(p, np.asarray(ring, dtype=float)))
        return
    lines = _rings(geom)
    multi = ET.SubElement(parent, "MultiGeometry") if len(lines) > 1 else parent
    for line in lines:
        ls = ET.SubElement(multi, "LineString")
        ET.SubElement(ls, "coordinates").text = _kml_coords(_wgs84(p, np.asarray(line)))


def stakeout_csv(p: Plan) -> str:
    """Stations and targets to set out (:data:`STAKEOUT_COLUMNS`), in the site's CRS and
    height system: a station at its ground mark (the terrain's height there, 0 on flat
    ground) with its instrument height above it, a target at its centre with the ground
    under it (:meth:`~planner.site.Site.ground_z`) and its height above that. Positions to
    the millimetre; heights too where the ground was measured (a DTM, the model's relief),
    to the decimetre where it is assumed (:func:`height_from`, said in ``height_from``)."""
    st = in_id_order(p.stations, "station_id")
    tg = in_id_order(p.targets, "target_id")
    ground = p.site.ground_z(tg[["x", "y"]].to_numpy(float))
    source, decimals = height_from(p.site)
    rows: list[dict[str, Any]] = [
        {
            "point_id": r.station_id,
            "easting": r.x,
            "northing": r.y,
            "height": r.ground_z,
            "code": "TRV" if r.purpose == "traverse" else "STN",
            "ground_z": r.ground_z,
            "above_ground_m": r.instrument_height_m,
            "height_from": source,
        }
        for r in st.itertuples()
    ]
    rows += [
        {
            "point_id": r.target_id,
            "easting": r.x,
            "northing": r.y,
            "height": r.z,
            "code": {"sphere": "TGT-SPHERE", "flat": "TGT-FLAT", "control": "CTL"}.get(
                r.type, f"TGT-{str(r.type).upper()}"
            )
            + ("-LVL" if getattr(r, "height_by", "") else ""),
            "ground_z": g,
            "above_ground_m": r.z - g,
            "height_from": source,
        }
        for r, g in zip(tg.itertuples(), ground, strict=True)
    ]
    if any(list(row) != STAKEOUT_COLUMNS for row in rows):  # a field left out is a bug
        raise ValueError(f"a stake-out row's fields differ from {STAKEOUT_COLUMNS}")
    table = pd.DataFrame(rows, columns=STAKEOUT_COLUMNS).round(3)  # to the millimetre
    return to_csv(table.round({"height": decimals, "ground_z": decimals}))


def height_from(site) -> tuple[str, int]:
    """Where a plan's heights come from, in words, and the decimals they are given to: the
    terrain model or relief (3: to the millimetre), the ground under a model's buildings
    joined across the streets (1: an assumption, to the decimetre), or none (3: heights above
    flat ground, 0 at every mark).

    >>> from planner.siteio import default_site
    >>> height_from(default_site())
    ('no terrain: heights above flat ground', 3)
    """
    t = site.terrain
    if t is None:
        return "no terrain: heights above flat ground", 3
    if not t.measured:
        return f"assumed: {t.source}; to 0.1 m", 1
    return t.source, 3
