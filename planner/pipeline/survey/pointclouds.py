"""Point clouds in the crew's formats: the rehearsal written, scanned poses read back.

* **E57** (ASTM E2807, the exchange format every registration program reads), through
  ``pye57`` (libE57Format): one scan per station, named by its id, its points in the
  scanner's own frame (single precision about the scanner, as scanners write them) with
  intensity and the grid's row and column (a structured scan: software builds its
  panorama and finds targets in it), and its pose — rotation and translation into the
  site's CRS.
* **LAS 1.4 / LAZ** (ASPRS), through ``laspy`` with ``lazrs``: every scan in the site's
  CRS (0.1 mm resolution), the station as ``point_source_id`` (1 = the first station of the
  legend), the surface's kind as ``classification`` (:data:`LAS_CLASSES`), and the extra
  attributes ``rms_mm`` (the point's predicted RMS), ``incidence_deg`` and ``surface``
  (the index of what it hit; the legend file names them).
* **Poses read back** (:func:`read_poses`): the scan headers of an E57 file as registration
  software exports a registered project (each scan's name and its pose's translation), or a
  CSV of station positions.
"""

from __future__ import annotations

import csv
import io
import re
import tempfile
from pathlib import Path

import numpy as np
import pandas as pd

from planner.errors import InputError
from planner.pipeline.inputs.schema import to_csv
from planner.pipeline.survey.rehearsal import POINT_KINDS, Rehearsal

__all__ = [
    "LAS_CLASSES",
    "POSE_COLUMNS",
    "TABLE_ALIASES",
    "e57_bytes",
    "find_columns",
    "laz_bytes",
    "legend_csv",
    "read_poses",
    "read_table",
]

#: ASPRS LAS 1.4 classification of each kind of surface (64 and 65 are user classes: the
#: targets); a kind not listed is 1, unclassified.
LAS_CLASSES = {
    "ground": 2,
    "terrain": 2,
    "tree": 5,
    "wall": 6,
    "roof": 6,
    "window": 6,
    "door": 6,
    "installation": 6,
    "ceiling": 6,
    "floor": 6,
    "sphere": 64,
    "checkerboard": 65,
}
#: The columns of the station poses read back.
POSE_COLUMNS = ["station_id", "x", "y", "z"]


def _quaternion(r: np.ndarray) -> np.ndarray:
    """The unit quaternion (w, x, y, z) of rotation matrix ``r``."""
    w = np.sqrt(max(0.0, 1.0 + np.trace(r))) / 2
    if w > 1e-6:
        return np.array(
            [
                w,
                (r[2, 1] - r[1, 2]) / (4 * w),
                (r[0, 2] - r[2, 0]) / (4 * w),
                (r[1, 0] - r[0, 1]) / (4 * w),
            ]
        )
    k = int(np.argmax(np.diag(r)))
    i, j = (k + 1) % 3, (k + 2) % 3
    q = np.zeros(4)
    q[k + 1] = np.sqrt(max(0.0, 1.0 + r[k, k] - r[i, i] - r[j, j])) / 2
    q[0] = (r[j, i] - r[i, j]) / (4 * q[k + 1])
    q[i + 1] = (r[i, k] + r[k, i]) / (4 * q[k + 1])
    q[j + 1] = (r[j, k] + r[k, j]) / (4 * q[k + 1])
    return q


def e57_bytes(reh: Rehearsal) -> bytes:
    """The rehearsal as one E57 file (module text)."""
    import pye57

    with tempfile.TemporaryDirectory(prefix="planner-e57-") as tmp:
        path = Path(tmp) / "scans.e57"
        with pye57.E57(str(path), mode="w") as e57:
            for s in reh.scans:
                if not s.n_points:
                    continue
                e57.write_scan_raw(
                    {
                        "cartesianX": s.local_xyz[:, 0],
                        "cartesianY": s.local_xyz[:, 1],
                        "cartesianZ": s.local_xyz[:, 2],
                        "intensity": s.intensity.astype(np.float32),
                        "rowIndex": s.row.astype(np.uint16),
                        "columnIndex": s.column.astype(np.uint16),
                    },
                    name=s.station_id,
                    rotation=_quaternion(s.rotation),
                    translation=s.position,
                )
        return path.read_bytes()


