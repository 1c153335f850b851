"""Widgets of the notebooks / Voilà dashboards. Thin: they collect inputs, call the package,
and show results; the science lives elsewhere.

* :class:`StationPlanner` — the main dashboard (site, scanner, requirements → plan).

The explorers of the accuracy figures and target sizes are in :mod:`planner.app.explorers`.
"""

from __future__ import annotations

import html
import io
import threading
import time
import traceback
import zipfile
from dataclasses import replace
from pathlib import Path

import ipywidgets as w
import numpy as np
import shapely
from IPython.display import display

from planner.app.as_scanned import AsScannedPanel
from planner.app.booklet import booklet_pdf
from planner.app.elevations import elevation_buildings, plot_elevations
from planner.app.maps import QUANTITIES, plot_coverage, quantity_label
from planner.app.plan_map import PlanMap
from planner.app.report import make_report
from planner.app.view3d import view_3d
from planner.app.widgets import (
    download_link,
    error_html,
    inventory_box,
    remember_kit,
    scanner_dropdown,
    show,
    upload_folder,
)
from planner.app.wording import SITE_LABELS, for_dashboard, time_words
from planner.classes import class_limits, parse_class
from planner.errors import PlannerError
from planner.materials import material_table
from planner.pipeline.documents.export import render
from planner.pipeline.engine.explain import explain_unmet, suggestions
from planner.pipeline.engine.planning import plan
from planner.pipeline.engine.whatif import (
    edit_targets,
    evaluate_stations,
    reoptimise,
    user_edits,
)
from planner.pipeline.geometry.facades import build_facades
from planner.pipeline.inputs.requirements import (
    HEIGHT_CONTROL,
    LINK_CHECKS,
    REGISTRATION_PROCESSING,
    SETTING_GROUPS,
    FieldSpec,
    PlanSettings,
    Requirements,
    field_specs,
    requirements_and_settings,
    setting_groups,
)
from planner.pipeline.inputs.resolved import resolve
from planner.scanner import Scanner
from planner.site import DEFAULT_NEAR_M, Passage
from planner.siteio import (
    DEFAULT_STOREY_HEIGHT_M,
    default_site,
    read_control,
    read_outlines,
    read_site,
)
from planner.targets import (
    parse_inventory,
)
from planner.zones import Zone

__all__ = ["StationPlanner"]


_MIME = {
    ".csv": "text/csv",
    ".geojson": "application/geo+json",
    ".txt": "text/plain",
    ".dxf": "image/vnd.dxf",
    ".kml": "application/vnd.google-earth.kml+xml",
    ".html": "text/html",
    ".pdf": "application/pdf",
}


def _zip(files: dict[str, bytes]) -> bytes:
    """Every file of the plan in one zip (fixed dates: the same plan, the same bytes)."""
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in files.items():
            z.writestr(zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0)), data)
    return buf.getvalue()


_STYLE = {"description_width": "initial"}
_FULL = w.Layout(width="98%")


def _number(
    value: float, lo: float, hi: float, step: float, description: str
) -> w.BoundedFloatText:
    """A labelled number box of the dashboard's controls."""
    return w.BoundedFloatText(
        value=value, min=lo, max=hi, step=step, description=description, style=_STYLE, layout=_FULL
    )


#: Upper bound of a number box whose field has none (the data class decides beyond it).
_NO_UPPER = 1e6


def _field_box(spec: FieldSpec, label: str | None = None) -> w.Widget:
    """A number box for a requirement or setting, with the data class's default, bounds and
    unit; an optional field shows 0 for "not required" (0 is outside its valid range)."""
    text = f"{label or spec.label} [{spec.unit}]" + (" (0: none)" if spec.optional else "")
    value = spec.default if spec.default is not None else 0.0
    if isinstance(value, tuple):
        value = value[0]
    lo = 0.0 if spec.lo is None or spec.optional else spec.lo  # 0: "none" where optional
    hi = _NO_UPPER if spec.hi is None else spec.hi
    if isinstance(spec.default, int) and not isinstance(spec.default, bool):
        return w.BoundedIntText(
            value=value, min=int(lo), max=int(hi), description=text, style=_STYLE, layout=_FULL
        )
    return _number(float(value), lo, hi, spec.step, text)


def _field_value(spec: FieldSpec, box: w.Widget):
    """A box's value for the data class: an optional field's 0 means "not given" (None)."""
    return None if spec.optional and not box.value else box.value


def _placed(note) -> bool:
    return bool(np.isfinite(note.x) and np.isfinite(note.y))


