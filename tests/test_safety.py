"""Safe under faults, bad input and hostile content.

* A plan folder always holds one complete plan — the old or the new — whatever happens at
  any write point (SIGKILL, SIGTERM, a full disk), and the user's own files survive.
* Bad input of every kind is exit code 2 with a message naming what and where; nothing is
  written; never a traceback. A bug is exit code 3 with the log file named.
* Work is estimated and implausible sites refused before any work.
* User-supplied strings never become live markup or spreadsheet formulas.
"""

from __future__ import annotations

import datetime
import json
import os
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from sites import run_cli as run

import planner
from planner.atomic import FAULT_ENV, write_text_atomic
from planner.errors import InputError
from planner.pipeline.documents.export import OWNED_FILES

SQUARE = {
    "type": "FeatureCollection",
    "features": [
        {
            "type": "Feature",
            "properties": {"id": "hut", "height": 6},
            "geometry": {
                "type": "Polygon",
                "coordinates": [
                    [
                        [500000, 5400000],
                        [500012, 5400000],
                        [500012, 5400010],
                        [500000, 5400010],
                        [500000, 5400000],
                    ]
                ],
            },
        }
    ],
}
FAST = [
    "--sample-spacing-m",
    "4",
    "--sample-height-step-m",
    "3",
    "--grid-m",
    "3",
    "--no-booklet",
    "-q",
]  # the booklet is tested in test_fieldwork


def _cli(
    *args: str, env: dict | None = None, cwd: Path | None = None
) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "planner", *args],
        capture_output=True,
        text=True,
        env={**os.environ, **(env or {})},
        cwd=cwd,
        timeout=300,
    )


def _plan_files(folder: Path) -> dict[str, bytes]:
    """The plan's files by name; the DXF as its sorted lines (ezdxf orders a few objects of
    its OBJECTS section by hash, which differs between processes: same content, other order)."""
    out = {p.name: p.read_bytes() for p in folder.iterdir() if p.name in OWNED_FILES}
    if "plan.dxf" in out:
        out["plan.dxf"] = b"\n".join(sorted(out["plan.dxf"].splitlines()))
    return out


def _leftovers(parent: Path) -> list[str]:
    return sorted(
        p.name for p in parent.rglob("*") if ".tls-planner-" in p.name or ".tmp-" in p.name
    )


@pytest.fixture(scope="module")
def two_plans(tmp_path_factory):
    """The files of an old plan and of a new one (a stricter requirement), made once by the
    command line; the tests below exchange them at every write point."""
    base = tmp_path_factory.mktemp("plans")
    site = base / "hut.geojson"
    site.write_text(json.dumps(SQUARE))
    new_args = ["plan", str(site), "--max-xy-mm", "3", *FAST]
    assert _cli("plan", str(site), "--out", str(base / "old"), *FAST).returncode == 0
    assert _cli(*new_args, "--out", str(base / "new")).returncode in (0, 1)
    old, new = _plan_files(base / "old"), _plan_files(base / "new")
    assert old != new and set(old) == set(new)
    return base, old, new, new_args


@pytest.fixture()
def old_and_new(tmp_path, two_plans):
    """A plan folder holding the old plan and files of the user's own; the new plan's
    folder; their contents."""
    base, old, new, new_args = two_plans
    out = tmp_path / "plan"
    shutil.copytree(base / "old", out)
    (out / "notes.txt").write_text("my notes")
    (out / "photos").mkdir()
    (out / "photos" / "north.jpg").write_bytes(b"\xff\xd8 jpeg")
    return out, base / "new", old, new, new_args


#: Writes the plan files of folder argv[1] into folder argv[2] as the command line does
#: (:func:`planner.atomic.replace_folder_files`), SIGTERM ending it as the command line's
#: handler does: a small process, so every write point is cheap to reach.
_SWITCH = f"""
import signal, sys
from pathlib import Path
from planner.atomic import replace_folder_files
signal.signal(signal.SIGTERM, lambda s, _f: sys.exit(128 + s))
data = {{p.name: p.read_bytes() for p in Path(sys.argv[1]).iterdir()}}
replace_folder_files(sys.argv[2], data, owned={tuple(OWNED_FILES)!r})
"""


