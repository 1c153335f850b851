"""The README's figures, made by code: the accuracy curves reproducing the papers' tables
and target sizes (:mod:`planner.app.curves`), and the plan of the built-in default site.

``planner figures`` (or :func:`make_figures`) regenerates ``figures/``.
"""

from __future__ import annotations

import io
from pathlib import Path

import matplotlib.pyplot as plt
from matplotlib.figure import Figure

from planner.app.curves import plot_height, plot_models, plot_planimetric, plot_target_sizes
from planner.app.maps import plot_coverage, plot_plan_map
from planner.atomic import check_output_folder, write_bytes_atomic
from planner.pipeline.engine.planning import plan
from planner.scanner import DEFAULT_SCANNER, Scanner

__all__ = ["make_figures"]


def _save(fig: Figure, path: Path) -> Path:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, metadata={"Software": None})
    plt.close(fig)
    return write_bytes_atomic(path, buf.getvalue())


def make_figures(out_dir: str | Path = "figures") -> list[Path]:
    """Regenerate the README figures in ``out_dir``; returns the files written. An
    ``out_dir`` that cannot hold them is an :class:`~planner.errors.InputError` before any
    work."""
    out = check_output_folder(out_dir)  # before the plan
    paper = Scanner.from_name(DEFAULT_SCANNER)
    default_plan = plan()
    written = [
        _save(plot_planimetric(paper, paper=True), out / "table1_planimetric_rms.png"),
        _save(plot_height(paper, paper=True), out / "table2_height_rms.png"),
        _save(plot_target_sizes(paper=True), out / "sossa_target_sizes.png"),
        _save(plot_models(paper, 0.0, 60.0), out / "models_paper_vs_3d.png"),
        _save(plot_plan_map(default_plan), out / "default_site_plan.png"),
        _save(plot_coverage(default_plan, "m_z_mm"), out / "default_site_m_z.png"),
    ]
    return written
