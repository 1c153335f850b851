"""The plan's output tables — their columns, each list written once — and the CSV writer every
file and download uses (:func:`to_csv`, text cells made inert for spreadsheets).

The table builders that fill these columns are in :mod:`planner.pipeline.engine.tables`; the files
are rendered and written by :mod:`planner.pipeline.documents.export`.
"""

from __future__ import annotations

import re

import pandas as pd

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
    "material",
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
    "height_by",
]
#: The registrations (station_b registered to station_a, or to the control network): common
#: targets usable by both, targets placed, the link's own predicted error at station_b's
#: facade points [mm], its geometry's strength — ``dilution``, that error over the RMS of
#: one target's centre difference (like a DOP: how much the targets' layout magnifies their
#: errors out at the facades; lower is stronger) — and the whole registration error
#: station_b's points end with [mm]. A cloud link the plan rehearsed
#: (:mod:`planner.pipeline.network.linkcheck`) gives the factor its error was taken at over the
#: model's (1: the model's held) and how often it failed [%] (empty: not rehearsed).
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
    "rehearsal_factor",
    "failure_pct",
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


#: The kit: per item of the inventory, how many the crew has (0: no count given), how many
#: the plan uses, how many stand at once at most and where — each from the first station
#: that sees it to the last, every scan that sees it observing it — and how many would, each
#: collected once its links' two scans are made (leap-frogged along the visiting order).
KIT_COLUMNS = [
    "item",
    "type",
    "size_mm",
    "owned",
    "used",
    "most_at_once",
    "at_station",
    "leapfrog_at_once",
]

#: The stake-out file a controller imports: point id, easting, northing, height, code (a
#: controller's PENZD order), then the ground's height under the point and the point's
#: height above it. Heights in the site's height system: a station's ``height`` is its
#: ground mark's (``ground_z``, the stations' column), ``above_ground_m`` its instrument
#: height (the stations' ``instrument_height_m``: the scanner's centre at their sum); a
#: target's ``height`` is its centre's, ``above_ground_m`` that above the ground under it.
STAKEOUT_COLUMNS = [
    "point_id",
    "easting",
    "northing",
    "height",
    "code",
    "ground_z",
    "above_ground_m",
    "height_from",
]


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
