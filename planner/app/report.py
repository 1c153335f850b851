"""The static HTML report of a :class:`~planner.pipeline.engine.result.Plan`: one self-contained
HTML file (tables, figures embedded as PNG), opening offline.

:data:`SECTIONS` says what the report holds, section by section; :class:`ReportContent`
makes each piece for one plan. :func:`render_html` writes them as one page directly (no
kernel); the notebook ``report.ipynb`` shows the same sections (:meth:`ReportContent.show`)
for whoever wants the report as a notebook. The report describes exactly the plan it is
given: ``planner report`` builds that plan with the same function as ``planner plan``, the
dashboard passes the plan on screen.
"""

from __future__ import annotations

import base64
import html
import io
import pickle
from pathlib import Path

import matplotlib.pyplot as plt
import pandas as pd
from IPython.display import HTML, display

from planner.app.elevations import elevation_buildings, plot_elevations
from planner.app.maps import plot_coverage, plot_plan_map
from planner.atomic import write_text_atomic
from planner.classes import parse_class
from planner.pipeline.engine.planning import plan
from planner.pipeline.engine.result import Plan
from planner.pipeline.engine.tables import PROCESSING_WORDS
from planner.pipeline.geometry.visibility import SIGHT_CLEARANCE_M
from planner.pipeline.inputs.requirements import PlanSettings, field_specs
from planner.pipeline.inputs.schema import in_id_order
from planner.reference import REFERENCES
from planner.text import printable

__all__ = ["SECTIONS", "ReportContent", "make_report", "render_html"]

#: The report, section by section: its heading, the words under it (HTML) and what it shows
#: (:class:`ReportContent`'s methods, with their arguments). The HTML report and the report
#: notebook both read it.
SECTIONS: list[tuple[str, str, tuple[tuple, ...]]] = [
    ("Terrestrial laser scanning: station plan", "", (("overview",),)),
    ("Site", "", (("site_table",),)),
    ("Scanner and requirements", "", (("scanner_and_requirements",),)),
    ("Plan map", "", (("plan_map",),)),
    (
        "Stations",
        "Coordinates in the site's CRS; the instrument height is above the ground.",
        (("stations",),),
    ),
    (
        "Visiting order and field time",
        "The stations in walking order (round buildings and no-go areas), the targets placed "
        "before each scan, set-up, scan time at the plan's scan step, and the sessions. The "
        "same schedule is in <code>route.csv</code> and the field booklet.",
        (("field_route",),),
    ),
    (
        "Registration targets",
        "Position, type, the smallest size its stations need — the larger of Sossa's 2d / 4d "
        "rule and practice (points per checkerboard quadrant, points on a sphere), "
        "<code>sized_by</code> naming the rule — the item of the inventory to set up, which "
        "way a wall target faces, and the predicted RMS of its fitted centre.",
        (("targets",),),
    ),
    (
        "Registration network",
        "Each station is registered to its parent (or to the control points) by the targets "
        "listed. <code>link_rms_mm</code> is the link's own predicted error at the child "
        "station's facade points, <code>dilution</code> how much the targets' layout "
        "magnifies their centre errors there (lower is stronger), "
        "<code>station_b_rms_mm</code> the whole registration error the child's points end "
        "with, accumulated from the datum.",
        (("registration",), ("registration_coverage",)),
    ),
    (
        "Predicted accuracy on the facades",
        "The total error at every sample — the scanner's from its assigned station and the "
        "registration's, added in quadrature — is what is judged against the requirement.",
        (("coverage", "m_x_mm"), ("coverage", "m_y_mm"), ("coverage", "m_z_mm")),
    ),
    (
        "Facade elevations",
        "Each wall drawn flat at its real outline (from the model: gables, set-back storeys, "
        "sloping walls), the facades of a building side by side; every sample coloured by the "
        "station it is scanned from, a red cross where it is unmet, grey on a party wall.",
        (("elevations",),),
    ),
    ("Per-facade summary", "", (("facades",),)),
    (
        "Zones",
        "Where the client asks for a different requirement: each zone, its requirement and "
        "sampling, and whether its samples meet it.",
        (("zones",),),
    ),
    ("Unmet areas", "", (("unmet",),)),
    ("Assumptions and references", "", (("assumptions",),)),
]


#: The report draws the elevations of this many buildings at most.
ELEVATION_BUILDINGS = 6

#: The visiting order's columns the report shows (those that vary from station to station;
#: ``route.csv`` has them all).
ROUTE_REPORT_COLUMNS = [
    "station_id",
    "session",
    "walk_m",
    "targets_to_set",
    "targets_to_collect",
    "targets_standing",
    "sector_start_deg",
    "sector_deg",
    "scan_min",
    "imaging_min",
    "station_min",
    "elapsed_min",
    "registers_to",
    "walk_note",
]

#: The plan's files a message may name: linked from the report, which is written beside them.
LINKED_FILES = ("site_repairs.csv", "coverage.csv", "route.csv", "targets.csv", "stations.csv")


def _pre(text: str) -> str:
    """Text as it is (escaped), the plan's files it names linked."""
    out = html.escape(text)
    for name in LINKED_FILES:
        out = out.replace(name, f"<a href='{name}'>{name}</a>")
    return f"<pre style='white-space:pre-wrap'>{out}</pre>"


