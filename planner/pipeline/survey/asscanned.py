"""Re-plan from what was scanned: the stations where the crew set up, and what is left.

On site a crew sets up where the ground allows, skips a scan, meets a van in front of a
facade. :func:`replan` takes the stations as scanned (read from the registered project's
E57 or a CSV, :func:`planner.pipeline.survey.pointclouds.read_poses`) and the targets as placed,
judges every sample again with the real positions — coverage, scanner ⊕ registration
with the targets that stood (the plan's, or where the file says they were placed, and the
control points: no other candidate) — and proposes the fewest extra stations for what is
left, each with its reason; the stations scanned keep their ids and the extra ones take
numbers never given before. The extra stations are registered with those same targets
(set again on their marks) or cloud to cloud: a target the scans made do not hold cannot
tie them.

:func:`compare_links` reads a registration program's report (the error of each link,
optionally its overlap) and sets it beside the plan's predicted link errors.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd
import shapely

from planner.errors import InputError
from planner.pipeline.engine.ids import id_number
from planner.pipeline.engine.judge import copy_plan, free_positions, network_layout
from planner.pipeline.engine.planning import choose_stations
from planner.pipeline.engine.result import Plan
from planner.pipeline.engine.whatif import (
    _target_index,
    _workbench,
    edit_candidates,
    evaluate_stations,
    one_setup_twice,
)
from planner.pipeline.evaluation.evaluate import Progress
from planner.pipeline.survey.pointclouds import find_columns, read_crew_csv, read_table
from planner.ranges import RANGES

if TYPE_CHECKING:
    from planner.pipeline.network.layout import Layout

__all__ = [
    "AS_SCANNED_COLUMNS",
    "REPORT_ALIASES",
    "Replan",
    "check_same_plan",
    "check_scanned",
    "compare_links",
    "match_ids",
    "pair_prediction",
    "read_link_report",
    "read_targets_placed",
    "replan",
]

#: A scanned station this far [m] from its planned place counts as moved.
MOVED_M = 0.05
#: A station the crew set up may stand this close [m] to a wall or obstacle (a tripod's
#: legs), nearer than the clearance the plan keeps for the stations it proposes.
TRIPOD_CLEARANCE_M = 0.3
#: Scans standing this far [m] (median) from the plan's stations of the same ids are not
#: the plan the crew followed.
FAR_FROM_PLAN_M = 10.0
#: A target placed farther than this [m] from its planned place is a typing error, not a
#: crew's adjustment.
TARGET_MOVED_LIMIT_M = 20.0
#: The table of stations as scanned against the plan (``scan_name``: as the file named it).
AS_SCANNED_COLUMNS = [
    "station_id",
    "scan_name",
    "status",
    "x",
    "y",
    "moved_m",
    "samples_met",
    "reason",
]


@dataclass(frozen=True)
class Replan:
    """The plan as scanned plus the extra stations, and how each station stands."""

    plan: Plan  # stations as scanned (purpose "hand" where moved or added) + extra ones
    stations: pd.DataFrame  # AS_SCANNED_COLUMNS
    scanned_plan: Plan  # the stations as scanned alone (their network, their links)
    before: tuple[int, int]  # samples met by the stations as scanned alone, and demanded

    @property
    def extra(self) -> pd.DataFrame:
        return self.stations[self.stations["status"] == "extra"]

    def summary(self) -> str:
        s = self.stations
        met, total = self.before
        after = int(self.plan.scanned["meets"].sum())
        counts = s["status"].value_counts()
        lines = [
            "As scanned: "
            + ", ".join(
                f"{int(counts.get(k, 0))} {k}"
                for k in ("as planned", "moved", "added on site", "skipped")
                if counts.get(k, 0)
            )
            + f"; {met} of {total} samples met by the scans made.",
        ]
        n = len(self.extra)
        if n:
            lines.append(
                f"Extra stations: {n} ({', '.join(self.extra['station_id'])}) → {after} of "
                f"{total} met."
            )
            lines += [f"  {r.station_id}: {r.reason}" for r in self.extra.itertuples()]
            route = self.plan.route.table if self.plan.route is not None else None
            if route is not None and "station_min" in route:
                back = route[route["station_id"].isin(self.extra["station_id"])]
                lines.append(
                    f"Return trip: {len(back)} set-up(s), {back['station_min'].sum():.0f} min "
                    "on station (set-up, targets, scans; the walk to the site not counted). "
                    "The route and field time in the files are the whole job's."
                )
        else:
            lines.append(
                "No extra station: "
                + (
                    "every sample is met."
                    if after == total
                    else f"{after} of {total} met; "
                    "no position meets the others (see the unmet samples' reasons)."
                )
            )
        return "\n".join(lines)


def replan(
    p: Plan,
    scanned: pd.DataFrame,
    *,
    targets_placed: pd.DataFrame | None = None,
    progress: Progress | None = None,
) -> Replan:
    """The plan ``p`` (made in this process; not changed) re-planned from the stations
    ``scanned`` (``station_id, x, y`` [m], site CRS) and the targets as placed
    (``target_id, x, y``; None: as planned): see the module text. A scan's name is matched
    to the plan's ids as a crew writes them ("s5", "S5", "5" are S05); a name the plan does
    not have is a station added on site, and a planned station missing from ``scanned`` was
    skipped."""
    p = copy_plan(p)  # the re-plan adds to the workbench; the plan on screen stays
    wb = _workbench(p)
    settings = wb.settings  # the scans made may stand nearer a wall than the plan's clearance
    wb.settings = replace(settings, clearance_m=_scan_clearance(settings.clearance_m))
    planned = p.scan_stations.set_index("station_id")
    scanned, targets_placed = check_scanned(p, scanned, targets_placed)
    xy = scanned[["x", "y"]].to_numpy(dtype=float)
    ids = scanned["station_id"].tolist()
    planned_targets = [_target_index(wb, p, t) for t in p.targets["target_id"]]
    if targets_placed is not None and len(targets_placed):
        _targets_as_placed(p, targets_placed)
    # the scans made hold the targets that stood: the plan's (or those placed by hand where
    # the file moved them) and the control points. Only those can tie them — to each other
    # and to the extra stations (whose crew sets targets on the same marks again)
    seen = wb.seen
    stood = seen.by_hand.copy()
    stood[planned_targets] = True
    stood |= np.asarray(seen.tc.type == "control")
    seen.barred = seen.barred | ~stood
    as_scanned = evaluate_stations(p, xy, ids)
    before = (int(as_scanned.scanned["meets"].sum()), len(as_scanned.scanned))
    left = set(as_scanned.unmet["sample_id"])
    new = as_scanned
    if left:  # the fewest others around the scans made, kept only where they meet more
        given = wb.given(p)
        again = choose_stations(wb, progress, locked=xy, locked_ids=ids, given=given)
        if again.scanned["meets"].sum() > before[0]:
            new = again
    for q in {id(new): new, id(as_scanned): as_scanned}.values():
        q.settings = settings
        q.messages = [m for m in q.messages if not m.startswith("Stations edited by hand")]
        q.messages.insert(0, f"Re-planned from {len(ids)} station(s) as scanned.")
    return Replan(
        plan=new,
        stations=_table(new, scanned, planned, left),
        scanned_plan=as_scanned,
        before=before,
    )


def match_ids(names: pd.Series, plan_ids: list[str], prefix: str = "S") -> pd.Series:
    """The plan's id for each name where one is meant — the same number in another case,
    padding or wording ("s5", "S005", "5", "Scan 005", "Setup_5" → "S05"; with ``prefix``
    "T", "t5" → "T05"); else the name itself.

    >>> match_ids(pd.Series(["s5", "S05", "12", "Scan 003", "S99"]), ["S05", "S12", "S03"]).tolist()
    ['S05', 'S05', 'S12', 'S03', 'S99']
    """
    number = {}
    for i in plan_ids:
        m = re.fullmatch(rf"{prefix}(\d+)", str(i))
        if m:
            number[int(m.group(1))] = i
    words = "scan|setup|station|st" if prefix == "S" else "target|tgt"
    pattern = re.compile(rf"(?:{prefix}|{words})?[\s_\-.#]*0*(\d+)", re.IGNORECASE)

    def one(name: str) -> str:
        m = pattern.fullmatch(name.strip())
        return number.get(int(m.group(1)), name) if m else name

    return names.astype(str).map(one)


def check_scanned(
    p: Plan, scanned: pd.DataFrame, targets_placed: pd.DataFrame | None = None
) -> tuple[pd.DataFrame, pd.DataFrame | None]:
    """The stations as scanned, checked against the plan before any work (an
    :class:`InputError` naming the fault): names matched to the plan's ids
    (:func:`match_ids`; the file's own in ``scan_name``), at least one of them the plan's,
    positions on the site (not all at one point, not kilometres away: poses not in the
    site's CRS), each where a station can stand, no two on one spot, the targets placed
    the plan's (matched as the stations are) and near their planned places. Returns both
    tables with the plan's ids."""
    wb = _workbench(p)
    out = scanned.copy()
    out["scan_name"] = out["station_id"].astype(str)
    out["station_id"] = match_ids(out["scan_name"], p.stations["station_id"].tolist())
    dup = out["station_id"][out["station_id"].duplicated()]
    if len(dup):
        names = out.loc[out["station_id"] == dup.iloc[0], "scan_name"].tolist()
        raise InputError(f"scans {' and '.join(names)} are both station {dup.iloc[0]}")
    if not out["station_id"].isin(p.stations["station_id"]).any():
        raise InputError(
            f"none of the scans ({', '.join(out['scan_name'].head(4))}"
            + (" …" if len(out) > 4 else "")
            + ") is a station of this plan: name each scan by its station id (S01, S02 …), "
            "and re-plan with the options the plan was made with"
        )
    xy = out[["x", "y"]].to_numpy(dtype=float)
    if len(xy) > 1 and np.ptp(xy, axis=0).max() < 1e-3:
        raise InputError(
            "every scan has the same position: the file's poses are not the stations' (export "
            "the registered project with each scan's pose in the site's CRS)"
        )
    st = p.scan_stations.set_index("station_id")
    same = out["station_id"].isin(st.index).to_numpy()
    gap = np.hypot(*(xy[same] - st.loc[out["station_id"][same], ["x", "y"]].to_numpy(float)).T)
    if same.sum() >= 2 and np.median(gap) > FAR_FROM_PLAN_M:
        raise InputError(
            f"the scans stand {np.median(gap):.0f} m (median) from the plan's stations of the "
            "same ids: this is not the plan the crew followed. Give the options it was made "
            "with (--plan DIR checks it), or the scans' coordinates in the site's CRS"
        )
    x0, y0, x1, y1 = shapely.total_bounds([b.footprint for b in p.site.buildings])
    far = p.scanner.max_range_m + max(x1 - x0, y1 - y0)
    off = np.hypot(xy[:, 0] - (x0 + x1) / 2, xy[:, 1] - (y0 + y1) / 2) > far
    if off.any():
        k = int(np.flatnonzero(off)[0])
        raise InputError(
            f"scan {out['scan_name'].iloc[k]} stands at E {xy[k, 0]:.1f}, N {xy[k, 1]:.1f}, "
            "far from the site: the poses are not in the site's CRS (export them in it, or "
            "give a CSV of the stations' coordinates)"
        )
    clear = _scan_clearance(wb.settings.clearance_m)
    for sid, q in zip(out["scan_name"], xy, strict=True):  # each refusal names the scan
        try:
            free_positions(wb, q, f"station {sid} as scanned", clear)
        except InputError as exc:
            raise InputError(
                str(exc).replace("; move it onto free ground", "")
                + ": the planner judges no station there. Check the file's coordinates "
                "(the site's CRS, x and y not swapped), or re-plan without that area"
            ) from None
    _one_setup_each(xy, out["scan_name"].tolist())
    if targets_placed is not None:
        targets_placed = targets_placed.assign(
            target_id=match_ids(targets_placed["target_id"], p.targets["target_id"].tolist(), "T")
        )
        planned_at = p.targets.set_index("target_id")[["x", "y"]]
        known = targets_placed[targets_placed["target_id"].isin(planned_at.index)]
        moved = np.hypot(
            *(
                known[["x", "y"]].to_numpy(float)
                - planned_at.loc[known["target_id"]].to_numpy(float)
            ).T
        )
        if (moved > TARGET_MOVED_LIMIT_M).any():
            k = int(np.argmax(moved))
            raise InputError(
                f"target {known['target_id'].iloc[k]} placed {moved[k]:.0f} m from where the "
                f"plan has it (more than {TARGET_MOVED_LIMIT_M:g} m): a typing error? Check "
                "its coordinates, or leave it out of the file if it was not set up"
            )
        unknown = sorted(set(targets_placed["target_id"]) - set(p.targets["target_id"]))
        if unknown:
            raise InputError(
                f"targets {', '.join(unknown[:5])} are not in the plan; give the plan's target "
                "ids with where each was placed"
            )
    return out, targets_placed


def _scan_clearance(clearance_m: float) -> float:
    return min(clearance_m, TRIPOD_CLEARANCE_M)


def _one_setup_each(xy: np.ndarray, ids: list[str]) -> None:
    pair = one_setup_twice(xy)
    if pair is not None:
        a, b, d = pair
        raise InputError(
            f"stations {ids[a]} and {ids[b]} were scanned {d:.2f} m apart: one set-up "
            "twice; give one of them"
        )


def _targets_as_placed(p: Plan, placed: pd.DataFrame) -> None:
    """The workbench's target candidates as the crew placed them (the plan's targets not
    listed ruled out, those moved offered where they stood); the plan is judged after."""
    known = set(p.targets["target_id"].astype(str))
    old = p.targets.set_index("target_id")[["x", "y"]]
    move = {
        str(r.target_id): (float(r.x), float(r.y))
        for r in placed.itertuples()
        if np.hypot(r.x - old.loc[r.target_id, "x"], r.y - old.loc[r.target_id, "y"]) >= MOVED_M
    }
    missing = sorted(known - set(placed["target_id"].astype(str)))
    edit_candidates(p, move=move, remove=missing)


def _table(new: Plan, scanned: pd.DataFrame, planned: pd.DataFrame, left: set) -> pd.DataFrame:
    met = new.stations.set_index("station_id")["samples_met"]
    rows = []
    for r in scanned.itertuples():
        sid = str(r.station_id)
        if sid in planned.index:
            d = float(np.hypot(r.x - planned.loc[sid, "x"], r.y - planned.loc[sid, "y"]))
            status = "moved" if d >= MOVED_M else "as planned"
        else:
            d, status = np.nan, "added on site"
        rows.append((sid, r.scan_name, status, r.x, r.y, d, int(met.get(sid, 0)), ""))
    scans = new.scan_stations
    again = set(scans["station_id"].astype(str))  # a skipped station the re-plan keeps: extra
    for sid in planned.index.difference(scanned["station_id"].astype(str)).difference(again):
        at = planned.loc[sid]
        rows.append((sid, "", "skipped", at["x"], at["y"], np.nan, 0, ""))
    known = set(scanned["station_id"].astype(str))
    number = [id_number(str(i), "S") or 0 for i in scans["station_id"]]
    for r in scans.iloc[np.argsort(number, kind="stable")].itertuples():
        if r.station_id not in known:
            reason = _reason(new, r, left)
            if r.station_id in planned.index:  # where the plan had it (the ids stay)
                reason += " (skipped: scan it where the plan has it)"
            rows.append((r.station_id, "", "extra", r.x, r.y, np.nan, int(r.samples_met), reason))
    return pd.DataFrame(rows, columns=AS_SCANNED_COLUMNS)


def _reason(p: Plan, st, left: set) -> str:
    """Why an extra station is there: the samples the scans made left unmet (``left``,
    sample ids) that it meets, by facade, or the scans it ties into the network."""
    cov = p.coverage
    mine = cov[(cov["station_id"] == st.station_id) & cov["meets"] & cov["sample_id"].isin(left)]
    if len(mine):
        by = mine.groupby("facade_id").size().sort_values(ascending=False)
        shown = ", ".join(f"{f} ({n})" for f, n in by.head(4).items())
        return f"meets {len(mine)} sample(s) left unmet: {shown}" + (" …" if len(by) > 4 else "")
    links = p.links
    ties = links[(links["station_a"] == st.station_id) | (links["station_b"] == st.station_id)]
    others = sorted({*ties["station_a"], *ties["station_b"]} - {st.station_id})
    if others:
        return f"ties {', '.join(map(str, others[:6]))} into the registration network"
    return f"{st.purpose} station"


def read_targets_placed(path: str | Path) -> pd.DataFrame:
    """Targets as placed: a CSV with ``target_id, x, y`` (the plan's ids, site CRS [m];
    :func:`~planner.pipeline.survey.pointclouds.read_table`)."""
    return read_table(path, "target_id", "targets as placed")[["target_id", "x", "y"]]


def check_same_plan(p: Plan, folder: str | Path) -> None:
    """An :class:`InputError` unless ``p``'s stations are those of the plan written in
    ``folder`` (its ``stations.csv``: the same ids, each within a millimetre): the re-plan
    must start from the plan the crew followed, and a report must show the plan written; a
    plan made again from its options is the same on any machine, but can differ with
    other options or another version of the planner."""
    path = Path(folder) / "stations.csv"
    if not path.is_file():
        raise InputError(f"{folder}: no stations.csv (give the folder planner plan wrote)")
    try:
        old = pd.read_csv(path, dtype={"station_id": str}).set_index("station_id")[["x", "y"]]
    except (ValueError, KeyError, UnicodeDecodeError, pd.errors.ParserError) as exc:
        raise InputError(f"{path}: not a plan's stations.csv ({exc})") from None
    new = p.stations.set_index("station_id")[["x", "y"]]
    differ = sorted(set(old.index) ^ set(new.index))
    if not differ:
        gap = np.hypot(*(old.loc[new.index].to_numpy(float) - new.to_numpy(float)).T)
        differ = [sid for sid, d in zip(new.index, gap, strict=True) if d > 1e-3]
    if differ:
        raise InputError(
            f"the plan made again from these options is not the plan in {folder} (stations "
            f"{', '.join(differ[:5])}{' …' if len(differ) > 5 else ''} differ): give the options "
            "that plan was made with (and the same version of the planner)"
        )


#: A registration report's columns under the names registration programs give them.
REPORT_ALIASES = {
    "station_a": (
        "station_a",
        "from",
        "scan_a",
        "scan a",
        "reference",
        "scan 1",
        "setup 1",
        "source",
    ),
    "station_b": (
        "station_b",
        "to",
        "scan_b",
        "scan b",
        "scan 2",
        "setup 2",
        "target scan",
        "moving",
    ),
    "error_mm": (
        "error_mm",
        "error",
        "bundle error",
        "link error",
        "rms",
        "rms_mm",
        "mean error",
        "deviation",
    ),
    "overlap_pct": ("overlap_pct", "overlap", "overlap %", "overlap (%)"),
}


def read_link_report(path: str | Path) -> pd.DataFrame:
    """A registration report's links: ``station_a, station_b, error_mm`` and, where
    given, ``overlap_pct`` — from a CSV whose columns bear those names or a registration
    program's (:data:`REPORT_ALIASES`; an error given in metres, ``… (m)``, is converted)."""
    df = read_crew_csv(path, "links (a registration report)")
    out = {}
    raw_error = pd.Series(dtype=object)
    units = ("", "m", "cm", "mm", "%")
    for key, (c, unit) in find_columns(df.columns, REPORT_ALIASES, units).items():
        col = df[c]
        if key == "error_mm":
            raw_error = col
        if key in ("error_mm", "overlap_pct"):
            text = col.astype(str).str.strip().str.rstrip("%").str.replace(",", ".")
            text = text.str.replace(r"\s*(mm|cm|m)$", "", regex=True)
            col = pd.to_numeric(text, errors="coerce")
            scale = {"m": 1000.0, "cm": 10.0}.get(unit, 1.0)
            col = col * scale if key == "error_mm" else col
        out[key] = col
    missing = [k for k in ("station_a", "station_b", "error_mm") if k not in out]
    if missing:
        raise InputError(
            f"{path}: no column for {', '.join(missing)} (give station_a, station_b, error_mm "
            "and optionally overlap_pct, or the report's own names such as From, To, Error)"
        )
    rep = pd.DataFrame(out)
    rep["station_a"] = rep["station_a"].astype(str).str.strip()
    rep["station_b"] = rep["station_b"].astype(str).str.strip()
    bad = (
        rep["error_mm"].isna()
        & raw_error.astype(str).str.strip().ne("").to_numpy()
        & raw_error.notna().to_numpy()
    )
    if bad.any():
        k = int(np.flatnonzero(bad.to_numpy())[0])
        raise InputError(
            f"{path}: row {k + 2}'s error {raw_error.iloc[k]!r} is not a number (give it in mm, "
            "or say the unit in the column's name: Error (m), Error (cm))"
        )
    error_range = RANGES["rms_mm"]
    for k, v in enumerate(rep["error_mm"]):
        if not np.isnan(v):
            error_range.check(float(v), f"{path}: row {k + 2}'s error [mm]")
    if "overlap_pct" in rep:
        for k, v in enumerate(rep["overlap_pct"]):
            if not np.isnan(v) and not 0.0 <= v <= 100.0:
                raise InputError(f"{path}: row {k + 2}'s overlap {v:g} % is not within 0–100 %")
    return rep


def compare_links(p: Plan, report: pd.DataFrame) -> pd.DataFrame:
    """Each reported link beside the plan's prediction, matched by its pair of scans (either
    direction), not by the plan's own list of links — registration software links the scans
    in the order they were made and adds the overlapping pairs it finds: ``predicted_mm``
    (the link's own predicted error: the plan's link, else what the plan predicts for that
    pair registered directly, cloud to cloud or on the targets both see —
    :func:`pair_prediction`), ``ratio`` reported/predicted, ``planned`` whether the plan
    has that link, and a verdict — within the prediction, up to twice it, over twice it, or
    no prediction (the two scans share too little)."""
    links = {frozenset((r.station_a, r.station_b)): r for r in p.links.itertuples(index=False)}
    ids = p.stations["station_id"].tolist()
    report = report.assign(
        station_a=match_ids(report["station_a"], ids), station_b=match_ids(report["station_b"], ids)
    )
    rows = []
    lay, order = network_layout(p), p.network_ids()
    for r in report.itertuples():
        link = links.get(frozenset((r.station_a, r.station_b)))
        if link is not None:
            pred, overlap = float(link.link_rms_mm), float(link.overlap_pct)
        else:
            pred, overlap = _predicted(lay, order, r.station_a, r.station_b)
        ratio = r.error_mm / pred if np.isfinite(pred) and pred > 0 else np.nan
        if np.isnan(pred):
            verdict = (
                "no prediction: not a pair of the plan's scanning stations, or the plan was "
                "read back from files (re-plan from its inputs to compare it)"
            )
        elif not np.isfinite(pred):
            verdict = "no prediction: the plan finds the two scans share too little to link"
        elif np.isnan(r.error_mm):
            verdict = "no error given"
        elif ratio <= 1.0:
            verdict = "within the prediction"
        elif ratio <= 2.0:
            verdict = "up to twice the prediction"
        else:
            verdict = "over twice the prediction: check this link"
        rows.append(
            {
                "station_a": r.station_a,
                "station_b": r.station_b,
                "planned": link is not None,
                "reported_mm": r.error_mm,
                "predicted_mm": pred,
                "ratio": ratio,
                "reported_overlap_pct": getattr(r, "overlap_pct", np.nan),
                "predicted_overlap_pct": overlap,
                "verdict": verdict,
            }
        )
    return pd.DataFrame(rows)


def pair_prediction(p: Plan, a: str, b: str) -> tuple[float, float]:
    """What the plan predicts for scan ``b`` registered directly to scan ``a`` (station
    ids): the link's own error at ``b``'s facade points [mm] — cloud to cloud where the
    registration is, else on the targets both see, as the plan would link them
    (:func:`~planner.pipeline.engine.judge.network_layout`) — and the two scans' overlap
    [%]. inf where the two share too little to link; NaN where the plan cannot tell (an id
    that is not one of its scanning stations, a plan read back from files)."""
    return _predicted(network_layout(p), p.network_ids(), a, b)


def _predicted(lay: Layout | None, order: list[str], a: str, b: str) -> tuple[float, float]:
    """:func:`pair_prediction` over a layout made once for many pairs."""
    if lay is None or a not in order or b not in order:
        return np.nan, np.nan
    i, j = order.index(a), order.index(b)
    _, err = lay.link(i, j)
    overlap = float(lay.overlap[i, j]) if lay.overlap is not None else np.nan
    return float(err), overlap
