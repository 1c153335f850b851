"""The blocks' plans stitched into one (:func:`stitch`): ids prefixed with the block's key,
the stations a neighbouring block makes redundant removed (:func:`redundant_stations`), the
blocks' networks tied across their seams where their frames were kept
(:mod:`planner.pipeline.network.seams`), one route through all stations.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd

from planner.cloud_registration import weakest_direction
from planner.pipeline.district.blocks import Block, KeptNetwork
from planner.pipeline.district.bounds import bound_fields, capped_meeting_reach, honest_bound
from planner.pipeline.engine.result import Plan, SolverReport
from planner.pipeline.engine.tables import (
    DATUM_LEVELLING_FIX,
    REASON_DATA,
    budget_message,
    rename_stations,
    rename_targets,
)
from planner.pipeline.field.route import field_route
from planner.pipeline.inputs.requirements import (
    PlanSettings,
    Requirements,
)
from planner.pipeline.inputs.schema import METRIC_KEYS
from planner.pipeline.network import seams
from planner.registration_error import datum_tilt_cov
from planner.scanner import Scanner
from planner.site import Site
from planner.sitecheck import notes_summary

__all__ = ["redundant_stations", "stitch"]


def _network_message(p: Plan, frame: KeptNetwork | None) -> str:
    """What a block's registration network says of itself (kept when the network is
    dropped for the trip back from the worker)."""
    if frame is not None:
        return frame.message
    return p.network.message if p.network is not None else ""


def stitch(
    site: Site,
    scanner: Scanner,
    req: Requirements,
    st: PlanSettings,
    blocks: list[Block],
    plans: list[Plan],
    reach: float,
    tables: list[pd.DataFrame] | None = None,
    frames: list[KeptNetwork | None] | None = None,
    *,
    jobs: bool = False,
) -> Plan:
    """One plan from the blocks' plans: ids prefixed with the block key (control points keep
    theirs), the stations a neighbouring block makes redundant removed (given the blocks'
    :func:`~planner.pipeline.district.blocks.meeting_table`), an honest bound (the far-apart
    blocks'; :func:`~planner.pipeline.district.schedule.plan_district` raises it to the blocks'
    covers at shared prices where that is larger), a message per block, one route. With the blocks'
    ``frames`` (:func:`~planner.pipeline.district.blocks.keep_frame`) their networks are tied into
    one across the seams; without, the blocks stay apart. ``jobs``: the blocks are groups of
    buildings far apart planned as separate jobs (:mod:`planner.pipeline.district.groups`),
    each with its own route."""
    parts, messages = _renamed_blocks(site, blocks, plans, frames, reach, jobs)
    stations, targets, coverage, facades, links, zones, cands, names = parts
    targets_df = _merge_control(pd.concat(targets, ignore_index=True))
    stations_df = pd.concat(stations, ignore_index=True)
    coverage_df = pd.concat(coverage, ignore_index=True)
    links_df = pd.concat(links, ignore_index=True)
    removed: list[str] = []
    if tables is not None:
        removed, stations_df, coverage_df, links_df, targets_df = _drop_redundant(
            blocks, tables, stations_df, coverage_df, links_df, targets_df
        )
        if removed:
            messages.append(
                f"{len(removed)} station(s) on block edges removed as redundant: every sample "
                "they met is met from another station, some of a neighbouring block (those "
                "samples are in that block's frame)."
            )
    cut = _cut_short(blocks, plans)
    if cut:
        messages.append(budget_message(st.time_limit_s, cut))
    solver = _district_solver(blocks, plans, reach, len(removed), cut, jobs)
    coverage_df, links_df, seam_notes = _tie_seams(
        site,
        scanner,
        req,
        st,
        blocks,
        plans,
        frames or [None] * len(blocks),
        reach,
        coverage_df,
        links_df,
        facades,
        removed,
    )
    messages += seam_notes
    if jobs:
        route = _joined_route(names, plans)
    else:
        route = field_route(site, scanner, st, stations_df, targets_df, coverage_df, links_df)
    messages.insert(0, f"Accuracy model: {st.model_description()}.")
    return Plan(
        site=site,
        scanner=scanner,
        requirements=req,
        settings=st,
        stations=stations_df,
        targets=targets_df,
        coverage=coverage_df,
        facades=pd.concat(facades, ignore_index=True),
        zones=pd.concat(zones, ignore_index=True),
        links=links_df,
        candidates=pd.concat(cands, ignore_index=True),
        network=None,
        route=route,
        solver=solver,
        messages=messages,
        timings_s={
            "blocks_s": float(sum(p.timings_s.get("total", 0.0) for p in plans)),
            "worker_peak_mb": max(p.timings_s.get("worker_peak_mb", 0.0) for p in plans),
        },
    )


def _renamed_blocks(
    site: Site,
    blocks: list[Block],
    plans: list[Plan],
    frames: list[KeptNetwork | None] | None,
    reach: float,
    jobs: bool = False,
) -> tuple[tuple[list, ...], list[str]]:
    """Each block's tables with its ids prefixed with the block's key (control points keep
    theirs) — stations, targets, coverage, facades, links, zones, candidates, and the id maps
    themselves (:func:`_block_ids`) — and the messages: the site's, then one per block."""
    stations, targets, coverage, facades, links, zones, cands = [], [], [], [], [], [], []
    names: list[tuple[dict[str, str], dict[str, str]]] = []
    messages = [
        *site.warnings,
        *notes_summary(site.notes),
        f"Jobs: {len(blocks)} groups of buildings far apart, each planned as its own job with "
        "its own registration network, datum and route; the travel between them is the "
        "crew's, and tying them into one frame needs control points of one system "
        "(--control, e.g. by GNSS)."
        if jobs
        else f"District: {len(blocks)} blocks planned on Dask, halo {reach:.0f} m.",
    ]
    word = "Group" if jobs else "Block"
    control = {c.id for c in site.control}
    frames = frames if frames is not None else [None] * len(blocks)
    for b, p, frame in zip(blocks, plans, frames, strict=True):
        sid, tid = _block_ids(b, p, control)
        names.append((sid, tid))
        st_b, cov_b, tg_b, lk_b = rename_stations(sid, p.stations, p.coverage, p.targets, p.links)
        tg_b, lk_b = rename_targets(tid, tg_b, lk_b)
        stations.append(st_b)
        targets.append(tg_b)
        coverage.append(cov_b.drop(columns=[REASON_DATA], errors="ignore"))
        facades.append(p.facades)
        links.append(lk_b)
        zones.append(p.zones)
        cands.append(p.candidates)
        net = _network_message(p, frame)
        messages.append(
            f"{word} {b.key} ({len(b.buildings)} buildings): {len(p.stations)} stations, "
            f"{int(p.scanned['meets'].sum())} of {len(p.scanned)} samples met, "
            f"{p.solver.status}, bound {p.solver.lower_bound}"
            + (f"; Registration: {net}." if net else "")
        )
    return (stations, targets, coverage, facades, links, zones, cands, names), messages