def _switch(new_dir: Path, out: Path, fault: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-c", _SWITCH, str(new_dir), str(out)],
        capture_output=True,
        text=True,
        env={**os.environ, FAULT_ENV: fault},
        timeout=60,
    )


def _user_files_intact(out: Path) -> None:
    assert (out / "notes.txt").read_text() == "my notes"
    assert (out / "photos" / "north.jpg").read_bytes() == b"\xff\xd8 jpeg"


def _put_back(out: Path, old: dict[str, bytes]) -> None:
    for name in OWNED_FILES:
        (out / name).unlink(missing_ok=True)
    for name, data in old.items():
        (out / name).write_bytes(data)


def test_kill_at_every_write_point_leaves_the_old_plan_or_the_new(old_and_new, tmp_path):
    """Fault injection: SIGKILL at the 1st, 2nd, … write point of the folder switch until
    one gets through; after every kill the folder is all old or all new (and the next write
    tidies what the kill left)."""
    out, new_dir, old, new, _ = old_and_new
    tally = {"old": 0, "new": 0}
    for n in range(1, 60):
        done = _switch(new_dir, out, str(n))
        files = _plan_files(out)
        _user_files_intact(out)
        if done.returncode != -signal.SIGKILL:
            assert done.returncode == 0, done.stderr
            assert files == new
            break
        assert files in (old, new), f"a mix after a kill at write point {n}"
        tally["old" if files == old else "new"] += 1
        if files == new:  # the old plan back for the next point (a clean save)
            _put_back(out, old)
    else:
        pytest.fail("the switch never completed")
    assert tally["old"] >= 5 and tally["new"] >= 1, tally  # the switch really happens in one step
    assert _leftovers(tmp_path) == []  # the last run recovered what the kills left


def test_full_disk_at_every_write_point_is_an_error_and_the_old_plan_stays(old_and_new, tmp_path):
    out, new_dir, old, new, _ = old_and_new
    failures = 0
    for n in range(1, 60):
        done = _switch(new_dir, out, f"{n}:ENOSPC")
        if done.returncode == 0:  # past the switch: tidying up never fails the save
            assert _plan_files(out) == new
            _user_files_intact(out)
            break
        failures += 1
        assert "No space left on device" in done.stderr
        assert _plan_files(out) == old
        _user_files_intact(out)
        assert _leftovers(tmp_path) == []
    assert failures >= 8


def test_sigterm_at_every_write_point_before_the_switch_stops_cleanly(old_and_new, tmp_path):
    out, new_dir, old, _, _ = old_and_new
    stopped = 0
    for n in range(1, 60):
        done = _switch(new_dir, out, f"{n}:TERM")
        if done.returncode == 0:
            break
        assert done.returncode == 128 + signal.SIGTERM, done.stderr
        files = _plan_files(out)
        _user_files_intact(out)
        assert _leftovers(tmp_path) == []
        if files != old:  # stopped after the switch: the new plan, whole
            _put_back(out, old)
        stopped += 1
    assert stopped >= 5


@pytest.mark.parametrize(
    ("fault", "exit_code"),
    [("6", -signal.SIGKILL), ("6:TERM", 128 + signal.SIGTERM), ("6:ENOSPC", 2)],
    ids=["kill", "sigterm", "full disk"],
)
def test_the_command_line_stopped_at_a_write_point(old_and_new, tmp_path, fault, exit_code):
    """End to end: ``planner plan`` stopped in the middle of writing its folder exits as
    it should, says why without a traceback, and leaves the old plan and the user's files;
    a stop it handles leaves no temporary, a kill's are tidied by the next write."""
    out, _, old, new, args = old_and_new
    done = _cli(*args, "--out", str(out), env={FAULT_ENV: fault})
    assert done.returncode == exit_code, done.stderr
    assert "Traceback" not in done.stderr
    assert _plan_files(out) == old
    _user_files_intact(out)
    if exit_code == 2:
        assert "No space left on device" in done.stderr
    if exit_code != -signal.SIGKILL:
        assert _leftovers(tmp_path) == []
        return
    done = _cli(*args, "--out", str(out))
    assert done.returncode in (0, 1)
    assert _plan_files(out) == new
    _user_files_intact(out)
    assert _leftovers(tmp_path) == []


