"""Why a plan leaves samples unmet, and what would meet them: per quantity, how many samples
fail, where, the best the plan's stations achieve there, the limits this plan does meet
everywhere (the smallest relaxation with these stations), and what else could help — an
elevated station where the ground cannot reach (a wall above a neighbour's roof), a scanner
of the catalogue that reaches farther for the same limits, a higher station for the upper
storeys."""

from __future__ import annotations

import numpy as np
import pandas as pd

from planner.pipeline.engine.result import Plan
from planner.pipeline.inputs.requirements import CHECKS
from planner.pipeline.inputs.resolved import reach_m
from planner.scanner import Scanner, catalogue

__all__ = ["EXPLAIN_COLUMNS", "explain_unmet", "relaxation_text", "suggestions"]

#: One row per failing quantity: its limit, the samples over it, the facades they are on,
#: the height range, and the worst value the plan's stations give there (what the plan meets).
EXPLAIN_COLUMNS = ["quantity", "limit", "unit", "samples", "facades", "z_from", "z_to", "worst"]


def explain_unmet(p: Plan) -> pd.DataFrame:
    """Per check (:data:`~planner.pipeline.inputs.requirements.CHECKS`) failing its site-wide limit
    at some unmet sample (:data:`EXPLAIN_COLUMNS`), the most failing first. The samples
    that need an elevated station are one row ("needs an elevated station"), those no
    station sees otherwise another ("not seen")."""
    u = p.unmet
    rows = []
    elevated = u["elevated_station"] != ""
    if elevated.any():
        rows.append(_row("needs an elevated station", np.nan, "", u[elevated], np.nan))
    u = u[~elevated]
    seen = u["station_id"] != ""
    for c in CHECKS:
        limit = c.limit_of(p.requirements)
        if limit is None or c.metric not in u:
            continue
        over = u[seen & ~c.passes(u[c.metric], float(limit))]
        if len(over):
            worst = float(over[c.metric].max() if c.sense == "max" else over[c.metric].min())
            rows.append(_row(c.label, float(limit), c.unit, over, worst))
    if (~seen).any():
        rows.append(_row("not seen", np.nan, "", u[~seen], np.nan))
    out = pd.DataFrame(rows, columns=EXPLAIN_COLUMNS)
    return out.sort_values("samples", ascending=False, kind="stable").reset_index(drop=True)


def _row(label: str, limit: float, unit: str, g: pd.DataFrame, worst: float) -> dict:
    return {
        "quantity": label,
        "limit": limit,
        "unit": unit,
        "samples": len(g),
        "facades": ", ".join(sorted(g["facade_id"].unique())),
        "z_from": round(float(g["z"].min()), 1),
        "z_to": round(float(g["z"].max()), 1),
        "worst": round(worst, 2),
    }


def _limits_met(p: Plan) -> str | None:
    """``m_x ≤ … mm (asked …), m_y ≤ …, m_z ≤ …`` that the plan's stations meet at every
    sample they see (rounded up to 0.1 mm); None when no station sees any."""
    cov = p.scanned[p.scanned["station_id"] != ""]
    if cov.empty:
        return None
    parts = []
    for c in CHECKS[:3]:  # m_x, m_y, m_z
        asked = c.limit_of(p.requirements)
        worst = float(cov[c.metric].max())
        parts.append(
            f"{c.label} ≤ {np.ceil(worst * 10) / 10:.1f} {c.unit}"
            + (f" (asked {asked:g})" if not c.passes(worst, asked) else "")
        )
    return ", ".join(parts) + " at every sample it sees"


def relaxation_text(p: Plan) -> str:
    """The limits the plan's stations meet at every sample they see: the smallest relaxation
    that makes this plan pass (registration included)."""
    met = _limits_met(p)
    return "no station sees any sample" if met is None else "this plan meets " + met


def _elevated_suggestions(u: pd.DataFrame) -> list[str]:
    """Where the ground cannot reach: one line per place an elevated station would stand."""
    out = []
    for where, g in u.groupby("elevated_station", sort=True):
        facades = ", ".join(sorted(g["facade_id"].unique()))
        place = f"on the {where}" if where.startswith("roof") else "on a lift or a mast"
        out.append(
            f"an elevated station {place} for {len(g)} sample(s) (facade {facades}, z "
            f"{g['z'].min():.1f}–{g['z'].max():.1f} m): the ground sees them only over a "
            "roof's edge, or not at all — no ground station is spent on them"
        )
    return out


def suggestions(p: Plan) -> list[str]:
    """What else could meet the requirement: an elevated station where the ground cannot
    reach (the samples' ``elevated_station``), catalogue scanners that reach farther for
    the same limits (:func:`planner.pipeline.engine.planning.reach_m`), a higher station where m_z
    fails high up at steep elevation angles, and the limits the plan meets."""
    u = p.unmet
    if u.empty:
        return []
    out = _elevated_suggestions(u[u["elevated_station"] != ""])
    u = u[u["elevated_station"] == ""]  # the ground cannot reach those: no scanner helps
    if u.empty:
        return out
    st = p.settings
    now = reach_m(p.scanner, p.requirements, st)
    better = []
    for name in catalogue():
        sc = Scanner.from_name(name)
        if sc.name == p.scanner.name:
            continue
        r = reach_m(sc, p.requirements, st)
        if r > now * 1.1:
            better.append((r, name))
    if better:
        names = ", ".join(f"{n} ({r:.0f} m)" for r, n in sorted(better, reverse=True)[:3])
        out.append(
            f"a scanner that keeps these limits farther out: {names}, against {now:.0f} m for "
            f"{p.scanner.name}"
        )
    steep = u[(u["m_z_mm"] > p.requirements.max_z_mm) & (u["nu_deg"].abs() > 30)]
    if len(steep):
        out.append(
            f"m_z fails at {len(steep)} sample(s) seen at elevation angles over 30° "
            f"(up to z {steep['z'].max():.1f} m): a station higher up — on a roof, a lift "
            f"or a tripod extension (--instrument-height-m, now {st.instrument_height_m:g} "
            "m) — sees them flatter"
        )
    met = _limits_met(p)
    if met is not None:
        out.append("the smallest relaxation with these stations: " + met)
    return out