class ReportContent:
    """The pieces of the report for one plan, each ready to ``display``. Every text that
    comes from the user (ids, names, labels, file names) is escaped."""

    def __init__(self, p: Plan) -> None:
        self.plan = p

    def parts(self):
        """Every section: (heading, words, the pieces it shows)."""
        for heading, words, shows in SECTIONS:
            yield heading, words, [getattr(self, name)(*args) for name, *args in shows]

    def show(self) -> None:
        """Display the report section by section (the report notebook's one cell)."""
        for n, (heading, words, pieces) in enumerate(self.parts()):
            tag = "h1" if n == 0 else "h2"
            display(
                HTML(
                    f"<{tag}>{html.escape(heading)}</{tag}>" + (f"<p>{words}</p>" if words else "")
                )
            )
            for piece in pieces:
                display(piece)

    @classmethod
    def load(cls, plan_path: str | None) -> ReportContent:
        """The plan pickled at ``plan_path`` by :func:`make_report`; None: the default site
        planned with the default requirements (when the notebook is run on its own)."""
        if plan_path is None:
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
        return in_id_order(self.plan.stations, "station_id").set_index("station_id").round(3)

    def field_route(self) -> pd.DataFrame | HTML:
        """The visiting order and field time, station by station, after its summary: the
        columns that change from station to station (the others are in the summary line
        and in ``route.csv``)."""
        r = self.plan.route
        if r is None or r.table.empty:
            return HTML("<p>No stations, no field work.</p>")
        t = r.table
        cols = [
            c
            for c in ROUTE_REPORT_COLUMNS
            if c in t and (t[c].nunique() > 1 or c in ("station_id", "station_min"))
        ]
        table = t.set_index("order")[cols].to_html(na_rep="", escape=True)
        return HTML(f"<p>{html.escape(r.summary())}</p><div class='table'>{table}</div>")

    def targets(self) -> pd.DataFrame:
        t = in_id_order(self.plan.targets, "target_id").copy()
        t["station_ids"] = t["station_ids"].map(", ".join)
        return t.set_index("target_id").round(
            {"x": 3, "y": 3, "z": 2, "min_size_mm": 1, "centre_rms_mm": 2}
        )

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
        return _closed(plot_plan_map(self.plan))

    def coverage(self, quantity: str):
        return _closed(plot_coverage(self.plan, quantity))

    def facades(self) -> pd.DataFrame:
        return self.plan.facade_table()

    def elevations(self):
        """The elevations of the first :data:`ELEVATION_BUILDINGS` planned buildings, one
        under the other."""
        ids = elevation_buildings(self.plan)
        shown = ids[:ELEVATION_BUILDINGS]
        fig, axes = plt.subplots(
            len(shown), 1, figsize=(11, 3.2 * len(shown)), layout="constrained", squeeze=False
        )
        for ax, b in zip(axes[:, 0], shown, strict=True):
            plot_elevations(self.plan, b, ax=ax)
        if len(ids) > len(shown):
            fig.suptitle(
                f"The first {len(shown)} of {len(ids)} buildings (the dashboard shows each)",
                fontsize=9,
            )
        return _closed(fig)

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
            reg = (
                "computed from the targets: each target's centre RMS (type, size, distance, "
                "incidence; a sphere's fit bias, a checkerboard's edge sampling); each scan "
                f"registered with {html.escape(p.registration_model() or '')} (heights against "
                "true vertical); propagated to every sample and added in quadrature"
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
    plt.close(fig)
    return fig


def render_html(p: Plan) -> str:
    """The report of plan ``p`` as one self-contained HTML page: every section of
    :data:`SECTIONS`, tables as HTML (empty cells blank), figures as embedded PNG."""
    body = []
    for n, (heading, words, pieces) in enumerate(ReportContent(p).parts()):
        tag = "h1" if n == 0 else "h2"
        body.append(f"<section><{tag}>{html.escape(heading)}</{tag}>")
        if words:
            body.append(f"<p>{words}</p>")
        body += [_as_html(piece) for piece in pieces]
        body.append("</section>")
    title = html.escape(f"tls-planner report: {p.site.name}")
    return (
        f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>{title}</title>'
        f"<style>{_CSS}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n"
    )


def _as_html(piece) -> str:
    """One piece of a section as HTML: text as it is, a table in a scrolling box (empty
    cells blank), a figure as an embedded PNG (closed after)."""
    if isinstance(piece, HTML):
        return piece.data
    if isinstance(piece, pd.DataFrame):
        return f"<div class='table'>{piece.to_html(na_rep='', escape=True)}</div>"
    buf = io.BytesIO()
    piece.savefig(buf, format="png", dpi=100, bbox_inches="tight")
    data = base64.b64encode(buf.getvalue()).decode("ascii")
    return f'<p><img alt="figure" src="data:image/png;base64,{data}"></p>'


_CSS = """
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 13px; margin: 2em auto;
       max-width: 1150px; color: #222; padding: 0 1em; }
h1 { font-size: 22px; } h2 { font-size: 17px; margin-top: 1.6em; border-bottom: 1px solid #ccc; }
.table { overflow-x: auto; max-width: 100%; }
table { border-collapse: collapse; font-size: 11px; margin: 0.5em 0; }
th, td { border: 1px solid #ddd; padding: 2px 6px; text-align: left; vertical-align: top;
         max-width: 22em; overflow-wrap: anywhere; }
th { background: #f3f3f3; }
img { max-width: 100%; height: auto; }
pre { background: #f7f7f7; padding: 0.6em; }
@media print { body { max-width: none; font-size: 10px; } table { font-size: 7.5px; }
               .table { overflow: visible; } section { break-inside: avoid-page; } }
"""


def make_report(p: Plan, out: str | Path) -> Path:
    """Write the report of plan ``p`` to ``out`` (:func:`render_html`), atomically."""
    return write_text_atomic(out, printable(render_html(p), keep="\n\r\t"), create_parents=False)
