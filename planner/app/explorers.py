"""The explorers' dashboards: light, with no plan behind them.

* :class:`AccuracyExplorer` — m_x, m_y, m_z curves and tables for a scanner;
* :class:`TargetExplorer` — target sizes vs distance and an inventory's reach.
"""

from __future__ import annotations

import html

import ipywidgets as w
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from IPython.display import display

from planner.accuracy import max_distance_m
from planner.accuracy3d import max_distance_3d_m
from planner.app.curves import plot_height, plot_models, plot_planimetric, plot_target_sizes
from planner.app.widgets import error_html, inventory_box, scanner_dropdown, show
from planner.errors import PlannerError
from planner.polar import slope_distance_m
from planner.reference import compare_table1, compare_table2
from planner.scanner import DEFAULT_SCANNER, Scanner
from planner.tables import SOSSA_DISTANCES_M, height_table, planimetric_table, target_size_table
from planner.targets import SOSSA_STEP_MM_AT_10M, parse_inventory, recommend_targets

__all__ = ["AccuracyExplorer", "TargetExplorer"]


class AccuracyExplorer:
    """Curves and tables of m_x, m_y (eq. 2) and m_z (eq. 4) for a chosen or typed scanner."""

    def __init__(self) -> None:
        style = {"description_width": "12em"}
        paper = Scanner.from_name(DEFAULT_SCANNER)  # typed figures start from the paper's
        self.source = w.ToggleButtons(options=["Catalogue", "Typed figures"], value="Catalogue")
        self.scanner = scanner_dropdown()
        self.range_mm = w.BoundedFloatText(
            value=paper.range_rms_mm,
            min=0.01,
            max=100,
            step=0.1,
            description="ranging a [mm]",
            style=style,
        )
        self.range_ppm = w.BoundedFloatText(
            value=paper.range_ppm,
            min=0,
            max=1000,
            step=10,
            description="ranging b [ppm]",
            style=style,
        )
        self.h_angle = w.BoundedFloatText(
            value=paper.angle_rms_arcsec,
            min=0.01,
            max=5000,
            step=0.1,
            description="H angle RMS [″]",
            style=style,
        )
        self.v_angle = w.BoundedFloatText(
            value=paper.tilt_rms_arcsec,
            min=0.01,
            max=5000,
            step=0.1,
            description="V angle RMS [″]",
            style=style,
        )
        # the sliders redraw on release, not at every step of a drag: a redraw takes about
        # 1.5 s (two figures), and the steps of a drag would queue up behind it
        slider = {"min": 0.0, "step": 5.0, "style": style, "continuous_update": False}
        self.distance = w.FloatRangeSlider(
            value=(0.0, 120.0),
            max=300.0,
            description="distance [m]",
            layout=w.Layout(width="95%"),
            **slider,
        )
        self.gamma = w.FloatSlider(value=30.0, max=85.0, description="γ [deg]", **slider)
        self.nu = w.FloatSlider(value=30.0, max=90.0, description="ν [deg]", **slider)
        self.limit = w.BoundedFloatText(
            value=4.0, min=0.1, max=100, step=0.5, description="requirement [mm]", style=style
        )
        self.verdict = w.HTML()
        self.plots = w.Output()
        self.tables = w.Output()
        self.error = w.HTML()
        inputs = [
            self.source,
            self.scanner,
            self.range_mm,
            self.range_ppm,
            self.h_angle,
            self.v_angle,
            self.distance,
            self.gamma,
            self.nu,
            self.limit,
        ]
        for widget in inputs:
            widget.observe(lambda _c: self.update(), "value")
        self.widget = w.VBox(
            [
                w.HBox([w.VBox(inputs[:6]), w.VBox(inputs[6:])]),
                self.error,
                self.verdict,
                self.plots,
                self.tables,
            ]
        )

    def current_scanner(self) -> Scanner:
        if self.source.value == "Catalogue":
            return Scanner.from_name(self.scanner.value)
        return Scanner(
            name="typed",
            range_rms_mm=self.range_mm.value,
            range_ppm=self.range_ppm.value,
            angle_rms_arcsec=self.h_angle.value,
            vertical_angle_rms_arcsec=self.v_angle.value,
            label="typed figures",
        )

    def update(self) -> None:
        self.error.value = ""
        try:
            sc = self.current_scanner()
        except PlannerError as exc:
            self.error.value = error_html(str(exc))
            return
        lo, hi = self.distance.value
        hi = max(hi, lo + 5.0)
        g, nu, limit = self.gamma.value, self.nu.value, self.limit.value
        lines = []
        for name in ("m_x", "m_y", "m_z"):
            reach_paper = float(max_distance_m(limit, sc, name, nu if name == "m_z" else g))
            if name != "m_z":  # eq. 2 works in the horizontal distance D = S·cos ν
                reach_paper = slope_distance_m(reach_paper, nu)
            reach_3d = float(max_distance_3d_m(limit, sc, name, g, nu, incidence_noise=True))
            lines.append(
                f"{name} ≤ {limit:g} mm at γ = {g:g}°, ν = {nu:g}°: "
                f"paper {_reach_text(reach_paper, lo, hi)}; 3-D {_reach_text(reach_3d, lo, hi)}"
            )
        self.verdict.value = "<ul>" + "".join(f"<li>{html.escape(t)}</li>" for t in lines) + "</ul>"
        fig, axes = plt.subplots(1, 3, figsize=(13, 3.8), layout="constrained")
        plot_planimetric(
            sc, sorted({0.0, 30.0, 60.0, g}), hi, axes=axes[:2], paper=sc.name == DEFAULT_SCANNER
        )
        plot_height(
            sc,
            sorted({0.0, 30.0, 60.0, 90.0, nu}),
            hi,
            ax=axes[2],
            paper=sc.name == DEFAULT_SCANNER,
        )
        for ax in axes:
            ax.axhline(limit, color="crimson", lw=0.8, ls="--")
            ax.set_xlim(lo, hi)
            ax.set_title(ax.get_title(), fontsize=10)
        fig.suptitle(
            f"The paper's tables for {sc.label}: eq. 2 (m_x, m_y vs D), eq. 4 (m_z vs S)",
            fontsize=11,
        )
        models = plot_models(sc, g, nu, hi, limit_mm=limit)
        for ax in models.axes:
            ax.set_xlim(lo, hi)
        show(self.plots, fig, models)
        t1 = planimetric_table(sc)
        t1.columns = [f"{a} γ={b:g}°" for a, b in t1.columns]
        t2 = height_table(sc)
        t2.columns = [f"m_z ν={v:g}°" for v in t2.columns]
        items = [
            w.HTML("<b>Table 1 layout (eq. 2), mm</b>"),
            t1.round(2),
            w.HTML("<b>Table 2 layout (eq. 4, S₀ = S), mm</b>"),
            t2.round(2),
        ]
        if sc.name == DEFAULT_SCANNER:
            mis = pd.concat(
                [
                    compare_table1().query("misprint").reset_index().assign(table="Table 1"),
                    compare_table2().query("misprint").reset_index().assign(table="Table 2"),
                ]
            )
            items += [
                w.HTML(
                    "<b>Cells of the paper that its own formulas do not give (the formula "
                    "wins):</b>"
                ),
                mis.round(3),
            ]
        show(self.tables, *items)

    def show(self) -> None:
        self.update()
        display(self.widget)


