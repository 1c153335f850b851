"""The calibration dashboard: upload your calibration measurements, see each step's result and
residual plots, and download or install the scanner profile they give. Thin: the science is
:mod:`planner.calibration`; this module only collects files and shows results.

It starts on the shipped example data (synthetic, with known values), so the page shows what
each step gives before any upload; an upload replaces that step's example.
"""

from __future__ import annotations

import html
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import ipywidgets as w
from IPython.display import display

from planner.app.calibration_plots import (
    example_path,
    plot_axes,
    plot_baseline,
    plot_lab,
    plot_six_segment,
)
from planner.app.widgets import (
    download_link,
    error_html,
    scanner_dropdown,
    show,
    upload_folder,
)
from planner.calibration import (
    BaselineResult,
    axis_errors,
    baseline_calibration,
    lab_test,
    profile_from_calibration,
    six_segment_constant,
    table_columns,
)
from planner.errors import PlannerError
from planner.scanner import Scanner, installed_profile_path, user_profile_dir

__all__ = ["CalibrationDashboard"]

_STYLE = {"description_width": "16em"}

#: Where a profile's figures come from (the choices of the profile's dropdowns): the step whose
#: result gives them, and its files in words.
_SOURCES = {
    "lab": ("lab", "lab files"),
    "baseline": ("distances", "distances file"),
    "axes": ("axes", "axis directions file"),
}
_WIDE = w.Layout(width="95%")


@dataclass
class _Slot:
    """One measurement file: the upload button, the name shown, and the example's name."""

    key: str
    title: str
    columns: str
    example: str
    upload: w.FileUpload
    name: w.HTML

    def path(self, folder: Path) -> tuple[Path, bool]:
        """The file to read (an upload, written to ``folder``, else the example) and whether
        it is the example."""
        files = self.upload.value
        if not files:
            return example_path(self.example), True
        f = files[0]
        p = folder / self.key
        p.mkdir(exist_ok=True)
        p = p / Path(f["name"]).name
        p.write_bytes(bytes(f["content"]))
        return p, False


def _slot(key: str, title: str, columns: str, example: str) -> _Slot:
    upload = w.FileUpload(
        accept=".csv,.txt", multiple=False, description=title, layout=w.Layout(width="22em")
    )
    return _Slot(key, title, columns, example, upload, w.HTML())


