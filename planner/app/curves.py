"""Accuracy curves reproducing the papers' tables (m_x, m_y by eq. 2, m_z by eq. 4, the
paper's model against the 3-D one) and target sizes by Sossa's rule, drawn with matplotlib.

The README's figures (:mod:`planner.app.figures`) and the explorers' dashboards
(:mod:`planner.app.explorers`) draw them; each takes an optional ``ax``.
"""

from __future__ import annotations

from collections.abc import Sequence

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from planner.accuracy import height_rms, planimetric_rms
from planner.accuracy3d import point_rms_3d
from planner.polar import horizontal_distance_m
from planner.reference import (
    SOSSA_TABLE2,
    compare_table1,
    compare_table2,
)
from planner.scanner import Scanner
from planner.targets import (
    DEFAULT_INVENTORY,
    SOSSA_STEP_MM_AT_10M,
    TARGET_TYPES,
    TargetItem,
    max_target_distance_m,
    min_target_size_mm,
)

__all__ = [
    "plot_height",
    "plot_models",
    "plot_planimetric",
    "plot_target_sizes",
]

_COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"]
#: The paper's angles keep their colours wherever they appear; any other angle is black.
_ANGLE_COLOURS = {0.0: "#1f77b4", 30.0: "#ff7f0e", 60.0: "#2ca02c", 90.0: "#d62728"}


def _angle_colour(angle: float) -> str:
    return _ANGLE_COLOURS.get(float(angle), "k")


def plot_planimetric(
    scanner: Scanner,
    gammas_deg: Sequence[float] = (0, 30, 60),
    max_distance_m: float = 120.0,
    *,
    station_rms_mm: float | tuple[float, float] = 0.0,
    paper: bool = False,
    axes: Sequence[Axes] | None = None,
) -> Figure:
    """m_x and m_y vs D, one curve per γ (eq. 2); ``paper=True`` overlays Table 1. On
    ``axes`` of the caller's figure the figure's title is the caller's."""
    own = axes is None
    if axes is None:
        fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True, layout="constrained")
    fig = axes[0].figure
    d = np.linspace(0.0, max_distance_m, 241)
    t1 = compare_table1(scanner) if paper else None
    for g in sorted({float(v) for v in gammas_deg}):
        c = _angle_colour(g)
        m_x, m_y = planimetric_rms(d, g, scanner, station_rms_mm)
        axes[0].plot(d, m_x, color=c, label=f"γ = {g:g}°")
        axes[1].plot(d, m_y, color=c, label=f"γ = {g:g}°")
        if t1 is not None and g in (0, 30, 60):
            for ax, comp in zip(axes, ("m_x", "m_y"), strict=True):
                cells = t1.xs((comp, g), level=(1, 2))
                ok, bad = cells[~cells["misprint"]], cells[cells["misprint"]]
                ax.plot(ok.index, ok["printed_mm"], "o", ms=4, mfc="none", color=c)
                ax.plot(bad.index, bad["printed_mm"], "x", ms=6, color="crimson")
    for ax, comp in zip(axes, ("m_x (along the facade)", "m_y (along the normal)"), strict=True):
        ax.set_xlabel("horizontal distance D [m]")
        ax.set_title(comp)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("RMS [mm]")
    axes[0].legend()
    if t1 is not None:
        axes[1].plot([], [], "o", mfc="none", color="grey", label="Table 1 as printed")
        axes[1].plot([], [], "x", color="crimson", label="misprint (formula wins)")
        axes[1].legend()
    if own:
        fig.suptitle(f"Planimetric RMS, eq. 2 of Voroshilov & Karachentsev — {scanner.label}")
    return fig


def plot_height(
    scanner: Scanner,
    nus_deg: Sequence[float] = (0, 30, 60, 90),
    max_distance_m: float = 120.0,
    *,
    paper: bool = False,
    ax: Axes | None = None,
) -> Figure:
    """m_z vs S, one curve per ν (eq. 4, S_0 = S); ``paper=True`` overlays Table 2. On the
    caller's ``ax`` the panel's title is short (the caller's figure names the scanner)."""
    own = ax is None
    if ax is None:
        fig, ax = plt.subplots(figsize=(6, 4), layout="constrained")
    fig = ax.figure
    s = np.linspace(0.0, max_distance_m, 241)
    t2 = compare_table2(scanner) if paper else None
    for nu in sorted({float(v) for v in nus_deg}):
        c = _angle_colour(nu)
        ax.plot(s, height_rms(s, nu, scanner), color=c, label=f"ν = {nu:g}°")
        if t2 is not None and nu in (0, 30, 60, 90):
            cells = t2.xs(nu, level=1)
            ok, bad = cells[~cells["misprint"]], cells[cells["misprint"]]
            ax.plot(ok.index, ok["printed_mm"], "o", ms=4, mfc="none", color=c)
            ax.plot(bad.index, bad["printed_mm"], "x", ms=6, color="crimson")
    if t2 is not None:
        ax.plot([], [], "o", mfc="none", color="grey", label="Table 2 as printed")
        ax.plot([], [], "x", color="crimson", label="misprint (formula wins)")
    ax.set_xlabel("slope distance S [m]")
    ax.set_ylabel("m_z [mm]")
    ax.grid(alpha=0.3)
    ax.legend()
    ax.set_title(f"Height RMS, eq. 4 — {scanner.label}" if own else "m_z (height)")
    return fig


