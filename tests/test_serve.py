"""``planner serve``: ready when it says so, loopback names only, stops whole on any ordinary
stop signal, refuses a taken port, and frees the kernels of closed pages."""

from __future__ import annotations

import os
import re
import secrets
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest

from planner.app.serve import _descendants, _marked, _stop
from planner.app.voila_server import INSTANCE_ENV, is_loopback_host


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _listening(port: int) -> bool:
    with socket.socket() as s:
        return s.connect_ex(("127.0.0.1", port)) == 0


def _start(port: int, *extra: str, tmp: Path | None = None) -> tuple[subprocess.Popen, str]:
    proc = subprocess.Popen(
        [sys.executable, "-m", "planner", "serve", "--port", str(port), *extra],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "TMPDIR": str(tmp)} if tmp else None,
    )
    line = proc.stdout.readline()  # blocks until the server says something
    if "Starting" in line:  # its kernel runs the dashboard ahead of the first page
        line = proc.stdout.readline()  # … until it says it is ready
    return proc, line


def _kernels(pid: int) -> list[int]:
    out = []
    for child in _descendants(pid):
        try:
            cmd = Path(f"/proc/{child}/cmdline").read_bytes()
        except OSError:
            continue
        if b"ipykernel" in cmd:
            out.append(child)
    return out


def _get(port: int, path: str = "/", host: str | None = None) -> int:
    req = urllib.request.Request(f"http://127.0.0.1:{port}{path}")
    if host:
        req.add_header("Host", host)
    try:
        with urllib.request.urlopen(req, timeout=120) as r:
            return r.status
    except urllib.error.HTTPError as exc:
        return exc.code


def _running(pid: int) -> bool:
    """Whether process ``pid`` is running: it exists and has not ended (a process that
    ended stays a zombie until its parent, for an orphan the machine's init, collects
    it; this machine's init takes about a second)."""
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state not in ("Z", "X")


def _kill_family(proc: subprocess.Popen) -> None:
    """A test's server gone whatever happened: it and every process it started (a failed
    assertion must not leave the Voilà server and its kernels running)."""
    if proc.poll() is None:
        family = _descendants(proc.pid)
        proc.kill()
        for pid in family:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass


def _stops_whole(proc: subprocess.Popen, port: int, sig: int) -> None:
    """``sig`` stops the server with exit code 0, its port closed and no process of its
    family left running."""
    family = _descendants(proc.pid)
    proc.send_signal(sig)
    assert proc.wait(60) == 0
    time.sleep(0.5)
    assert not _listening(port), "the port still answers after the stop"
    alive = [p for p in family if _running(p)]
    assert alive == [], f"processes left running: {alive}"


@pytest.mark.parametrize(
    ("sig", "notebook"),
    [
        (signal.SIGTERM, []),  # the station planner, served by default
        (signal.SIGINT, ["--notebook", "targets.ipynb"]),  # a lighter dashboard: the same
    ],  # server, a shorter warm-up (SIGHUP: below)
    ids=["SIGTERM", "SIGINT"],
)
def test_serve_is_ready_when_it_says_so_and_stops_whole_on_a_signal(sig, notebook):
    """Ready means warm; a page takes the warm kernel and another is warmed behind it
    (the default dashboard's server, where that matters most); a stop signal stops the
    server and every kernel it started."""
    port = _free_port()
    proc, line = _start(port, *notebook)
    try:
        assert re.search(rf"ready at http://127\.0\.0\.1:{port}/", line), line
        assert _get(port, "/tls-planner/instance") == 200  # answers at once: no race
        # ready means warm: a kernel has run the dashboard before any page asked for it
        assert len(_kernels(proc.pid)) == 1
        if not notebook:  # the page takes that kernel; another is started behind it
            assert _get(port) == 200
            deadline = time.time() + 30
            while len(_kernels(proc.pid)) < 2 and time.time() < deadline:
                time.sleep(0.2)
            assert len(_kernels(proc.pid)) == 2
        _stops_whole(proc, port, sig)
    finally:
        _kill_family(proc)


