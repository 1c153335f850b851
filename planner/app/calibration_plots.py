"""Residual plots of the calibration steps (used by the calibration notebook). No science."""

from __future__ import annotations

from importlib import resources
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from planner.calibration import (
    AxisResult,
    BaselineResult,
    LabTest,
    SixSegmentResult,
    axis_error_effect,
)

__all__ = ["example_path", "plot_axes", "plot_baseline", "plot_lab", "plot_six_segment"]


def example_path(name: str) -> Path:
    """A file of the shipped example calibration data (``planner/data/calibration``)."""
    return Path(str(resources.files("planner.data").joinpath("calibration", name)))


def plot_lab(t: LabTest) -> Figure:
    """Helmert residuals per target, and every pair's Δ against its distance with ±M_r."""
    fig, axes = plt.subplots(1, 4, figsize=(15, 3.6), layout="constrained")
    r = t.helmert.residuals
    x = np.arange(len(r))
    for comp, off in (("dx_mm", -0.25), ("dy_mm", 0.0), ("dz_mm", 0.25)):
        axes[0].bar(x + off, r[comp], width=0.25, label=comp.split("_")[0])
    axes[0].set_title(f"Helmert residuals (σ₀ {t.helmert.sigma0_mm:.2f} mm)")
    axes[0].set_xlabel("target")
    axes[0].set_ylabel("mm")
    axes[0].legend(fontsize=7)
    for ax, part, key, unit, title in (
        (axes[1], "distance", "distance_mm", "mm", "distance"),
        (axes[2], "horizontal", "horizontal_arcsec", "″", "horizontal direction φ"),
        (axes[3], "vertical", "vertical_arcsec", "″", "vertical direction θ"),
    ):
        col = f"d_{key}"
        sig = t.pairs[f"significant_{part}"]
        ax.scatter(t.pairs["distance_m"], t.pairs[col], s=3, c=np.where(sig, "crimson", "0.4"))
        big = t.M_r[key]
        ax.axhline(big, color="crimson", ls="--", lw=0.8)
        ax.axhline(-big, color="crimson", ls="--", lw=0.8)
        ax.set_title(f"Δ {title}\nm_r {t.m_r[key]:.1f} {unit}, M_r {big:.1f} {unit}", fontsize=10)
        ax.set_xlabel("pair distance [m]")
        ax.set_ylabel(unit)
    return fig


def plot_baseline(r: BaselineResult) -> Figure:
    """Reference − measured against the distance, the fitted k + R·D, and the residuals."""
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 3.5), layout="constrained")
    d = r.residuals["measured_m"]
    obs = (r.residuals["reference_m"] - d) * 1000
    a.plot(d, obs, "o", ms=4, label="reference − measured")
    xs = np.linspace(0, d.max(), 50)
    a.plot(
        xs,
        r.k_mm + r.scale_ppm * 1e-3 * xs,
        "-",
        label=f"k + R·D: {r.k_mm:+.2f} mm, {r.scale_ppm:+.1f} ppm",
    )
    a.set_xlabel("distance [m]")
    a.set_ylabel("mm")
    a.legend(fontsize=8)
    b.plot(d, r.residuals["residual_mm"], "o", ms=4)
    b.axhline(0, color="0.5", lw=0.8)
    b.set_title(f"residuals after correction, RMS {r.residual_rms_mm:.2f} mm")
    b.set_xlabel("distance [m]")
    return fig


def plot_six_segment(r: SixSegmentResult) -> Figure:
    """Residuals of the all-combinations adjustment."""
    fig, ax = plt.subplots(figsize=(6, 3.2), layout="constrained")
    labels = [f"{a}-{b}" for a, b in zip(r.residuals["from"], r.residuals["to"], strict=True)]
    ax.bar(labels, r.residuals["residual_mm"])
    ax.set_title(f"six-segment residuals; C = {r.k_mm:+.2f} ± {r.k_se_mm:.2f} mm")
    ax.set_ylabel("mm")
    ax.tick_params(axis="x", labelrotation=90, labelsize=7)
    return fig


def plot_axes(r: AxisResult) -> Figure:
    """Direction differences against the vertical angle, the fitted c / cos α + i·tan α."""
    fig, ax = plt.subplots(figsize=(6, 3.5), layout="constrained")
    alpha = r.residuals["vertical_angle_deg"].to_numpy()
    line = np.linspace(alpha.min(), alpha.max(), 100)
    fit = axis_error_effect(r.c_deg, r.i_deg, line) * 3600
    o = r.orientation_deg or 0.0
    diff = (
        (r.residuals["observed_deg"] - r.residuals["reference_deg"] - o + 180) % 360 - 180
    ) * 3600
    ax.plot(alpha, diff, "o", label="observed − reference − orientation")
    ax.plot(line, fit, "-", label=f"c = {r.c_deg * 3600:.1f}″, i = {r.i_deg * 3600:.1f}″")
    ax.set_xlabel("vertical angle α [deg]")
    ax.set_ylabel("″")
    ax.legend(fontsize=8)
    ax.set_title(f"axis errors; residual RMS {r.residual_rms_arcsec:.1f}″")
    return fig
