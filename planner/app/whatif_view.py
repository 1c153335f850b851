"""The what-if map of the dashboard: stations dragged, added, deleted and locked by hand on
an interactive map, targets moved, added and ruled out, the plan judged again at once
(:mod:`planner.pipeline.whatif`).

The map is a ``bqplot`` figure: it is an ipywidget (served by Voilà like any other, no
server-side rendering per drag), its scatter marks can be dragged in the browser with the
new positions sent back as data coordinates, and a click on the background can add a point —
the three things a by-hand edit needs. Matplotlib (``ipympl``) would redraw a PNG per
change; ``ipyleaflet`` wants web-map tiles and lon/lat where a survey works in its own
projected grid.
"""

from __future__ import annotations

import html
from collections.abc import Callable

import bqplot as bq
import ipywidgets as w
import numpy as np
import shapely

from planner.app.maps import COLOURS
from planner.errors import PlannerError
from planner.pipeline.result import Plan
from planner.pipeline.schema import SYMBOLS

__all__ = ["WhatIfMap"]

#: What a click on the map does.
MODES = [
    ("Move (drag)", "move"),
    ("Add station", "add"),
    ("Add target", "add-target"),
    ("Delete", "delete"),
    ("Lock / unlock", "lock"),
    ("Pick buildings", "pick"),
]


def _rings(geoms) -> tuple[np.ndarray, np.ndarray]:
    """Outer rings of the polygons as ``(n, m)`` x and y arrays (bqplot draws one line per
    row), shorter rings padded with their closing vertex; one dummy point when none."""
    rings = [
        np.asarray(poly.exterior.coords)
        for g in geoms
        for poly in getattr(g, "geoms", [g])
        if isinstance(poly, shapely.Polygon) and not poly.is_empty
    ]
    if not rings:
        return np.full((1, 2), np.nan), np.full((1, 2), np.nan)
    m = max(len(r) for r in rings)
    padded = np.stack([np.vstack([r, np.repeat(r[-1:], m - len(r), axis=0)]) for r in rings])
    return padded[:, :, 0], padded[:, :, 1]


#: The outlines and labels never take a click: a click on a building reaches the map (and
#: is refused there with the reason) instead of vanishing into the outline.
_CSS = """<style>
.planner-whatif-map path.line, .planner-whatif-map path.area, .planner-whatif-map text.label
{ pointer-events: none; }
</style>"""


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


