"""Why a plan leaves samples unmet, and what would meet them: per quantity, how many samples
fail, where, the best the plan's stations achieve there, the limits this plan does meet
everywhere (the smallest relaxation with these stations), and what else could help — a
scanner of the catalogue that reaches farther for the same limits, a higher station for the
upper storeys."""

from __future__ import annotations

import numpy as np
import pandas as pd

from planner.pipeline.planning import reach_m
from planner.pipeline.result import Plan
from planner.scanner import Scanner, catalogue

__all__ = ["EXPLAIN_COLUMNS", "explain_unmet", "relaxation_text", "suggestions"]

#: One row per failing quantity: its limit, the samples over it, the facades they are on,
#: the height range, and the worst value the plan's stations give there (what the plan meets).
EXPLAIN_COLUMNS = ["quantity", "limit", "unit", "samples", "facades", "z_from", "z_to", "worst"]

#: The quantities explained (coverage column, label, requirement attribute, unit).
_QUANTITIES = (
    ("m_x_mm", "m_x", "max_x_mm", "mm"),
    ("m_y_mm", "m_y", "max_y_mm", "mm"),
    ("m_z_mm", "m_z", "max_z_mm", "mm"),
    ("gamma_deg", "γ", "max_gamma_deg", "°"),
    ("spacing_mm", "point spacing", "max_spacing_mm", "mm"),
)


def explain_unmet(p: Plan) -> pd.DataFrame:
    """Per quantity over its site-wide limit at some unmet sample (:data:`EXPLAIN_COLUMNS`),
    the most failing first. Samples no station sees are one row, quantity "not seen"."""
    u = p.unmet
    rows = []
    seen = u["station_id"] != ""
    for col, label, attr, unit in _QUANTITIES:
        limit = getattr(p.requirements, attr, None)
        if limit is None or col not in u:
            continue
        over = u[seen & (u[col] > float(limit) * (1 + 1e-9))]
        if len(over):
            rows.append(_row(label, float(limit), unit, over, float(over[col].max())))
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


def relaxation_text(p: Plan) -> str:
    """The limits the plan's stations meet at every sample they see: the smallest relaxation
    that makes this plan pass (registration included)."""
    cov = p.scanned[p.scanned["station_id"] != ""]
    if cov.empty:
        return "no station sees any sample"
    parts = []
    for col, label, attr, unit in _QUANTITIES[:3]:
        asked = getattr(p.requirements, attr)
        worst = float(cov[col].max())
        parts.append(
            f"{label} ≤ {np.ceil(worst * 10) / 10:.1f} {unit}"
            + (f" (asked {asked:g})" if worst > asked * (1 + 1e-9) else "")
        )
    return "this plan meets " + ", ".join(parts) + " at every sample it sees"


def suggestions(p: Plan) -> list[str]:
    """What else could meet the requirement: catalogue scanners that reach farther for the
    same limits (:func:`planner.pipeline.planning.reach_m`), and a higher station where m_z
    fails high up at steep elevation angles."""
    out = []
    table = explain_unmet(p)
    if table.empty:
        return out
    st = p.settings
    now = reach_m(p.scanner, p.requirements, st.station_rms_pair, st.model)
    better = []
    for name in catalogue():
        sc = Scanner.from_name(name)
        if sc.name == p.scanner.name:
            continue
        r = reach_m(sc, p.requirements, st.station_rms_pair, st.model)
        if r > now * 1.1:
            better.append((r, name))
    if better:
        names = ", ".join(f"{n} ({r:.0f} m)" for r, n in sorted(better, reverse=True)[:3])
        out.append(
            f"a scanner that keeps these limits farther out: {names}, against {now:.0f} m for "
            f"{p.scanner.name}"
        )
    mz = table[table["quantity"] == "m_z"]
    if len(mz):
        u = p.unmet
        steep = u[(u["m_z_mm"] > p.requirements.max_z_mm) & (u["nu_deg"].abs() > 30)]
        if len(steep):
            out.append(
                f"m_z fails at {len(steep)} sample(s) seen at elevation angles over 30° "
                f"(up to z {steep['z'].max():.1f} m): a station higher up — on a roof, a lift "
                f"or a tripod extension (--instrument-height-m, now {st.instrument_height_m:g} "
                "m) — sees them flatter"
            )
    out.append(
        "the smallest relaxation with these stations: "
        + relaxation_text(p).removeprefix("this plan meets ")
    )
    return out
