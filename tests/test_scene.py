"""The scene and its one sight-line interface (planner/pipeline/geometry/scene.py): the ray engine
against an independent ray–triangle test, the rays against the prism test on footprints,
and negative controls (an overhang or a tree removed: what it hid is seen)."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from planner.citymodel import Surface
from planner.pipeline.geometry.scene import Scene
from planner.pipeline.geometry.visibility import bridge_interval, clear_height, visible
from planner.site import Building, Obstacle, Site
from planner.siteio import default_site
from planner.synthetic import town

FAR = Building("far", shapely.box(100, 100, 110, 110), 10.0)


def _segments_hit(tri: np.ndarray, org: np.ndarray, vec: np.ndarray) -> np.ndarray:
    """(P,) the nearest hit along each segment as a fraction of it (inf: none), by the
    Möller–Trumbore test written out in NumPy over every (segment, triangle) pair — the
    independent reference for the engine."""
    a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
    e1, e2 = b - a, c - a
    out = np.full(len(org), np.inf)
    for i in range(len(org)):
        d = vec[i]
        p = np.cross(d, e2)
        det = (e1 * p).sum(axis=1)
        ok = np.abs(det) > 1e-12
        inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
        s = org[i] - a
        u = (s * p).sum(axis=1) * inv
        q = np.cross(s, e1)
        v = (q * d).sum(axis=1) * inv
        t = (e2 * q).sum(axis=1) * inv
        hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0) & (t < 1)
        if hit.any():
            out[i] = t[hit].min()
    return out


def _mesh_site(tri: np.ndarray) -> Site:
    """A site whose only obstacle is the triangles (T, 3, 3)."""
    where = shapely.box(-1, -1, 1, 1)
    return Site([FAR], obstacles=[Obstacle("mesh", where, 1.0, mesh=tri)])


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_rays_match_an_independent_ray_triangle_test(seed):
    rng = np.random.default_rng(seed)
    centre = rng.uniform(0, 40, (60, 1, 3))
    tri = centre + rng.normal(0, 4, (60, 3, 3))
    scene = Scene(_mesh_site(tri), "rays")
    org = rng.uniform(-5, 45, (400, 3))
    vec = rng.uniform(-5, 45, (400, 3)) - org
    ref = _segments_hit(tri, org, vec)
    blocked = scene.occluded(org, vec)
    # the engine casts in single precision: a hit this close to an end or an edge may go
    # either way, and is left out of the comparison
    length = np.linalg.norm(vec, axis=1)
    clear_of_ends = ~np.isfinite(ref) | ((ref * length > 1e-3) & ((1 - ref) * length > 1e-3))
    assert (blocked == np.isfinite(ref))[clear_of_ends].mean() >= 0.995
    assert np.isfinite(ref).sum() > 50  # the scenes are dense enough to test
    # first hits: the distance to the nearest triangle
    dist, which = scene.first_hit(org, vec, length)
    both = np.isfinite(ref) & np.isfinite(dist)
    assert dist[both] == pytest.approx(ref[both] * length[both], abs=2e-3)  # m
    assert (which[both] >= 0).all()


def _prism_seen(scene: Scene, src: np.ndarray, dst: np.ndarray) -> np.ndarray:
    zc = clear_height(src[:, :2], src[:, 2], dst[:, :2], scene.edges, scene.edge_heights, 0.0)
    lo = up = None
    b, bottoms, tops = scene.bridges
    if len(b):
        lo, up = bridge_interval(src[:, :2], src[:, 2], dst[:, :2], b, bottoms, tops, 0.0)
    return visible(dst[:, 2], zc, lo, up)


@pytest.mark.parametrize(
    "site", [default_site(), town(6, seed=2, gateways="passage")], ids=["default", "gated"]
)
def test_rays_and_prisms_agree_on_footprints(site):
    """Footprints on flat ground, both engines exact (no clearance): the same answer for
    every line whose ends are in the open."""
    rays = Scene(site, "rays")
    assert Scene(site).engine == "prisms"
    rng = np.random.default_rng(3)
    x0, y0, x1, y1 = rays._extent()
    n = 10_000
    ends = [
        np.column_stack(
            [
                rng.uniform(x0 - 20, x1 + 20, n),
                rng.uniform(y0 - 20, y1 + 20, n),
                rng.uniform(0.2, 25, n),
            ]
        )
        for _ in range(2)
    ]
    # ends in the open: not in a building, nor in the floors over a gateway (the 2.5-D test
    # takes every end to be in the open)
    solid = shapely.union_all([g for _, g, _ in site.blockers] + [g for _, g, _, _ in site.bridges])
    out = ~shapely.contains_xy(solid, ends[0][:, 0], ends[0][:, 1])
    out &= ~shapely.contains_xy(solid, ends[1][:, 0], ends[1][:, 1])
    src, dst = ends[0][out], ends[1][out]
    by_rays = ~rays.occluded(src, dst - src)
    by_prisms = _prism_seen(rays, src, dst)
    assert len(src) > 5_000 and 0.2 < by_rays.mean() < 0.9
    assert (by_rays != by_prisms).sum() <= 1  # a line grazing an edge within rounding


def test_the_clearance_blocks_a_line_grazing_an_edge():
    """A line passing 1 cm over a wall's top is blocked with the clearance (2 cm), seen
    without — by both engines."""
    site = Site([Building("w", shapely.box(0, 0, 1, 10), 5.0)])
    src, dst = np.array([[-20.0, 5.0, 4.0]]), np.array([[20.0, 5.0, 6.02]])  # 5.01 m at the wall
    rays = Scene(site, "rays")
    assert not rays.seen(src, dst)[0]
    assert not Scene(site, "prisms").seen(src, dst)[0]
    assert not rays.occluded(src, dst - src)[0]  # no clearance: the exact geometry


def _canopy_site(with_canopy: bool) -> Site:
    """A 10 m wall (y = 0, facing −y) with a 1 m deep canopy at 3 m over its whole length."""
    wall = np.array([[0, 0, 0], [20, 0, 0], [20, 0, 10], [0, 0, 10]], float)
    surfaces = [Surface("wall", (wall,))]
    back = [
        np.array([[20, 0, 0], [20, 8, 0], [20, 8, 10], [20, 0, 10]], float),
        np.array([[20, 8, 0], [0, 8, 0], [0, 8, 10], [20, 8, 10]], float),
        np.array([[0, 8, 0], [0, 0, 0], [0, 0, 10], [0, 8, 10]], float),
    ]
    surfaces += [Surface("wall", (r,)) for r in back]
    surfaces.append(
        Surface("roof", (np.array([[0, 0, 10], [20, 0, 10], [20, 8, 10], [0, 8, 10]], float),))
    )
    surfaces.append(
        Surface("ground", (np.array([[0, 0, 0], [0, 8, 0], [20, 8, 0], [20, 0, 0]], float),))
    )
    if with_canopy:
        top = np.array([[0, -1, 3.0], [20, -1, 3.0], [20, 0, 3.0], [0, 0, 3.0]], float)
        surfaces.append(Surface("ceiling", (top[::-1],)))
        surfaces.append(Surface("floor", (top + np.array([0.0, 0.0, 0.1]),)))
    b = Building("shop", shapely.box(0, 0, 20, 8), 10.0, base_z=0.0, surfaces=tuple(surfaces))
    return Site([b])


def test_negative_control_an_overhang_hides_what_is_above_it_and_nothing_once_removed():
    """Points just above a canopy seen from a station 8 m out at 1.5 m: the canopy hides
    them; without it they are seen. Points well above it are seen either way."""
    station = np.array([10.0, -8.0, 1.5])
    pts = np.array([[x, -0.02, z] for x in (5.0, 10.0, 15.0) for z in (3.2, 3.3, 7.0)])
    with_canopy = Scene(_canopy_site(True), "rays").seen(station, pts)
    without = Scene(_canopy_site(False), "rays").seen(station, pts)
    low = pts[:, 2] < 4
    assert not with_canopy[low].any()
    assert without.all()
    assert with_canopy[~low].all()


def test_negative_control_a_tree_crown_hides_and_its_trunk_does_not():
    """A tree with a crown from 3 m to 10 m between a station and a wall: the line at 5 m
    is blocked by the crown, the one at 1.5 m passes beside... under it only past the
    trunk; without the tree both are seen."""
    b = Building("b", shapely.box(0, 0, 20, 8), 12.0)
    tree = Obstacle("t", shapely.Point(10, -6).buffer(2.5), 10.0, "tree", crown_base_m=3.0)
    station = np.array([10.0, -12.0, 1.5])
    pts = np.array([[10.0, -0.02, 5.0], [13.0, -0.02, 1.5]])
    seen = Scene(Site([b], obstacles=[tree])).seen(station, pts)
    assert seen.tolist() == [False, True]
    assert Scene(Site([b])).seen(station, pts).all()
    assert Scene(Site([b], obstacles=[tree])).engine == "rays"


def test_inside_names_the_building_and_ignores_the_terrain_under_it():
    site = _canopy_site(False)
    scene = Scene(site, "rays")
    got = scene.inside(np.array([[10.0, 4.0, 2.0], [10.0, -2.0, 2.0], [30.0, 4.0, 2.0]]))
    assert got.tolist() == ["shop", "", ""]


def test_the_prism_engine_refuses_a_3d_site():
    with pytest.raises(Exception, match="prism engine"):
        Scene(_canopy_site(True), "prisms")
