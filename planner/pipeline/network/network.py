"""The registration network as planned (:class:`Network`): its stations, links, targets
placed, datum and the error of every scan's pose, and the words that describe it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from scipy.spatial import cKDTree

from planner.pipeline.evaluation.evaluate import Registration
from planner.pipeline.network.targets import Sight, TargetCandidates
from planner.registration_error import (
    CONTROL,
    Link,
    NetworkError,
    transport_pose_cov,
)

__all__ = [
    "MODE_WORDS",
    "Network",
    "control_messages",
    "network_message",
]


@dataclass(kw_only=True)
class Network:
    """The registration network over the chosen stations."""

    stations: np.ndarray  # candidate indices: cover stations first, then linking ones
    n_link_stations: int
    links: list[Link]  # the registrations (a tree from the datum), parent first
    link_error_mm: dict[tuple[int, int], float]  # the link alone, at the child's points
    link_sigma_mm: dict[tuple[int, int], float]  # RMS of one target's centre difference
    linkable: list[tuple[int, int, int]]  # every pair with >= 3 common targets (a, b, count)
    targets: list[int]  # target candidate indices placed
    datum: int | None  # a station position, or None for the control network
    error: NetworkError | None  # pose covariances
    n_groups: int
    message: str
    sight: Sight  # of ``stations``
    candidates: TargetCandidates  # where targets could go; ``targets`` index them
    station_xyz: np.ndarray  # (K, 3) scanner centres [m]
    #: every observation adjusted: (station, target) → centre RMS [mm] per axis
    centre_rms: dict[tuple[int, int], float] = field(default_factory=dict)
    #: groups tied by planned control (:mod:`planner.pipeline.network.control`)
    ties: list = field(default_factory=list)
    #: how the scans are registered: targets, cloud or hybrid
    mode: str = "targets"
    #: the cloud links used, by (parent, child)
    clouds: dict = field(default_factory=dict)
    #: each link's weakest direction, in words, at its child's facade points
    weakest: dict = field(default_factory=dict)
    #: (K, K) overlap of the stations' scans [%] (None: targets only)
    overlap: np.ndarray | None = None
    #: how the network's vertical is held
    #: (:meth:`~planner.pipeline.inputs.requirements.PlanSettings.tilt_model`)
    tilt_model: str = "datum"
    #: targets whose heights a planned level run measures (index → RMS of the height [mm])
    levelled: dict = field(default_factory=dict)
    #: the adjustment's inputs, the levelled heights left out (for judging the network with
    #: other height control: :func:`~planner.pipeline.network.registration.readjusted`)
    adjusted: dict = field(default_factory=dict, repr=False)

    @property
    def tied(self) -> np.ndarray:
        if self.error is None:
            return np.zeros(len(self.stations), dtype=bool)
        return self.error.tied

    def registration(self) -> Registration | None:
        """The registration error of the network's stations (exact), for :func:`judging
        <planner.pipeline.evaluation.evaluate.assign_stations>` a plan."""
        if self.error is None:
            return None
        return Registration(
            pose_cov=self.error.pose_cov,
            station_xyz=self.station_xyz,
            tied=self.error.tied | (len(self.stations) == 1),
        )

    def leaning_datum(self) -> np.ndarray | None:
        """Where the datum whose tilt leans the whole network stands (x, y, z): 6-parameter
        registrations to a station datum whose vertical the network keeps
        (:func:`~planner.registration_error.datum_tilt_cov`); None where a compensator
        levels every scan, every scan's tilt reading or a level run holds the vertical, or
        control points fix it."""
        if self.tilt_model != "datum" or self.levelled or self.datum is None or self.error is None:
            return None
        return self.station_xyz[self.datum]

    def leans(self) -> np.ndarray:
        """(K,) the stations whose pose carries the datum's lean: tied to the datum (also
        through a traverse from a tied station), not by planned GNSS control of their own."""
        if self.leaning_datum() is None:
            return np.zeros(len(self.stations), dtype=bool)
        out = self.tied.copy()
        for tie in self.ties:
            if tie.start < 0:
                out[list(tie.stations)] = False
        return out

    @property
    def datum_station(self) -> int | None:
        """The datum as a candidate index (None: the control network, or no datum)."""
        return None if self.datum is None else int(self.stations[self.datum])

    @property
    def backbone(self) -> np.ndarray:
        """The stations others are registered to (candidate indices): the network's frame,
        which a new choice of stations keeps."""
        parents = {lk.parent for lk in self.links if lk.parent != CONTROL}
        return self.stations[sorted(parents)] if parents else self.stations[:0]

    def estimate(self, cand_xy: np.ndarray, cand_z: np.ndarray) -> Registration | None:
        """The registration error every candidate would have if it joined this network, for
        choosing stations with their registration in view: a station of the network keeps
        its own; another candidate gets the pose error of the nearest tied station, carried
        to where it stands, plus the error of one of this network's better links (its lower
        quartile). An estimate, on the hopeful side: the chosen stations' network is then
        built and judged exactly, and stations are added again where it falls short, while
        a pessimistic estimate (the median link, once targets hide each other) could rule
        out every candidate and leave the samples short."""
        if self.error is None or not self.error.tied.any():
            return None
        tied = np.flatnonzero(self.error.tied)
        net_xyz = self.station_xyz
        xyz = np.column_stack([cand_xy, cand_z])
        _, nearest = cKDTree(net_xyz[tied, :2]).query(cand_xy)
        j = tied[nearest]
        pose = transport_pose_cov(self.error.pose_cov[j], net_xyz[j], xyz)
        links = list(self.error.link_cov.values())
        if links:
            size = [np.trace(c[:3, :3]) for c in links]
            pose += links[int(np.argsort(size)[len(size) // 4])]
        own = self.stations[self.error.tied]
        pose[own] = self.error.pose_cov[self.error.tied]
        return Registration(pose_cov=pose, station_xyz=xyz, tied=np.ones(len(xyz), dtype=bool))


def control_messages(net: Network) -> str:
    """The network's message again, after planned control tied some of its groups."""
    k = len(net.stations)
    untied = int((~net.tied).sum())
    tied_by = sum(len(t.stations) for t in net.ties)
    head = network_message(
        k, net.n_link_stations, net.datum, untied, net.n_groups, net.candidates, net.links, net.mode
    )
    if tied_by and untied == 0:
        head = f"{MODE_WORDS[net.mode]} — the {k} stations form one registration network"
    if tied_by:
        head += f" ({tied_by} of them through planned control)"
    return head


#: How each registration mode is said in the summary.
MODE_WORDS = {
    "targets": "by targets",
    "cloud": "cloud to cloud",
    "hybrid": "hybrid (cloud to cloud, targets where a link is weak)",
}


def network_message(k, n_link, datum, untied, n_groups, tc, links, mode="targets") -> str:
    return f"{MODE_WORDS[mode]}{_counts(links, mode)} — " + _network_words(
        k, n_link, datum, untied, n_groups, tc, links, mode
    )


def _counts(links, mode) -> str:
    if mode == "targets" or not links:
        return ""
    n_cloud = sum(lk.info is not None for lk in links)
    return f": {n_cloud} cloud link(s), {len(links) - n_cloud} by targets"


def _network_words(k, n_link, datum, untied, n_groups, tc, links, mode) -> str:
    if k <= 1 and not tc.is_control.any():
        return "one station: no registration needed"
    added = f" after adding {n_link} linking station{'s' if n_link != 1 else ''}" if n_link else ""
    if datum == CONTROL:
        n_ctl = len({t for lk in links if lk.parent == CONTROL for t in lk.targets})
        head = f"tied to the site network through {n_ctl} control points"
    else:
        head = f"the {k} stations form one registration network"
    if untied == 0:
        return head + added
    if mode == "cloud":
        return (
            f"{untied} of the {k} stations cannot be tied to the others cloud to cloud (in "
            f"{n_groups} groups: the surfaces they share with the others overlap too little or "
            "leave a direction free, as one straight wall and the ground leave the shift along "
            "the wall); add targets where the clouds are weak (--registration hybrid), move "
            "or add a station that sees a cross wall or a corner, or tie them by control"
        )
    by = "common targets or surfaces" if mode == "hybrid" else "common targets"
    return (
        f"{untied} of the {k} stations cannot be tied to the others by {by} "
        f"(even{added or ' without linking stations'}, in {n_groups} groups); tie them by a "
        "traverse, by control points coordinated with a total station (--control), or add "
        "a station by hand"
    )
