"""The static HTML report: the parameterised notebook ``report.ipynb`` executed headless
(nbclient) and exported without code (nbconvert), images embedded, opening offline.

:class:`ReportContent` is what the notebook's cells display; :func:`make_report` runs it.
"""

from __future__ import annotations

import html
import re
import tempfile
from pathlib import Path
from typing import Any

import nbformat
import pandas as pd
from IPython.display import Markdown

from planner.errors import InputError, PlannerError
from planner.io import write_text_atomic
from planner.planning import Plan, plan
from planner.requirements import PlanSettings, Requirements
from planner.scanner import load_scanner

__all__ = ["ReportContent", "make_report"]

PARAMETERS = (
    "site_path",
    "default_height_m",
    "buildings",
    "scanner",
    "max_xy_mm",
    "max_z_mm",
    "max_gamma_deg",
    "max_spacing_mm",
    "stations_per_sample",
    "grid_m",
)


def _inputs(
    site_path=None,
    default_height_m=None,
    buildings=None,
    scanner="leica-4mm-60urad",
    max_xy_mm=5.0,
    max_z_mm=5.0,
    max_gamma_deg=75.0,
    max_spacing_mm=None,
    stations_per_sample=1,
    grid_m=2.0,
):
    from planner.siteio import default_site, read_site

    if site_path:
        site = read_site(site_path, default_height_m=default_height_m, buildings=buildings)
    else:
        site = default_site(buildings=buildings)
    xy = tuple(max_xy_mm) if isinstance(max_xy_mm, list | tuple) else max_xy_mm
    req = Requirements(
        max_xy_mm=xy,
        max_z_mm=max_z_mm,
        max_gamma_deg=max_gamma_deg,
        max_spacing_mm=max_spacing_mm,
        stations_per_sample=stations_per_sample,
    )
    return site, load_scanner(scanner), req, PlanSettings(grid_m=grid_m)


class ReportContent:
    """The pieces of the report for one plan, each ready to ``display``."""

    def __init__(self, p: Plan) -> None:
        self.plan = p

    @classmethod
    def from_parameters(cls, **params: Any) -> ReportContent:
        return cls(plan(*_inputs(**params)))

    def overview(self) -> Markdown:
        p = self.plan
        verdict = (
            "**every requirement is met**"
            if p.meets_all
            else f"**{len(p.unmet)} samples are not met**"
        )
        return Markdown(
            f"Site **{p.site.name}**, scanner **{p.scanner.label}** (`{p.scanner.name}`): "
            f"{len(p.stations)} stations and {len(p.targets)} registration targets; {verdict}.\n\n"
            + "```\n"
            + p.summary()
            + "\n```"
        )

    def site_table(self) -> pd.DataFrame:
        p = self.plan
        rows = [
            {
                "feature": b.id,
                "role": "building" + (" (planned)" if b.planned else " (blocks only)"),
                "height_m": b.height_m,
                "area_m2": round(b.footprint.area, 1),
            }
            for b in p.site.buildings
        ]
        rows += [
            {
                "feature": o.id,
                "role": o.kind,
                "height_m": o.height_m,
                "area_m2": round(o.geometry.area, 1),
            }
            for o in p.site.obstacles
        ]
        rows += [
            {
                "feature": a.id,
                "role": "no-go",
                "height_m": None,
                "area_m2": round(a.geometry.area, 1),
            }
            for a in p.site.no_go
        ]
        return pd.DataFrame(rows).set_index("feature")

    def scanner_and_requirements(self) -> pd.DataFrame:
        p = self.plan
        sc, req, st = p.scanner, p.requirements, p.settings
        rows = [
            ("scanner", f"{sc.label} ({sc.name})"),
            ("ranging RMS", f"{sc.range_rms_mm:g} mm + {sc.range_ppm:g} ppm"),
            (
                "angular RMS",
                f"{sc.angle_rms_arcsec:g}″ horizontal, {sc.tilt_rms_arcsec:g}″ vertical",
            ),
            (
                "range, vertical field",
                f"{sc.min_range_m:g}–{sc.max_range_m:g} m, "
                f"{sc.vertical_fov_deg[0]:g}° to {sc.vertical_fov_deg[1]:g}°",
            ),
            ("source of the figures", sc.source),
            ("required m_x, m_y, m_z", f"{req.max_x_mm:g}, {req.max_y_mm:g}, {req.max_z_mm:g} mm"),
            ("largest deviation γ", f"{req.max_gamma_deg:g}°"),
            (
                "largest point spacing",
                f"{req.max_spacing_mm:g} mm" if req.max_spacing_mm else "not required",
            ),
            ("stations per sample", str(req.stations_per_sample)),
            ("candidate grid, clearance", f"{st.grid_m:g} m, {st.clearance_m:g} m"),
            (
                "facade samples",
                f"every {st.sample_spacing_m:g} m along, {st.sample_height_step_m:g} m up",
            ),
            ("instrument height", f"{st.instrument_height_m:g} m"),
        ]
        return pd.DataFrame(rows, columns=["item", "value"]).set_index("item")

    def stations(self) -> pd.DataFrame:
        return self.plan.stations.set_index("station_id").round(3)

    def targets(self) -> pd.DataFrame:
        t = self.plan.targets.copy()
        t["station_ids"] = t["station_ids"].map(", ".join)
        return t.set_index("target_id").round({"x": 3, "y": 3, "z": 2, "min_size_mm": 1})

    def plan_map(self):
        from planner.maps import plot_plan_map

        return _closed(plot_plan_map(self.plan))

    def coverage(self, quantity: str):
        from planner.maps import plot_coverage

        return _closed(plot_coverage(self.plan, quantity))

    def facades(self) -> pd.DataFrame:
        return self.plan.facade_table()

    def unmet(self):
        u = self.plan.unmet
        if u.empty:
            return Markdown("Every facade sample meets every requirement.")
        return (
            u.groupby(["facade_id", "reason"])
            .agg(samples=("sample_id", "size"), z_from=("z", "min"), z_to=("z", "max"))
            .round(1)
        )

    def assumptions(self) -> Markdown:
        p = self.plan
        notes = "\n".join(f"- {html.escape(m)}" for m in p.messages) or "- none"
        return Markdown(
            "- Accuracy: m_x, m_y by eq. 2 and m_z by eq. 4 (S₀ = S, m_ν0 = m_ν) of Voroshilov & "
            "Karachentsev, with the ranging RMS at the slope distance; station/registration RMS "
            f"{p.settings.station_rms_mm} mm.\n"
            "- Visibility: 2.5-D — footprints extruded to their heights block the beam; "
            "flat ground.\n"
            "- Target sizes: Sossa's 2d (flat) / 4d (sphere, cylinder) rule at the farther "
            "station, a flat target seen at incidence θ needing 2d / cos θ.\n"
            f"- Scanner notes: {html.escape(p.scanner.notes or 'none')}\n\n"
            f"Messages of the planner:\n\n{notes}\n\n"
            "**References.** A.P. Voroshilov, Y.A. Karachentsev, *Choice of station location at "
            "surface laser scanning of buildings and constructions* (eq. 1–4, Tables 1–2). "
            "B. Sossa, *Determination of optimal type and size of plane-based targets used in TLS "
            "calibration*, Inzhenerna heodeziia 65 (2018) (Tables 1–2). Laboratory uncertainty of "
            "TLS (Belgrade metrological laboratory) and Chinese papers on TLS calibration for the "
            "scanner figures."
        )


