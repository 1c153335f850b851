"""Plots of a plan: the site map and the coverage of the facades. No science here.

Used by the dashboard, the report and ``planner figures``.
"""

from __future__ import annotations

import math

import matplotlib.colors as mcolors
import matplotlib.patheffects as patheffects
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
import shapely
import shapely.affinity
from matplotlib.axes import Axes
from matplotlib.collections import PatchCollection
from matplotlib.figure import Figure
from matplotlib.patches import FancyArrowPatch, PathPatch, Rectangle, Wedge
from matplotlib.patches import Polygon as MplPolygon
from matplotlib.path import Path as MplPath
from matplotlib.textpath import TextToPath
from matplotlib.ticker import FuncFormatter, Locator
from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar
from shapely.geometry.base import BaseGeometry

from planner.crs import name_of as crs_name
from planner.pipeline.engine.result import Plan
from planner.pipeline.field.route import view_sectors
from planner.pipeline.inputs.schema import STATION_ID, STATION_PURPOSES, SYMBOLS
from planner.site import Building, Site

__all__ = [
    "RoundLocator",
    "grid_label",
    "legend_outside",
    "place_labels",
    "planned_area",
    "plot_coverage",
    "plot_plan_map",
    "plot_site",
    "round_step",
    "round_ticks",
    "scale_bar_length",
    "survey_frame",
    "title_on_page",
]

QUANTITIES = {
    "m_x_mm": "m_x [mm]",
    "m_y_mm": "m_y [mm]",
    "m_z_mm": "m_z [mm]",
    "reg_m_x_mm": "registration part of m_x [mm]",
    "reg_m_y_mm": "registration part of m_y [mm]",
    "reg_m_z_mm": "registration part of m_z [mm]",
}
#: The limit each plotted quantity is coloured against (its requirement).
_LIMIT_OF = {"x": "max_x_mm", "y": "max_y_mm", "z": "max_z_mm"}


def quantity_label(quantity: str) -> str:
    """The short name of a coverage quantity, for a button (:data:`QUANTITIES`' words).

    >>> quantity_label("m_x_mm"), quantity_label("reg_m_z_mm")
    ('m_x', 'registration z')
    """
    words = QUANTITIES[quantity].removesuffix(" [mm]")
    return words.replace("registration part of m_", "registration ")


def quantity_limit(p: Plan, quantity: str) -> float:
    """The site-wide limit a coverage quantity is coloured against [mm]."""
    return float(getattr(p.requirements, _LIMIT_OF[quantity[-4]]))


def _patch(geom, **kw) -> PathPatch:
    verts, codes = [], []
    for poly in shapely.get_parts(geom):
        for ring in [poly.exterior, *poly.interiors]:
            xy = np.asarray(ring.coords)[:, :2]
            verts.append(xy)
            codes += [MplPath.MOVETO] + [MplPath.LINETO] * (len(xy) - 2) + [MplPath.CLOSEPOLY]
    return PathPatch(MplPath(np.vstack(verts), codes), **kw)


#: Colours of the drawn kinds (one place: map, legend, booklet).
COLOURS = {
    "planned": "#7f8c8d",
    "other": "#d5d8dc",
    "tree": "#58d68d",
    "obstacle": "#a04000",
    "no-go": "#f4cccc",
    "cover": "#c0392b",
    "hand": "#e67e22",
    "best-effort": "#7d3c98",
    "link": "#1f618d",
    "registration": "#1f618d",
    "target": "#8e44ad",
    "route": "#117a65",
    "sector": "#f5b041",
    "passage": "#d4ac0d",
    "traverse": "#17202a",
}


#: A label on a map: cut at the map's frame (a building's at the edge), never laid out as
#: if it stood beside the map (the constrained layout would squeeze the map's axis off the
#: page for a label that spills over its frame).
MAP_TEXT = {"clip_on": True, "in_layout": False}


def _draw_building(ax: Axes, b: Building, labelled: set[str]) -> None:
    """A building's footprint (planned dark, others light), a 3-D building's roof edges and
    ridges, its id and height; a legend entry for each kind not yet ``labelled``."""
    kind = "planned" if b.planned else "other"
    label = "building (planned)" if b.planned else "building (blocks the beam)"
    ax.add_patch(
        _patch(
            b.footprint,
            fc=COLOURS[kind],
            ec="k",
            lw=0.8,
            label=None if kind in labelled else label,
        )
    )
    labelled.add(kind)
    if b.surfaces:  # a 3-D building: its roof's edges and ridges, its parts' outlines
        roof = [s.rings[0][:, :2] for s in b.surfaces if s.kind == "roof"]
        for ring in roof:
            ax.add_patch(MplPolygon(ring, closed=True, fill=False, ec="0.55", lw=0.4, zorder=2))
        if roof and "roof" not in labelled:
            ax.plot([], [], color="0.55", lw=0.4, label="roof edges and ridges (3-D model)")
            labelled.add("roof")
    c = b.footprint.representative_point()
    ax.annotate(
        f"{b.id}\n{round(b.height_m, 1):g} m",
        (c.x, c.y),
        ha="center",
        va="center",
        fontsize=7,
        color="w" if b.planned else "k",
        **MAP_TEXT,
    )


