"""End to end in a real browser: Voilà serves the station planner on loopback; headless
Debian Chromium (driven by playwright) works on one page as a surveyor would, test after
test in the order of this file (each needs only a page showing a plan): labels that fit at
1280 and 1920 px, a changed input marking the plan out of date, the field work tab and its
downloads, stations dragged, added, deleted and locked, an unmet requirement explained, a
cancelled plan, a stricter requirement and a bad upload. One page (one kernel) for all of
them: a page load runs the whole notebook. Screenshots go to test-artifacts/. Nothing may be
fetched from outside the machine."""

from __future__ import annotations

import os
import re
import shutil
import socket
import subprocess
import tempfile
import time
import zipfile
from pathlib import Path

import numpy as np
import pytest

from planner.app.notebooks import notebook_path
from planner.app.serve import _stop, server_state, voila_command

# one worker runs this module (scripts/test distributes by file): one dashboard server and
# one page for all of its tests
pytestmark = pytest.mark.browser

CHROMIUM = "/usr/bin/chromium"
ARTIFACTS = Path(__file__).resolve().parent.parent / "test-artifacts"
FLAGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _need_browser():
    if not Path(CHROMIUM).exists() or shutil.which("chromium") is None:
        if os.environ.get("CI"):
            pytest.fail(
                "Debian's chromium is missing: scripts/setup dev installs it "
                "(apt-get install chromium)"
            )
        pytest.skip("Debian's chromium is not installed (scripts/setup dev installs it)")
    return pytest.importorskip("playwright.sync_api")


#: The log (Voilà's and its kernels' output) of each server running, by its URL.
LOGS: dict = {}


def _log_tail(page, n: int = 3000) -> str:
    """The end of the log of the server that serves ``page``."""
    log = next((log for url, log in LOGS.items() if page.url.startswith(url)), None)
    if log is None:
        return "(no log)"
    size = os.fstat(log.fileno()).st_size  # read where the server is not writing: pread
    return os.pread(log.fileno(), n, max(0, size - n)).decode(errors="replace")


def _serve(notebook: str, **env_extra: str):
    """Serve one shipped dashboard as ``planner serve --notebook`` does; yield its URL once
    its pre-started kernel has run the dashboard (as ``planner serve`` says "ready")."""
    _need_browser()
    port = free_port()
    cmd, env = voila_command(notebook_path(notebook), port)
    # one page per server here: the kernel the server would warm for a next page (the whole
    # dashboard and its plan, beside the page's own work) is not started (test_serve
    # checks that one is). A second page on one of these servers would wait for it: open
    # it on a server of its own
    cmd.append("--VoilaKernelManager.fill_delay=86400")
    env.update(env_extra)
    # Voilà's log to a file: a pipe nobody reads fills up and stalls the server
    log = tempfile.TemporaryFile()
    proc = subprocess.Popen(
        cmd, env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True
    )
    url = f"http://127.0.0.1:{port}/"
    deadline = time.time() + 90
    while time.time() < deadline:
        if proc.poll() is not None:
            log.seek(0)
            pytest.fail(f"voila exited: {log.read().decode(errors='replace')[-2000:]}")
        if server_state(port) == "warm":
            break
        time.sleep(0.5)
    else:
        _stop(proc, grace_s=0.0)
        pytest.fail("voila did not answer within 90 s")
    LOGS[url] = log
    yield url
    _stop(proc, grace_s=0.0)  # its kernels too, at once (stopping cleanly: test_serve)
    del LOGS[url]
    log.close()


@pytest.fixture(scope="module")
def dashboard_url():
    yield from _serve("station_planner.ipynb")


def _set_number(page, label: str, value: str) -> None:
    box = page.locator(f".widget-inline-hbox:has(label:text-is('{label}')) input")
    box.fill(value)
    box.press("Enter")


#: The toolbar (Plan, status) stays at the top of the window over this many px of the page.
TOOLBAR_PX = 120

#: Requests the shared page made to anything not on this machine.
EXTERNAL: list[str] = []
#: The station count of the first plan the page showed (the default site's).
FIRST: list[str] = []


@pytest.fixture(scope="module")
def browser():
    """One headless Chromium for the module (playwright's sync API runs one at a time)."""
    sync = _need_browser()
    ARTIFACTS.mkdir(exist_ok=True)
    with sync.sync_playwright() as pw:
        b = pw.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        yield b
        b.close()


@pytest.fixture(scope="module")
def page(browser, dashboard_url):
    """One page of the dashboard for the module's tests, opened at 1500 px; the time from
    the request to the first plan on screen is printed."""
    local = ("http://127.0.0.1", "ws://127.0.0.1", "data:", "blob:", "about:")
    pg = browser.new_page(viewport={"width": 1500, "height": 1100}, accept_downloads=True)
    pg.on("request", lambda r: None if r.url.startswith(local) else EXTERNAL.append(r.url))
    t0 = time.perf_counter()
    pg.goto(dashboard_url, timeout=120_000)
    pg.locator(".station-count").wait_for(timeout=120_000)
    print(f"page load to first plan: {time.perf_counter() - t0:.1f} s")
    FIRST[:] = [pg.locator(".station-count").inner_text()]
    yield pg
    pg.close()


