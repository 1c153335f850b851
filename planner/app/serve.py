"""``planner serve``: a dashboard served by Voilà on 127.0.0.1, supervised.

* The port is checked first: a taken port is an error, not a silent move to another.
* The URL is printed when the page really answers, not when the process starts: the
  dashboard's kernel is started and its notebook run (the default plan made) before anyone
  asks — Voilà's preheated kernel pool, one kernel ahead — so a page opens at once; the
  pool is refilled in the background after each page load.
* Voilà runs in a session of its own (:mod:`planner.app.voila_server`, loopback ``Host``
  names only); any ordinary stop signal (Ctrl+C, SIGTERM, SIGHUP) stops it, its kernels and
  everything they started — nothing keeps listening.
* Kernels of closed pages are shut down after ``kernel_idle_s`` (Jupyter's idle culling of
  kernels with no page connected), and the dashboards' upload folders live under one
  temporary folder that goes with the server.
"""

from __future__ import annotations

import collections
import contextlib
import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request
from collections.abc import Callable
from pathlib import Path

from planner.app.voila_server import INSTANCE_ENV, INSTANCE_PATH, POOL_HEADER
from planner.errors import InputError

__all__ = ["UPLOAD_ROOT_ENV", "port_is_free", "serve", "server_state", "voila_command"]

#: Where the dashboards put uploaded files (a folder the server removes when it stops).
UPLOAD_ROOT_ENV = "TLS_PLANNER_UPLOAD_ROOT"


def port_is_free(port: int) -> bool:
    with socket.socket() as s:
        try:
            s.bind(("127.0.0.1", port))
        except OSError:
            return False
    return True


def voila_command(
    notebook: Path,
    port: int,
    *,
    kernel_idle_s: float = 600.0,
    upload_root: str | None = None,
    preheat: bool = True,
) -> tuple[list[str], dict[str, str]]:
    """The command line and environment of the Voilà server for ``notebook`` on
    127.0.0.1:``port`` (the package's offline template, found through ``JUPYTER_PATH``;
    with ``preheat`` one kernel runs the notebook before a page asks for it)."""
    jupyter_dir = Path(__file__).resolve().parent / "jupyter"
    env = dict(os.environ)
    env["JUPYTER_PATH"] = os.pathsep.join(
        p for p in (str(jupyter_dir), env.get("JUPYTER_PATH")) if p
    )
    if upload_root:
        env[UPLOAD_ROOT_ENV] = upload_root
    cmd = [
        sys.executable,
        "-m",
        "planner.app.voila_server",
        str(notebook),
        f"--port={port}",
        "--Voila.port_retries=0",
        "--Voila.ip=127.0.0.1",
        "--no-browser",
        "--show_tracebacks=False",
        "--template=planner-offline",
        f"--preheat_kernel={bool(preheat)}",
        "--pool_size=1",
        f"--MappingKernelManager.cull_idle_timeout={int(kernel_idle_s)}",
        f"--MappingKernelManager.cull_interval={max(1, int(kernel_idle_s) // 4)}",
        "--MappingKernelManager.cull_connected=False",
    ]
    return cmd, env


def _descendants(pid: int) -> list[int]:
    """Every process started (directly or not) by ``pid``, read from /proc."""
    children: dict[int, list[int]] = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        ppid = int(stat.rsplit(")", 1)[1].split()[1])
        children.setdefault(ppid, []).append(int(entry.name))
    out, todo = [], [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            out.append(child)
            todo.append(child)
    return out


def _marked(instance: str) -> list[int]:
    """The processes whose environment holds the server's instance id (:data:`INSTANCE_ENV`),
    which every kernel inherits: found even where a kernel started as the server stopped
    and its parent is gone."""
    mark = f"{INSTANCE_ENV}={instance}".encode()
    out = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        with contextlib.suppress(OSError):
            if mark in (entry / "environ").read_bytes().split(b"\0"):
                out.append(int(entry.name))
    return out


def _stop(proc: subprocess.Popen, grace_s: float = 10.0, instance: str = "") -> None:
    """Stop the Voilà server and everything under it: Ctrl+C first (Voilà shuts its kernels
    down), then SIGKILL for whatever is left after ``grace_s``: the processes under it when
    the stop began and, given the server's ``instance`` id, any that carry it."""
    family = _descendants(proc.pid)
    if proc.poll() is None:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGINT)
        try:
            proc.wait(grace_s)
        except subprocess.TimeoutExpired:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    if instance:  # (the server has ended: no kernel starts after this)
        family = sorted(set(family) | set(_marked(instance)))
    for pid in family:  # kernels run in sessions of their own
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.kill(pid, signal.SIGKILL)