def _drop_redundant(
    blocks: list[Block],
    tables: list[pd.DataFrame],
    stations: pd.DataFrame,
    coverage: pd.DataFrame,
    links: pd.DataFrame,
    targets: pd.DataFrame,
) -> tuple[list[str], pd.DataFrame, pd.DataFrame, pd.DataFrame, pd.DataFrame]:
    """The stations on block edges a neighbouring block makes redundant
    (:func:`redundant_stations`, given the blocks' meeting tables), and the tables without
    them: stations, coverage, links, targets."""
    meeting = pd.concat(
        [
            t.assign(station_id=f"{b.key}-" + t["station_id"].astype(str))
            for b, t in zip(blocks, tables, strict=True)
        ],
        ignore_index=True,
    )
    removed = redundant_stations(stations, coverage, links, meeting)
    if removed:
        stations, coverage, links, targets = _without(
            removed, stations, coverage, links, targets, meeting
        )
    return removed, stations, coverage, links, targets


def _district_solver(
    blocks: list[Block],
    plans: list[Plan],
    reach: float,
    removed: int,
    cut: list[str],
    jobs: bool = False,
) -> SolverReport:
    """The district's solver report: the blocks' covers summed less the stations
    ``removed``, the honest bound of the blocks far apart
    (:func:`~planner.pipeline.district.bounds.honest_bound`), the blocks' work summed."""
    objective = int(sum(p.solver.objective for p in plans)) - removed
    far = honest_bound(blocks, plans, reach)
    statuses = {p.solver.status for p in plans}
    return SolverReport(
        method=f"jobs ({len(blocks)} groups)" if jobs else f"district ({len(blocks)} blocks)",
        status=statuses.pop() if len(statuses) == 1 else "mixed: " + ", ".join(sorted(statuses)),
        objective=objective,
        **bound_fields(objective, far, 0.0),
        far_bound=far,
        seconds=max(float(p.solver.seconds) for p in plans),
        greedy_objective=sum(int(p.solver.greedy_objective or 0) for p in plans),
        parts=sum(int(p.solver.parts) for p in plans),
        reach_m=reach,
        meeting_reach_m=max(capped_meeting_reach(p, reach) for p in plans),
        candidates=sum(int(p.solver.candidates) for p in plans),
        samples=sum(int(p.solver.samples) for p in plans),
        pairs=sum(int(p.solver.pairs) for p in plans),
        registration_rounds=max(int(p.solver.registration_rounds) for p in plans),
        blocks=len(blocks),
        block_bound_sum=float(sum(p.solver.lower_bound or 0 for p in plans)),
        redundant_removed=removed,
        cut_short=cut,
    )


