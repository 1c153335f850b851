"""The plan's files: stations, targets, coverage and facades as CSV, everything as GeoJSON,
and the summary text — rendered here, written by :func:`save`.

The column lists below are the file contract (one place each).
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from planner.atomic import replace_folder_files
from planner.pipeline.deliver import dxf_text, kml_text, stakeout_csv
from planner.pipeline.result import LINK_COLUMNS, TARGET_COLUMNS, ZONE_COLUMNS, Plan
from planner.pipeline.route import ROUTE_COLUMNS
from planner.sitecheck import notes_table

__all__ = [
    "COVERAGE_COLUMNS",
    "LINK_COLUMNS",
    "STATION_COLUMNS",
    "TARGET_COLUMNS",
    "ZONE_COLUMNS",
    "coverage_csv",
    "geojson",
    "render",
    "save",
    "stations_csv",
    "targets_csv",
]

STATION_COLUMNS = ["station_id", "x", "y", "instrument_height_m", "purpose"]
COVERAGE_COLUMNS = [
    "building_id",
    "facade_id",
    "sample_id",
    "x",
    "y",
    "z",
    "station_id",
    "distance_m",
    "slope_distance_m",
    "gamma_deg",
    "nu_deg",
    "incidence_deg",
    "m_x_mm",
    "m_y_mm",
    "m_z_mm",
    "meets",
    "model",
    "scanner_m_x_mm",
    "scanner_m_y_mm",
    "scanner_m_z_mm",
    "reg_m_x_mm",
    "reg_m_y_mm",
    "reg_m_z_mm",
    "spacing_mm",
    "reason",
    "elevated_station",
    "zone",
]


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


def to_csv(df: pd.DataFrame) -> str:
    """A table as CSV: 3 decimals (1 mm), text cells neutralised (:func:`neutralise`)."""
    out = df.copy()
    for col in out.select_dtypes(include=["object", "string"]).columns:
        out[col] = out[col].map(neutralise)
    return out.to_csv(index=False, float_format="%.3f")


def stations_csv(p: Plan) -> str:
    return to_csv(p.stations[STATION_COLUMNS])


def targets_csv(p: Plan) -> str:
    t = p.targets.copy()
    t["station_ids"] = t["station_ids"].map(lambda ids: ";".join(ids))
    return to_csv(t[TARGET_COLUMNS])


#: Columns written only when the plan has them (an accuracy class was asked for).
OPTIONAL_COVERAGE_COLUMNS = ["class_achieved"]


def links_csv(p: Plan) -> str:
    return to_csv(p.links[LINK_COLUMNS])


def zones_csv(p: Plan) -> str:
    return to_csv(p.zones[ZONE_COLUMNS])


def coverage_csv(p: Plan) -> str:
    extra = [c for c in OPTIONAL_COVERAGE_COLUMNS if c in p.coverage.columns]
    return to_csv(p.scanned[COVERAGE_COLUMNS + extra])


def facades_csv(p: Plan) -> str:
    return to_csv(p.facades)


def site_repairs_csv(p: Plan) -> str | None:
    """What the site reader repaired or let pass (:mod:`planner.sitecheck`), a row per
    feature or pair; None when it did nothing."""
    if not p.site.notes:
        return None
    return to_csv(notes_table(p.site.notes))


def route_csv(p: Plan) -> str | None:
    return None if p.route is None else to_csv(p.route.table[ROUTE_COLUMNS])


def summary_text(p: Plan, limit: int = 50) -> str:
    """The summary and the first ``limit`` unmet samples with their reasons."""
    u = p.unmet
    if u.empty:
        listing = "Every sample meets the requirements."
    else:
        lines = [f"Unmet samples: {len(u)} (first {min(limit, len(u))}):"]
        for r in u.head(limit).itertuples():
            lines.append(f"  {r.sample_id} at ({r.x:.2f}, {r.y:.2f}, z {r.z:.1f} m): {r.reason}")
        listing = "\n".join(lines)
    return p.summary() + "\n" + listing + "\n"


def _to_geojson(geom: Any) -> dict:
    import shapely

    return json.loads(shapely.to_geojson(shapely.set_precision(geom, 0.001)))


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


def geojson(p: Plan) -> dict:
    """Buildings, obstacles, no-go areas, facades, stations, links, targets and unmet samples
    as one GeoJSON FeatureCollection (a ``layer`` property on every feature)."""
    feats: list[dict] = []

    def add(geom: dict, **props: Any) -> None:
        feats.append({"type": "Feature", "geometry": geom, "properties": _clean(props)})

    for b in p.site.buildings:
        add(
            _to_geojson(b.footprint),
            layer="building",
            building_id=b.id,
            height_m=b.height_m,
            planned=b.planned,
            name=b.name,
        )
    for o in p.site.obstacles:
        add(
            _to_geojson(o.geometry),
            layer="obstacle",
            obstacle_id=o.id,
            kind=o.kind,
            height_m=o.height_m,
        )
    for a in p.site.no_go:
        add(_to_geojson(a.geometry), layer="no-go", area_id=a.id)
    for g in p.site.passages:
        add(
            _to_geojson(g.geometry),
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
    st = p.stations.set_index("station_id")
    for r in p.stations.itertuples():
        add(
            {"type": "Point", "coordinates": [r.x, r.y]},
            layer="station",
            station_id=r.station_id,
            instrument_height_m=r.instrument_height_m,
            purpose=r.purpose,
            samples_met=r.samples_met,
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
        add(
            geom,
            layer="link",
            station_a=r.station_a,
            station_b=r.station_b,
            common_targets=r.common_targets,
            targets_placed=r.targets_placed,
            target_ids=r.target_ids,
            link_rms_mm=r.link_rms_mm,
            dilution=r.dilution,
            station_b_rms_mm=r.station_b_rms_mm,
        )
    for r in p.targets.itertuples():
        add(
            {"type": "Point", "coordinates": [r.x, r.y, r.z]},
            layer="target",
            target_id=r.target_id,
            type=r.type,
            min_size_mm=r.min_size_mm,
            size_mm=r.size_mm,
            item=r.item,
            sized_by=r.sized_by,
            station_ids=";".join(r.station_ids),
            facing_deg=r.facing_deg,
            centre_rms_mm=r.centre_rms_mm,
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
    for r in p.unmet.itertuples():
        add(
            {"type": "Point", "coordinates": [r.x, r.y, r.z]},
            layer="unmet",
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
    if p.site.crs:
        out["crs"] = {"type": "name", "properties": {"name": p.site.crs}}
    out["features"] = feats
    return out


def geojson_text(p: Plan) -> str:
    return json.dumps(geojson(p), indent=1, allow_nan=False) + "\n"


#: Every file of a plan folder and how it is rendered (one list: save, downloads, zip).
FILES = {
    "stations.csv": stations_csv,
    "targets.csv": targets_csv,
    "coverage.csv": coverage_csv,
    "facades.csv": facades_csv,
    "links.csv": links_csv,
    "zones.csv": zones_csv,
    "plan.geojson": geojson_text,
    "plan.dxf": dxf_text,
    "plan.kml": kml_text,  # only when the site has a CRS
    "stakeout.csv": stakeout_csv,
    "route.csv": route_csv,
    "site_repairs.csv": site_repairs_csv,
    "summary.txt": summary_text,
}


def render(p: Plan) -> dict[str, str]:
    """Every file of the plan as text, by file name (those a plan cannot have left out)."""
    out = {name: make(p) for name, make in FILES.items()}
    return {name: text for name, text in out.items() if text is not None}


#: Every file name a plan folder may hold from any run (so an old plan's file is never
#: mistaken for one of the user's own and carried into the new plan).
OWNED_FILES = (*FILES, "booklet.pdf")


def save(p: Plan, out_dir: str | Path, extra: dict[str, bytes] | None = None) -> list[Path]:
    """Write the plan's files into ``out_dir`` as one set: the folder holds the old plan or
    the new one, never a mix, whatever happens part-way (an error, a signal, a full disk);
    the user's own files in it are kept (:func:`planner.atomic.replace_folder_files`).
    ``extra``: more files of the plan made by the application (the booklet), by name."""
    data = {name: text.encode("utf-8") for name, text in render(p).items()}
    data.update(extra or {})
    return replace_folder_files(out_dir, data, owned=OWNED_FILES)
