"""The plan's tables and its words: the coverage of every sample with the reason it is not
met, the per-facade and per-zone summaries, the targets and links tables, and the messages
the summary prints (:data:`planner.pipeline.inputs.schema`'s columns).

:func:`planner.pipeline.engine.judge.assemble` builds a plan from them.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
import pandas as pd
import shapely

from planner.classes import achieved_class, parse_class
from planner.pipeline.evaluation.diagnosis import Diagnosis
from planner.pipeline.evaluation.evaluate import Assignment, CandidateEvaluation, Context
from planner.pipeline.geometry.facades import FacadeSet
from planner.pipeline.geometry.zoning import ZoneTable
from planner.pipeline.inputs.requirements import (
    CHECKS,
    REGISTRATION_PROCESSING,
    PlanSettings,
    Requirements,
)
from planner.pipeline.inputs.schema import (
    COVERAGE_COLUMNS,
    LINK_COLUMNS,
    METRIC_KEYS,
    TARGET_COLUMNS,
    ZONE_COLUMNS,
    id_key,
)
from planner.pipeline.network.linkcheck import MAX_FAILURE, PROBE_SIGMAS
from planner.pipeline.network.network import Network
from planner.pipeline.network.targets import TargetCandidates
from planner.registration_error import CONTROL, Link, datum_lean_mm
from planner.targets import choose_target

__all__ = [
    "PROCESSING_WORDS",
    "REASON_DATA",
    "Reason",
    "budget_message",
    "class_family",
    "coverage_table",
    "enclosed_messages",
    "facade_summary",
    "registration_messages",
    "rename_stations",
    "rename_targets",
    "target_numbers",
    "targets_and_links",
    "unmet_messages",
    "untied_places",
    "zone_summary",
]


def budget_message(time_limit_s: float, cut: list[str]) -> str:
    """What the clock stopped, as the plan says it (only the optimiser's search reads it:
    the rest of the plan is decided by work)."""
    return (
        f"Time budget: the {time_limit_s:g} s ran out on this machine; it stopped "
        f"{'; '.join(dict.fromkeys(cut))}. Every sample was evaluated and the network built "
        "whole; the plan may differ from one made with more time (raise --time-limit-s)."
    )


def _reason(
    ctx: Context,
    sample: int,
    n_view: int,
    best: dict[str, float],
    n_meet: int,
    roof: str = "",
    assumed: bool = False,
) -> str:
    """Why no station meets ``sample``, in words: each check the best candidate fails; where
    the ground cannot reach it, that it needs an elevated station (on ``roof``'s roof), or,
    where that roof's height is ``assumed`` (the file gave none), that its height decides."""
    where = (
        f"over {roof!r}, whose height is assumed (the file gives none): give its height to "
        "know whether a station on the ground, or on that roof, can see it"
        if assumed
        else f"over the roof of {roof!r}: it needs an elevated station (e.g. on that roof)"
    )
    if n_view == 0 and roof:
        return f"no ground station sees it {where}"
    if n_view == 0:
        return "no ground station sees it: it needs an elevated station (a lift or a mast)"
    why = _unmet_checks(ctx, sample, best, n_meet)
    if roof:
        return f"{why} from the ground, seen only {where}"
    return why


def _unmet_checks(ctx: Context, sample: int, best: dict[str, float], n_meet: int) -> str:
    """Each check the best candidate fails at ``sample``, in words."""
    k = int(ctx.stations_needed[sample])
    if 0 < n_meet < k:
        return f"only {n_meet} station position(s) meet every requirement here; {k} required"
    parts = []
    for c in CHECKS:
        limit = float(ctx.limits[c.key][sample])
        if np.isfinite(limit) and not c.passes(np.float64(best[c.key]), limit):
            parts.append(c.shortfall(best[c.key], limit))
    if parts:
        return "; ".join(parts)
    if best["score"] <= 1.0 and ctx.settings.computes_registration:
        return (
            "the registration error leaves too little: the best station meets it by the "
            f"scanner's error alone ({best['score']:.2f} × the limits), none with the "
            "registration error of the network added"
        )
    each = [
        f"{c.label} {best[c.key]:.1f} {c.unit} (limit {float(ctx.limits[c.key][sample]):g})"
        for c in CHECKS[:3]
        if np.isfinite(ctx.limits[c.key][sample])
    ]
    return (
        "no single station meets every requirement at once: each alone is achievable (best "
        + ", ".join(each)
        + f"), together at best {best['score']:.2f} × the limits"
    )


def _diagnosed_reasons(
    ctx: Context,
    diagnosis: Diagnosis,
    samples: np.ndarray,
    n_ok_cand: np.ndarray,
    reason: np.ndarray,
) -> np.ndarray:
    """The reasons of ``samples`` no candidate meets, from their diagnosis (into
    ``reason``); and where an elevated station would see them (per sample, "" none)."""
    elevated = np.full(len(reason), "", dtype=object)
    assumed = ctx.site.assumed_heights
    for i in samples:
        found = diagnosis.at(int(i))
        if found is None:
            reason[i] = "no station meets it (not diagnosed further: the time limit ran out)"
            continue
        n_view, best, roof = found
        made_up = roof in assumed
        reason[i] = _reason(ctx, int(i), n_view, best, int(n_ok_cand[i]), roof, made_up)
        if made_up:  # no station proposed on a height made up
            continue
        if n_view == 0 or roof:
            elevated[i] = f"roof of {roof}" if roof else "above the ground"
    return elevated


def _dark_wall_words(ctx: Context, idx: np.ndarray, reason: np.ndarray) -> None:
    """Add to the reasons of samples ``idx`` (no position meets them) what their wall's
    material costs, where it returns less than the datasheet's reference surface."""
    if not len(idx) or not len(ctx.reflectance):
        return
    st, sc = ctx.settings, ctx.scanner
    rho = ctx.reflectance[idx]
    dark = np.isfinite(rho) & (rho < sc.ref_reflectance)
    idx, rho = idx[dark], rho[dark]
    factor = sc.range_rms_on(10.0, rho) / sc.range_rms_at(10.0)  # at any distance the same
    for i, r, f in zip(idx, rho, factor, strict=True):
        m = st.material_table[ctx.material[i]]
        reason[i] += (
            f"; the wall is {m.label} ({r:.0%} on a {st.surface_condition} day): ranging "
            f"{f:.1f}× the datasheet's"
        )


def coverage_table(
    ctx: Context,
    ev: CandidateEvaluation,
    diagnosis: Diagnosis,
    assignment: Assignment,
    ids: list[str],
    net: Network | None = None,
    zone_ids: np.ndarray | None = None,
    class_family: str | None = None,
) -> pd.DataFrame:
    """One row per sample: its station, the metrics there, whether it meets its
    requirement, and why not."""
    fac = ctx.facades
    ctx_zone_ids = zone_ids if zone_ids is not None else np.full(len(fac.z), "", dtype=object)
    n = len(fac.z)
    k_req = ctx.stations_needed
    n_ok_cand = np.asarray(ev.ok.sum(axis=1)).ravel()
    picked, n_meeting = assignment.metrics, assignment.n_meeting
    names = np.array([*ids, ""], dtype=object)
    station = names[assignment.station]  # -1 picks the "" at the end
    demanded = ~fac.party_wall
    meets = (n_meeting >= k_req) & demanded
    reason = np.full(n, "", dtype=object)
    candidates_meet = ~meets & demanded & (n_ok_cand >= k_req)
    untied = np.zeros(n, dtype=bool)
    places = untied_places(ctx, net)
    if net is not None and net.error is not None and len(ids) > 1:
        has = assignment.station >= 0
        untied[has] = ~net.error.tied[assignment.station[has]]
    lean_at = net.leaning_datum() if net is not None else None
    datum = None if lean_at is None else (ids[net.datum], lean_at[:2])
    named = np.full(n, None, dtype=object)  # the reasons naming stations, as data
    for i in np.flatnonzero(candidates_meet):
        place = places.get(int(assignment.station[i]), "") if untied[i] else ""
        named[i] = _short_reason(
            ctx, i, picked, station[i], untied[i], n_meeting[i], k_req[i], place, datum
        )
        reason[i] = named[i].text()
    hopeless = np.flatnonzero(~meets & demanded & (n_ok_cand < k_req) & ev.evaluated)
    elevated = _diagnosed_reasons(ctx, diagnosis, hopeless, n_ok_cand, reason)
    _dark_wall_words(ctx, hopeless, reason)
    reason[~meets & demanded & ~ev.evaluated] = "not evaluated: the time budget ran out"
    reason[fac.party_wall] = "party wall (against a neighbour): not scanned"
    named[~meets & demanded & ~ev.evaluated] = None
    named[fac.party_wall] = None
    extra = {}
    if class_family:  # the class each sample achieves, beside pass/fail
        extra["class_achieved"] = achieved_class(
            picked["m_x_mm"], picked["m_y_mm"], picked["m_z_mm"], class_family
        )
    data = {
        "building_id": fac.building_id[fac.facade],
        "facade_id": fac.facade_id[fac.facade],
        "sample_id": fac.sample_id,
        "x": fac.xy[:, 0],
        "y": fac.xy[:, 1],
        "z": fac.z,
        "station_id": station,
        **{k: picked[k] for k in METRIC_KEYS},
        "meets": meets,
        "model": ctx.settings.model,
        "reason": reason,
        "elevated_station": elevated,
        "zone": ctx_zone_ids,
        "material": ctx.material if len(ctx.material) == n else np.full(n, "", dtype=object),
        # beside the file's columns: how many stations meet it, whether on a party wall,
        # the reason as data
        "stations_meeting": n_meeting,
        "party_wall": fac.party_wall,
        REASON_DATA: [
            r if r is not None else Reason(_literal(t)) for r, t in zip(named, reason, strict=True)
        ],
        **extra,
    }
    return pd.DataFrame(data)[
        [*COVERAGE_COLUMNS, "stations_meeting", "party_wall", *extra, REASON_DATA]
    ]


#: The coverage's column of :class:`Reason` (not written to files): the reason's words and
#: the stations it names, so that a district renames stations without reading the words.
REASON_DATA = "reason_data"


def target_numbers(
    targets: pd.DataFrame,
    visit: dict[str, int],
    kept: dict[str, str] | None = None,
    after: int = 0,
) -> dict[str, str]:
    """New ids for the targets (old id → new): T01, T02 … in the order the crew first needs
    them (the visit, ``visit``: station id → its place in the route, of the first station
    that scans each), a control point keeping its own id. A plan made from an earlier one:
    the targets in ``kept`` (old id → the id the earlier plan gave it) keep that, and the
    others are numbered from ``after`` + 1 (no id given twice)."""
    kept = kept or {}
    first = [
        min((visit.get(s, len(visit)) for s in seen), default=len(visit))
        for seen in targets["station_ids"]
    ]
    ours = [k for k, t in enumerate(targets["type"]) if t != "control"]
    ours.sort(key=lambda k: first[k])  # (stable: the network's order among equals)
    ids = targets["target_id"].astype(str).tolist()
    mine = set(ours)
    taken = {ids[k] for k in range(len(ids)) if k not in mine} | set(kept.values())
    names = (f"T{n:02d}" for n in itertools.count(after + 1))
    free = (t for t in names if t not in taken)
    return {ids[k]: kept.get(ids[k]) or next(free) for k in ours}


def rename_targets(
    mapping: dict[str, str], targets: pd.DataFrame, links: pd.DataFrame
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """The targets and links with the targets renamed (``mapping``: old id → new; an id not
    in it is kept)."""
    targets = targets.assign(target_id=targets["target_id"].map(lambda t: mapping.get(t, t)))
    links = links.assign(
        target_ids=links["target_ids"].map(
            lambda ids: ";".join(mapping.get(t, t) for t in str(ids).split(";") if t)
        )
    )
    return targets, links


def rename_stations(
    mapping: dict[str, str],
    stations: pd.DataFrame,
    coverage: pd.DataFrame,
    targets: pd.DataFrame,
    links: pd.DataFrame,
) -> tuple[pd.DataFrame, pd.DataFrame, pd.DataFrame, pd.DataFrame]:
    """The plan's tables with its stations renamed (``mapping``: old id → new; an id not in
    it is kept): the stations, the coverage (its reasons written again from their data), the
    stations that see each target and the links. The one place a station's id is rewritten
    in the tables (the route's: :meth:`~planner.pipeline.field.route.FieldRoute.renamed`)."""

    def one(s: str) -> str:
        return mapping.get(s, s)

    stations = stations.assign(station_id=stations["station_id"].map(one))
    coverage = coverage.assign(station_id=coverage["station_id"].map(one))
    if REASON_DATA in coverage:
        data = [Reason(r.template, tuple(map(one, r.stations))) for r in coverage[REASON_DATA]]
        coverage = coverage.assign(reason=[r.text() for r in data], **{REASON_DATA: data})
    targets = targets.assign(
        station_ids=targets["station_ids"].map(lambda ids: sorted(map(one, ids), key=id_key))
    )
    links = links.assign(
        station_a=links["station_a"].map(one), station_b=links["station_b"].map(one)
    )
    return stations, coverage, targets, links


@dataclass(frozen=True)
class Reason:
    """Why a sample is not met, as data: ``template`` with ``{0}``, ``{1}`` … where the
    stations it names go (their ids, ``stations``); :meth:`text` renders it."""

    template: str
    stations: tuple[str, ...] = ()

    def text(self, rename: dict[str, str] | None = None) -> str:
        """The reason in words, the stations under their names in ``rename`` if given."""
        ids = self.stations if rename is None else tuple(rename.get(s, s) for s in self.stations)
        return self.template.format(*ids)


def _literal(text: str) -> str:
    """``text`` as a template that names no station (braces kept as they are)."""
    return text.replace("{", "{{").replace("}", "}}")


def _short_reason(
    ctx: Context,
    i: int,
    picked: dict[str, np.ndarray],
    station: str,
    untied: bool,
    n_meeting: int,
    k_req: int,
    place: str = "",
    datum: tuple[str, np.ndarray] | None = None,
) -> Reason:
    """Why a sample some candidate could meet is not met by the chosen stations (``place``:
    where an untied station stands, :func:`untied_places`; ``datum``: the datum station's id
    and position, whose levelling leans the network of a scanner without a compensator)."""
    if untied and place:
        return Reason(
            "its station {0} stands in "
            + _literal(f"{place}, which no registration reaches: {ENCLOSED_FIX}"),
            (station,),
        )
    if untied:
        return Reason("its station {0} cannot be tied to the registration network", (station,))
    worst = None
    for c in "xyz":
        total, scanner = picked[f"m_{c}_mm"][i], picked[f"scanner_m_{c}_mm"][i]
        reg = picked[f"reg_m_{c}_mm"][i]
        limit = float(ctx.limits[f"m_{c}"][i])
        if np.isfinite(limit) and scanner <= limit < total and np.isfinite(reg):
            if worst is None or total / limit > worst[0]:
                worst = (total / limit, c, scanner, reg, total, limit)
    if worst is not None:
        _, c, scanner, reg, total, limit = worst
        text = (
            f"the registration error takes it over: m_{c} {scanner:.1f} mm from the scanner "
            f"⊕ {reg:.1f} mm registration (station {{0}}) = {total:.1f} mm > {limit:g} mm"
        )
        if datum is not None and c == "z":
            far = float(np.hypot(*(ctx.facades.xy[i] - datum[1])))
            m_nu0 = ctx.scanner.datum_tilt_rms_arcsec
            lean = float(datum_lean_mm(far, m_nu0))
            if lean >= 0.5 * reg:
                text += (
                    f"; {lean:.1f} mm of it is the levelling of the datum {{1}} "
                    f"({m_nu0:g}″ at {far:.0f} m): {_literal(DATUM_LEVELLING_FIX)}"
                )
                return Reason(text, (station, datum[0]))
        return Reason(text, (station,))
    if k_req > 1:
        return Reason(
            f"the chosen stations give {n_meeting} of the {k_req} views required (views "
            f"{ctx.req.min_view_angle_deg:g}° apart in direction)"
        )
    return Reason("the chosen stations do not cover this sample")


#: What keeps heights true far from the datum of a scanner without a compensator.
DATUM_LEVELLING_FIX = (
    "level that scan better (a scanner with a compensator: its levelling figure, "
    "--levelling-rms-arcsec) or tie the heights to control points (--control)"
)


#: What ties a closed courtyard's stations to the others.
ENCLOSED_FIX = (
    "mark its gateway (a feature with role passage, or OpenStreetMap's "
    "tunnel=building_passage) or give control points (--control)"
)


def untied_places(ctx: Context, net: Network | None) -> dict[int, str]:
    """Where the stations not tied to the network stand, in words, by their position in
    ``net``: "the courtyard enclosed by A, B, C" for a closed courtyard (open ground no
    other station's region reaches,
    :class:`~planner.pipeline.geometry.candidates.GroundRegions`)."""
    if net is None or net.error is None or len(net.stations) <= 1:
        return {}
    untied = np.flatnonzero(~net.error.tied)
    out = {}
    for k, r in zip(untied, ctx.regions.label(net.station_xyz[untied, :2]), strict=True):
        if ctx.regions.enclosed(int(r)):
            blds = ctx.regions.enclosing(int(r))
            more = f" and {len(blds) - 6} more" if len(blds) > 6 else ""
            out[int(k)] = f"the courtyard enclosed by {', '.join(blds[:6])}{more}"
    return out


def enclosed_messages(places: dict[int, str], ids: list[str]) -> list[str]:
    """One line per closed courtyard whose stations cannot be tied."""
    by_place: dict[str, list[str]] = {}
    for k, place in places.items():
        by_place.setdefault(place, []).append(ids[k])
    return [
        f"Registration: {place[0].upper()}{place[1:]} (station(s) {', '.join(sorted(st))}) "
        f"cannot be tied to the others — no station outside sees its targets: {ENCLOSED_FIX}. "
        "No station is added there for the registration error."
        for place, st in by_place.items()
    ]


def class_family(req: Requirements, zones: ZoneTable) -> str | None:
    """The family of the accuracy class asked for (site-wide or in a zone), if any."""
    for r in [req, *zones.requirements]:
        if r.accuracy_class:
            return parse_class(r.accuracy_class)[0].family
    return None


def zone_summary(zones: ZoneTable, cov: pd.DataFrame) -> pd.DataFrame:
    """Each zone: where, its requirement, its sampling, and whether it is met."""
    scanned = ~cov["party_wall"].to_numpy()
    met = cov["meets"].to_numpy() & scanned
    said: dict[int, str] = {}  # zones share Requirements objects: each described once
    rows = []
    for z, r, idx in zip(zones.zones, zones.requirements, zones.members, strict=True):
        samples, ok = int(scanned[idx].sum()), int(met[idx].sum())
        if id(r) not in said:
            said[id(r)] = r.describe()
        rows.append(
            {
                "zone_id": z.id,
                "where": z.describe(),
                "requirement": said[id(r)],
                "sample_spacing_m": z.sample_spacing_m,
                "samples": samples,
                "met": ok,
                "unmet": samples - ok,
            }
        )
    return pd.DataFrame(rows, columns=ZONE_COLUMNS)


def facade_summary(fac: FacadeSet, cov: pd.DataFrame) -> pd.DataFrame:
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
    zones_on = cov.groupby("facade_id", sort=False)["zone"].agg(
        lambda s: ";".join(sorted({z for v in s if v for z in v.split(";")}))
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
            "z0": fac.z0,
            "base_z": fac.base_z,
            "normal_z": fac.normal_z,
            # its shape on its elevation: u along it from (x0, y0), h above base_z [m]
            "outline_wkt": shapely.to_wkt(fac.outline, rounding_precision=3),
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
    out["zones"] = out["facade_id"].map(zones_on).fillna("").to_numpy(dtype=object)
    materials_on = allby["material"].agg(lambda s: ";".join(sorted({v for v in s if v})))
    out["materials"] = out["facade_id"].map(materials_on).fillna("").to_numpy(dtype=object)
    return out


def targets_and_links(
    ctx: Context,
    tc: TargetCandidates,
    net: Network | None,
    ids: list[str],
    coverage: pd.DataFrame,
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """The target list (where, which type, how big and by which rule, which stations use
    it) and the per-link report (targets in common, placed, the link's own predicted error
    and the registration error the child station ends with)."""
    if net is None or not len(ids):
        return pd.DataFrame(columns=TARGET_COLUMNS), pd.DataFrame(columns=LINK_COLUMNS)
    fac, st = ctx.facades, ctx.settings
    sight = net.sight
    users: dict[int, set[int]] = {}
    for lk in net.links:
        for t in lk.targets:
            users.setdefault(t, set()).add(lk.child)
            if lk.parent != CONTROL:
                users[t].add(lk.parent)
    rows = []
    tid: dict[int, str] = {}
    for t in net.targets:
        who = sorted(users.get(t, ()))
        control = tc.type[t] == "control"
        if control:
            size, item = float("nan"), ""
            seen_by = np.array(who, dtype=int)
        else:
            need_users = sight.need_mm[t, who]
            chosen = choose_target(float(need_users.max()), tc.type[t], st.inventory)
            size = chosen.size_mm if chosen else float("nan")
            item = chosen.name if chosen else ""
            seen_by = np.flatnonzero(sight.usable[t] & (sight.need_mm[t] <= size))
            # the sightings the registration counts (a target leap-frogged: its window's)
            seen_by = np.array([j for j in seen_by if (j, t) in net.centre_rms], dtype=int)
        far = who[int(np.argmax(sight.need_mm[t, who]))] if who else 0
        f = int(tc.facade[t])
        nx, ny = tc.normal[t]
        label = (
            tc.control_id[t]
            if control
            else f"T{len([x for x in tid.values() if x.startswith('T')]) + 1:02d}"
        )
        tid[t] = label
        rows.append(
            {
                "target_id": label,
                "x": tc.xyz[t, 0],
                "y": tc.xyz[t, 1],
                "z": tc.xyz[t, 2],
                "type": tc.type[t],
                "min_size_mm": float(sight.need_mm[t, seen_by].max()) if len(seen_by) else np.nan,
                "size_mm": size,
                "sized_by": sight.rule[t, far],
                "station_ids": [ids[s] for s in seen_by],
                "item": item,
                "facade_id": fac.facade_id[f] if f >= 0 else "",
                # which way a wall target faces: azimuth of its normal, clockwise from grid north
                "facing_deg": float(np.degrees(np.arctan2(nx, ny)) % 360.0) if f >= 0 else np.nan,
                "centre_rms_mm": max(
                    (net.centre_rms.get((j, t), np.nan) for j in who), default=np.nan
                ),
                "height_by": "level run" if t in net.levelled else "",
            }
        )
    targets = pd.DataFrame(rows, columns=TARGET_COLUMNS)
    return targets, _link_table(net, tc, ids, coverage, tid)


def _link_table(
    net: Network, tc: TargetCandidates, ids: list[str], coverage: pd.DataFrame, tid: dict[int, str]
) -> pd.DataFrame:
    """The per-link report (:data:`~planner.pipeline.inputs.schema.LINK_COLUMNS`): the
    targets in common and placed (``tid``: their ids), the link's own predicted error, its
    dilution and the registration error the child station ends with."""
    worst_at = coverage.groupby("station_id")[["reg_m_x_mm", "reg_m_y_mm", "reg_m_z_mm"]].max()
    return pd.DataFrame(
        [
            {
                "station_a": "control" if lk.parent == CONTROL else ids[lk.parent],
                "station_b": ids[lk.child],
                "common_targets": _common_count(net, tc, lk),
                "targets_placed": len(lk.targets),
                "target_ids": ";".join(tid[t] for t in lk.targets),
                "link_rms_mm": net.link_error_mm.get((lk.parent, lk.child), np.nan),
                "dilution": net.link_error_mm.get((lk.parent, lk.child), np.nan)
                / net.link_sigma_mm.get((lk.parent, lk.child), np.nan),
                "station_b_rms_mm": float(worst_at.loc[ids[lk.child]].max())
                if ids[lk.child] in worst_at.index
                else np.nan,
                **_link_kind(net, lk),
            }
            for lk in net.links
        ],
        columns=LINK_COLUMNS,
    )


def _link_kind(net: Network, lk: Link) -> dict:
    """How a link registers (targets or cloud), the overlap of its two scans [%] (where the
    surfaces were modelled), the direction its own error is largest in and, for a cloud
    link the plan rehearsed, the factor on the model's error and its failures [%]."""
    ov = net.overlap
    overlap = float(ov[lk.parent, lk.child]) if ov is not None and lk.parent != CONTROL else np.nan
    cl = net.clouds.get((lk.parent, lk.child))
    check = cl.check if cl is not None else None
    return {
        "kind": lk.kind,
        "overlap_pct": overlap,
        "weakest_direction": net.weakest.get((lk.parent, lk.child), ""),
        "rehearsal_factor": float(np.sqrt(cl.scale)) if check is not None else np.nan,
        "failure_pct": 100.0 * check.failure if check is not None else np.nan,
    }


def _common_count(net: Network, tc: TargetCandidates, lk: Link) -> int:
    usable = net.sight.usable
    if lk.parent == CONTROL:
        return int((usable[:, lk.child] & tc.is_control).sum())
    return int((usable[:, lk.parent] & usable[:, lk.child] & ~tc.is_control).sum())


#: What the predicted registration error assumes of the registration software, per
#: ``registration_processing`` (said in the summary, the report and the booklet through the
#: summary's message).
PROCESSING_WORDS = {
    "adjustment": f"It assumes {REGISTRATION_PROCESSING['adjustment']}; registered pair by "
    "pair along the links instead, the errors add up along the chain and can exceed it (plan "
    "for that with --registration-processing pairwise).",
    "pairwise": f"It assumes {REGISTRATION_PROCESSING['pairwise']}: the errors add up along "
    "the chain; one adjustment of every scan's targets and surfaces together does at least "
    "as well.",
}


def rehearsal_message(net: Network, checks: dict, ctx: Context) -> str:
    """What the rehearsal of the cloud links found (:mod:`planner.pipeline.network.linkcheck`):
    the network's links rehearsed, those the model held and those taken at a larger error,
    and the pairs tried that failed too often to be links (``checks``: every rehearsal made
    for the plan, by candidate pair)."""
    used = [cl for cl in net.clouds.values() if cl is not None and cl.check is not None]
    if not checks:
        return ""
    sc, st = ctx.scanner, ctx.settings
    pos, head, _ = sc.start_error
    start = "the scanner's own tracking (VIS)" if sc.prealign == "vis" else "the operator's picking"
    weaker = [np.sqrt(cl.scale) for cl in used if cl.scale > 1.0]
    failed = sum(not c.holds for c in checks.values())
    trials = max((len(c.errors) for c in checks.values()), default=0)
    words = (
        f"Cloud links rehearsed: {len(checks)} pair(s) of scans simulated in the scene (thinned "
        f"to {st.cloud_spacing_mm:g} mm as the registration thins them, the surfaces' own "
        f"{st.cloud_floor_mm:g} mm error per 2 m cell) and registered by a generalized ICP "
        f"(small_gicp) {trials} time(s) from {start} ({pos:g} mm, {head / 3600:.2f}° of "
        f"heading) and from {PROBE_SIGMAS:g} σ off; of the network's {len(used)} cloud "
        f"link(s), {len(used) - len(weaker)} held the model's error"
    )
    if weaker:
        words += f", {len(weaker)} are taken at up to {max(weaker):.1f} × it"
    if failed:
        words += (
            f"; {failed} pair(s) failed more than {MAX_FAILURE:.0%} of the time and are no links"
        )
    return words + "."


def registration_messages(
    coverage: pd.DataFrame, links: pd.DataFrame, st: PlanSettings
) -> list[str]:
    """The worst predicted registration error and where; the weakest link."""
    if not st.computes_registration:
        if st.station_rms_pair != (0.0, 0.0):
            return [f"Registration error: the fixed station RMS {st.station_rms_mm} mm (as given)."]
        return ["Registration error: not counted (--no-registration-error)."]
    cov = coverage[~coverage["party_wall"] & (coverage["station_id"] != "")]
    if cov.empty:
        return []
    parts = cov[["reg_m_x_mm", "reg_m_y_mm", "reg_m_z_mm"]]
    worst = parts.max(axis=1)
    if not np.isfinite(worst).any():
        return []
    i = worst.idxmax()
    row = cov.loc[i]
    out = [
        f"Registration error: worst {worst[i]:.1f} mm (m_{parts.loc[i].idxmax().split('_')[2]}) at "
        f"{row['sample_id']} scanned from {row['station_id']}; median {worst.median():.1f} mm. "
        + PROCESSING_WORDS[st.registration_processing]
    ]
    if len(links):
        weak = links.loc[links["link_rms_mm"].idxmax()]
        how = (
            f"cloud to cloud, {weak['overlap_pct']:.0f} % overlap"
            if weak["kind"] == "cloud"
            else f"{weak['targets_placed']} targets of {weak['common_targets']} in common"
        )
        dilution = f", dilution {weak['dilution']:.1f}" if weak["kind"] != "cloud" else ""
        out.append(
            f"Weakest link: {weak['station_a']} → {weak['station_b']}, {how}, "
            f"{weak['link_rms_mm']:.1f} mm on its own ({weak['weakest_direction']}{dilution})."
        )
    return out


#: Facades the summary lists with their unmet samples (the rest: coverage.csv).
UNMET_FACADES_SHOWN = 12


def unmet_messages(unmet: pd.DataFrame) -> list[str]:
    """The unmet samples by facade, the most unmet first (at most
    :data:`UNMET_FACADES_SHOWN`), each with its most frequent reason."""
    out = [f"{len(unmet)} sample(s) do not meet the requirements:"]
    groups = sorted(
        unmet.groupby(["building_id", "facade_id"], sort=True), key=lambda kv: -len(kv[1])
    )
    for (bid, fid), g in groups[:UNMET_FACADES_SHOWN]:
        reasons = g["reason"].value_counts()
        out.append(
            f"  facade {fid} (building {bid}): {len(g)} sample(s), "
            f"z {g['z'].min():.1f}–{g['z'].max():.1f} m"
            f" — {reasons.index[0]}"
            + (f" (and {len(reasons) - 1} other reason(s))" if len(reasons) > 1 else "")
        )
    if len(groups) > UNMET_FACADES_SHOWN:
        rest = sum(len(g) for _, g in groups[UNMET_FACADES_SHOWN:])
        out.append(
            f"  … and {rest} sample(s) on {len(groups) - UNMET_FACADES_SHOWN} other facade(s) "
            "(coverage.csv)"
        )
    return out
