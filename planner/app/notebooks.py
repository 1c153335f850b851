"""The shipped notebooks (Voilà dashboards and the report) and where they are installed."""

from __future__ import annotations

from pathlib import Path

from planner.errors import InputError

__all__ = ["DASHBOARDS", "notebook_path"]

#: The notebooks ``planner serve --notebook`` serves (the first is the default).
DASHBOARDS = (
    "station_planner.ipynb",
    "accuracy_explorer.ipynb",
    "targets.ipynb",
    "calibration.ipynb",
)


def notebook_path(name: str) -> Path:
    """A shipped notebook: inside the installed package, or ``notebooks/`` of a checkout."""
    here = Path(__file__).resolve().parent.parent  # the planner package
    for folder in (here / "notebooks", here.parent / "notebooks"):
        if (folder / name).is_file():
            return folder / name
    raise InputError(f"notebook {name!r} is not installed (looked in {here / 'notebooks'})")