def test_serve_refuses_strangers_and_a_taken_port_and_frees_idle_kernels(tmp_path):
    """One server for what needs no fresh one: other host names and a taken port refused;
    page loads leave kernels, and with nobody connected they are culled after the idle time
    — all but the one kept warm for the next page; SIGHUP stops it whole, and the upload
    folder goes with it (the server gets a temporary folder of its own: other servers, of
    other tests, may be running)."""
    port = _free_port()
    proc, line = _start(port, "--notebook", "targets.ipynb", "--kernel-idle-s", "10", tmp=tmp_path)
    try:
        assert "ready" in line
        assert _get(port, "/", host="evil.example") == 403  # DNS rebinding
        assert _get(port, "/voila/static/voila.js", host=f"evil.example:{port}") == 403
        assert _get(port, "/tls-planner/instance", host=f"localhost:{port}") == 200
        second = subprocess.run(
            [sys.executable, "-m", "planner", "serve", "--port", str(port)],
            capture_output=True,
            text=True,
            timeout=60,
        )
        assert second.returncode == 2 and f"port {port} on 127.0.0.1 is taken" in second.stderr
        for _ in range(2):
            assert _get(port) == 200
        # the two pages' kernels, counted at once: a page's kernel is culled 10 s after its
        # page, and a page loads in seconds even on a loaded machine
        assert len(_kernels(proc.pid)) >= 2
        # a template's static file is served; an encoded way out of it is not found (never
        # a server error), after pages were served
        assert _get(port, "/voila/templates/lab/static/voila.js") == 200
        for sneaky in ("lab/static/..%2f..%2f..%2fetc%2fpasswd", "..%2f..%2fetc", "lab%2fstatic"):
            assert _get(port, "/voila/templates/" + sneaky) == 404, sneaky
        deadline = time.time() + 60
        while len(_kernels(proc.pid)) > 1 and time.time() < deadline:
            time.sleep(0.5)
        assert len(_kernels(proc.pid)) == 1
        uploads = [p for p in tmp_path.iterdir() if p.name.startswith("tls-planner-serve-")]
        assert uploads  # the server's upload folder exists while it runs …
        _stops_whole(proc, port, signal.SIGHUP)
    finally:
        _kill_family(proc)
    assert not any(p.exists() for p in uploads)  # … and goes with it


def test_loopback_host_names():
    assert is_loopback_host("127.0.0.1:8866") and is_loopback_host("[::1]:8866")
    assert is_loopback_host("localhost") and is_loopback_host("127.1.2.3")
    assert not is_loopback_host("evil.example") and not is_loopback_host("10.0.0.1")
    assert not is_loopback_host("localhost.evil.example")


def test_a_kernel_no_longer_under_the_server_is_stopped_by_its_mark():
    """Every kernel inherits the server's instance id: a process carrying it is stopped
    with the server even when it is no longer under it (a kernel started as the server
    stopped); a process without it is left alone."""
    token = secrets.token_hex(8)
    sleeper = [sys.executable, "-c", "import time; time.sleep(60)"]
    start = f"import subprocess; subprocess.Popen({sleeper!r}, start_new_session=True)"
    server = subprocess.Popen(  # starts its "kernel" and ends at once: an orphan
        [sys.executable, "-c", start], env={**os.environ, INSTANCE_ENV: token}
    )
    stranger = subprocess.Popen(sleeper)
    try:
        assert server.wait(30) == 0
        deadline = time.time() + 30
        while not _marked(token) and time.time() < deadline:
            time.sleep(0.1)
        orphans = _marked(token)
        assert len(orphans) == 1 and _running(orphans[0])
        _stop(server, grace_s=0.0, instance=token)
        time.sleep(0.2)
        assert not _running(orphans[0])  # stopped (a zombie until init collects it)
        assert stranger.poll() is None  # not the server's: left alone
    finally:
        stranger.kill()
        for pid in _marked(token):
            os.kill(pid, signal.SIGKILL)