def plot_site(site: Site, ax: Axes | None = None, window: BaseGeometry | None = None) -> Axes:
    """Buildings (planned dark, others light), obstacles, no-go areas and the boundary, in
    the site's coordinates, each kind with a legend entry; only those meeting ``window``
    when one is given (a page showing one station's surroundings)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 7), layout="constrained")

    def shown(items, geom_of):
        if window is None:
            return list(items)
        return [i for i in items if geom_of(i).intersects(window)]

    if site.boundary is not None:
        ax.add_patch(_patch(site.boundary, fill=False, ls="--", ec="0.4", lw=1))
        ax.plot([], [], ls="--", color="0.4", lw=1, label="survey boundary")
    for n, a in enumerate(shown(site.no_go, lambda a: a.geometry)):
        ax.add_patch(
            _patch(
                a.geometry,
                fc=COLOURS["no-go"],
                ec="#cc6666",
                hatch="//",
                lw=0.5,
                label="no-go area" if n == 0 else None,
            )
        )
    labelled: set[str] = set()
    for b in shown(site.buildings, lambda b: b.footprint):
        _draw_building(ax, b, labelled)
    for n, g in enumerate(shown(site.passages, lambda g: g.geometry)):
        ax.add_patch(
            _patch(
                g.geometry,
                fill=False,
                ec=COLOURS["passage"],
                ls="--",
                lw=1.4,
                zorder=3,
                label="passage (gateway)" if n == 0 else None,
            )
        )
    for ob in shown(site.obstacles, lambda o: o.geometry):
        kind = "tree" if ob.kind == "tree" else "obstacle"
        ax.add_patch(
            _patch(
                ob.geometry,
                fc=COLOURS[kind],
                ec="k",
                lw=0.5,
                alpha=0.8,
                label=None if kind in labelled else kind,
            )
        )
        labelled.add(kind)
    ax.set_aspect("equal")
    ax.autoscale_view()
    return ax


def plot_plan_map(
    p: Plan,
    ax: Axes | None = None,
    *,
    candidates: bool = True,
    sectors: bool = True,
    route: bool = True,
    order_labels: bool = False,
) -> Figure:
    """The plan as a survey drawing in the site's coordinates, to scale: candidate heat map
    (samples each position meets), stations with their view sectors, registration links,
    targets with their ids, the walking route, unmet samples; a coordinate grid in absolute
    values, a scale bar, a grid-north arrow and a legend of everything drawn; labels placed
    so that they do not overlap. It frames the planned area (:func:`planned_area`): of the
    rest of the site only what stands in it is drawn."""
    if ax is None:
        _, ax = plt.subplots(figsize=(11, 8), layout="constrained")
    fig = ax.figure
    x0, y0, x1, y1 = _plan_extent(p)  # the planned area: the rest of the site is not drawn
    if candidates:
        _draw_candidates(p, ax)
    plot_site(p.site, ax, window=shapely.box(x0, y0, x1, y1))
    if sectors:
        _draw_sectors(p, ax)
    if route:
        _draw_route(p, ax)
    labels: list[tuple[float, float, str, dict]] = []
    _draw_traverses(p, ax)
    _draw_links(p, ax, labels)
    target_labels: list[tuple[float, float, str, dict]] = []
    draw_targets(ax, p.targets, target_labels)
    labels += _draw_stations(p, ax, order_labels)
    un = p.unmet
    if len(un):
        ax.scatter(
            un["x"],
            un["y"],
            marker="x",
            c="red",
            s=30,
            zorder=6,
            label=f"unmet samples ({len(un)})",
        )
    title = f"{len(p.stations)} stations, {len(p.targets)} targets — {p.site.name}"
    if len(labels) + len(target_labels) <= MAX_MAP_LABELS:
        labels += target_labels
    else:  # a district: its target ids would only bury the stations' (the pages have them)
        title += " (target ids: targets.csv and each station's page)"
    title_on_page(ax, title)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    survey_frame(ax, p.site.crs)
    place_labels(ax, labels)
    legend_outside(ax)
    settle_layout(fig)
    return fig


def settle_layout(fig: Figure) -> None:
    """Lay the figure out once more with everything on it: the constrained layout's first
    placing of a map sized by its aspect leaves room for the y axis as its labels stood
    before (a map's coordinates were cut at the page's left edge)."""
    engine = fig.get_layout_engine()
    if engine is not None:
        engine.execute(fig)


def _draw_candidates(p: Plan, ax: Axes) -> None:
    """The candidate positions coloured by the samples each meets (with a colour bar), or
    grey where none meets one."""
    fig = ax.figure
    if len(p.candidates) and not p.candidates["samples_met"].any():
        # nothing to scale a colour bar by (it would run from -0.1 to 0.1): grey positions
        ax.scatter(
            p.candidates["x"],
            p.candidates["y"],
            s=4,
            marker="s",
            color="0.6",
            lw=0,
            zorder=0,
            label="candidate position (none meets a sample as asked)",
        )
    elif len(p.candidates):
        c = p.candidates
        sc = ax.scatter(
            c["x"],
            c["y"],
            c=c["samples_met"],
            s=4,
            marker="s",
            cmap="viridis",
            alpha=0.55,
            lw=0,
            zorder=0,
        )
        fig.colorbar(
            sc,
            ax=ax,
            shrink=0.4,
            aspect=15,
            anchor=(0.0, 0.0),
            label="samples a station here meets",
        )


def _draw_sectors(p: Plan, ax: Axes) -> None:
    """Each station's view sector, faint."""
    st = p.stations.set_index("station_id")
    if len(p.stations):
        wedges = [
            Wedge((st.at[sid, "x"], st.at[sid, "y"]), radius, 90 - end, 90 - start)
            for sid, (start, end, radius) in view_sectors(p.stations, p.coverage, p.targets).items()
        ]
        ax.add_collection(
            PatchCollection(wedges, fc=COLOURS["sector"], ec="#d68910", alpha=0.07, lw=0.6)
        )
        ax.fill([], [], fc=COLOURS["sector"], ec="#d68910", alpha=0.3, label="scan sector")


