"""The dashboard's one map: the site before it is planned, the plan (stations, targets,
links, route), its coverage (every facade column coloured by the quantity chosen) and the
edits by hand (stations dragged, added, deleted, locked; targets moved, added, ruled out;
buildings picked; a facade picked for a zone and its range dragged along the wall; a
passage drawn through a building) — judged again at once
(:mod:`planner.pipeline.engine.whatif`).

The map is a ``bqplot`` figure: an ipywidget (served by Voilà like any other, nothing
rendered on the server per drag, no tile server: only the site's own layers), with pan and
zoom, hover for ids and values, marks that can be dragged in the browser with their new
positions sent back in the site's coordinates, and clicks on the background that come back
as points. Matplotlib (``ipympl``) would redraw a PNG per change; ``ipyleaflet`` wants web
tiles and longitude/latitude where a survey works in its own projected grid.

No science here: the map shows what the plan holds and hands each edit to the page's
callbacks (:class:`planner.app.dashboard.StationPlanner` runs the pipeline).
"""

from __future__ import annotations

import html
import math
from collections.abc import Callable, Sequence

import anywidget
import bqplot as bq
import ipywidgets as w
import numpy as np
import pandas as pd
import shapely
import traitlets

from planner.app.maps import (
    COLOURS,
    MAP_MARGIN,
    MAP_MARGIN_M,
    QUANTITIES,
    grid_label,
    planned_area,
    quantity_label,
    quantity_limit,
    round_step,
    round_ticks,
    scale_bar_length,
    tick_decimals,
)
from planner.errors import PlannerError
from planner.pipeline.engine.result import Plan
from planner.pipeline.inputs.schema import STATION_PURPOSES, SYMBOLS
from planner.site import DEFAULT_PASSAGE_HEIGHT_M, DEFAULT_PASSAGE_WIDTH_M

__all__ = ["COLOUR_BY", "MODES", "MapView", "PlanMap", "declutter", "station_tips", "target_tips"]

#: What a click on the map does, with the hint shown while the mode is on.
MODES = [
    ("Pan / zoom", "pan", "Drag the map to pan it, turn the mouse wheel to zoom."),
    (
        "Move (drag)",
        "move",
        "Drag a station (▲) or a target to move it — a wall target slides along its wall.",
    ),
    ("Add station", "add", "Click on free ground to put a station there."),
    ("Add target", "add-target", "Click on free ground to put a sphere on a stand there."),
    (
        "Delete",
        "delete",
        "Click a station to remove it, or a target to rule it out (no link uses it again).",
    ),
    (
        "Lock / unlock",
        "lock",
        "Click a station to keep it when the rest is optimised again (Re-optimise).",
    ),
    ("Pick buildings", "pick", "Click a building to plan it or leave it out."),
    (
        "Pick a facade",
        "facade",
        "Click beside a wall to pick it for a zone (Zones, on the left); then drag the "
        "orange ends of its range along the wall.",
    ),
    (
        "Zone range",
        "range",
        "Drag the orange ends along the wall to set the zone's range (its facade is the one "
        "chosen under Zones, on the left).",
    ),
    (
        "Draw a passage",
        "passage",
        "Click on both sides of a building where a gateway goes through it under the floors "
        "(footprints do not show it): the passage joins the site.",
    ),
]

#: What the facade samples are coloured by: (label, coverage column) — met or not, or the
#: coverage plot's quantities.
COLOUR_BY = [("met / unmet", "meets"), *((quantity_label(q), q) for q in QUANTITIES)]

#: The map's plot area on screen assumed until the browser tells its size [px] (bqplot does
#: not: :class:`MapView`'s probe does).
MAP_PX = 640.0
#: The least gap between two grid lines on screen [px] (a 7-digit northing fits between).
TICK_GAP_PX = 90.0
#: A label's size on screen: per character, its height and the gap kept [px].
LABEL_CHAR_PX, LABEL_HEIGHT_PX = 7.5, 14.0

_GREEN, _YELLOW, _RED = "#1e8449", "#f4d03f", "#c0392b"

#: Outlines, labels and the lines never take a click: a click on a building reaches the map
#: (and is refused there with the reason, or picks it) instead of vanishing into the outline;
#: while a mode works with clicks on the ground, the samples let them through too.
_CSS = """<style>
.planner-map path.line, .planner-map path.area, .planner-map text.label
{ pointer-events: none; }
.planner-map.planner-map-ground g.object_grp path.dot { pointer-events: none; }
.planner-map-hint { color: #444; }
.bqplot_tooltip_div td.tooltiptext { white-space: pre-line; text-align: left; }
</style>"""

_PAN_MODES = {"pan"}
_GROUND_MODES = {"pick", "facade", "passage"}  # the click's position is what counts


def declutter(x: np.ndarray, y: np.ndarray, texts: Sequence[str], m_per_px: float) -> np.ndarray:
    """Which labels to show so that none overlaps another: each label (at its point, to
    the upper right, ``LABEL_CHAR_PX`` per character by ``LABEL_HEIGHT_PX``) is kept, in
    the order given (the first the most important), where it overlaps none kept before it.

    >>> declutter(np.array([0.0, 1.0, 50.0]), np.zeros(3), ["S01", "S02", "S03"], 0.5)
    array([ True, False,  True])
    """
    keep = np.zeros(len(texts), dtype=bool)
    boxes: list[tuple[float, float, float, float]] = []
    for k, (px, py, t) in enumerate(zip(x, y, texts, strict=True)):
        if not t or not (math.isfinite(px) and math.isfinite(py)):
            continue
        w_m = (len(t) * LABEL_CHAR_PX + 4.0) * m_per_px
        h_m = LABEL_HEIGHT_PX * m_per_px
        box = (px, py, px + w_m, py + h_m)
        if all(box[2] < b[0] or b[2] < box[0] or box[3] < b[1] or b[3] < box[1] for b in boxes):
            boxes.append(box)
            keep[k] = True
    return keep


def _rings(geoms) -> tuple[np.ndarray, np.ndarray]:
    """Outer rings of the polygons as ``(n, m)`` x and y arrays (bqplot draws one line per
    row), shorter rings padded with their closing vertex; one dummy point when none."""
    rings = [
        np.asarray(poly.exterior.coords)
        for g in geoms
        for poly in getattr(g, "geoms", [g])
        if isinstance(poly, shapely.Polygon) and not poly.is_empty
    ]
    return _rows(rings)


