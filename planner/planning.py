"""The orchestrator: ``plan(site, scanner, requirements) -> Plan``, and the plan's files.

Steps: facades and samples → candidate stations → evaluation of every candidate × sample →
fewest stations (integer program) → registration network and targets → coverage by the
chosen stations → per-facade summary and unmet samples with the reason.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from planner.accuracy import station_rms_pair
from planner.candidates import candidate_grid, reach_m
from planner.errors import InputError
from planner.evaluate import (
    METRIC_KEYS,
    Context,
    best_achievable,
    evaluate_candidates,
    evaluate_stations,
)
from planner.facades import build_facades
from planner.io import write_text_atomic
from planner.optimise import CoverSolution, solve_cover
from planner.registration import connect, target_candidates, target_table_rows
from planner.requirements import PlanSettings, Requirements
from planner.scanner import Scanner, load_scanner
from planner.site import Site
from planner.siteio import default_site

__all__ = ["COVERAGE_COLUMNS", "STATION_COLUMNS", "TARGET_COLUMNS", "Plan", "plan"]

STATION_COLUMNS = ["station_id", "x", "y", "instrument_height_m"]
TARGET_COLUMNS = ["target_id", "x", "y", "z", "type", "min_size_mm", "size_mm", "station_ids"]
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
    "m_x_mm",
    "m_y_mm",
    "m_z_mm",
    "meets",
]

Progress = Callable[[float, str], None]


@dataclass
class Plan:
    """A field plan: stations, targets, coverage of every facade sample, and diagnostics.

    DataFrames (coordinates in the site's CRS, heights above the ground):

    * ``stations`` — ``station_id, x, y, instrument_height_m, purpose`` ("cover" or "link"),
      ``samples_met``;
    * ``targets`` — ``target_id, x, y, z, type, min_size_mm, size_mm, station_ids`` (a list),
      ``item``;
    * ``coverage`` — one row per facade sample, the columns of :data:`COVERAGE_COLUMNS` plus
      ``spacing_mm, stations_meeting, party_wall, reason``;
    * ``facades`` — per-facade summary; ``links`` — registration links between stations;
    * ``candidates`` — every candidate position with the number of samples it meets.
    """

    site: Site
    scanner: Scanner
    requirements: Requirements
    settings: PlanSettings
    stations: pd.DataFrame
    targets: pd.DataFrame
    coverage: pd.DataFrame
    facades: pd.DataFrame
    links: pd.DataFrame
    candidates: pd.DataFrame
    solver: dict[str, Any]
    messages: list[str] = field(default_factory=list)
    timings_s: dict[str, float] = field(default_factory=dict)

    @property
    def unmet(self) -> pd.DataFrame:
        """Samples (not on party walls) where the requirements are not met."""
        c = self.coverage
        return c[~c["meets"] & ~c["party_wall"]]

    def facade_table(self) -> pd.DataFrame:
        """The per-facade summary as shown to a surveyor (indexed by facade id)."""
        cols = [
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
        return self.facades.set_index("facade_id")[cols].round(2)

    @property
    def meets_all(self) -> bool:
        return self.unmet.empty

    def summary(self) -> str:
        """A few lines a surveyor reads first."""
        req, sc = self.requirements, self.scanner
        cov = self.coverage[~self.coverage["party_wall"]]
        n_cover = int((self.stations["purpose"] == "cover").sum())
        n_link = int((self.stations["purpose"] == "link").sum())
        s = self.solver
        lines = [
            f"Site {self.site.name!r}: {len(self.site.planned)} building(s) planned, "
            f"{len(self.facades)} facades, {len(cov)} samples "
            f"(+{int(self.coverage['party_wall'].sum())} on party walls, not demanded)",
            f"Scanner {sc.name}; required m_x <= {req.max_x_mm:g} mm, m_y <= {req.max_y_mm:g} mm, "
            f"m_z <= {req.max_z_mm:g} mm, γ <= {req.max_gamma_deg:g}°"
            + (f", spacing <= {req.max_spacing_mm:g} mm" if req.max_spacing_mm else "")
            + (
                f", {req.stations_per_sample} stations per sample"
                if req.stations_per_sample > 1
                else ""
            ),
            f"Stations: {len(self.stations)} ({n_cover} to cover"
            + (f", {n_link} to link" if n_link else "")
            + f"), chosen by {s['method']} "
            f"({s['status']}; objective {s['objective']}"
            + (
                f", lower bound {s['lower_bound']:g}, gap {100 * s['gap']:.1f} %"
                if s.get("gap") is not None
                else ""
            )
            + (f"; greedy {s['greedy_objective']}" if s.get("greedy_objective") is not None else "")
            + f") from {len(self.candidates)} candidates",
            f"Targets: {len(self.targets)}"
            + (
                " ("
                + ", ".join(f"{n} {t}" for t, n in self.targets["type"].value_counts().items())
                + ")"
                if len(self.targets)
                else ""
            ),
            f"Samples meeting every requirement: {int(cov['meets'].sum())} of {len(cov)}",
        ]
        return "\n".join(lines + self.messages)

    # -- files ----------------------------------------------------------------------------
    def stations_csv(self) -> str:
        return self.stations[STATION_COLUMNS].to_csv(index=False, float_format="%.3f")

    def targets_csv(self) -> str:
        t = self.targets.copy()
        t["station_ids"] = t["station_ids"].map(lambda ids: ";".join(ids))
        return t[TARGET_COLUMNS].to_csv(index=False, float_format="%.3f")

    def coverage_csv(self) -> str:
        c = self.coverage[~self.coverage["party_wall"]]
        return c[COVERAGE_COLUMNS].to_csv(index=False, float_format="%.3f")

    def geojson(self) -> dict:
        """Buildings, facades, stations, links, targets and unmet samples as GeoJSON."""
        feats: list[dict] = []

        def add(geom: dict, **props: Any) -> None:
            feats.append({"type": "Feature", "geometry": geom, "properties": _clean(props)})

        for b in self.site.buildings:
            add(
                json.loads(_to_geojson(b.footprint)),
                layer="building",
                building_id=b.id,
                height_m=b.height_m,
                planned=b.planned,
                name=b.name,
            )
        for o in self.site.obstacles:
            add(
                json.loads(_to_geojson(o.geometry)),
                layer="obstacle",
                obstacle_id=o.id,
                kind=o.kind,
                height_m=o.height_m,
            )
        for a in self.site.no_go:
            add(json.loads(_to_geojson(a.geometry)), layer="no-go", area_id=a.id)
        for r in self.facades.itertuples():
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
        st = self.stations.set_index("station_id")
        for r in self.stations.itertuples():
            add(
                {"type": "Point", "coordinates": [r.x, r.y]},
                layer="station",
                station_id=r.station_id,
                instrument_height_m=r.instrument_height_m,
                purpose=r.purpose,
                samples_met=r.samples_met,
            )
        for r in self.links.itertuples():
            a, b = st.loc[r.station_a], st.loc[r.station_b]
            add(
                {"type": "LineString", "coordinates": [[a.x, a.y], [b.x, b.y]]},
                layer="link",
                station_a=r.station_a,
                station_b=r.station_b,
                common_targets=r.common_targets,
                targets_placed=r.targets_placed,
            )
        for r in self.targets.itertuples():
            add(
                {"type": "Point", "coordinates": [r.x, r.y, r.z]},
                layer="target",
                target_id=r.target_id,
                type=r.type,
                min_size_mm=r.min_size_mm,
                size_mm=r.size_mm,
                item=r.item,
                station_ids=";".join(r.station_ids),
            )
        for r in self.unmet.itertuples():
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
            "name": f"tls-planner plan: {self.site.name}",
        }
        if self.site.crs:
            out["crs"] = {"type": "name", "properties": {"name": self.site.crs}}
        out["features"] = feats
        return out

    def save(self, out_dir: str | Path) -> list[Path]:
        """Write stations.csv, targets.csv, coverage.csv, facades.csv, plan.geojson and
        summary.txt into ``out_dir``. Every file is rendered first, then written atomically:
        a failure never leaves a half-written file over a good one."""
        out = Path(out_dir)
        if out.exists() and not out.is_dir():
            raise InputError(f"{out} exists and is not a folder; choose another --out")
        texts = {
            "stations.csv": self.stations_csv(),
            "targets.csv": self.targets_csv(),
            "coverage.csv": self.coverage_csv(),
            "facades.csv": self.facades.to_csv(index=False, float_format="%.3f"),
            "plan.geojson": json.dumps(self.geojson(), indent=1, allow_nan=False) + "\n",
            "summary.txt": self.summary() + "\n" + _unmet_listing(self) + "\n",
        }
        return [write_text_atomic(out / name, text) for name, text in texts.items()]


def _to_geojson(geom: Any) -> str:
    import shapely

    return shapely.to_geojson(shapely.set_precision(geom, 0.001))


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


def _unmet_listing(p: Plan, limit: int = 50) -> str:
    u = p.unmet
    if u.empty:
        return "Every sample meets the requirements."
    lines = [f"Unmet samples: {len(u)} (first {min(limit, len(u))}):"]
    for r in u.head(limit).itertuples():
        lines.append(f"  {r.sample_id} at ({r.x:.2f}, {r.y:.2f}, z {r.z:.1f} m): {r.reason}")
    return "\n".join(lines)


# -- the orchestrator ---------------------------------------------------------------------
def plan(
    site: Site | None = None,
    scanner: Scanner | str | None = None,
    requirements: Requirements | None = None,
    settings: PlanSettings | None = None,
    *,
    progress: Progress | None = None,
) -> Plan:
    """Plan the fewest stations meeting ``requirements`` around the planned buildings.

    Defaults: the built-in default site, the scanner of Voroshilov & Karachentsev's example
    (``leica-4mm-60urad``), :class:`Requirements()` and :class:`PlanSettings()`.
    Infeasible requirements do not raise: the samples no candidate can satisfy come back
    with ``meets`` False and the reason (see :attr:`Plan.unmet`).
    """
    timings: dict[str, float] = {}
    t0 = time.perf_counter()
    site = site or default_site()
    sc = load_scanner(scanner or "leica-4mm-60urad")
    req = requirements or Requirements()
    st = settings or PlanSettings()
    say = progress or (lambda _f, _m: None)
    messages = list(site.warnings)

    say(0.0, "sampling facades")
    fac = build_facades(site, st.sample_spacing_m, st.sample_height_step_m)
    reach = reach_m(sc, req, station_rms_pair(st.station_rms_mm))
    cand = candidate_grid(site, fac, reach, st.grid_m, st.clearance_m)
    ctx = Context.build(site, fac, sc, req, st, reach)
    timings["setup"] = time.perf_counter() - t0
    if len(cand) == 0:
        messages.append(
            "no free ground for a station within reach of the facades "
            f"({reach:.0f} m, clearance {st.clearance_m:g} m)"
        )

    t = time.perf_counter()
    ev = evaluate_candidates(ctx, cand, progress=lambda f, m: say(0.05 + 0.6 * f, m))
    timings["evaluate"] = time.perf_counter() - t

    say(0.7, "choosing the fewest stations")
    t = time.perf_counter()
    n_ok = np.asarray(ev.ok.sum(axis=1)).ravel()
    k = req.stations_per_sample
    demand = np.where(fac.party_wall, 0, np.minimum(k, n_ok))
    sol: CoverSolution = solve_cover(ev.ok, demand, st.time_limit_s, st.method)
    timings["optimise"] = time.perf_counter() - t

    say(0.85, "registration network and targets")
    t = time.perf_counter()
    stand_xy = candidate_grid(site, fac, min(reach, 40.0), st.target_spacing_m, st.clearance_m)
    tc = target_candidates(ctx, stand_xy)
    net = connect(ctx, tc, cand, sol.chosen) if len(sol.chosen) else None
    station_idx = net.stations if net is not None else np.empty(0, dtype=np.int64)
    timings["registration"] = time.perf_counter() - t

    say(0.93, "coverage of the chosen stations")
    t = time.perf_counter()
    station_xy = cand[station_idx] if len(station_idx) else np.empty((0, 2))
    ids = [f"S{i + 1:02d}" for i in range(len(station_idx))]
    dense = evaluate_stations(ctx, station_xy)
    coverage = _coverage(ctx, ev, dense, ids, cand)
    stations = pd.DataFrame(
        {
            "station_id": ids,
            "x": station_xy[:, 0] if len(ids) else [],
            "y": station_xy[:, 1] if len(ids) else [],
            "instrument_height_m": st.instrument_height_m,
            "purpose": ["cover"] * (len(ids) - (net.n_link_stations if net else 0))
            + ["link"] * (net.n_link_stations if net else 0),
            "samples_met": dense["ok"].sum(axis=0) if len(ids) else [],
        }
    )
    targets, links = _targets_and_links(ctx, tc, net, ids)
    timings["coverage"] = time.perf_counter() - t
    if net is not None:
        messages.append(f"Registration: {net.message}.")
    unmet = coverage[~coverage["meets"] & ~coverage["party_wall"]]
    if len(unmet):
        messages.extend(_unmet_messages(unmet))
    candidates = pd.DataFrame(
        {"x": cand[:, 0], "y": cand[:, 1], "samples_met": np.asarray(ev.ok.sum(axis=0)).ravel()}
    )
    solver = {
        "method": sol.method,
        "status": sol.status,
        "objective": sol.objective,
        "lower_bound": sol.lower_bound,
        "gap": sol.gap,
        "seconds": sol.seconds,
        "greedy_objective": sol.greedy_objective,
        "reach_m": reach,
        "candidates": len(cand),
        "samples": int((~fac.party_wall).sum()),
    }
    timings["total"] = time.perf_counter() - t0
    say(1.0, "plan ready")
    return Plan(
        site,
        sc,
        req,
        st,
        stations,
        targets,
        coverage,
        _facade_summary(fac, coverage),
        links,
        candidates,
        solver,
        messages,
        timings,
    )


def _reason(ctx: Context, n_view: int, b: dict[str, float], n_meet: int) -> str:
    req = ctx.req
    if n_view == 0:
        return "no free station position sees this point (blocked, or out of the scanner's range)"
    k = req.stations_per_sample
    if 0 < n_meet < k:
        return f"only {n_meet} station position(s) meet every requirement here; {k} required"
    parts = []
    for key, label, limit, unit in (
        ("m_x_mm", "m_x", req.max_x_mm, "mm"),
        ("m_y_mm", "m_y", req.max_y_mm, "mm"),
        ("m_z_mm", "m_z", req.max_z_mm, "mm"),
        ("gamma_deg", "γ", req.max_gamma_deg, "°"),
        ("spacing_mm", "point spacing", req.max_spacing_mm, "mm"),
    ):
        if limit is not None and b[key] > limit:
            parts.append(f"best achievable {label} {b[key]:.1f} {unit} > {limit:g} {unit}")
    if parts:
        return "; ".join(parts)
    return (
        f"no single station meets every requirement at once (closest: {b['score']:.2f} × "
        "the limits)"
    )


def _coverage(
    ctx: Context, ev: Any, dense: dict[str, np.ndarray], ids: list[str], cand_xy: np.ndarray
) -> pd.DataFrame:
    fac = ctx.facades
    n = len(fac.z)
    k_req = ctx.req.stations_per_sample
    n_ok_cand = np.asarray(ev.ok.sum(axis=1)).ravel()
    keys = METRIC_KEYS
    if ids:  # the assigned station: the best meeting one, else the best that sees the sample
        score = np.where(dense["ok"], dense["score"], dense["score"] + 1e6)
        score = np.where(dense["view"], score, np.inf)
        assigned = np.argmin(score, axis=1)
        has = np.isfinite(score[np.arange(n), assigned])
        picked = {k: np.where(has, dense[k][np.arange(n), assigned], np.nan) for k in keys}
        station = np.where(has, np.array(ids, dtype=object)[assigned], "")
        n_meeting = dense["ok"].sum(axis=1)
    else:
        picked = {k: np.full(n, np.nan) for k in keys}
        station = np.full(n, "", dtype=object)
        n_meeting = np.zeros(n, dtype=int)
    meets = (n_meeting >= k_req) & ~fac.party_wall
    reason = np.full(n, "", dtype=object)
    short = np.flatnonzero(~meets & ~fac.party_wall & (n_ok_cand >= k_req))
    reason[short] = [
        f"the chosen stations do not cover this sample ({n_meeting[i]} of {k_req})" for i in short
    ]
    hopeless = np.flatnonzero(~meets & ~fac.party_wall & (n_ok_cand < k_req))
    if len(hopeless):
        diag = best_achievable(ctx, cand_xy, hopeless)
        for j, i in enumerate(hopeless):
            b = {key: float(v[j]) for key, v in diag.items()}
            reason[i] = _reason(ctx, int(ev.n_view[i]), b, int(n_ok_cand[i]))
    reason[fac.party_wall] = "party wall (against a neighbour): not scanned"
    return pd.DataFrame(
        {
            "building_id": fac.building_id[fac.facade],
            "facade_id": fac.facade_id[fac.facade],
            "sample_id": fac.sample_id,
            "x": fac.xy[:, 0],
            "y": fac.xy[:, 1],
            "z": fac.z,
            "station_id": station,
            "distance_m": picked["distance_m"],
            "slope_distance_m": picked["slope_distance_m"],
            "gamma_deg": picked["gamma_deg"],
            "nu_deg": picked["nu_deg"],
            "m_x_mm": picked["m_x_mm"],
            "m_y_mm": picked["m_y_mm"],
            "m_z_mm": picked["m_z_mm"],
            "meets": meets,
            "spacing_mm": picked["spacing_mm"],
            "stations_meeting": n_meeting,
            "party_wall": fac.party_wall,
            "reason": reason,
        }
    )


def _facade_summary(fac: Any, cov: pd.DataFrame) -> pd.DataFrame:
    rows = []
    for f in range(fac.n_facades):
        c = cov[cov["facade_id"] == fac.facade_id[f]]
        scanned = c[~c["party_wall"]]
        rows.append(
            {
                "building_id": fac.building_id[f],
                "facade_id": fac.facade_id[f],
                "x0": fac.start[f, 0],
                "y0": fac.start[f, 1],
                "x1": fac.end[f, 0],
                "y1": fac.end[f, 1],
                "length_m": fac.length_m[f],
                "height_m": fac.height_m[f],
                "courtyard": bool(fac.courtyard[f]),
                "samples": len(c),
                "party_wall_samples": int(c["party_wall"].sum()),
                "met": int(scanned["meets"].sum()),
                "unmet": int((~scanned["meets"]).sum()),
                "worst_m_x_mm": scanned["m_x_mm"].max(),
                "worst_m_y_mm": scanned["m_y_mm"].max(),
                "worst_m_z_mm": scanned["m_z_mm"].max(),
                "stations": ";".join(sorted(s for s in scanned["station_id"].unique() if s)),
            }
        )
    return pd.DataFrame(rows)


def _targets_and_links(
    ctx: Context, tc: Any, net: Any, ids: list[str]
) -> tuple[pd.DataFrame, pd.DataFrame]:
    tcols = [*TARGET_COLUMNS, "item"]
    lcols = ["station_a", "station_b", "common_targets", "targets_placed"]
    if net is None or not len(ids):
        return pd.DataFrame(columns=tcols), pd.DataFrame(columns=lcols)
    rows = target_table_rows(ctx, tc, net)
    targets = pd.DataFrame(
        {
            "target_id": [f"T{i + 1:02d}" for i in range(len(rows))],
            "x": [r["x"] for r in rows],
            "y": [r["y"] for r in rows],
            "z": [r["z"] for r in rows],
            "type": [r["type"] for r in rows],
            "min_size_mm": [r["min_size_mm"] for r in rows],
            "size_mm": [r["size_mm"] for r in rows],
            "station_ids": [[ids[s] for s in r["stations"]] for r in rows],
            "item": [r["item"] for r in rows],
        },
        columns=tcols,
    )
    placed: dict[tuple[int, int], int] = {}
    for t in net.targets:
        for link in net.target_links[t]:
            placed[link] = placed.get(link, 0) + 1
    links = pd.DataFrame(
        [
            {
                "station_a": ids[a],
                "station_b": ids[b],
                "common_targets": n,
                "targets_placed": placed.get((a, b), 0),
            }
            for a, b, n in net.links
        ],
        columns=lcols,
    )
    return targets, links


def _unmet_messages(unmet: pd.DataFrame) -> list[str]:
    out = [f"{len(unmet)} sample(s) do not meet the requirements:"]
    for (bid, fid), g in unmet.groupby(["building_id", "facade_id"], sort=True):
        reasons = g["reason"].value_counts()
        out.append(
            f"  facade {fid} (building {bid}): {len(g)} sample(s), "
            f"z {g['z'].min():.1f}–{g['z'].max():.1f} m"
            f" — {reasons.index[0]}"
            + (f" (and {len(reasons) - 1} other reason(s))" if len(reasons) > 1 else "")
        )
    return out
