"""The maps drawn to scale: the printed ones (the booklet's overview and station pages, the
report's plan map) and the dashboard's view, without a browser: a metre as long across as
up, grid values at round steps, a scale bar and a north arrow, the planned area framed (not
the whole file), a title that stays on the page."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from matplotlib.backends.backend_agg import FigureCanvasAgg
from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar
from sites import rect

from planner import plan
from planner.app.maps import round_step, round_ticks, scale_bar_length
from planner.site import Building, Site

ROUND = (1.0, 2.0, 5.0)


def _mantissa(v: float) -> float:
    return v / 10 ** math.floor(math.log10(v) + 1e-12)


@given(st.floats(min_value=1e-3, max_value=1e6))
def test_a_round_step_is_1_2_or_5_times_a_power_of_ten_and_the_least_above(raw):
    step = round_step(raw)
    assert step >= raw * (1 - 1e-9)
    assert any(math.isclose(_mantissa(step), m) for m in ROUND)
    below = [m * 10.0**e for e in range(-4, 8) for m in ROUND if m * 10.0**e < step * 0.999]
    assert all(b < raw * (1 - 1e-9) for b in below)  # none smaller would do


@given(st.floats(-1e7, 1e7), st.floats(1.0, 5e3), st.sampled_from([0.5, 1.0, 2.0, 20.0, 50.0]))
def test_round_ticks_are_the_multiples_of_the_step_in_the_range(lo, span, step):
    ticks = round_ticks(lo, lo + span, step)
    assert np.all(ticks >= lo - 1e-6) and np.all(ticks <= lo + span + 1e-6)
    assert np.allclose(ticks / step, np.round(ticks / step), atol=1e-6)
    assert len(ticks) >= math.floor(span / step)


def test_a_scale_bar_is_a_round_length_near_a_fifth_of_the_width():
    for span in (37.0, 100.0, 180.0, 950.0, 4200.0):
        length = scale_bar_length(span)
        assert any(math.isclose(_mantissa(length), m) for m in ROUND)
        assert span / 12 <= length <= span / 2


@pytest.fixture(scope="module")
def far_plan():
    """A 20 × 20 m building planned, and an unplanned one 400 m east (another building of
    the same file, as a district's): the plan's maps must not frame it."""
    site = Site(
        [
            Building("sq", rect(0, 0, 20, 20), 10.0),
            Building("far", rect(400, 0, 420, 20), 10.0, planned=False),
        ],
        crs="EPSG:25832",
        name="a site whose name is long enough to run off an A4 page if it were not broken "
        "into lines: Hauptstraße 1–17 and the courtyard behind them, Musterstadt",
    )
    return plan(site)


def _drawn(fig):
    FigureCanvasAgg(fig)
    fig.canvas.draw()
    return fig.canvas.get_renderer()


def _is_round_grid(ax) -> float:
    """The grid's step, the same across and up, a round one (1, 2 or 5 × 10^k m)."""
    xs, ys = ax.xaxis.get_majorticklocs(), ax.yaxis.get_majorticklocs()
    x0, x1 = ax.get_xlim()
    xs = xs[(xs >= x0) & (xs <= x1)]
    step = float(np.diff(xs)[0])
    assert np.allclose(np.diff(xs), step) and np.allclose(np.diff(ys), step)
    assert any(math.isclose(_mantissa(step), m) for m in ROUND), step
    assert np.allclose(xs / step, np.round(xs / step))
    return step


def _scale_bar_and_north(ax) -> None:
    assert any(isinstance(a, AnchoredSizeBar) for a in ax.artists)
    assert any(t.get_text() == "N" for t in ax.texts)


def test_the_booklet_overview_is_to_scale_and_frames_the_planned_area(far_plan):
    from planner.app.booklet import _overview

    fig = _overview(far_plan)
    renderer = _drawn(fig)
    ax = fig.axes[0]
    assert ax.get_aspect() == 1.0  # equal: a metre as long across as up
    box = ax.get_window_extent(renderer)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    assert (x1 - x0) / box.width == pytest.approx((y1 - y0) / box.height, rel=1e-3)  # m/px
    xy = far_plan.stations[["x", "y"]].to_numpy()
    assert np.all((xy[:, 0] > x0) & (xy[:, 0] < x1) & (xy[:, 1] > y0) & (xy[:, 1] < y1))
    assert x0 <= 500_000.0 and 500_020.0 <= x1  # the planned building
    assert x1 < 500_400.0  # the far building is not framed …
    assert not any(t.get_text().startswith("far") for t in ax.texts)  # … nor labelled
    _is_round_grid(ax)
    _scale_bar_and_north(ax)
    page = fig.bbox
    for text in (ax.title, ax.xaxis.label, ax.yaxis.label):  # nothing cut at the edges
        bb = text.get_window_extent(renderer)
        assert page.x0 <= bb.x0 and bb.x1 <= page.x1 and bb.y1 <= page.y1, text.get_text()
    assert "\n" in ax.title.get_text()  # (the long name broken into lines)
    for t in ax.yaxis.get_ticklabels():
        assert t.get_window_extent(renderer).x0 >= page.x0


def test_a_station_page_map_is_to_scale_with_a_round_grid(far_plan):
    from planner.app.booklet import _station_page
    from planner.pipeline.field.route import view_sectors

    sectors = view_sectors(far_plan.stations, far_plan.coverage, far_plan.targets)
    fig = _station_page(far_plan, 0, sectors)
    renderer = _drawn(fig)
    ax = fig.axes[0]
    assert ax.get_aspect() == 1.0
    box = ax.get_window_extent(renderer)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    assert (x1 - x0) / box.width == pytest.approx((y1 - y0) / box.height, rel=1e-3)
    _is_round_grid(ax)
    _scale_bar_and_north(ax)
    legend = ax.get_legend().get_window_extent(renderer)
    assert legend.x0 >= box.x1  # beside the map: it hides nothing on it


def test_the_report_plan_map_frames_the_planned_area(far_plan):
    from planner.app.maps import plot_plan_map

    fig = plot_plan_map(far_plan)
    _drawn(fig)
    ax = fig.axes[0]
    assert ax.get_aspect() == 1.0 and ax.get_xlim()[1] < 500_400.0
    _is_round_grid(ax)


def test_the_dashboard_map_keeps_one_scale_across_and_up(far_plan):
    """The dashboard's view, as the browser would size it: framed, resized, zoomed."""
    from planner.app.plan_map import PlanMap

    m = PlanMap(lambda *_a: None, lambda *_a: None, lambda **_k: None)
    m.show_plan(far_plan)

    def m_per_px():
        w, h = m.view.px
        return (m.sx.max - m.sx.min) / w, (m.sy.max - m.sy.min) / h

    for size in ([1023.6, 705.0], [480.0, 900.0]):
        m.view.probe.plot_px = size  # (as the page reports the plot area)
        mx, my = m_per_px()
        assert mx == pytest.approx(my, rel=1e-9)
        assert m.sx.max < 500_400.0  # the plan framed, not the far building
        xy = far_plan.stations[["x", "y"]].to_numpy()
        assert np.all((xy[:, 0] > m.sx.min) & (xy[:, 0] < m.sx.max))
        assert np.all((xy[:, 1] > m.sy.min) & (xy[:, 1] < m.sy.max))
        ticks = [np.asarray(a.tick_values) for a in m.view.axes]
        step = float(np.diff(ticks[0])[0])
        assert any(math.isclose(_mantissa(step), r) for r in ROUND)
        assert np.allclose(np.diff(ticks[1]), step)  # the same step up as across
    # a zoom in the browser (both scales by one factor), then a resize: the scale is kept
    with m.sx.hold_sync(), m.sy.hold_sync():
        cx, cy = (m.sx.min + m.sx.max) / 2, (m.sy.min + m.sy.max) / 2
        m.sx.min, m.sx.max = cx - (cx - m.sx.min) / 2, cx + (m.sx.max - cx) / 2
        m.sy.min, m.sy.max = cy - (cy - m.sy.min) / 2, cy + (m.sy.max - cy) / 2
    zoomed = m_per_px()
    m.view.probe.plot_px = [700.0, 700.0]
    assert m_per_px() == pytest.approx(zoomed, rel=1e-9)
    assert m.view.bar_label.text[0].endswith(" m") and list(m.view.north_label.text) == ["N"]
    tips = list(m.stations.names)
    assert tips and all("\nE " in t and "\nN " in t and "nearest station" in t for t in tips)


@pytest.mark.parametrize(
    ("ids", "lines"),
    [(["C1-1", "C1-2"], 1), ([1.0, 2.0], 2), ([], 0)],
    ids=["text", "numbers", "no traverse"],
)
def test_traverses_are_drawn_whatever_type_their_ids_have(default_plan, ids, lines):
    """The report of a district plan ended in AttributeError (".str accessor") where the
    traverse ids were not text: they are drawn as text, one line per traverse; none is
    drawn without them."""
    import copy

    import pandas as pd
    from matplotlib.figure import Figure

    from planner.app.maps import _draw_traverses

    p = copy.deepcopy(default_plan)
    rows = pd.DataFrame(
        {
            "station_id": ids,
            "purpose": ["traverse"] * len(ids),
            "x": [0.0, 10.0][: len(ids)],
            "y": [0.0, 5.0][: len(ids)],
        }
    )
    p.stations = rows if ids else rows.astype({"station_id": float})
    ax = Figure().subplots()
    _draw_traverses(p, ax)
    assert len(ax.lines) == lines  # one per traverse (C1-1, C1-2: the traverse C1)
