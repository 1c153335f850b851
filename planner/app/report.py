"""The static HTML report: the notebook ``report.ipynb`` executed headless (nbclient) on a
given :class:`~planner.pipeline.result.Plan` and exported without code (nbconvert), images
embedded, opening offline.

The report describes exactly the plan it is given: ``planner report`` builds that plan with
the same function as ``planner plan``, the dashboard passes the plan on screen.
:class:`ReportContent` is what the notebook's cells display; :func:`make_report` runs it.
"""

from __future__ import annotations

import html
import pickle
import re
import tempfile
from pathlib import Path
from typing import Any

import pandas as pd
from IPython.display import HTML

from planner.atomic import write_text_atomic
from planner.errors import PlannerError
from planner.pipeline.planning import PROCESSING_WORDS
from planner.pipeline.requirements import PlanSettings, field_specs
from planner.pipeline.result import Plan
from planner.pipeline.visibility import SIGHT_CLEARANCE_M
from planner.reference import REFERENCES

__all__ = ["ReportContent", "make_report"]


def _pre(text: str) -> str:
    return f"<pre style='white-space:pre-wrap'>{html.escape(text)}</pre>"


class ReportContent:
    """The pieces of the report for one plan, each ready to ``display``. Every text that
    comes from the user (ids, names, labels, file names) is escaped."""

    def __init__(self, p: Plan) -> None:
        self.plan = p

    @classmethod
    def load(cls, plan_path: str | None) -> ReportContent:
        """The plan pickled at ``plan_path`` by :func:`make_report`; None: the default site
        planned with the default requirements (when the notebook is run on its own)."""
        if plan_path is None:
            from planner.pipeline.planning import plan

            return cls(plan())
        with open(plan_path, "rb") as fh:
            return cls(pickle.load(fh))

    def overview(self) -> HTML:
        p = self.plan
        verdict = (
            "<b>every requirement is met</b>"
            if p.meets_all
            else f"<b>{len(p.unmet)} samples are not met</b>"
        )
        return HTML(
            f"<p>Site <b>{html.escape(p.site.name)}</b>, scanner "
            f"<b>{html.escape(p.scanner.label)}</b> (<code>{html.escape(p.scanner.name)}"
            f"</code>): {len(p.stations)} stations and {len(p.targets)} registration "
            f"targets; {verdict}.</p>" + _pre(p.summary())
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
        """The scanner's figures, every requirement (from the table of checks) and every
        setting (from the data class), as one table."""
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
            ("requirement", req.describe()),
        ]
        if req.accuracy_class:
            from planner.classes import parse_class

            for c in parse_class(req.accuracy_class):
                rows.append((f"class {c.name}", f"{c.describe()} — {c.source}"))
        rows.append(("accuracy model", st.model_description()))
        for name, spec in field_specs(PlanSettings).items():
            value = getattr(st, name)
            shown = "the scanner's" if value is None else f"{value} {spec.unit}"
            rows.append((spec.label, shown))
        rows.append(("method", st.method))
        rows.append(
            (
                "target inventory",
                ", ".join(f"{i.name} ({i.type} {i.size_mm:g} mm)" for i in st.inventory),
            )
        )
        return pd.DataFrame(rows, columns=["item", "value"]).set_index("item")

    def stations(self) -> pd.DataFrame:
        return self.plan.stations.set_index("station_id").round(3)

    def field_route(self) -> pd.DataFrame | HTML:
        """The visiting order and field time, station by station, after its summary."""
        r = self.plan.route
        if r is None or r.table.empty:
            return HTML("<p>No stations, no field work.</p>")
        display_html = HTML(f"<p>{html.escape(r.summary())}</p>")
        cols = [c for c in r.table.columns if c not in ("x", "y")]
        return HTML(display_html.data + r.table[cols].set_index("order").to_html(na_rep=""))

    def targets(self) -> pd.DataFrame:
        t = self.plan.targets.copy()
        t["station_ids"] = t["station_ids"].map(", ".join)
        return t.set_index("target_id").round({"x": 3, "y": 3, "z": 2, "min_size_mm": 1})

    def registration(self) -> pd.DataFrame | HTML:
        links = self.plan.links
        if links.empty:
            return HTML(f"<p>{html.escape(self._network_message())}</p>")
        return links.set_index(["station_a", "station_b"]).round(2)

    def registration_coverage(self):
        """The registration part of the error on the facades, for its largest component."""
        cov = self.plan.scanned
        parts = ["reg_m_x_mm", "reg_m_y_mm", "reg_m_z_mm"]
        if cov[parts].isna().all().all():
            return HTML("<p>No registration error is computed for this plan.</p>")
        return self.coverage(cov[parts].max().idxmax())

    def _network_message(self) -> str:
        msg = [m for m in self.plan.messages if m.startswith("Registration:")]
        return msg[0] if msg else "No registration network."

    def plan_map(self):
        from planner.app.maps import plot_plan_map

        return _closed(plot_plan_map(self.plan))

    def coverage(self, quantity: str):
        from planner.app.maps import plot_coverage

        return _closed(plot_coverage(self.plan, quantity))

    def facades(self) -> pd.DataFrame:
        return self.plan.facade_table()

    def zones(self) -> pd.DataFrame | HTML:
        z = self.plan.zones
        if z.empty:
            return HTML("<p>No zones: the site-wide requirement applies everywhere.</p>")
        return z.set_index("zone_id")

    def unmet(self) -> pd.DataFrame | HTML:
        areas = self.plan.unmet_areas()
        if areas.empty:
            return HTML("<p>Every facade sample meets every requirement.</p>")
        return areas.set_index(["facade_id", "reason"])

    def assumptions(self) -> HTML:
        p = self.plan
        notes = "".join(f"<li>{html.escape(m)}</li>" for m in p.messages) or "<li>none</li>"
        refs = "".join(f"<li>{html.escape(text)}</li>" for text in REFERENCES.values())
        st = p.settings
        if not st.computes_registration:
            reg = (
                f"a fixed station RMS of {html.escape(str(st.station_rms_mm))} mm (given)"
                if st.station_rms_pair != (0.0, 0.0)
                else "not counted (scanner error only)"
            )
        else:
            together = (
                "every scan's targets adjusted together to the datum"
                if st.registration_processing == "adjustment"
                else "each scan registered to the one before it along the links"
            )
            reg = (
                "computed from the targets: each target's centre RMS (type, size, distance, "
                f"incidence; a sphere's fit bias, a checkerboard's edge sampling), {together}, "
                "the datum's levelling turning the whole network (heights against true "
                "vertical), propagated to every sample and added in quadrature"
            )
        items = [
            f"Accuracy model: {html.escape(st.model_description())}, the ranging RMS at "
            "the slope distance (docs/science.md of tls-planner).",
            f"Registration error: {reg}."
            + (
                f" {PROCESSING_WORDS[st.registration_processing]}"
                if st.computes_registration
                else ""
            ),
            "Visibility: 2.5-D — footprints extruded to their heights block the beam, every "
            f"sight line keeping {SIGHT_CLEARANCE_M * 1000:.0f} mm from their edges, corners "
            "and roof edges; flat ground; the spheres on their stands, set up together, hide "
            "the targets behind them.",
            "Target sizes: the larger of Sossa's 2d (flat) / 4d (sphere, cylinder) rule (2d / "
            "cos θ on a wall seen at incidence θ) and practice "
            f"({st.min_points_per_quadrant:g} points per checkerboard quadrant, "
            f"{st.min_points_on_sphere:g} points on a sphere), at the most demanding station; "
            f"checkerboards used up to {st.max_target_incidence_deg:g}° incidence.",
            f"Scanner notes: {html.escape(p.scanner.notes or 'none')}",
        ]
        return HTML(
            "<ul>"
            + "".join(f"<li>{i}</li>" for i in items)
            + "</ul><p>Messages of the planner:</p><ul>"
            + notes
            + "</ul><p><b>References.</b></p><ul>"
            + refs
            + "</ul>"
        )