class WhatIfMap:
    """Stations on the site, editable; facade samples green (met) or red (unmet).

    ``evaluate(xy, ids)``, ``edit_targets(remove=, move=, add_xy=)`` and
    ``reoptimise(locked_xy)``
    are given by the dashboard (they run the pipeline); this class only holds the map, the
    edit modes and the lock marks."""

    def __init__(
        self,
        evaluate: Callable[[np.ndarray, list[str | None]], None],
        reoptimise: Callable[[np.ndarray], None],
        edit_targets: Callable[..., None],
    ) -> None:
        self._evaluate, self._reoptimise, self._edit_targets = evaluate, reoptimise, edit_targets
        self.sx, self.sy = bq.LinearScale(), bq.LinearScale()
        scales = {"x": self.sx, "y": self.sy}
        self.buildings = bq.Lines(
            x=np.zeros((1, 2)),
            y=np.zeros((1, 2)),
            fill="inside",
            colors=["#555"],
            scales=scales,
            stroke_width=1,
        )
        self.others = bq.Lines(
            x=np.zeros((1, 2)), y=np.zeros((1, 2)), fill="inside", colors=["#bbb"], scales=scales
        )
        self.passages = bq.Lines(  # gateways through buildings: dashed, on top of them
            x=np.zeros((1, 2)),
            y=np.zeros((1, 2)),
            colors=[COLOURS["passage"]],
            line_style="dashed",
            stroke_width=2,
            scales=scales,
        )
        self.samples = bq.Scatter(
            x=[],
            y=[],
            color=[],
            scales={**scales, "color": bq.ColorScale(min=0, max=1, colors=["#1e8449", "#c0392b"])},
            default_size=12,
            stroke=None,
            display_names=False,
        )
        self.targets = bq.Scatter(
            x=[],
            y=[],
            scales=scales,
            marker="diamond",
            colors=[COLOURS["target"]],
            stroke="white",
            default_size=60,
            display_names=False,
            tooltip=bq.Tooltip(fields=["name"], labels=["target"]),  # its id on hover
        )
        self.stations = bq.Scatter(
            x=[],
            y=[],
            names=[],
            display_names=True,
            scales=scales,
            marker=SYMBOLS["station"],
            colors=[COLOURS["hand"]],
            stroke="black",
            default_size=140,
            enable_move=True,
        )
        ax = [
            bq.Axis(scale=self.sx, label="E [m]", tick_format=".0f", num_ticks=5),
            bq.Axis(
                scale=self.sy,
                label="N [m]",
                orientation="vertical",
                tick_format=".0f",
                num_ticks=5,
                label_offset="65px",
            ),
        ]
        self.picks = bq.Scatter(  # each building's id at its centre: picked in "pick" mode
            x=[],
            y=[],
            names=[],
            display_names=True,
            scales=scales,
            marker="square",
            colors=["white"],
            stroke="#333",
            default_size=16,  # (smaller than a target's mark: never mistaken for one)
            tooltip=bq.Tooltip(fields=["name"], labels=["building"]),
        )
        self.notice = bq.Label(  # why a click was refused, where it was made
            x=[],
            y=[],
            text=[],
            scales=scales,
            colors=["#922b21"],
            default_size=13,
            font_weight="bold",
            x_offset=10,
            y_offset=-10,
        )
        self.figure = bq.Figure(
            marks=[
                self.others,
                self.buildings,
                self.passages,
                self.samples,
                self.picks,
                self.targets,
                self.stations,
                self.notice,
            ],
            axes=ax,
            padding_x=0,
            padding_y=0,
            fig_margin={"top": 10, "bottom": 45, "left": 80, "right": 10},
            layout=w.Layout(width="100%", height="560px"),
        )
        self.figure.add_class("planner-whatif-map")
        self.mode = w.ToggleButtons(options=MODES, value="move", description="Click to")
        self.reopt = w.Button(description="Re-optimise around the locked", icon="refresh")
        self.reopt.layout.width = "22em"
        # room for three lines: a longer status never pushes the map down under the cursor
        self.status = w.HTML("", layout=w.Layout(min_height="4.6em"))
        self.status.add_class("planner-whatif-status")
        self._framed = None  # the site the map's view was fitted to (kept through edits)
        self.on_pick: Callable[[str], None] = lambda _id: None  # the page's: plan it or not
        self._pick_ids: list[str] = []
        self.locked: list[bool] = []
        self._xy = np.empty((0, 2))
        self._ids: list[str | None] = []  # the station each position is (None: added)
        self._target_ids: list[str] = []
        self._target_xy = np.empty((0, 2))
        self._quiet = False
        self.mode.observe(lambda _c: self._set_mode(), "value")
        self.stations.on_drag_end(lambda _m, e: self._dragged(e))
        self.stations.on_element_click(lambda _m, e: self._clicked(e))
        self.stations.observe(lambda _c: self._maybe_added(), names=["x"])
        self.targets.on_drag_end(lambda _m, e: self._target_dragged(e))
        self.targets.on_element_click(lambda _m, e: self._target_clicked(e))
        self.targets.observe(lambda _c: self._maybe_target_added(), names=["x"])
        self.picks.on_element_click(lambda _m, e: self._picked(e))
        self.reopt.on_click(lambda _b: self._reoptimise(self._xy[np.asarray(self.locked, bool)]))
        self.widget = w.VBox(
            [
                w.HTML(_CSS),
                w.HTML(
                    "<small>Drag a station (▲) or a target (◆) to move it — a wall target "
                    "slides along its wall; <b>Add station</b> / <b>Add target</b> (a sphere "
                    "on a stand) puts one where you click; <b>Delete</b> removes the station "
                    "clicked, or rules the target clicked out (no link uses it again); "
                    "<b>Lock</b> keeps a station when the rest is optimised again. The plan "
                    "(coverage, accuracy with the registration error, targets) is judged again "
                    "after every edit. Green samples meet the requirement, red ones do not."
                    "</small>"
                ),
                self.mode,
                self.reopt,
                self.status,
                self.figure,
            ]
        )

    # -- showing a site and a plan -------------------------------------------------------------
    def _draw_site(self, site) -> None:
        """Buildings (planned dark, others light), obstacles, passages, the buildings' ids."""
        xs, ys = _rings(b.footprint for b in site.planned)
        self.buildings.x, self.buildings.y = xs, ys
        others = [b.footprint for b in site.buildings if not b.planned]
        others += [o.geometry for o in site.obstacles]
        xs, ys = _rings(others)
        self.others.x, self.others.y = xs, ys
        xs, ys = _rings(a.geometry for a in site.passages)
        self.passages.x, self.passages.y = xs, ys
        centres = [b.footprint.representative_point() for b in site.buildings]
        self._pick_ids = [b.id for b in site.buildings]
        with self.picks.hold_sync():
            self.picks.x = [c.x for c in centres]
            self.picks.y = [c.y for c in centres]
            self.picks.names = self._pick_ids

    def show_site(self, site) -> None:
        """Draw a site before it is planned: its buildings with their ids (a click on an id
        in "Pick buildings" mode plans the building or leaves it out), nothing planned yet."""
        self._draw_site(site)
        self._quiet = True
        self.samples.x, self.samples.y, self.samples.color = [], [], []
        self._xy, self._ids, self.locked = np.empty((0, 2)), [], []
        self._target_ids, self._target_xy = [], np.empty((0, 2))
        with self.stations.hold_sync():
            self.stations.x, self.stations.y, self.stations.names = [], [], []
        self._draw_targets()
        self._quiet = False
        self._say_at(None)
        x0, y0, x1, y1 = shapely.union_all([b.footprint for b in site.buildings]).bounds
        self._frame((x0 + x1) / 2, (y0 + y1) / 2, max(x1 - x0, y1 - y0) / 2 + 10.0)
        self._framed = site
        n = len(site.planned)
        self.status.value = (
            f"The site: {len(site.buildings)} buildings, {n} to plan (dark). <b>Pick "
            "buildings</b>, then click a building's id to plan it or leave it out; "
            "<b>Plan</b> places the stations."
        )

    def _picked(self, event) -> None:
        k = int(event.get("data", {}).get("index", -1))
        if self.mode.value == "pick" and 0 <= k < len(self._pick_ids):
            self.on_pick(self._pick_ids[k])

    def show_plan(self, p: Plan, message: str = "") -> None:
        """Draw ``p``: site, samples (met / unmet), targets, stations (locks kept by position)."""
        old = {tuple(np.round(xy, 3)): lk for xy, lk in zip(self._xy, self.locked, strict=True)}
        self._draw_site(p.site)
        cov = p.scanned
        self.samples.x, self.samples.y = cov["x"].to_numpy(), cov["y"].to_numpy()
        self.samples.color = (~cov["meets"].to_numpy()).astype(float)
        self._target_ids = [str(t) for t in p.targets["target_id"]]
        self._target_xy = p.targets[["x", "y"]].to_numpy(dtype=float).reshape(-1, 2)
        scans = p.scan_stations  # (a traverse's set-ups are planned with the network)
        xy = scans[["x", "y"]].to_numpy(dtype=float)
        self._xy = xy
        self._ids = [str(s) for s in scans["station_id"]]
        self.locked = [old.get(tuple(np.round(q, 3)), False) for q in xy]
        self._quiet = True
        with self.stations.hold_sync():
            self.stations.x, self.stations.y = xy[:, 0], xy[:, 1]
            self.stations.names = self._names(scans["station_id"])
        self._draw_targets()
        self._quiet = False
        self._say_at(None)
        if self._framed is not p.site:  # a new site is framed; an edit keeps the view
            self._fit_extent(p)
            self._framed = p.site
        self.status.value = message  # a status never outlives what it describes

    def _names(self, ids) -> list[str]:
        return [f"{s} 🔒" if lk else str(s) for s, lk in zip(ids, self.locked, strict=True)]

    def _fit_extent(self, p: Plan) -> None:
        pts = [p.scanned[["x", "y"]].to_numpy(), self._xy, self._target_xy]
        allxy = np.vstack([q for q in pts if len(q)])
        lo, hi = allxy.min(axis=0), allxy.max(axis=0)
        centre = (lo + hi) / 2
        self._frame(centre[0], centre[1], float((hi - lo).max()) / 2 + 10.0)

    def _frame(self, x: float, y: float, half: float) -> None:
        """A square view round (x, y) on a figure kept square: a metre as long across as up."""
        half = max(half, 20.0)
        self.sx.min, self.sx.max = float(x - half), float(x + half)
        self.sy.min, self.sy.max = float(y - half), float(y + half)
        self.figure.min_aspect_ratio = self.figure.max_aspect_ratio = 1.0

    # -- edits -----------------------------------------------------------------------------------
    def _draw_targets(self) -> None:
        quiet, self._quiet = self._quiet, True
        with self.targets.hold_sync():
            self.targets.x, self.targets.y = self._target_xy[:, 0], self._target_xy[:, 1]
            self.targets.names = self._target_ids
        self._quiet = quiet

    def _set_mode(self) -> None:
        mode = self.mode.value
        self.stations.enable_move = self.targets.enable_move = mode == "move"
        self.stations.interactions = {"click": "add"} if mode == "add" else {}
        self.targets.interactions = {"click": "add"} if mode == "add-target" else {}

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
            ids = [n.removesuffix(" 🔒") for n in self.stations.names]
            self.stations.names = self._names(ids)
            n = sum(self.locked)
            self.status.value = f"{n} station(s) locked: re-optimise to keep them and plan the rest"

    def _target_dragged(self, event) -> None:
        k = int(event.get("index", -1))
        if 0 <= k < len(self._target_ids):
            x, y = float(self.targets.x[k]), float(self.targets.y[k])
            self._targets_edit("moved", move={self._target_ids[k]: (x, y)})

    def _target_clicked(self, event) -> None:
        k = int(event.get("data", {}).get("index", -1))
        if self.mode.value == "delete" and 0 <= k < len(self._target_ids):
            self._targets_edit("ruled out", remove=[self._target_ids[k]])

    def _maybe_target_added(self) -> None:
        if self._quiet or self.mode.value != "add-target":
            return
        if len(self.targets.x) > len(self._target_ids):
            xy = np.array([[float(self.targets.x[-1]), float(self.targets.y[-1])]])
            self._targets_edit("added", add_xy=xy)

    def _targets_edit(self, what: str, **edits) -> None:
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

    def _edit(self, xy: np.ndarray, ids: list[str | None], what: str) -> None:
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
            return