class ZoneEditor:
    """Add zones without editing files: pick a facade, drag (or type) the along-facade and
    height ranges, give the requirement and the finer spacing, Add. The zones are checked
    when the plan is made (a message, never a traceback)."""

    def __init__(self) -> None:
        rq = field_specs(Requirements)
        self.facade = w.Dropdown(options=[], description="facade", style=_STYLE, layout=_FULL)
        slider = dict(min=0.0, max=10.0, step=0.1, readout_format=".1f", style=_STYLE, layout=_FULL)
        self.along = w.FloatRangeSlider(value=(0.0, 10.0), description="along [m]", **slider)
        self.height = w.FloatRangeSlider(value=(0.0, 10.0), description="height [m]", **slider)
        self.max_xy = _field_box(rq["max_xy_mm"], "zone: largest m_x, m_y")
        self.max_z = _field_box(rq["max_z_mm"], "zone: largest m_z")
        self.spacing = _number(0.0, 0.0, 100.0, 0.25, "zone: sample spacing [m] (0: as the site)")
        self.add = w.Button(description="Add zone", icon="plus")
        self.clear = w.Button(description="Remove zones")
        self.listing = w.HTML("<small>No zones: one requirement everywhere.</small>")
        self.zones: list = []
        self.on_change = lambda: None  # the page's: a zone added or removed dates the plan
        self.on_range = lambda _facade, _lo, _hi: None  # the map's: the range on its wall
        self.on_zones = lambda: None  # the map's: the zones' stretches of wall
        self._sizes: dict[str, tuple[float, float]] = {}
        #: each facade's ends (E, N [m]): where its range lies on the map
        self.ends: dict[str, tuple[np.ndarray, np.ndarray]] = {}
        self.facade.observe(lambda _c: self.fit_ranges(), "value")
        self.along.observe(lambda _c: self._range_changed(), "value")
        self.add.on_click(lambda _b: self.add_zone())
        self.clear.on_click(lambda _b: self.remove_all())
        self.widget = w.VBox(
            [
                w.HTML("<h3>Zones</h3><small>a stricter requirement on part of a facade</small>"),
                self.facade,
                self.along,
                self.height,
                self.max_xy,
                self.max_z,
                self.spacing,
                w.HBox([self.add, self.clear]),
                self.listing,
            ]
        )

    def show_facades(self, site) -> None:
        """Offer the facades of ``site`` (ids as facades.csv names them)."""
        fac = build_facades(site, 2.0, 2.0)
        self._sizes = {
            str(fid): (float(length), float(h))
            for fid, length, h in zip(fac.facade_id, fac.length_m, fac.height_m, strict=True)
        }
        self.ends = {
            str(fid): (a, b) for fid, a, b in zip(fac.facade_id, fac.start, fac.end, strict=True)
        }
        kept = self.facade.value if self.facade.value in self._sizes else None
        ranges = (self.along.value, self.height.value)
        self.facade.options = list(self._sizes)
        self.facade.value = kept or next(iter(self._sizes), None)
        self.fit_ranges()
        if kept:  # the same facade on the redrawn site: the ranges set on it stay
            self.along.value, self.height.value = ranges

    def ranges(self) -> list[tuple[str, float, float]]:
        """Each zone added on a stretch of its facade: ``(facade_id, from_m, to_m)``."""
        return [(z.facade_id, *z.along_m) for z in self.zones if z.along_m is not None]

    def _range_changed(self) -> None:
        if self.facade.value:
            self.on_range(self.facade.value, *self.along.value)

    def fit_ranges(self) -> None:
        """The facade's whole length and height as the ranges."""
        size = self._sizes.get(self.facade.value)
        if size is None:
            return
        for slider, top in ((self.along, size[0]), (self.height, size[1])):
            slider.max = round(top, 1)
            slider.value = (0.0, round(top, 1))

    def add_zone(self) -> None:
        if not self.facade.value:
            self.listing.value = error_html("choose a facade first")
            return
        requirement = {"max_xy_mm": self.max_xy.value, "max_z_mm": self.max_z.value}
        try:
            zone = Zone(
                id=f"Z{len(self.zones) + 1}",
                facade_id=self.facade.value,
                along_m=tuple(self.along.value),
                height_m=tuple(self.height.value),
                requirement=requirement,
                sample_spacing_m=self.spacing.value or None,
                sample_height_step_m=self.spacing.value or None,
            )
        except PlannerError as exc:
            self.listing.value = error_html(str(exc))
            return
        self.zones.append(zone)
        self._list()
        self.on_change()
        self.on_zones()

    def remove_all(self) -> None:
        had = bool(self.zones)
        self.zones = []
        self._list()
        if had:
            self.on_change()
            self.on_zones()

    def _list(self) -> None:
        if not self.zones:
            self.listing.value = "<small>No zones: one requirement everywhere.</small>"
            return
        items = "".join(
            f"<li>{html.escape(z.id)}: {html.escape(z.describe())}; m_x, m_y ≤ "
            f"{z.requirement['max_xy_mm']:g} mm, m_z ≤ {z.requirement['max_z_mm']:g} mm"
            + (f"; samples every {z.sample_spacing_m:g} m" if z.sample_spacing_m else "")
            + "</li>"
            for z in self.zones
        )
        self.listing.value = f"<ul class='planner-zones' style='margin:0'>{items}</ul>"


class _Cancelled(Exception):
    """Raised from the progress callback when the user pressed Cancel."""


#: Settings shown in "More settings", generated from the data classes' specs (one source of
#: truth with the command line: label, unit, default, bounds). Those on the main panel and
#: the limits of work are left out.
_MAIN_FIELDS = {
    "max_xy_mm",
    "max_z_mm",
    "max_gamma_deg",
    "max_spacing_mm",
    "stations_per_sample",
    "grid_m",
    "max_samples",
    "max_pairs",
}

#: The height a building without one is drawn with (only drawn: the plan asks for one) [m].
DRAWING_HEIGHT_M = 10.0

#: The result tabs, in order; the site, the plan and its coverage are drawn, and edited by
#: hand, on the "Map" (:class:`planner.app.plan_map.PlanMap`).
TABS = [
    "Map",
    "Coverage",
    "Elevations",
    "3-D view",
    "Facades",
    "Registration",
    "Unmet",
    "Stations & field work",
    "As scanned",
    "Downloads",
]
MAP_TAB = TABS.index("Map")

_CSS = """<style>
.planner-toolbar { position: sticky; top: 0; z-index: 50; background: white;
  border-bottom: 1px solid #ddd; padding: 4px 0 2px 0; }
.planner-root, .jp-OutputArea:has(.planner-toolbar), .jp-OutputArea-child:has(.planner-toolbar),
.jp-OutputArea-output:has(.planner-toolbar) { overflow: visible !important; }
.planner-stale { opacity: 0.45; }
.bqplot_tooltip_div { pointer-events: none; }
.planner-stale-banner { background:#fff3cd; border:1px solid #e0c36a; padding:4px 10px;
  border-radius:4px; margin-bottom:6px }
.widget-label, .widget-label-basic { overflow: visible !important; }
.lm-TabBar-content { flex-wrap: wrap; }
.lm-TabBar-tab { min-width: fit-content !important; flex: 0 0 auto !important; }
</style>"""