def _plan_and_wait(page) -> None:
    """Press Plan and wait until the plan of the inputs on screen is shown; if it is not,
    the failure says what the page showed and what the server (and the kernel) logged."""
    status = page.locator(".planner-status")
    error = page.locator(".planner-toolbar .planner-error")
    old = status.inner_text()
    assert error.count() == 0, f"an error on the page before Plan: {error.first.inner_text()}"
    page.get_by_role("button", name="Plan", exact=True).click()
    try:
        page.wait_for_function(
            "(old) => { const t = document.querySelector('.planner-status').innerText;"
            " return (t !== old && t.includes('planning: done'))"
            " || document.querySelector('.planner-toolbar .planner-error') !== null; }",
            arg=old,
            timeout=120_000,
        )
    except Exception as exc:  # playwright's TimeoutError
        page.screenshot(path=str(ARTIFACTS / "dashboard-plan-timeout.png"), full_page=True)
        pytest.fail(f"{exc}\nstatus line: {status.inner_text()!r}\nserver log:\n{_log_tail(page)}")
    assert error.count() == 0, f"{error.first.inner_text()}\nserver log:\n{_log_tail(page)}"


@pytest.mark.parametrize("width", [1280, 1920])
def test_no_label_is_cut_off(page, width):
    page.set_viewport_size({"width": width, "height": 1100})
    more = page.get_by_text("More settings (as on the command line)")
    if width == 1280:
        more.click()  # opened once, stays open
    _open_map(page)
    page.wait_for_timeout(500)
    cut = _cut_off(page)
    page.screenshot(path=str(ARTIFACTS / f"dashboard-{width}px.png"), full_page=True)
    page.locator(".planner-map").scroll_into_view_if_needed()
    page.screenshot(path=str(ARTIFACTS / f"dashboard-map-{width}px.png"))
    page.set_viewport_size({"width": 1500, "height": 1100})
    assert cut == [], f"cut off at {width} px: {cut}"


def _ticks(page) -> tuple[list[tuple[float, float]], list[tuple[float, float]]]:
    """The map's grid ticks as (value [m], position [px]) for the eastings and the
    northings, the positions from the ticks' own transforms (no text measured)."""
    ticks = page.evaluate(
        """() => [...document.querySelectorAll('.planner-map g.tick')].map(t => {
            const m = /translate\\(([-0-9.e]+)[ ,]+([-0-9.e]+)\\)/.exec(
                t.getAttribute('transform'));
            return {v: parseFloat(t.textContent.replace(/[^0-9.-]/g, '')),
                    x: m ? parseFloat(m[1]) : NaN, y: m ? parseFloat(m[2]) : NaN};
        }).filter(t => isFinite(t.v) && isFinite(t.x))"""
    )
    east = [(t["v"], t["x"]) for t in ticks if 1e5 <= t["v"] < 1e6]  # (6 digits)
    north = [(t["v"], t["y"]) for t in ticks if t["v"] >= 1e6]  # (7 digits)
    return east, north


def _m_per_px(page) -> tuple[float, float]:
    """Metres per pixel across and up on the map as drawn: the slopes of its ticks."""
    east, north = _ticks(page)
    assert len(east) >= 3 and len(north) >= 3, (east, north)
    sx = np.polyfit([v for v, _ in east], [p for _, p in east], 1)[0]
    sy = np.polyfit([v for v, _ in north], [p for _, p in north], 1)[0]
    return 1.0 / sx, -1.0 / sy  # (a northing grows up the screen)


def _round(values: list[float]) -> bool:
    """Whether the values are multiples of one round step (1, 2 or 5 × 10^k m), one step
    apart."""
    steps = np.diff(sorted(values))
    step = float(steps[0])
    mantissa = step / 10 ** np.floor(np.log10(step))
    return (
        np.allclose(steps, step)
        and any(np.isclose(mantissa, m) for m in (1.0, 2.0, 5.0))
        and all(abs(v / step - round(v / step)) < 1e-6 for v in values)
    )


def test_the_map_is_to_scale_with_round_grid_values(page):
    """A metre as long across as up (within 1 %) on the default site's plan, as framed, the
    whole site, after a zoom and at another window size; the grid's values round (multiples
    of 1, 2 or 5 × 10^k m, the same step across and up); a scale bar and a north arrow."""
    _open_map(page)
    seen = {}
    for view in ("plan", "whole site", "zoomed", "1280 px wide"):
        if view == "whole site":
            page.get_by_role("button", name="Whole site").click()
        elif view == "zoomed":
            _mode(page, "Pan / zoom")
            box = page.locator(".planner-map").bounding_box()
            page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
            page.mouse.wheel(0, -300)
        elif view == "1280 px wide":
            page.set_viewport_size({"width": 1280, "height": 900})
            _open_map(page)
        page.wait_for_timeout(1500)  # (the view drawn, the kernel's ticks sent back)
        mx, my = _m_per_px(page)
        seen[view] = (mx, my)
        assert mx == pytest.approx(my, rel=0.01), (view, mx, my)  # m/px
        east, north = _ticks(page)
        assert _round([v for v, _ in east]) and _round([v for v, _ in north]), (view, east, north)
        assert np.diff([v for v, _ in east])[0] == np.diff([v for v, _ in north])[0]
    print("m/px across, up:", {k: (round(a, 4), round(b, 4)) for k, (a, b) in seen.items()})
    words = page.evaluate(
        "() => [...document.querySelectorAll('.planner-map text')].map(t => t.textContent)"
    )
    assert "N" in words and any(t.endswith(" m") and t[:-2].isdigit() for t in words), words
    page.locator(".planner-map").screenshot(path=str(ARTIFACTS / "dashboard-map-to-scale.png"))
    page.set_viewport_size({"width": 1500, "height": 1100})
    _mode(page, "Move (drag)")
    page.get_by_role("button", name="Fit to the plan").click()
    page.wait_for_timeout(1000)


