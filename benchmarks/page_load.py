"""Page request → first plan on screen, with and without the pre-started kernel (run by
hand; never part of the test suite).

    .venv/bin/python benchmarks/page_load.py [--loads 3] [--gap-s 20]

Serves the station planner as ``planner serve`` does (:func:`planner.app.serve.voila_command`)
once with Voilà's preheated kernel pool (what ``planner serve`` runs) and once without it
(every page runs the notebook when asked), then opens the page ``--loads`` times in headless
Chromium: from ``page.goto`` to the station count of the first plan on screen. Between
loads it waits ``--gap-s`` (the pool is refilled behind each page; a user opening pages
faster than that waits for the refill). Writes its section of benchmarks/RESULTS.md.
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
from planner.app.notebooks import notebook_path
from planner.app.serve import port_is_free, server_state, voila_command

FLAGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking", "--no-first-run"]


def _port() -> int:
    return next(p for p in range(18800, 18900) if port_is_free(p))


def _warm(port: int, timeout_s: float = 180.0) -> float:
    t0 = time.perf_counter()
    while time.perf_counter() - t0 < timeout_s:
        if server_state(port) == "warm":
            return time.perf_counter() - t0
        time.sleep(0.2)
    raise SystemExit("the dashboard server did not start")


def loads(preheat: bool, n: int, gap_s: float) -> tuple[float, list[float]]:
    from playwright.sync_api import sync_playwright

    port = _port()
    cmd, env = voila_command(notebook_path("station_planner.ipynb"), port, preheat=preheat)
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    url = f"http://127.0.0.1:{port}/"
    try:
        start_s = _warm(port)
        out = []
        with sync_playwright() as pw:
            browser = pw.chromium.launch(executable_path="/usr/bin/chromium", args=FLAGS)
            for i in range(n):
                page = browser.new_page(viewport={"width": 1280, "height": 900})
                t0 = time.perf_counter()
                page.goto(url, timeout=180_000)
                page.locator(".station-count").wait_for(timeout=180_000)
                out.append(time.perf_counter() - t0)
                print(f"preheat={preheat} load {i + 1}: {out[-1]:.1f} s", flush=True)
                page.close()
                time.sleep(gap_s)
            browser.close()
    finally:
        proc.terminate()
        proc.wait(60)
    return start_s, out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--loads", type=int, default=3)
    ap.add_argument("--gap-s", type=float, default=20.0)
    args = ap.parse_args()
    rows = []
    for preheat in (False, True):
        start_s, times = loads(preheat, args.loads, args.gap_s)
        rows.append(
            f"| {'preheated kernel (planner serve)' if preheat else 'kernel started per page'} "
            f"| {start_s:.1f} s | {statistics.median(times):.1f} s | {min(times):.1f} s "
            f"| {max(times):.1f} s |"
        )
    write_section(
        "page-load",
        [
            "## Dashboard: page request to first plan (benchmarks/page_load.py)",
            "",
            f"`benchmarks/page_load.py --loads {args.loads} --gap-s {args.gap_s:g}`, "
            f"{machine()}; headless Chromium at 1280 × 900, from the request to the station "
            "count of the default plan on screen.",
            "",
            "| server | server start to ready | median | min | max |",
            "|---|---|---|---|---|",
            *rows,
        ],
    )


if __name__ == "__main__":
    main()