def test_single_files_are_atomic(tmp_path, monkeypatch):
    """The report file and installed profiles: all or nothing, no temporary left."""
    target = tmp_path / "report.html"
    target.write_text("old")
    for n in (1, 2, 3):
        monkeypatch.setenv(FAULT_ENV, f"{n}:ENOSPC")
        monkeypatch.setattr(planner.atomic, "_points", 0)
        with pytest.raises(OSError):
            write_text_atomic(target, "new")
        assert target.read_text() == "old"
        assert [p.name for p in tmp_path.iterdir()] == ["report.html"]
    monkeypatch.delenv(FAULT_ENV)
    write_text_atomic(target, "new")
    assert target.read_text() == "new"
    killed = _cli_python(
        f"import os; os.environ[{FAULT_ENV!r}] = '3'\n"
        "from planner.atomic import write_text_atomic\n"
        f"write_text_atomic({str(target)!r}, 'newer')"
    )
    assert killed.returncode == -signal.SIGKILL
    assert target.read_text() == "new"
    write_text_atomic(target, "newest")  # removes the killed writer's temporary
    assert [p.name for p in tmp_path.iterdir()] == ["report.html"]


def _cli_python(code: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)


# -- bad input: exit 2, a message, nothing written -----------------------------------------
def _feature(coords, **props):
    return {
        "type": "Feature",
        "properties": props,
        "geometry": {"type": "Polygon", "coordinates": [coords]},
    }


def _square(x0=500000.0, y0=5400000.0, s=20.0):
    return [[x0, y0], [x0 + s, y0], [x0 + s, y0 + s], [x0, y0 + s], [x0, y0]]


def _fc(*features, **extra):
    return json.dumps({"type": "FeatureCollection", "features": list(features), **extra})


