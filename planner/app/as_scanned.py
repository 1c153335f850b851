"""The dashboard's "As scanned" tab: the stations as the crew scanned them, and what is left.

The surveyor uploads the registered project's E57 (its scan poses) or a CSV of the station
positions — optionally the targets as placed and the registration program's link report —
and presses *Re-plan from the scans*: :func:`planner.pipeline.survey.asscanned.replan` judges
every sample with the stations as scanned and proposes the fewest extra stations; the map
and every tab then show that plan, this tab the table of stations (as planned, moved,
skipped, added on site, extra with its reason) and the links as registered against the
plan, with the booklet of the extra stations to download.
"""

from __future__ import annotations

import html
import threading
from collections.abc import Callable
from pathlib import Path

import ipywidgets as w

from planner.app.widgets import download_link, error_html, show
from planner.errors import PlannerError
from planner.pipeline.engine.judge import workbench_of
from planner.pipeline.survey.asscanned import (
    Replan,
    check_scanned,
    compare_links,
    read_link_report,
    read_targets_placed,
    replan,
)
from planner.pipeline.survey.pointclouds import read_poses

__all__ = ["AsScannedPanel"]


class AsScannedPanel:
    """The tab's widgets. ``plan_of`` gives the plan on screen (None: none yet); ``start``
    runs ``make(progress) -> Plan`` in the background as the Plan button does and shows
    its plan; ``folder()`` is where uploads are written; ``busy()`` whether a run is under
    way (one at a time)."""

    def __init__(
        self,
        plan_of: Callable,
        start: Callable,
        folder: Callable[[], Path],
        busy: Callable[[], bool],
    ) -> None:
        self._plan_of, self._start, self._folder, self._busy = plan_of, start, folder, busy
        self.poses = w.FileUpload(accept=".e57,.csv", multiple=False, description="Scans")
        self.targets = w.FileUpload(accept=".csv", multiple=False, description="Targets")
        self.report = w.FileUpload(accept=".csv,.txt", multiple=False, description="Report")
        self.button = w.Button(
            description="Re-plan from the scans",
            button_style="primary",
            layout=w.Layout(width="auto"),
        )
        self.status = w.HTML("")
        self.out = w.Output()
        self.booklet = w.HTML("")
        self.last: Replan | None = None
        self._links = None  # the link report compared, for the last re-plan
        #: the plan the crew scanned (a second re-plan starts from it, not from the first
        #: re-plan's result)
        self.base = None
        self.button.on_click(lambda _b: self.run())
        self.widget = w.VBox(
            [
                w.HTML(
                    "<p>The stations as scanned: the registered project's <b>E57</b> (scans "
                    "named by station id, with their poses) or a <b>CSV</b> "
                    "<code>station_id, x, y</code>. Optional: the targets as placed "
                    "(<code>target_id, x, y</code>) and the registration program's link "
                    "report (<code>from, to, error</code> [mm], overlap). A registered "
                    "project's E57 is often gigabytes: export the poses alone (or the CSV) "
                    "to upload it here; <code>planner replan</code> reads any size.</p>"
                ),
                w.HBox([self.poses, self.targets, self.report]),
                self.button,
                self.status,
                self.out,
                self.booklet,
            ]
        )
        self.widget.add_class("planner-as-scanned")

    def _saved(self, upload: w.FileUpload, role: str) -> Path | None:
        if not upload.value:
            return None
        f = upload.value[0]
        path = self._folder() / f"as-scanned-{role}-{Path(f['name']).name}"
        path.write_bytes(bytes(f["content"]))
        return path

    def run(self):
        """Read the uploads and re-plan in the background (errors said here); the thread
        that shows the result when the re-plan ends, or None where nothing was started."""
        if self._busy():
            self.status.value = error_html(
                "a plan is being made; re-plan when it is done", "Cannot re-plan"
            )
            return None
        shown = self._plan_of()
        if self.last is None or shown is not self.last.plan:  # a plan of its own on screen
            self.base = shown
        base = self.base
        try:
            if base is None or workbench_of(base) is None:
                raise PlannerError(
                    "make a plan first (the plan the crew scanned; a district plan cannot "
                    "be re-planned here: use planner replan)"
                )
            poses = self._saved(self.poses, "scans")
            if poses is None:
                raise PlannerError("choose the scans' E57 or a CSV of station positions")
            scanned = read_poses(poses)
            placed_path = self._saved(self.targets, "targets")
            report_path = self._saved(self.report, "report")
            placed = read_targets_placed(placed_path) if placed_path else None
            report = read_link_report(report_path) if report_path else None
            check_scanned(base, scanned, placed)  # refused here: the plan on screen stays
        except (PlannerError, ValueError) as exc:
            self.status.value = error_html(str(exc), "Cannot re-plan")
            return None
        self.status.value = "<i>re-planning from the scans…</i>"
        self.booklet.value = ""

        def make(progress):
            r = replan(base, scanned, targets_placed=placed, progress=progress)
            self.last = r
            self._links = compare_links(r.scanned_plan, report) if report is not None else None
            return r.plan

        worker = self._start(make, "re-planned from the scans", fresh=False)
        # this tab's table once the map and the other tabs show the new plan
        done = threading.Thread(target=self._show_when_done, args=(worker,), daemon=True)
        done.start()
        return done

    def _show_when_done(self, worker: threading.Thread) -> None:
        worker.join()
        r = self.last
        if r is not None and self._plan_of() is r.plan:
            self._show(r, self._links)
        elif self.status.value.startswith("<i>re-planning"):
            self.status.value = ""  # (the re-plan failed or was cancelled: the toolbar says)

    def _show(self, r: Replan, links) -> None:
        self.status.value = (
            "<div style='white-space:pre-line;word-break:normal'>"
            + html.escape(r.summary())
            + "</div>"
        )
        tables = [r.stations.set_index("station_id").round({"x": 3, "y": 3, "moved_m": 2})]
        if links is not None:
            tables += [w.HTML("<b>Links as registered against the plan</b>"), links.round(2)]
        show(self.out, *tables)
        if len(r.extra):
            from planner.app.booklet import booklet_pdf

            data = booklet_pdf(r.plan, only=set(r.extra["station_id"]))
            self.booklet.value = download_link(
                "booklet-extra-stations.pdf", data, "application/pdf"
            )