def _reach_text(reach: float, lo: float, hi: float) -> str:
    if np.isnan(reach) or reach < lo:
        return f"exceeded already at {lo:.0f} m"
    if reach >= hi:
        return f"over the whole range to {hi:.0f} m"
    return f"up to S = {reach:.1f} m"


class TargetExplorer:
    """Minimum target sizes (2d / 4d) vs distance, and how far each inventory item serves."""

    def __init__(self) -> None:
        style = {"description_width": "12em"}
        self.step = w.BoundedFloatText(
            value=SOSSA_STEP_MM_AT_10M,
            min=0.1,
            max=50.0,
            step=0.1,
            description="scan step at 10 m [mm]",
            style=style,
        )
        self.max_distance = w.BoundedFloatText(
            value=max(SOSSA_DISTANCES_M),
            min=10,
            max=2000,
            step=10,
            description="up to [m]",
            style=style,
        )
        self.inventory = inventory_box(
            "inventory (name, type, size mm)", style, w.Layout(width="60%", height="7em")
        )
        self.error = w.HTML()
        self.out = w.Output()
        for widget in (self.step, self.max_distance, self.inventory):
            widget.observe(lambda _c: self.update(), "value")
        self.widget = w.VBox([self.step, self.max_distance, self.inventory, self.error, self.out])

    def update(self) -> None:
        self.error.value = ""
        try:
            items = parse_inventory(self.inventory.value)
            fig = plot_target_sizes(self.step.value, self.max_distance.value, items)
            table = target_size_table(step_mm_at_10m=self.step.value)
            reach = recommend_targets(
                self.max_distance.value, items, step_mm_at_10m=self.step.value
            )
        except (PlannerError, ValueError) as exc:
            self.error.value = error_html(str(exc))
            return
        show(
            self.out,
            fig,
            w.HTML("<b>Sossa's Table 2 layout (mm)</b>"),
            table,
            w.HTML("<b>Your inventory: the farthest distance each item qualifies</b>"),
            reach[["name", "type", "size_mm", "max_distance_m"]].round(1),
        )

    def show(self) -> None:
        self.update()
        display(self.widget)