def _draw_route(p: Plan, ax: Axes) -> None:
    """The walking route between the stations, its length in the legend."""
    if p.route is not None and len(p.route.legs) > 1:
        for leg in (g for g in p.route.legs[1:] if len(g) >= 2):
            ax.plot(leg[:, 0], leg[:, 1], color=COLOURS["route"], lw=1.1, ls=(0, (4, 2)), zorder=2)
        ax.plot(
            [],
            [],
            color=COLOURS["route"],
            lw=1.1,
            ls=(0, (4, 2)),
            label=f"walking route ({p.route.table['walk_m'].sum():.0f} m)",
        )


def _draw_stations(p: Plan, ax: Axes, order_labels: bool) -> list[tuple[float, float, str, dict]]:
    """The stations by purpose; their labels (the visit in brackets where ``order_labels``
    and the id does not say it)."""
    labels: list[tuple[float, float, str, dict]] = []
    order = {}
    if order_labels and p.route is not None:
        order = dict(zip(p.route.table["station_id"], p.route.table["order"], strict=True))
    for purpose in STATION_PURPOSES:
        s = p.stations[p.stations["purpose"] == purpose]
        if len(s):
            ax.plot(
                s["x"],
                s["y"],
                MARKERS["station"],
                color=COLOURS[purpose],
                ms=9,
                mec="k",
                ls="none",
                zorder=5,
                label=f"station ({STATION_PURPOSES[purpose]})"
                if purpose != "registration" or not (p.stations["purpose"] == "link").any()
                else None,
            )
    for r in p.stations.itertuples():
        n = order.get(r.station_id)  # the visit shown where the id does not say it
        says_it = n is None or r.station_id == STATION_ID.format(n)
        text = r.station_id if says_it else f"{r.station_id} ({n})"
        labels.append((r.x, r.y, text, {"fontsize": 8, "weight": "bold"}))
    return labels


#: A plan map with more labels than this leaves out the targets' ids.
MAX_MAP_LABELS = 400

#: Matplotlib's marker of each symbol (:data:`~planner.pipeline.inputs.schema.SYMBOLS`).
MARKERS = {
    kind: {"triangle-up": "^", "square": "s", "circle": "o", "triangle-down": "v"}[shape]
    for kind, shape in SYMBOLS.items()
}
_TARGET_MARKERS = {k: MARKERS[k] for k in ("flat", "sphere", "control")}