def server_state(port: int, instance: str = "") -> str:
    """``""`` until the server with this instance id (``planner serve`` gives each its own;
    a server started without one answers ``""``) answers on ``port``, then ``"warming"``
    while its pre-started kernel runs the dashboard and ``"warm"`` when a page opens at
    once; no page is loaded, so no kernel is started by asking."""
    try:
        with urllib.request.urlopen(f"http://127.0.0.1:{port}{INSTANCE_PATH}", timeout=5) as r:
            if r.status != 200 or r.read().decode() != instance:
                return ""
            return r.headers.get(POOL_HEADER, "warm")
    except OSError:
        return ""


def serve(
    notebook: Path,
    port: int,
    *,
    kernel_idle_s: float = 600.0,
    ready_timeout_s: float = 180.0,
    say: Callable[[str], None] = print,
) -> int:
    """Serve ``notebook`` until a stop signal; the exit code (0 on an ordinary stop)."""
    if not port_is_free(port):
        raise InputError(
            f"port {port} on 127.0.0.1 is taken (another planner serve?); stop that one or "
            "choose another port with --port"
        )
    upload_root = tempfile.mkdtemp(prefix="tls-planner-serve-")
    cmd, env = voila_command(notebook, port, kernel_idle_s=kernel_idle_s, upload_root=upload_root)
    instance = secrets.token_hex(8)
    env[INSTANCE_ENV] = instance
    stop_requested: list[int] = []

    def on_signal(signum: int, _frame: object) -> None:
        stop_requested.append(signum)

    previous = {
        sig: signal.signal(sig, on_signal) for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
    }
    proc = subprocess.Popen(
        cmd, env=env, start_new_session=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE
    )
    # Voilà logs to stderr all day: read it as it comes (an unread pipe fills and stalls the
    # server) and keep the last lines for the message if it stops
    log: collections.deque[bytes] = collections.deque(maxlen=20)
    threading.Thread(target=log.extend, args=(proc.stderr,), daemon=True).start()
    try:
        url = f"http://127.0.0.1:{port}/"
        deadline = time.monotonic() + ready_timeout_s
        said_warming = False
        while not stop_requested and (state := server_state(port, instance)) != "warm":
            if state == "warming" and not said_warming:
                say(f"Starting the dashboard at {url}: running it once so that it opens at once")
                said_warming = True
            if proc.poll() is not None:
                time.sleep(0.2)  # the last lines read
                message = [line.decode(errors="replace").strip() for line in log]
                message = [line for line in message if line]
                raise InputError(
                    f"the dashboard server stopped while starting (exit code {proc.returncode}"
                    + (f": {message[-1]}" if message else "")
                    + ")"
                )
            if time.monotonic() > deadline:
                raise InputError(f"the dashboard did not answer within {ready_timeout_s:g} s")
            time.sleep(0.3)
        if not stop_requested:
            say(f"The dashboard is ready at {url} (Ctrl+C stops it)")
        while not stop_requested and proc.poll() is None:
            time.sleep(0.2)
        return 0 if stop_requested or proc.returncode == 0 else int(proc.returncode or 1)
    finally:
        _stop(proc, instance=instance)
        for sig, handler in previous.items():
            signal.signal(sig, handler)
        shutil.rmtree(upload_root, ignore_errors=True)
