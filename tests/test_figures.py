"""figures/ is regenerated from the code."""

from __future__ import annotations

import pytest

from planner.app.cli import main


def test_cli_figures_writes_the_readme_pngs(tmp_path, capsys):
    """``planner figures`` (:func:`~planner.app.figures.make_figures`) writes every README
    figure as a PNG and says so."""
    out = tmp_path / "figs"
    assert main(["figures", "--out", str(out)]) == 0
    said = capsys.readouterr().out
    names = {
        "table1_planimetric_rms.png",
        "table2_height_rms.png",
        "sossa_target_sizes.png",
        "default_site_plan.png",
        "default_site_m_z.png",
        "models_paper_vs_3d.png",
    }
    assert {p.name for p in out.iterdir()} == names
    for name in names:
        assert name in said
        data = (out / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 10_000


@pytest.mark.parametrize(("gamma", "nu"), [(30.0, 30.0), (45.0, 90.0), (0.0, 0.0)])
def test_accuracy_explorer_plots_are_legible(monkeypatch, gamma, nu):
    """One legend entry per angle, a colour of its own per angle, and no title overlapping
    another or leaving the figure (the issue: '30°' twice, 0° and 90° alike, titles collided)."""
    import matplotlib.pyplot as plt
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from planner.app import explorers, widgets

    figures = []
    real = widgets.output
    monkeypatch.setattr(
        widgets,
        "output",
        lambda obj: (
            (figures.append(obj), real(obj))[1] if isinstance(obj, plt.Figure) else real(obj)
        ),
    )
    ui = explorers.AccuracyExplorer()
    ui.gamma.value, ui.nu.value = gamma, nu  # each value changed draws the plots again
    if not figures:  # (the values it starts with: nothing changed, nothing drawn)
        ui.update()
    fig = figures[-2]  # the last update's first figure: the paper's tables
    assert f"γ = {gamma:g}°, ν = {nu:g}°" in figures[-1]._suptitle.get_text()  # its update
    FigureCanvasAgg(fig).draw()
    renderer = fig.canvas.get_renderer()
    box = fig.bbox
    titles = [ax.title for ax in fig.axes if ax.get_title()] + [fig._suptitle]
    extents = [t.get_window_extent(renderer) for t in titles]
    for t, e in zip(titles, extents, strict=True):
        assert e.x0 >= box.x0 - 1 and e.x1 <= box.x1 + 1, f"{t.get_text()!r} leaves the figure"
    for i, a in enumerate(extents):
        for b in extents[i + 1 :]:
            assert not a.overlaps(b), "two titles overlap"
    for ax in fig.axes:
        lines = [ln for ln in ax.get_lines() if ln.get_label().startswith(("γ", "ν"))]
        labels = [ln.get_label() for ln in lines]
        assert len(labels) == len(set(labels)), f"a legend entry twice: {labels}"
        colours = [ln.get_color() for ln in lines]
        assert len(colours) == len(set(colours)), f"two angles share a colour: {labels}"
