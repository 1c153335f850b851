"""The printable field booklet (PDF): an overview map, then one page per station in visiting
order. No science here: everything comes from the plan and its route.

Matplotlib writes the multi-page PDF (``PdfPages``); no other dependency. The same plan gives
the same bytes (no creation date is written). A station's page has a fixed layout (no
layout engine) and draws only what its map window shows, so a page costs the same in a
district of a thousand buildings as around one. It is always whole: the same plan gives
the same booklet on any machine.
"""

from __future__ import annotations

import io
import textwrap
from collections.abc import Collection

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.backends.backend_pdf import PdfPages
from matplotlib.figure import Figure
from matplotlib.patches import Wedge
from matplotlib.transforms import Bbox, BboxTransformTo, TransformedBbox, offset_copy
from shapely.geometry import box

from planner.app.maps import (
    COLOURS,
    MARKERS,
    draw_targets,
    place_labels,
    plot_plan_map,
    plot_site,
    settle_layout,
    survey_frame,
    title_on_page,
)
from planner.crs import name_of as crs_name
from planner.pipeline.engine.result import Plan
from planner.pipeline.field.route import kit_words, view_sectors
from planner.pipeline.field.setout import (
    CornerTies,
    compass_word,
    ties_text,
    wall_place,
    walls_scanned,
)
from planner.pipeline.inputs.schema import STATION_PURPOSES

__all__ = ["booklet_pdf", "compass", "kit_list", "target_places"]

A4_LANDSCAPE = (11.69, 8.27)
A4_PORTRAIT = (8.27, 11.69)
#: Where a station page's parts sit (figure fractions: left, bottom, width, height).
HEAD_BOX = (0.06, 0.745, 0.9, 0.21)
MAP_BOX = (0.14, 0.355, 0.8, 0.37)
TABLE_BOX = (0.06, 0.035, 0.9, 0.25)
#: A line of the station page's facts, and the gap after each fact (head axes fractions).
FACT_LINE, FACT_GAP = 0.056, 0.022
#: A line of the targets table (table axes fraction): what fits decides the rows shown.
TABLE_LINE = 0.05


def compass(azimuth_deg: float) -> str:
    """An azimuth as a compass point and degrees, e.g. ``SW (225°)``."""
    if azimuth_deg is None or not np.isfinite(azimuth_deg):
        return ""
    return f"{compass_word(azimuth_deg, short=True)} ({azimuth_deg:.0f}°)"


def booklet_pdf(p: Plan, only: Collection[str] | None = None) -> bytes:
    """The field booklet of a plan as PDF bytes: the overview map with the plan's summary,
    then a page per station in visiting order (coordinates, instrument height, targets to
    set up before it, scan sector, resolution and time, links); ``only``: pages for these
    stations alone (the extra stations of a re-plan). Always whole: a document of the plan
    does not depend on the machine's speed."""
    buf = io.BytesIO()
    meta = {"Title": f"tls-planner field booklet: {p.site.name}", "CreationDate": None}
    route = list(_route(p)["station_id"]) if len(_route(p)) else []
    with plt.rc_context({"pdf.fonttype": 42}), PdfPages(buf, metadata=meta) as pdf:
        pdf.savefig(_overview(p))
        sectors = view_sectors(p.stations, p.coverage, p.targets)  # once, not per page
        ties = CornerTies(p.site)  # (the corners too)
        for k, s in enumerate(route):  # figures outside pyplot: nothing to close
            if only is None or s in only:
                pdf.savefig(_station_page(p, k, sectors, ties))
    return buf.getvalue()


def _route(p: Plan) -> pd.DataFrame:
    return p.route.table if p.route is not None else pd.DataFrame()


def _overview(p: Plan) -> Figure:
    fig = Figure(figsize=A4_LANDSCAPE, layout="constrained")
    grid = fig.add_gridspec(2, 1, height_ratios=[5.2, 1])
    ax = fig.add_subplot(grid[0])
    plot_plan_map(p, ax, candidates=False, order_labels=True)  # (the planned area, to scale)
    title_on_page(ax, f"Field booklet — {p.site.name}: overview")
    text = fig.add_subplot(grid[1])
    text.axis("off")
    lines = [
        "Labels: in brackets a station's place in the visiting order, where its id does not "
        "give it. The map shows the planned buildings, the stations and the targets; the "
        "site's other buildings only where they stand among them.",
        f"Scanner {p.scanner.label or p.scanner.name}; required {p.requirements.describe()}; "
        f"model: {p.settings.model_description()}",
        f"Coordinates: {crs_name(p.site.crs) if p.site.crs else 'local metres (no CRS)'}; "
        f"{len(p.stations)} stations, {len(p.targets)} targets; samples meeting every "
        f"requirement: {int(p.scanned['meets'].sum())} of {len(p.scanned)}",
    ]
    if p.route is not None:
        lines.append(p.route.summary())
        lines.append(kit_list(p))
    text.text(
        0.0,
        1.0,
        "\n".join(_wrap(line, 170) for line in lines),
        va="top",
        fontsize=7.5,
        family="DejaVu Sans",
    )
    settle_layout(fig)  # (the title and the text below it placed)
    return fig