#: (name, file name, content, extra arguments, what the message must say)
SITE_ATTACKS = [
    (
        "coordinates of 1e300",
        "a.geojson",
        _fc(
            _feature([[1e300, 1e300], [1e300 + 1, 1e300], [1e300, 2e300], [1e300, 1e300]], height=9)
        ),
        [],
        "beyond any projected CRS",
    ),
    (
        "properties is a list",
        "a.geojson",
        '{"type":"FeatureCollection","features":[{"type":"Feature","properties":[1,2],'
        '"geometry":{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,0]]]}}]}',
        [],
        "'properties' of type list",
    ),
    (
        "100 000-deep nested JSON",
        "a.geojson",
        "[" * 100_000 + "]" * 100_000,
        [],
        "nested too deeply",
    ),
    (
        "a NaN coordinate in a CSV",
        "a.csv",
        "id,x,y,height\nA,500000,5400000,9\nA,nan,5400000,9\nA,500010,5400010,9\n",
        [],
        "must be finite numbers",
    ),
    ("height true", "a.geojson", _fc(_feature(_square(), height=True)), [], "height True"),
    (
        "a 1e-9 m building",
        "a.geojson",
        _fc(_feature(_square(), height=1e-9)),
        [],
        "lower than a building",
    ),
    (
        "a 1e4 m building",
        "a.geojson",
        _fc(_feature(_square(), height=1e4)),
        [],
        "higher than any building",
    ),
    (
        "a 1e9 m building",
        "a.geojson",
        _fc(_feature(_square(), height=1e9)),
        [],
        "higher than any building",
    ),
    (
        "a 5 km footprint",
        "a.geojson",
        _fc(_feature(_square(s=5000.0), height=10)),
        [],
        "larger than a real building",
    ),
    (
        "heights differing per vertex",
        "a.csv",
        "id,x,y,height\nA,500000,5400000,10\nA,500020,5400000,12\nA,500020,5400020,10\n",
        [],
        "one feature has one height",
    ),
    (
        "a CRS84 label on metres",
        "a.geojson",
        _fc(
            _feature(_square(), height=10),
            crs={"type": "name", "properties": {"name": "urn:ogc:def:crs:OGC:1.3:CRS84"}},
        ),
        [],
        "longitude/latitude",
    ),
    ("an empty file", "a.geojson", "", [], "is empty"),
    ("binary content", "a.csv", "\x00\x01\x02", [], "binary"),
    (
        "a bow-tie",
        "a.geojson",
        _fc(
            _feature(
                [
                    [500000, 5400000],
                    [500010, 5400010],
                    [500010, 5400000],
                    [500000, 5400010],
                    [500000, 5400000],
                ],
                height=9,
            )
        ),
        [],
        "Self-intersection",
    ),
    (
        "a point, not a polygon",
        "a.geojson",
        json.dumps(
            {
                "type": "Feature",
                "properties": {"height": 3},
                "geometry": {"type": "Point", "coordinates": [500000, 5400000]},
            }
        ),
        [],
        "must be a Polygon",
    ),
    ("a JSON list", "a.geojson", "[1, 2, 3]", [], "not GeoJSON"),
    ("GeoJSON of unknown type", "a.geojson", '{"type": "Circle"}', [], "unknown GeoJSON type"),
    ("a WKT line that is not WKT", "a.wkt", "POLYGON ((0 0, 1 1", [], "not WKT"),
    ("CSV without x", "a.csv", "id,east,y\nA,1,2\n", [], "missing x"),
    (
        "a WKT site file in degrees without --crs",
        "a.wkt",
        "POLYGON ((9.1 48.1, 9.1001 48.1, 9.1001 48.1001, 9.1 48.1));height=9\n",
        [],
        "longitude/latitude",
    ),
    (
        "sample spacing 1 cm",
        "a.geojson",
        _fc(_feature(_square(), height=10)),
        ["--sample-spacing-m", "0.01", "--sample-height-step-m", "0.01"],
        "more than",
    ),
    (
        "a grid of 1 cm",
        "a.geojson",
        _fc(_feature(_square(), height=10)),
        ["--grid-m", "0.01"],
        "grid_m must be >= 0.25",
    ),
]


@pytest.mark.parametrize(
    ("content", "name", "extra", "message"),
    [pytest.param(c, n, e, m, id=i) for i, n, c, e, m in SITE_ATTACKS],
)
def test_bad_site_input_is_exit_2_with_a_message_and_nothing_written(
    tmp_path, monkeypatch, content, name, extra, message
):
    """Refused before any work: no Dask cluster is started for it (facades of too many
    samples send ``--district auto`` to district mode; each block's are counted first)."""
    import planner.pipeline.district.schedule as district

    def no_cluster(*_a, **_k):
        raise AssertionError("a Dask cluster was started for an input to refuse")

    monkeypatch.setattr(district, "local_cluster", no_cluster)
    path = tmp_path / name
    path.write_text(content) if isinstance(content, str) else path.write_bytes(content)
    out = tmp_path / "out"
    code, _, err = run("plan", str(path), "--out", str(out), *extra)
    assert code == 2, err
    assert message in err, err
    assert "Traceback" not in err and "internal error" not in err
    assert not out.exists()