def test_hovering_a_station_or_target_tells_where_it_stands(page):
    """The tooltip of a station: its id and purpose, easting and northing, the ground's
    and the instrument's heights, and the nearest other station with its distance; of a
    target: its id, easting, northing, height and the nearest station."""
    _open_map(page)
    b = _station_in_the_clear(page)
    page.mouse.move(b["x"], b["y"])
    tip = page.locator(".bqplot_tooltip_div:visible")
    tip.wait_for(timeout=10_000)
    text = tip.inner_text()
    lines = [t.strip() for t in text.splitlines() if t.strip()]
    east = [float(t[2:-2].replace(" ", "")) for t in lines if t.startswith("E ")]
    north = [float(t[2:-2].replace(" ", "")) for t in lines if t.startswith("N ")]
    assert 690_900 < east[0] < 691_200 and 5_334_900 < north[0] < 5_335_100, text  # m
    assert "ground " in text and "instrument " in text and "above it" in text, text
    assert "nearest station: S" in text and text.rstrip().endswith(" m"), text
    page.screenshot(path=str(ARTIFACTS / "dashboard-map-hover.png"))
    targets = _marks(page, 5, 10)
    box = page.locator(".planner-map").bounding_box()
    t = min(targets, key=lambda q: abs(q["x"] - box["x"]) + abs(q["y"] - box["y"]))
    page.mouse.move(t["x"], t["y"])
    page.wait_for_function(
        "() => [...document.querySelectorAll('.bqplot_tooltip_div')]"
        ".some(d => d.offsetParent !== null && d.innerText.includes('height '))",
        timeout=10_000,
    )
    text = page.locator(".bqplot_tooltip_div:visible").inner_text()
    assert "target" in text and "nearest station: S" in text and "E " in text, text
    page.mouse.move(box["x"] + 5, box["y"] + box["height"] - 5)


def _cut_off(page) -> list[str]:
    """The texts of labels, buttons, tabs and selects that do not fit: wider than their own
    box (measured overflow), clipped by an ancestor that hides overflow, or — a select —
    whose chosen text, measured in its font, is wider than the box."""
    return page.evaluate(
        """() => {
        const out = [];
        const clipped = (e) => {
            const r = e.getBoundingClientRect();
            for (let a = e.parentElement; a; a = a.parentElement) {
                const st = getComputedStyle(a);
                // inside a scroller (a pane, the page) the user scrolls to it: not a cut
                if (/auto|scroll/.test(st.overflowX + st.overflowY)) return false;
                const b = a.getBoundingClientRect();
                if (/hidden|clip/.test(st.overflowX) &&
                    (r.right > b.right + 1 || r.left < b.left - 1)) return true;
                if (/hidden|clip/.test(st.overflowY) &&
                    (r.bottom > b.bottom + 1 || r.top < b.top - 1)) return true;
            }
            return false;
        };
        for (const e of document.querySelectorAll(
                '.widget-label, .widget-label-basic, .widget-button, .widget-toggle-button,'
                + ' .lm-TabBar-tabLabel, .widget-checkbox label, .widget-upload')) {
            if (e.offsetParent === null || !e.innerText.trim()) continue;  // not shown
            if (e.scrollWidth > e.clientWidth + 1 || clipped(e)) out.push(e.innerText);
        }
        const ctx = document.createElement('canvas').getContext('2d');
        for (const s of document.querySelectorAll('select')) {
            if (s.offsetParent === null) continue;
            const st = getComputedStyle(s);
            ctx.font = st.font;
            const text = s.options[s.selectedIndex].text;
            if (ctx.measureText(text).width + 30 > s.clientWidth) out.push(text);
        }
        return out;
    }"""
    )


def test_the_plan_button_and_status_stay_in_sight(page):
    """Scrolled to the bottom of the page, the toolbar (Plan, progress, status) is still at
    the top of the window."""
    scroll = """(to) => { for (const e of document.querySelectorAll('*')) {
        const y = getComputedStyle(e).overflowY;
        if ((y === 'auto' || y === 'scroll') && e.scrollHeight > e.clientHeight + 10)
            e.scrollTop = to === 'end' ? e.scrollHeight : 0; } }"""
    page.evaluate(scroll, "end")
    page.wait_for_timeout(300)
    for locator in (
        page.get_by_role("button", name="Plan", exact=True),
        page.locator(".planner-status"),
    ):
        box = locator.bounding_box()
        assert box is not None and 0 <= box["y"] <= 120, box  # px from the window's top
    page.evaluate(scroll, "top")


def test_changed_input_marks_the_plan_out_of_date(page):
    assert page.locator(".planner-stale-banner").count() == 0
    _set_number(page, "largest m_z [mm]", "4")
    banner = page.locator(".planner-stale-banner")
    banner.wait_for(timeout=30_000)
    assert "Out of date" in banner.inner_text()
    _plan_and_wait(page)
    assert page.locator(".planner-stale-banner").count() == 0


