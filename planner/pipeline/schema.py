"""The plan's output tables — their columns, each list written once — and the writers every
file and download uses: CSV (:func:`to_csv`, text cells made inert for spreadsheets) and the
layered GeoJSON of a plan (:func:`geojson`, which the DXF and KML writers read too).

The table builders that fill these columns are in :mod:`planner.pipeline.tables`; the files
are rendered and written by :mod:`planner.pipeline.export`.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
import pandas as pd
import shapely

if TYPE_CHECKING:
    from planner.pipeline.result import Plan

__all__ = [
    "COVERAGE_COLUMNS",
    "FACADE_TABLE_COLUMNS",
    "KIT_COLUMNS",
    "LINK_COLUMNS",
    "MEETING_COLUMNS",
    "METRIC_KEYS",
    "OPTIONAL_COVERAGE_COLUMNS",
    "ROUTE_COLUMNS",
    "STAKEOUT_COLUMNS",
    "STATION_COLUMNS",
    "STATION_ID",
    "STATION_PURPOSES",
    "SYMBOLS",
    "TARGET_COLUMNS",
    "ZONE_COLUMNS",
    "geojson",
    "geometry_json",
    "id_key",
    "in_id_order",
    "neutralise",
    "to_csv",
]

#: Why a station is in the plan (the ``purpose`` column of the stations), in the words of the
#: summary and of the map's legend, in the order they are listed.
STATION_PURPOSES = {
    "hand": "placed by hand",
    "best-effort": "best effort, for samples no position meets",
    "cover": "to cover",
    "link": "to link the network",
    "registration": "for the registration error",
    "traverse": "a total-station set-up of a traverse (planned control)",
}

#: The stations: where (site CRS), the ground's height there and the instrument's above it
#: (the scanner's centre is at ``ground_z + instrument_height_m``, in the site's height
#: system; ``ground_z`` is 0 on flat ground), and why the station is in the plan.
STATION_COLUMNS = ["station_id", "x", "y", "ground_z", "instrument_height_m", "purpose"]

#: A scanner station's id: S01, S02 … in visiting order (beyond 99, more digits).
STATION_ID = "S{:02d}"

#: The symbol of each kind of point on every map: the dashboard, the booklet and the drawing
#: (DXF) speak one symbol language.
SYMBOLS = {
    "station": "triangle-up",
    "flat": "square",
    "sphere": "circle",
    "control": "triangle-down",
}

#: Per-pair quantities reported for chosen stations (besides ``score``, ``view``, ``ok``).
METRIC_KEYS = (
    "distance_m",
    "slope_distance_m",
    "gamma_deg",
    "nu_deg",
    "incidence_deg",
    "m_x_mm",
    "m_y_mm",
    "m_z_mm",
    "spacing_mm",
    "scanner_m_x_mm",
    "scanner_m_y_mm",
    "scanner_m_z_mm",
    "reg_m_x_mm",
    "reg_m_y_mm",
    "reg_m_z_mm",
)

#: coverage.csv: the sample, its station, the totals of its metrics, whether it meets its
#: requirement, the scanner's and the registration's parts, the spacing and why not met.
COVERAGE_COLUMNS = [
    "building_id",
    "facade_id",
    "sample_id",
    "x",
    "y",
    "z",
    "station_id",
    *(k for k in METRIC_KEYS if k != "spacing_mm" and not k.startswith(("scanner", "reg"))),
    "meets",
    "model",
    *(k for k in METRIC_KEYS if k.startswith(("scanner", "reg"))),
    "spacing_mm",
    "reason",
    "elevated_station",
    "zone",
]


#: Columns written only when the plan has them (an accuracy class was asked for).
OPTIONAL_COVERAGE_COLUMNS = ["class_achieved"]


#: The zones as planned: where, the requirement inside, the sample spacing there [m], and
#: how many of its samples (not on party walls) meet it.
ZONE_COLUMNS = ["zone_id", "where", "requirement", "sample_spacing_m", "samples", "met", "unmet"]

#: The target list: where (site CRS; z the centre's height in the site's height system),
#: which type, the smallest size its stations need and the item placed, the rule that sized
#: it, the stations using it, the wall it is on and which way it faces (azimuth of the
#: normal), its centre's RMS [mm].
TARGET_COLUMNS = [
    "target_id",
    "x",
    "y",
    "z",
    "type",
    "min_size_mm",
    "size_mm",
    "item",
    "sized_by",
    "station_ids",
    "facade_id",
    "facing_deg",
    "centre_rms_mm",
]
#: The registrations (station_b registered to station_a, or to the control network): common
#: targets usable by both, targets placed, the link's own predicted error at station_b's
#: facade points [mm], its geometry's strength — ``dilution``, that error over the RMS of
#: one target's centre difference (like a DOP: how much the targets' layout magnifies their
#: errors out at the facades; lower is stronger) — and the whole registration error
#: station_b's points end with [mm].
LINK_COLUMNS = [
    "station_a",
    "station_b",
    "common_targets",
    "targets_placed",
    "target_ids",
    "link_rms_mm",
    "dilution",
    "station_b_rms_mm",
    "kind",
    "overlap_pct",
    "weakest_direction",
]

#: The per-facade summary as a surveyor reads it (dashboard, report).
FACADE_TABLE_COLUMNS = [
    "building_id",
    "length_m",
    "samples",
    "party_wall_samples",
    "met",
    "unmet",
    "worst_m_x_mm",
    "worst_m_y_mm",
    "worst_m_z_mm",
    "stations",
]


#: route.csv: one row per station in visiting order.
ROUTE_COLUMNS = [
    "order",
    "station_id",
    "x",
    "y",
    "session",
    "walk_m",
    "walk_min",
    "targets_to_set",
    "targets_min",
    "targets_to_collect",
    "collect_min",
    "targets_standing",
    "setup_min",
    "sector_start_deg",
    "sector_deg",
    "preset",
    "step_mm_at_10m",
    "scan_points_million",
    "scan_min",
    "imaging_min",
    "station_min",
    "elapsed_min",
    "max_spacing_mm",
    "links_to",
    "registers_to",
    "walk_note",
]


#: The kit: per item of the inventory, how many the crew has, how many the plan uses and
#: how many stand at once at most (leap-frogged along the visiting order), and where.
KIT_COLUMNS = ["item", "type", "size_mm", "owned", "used", "most_at_once", "at_station"]

#: The stake-out file a controller imports: point id, easting, northing, height, code.
STAKEOUT_COLUMNS = ["point_id", "easting", "northing", "height", "code"]


#: The columns of :func:`meeting_table`.
MEETING_COLUMNS = ["facade_id", "sample_id", "x", "y", "z", "station_id", "own", "needed"]


#: A text cell starting with one of these is a formula to a spreadsheet (CSV injection).
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def neutralise(value: object) -> object:
    """A text that a spreadsheet would run as a formula, made inert with a leading
    apostrophe (OWASP's advice for CSV injection); anything else unchanged.

    Examples
    --------
    >>> [neutralise(v) for v in ("=1+2", "@SUM(A1)", "main-f01", -3.5)]
    ["'=1+2", "'@SUM(A1)", 'main-f01', -3.5]
    """
    if isinstance(value, str) and value.startswith(_FORMULA_START):
        return "'" + value
    return value


def in_id_order(df: pd.DataFrame, column: str) -> pd.DataFrame:
    """The rows in the order of their ids as a surveyor reads a list: by the text before the
    id's number, then the number (S02 before S10, K01-S03 before K02-S01).

    >>> in_id_order(pd.DataFrame({"id": ["S10", "TS1", "S02"]}), "id")["id"].tolist()
    ['S02', 'S10', 'TS1']
    """
    ids = df[column].astype(str).tolist()
    return df.iloc[sorted(range(len(df)), key=lambda k: id_key(ids[k]))]


def id_key(text: str) -> tuple[str, int, str]:
    """The sort key of an id as a surveyor reads a list (:func:`in_id_order`)."""
    m = re.fullmatch(r"(.*?)(\d+)", text)
    return (m.group(1), int(m.group(2)), text) if m else (text, -1, text)


def to_csv(df: pd.DataFrame) -> str:
    """A table as CSV: 3 decimals (1 mm), text cells neutralised (:func:`neutralise`)."""
    out = df.copy()
    for col in out.select_dtypes(include=["object", "string"]).columns:
        out[col] = out[col].map(neutralise)
    return out.to_csv(index=False, float_format="%.3f")


def geometry_json(geom: Any) -> dict:
    """A shapely geometry as a GeoJSON geometry (coordinates to the millimetre)."""
    return json.loads(shapely.to_geojson(shapely.set_precision(geom, 0.001)))


def _columns(row: Any, columns: Sequence[str], skip: Sequence[str] = ()) -> dict[str, Any]:
    """A table row's columns (one of the column lists) as a feature's properties, those in
    ``skip`` (the geometry's) left out; a list (a target's stations) ";"-joined, as the
    CSV writes it."""
    out = {}
    for c in columns:
        if c in skip:
            continue
        v = getattr(row, c)  # a column the table lacks is a bug: said, not written empty
        out[c] = ";".join(map(str, v)) if isinstance(v, list | tuple) else v
    return out


def _clean(props: dict[str, Any]) -> dict[str, Any]:
    out = {}
    for k, v in props.items():
        if isinstance(v, np.generic):
            v = v.item()
        if isinstance(v, float) and not math.isfinite(v):
            v = None
        elif isinstance(v, float):
            v = round(v, 3)
        out[k] = v
    return out


def _ground_of(p: Plan):
    """The plan's ground heights, a function of points (P, 2)."""
    if p.workbench is not None:
        return p.workbench.ctx.scene.ground_z
    from planner.pipeline.scene import Scene

    return Scene(p.site).ground_z


def wall_rings(p: Plan) -> list[list[np.ndarray]]:
    """Every facade of the plan in 3-D, from its outline on its elevation
    (``outline_wkt``): per facade its rings (exterior first), each (n, 3) [m] in the site's
    CRS and height system."""
    from planner.pipeline.facades import on_facade

    out = []
    for r in p.facades.itertuples():
        rings = []
        for poly in shapely.get_parts(shapely.from_wkt(r.outline_wkt)):
            for ring in [poly.exterior, *poly.interiors]:
                uh = np.asarray(ring.coords)
                n = len(uh)
                xy, z = on_facade(
                    np.tile([r.x0, r.y0], (n, 1)),
                    np.tile([r.x1, r.y1], (n, 1)),
                    np.full(n, r.normal_z),
                    np.full(n, r.z0),
                    np.full(n, r.base_z),
                    uh[:, 0],
                    uh[:, 1],
                )
                rings.append(np.column_stack([xy, z]))
        out.append(rings)
    return out


def geojson(p: Plan) -> dict:
    """Buildings, obstacles, no-go areas, facades, stations, links, targets and unmet samples
    as one GeoJSON FeatureCollection (a ``layer`` property on every feature)."""
    feats: list[dict] = []

    def add(geom: dict, **props: Any) -> None:
        feats.append({"type": "Feature", "geometry": geom, "properties": _clean(props)})

    for b in p.site.buildings:
        add(
            geometry_json(b.footprint),
            layer="building",
            building_id=b.id,
            height_m=b.height_m,
            planned=b.planned,
            name=b.name,
        )
    for o in p.site.obstacles:
        add(
            geometry_json(o.geometry),
            layer="obstacle",
            obstacle_id=o.id,
            kind=o.kind,
            height_m=o.height_m,
        )
    for a in p.site.no_go:
        add(geometry_json(a.geometry), layer="no-go", area_id=a.id)
    for g in p.site.passages:
        add(
            geometry_json(g.geometry),
            layer="passage",
            passage_id=g.id,
            clear_height_m=g.clear_height_m,
        )
    for r in p.facades.itertuples():
        add(
            {"type": "LineString", "coordinates": [[r.x0, r.y0], [r.x1, r.y1]]},
            layer="facade",
            building_id=r.building_id,
            facade_id=r.facade_id,
            length_m=r.length_m,
            samples=r.samples,
            party_wall_samples=r.party_wall_samples,
            met=r.met,
            unmet=r.unmet,
            stations=r.stations,
        )
    three_d = p.site.is_3d  # heights in the site's system: 3-D coordinates, ground said
    if three_d:
        for f, shape in enumerate(wall_rings(p)):
            r = p.facades.iloc[f]
            add(
                {"type": "Polygon", "coordinates": [np.round(ring, 3).tolist() for ring in shape]},
                layer="wall",
                building_id=r.building_id,
                facade_id=r.facade_id,
                met=r.met,
                unmet=r.unmet,
            )
    ground = _ground_of(p) if three_d else None
    st = p.stations.set_index("station_id")
    for r in p.stations.itertuples():
        extra = {}
        coords = [r.x, r.y]
        if three_d:  # the scanner's centre
            coords.append(round(r.ground_z + r.instrument_height_m, 3))
            extra["ground_z"] = r.ground_z
        add(
            {"type": "Point", "coordinates": coords},
            layer="station",
            **_columns(r, STATION_COLUMNS, ("x", "y", "ground_z")),
            samples_met=r.samples_met,
            **extra,
        )
    tg = p.targets.set_index("target_id")
    for r in p.links.itertuples():
        b = st.loc[r.station_b]
        if r.station_a == "control":  # tied to the control points it uses: a line to each
            ends = [tg.loc[t] for t in r.target_ids.split(";") if t in tg.index]
            geom = {
                "type": "MultiLineString",
                "coordinates": [[[b.x, b.y], [c.x, c.y]] for c in ends],
            }
        else:
            a = st.loc[r.station_a]
            geom = {"type": "LineString", "coordinates": [[a.x, a.y], [b.x, b.y]]}
        add(geom, layer="link", **_columns(r, LINK_COLUMNS))
    t_ground = ground(p.targets[["x", "y"]].to_numpy(float)) if three_d else None
    for k, r in enumerate(p.targets.itertuples()):
        extra = {"ground_z": float(t_ground[k])} if three_d else {}
        add(
            {"type": "Point", "coordinates": [r.x, r.y, r.z]},
            layer="target",
            **extra,
            **_columns(r, TARGET_COLUMNS, ("x", "y", "z")),
        )
    if p.route is not None:
        t = p.route.table
        for n, leg in enumerate(p.route.legs[1:], start=1):
            add(
                {"type": "LineString", "coordinates": np.round(leg, 3).tolist()},
                layer="route",
                order=int(t["order"].iloc[n]),
                station_a=t["station_id"].iloc[n - 1],
                station_b=t["station_id"].iloc[n],
                walk_m=float(t["walk_m"].iloc[n]),
                session=int(t["session"].iloc[n]),
                walk_note=t["walk_note"].iloc[n],
            )
    u_ground = ground(p.unmet[["x", "y"]].to_numpy(float)) if three_d else None
    for k, r in enumerate(p.unmet.itertuples()):
        extra = {"ground_z": float(u_ground[k])} if three_d else {}
        add(
            {"type": "Point", "coordinates": [r.x, r.y, r.z]},
            layer="unmet",
            **extra,
            building_id=r.building_id,
            facade_id=r.facade_id,
            sample_id=r.sample_id,
            reason=r.reason,
        )
    out: dict[str, Any] = {
        "type": "FeatureCollection",
        "name": f"tls-planner plan: {p.site.name}",
        "accuracy_model": p.settings.model_description(),
    }
    if (model := p.registration_model()) is not None:  # and what it assumes of the software
        from planner.pipeline.requirements import REGISTRATION_PROCESSING

        processing = REGISTRATION_PROCESSING[p.settings.registration_processing]
        out["registration_model"] = f"{model}, {processing}"
    if p.site.crs:
        out["crs"] = {"type": "name", "properties": {"name": p.site.crs}}
    out["features"] = feats
    return out