SCANNER_ATTACKS = [
    ("the table is a list", "scanner = [1, 2]\n", "holds no [[scanner]] tables"),
    (
        "a list as a figure",
        '[[scanner]]\nname="x"\nrange_rms_mm=2\nangle_rms_arcsec=[1,2]\n',
        "must be a number",
    ),
    (
        "a misspelt key",
        '[[scanner]]\nname="x"\nrange_rms_mm=2\nangle_rms_arcsec=9\nmax_rang_m=50\n',
        "did you mean 'max_range_m'",
    ),
    ("not TOML", "this is not toml = = =", "is not valid TOML"),
    (
        "a negative ranging RMS",
        '[[scanner]]\nname="x"\nrange_rms_mm=-2\nangle_rms_arcsec=9\n',
        "range_rms_mm must be >= 0.01",
    ),
    ("no angles", '[[scanner]]\nname="x"\nrange_rms_mm=2\n', "lacks angle_rms_arcsec"),
]


@pytest.mark.parametrize(
    ("text", "message"), [pytest.param(t, m, id=i) for i, t, m in SCANNER_ATTACKS]
)
def test_bad_scanner_profiles_are_exit_2(tmp_path, text, message):
    profile = tmp_path / "scanner.toml"
    profile.write_text(text)
    out = tmp_path / "out"
    code, _, err = run("plan", "--scanner", str(profile), "--out", str(out), "-q")
    assert code == 2 and message in err, err
    assert not out.exists()


CALIBRATION_ATTACKS = [
    ("empty", "", "is empty"),
    ("binary", "\x00\x01garbage", "binary"),
    ("header only", "measured_m,reference_m\n", "has no rows"),
    ("text values", "measured_m,reference_m\n5,abc\n10,10\n20,20\n", "non-numeric"),
    (
        "a 1e12 blunder",
        "measured_m,reference_m\n5,5.001\n10,10.002\n20,20.001\n60,1e12\n",
        "not the same distance",
    ),
]


@pytest.mark.parametrize(
    ("text", "message"), [pytest.param(t, m, id=i) for i, t, m in CALIBRATION_ATTACKS]
)
def test_bad_calibration_files_are_exit_2(tmp_path, text, message):
    path = tmp_path / "baseline.csv"
    path.write_text(text)
    code, _, err = run(
        "calibrate", "baseline", str(path), "--profile-out", str(tmp_path / "p.toml")
    )
    assert code == 2 and message in err, err
    assert not (tmp_path / "p.toml").exists()


def test_baseline_outliers_are_flagged(tmp_path):
    path = tmp_path / "baseline.csv"
    rows = [(5, 5.001), (10, 10.002), (20, 20.001), (30, 30.0025), (40, 40.002), (50, 50.0015)]
    path.write_text(
        "measured_m,reference_m\n" + "".join(f"{a},{b}\n" for a, b in rows) + "45,45.03\n"
    )
    code, out, err = run("calibrate", "baseline", str(path))
    assert code == 0, err
    assert "row 8 (measured 45 m) is an outlier" in out


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["report", "--out", "{tmp}/missing/r.html"], "does not exist"),
        (["report", "--out", "{tmp}"], "must name an .html file"),
        (["report", "--out", "{tmp}/dir.html"], "is a folder"),
        (["plan", "--out", "{tmp}/x", "--scanner", "no-such-scanner"], "Unknown scanner"),
        (["plan", "--out", "{tmp}/x", "--max-z-mm", "-1"], "max_z_mm must be >= 0.01"),
        (["plan", "--out", "{tmp}/x", "--max-gamma-deg", "95"], "max_gamma_deg must be > 0 and"),
        (["plan", "--out", "{tmp}/x", "--buildings", "nope"], "no building with id"),
        (["plan", "--out", "{tmp}/x", "--inventory", "{tmp}/inv.txt"], "inventory line 1"),
        (["plan", "--out", "{tmp}/x", "--max-site-size-m", "5"], "km across"),
    ],
)
def test_bad_outputs_and_options_are_exit_2(tmp_path, args, message):
    (tmp_path / "dir.html").mkdir()
    (tmp_path / "file.txt").write_text("a file")
    (tmp_path / "inv.txt").write_text("sphere, 200\n")
    argv = [a.format(tmp=tmp_path) for a in args]
    code, _, err = run(*argv, "-q")
    assert code == 2 and message in err, err
    assert not (tmp_path / "missing").exists() and not (tmp_path / "x").exists()


