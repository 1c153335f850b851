"""The plan's files: stations, targets, coverage and facades as CSV, everything as GeoJSON,
DXF, KML, the stake-out file and the summary text — rendered here, written by :func:`save`.

The columns (the file contract) and the CSV and GeoJSON writers are in
:mod:`planner.pipeline.inputs.schema`.
"""

from __future__ import annotations

import json
from pathlib import Path

from planner.atomic import replace_folder_files
from planner.pipeline.documents.deliver import dxf_text, kml_text, stakeout_csv
from planner.pipeline.documents.geojson import geojson
from planner.pipeline.engine.result import Plan
from planner.pipeline.inputs.schema import (
    COVERAGE_COLUMNS,
    LINK_COLUMNS,
    OPTIONAL_COVERAGE_COLUMNS,
    ROUTE_COLUMNS,
    STATION_COLUMNS,
    TARGET_COLUMNS,
    ZONE_COLUMNS,
    in_id_order,
    to_csv,
)
from planner.sitecheck import notes_table
from planner.text import printable

__all__ = [
    "FILES",
    "coverage_csv",
    "render",
    "save",
    "stations_csv",
    "targets_csv",
]


def stations_csv(p: Plan) -> str:
    return to_csv(in_id_order(p.stations, "station_id")[STATION_COLUMNS])


def targets_csv(p: Plan) -> str:
    t = in_id_order(p.targets, "target_id").copy()
    t["station_ids"] = t["station_ids"].map(lambda ids: ";".join(ids))
    return to_csv(t[TARGET_COLUMNS])


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
    """Every file of the plan as text, by file name (those a plan cannot have left out); no
    control character of a user's id or name gets into one (:func:`planner.text.printable`:
    a KML stays valid XML, a summary shown in a terminal runs nothing)."""
    out = {name: make(p) for name, make in FILES.items()}
    return {name: printable(text, keep=_LINES) for name, text in out.items() if text is not None}


#: The control characters a text file keeps: its line breaks and tabs.
_LINES = "\n\r\t"


#: Every file name a plan folder may hold from any run (so an old plan's file is never
#: mistaken for one of the user's own and carried into the new plan).
OWNED_FILES = (*FILES, "booklet.pdf")


def save(
    p: Plan,
    out_dir: str | Path,
    extra: dict[str, bytes] | None = None,
    owned: tuple[str, ...] = (),
) -> list[Path]:
    """Write the plan's files into ``out_dir`` as one set: the folder holds the old plan or
    the new one, never a mix, whatever happens part-way (an error, a signal, a full disk);
    the user's own files in it are kept (:func:`planner.atomic.replace_folder_files`).
    ``extra``: more files of the plan made by the application (the booklet), by name;
    ``owned``: more names a run of the same command may have written there (an old one the
    new set lacks is removed, not kept as if it were the user's)."""
    data = {name: text.encode("utf-8") for name, text in render(p).items()}
    data.update(extra or {})
    return replace_folder_files(out_dir, data, owned=(*OWNED_FILES, *owned))
