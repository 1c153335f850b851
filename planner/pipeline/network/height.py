"""Planned height control: targets whose heights a level run measures.

Without a compensator, and where the software holds the network's vertical by the datum
scan alone (:meth:`~planner.pipeline.inputs.requirements.PlanSettings.tilt_model` "datum"),
the whole network leans with the datum's tilt: heights err in proportion to the distance
from the datum (:func:`planner.registration_error.datum_tilt_cov`), and on a street or a
district every sample far from the datum fails m_z. Every scan's tilt reading ("readings")
leans it by their combined error instead — smaller, but with an IMU's 180″ still tens of
millimetres over a site. The cheapest tie a crew makes is a level
run: a digital level from one of the placed targets to a few others, their heights (in the
run's own datum) known to ``level_rms_mm`` each. Two or more such heights hold the network's
vertical; the adjustment takes each as an observation (:func:`planner.registration_error.
adjust`, ``heights_mm``), so every sample's registration error carries them.

Which targets (:func:`levelled_targets`): where the datum's lean would reach
:data:`LEAN_SHARE` of the strictest height limit within the network, the fewest placed
targets (greedily: each the one near the most stations still short) such that every station
stands within the distance over which the datum's tilt leans by that share of the limit from
the datum or a levelled target; at least :data:`MIN_LEVELLED` (the others farthest apart),
which hold both axes of the tilt.

Default accuracy: 1.0 mm a height — a digital level's run over a site's few hundred metres
(Leica DNA03: 0.3 mm per km of double run, Schneider & Dixon, "The new Leica Digital Levels
DNA03 and DNA10", FIG XXII International Congress, Washington 2002) is a few tenths of a
millimetre, and reading the height of the target's centre above the staff's mark about a
millimetre; the user's figure (``--level-rms-mm``) replaces it.
"""

from __future__ import annotations

import numpy as np

from planner.pipeline.evaluation.evaluate import Context
from planner.registration_error import datum_lean_mm

__all__ = ["LEAN_SHARE", "MIN_LEVELLED", "levelled_targets"]

#: Height control is planned where the datum's lean would take this share of the strictest
#: height limit within the network, and levelled targets are placed so that no station is
#: farther than that lean's distance from the datum or one of them.
LEAN_SHARE = 0.5
#: … and only where the datum's lean alone takes more than this share of the samples over
#: what their height limit leaves the registration (the plan's own rounds serve a few).
SHORT_SHARE = 0.02
#: At least this many targets are levelled (two fix the tilt along their line, three both).
MIN_LEVELLED = 3


def levelled_targets(
    ctx: Context,
    station_xyz: np.ndarray,
    datum: int | None,
    target_xyz: np.ndarray,
    placed: list[int],
    *,
    force: bool = False,
    room: tuple[np.ndarray, np.ndarray] | None = None,
) -> dict[int, float]:
    """The placed targets a level run measures (target index → RMS of its height [mm]); none
    where the settings plan no height control (``force``: the run they would plan), the
    network does not lean with its datum, or the lean stays within :data:`LEAN_SHARE` of
    the height limit. ``room``: the samples' plan positions (P, 2) [m] and the height error
    each leaves the registration [mm]; then a run only where the datum's lean alone takes
    more than :data:`SHORT_SHARE` of them over it."""
    st, sc = ctx.settings, ctx.scanner
    if not (force or st.height_control in ("level", "always")):
        return {}
    model = st.tilt_model(sc)
    if model not in ("datum", "readings") or datum is None or datum < 0:
        return {}
    if st.registration_processing != "adjustment":  # the heights enter the adjustment
        return {}
    if not st.computes_registration or len(placed) < 2:
        return {}
    limit = float(np.nanmin(ctx.limits["m_z"])) if len(ctx.limits["m_z"]) else np.inf
    # the lean: the datum's tilt, or every scan's reading combined (about σ/√K)
    tau = (
        sc.datum_tilt_rms_arcsec
        if model == "datum"
        else sc.tilt_sensor_rms_arcsec / np.sqrt(len(station_xyz))
    )
    per_m = float(datum_lean_mm(1.0, tau))
    if not np.isfinite(limit) or per_m <= 0:
        return {}
    radius = LEAN_SHARE * limit / per_m  # [m]: the lean's distance
    xy = station_xyz[:, :2]
    if room is not None and not force and st.height_control != "always":
        at_xy, left = room
        lean = per_m * np.hypot(*(np.asarray(at_xy) - xy[datum]).T)
        if (lean > left).sum() <= SHORT_SHARE * max(len(left), 1):
            return {}
    far = np.hypot(*(xy - xy[datum]).T)
    if far.max() <= radius:
        return {}
    at = np.asarray(target_xyz)[placed, :2]
    near = np.hypot(*(xy[:, None, :] - at[None, :, :]).transpose(2, 0, 1)) <= radius  # (K, T)
    short = far > radius  # the stations the datum's lean reaches too far
    chosen: list[int] = []
    while short.any() and len(chosen) < len(placed):  # the target serving the most of them
        k = int(np.argmax(near[short].sum(axis=0)))
        if not near[short, k].any():
            break
        chosen.append(k)
        short &= ~near[:, k]
    spread = np.hypot(*(at - xy[datum]).T)
    while len(chosen) < min(MIN_LEVELLED, len(placed)):  # both axes: the farthest others
        d = np.min([np.hypot(*(at - at[c]).T) for c in chosen], axis=0) if chosen else spread
        d[chosen] = -1.0
        chosen.append(int(np.argmax(d)))
    return {int(placed[k]): float(st.level_rms_mm) for k in chosen}