@pytest.mark.parametrize("command", ["plan", "figures"])
@pytest.mark.parametrize(
    ("out", "message"),
    [
        ("", "the output folder is empty"),
        ("{tmp}/file.txt", "exists and is not a folder"),
        ("{tmp}/file.txt/plan", "file.txt' is not a folder"),
        ("{tmp}/loop/plan", "cannot be followed"),  # a symbolic link to itself
    ],
)
def test_a_bad_output_folder_is_refused_before_the_plan(
    monkeypatch, tmp_path, command, out, message
):
    """A plan can take minutes: an --out that cannot be written is said at once."""
    import planner.app.figures as figures
    import planner.pipeline.engine.planning as planning

    def planned(*_a, **_k):
        raise AssertionError("planned before the output folder was checked")

    monkeypatch.setattr(planning, "plan", planned)
    monkeypatch.setattr(figures, "plan", planned)
    (tmp_path / "file.txt").write_text("a file")
    (tmp_path / "loop").symlink_to("loop")
    code, _, err = run(command, "--out", out.format(tmp=tmp_path), *(["-q"] * (command == "plan")))
    assert code == 2 and message in err, err
    assert (tmp_path / "file.txt").read_text() == "a file"


def test_an_internal_error_is_exit_3_with_a_log(monkeypatch, tmp_path):
    """A bug is not "bad input" and not "some samples unmet": its own code, one line, a log."""
    import planner.pipeline.engine.planning as planning

    def broken(*_a, **_k):
        raise ZeroDivisionError("a bug")

    monkeypatch.setattr(planning, "build_facades", broken)
    code, _, err = run("plan", "--out", str(tmp_path / "x"), "-q")
    assert code == 3
    assert "internal error (ZeroDivisionError: a bug)" in err and "Traceback" not in err
    log = Path(err.split("details in ")[1].strip())
    assert "Traceback" in log.read_text() and "ZeroDivisionError" in log.read_text()
    log.unlink()


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: planner.plan("site.geojson"), "site must be a planner.Site"),
        (lambda: planner.plan(None, None, {"max_z_mm": 5}), "requirements must be"),
        (lambda: planner.plan(None, None, None, [1]), "settings must be"),
        (lambda: planner.plan(None, 42), "scanner must be a Scanner"),
        (lambda: planner.Site(buildings="abc"), "must be a list of Building"),
        (
            lambda: planner.Site([planner.Building("a", [[0, 0], [1, 0], [1, 1]], 10)]),
            "shapely Polygon is expected",
        ),
        (lambda: planner.Site(["not a building"]), "must hold Building objects"),
        (lambda: planner.Requirements(max_z_mm="5"), "max_z_mm must be a number"),
        (lambda: planner.Requirements(max_xy_mm=(1, 2, 3)), "one number or a pair"),
        (lambda: planner.Requirements(stations_per_sample=2.5), "whole number"),
        (lambda: planner.PlanSettings(method="fast"), "method must be one of"),
        (lambda: planner.read_site(42), "named by a path"),
    ],
)
def test_the_python_api_refuses_wrong_types_with_input_error(call, message):
    with pytest.raises(InputError, match=message):
        call()


# -- scanner profiles ---------------------------------------------------------------------
def test_profile_folder_clashes_and_broken_files_are_skipped_with_a_warning(tmp_path, monkeypatch):
    from planner.scanner import Scanner, user_profiles

    folder = tmp_path / "profiles"
    folder.mkdir()
    monkeypatch.setenv("TLS_PLANNER_PROFILES", str(folder))
    (folder / "clash.toml").write_text(
        '[[scanner]]\nname = "leica-p20-lab"\nrange_rms_mm = 0.1\nangle_rms_arcsec = 0.1\n'
    )
    (folder / "broken.toml").write_text("[[scanner]\nname = ")
    (folder / "mine.toml").write_text(
        '[[scanner]]\nname = "mine"\nrange_rms_mm = 1.5\nangle_rms_arcsec = 8.0\n'
    )
    found, warnings = user_profiles()
    assert list(found) == ["mine"]
    assert any("catalogue's" in w for w in warnings) and any("broken.toml" in w for w in warnings)
    assert Scanner.from_name("leica-p20-lab").range_rms_mm == 1.7  # the catalogue's figures
    code, out, err = run("scanners")
    assert code == 0 and "mine" in out and "your profile" in out and "broken.toml" in err
    code, _, err = run("plan", "--scanner", "mine", "--out", str(tmp_path / "p"), "-q")
    assert code in (0, 1), err