def draw_targets(
    ax: Axes,
    targets: pd.DataFrame,
    labels: list,
    *,
    kinds: tuple[str, ...] = ("flat", "sphere"),
    size: float = 28,
    legend_suffix: str = "",
    fontsize: float = 6,
) -> None:
    """Targets of ``kinds`` as white markers (control points black), each kind once in the
    legend; their ids go to ``labels`` (for :func:`place_labels`)."""
    for kind in kinds:
        t = targets[targets["type"] == kind]
        if not len(t):
            continue
        ax.scatter(
            t["x"],
            t["y"],
            marker=_TARGET_MARKERS[kind],
            s=size,
            fc="k" if kind == "control" else "w",
            ec=COLOURS["target"],
            lw=1.5,
            zorder=4,
            label=f"{kind} target{legend_suffix}",
        )
        style = {"fontsize": fontsize, "color": COLOURS["target"]}
        labels.extend((r.x, r.y, r.target_id, style) for r in t.itertuples())


def legend_outside(ax: Axes) -> None:
    """The legend beside the drawing (the figure's, when its layout makes room for it)."""
    fig = ax.figure
    handles, names = ax.get_legend_handles_labels()
    if fig.get_layout_engine() is not None:
        fig.legend(handles, names, loc="outside right upper", fontsize=7, framealpha=0.9)
    else:
        ax.legend(handles, names, loc="upper left", fontsize=6.5, framealpha=0.9)


#: A map's margin round what it shows: this share of its larger side, at least
#: ``MAP_MARGIN_M``.
MAP_MARGIN, MAP_MARGIN_M = 0.06, 3.0


def planned_area(site: Site, *points: np.ndarray) -> tuple[float, float, float, float]:
    """What a map of a plan frames (x0, y0, x1, y1 [m]): the buildings planned and the
    ``points`` ((n, 2) arrays: the stations, the targets) — not the rest of the site's
    file (a district's other buildings only block the beam)."""
    pts = [shapely.get_coordinates(b.footprint) for b in site.planned]
    pts += [np.asarray(q, dtype=float).reshape(-1, 2) for q in points]
    pts = [q for q in pts if len(q)]
    if not pts:  # (nothing planned: the whole site)
        pts = [shapely.get_coordinates(b.footprint) for b in site.buildings]
    allxy = np.vstack(pts)
    (x0, y0), (x1, y1) = allxy.min(axis=0), allxy.max(axis=0)
    return float(x0), float(y0), float(x1), float(y1)


def _plan_extent(p: Plan) -> tuple[float, float, float, float]:
    """The plan map's extent: :func:`planned_area` of the plan with a margin (a scan
    sector may run off the sheet)."""
    xy = [df[["x", "y"]].to_numpy(dtype=float) for df in (p.stations, p.targets)]
    x0, y0, x1, y1 = planned_area(p.site, *xy)
    pad = max(MAP_MARGIN * max(x1 - x0, y1 - y0), MAP_MARGIN_M)
    return x0 - pad, y0 - pad, x1 + pad, y1 + pad


#: The mantissas of a round number on a map (its grid's step, its scale bar): 1, 2 or 5 ×
#: 10^k m — one rule for the dashboard's map and the printed ones.
ROUND_MANTISSAS = (1.0, 2.0, 5.0)


def round_step(raw: float) -> float:
    """The smallest round number (1, 2 or 5 × 10^k) at or above ``raw`` (> 0).

    >>> round_step(13.0), round_step(0.3), round_step(20.0), round_step(51.0)
    (20.0, 0.5, 20.0, 100.0)
    """
    raw = max(float(raw), 1e-9)
    k = math.floor(math.log10(raw))
    steps = [m * 10.0**e for e in (k, k + 1) for m in ROUND_MANTISSAS]
    return float(next(v for v in steps if v >= raw * (1.0 - 1e-9)))


def round_ticks(lo: float, hi: float, step: float) -> np.ndarray:
    """The multiples of ``step`` from ``lo`` to ``hi`` (where a map's grid lines go).

    >>> round_ticks(690954.2, 691021.0, 20.0).tolist()
    [690960.0, 690980.0, 691000.0, 691020.0]
    """
    first = math.ceil(lo / step - 1e-9)
    last = math.floor(hi / step + 1e-9)
    digits = tick_decimals(step) + 1
    return np.round(np.arange(first, last + 1) * step, digits)


def tick_decimals(step: float) -> int:
    """The decimals a grid of ``step`` needs (0 for a step of 1 m or more).

    >>> tick_decimals(20.0), tick_decimals(0.5), tick_decimals(0.05)
    (0, 1, 2)
    """
    return max(0, -math.floor(math.log10(step) + 1e-9))


def scale_bar_length(span: float) -> float:
    """A scale bar's length: the round number (1, 2 or 5 × 10^k m) nearest a fifth of
    ``span`` (the width the map shows [m]).

    >>> scale_bar_length(100.0), scale_bar_length(180.0), scale_bar_length(40.0)
    (20.0, 50.0, 10.0)
    """
    raw = max(span / 5.0, 1e-3)
    k = math.floor(math.log10(raw))
    steps = [m * 10.0**e for e in (k, k + 1) for m in ROUND_MANTISSAS]
    return float(min(steps, key=lambda v: abs(math.log(v / raw))))


