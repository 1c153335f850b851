"""On-screen latency of the map's edits by hand on the default site (run by hand; never
part of the test suite).

    .venv/bin/python benchmarks/edit_latency.py [--repeats 3]

Serves the station planner as ``planner serve`` does, opens it in headless Chromium at
1500 × 1100, and on the "Map" tab drags a station, adds one on free ground and
deletes one, ``--repeats`` times each: from the mouse-up (or click) to the map's status
saying the plan was judged again, beside the kernel's own time for the edit (the status
prints it). Writes the ``edit-latency`` section of benchmarks/RESULTS.md.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time
from pathlib import Path

from _results import machine, write_section

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from page_load import FLAGS, _port, _warm

from planner.app.notebooks import notebook_path
from planner.app.serve import voila_command

#: The map's marks wider than this [px] are stations (targets and samples are smaller).
STATION_PX = 10


def _stations(page) -> list[dict]:
    """Screen centres of the station marks in view (below the toolbar), nearest the
    middle of the map first."""
    marks = page.evaluate(
        """(lo) => [...document.querySelectorAll('.planner-map g.object_grp path.dot')]
            .map(d => d.getBoundingClientRect()).filter(r => r.width > lo)
            .map(r => ({x: r.x + r.width / 2, y: r.y + r.height / 2}))""",
        STATION_PX,
    )
    box = page.locator(".planner-map").bounding_box()
    mid = (box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    seen = [m for m in marks if 150 < m["y"] < page.viewport_size["height"] - 40]
    return sorted(seen, key=lambda m: abs(m["x"] - mid[0]) + abs(m["y"] - mid[1]))


def _timed(page, act) -> tuple[float, float]:
    """Seconds from ``act`` to the status changing, and the kernel's seconds it reports."""
    status = page.locator(".planner-map-status")
    old = status.inner_text()
    t0 = time.perf_counter()
    act()
    page.wait_for_function(
        "(old) => document.querySelector('.planner-map-status').innerText !== old",
        arg=old,
        timeout=10_000,
    )
    seen = time.perf_counter() - t0
    if "judged again" not in status.inner_text():  # refused (on a building): not an edit
        raise RuntimeError(status.inner_text())
    return seen, float(page.locator(".planner-edit-s").inner_text())


def _first(page, into: list, attempts: list) -> None:
    """Time the first of ``attempts`` (actions) the page takes as an edit (one refused — a
    drag into a building, a click beside the mark — or not taken: the next)."""
    from playwright.sync_api import TimeoutError as NotTaken

    for act in attempts:
        try:
            into.append(_timed(page, act))
            return
        except (RuntimeError, NotTaken):
            page.wait_for_timeout(300)


def main() -> None:
    from playwright.sync_api import sync_playwright

    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    port = _port()
    cmd, env = voila_command(notebook_path("station_planner.ipynb"), port)
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    results: dict[str, list[tuple[float, float]]] = {"drag": [], "add": [], "delete": []}
    try:
        _warm(port)
        with sync_playwright() as pw:
            browser = pw.chromium.launch(executable_path="/usr/bin/chromium", args=FLAGS)
            page = browser.new_page(viewport={"width": 1500, "height": 1100})
            page.goto(f"http://127.0.0.1:{port}/", timeout=180_000)
            page.locator(".station-count").wait_for(timeout=180_000)
            page.locator(".lm-TabBar-tabLabel:text-is('Map')").click()
            page.evaluate(
                "() => document.querySelector('.planner-map').scrollIntoView({block: 'end'})"
            )
            page.wait_for_timeout(1500)
            for _ in range(args.repeats):

                def drag(b):
                    page.mouse.move(b["x"], b["y"])
                    page.mouse.down()
                    page.mouse.move(b["x"] + 12, b["y"] + 8, steps=5)
                    page.mouse.up()

                page.get_by_role("button", name="Move (drag)", exact=True).click()
                page.wait_for_timeout(800)
                _first(page, results["drag"], [lambda b=b: drag(b) for b in _stations(page)])
                page.get_by_role("button", name="Add station", exact=True).click()
                page.wait_for_timeout(800)
                c = _stations(page)[0]
                spots = [(c["x"] + dx, c["y"] + dy) for dx in (30, -30, 45) for dy in (30, -30, 0)]
                _first(page, results["add"], [lambda q=q: page.mouse.click(*q) for q in spots])
                page.get_by_role("button", name="Delete", exact=True).click()
                page.wait_for_timeout(800)
                _first(
                    page,
                    results["delete"],
                    [lambda s=s: page.mouse.click(s["x"], s["y"]) for s in _stations(page)],
                )
                print({k: v[-1] for k, v in results.items() if v}, flush=True)
            browser.close()
    finally:
        proc.terminate()
        proc.wait(60)
    rows = [
        f"| {kind} | {len(v)} | {statistics.median([s for s, _ in v]):.2f} s | "
        f"{max(s for s, _ in v):.2f} s | {statistics.median([k for _, k in v]):.2f} s |"
        for kind, v in results.items()
        if v
    ]
    write_section(
        "edit-latency",
        [
            "## Dashboard: on-screen latency of edits by hand (benchmarks/edit_latency.py)",
            "",
            f"`benchmarks/edit_latency.py --repeats {args.repeats}`, {machine()}; headless "
            "Chromium at 1500 × 1100, default site: from the mouse-up (drag) or click (add, "
            "delete) to the map's status saying the plan was judged again.",
            "",
            "| edit | runs | median on screen | max on screen | median in the kernel |",
            "|---|---|---|---|---|",
            *rows,
        ],
    )


if __name__ == "__main__":
    main()
