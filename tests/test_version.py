"""One version: the installed package's metadata (pyproject.toml) is what ``planner``
says."""

from __future__ import annotations

import tomllib
from pathlib import Path

import planner


def test_the_package_says_the_version_pyproject_gives():
    meta = tomllib.loads((Path(__file__).parents[1] / "pyproject.toml").read_text())
    assert planner.__version__ == meta["project"]["version"]