def kit_list(p: Plan) -> str:
    """The targets to pack, item by item: how many the plan uses and the most standing at
    once against the kit (:func:`~planner.pipeline.field.route.kit_words`)."""
    if p.route is None or p.route.kit.empty:
        return "Kit: no targets to pack."
    words = []
    for k in p.route.kit.itertuples():
        if not k.item:  # targets no item of the inventory is big enough for
            words.append(f"{k.used} {k.type} target(s) no item of your inventory fits")
            continue
        words.append(f"{k.item} ({k.type} {k.size_mm:g} mm): {k.used} placed; {kit_words(k)}")
    return "Kit to pack: " + "; ".join(words) + "."


def _wrap(text: str, width: int) -> str:
    return "\n".join(textwrap.wrap(text, width)) or text


def _station_page(
    p: Plan,
    n: int,
    sectors: dict[str, tuple[float, float, float]],
    ties: CornerTies | None = None,
) -> Figure:
    r = _route(p).iloc[n]
    sid = r["station_id"]
    st = p.stations.set_index("station_id").loc[sid]
    fig = Figure(figsize=A4_PORTRAIT)  # a fixed layout: no layout engine per page
    head = _Box(fig, HEAD_BOX)  # text only: no axes to lay out
    total = len(_route(p))
    head.title(
        f"{sid} — station {int(r['order'])} of {total}, session {int(r['session'])}",
        fontsize=14,
    )
    end = (r["sector_start_deg"] + r["sector_deg"]) % 360
    sector = (
        "full turn (360°)"
        if r["sector_deg"] >= 360
        else f"from {r['sector_start_deg']:.0f}° clockwise to {end:.0f}° "
        f"({r['sector_deg']:.0f}°, grid bearings)"
    )
    walk = "start here" if n == 0 else f"{r['walk_m']:.0f} m, {r['walk_min']:.0f} min"
    if r["walk_note"]:
        walk += f" ({r['walk_note']})"
    ties = ties or CornerTies(p.site)
    (set_out,) = ties(np.array([[st["x"], st["y"]]]))
    facts = [
        ("Easting / Northing", f"{st['x']:.3f} / {st['y']:.3f} m"),
        ("Set out (tape)", ties_text(set_out)),
        (
            "Instrument height, why here",
            f"{st['instrument_height_m']:.2f} m above the ground; "
            f"{STATION_PURPOSES.get(str(st['purpose']), str(st['purpose']))}",
        ),
        ("Walk from the previous station", walk),
        ("Scan sector", sector),
        (
            "Scanner setting",
            (f"'{r['preset']}': " if r["preset"] else "")
            + f"step {r['step_mm_at_10m']:g} mm at 10 m; point spacing on its facades at most "
            f"{r['max_spacing_mm']:g} mm",
        ),
        (
            "Expected scan time",
            f"{r['scan_min']:.1f} min ({r['scan_points_million']:g} M points)"
            + (f", then images {r['imaging_min']:.1f} min" if r["imaging_min"] > 0 else ""),
        ),
        (
            "Time at this station",
            f"{r['station_min']:.0f} min with set-up ({r['setup_min']:g} min) and targets; "
            f"{r['elapsed_min']:.0f} min since the start",
        ),
        ("Register to", _register_to(p, sid, r)),
        (
            "Walls it scans",
            "none: a total station's set-up of the traverse"
            if st["purpose"] == "traverse"
            else walls_scanned(p.coverage, p.facades, sid),
        ),
    ]
    y = 0.95
    for label, value in facts:  # each fact as many lines as it needs
        text = _wrap(value, 92)
        head.text(0.0, y, label, fontsize=8, weight="bold", va="top")
        head.text(0.3, y, text, fontsize=8, va="top")
        y -= FACT_LINE * (text.count("\n") + 1) + FACT_GAP
    ax = fig.add_axes(MAP_BOX)
    _station_map(p, sid, ax, sectors.get(sid, (0.0, 0.0, 20.0)))
    table_ax = fig.add_axes(TABLE_BOX)
    table_ax.axis("off")
    _targets_table(p, sid, r, table_ax, ties)
    return fig


