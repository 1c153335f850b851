"""``planner report``: one self-contained HTML file with the tables and embedded figures."""

from __future__ import annotations

import re

import pytest
from test_cli import PAPER_5MM, run


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
    assert code == 2 and "max_z_mm must be > 0" in err
    assert not (tmp_path / "r.html").exists()
    code, _, err = run(
        "report",
        *PAPER_5MM,
        "--out",
        str(tmp_path / "r.pdf"),
    )
    assert code == 2 and "must name an .html file" in err


@pytest.mark.booklet
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