def grid_label(value: float, step: float) -> str:
    """A grid coordinate as a surveyor reads it: whole metres in groups of three digits
    (more decimals where the grid's ``step`` is under a metre).

    >>> grid_label(5335060.0, 20.0), grid_label(691002.5, 0.5)
    ('5 335 060', '691 002.5')
    """
    return f"{value:,.{tick_decimals(step)}f}".replace(",", " ")


#: The least distance between two grid lines on paper [in] (a 7-digit northing of
#: ``GRID_LABEL_PT`` fits between two across).
GRID_GAP_IN, GRID_LABEL_PT = 0.7, 8.0


class RoundLocator(Locator):
    """Grid lines at the multiples of a round step (:func:`round_step`) at least
    :data:`GRID_GAP_IN` apart on paper: on a map drawn to scale, the same step across as
    up."""

    def __init__(self, gap_in: float = GRID_GAP_IN) -> None:
        self.gap_in = gap_in
        self.step = 1.0  # [m] (the labels' decimals follow it)

    def __call__(self) -> np.ndarray:
        lo, hi = self.axis.get_view_interval()
        return self.tick_values(lo, hi)

    def tick_values(self, vmin: float, vmax: float) -> np.ndarray:
        """The grid's values between ``vmin`` and ``vmax``."""
        lo, hi = sorted((float(vmin), float(vmax)))
        ax = self.axis.axes
        box = ax.get_position(original=False)  # (after the aspect is applied)
        width, height = ax.figure.get_size_inches()
        inches = box.width * width if self.axis.axis_name == "x" else box.height * height
        self.step = round_step((hi - lo) / max(inches, 0.1) * self.gap_in)
        return round_ticks(lo, hi, self.step)


def survey_frame(ax: Axes, crs: str | None) -> None:
    """What makes a plot a survey drawing: equal scale across and up, absolute coordinates
    on both axes (no offset) on a grid of round steps, a scale bar and a grid-north arrow."""
    ax.set_aspect("equal", adjustable="box")
    for axis in (ax.xaxis, ax.yaxis):
        locator = RoundLocator()
        axis.set_major_locator(locator)
        axis.set_major_formatter(FuncFormatter(lambda v, _, k=locator: grid_label(v, k.step)))
    ax.tick_params(labelsize=GRID_LABEL_PT)
    ax.grid(True, color="0.75", lw=0.4, ls="-", zorder=-1)
    where = f" — {crs_name(crs)}" if crs else " (local metres, no CRS)"
    ax.set_xlabel(f"Easting [m]{where}", fontsize=8)
    ax.set_ylabel("Northing [m]", fontsize=8)
    x0, x1 = ax.get_xlim()
    length = scale_bar_length(x1 - x0)
    ax.add_artist(
        AnchoredSizeBar(
            ax.transData,
            length,
            f"{length:g} m",
            "lower right",
            pad=0.5,
            sep=3,
            frameon=True,
            size_vertical=(x1 - x0) / 250,
            fontproperties={"size": 7},
        )
    )
    _north_arrow(ax)


def _north_arrow(ax: Axes) -> None:
    """An arrow to grid north (up: the map is in a projected grid, easting across) and its
    N, inside the upper right corner, on a white ground."""
    white = [patheffects.withStroke(linewidth=3.5, foreground="w")]
    ax.annotate(
        "",
        xy=(0.955, 0.925),
        xytext=(0.955, 0.83),
        xycoords="axes fraction",
        arrowprops=dict(arrowstyle="-|>", color="k", lw=1.5, mutation_scale=14),
        zorder=8,
    )
    ax.annotate(
        "N",
        xy=(0.955, 0.93),
        xycoords="axes fraction",
        ha="center",
        va="bottom",
        fontsize=9,
        weight="bold",
        zorder=8,
        path_effects=white,
    )


def title_on_page(ax: Axes, text: str, share: float = 0.6) -> None:
    """Set ``ax``'s title, broken into lines no wider than ``share`` of the page (a long
    site name): never cut at the page's edges. (Matplotlib's own ``wrap=True`` upsets the
    constrained layout: it lays the title out unbroken.)"""
    ax.set_title(text)
    prop = ax.title.get_fontproperties()
    limit = share * ax.figure.get_figwidth() * 72.0  # [points]
    lines: list[str] = []
    line = ""
    for word in text.split():
        trial = f"{line} {word}".strip()
        if line and _TEXT_PATH.get_text_width_height_descent(trial, prop, False)[0] > limit:
            lines.append(line)
            line = word
        else:
            line = trial
    ax.set_title("\n".join([*lines, line]))


