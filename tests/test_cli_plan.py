"""``planner plan``: the file contract, exit codes 0/1/2, atomic writes."""

from __future__ import annotations

import json

import pandas as pd
import pytest
from sites import PAPER_5MM
from sites import run_cli as run

from planner.app.cli import main
from planner.pipeline.inputs.schema import COVERAGE_COLUMNS, STATION_COLUMNS, TARGET_COLUMNS

FAST = ["--sample-spacing-m", "3", "--sample-height-step-m", "3"]


def test_default_site_plan_meets_and_writes_the_contract(tmp_path):
    out = tmp_path / "plan"
    code, stdout, _ = run(
        "plan",
        *PAPER_5MM,
        "--out",
        str(out),
        "-q",
    )
    assert code == 0, stdout
    assert "(optimal; objective" in stdout and "gap 0.0 %" in stdout
    stations = pd.read_csv(out / "stations.csv")
    targets = pd.read_csv(out / "targets.csv")
    coverage = pd.read_csv(out / "coverage.csv")
    assert list(stations.columns) == STATION_COLUMNS
    assert list(targets.columns) == TARGET_COLUMNS
    assert list(coverage.columns) == COVERAGE_COLUMNS
    assert coverage["meets"].all()
    assert (stations["instrument_height_m"] == 1.5).all()
    # coordinates are written back in the site's CRS (ETRS89 / UTM 32N here)
    assert (
        stations["x"].between(690_900, 691_100).all()
        and stations["y"].between(5_334_900, 5_335_100).all()
    )
    assert set(coverage["station_id"]) <= set(stations["station_id"])
    for ids in targets["station_ids"]:
        assert set(ids.split(";")) <= set(stations["station_id"]) and len(ids.split(";")) >= 2
    gj = json.loads((out / "plan.geojson").read_text())
    layers = {f["properties"]["layer"] for f in gj["features"]}
    assert {"building", "facade", "station", "target", "link", "obstacle"} <= layers
    assert gj["crs"]["properties"]["name"].endswith("25832")


def test_wall_just_above_a_lower_neighbours_roof_is_unseen_from_the_ground(tmp_path):
    """With 3 m rows the east wall has samples at z = 7.5 m, just above the 7 m annex roof
    (12 m deep): from 1.5 m they would be seen only from ~144 m away — out of reach."""
    code, stdout, _ = run(
        "plan",
        *PAPER_5MM,
        "--out",
        str(tmp_path),
        "-q",
        *FAST,
    )
    assert code == 1
    cov = pd.read_csv(tmp_path / "coverage.csv")
    unmet = cov[~cov["meets"]]
    assert set(unmet["facade_id"]) == {"main-f09"} and set(unmet["z"]) == {7.5}
    assert set(unmet["elevated_station"]) == {"roof of annex"}
    assert "no ground station sees it over the roof of 'annex'" in stdout


def test_unmet_samples_exit_1_and_are_listed(tmp_path):
    code, stdout, _ = run(
        "plan",
        "--scanner",
        "leica-4mm-60urad",
        "--max-xy-mm",
        "3,3.5",
        "--max-z-mm",
        "2",
        "--out",
        str(tmp_path),
        "-q",
        *FAST,
    )
    assert code == 1
    assert "Unmet samples" in stdout and "best achievable m_z" in stdout
    cov = pd.read_csv(tmp_path / "coverage.csv")
    assert (~cov["meets"]).sum() > 0
    gj = json.loads((tmp_path / "plan.geojson").read_text())
    n_unmet = sum(f["properties"]["layer"] == "unmet" for f in gj["features"])
    assert n_unmet == (~cov["meets"]).sum()


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        (["--buildings", "nope"], "no building with id 'nope'"),
        (["--max-gamma-deg", "95"], "max_gamma_deg must be > 0 and <= 89"),
        (["--grid-m", "-1"], "grid_m must be >= 0.25"),
        (["--scanner", "unknown"], "Unknown scanner"),
        (
            ["--scanner", "leica-rtc360", "--preset", "ultra"],
            "no preset 'ultra'; its presets: low, medium, high",
        ),
        (["--drawing-scale", "0"], "drawing_scale must be >= 1"),
    ],
)
def test_bad_input_exits_2_and_writes_nothing(tmp_path, extra, message):
    out = tmp_path / "never"
    argv = [
        "plan",
        *PAPER_5MM,
        "--out",
        str(out),
        "-q",
        *extra,
    ]
    code, _, err = run(*argv)
    assert code == 2
    assert message in err and "Traceback" not in err
    assert not out.exists()


