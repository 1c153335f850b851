"""Re-plan from what was scanned: the stations where the crew set up, and what is left.

On site a crew sets up where the ground allows, skips a scan, meets a van in front of a
facade. :func:`replan` takes the stations as scanned (read from the registered project's
E57 or a CSV, :func:`planner.pipeline.pointclouds.read_poses`) and the targets as placed,
judges every sample again with the real positions — coverage, scanner ⊕ registration —
and proposes the fewest extra stations for what is left, each with its reason; the
stations scanned keep their ids and the extra ones take numbers never given before.

:func:`compare_links` reads a registration program's report (the error of each link,
optionally its overlap) and sets it beside the plan's predicted link errors.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from planner.errors import InputError
from planner.pipeline.evaluate import Progress
from planner.pipeline.planning import choose_stations
from planner.pipeline.result import Plan
from planner.pipeline.whatif import _workbench, edit_targets, evaluate_stations

__all__ = [
    "AS_SCANNED_COLUMNS",
    "REPORT_ALIASES",
    "Replan",
    "compare_links",
    "read_link_report",
    "read_targets_placed",
    "replan",
]

#: A scanned station this far [m] from its planned place counts as moved.
MOVED_M = 0.05
#: Two scans within this [m] of each other are one set-up twice.
SAME_SPOT_M = 0.5
#: The table of stations as scanned against the plan.
AS_SCANNED_COLUMNS = ["station_id", "status", "x", "y", "moved_m", "samples_met", "reason"]


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
    """The plan ``p`` (made in this process) re-planned from the stations ``scanned``
    (``station_id, x, y`` [m], site CRS) and the targets as placed (``target_id, x, y``;
    None: as planned): see the module text. A scanned id the plan does not have is a
    station added on site; a planned station missing from ``scanned`` was skipped."""
    wb = _workbench(p)
    planned = p.scan_stations.set_index("station_id")
    xy = scanned[["x", "y"]].to_numpy(dtype=float)
    ids = scanned["station_id"].astype(str).tolist()
    _one_setup_each(xy, ids)
    if targets_placed is not None and len(targets_placed):
        p = _targets_as_placed(p, targets_placed)
    wb.last_station = max(wb.last_station, _highest(p))
    as_scanned = evaluate_stations(p, xy, ids)
    before = (int(as_scanned.scanned["meets"].sum()), len(as_scanned.scanned))
    left = set(as_scanned.unmet["sample_id"])
    new = as_scanned
    if left:  # the fewest others around the scans made, kept only where they meet more
        again = choose_stations(wb, progress, locked=xy, locked_ids=ids, edited=True)
        if again.scanned["meets"].sum() > before[0]:
            new = again
    return Replan(
        plan=new,
        stations=_table(new, scanned, planned, left),
        scanned_plan=as_scanned,
        before=before,
    )


def _one_setup_each(xy: np.ndarray, ids: list[str]) -> None:
    d = np.hypot(*(xy[:, None, :] - xy[None, :, :]).transpose(2, 0, 1))
    d[np.tri(len(xy), dtype=bool)] = np.inf
    if len(xy) > 1 and d.min() < SAME_SPOT_M:
        a, b = np.unravel_index(int(np.argmin(d)), d.shape)
        raise InputError(
            f"stations {ids[a]} and {ids[b]} were scanned {d[a, b]:.2f} m apart: one set-up "
            "twice; give one of them"
        )


def _highest(p: Plan) -> int:
    nums = p.stations["station_id"].astype(str).str.extract(r"^S(\d+)$")[0].dropna()
    return int(nums.astype(int).max()) if len(nums) else 0


def _targets_as_placed(p: Plan, placed: pd.DataFrame) -> Plan:
    known = set(p.targets["target_id"].astype(str))
    unknown = sorted(set(placed["target_id"].astype(str)) - known)
    if unknown:
        raise InputError(
            f"targets {', '.join(unknown[:5])} are not in the plan; give the plan's target ids "
            "with where each was placed"
        )
    old = p.targets.set_index("target_id")[["x", "y"]]
    move = {
        str(r.target_id): (float(r.x), float(r.y))
        for r in placed.itertuples()
        if np.hypot(r.x - old.loc[r.target_id, "x"], r.y - old.loc[r.target_id, "y"]) >= MOVED_M
    }
    missing = sorted(known - set(placed["target_id"].astype(str)))
    return edit_targets(p, move=move, remove=missing) if move or missing else p


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
        rows.append((sid, status, r.x, r.y, d, int(met.get(sid, 0)), ""))
    for sid in planned.index.difference(scanned["station_id"].astype(str)):
        rows.append((sid, "skipped", planned.loc[sid, "x"], planned.loc[sid, "y"], np.nan, 0, ""))
    known = set(scanned["station_id"].astype(str)) | set(planned.index)
    scans = new.scan_stations
    by_number = scans["station_id"].str.extract(r"(\d+)$")[0].astype(float).to_numpy()
    for r in scans.iloc[np.argsort(by_number, kind="stable")].itertuples():
        if r.station_id not in known:
            rows.append(
                (r.station_id, "extra", r.x, r.y, np.nan, int(r.samples_met), _reason(new, r, left))
            )
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
    """Targets as placed: a CSV with ``target_id, x, y`` (the plan's ids, site CRS [m])."""
    try:
        df = pd.read_csv(path, dtype={"target_id": str})
    except (OSError, ValueError, UnicodeDecodeError, pd.errors.ParserError) as exc:
        raise InputError(f"{path}: not a readable CSV ({exc})") from None
    df.columns = [str(c).strip().lower() for c in df.columns]
    if not {"target_id", "x", "y"} <= set(df.columns):
        raise InputError(f"{path}: needs the columns target_id, x, y (where each was placed)")
    for c in ("x", "y"):
        df[c] = pd.to_numeric(df[c], errors="coerce")
    if df[["x", "y"]].isna().any().any():
        raise InputError(f"{path}: every target needs x and y as numbers (site CRS)")
    return df[["target_id", "x", "y"]]


#: A registration report's columns under the names registration programs give them.
REPORT_ALIASES = {
    "station_a": ("station_a", "from", "scan_a", "reference", "scan 1", "setup 1", "source"),
    "station_b": ("station_b", "to", "scan_b", "scan 2", "setup 2", "target scan", "moving"),
    "error_mm": ("error_mm", "error", "bundle error", "link error", "rms", "rms_mm", "mean error"),
    "overlap_pct": ("overlap_pct", "overlap", "overlap %", "overlap (%)"),
}


def read_link_report(path: str | Path) -> pd.DataFrame:
    """A registration report's links: ``station_a, station_b, error_mm`` and, where
    given, ``overlap_pct`` — from a CSV whose columns bear those names or a registration
    program's (:data:`REPORT_ALIASES`; an error given in metres, ``… (m)``, is converted)."""
    try:
        df = pd.read_csv(path, sep=None, engine="python")
    except (OSError, ValueError, UnicodeDecodeError, pd.errors.ParserError) as exc:
        raise InputError(f"{path}: not a readable CSV ({exc})") from None
    out = {}
    for key, names in REPORT_ALIASES.items():
        for c in df.columns:
            bare = str(c).strip().lower()
            unit_m = bare.endswith("(m)") or bare.endswith("[m]")
            bare = bare.removesuffix("(m)").removesuffix("[m]").removesuffix("(mm)").strip()
            if bare in names:
                col = df[c]
                if key in ("error_mm", "overlap_pct"):
                    col = pd.to_numeric(col.astype(str).str.rstrip("%"), errors="coerce")
                    col = col * 1000 if unit_m and key == "error_mm" else col
                out[key] = col
                break
    missing = [k for k in ("station_a", "station_b", "error_mm") if k not in out]
    if missing:
        raise InputError(
            f"{path}: no column for {', '.join(missing)} (give station_a, station_b, error_mm "
            "and optionally overlap_pct, or the report's own names such as From, To, Error)"
        )
    rep = pd.DataFrame(out)
    rep["station_a"] = rep["station_a"].astype(str).str.strip()
    rep["station_b"] = rep["station_b"].astype(str).str.strip()
    return rep


def compare_links(p: Plan, report: pd.DataFrame) -> pd.DataFrame:
    """Each reported link beside the plan's prediction (either direction of the pair):
    ``predicted_mm`` (the link's own predicted error), ``ratio`` reported/predicted and a
    verdict — within the prediction, up to twice it, over twice it, or not a link of the
    plan."""
    links = {frozenset((r.station_a, r.station_b)): r for r in p.links.itertuples(index=False)}
    rows = []
    for r in report.itertuples():
        k = frozenset((r.station_a, r.station_b))
        link = links.get(k)
        pred = float(link.link_rms_mm) if link is not None else np.nan
        ratio = r.error_mm / pred if pred > 0 else np.nan
        if np.isnan(pred):
            verdict = "not a link of the plan"
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
                "reported_mm": r.error_mm,
                "predicted_mm": pred,
                "ratio": ratio,
                "reported_overlap_pct": getattr(r, "overlap_pct", np.nan),
                "predicted_overlap_pct": float(link.overlap_pct) if link is not None else np.nan,
                "verdict": verdict,
            }
        )
    return pd.DataFrame(rows)