_TEXT_PATH = TextToPath()


#: Where a label may sit round its point [points]: tried in this order.
LABEL_OFFSETS = np.array(
    [(4, 4), (4, -11), (-6, 4), (-6, -11), (8, -3), (-8, -3), (0, 9), (0, -15)], dtype=float
)


def place_labels(ax: Axes, items: list[tuple[float, float, str, dict]]) -> None:
    """Annotate each (x, y, text, style) next to its point, trying eight positions round it
    and taking the first whose box overlaps no label already placed (else the least
    overlapping): readable with many stations and targets close together. The overlaps of
    one label's eight boxes with every label placed are computed at once (NumPy), so a
    thousand labels take milliseconds, not seconds."""
    fig = ax.figure
    engine = fig.get_layout_engine()
    if engine is not None:
        engine.execute(fig)  # fixes the layout, so data → pixel is final
    ax.apply_aspect()
    to_px = ax.transData.transform
    placed = np.empty((len(items), 4))
    dpi_scale = fig.dpi / 72.0
    dx, dy = LABEL_OFFSETS[:, 0], LABEL_OFFSETS[:, 1]
    shift = np.where(dx < 0, 1.0, np.where(dx == 0, 0.5, 0.0))  # of the width, to the left
    for n, (x, y, text, style) in enumerate(items):
        px, py = to_px((x, y))
        w = 0.62 * style.get("fontsize", 8) * len(text) * dpi_scale
        h = 1.1 * style.get("fontsize", 8) * dpi_scale
        left = px + dx * dpi_scale - shift * w
        bottom = py + dy * dpi_scale
        boxes = np.column_stack([left, bottom, left + w, bottom + h])  # (8, 4)
        b = placed[:n]
        ow = np.minimum(boxes[:, None, 2], b[None, :, 2]) - np.maximum(
            boxes[:, None, 0], b[None, :, 0]
        )
        oh = np.minimum(boxes[:, None, 3], b[None, :, 3]) - np.maximum(
            boxes[:, None, 1], b[None, :, 1]
        )
        hit = (np.maximum(ow, 0.0) * np.maximum(oh, 0.0)).sum(axis=1)  # (8,)
        free = np.flatnonzero(hit == 0)
        k = int(free[0]) if len(free) else int(np.argmin(hit))
        placed[n] = boxes[k]
        ax.annotate(
            text,
            (x, y),
            xytext=(dx[k], dy[k]),
            textcoords="offset points",
            ha="right" if dx[k] < 0 else ("center" if dx[k] == 0 else "left"),
            va="bottom",
            zorder=7,
            bbox=dict(boxstyle="square,pad=0.05", fc="w", ec="none", alpha=0.6),
            **MAP_TEXT,
            **style,
        )


def _draw_traverses(p: Plan, ax: Axes) -> None:
    """The total-station traverses of planned control: their legs, set-up to set-up (ids
    read as text: a district's stitched table, or one without a traverse, may hold them as
    numbers or nothing — the report of a district plan ended in AttributeError there)."""
    tr = p.stations[p.stations["purpose"].astype(str) == "traverse"]
    if tr.empty:
        return
    ids = tr["station_id"].astype(str)
    for n, (_, legs) in enumerate(tr.assign(station_id=ids).groupby(ids.str.split("-").str[0])):
        legs = legs.sort_values("station_id")
        ax.plot(
            legs["x"],
            legs["y"],
            color=COLOURS["traverse"],
            lw=1.2,
            ls="-.",
            zorder=4,
            label="traverse (planned control)" if n == 0 else None,
        )