def _tie_seams(
    site: Site,
    scanner: Scanner,
    req: Requirements,
    st: PlanSettings,
    blocks: list[Block],
    plans: list[Plan],
    kept: list[KeptNetwork | None],
    reach: float,
    coverage: pd.DataFrame,
    links: pd.DataFrame,
    facades: list[pd.DataFrame],
    removed: list[str],
) -> tuple[pd.DataFrame, pd.DataFrame, list[str]]:
    """The blocks' networks tied into one across their seams
    (:mod:`planner.pipeline.network.seams`): every sample judged again with its block's frame error;
    the seams as links; what was tied and what could not be, said."""
    if len(blocks) < 2 or not st.computes_registration or any(k is None for k in kept):
        return coverage, links, []
    frames, targets, datums, leaning = _block_frames(blocks, plans, kept, set(removed))
    ctx_of = seams.context_of(site, scanner, req, st, reach)
    found = seams.seam_links(site, ctx_of, frames, targets)
    extra, used = seams.tie_blocks(frames, found, [k.held for k in kept])
    # one datum's tilt leans the district's frame: the root block's, in place of each
    # block's own (a scanner without a compensator)
    root = seams.root_block(frames)
    lean = datums[root]
    tau = scanner.datum_tilt_rms_arcsec
    per_station, xyz = _frame_errors(frames, extra, datums, leaning, lean, tau)
    limits = np.concatenate([fr.limits for fr in kept])
    facade_df = pd.concat(facades, ignore_index=True)
    coverage, over = seams.add_frame_errors(coverage, facade_df, per_station, xyz, limits)
    n_lost, n_height = int(over.any(axis=1).sum()), int(over[:, 2].sum())
    lost = [b.key for b, e, f in zip(blocks, extra, frames, strict=True) if e is None and f.ids]
    for b, e, f in zip(blocks, extra, frames, strict=True):
        if e is None and f.ids:
            coverage = seams.untied_blocks(coverage, set(f.ids), b.key)
    links = _with_seam_links(links, frames, used)
    notes = _seam_notes(blocks, used, lost, n_lost, n_height, root, lean is not None, tau)
    return coverage, links, notes