def test_field_work_tab_shows_the_visiting_order(page):
    n = int(page.locator(".station-count").inner_text().split()[0])
    page.get_by_text("Stations & field work", exact=True).click()
    summary = page.locator("p:has-text('Field time:')")
    summary.wait_for(timeout=30_000)
    assert "Visiting order:" in summary.inner_text()
    rows = page.locator(".widget-output table").last.locator("tbody tr")
    assert rows.count() == n
    page.screenshot(path=str(ARTIFACTS / "dashboard-field-work.png"), full_page=True)
    page.get_by_text("Downloads", exact=True).click()  # (its files made when it opens)
    page.locator("a.planner-download[download='route.csv']").first.wait_for(timeout=30_000)
    assert page.locator("a.planner-download[download='route.csv']").count() == 1
    page.get_by_role("button", name="Make field booklet (PDF)").click()
    booklet = page.locator("a.planner-download[download='booklet.pdf']")
    booklet.first.wait_for(timeout=120_000)
    page.screenshot(path=str(ARTIFACTS / "dashboard-booklet.png"), full_page=True)
    # plan.zip now holds the booklet with every file of the plan
    with page.expect_download() as download:
        page.locator("a.planner-download[download='plan.zip']").click()
    with zipfile.ZipFile(download.value.path()) as z:
        names = set(z.namelist())
    assert {"booklet.pdf", "route.csv", "stations.csv", "summary.txt"} <= names, names


def _station_boxes(page) -> list[dict]:
    """Screen centres of the station triangles of the map (the large marks)."""
    return _marks(page, 10, 1e9)


def _station_in_the_clear(page) -> dict:
    """The station mark on screen farthest from every other mark (a click on it reaches
    it, not a target drawn beside it)."""
    everything = _marks(page, 0, 1e9)
    view = page.viewport_size

    def room(b):
        others = [q for q in everything if (q["x"], q["y"]) != (b["x"], b["y"])]
        return min(abs(q["x"] - b["x"]) + abs(q["y"] - b["y"]) for q in others)

    shown = [
        b
        for b in _station_boxes(page)
        if 0 < b["x"] < view["width"] and TOOLBAR_PX < b["y"] < view["height"]
    ]
    return max(shown, key=room)


def _open_map(page) -> None:
    """Open the Map tab (the one map of the site, the plan and the edits)."""
    page.locator(".lm-TabBar-tabLabel:text-is('Map')").click()
    page.locator(".planner-map").wait_for(timeout=30_000)
    # the whole map in the window, below the toolbar that stays at the top
    page.evaluate("() => document.querySelector('.planner-map').scrollIntoView({block: 'end'})")
    page.wait_for_timeout(300)


def _mode(page, name: str) -> None:
    """Choose what a click on the map does (the button is above the map: clicking it
    scrolls the page; the map is brought back whole into the window)."""
    page.get_by_role("button", name=name, exact=True).click()
    page.evaluate("() => document.querySelector('.planner-map').scrollIntoView({block: 'end'})")
    page.wait_for_timeout(300)


def _edit_tab_stations(page) -> list[dict]:
    """Open the Map tab; the screen centres of its station marks, one for each station
    the plan's count says."""
    n = int(page.locator(".station-count").inner_text().split()[0])
    _open_map(page)
    page.wait_for_timeout(1000)
    boxes = _station_boxes(page)
    assert len(boxes) == n
    return boxes


def test_dragging_a_station_changes_the_coverage(page):
    """A station dragged onto free ground is judged again; one dragged into a building or
    a no-go area is refused, saying why, and snaps back (the next station is tried)."""
    boxes = _edit_tab_stations(page)
    status = page.locator(".planner-map-status")
    view = page.viewport_size
    for k in range(len(boxes)):
        b = boxes[k]
        if not (TOOLBAR_PX < b["y"] < view["height"] - 40 and b["x"] < view["width"] - 40):
            continue  # (under the toolbar, or its drag would leave the window)
        old = status.inner_text()
        page.mouse.move(b["x"], b["y"])
        page.mouse.down()
        page.mouse.move(b["x"] + 30, b["y"] + 20, steps=8)
        t0 = time.perf_counter()
        page.mouse.up()
        page.wait_for_function(
            "(old) => { const t = document.querySelector('.planner-map-status').innerText;"
            " return t !== old && (t.includes('judged') || t.includes('Not moved')); }",
            arg=old,
            timeout=30_000,
        )
        seen_s = time.perf_counter() - t0
        text = status.inner_text()
        if "judged" in text:
            break
        assert text.startswith("Not moved: ") and "move it onto free ground" in text, text
    else:
        pytest.fail("no station could be dragged onto free ground")
    edit_s = float(page.locator(".planner-edit-s").inner_text())
    print(f"re-evaluation after a drag: {edit_s:.2f} s in the kernel, {seen_s:.2f} s on screen")
    assert "samples meet the requirement" in text
    assert edit_s < 5.0  # s: generous for a loaded CI machine; the benchmark measures it
    for _ in range(25):  # the marks are redrawn just after the status: wait for them
        moved = _station_boxes(page)
        if abs(moved[k]["x"] - b["x"]) > 10 or abs(moved[k]["y"] - b["y"]) > 10:  # px
            break
        page.wait_for_timeout(200)
    assert abs(moved[k]["x"] - b["x"]) > 10 or abs(moved[k]["y"] - b["y"]) > 10  # px
    page.screenshot(path=str(ARTIFACTS / "dashboard-edit-stations.png"), full_page=True)