def laz_bytes(reh: Rehearsal, compressed: bool = True) -> bytes:
    """Every scan in one LAS 1.4 file (LAZ where ``compressed``), in the site's CRS."""
    import laspy

    if not reh.scans:
        raise InputError("no scan to write: the plan has no scanning station")
    xyz = np.concatenate([s.world_xyz for s in reh.scans])
    header = laspy.LasHeader(point_format=6, version="1.4")
    header.offsets = np.floor(xyz.min(axis=0)) if len(xyz) else np.zeros(3)
    header.scales = np.array([1e-4, 1e-4, 1e-4])
    header.add_extra_dims(
        [
            laspy.ExtraBytesParams("rms_mm", "f4", description="predicted RMS of the point mm"),
            laspy.ExtraBytesParams("incidence_deg", "f4", description="incidence angle deg"),
            laspy.ExtraBytesParams("surface", "u4", description="surface index (legend)"),
        ]
    )
    if reh.crs:
        import pyproj

        header.add_crs(pyproj.CRS.from_user_input(reh.crs))
    las = laspy.LasData(header)
    las.x, las.y, las.z = xyz[:, 0], xyz[:, 1], xyz[:, 2]
    cat = np.concatenate
    las.intensity = np.round(cat([s.intensity for s in reh.scans]) * 65535).astype(np.uint16)
    las.point_source_id = cat(
        [np.full(s.n_points, k + 1, dtype=np.uint16) for k, s in enumerate(reh.scans)]
    )
    classes = np.array([LAS_CLASSES.get(k, 1) for k in POINT_KINDS], dtype=np.uint8)
    las.classification = classes[cat([s.kind for s in reh.scans])]
    las.rms_mm = cat([s.rms_mm for s in reh.scans])
    las.incidence_deg = cat([s.incidence_deg for s in reh.scans])
    las.surface = cat([s.surface for s in reh.scans]).astype(np.uint32)
    buf = io.BytesIO()
    las.write(buf, do_compress=compressed)
    return buf.getvalue()


def legend_csv(reh: Rehearsal) -> str:
    """What the clouds' numbers stand for: each station's ``point_source_id`` and pose, each
    ``surface`` index's id, each ``classification``'s kind."""
    rows = [
        ("point_source_id", k + 1, s.station_id, *np.round(s.position, 4))
        for k, s in enumerate(reh.scans)
    ]
    rows += [("surface", k, sid, None, None, None) for k, sid in enumerate(reh.surfaces)]
    rows += [
        (
            "classification",
            c,
            ", ".join(k for k in POINT_KINDS if LAS_CLASSES.get(k, 1) == c),
            None,
            None,
            None,
        )
        for c in sorted({*LAS_CLASSES.values(), 1})
    ]
    return to_csv(pd.DataFrame(rows, columns=["attribute", "value", "means", "x", "y", "z"]))


#: Column names a station or target table may use for each of the planner's columns.
TABLE_ALIASES = {
    "station_id": (
        "station_id",
        "station",
        "name",
        "scan",
        "setup",
        "id",
        "point",
        "point_id",
        "pointid",
    ),
    "target_id": ("target_id", "target", "name", "id", "point", "point_id", "pointid"),
    "x": ("x", "e", "east", "easting"),
    "y": ("y", "n", "north", "northing"),
    "z": ("z", "h", "height", "elevation"),
}


def find_columns(
    columns, aliases: dict[str, tuple[str, ...]], units: tuple[str, ...] | None = None
) -> dict[str, tuple[object, str]]:
    """For each key of ``aliases``, the first of ``columns`` not taken by an earlier key
    whose name — lower case, a byte-order mark and a unit in brackets at its end left out,
    spaces as underscores — is one of the key's names; with that unit ("" none). ``units``:
    the units a name may carry (a column with another does not match); None: any.

    >>> find_columns(["Point ID", "Easting (m)", "N"], {"id": ("point_id",), "x": ("easting",)})
    {'id': ('Point ID', ''), 'x': ('Easting (m)', 'm')}
    """
    found: dict[str, tuple[object, str]] = {}
    for key, names in aliases.items():
        wanted = {n.replace(" ", "_") for n in names}
        for c in columns:
            name = str(c).strip().lstrip("\ufeff").lower()
            unit = re.search(r"\s*[\(\[]([^\)\]]*)[\)\]]$", name)
            if units is not None and (unit.group(1).strip() if unit else "") not in units:
                continue
            bare = (name[: unit.start()] if unit else name).strip().replace(" ", "_")
            if bare in wanted and all(c != t for t, _ in found.values()):
                found[key] = (c, unit.group(1).strip() if unit else "")
                break
    return found


def read_crew_csv(path: str | Path, what: str, **kw) -> pd.DataFrame:
    """A CSV as a crew gives it (comma- or semicolon-separated, sniffed; UTF-8 with or
    without a byte-order mark): an :class:`InputError` saying why where it is not one —
    empty, not text, no delimiter to be found. ``kw`` goes to :func:`pandas.read_csv`."""
    try:
        return pd.read_csv(path, sep=None, engine="python", encoding="utf-8-sig", **kw)
    except UnicodeDecodeError:
        raise InputError(
            f"{path}: not UTF-8 text; save it as CSV UTF-8 (Excel: CSV UTF-8, comma delimited)"
        ) from None
    except pd.errors.EmptyDataError:
        raise InputError(f"{path}: empty; a CSV of {what} with a header row is needed") from None
    except (OSError, ValueError, csv.Error, pd.errors.ParserError) as exc:
        if _blank(path):
            raise InputError(
                f"{path}: empty; a CSV of {what} with a header row is needed"
            ) from None
        raise InputError(f"{path}: not a readable CSV of {what} ({exc})") from None


