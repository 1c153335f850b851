"""Targets within the kit (planner.pipeline.engine.kit): the crew's inventory is a
constraint — targets leap-frog, each standing over its links' window of the visiting order
with only those sightings adjusted, and where that is not enough the network is a
leap-frogging traverse; the plan says what it cost, or what the kit lacks."""

from __future__ import annotations

import copy

import numpy as np
import pytest

from planner.pipeline.engine.kit import leapfrogged, over_kit
from planner.pipeline.engine.planning import plan
from planner.scanner import Scanner
from planner.siteio import default_site


@pytest.fixture(scope="module")
def p50():
    return plan(default_site(), Scanner.from_name("leica-p50"))


def test_a_plan_within_the_kit_never_stands_more_than_it_owns(p50):
    """The P50 on the default site: planned with every target standing from its first sight
    to its last, 7 or more 200 mm spheres stood at once against the kit's six; the plan
    now leap-frogs them along a traverse, never more than six standing at any stop of the
    route, every sample still met, and says so."""
    kit = p50.route.kit.set_index("item")
    assert kit.loc["sphere-200", "most_at_once"] <= kit.loc["sphere-200", "owned"] == 6
    assert (p50.route.table["targets_standing"] <= 6 + kit["owned"].drop("sphere-200").sum()).all()
    assert p50.meets_all
    words = next(m for m in p50.messages if m.startswith("Kit: the sphere-200 leap-frog"))
    assert "936 samples met, as with every target standing" in words
    assert not over_kit(p50)


def test_the_leapfrogged_sightings_lie_within_each_targets_window(p50):
    """Every sighting the adjustment counts of a leap-frogged target is from a station
    scanned between the first and the last scan of the links that use it."""
    net = p50.network
    position = {s: n for n, s in enumerate(p50.route.table["station_id"])}
    visit = [position[s] for s in p50.network_ids()]
    users: dict[int, set[int]] = {}
    for lk in net.links:
        for t in lk.targets:
            users.setdefault(t, set()).update({lk.parent, lk.child})
    for j, t in net.centre_rms:
        if t in users:
            lo, hi = min(visit[s] for s in users[t]), max(visit[s] for s in users[t])
            assert lo <= visit[j] <= hi
    # the rule itself: a target seen from outside its links' window loses that sighting
    items = dict.fromkeys({t for _, t in net.centre_rms}, "sphere-200")
    far = {(j, t): 1.0 for j in range(len(visit)) for t in users}
    every = copy.copy(net)
    every.centre_rms = far
    kept = leapfrogged(every, items, {"sphere-200"}, visit)
    assert 0 < len(kept) < len(far)


def test_where_the_kit_cannot_serve_the_plan_says_what_it_would_take(default_plan):
    """The default plan's hub stands 20 spheres at S04: no leap-frogging layout fits six
    and meets as many samples; the plan keeps its network and says what a traverse would
    cost, and the field time what to bring."""
    words = next(m for m in default_plan.messages if m.startswith("Kit: no layout"))
    assert "would still stand at once" in words or "would be met instead of 936" in words
    assert "bring" in default_plan.summary()
    assert np.isfinite(default_plan.route.kit["most_at_once"]).all()