class _Box:
    """A part of a page that holds only text, placed in its own unit square (as an axes'
    coordinates, without an axes: nothing to lay out or draw but the words)."""

    def __init__(self, fig: Figure, where: tuple[float, float, float, float]) -> None:
        self.fig = fig
        self.transform = BboxTransformTo(TransformedBbox(Bbox.from_bounds(*where), fig.transFigure))

    def text(self, x: float, y: float, s: str, **kw):
        return self.fig.text(x, y, s, transform=self.transform, **kw)

    def title(self, s: str, fontsize: float) -> None:
        """Bold, at the left above the box (where an axes' title stands)."""
        pad = plt.rcParams["axes.titlepad"]  # where an axes' title stands [points]
        above = offset_copy(self.transform, fig=self.fig, y=pad, units="points")
        self.fig.text(0.0, 1.0, s, transform=above, fontsize=fontsize, weight="bold")


def _register_to(p: Plan, sid: str, r: pd.Series) -> str:
    """The scans scanned before this one that it is registered to, and how."""
    if not r["registers_to"]:
        return "first scan" if r["order"] == 1 else "— (not linked to an earlier scan)"
    words = []
    lk = p.links
    for other in str(r["registers_to"]).split():
        pair = lk[
            ((lk["station_a"] == other) & (lk["station_b"] == sid))
            | ((lk["station_a"] == sid) & (lk["station_b"] == other))
        ]
        if not len(pair):
            words.append(other)
        elif pair["kind"].iloc[0] == "cloud":
            words.append(f"{other} (cloud to cloud, {pair['overlap_pct'].iloc[0]:.0f} % overlap)")
        else:
            words.append(f"{other} ({pair['targets_placed'].iloc[0]} targets)")
    return "; ".join(words)


def _station_map(p: Plan, sid: str, ax, sector: tuple[float, float, float]) -> None:
    """The surroundings of one station: its sector, its targets with ids, the way in."""
    st = p.stations.set_index("station_id")
    x, y = st.at[sid, "x"], st.at[sid, "y"]
    start, end, radius = sector
    mine = p.targets[p.targets["station_ids"].map(lambda s: sid in s)]
    # a square round the station and every target it scans, the station's sector at least
    pts = np.vstack([[[x, y]], mine[["x", "y"]].to_numpy(float).reshape(-1, 2)])
    lo, hi = pts.min(axis=0) - 4.0, pts.max(axis=0) + 4.0
    cx, cy = (lo + hi) / 2
    half = max(15.0 * 1.1, float((hi - lo).max()) / 2 * 1.1)
    wide = min(radius, 60.0) * 1.1  # the sector round the station, where that holds them
    if half < wide and np.all(np.abs(pts - [x, y]) <= wide):
        cx, cy, half = x, y, wide
    window = box(cx - half, cy - half, cx + half, cy + half)
    plot_site(p.site, ax, window=window)
    ax.add_patch(
        Wedge(
            (x, y),
            radius,
            90 - end,
            90 - start,
            fc=COLOURS["sector"],
            ec="#d68910",
            alpha=0.25,
            label="scan sector",
        )
    )
    labels: list = []
    draw_targets(
        ax,
        mine,
        labels,
        kinds=("flat", "sphere", "control"),
        size=40,
        legend_suffix=f" scanned from {sid}",
        fontsize=7,
    )
    if p.route is not None:
        order = list(p.route.table["station_id"])
        k = order.index(sid)
        leg = p.route.legs[k]
        if k > 0 and len(leg) >= 2:
            ax.plot(leg[:, 0], leg[:, 1], color=COLOURS["route"], ls=(0, (4, 2)), lw=1.2)
            ax.plot(
                [], [], color=COLOURS["route"], ls=(0, (4, 2)), label=f"walk from {order[k - 1]}"
            )
    others = p.stations[
        (p.stations["station_id"] != sid)
        & (p.stations["x"].sub(cx).abs() <= half)
        & (p.stations["y"].sub(cy).abs() <= half)
    ]
    ax.plot(
        others["x"],
        others["y"],
        MARKERS["station"],
        color="0.55",
        ms=7,
        mec="k",
        ls="none",
        zorder=5,
    )
    labels += [
        (o.x, o.y, o.station_id, {"fontsize": 7, "color": "0.3"}) for o in others.itertuples()
    ]
    ax.plot(x, y, MARKERS["station"], color=COLOURS["cover"], ms=11, mec="k", zorder=6, label=sid)
    labels.insert(0, (x, y, sid, {"fontsize": 10, "weight": "bold"}))
    ax.set_xlim(cx - half, cx + half)
    ax.set_ylim(cy - half, cy + half)
    survey_frame(ax, p.site.crs)
    ax.set_anchor("W")  # the square map at the left of its box, its legend beside it
    place_labels(ax, labels)
    ax.legend(loc="upper left", bbox_to_anchor=(1.03, 1.0), borderaxespad=0.0, fontsize=6.5)