def _seam_notes(
    blocks: list[Block],
    used: list,
    lost: list[str],
    n_lost: int,
    n_height: int,
    root: int,
    leaning: bool,
    tau: float,
) -> list[str]:
    """What the seams tied and what they could not, and the samples met within their block
    that the common frame takes over a limit (in height: the root block's datum's lean,
    ``leaning``, of ``tau`` arc-seconds)."""
    notes = []
    tied = len(blocks) - len(lost)
    worst = max((s.rms_mm for s in used), default=0.0)
    notes.append(
        f"District network: {tied} of {len(blocks)} blocks tied into one frame across "
        f"{len(used)} seam(s) (common targets of neighbouring blocks' stations; worst seam "
        f"{worst:.1f} mm), every sample judged with its block's frame error"
        + (
            f"; {', '.join(lost)} could not be tied (no station shares three targets with a "
            "neighbouring block's): their samples are not in the common frame"
            if lost
            else ""
        )
        + "."
    )
    if n_lost:
        notes.append(
            f"District network: {n_lost} sample(s) met within their block exceed a limit in "
            "the common frame, with the seams' error added"
            + (
                f"; {n_height} of them in height, where the frame leans about the datum "
                f"station of block {blocks[root].key} (its levelling, {tau:g}″ RMS, carried "
                f"to every block): {DATUM_LEVELLING_FIX}"
                if leaning and n_height
                else ""
            )
            + "."
        )
    return notes


def _block_frames(
    blocks: list[Block], plans: list[Plan], kept: list[KeptNetwork], gone: set[str]
) -> tuple[list, list[pd.DataFrame], list, list[np.ndarray]]:
    """Each block's frame as the seams take it (its stations not ``gone``, ids prefixed),
    its targets (ids prefixed), the datum whose tilt leans it, and which stations carry
    that lean."""
    frames, targets, datums, leaning = [], [], [], []
    for b, p, fr in zip(blocks, plans, kept, strict=True):
        xyz, pose, tied, datum, leans = fr.xyz, fr.pose_cov, fr.tied, fr.datum, fr.leans
        ids = [f"{b.key}-{s}" for s in p.stations["station_id"][: len(xyz)]]
        keep = np.array([i not in gone for i in ids], dtype=bool)
        datums.append(datum)
        leaning.append(np.asarray(leans, dtype=bool)[keep])
        frames.append(
            seams.BlockFrame(
                [i for i, k in zip(ids, keep, strict=True) if k],
                np.asarray(xyz)[keep],
                np.asarray(pose)[keep],
                np.asarray(tied, dtype=bool)[keep],
            )
        )
        t = p.targets.copy()
        t["target_id"] = [f"{b.key}-{x}" for x in t["target_id"]]
        targets.append(t)
    return frames, targets, datums, leaning


def _frame_errors(
    frames: list, extra: list, datums: list, leaning: list, lean: np.ndarray | None, tau: float
) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray]]:
    """Every station's pose covariance from its block's seams, with one datum's tilt
    leaning the district's frame (``lean``, the root block's: a scanner without a
    compensator) in place of each block's own; and every station's centre."""
    per_station, xyz = {}, {}
    for f, e, own, leans in zip(frames, extra, datums, leaning, strict=True):
        if e is not None:
            e = e.copy()
            if lean is not None:  # (a levelled scanner's frames do not lean)
                e[leans] += datum_tilt_cov(f.xyz[leans], lean, tau)
            if own is not None:
                e[leans] -= datum_tilt_cov(f.xyz[leans], own, tau)
            per_station |= dict(zip(f.ids, e, strict=True))
        xyz |= dict(zip(f.ids, f.xyz, strict=True))
    return per_station, xyz


def _with_seam_links(links: pd.DataFrame, frames: list, used: list) -> pd.DataFrame:
    """The links with the seams used as links by targets: the common targets of two
    blocks' stations, the weakest direction said."""
    rows = [
        {
            "station_a": frames[s.block_a].ids[s.a],
            "station_b": frames[s.block_b].ids[s.b],
            "common_targets": len(s.target_ids),
            "targets_placed": len(s.target_ids),
            "target_ids": ";".join(s.target_ids),
            "link_rms_mm": s.rms_mm,
            "dilution": np.nan,
            "station_b_rms_mm": np.nan,
            "kind": "targets",  # a seam: the common targets of two blocks' stations
            "overlap_pct": np.nan,
            "weakest_direction": weakest_direction(s.cov),
        }
        for s in used
    ]
    if rows:
        return pd.concat([links, pd.DataFrame(rows, columns=links.columns)], ignore_index=True)
    return links


