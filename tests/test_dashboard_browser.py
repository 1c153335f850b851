"""End to end in a real browser: Voilà serves the station planner on loopback; headless
Debian Chromium (driven by playwright) changes a requirement, presses Plan, sees a new
result; uploads a bad footprint and sees a readable error. Screenshots go to
test-artifacts/. Nothing may be fetched from outside the machine."""

from __future__ import annotations

import os
import shutil
import socket
import subprocess
import time
import urllib.request
from pathlib import Path

import pytest

from planner.app.notebooks import notebook_path
from planner.app.serve import voila_command

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


@pytest.fixture(scope="module")
def dashboard_url():
    _need_browser()
    port = free_port()
    cmd, env = voila_command(notebook_path("station_planner.ipynb"), port)
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    url = f"http://127.0.0.1:{port}/"
    deadline = time.time() + 90
    while time.time() < deadline:
        if proc.poll() is not None:
            pytest.fail(f"voila exited: {proc.stdout.read().decode(errors='replace')[-2000:]}")
        try:
            with urllib.request.urlopen(url, timeout=5):
                break
        except OSError:
            time.sleep(0.5)
    else:
        proc.kill()
        pytest.fail("voila did not answer within 90 s")
    yield url
    proc.terminate()
    try:
        proc.wait(10)
    except subprocess.TimeoutExpired:
        proc.kill()


def _set_number(page, label: str, value: str) -> None:
    box = page.locator(f".widget-inline-hbox:has(label:text-is('{label}')) input")
    box.fill(value)
    box.press("Enter")


def test_plan_then_bad_upload_in_a_real_browser(dashboard_url, tmp_path):
    sync = _need_browser()
    ARTIFACTS.mkdir(exist_ok=True)
    external: list[str] = []
    local = ("http://127.0.0.1", "ws://127.0.0.1", "data:", "blob:", "about:")
    with sync.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        page = browser.new_page(viewport={"width": 1500, "height": 1100})
        page.on("request", lambda r: None if r.url.startswith(local) else external.append(r.url))
        page.goto(dashboard_url, timeout=120_000)
        count = page.locator(".station-count")
        count.wait_for(timeout=120_000)
        first = count.inner_text()
        assert first.endswith("stations")
        # a stricter requirement needs more stations
        _set_number(page, "largest m_x [mm]", "3")
        _set_number(page, "largest m_y [mm]", "3")
        page.get_by_role("button", name="Plan", exact=True).click()
        page.wait_for_function(
            "(old) => { const e = document.querySelector('.station-count');"
            " return e && e.innerText !== old; }",
            arg=first,
            timeout=120_000,
        )
        second = count.inner_text()
        assert int(second.split()[0]) > int(first.split()[0])
        assert "samples unmet" in page.locator("h3:has(.station-count)").inner_text()
        page.screenshot(path=str(ARTIFACTS / "dashboard-plan.png"), full_page=True)
        # a bad footprint: a self-intersecting polygon
        bad = tmp_path / "bowtie.geojson"
        bad.write_text(
            '{"type": "Feature", "properties": {"height": 9}, "geometry": {"type": '
            '"Polygon", "coordinates": [[[500000, 5400000], [500010, 5400010], '
            "[500010, 5400000], [500000, 5400010], [500000, 5400000]]]}}"
        )
        with page.expect_file_chooser() as chooser:
            page.locator(".widget-upload").click()
        chooser.value.set_files(str(bad))
        page.get_by_role("button", name="Plan", exact=True).click()
        error = page.locator(".planner-error")
        error.wait_for(timeout=60_000)
        text = error.inner_text()
        assert "not a valid polygon" in text and "Self-intersection" in text
        assert "Traceback" not in page.content()
        page.screenshot(path=str(ARTIFACTS / "dashboard-bad-upload.png"), full_page=True)
        browser.close()
    assert external == [], f"the page fetched from outside the machine: {external}"


def test_field_work_tab_shows_the_visiting_order(dashboard_url):
    sync = _need_browser()
    ARTIFACTS.mkdir(exist_ok=True)
    with sync.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        page = browser.new_page(viewport={"width": 1500, "height": 1100})
        page.goto(dashboard_url, timeout=120_000)
        count = page.locator(".station-count")
        count.wait_for(timeout=120_000)
        n = int(count.inner_text().split()[0])
        page.get_by_text("Stations & field work", exact=True).click()
        summary = page.locator("p:has-text('Field time:')")
        summary.wait_for(timeout=30_000)
        assert "Visiting order:" in summary.inner_text()
        rows = page.locator(".widget-output table").last.locator("tbody tr")
        assert rows.count() == n
        page.screenshot(path=str(ARTIFACTS / "dashboard-field-work.png"), full_page=True)
        page.get_by_text("Downloads", exact=True).click()
        assert page.locator("a.planner-download[download='route.csv']").count() == 1
        page.get_by_role("button", name="Make field booklet (PDF)").click()
        booklet = page.locator("a.planner-download[download='booklet.pdf']")
        booklet.wait_for(timeout=120_000)
        page.screenshot(path=str(ARTIFACTS / "dashboard-booklet.png"), full_page=True)
        browser.close()
