"""The orchestrator: ``plan(site, scanner, requirements, settings) -> Plan``.

Steps: facades and samples → candidate stations → evaluation of every candidate × sample →
fewest stations (:mod:`~planner.pipeline.optimise`) → registration network and targets
(:mod:`~planner.pipeline.registration`) → coverage by the chosen stations → per-facade
summary and unmet samples with the reason. The result type is
:class:`~planner.pipeline.result.Plan`; its files are written by
:mod:`~planner.pipeline.export`.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd

from planner.accuracy import reach_bound_m
from planner.accuracy3d import reach_bound_3d_m
from planner.errors import InputError
from planner.pipeline.candidates import candidate_grid
from planner.pipeline.evaluate import (
    METRIC_KEYS,
    Assignment,
    CandidateEvaluation,
    Context,
    assign_stations,
    best_achievable,
    evaluate_candidates,
)
from planner.pipeline.facades import FacadeSet, build_facades, estimate_samples
from planner.pipeline.optimise import solve_cover
from planner.pipeline.registration import (
    Network,
    TargetCandidates,
    connect,
    target_candidates,
    target_table_rows,
)
from planner.pipeline.requirements import CHECKS, PlanSettings, Requirements
from planner.pipeline.result import Plan
from planner.scanner import DEFAULT_SCANNER, Scanner, load_scanner
from planner.site import Site

__all__ = ["plan"]

Progress = Callable[[float, str], None]

#: Candidate stations farther than this from a facade are not searched [m] (the accuracy
#: bound usually stops well before).
MIN_SEARCH_RADIUS_M = 25.0
#: Evaluation speed used to put a work estimate in minutes [pairs per second].
PAIRS_PER_S = 20e6
#: The optimiser always gets at least this long, even when the evaluation used the budget
#: (greedy set cover takes well under it) [s].
MIN_SOLVER_S = 2.0


def reach_m(
    scanner: Scanner,
    req: Requirements,
    station_rms_mm: tuple[float, float],
    model: str = "3d",
) -> float:
    """Search radius for candidate stations [m]: the distance beyond which no station can
    meet the requirements under ``model`` (:func:`planner.accuracy.reach_bound_m`,
    :func:`planner.accuracy3d.reach_bound_3d_m`), within the scanner's and the requirement's
    range, and never below :data:`MIN_SEARCH_RADIUS_M` — so that even an infeasible
    requirement gets candidates close by and the plan can say what is achievable."""
    if model == "paper":
        bound = reach_bound_m(scanner, req.max_x_mm, req.max_y_mm, req.max_z_mm, station_rms_mm)
    else:
        bound = reach_bound_3d_m(scanner, req.max_x_mm, req.max_y_mm, station_rms_mm)
    limit = min(scanner.max_range_m, req.max_range_m or np.inf)
    return float(min(limit, max(bound, MIN_SEARCH_RADIUS_M)))


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
    (:data:`~planner.scanner.DEFAULT_SCANNER`), ``Requirements()`` and ``PlanSettings()``.
    Infeasible requirements do not raise: the samples no candidate can satisfy come back
    with ``meets`` False and the reason (see :attr:`Plan.unmet`).
    """
    from planner.siteio import default_site

    timings: dict[str, float] = {}
    t0 = time.perf_counter()
    _expect(site, Site, "site", "read one with planner.read_site(path) or planner.default_site()")
    _expect(requirements, Requirements, "requirements", "e.g. Requirements(max_xy_mm=4)")
    _expect(settings, PlanSettings, "settings", "e.g. PlanSettings(grid_m=2)")
    if scanner is not None and not isinstance(scanner, Scanner | str | Path):
        raise InputError(
            f"scanner must be a Scanner, a catalogue name or a profile file; got "
            f"{type(scanner).__name__}"
        )
    site = site or default_site()
    sc = load_scanner(scanner or DEFAULT_SCANNER)
    req = requirements or Requirements()
    st = settings or PlanSettings()
    say = progress or (lambda _f, _m: None)
    messages = list(site.warnings)

    deadline = time.monotonic() + st.time_limit_s
    say(0.0, "sampling facades")
    n_est = estimate_samples(site, st.sample_spacing_m, st.sample_height_step_m)
    if n_est > st.max_samples:
        raise InputError(
            f"the facades would need about {n_est:,} samples at {st.sample_spacing_m:g} m × "
            f"{st.sample_height_step_m:g} m, more than {st.max_samples:,.0f}; use coarser "
            "samples (--sample-spacing-m, --sample-height-step-m), plan fewer buildings, or "
            "raise the limit (--max-samples)"
        )
    fac = build_facades(site, st.sample_spacing_m, st.sample_height_step_m)
    reach = reach_m(sc, req, st.station_rms_pair, st.model)
    cand = candidate_grid(site, fac, reach, st.grid_m, st.clearance_m)
    ctx = Context.build(site, fac, sc, req, st, reach)
    pairs = ctx.pair_count(cand)
    if pairs > st.max_pairs:
        raise InputError(
            f"the plan would evaluate {pairs:.3g} station × sample pairs (about "
            f"{pairs / PAIRS_PER_S / 60:.0f} min), more than {st.max_pairs:.3g}; use a coarser "
            "grid (--grid-m) or coarser samples, plan fewer buildings, or raise the limit "
            "(--max-pairs)"
        )
    timings["setup"] = time.perf_counter() - t0
    if len(cand) == 0:
        messages.append(
            "no free ground for a station within reach of the facades "
            f"({reach:.0f} m, clearance {st.clearance_m:g} m)"
        )

    t = time.perf_counter()
    ev = evaluate_candidates(
        ctx, cand, progress=lambda f, m: say(0.05 + 0.6 * f, m), deadline=deadline
    )
    timings["evaluate"] = time.perf_counter() - t
    if not ev.evaluated.all():
        messages.append(
            f"The time limit of {st.time_limit_s:g} s ran out during the evaluation: "
            f"{int(ev.evaluated.sum())} of {len(fac.z)} samples were evaluated; the plan covers "
            "those. Raise --time-limit-s for the whole site."
        )

    say(0.7, "choosing the fewest stations")
    t = time.perf_counter()
    n_ok = np.asarray(ev.ok.sum(axis=1)).ravel()
    demand = np.where(fac.party_wall, 0, np.minimum(req.stations_per_sample, n_ok))
    remaining = max(MIN_SOLVER_S, deadline - time.monotonic())
    sol = solve_cover(ev.ok, demand, remaining, st.method)
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
    assignment = assign_stations(ctx, station_xy)
    coverage = _coverage(ctx, ev, assignment, ids, cand, deadline)
    n_link = net.n_link_stations if net else 0
    stations = pd.DataFrame(
        {
            "station_id": ids,
            "x": station_xy[:, 0],
            "y": station_xy[:, 1],
            "instrument_height_m": st.instrument_height_m,
            "purpose": ["cover"] * (len(ids) - n_link) + ["link"] * n_link,
            "samples_met": assignment.met_by_station,
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
        "pairs": pairs,
    }
    messages.insert(0, f"Accuracy model: {st.model_description()}.")
    timings["total"] = time.perf_counter() - t0
    say(1.0, "plan ready")
    return Plan(
        site=site,
        scanner=sc,
        requirements=req,
        settings=st,
        stations=stations,
        targets=targets,
        coverage=coverage,
        facades=_facade_summary(fac, coverage),
        links=links,
        candidates=candidates,
        solver=solver,
        messages=messages,
        timings_s=timings,
    )


def _expect(value: object, kind: type, name: str, hint: str) -> None:
    """The Python API's boundary: a wrong type is an InputError saying what to pass."""
    if value is not None and not isinstance(value, kind):
        raise InputError(
            f"{name} must be a planner.{kind.__name__} ({hint}); got {type(value).__name__}"
            + (f" {value!r}"[:80] if isinstance(value, str | Path) else "")
        )


def _reason(ctx: Context, sample: int, n_view: int, best: dict[str, float], n_meet: int) -> str:
    """Why no station meets ``sample``, in words: each check the best candidate fails."""
    if n_view == 0:
        return "no free station position sees this point (blocked, or out of the scanner's range)"
    k = ctx.req.stations_per_sample
    if 0 < n_meet < k:
        return f"only {n_meet} station position(s) meet every requirement here; {k} required"
    parts = []
    for c in CHECKS:
        limit = float(ctx.limits[c.key][sample])
        if np.isfinite(limit) and not c.passes(np.float64(best[c.key]), limit):
            parts.append(c.shortfall(best[c.key], limit))
    if parts:
        return "; ".join(parts)
    return (
        f"no single station meets every requirement at once (closest: {best['score']:.2f} × "
        "the limits)"
    )


def _coverage(
    ctx: Context,
    ev: CandidateEvaluation,
    assignment: Assignment,
    ids: list[str],
    cand_xy: np.ndarray,
    deadline: float = math.inf,
) -> pd.DataFrame:
    fac = ctx.facades
    n = len(fac.z)
    k_req = ctx.req.stations_per_sample
    n_ok_cand = np.asarray(ev.ok.sum(axis=1)).ravel()
    picked, n_meeting = assignment.metrics, assignment.n_meeting
    names = np.array([*ids, ""], dtype=object)
    station = names[assignment.station]  # -1 picks the "" at the end
    demanded = ~fac.party_wall
    meets = (n_meeting >= k_req) & demanded
    reason = np.full(n, "", dtype=object)
    short = np.flatnonzero(~meets & demanded & (n_ok_cand >= k_req))
    reason[short] = [
        f"the chosen stations do not cover this sample ({n_meeting[i]} of {k_req})" for i in short
    ]
    hopeless = np.flatnonzero(~meets & demanded & (n_ok_cand < k_req) & ev.evaluated)
    if len(hopeless):
        diag = best_achievable(ctx, cand_xy, hopeless, deadline)
        for j, i in enumerate(hopeless):
            if not diag["done"][j]:
                reason[i] = "no station meets it (not diagnosed further: the time limit ran out)"
                continue
            best = {key: float(v[j]) for key, v in diag.items()}
            reason[i] = _reason(ctx, int(i), int(ev.n_view[i]), best, int(n_ok_cand[i]))
    reason[~meets & demanded & ~ev.evaluated] = (
        f"not evaluated: the time limit of {ctx.settings.time_limit_s:g} s ran out"
    )
    reason[fac.party_wall] = "party wall (against a neighbour): not scanned"
    extra = {}
    if ctx.req.accuracy_class:  # the class each sample achieves, beside pass/fail
        from planner.classes import achieved_class, parse_class

        family = parse_class(ctx.req.accuracy_class)[0].family
        extra["class_achieved"] = achieved_class(
            picked["m_x_mm"], picked["m_y_mm"], picked["m_z_mm"], family
        )
    return pd.DataFrame(
        {
            "building_id": fac.building_id[fac.facade],
            "facade_id": fac.facade_id[fac.facade],
            "sample_id": fac.sample_id,
            "x": fac.xy[:, 0],
            "y": fac.xy[:, 1],
            "z": fac.z,
            "station_id": station,
            **{k: picked[k] for k in METRIC_KEYS if k != "spacing_mm"},
            "meets": meets,
            "model": ctx.settings.model,
            "spacing_mm": picked["spacing_mm"],
            "stations_meeting": n_meeting,
            "party_wall": fac.party_wall,
            "reason": reason,
            **extra,
        }
    )


def _facade_summary(fac: FacadeSet, cov: pd.DataFrame) -> pd.DataFrame:
    scanned = cov[~cov["party_wall"]]
    by = scanned.groupby("facade_id", sort=False)
    stats = pd.DataFrame(
        {
            "met": by["meets"].sum(),
            "unmet": by["meets"].size() - by["meets"].sum(),
            "worst_m_x_mm": by["m_x_mm"].max(),
            "worst_m_y_mm": by["m_y_mm"].max(),
            "worst_m_z_mm": by["m_z_mm"].max(),
            "stations": by["station_id"].agg(lambda s: ";".join(sorted(v for v in set(s) if v))),
        }
    )
    allby = cov.groupby("facade_id", sort=False)
    out = pd.DataFrame(
        {
            "building_id": fac.building_id,
            "facade_id": fac.facade_id,
            "x0": fac.start[:, 0],
            "y0": fac.start[:, 1],
            "x1": fac.end[:, 0],
            "y1": fac.end[:, 1],
            "length_m": fac.length_m,
            "height_m": fac.height_m,
            "courtyard": fac.courtyard.astype(bool),
        }
    )
    out["samples"] = out["facade_id"].map(allby.size()).fillna(0).astype(int)
    out["party_wall_samples"] = (
        out["facade_id"].map(allby["party_wall"].sum()).fillna(0).astype(int)
    )
    stats = stats.reindex(out["facade_id"])
    for col in ("met", "unmet"):
        out[col] = stats[col].fillna(0).astype(int).to_numpy()
    for col in ("worst_m_x_mm", "worst_m_y_mm", "worst_m_z_mm"):
        out[col] = stats[col].to_numpy(dtype=float)
    out["stations"] = stats["stations"].fillna("").to_numpy(dtype=object)
    return out


def _targets_and_links(
    ctx: Context, tc: TargetCandidates, net: Network | None, ids: list[str]
) -> tuple[pd.DataFrame, pd.DataFrame]:
    tcols = [
        "target_id",
        "x",
        "y",
        "z",
        "type",
        "min_size_mm",
        "size_mm",
        "station_ids",
        "item",
        "facade_id",
        "facing_deg",
    ]
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
            "facade_id": [r["facade_id"] for r in rows],
            "facing_deg": [r["facing_deg"] for r in rows],
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
