"""Ids that stay: what a plan's stations and targets were called, for the plans made from it.

Once a plan's ids are printed in a booklet (or scanned under), they must not change. A plan
made from an earlier one — edited by hand, re-optimised around locked stations, planned
again after a passage, a zone or a setting changed, or re-planned from what was scanned —
is given the earlier plan's :class:`GivenIds`: a station standing where one of the earlier
plan's stood keeps its id, as does a target at an earlier target's place; every other takes
a number never given before (after the highest the earlier plans gave), so a deleted id is
never given to something else.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np
import pandas as pd

__all__ = ["SAME_PLACE_M", "GivenIds", "id_number", "ids_at"]

#: Two positions closer than this [m] are one place (a station or a target that has not
#: moved: positions are kept to the millimetre).
SAME_PLACE_M = 1e-3


def id_number(ident: str, prefix: str) -> int | None:
    """The number of an id such as ``S07`` or ``T12`` (``prefix`` "S" or "T"); None for
    an id of another form (a control point's own, a station named on site).

    >>> id_number("S07", "S"), id_number("T112", "T"), id_number("GCP4", "T")
    (7, 112, None)
    """
    m = re.fullmatch(rf"{prefix}(\d+)", str(ident))
    return int(m.group(1)) if m else None


@dataclass(frozen=True)
class GivenIds:
    """The ids an earlier plan gave: its stations' positions (``station_xy``, (k, 2) [m])
    and ids, its targets' positions (``target_xyz``, (t, 3) [m]) and ids, and the highest
    station and target numbers ever given (those of plans before it counted)."""

    station_xy: np.ndarray
    station_ids: tuple[str, ...]
    target_xyz: np.ndarray
    target_ids: tuple[str, ...]
    last_station: int = 0
    last_target: int = 0

    @classmethod
    def of(
        cls,
        stations: pd.DataFrame,
        targets: pd.DataFrame,
        last_station: int = 0,
        last_target: int = 0,
    ) -> GivenIds:
        """The ids of a plan's scanning ``stations`` (a traverse's set-ups are planned again
        with the network, under their own ids) and ``targets`` (control points keep their
        own ids anyway, and are left out); ``last_station``, ``last_target``: the highest
        numbers given before them."""
        ours = targets[targets["type"] != "control"] if "type" in targets else targets
        s_ids = tuple(stations["station_id"].astype(str))
        t_ids = tuple(ours["target_id"].astype(str))
        return cls(
            station_xy=stations[["x", "y"]].to_numpy(float).reshape(-1, 2),
            station_ids=s_ids,
            target_xyz=ours[["x", "y", "z"]].to_numpy(float).reshape(-1, 3),
            target_ids=t_ids,
            last_station=max([last_station, *(id_number(s, "S") or 0 for s in s_ids)]),
            last_target=max([last_target, *(id_number(t, "T") or 0 for t in t_ids)]),
        )

    def stations_at(self, xy: np.ndarray) -> list[str | None]:
        """The id of the earlier station at each position ``xy`` (k, 2) [m], None where none
        stood (each id once, the first position keeping it)."""
        return ids_at(self.station_xy, self.station_ids, xy)

    def targets_at(self, xyz: np.ndarray) -> list[str | None]:
        """The id of the earlier target at each position ``xyz`` (t, 3) [m], None where none
        stood (each id once)."""
        return ids_at(self.target_xyz, self.target_ids, xyz)


def ids_at(
    known: np.ndarray, ids: tuple[str, ...] | list[str], points: np.ndarray
) -> list[str | None]:
    """The id of the ``known`` position ((k, d) [m], one per id) at each of ``points`` (within
    :data:`SAME_PLACE_M`; the first of ``ids`` standing there that no earlier point took),
    None where none stands: each id given once. The one rule of "the same place"."""
    known = np.asarray(known, dtype=float)
    points = np.asarray(points, dtype=float).reshape(-1, known.shape[1])
    out: list[str | None] = []
    used: set[str] = set()
    for p in points:
        near = np.flatnonzero(np.abs(known - p).max(axis=1) < SAME_PLACE_M)
        sid = next((ids[k] for k in near if ids[k] not in used), None)
        if sid is not None:
            used.add(sid)
        out.append(sid)
    return out