@pytest.mark.parametrize(
    "name", ["../escaped", "a/b", "UPPER CASE", "", ".hidden", "leica-p20-lab"]
)
def test_install_names_are_checked_before_any_work(tmp_path, monkeypatch, name):
    folder = tmp_path / "profiles"
    monkeypatch.setenv("TLS_PLANNER_PROFILES", str(folder))
    data = Path(planner.__file__).parent / "data" / "calibration" / "baseline.csv"
    code, out, err = run("calibrate", "baseline", str(data), "--install", "--name", name)
    assert code == 2 and (
        "cannot name a scanner profile" in err or "reserved" in err or "needs a profile name" in err
    ), err
    assert out == ""  # refused before any computation
    assert not folder.exists() or not any(folder.iterdir())
    assert not (tmp_path / "escaped.toml").exists()


# -- hostile content ----------------------------------------------------------------------
HOSTILE = "<img src=x onerror=alert(1)><script>alert(2)</script>```"


def _hostile_site():
    from shapely.geometry import box

    from planner.site import Building, Obstacle, Site

    return Site(
        [Building(HOSTILE, box(500000, 5400000, 500020, 5400015), 9.0, name=HOSTILE)],
        obstacles=[Obstacle("=cmd|' /C calc'!A0", box(500030, 5400000, 500031, 5400001), 3.0)],
        name=HOSTILE,
    )


def test_csv_cells_that_a_spreadsheet_would_run_are_neutralised(tmp_path):
    from planner.pipeline.documents.export import render

    p = planner.plan(_hostile_site(), settings=planner.PlanSettings(sample_spacing_m=5))
    files = render(p)
    for name in ("coverage.csv", "facades.csv"):
        for line in files[name].splitlines()[1:]:
            for cell in line.split(","):
                assert not cell.startswith(("=", "+", "@")), (name, cell)
    assert "<img" in files["coverage.csv"]  # kept, as inert text (a CSV has no markup)


def test_the_report_shows_hostile_strings_as_text(tmp_path):
    from planner.app.report import make_report

    p = planner.plan(_hostile_site(), settings=planner.PlanSettings(sample_spacing_m=5))
    html = make_report(p, tmp_path / "r.html").read_text()
    assert "<img src=x" not in html and "<script>alert" not in html
    assert "&lt;img src=x onerror=alert(1)&gt;" in html


def test_the_dashboard_shows_hostile_strings_as_text(tmp_path):
    from planner.app.dashboard import StationPlanner

    ui = StationPlanner()
    site_path = tmp_path / "hostile.geojson"
    feature = _feature(_square(), height=9, id=HOSTILE, name=HOSTILE)
    feature["properties"]["role"] = "building"
    site_path.write_text(_fc(feature))
    ui.site_source.value = "Upload a file"
    data = site_path.read_bytes()
    ui.upload.value = (
        {
            "name": site_path.name,
            "type": "",
            "size": len(data),
            "content": data,
            "last_modified": datetime.datetime(2026, 1, 1),
        },
    )
    ui.run()
    shown = ui.summary.value + ui.error.value
    assert ui.plan is not None and "<img src=x" not in shown and "<script>" not in shown
    for out in (ui.fac_out, ui.unmet_out):
        for item in out.outputs:
            for mime, value in item.get("data", {}).items():
                if "html" in mime:
                    assert "<img src=x" not in value and "<script>alert" not in value