def _marks(page, lo: float, hi: float) -> list[dict]:
    """Screen centres of the map's marks between ``lo`` and ``hi`` px wide
    (stations are the large triangles, targets the middle-sized diamonds, samples small)."""
    return page.evaluate(
        """([lo, hi]) => {
        const fig = document.querySelector('.planner-map');
        return [...fig.querySelectorAll('g.object_grp path.dot')]
            .map(d => d.getBoundingClientRect())
            .filter(r => r.width > lo && r.width <= hi)
            .map(r => ({x: r.x + r.width / 2, y: r.y + r.height / 2}));
    }""",
        [lo, hi],
    )


def _status_after(page, action, timeout_ms: int = 30_000) -> str:
    """Run ``action`` and return the map's status once it has changed."""
    old = page.locator(".planner-map-status").inner_text()
    action()
    try:
        page.wait_for_function(
            "(old) => document.querySelector('.planner-map-status').innerText !== old",
            arg=old,
            timeout=timeout_ms,
        )
    except _need_browser().TimeoutError:
        page.screenshot(path=str(ARTIFACTS / "dashboard-status-unchanged.png"), full_page=True)
        raise
    page.wait_for_timeout(1000)  # the marks are drawn after the status
    return page.locator(".planner-map-status").inner_text()


def _screen_of(page):
    """The what-if map's data → screen transform (E, N [m] → px), read from its axes' tick
    labels: two linear fits."""
    ticks = page.evaluate(
        """() => {
        const fig = document.querySelector('.planner-map');
        return [...fig.querySelectorAll('g.tick')].map(t => {
            const r = t.querySelector('text').getBoundingClientRect();
            return {v: parseFloat(t.textContent.replace(/[^0-9.-]/g, '')),
                    x: r.x + r.width / 2, y: r.y + r.height / 2};
        }).filter(t => isFinite(t.v));
    }"""
    )
    xs = [t for t in ticks if 1e5 <= t["v"] < 1e6]  # eastings (6 digits), northings (7)
    ys = [t for t in ticks if t["v"] >= 1e6]
    ax = np.polyfit([t["v"] for t in xs], [t["x"] for t in xs], 1)
    ay = np.polyfit([t["v"] for t in ys], [t["y"] for t in ys], 1)
    return lambda e, n: (float(np.polyval(ax, e)), float(np.polyval(ay, n)))


def _from_map(page, xy: tuple[float, float]) -> tuple[float, float]:
    """A point on screen [px] from the map's upper left corner."""
    box = page.locator(".planner-map").bounding_box()
    return xy[0] - box["x"], xy[1] - box["y"]


def _stations_in(status: str) -> int:
    return int(status.split(" stations")[0].split()[-1])


