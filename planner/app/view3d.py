"""The 3-D view of a plan: the scene the sight lines were cast against (the model's walls,
roofs, the terrain, trees), the facade samples coloured met / unmet, the stations with
their ids and the targets — an interactive WebGL widget (K3D-jupyter, Trzesiok et al.,
https://k3d-jupyter.org) that turns, pans and zooms in the dashboard.
"""

from __future__ import annotations

import numpy as np

from planner.pipeline.engine.judge import workbench_of
from planner.pipeline.engine.result import Plan
from planner.pipeline.geometry.scene import TRIANGLE_KINDS, Scene

__all__ = ["KIND_COLOURS", "view_3d", "view_extent"]

#: The colour of each kind of surface (0xRRGGBB), in :data:`TRIANGLE_KINDS`' order.
KIND_COLOURS = {
    "wall": 0xD9D4C7,
    "roof": 0xA8553A,
    "ground": 0x8C8C8C,
    "ceiling": 0xB8B2A4,
    "floor": 0xB8B2A4,
    "window": 0x6FA8DC,
    "door": 0x8D6E63,
    "installation": 0x9E9E9E,
    "terrain": 0xC5D6A8,
    "tree": 0x2E7D32,
    "obstacle": 0x757575,
}
#: The view reaches this far beyond the stations and the planned buildings [m].
MARGIN_M = 20.0
MET, UNMET, PARTY = 0x2E9D4A, 0xD62728, 0xB0B0B0
STATION, TARGET = 0x1F4E9D, 0xF28E1C


def view_extent(p: Plan) -> tuple[float, float, float, float]:
    """The plan's planned buildings and stations, with :data:`MARGIN_M` around."""
    xy = [p.stations[["x", "y"]].to_numpy(float)]
    for b in p.site.planned:
        xy.append(np.asarray(b.footprint.envelope.exterior.coords)[:, :2])
    pts = np.vstack(xy)
    lo, hi = pts.min(axis=0) - MARGIN_M, pts.max(axis=0) + MARGIN_M
    return float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1])


def _camera(p: Plan, origin: np.ndarray) -> list[float]:
    """Looking at the planned buildings from the south-south-west, 35° down, from far
    enough to see them whole (K3D's camera: eye, target, up)."""
    x0, y0, x1, y1 = np.array([b.footprint.bounds for b in p.site.planned]).T[[0, 1, 2, 3]].tolist()
    lo = np.array([min(x0), min(y0)])
    hi = np.array([max(x1), max(y1)])
    top = max(b.top_z for b in p.site.planned)
    base = min(float(b.base_z or 0.0) for b in p.site.planned)
    target = np.array([*(lo + hi) / 2, (base + top) / 2]) - origin
    r = max(float(np.hypot(*(hi - lo))) / 2, top - base) * 2.2 + 10.0
    eye = target + r * np.array([-0.35, -0.75, 0.57])
    return [*eye.tolist(), *target.tolist(), 0.0, 0.0, 1.0]


def view_3d(p: Plan, height_px: int = 560):
    """The plan in 3-D as a K3D plot (a widget): the scene within :func:`view_extent`, the
    samples, stations (labelled) and targets."""
    import k3d

    wb = workbench_of(p)
    scene = wb.ctx.scene if wb is not None else Scene(p.site, "rays")
    tri, _, kind, _ = scene.mesh
    x0, y0, x1, y1 = view_extent(p)
    centre = tri.mean(axis=1) if len(tri) else np.empty((0, 3))
    near = (centre[:, 0] >= x0) & (centre[:, 0] <= x1) & (centre[:, 1] >= y0) & (centre[:, 1] <= y1)
    origin = scene.origin
    plot = k3d.plot(
        grid_visible=False,
        menu_visibility=False,
        axes_helper=0,
        height=height_px,
        background_color=0xFFFFFF,
        camera_auto_fit=False,
    )
    plot.camera = _camera(p, origin)
    codes = np.array([KIND_COLOURS[k] for k in TRIANGLE_KINDS], dtype=np.uint32)
    for k in np.unique(kind[near]):
        sel = near & (kind == k)
        v = (tri[sel].reshape(-1, 3) - origin).astype(np.float32)
        plot += k3d.mesh(
            v,
            np.arange(len(v), dtype=np.uint32).reshape(-1, 3),
            color=int(codes[k]),
            flat_shading=True,
            side="double",
            name=TRIANGLE_KINDS[k],
        )
    cov = p.coverage
    pts = (cov[["x", "y", "z"]].to_numpy(float) - origin).astype(np.float32)
    state = np.where(cov["party_wall"], PARTY, np.where(cov["meets"], MET, UNMET)).astype(np.uint32)
    plot += k3d.points(pts, colors=state, point_size=0.5, shader="flat", name="samples")
    st = p.stations
    ground = st["ground_z"].to_numpy(float) if "ground_z" in st else np.zeros(len(st))
    s_xyz = np.column_stack(
        [st[["x", "y"]].to_numpy(float), ground + st["instrument_height_m"].to_numpy(float)]
    )
    s_xyz = (s_xyz - origin).astype(np.float32)
    plot += k3d.points(s_xyz, color=STATION, point_size=1.4, shader="flat", name="stations")
    for sid, xyz in zip(st["station_id"], s_xyz, strict=True):
        plot += k3d.text(
            str(sid),
            position=(xyz + np.array([0.0, 0.0, 1.5])).tolist(),
            color=STATION,
            size=0.8,
            label_box=False,
        )
    tg = p.targets
    if len(tg):
        t_xyz = (tg[["x", "y", "z"]].to_numpy(float) - origin).astype(np.float32)
        plot += k3d.points(t_xyz, color=TARGET, point_size=0.6, shader="flat", name="targets")
    return plot
