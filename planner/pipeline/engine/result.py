"""The result of planning: :class:`Plan` — stations, targets, coverage and diagnostics.

The plan's files (CSV, GeoJSON, summary) are written by :mod:`planner.pipeline.documents.export`
(``export.save(plan, folder)``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from planner.crs import name_of as crs_name
from planner.pipeline.field.route import FieldRoute
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.pipeline.inputs.schema import FACADE_TABLE_COLUMNS, STATION_PURPOSES, ZONE_COLUMNS
from planner.pipeline.network.network import Network
from planner.pipeline.optimise.spacing import close_pairs
from planner.scanner import Scanner
from planner.site import Site

__all__ = ["Plan", "SolverReport"]


@dataclass
class SolverReport:
    """How the stations were chosen: the optimiser's method and status, the cover's size and
    the proven lower bound on it (and the gap), what the time budget cut short, and the work
    behind it (reach, candidates, samples, pairs evaluated). A district's plan adds its
    blocks: the bound of the blocks far apart, the one at shared prices, the stations removed
    as redundant; a block's plan the farthest pair meeting a sample."""

    method: str
    status: str
    objective: int
    lower_bound: float | None = None
    gap: float | None = None
    seconds: float = 0.0
    greedy_objective: int | None = None
    reductions: str = ""
    parts: int = 0
    registration_rounds: int = 0
    cut_short: list[str] = field(default_factory=list)
    samples_total: int = 0
    samples_evaluated: int = 0
    reach_m: float = math.inf
    candidates: int = 0
    samples: int = 0
    pairs: int = 0
    meeting_reach_m: float | None = None
    blocks: int = 0
    far_bound: float | None = None
    shared_bound: float | None = None
    block_bound_sum: float | None = None
    redundant_removed: int = 0
    #: pairs of stations closer than the crew's spacing the merging's time left untried
    spacing_untried: int = 0


#: The summary lists this many zones at most (zones.csv holds them all).
LISTED_ZONES = 20
#: The summary names at most this many pairs of stations closer than the crew's spacing.
LISTED_PAIRS = 12