def test_adding_deleting_and_locking_by_hand(page):
    """Add a station where clicked, delete one, rule a target out, lock a station and
    re-optimise around it: each judged again, the locked station kept where it stood."""
    boxes = _edit_tab_stations(page)
    _mode(page, "Add station")
    # a click inside a building is refused, and the map says why where it was clicked
    to_screen = _screen_of(page)
    inside = to_screen(691040.0, 5335028.0)  # in the default site's main building
    on_map = _from_map(page, inside)
    text, timeout = "", _need_browser().TimeoutError
    for _ in range(4):  # (the mode reaches the map through the kernel: a first click may
        try:  # come before it)
            text = _status_after(page, lambda: page.mouse.click(*inside), timeout_ms=5000)
            break
        except timeout:
            continue
    assert "Not added" in text and "inside building main" in text, text
    notice = page.evaluate(
        """() => [...document.querySelectorAll('.planner-map text')]
            .map(t => t.textContent).filter(t => t.startsWith('not added'))"""
    )
    assert notice == ["not added: inside building main"], notice
    # add: a click on free ground next to a station (stations stand on free ground)
    marks = _marks(page, 0, 1e9)
    spots = [
        (b["x"] + dx, b["y"] + dy) for b in boxes[:4] for dx in (-24, 24, 0) for dy in (-24, 24, 0)
    ]
    free = [s for s in spots if all(abs(q["x"] - s[0]) + abs(q["y"] - s[1]) > 14 for q in marks)]
    for x, y in free:  # a click too near a station or inside a building is refused
        try:
            text = _status_after(page, lambda x=x, y=y: page.mouse.click(x, y), timeout_ms=5000)
        except timeout:  # on a mark: the next spot
            continue
        if "judged again" in text:
            break
        assert text.startswith("Not added: "), text  # refused, saying why
    assert "judged again" in text, text
    assert _stations_in(text) >= len(boxes) + 1
    assert len(_station_boxes(page)) == _stations_in(text)
    # the map kept its view: the same metre under the same pixel of the map (the page above
    # it may have grown or shrunk with the plan's words)
    assert _from_map(page, _screen_of(page)(691040.0, 5335028.0)) == pytest.approx(on_map, abs=1.0)
    # delete: the station clicked goes
    before = _stations_in(text)
    _mode(page, "Delete")
    b = _station_in_the_clear(page)
    text = _status_after(page, lambda: page.mouse.click(b["x"], b["y"]))
    assert _stations_in(text) == before - 1, text
    # a target clicked in Delete mode is ruled out: no target is drawn there any more (the
    # marks read once the map has redrawn after the deletion: a click on marks being
    # replaced is lost on a loaded machine)
    page.wait_for_timeout(1000)
    targets_before = _marks(page, 5, 10)
    box = page.locator(".planner-map").bounding_box()
    mid = (box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    t = min(targets_before, key=lambda q: abs(q["x"] - mid[0]) + abs(q["y"] - mid[1]))
    text = _status_after(page, lambda: page.mouse.click(t["x"], t["y"]))
    assert "judged again" in text, text
    page.wait_for_timeout(500)
    left = _marks(page, 5, 10)
    assert all(abs(q["x"] - t["x"]) + abs(q["y"] - t["y"]) > 2 for q in left)  # px
    # lock one station, re-optimise the rest around it
    before_rows = _station_rows(page)
    _open_map(page)
    page.wait_for_timeout(500)
    _mode(page, "Lock / unlock")
    b = _station_in_the_clear(page)
    text = _status_after(page, lambda: page.mouse.click(b["x"], b["y"]))
    assert "1 station(s) locked" in text
    page.get_by_role("button", name="Re-optimise around the locked").click()
    page.wait_for_function(
        "() => document.querySelector('.planner-status').innerText.includes('re-optimising: done')",
        timeout=120_000,
    )
    page.mouse.move(1, 1)  # (off the map: its hover tip goes)
    page.get_by_text("Summary", exact=True).click()
    summary = page.locator("details pre").first.inner_text()
    # the locked station kept, and those dragged or added by hand before with it
    hand = re.search(r"\b(\d+) placed by hand", summary)
    assert hand and int(hand.group(1)) >= 1, [s for s in summary.splitlines() if "Station" in s]
    page.screenshot(path=str(ARTIFACTS / "dashboard-edit-by-hand.png"), full_page=True)
    # a station stands where one stood (the locked one; E, N to the millimetre), and every
    # station standing where one stood keeps its id; the new ones take numbers never given
    after = _station_rows(page)
    assert any(
        abs(e - e0) < 0.001 and abs(n - n0) < 0.001
        for e, n in after.values()
        for e0, n0 in before_rows.values()
    )  # m
    top = max(int(s[1:]) for s in before_rows)
    for sid, (e, n) in after.items():
        was = [s for s, (e0, n0) in before_rows.items() if abs(e - e0) + abs(n - n0) < 0.002]
        assert was == [sid] if was else int(sid[1:]) > top, (sid, was)


def _station_rows(page) -> dict[str, tuple[float, float]]:
    """E and N of every station as the Stations & field work table prints them."""
    page.get_by_text("Stations & field work", exact=True).click()  # (drawn as it opens)
    table = page.locator("table:has(th:text-is('station_id')):has(th:text-is('x'))").last
    table.wait_for(timeout=30_000)
    heads = [h.strip() for h in table.locator("thead tr").first.locator("th").all_inner_texts()]
    out = {}
    for row in table.locator("tbody tr").all():
        cells = [c.strip() for c in row.locator("th, td").all_inner_texts()]
        named = dict(zip(heads, cells, strict=False))
        out[named["station_id"]] = (float(named["x"]), float(named["y"]))
    return out


def _station_labels(page) -> list[dict]:
    """The station ids written on the map, with their boxes on screen."""
    return page.evaluate(
        """() => [...document.querySelectorAll('.planner-map text')]
            .filter(t => /^S\\d+/.test(t.textContent))
            .map(t => { const r = t.getBoundingClientRect();
                        return {t: t.textContent, x0: r.left, x1: r.right, y0: r.top,
                                y1: r.bottom}; })"""
    )


def test_the_map_zooms_keeps_labels_apart_picks_a_facade_and_draws_a_passage(page):
    """The one map: station ids never written over each other; the wheel zooms in Pan /
    zoom mode and "Fit to the plan" frames it again; a click beside a wall in "Pick a
    facade" mode picks that wall for a zone and the end of its range dragged along the wall
    sets the zone's range; two clicks across a building in "Draw a passage" mode add a
    gateway, and the plan is out of date."""
    from planner.pipeline.geometry.facades import build_facades
    from planner.siteio import default_site

    _open_map(page)
    labels = _station_labels(page)
    assert labels, "no station id on the map"
    for i, a in enumerate(labels):
        for b in labels[i + 1 :]:
            apart = (
                a["x1"] <= b["x0"] or b["x1"] <= a["x0"] or a["y1"] <= b["y0"] or b["y1"] <= a["y0"]
            )
            assert apart, (a, b)
    to_screen = _screen_of(page)
    span = to_screen(691040.0, 0)[0] - to_screen(691000.0, 0)[0]  # px for 40 m
    _mode(page, "Pan / zoom")
    box = page.locator(".planner-map").bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    page.mouse.wheel(0, -400)
    page.wait_for_timeout(1500)
    zoomed = _screen_of(page)
    assert zoomed(691040.0, 0)[0] - zoomed(691000.0, 0)[0] > 1.2 * span  # px: zoomed in
    page.get_by_role("button", name="Fit to the plan").click()
    page.evaluate("() => document.querySelector('.planner-map').scrollIntoView({block: 'end'})")
    page.wait_for_timeout(1500)
    fitted = _screen_of(page)
    # framed on the plan again (the stations may have moved since: within a few per cent)
    assert fitted(691040.0, 0)[0] - fitted(691000.0, 0)[0] == pytest.approx(span, rel=0.05)  # px
    # a facade picked beside its wall: the one nearest the click
    fac = build_facades(default_site(), 2.0, 2.0)
    k = 0
    a, b = fac.start[k], fac.end[k]
    at = a + 0.5 * (b - a) + 1.5 * fac.normal[k]  # 1.5 m out from the middle of the wall
    _mode(page, "Pick a facade")
    to_screen = _screen_of(page)
    text = _status_after(page, lambda: page.mouse.click(*to_screen(*at)))
    assert str(fac.facade_id[k]) in text and "picked for a zone" in text, text
    select = page.locator(".widget-inline-hbox:has(label:text-is('facade')) select")
    assert select.input_value() == str(fac.facade_id[k])
    # its range's start dragged 4 m along the wall (and off it): the zone's range follows
    page.evaluate("() => document.querySelector('.planner-map').scrollIntoView({block: 'end'})")
    page.wait_for_timeout(500)
    to_screen = _screen_of(page)
    length = float(np.hypot(*(b - a)))
    start = to_screen(*a)
    end = to_screen(*(a + 4.0 * (b - a) / length + 1.0 * fac.normal[k]))
    readout = page.locator(".widget-inline-hbox:has(label:text-is('along [m]')) .widget-readout")
    before = readout.inner_text()
    page.mouse.move(*start)
    page.mouse.down()
    page.mouse.move(*end, steps=8)
    page.mouse.up()
    for _ in range(50):  # the slider follows once the kernel has the drag
        if readout.inner_text() != before:
            break
        page.wait_for_timeout(200)
    lo, hi = (float(v) for v in readout.inner_text().replace("–", " ").split())
    assert lo == pytest.approx(4.0, abs=0.3) and hi == pytest.approx(length, abs=0.1)  # m
    # a passage drawn through main's south wing into its courtyard
    _mode(page, "Draw a passage")
    to_screen = _screen_of(page)
    page.mouse.click(*to_screen(691005.0, 5334999.0))
    page.wait_for_timeout(800)
    text = _status_after(page, lambda: page.mouse.click(*to_screen(691005.0, 5335009.0)))
    assert "Passage drawn-1 drawn" in text, text
    page.locator(".planner-stale-banner").wait_for(timeout=30_000)
    page.screenshot(path=str(ARTIFACTS / "dashboard-map-passage.png"))
    page.get_by_role("button", name="Remove the passages drawn").click()
    _mode(page, "Move (drag)")


def test_an_unmet_requirement_explains_itself(page):
    _set_number(page, "largest m_z [mm]", "2")
    _plan_and_wait(page)
    hints = page.locator(".planner-hints").first  # the summary is shown on two tabs
    hints.wait_for(timeout=30_000)
    text = hints.inner_text()
    assert "the smallest relaxation with these stations: " in text
    assert "m_z ≤" in text and "(asked 2)" in text
    assert int(page.locator(".station-count").inner_text().split()[0]) > 0  # best effort
    page.get_by_text("Unmet", exact=True).click()
    table = page.locator(".widget-output table").filter(has_text="quantity").first
    table.wait_for(timeout=30_000)
    assert "m_z" in table.inner_text()
    page.screenshot(path=str(ARTIFACTS / "dashboard-unmet.png"), full_page=True)


def test_cancel_stops_the_plan(page):
    first = page.locator(".station-count").inner_text()
    _set_number(page, "largest m_x [mm]", "3")
    page.get_by_role("button", name="Plan", exact=True).click()
    page.locator("button:has-text('Cancel')").click()
    status = page.locator(".planner-status")
    page.wait_for_function(
        "() => document.querySelector('.planner-status').innerText.includes('cancelled')",
        timeout=60_000,
    )
    assert "previous one" in status.inner_text()
    assert page.locator(".station-count").inner_text() == first
    assert page.get_by_role("button", name="Plan", exact=True).is_enabled()


def test_stricter_plan_then_bad_upload(page, tmp_path):
    """Next to last (it leaves the page with an error): the requirement made stricter than the
    default plan's needs more stations; a bad footprint is refused readably; the page
    fetched nothing from outside the machine all along."""
    count = page.locator(".station-count")
    first = FIRST[0]
    assert first.endswith("stations")
    # a stricter requirement needs more stations (4 mm: 19 stations, 2 samples unmet in
    # 4 s; 3 mm would take 40 s to plan 184 stations)
    _set_number(page, "largest m_x [mm]", "4")
    _set_number(page, "largest m_y [mm]", "4")
    _set_number(page, "largest m_z [mm]", "5")
    _plan_and_wait(page)
    second = count.inner_text()
    assert int(second.split()[0]) > int(first.split()[0])
    assert "samples unmet" in page.locator("h3:has(.station-count)").inner_text()
    count.scroll_into_view_if_needed()  # the page is scrolled down to the Plan button
    page.screenshot(path=str(ARTIFACTS / "dashboard-plan.png"), full_page=True)
    # a bad footprint: a self-intersecting polygon
    bad = tmp_path / "bowtie.geojson"
    bad.write_text(
        '{"type": "Feature", "properties": {"height": 9}, "geometry": {"type": '
        '"Polygon", "coordinates": [[[500000, 5400000], [500010, 5400010], '
        "[500010, 5400000], [500000, 5400010], [500000, 5400000]]]}}"
    )
    with page.expect_file_chooser() as chooser:
        page.locator(".widget-upload").first.click()  # the site file (the As scanned tab has more)
    chooser.value.set_files(str(bad))
    page.get_by_role("button", name="Plan", exact=True).click()
    error = page.locator(".planner-toolbar .planner-error")
    error.wait_for(timeout=60_000)
    text = error.inner_text()
    assert "not a valid polygon" in text and "Self-intersection" in text
    # the map draws the file as far as it can, the building that stops the plan outlined
    drawn = page.locator(".planner-map-status .planner-error").inner_text()
    assert "outlined in red" in drawn and "Self-intersection" in drawn
    assert "Traceback" not in page.content()
    # the error replaces the old plan: no result, no downloads of the old plan
    assert page.locator(".station-count").count() == 0
    assert page.locator("a.planner-download").count() == 0
    assert "bowtie.geojson" in page.locator(".planner-file").inner_text()
    page.screenshot(path=str(ARTIFACTS / "dashboard-bad-upload.png"), full_page=True)
    assert EXTERNAL == [], f"the page fetched from outside the machine: {EXTERNAL}"


def test_a_city_model_uploaded_shows_its_elevations_and_3d_view(page, tmp_path):
    """Last of the station planner's (after an error on screen): a CityJSON model uploaded
    and planned, the error replaced by its plan; the Elevations tab draws the first
    building's walls at their outlines, the 3-D view a WebGL canvas (Chromium draws it in
    software)."""
    from planner.synthetic3d import lod2_town, write_model

    model = write_model(lod2_town(2, seed=1, trees=1), tmp_path / "town.city.json")
    with page.expect_file_chooser() as chooser:
        page.locator(".widget-upload").first.click()
    chooser.value.set_files(str(model))
    page.get_by_role("button", name="Plan", exact=True).click()
    page.locator(".station-count").wait_for(timeout=120_000)  # the error replaced by a plan
    assert page.locator(".planner-toolbar .planner-error").count() == 0
    summary = page.locator("details:has(summary:text-is('Summary')) pre").first.text_content()
    assert "Heights: DHHN2016 height" in summary
    tabs = page.locator(".widget-tab").first
    page.locator(".lm-TabBar-tab:has-text('Elevations')").click()
    figure = tabs.locator("img:visible").first
    figure.wait_for(timeout=60_000)
    assert figure.bounding_box()["width"] > 500
    chosen = tabs.locator(".widget-dropdown:has(label:text-is('building')) select")
    assert chosen.input_value() == "B01"
    tabs.screenshot(path=str(ARTIFACTS / "dashboard-elevations.png"))
    page.locator(".lm-TabBar-tab:has-text('3-D view')").click()
    canvas = tabs.locator("canvas:visible").first
    canvas.wait_for(timeout=60_000)
    assert canvas.bounding_box()["height"] > 300
    page.wait_for_timeout(1500)  # the scene drawn in software
    tabs.screenshot(path=str(ARTIFACTS / "dashboard-3d.png"))
    assert EXTERNAL == [], f"the page fetched from outside the machine: {EXTERNAL}"


@pytest.fixture(scope="module")
def calibration(tmp_path_factory):
    profiles = tmp_path_factory.mktemp("profiles")
    for url in _serve("calibration.ipynb", TLS_PLANNER_PROFILES=str(profiles)):
        yield url, profiles


def test_calibration_dashboard_uploads_plots_once_and_installs(browser, calibration, tmp_path):
    """`planner serve --notebook calibration.ipynb`: the example's residual plots, each shown
    once; an uploaded baseline file replaces the example's result; the profile downloads as
    TOML and installs where the planner finds it by name; nothing cut off at 1280 px."""
    url, profiles = calibration
    from planner.app.calibration_plots import example_path

    rows = example_path("baseline.csv").read_text().splitlines()
    mine = tmp_path / "my_baseline.csv"
    mine.write_text("\n".join(rows[:-2]) + "\n")  # two distances fewer than the example
    page = browser.new_page(viewport={"width": 1280, "height": 2400}, accept_downloads=True)
    page.goto(url, timeout=120_000)
    page.locator("a[download='my-scanner.toml']").wait_for(timeout=120_000)
    for tab in ("Lab test", "Distances", "Axis errors"):
        page.get_by_text(tab, exact=True).click()
        page.wait_for_timeout(300)
        shown = page.locator(".widget-tab-contents img:visible, .lm-TabPanel img:visible")
        assert shown.count() == 1, f"{tab}: {shown.count()} plots shown"
        if tab == "Lab test":
            page.screenshot(path=str(ARTIFACTS / "calibration-lab.png"), full_page=True)
    assert page.locator(".calibration-file").nth(2).inner_text() == "example: baseline.csv"
    with page.expect_file_chooser() as chooser:
        page.locator(".widget-upload").nth(2).click()
    chooser.value.set_files(str(mine))
    page.get_by_text("Distances", exact=True).click()
    page.wait_for_function(
        "(n) => document.body.innerText.includes(`Baseline comparison of ${n} distances`)",
        arg=len(rows) - 3,
        timeout=30_000,
    )
    assert "my_baseline.csv" in page.locator(".calibration-file").nth(2).inner_text()
    # the example's profile was withdrawn before the new result showed; wait for the new
    page.locator("a[download='my-scanner.toml']").wait_for(timeout=30_000)
    with page.expect_download() as download:
        page.locator("a[download='my-scanner.toml']").click()
    toml = Path(download.value.path()).read_text()
    assert 'name = "my-scanner"' in toml and "[[scanner]]" in toml
    assert f"n = {len(rows) - 3}.0 }}" in toml  # the uploaded file's, not the example's
    page.get_by_role("button", name="Install").click()
    page.locator(".calibration-installed").wait_for(timeout=30_000)
    assert (profiles / "my-scanner.toml").read_text() == toml
    cut = _cut_off(page)
    page.screenshot(path=str(ARTIFACTS / "calibration-1280px.png"), full_page=True)
    page.close()
    assert cut == [], f"cut off at 1280 px: {cut}"