def _draw_links(p: Plan, ax: Axes, labels: list) -> None:
    """The registrations as curved arcs between stations, dotted by targets, dashed cloud to
    cloud (to each control point used, for a station tied to the control network) — a
    relation, not a way: curved so it does not read as a line through a building —
    coloured and labelled by the link's own predicted error; the control points as black
    triangles."""
    st = p.stations.set_index("station_id")
    tg = p.targets.set_index("target_id")
    ctl = p.targets[p.targets["type"] == "control"]
    if len(ctl):
        ax.scatter(
            ctl["x"],
            ctl["y"],
            marker=MARKERS["control"],
            s=40,
            c="k",
            zorder=4,
            label="control point",
        )
        for r in ctl.itertuples():
            labels.append((r.x, r.y, r.target_id, {"fontsize": 6}))
    if not len(p.links):
        return
    worst = float(np.nanmax(p.links["link_rms_mm"])) or 1.0
    cmap = plt.get_cmap("cool")
    for r in p.links.itertuples():
        b = st.loc[r.station_b]
        if r.station_a == "control":
            ends = [tg.loc[t] for t in r.target_ids.split(";") if t in tg.index]
            style = dict(color="0.3", lw=0.8, ls="--")
        else:
            ends = [st.loc[r.station_a]]
            share = r.link_rms_mm / worst if np.isfinite(r.link_rms_mm) else 1.0
            # cloud to cloud: dashed (the scans' overlap ties them); by targets: dotted
            ls = "--" if getattr(r, "kind", "targets") == "cloud" else ":"
            style = dict(color=cmap(share), lw=1.0 + 1.5 * share, ls=ls)
        for a in ends:
            ax.add_patch(
                FancyArrowPatch(
                    (a.x, a.y),
                    (b.x, b.y),
                    connectionstyle="arc3,rad=0.25",
                    arrowstyle="-",
                    zorder=3,
                    alpha=0.9,
                    **style,
                )
            )
        if r.station_a != "control" and np.isfinite(r.link_rms_mm):
            a = ends[0]
            # the arc's middle: off the chord by a quarter of its length, to its left
            mx, my = (a.x + b.x) / 2, (a.y + b.y) / 2
            nx, ny = -(b.y - a.y) * 0.125, (b.x - a.x) * 0.125
            labels.append(
                (mx + nx, my + ny, f"{r.link_rms_mm:.1f}", {"fontsize": 6, "color": "#1b4f72"})
            )
    kinds = set(p.links["kind"]) if "kind" in p.links else {"targets"}
    if "targets" in kinds:
        ax.plot([], [], color=cmap(1.0), lw=2.5, ls=":", label="registration link (its RMS, mm)")
    if "cloud" in kinds:
        ax.plot([], [], color=cmap(1.0), lw=2.5, ls="--", label="cloud-to-cloud link (RMS, mm)")


def _draw_zones(p: Plan, ax: Axes, off: dict, f) -> None:
    """The zones outlined on the facade strips (dashed), labelled with their id."""
    for z in p.site.zones:
        if z.facade_id is not None:
            facades = [z.facade_id] if z.facade_id in off else []
        else:
            facades = [fid for fid in off if f.loc[fid, "building_id"] == z.building_id]
        for fid in facades:
            x0, length, height = off[fid], f.loc[fid, "length_m"], f.loc[fid, "height_m"]
            style = dict(fill=False, ec="#1f3a93", lw=1.3, ls="--", zorder=5)
            if z.elevation is not None:
                xy = np.asarray(z.elevation.exterior.coords) + np.array([x0, 0.0])
                ax.add_patch(MplPolygon(xy, closed=True, **style))
                label_at = (xy[:, 0].min(), xy[:, 1].max())
            else:
                a0, a1 = z.along_m or (0.0, length)
                h0, h1 = z.height_m or (0.0, height)
                ax.add_patch(Rectangle((x0 + a0, h0), a1 - a0, h1 - h0, **style))
                label_at = (x0 + a0, h1)
            ax.annotate(
                z.id,
                label_at,
                xytext=(2, 2),
                textcoords="offset points",
                fontsize=6,
                color="#1f3a93",
                zorder=6,
            )


#: Colours of an accuracy against its limit: greens at or below it (darker: better), reds
#: above it (darker: worse) — pass or fail at a glance, the same for every quantity.
PASS_FAIL = mcolors.ListedColormap(
    np.vstack(
        [
            plt.get_cmap("Greens_r")(np.linspace(0.05, 0.75, 128)),
            plt.get_cmap("Reds")(np.linspace(0.45, 1.0, 128)),
        ]
    ),
    name="pass_fail",
)


#: The gap between two facades drawn side by side (unrolled) [m].
UNROLL_GAP_M = 2.0


def facade_offsets(f: pd.DataFrame) -> dict[str, float]:
    """Where each facade (the facade table indexed by id) starts when the facades are drawn
    side by side, :data:`UNROLL_GAP_M` apart [m]."""
    offset = np.concatenate([[0.0], np.cumsum(f["length_m"].to_numpy() + UNROLL_GAP_M)[:-1]])
    return dict(zip(f.index, offset, strict=True))


def unrolled(cov: pd.DataFrame, f: pd.DataFrame, off: dict[str, float]) -> tuple:
    """Samples (coverage rows) on their facades drawn side by side: the distance along
    (plus the facade's offset) and the height above the building's base [m]."""
    row = f.loc[cov["facade_id"]]
    dx, dy = (row["x1"] - row["x0"]).to_numpy(), (row["y1"] - row["y0"]).to_numpy()
    length = np.maximum(np.hypot(dx, dy), 1e-9)
    along = (
        (cov["x"].to_numpy() - row["x0"].to_numpy()) * dx
        + (cov["y"].to_numpy() - row["y0"].to_numpy()) * dy
    ) / length
    base = row["base_z"].to_numpy() if "base_z" in row else 0.0
    return along + cov["facade_id"].map(off).to_numpy(), cov["z"].to_numpy() - base


