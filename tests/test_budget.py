"""The same plan on any machine (issue 65): work, not the clock, decides a plan. A clock that
races (every look at it an hour later, as on a machine loaded far beyond its cores) or a
budget of a fraction of a second gives the same stations, targets and coverage as an idle
clock: the evaluation, the diagnosis, the registration network and its rounds, the merging
and the kit's visiting order are bounded by counts, and only the optimiser's search for a
smaller cover reads the clock — and says so when it stopped it."""

from __future__ import annotations

import hashlib
import json
import time

import numpy as np
import pandas as pd
import pytest
from sites import run_cli

from planner import PlanSettings, plan
from planner.synthetic import town, town_geojson


def _fast_clock(monkeypatch, factor: float) -> None:
    """time.monotonic running ``factor`` times as fast as it does: to the plan, a machine
    whose every step takes ``factor`` times as long (a load of about ``factor`` per core)."""
    real = time.monotonic
    t0 = real()
    monkeypatch.setattr(time, "monotonic", lambda: t0 + factor * (real() - t0))


def _racing_clock(monkeypatch, step_s: float = 3600.0) -> None:
    """time.monotonic running ``step_s`` further at every look: a machine so loaded that
    any budget is spent before the plan starts."""
    real = time.monotonic
    looks = [0]

    def racing() -> float:
        looks[0] += 1
        return real() + step_s * looks[0]

    monkeypatch.setattr(time, "monotonic", racing)


def _tables(p) -> list[str]:
    numbers = p.coverage.select_dtypes("number").round(9)
    return [
        p.stations.to_csv(),
        p.targets.to_csv(),
        p.links.to_csv(),
        numbers.to_csv(),
        p.coverage["meets"].to_csv(),
    ]


@pytest.mark.parametrize("site", [None, town(4, seed=3)], ids=["default site", "four buildings"])
def test_a_loaded_machine_gives_the_same_plan(monkeypatch, site):
    """Idle against a machine five times slower in every step (the clock five times as
    fast), given 3 s — which the loaded machine overruns (before, the evaluation and the
    registration rounds were cut short there): the same tables, number for number, nothing
    said to be cut short."""
    settings = PlanSettings(time_limit_s=3)
    calm = plan(site, settings=settings)
    _fast_clock(monkeypatch, 5.0)
    t0 = time.monotonic()
    loaded = plan(site, settings=settings)
    assert time.monotonic() - t0 > 3.0  # s, on the fast clock: the budget overrun
    assert calm.solver.cut_short == [] and loaded.solver.cut_short == []
    assert _tables(loaded) == _tables(calm)
    assert not any(m.startswith("Time budget") for m in loaded.messages)


def test_a_spent_budget_stops_only_the_optimisers_search(monkeypatch):
    """A budget spent before the plan starts (every look at the clock an hour later): every
    sample is still evaluated, every station tied as on an idle machine, the plan meets as
    much; only the optimiser's search for fewer stations may stop early, and the plan says
    that it may then differ from one made with more time."""
    calm = plan()
    _racing_clock(monkeypatch)
    hurried = plan()
    assert hurried.solver.samples_evaluated == hurried.solver.samples_total
    assert (hurried.coverage["reason"] != "not evaluated: the time budget ran out").all()
    assert hurried.network.tied.all() and calm.network.tied.all()
    assert int(hurried.scanned["meets"].sum()) == int(calm.scanned["meets"].sum())  # 936
    for what in hurried.solver.cut_short:
        assert what.startswith("the optimiser's search for fewer stations")
    if hurried.solver.cut_short:
        words = next(m for m in hurried.messages if m.startswith("Time budget"))
        assert "may differ from one made with more time" in words
        assert "Every sample was evaluated and the network built whole" in words


def _digest(folder, name: str) -> str:
    return hashlib.sha256((folder / name).read_bytes()).hexdigest()


@pytest.mark.booklet
def test_the_command_writes_the_same_files_with_a_budget_of_seconds(tmp_path):
    """``planner plan`` with --time-limit-s 3 (spent, on a loaded machine, by the command's
    start and imports) and with 120 s: byte-identical stations, targets, coverage, GeoJSON
    and booklet — the booklet whole (before, it left out the pages there was no time for,
    and the evaluation stopped part way). Only the optimiser's search reads the budget, in
    CPU seconds, which these covers do not reach."""
    site = tmp_path / "town.geojson"
    site.write_text(json.dumps(town_geojson(town(5, seed=2))))
    outs = []
    for budget in ("120", "3"):
        out = tmp_path / f"plan-{budget}"
        code, _stdout, err = run_cli(
            "plan", str(site), "--time-limit-s", budget, "--booklet", "--out", str(out), "-q"
        )
        assert code in (0, 1), err
        outs.append(out)
    for name in ("stations.csv", "targets.csv", "coverage.csv", "plan.geojson", "booklet.pdf"):
        assert _digest(outs[0], name) == _digest(outs[1], name), name
    cov = pd.read_csv(outs[1] / "coverage.csv", keep_default_na=False)
    assert not (cov["reason"] == "not evaluated: the time budget ran out").any()
    assert np.isin(cov["meets"].astype(str), ["True", "False"]).all()


def test_a_report_is_of_the_plan_written(tmp_path):
    """``planner report --plan DIR`` reports the plan in DIR: the plan made again from the
    same options is that plan (the same on any machine), so it is rendered; from other
    options it is refused with exit 2, naming the stations that differ — before, a report
    re-planned silently and could show 21 stations where the plan had 27."""
    out = tmp_path / "plan"
    code, _stdout, err = run_cli("plan", "--out", str(out), "-q")
    assert code == 0, err
    report = tmp_path / "report.html"
    code, _stdout, err = run_cli(
        "report", "--grid-m", "3", "--plan", str(out), "--out", str(report), "-q"
    )
    assert code == 2 and "is not the plan in" in err and "Traceback" not in err
    assert not report.exists()
    code, _stdout, err = run_cli("report", "--plan", str(out), "--out", str(report), "-q")
    assert code == 0, err
    html = report.read_text()
    ids = pd.read_csv(out / "stations.csv", dtype={"station_id": str})["station_id"]
    assert all(sid in html for sid in ids)
