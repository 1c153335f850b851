"""Shared fixtures: the paper's scanner and a few named test scanners."""

from __future__ import annotations

import os
import sys

import pytest

from planner import Scanner
from planner.app.voila_server import skip_iri_grammar

skip_iri_grammar()  # nbformat and nbclient here import jsonschema as the server does


@pytest.fixture(autouse=True, scope="session")
def _own_profile_folder(tmp_path_factory):
    """No test reads or writes the real user profile folder (~/.tls-planner/scanners)."""
    folder = tmp_path_factory.mktemp("profiles")
    mp = pytest.MonkeyPatch()
    mp.setenv("TLS_PLANNER_PROFILES", str(folder))
    yield folder
    mp.undo()


#: A one-page PDF standing in for the field booklet.
_STAND_IN_PDF = (
    b"%PDF-1.4\n1 0 obj<</Type/Catalog/Pages 2 0 R>>endobj\n"
    b"2 0 obj<</Type/Pages/Kids[3 0 R]/Count 1>>endobj\n"
    b"3 0 obj<</Type/Page/Parent 2 0 R/MediaBox[0 0 595 842]>>endobj\n"
    b"trailer<</Root 1 0 R>>\n%%EOF\n"
)


@pytest.fixture(autouse=True)
def _quick_booklet(request, monkeypatch):
    """The field booklet costs about a third of a second a page (matplotlib): tests in this
    process that draw one on the way (``planner plan --booklet``, the dashboard's button)
    but are not about it get a one-page stand-in. Tests about the booklet (or timing the
    whole command) are marked ``booklet``."""
    if request.node.get_closest_marker("booklet"):
        return
    import planner.app.booklet as booklet

    def stand_in(_p, only=None) -> bytes:
        return _STAND_IN_PDF

    monkeypatch.setattr(booklet, "booklet_pdf", stand_in)
    dashboard = sys.modules.get("planner.app.dashboard")  # (it holds its own name for it)
    if dashboard is not None:
        monkeypatch.setattr(dashboard, "booklet_pdf", stand_in)


@pytest.fixture(scope="session")
def default_plan():
    """The plan of the defaults (site, scanner, requirements, settings), made once for the
    session (each test worker): most modules read it. A test that edits a plan edits a
    ``copy.deepcopy`` of it."""
    from planner import plan

    return plan()


@pytest.fixture(scope="session")
def paper_scanner() -> Scanner:
    """Voroshilov & Karachentsev's worked example: m_S = 4 mm, m_β = m_ν = 12.4″, station
    errors zero."""
    return Scanner.from_name("leica-4mm-60urad")


@pytest.fixture(scope="session")
def ppm_scanner() -> Scanner:
    """Ranging a + b·D (2 mm + 100 ppm, Liu & Zhang's accuracy ±(2 + L/10000) mm), distinct H
    and V angles."""
    return Scanner(
        name="ppm-test",
        range_rms_mm=2.0,
        range_ppm=100.0,
        angle_rms_arcsec=12.4,
        vertical_angle_rms_arcsec=20.0,
        step_mm_at_10m=2.0,
        min_range_m=0.5,
        max_range_m=120.0,
    )


try:  # property-based tests: the same examples on every CI run, fresh ones locally
    from hypothesis import settings as _hypothesis_settings

    _hypothesis_settings.register_profile("ci", derandomize=True, database=None)
    _hypothesis_settings.register_profile("dev", database=None)
    _hypothesis_settings.load_profile("ci" if os.environ.get("CI") else "dev")
except ImportError:  # pragma: no cover - hypothesis is a dev dependency
    pass


class _Sentinel:
    """A listener on the loopback that nothing should ever call: the hostile files of the
    tests name its address (a URL, a WFS server, a scheduler), and a connection means the
    planner fetched something. It records every connection it accepts."""

    def __init__(self) -> None:
        import socket
        import threading

        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(16)
        self.port = self.sock.getsockname()[1]
        self.calls: list[bytes] = []
        threading.Thread(target=self._serve, name="sentinel", daemon=True).start()

    def _serve(self) -> None:
        while True:
            try:
                conn, _ = self.sock.accept()
            except OSError:
                return
            with conn:
                conn.settimeout(1.0)
                try:
                    self.calls.append(conn.recv(200) or b"(connected)")
                except OSError:
                    self.calls.append(b"(connected)")

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.port}"


@pytest.fixture(autouse=True, scope="session")
def sentinel():
    """The loopback listener no request may reach during the suite (:class:`_Sentinel`):
    the session fails if one did."""
    s = _Sentinel()
    yield s
    s.sock.close()
    assert not s.calls, f"the planner made {len(s.calls)} request(s) on the loopback: {s.calls}"