def _closed(fig):
    """Close a figure so it is shown once, as the cell's value (not again by pyplot)."""
    import matplotlib.pyplot as plt

    plt.close(fig)
    return fig


def _parameter_cell(params: dict[str, Any]):
    import nbformat

    lines = ["# injected parameters"] + [f"{k} = {v!r}" for k, v in params.items()]
    cell = nbformat.v4.new_code_cell("\n".join(lines))
    cell.metadata["tags"] = ["injected-parameters"]
    return cell


def make_report(p: Plan, out: str | Path, *, timeout_s: int = 600) -> Path:
    """Execute the report notebook on the plan ``p`` and write a self-contained HTML file."""
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError
    from nbconvert import HTMLExporter

    from planner.app.notebooks import notebook_path

    nb = nbformat.read(notebook_path("report.ipynb"), as_version=4)
    with tempfile.TemporaryDirectory(prefix="planner-report-") as tmp:
        plan_file = Path(tmp) / "plan.pickle"
        with open(plan_file, "wb") as fh:
            pickle.dump(p, fh, protocol=pickle.HIGHEST_PROTOCOL)
        at = next(
            (i for i, c in enumerate(nb.cells) if "parameters" in c.metadata.get("tags", [])), -1
        )
        nb.cells.insert(at + 1, _parameter_cell({"plan_path": str(plan_file)}))
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
    return write_text_atomic(out, _offline(body), create_parents=False)


_EXTERNAL = re.compile(r"<script[^>]+src=\"https?://[^\"]+\"[^>]*>\s*</script>", re.I)


def _offline(body: str) -> str:
    """Drop scripts fetched from the network (MathJax, require.js): the report has no maths
    to typeset and no widgets to run, and must open offline."""
    return _EXTERNAL.sub("", body)
