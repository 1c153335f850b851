"""``planner report``: one self-contained HTML file with the tables and embedded figures."""

from __future__ import annotations

import html.parser
import re
from pathlib import Path

import pandas as pd
import pytest
from sites import PAPER_5MM
from sites import run_cli as run


def test_report_html_is_self_contained(tmp_path):
    out = tmp_path / "report.html"
    code, stdout, err = run(
        "report",
        *PAPER_5MM,
        "--out",
        str(out),
        "-q",
    )
    assert code == 0, err
    html = out.read_text()
    assert "self-contained" in stdout
    # the station and target tables
    for sid in ("S01", "S05"):
        assert f">{sid}<" in html
    assert ">T01<" in html and "sphere-200" in html
    assert "Registration targets" in html and "Unmet areas" in html
    # embedded figures: the plan map and three coverage plots at least
    assert len(re.findall(r'src="data:image/png;base64,', html)) >= 4
    # no input cells, no code
    assert 'class="jp-CodeMirrorEditor' not in html and "ReportContent.load" not in html
    assert "plan_path" not in html  # not even the parameters
    # nothing fetched from the network when it opens
    assert not re.search(r'<(script|link|img)[^>]+(src|href)="https?://', html)


def test_report_bad_input_exits_2(tmp_path):
    code, _, err = run(
        "report",
        "--scanner",
        "leica-4mm-60urad",
        "--max-xy-mm",
        "5",
        "--max-z-mm",
        "-1",
        "--out",
        str(tmp_path / "r.html"),
    )
    assert code == 2 and "max_z_mm must be >= 0.01" in err
    assert not (tmp_path / "r.html").exists()
    code, _, err = run(
        "report",
        *PAPER_5MM,
        "--out",
        str(tmp_path / "r.pdf"),
    )
    assert code == 2 and "must name an .html file" in err


def test_dashboard_report_and_booklet_join_plan_zip():
    """The dashboard's Make report / Make booklet buttons offer the file and add it to
    plan.zip with the plan's files; with no plan they say so."""
    import base64
    import io
    import re
    import zipfile

    from planner.app.dashboard import StationPlanner

    ui = StationPlanner()
    ui.make_booklet()
    assert "make a plan first" in ui.booklet_status.value
    ui.run()
    ui.make_report()
    ui.make_booklet()
    assert 'download="report.html"' in ui.report_status.value
    assert 'download="booklet.pdf"' in ui.booklet_status.value
    data = re.search(
        r'download="plan.zip" href="data:application/zip;base64,([^"]+)"', ui.downloads.value
    ).group(1)
    names = set(zipfile.ZipFile(io.BytesIO(base64.b64decode(data))).namelist())
    assert {"report.html", "booklet.pdf", "stations.csv", "plan.dxf"} <= names


def _text(html_page: str) -> str:
    """The report's words: tags and embedded images out, entities decoded."""
    import html as html_

    no_img = re.sub(r"data:image/png;base64,[^\"']+", "", html_page)
    return html_.unescape(re.sub(r"<[^>]+>", " ", no_img))


@pytest.fixture(scope="module")
def strict_plan():
    """The default site at 3 / 3 mm: some samples unmet (one plan for the module)."""
    from planner import Requirements, plan

    return plan(requirements=Requirements(max_xy_mm=3, max_z_mm=3))


def test_the_reports_numbers_are_the_files_numbers(strict_plan):
    """The report says what the plan's files hold: stations, targets, samples met and not,
    the field time, the visiting order, the solver's bound and gap, every station's
    purpose kept through an edit by hand; no NaN, no None; the site's notes linked to
    their file."""
    import io

    import pandas as pd

    from planner.app.report import render_html
    from planner.pipeline.documents.export import render
    from planner.pipeline.engine.whatif import evaluate_stations

    p = strict_plan
    xy = p.stations[["x", "y"]].to_numpy().copy()
    xy[0] += [0.5, 0.0]  # one station moved by hand: it alone becomes "hand"
    q = evaluate_stations(p, xy, list(p.stations["station_id"]))
    files = render(q)
    text = _text(render_html(q))
    stations = pd.read_csv(io.StringIO(files["stations.csv"]))
    targets = pd.read_csv(io.StringIO(files["targets.csv"]))
    cov = pd.read_csv(io.StringIO(files["coverage.csv"]), keep_default_na=False)
    route = pd.read_csv(io.StringIO(files["route.csv"]), keep_default_na=False)
    met = int(cov["meets"].astype(str).eq("True").sum())
    assert f"{len(stations)} stations and {len(targets)} registration targets" in text
    assert f"{len(cov) - met} samples are not met" in text
    assert re.search(rf"Samples meeting every requirement[^:]*: {met} of {len(cov)}\b", text)
    minutes = round(route["station_min"].sum())
    shown = f"{minutes // 60} h {minutes % 60:02d} min" if minutes >= 60 else f"{minutes} min"
    assert f"Field time: {shown} in " in text
    assert "Visiting order: " + " → ".join(route["station_id"]) + "." in text
    assert (stations["purpose"] == "hand").sum() == 1
    assert sorted(set(stations["purpose"])) != ["hand"]  # the others keep theirs
    for sid, purpose in zip(stations["station_id"], stations["purpose"], strict=True):
        # x, y, the ground's height and the instrument's
        assert re.search(rf"\b{sid}\s+[\d.]+\s+[\d.]+\s+[\d.]+\s+[\d.]+\s+{purpose}\b", text)
    for found in re.finditer(r"lower bound ([\d.]+), gap ([\d.]+) %", text):
        objective = int(re.search(r"objective (\d+)", text[: found.start()][-80:]).group(1))
        bound, gap = float(found.group(1)), float(found.group(2))
        assert bound <= objective
        assert gap == pytest.approx(100 * (objective - bound) / objective, abs=0.06)  # %
    assert not re.search(r"\bNaN\b|\bnan\b|\bNone\b", text)


