"""A requirement too strict gives the plan that comes closest (best effort) and says which
quantity fails, where, by how much, and what would meet it (planner.pipeline.engine.explain)."""

import re

import pytest

from planner.pipeline.engine.explain import explain_unmet, relaxation_text, suggestions
from planner.pipeline.engine.planning import plan
from planner.pipeline.inputs.requirements import Requirements


@pytest.fixture(scope="module")
def strict():
    # the default site's best achievable m_z at its upper storeys is about 2.6-2.9 mm
    return plan(requirements=Requirements(max_xy_mm=5, max_z_mm=2.0))


def test_too_strict_gives_stations_not_zero(strict):
    assert len(strict.stations) > 0
    assert len(strict.unmet) > 0
    assert any(m.startswith("Best effort:") for m in strict.messages)
    assert (strict.stations["purpose"] == "best-effort").any()
    # every unmet sample within the ground's reach is seen by a station and carries its
    # predicted values; none is spent on those above the annex's roof
    ground = strict.unmet[strict.unmet["elevated_station"] == ""]
    assert (ground["station_id"] != "").all()
    above = strict.unmet[strict.unmet["elevated_station"] != ""]
    assert set(above["elevated_station"]) == {"roof of annex"}


def test_the_failing_quantity_is_named_with_its_limit_and_worst_value(strict):
    t = explain_unmet(strict)
    assert t.iloc[0]["quantity"] == "m_z"
    row = t.iloc[0]
    assert row["limit"] == pytest.approx(2.0)  # mm
    ground = strict.unmet[strict.unmet["elevated_station"] == ""]
    assert row["samples"] == int((ground["m_z_mm"] > 2.0).sum())
    assert row["worst"] == pytest.approx(ground["m_z_mm"].max(), abs=0.01)  # mm
    assert "needs an elevated station" in set(t["quantity"])


def test_the_relaxation_is_what_the_plan_meets(strict):
    text = relaxation_text(strict)
    got = {q: float(v) for q, v in re.findall(r"(m_[xyz]) ≤ ([\d.]+) mm", text)}
    seen = strict.scanned[strict.scanned["station_id"] != ""]
    for q, v in got.items():
        worst = seen[f"{q}_mm"].max()
        assert worst <= v + 1e-9 and v - worst < 0.1 + 1e-9  # mm: rounded up to 0.1 mm
    assert "(asked 2)" in text


def test_suggestions_lead_somewhere(strict):
    s = suggestions(strict)
    assert any("station higher up" in x for x in s)
    assert any(x.startswith("the smallest relaxation") for x in s)


def test_a_reason_for_conflicting_requirements_names_each_quantity():
    p = plan(requirements=Requirements(max_xy_mm=3.0, max_z_mm=2.5))
    both = p.unmet[p.unmet["reason"].str.startswith("no single station")]
    assert len(both)
    assert both["reason"].str.contains(r"m_y [\d.]+ mm \(limit 3\)").all()
