"""Line of sight: the compiled crossing test against shapely's segment intersections (the
exact geometry, ``clearance_m=0``), the clearance a sight line keeps from footprint
corners and roof edges, and targets on stands as obstacles."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from planner.pipeline.geometry.visibility import (
    SIGHT_CLEARANCE_M,
    STAND_RADIUS_M,
    bridge_interval,
    clear_height,
    edges_in_box,
    stand_blocks,
    visible,
)


def _reference(src, zs, dst, edges, heights):
    """z_clear by shapely: every edge a sight line crosses at one point strictly between
    its ends, at fraction t of the way, raises it to z_s + (H − z_s)/t."""
    out = np.full(len(src), -np.inf)
    lines = shapely.linestrings(np.stack([src, dst], axis=1))
    walls = shapely.linestrings(edges.reshape(-1, 2, 2))
    for i, line in enumerate(lines):
        hit = shapely.intersection(line, walls)
        for e in np.flatnonzero(shapely.get_type_id(hit) == 0):  # a single point
            t = shapely.line_locate_point(line, hit[e], normalized=True)
            if 1e-6 < t < 1 - 1e-6:
                out[i] = max(out[i], zs[i] + (heights[e] - zs[i]) / t)
    return out


@pytest.mark.parametrize("seed", range(5))
def test_clear_height_matches_shapely_on_random_walls(seed):
    rng = np.random.default_rng(seed)
    n_lines, n_edges = 300, 60
    src = rng.uniform(0, 100, (n_lines, 2))
    dst = rng.uniform(0, 100, (n_lines, 2))
    zs = rng.uniform(1.0, 2.0, n_lines)
    start = rng.uniform(0, 100, (n_edges, 2))
    edges = np.column_stack([start, start + rng.uniform(-15, 15, (n_edges, 2))])
    edges[:10, 3] = edges[:10, 1]  # some walls along the axes, as footprints often are
    edges[10:20, 2] = edges[10:20, 0]
    heights = rng.uniform(3.0, 30.0, n_edges)
    got = clear_height(src, zs, dst, edges, heights, clearance_m=0.0)
    want = _reference(src, zs, dst, edges, heights)
    blocked = np.isfinite(want)
    assert 30 < blocked.sum() < n_lines  # the random walls block some lines, not all
    np.testing.assert_array_equal(np.isfinite(got), blocked)
    np.testing.assert_allclose(got[blocked], want[blocked], rtol=0, atol=1e-6)  # m


@pytest.mark.parametrize("seed", range(3))
def test_grouped_lines_see_exactly_the_edges_in_their_box(seed):
    """Lines in groups (many scanner positions in one call), each group seen past the edges
    :func:`edges_in_box` selects for its box: the same heights, to the bit, as one call per
    group with those edges; and a box that holds no edge sees nothing."""
    rng = np.random.default_rng(seed)
    n_groups, per, n_edges = 6, 40, 80
    start = rng.uniform(0, 100, (n_edges, 2))
    edges = np.column_stack([start, start + rng.uniform(-15, 15, (n_edges, 2))])
    heights = rng.uniform(3.0, 30.0, n_edges)
    centre = rng.uniform(20, 80, (n_groups, 2))
    src = np.repeat(centre, per, axis=0)
    dst = src + rng.uniform(-30, 30, (n_groups * per, 2))
    zs = rng.uniform(1.0, 2.0, n_groups * per)
    half = rng.uniform(5, 40, n_groups)
    boxes = np.column_stack([centre - half[:, None], centre + half[:, None]])
    boxes[0] = [500.0, 500.0, 510.0, 510.0]  # far from every edge
    starts = np.arange(n_groups + 1) * per
    got = clear_height(src, zs, dst, edges, heights, groups=(starts, boxes))
    for g in range(n_groups):
        lines = slice(starts[g], starts[g + 1])
        near = edges_in_box(edges, tuple(boxes[g]))
        want = clear_height(src[lines], zs[lines], dst[lines], edges[near], heights[near])
        np.testing.assert_array_equal(got[lines], want)
    assert np.all(got[:per] == -np.inf)
    assert np.isfinite(got).sum() > 20  # the walls block some lines


def test_clear_height_ignores_walls_the_line_only_touches_or_runs_along():
    edges = np.array(
        [
            [10.0, -5.0, 10.0, 5.0],  # crossed halfway: counts
            [0.0, 0.0, 20.0, 0.0],  # along the line itself: parallel, no crossing
            [-5.0, -5.0, 5.0, 5.0],  # through the scanner's own position: t = 0
            [25.0, -1.0, 25.0, 1.0],  # beyond the facade end: t > 1
        ]
    )
    z = clear_height(
        np.array([[0.0, 0.0]]), 1.5, np.array([[20.0, 0.0]]), edges, np.full(4, 9.0), 0.0
    )
    assert z[0] == pytest.approx(1.5 + (9.0 - 1.5) / 0.5, abs=1e-9)  # m: 16.5 from the halfway wall
    # and a scanner and facade point with nothing between: -inf
    z = clear_height(
        np.array([[0.0, 0.0]]), 1.5, np.array([[5.0, 0.0]]), edges[:1], np.ones(1), clearance_m=0.0
    )
    assert z[0] == -np.inf


#: A 10 m square building, 8 m high, with its north-west corner at (10, 10).
BOX = np.array([[10.0, 0.0, 10.0, 10.0], [10.0, 10.0, 20.0, 10.0], [20.0, 10.0, 20.0, 0.0]])


def _past_the_corner(miss_m: float) -> np.ndarray:
    """Clear height of a point 10 m beyond the corner (10, 10), seen from (0, 10 + 2·miss)
    low at 1.5 m: the sight line passes the corner ``miss_m`` outside the footprint."""
    src = np.array([[0.0, 10.0 + 2 * miss_m]])
    dst = np.array([[20.0, 10.0]])  # the line passes x = 10 at y = 10 + miss
    return clear_height(src, 1.5, dst, BOX, np.full(3, 8.0))


def test_a_sight_line_grazing_a_corner_is_blocked_one_passing_clear_is_not():
    """The 2.5-D test is exact at float precision, so a line passing a building corner by
    1 mm counted as seen — in 3-D (ray casting on the extruded footprints; the beam has a
    width) such samples were hidden. A sight line keeps SIGHT_CLEARANCE_M from every
    footprint edge: 1 mm past the corner is blocked, 0.1 m past it is seen (the control)."""
    assert SIGHT_CLEARANCE_M == pytest.approx(0.02, abs=1e-12)  # m
    grazing = _past_the_corner(0.001)
    assert visible(np.array([3.0]), grazing)[0] == False  # noqa: E712 — hidden at 3 m
    assert grazing[0] > 8.0  # m: only over the roof
    clear = _past_the_corner(0.1)
    assert clear[0] == -np.inf  # nothing crossed
    # the exact geometry (no clearance) passes the grazing line: today's knife edge
    exact = clear_height(
        np.array([[0.0, 10.002]]), 1.5, np.array([[20.0, 10.0]]), BOX, np.full(3, 8.0), 0.0
    )
    assert exact[0] == -np.inf


def test_a_sight_line_grazing_a_roof_edge_is_blocked_one_passing_clear_is_not():
    """Over a lower building's roof: a point whose sight line passes the roof edge 1 mm
    above it is hidden; 0.1 m above it, seen. The clearance adds SIGHT_CLEARANCE_M / t at
    the point (t: where along the line the edge is crossed)."""
    wall = np.array([[10.0, -5.0, 10.0, 5.0]])  # a 6 m wall halfway to a facade at x = 20
    src, dst = np.array([[0.0, 0.0]]), np.array([[20.0, 0.0]])
    exact = clear_height(src, 1.5, dst, wall, np.array([6.0]), clearance_m=0.0)[0]
    padded = clear_height(src, 1.5, dst, wall, np.array([6.0]))[0]
    assert exact == pytest.approx(10.5, abs=1e-9)  # m: 1.5 + (6 − 1.5) / 0.5
    assert padded == pytest.approx(10.5 + SIGHT_CLEARANCE_M / 0.5, abs=1e-9)  # m
    just_over = exact + 2 * 0.001  # the line passes the edge 1 mm above it
    assert visible(np.array([just_over]), exact)[0]  # the knife edge: seen without clearance
    assert not visible(np.array([just_over]), padded)[0]
    assert visible(np.array([exact + 2 * 0.1]), padded)[0]  # 0.1 m above the edge: seen


def test_the_floors_over_a_passage_keep_the_clearance_too():
    """A line under a gateway's floors (bottom 4 m, top 12 m) hides a wider band by the
    clearance at both ends."""
    bridge = np.array([[10.0, -5.0, 10.0, 5.0]])
    src, dst = np.array([[0.0, 0.0]]), np.array([[20.0, 0.0]])
    lo0, up0 = bridge_interval(src, 1.5, dst, bridge, np.array([4.0]), np.array([12.0]), 0.0)
    lo, up = bridge_interval(src, 1.5, dst, bridge, np.array([4.0]), np.array([12.0]))
    assert lo0[0] == pytest.approx(6.5, abs=1e-9) and up0[0] == pytest.approx(22.5, abs=1e-9)
    assert lo[0] == pytest.approx(6.5 - SIGHT_CLEARANCE_M / 0.5, abs=1e-9)  # m
    assert up[0] == pytest.approx(22.5 + SIGHT_CLEARANCE_M / 0.5, abs=1e-9)  # m


def test_a_sphere_on_its_stand_hides_what_is_behind_it():
    """A station at 1.5 m sighting a target 20 m away at 1.6 m: a 0.2 m-radius sphere on the
    line 12 m out hides it; one 0.25 m beside the line (past radius + clearance) does not,
    nor one behind the target or behind the station; its stand (a pole up to the sphere)
    hides a line that passes over it lower down, not one passing above the sphere."""
    src = np.array([[0.0, 0.0, 1.5]])
    dst = np.array([[20.0, 0.0, 1.6]])
    spheres = np.array(
        [
            [12.0, 0.0, 1.56],  # on the line
            [12.0, 0.25, 1.56],  # beside it, 0.25 m > 0.2 + 0.02
            [12.0, 0.21, 1.56],  # beside it, within radius + clearance
            [22.0, 0.0, 1.6],  # behind the target
            [-2.0, 0.0, 1.5],  # behind the station
        ]
    )
    got = stand_blocks(src, dst, spheres, 0.2)[0]
    assert got.tolist() == [True, False, True, False, False]
    # the stand: a line descending to a mark on the ground passes over a stand 10 m out at
    # 0.75 m, below its sphere at 1.6 m (hidden); a line rising to 3 m passes the sphere's
    # top (1.8 m) at 2.25 m (seen)
    stand = np.array([[10.0, 0.0, 1.6]])
    down = stand_blocks(src, np.array([[20.0, 0.0, 0.0]]), stand, 0.2)[0, 0]
    up = stand_blocks(src, np.array([[20.0, 0.0, 3.0]]), stand, 0.2)[0, 0]
    assert down and not up
    # the pole's width: a descending line 0.06 m beside it is hidden, 0.08 m beside it seen
    assert STAND_RADIUS_M + SIGHT_CLEARANCE_M == pytest.approx(0.07, abs=1e-12)  # m
    near = np.array([[10.0, 0.06, 1.6]])
    far = np.array([[10.0, 0.08, 1.6]])
    low = np.array([[20.0, 0.0, 0.0]])
    assert stand_blocks(src, low, near, 0.01)[0, 0] and not stand_blocks(src, low, far, 0.01)[0, 0]


def _stand_blocks_numpy(src, dst, centre, radius, stand_r=STAND_RADIUS_M, clear=SIGHT_CLEARANCE_M):
    """The stand test written with NumPy arrays (every pair at once), as a reference."""
    p, v = src[:, None, :], dst[:, None, :] - src[:, None, :]
    c = centre[None, :, :]
    r = np.broadcast_to(np.asarray(radius, dtype=float), c.shape[1:2])[None, :]
    w = c - p
    with np.errstate(divide="ignore", invalid="ignore"):
        t3 = (w * v).sum(axis=-1) / (v * v).sum(axis=-1)
        d3 = np.linalg.norm(w - t3[..., None] * v, axis=-1)
        vh, wh = v[..., :2], w[..., :2]
        t2 = (wh * vh).sum(axis=-1) / (vh * vh).sum(axis=-1)
        d2 = np.linalg.norm(wh - t2[..., None] * vh, axis=-1)
        z = p[..., 2] + t2 * v[..., 2]
    sphere = (t3 > 0) & (t3 < 1) & (d3 < r + clear)
    stand = (t2 > 0) & (t2 < 1) & (d2 < stand_r + clear) & (z < c[..., 2] - r + clear)
    return sphere | stand


def test_the_compiled_stand_test_is_the_numpy_one_pair_for_pair():
    """Random lines (some of zero length, some through a sphere's centre) against random
    spheres and stands: the compiled loop answers as the vectorised NumPy test does."""
    rng = np.random.default_rng(7)
    blocked = 0
    for n in range(200):
        src, dst = rng.uniform(-20, 20, (2, rng.integers(1, 40), 3))
        centre = rng.uniform(-20, 20, (rng.integers(0, 10), 3))
        if n % 10 == 0:
            dst[0] = src[0]  # a line of no length
        if n % 7 == 0 and len(centre):
            centre[0] = (src[0] + dst[0]) / 2  # a sphere on the line
        radius = rng.uniform(0.05, 0.3, len(centre)) if n % 2 else 0.1
        stand_r = 2.0 if n % 3 == 0 else STAND_RADIUS_M  # wide stands: more of them hit
        want = _stand_blocks_numpy(src, dst, centre, radius, stand_r)
        got = stand_blocks(src, dst, centre, radius, stand_radius_m=stand_r)
        np.testing.assert_array_equal(got, want)
        blocked += int(want.sum())
    assert blocked > 100  # the comparison met blocked pairs, not only clear ones


def test_one_end_is_shared_by_every_sight_line_as_before():
    """One station against many targets (the ends broadcast, as NumPy's test did)."""
    src = np.array([[0.0, 0.0, 1.5]])
    dst = np.array([[20.0, 0.0, 1.5], [20.0, 5.0, 1.5], [20.0, -5.0, 1.5]])
    centre = np.array([[10.0, 0.0, 1.5], [10.0, 2.5, 1.5]])
    want = _stand_blocks_numpy(np.repeat(src, 3, axis=0), dst, centre, 0.1)
    np.testing.assert_array_equal(stand_blocks(src, dst, centre, 0.1), want)
    np.testing.assert_array_equal(stand_blocks(dst, src, centre, 0.1), want)
    assert want.sum() == 2  # the first line by the first sphere, the second by the second


@pytest.mark.parametrize("engine", ["prisms", "rays"])
def test_a_round_tower_drawn_as_many_edges_is_seen_all_round(engine):
    """A tower of 20 m radius drawn as 200 edges (0.63 m each): its facades are merged
    chords up to 10 cm behind the drawn outline, and the outline is the facade itself, not
    a wall in front of it (prisms), and its rays end in front of them (rays) — every sample
    is met by a few stations (it was 1 station and 6 of 402 samples with either engine).
    Negative control: the drawn edges do stand in front of the chord."""
    import planner
    from planner.pipeline.geometry.facades import MERGE_OFFSET_M
    from planner.pipeline.geometry.visibility import edges_in_front, own_edges
    from planner.site import Building, Site

    a = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    ring = np.c_[20 * np.cos(a), 20 * np.sin(a)] + [500000.0, 5400000.0]
    site = Site([Building("tower", shapely.Polygon(ring), 12.0)], crs="EPSG:25832")
    p = planner.plan(site, settings=planner.PlanSettings(time_limit_s=60, sight_engine=engine))
    assert len(p.facades) == 34  # merged: 200 edges → 34 facades
    assert p.coverage["meets"].all() and 3 <= len(p.stations) <= 8
    edges = np.array([[*ring[k], *ring[(k + 1) % 200]] for k in range(200)])
    f = p.facades.iloc[0]
    start, end = np.array([f.x0, f.y0]), np.array([f.x1, f.y1])
    normal = np.array([end[1] - start[1], start[0] - end[0]]) / f.length_m
    normal *= np.sign(normal @ (start - ring.mean(axis=0)))  # outward
    box = (*(ring.min(axis=0) - 50), *(ring.max(axis=0) + 50))
    front = edges_in_front(edges, start, normal, box)
    own = own_edges(edges, start, normal, end, MERGE_OFFSET_M)
    assert own.sum() >= 5 and (front & own).sum() >= 4  # its run: in front of its chord …
    assert own.sum() < 10  # … and no other edge of the tower