@dataclass(kw_only=True, eq=False)
class Plan:
    """A field plan: stations, targets, coverage of every facade sample, and diagnostics.

    A plain result: it holds no machinery. What it was made from (for what-if edits) is kept
    beside it, :func:`planner.pipeline.engine.judge.workbench_of`. Coordinates are in the
    site's CRS [m], heights in its height system [m], errors [mm].

    Attributes
    ----------
    site, scanner, requirements, settings
        What the plan was made for and with (settings resolved for the scanner,
        :meth:`PlanSettings.for_scanner`).
    stations : DataFrame
        :data:`~planner.pipeline.inputs.schema.STATION_COLUMNS` [m] — ``purpose`` one of
        :data:`~planner.pipeline.inputs.schema.STATION_PURPOSES` ("cover" chosen by the optimiser,
        "link" tying the network, "registration" added for the registration error, "hand" placed or
        locked by the surveyor, "best-effort" for samples no position meets, "traverse" a total
        station's set-up) — and ``samples_met``.
    targets : DataFrame
        :data:`~planner.pipeline.inputs.schema.TARGET_COLUMNS` (``station_ids`` a list; size [mm],
        position [m]).
    coverage : DataFrame
        One row per facade sample: :data:`~planner.pipeline.inputs.schema.COVERAGE_COLUMNS` (m_x,
        m_y, m_z [mm] the totals, scanner ⊕ registration, and both parts) plus ``stations_meeting,
        party_wall``.
    facades : DataFrame
        One row per facade: its ends [m], samples, met and unmet
        (:data:`~planner.pipeline.inputs.schema.FACADE_TABLE_COLUMNS` shown).
    links : DataFrame
        The registrations between scans, :data:`~planner.pipeline.inputs.schema.LINK_COLUMNS` (RMS
        [mm], overlap [%]).
    candidates : DataFrame
        Every candidate position [m] with the number of samples it meets.
    solver : SolverReport
        How the stations were chosen, the bound on their number, what the budget cut.
    zones : DataFrame
        Each zone of the site (:mod:`planner.zones`):
        :data:`~planner.pipeline.inputs.schema.ZONE_COLUMNS`.
    network : Network or None
        The registration network behind ``links`` (pose covariances [m², rad²], the
        observations and their RMS); None where none was built (a district's blocks).
    route : FieldRoute or None
        The visiting order, walks [m] and field time [min] (:mod:`planner.pipeline.field.route`).
    messages : list of str
        What the surveyor is told beyond the tables, in the summary's order.
    timings_s : dict
        Seconds per planning stage (and a district worker's peak memory [MB]).
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
    solver: SolverReport
    zones: pd.DataFrame = field(default_factory=lambda: pd.DataFrame(columns=ZONE_COLUMNS))
    network: Network | None = None  # the registration network
    route: FieldRoute | None = None  # visiting order and field time
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

    @property
    def scan_stations(self) -> pd.DataFrame:
        """The stations that scan (the total station's traverse set-ups left out)."""
        return self.stations[self.stations["purpose"] != "traverse"]

    def network_ids(self) -> list[str]:
        """The station ids in the order of the registration network's stations (its
        indices: links, observations), matched by position; none without a network."""
        if self.network is None:
            return []
        st = self.scan_stations.set_index("station_id")[["x", "y"]]
        x, y = st["x"].to_numpy(dtype=float), st["y"].to_numpy(dtype=float)
        return [
            str(st.index[int(np.argmin(np.hypot(x - sx, y - sy)))])
            for sx, sy in self.network.station_xyz[:, :2]
        ]

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

    def scene_description(self) -> str:
        """What the sight lines were cast against, in words."""
        site = self.site
        n3 = sum(1 for b in site.buildings if b.surfaces)
        parts = []
        if n3:
            parts.append(f"{n3} building(s) as their 3-D model")
        if len(site.buildings) > n3:
            parts.append(f"{len(site.buildings) - n3} building(s) as footprints with heights")
        trees = sum(1 for o in site.obstacles if o.kind == "tree")
        if trees:
            parts.append(f"{trees} tree(s)")
        if site.terrain is not None:
            parts.append(f"the terrain ({site.terrain.source})")
        return "sight lines cast against " + ", ".join(parts)

    def registration_model(self) -> str | None:
        """How the promised registration error registers each scan, in words (the summary
        and plan.geojson say it): 4 parameters for a scanner whose compensator levels each
        scan, else 6 — and then whether the datum scan's levelling leans the network or
        control points hold the vertical. None where the error is not computed (the
        summary's registration lines say so)."""
        if not self.settings.computes_registration:
            return None
        if self.scanner.is_levelled:
            return (
                "4 parameters per scan (shifts in x, y, z and the rotation about the "
                "vertical; the scanner's compensator levels each scan, its residual tilt "
                "counted)"
            )
        net = self.network
        if net is None:  # a district's blocks or the jobs: each its own network
            vertical = (
                "each block's or job's frame holds its own vertical: its datum scan's "
                "levelling, its scans' tilt readings, a level run or control"
            )
        elif net.levelled:
            vertical = "a level run to some of the targets holds the vertical"
        elif net.datum is not None and net.tilt_model == "readings":
            vertical = "every scan's recorded tilt holds the vertical, adjusted together"
        elif net.leaning_datum() is None:
            vertical = "control points hold the vertical"
        else:
            vertical = "the network leans with the datum scan's levelling"
        return f"6 parameters per scan (shifts in x, y, z and three rotations; {vertical})"

    def spacing_summary(self) -> str | None:
        """The crew's station spacing in words (:mod:`planner.pipeline.optimise.spacing`):
        the closest pair where none stands closer, else the closer pairs by why they stay;
        None for fewer than two scanning stations."""
        st, spacing = self.scan_stations, self.settings.station_spacing_m
        if len(st) < 2:
            return None
        xy = st[["x", "y"]].to_numpy(float)
        ids, purpose = st["station_id"].astype(str).tolist(), st["purpose"].astype(str).tolist()
        if spacing <= 0:
            return "Station spacing: not kept (station_spacing_m = 0)."
        close = close_pairs(xy, spacing)
        if not close:
            d = np.hypot(*(xy[:, None, :] - xy[None, :, :]).transpose(2, 0, 1))
            np.fill_diagonal(d, np.inf)
            i, j = np.unravel_index(np.argmin(d), d.shape)
            return (
                f"Station spacing: no two set-ups closer than {spacing:g} m (the closest: "
                f"{ids[i]}–{ids[j]}, {d[i, j]:.1f} m)."
            )
        untried = self.solver.spacing_untried
        other = (
            "a district's blocks are merged each on its own, not across their seams"
            if self.solver.blocks
            else "one set-up in their place meets fewer samples or breaks the network"
            + (
                f", or ({untried} pair(s)) untried: the merging's limit was reached"
                if untried
                else ""
            )
        )
        why: dict[str, list[str]] = {}
        for i, j in close:
            pair = {purpose[i], purpose[j]}
            reason = (
                STATION_PURPOSES["hand"]
                if "hand" in pair
                else STATION_PURPOSES["best-effort"]
                if "best-effort" in pair
                else other
            )
            why.setdefault(reason, []).append(
                f"{ids[i]}–{ids[j]} {float(np.hypot(*(xy[i] - xy[j]))):.1f} m"
            )
        parts = [
            ", ".join(p[:LISTED_PAIRS])
            + (f" and {len(p) - LISTED_PAIRS} more" if len(p) > LISTED_PAIRS else "")
            + f" ({reason})"
            for reason, p in why.items()
        ]
        return f"Station spacing: {len(close)} pair(s) closer than {spacing:g} m, kept: " + (
            "; ".join(parts) + "."
        )

    def summary(self) -> str:
        """A few lines a surveyor reads first."""
        req, sc, s = self.requirements, self.scanner, self.solver
        cov = self.scanned
        purposes = self.stations["purpose"].value_counts()
        solver = f"({s.status}; objective {s.objective}"
        if s.gap is not None:
            solver += f", lower bound {s.lower_bound:g}, gap {100 * s.gap:.1f} %"
        scans = len(self.scan_stations)
        if self.settings.computes_registration and scans > s.objective and s.blocks == 0:
            # the bound is the scanner's cover's: the stations the registration added beyond
            # it are said, not left to contradict it
            solver += (
                f" for the cover by the scanner's error alone; {scans - s.objective} more "
                "for the registration (its error, its links)"
            )
        if s.greedy_objective is not None:
            solver += f"; greedy {s.greedy_objective}"
        if s.reductions:
            solver += f"; reductions: {s.reductions}; {s.parts} independent part(s)"
        solver += ")"
        types = self.targets["type"].value_counts()
        lines = [
            f"Site {self.site.name!r}: {len(self.site.planned)} building(s) planned, "
            f"{len(self.facades)} facades, {len(cov)} samples "
            f"(+{int(self.coverage['party_wall'].sum())} on party walls, not demanded)",
            f"Scanner {sc.name}; required {req.describe()}",
            "Coordinates: "
            + (
                crs_name(self.site.crs)
                if self.site.crs
                else "no CRS given "
                "(local metres; name it with --crs to get plan.kml and a georeferenced plan)"
            ),
            f"Stations: {len(self.stations)} ("
            + ", ".join(
                f"{purposes[key]} {words}"
                for key, words in STATION_PURPOSES.items()
                if purposes.get(key, 0)
            )
            + ("none" if self.stations.empty else "")
            + (
                f"); the covering ones chosen by {s.method} {solver} from "
                f"{len(self.candidates)} candidates"
                if s.method != "hand placement"
                else f"; the optimiser's lower bound {s.lower_bound:g})"
                if s.lower_bound is not None
                else ")"
            ),
            f"Targets: {len(self.targets)}"
            + (" (" + ", ".join(f"{n} {t}" for t, n in types.items()) + ")" if len(types) else ""),
            "Samples meeting every requirement"
            + (" (scanner ⊕ registration)" if self.settings.computes_registration else "")
            + f": {int(cov['meets'].sum())} of {len(cov)}",
        ]
        if (spaced := self.spacing_summary()) is not None:
            lines.insert(4, spaced)
        if self.site.is_3d:  # heights and the scene, said where they are more than footprints
            lines.insert(3, f"Heights: {self.site.height_system}; {self.scene_description()}")
        if self.route is not None:
            lines.append(self.route.summary())
        zones = self.zones
        if len(zones) > LISTED_ZONES:  # the unmet first, the most unmet first
            zones = zones.sort_values("unmet", ascending=False, kind="stable").head(LISTED_ZONES)
            lines.append(
                f"Zones: {len(self.zones)}, {int((self.zones['unmet'] == 0).sum())} met in "
                f"full; the {LISTED_ZONES} with the most unmet samples below, all in zones.csv"
            )
        for z in zones.itertuples():
            state = "met" if z.unmet == 0 else f"{z.unmet} of {z.samples} samples unmet"
            lines.append(f"Zone {z.zone_id} ({z.where}; {z.requirement}): {state}")
        if (model := self.registration_model()) is not None:
            lines.append(f"Registration model: {model}.")
        return "\n".join(lines + self.messages)