def test_every_table_of_the_report_fits_the_page(tmp_path, strict_plan):
    """Opened in Chromium at 1280 px, no table of the report is wider than the page."""
    from test_dashboard_browser import CHROMIUM, FLAGS, _need_browser

    from planner.app.report import make_report

    sync = _need_browser()
    out = make_report(strict_plan, tmp_path / "r.html")
    with sync.sync_playwright() as pw:
        b = pw.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        page = b.new_page(viewport={"width": 1280, "height": 900})
        page.goto(out.as_uri())
        widths = page.evaluate(
            """() => [...document.querySelectorAll('table')].map(t => [
                t.closest('section').querySelector('h1,h2').textContent,
                t.getBoundingClientRect().right,
                t.closest('section').getBoundingClientRect().right])"""
        )
        b.close()
    assert len(widths) >= 6
    for heading, right, page_right in widths:
        assert right <= page_right + 0.5, f"the table under {heading!r} runs off the page"


def test_the_report_makes_its_plan_as_plan_does(tmp_path, monkeypatch):
    """``planner report`` takes the district options and makes its plan with the one
    function ``planner plan`` uses (:func:`planner.app.commands.make_plan`: district mode where
    ``plan`` takes it, the documents' share of the budget) — it planned in one process
    before, and showed another plan than ``plan``'s. (District mode itself:
    test_district.py.)"""
    import planner.app.commands as commands
    from planner.errors import InputError

    seen = []

    def make_plan(args, progress):
        seen.append((args.district, args.block_m, args.workers))
        raise InputError("stop here: the plan is make_plan's")

    monkeypatch.setattr(commands, "make_plan", make_plan)
    for command, out in (("report", "r.html"), ("plan", "p")):
        code, _, err = run(command, "--district", "on", "--block-m", "300", "--workers", "1",
                           "--out", str(tmp_path / out), "-q")  # fmt: skip
        assert code == 2 and "stop here" in err, err
    assert seen == [("on", 300.0, 1)] * 2  # the report's, then the plan's


# -- the report shows exactly the plan ``plan`` makes -------------------------------------
class _Cells(html.parser.HTMLParser):
    """The text of every table cell, row by row."""

    def __init__(self) -> None:
        super().__init__()
        self.rows: list[list[str]] = []
        self._cell: list[str] | None = None

    def handle_starttag(self, tag, attrs):
        if tag == "tr":
            self.rows.append([])
        elif tag in ("td", "th"):
            self._cell = []

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None and self.rows:
            self.rows[-1].append("".join(self._cell).strip())
            self._cell = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


def test_report_describes_the_plan_that_plan_makes(tmp_path, monkeypatch):
    """Non-default settings and a scanner profile given by a relative path: the report's
    station table equals stations.csv of ``plan`` with the same arguments."""
    monkeypatch.chdir(tmp_path)
    Path("profiles").mkdir()
    Path("profiles/mine.toml").write_text(
        '[[scanner]]\nname = "mine"\nrange_rms_mm = 2.0\nangle_rms_arcsec = 8.0\n'
        "vertical_angle_rms_arcsec = 10.0\nmax_range_m = 80.0\n"
    )
    flags = [
        "--scanner",
        "profiles/mine.toml",
        "--max-xy-mm",
        "4",
        "--max-z-mm",
        "4.5",
        "--grid-m",
        "3",
        "--clearance-m",
        "1.5",
        "--instrument-height-m",
        "1.8",
        "--sample-spacing-m",
        "3",
        "--sample-height-step-m",
        "3",
        "--station-rms-mm",
        "0.5",
        "--step-mm-at-10m",
        "3",
        "--max-range-m",
        "70",
        "--method",
        "greedy",
        "-q",
    ]
    code, _, err = run("plan", *flags, "--out", "plan")
    assert code in (0, 1), err
    code, _, err = run("report", *flags, "--out", "report.html")
    assert code == 0, err
    stations = pd.read_csv("plan/stations.csv")
    parser = _Cells()
    parser.feed(Path("report.html").read_text())
    reported = {  # the station table's rows: id, x, y, ground, height, purpose, samples met
        r[0]: r
        for r in parser.rows
        if len(r) == 7 and r[0].startswith("S") and r[0][1:].isdigit() and r[5] in ("cover", "link")
    }
    assert sorted(reported) == sorted(stations["station_id"])
    for s in stations.itertuples():
        row = reported[s.station_id]
        assert float(row[1]) == pytest.approx(s.x, abs=1e-3)  # m
        assert float(row[2]) == pytest.approx(s.y, abs=1e-3)  # m
        assert float(row[3]) == pytest.approx(0.0)  # flat ground
        assert float(row[4]) == pytest.approx(1.8)  # the instrument height given
    summary = next(
        line for line in Path("plan/summary.txt").read_text().splitlines() if "Stations:" in line
    )
    assert "greedy" in summary and summary in Path("report.html").read_text()
