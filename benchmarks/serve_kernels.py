"""Kernels and memory of ``planner serve`` under page loads (run by hand; never in the suite).

    .venv/bin/python benchmarks/serve_kernels.py [--loads 20] [--idle-s 30]

Opens the dashboard ``--loads`` times in headless Chromium (each page in its own tab, waits
for the first plan, closes the tab), then counts the kernel processes and their resident
memory: right after the loads, and after the idle time has passed (kernels of closed pages
are culled). Writes its section of benchmarks/RESULTS.md.
"""

from __future__ import annotations

import argparse
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

from _results import machine, write_section

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from planner.app.serve import _descendants

FLAGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]


def kernels(pid: int) -> tuple[int, float]:
    """Number of kernel processes under ``pid`` and their resident memory [MB]."""
    n, rss = 0, 0.0
    for child in _descendants(pid):
        try:
            if b"ipykernel" not in Path(f"/proc/{child}/cmdline").read_bytes():
                continue
            for line in Path(f"/proc/{child}/status").read_text().splitlines():
                if line.startswith("VmRSS:"):
                    rss += int(line.split()[1]) / 1024
            n += 1
        except OSError:
            continue
    return n, rss


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--loads", type=int, default=20)
    ap.add_argument("--idle-s", type=float, default=30.0)
    args = ap.parse_args()
    from playwright.sync_api import sync_playwright

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "planner",
            "serve",
            "--port",
            str(port),
            "--kernel-idle-s",
            str(args.idle_s),
        ],
        stdout=subprocess.PIPE,
        text=True,
    )
    line = ""
    while "ready" not in line:  # "Starting …" while its kernel runs the dashboard, then ready
        line = proc.stdout.readline()
        print(line.strip())
    url = f"http://127.0.0.1:{port}/"
    try:
        with sync_playwright() as pw:
            browser = pw.chromium.launch(executable_path="/usr/bin/chromium", args=FLAGS)
            peak = (0, 0.0)
            t0 = time.time()
            for i in range(args.loads):
                page = browser.new_page()
                page.goto(url, timeout=180_000)
                page.locator(".station-count").wait_for(timeout=180_000)
                page.close()
                now = kernels(proc.pid)
                peak = max(peak, now)
                print(f"load {i + 1}: {now[0]} kernels, {now[1]:.0f} MB")
            browser.close()
        loads_s = time.time() - t0
        after = kernels(proc.pid)
        time.sleep(args.idle_s * 2 + 5)
        culled = kernels(proc.pid)
    finally:
        proc.send_signal(signal.SIGTERM)
        proc.wait(60)
    print(f"after the loads: {after}; after {args.idle_s * 2 + 5:.0f} s: {culled}")
    write_section(
        "serve-kernels",
        [
            "## Kernels of `planner serve` under page loads",
            "",
            f"`benchmarks/serve_kernels.py --loads {args.loads} --idle-s {args.idle_s:g}`, "
            f"{machine()}. Each load opens the dashboard in a new headless-Chromium tab, waits "
            f"for the first plan and closes the tab ({loads_s:.0f} s for all loads).",
            "",
            "| moment | kernels | their resident memory |",
            "|---|---|---|",
            f"| most at once during the loads | {peak[0]} | {peak[1]:.0f} MB |",
            f"| right after the last tab closed | {after[0]} | {after[1]:.0f} MB |",
            f"| {args.idle_s * 2 + 5:.0f} s later (idle culling at {args.idle_s:g} s) | "
            f"{culled[0]} | {culled[1]:.0f} MB |",
        ],
    )


if __name__ == "__main__":
    main()
