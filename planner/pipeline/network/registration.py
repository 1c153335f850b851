"""Registration planning: the targets that tie the scans together, the network of pairwise
registrations, and its error at every facade sample (:func:`build_network`, which puts
the room's pieces together).

1. Where targets can go and what each station sees of them:
   :mod:`~planner.pipeline.network.targets`.
2. The targets of each link: :mod:`~planner.pipeline.network.links`.
3. Linking stations where groups of stations cannot be linked:
   :mod:`~planner.pipeline.network.bridges`.
4. The datum and the tree of registrations: :mod:`~planner.pipeline.network.layout`;
   cloud-to-cloud links: :mod:`~planner.pipeline.network.clouds`.
5. The network as planned: :class:`~planner.pipeline.network.network.Network`. The error
   the plan is judged on is that of the simultaneous adjustment of every placed target each
   station sees (:func:`planner.registration_error.adjust`), as registration software
   computes it.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from planner.cloud_registration import weakest_direction
from planner.pipeline.evaluation.evaluate import Context
from planner.pipeline.network.bridges import find_bridges, link_groups, linking_hops, shared_targets
from planner.pipeline.network.height import levelled_targets
from planner.pipeline.network.layout import HIDDEN_DETOUR, Layout, Stands
from planner.pipeline.network.network import Network, network_message
from planner.pipeline.network.targets import (
    Sight,
    SightCache,
    TargetCandidates,
    centre_rms,
    item_sizes,
)
from planner.registration_error import (
    CONTROL,
    Link,
    NetworkError,
    adjust,
    propagate,
    transport_pose_cov,
)

__all__ = [
    "build_network",
]


def build_network(
    ctx: Context,
    tc: TargetCandidates,
    cand_xy: np.ndarray,
    chosen: np.ndarray,
    probes: dict[int, np.ndarray],
    *,
    goal_mm: float,
    weak_mm: float = np.inf,
    cache: SightCache | None = None,
    datum: int | None = None,
    height_room: tuple[np.ndarray, np.ndarray] | None = None,
    chain: Sequence[int] | None = None,
    cap: int | None = None,
    standing: Sequence[int] = (),
) -> Network:
    """Link the chosen stations into one registration network (module docstring).

    ``probes`` maps a position in ``chosen`` to the facade points it serves (P, 3) [m]; a
    linking station without points is probed at its own targets' spread. A link whose own
    error exceeds ``weak_mm`` is strengthened, where linking stations can, by a detour
    that makes the worst station's error smaller. ``cache`` keeps the candidates' sights
    between calls. ``datum`` (a candidate index) keeps the datum of the network this one
    grows from, when it is among the stations.
    ``height_room``: the samples' plan positions (P, 2) [m] and the height error each leaves
    the registration [mm], for deciding a level run
    (:func:`~planner.pipeline.network.height.levelled_targets`). ``chain`` and ``cap``: a
    leap-frogging kit's layout (:class:`~planner.pipeline.network.layout.Layout`).
    ``standing``: spheres another network has set up (targets), which hide what lies behind
    them from these stations too.
    """
    seen = cache if cache is not None else SightCache(ctx, tc, cand_xy)
    n_cover = len(chosen)
    stations = [int(c) for c in chosen]
    where = (datum, (chain, cap))
    lay = _layout(ctx, seen, cand_xy, stations, probes, goal_mm, weak_mm, *where)
    stations, station_xyz, datum, k = lay.stations, lay.station_xyz, lay.datum, lay.k
    links, link_error, placed, stands, behind = _tree_links(ctx, tc, lay, standing)
    # the spheres set up (and another network's) hide targets from stations
    sight = stands.hide(lay.sight, placed | set(stands.spheres))
    users, final_rms, observed = _final_sizes(ctx, tc, sight, links)
    control_rms = {int(t): float(tc.control_rms_mm[t]) for t in np.flatnonzero(tc.is_control)}
    error, adjusted, levelled = _levelled_error(
        ctx, lay, tc, links, (final_rms, observed, control_rms, users), placed, height_room
    )
    link_sigma: dict[tuple[int, int], float] = {}
    if error is not None:
        link_sigma = _own_link_errors(lay, links, error, final_rms, control_rms, link_error)
    n_groups = int(link_groups(k, lay.pairs).max() + 1) if k else 0
    untied = int((~error.tied).sum()) if error is not None else k
    message = network_message(k, k - n_cover, datum, untied, n_groups, tc, links, lay.mode)
    if behind:
        message += (
            f"; {behind} link(s) could only use targets behind another link's sphere and are "
            "not made (the spheres stand together as the route sets them up)"
        )
    linkable = [(a, b, len(shared_targets(sight, tc, a, b))) for a, b in lay.pairs]
    return Network(
        stations=np.array(stations, dtype=np.int64),
        n_link_stations=k - n_cover,
        links=links,
        link_error_mm=link_error,
        link_sigma_mm=link_sigma,
        linkable=linkable,
        targets=sorted(placed),
        datum=None if datum == CONTROL else datum,
        error=error,
        n_groups=n_groups,
        message=message,
        sight=sight,
        candidates=tc,
        station_xyz=station_xyz,
        centre_rms=observed,
        mode=lay.mode,
        weakest=_weakest_directions(lay, links, error),
        clouds={
            (lk.parent, lk.child): lay.cloud(lk.parent, lk.child)
            for lk in links
            if lk.info is not None
        },
        overlap=lay.overlap,
        tilt_model=ctx.settings.tilt_model(ctx.scanner),
        levelled=levelled,
        adjusted=adjusted,
    )


def _layout(
    ctx: Context,
    seen: SightCache,
    cand_xy: np.ndarray,
    stations: list[int],
    probes: dict[int, np.ndarray],
    goal_mm: float,
    weak_mm: float,
    datum: int | None,
    kit: tuple = (None, None),
) -> Layout:
    """The network's layout over ``stations`` and the linking stations they need (and a
    detour where a link is weaker than ``weak_mm``, if it makes the worst station's error
    smaller)."""
    lay = _checked(ctx, lambda: Layout(ctx, seen, cand_xy, stations, probes, goal_mm, datum, *kit))
    groups = link_groups(lay.k, lay.pairs)
    # stations neither targets nor clouds tie: linking stations (not in a kit's chain)
    if groups.max() > 0 and kit[0] is None:
        hops = linking_hops(ctx, seen, cand_xy, stations, lay.mode, lay.sight)
        extra = find_bridges(hops, groups) if hops else []
        if extra:
            lay = _checked(
                ctx, lambda: Layout(ctx, seen, cand_xy, stations + extra, probes, goal_mm, datum)
            )
    weak = np.zeros(1)
    if np.isfinite(weak_mm) and lay.k > 1 and kit[0] is None:
        weak = lay.weak_groups(weak_mm)
    if weak.max() > 0:  # too weak: a detour, if it helps
        hops = linking_hops(ctx, seen, cand_xy, lay.stations, lay.mode, lay.sight)
        extra = find_bridges(hops, weak) if hops else []
        if extra:
            more = lay.stations + extra
            trial = _checked(ctx, lambda: Layout(ctx, seen, cand_xy, more, probes, goal_mm, datum))
            if len(trial.cost) >= len(lay.cost) and trial.worst_var < 0.8 * lay.worst_var:
                lay = trial
    return lay


#: Layouts rebuilt at most this often while their new cloud links are rehearsed.
CHECK_ROUNDS = 3


def _checked(ctx: Context, make: Callable[[], Layout]) -> Layout:
    """The layout ``make`` gives, with every cloud link of its tree rehearsed once the plan
    rehearses them (:mod:`~planner.pipeline.network.linkcheck`): a link that
    fails too often is no link, one the rehearsal finds weaker than the model is weakened,
    and the layout is made again over them until its tree holds only rehearsed links (at
    most :data:`CHECK_ROUNDS` times; the last layout's new links are then rehearsed and
    the tree keeps them only if they hold: a station they alone tied is said untied)."""
    lay = make()
    if lay.mode == "targets" or not lay.seen.clouds.rehearsing:
        return lay
    for _ in range(CHECK_ROUNDS):
        todo = lay.unchecked()
        if not todo:
            return lay
        for i, j in todo:
            lay.check(i, j)
        lay = make()
    for i, j in lay.unchecked():  # the last layout's new links: rehearsed, not remade
        lay.check(i, j)
    return lay


def _tree_links(
    ctx: Context, tc: TargetCandidates, lay: Layout, standing: Sequence[int] = ()
) -> tuple[list[Link], dict[tuple[int, int], float], set[int], Stands, int]:
    """The links in tree order, each preferring the targets already set up (those the
    surveyor placed by hand are taken first by every link that sees them:
    :func:`~planner.pipeline.network.links.choose_link_targets`): the links, each one's own
    error [mm], the targets placed, the sphere stands set up, and how many links could only
    use targets behind another link's sphere (not made: the stations they would tie are tied
    otherwise, or said untied)."""
    placed: set[int] = set()
    links: list[Link] = []
    link_error: dict[tuple[int, int], float] = {}
    station_xyz, datum = lay.station_xyz, lay.datum
    stands = Stands(ctx, tc, station_xyz)
    stands.spheres = [int(t) for t in standing if tc.type[t] == "sphere"]
    tied = [] if datum is None or datum == CONTROL else [datum]
    paired = set(lay.pairs)
    behind = 0  # links that can only use a target another link's sphere hides
    for parent, child in lay.tree:
        if parent != CONTROL and parent not in tied:
            continue  # its parent could not be tied: nor can it, this way
        targets, err = lay.link(parent, child, placed, stands)
        cl = lay.cloud(parent, child)
        if not targets and cl is not None:  # cloud to cloud
            links.append(Link(parent, child, (), cl.information))
            link_error[(parent, child)] = err
            tied.append(child)
            continue
        if lay.mode == "cloud":  # its cloud link failed its rehearsal: the child is untied
            continue
        if not targets:  # the targets set up hide this link's: register it to another
            bound = max(lay.goal_mm, HIDDEN_DETOUR * lay.link(parent, child)[1])
            others = [(i, lay.link(i, child, placed, stands)) for i in tied if i != parent]
            others = [
                (e, i, t)
                for i, (t, e) in others
                if t and e <= bound and (min(i, child), max(i, child)) in paired
            ]
            if others:
                err, parent, targets = min(others)
        if not targets:  # only targets another link's sphere hides: no link (the spheres
            # stand together as the route sets them up); the message says so
            behind += 1
            continue
        links.append(Link(parent, child, tuple(targets)))
        link_error[(parent, child)] = err
        placed.update(targets)
        stands.set_up((parent, child), targets)
        tied.append(child)
    return links, link_error, placed, stands, behind


def _levelled_error(
    ctx: Context,
    lay: Layout,
    tc: TargetCandidates,
    links: list[Link],
    obs: tuple,
    placed: set[int],
    height_room: tuple[np.ndarray, np.ndarray] | None,
) -> tuple[NetworkError | None, dict, dict[int, float]]:
    """The network's error (:func:`_network_error` of ``obs``: the links' and every
    sighting's centre RMS, the control's, each target's users) with the level run it plans
    (:func:`~planner.pipeline.network.height.levelled_targets`), and that run; none where
    groups are left to planned control (a traverse, GNSS), which holds the vertical of what
    it ties, not a level run planned before it."""
    station_datum = None if lay.datum == CONTROL else lay.datum  # control holds the vertical
    levelled = levelled_targets(
        ctx, lay.station_xyz, station_datum, tc.xyz, sorted(placed), room=height_room
    )
    error, adjusted = _network_error(ctx, lay, tc, links, *obs, levelled)
    if levelled and error is not None and not error.tied.all():
        levelled = {}
        error, adjusted = _network_error(ctx, lay, tc, links, *obs)
    return error, adjusted, levelled


def _final_sizes(
    ctx: Context, tc: TargetCandidates, sight: Sight, links: list[Link]
) -> tuple[dict[int, set[int]], dict[tuple[int, int], float], dict[tuple[int, int], float]]:
    """The final sizes: each placed target gets the smallest item that serves every station
    using it, and the centre RMS with that item [mm]: the stations using each target, the
    links' observations and every station's that sees one (keyed (station, target))."""
    users: dict[int, set[int]] = {}
    for lk in links:
        for t in lk.targets:
            users.setdefault(t, set()).add(lk.child)
            if lk.parent != CONTROL:
                users[t].add(lk.parent)
    final_rms: dict[tuple[int, int], float] = {}  # the links' observations
    observed: dict[tuple[int, int], float] = {}  # and every other station's that sees one
    for t, who in users.items():
        need = max(float(sight.need_mm[t, j]) for j in who)
        size = float(item_sizes(ctx, tc, np.array([t]), np.array([need]))[0])
        for j in who:
            final_rms[(j, t)] = observed[(j, t)] = centre_rms(ctx, tc, sight, t, j, size)
        if tc.type[t] == "control":
            continue  # a control point is observed by the stations its links tie to it
        for j in map(int, np.flatnonzero(sight.usable[t] & (sight.need_mm[t] <= size))):
            if (j, t) not in observed:
                observed[(j, t)] = centre_rms(ctx, tc, sight, t, j, size)
    return users, final_rms, observed


def _network_error(
    ctx: Context,
    lay: Layout,
    tc: TargetCandidates,
    links: list[Link],
    final_rms: dict[tuple[int, int], float],
    observed: dict[tuple[int, int], float],
    control_rms: dict[int, float],
    users: dict[int, set[int]],
    heights: dict[int, float] | None = None,
) -> tuple[NetworkError | None, dict]:
    """The network's error: the chain's (:func:`planner.registration_error.propagate`),
    with the pose covariances of the adjustment of every target each scan sees where the
    software adjusts them together (:func:`planner.registration_error.adjust`), with the
    ``heights`` of the levelled targets (:mod:`planner.pipeline.network.height`). None: no
    link and no datum. With it, the adjustment's inputs but the heights (for
    :func:`readjusted`; empty where the chain's error is the plan's)."""
    if not links and lay.datum is None:
        return None, {}
    levelled = ctx.scanner.is_levelled
    datum = None if lay.datum == CONTROL else lay.datum
    error = propagate(
        lay.station_xyz,
        tc.xyz,
        final_rms,
        links,
        datum=datum,
        control_rms_mm=control_rms,
        levelled=levelled,
        tilt_rms_arcsec=ctx.scanner.datum_tilt_rms_arcsec,
    )
    if error is None or ctx.settings.registration_processing != "adjustment":
        return error, {}
    # the registration as it is computed: every target each scan sees, adjusted together
    # (pairwise: each scan registered to its parent on the link's targets, the chain's)
    inputs = {
        "station_xyz": lay.station_xyz,
        "target_xyz": tc.xyz,
        "target_rms_mm": observed,
        "tied": error.tied,
        "datum": datum,
        "control_rms_mm": {t: r for t, r in control_rms.items() if t in users},
        "levelled": levelled,
        "tilt_rms_arcsec": ctx.scanner.datum_tilt_rms_arcsec,
        "relative": [(lk.parent, lk.child, lk.info) for lk in links if lk.info is not None],
    }
    error.pose_cov = readjusted(ctx, inputs, heights or {})
    return error, inputs


def readjusted(ctx: Context, inputs: dict, heights: dict[int, float]) -> np.ndarray:
    """The pose covariances of the adjustment of ``inputs`` (:func:`_network_error`'s) with
    the ``heights`` of levelled targets (none: the network as it leans without them)."""
    datum, tied = inputs["datum"], inputs["tied"]
    return adjust(
        **inputs,
        tilt_readings=_tilt_readings(ctx, tied, datum, bool(heights)),
        heights_mm=heights,
    )


def _tilt_readings(
    ctx: Context, tied: np.ndarray, datum: int | None, levelled: bool
) -> dict[int, float] | None:
    """The tilt readings the adjustment takes (station → RMS [″]): every tied scan's where
    the software uses them; the datum's alone — its own vertical as a prior, which the
    levelled heights then improve — where a level run holds the vertical; else none (the
    datum's lean is added as it stands: :func:`planner.registration_error.datum_tilt_cov`)."""
    sc = ctx.scanner
    model = ctx.settings.tilt_model(sc)
    if model == "readings":
        return dict.fromkeys(np.flatnonzero(tied).tolist(), sc.tilt_sensor_rms_arcsec)
    if model == "datum" and levelled and datum is not None:
        return {datum: sc.datum_tilt_rms_arcsec}
    return None


def _own_link_errors(
    lay: Layout,
    links: list[Link],
    error: NetworkError,
    final_rms: dict[tuple[int, int], float],
    control_rms: dict[int, float],
    link_error: dict[tuple[int, int], float],
) -> dict[tuple[int, int], float]:
    """Each link's own error with the final sizes, at the facade points of its child (into
    ``link_error``); and the RMS of one target's centre difference in it (its dilution's
    denominator), returned."""
    link_sigma: dict[tuple[int, int], float] = {}
    for lk in links:
        if lk.info is not None:
            continue  # a cloud link's own error is known (Layout.link)
        key = (lk.parent, lk.child)
        link_error[key] = lay.error_at_probes(error.link_cov[key], lk.child)
        s2 = [
            (control_rms[t] if lk.parent == CONTROL else final_rms[(lk.parent, t)]) ** 2
            + final_rms[(lk.child, t)] ** 2
            for t in lk.targets
        ]
        link_sigma[(lk.parent, lk.child)] = float(np.sqrt(np.mean(s2)))
    return link_sigma


def _weakest_directions(
    lay: Layout, links: list[Link], error: NetworkError | None
) -> dict[tuple[int, int], str]:
    """Each link's weakest direction at the middle of its child's facade points."""
    weakest = {}
    for lk in links:
        key = (lk.parent, lk.child)
        cov = lay.cloud(*key).cov if lk.info is not None else None
        if cov is None and error is not None and key in error.link_cov:
            cov = error.link_cov[key]
        if cov is not None and np.isfinite(np.diag(cov)).all():
            mid = lay.probe(lk.child).mean(axis=0)
            cov = transport_pose_cov(cov, lay.station_xyz[lk.child], mid)
        weakest[key] = weakest_direction(cov) if cov is not None else ""
    return weakest
