"""Facade elevations: each wall of a building drawn flat at its real outline (a gable, a
set-back storey, a sloping mansard wall), side by side, with every sample coloured by the
station it is assigned to — a cross where it is unmet, grey on a party wall. Surveyors
check coverage on elevations; the dashboard's Elevations tab and the report draw these.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from planner.app.maps import UNROLL_GAP_M, draw_outlines, facade_offsets, facade_outline, unrolled
from planner.pipeline.engine.result import Plan

__all__ = ["elevation_buildings", "plot_elevations"]

#: Facades shown in one figure, at most (the rest said in the title).
MAX_FACADES = 40


def elevation_buildings(p: Plan) -> list[str]:
    """The planned buildings with facades, in the facade table's order."""
    return list(dict.fromkeys(p.facades["building_id"]))


def _name_facades(ax: Axes, f: pd.DataFrame, off: dict, building_id: str) -> None:
    """Each facade's id (without its building's) above its outline."""
    for row in f.itertuples():
        b = facade_outline(row).bounds
        ax.annotate(
            str(row.Index).removeprefix(f"{building_id}-"),
            (off[row.Index] + b[2] / 2, b[3]),
            xytext=(0, 2),
            textcoords="offset points",
            ha="center",
            va="bottom",
            fontsize=7,
            color="0.3",
        )


def _legend(ax: Axes, stations: list[str], colour: dict, n_unmet: int, party: bool) -> None:
    """A legend of the stations' colours (the first 20), the unmet samples and party walls."""
    handles = [
        plt.Line2D([], [], ls="", marker="o", color=colour[s], label=s) for s in stations[:20]
    ]
    if n_unmet:
        handles.append(
            plt.Line2D([], [], ls="", marker="x", color="red", label=f"unmet ({n_unmet})")
        )
    if party:
        handles.append(plt.Line2D([], [], ls="", marker="o", color="0.7", label="party wall"))
    if handles:
        ax.legend(
            handles=handles,
            loc="upper left",
            bbox_to_anchor=(1.0, 1.0),
            fontsize=7,
            title="station",
        )


def plot_elevations(p: Plan, building_id: str | None = None, ax: Axes | None = None) -> Figure:
    """The facades of ``building_id`` (default: the first planned) unrolled side by side at
    their real outlines, heights above the building's base; samples coloured by their
    station, unmet ones crossed red, party walls grey."""
    fac = p.facades
    if building_id is None:
        building_id = elevation_buildings(p)[0]
    mine = fac[fac["building_id"] == building_id]
    if mine.empty:
        raise ValueError(f"no facade of building {building_id!r} in the plan")
    cut = len(mine) > MAX_FACADES
    f = mine.iloc[:MAX_FACADES].set_index("facade_id")
    tops = f["z0"] - f["base_z"] + f["height_m"]
    if ax is None:
        width = float(f["length_m"].sum() + UNROLL_GAP_M * len(f))
        tall = float(tops.max())
        _, ax = plt.subplots(
            figsize=(11, min(6.5, max(2.8, 11 * tall / max(width, 1) + 1.6))), layout="constrained"
        )
    fig = ax.figure
    off = facade_offsets(f)
    draw_outlines(ax, f, off)
    cov = p.coverage[p.coverage["facade_id"].isin(f.index)]
    u, h = unrolled(cov, f, off)
    stations = sorted(s for s in cov["station_id"].unique() if s)
    palette = plt.get_cmap("tab20")
    colour = {s: palette(i % 20) for i, s in enumerate(stations)}
    party = cov["party_wall"].to_numpy(bool)
    met = cov["meets"].to_numpy(bool) & ~party
    unmet = ~cov["meets"].to_numpy(bool) & ~party
    c = np.array([colour.get(k, (0.5, 0.5, 0.5, 1.0)) for k in cov["station_id"]]).reshape(-1, 4)
    ax.scatter(u[met], h[met], c=c[met], s=16, lw=0)
    if unmet.any():
        ax.scatter(u[unmet], h[unmet], marker="x", c="red", s=22, lw=1.2)
    if party.any():
        ax.scatter(u[party], h[party], c="0.7", s=10, lw=0)
    _name_facades(ax, f, off, building_id)
    last = list(off)[-1]
    ax.set_xlim(-UNROLL_GAP_M / 2, off[last] + f.loc[last, "length_m"] + UNROLL_GAP_M / 2)
    ax.set_ylim(
        min(0.0, float((f["z0"] - f["base_z"]).min())) - 0.5, float(tops.max()) * 1.12 + 1.0
    )
    ax.set_aspect("equal", adjustable="box")
    _legend(ax, stations, colour, int(unmet.sum()), bool(party.any()))
    base = float(f["base_z"].iloc[0])
    ax.set_xlabel("distance along each facade [m] (facades side by side)")
    if p.site.is_3d:
        ax.set_ylabel(f"height above the base [m]\n(base {base:.2f} m)")
        datum = p.site.height_system
    else:
        ax.set_ylabel("height [m]")
        datum = "metres above the ground"
    more = f" (the first {MAX_FACADES} of its facades)" if cut else ""
    ax.set_title(
        f"Elevations of {building_id}{more}: each sample by its station; heights in {datum}",
        fontsize=9,
    )
    return fig
