"""Plots of a plan: the site map and the coverage of the facades. No science here.

Used by the dashboard, the report and ``planner figures``.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import shapely
from matplotlib.axes import Axes
from matplotlib.collections import PatchCollection
from matplotlib.figure import Figure
from matplotlib.patches import PathPatch, Wedge
from matplotlib.path import Path as MplPath

from planner.pipeline.result import Plan
from planner.site import Site

__all__ = ["plot_coverage", "plot_plan_map", "plot_site"]

QUANTITIES = {
    "m_x_mm": "m_x [mm]",
    "m_y_mm": "m_y [mm]",
    "m_z_mm": "m_z [mm]",
    "reg_m_x_mm": "registration part of m_x [mm]",
    "reg_m_y_mm": "registration part of m_y [mm]",
    "reg_m_z_mm": "registration part of m_z [mm]",
}
#: The limit each plotted quantity is coloured against (its requirement).
_LIMIT_OF = {"x": "max_x_mm", "y": "max_y_mm", "z": "max_z_mm"}


def _patch(geom, **kw) -> PathPatch:
    verts, codes = [], []
    for poly in shapely.get_parts(geom):
        for ring in [poly.exterior, *poly.interiors]:
            xy = np.asarray(ring.coords)[:, :2]
            verts.append(xy)
            codes += [MplPath.MOVETO] + [MplPath.LINETO] * (len(xy) - 2) + [MplPath.CLOSEPOLY]
    return PathPatch(MplPath(np.vstack(verts), codes), **kw)


def plot_site(site: Site, ax: Axes | None = None, origin: np.ndarray | None = None) -> Axes:
    """Buildings (planned dark, others light), obstacles, no-go areas and the boundary."""
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 7), layout="constrained")
    o = np.zeros(2) if origin is None else origin
    shift = lambda g: shapely.transform(g, lambda c: c - o)  # noqa: E731
    if site.boundary is not None:
        ax.add_patch(_patch(shift(site.boundary), fill=False, ls="--", ec="0.4", lw=1))
    for a in site.no_go:
        ax.add_patch(_patch(shift(a.geometry), fc="#f4cccc", ec="#cc6666", hatch="//", lw=0.5))
    for b in site.buildings:
        fc = "#7f8c8d" if b.planned else "#d5d8dc"
        ax.add_patch(_patch(shift(b.footprint), fc=fc, ec="k", lw=0.8))
        c = shift(b.footprint).representative_point()
        ax.annotate(
            f"{b.id}\n{b.height_m:g} m",
            (c.x, c.y),
            ha="center",
            va="center",
            fontsize=7,
            color="w" if b.planned else "k",
        )
    for ob in site.obstacles:
        fc = "#58d68d" if ob.kind == "tree" else "#a04000"
        ax.add_patch(_patch(shift(ob.geometry), fc=fc, ec="k", lw=0.5, alpha=0.8))
    ax.set_aspect("equal")
    ax.autoscale_view()
    return ax


def plot_plan_map(
    p: Plan, ax: Axes | None = None, *, candidates: bool = True, sectors: bool = True
) -> Figure:
    """The plan on the site: candidate heat map (samples each position meets), stations with
    their view sectors, registration links, targets, unmet samples."""
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 7.5), layout="constrained")
    fig = ax.figure
    origin = (
        np.array([p.candidates["x"].min(), p.candidates["y"].min()])
        if len(p.candidates)
        else np.array(p.site.planned[0].footprint.bounds[:2])
    )
    origin = np.floor(origin / 10) * 10
    if candidates and len(p.candidates):
        c = p.candidates
        sc = ax.scatter(
            c["x"] - origin[0],
            c["y"] - origin[1],
            c=c["samples_met"],
            s=4,
            marker="s",
            cmap="viridis",
            alpha=0.55,
            lw=0,
            zorder=0,
        )
        fig.colorbar(sc, ax=ax, shrink=0.6, label="samples a station here meets")
    plot_site(p.site, ax, origin)
    st = p.stations.set_index("station_id")
    cov = p.coverage[p.coverage["station_id"] != ""]
    if sectors and len(cov):
        wedges = []
        for sid, g in cov.groupby("station_id"):
            sx, sy = st.loc[sid, ["x", "y"]]
            ang = np.degrees(np.arctan2(g["y"] - sy, g["x"] - sx))
            ang = np.sort(np.mod(ang, 360))
            gaps = np.diff(np.append(ang, ang[0] + 360))
            k = int(np.argmax(gaps))
            start, end = ang[(k + 1) % len(ang)], ang[k]
            radius = float(np.hypot(g["x"] - sx, g["y"] - sy).max())
            wedges.append(
                Wedge(
                    (sx - origin[0], sy - origin[1]),
                    radius,
                    start,
                    end if end > start else end + 360,
                )
            )
        ax.add_collection(PatchCollection(wedges, fc="#f5b041", ec="#d68910", alpha=0.12, lw=0.6))
    _draw_links(p, ax, origin)
    for kind, marker in (("flat", "s"), ("sphere", "o")):
        t = p.targets[p.targets["type"] == kind]
        if len(t):
            ax.scatter(
                t["x"] - origin[0],
                t["y"] - origin[1],
                marker=marker,
                s=28,
                fc="w",
                ec="#8e44ad",
                lw=1.5,
                zorder=4,
                label=f"{kind} target",
            )
    for r in p.stations.itertuples():
        colour = "#c0392b" if r.purpose == "cover" else "#1f618d"
        ax.plot(r.x - origin[0], r.y - origin[1], "^", color=colour, ms=9, mec="k", zorder=5)
        ax.annotate(
            r.station_id,
            (r.x - origin[0], r.y - origin[1]),
            xytext=(4, 4),
            textcoords="offset points",
            fontsize=8,
            weight="bold",
            zorder=6,
        )
    un = p.unmet
    if len(un):
        ax.scatter(
            un["x"] - origin[0],
            un["y"] - origin[1],
            marker="x",
            c="red",
            s=30,
            zorder=6,
            label=f"unmet samples ({len(un)})",
        )
    ax.plot([], [], "^", color="#c0392b", mec="k", label="station")
    ax.legend(loc="upper left", fontsize=7, framealpha=0.9)
    crs = f" ({p.site.crs})" if p.site.crs else ""
    ax.set_xlabel(f"E − {origin[0]:.0f} [m]{crs}")
    ax.set_ylabel(f"N − {origin[1]:.0f} [m]")
    ax.set_title(f"{len(p.stations)} stations, {len(p.targets)} targets — {p.site.name}")
    ax.autoscale_view()
    return fig


def _draw_links(p: Plan, ax: Axes, origin: np.ndarray) -> None:
    """The registrations as lines between stations (to each control point used, for a
    station tied to the control network), coloured and labelled by the link's own
    predicted error; the control points as black triangles."""
    st = p.stations.set_index("station_id")
    tg = p.targets.set_index("target_id")
    ctl = p.targets[p.targets["type"] == "control"]
    if len(ctl):
        ax.scatter(
            ctl["x"] - origin[0],
            ctl["y"] - origin[1],
            marker="v",
            s=40,
            c="k",
            zorder=4,
            label="control point",
        )
    if not len(p.links):
        return
    worst = float(np.nanmax(p.links["link_rms_mm"])) or 1.0
    cmap = plt.get_cmap("cool")
    for r in p.links.itertuples():
        b = st.loc[r.station_b]
        if r.station_a == "control":
            ends = [tg.loc[t] for t in r.target_ids.split(";") if t in tg.index]
            style = dict(color="0.3", lw=0.8, ls="--")
        else:
            ends = [st.loc[r.station_a]]
            share = r.link_rms_mm / worst if np.isfinite(r.link_rms_mm) else 1.0
            style = dict(color=cmap(share), lw=1.0 + 1.5 * share)
        for a in ends:
            ax.plot(
                [a.x - origin[0], b.x - origin[0]],
                [a.y - origin[1], b.y - origin[1]],
                **style,
                zorder=3,
            )
        if r.station_a != "control" and np.isfinite(r.link_rms_mm):
            a = ends[0]
            ax.annotate(
                f"{r.link_rms_mm:.1f}",
                ((a.x + b.x) / 2 - origin[0], (a.y + b.y) / 2 - origin[1]),
                fontsize=6,
                color="#1b4f72",
                ha="center",
                zorder=6,
            )
    ax.plot([], [], color=cmap(1.0), lw=2.5, label="registration link (its own RMS, mm)")


def _draw_zones(p: Plan, ax: Axes, off: dict, f) -> None:
    """The zones outlined on the facade strips (dashed), labelled with their id."""
    from matplotlib.patches import Polygon as MplPolygon
    from matplotlib.patches import Rectangle

    for z in p.site.zones:
        if z.facade_id is not None:
            facades = [z.facade_id] if z.facade_id in off else []
        else:
            facades = [fid for fid in off if f.loc[fid, "building_id"] == z.building_id]
        for fid in facades:
            x0, length, height = off[fid], f.loc[fid, "length_m"], f.loc[fid, "height_m"]
            style = dict(fill=False, ec="#1f3a93", lw=1.3, ls="--", zorder=5)
            if z.elevation is not None:
                xy = np.asarray(z.elevation.exterior.coords) + np.array([x0, 0.0])
                ax.add_patch(MplPolygon(xy, closed=True, **style))
                label_at = (xy[:, 0].min(), xy[:, 1].max())
            else:
                a0, a1 = z.along_m or (0.0, length)
                h0, h1 = z.height_m or (0.0, height)
                ax.add_patch(Rectangle((x0 + a0, h0), a1 - a0, h1 - h0, **style))
                label_at = (x0 + a0, h1)
            ax.annotate(
                z.id,
                label_at,
                xytext=(2, 2),
                textcoords="offset points",
                fontsize=6,
                color="#1f3a93",
                zorder=6,
            )


def plot_coverage(p: Plan, quantity: str = "m_x_mm", ax: Axes | None = None) -> Figure:
    """The facades unrolled side by side (distance along the facades vs height), each sample
    coloured by the predicted RMS from its assigned station; unmet samples ringed red,
    party walls grey."""
    if quantity not in QUANTITIES:
        raise ValueError(f"quantity must be one of {', '.join(QUANTITIES)}")
    if ax is None:
        _, ax = plt.subplots(figsize=(11, 3.6), layout="constrained")
    fig = ax.figure
    cov = p.coverage.copy()
    f = p.facades.set_index("facade_id")
    offset = np.concatenate([[0.0], np.cumsum(f["length_m"].to_numpy() + 2.0)[:-1]])
    off = dict(zip(f.index, offset, strict=True))
    along = np.hypot(
        cov["x"] - f.loc[cov["facade_id"], "x0"].to_numpy(),
        cov["y"] - f.loc[cov["facade_id"], "y0"].to_numpy(),
    )
    cov["u"] = along + cov["facade_id"].map(off)
    limit = getattr(p.requirements, _LIMIT_OF[quantity[-4]])
    ok = cov[~cov["party_wall"]]
    sc = ax.scatter(
        ok["u"],
        ok["z"],
        c=ok[quantity],
        cmap="RdYlGn_r",
        vmin=0,
        vmax=limit * 1.25,
        s=18,
        marker="s",
    )
    fig.colorbar(sc, ax=ax, label=f"{QUANTITIES[quantity]} (limit {limit:g})", pad=0.01)
    pw = cov[cov["party_wall"]]
    if len(pw):
        ax.scatter(pw["u"], pw["z"], c="0.75", s=18, marker="s", label="party wall")
    un = ok[~ok["meets"]]
    if len(un):
        ax.scatter(
            un["u"],
            un["z"],
            facecolors="none",
            edgecolors="red",
            s=40,
            lw=1.2,
            label=f"unmet ({len(un)})",
        )
    for fid, x0 in off.items():
        ax.axvline(x0 - 1.0, color="0.85", lw=0.8)
        ax.annotate(
            fid.split("-")[-1],
            (x0 + f.loc[fid, "length_m"] / 2, 0),
            xytext=(0, -12),
            textcoords="offset points",
            ha="center",
            fontsize=6,
            color="0.4",
        )
    _draw_zones(p, ax, off, f)
    ax.set_xlabel("distance along the facades [m] (facades side by side)")
    ax.set_ylabel("height [m]")
    if len(pw) or len(un):
        ax.legend(loc="upper right", fontsize=7)
    ax.set_title(
        f"Predicted {QUANTITIES[quantity]} at every facade sample, from its assigned station"
    )
    return fig