def _rows(lines: Sequence[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """Polylines (each ``(m, 2)``) as ``(n, m)`` x and y arrays, padded with their last
    vertex; one dummy NaN point when none."""
    if not lines:
        return np.full((1, 2), np.nan), np.full((1, 2), np.nan)
    m = max(len(r) for r in lines)
    padded = np.stack([np.vstack([r, np.repeat(r[-1:], m - len(r), axis=0)]) for r in lines])
    return padded[:, :, 0], padded[:, :, 1]


def _edited_point(before: np.ndarray, after: np.ndarray) -> np.ndarray | None:
    """Where an edit was made: the point added, or the one moved farthest."""
    if len(after) > len(before):
        return after[-1]
    if len(after) == len(before) and len(after):
        return after[int(np.argmax(np.hypot(*(after - before).T)))]
    return None


def _short(message: str) -> str:
    """The reason of a refusal in a few words for the map (the status has all of it)."""
    words = message.split(";")[0]
    for cut in (" stands ", " would stand "):
        if cut in words:
            words = words.split(cut, 1)[1]
    return words if len(words) <= 60 else words[:57] + "…"


def _nearest(xy: np.ndarray, others: np.ndarray, same: bool) -> tuple[np.ndarray, np.ndarray]:
    """For each point of ``xy``, the nearest of ``others`` (its index, -1 where none) and
    its distance [m]; ``same``: the two are one set (a point is not its own nearest)."""
    if not len(xy) or len(others) < (2 if same else 1):
        return np.full(len(xy), -1), np.full(len(xy), np.nan)
    d = np.hypot(*(xy[:, None, :] - others[None, :, :]).transpose(2, 0, 1))
    if same:
        np.fill_diagonal(d, np.inf)
    k = np.argmin(d, axis=1)
    return k, d[np.arange(len(xy)), k]


def _where(x: float, y: float) -> str:
    """A position as a crew reads it off the map's grid: easting and northing [m] to the
    centimetre, a line each."""
    return f"E {grid_label(x, 0.01)} m\nN {grid_label(y, 0.01)} m"


def station_tips(stations: pd.DataFrame) -> list[str]:
    """Each station's words on hover (a line each): its id and why it is there, where it
    stands (easting, northing), the ground's height there and the instrument's above it,
    and the nearest other station with its distance.

    >>> t = pd.DataFrame({"station_id": ["S01", "S02"], "x": [691000.0, 691030.0],
    ...     "y": [5335000.0, 5335040.0], "ground_z": [101.2, 101.5],
    ...     "instrument_height_m": [1.5, 1.6], "purpose": ["cover", "link"]})
    >>> print(station_tips(t)[0])
    S01 — to cover
    E 691 000.00 m
    N 5 335 000.00 m
    ground 101.20 m, instrument 1.50 m above it
    nearest station: S02, 50.0 m
    """
    xy = stations[["x", "y"]].to_numpy(dtype=float).reshape(-1, 2)
    ids = [str(s) for s in stations["station_id"]]
    near, dist = _nearest(xy, xy, same=True)
    out = []
    for r, k, d in zip(stations.itertuples(), near, dist, strict=True):
        purpose = STATION_PURPOSES.get(str(r.purpose), str(r.purpose))
        nearest = f"{ids[k]}, {d:.1f} m" if k >= 0 else "none (the only station)"
        out.append(
            f"{r.station_id} — {purpose}\n{_where(r.x, r.y)}\n"
            f"ground {r.ground_z:.2f} m, instrument {r.instrument_height_m:.2f} m above it\n"
            f"nearest station: {nearest}"
        )
    return out


def target_tips(targets: pd.DataFrame, stations: pd.DataFrame) -> list[str]:
    """Each target's words on hover: its id, kind and item, where it stands (easting,
    northing), its height, the stations that scan it and the nearest station with its
    distance."""
    xy = targets[["x", "y"]].to_numpy(dtype=float).reshape(-1, 2)
    sxy = stations[["x", "y"]].to_numpy(dtype=float).reshape(-1, 2)
    ids = [str(s) for s in stations["station_id"]]
    near, dist = _nearest(xy, sxy, same=False)
    out = []
    for r, k, d in zip(targets.itertuples(), near, dist, strict=True):
        item = f" ({r.item})" if isinstance(getattr(r, "item", None), str) and r.item else ""
        used = getattr(r, "station_ids", None)
        used = ", ".join(str(u) for u in used) if isinstance(used, list | tuple) else ""
        out.append(
            f"{r.target_id} — {r.type} target{item}\n{_where(r.x, r.y)}\n"
            f"centre at height {r.z:.2f} m\n"
            + (f"scanned from {used}\n" if used else "")
            + (f"nearest station: {ids[k]}, {d:.1f} m" if k >= 0 else "no station")
        )
    return out


def _columns(scanned: pd.DataFrame, quantity: str) -> pd.DataFrame:
    """One row per facade column (the samples of one place on the wall, every height): its
    position, the worst value of ``quantity`` there (an unmet sample makes the column
    unmet) and the words of its tooltip."""
    col = scanned["sample_id"].astype(str).str.rsplit("-", n=1).str[0]
    if quantity == "meets":
        g = scanned.assign(column=col, bad=~scanned["meets"]).groupby("column", sort=False)
        out = g.agg(x=("x", "first"), y=("y", "first"), unmet=("bad", "sum"), n=("bad", "size"))
        unmet = out["unmet"]
        out["value"] = (unmet > 0).astype(float)
        out["text"] = [
            f"{c}: {u} of {n} heights unmet" if u else f"{c}: all {n} heights met"
            for c, u, n in zip(out.index, unmet, out["n"], strict=True)
        ]
        return out
    unseen = ~np.isfinite(scanned[quantity].to_numpy(dtype=float))
    g = scanned.assign(column=col, unseen=unseen).groupby("column", sort=False)
    out = g.agg(
        x=("x", "first"),
        y=("y", "first"),
        value=(quantity, "max"),
        n=("x", "size"),
        unseen=("unseen", "sum"),
    )
    name = quantity_label(quantity)
    out["text"] = [
        f"{c}: {name} unseen at all {n} heights"
        if u == n
        else f"{c}: {name} {v:.2f} mm, the worst of {n - u} heights seen"
        + (f"; {u} unseen" if u else "")
        for c, v, n, u in zip(out.index, out["value"], out["n"], out["unseen"], strict=True)
    ]
    out.loc[out["unseen"] > 0, "value"] = np.nan  # (drawn as beyond the limit)
    return out


#: The browser side of :class:`_PlotSize`: every 0.3 s, the size of the plot area of the
#: map in the same box (``.planner-map-box``) as laid out on screen, sent when it changed
#: (none while the map is hidden: another tab).
_PLOT_SIZE_JS = """
function render({ model, el }) {
  let last = "";
  const look = () => {
    const box = el.closest(".planner-map-box");
    const area = box && box.querySelector(".planner-map rect.plotarea_background");
    if (!area) return;
    const r = area.getBoundingClientRect();
    if (r.width < 50 || r.height < 50) return;
    const size = [Math.round(r.width * 10) / 10, Math.round(r.height * 10) / 10];
    if (size.join("x") === last) return;
    last = size.join("x");
    model.set("plot_px", size);
    model.save_changes();
  };
  const timer = setInterval(look, 300);
  look();
  return () => clearInterval(timer);
}
export default { render };
"""


class _PlotSize(anywidget.AnyWidget):
    """The map's plot area as the browser lays it out, ``[width, height]`` [px] (empty until
    a page shows it): bqplot does not tell the kernel. Nothing on screen."""

    _esm = _PLOT_SIZE_JS
    plot_px = traitlets.List(traitlets.Float(), default_value=[]).tag(sync=True)


class MapView:
    """What the map shows, to scale: its two scales always span one number of metres per
    pixel across and up, from the plot area's size the browser reports (a frame, a resize;
    a pan or zoom keeps the ratio); grid lines at round steps (1, 2 or 5 × 10^k m, the
    printed maps' rule: :func:`~planner.app.maps.round_step`); a scale bar and a grid-north
    arrow (the map is drawn in the site's projected grid: up is grid north).

    ``on_change`` is called after every change of the view (the labels kept apart anew)."""

    def __init__(self, sx: bq.LinearScale, sy: bq.LinearScale, ax_x: bq.Axis, ax_y: bq.Axis):
        self.sx, self.sy, self.axes = sx, sy, (ax_x, ax_y)
        self.px = (MAP_PX, MAP_PX)  # the plot area [px] (until the browser tells)
        self.box: tuple[float, float, float, float] | None = None  # framed, not panned since
        self.on_change: Callable[[], None] = lambda: None
        self._ours = False  # the scales are being set here (not panned or zoomed)
        self.probe = _PlotSize(layout=w.Layout(display="none"))
        self._marks_made()
        self._draw_north()
        self.probe.observe(lambda _c: self._resized(), names=["plot_px"])
        for scale in (sx, sy):  # (a pan or zoom sets min and max at once: max is enough)
            scale.observe(lambda _c: self._moved(), names=["max"])

    def _marks_made(self) -> None:
        """The scale bar (lower left) and the north arrow (upper right), placed in fractions
        of the plot area: a pan or zoom does not move them."""
        frac = {axis: bq.LinearScale(min=0.0, max=1.0, allow_padding=False) for axis in ("x", "y")}
        nan2 = np.full((1, 2), np.nan)
        self.bar_ground = bq.Lines(  # a white ground under the bar and its words
            x=nan2,
            y=nan2,
            scales=frac,
            fill="inside",
            colors=["#ffffffcc"],
            fill_colors=["white"],
            fill_opacities=[0.8],
            stroke_width=0,
        )
        self.bar = bq.Lines(x=nan2, y=nan2, scales=frac, colors=["black"], stroke_width=2)
        self.bar_label = bq.Label(
            x=[],
            y=[],
            text=[],
            scales=frac,
            colors=["black"],
            default_size=12,
            align="middle",
            y_offset=-9,
        )
        self.north = bq.Lines(
            x=nan2,
            y=nan2,
            scales=frac,
            colors=["black"],
            fill="inside",
            fill_colors=["black", "black"],
            stroke_width=2,
        )
        self.north_label = bq.Label(
            x=[],
            y=[],
            text=[],
            scales=frac,
            colors=["black"],
            default_size=14,
            font_weight="bold",
            align="middle",
            y_offset=-6,
        )
        self.marks = [self.bar_ground, self.bar, self.bar_label, self.north, self.north_label]

    def m_per_px(self) -> float:
        """Metres per pixel on screen, across and up alike."""
        if self.sx.min is None or self.sx.max is None:
            return 0.1
        return float(self.sx.max - self.sx.min) / self.px[0]

    def frame(self, bounds: Sequence[float], least_m: float = 40.0) -> None:
        """Show ``bounds`` (x0, y0, x1, y1 [m]) whole with a margin (the printed maps'), at
        least ``least_m`` across: the largest scale that holds it on the plot area."""
        x0, y0, x1, y1 = (float(v) for v in bounds)
        pad = max(MAP_MARGIN * max(x1 - x0, y1 - y0), MAP_MARGIN_M)
        half = max((x1 - x0) / 2 + pad, least_m / 2), max((y1 - y0) / 2 + pad, least_m / 2)
        self.box = ((x0 + x1) / 2 - half[0], (y0 + y1) / 2 - half[1])
        self.box += ((x0 + x1) / 2 + half[0], (y0 + y1) / 2 + half[1])
        self._fit_box()

    def _fit_box(self) -> None:
        bx0, by0, bx1, by1 = self.box
        w_px, h_px = self.px
        self._show((bx0 + bx1) / 2, (by0 + by1) / 2, max((bx1 - bx0) / w_px, (by1 - by0) / h_px))

    def _show(self, x: float, y: float, m_per_px: float) -> None:
        """Centre the view on (x, y) at ``m_per_px`` across and up."""
        half_x, half_y = m_per_px * self.px[0] / 2, m_per_px * self.px[1] / 2
        self._ours = True
        try:
            with self.sx.hold_sync(), self.sy.hold_sync():
                self.sy.min, self.sy.max = float(y - half_y), float(y + half_y)
                self.sx.min, self.sx.max = float(x - half_x), float(x + half_x)
        finally:
            self._ours = False
        self._drawn()

    def _moved(self) -> None:
        if self._ours:
            return
        self.box = None  # panned or zoomed in the browser: a resize keeps its scale
        self._drawn()

    def _resized(self) -> None:
        """The plot area changed size on screen: the box framed is framed again; a view
        panned or zoomed keeps its centre and scale (more or less of it shows)."""
        size = self.probe.plot_px
        if len(size) != 2 or min(size) <= 0:
            return
        old, self.px = self.px, (float(size[0]), float(size[1]))
        self._draw_north()  # (its pixels, in the new fractions)
        if self.box is not None:
            self._fit_box()
        elif self.sx.min is not None and self.sy.min is not None:
            mx = (self.sx.max - self.sx.min) / old[0]
            my = (self.sy.max - self.sy.min) / old[1]
            cx, cy = (self.sx.min + self.sx.max) / 2, (self.sy.min + self.sy.max) / 2
            self._show(cx, cy, math.sqrt(mx * my))

    def _drawn(self) -> None:
        """The grid and the scale bar for the view shown; then ``on_change``."""
        if None in (self.sx.min, self.sx.max, self.sy.min, self.sy.max):
            return
        step = round_step(self.m_per_px() * TICK_GAP_PX)
        for axis, scale in zip(self.axes, (self.sx, self.sy), strict=True):
            with axis.hold_sync():
                axis.tick_values = round_ticks(scale.min, scale.max, step)
                axis.tick_format = f".{tick_decimals(step)}f"
        span = float(self.sx.max - self.sx.min)
        length = scale_bar_length(span)
        self._draw_bar(length / span, f"{length:g} m")
        self.on_change()

    def _draw_bar(self, share: float, words: str) -> None:
        """The scale bar, ``share`` of the plot's width, its length in ``words``."""
        px_x, px_y = 1.0 / self.px[0], 1.0 / self.px[1]  # a pixel, in fractions
        x0, y0 = 14 * px_x, 14 * px_y
        x1, tick = x0 + share, 5 * px_y
        ground = np.array([[x0 - 8 * px_x, y0 - 6 * px_y], [x1 + 8 * px_x, y0 + 26 * px_y]])
        with self.bar_ground.hold_sync():
            self.bar_ground.x = [ground[[0, 1, 1, 0, 0], 0]]
            self.bar_ground.y = [ground[[0, 0, 1, 1, 0], 1]]
        with self.bar.hold_sync():  # the bar with its two end ticks
            self.bar.x = [[x0, x0, x1, x1]]
            self.bar.y = [[y0 + tick, y0, y0, y0 + tick]]
        with self.bar_label.hold_sync():
            self.bar_label.x, self.bar_label.y = [(x0 + x1) / 2], [y0 + tick]
            self.bar_label.text = [words]

    def _draw_north(self) -> None:
        """An arrow up (grid north) with its N, near the upper right corner (below the
        figure's own toolbar)."""
        px_x, px_y = 1.0 / self.px[0], 1.0 / self.px[1]
        x, y0, y1 = 1.0 - 26 * px_x, 1.0 - 100 * px_y, 1.0 - 58 * px_y
        head_w, head_h = 6 * px_x, 14 * px_y
        with self.north.hold_sync():  # the shaft, then the head (a filled triangle)
            self.north.x = [[x, x, x, x], [x - head_w, x, x + head_w, x - head_w]]
            self.north.y = [
                [y0, y1 - head_h, y1 - head_h, y0],
                [y1 - head_h, y1, y1 - head_h, y1 - head_h],
            ]
        with self.north_label.hold_sync():
            self.north_label.x, self.north_label.y, self.north_label.text = [x], [y1], ["N"]


class PlanMap:
    """The site, the plan and its coverage on one interactive map, and every edit by hand.

    The page gives the callbacks that run the pipeline: ``evaluate(xy, ids)``,
    ``reoptimise(locked_xy)``, ``edit_targets(remove=, move=, add_xy=)``; and, set after,
    ``on_pick(building_id)``, ``on_facade(facade_id)``, ``on_range_dragged(from_m, to_m)``
    and ``on_passage(xy0, xy1)``. Edits need a plan on the map: without one (a new site
    drawn) they are refused, saying so. This class only holds the map, the modes and the marks."""

    def __init__(
        self,
        evaluate: Callable[[np.ndarray, list[str | None]], None],
        reoptimise: Callable[[np.ndarray], None],
        edit_targets: Callable[..., None],
    ) -> None:
        self._evaluate, self._reoptimise, self._edit_targets = evaluate, reoptimise, edit_targets
        self.on_pick: Callable[[str], None] = lambda _id: None
        self.on_facade: Callable[[str], None] = lambda _id: None
        self.on_range_dragged: Callable[[float, float], None] = lambda _a, _b: None
        self.on_passage: Callable[[np.ndarray, np.ndarray], None] = lambda _a, _b: None
        # (no padding: the plot area's pixels are the scales' whole range, as MapView counts)
        self.sx, self.sy = bq.LinearScale(allow_padding=False), bq.LinearScale(allow_padding=False)
        self._site_marks()
        self._plan_marks_made()
        self._label_marks()
        self.figure = self._figure()
        self._controls()
        self._reset_state()
        self._wire()
        self.widget = self._lay_out()
        self._set_mode()

    def _lines(self, **kw) -> bq.Lines:
        nan2 = np.full((1, 2), np.nan)
        return bq.Lines(x=nan2, y=nan2, scales={"x": self.sx, "y": self.sy}, **kw)

    def _dots(self, **kw) -> bq.Scatter:
        sc = {"x": self.sx, "y": self.sy}
        return bq.Scatter(**{"x": [], "y": [], "scales": sc, "display_names": False, **kw})

    def _site_marks(self) -> None:
        """The site's marks: buildings, roofs, passages, problems, zones, the picks, and
        the marks the modes draw with (the zone range's handles, a passage's start, the
        ground's clicks)."""
        self.others = self._lines(fill="inside", colors=["#bbb"], stroke_width=1)
        self.buildings = self._lines(fill="inside", colors=["#555"], stroke_width=1)
        # a 3-D building's roof: its edges and ridges over the footprint
        self.roofs = self._lines(colors=["#a9a9a9"], stroke_width=0.6)
        self.passages = self._lines(
            colors=[COLOURS["passage"]], line_style="dashed", stroke_width=2
        )
        self.problems = self._lines(
            colors=["#c0392b"], stroke_width=3
        )  # features that stop the plan
        self.zone_lines = self._lines(colors=["#7d3c98"], stroke_width=5)  # the zones added
        self.facade_line = self._lines(colors=["#e67e22"], stroke_width=6)  # the facade picked
        self.picks = self._dots(  # each building's centre: its id on hover
            marker="square",
            colors=["white"],
            stroke="#333",
            default_size=16,  # (smaller than a target's mark: never mistaken for one)
            tooltip=bq.Tooltip(fields=["name"], labels=["building"]),
        )
        self.marked = self._dots(  # where a site problem is (red crosses)
            marker="cross",
            colors=["#c0392b"],
            default_size=90,
            tooltip=bq.Tooltip(fields=["name"], labels=["problem"]),
        )
        self.repaired = self._dots(  # where the site was repaired (site_repairs.csv)
            marker="diamond",
            colors=["#d4ac0d"],
            stroke="#7d6608",
            default_size=40,
            tooltip=bq.Tooltip(fields=["name"], labels=["repaired"]),
        )
        self.handles = self._dots(  # the zone range's ends, dragged along the facade
            marker="circle",
            colors=["#e67e22"],
            stroke="black",
            default_size=110,
            visible=False,
        )
        self.draft = self._dots(
            marker="cross", colors=["#d4ac0d"], default_size=120
        )  # passage start
        self.catch = self._dots(  # clicks on the ground in the modes that want their position
            marker="circle", colors=["#00000000"], default_size=1, interactions={"click": "add"}
        )

    def _plan_marks_made(self) -> None:
        """The plan's marks: route, links, candidates, samples, targets, stations."""
        sc = {"x": self.sx, "y": self.sy}
        self.route = self._lines(colors=[COLOURS["route"]], line_style="dashed", stroke_width=1.5)
        self.target_links = self._lines(colors=["#c71585"], line_style="dotted", stroke_width=2)
        self.cloud_links = self._lines(colors=["#c71585"], line_style="dashed", stroke_width=2)
        self.candidates = self._dots(
            marker="square",
            default_size=10,
            stroke=None,
            scales={**sc, "color": bq.ColorScale(colors=["#d6eaf8", "#1b4f72"])},
            tooltip=bq.Tooltip(fields=["name"], labels=["candidate"]),
            visible=False,
        )
        self.colour_scale = bq.ColorScale(min=0, max=1, colors=[_GREEN, _RED])
        self.samples = self._dots(
            color=[],
            scales={**sc, "color": self.colour_scale},
            default_size=14,
            stroke=None,
            tooltip=bq.Tooltip(fields=["name"], labels=["facade"]),
        )
        self.target_marks = {}
        for kind, colour in (("flat", "#8e44ad"), ("sphere", "#8e44ad"), ("control", "#17202a")):
            self.target_marks[kind] = self._dots(
                marker=SYMBOLS[kind],
                colors=[colour],
                stroke="white",
                default_size=60,
                tooltip=bq.Tooltip(fields=["name"], labels=[f"{kind} target"]),
            )
        self.stations = self._dots(
            names=[],
            marker=SYMBOLS["station"],
            colors=[COLOURS["hand"]],
            stroke="black",
            default_size=140,
            enable_move=True,
            tooltip=bq.Tooltip(fields=["name"], labels=["station"]),
        )

    def _label_marks(self) -> None:
        """Station and building labels, the notice of a refused click, the colour axis."""
        self.labels = bq.Label(
            x=[],
            y=[],
            text=[],
            scales={"x": self.sx, "y": self.sy},
            colors=["black"],
            default_size=12,
            x_offset=8,
            y_offset=-8,
        )
        self.building_labels = bq.Label(
            x=[],
            y=[],
            text=[],
            scales={"x": self.sx, "y": self.sy},
            colors=["#17202a"],
            default_size=11,
            x_offset=6,
            y_offset=-4,
        )
        self.notice = bq.Label(  # why a click was refused, where it was made
            x=[],
            y=[],
            text=[],
            scales={"x": self.sx, "y": self.sy},
            colors=["#922b21"],
            default_size=13,
            font_weight="bold",
            x_offset=10,
            y_offset=-10,
        )
        self.colour_axis = bq.ColorAxis(
            scale=self.colour_scale, orientation="vertical", side="right", label="", visible=False
        )

    def _figure(self) -> bq.Figure:
        """The map's figure with its axes, every mark in drawing order, and pan and zoom."""
        ax_x = bq.Axis(scale=self.sx, label="E [m]", tick_format=".0f")
        ax_y = bq.Axis(
            scale=self.sy,
            label="N [m]",
            orientation="vertical",
            tick_format=".0f",
            label_offset="65px",
        )
        axes = [ax_x, ax_y, self.colour_axis]
        self.view = MapView(self.sx, self.sy, ax_x, ax_y)
        self._plan_marks = [
            self.route,
            self.target_links,
            self.cloud_links,
            self.samples,
            self.stations,
            self.labels,
            *self.target_marks.values(),
        ]
        figure = bq.Figure(
            marks=[
                self.others,
                self.buildings,
                self.roofs,
                self.passages,
                self.problems,
                self.candidates,
                self.zone_lines,
                self.facade_line,
                self.route,
                self.target_links,
                self.cloud_links,
                self.samples,
                self.picks,
                self.marked,
                self.repaired,
                *self.target_marks.values(),
                self.stations,
                self.handles,
                self.draft,
                self.catch,
                self.building_labels,
                self.labels,
                self.notice,
                *self.view.marks,  # the scale bar and the north arrow, over everything
            ],
            axes=axes,
            padding_x=0,
            padding_y=0,
            fig_margin={"top": 10, "bottom": 45, "left": 80, "right": 70},
            # the map grows with the window, never below a usable size; a metre as long
            # across as up whatever its shape (MapView)
            layout=w.Layout(width="100%", height="calc(100vh - 240px)", min_height="460px"),
        )
        figure.add_class("planner-map")
        self.panzoom = bq.interacts.PanZoom(scales={"x": [self.sx], "y": [self.sy]})
        return figure

    def _controls(self) -> None:
        """The modes, view buttons, layer switches, passage options, status and legend."""
        self.mode = w.ToggleButtons(
            options=[(label, key) for label, key, _ in MODES],
            value="move",
            description="Click to",
            tooltips=[hint for _, _, hint in MODES],
            style={"button_width": "auto"},
        )
        self.hint = w.HTML("")
        self.hint.add_class("planner-map-hint")
        self.fit = w.Button(description="Fit to the plan", icon="expand")
        self.whole = w.Button(description="Whole site")
        self.reopt = w.Button(description="Re-optimise around the locked", icon="refresh")
        for button in (self.fit, self.whole, self.reopt):
            button.layout.width = "auto"
        self.colour_by = w.Dropdown(
            options=COLOUR_BY,
            value="meets",
            description="Colour samples by",
            style={"description_width": "initial"},
            layout=w.Layout(width="18em"),
        )
        self.show_links = w.Checkbox(value=True, description="links", indent=False)
        self.show_route = w.Checkbox(value=True, description="route", indent=False)
        self.show_candidates = w.Checkbox(value=False, description="candidates", indent=False)
        for box in (self.show_links, self.show_route, self.show_candidates):
            box.layout.width = "8em"
        narrow = {"style": {"description_width": "initial"}, "layout": w.Layout(width="15em")}
        self.passage_width = w.BoundedFloatText(
            value=DEFAULT_PASSAGE_WIDTH_M,
            min=0.5,
            max=30.0,
            step=0.5,
            description="passage width [m]",
            **narrow,
        )
        self.passage_height = w.BoundedFloatText(
            value=DEFAULT_PASSAGE_HEIGHT_M,
            min=1.0,
            max=20.0,
            step=0.5,
            description="clear height [m]",
            **narrow,
        )
        self.clear_passages = w.Button(
            description="Remove the passages drawn", layout=w.Layout(width="auto")
        )
        self.passage_box = w.HBox([self.passage_width, self.passage_height, self.clear_passages])
        self.passage_box.layout.display = "none"
        # room for three lines: a longer status never pushes the map down under the cursor
        self.status = w.HTML("", layout=w.Layout(min_height="4.6em"))
        self.status.add_class("planner-map-status")
        self.legend = w.HTML(_legend())

    def _reset_state(self) -> None:
        """Nothing drawn yet: no site, no plan, no edits."""
        self._framed = None  # the site the map's view was fitted to (kept through edits)
        self._framed_ids: set[str] = set()  # its buildings (the same site read again)
        self._site = None
        self._plan: Plan | None = None
        self._cand_shown = None  # the candidates table on the map (sent once per plan)
        self._pick_ids: list[str] = []
        self._facades: tuple[list[str], np.ndarray, np.ndarray] = (
            [],
            np.empty((0, 2)),
            np.empty((0, 2)),
        )
        self._facade = ""  # the facade picked for a zone
        self._first: np.ndarray | None = None  # a passage's first click
        self.locked: list[bool] = []
        self._xy = np.empty((0, 2))
        self._ids: list[str | None] = []  # the station each position is (None: added)
        self._purposes: list[str] = []
        self._targets: dict[str, tuple[list[str], np.ndarray]] = {
            kind: ([], np.empty((0, 2))) for kind in self.target_marks
        }
        self._target_tips: dict[str, list[str]] = {}  # the words on hover, by kind
        self._quiet = False

    def _wire(self) -> None:
        """The marks' and controls' events to their handlers."""
        self.mode.observe(lambda _c: self._set_mode(), "value")
        self.stations.on_drag_end(lambda _m, e: self._dragged(e))
        self.stations.on_element_click(lambda _m, e: self._clicked(e))
        self.stations.observe(lambda _c: self._maybe_added(), names=["x"])
        for kind, mark in self.target_marks.items():
            mark.on_drag_end(lambda _m, e, k=kind: self._target_dragged(k, e))
            mark.on_element_click(lambda _m, e, k=kind: self._target_clicked(k, e))
            mark.observe(lambda _c, k=kind: self._maybe_target_added(k), names=["x"])
        self.catch.observe(lambda _c: self._ground_clicked(), names=["x"])
        self.handles.on_drag_end(lambda _m, e: self._handle_dragged(e))
        self.fit.on_click(lambda _b: self.fit_view())
        self.whole.on_click(lambda _b: self.whole_view())
        self.reopt.on_click(lambda _b: self._reoptimise_locked())
        self.colour_by.observe(lambda _c: self._draw_samples(), "value")
        self.show_links.observe(lambda _c: self._layers(), "value")
        self.show_route.observe(lambda _c: self._layers(), "value")
        self.show_candidates.observe(lambda _c: self._layers(), "value")
        # after every view change: a pan, a zoom, a frame, the window resized
        self.view.on_change = self._draw_labels

    def _lay_out(self) -> w.VBox:
        box = w.VBox(
            [
                w.HTML(_CSS),
                self.mode,
                self.hint,
                self.passage_box,
                w.HBox(
                    [
                        self.fit,
                        self.whole,
                        self.reopt,
                        self.colour_by,
                        self.show_links,
                        self.show_route,
                        self.show_candidates,
                    ],
                    layout=w.Layout(flex_flow="row wrap", align_items="center"),
                ),
                self.status,
                self.figure,
                self.view.probe,
                self.legend,
            ]
        )
        box.add_class("planner-map-box")  # (the probe measures the figure in it)
        return box

    # -- showing a site and a plan -------------------------------------------------------------
    def _draw_site(self, site, heights_known: bool = True) -> None:
        """Buildings (planned dark, others light), obstacles, passages, the buildings' ids
        (with their heights where ``heights_known``; the problems marked are the previous
        site's: cleared)."""
        self._site = site
        xs, ys = _rings(b.footprint for b in site.planned)
        self.buildings.x, self.buildings.y = xs, ys
        others = [b.footprint for b in site.buildings if not b.planned]
        others += [o.geometry for o in site.obstacles]
        xs, ys = _rings(others)
        self.others.x, self.others.y = xs, ys
        xs, ys = _rings(a.geometry for a in site.passages)
        self.passages.x, self.passages.y = xs, ys
        roof = [s.rings[0][:, :2] for b in site.buildings for s in b.surfaces if s.kind == "roof"]
        self.roofs.x, self.roofs.y = _rows([np.vstack([r, r[:1]]) for r in roof])
        centres = [b.footprint.representative_point() for b in site.buildings]
        self._pick_ids = [b.id for b in site.buildings]
        with self.picks.hold_sync():
            self.picks.x = [c.x for c in centres]
            self.picks.y = [c.y for c in centres]
            self.picks.names = [
                f"{b.id} ({f'{round(b.height_m, 1):g} m' if heights_known else 'as drawn'}"
                f"{'' if b.planned else ', not planned'})"
                for b in site.buildings
            ]
        self.mark_problems([], [])
        self.mark_repairs([])
        self._draw_labels()

    def show_site(
        self, site, message: str = "", keep_plan: bool = False, heights_known: bool = True
    ) -> None:
        """Draw a site before it is planned: its buildings with their ids (a click on one in
        "Pick buildings" mode plans the building or leaves it out), nothing planned yet — or,
        with ``keep_plan`` (the same buildings: one picked, a passage drawn), the plan on the
        map kept, dimmed: it is out of date."""
        if keep_plan and self._plan is not None:
            self._draw_site(site, heights_known)
            self.set_stale(True)  # (the view stays the plan's)
            self.status.value = message
            return
        self._plan = None
        self._draw_site(site, heights_known)
        self.show_site_marks_cleared()
        self.set_stale(False)
        self._say_at(None)
        ids = {b.id for b in site.buildings}
        if ids != self._framed_ids:  # a new site is framed whole; the same one keeps the view
            self.whole_view()
        self._framed, self._framed_ids = site, ids
        n = len(site.planned)
        self.status.value = message or (
            f"The site: {len(site.buildings)} buildings, {n} to plan (dark). <b>Pick "
            "buildings</b>, then click a building to plan it or leave it out; "
            "<b>Plan</b> places the stations."
        )
        self._draw_labels()

    def show_outlines(self, outlines: Sequence[tuple[str, str, object]], message: str) -> None:
        """A site file's outlines as drawn, ``(id, role, geometry)`` (the file cannot be
        read into a site): light, their ids on them; nothing can be picked or planned."""
        self.show_nothing(message)
        polygons = [(i, g) for i, _r, g in outlines if g.geom_type in ("Polygon", "MultiPolygon")]
        xs, ys = _rings([g for _, g in polygons])
        self.others.x, self.others.y = xs, ys
        xs, ys = _rows(
            [shapely.get_coordinates(g) for _, _r, g in outlines if "Line" in g.geom_type]
        )
        self.passages.x, self.passages.y = xs, ys
        spots = [g.representative_point() for _, g in polygons]
        self._pick_ids = [i for i, _ in polygons]
        with self.picks.hold_sync():
            self.picks.x, self.picks.y = [q.x for q in spots], [q.y for q in spots]
            self.picks.names = [f"{i} (as drawn in the file)" for i, _ in polygons]
        self._frame_points([shapely.get_coordinates(g) for _, _r, g in outlines])
        self._draw_labels()

    def show_nothing(self, message: str) -> None:
        """No site to draw (it cannot be read): an empty map and why."""
        self._site, self._plan, self._framed, self._framed_ids = None, None, None, set()
        nan2 = np.full((1, 2), np.nan)
        for mark in (self.buildings, self.others, self.passages, self.problems, self.zone_lines):
            mark.x, mark.y = nan2, nan2
        self._pick_ids = []
        self.picks.x, self.picks.y, self.picks.names = [], [], []
        self.repaired.x, self.repaired.y = [], []
        self.show_facades([], np.empty((0, 2)), np.empty((0, 2)))
        self._first = None
        self.draft.x, self.draft.y = [], []
        self._say_at(None)
        self.show_site_marks_cleared()
        self.building_labels.x, self.building_labels.y, self.building_labels.text = [], [], []
        self.status.value = message

    def show_site_marks_cleared(self) -> None:
        """Nothing of a plan on the map."""
        self._quiet = True
        self.samples.x, self.samples.y, self.samples.color = [], [], []
        self._xy, self._ids, self.locked, self._purposes = np.empty((0, 2)), [], [], []
        self._targets = {k: ([], np.empty((0, 2))) for k in self.target_marks}
        self._target_tips = {}
        with self.stations.hold_sync():
            self.stations.x, self.stations.y, self.stations.names = [], [], []
        for mark in (self.route, self.target_links, self.cloud_links):
            mark.x, mark.y = np.full((1, 2), np.nan), np.full((1, 2), np.nan)
        self.candidates.x, self.candidates.y = [], []
        self._cand_shown = None
        self.marked.x, self.marked.y = [], []
        self._draw_targets()
        self._quiet = False
        self._draw_labels()

    def mark_problems(self, geoms: Sequence, notes: Sequence[tuple[float, float, str]]) -> None:
        """Outline the features that stop the plan (``geoms``, red) and cross the places of
        ``notes`` (x, y, what is wrong there; its words on hover)."""
        xs, ys = _rings(geoms)
        self.problems.x, self.problems.y = xs, ys
        _place(self.marked, notes)

    def mark_repairs(self, notes: Sequence[tuple[float, float, str]]) -> None:
        """The places the site was repaired or a problem let pass (x, y, what was done;
        its words on hover): not problems — the plan goes ahead."""
        _place(self.repaired, notes)

    def show_plan(self, p: Plan, message: str = "", stale: bool = False) -> None:
        """Draw ``p``: site, samples, links, route, targets, stations (locks kept by
        position). ``stale``: the inputs changed since ``p`` was made (an edit by hand of an
        out-of-date plan) — the site drawn stays the inputs', the plan's marks dimmed."""
        old = {tuple(np.round(xy, 3)): lk for xy, lk in zip(self._xy, self.locked, strict=True)}
        self._plan = p
        if not (stale and self._site is not None):
            self._draw_site(p.site)
        self._draw_samples()
        self._targets, self._target_tips = {}, {}
        for kind in self.target_marks:
            rows = p.targets[p.targets["type"] == kind]
            self._targets[kind] = (
                [str(t) for t in rows["target_id"]],
                rows[["x", "y"]].to_numpy(dtype=float).reshape(-1, 2),
            )
            self._target_tips[kind] = target_tips(rows, p.scan_stations)
        scans = p.scan_stations  # (a traverse's set-ups are planned with the network)
        xy = scans[["x", "y"]].to_numpy(dtype=float)
        self._xy = xy
        self._ids = [str(s) for s in scans["station_id"]]
        self._purposes = [str(s) for s in scans["purpose"]]
        self.locked = [old.get(tuple(np.round(q, 3)), False) for q in xy]
        self._quiet = True
        with self.stations.hold_sync():
            self.stations.x, self.stations.y = xy[:, 0], xy[:, 1]
            self.stations.names = station_tips(scans)  # (id, purpose, E, N, heights, nearest)
            self.stations.colors = [COLOURS.get(pu, COLOURS["hand"]) for pu in self._purposes]
        self._draw_targets()
        self._quiet = False
        self._draw_links(p)
        self._draw_candidates()
        self.set_stale(stale)
        self._say_at(None)
        if self._framed is not p.site:  # a new plan is framed; an edit keeps the view
            self.fit_view()
            self._framed, self._framed_ids = p.site, {b.id for b in p.site.buildings}
        self._draw_labels()
        self.status.value = message  # a status never outlives what it describes

    def _draw_samples(self) -> None:
        """The facade columns coloured by the quantity chosen (the worst of their heights),
        its value on hover."""
        p = self._plan
        if p is None:
            return
        quantity = self.colour_by.value
        cols = _columns(p.scanned, quantity)
        if quantity == "meets":
            self.colour_scale.min, self.colour_scale.max, self.colour_scale.mid = 0.0, 1.0, None
            self.colour_scale.colors = [_GREEN, _RED]
            self.colour_axis.visible = False
        else:  # green to the site-wide limit, red beyond (as the coverage plot)
            limit = quantity_limit(p, quantity)
            self.colour_scale.min, self.colour_scale.mid = 0.0, limit
            self.colour_scale.max = 2.0 * limit
            self.colour_scale.colors = [_GREEN, _YELLOW, _RED]
            self.colour_axis.label = QUANTITIES[quantity]
            self.colour_axis.visible = True
        with self.samples.hold_sync():
            self.samples.x, self.samples.y = cols["x"].to_numpy(), cols["y"].to_numpy()
            self.samples.color = np.nan_to_num(cols["value"].to_numpy(dtype=float), nan=2e3)
            self.samples.names = cols["text"].tolist()

    def _draw_links(self, p: Plan) -> None:
        at = dict(zip(p.stations["station_id"], p.stations[["x", "y"]].to_numpy(), strict=True))
        for kind, mark in (("targets", self.target_links), ("cloud", self.cloud_links)):
            rows = p.links[p.links["kind"] == kind] if "kind" in p.links else p.links[:0]
            segs = [
                np.array([at[a], at[b]])
                for a, b in zip(rows["station_a"], rows["station_b"], strict=True)
                if a in at and b in at
            ]
            mark.x, mark.y = _rows(segs)
        legs = []
        if p.route is not None and len(p.route.legs):
            legs = [np.asarray(leg, dtype=float).reshape(-1, 2) for leg in p.route.legs]
        self.route.x, self.route.y = _rows([g for g in legs if len(g) > 1])
        self._layers()

    def _draw_candidates(self) -> None:
        """The candidate grid coloured by the samples each meets — sent to the browser only
        while shown, and once per plan (an edit by hand keeps its plan's grid)."""
        cand = self._plan.candidates if self._plan is not None else None
        shown = self._cand_shown
        if not self.show_candidates.value or cand is None:
            return
        if shown is not None and (cand is shown or cand.equals(shown)):
            return
        self._cand_shown = cand
        with self.candidates.hold_sync():
            self.candidates.x, self.candidates.y = cand["x"].to_numpy(), cand["y"].to_numpy()
            self.candidates.color = cand["samples_met"].to_numpy(dtype=float)
            self.candidates.names = [f"meets {int(n)} samples" for n in cand["samples_met"]]

    def _layers(self) -> None:
        self.target_links.visible = self.cloud_links.visible = self.show_links.value
        self.route.visible = self.show_route.value
        self.candidates.visible = self.show_candidates.value
        self._draw_candidates()

    def set_stale(self, stale: bool) -> None:
        """Dim the plan's marks (the inputs changed since it was made); the site stays as
        drawn (it is the inputs')."""
        for mark in self._plan_marks:
            mark.opacities = [0.3] if stale else [1.0]

    def fit_view(self) -> None:
        """Frame the planned buildings, the stations and the targets (the area the printed
        maps frame: :func:`~planner.app.maps.planned_area`)."""
        pts = [self._xy, *(xy for _ids, xy in self._targets.values())]
        if self._site is not None:
            self.view.frame(planned_area(self._site, *pts))
        else:
            self._frame_points(pts)

    def whole_view(self) -> None:
        """Frame every building of the site, and the plan's stations and targets."""
        if self._site is None:
            return
        pts = [shapely.get_coordinates(b.footprint) for b in self._site.buildings]
        self._frame_points([*pts, self._xy, *(xy for _ids, xy in self._targets.values())])

    def _frame_points(self, pts: list[np.ndarray]) -> None:
        pts = [q for q in pts if len(q)]
        if pts:
            allxy = np.vstack(pts)
            self.view.frame((*allxy.min(axis=0), *allxy.max(axis=0)))

    def _m_per_px(self) -> float:
        return self.view.m_per_px()

    def _draw_labels(self) -> None:
        """Station ids (a lock shown) and building ids where they do not pile up — the ids
        of those left out on hover; zooming in shows them."""
        m = self._m_per_px()
        st = [f"{s} 🔒" if lk else str(s) for s, lk in zip(self._ids, self.locked, strict=True)]
        xy = self._xy
        keep = declutter(xy[:, 0], xy[:, 1], st, m) if len(xy) else np.zeros(0, bool)
        with self.labels.hold_sync():
            self.labels.x, self.labels.y = xy[keep, 0], xy[keep, 1]
            self.labels.text = [t for t, k in zip(st, keep, strict=True) if k]
        bx = np.asarray(self.picks.x, dtype=float)
        by = np.asarray(self.picks.y, dtype=float)
        names = list(self._pick_ids)
        # a building label is kept clear of the station labels shown
        allx = np.concatenate([xy[keep, 0], bx])
        ally = np.concatenate([xy[keep, 1], by])
        both = declutter(allx, ally, [*self.labels.text, *names], m)[int(keep.sum()) :]
        with self.building_labels.hold_sync():
            self.building_labels.x, self.building_labels.y = bx[both], by[both]
            self.building_labels.text = [t for t, k in zip(names, both, strict=True) if k]

    # -- modes -----------------------------------------------------------------------------------
    def locked_xy(self) -> np.ndarray:
        """The positions ``(k, 2)`` [m] of the stations locked on the map."""
        return self._xy[np.asarray(self.locked, bool)].reshape(-1, 2)

    def _reoptimise_locked(self) -> None:
        if not self._no_plan("re-optimised"):
            self._reoptimise(self.locked_xy())

    def _set_mode(self) -> None:
        mode = self.mode.value
        self.hint.value = (
            "<small>"
            + html.escape(next(h for _, k, h in MODES if k == mode))
            + " Hover over a mark for its id and values.</small>"
        )
        self.figure.interaction = self.panzoom if mode in _PAN_MODES else None
        moving = mode == "move"
        self.stations.enable_move = moving
        for mark in self.target_marks.values():
            mark.enable_move = moving
        self.stations.interactions = {"click": "add"} if mode == "add" else {"hover": "tooltip"}
        self.target_marks["sphere"].interactions = (
            {"click": "add"} if mode == "add-target" else {"hover": "tooltip"}
        )
        self.catch.interactions = {"click": "add"} if mode in _GROUND_MODES else {}
        if mode in _GROUND_MODES:
            self.figure.add_class("planner-map-ground")
        else:
            self.figure.remove_class("planner-map-ground")
        ranging = mode == "range" and bool(self._facade)
        self.handles.visible = self.handles.enable_move = ranging
        self.facade_line.visible = mode in ("range", "facade") and bool(self._facade)
        self.passage_box.layout.display = "flex" if mode == "passage" else "none"
        if mode != "passage":
            self._first = None
            self.draft.x, self.draft.y = [], []

    def _ground_clicked(self) -> None:
        """A click on the ground in a mode that wants its position (the catcher scatter took
        it as a point): pick the building or facade there, or draw a passage's end."""
        if self._quiet or not len(self.catch.x) or len(self.catch.y) != len(self.catch.x):
            return
        xy = np.array([float(self.catch.x[-1]), float(self.catch.y[-1])])
        self._quiet = True
        self.catch.x, self.catch.y = [], []
        self._quiet = False
        mode = self.mode.value
        if mode == "pick":
            hit = self._building_at(xy)
            if hit is None:
                self._say_at(xy, "no building here")
                return
            self._say_at(None)
            self.on_pick(hit)
        elif mode == "facade":
            self._facade_at(xy)
        elif mode == "passage":
            self._passage_click(xy)

    def _building_at(self, xy: np.ndarray) -> str | None:
        if self._site is None:
            return None
        point = shapely.Point(xy)
        for b in self._site.buildings:
            if b.footprint.buffer(0.5).contains(point):
                return b.id
        return None

    # -- zones: a facade picked, its range dragged ----------------------------------------------
    def show_facades(self, ids: Sequence[str], start: np.ndarray, end: np.ndarray) -> None:
        """The facades a zone can be put on (as facades.csv names them), for picking."""
        self._facades = (list(ids), np.asarray(start, float), np.asarray(end, float))
        self._facade = ""
        self.facade_line.x, self.facade_line.y = np.full((1, 2), np.nan), np.full((1, 2), np.nan)
        self.handles.x, self.handles.y = [], []

    def _facade_at(self, xy: np.ndarray) -> None:
        ids, a, b = self._facades
        if not ids:
            self._say_at(xy, "no facade to pick")
            return
        ab = b - a
        t = np.clip(np.einsum("ij,ij->i", xy - a, ab) / np.einsum("ij,ij->i", ab, ab), 0, 1)
        d = np.hypot(*(a + t[:, None] * ab - xy).T)
        k = int(np.argmin(d))
        if d[k] > max(3.0, 12.0 * self._m_per_px()):  # [m]: a click within ~12 px of a wall
            self._say_at(xy, "click on a wall")
            return
        self._say_at(None)
        self.on_facade(ids[k])
        self.mode.value = "range"  # its ends to drag next

    def _wall(self, facade_id: str) -> tuple[np.ndarray, np.ndarray, float] | None:
        """A facade's start, unit direction and length [m]; None where it is not on the map."""
        ids, a, b = self._facades
        if facade_id not in ids:
            return None
        k = ids.index(facade_id)
        length = float(np.hypot(*(b[k] - a[k])))
        return a[k], (b[k] - a[k]) / max(length, 1e-9), length

    def _stretch(self, facade_id: str, from_m: float, to_m: float) -> np.ndarray | None:
        """The stretch ``from_m`` … ``to_m`` along a facade, its two ends (E, N [m])."""
        wall = self._wall(facade_id)
        if wall is None:
            return None
        start, u, _length = wall
        return np.array([start + from_m * u, start + to_m * u])

    def show_zone_range(self, facade_id: str, from_m: float, to_m: float) -> None:
        """Mark the range ``from_m`` … ``to_m`` along ``facade_id`` (thick, with its two ends
        to drag in "Zone range" mode)."""
        ends = self._stretch(facade_id, from_m, to_m)
        if ends is None:
            return
        self._facade = facade_id
        self.facade_line.x, self.facade_line.y = ends[None, :, 0], ends[None, :, 1]
        with self.handles.hold_sync():
            self.handles.x, self.handles.y = ends[:, 0], ends[:, 1]
        self._set_mode()

    def show_zones(self, ranges: Sequence[tuple[str, float, float]]) -> None:
        """The zones added, each as its stretch of wall: ``(facade_id, from_m, to_m)``."""
        stretches = [self._stretch(*r) for r in ranges]
        self.zone_lines.x, self.zone_lines.y = _rows([q for q in stretches if q is not None])

    def _handle_dragged(self, _event) -> None:
        wall = self._wall(self._facade)
        if wall is None:
            return
        start, u, length = wall
        pts = np.column_stack(
            [np.asarray(self.handles.x, float), np.asarray(self.handles.y, float)]
        )
        along = np.clip((pts - start) @ u, 0.0, length)
        lo, hi = float(min(along)), float(max(along))
        self.show_zone_range(self._facade, lo, hi)  # back onto the wall
        self.on_range_dragged(round(lo, 1), round(hi, 1))

    # -- passages ---------------------------------------------------------------------------------
    def _passage_click(self, xy: np.ndarray) -> None:
        if self._first is None:
            self._first = xy
            self.draft.x, self.draft.y = [xy[0]], [xy[1]]
            self._say_at(xy, "now click on the other side of the building")
            return
        first, self._first = self._first, None
        self.draft.x, self.draft.y = [], []
        self._say_at(None)
        try:
            self.on_passage(first, xy)
        except PlannerError as exc:
            self._say_at(xy, f"no passage: {_short(str(exc))}")
            self.status.value = (
                f"<span class='planner-error' style='color:#922'>No passage drawn: "
                f"{html.escape(str(exc))}</span>"
            )

    # -- edits -----------------------------------------------------------------------------------
    def _draw_targets(self) -> None:
        quiet, self._quiet = self._quiet, True
        for kind, mark in self.target_marks.items():
            ids, xy = self._targets.get(kind, ([], np.empty((0, 2))))
            with mark.hold_sync():
                mark.x, mark.y = xy[:, 0], xy[:, 1]
                tips = self._target_tips.get(kind, [])
                mark.names = tips if len(tips) == len(ids) else list(ids)
        self._quiet = quiet

    def _current(self) -> np.ndarray:
        return np.column_stack([np.asarray(self.stations.x), np.asarray(self.stations.y)])

    def _dragged(self, _event) -> None:
        self._edit(self._current(), self._ids, "moved")

    def _maybe_added(self) -> None:
        if self._quiet or self.mode.value != "add":
            return
        xy = self._current()
        if len(xy) > len(self._xy):
            self.locked += [False] * (len(xy) - len(self._xy))
            self._edit(xy, [*self._ids, *[None] * (len(xy) - len(self._xy))], "added")

    def _clicked(self, event) -> None:
        k = int(event.get("data", {}).get("index", -1))
        if not 0 <= k < len(self._xy):
            return
        if self.mode.value == "delete":
            keep = np.arange(len(self._xy)) != k
            self.locked = [lk for lk, kp in zip(self.locked, keep, strict=True) if kp]
            self._edit(
                self._xy[keep], [i for i, kp in zip(self._ids, keep, strict=True) if kp], "deleted"
            )
        elif self.mode.value == "lock":
            self.locked[k] = not self.locked[k]
            self._draw_labels()
            n = sum(self.locked)
            self.status.value = f"{n} station(s) locked: re-optimise to keep them and plan the rest"

    def _target_dragged(self, kind: str, event) -> None:
        ids, _xy = self._targets.get(kind, ([], None))
        mark = self.target_marks[kind]
        k = int(event.get("index", -1))
        if 0 <= k < len(ids):
            x, y = float(mark.x[k]), float(mark.y[k])
            self._targets_edit("moved", move={ids[k]: (x, y)})

    def _target_clicked(self, kind: str, event) -> None:
        ids, _xy = self._targets.get(kind, ([], None))
        k = int(event.get("data", {}).get("index", -1))
        if self.mode.value == "delete" and 0 <= k < len(ids):
            self._targets_edit("ruled out", remove=[ids[k]])

    def _maybe_target_added(self, kind: str) -> None:
        if self._quiet or self.mode.value != "add-target" or kind != "sphere":
            return
        mark = self.target_marks[kind]
        if len(mark.x) > len(self._targets[kind][0]):
            xy = np.array([[float(mark.x[-1]), float(mark.y[-1])]])
            self._targets_edit("added", add_xy=xy)

    def _targets_edit(self, what: str, **edits) -> None:
        if self._no_plan(what):
            return
        try:
            self._edit_targets(**edits)
        except PlannerError as exc:
            self.status.value = (
                f"<span class='planner-error' style='color:#922'>Target not {what}: "
                f"{html.escape(str(exc))}</span>"
            )
            self._draw_targets()  # back where they were

    def _say_at(self, xy: np.ndarray | None, text: str = "") -> None:
        """Write ``text`` on the map at ``xy`` (None: clear it)."""
        with self.notice.hold_sync():
            if xy is None:
                self.notice.x, self.notice.y, self.notice.text = [], [], []
            else:
                self.notice.x, self.notice.y = [float(xy[0])], [float(xy[1])]
                self.notice.text = [text]

    def _no_plan(self, what: str) -> bool:
        """Whether there is no plan on the map to edit (the site changed): said, and the
        marks put back."""
        if self._plan is not None:
            return False
        self.status.value = (
            f"<span class='planner-error' style='color:#922'>Not {what}: there is no plan on "
            "the map for this site yet; press <b>Plan</b> first.</span>"
        )
        self._quiet = True
        self.stations.x, self.stations.y = self._xy[:, 0], self._xy[:, 1]
        self._quiet = False
        self._draw_targets()
        return True

    def _edit(self, xy: np.ndarray, ids: list[str | None], what: str) -> None:
        if self._no_plan(what):
            self.locked = self.locked[: len(self._xy)]
            return
        before, locks, names = self._xy, list(self.locked), self._ids
        self._xy, self._ids = xy, list(ids)  # the locks are aligned with the edited positions
        try:
            self._evaluate(xy, self._ids)
        except PlannerError as exc:
            self._xy, self.locked, self._ids = before, locks[: len(before)], names
            self.status.value = (
                f"<span class='planner-error' style='color:#922'>Not {what}: "
                f"{html.escape(str(exc))}</span>"
            )
            self._say_at(_edited_point(before, xy), f"not {what}: {_short(str(exc))}")
            self._quiet = True
            self.stations.x, self.stations.y = self._xy[:, 0], self._xy[:, 1]
            self._quiet = False
            self._draw_labels()


def _place(mark: bq.Scatter, notes: Sequence[tuple[float, float, str]]) -> None:
    """Put ``mark``'s points at the notes' places, their words on hover."""
    with mark.hold_sync():
        mark.x = [n[0] for n in notes]
        mark.y = [n[1] for n in notes]
        mark.names = [n[2] for n in notes]


def _legend() -> str:
    """The map's symbols in words, under it (the same language as the printed maps)."""
    item = "<span style='margin-right:1.2em;white-space:nowrap'>{}</span>"
    parts = [
        f"<b style='color:{COLOURS['cover']}'>▲</b> station (colour: why it is there; "
        "hover: its place and nearest station)",
        "<b style='color:#8e44ad'>■</b> flat target",
        "<b style='color:#8e44ad'>●</b> sphere",
        "<b>▼</b> control point",
        f"<b style='color:{_GREEN}'>•</b>/<b style='color:{_RED}'>•</b> facade samples "
        "(met / unmet, or the value chosen)",
        "<b style='color:#c71585'>┈</b> link by targets",
        "<b style='color:#c71585'>╌</b> cloud-to-cloud link",
        f"<b style='color:{COLOURS['route']}'>╌</b> walking route",
        f"<b style='color:{COLOURS['passage']}'>▭</b> passage",
        "<b style='color:#c0392b'>✕</b> site problem (stops the plan)",
        "<b style='color:#d4ac0d'>◆</b> site repaired (site_repairs.csv)",
    ]
    return "<small>" + "".join(item.format(p) for p in parts) + "</small>"