def facade_outline(row) -> BaseGeometry:
    """A facade's shape on its elevation (``u`` along it, ``h`` above its building's base),
    from the facade table's ``outline_wkt`` (else its rectangle)."""
    text = getattr(row, "outline_wkt", "") or ""
    if text:
        return shapely.from_wkt(text)
    h0 = getattr(row, "z0", 0.0) - getattr(row, "base_z", 0.0)
    return shapely.box(0.0, h0, row.length_m, h0 + row.height_m)


def draw_outlines(ax: Axes, f: pd.DataFrame, off: dict[str, float]) -> None:
    """The facades' outlines, side by side at their offsets."""
    for row in f.itertuples():
        shape = shapely.affinity.translate(facade_outline(row), off[row.Index], 0.0)
        ax.add_patch(_patch(shape, facecolor="0.95", edgecolor="0.6", lw=0.6, zorder=0))


def pass_fail_norm(limit_mm: float) -> mcolors.TwoSlopeNorm:
    """0 → the limit on the green half, the limit → twice it on the red half (one range per
    quantity: twice its limit)."""
    return mcolors.TwoSlopeNorm(vmin=0.0, vcenter=limit_mm, vmax=2.0 * limit_mm)


def plot_coverage(p: Plan, quantity: str = "m_x_mm", ax: Axes | None = None) -> Figure:
    """The facades unrolled side by side (distance along the facades vs height), each sample
    coloured by the predicted RMS from its assigned station; unmet samples ringed red,
    party walls grey."""
    if quantity not in QUANTITIES:
        raise ValueError(f"quantity must be one of {', '.join(QUANTITIES)}")
    if ax is None:
        _, ax = plt.subplots(figsize=(11, 3.6), layout="constrained")
    fig = ax.figure
    cov = p.coverage.copy()
    f = p.facades.set_index("facade_id")
    off = facade_offsets(f)
    offset = np.array(list(off.values()))
    cov["u"], cov["z"] = unrolled(cov, f, off)  # heights above each building's base
    draw_outlines(ax, f, off)
    limit = quantity_limit(p, quantity)
    ok = cov[~cov["party_wall"]]
    sc = ax.scatter(
        ok["u"],
        ok["z"],
        c=ok[quantity],
        cmap=PASS_FAIL,
        norm=pass_fail_norm(limit),
        s=18,
        marker="s",
    )
    bar = fig.colorbar(sc, ax=ax, pad=0.01, extend="max")
    bar.set_label(f"{QUANTITIES[quantity]}: green ≤ {limit:g} mm (the limit) < red", fontsize=8)
    bar.set_ticks([0, limit / 2, limit, 1.5 * limit, 2 * limit])
    pw = cov[cov["party_wall"]]
    if len(pw):
        ax.scatter(pw["u"], pw["z"], c="0.75", s=18, marker="s", label="party wall")
    un = ok[~ok["meets"]]
    if len(un):
        ax.scatter(
            un["u"],
            un["z"],
            facecolors="none",
            edgecolors="red",
            s=40,
            lw=1.2,
            label=f"unmet ({len(un)})",
        )
    span = float(offset[-1] + f["length_m"].iloc[-1]) if len(f) else 1.0
    for fid, x0 in off.items():
        ax.axvline(x0 - 1.0, color="0.85", lw=0.8)
        # about 150 characters of 7 pt fit across the strips: a label longer than its strip
        # is turned up
        narrow = f.loc[fid, "length_m"] < len(fid) * span / 150
        ax.annotate(
            fid,
            (
                x0 + f.loc[fid, "length_m"] / 2,
                f.loc[fid, "z0"] - f.loc[fid, "base_z"] + f.loc[fid, "height_m"],
            ),
            xytext=(0, 3),
            textcoords="offset points",
            ha="left" if narrow else "center",
            va="bottom",
            rotation=60 if narrow else 0,
            rotation_mode="anchor",
            fontsize=7,
            color="0.25",
            annotation_clip=False,
        )
    low = min(0.0, float((f["z0"] - f["base_z"]).min()))
    ax.set_ylim(low, float((f["z0"] - f["base_z"] + f["height_m"]).max()) * 1.15 + 1.0)
    _draw_zones(p, ax, off, f)
    ax.set_xlabel("distance along the facades [m] (facades side by side)")
    ax.set_ylabel("height above the building's base [m]" if p.site.is_3d else "height [m]")
    if len(pw) or len(un):
        ax.legend(loc="upper right", fontsize=7)
    ax.set_title(
        f"Predicted {QUANTITIES[quantity]} at every facade sample, from its assigned station"
    )
    return fig