class CalibrationDashboard:
    """Lab test (Belgrade procedure), baseline or six-segment distances and axis errors (Liu &
    Zhang) from uploaded files → a scanner profile to download or install."""

    def __init__(self) -> None:
        self._measurement_inputs()
        self._profile_inputs()
        self._quiet = False
        self._replace: str | None = None  # the name whose installed file a 2nd click replaces
        self.results: dict[str, object] = {}
        self.scanner: Scanner | None = None
        self._wire()
        self.widget = self._lay_out()
        self.use_example()

    def _measurement_inputs(self) -> None:
        """The four uploads, the declared precision, the example button and the result tabs."""
        self._tmp = upload_folder()
        self.slots = {
            s.key: s
            for s in (
                _slot("reference", "Lab reference", "id, x, y, z [m]", "lab_reference.csv"),
                _slot("scan", "Lab scan", "id, x, y, z [m]", "lab_scan.csv"),
                _slot(
                    "distances",
                    "Distances",
                    "measured_m, reference_m (baseline) or from, to, distance_m (six-segment)",
                    "baseline.csv",
                ),
                _slot(
                    "axes",
                    "Axis directions",
                    "vertical_angle_deg, observed_deg, reference_deg",
                    "axes.csv",
                ),
            )
        }
        self.precision = w.BoundedFloatText(
            value=2.0,
            min=0.0,
            max=100.0,
            step=0.5,
            description="declared target precision [mm] (0: no check)",
            style={"description_width": "initial"},
            layout=w.Layout(width="30em"),
        )
        self.example = w.Button(
            description="Use the example data", icon="undo", layout=w.Layout(width="16em")
        )
        self.outs = {k: w.Output() for k in ("lab", "distances", "axes")}
        self.tabs = w.Tab(children=[self.outs[k] for k in self.outs])
        for i, title in enumerate(("Lab test", "Distances", "Axis errors")):
            self.tabs.set_title(i, title)

    def _profile_inputs(self) -> None:
        """The profile's name, the base scanner, where each figure comes from, Install."""
        self.name = w.Text(
            value="my-scanner",
            description="profile name",
            style=_STYLE,
            layout=w.Layout(width="36em"),
        )
        self.base = scanner_dropdown()
        self.base.description = "other figures from"
        self.base.style = _STYLE
        self.range_from = w.Dropdown(
            options=[
                ("the distances (baseline residuals)", "baseline"),
                ("the lab test (m_r of distances)", "lab"),
                ("the base profile", None),
            ],
            value="baseline",
            description="ranging RMS from",
            style=_STYLE,
            layout=w.Layout(width="40em"),
        )
        self.angles_from = w.Dropdown(
            options=[
                ("the axis-error residuals (horizontal)", "axes"),
                ("the lab test (m_r of φ and θ)", "lab"),
                ("the base profile", None),
            ],
            value="axes",
            description="angle RMS from",
            style=_STYLE,
            layout=w.Layout(width="40em"),
        )
        self.include_scale = w.Checkbox(
            value=False,
            description="keep the scale R as the ppm part (distances will not be corrected)",
            indent=False,
            layout=w.Layout(width="auto"),
        )
        self.profile_out = w.Output()
        self.download = w.HTML()
        self.install = w.Button(description="Install", icon="download", button_style="primary")
        self.install_status = w.HTML()

    def _wire(self) -> None:
        self.example.on_click(lambda _b: self.use_example())
        self.install.on_click(lambda _b: self.install_profile())
        for s in self.slots.values():
            s.upload.observe(lambda _c, key=s.key: self._uploaded(key), "value")
        self.precision.observe(lambda _c: self._compute("lab"), "value")
        for box in (self.name, self.base, self.range_from, self.angles_from, self.include_scale):
            box.observe(lambda _c: self._profile(), "value")

    def _lay_out(self) -> w.VBox:
        files = [
            w.VBox(
                [
                    w.HBox([s.upload, s.name]),
                    w.HTML(f"<small style='color:#555'>columns: {html.escape(s.columns)}</small>"),
                ]
            )
            for s in self.slots.values()
        ]
        return w.VBox(
            [
                w.HTML("<h3>1 · Measurements</h3>"),
                w.HTML(
                    "Upload your CSV files (comma, semicolon or tab separated). Until you do, "
                    "each step shows the shipped example: synthetic data with known values."
                ),
                *files,
                self.precision,
                self.example,
                w.HTML("<h3>2 · Results and residuals</h3>"),
                self.tabs,
                w.HTML("<h3>3 · The profile</h3>"),
                self.name,
                self.base,
                self.range_from,
                self.angles_from,
                self.include_scale,
                self.profile_out,
                w.HBox([self.download, self.install]),
                self.install_status,
            ],
            layout=w.Layout(max_width="1200px"),
        )

    # -- inputs ------------------------------------------------------------------------------
    def use_example(self) -> None:
        """Every step back on the shipped example data."""
        self._quiet = True  # one computation per step below, not one per cleared upload
        try:
            for s in self.slots.values():
                s.upload.value = ()
        finally:
            self._quiet = False
        for key in self.outs:
            self._compute(key, profile=False)
        self._profile()

    def _uploaded(self, key: str) -> None:
        if not self._quiet:
            self._compute("lab" if key in ("reference", "scan") else key)

    def _names(self, *keys: str) -> None:
        for key in keys:
            s = self.slots[key]
            files = s.upload.value
            s.name.value = (
                f"<small class='calibration-file'>{html.escape(files[0]['name'])} "
                f"({len(bytes(files[0]['content'])) / 1024:.1f} kB)</small>"
                if files
                else f"<small class='calibration-file' style='color:#777'>example: "
                f"{s.example}</small>"
            )

    # -- the steps ---------------------------------------------------------------------------
    def _compute(self, step: str, profile: bool = True) -> None:
        """Run one step on its files and show its result; a failure replaces the result."""
        keys = ("reference", "scan") if step == "lab" else (step,)
        if profile:
            self._withdraw()  # the old profile is not offered beside the new result
        self._names(*keys)
        run: Callable[[], tuple[object, list]] = getattr(self, f"_run_{step}")
        self.results.pop(step, None)
        try:
            result, shown = run()
        except PlannerError as exc:
            show(self.outs[step], w.HTML(error_html(str(exc), "Cannot calibrate")))
        else:
            self.results[step] = result
            show(self.outs[step], *shown)
        if profile:
            self._profile()

    def _paths(self, *keys: str) -> tuple[list[Path], bool]:
        folder = Path(self._tmp.name)
        out = [self.slots[k].path(folder) for k in keys]
        return [p for p, _ in out], all(ex for _, ex in out)

    @staticmethod
    def _text(lines: list[str], warnings: list[str] = (), example: bool = False) -> w.HTML:
        head = "<p><i>Example data (synthetic, known values).</i></p>" if example else ""
        warn = "".join(f"<li class='calibration-warning'>{html.escape(t)}</li>" for t in warnings)
        return w.HTML(
            head
            + "<pre style='margin:0'>"
            + html.escape("\n".join(lines))
            + "</pre>"
            + (f"<ul style='color:#8a5a00'>{warn}</ul>" if warn else "")
        )

    def _run_lab(self):
        (ref, scan), example = self._paths("reference", "scan")
        t = lab_test(ref, scan, declared_target_precision_mm=self.precision.value or None)
        lines = t.lines()
        if t.network:
            lines.append(t.network)
        return t, [
            self._text(lines, t.warnings, example),
            t.summary().round(2),
            plot_lab(t),
        ]

    def _run_distances(self):
        (path,), example = self._paths("distances")
        if {"from", "to", "distance_m"} <= table_columns(path):
            r = six_segment_constant(path)
            note = (
                "The six-segment method gives the additive constant only: correct your "
                "distances by k; the ranging RMS of a profile comes from a baseline comparison "
                "or the lab test."
            )
            return r, [self._text([*r.lines(), "", note], [], example), plot_six_segment(r)]
        r = baseline_calibration(path)
        return r, [self._text(r.lines(), r.warnings, example), plot_baseline(r)]

    def _run_axes(self):
        (path,), example = self._paths("axes")
        r = axis_errors(path)
        return r, [self._text(r.lines(), [], example), plot_axes(r)]

    # -- the profile -------------------------------------------------------------------------
    def _profile(self) -> None:
        """The profile of the chosen figures; nothing to download while it cannot be made."""
        self._withdraw()
        baseline = self.results.get("distances")
        try:
            for source in (self.range_from.value, self.angles_from.value):
                key, what = _SOURCES.get(source, (None, ""))
                if key is not None and key not in self.results:
                    raise PlannerError(
                        f"the figures chosen come from the {what}, which gave no result "
                        "(see its tab); upload a good file or choose another source"
                    )
            if self.range_from.value == "baseline" and not isinstance(baseline, BaselineResult):
                raise PlannerError(
                    "ranging from the distances needs a baseline comparison (measured_m, "
                    "reference_m); a six-segment file gives the additive constant only — "
                    "choose the lab test or the base profile"
                )
            scanner, notes = profile_from_calibration(
                self.name.value.strip(),
                base=Scanner.from_name(self.base.value),
                lab=self.results.get("lab"),
                baseline=baseline if isinstance(baseline, BaselineResult) else None,
                axes=self.results.get("axes"),
                range_from=self.range_from.value,
                angles_from=self.angles_from.value,
                include_scale=self.include_scale.value,
            )
            toml = scanner.profile_file_text()
        except PlannerError as exc:
            show(self.profile_out, w.HTML(error_html(str(exc), "No profile")))
            return
        self.scanner = scanner
        lines = [
            f"ranging {scanner.range_rms_mm:.2f} mm + {scanner.range_ppm:.1f} ppm, angles "
            f"{scanner.angle_rms_arcsec:.1f}″ horizontal, {scanner.tilt_rms_arcsec:.1f}″ "
            f"vertical; the rest from {self.base.value}",
        ]
        show(
            self.profile_out,
            self._text(lines, notes),
            w.HTML(
                "<details><summary>the profile file</summary><pre class='calibration-toml'>"
                + html.escape(toml)
                + "</pre></details>"
            ),
        )
        self.download.value = download_link(
            f"{scanner.name}.toml", toml.encode("utf-8"), "application/toml"
        )
        self.install.disabled = False

    def _withdraw(self) -> None:
        """No profile on offer: no download, no install."""
        self.scanner = None
        self.download.value = ""
        self.install.disabled = True
        self.install_status.value = ""
        self._replace = None

    def install_profile(self) -> None:
        """Install the profile in the user's profile folder, to choose it by name in the
        planner (the command line's ``--install``); an installed profile of the same name is
        replaced only on a second click."""
        if self.scanner is None:
            return
        try:
            path = installed_profile_path(self.scanner.name)
        except PlannerError as exc:
            self.install_status.value = error_html(str(exc), "Not installed")
            return
        if path.exists() and self._replace != self.scanner.name:
            self._replace = self.scanner.name
            self.install_status.value = (
                f"<span class='calibration-installed'>A profile {self.scanner.name!r} is "
                f"installed already ({html.escape(str(path))}); press Install again to replace "
                "it, or choose another name.</span>"
            )
            return
        self.scanner.save(path)
        self._replace = None
        self.install_status.value = (
            f"<span class='calibration-installed'>Installed {self.scanner.name!r} in "
            f"{html.escape(str(user_profile_dir()))}: choose it in the station planner (reload "
            f"the page) or use <code>--scanner {self.scanner.name}</code>.</span>"
        )

    def show(self) -> None:
        display(self.widget)