def _cut_short(blocks: list[Block], plans: list[Plan]) -> list[str]:
    """What the time budget cut short in the blocks, each kind once with the blocks it
    happened in (the evaluation with the samples left out over all blocks)."""
    kinds: dict[str, list[str]] = {}
    for b, p in zip(blocks, plans, strict=True):
        for what in p.solver.cut_short:
            kinds.setdefault(what.split(" (")[0], []).append(b.key)
    out = []
    for what, keys in kinds.items():
        shown = ", ".join(keys[:6]) + (f" and {len(keys) - 6} more" if len(keys) > 6 else "")
        if what == "the evaluation":
            total = sum(int(p.solver.samples_total) for p in plans)
            done = sum(int(p.solver.samples_evaluated) for p in plans)
            what = f"the evaluation ({done} of {total} samples; the plan covers those)"
        out.append(f"{what} in {len(keys)} of {len(blocks)} blocks ({shown})")
    return out


def redundant_stations(
    stations: pd.DataFrame, coverage: pd.DataFrame, links: pd.DataFrame, meeting: pd.DataFrame
) -> list[str]:
    """Covering (or linking) stations whose every met sample stays met without them (ids),
    fewest samples first, each checked against those already removed. Only a station no
    other is registered to and no unmet sample is scanned from (its best achievable values
    are those of its station) can go, and only samples needing one station are served from
    elsewhere; a sample of another block counts where that block's stations meet it on the
    same point (to the millimetre) and it lies in no zone (a zone's requirement is its own
    block's)."""
    pairs = _counting_pairs(coverage, meeting)  # only the samples met now must stay met
    multi = set(pairs.loc[pairs["own"] & (pairs["needed"] > 1), "station_id"])
    parents = set(links["station_a"])
    unmet = set(coverage.loc[~coverage["meets"] & ~coverage["party_wall"], "station_id"])
    movable = stations[(stations["purpose"] == "cover") | (stations["purpose"] == "link")][
        "station_id"
    ]
    movable = [s for s in movable if s not in parents | multi | unmet]
    by_sample: dict[tuple, set[str]] = {}
    by_station: dict[str, list[tuple]] = {}
    samples = zip(pairs["facade_id"], pairs["sample_id"], strict=True)
    for smp, s in zip(samples, pairs["station_id"], strict=True):
        by_sample.setdefault(smp, set()).add(s)
        by_station.setdefault(s, []).append(smp)
    removed: list[str] = []
    for s in sorted(movable, key=lambda s: len(by_station.get(s, []))):
        gone = {*removed, s}
        if all(by_sample[smp] - gone for smp in by_station.get(s, [])):
            removed.append(s)
    return removed


def _counting_pairs(coverage: pd.DataFrame, meeting: pd.DataFrame) -> pd.DataFrame:
    """The rows of the meeting table that count for the samples met now: a block's own, and
    another block's where it is the same point (to the millimetre) outside zones."""
    key = ["facade_id", "sample_id"]
    met = coverage.loc[coverage["meets"] & ~coverage["party_wall"], [*key, "x", "y", "z", "zone"]]
    rows = meeting.merge(met, on=key, suffixes=("", "_c"))
    same = rows[["x", "y", "z"]].to_numpy() - rows[["x_c", "y_c", "z_c"]].to_numpy()
    counts = rows["own"] | ((np.abs(same).max(axis=1) < 1e-3) & (rows["zone"] == ""))
    return rows.loc[counts, meeting.columns]


