"""figures/ is regenerated from the code."""

from __future__ import annotations

from planner.app.cli import main
from planner.app.figures import make_figures


def test_make_figures_writes_pngs(tmp_path):
    paths = make_figures(tmp_path)
    assert {p.name for p in paths} == {
        "table1_planimetric_rms.png",
        "table2_height_rms.png",
        "sossa_target_sizes.png",
        "default_site_plan.png",
        "default_site_m_z.png",
        "models_paper_vs_3d.png",
    }
    for p in paths:
        data = p.read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10_000


def test_cli_figures(tmp_path, capsys):
    assert main(["figures", "--out", str(tmp_path / "figs")]) == 0
    assert "table2_height_rms.png" in capsys.readouterr().out