def _blank(path: str | Path) -> bool:
    """Whether a file holds nothing but white space (read no further than its first KB)."""
    try:
        with open(path, "rb") as f:
            head = f.read(1024)
            return not head.strip() and not f.read(1)
    except OSError:
        return False


def read_table(path: str | Path, id_column: str, what: str) -> pd.DataFrame:
    """A CSV of points — ``id_column, x, y`` and ``z`` (optional, NaN where not given) —
    under the planner's names or common others (:data:`TABLE_ALIASES`: Name, E, N, H,
    Easting…), comma- or semicolon-separated (a decimal comma with semicolons), ids kept
    as written ("01" stays "01"); an :class:`InputError` saying what is wrong otherwise.
    ``what`` names the table in messages."""
    df = read_crew_csv(path, what, dtype=str, skipinitialspace=True)
    df = df.dropna(how="all")  # (a spreadsheet's empty rows: ",,")
    keys = (id_column, "x", "y", "z")
    found = {
        k: c for k, (c, _) in find_columns(df.columns, {k: TABLE_ALIASES[k] for k in keys}).items()
    }
    missing = [k for k in (id_column, "x", "y") if k not in found]
    if missing:
        raise InputError(
            f"{path}: a table of {what} needs the columns {id_column}, x, y (z optional; "
            f"also Name, E/Easting, N/Northing, H); missing " + ", ".join(missing)
        )
    out = pd.DataFrame({id_column: df[found[id_column]].astype(str).str.strip()})
    for key in ("x", "y", "z"):
        text = df[found[key]] if key in found else pd.Series(np.nan, index=df.index)
        out[key] = pd.to_numeric(
            text.astype(str).str.strip().str.replace(",", "."), errors="coerce"
        )
    bad = ~np.isfinite(out[["x", "y"]].to_numpy(dtype=float)).all(axis=1)
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise InputError(f"{path}: row {k + 2} has no usable x, y (numbers in the site's CRS)")
    return _checked(out, path, id_column)


def read_poses(path: str | Path) -> pd.DataFrame:
    """Station positions as scanned (:data:`POSE_COLUMNS`, site CRS [m]) from an E57 file's
    scan headers (the scan's name its station id, the pose's translation its position) or
    a CSV (:func:`read_table`)."""
    p = Path(path)
    if not p.is_file():
        raise InputError(f"{path}: no such file (give the E57 or CSV of the stations as scanned)")
    if p.suffix.lower() == ".e57":
        return _e57_poses(p)
    if p.suffix.lower() not in (".csv", ".txt"):
        raise InputError(
            f"{path}: the stations as scanned are read from an .e57 file (its scan poses) or "
            "a .csv with columns station_id, x, y[, z]"
        )
    return read_table(p, "station_id", "stations as scanned")


def _e57_poses(p: Path) -> pd.DataFrame:
    import pye57

    rows = []
    try:
        with pye57.E57(str(p)) as e57:
            for k in range(e57.scan_count):
                h = e57.get_header(k)
                name = h["name"].value() if h.node.isDefined("name") else f"scan {k + 1}"
                if not h.has_pose():
                    raise InputError(
                        f"{p}: scan {k + 1} ({name}) has no pose: export the registered "
                        "project (scans with their poses) from the registration software"
                    )
                rows.append((name, *np.asarray(h.translation, dtype=float)))
    except InputError:
        raise
    except Exception as exc:  # libE57Format raises its own types for a broken file
        first = (str(exc).splitlines() or [type(exc).__name__])[0]
        raise InputError(f"{p}: not a readable E57 file ({first})") from None
    return _checked(pd.DataFrame(rows, columns=POSE_COLUMNS), p)


def read_e57_scans(path: str | Path) -> list[dict]:
    """Every scan of an E57 file: its name, rotation matrix, translation and points in its
    own frame (for checks and tests)."""
    import pye57

    out = []
    with pye57.E57(str(path)) as e57:
        for k in range(e57.scan_count):
            h = e57.get_header(k)
            d = e57.read_scan_raw(k)
            out.append(
                {
                    "name": h["name"].value(),
                    "rotation": np.asarray(h.rotation_matrix, dtype=float),
                    "translation": np.asarray(h.translation, dtype=float),
                    "xyz": np.column_stack([d["cartesianX"], d["cartesianY"], d["cartesianZ"]]),
                    "intensity": np.asarray(d["intensity"]),
                }
            )
    return out


def _checked(df: pd.DataFrame, path, id_column: str = "station_id") -> pd.DataFrame:
    df[id_column] = df[id_column].astype(str).str.strip()
    dup = df[id_column][df[id_column].duplicated()]
    if len(dup):
        raise InputError(
            f"{path}: {dup.iloc[0]} is given twice; one position each (name a second set-up "
            "on the same spot as one of its own)"
        )
    if df.empty:
        raise InputError(f"{path}: nothing in it")
    return df.reset_index(drop=True)
