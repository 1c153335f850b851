"""Field and CAD deliverables of a plan: DXF (``ezdxf``), KML (WGS 84) and a stake-out file.

All three are drawn from the plan's GeoJSON features (:func:`planner.pipeline.export.geojson`),
so every output shows the same stations, targets, links and unmet samples at the same
coordinates: real coordinates in the site's CRS, no local shift (KML: longitude/latitude).
"""

from __future__ import annotations

import contextlib
import io
import math
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from typing import Any

import numpy as np

from planner.pipeline.result import Plan
from planner.pipeline.route import view_sectors
from planner.pipeline.schema import STAKEOUT_COLUMNS, geojson, geometry_json, to_csv

__all__ = ["DXF_LAYERS", "dxf_text", "kml_text", "stakeout_csv"]

#: DXF layer of each GeoJSON layer, with its AutoCAD colour index.
DXF_LAYERS = {
    "building": ("BUILDINGS", 7),
    "obstacle": ("OBSTACLES", 3),
    "no-go": ("NO-GO", 1),
    "passage": ("PASSAGES", 2),
    "boundary": ("BOUNDARY", 8),
    "facade": ("FACADES", 9),
    "station": ("STATIONS", 5),
    "target": ("TARGETS", 6),
    "link": ("LINKS", 4),
    "unmet": ("UNMET", 1),
    "sector": ("VIEW-SECTORS", 140),
    "route": ("ROUTE", 30),
    "info": ("PLAN-INFO", 7),
}


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


def dxf_text(p: Plan) -> str:
    """The plan as a DXF drawing (R2010, metres) in the site's coordinates: a layer per kind
    (:data:`DXF_LAYERS`); stations and targets as blocks with attributes (station: ID,
    HEIGHT, PURPOSE; target: ID, TYPE, SIZE_MM, FACADE, FACING_DEG); links, unmet samples,
    view sectors; the CRS, scanner and requirement on PLAN-INFO."""
    import ezdxf  # heavy: only when a DXF is written
    from ezdxf.enums import TextEntityAlignment

    with _same_bytes(ezdxf):  # ezdxf stamps its metadata when the document is made
        doc = ezdxf.new("R2010", setup=True)
    doc.units = ezdxf.units.M
    for name, colour in DXF_LAYERS.values():
        doc.layers.add(name, color=colour)
    station = doc.blocks.new("STATION")
    station.add_circle((0, 0), 0.4)
    station.add_line((-0.6, 0), (0.6, 0))
    station.add_line((0, -0.6), (0, 0.6))
    for n, tag in enumerate(("ID", "HEIGHT", "PURPOSE")):
        station.add_attdef(tag, (0.6, 0.2 - 0.6 * n), dxfattribs={"height": 0.5})
    target = doc.blocks.new("TARGET")
    target.add_lwpolyline([(0, 0.35), (-0.3, -0.2), (0.3, -0.2)], close=True)
    for n, tag in enumerate(("ID", "TYPE", "SIZE_MM", "FACADE", "FACING_DEG")):
        target.add_attdef(tag, (0.4, 0.1 - 0.4 * n), dxfattribs={"height": 0.3})
    msp = doc.modelspace()
    for f in _features(p):
        props, geom = f["properties"], f["geometry"]
        layer = DXF_LAYERS[props["layer"]][0]
        if props["layer"] == "station":
            x, y = geom["coordinates"][:2]
            ref = msp.add_blockref("STATION", (x, y, 0.0), dxfattribs={"layer": layer})
            ref.add_auto_attribs(
                {
                    "ID": props["station_id"],
                    "HEIGHT": f"{props['instrument_height_m']:.3f}",
                    "PURPOSE": props["purpose"],
                }
            )
        elif props["layer"] == "target":
            x, y, z = geom["coordinates"]
            ref = msp.add_blockref("TARGET", (x, y, z), dxfattribs={"layer": layer})
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
        else:
            closed = geom["type"] in ("Polygon", "MultiPolygon")
            for ring in _rings(geom):
                msp.add_lwpolyline(
                    [tuple(c[:2]) for c in ring], close=closed, dxfattribs={"layer": layer}
                )
    if p.site.boundary is not None:
        for ring in _rings(geometry_json(p.site.boundary)):
            msp.add_lwpolyline([tuple(c[:2]) for c in ring], dxfattribs={"layer": "BOUNDARY"})
    st = p.stations.set_index("station_id")
    for sid, (start, end, radius) in view_sectors(p.stations, p.coverage, p.targets).items():
        pts = _sector_points(st.at[sid, "x"], st.at[sid, "y"], start, end, radius)
        msp.add_lwpolyline(pts, close=True, dxfattribs={"layer": "VIEW-SECTORS"})
    x0, y0 = _lower_left(p)
    msp.add_text(_info(p), height=1.0, dxfattribs={"layer": "PLAN-INFO"}).set_placement(
        (x0, y0 - 3.0), align=TextEntityAlignment.LEFT
    )
    stream = io.StringIO()
    with _same_bytes(ezdxf):  # … and its header dates when it is written
        doc.write(stream)
    return stream.getvalue()


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
    import shapely

    xy = shapely.get_coordinates([b.footprint for b in p.site.buildings])
    return float(xy[:, 0].min()), float(xy[:, 1].min())


def _info(p: Plan) -> str:
    crs = p.site.crs or "no CRS given (local metres)"
    return (
        f"tls-planner plan of {p.site.name}; coordinates: {crs}; scanner {p.scanner.name}; "
        f"required {p.requirements.describe()}"
    )


def _wgs84(p: Plan, coords: np.ndarray) -> np.ndarray:
    from planner.crs import to_wgs84

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
        _kml_geometry(p, mark, geom)
    ET.indent(kml)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(kml, encoding="unicode") + "\n"


def _kml_geometry(p: Plan, parent: ET.Element, geom: dict) -> None:
    kind, c = geom["type"], geom["coordinates"]
    if kind == "Point":
        xyz = np.asarray([c], dtype=float)
        pt = ET.SubElement(parent, "Point")
        z = xyz[:, 2] if xyz.shape[1] > 2 else None
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
    """Stations and targets to set out: point id, easting, northing, height and code
    (:data:`STAKEOUT_COLUMNS`), in the site's CRS; height above the site's ground (a
    station: its ground mark, 0; a target: its centre)."""
    import pandas as pd

    rows: list[dict[str, Any]] = [
        {
            "point_id": r.station_id,
            "easting": r.x,
            "northing": r.y,
            "height": 0.0,
            "code": "TRV" if r.purpose == "traverse" else "STN",
        }
        for r in p.stations.itertuples()
    ]
    rows += [
        {
            "point_id": r.target_id,
            "easting": r.x,
            "northing": r.y,
            "height": r.z,
            "code": {"sphere": "TGT-SPHERE", "flat": "TGT-FLAT", "control": "CTL"}.get(
                r.type, f"TGT-{str(r.type).upper()}"
            ),
        }
        for r in p.targets.itertuples()
    ]
    df = pd.DataFrame(rows, columns=STAKEOUT_COLUMNS).round(
        {"easting": 3, "northing": 3, "height": 3}
    )
    return to_csv(df)