def _closed(fig):
    """Close a figure so it is shown once, as the cell's value (not again by pyplot)."""
    import matplotlib.pyplot as plt

    plt.close(fig)
    return fig


def _parameter_cell(params: dict[str, Any]) -> nbformat.NotebookNode:
    lines = ["# injected parameters"] + [f"{k} = {v!r}" for k, v in params.items()]
    cell = nbformat.v4.new_code_cell("\n".join(lines))
    cell.metadata["tags"] = ["injected-parameters"]
    return cell


def make_report(out: str | Path, *, timeout_s: int = 600, **params: Any) -> Path:
    """Execute the report notebook with ``params`` and write a self-contained HTML file.

    Parameters are those of the notebook's parameters cell (see :data:`PARAMETERS`); they
    are checked (site read, requirements validated) before the notebook runs.
    """
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError
    from nbconvert import HTMLExporter

    from planner.dashboard import notebook_path

    unknown = set(params) - set(PARAMETERS)
    if unknown:
        raise InputError(
            f"unknown report parameter(s) {', '.join(sorted(unknown))}; "
            f"known: {', '.join(PARAMETERS)}"
        )
    if params.get("site_path"):
        params["site_path"] = str(Path(params["site_path"]).resolve())
    _inputs(**params)  # bad input stops here, with the planner's message
    nb = nbformat.read(notebook_path("report.ipynb"), as_version=4)
    at = next((i for i, c in enumerate(nb.cells) if "parameters" in c.metadata.get("tags", [])), -1)
    nb.cells.insert(at + 1, _parameter_cell(params))
    with tempfile.TemporaryDirectory(prefix="planner-report-") as tmp:
        client = NotebookClient(
            nb, timeout=timeout_s, kernel_name="python3", resources={"metadata": {"path": tmp}}
        )
        try:
            client.execute()
        except CellExecutionError as exc:
            raise PlannerError(
                f"the report notebook failed: {str(exc).strip().splitlines()[-1]}"
            ) from None
    exporter = HTMLExporter(
        template_name="lab",
        exclude_input=True,
        exclude_input_prompt=True,
        exclude_output_prompt=True,
    )
    body, _ = exporter.from_notebook_node(nb)
    return write_text_atomic(out, _offline(body))


_EXTERNAL = re.compile(r"<script[^>]+src=\"https?://[^\"]+\"[^>]*>\s*</script>", re.I)


def _offline(body: str) -> str:
    """Drop scripts fetched from the network (MathJax, require.js): the report has no maths
    to typeset and no widgets to run, and must open offline."""
    return _EXTERNAL.sub("", body)