def test_bad_site_file_exits_2(tmp_path):
    bad = tmp_path / "site.geojson"
    bad.write_text("not json at all")
    code, _, err = run(
        "plan",
        str(bad),
        *PAPER_5MM,
        "--out",
        str(tmp_path / "o"),
    )
    assert code == 2 and "content looks like CSV" in err
    assert not (tmp_path / "o").exists()


def test_site_file_with_height_and_selection(tmp_path):
    e, n = 600_000.0, 5_500_000.0
    feats = []
    for i in range(6):
        x = e + 30 * i
        feats.append(
            {
                "type": "Feature",
                "id": f"h{i}",
                "properties": {},
                "geometry": {
                    "type": "Polygon",
                    "coordinates": [[[x, n], [x + 20, n], [x + 20, n + 12], [x, n + 12], [x, n]]],
                },
            }
        )
    site = tmp_path / "street.geojson"
    site.write_text(json.dumps({"type": "FeatureCollection", "features": feats}))
    code, stdout, _ = run(
        "plan",
        str(site),
        "--height",
        "9",
        "--buildings",
        "h2",
        "--scanner",
        "leica-hds3000",
        "--max-xy-mm",
        "6",
        "--max-z-mm",
        "6",
        "--out",
        str(tmp_path / "o"),
        "-q",
        *FAST,
    )
    assert code == 0, stdout
    assert "buildings without a height given the default height 9 m" in stdout
    cov = pd.read_csv(tmp_path / "o" / "coverage.csv")
    assert set(cov["building_id"]) == {"h2"}


def test_main_job_serves_the_dashboard_on_loopback(monkeypatch):
    """``planner`` alone serves the station planner (the serving itself: test_serve.py)."""
    import planner.app.serve as serve_module

    seen = {}

    def fake_serve(notebook, port, **kw):
        seen.update(notebook=notebook, port=port, **kw)
        return 0

    monkeypatch.setattr(serve_module, "serve", fake_serve)
    assert main([]) == 0
    assert seen["notebook"].name == "station_planner.ipynb" and seen["port"] == 8866
    cmd, env = serve_module.voila_command(seen["notebook"], 8866)
    assert cmd[1:3] == ["-m", "planner.app.voila_server"] and cmd[3].endswith(".ipynb")
    assert "--Voila.ip=127.0.0.1" in cmd and "--template=planner-offline" in cmd
    assert "--Voila.port_retries=0" in cmd
    assert any(a.startswith("--MappingKernelManager.cull_idle_timeout=") for a in cmd)
    assert "jupyter" in env["JUPYTER_PATH"]


def test_the_registration_processing_is_chosen_on_the_command_line(tmp_path):
    """``--registration-processing pairwise``: the promise assumes each scan registered to
    the one before it along the links, and the summary says so; a wrong value is refused
    (exit 2) naming the valid ones."""
    code, _, err = run(
        "plan",
        *PAPER_5MM,
        "--registration-processing",
        "pairwise",
        "--out",
        str(tmp_path / "p"),
        "-q",
        *FAST,
    )
    assert code in (0, 1), err
    summary = (tmp_path / "p" / "summary.txt").read_text()
    assert "It assumes each scan registered on its own to the one before it" in summary
    code, _, err = run("plan", *PAPER_5MM, "--registration-processing", "chain", "--out", "x")
    assert code == 2 and "adjustment" in err and "pairwise" in err


def test_the_scanners_levelling_is_given_on_the_command_line(tmp_path):
    """``--levelling-rms-arcsec 3``: the default scanner (no compensator) planned levelled,
    each scan registered with 4 parameters; a negative figure is refused (exit 2) with its
    range and unit."""
    code, _, err = run(
        "plan",
        *PAPER_5MM,
        "--levelling-rms-arcsec",
        "3",
        "--out",
        str(tmp_path / "p"),
        "-q",
        *FAST,
    )
    assert code in (0, 1), err
    summary = (tmp_path / "p" / "summary.txt").read_text()
    assert "Registration model: 4 parameters per scan" in summary
    code, _, err = run("plan", "--levelling-rms-arcsec", "-1", "--out", str(tmp_path / "x"))
    assert code == 2 and "arc-seconds" in err and not (tmp_path / "x").exists()