def target_places(p: Plan, target_ids: list[str], ties: CornerTies | None = None) -> list[str]:
    """Where each target goes, in a crew's words: a wall target by its building, wall,
    distance from the wall's end and height above the ground; a stand by tape ties from two
    building corners (:func:`~planner.pipeline.field.setout.ties_text`) and its height
    above the ground; a control point as the mark it is."""
    tg = p.targets.set_index("target_id").loc[target_ids]
    fac = p.facades.set_index("facade_id")
    on_wall = (tg["type"] == "flat") & tg["facade_id"].isin(fac.index)
    loose = tg[~on_wall & (tg["type"] != "control")]
    tied = (ties or CornerTies(p.site))(loose[["x", "y"]].to_numpy(float))
    by_target = dict(zip(loose.index, tied, strict=True))
    # heights above the ground (the z are in the site's height system: on a terrain, 500 m)
    high = tg["z"].to_numpy(float) - p.site.ground_z(tg[["x", "y"]].to_numpy(float))
    out = []
    for (tid, t), wall, h in zip(tg.iterrows(), on_wall, high, strict=True):
        if wall:
            out.append(wall_place(fac.loc[t["facade_id"]], t["x"], t["y"], h))
        elif t["type"] == "control":
            out.append("control point: its mark is already there")
        else:
            where = "on a stand" if t["type"] != "flat" else "on its wall"
            out.append(f"{t['type']} {where}, {h:.1f} m high: {ties_text(by_target[tid])}")
    return out


def _targets_table(p: Plan, sid: str, r: pd.Series, ax, ties: CornerTies) -> None:
    ids = [t for t in str(r["targets_to_set"]).split(" ") if t]
    collect = [t for t in str(r.get("targets_to_collect", "")).split(" ") if t]
    ax.set_title(
        f"Set up before scanning {sid}: {len(ids)} target(s)"
        + ("" if ids else " — none new, all were placed for an earlier station")
        + (f". Collect after it: {' '.join(collect)}" if collect else ". Collect after it: none"),
        loc="left",
        fontsize=9,
        weight="bold",
    )
    if not ids:
        return
    tg = p.targets.set_index("target_id").loc[ids]
    rows = []
    for (tid, t), where in zip(tg.iterrows(), target_places(p, ids, ties), strict=True):
        size = "" if t["size_mm"] is None or not np.isfinite(t["size_mm"]) else f"{t['size_mm']:g}"
        item = t["item"] if isinstance(t.get("item"), str) and t["item"] else str(t["type"])
        rows.append([tid, item, size, _wrap(where, 66), f"{t['x']:.3f}", f"{t['y']:.3f}", ""])
    lines = [r[3].count("\n") + 1 for r in rows]
    room = 1.0 / TABLE_LINE - 1.4  # lines under the header (a row: its lines + 0.3)
    n_shown = max(1, int(np.searchsorted(np.cumsum(np.add(lines, 0.3)), room, side="right")))
    shown = rows[:n_shown]
    table = ax.table(
        cellText=shown,
        colLabels=["id", "item", "size mm", "where", "easting", "northing", "notes"],
        loc="upper left",
        cellLoc="left",
        colWidths=[0.05, 0.09, 0.06, 0.47, 0.1, 0.11, 0.12],
    )
    table.auto_set_font_size(False)
    table.set_fontsize(6.5)
    for (row, _col), cell in table.get_celld().items():
        cell.set_height(TABLE_LINE * (1.4 if row == 0 else lines[row - 1] + 0.3))
    if len(rows) > len(shown):
        left = " ".join(r[0] for r in rows[len(shown) :])
        ax.text(0, -0.03, f"… and {left}: see targets.csv and the stake-out file", fontsize=7)
