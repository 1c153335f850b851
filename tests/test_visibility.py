"""Line of sight: the compiled crossing test against shapely's segment intersections."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from planner.pipeline.visibility import clear_height


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
    got = clear_height(src, zs, dst, edges, heights)
    want = _reference(src, zs, dst, edges, heights)
    blocked = np.isfinite(want)
    assert 30 < blocked.sum() < n_lines  # the random walls block some lines, not all
    np.testing.assert_array_equal(np.isfinite(got), blocked)
    np.testing.assert_allclose(got[blocked], want[blocked], rtol=0, atol=1e-6)  # m


def test_clear_height_ignores_walls_the_line_only_touches_or_runs_along():
    edges = np.array(
        [
            [10.0, -5.0, 10.0, 5.0],  # crossed halfway: counts
            [0.0, 0.0, 20.0, 0.0],  # along the line itself: parallel, no crossing
            [-5.0, -5.0, 5.0, 5.0],  # through the scanner's own position: t = 0
            [25.0, -1.0, 25.0, 1.0],  # beyond the facade end: t > 1
        ]
    )
    z = clear_height(np.array([[0.0, 0.0]]), 1.5, np.array([[20.0, 0.0]]), edges, np.full(4, 9.0))
    assert z[0] == pytest.approx(1.5 + (9.0 - 1.5) / 0.5, abs=1e-9)  # m: 16.5 from the halfway wall
    # and a scanner and facade point with nothing between: -inf
    z = clear_height(np.array([[0.0, 0.0]]), 1.5, np.array([[5.0, 0.0]]), edges[:1], np.ones(1))
    assert z[0] == -np.inf