class StationPlanner:
    """The station-planner dashboard: site, scanner, requirements, Plan, results on one map,
    edits, downloads. The plan on screen always matches the inputs shown: changing an input
    marks it out of date, an error replaces it."""

    def __init__(self) -> None:
        self._site_inputs()
        self._scanner_inputs()
        self._requirement_inputs()
        more = self._more_settings()
        self._model_inputs()
        self._run_controls()
        self._result_tabs()
        self.inputs = [
            self.site_source,
            self.upload,
            self.control_upload,
            self.levelling,
            self.height,
            self.storey,
            self.crs,
            self.make_valid,
            self.buildings,
            self.scanner,
            self.preset,
            self.max_x,
            self.max_y,
            self.max_z,
            self.max_gamma,
            self.max_spacing,
            self.per_sample,
            self.accuracy_class,
            self.model,
            self.registration,
            self.processing,
            self.height_control,
            self.link_check,
            self.surface_condition,
            self.default_material,
            self.grid,
            self.registration_error,
            self.imaging,
            self.demand_roofs,
            self.sight_engine,
            self.inventory,
            *self.more.values(),
        ]
        self.widget = self._lay_out(more)
        self._reset_state()
        self._wire()

    def _site_inputs(self) -> None:
        """The site: the default one or a file, and how to read it."""
        self.site_source = w.ToggleButtons(
            options=["Default site", "Upload a file"], value="Default site"
        )
        self.upload = w.FileUpload(
            accept=".geojson,.json,.jsonl,.gml,.xml,.ifc,.wkt,.txt,.csv,.gpkg,.kml,.kmz",
            multiple=False,
            description="Site file",
        )
        self.upload_name = w.HTML("<small>no file chosen</small>")
        self.upload_name.add_class("planner-upload-name")
        self.control_upload = w.FileUpload(
            accept=".csv,.txt", multiple=False, description=SITE_LABELS["--control"]
        )
        self.control_name = w.HTML("<small>none: the first scan is the datum</small>")
        self._control_path: Path | None = None
        self.height = _number(0.0, 0.0, 1000.0, 0.5, SITE_LABELS["--height"])
        self.storey = _number(
            DEFAULT_STOREY_HEIGHT_M, 0.5, 20.0, 0.1, SITE_LABELS["--storey-height-m"]
        )
        self.crs = w.Text(
            value="",
            placeholder="as in the file, e.g. EPSG:25832",
            description=SITE_LABELS["--crs"],
            style=_STYLE,
            layout=_FULL,
        )
        self.make_valid = w.Checkbox(
            value=False, description=SITE_LABELS["--make-valid"], indent=False
        )
        self.buildings = w.Text(
            value="",
            placeholder="all (as in the file)",
            style=_STYLE,
            description=SITE_LABELS["--buildings"],
            layout=_FULL,
        )

    def _scanner_inputs(self) -> None:
        """The scanner and its setting (preset), offered for the scanner chosen."""
        self.scanner = scanner_dropdown()
        self.preset = w.Dropdown(description="scanner setting", style=_STYLE, layout=_FULL)
        self.levelling = _number(0.0, 0.0, 3600.0, 0.5, SITE_LABELS["--levelling-rms-arcsec"])
        self.scanner.observe(lambda _c: self._offer_presets(), "value")
        self._offer_presets()

    def _requirement_inputs(self) -> None:
        """The main requirements and the candidate grid, from the data classes' specs."""
        rq, ps = field_specs(Requirements), field_specs(PlanSettings)
        self.max_x = _field_box(rq["max_xy_mm"], "largest m_x")
        self.max_y = _field_box(rq["max_xy_mm"], "largest m_y")
        self.max_z = _field_box(rq["max_z_mm"])
        self.max_gamma = _field_box(rq["max_gamma_deg"])
        self.max_spacing = _field_box(rq["max_spacing_mm"])
        self.per_sample = _field_box(rq["stations_per_sample"])
        self.grid = _field_box(ps["grid_m"])

    def _more_settings(self) -> w.Accordion:
        """Every other requirement and setting, in the command line's groups, and the
        zones; folded away."""
        rq, ps = field_specs(Requirements), field_specs(PlanSettings)
        self._specs = {**rq, **ps}
        self.more = {
            name: _field_box(spec) for name, spec in self._specs.items() if name not in _MAIN_FIELDS
        }
        self.registration_error = w.Checkbox(
            value=PlanSettings().registration_error,
            description=SITE_LABELS["--registration-error"],
            indent=False,
        )
        self.imaging = w.Checkbox(
            value=PlanSettings().imaging, description=SITE_LABELS["--imaging"], indent=False
        )
        self.demand_roofs = w.Checkbox(
            value=PlanSettings().demand_roofs,
            description=SITE_LABELS["--demand-roofs"],
            indent=False,
        )
        self.sight_engine = w.Dropdown(
            options=[
                ("auto (prisms on footprints, else rays)", "auto"),
                ("rays on the 3-D scene", "rays"),
                ("prisms (footprints on flat ground)", "prisms"),
            ],
            value=PlanSettings().sight_engine,
            description=SITE_LABELS["--sight-engine"],
            style=_STYLE,
            layout=_FULL,
        )
        self.inventory = inventory_box(
            SITE_LABELS["--inventory"], _STYLE, w.Layout(width="98%", height="8em")
        )
        self.surface_condition = w.Dropdown(
            options=[("dry", "dry"), ("wet (after rain: porous walls darker)", "wet")],
            value=PlanSettings().surface_condition,
            description=SITE_LABELS["--surface-condition"],
            style=_STYLE,
            layout=_FULL,
        )
        self.default_material = w.Dropdown(
            options=[("the datasheet's reference surface", "")]
            + [(f"{m.label} ({m.reflectance:.0%})", m.name) for m in material_table().values()],
            value="",
            description=SITE_LABELS["--default-material"],
            style=_STYLE,
            layout=_FULL,
        )
        # the settings in their groups (one order for the page and the command line's help)
        extra = {
            "registration_error": self.registration_error,
            "imaging": self.imaging,
            "demand_roofs": self.demand_roofs,
            "sight_engine": self.sight_engine,
            "inventory": self.inventory,
            "surface_condition": self.surface_condition,
            "default_material": self.default_material,
        }
        sections: list[w.Widget] = [w.HTML("<b>Requirements</b>")]
        sections += [self.more[n] for n in rq if n in self.more]
        for key, title in SETTING_GROUPS.items():
            boxes = [
                self.more.get(n) or extra[n]
                for n in setting_groups()[key]
                if n in self.more or n in extra
            ]
            if boxes:
                sections += [w.HTML(f"<b>{title}</b>"), *boxes]
        more = w.Accordion(children=[w.VBox(sections)])
        more.set_title(0, "More settings (as on the command line)")
        more.selected_index = None
        self.zone_editor = ZoneEditor()
        return more

    def _model_inputs(self) -> None:
        """An accuracy class, the accuracy model and how the scans are registered."""
        self.accuracy_class = w.Combobox(
            value="",
            placeholder="none: the limits above; or e.g. OGL4/OGH3, LOA40",
            options=[*(f"OGL{i}/OGH{i}" for i in range(2, 6)), "LOA30", "LOA40", "LOA50"],
            description="accuracy class",
            style=_STYLE,
            layout=_FULL,
            ensure_option=False,
        )
        self.class_note = w.HTML("")
        self.model = w.ToggleButtons(
            options=[("3-D model", "3d"), ("paper (eq. 2, 4)", "paper")],
            value=PlanSettings().model,
            description="accuracy model",
            style=_STYLE,
        )
        self.registration = w.ToggleButtons(
            options=[
                ("scanner's usual", "auto"),
                ("targets", "targets"),
                ("cloud to cloud", "cloud"),
                ("hybrid", "hybrid"),
            ],
            value=PlanSettings().registration,
            description="registration",
            tooltips=[
                "the scanner profile's workflow (targets when it names none)",
                "common targets tie the scans",
                "the surfaces two scans share tie them (ICP)",
                "cloud to cloud, targets only where a link is weak",
            ],
            style=_STYLE,
        )
        self.processing = w.ToggleButtons(
            options=[("in one adjustment", "adjustment"), ("pair by pair", "pairwise")],
            value=PlanSettings().registration_processing,
            description=SITE_LABELS["--registration-processing"],
            tooltips=list(REGISTRATION_PROCESSING.values()),
            style=_STYLE,
        )
        self.height_control = w.ToggleButtons(
            options=[("level run", "level"), ("always", "always"), ("none", "none")],
            value=PlanSettings().height_control,
            description=SITE_LABELS["--height-control"],
            tooltips=list(HEIGHT_CONTROL.values()),
            style=_STYLE,
        )
        self.link_check = w.ToggleButtons(
            options=[("rehearsed", "rehearse"), ("model only", "model")],
            value=PlanSettings().link_check,
            description=SITE_LABELS["--link-check"],
            tooltips=list(LINK_CHECKS.values()),
            style=_STYLE,
        )
        self.accuracy_class.observe(lambda _c: self._show_class(), "value")

    def _run_controls(self) -> None:
        """Plan, Cancel, progress, status, errors and the plan's summary."""
        self.plan_button = w.Button(description="Plan", button_style="primary")
        self.cancel_button = w.Button(description="Cancel", icon="stop", disabled=True)
        self.progress = w.FloatProgress(
            value=0.0, min=0.0, max=1.0, description="", layout=w.Layout(width="40%")
        )
        self.status = w.HTML("")
        self.status.add_class("planner-status")
        self.error = w.HTML("")
        self.stale = w.HTML("")
        self.summary = w.HTML("")

    def _result_tabs(self) -> None:
        """The result tabs (:data:`TABS`): the map, tables, figures, downloads."""
        self.quantity = w.ToggleButtons(
            options=[(quantity_label(q), q) for q in QUANTITIES],
            value="m_x_mm",
            description="Colour by",
        )
        self.cov_out, self.fac_out, self.unmet_out, self.reg_out = (w.Output() for _ in range(4))
        self.field_out = w.Output()
        # the facade elevations of one building at a time, and the plan in 3-D
        self.elev_building = w.Dropdown(description="building", options=[])
        self.elev_out = w.Output()
        self.elev_building.observe(lambda _c: self._redraw("Elevations"), "value")
        self.view3d_box = w.VBox([])
        self.map = PlanMap(self.evaluate_by_hand, self.reoptimise, self.edit_targets_by_hand)
        self.map.on_pick = self._toggle_building
        self.map.on_facade = self._pick_facade
        self.map.on_range_dragged = self._drag_range
        self.map.on_passage = self._draw_passage
        self.map.clear_passages.on_click(lambda _b: self._clear_passages())
        self.zone_editor.on_range = self.map.show_zone_range
        self.zone_editor.on_zones = lambda: self.map.show_zones(self.zone_editor.ranges())
        #: passages drawn on the map (gateways the file does not show), added to the site
        self.drawn_passages: list[Passage] = []
        self._upload_path: Path | None = None  # the uploaded file, written once
        #: one drawing of the site at a time (the kernel's and the planning thread's)
        self._drawing = threading.Lock()
        self.booklet_button = w.Button(description="Make field booklet (PDF)")
        self.booklet_status = w.HTML("")
        self.downloads = w.HTML("")
        self.report_button = w.Button(description="Make HTML report")
        self.report_status = w.HTML("")
        self.as_scanned = AsScannedPanel(
            lambda: self.plan,
            self.start,
            lambda: Path(self._tmp.name),
            lambda: self._worker is not None and self._worker.is_alive(),
        )
        self.tabs = w.Tab(
            children=[
                self.map.widget,
                w.VBox([self.quantity, self.cov_out]),
                w.VBox([self.elev_building, self.elev_out]),
                self.view3d_box,
                self.fac_out,
                self.reg_out,
                self.unmet_out,
                self.field_out,
                self.as_scanned.widget,
                w.VBox(
                    [
                        self.downloads,
                        w.HBox([self.report_button, self.booklet_button]),
                        self.report_status,
                        self.booklet_status,
                    ]
                ),
            ]
        )
        for i, title in enumerate(TABS):
            self.tabs.set_title(i, title)

    def _lay_out(self, more: w.Accordion) -> w.VBox:
        """The page: the toolbar on top, the inputs on the left, the results on the right."""
        controls = w.VBox(
            [
                w.HTML(_CSS + "<h3>Site</h3>"),
                self.site_source,
                w.HBox([self.upload, self.upload_name]),
                w.HBox([self.control_upload, self.control_name]),
                self.height,
                self.storey,
                self.crs,
                self.make_valid,
                self.buildings,
                w.HTML("<h3>Scanner</h3>"),
                self.scanner,
                self.preset,
                self.levelling,
                w.HTML("<h3>Requirements</h3>"),
                self.max_x,
                self.max_y,
                self.max_z,
                self.max_gamma,
                self.max_spacing,
                self.per_sample,
                self.accuracy_class,
                self.class_note,
                self.model,
                self.registration,
                self.processing,
                self.height_control,
                self.link_check,
                self.grid,
                more,
                self.zone_editor.widget,
            ],
            layout=w.Layout(width="34%", min_width="340px"),
        )
        # Plan, Cancel, progress, status and error in a bar that stays at the top of the
        # window however far the page is scrolled
        self.toolbar = w.VBox(
            [
                w.HBox(
                    [self.plan_button, self.cancel_button, self.progress],
                    layout=w.Layout(align_items="center"),
                ),
                self.status,
                self.error,
            ]
        )
        self.toolbar.add_class("planner-toolbar")  # (sticky: its boxes do not clip it)
        self.results = w.VBox([self.summary, self.tabs], layout=w.Layout(width="100%"))
        widget = w.VBox(
            [
                self.toolbar,
                w.HBox(
                    [controls, w.VBox([self.stale, self.results], layout=w.Layout(width="64%"))]
                ),
            ]
        )
        widget.add_class("planner-root")
        return widget

    def _reset_state(self) -> None:
        """No plan on screen, nothing running."""
        self.plan = None
        self._handed_out: set[str] = set()  # the sites whose plan's ids went out in a file
        self._kept: dict[str, tuple] = {}  # per site: what its next plan keeps (_remember)
        self._files: dict[str, bytes] = {}  # the downloads of the plan on screen
        self._unshown: set[str] = set()  # tabs not yet drawn for the plan on screen
        self._hints = ""  # what would meet the unmet samples, in the page's words
        self._cancel = threading.Event()
        self._changed = False
        self._worker: threading.Thread | None = None
        self._status_lock = threading.Lock()  # the status line: one writer at a time
        self._ended = threading.Event()  # the background run's end (none yet: ended)
        self._ended.set()
        self.last_edit_s: float | None = None
        self._tmp = upload_folder()

    def _wire(self) -> None:
        """The widgets' events to their handlers (thin callbacks)."""
        # links: thin callbacks
        self.accuracy_class.observe(lambda _c: self._show_class(), "value")
        self.plan_button.on_click(lambda _b: self.start())
        self.cancel_button.on_click(lambda _b: self.cancel())
        self.upload.observe(lambda _c: self._uploaded(), "value")
        self.control_upload.observe(lambda _c: self._control_uploaded(), "value")
        self.quantity.observe(lambda _c: self._redraw("Coverage"), "value")
        self.tabs.observe(lambda _c: self._draw_tab(), "selected_index")
        self.report_button.on_click(lambda _b: self.make_report())
        self.booklet_button.on_click(lambda _b: self.make_booklet())
        self.site_source.observe(lambda _c: self._source_changed(), "value")
        self.buildings.observe(lambda _c: self._offer_facades(), "value")
        for widget in self.inputs:
            widget.observe(lambda _c: self._mark_stale(), "value")
        self.zone_editor.on_change = self._mark_stale
        self._offer_facades()

    # -- honest state ----------------------------------------------------------------------------
    def _mark_stale(self) -> None:
        """The inputs changed since the plan on screen: say so and dim it (Plan makes it
        current again)."""
        with self._status_lock:  # (the run's end takes the lock: no change is lost)
            if not self._ended.is_set():  # the plan being made read the inputs before this
                self._changed = True
                return
        if self.plan is None:
            return
        self._show_stale()

    def _show_stale(self) -> None:
        self.stale.value = (
            "<div class='planner-stale-banner'><b>Out of date:</b> the inputs changed since "
            "this plan was made. Press <b>Plan</b> to plan with them; the plan below is for "
            "the previous inputs.</div>"
        )
        self._dim(True)

    def _dim(self, stale: bool) -> None:
        """Dim (or not) what shows the plan: the summary, the tabs but the map, and on the
        map the plan's marks — not the site drawn there, which is the inputs'."""
        tabs = [t for k, t in enumerate(self.tabs.children) if k != MAP_TAB]
        for box in [self.summary, *tabs]:
            if stale:
                box.add_class("planner-stale")
            else:
                box.remove_class("planner-stale")
        self.map.set_stale(stale)

    def _clear_results(self) -> None:
        """No plan on screen (after an error: the error replaces the old plan)."""
        self.plan = None
        self._files, self._unshown = {}, set()
        self.stale.value = ""
        self._dim(False)
        self.summary.value = ""
        for out in (self.cov_out, self.fac_out, self.unmet_out, self.reg_out, self.field_out):
            show(out)
        show(self.elev_out)
        self.view3d_box.children = []
        self._offer_facades()  # the site alone on the map (or why it cannot be drawn)
        self.downloads.value = "<p>No plan: nothing to download.</p>"
        self.report_status.value = self.booklet_status.value = ""

    def _uploaded(self) -> None:
        files = self.upload.value
        if files:
            f = files[0]
            self.upload_name.value = (
                f"<small class='planner-file'>{html.escape(f['name'])} "
                f"({len(bytes(f['content'])) / 1024:.1f} kB)</small>"
            )
            path = Path(self._tmp.name) / Path(f["name"]).name
            path.write_bytes(bytes(f["content"]))
            self._upload_path = path
        dropped = self._drop_passages()
        self.site_source.value = "Upload a file"
        self._offer_facades()
        self._say_dropped(dropped)
        self.tabs.selected_index = MAP_TAB  # the site uploaded, drawn at once

    def _control_uploaded(self) -> None:
        """A control point file chosen: read at once (a bad file said where it is), used by
        the next plan."""
        files = self.control_upload.value
        if not files:
            return
        f = files[0]
        path = Path(self._tmp.name) / f"control-{Path(f['name']).name}"
        path.write_bytes(bytes(f["content"]))
        try:
            points = read_control(path)
        except PlannerError as exc:
            self._control_path = None
            self.control_name.value = error_html(str(exc))
            return
        self._control_path = path
        self.control_name.value = (
            f"<small class='planner-file'>{html.escape(f['name'])}: {len(points)} control "
            "point(s), tying the stations that see three to the site's frame</small>"
        )

    def _site(self, near_m: float = DEFAULT_NEAR_M, drawing: bool = False):
        """The site chosen (default or uploaded) with the passages drawn on the map, without
        the editor's zones; problems farther than ``near_m`` from the buildings to plan are
        noted, not refused. ``drawing``: read only to draw it (repaired where it can be,
        buildings without a height given :data:`DRAWING_HEIGHT_M`)."""
        ids = self._building_ids() or None
        if self.site_source.value == "Default site":
            site = default_site(buildings=ids)
        else:
            path = self._uploaded_file()
            site = read_site(
                path,
                default_height_m=self.height.value or (DRAWING_HEIGHT_M if drawing else None),
                buildings=ids,
                repair=self.make_valid.value or drawing,
                crs=self.crs.value.strip() or None,
                storey_height_m=self.storey.value,
                near_m=near_m,
            )
        if self.drawn_passages:
            site = replace(site, passages=[*site.passages, *self.drawn_passages])
        if self._control_path is not None:
            site = replace(site, control=[*site.control, *read_control(self._control_path)])
        return site

    def _uploaded_file(self) -> Path:
        if self._upload_path is None:
            raise PlannerError(
                "choose a footprint file (.geojson, .wkt, .csv, .gpkg, .kml or .kmz) to upload "
                "first"
            )
        return self._upload_path

    def _source_changed(self) -> None:
        dropped = self._drop_passages()
        self._offer_facades()
        self._say_dropped(dropped)

    def _drop_passages(self) -> int:
        """Passages drawn on one site do not pass to another: dropped (how many)."""
        n = len(self.drawn_passages)
        self.drawn_passages = []
        return n

    def _say_dropped(self, n: int) -> None:
        if n:
            self.map.status.value += (
                f"<br>{n} passage(s) drawn on the previous site dropped: draw them again on "
                "this one."
            )

    def _offer_facades(self) -> None:
        """The zone editor offers the facades of the site chosen and the map draws it, before
        any plan. A site that cannot be planned is drawn as far as it can be read, the
        features that stop it outlined in red and named on hover (the error says the rest);
        repairs made are crossed where they were made. Drawing never breaks the page: what
        it cannot draw, the map says."""
        try:
            with self._drawing:
                self._draw_site()
        except Exception as exc:  # (a bug in drawing: said on the map, the page works on)
            traceback.print_exc()
            self.map.show_nothing(
                error_html(f"{type(exc).__name__}: {exc}", head="The site cannot be drawn")
            )

    def _draw_site(self) -> None:
        try:
            site = self._site()
        except PlannerError as exc:
            self.zone_editor.facade.options = []
            self.map.show_facades([], np.empty((0, 2)), np.empty((0, 2)))
            self._draw_problems(exc)
            return
        self.zone_editor.show_facades(site)
        ends = self.zone_editor.ends
        starts, stops = (
            np.array([a for a, _ in ends.values()]),
            np.array([b for _, b in ends.values()]),
        )
        self.map.show_facades(list(ends), starts, stops)
        if self.zone_editor.facade.value:  # the facade picked stays picked on the new site
            self.map.show_zone_range(self.zone_editor.facade.value, *self.zone_editor.along.value)
        same = self.plan is not None and {b.id for b in site.buildings} == {
            b.id for b in self.plan.site.buildings
        }
        self.map.show_site(site, keep_plan=same)  # (a plan kept is out of date: dimmed)
        self.map.mark_repairs([(n.x, n.y, n.words()) for n in site.notes if _placed(n)])
        self.map.show_zones(self.zone_editor.ranges())

    def _draw_problems(self, exc: PlannerError) -> None:
        """The site as far as it can be read, with the features ``exc`` names outlined: as a
        site (repaired where it can be, heights filled in), else the file's outlines as
        drawn; where nothing can be read, the reason on the map."""
        problems = getattr(exc, "problems", [])
        named = {i for pr in problems for i in pr.ids}
        words = {i: pr.text for pr in problems for i in pr.ids}
        n = len(problems)
        message = error_html(
            str(exc),
            head=f"The site cannot be planned ({n} problem{'' if n == 1 else 's'}, outlined in "
            "red on the map)",
        )
        try:
            site = self._site(drawing=True) if problems else None
        except PlannerError:
            site = None
        if site is not None:
            features = [
                *((b.id, b.footprint) for b in site.buildings),
                *((o.id, o.geometry) for o in site.obstacles),
                *((a.id, a.geometry) for a in site.passages),
            ]
            self.map.show_site(site, message=message, heights_known=False)
        else:
            try:
                outlines = (
                    read_outlines(self._uploaded_file(), crs=self.crs.value.strip() or None)
                    if self.site_source.value != "Default site"
                    else []
                )
            except PlannerError:
                outlines = []
            if not outlines:
                self.map.show_nothing(error_html(str(exc), head="The site cannot be drawn"))
                return
            features = [(i, g) for i, _role, g in outlines]
            self.map.show_outlines(outlines, message)
        bad = [(i, g) for i, g in features if i in named]
        spots = [(g.representative_point(), words[i]) for i, g in bad]
        self.map.mark_problems([g for _, g in bad], [(q.x, q.y, t) for q, t in spots])

    def _pick_facade(self, facade_id: str) -> None:
        """A wall picked on the map: the zone editor takes it, its whole length the range."""
        if self.zone_editor.facade.value == facade_id:
            self.zone_editor.fit_ranges()  # (picked again: its whole length again)
        self.zone_editor.facade.value = facade_id
        self.map.status.value = (
            f"Facade <b>{html.escape(facade_id)}</b> picked for a zone: drag the orange ends "
            "along the wall to set its range, give its requirement under <b>Zones</b> and "
            "<b>Add zone</b>."
        )

    def _drag_range(self, from_m: float, to_m: float) -> None:
        """The zone's range dragged on the map: the editor's slider follows."""
        self.zone_editor.along.value = (from_m, to_m)

    def _draw_passage(self, xy0: np.ndarray, xy1: np.ndarray) -> None:
        """A passage drawn across a building on the map: checked with the site (a
        :class:`~planner.errors.PlannerError` says why it cannot be one), then kept."""
        taken = {a.id for a in self.drawn_passages}
        n = next(k for k in range(1, len(taken) + 2) if f"drawn-{k}" not in taken)
        line = shapely.LineString([tuple(xy0), tuple(xy1)])
        if line.length < 1.0:
            raise PlannerError("a passage needs two clicks at least 1 m apart, across a building")
        passage = Passage.along(
            f"drawn-{n}", line, self.map.passage_width.value, self.map.passage_height.value
        )
        site = self._site()
        replace(site, passages=[*site.passages, passage])  # the site's checks, or why not
        self.drawn_passages.append(passage)
        self._offer_facades()
        self._mark_stale()
        self.map.status.value = (
            f"Passage <b>{passage.id}</b> drawn ({self.map.passage_width.value:g} m wide, "
            f"{self.map.passage_height.value:g} m clear): <b>Plan</b> to plan with it."
        )

    def _clear_passages(self) -> None:
        if self.drawn_passages:
            self.drawn_passages = []
            self._offer_facades()
            self._mark_stale()

    def _building_ids(self) -> list[str]:
        """The ids in "Buildings to plan" (empty: all of the file's)."""
        return [s.strip() for s in self.buildings.value.split(",") if s.strip()]

    def _toggle_building(self, building_id: str) -> None:
        """A building picked on the map: planned, or left out (the list of buildings to plan
        follows; an empty list plans them all)."""
        ids = self._building_ids()
        if building_id in ids:
            ids.remove(building_id)
        else:
            ids.append(building_id)
        self.buildings.value = ", ".join(ids)

    # -- actions -----------------------------------------------------------------------------
    def _inputs(self):
        cls = self.accuracy_class.value.strip() or None
        more = {name: _field_value(self._specs[name], box) for name, box in self.more.items()}
        req, settings = requirements_and_settings(
            {
                **more,
                "accuracy_class": cls,
                "max_xy_mm": None if cls else (self.max_x.value, self.max_y.value),
                "max_z_mm": None if cls else self.max_z.value,
                "model": self.model.value,
                "registration": self.registration.value,
                "registration_processing": self.processing.value,
                "height_control": self.height_control.value,
                "link_check": self.link_check.value,
                "preset": self.preset.value or None,
                "max_gamma_deg": self.max_gamma.value,
                "max_spacing_mm": _field_value(self._specs["max_spacing_mm"], self.max_spacing),
                "stations_per_sample": int(self.per_sample.value),
                "grid_m": self.grid.value,
                "registration_error": self.registration_error.value,
                "imaging": self.imaging.value,
                "demand_roofs": self.demand_roofs.value,
                "sight_engine": self.sight_engine.value,
                "inventory": parse_inventory(self.inventory.value),
                "surface_condition": self.surface_condition.value,
                "default_material": self.default_material.value or None,
            }
        )
        remember_kit(self.inventory.value)  # (it parsed) the crew's kit for the next session
        scanner = Scanner.from_name(self.scanner.value)
        if self.levelling.value > 0:
            scanner = scanner.with_levelling(self.levelling.value)
        # a problem farther than any station reaches cannot change the plan
        site = self._site(resolve(scanner, req, settings).reach_m)
        if self.zone_editor.zones:
            site = replace(site, zones=[*site.zones, *self.zone_editor.zones])
        return site, scanner, req, settings

    def _offer_presets(self) -> None:
        """The chosen scanner's settings by the maker's names (the command line's
        --preset), "chosen by the plan" first (the coarsest meeting the spacing, else the
        usual one)."""
        sc = Scanner.from_name(self.scanner.value)
        # "" for the plan's choice: a None value would leave the select showing nothing
        self.preset.options = [("chosen by the plan", "")] + [
            (p.name + (" (usual)" if p.name == sc.default_preset else ""), p.name)
            for p in sc.presets
        ]
        self.preset.value = ""
        self.preset.disabled = not sc.presets

    def _show_class(self) -> None:
        """The chosen class, what it means and what it sets (the limit boxes follow it)."""
        text = self.accuracy_class.value.strip()
        for box in (self.max_x, self.max_y, self.max_z):
            box.disabled = bool(text)
        if not text:
            self.class_note.value = ""
            return
        try:
            classes, limits = parse_class(text), class_limits(text)
        except PlannerError as exc:
            self.class_note.value = error_html(str(exc))
            return
        if "max_xy_mm" in limits:
            self.max_x.value = self.max_y.value = limits["max_xy_mm"]
        if "max_z_mm" in limits:
            self.max_z.value = limits["max_z_mm"]
        self.class_note.value = (
            "<small>" + "<br>".join(html.escape(c.describe()) for c in classes) + "</small>"
        )

    def _progress(self, fraction: float, message: str) -> None:
        """The pipeline's progress: the bar, the step and the time so far; Cancel takes
        effect here (the next step the pipeline reports)."""
        if self._cancel.is_set():
            raise _Cancelled
        self.progress.value = fraction
        self._step = message

    def _tick(self, label: str, t0: float, ended: threading.Event) -> None:
        """Elapsed time, about how long is left (:func:`~planner.app.wording.time_words`)
        and the current step, twice a second until the run ``ended`` (after Cancel: that it
        is being cancelled, until the step it is in ends)."""
        while True:
            with self._status_lock:
                if ended.is_set():
                    return
                doing = "cancelling" if self._cancel.is_set() else label
                took = time_words(time.perf_counter() - t0, float(self.progress.value))
                self.status.value = (
                    f"<i>{html.escape(doing)}… {took} — {html.escape(self._step)}</i>"
                )
            if ended.wait(0.5):
                return

    def _begin(self) -> float:
        self._cancel.clear()
        self._changed = False
        self._step = "starting"
        self.error.value = ""
        self.progress.value = 0.0
        self.plan_button.disabled = True
        self.map.reopt.disabled = True
        self.cancel_button.disabled = False
        return time.perf_counter()

    def _work(self, make, label: str, fresh: bool = True) -> str:
        """Run ``make(progress) -> Plan`` and show the result, an error (which replaces the
        plan on screen) or the cancellation (which leaves the previous plan as it was);
        returns the status line that ends the run."""
        t0 = time.perf_counter()
        try:
            p = make(self._progress)
        except _Cancelled:
            return (
                f"<i>cancelled after {time.perf_counter() - t0:.1f} s; the plan on screen "
                "is the previous one</i>"
            )
        except (PlannerError, ValueError) as exc:
            self._clear_results()
            self.error.value = error_html(str(exc))
            return ""
        except Exception as exc:  # never a dead widget: say what happened
            self._clear_results()
            self.error.value = error_html(f"unexpected {type(exc).__name__}: {exc}")
            traceback.print_exc()
            return ""
        self.plan = p
        self._show_results(fresh=fresh)
        took = time.perf_counter() - t0
        return f"<i>{html.escape(label)}: done in {took:.1f} s, at {time.strftime('%H:%M:%S')}</i>"

    def _planner(self):
        """The work of Plan for the inputs on screen (read now, so that edits made while it
        runs mark the result out of date)."""
        try:
            site, sc, req, st = self._inputs()
        except (PlannerError, ValueError) as exc:
            error = exc

            def fail(_progress):
                raise error

            return fail
        if self.plan is not None:
            self._remember(self.plan)
        kept = self._kept.get(site.name)
        if kept is None or not (kept[2] or site.name in self._handed_out):  # from S01
            return lambda progress: plan(site, sc, req, st, progress=progress)
        # the site planned again (a passage, a zone, a setting changed; after an error, too)
        # once its ids went out in a file or the surveyor edited its plan: the ids given
        # stay, and the stations locked or placed by hand are kept where they can still stand
        given, keep, _edited = kept
        return lambda progress: plan(
            site, sc, req, st, progress=progress, locked=keep if len(keep) else None, given=given
        )

    def _remember(self, p) -> None:
        """Keep what a plan of ``p``'s site made next keeps of it (per site, by its name):
        its ids and the stations locked on the map or placed by hand, and whether the
        surveyor edited it (moved, added, deleted or locked stations)."""
        locked = self.map.locked_xy()
        edited = bool(
            len(locked)
            or (p.stations["purpose"] == "hand").any()
            or p.solver.method == "hand placement"
        )
        was = self._kept.get(p.site.name)
        given, keep = user_edits(p, locked)
        self._kept[p.site.name] = (given, keep, edited or (was is not None and was[2]))

    def run(self) -> None:
        """Plan with the current inputs and show the result, waiting for it (the notebook's
        first plan; the Plan button works in the background: :meth:`start`)."""
        self._begin()
        try:
            self.status.value = self._work(self._planner(), "planned")
        finally:
            self._end()

    def _end(self) -> None:
        self.plan_button.disabled = False
        self.map.reopt.disabled = False
        self.cancel_button.disabled = True

    def start(self, make=None, label: str = "planning", fresh: bool = True) -> threading.Thread:
        """Plan in the background (the kernel stays free for Cancel), the elapsed time and
        the current step shown twice a second.

        The status line is written under one lock, and the run's last line ends the ticking
        first: the kernel sends each thread's widget updates in the order they are made, so
        a tick written while the last line was being written could otherwise arrive after it
        and stay on screen as "planning… N s" over a finished plan."""
        if self._worker is not None and self._worker.is_alive():
            return self._worker
        make = make or self._planner()
        t0 = self._begin()
        ended = self._ended = threading.Event()

        def work():
            last = ""
            try:
                last = self._work(make, label, fresh)
            finally:
                try:
                    with self._status_lock:
                        ended.set()
                        self.status.value = last
                        if self._changed and self.plan is not None:  # edited while it ran
                            self._show_stale()
                finally:
                    self._worker = None
                    self._end()

        self._worker = threading.Thread(target=work, daemon=True, name="planner")
        self._worker.start()
        threading.Thread(target=self._tick, args=(label, t0, ended), daemon=True).start()
        return self._worker

    def cancel(self) -> None:
        """Stop the work at the next step it reports."""
        self._cancel.set()
        with self._status_lock:
            if not self._ended.is_set():  # (a run that has ended keeps its last line)
                self.status.value = "<i>cancelling…</i>"

    def evaluate_by_hand(self, xy, ids=None) -> None:
        """The plan with the stations at ``xy`` (the map's edit; ``ids`` the station
        each position is, None for one added), judged at once."""
        self._by_hand(lambda p: evaluate_stations(p, xy, ids))

    def edit_targets_by_hand(self, **edits) -> None:
        """The plan with its targets ruled out, moved or added (the map's edit),
        judged at once (:func:`planner.pipeline.engine.whatif.edit_targets`)."""
        self._by_hand(lambda p: edit_targets(p, **edits))

    def _by_hand(self, edit) -> None:
        if self.plan is None:
            raise PlannerError("make a plan first")
        t0 = time.perf_counter()
        p = edit(self.plan)
        self.last_edit_s = time.perf_counter() - t0
        self.plan = p
        met, n = int(p.scanned["meets"].sum()), len(p.scanned)
        mine = [m for m in p.messages if m.startswith("Targets placed or moved by hand")]
        self.map.show_plan(
            p,
            f"<b>{len(p.stations)} stations, {len(p.targets)} targets</b>: {met} of {n} "
            "samples meet the requirement (registration included) — judged again in "
            f"<span class='planner-edit-s'>{self.last_edit_s:.2f}</span> s"
            + "".join(f"<br>{html.escape(m)}" for m in mine),
            stale=bool(self.stale.value),  # (an out-of-date plan edited stays out of date)
        )
        self._show_results(whatif=False, fresh=False)

    def reoptimise(self, locked_xy) -> None:
        """Keep the locked stations, choose the fewest others around them (background)."""
        base = self.plan
        if base is None:
            self.map.status.value = error_html("make a plan first")
            return
        self.start(
            lambda progress: reoptimise(base, locked_xy, progress), "re-optimising", fresh=False
        )

    def _show_results(self, whatif: bool = True, fresh: bool = True) -> None:
        """Show the plan in every tab; ``fresh`` — made from the inputs on screen (clears
        the out-of-date mark; an edit by hand or a re-optimisation keeps the plan's inputs)."""
        p = self.plan
        if fresh:
            self.stale.value = ""
            self._dim(False)
        n_met = int(p.scanned["meets"].sum())
        n_all = len(p.scanned)
        best_effort = any(m.startswith("Best effort") for m in p.messages)
        verdict = (
            "<span style='color:#1e8449'>every requirement met</span>"
            if p.meets_all
            else f"<span style='color:#922'>{len(p.unmet)} samples unmet</span>"
            + (" — <b>best effort</b>: no position meets some samples" if best_effort else "")
        )
        hints = ""
        if not p.meets_all:
            items = "".join(f"<li>{html.escape(for_dashboard(s))}</li>" for s in suggestions(p))
            hints = f"<p><b>What would meet it:</b></p><ul class='planner-hints'>{items}</ul>"

        self.summary.value = (
            f"<h3><span class='station-count'>{len(p.stations)} stations</span>, "
            f"{len(p.targets)} targets — {verdict}</h3>{hints}"
            f"<p>{n_met} of {n_all} samples meet every requirement.</p>"
            f"<details><summary>Summary</summary><pre style='white-space:pre-wrap;"
            f"font-size:85%'>{html.escape(for_dashboard(p.summary()))}</pre></details>"
        )
        if whatif:
            self.map.show_plan(p, "", stale=not fresh and bool(self.stale.value))
        if not fresh and self.stale.value:
            self._dim(True)
        self._hints = hints
        # the other tabs, and the files to download, are drawn for this plan when opened
        # (an edit by hand does not redraw every tab and every file): the one on screen now
        self._unshown = {name for name in TABS if name != "Map"}
        self._files = {}
        for out in (self.cov_out, self.fac_out, self.unmet_out, self.reg_out, self.field_out):
            show(out)  # (nothing of the previous plan shows meanwhile)
        show(self.elev_out)
        self.view3d_box.children = []
        self.downloads.value = ""
        self._draw_tab()
        self.report_status.value = ""
        self.booklet_status.value = ""
        self.progress.value = 1.0

    def _draw_tab(self) -> None:
        """The tab on screen drawn for the plan on screen, once."""
        name = TABS[self.tabs.selected_index or 0]
        if self.plan is None or name not in self._unshown:
            return
        self._unshown.discard(name)
        draw = {
            "Coverage": self._draw_coverage,
            "Elevations": self._draw_elevations,
            "3-D view": self._draw_3d,
            "Facades": self._draw_facades,
            "Registration": self._draw_registration,
            "Unmet": self._draw_unmet,
            "Stations & field work": self._draw_field_work,
            "As scanned": lambda: None,  # (drawn when a re-plan ends)
            "Downloads": self._offer_downloads,
        }
        draw[name]()

    def _draw_facades(self) -> None:
        show(self.fac_out, self.plan.facade_table())

    def _draw_elevations(self) -> None:
        """The chosen building's facades at their real outlines, samples by station."""
        buildings = elevation_buildings(self.plan)
        if list(self.elev_building.options) != buildings:
            self.elev_building.options = buildings  # (its value: None)
            if buildings:  # the first chosen: its observer draws this tab
                self.elev_building.value = buildings[0]
            return
        if self.elev_building.value is not None:
            show(self.elev_out, plot_elevations(self.plan, self.elev_building.value))

    def _draw_3d(self) -> None:
        """The plan in 3-D: the scene, the samples met and unmet, stations and targets."""
        self.view3d_box.children = [
            w.HTML(
                "<small>Drag to turn, right-drag to pan, scroll to zoom. Samples: green met, "
                "red unmet, grey party wall; stations blue, targets orange.</small>"
            ),
            view_3d(self.plan),
        ]

    def _redraw(self, name: str) -> None:
        """Tab ``name`` drawn again (at once where it is shown)."""
        self._unshown.add(name)
        self._draw_tab()

    def _draw_registration(self) -> None:
        p = self.plan
        network = [m for m in p.messages if m.startswith(("Registration", "Weakest link"))]
        show(
            self.reg_out,
            w.HTML("".join(f"<p>{html.escape(m)}</p>" for m in network)),
            p.links.set_index(["station_a", "station_b"]).round(2),
        )

    def _draw_unmet(self) -> None:
        p = self.plan
        if p.unmet.empty:
            show(self.unmet_out, w.HTML("<p>Every sample meets the requirements.</p>"))
            return
        show(
            self.unmet_out,
            w.HTML("<p><b>Which quantity fails, where, and the worst value there:</b></p>"),
            explain_unmet(p).set_index("quantity"),
            w.HTML(
                self._hints + "<p>Unmet samples by facade and reason (with the best achievable "
                "value):</p>"
            ),
            p.unmet_areas().set_index("facade_id"),
        )

    def _draw_field_work(self) -> None:
        p = self.plan
        if p.route is not None:
            show(
                self.field_out,
                w.HTML(f"<p>{html.escape(p.route.summary())}</p>"),
                p.route.table.set_index("order").round({"x": 3, "y": 3}),
            )

    def _plan_files(self) -> dict[str, bytes]:
        """The files of the plan on screen (made when first asked for), with the report and
        the booklet once they are made."""
        if self.plan is not None and not self._files:
            self._files = {name: text.encode() for name, text in render(self.plan).items()}
            self._handed_out.add(self.plan.site.name)  # its ids are out: a re-plan keeps them
        return self._files

    def _offer_downloads(self) -> None:
        """A link per file of the plan on screen, and plan.zip of them all (with the report
        and the booklet once they are made)."""
        files = self._plan_files()
        links = [download_link(n, data, _MIME[Path(n).suffix]) for n, data in files.items()]
        links.append(download_link("plan.zip", _zip(files), "application/zip"))
        self.downloads.value = "<p>" + "".join(links) + "</p>"

    def _add_download(self, name: str, data: bytes, status: w.HTML) -> None:
        self._plan_files()[name] = data
        self._offer_downloads()
        status.value = download_link(name, data, _MIME[Path(name).suffix]) + (
            "<small>(also in plan.zip)</small>"
        )

    def _draw_coverage(self) -> None:
        if self.plan is not None:
            show(self.cov_out, plot_coverage(self.plan, self.quantity.value))

    def make_report(self) -> None:
        """Render the static HTML report of the current inputs and offer it for download."""

        def build(p) -> bytes:
            out = Path(self._tmp.name) / "report.html"
            make_report(p, out)
            return out.read_bytes()

        self._make(
            "report.html",
            build,
            "rendering the report (a few seconds)",
            self.report_status,
            self.report_button,
        )

    def make_booklet(self) -> None:
        """Render the field booklet of the plan on screen and offer it for download."""
        self._make(
            "booklet.pdf",
            booklet_pdf,
            "drawing the booklet (a page per station)",
            self.booklet_status,
            self.booklet_button,
        )

    def _make(self, name: str, build, doing: str, status: w.HTML, button: w.Button) -> None:
        """Make one more file of the plan on screen (``button`` off meanwhile, news in
        ``status``), then offer it for download and in plan.zip."""
        if self.plan is None:
            status.value = error_html("make a plan first")
            return
        status.value = f"<i>{doing}…</i>"
        button.disabled = True
        try:
            self._add_download(name, build(self.plan), status)
        except Exception as exc:  # the file's own failure, shown where it was asked for
            status.value = error_html(f"the {Path(name).stem} failed: {exc}")
        finally:
            button.disabled = False

    def show(self) -> None:
        display(self.widget)