def plot_models(
    scanner: Scanner,
    gamma_deg: float = 0.0,
    nu_deg: float = 60.0,
    max_distance_m: float = 120.0,
    *,
    incidence_noise: bool = True,
    limit_mm: float | None = None,
    axes: Sequence[Axes] | None = None,
) -> Figure:
    """m_x, m_y and m_z vs the slope distance for one beam geometry (γ, ν), by the paper's
    eq. 2 and 4 (dashed) and by the full 3-D model (solid; with the incidence term dotted
    when ``incidence_noise``) — the two models side by side."""
    if axes is None:
        fig, axes = plt.subplots(1, 3, figsize=(13, 3.8), sharey=True, layout="constrained")
    fig = axes[0].figure
    s = np.linspace(0.0, max_distance_m, 241)
    d = horizontal_distance_m(s, nu_deg)
    paper_xy = planimetric_rms(d, gamma_deg, scanner, ranging_distance_m=s)
    paper = (*paper_xy, height_rms(s, nu_deg, scanner))
    model = point_rms_3d(s, gamma_deg, nu_deg, scanner)
    noisy = point_rms_3d(s, gamma_deg, nu_deg, scanner, incidence_noise=True)
    names = ("m_x (along the facade)", "m_y (along the normal)", "m_z (height)")
    for ax, name, a, b, c in zip(axes, names, paper, model, noisy, strict=True):
        ax.plot(s, a, "--", color="#7f7f7f", label="paper: eq. 2 / eq. 4")
        ax.plot(s, b, "-", color="#1f77b4", label="3-D propagation")
        if incidence_noise:
            ax.plot(s, c, ":", color="#d62728", lw=1.8, label="3-D + incidence noise")
        if limit_mm is not None:
            ax.axhline(limit_mm, color="crimson", lw=0.8, ls="--", label=f"limit {limit_mm:g} mm")
        ax.set_title(name, fontsize=10)
        ax.set_xlabel("slope distance S [m]")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("RMS [mm]")
    axes[0].legend(fontsize=8)
    fig.suptitle(
        f"The two models at γ = {gamma_deg:g}°, ν = {nu_deg:g}° — {scanner.label}", fontsize=11
    )
    return fig


def plot_target_sizes(
    step_mm_at_10m: float = SOSSA_STEP_MM_AT_10M,
    max_distance_m: float = 350.0,
    inventory: Sequence[TargetItem] = DEFAULT_INVENTORY,
    *,
    paper: bool = False,
    ax: Axes | None = None,
) -> Figure:
    """Minimum target size vs distance (2d flat, 4d sphere and cylinder) and an inventory."""
    if ax is None:
        fig, ax = plt.subplots(figsize=(9, 4.5), layout="constrained")
    fig = ax.figure
    d = np.linspace(0.0, max_distance_m, 351)
    styles = {"flat": "-", "sphere": "--", "cylinder": ":"}
    for t in TARGET_TYPES:
        rule = "2d" if t == "flat" else "4d"
        ax.plot(
            d,
            min_target_size_mm(d, t, step_mm_at_10m=step_mm_at_10m),
            styles[t],
            color="k",
            label=f"{t} ({rule})",
        )
    if paper:
        for row, marker, types in (("flat", "o", "flat"), ("sphere", "s", "sphere, cylinder")):
            ax.plot(
                SOSSA_TABLE2.columns,
                SOSSA_TABLE2.loc[row],
                marker,
                mfc="none",
                color="k",
                label=f"Sossa Table 2 ({types})",
            )
    for i, item in enumerate(inventory):
        c = _COLOURS[i % len(_COLOURS)]
        reach = float(max_target_distance_m(item.size_mm, item.type, step_mm_at_10m=step_mm_at_10m))
        ax.hlines(
            item.size_mm,
            0,
            min(reach, max_distance_m),
            color=c,
            lw=2,
            label=f"{item.name}: up to {reach:.0f} m",
        )
    ax.set_xlabel("distance to scanner [m]")
    ax.set_ylabel("minimum target size [mm]")
    ax.set_xlim(0, max_distance_m)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.set_title(f"Target size by Sossa's 2d / 4d rule, step {step_mm_at_10m:g} mm at 10 m")
    return fig
