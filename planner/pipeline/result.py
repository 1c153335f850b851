"""The result of planning: :class:`Plan` — stations, targets, coverage and diagnostics.

The plan's files (CSV, GeoJSON, summary) are written by :mod:`planner.pipeline.export`;
:meth:`Plan.save` is a shortcut to it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

from planner.pipeline.requirements import PlanSettings, Requirements
from planner.scanner import Scanner
from planner.site import Site

__all__ = ["FACADE_TABLE_COLUMNS", "Plan"]

#: The per-facade summary as a surveyor reads it (dashboard, report).
FACADE_TABLE_COLUMNS = [
    "building_id",
    "length_m",
    "samples",
    "party_wall_samples",
    "met",
    "unmet",
    "worst_m_x_mm",
    "worst_m_y_mm",
    "worst_m_z_mm",
    "stations",
]


@dataclass(kw_only=True)
class Plan:
    """A field plan: stations, targets, coverage of every facade sample, and diagnostics.

    DataFrames (coordinates in the site's CRS, heights above the ground):

    * ``stations`` — ``station_id, x, y, instrument_height_m, purpose`` ("cover" or "link"),
      ``samples_met``;
    * ``targets`` — ``target_id, x, y, z, type, min_size_mm, size_mm, station_ids`` (a list),
      ``item``;
    * ``coverage`` — one row per facade sample, the columns of
      :data:`planner.pipeline.export.COVERAGE_COLUMNS` plus ``spacing_mm,
      stations_meeting, party_wall, reason``;
    * ``facades`` — per-facade summary; ``links`` — registration links between stations;
    * ``candidates`` — every candidate position with the number of samples it meets.
    """

    site: Site
    scanner: Scanner
    requirements: Requirements
    settings: PlanSettings
    stations: pd.DataFrame
    targets: pd.DataFrame
    coverage: pd.DataFrame
    facades: pd.DataFrame
    links: pd.DataFrame
    candidates: pd.DataFrame
    solver: dict[str, Any]
    messages: list[str] = field(default_factory=list)
    timings_s: dict[str, float] = field(default_factory=dict)

    @property
    def unmet(self) -> pd.DataFrame:
        """Samples (not on party walls) where the requirements are not met."""
        c = self.coverage
        return c[~c["meets"] & ~c["party_wall"]]

    @property
    def meets_all(self) -> bool:
        return self.unmet.empty

    @property
    def scanned(self) -> pd.DataFrame:
        """Coverage of the samples that are demanded (not on party walls)."""
        return self.coverage[~self.coverage["party_wall"]]

    def facade_table(self) -> pd.DataFrame:
        """The per-facade summary as shown to a surveyor (indexed by facade id)."""
        return self.facades.set_index("facade_id")[FACADE_TABLE_COLUMNS].round(2)

    def unmet_areas(self) -> pd.DataFrame:
        """Unmet samples grouped by facade and reason: how many, and the height range."""
        u = self.unmet
        cols = ["facade_id", "reason", "samples", "z_from", "z_to"]
        if u.empty:
            return pd.DataFrame(columns=cols)
        return (
            u.groupby(["facade_id", "reason"])
            .agg(samples=("sample_id", "size"), z_from=("z", "min"), z_to=("z", "max"))
            .reset_index()
            .round(1)[cols]
        )

    def summary(self) -> str:
        """A few lines a surveyor reads first."""
        req, sc, s = self.requirements, self.scanner, self.solver
        cov = self.scanned
        n_cover = int((self.stations["purpose"] == "cover").sum())
        n_link = int((self.stations["purpose"] == "link").sum())
        solver = f"({s['status']}; objective {s['objective']}"
        if s.get("gap") is not None:
            solver += f", lower bound {s['lower_bound']:g}, gap {100 * s['gap']:.1f} %"
        if s.get("greedy_objective") is not None:
            solver += f"; greedy {s['greedy_objective']}"
        solver += ")"
        types = self.targets["type"].value_counts()
        lines = [
            f"Site {self.site.name!r}: {len(self.site.planned)} building(s) planned, "
            f"{len(self.facades)} facades, {len(cov)} samples "
            f"(+{int(self.coverage['party_wall'].sum())} on party walls, not demanded)",
            f"Scanner {sc.name}; required {req.describe()}",
            f"Stations: {len(self.stations)} ({n_cover} to cover"
            + (f", {n_link} to link" if n_link else "")
            + f"), chosen by {s['method']} {solver} from {len(self.candidates)} candidates",
            f"Targets: {len(self.targets)}"
            + (" (" + ", ".join(f"{n} {t}" for t, n in types.items()) + ")" if len(types) else ""),
            f"Samples meeting every requirement: {int(cov['meets'].sum())} of {len(cov)}",
        ]
        return "\n".join(lines + self.messages)

    def save(self, out_dir: str | Path) -> list[Path]:
        """Write the plan's files into ``out_dir`` (see :func:`planner.pipeline.export.save`)."""
        from planner.pipeline.export import save

        return save(self, out_dir)