def _without(
    removed: list[str],
    stations: pd.DataFrame,
    coverage: pd.DataFrame,
    links: pd.DataFrame,
    targets: pd.DataFrame,
    meeting: pd.DataFrame,
) -> tuple[pd.DataFrame, pd.DataFrame, pd.DataFrame, pd.DataFrame]:
    """The plan's tables without the ``removed`` stations: their samples served by the
    remaining station meeting them (:func:`_counting_pairs`) with the smallest largest RMS
    (its metrics taken over) and counted again, their links gone, and the targets no link
    uses any more."""

    gone = set(removed)
    key = ["facade_id", "sample_id"]
    cov = coverage.copy()
    left = _counting_pairs(coverage, meeting)
    left = left[~left["station_id"].isin(gone)]
    left = left.assign(worst=left[["m_x_mm", "m_y_mm", "m_z_mm"]].max(axis=1))
    best = left.sort_values("worst").drop_duplicates(key).set_index(key)
    counts = left.groupby(key)["station_id"].nunique()
    idx = cov.set_index(key).index
    moved = cov["station_id"].isin(gone).to_numpy()
    take = best.reindex(idx[moved])
    cov.loc[moved, "station_id"] = take["station_id"].to_numpy()
    for k in METRIC_KEYS:  # as floats: an empty block's table makes the concatenation objects
        if k in cov.columns:
            cov.loc[moved, k] = pd.to_numeric(take[k], errors="coerce").to_numpy(dtype=float)
    met = cov["meets"].to_numpy()
    cov.loc[met, "stations_meeting"] = counts.reindex(idx[met]).fillna(0).astype(int).to_numpy()
    links = links[~links["station_b"].isin(gone)].reset_index(drop=True)
    used = {t for ids in links["target_ids"] for t in str(ids).split(";") if t}
    targets = targets[targets["target_id"].isin(used) | (targets["type"] == "control")].copy()
    targets["station_ids"] = targets["station_ids"].map(
        lambda ids: [s for s in ids if s not in gone]
    )
    stations = stations[~stations["station_id"].isin(gone)].reset_index(drop=True)
    return stations, cov, links, targets.reset_index(drop=True)


def _merge_control(t: pd.DataFrame) -> pd.DataFrame:
    """A control point seen from stations of several blocks: one row, every station."""
    ctl = t[t["type"] == "control"]
    if ctl.empty or not ctl["target_id"].duplicated().any():
        return t
    merged = ctl.groupby("target_id", sort=False).agg(
        {c: "first" for c in t.columns if c not in ("target_id", "station_ids")}
        | {"station_ids": lambda s: sorted({x for ids in s for x in ids})}
    )
    merged = merged.reset_index()[t.columns]
    return pd.concat([t[t["type"] != "control"], merged], ignore_index=True)


def _block_ids(b: Block, p: Plan, control: set[str]) -> tuple[dict[str, str], dict[str, str]]:
    """A block's (or job's) station and target ids in the stitched plan, old → new: prefixed
    with its key (control points keep theirs)."""
    sid = {s: f"{b.key}-{s}" for s in p.stations["station_id"]}
    tid = {t: f"{b.key}-{t}" for t in p.targets["target_id"] if t not in control}
    return sid, tid


def _joined_route(ids: list[tuple[dict, dict]], plans: list[Plan]):
    """One route of the jobs' own routes, one after another (each job's ids renamed by its
    ``ids``, :func:`_block_ids`): each job's walks its own, the travel between groups the
    crew's (the first station of a job has no walk); sessions and the elapsed time run on
    from the job before."""
    routes = [p.route.renamed(*names) for names, p in zip(ids, plans, strict=True)]
    tables: list[pd.DataFrame] = []
    for r in routes:
        if not len(r.table):
            continue
        t = r.table.copy()
        if tables:  # the travel from the job before is the crew's
            t.loc[t.index[0], "walk_note"] = "each a job's first: the travel to it is the crew's"
            t["session"] += int(tables[-1]["session"].max())
            t["elapsed_min"] += float(tables[-1]["elapsed_min"].iloc[-1])
        tables.append(t)
    table = pd.concat(tables, ignore_index=True) if tables else routes[0].table
    if len(table):
        table["order"] = np.arange(1, len(table) + 1)
    kits = [r.kit for r in routes if len(r.kit)]
    kit = routes[0].kit
    if kits:  # the kit travels from job to job: the most any one job needs of each item
        both = pd.concat(kits, ignore_index=True)
        kit = both.loc[both.groupby("item")["most_at_once"].idxmax()].reset_index(drop=True)
    return replace(
        routes[0],
        table=table,
        legs=[leg for r in routes for leg in r.legs],
        kit=kit,
        on_site=any(r.on_site for r in routes),
    )
