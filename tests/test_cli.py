"""The command line: tables for any scanner, the target table, errors with exit code 2."""

from __future__ import annotations

import io
import subprocess
import sys
from dataclasses import fields

import pandas as pd
import pytest
from sites import run_cli as run

from planner.pipeline.inputs.requirements import (
    PlanSettings,
    Requirements,
)
from planner.scanner import DEFAULT_SCANNER


def test_accuracy_prints_both_tables_for_the_paper_scanner():
    code, out, _ = run("accuracy", "--scanner", "leica-4mm-60urad")
    assert code == 0
    assert "Table 1 layout" in out and "Table 2 layout" in out
    rows_120 = [
        [float(v) for v in ln.split()[1:]] for ln in out.splitlines() if ln.startswith("120")
    ]
    # the 120 m row of Table 1 (m_x then m_y at γ = 0/30/60) and of Table 2 (ν = 0/30/60/90)
    assert rows_120 == [[7.2, 6.6, 5.0, 4.0, 5.0, 6.6], [10.2, 9.8, 8.8, 8.2]]


def test_accuracy_csv_for_chosen_distances_and_angles():
    code, out, _ = run(
        "accuracy",
        "--scanner",
        "leica-p20-lab",
        "--distances",
        "5,25",
        "--angles",
        "0,45",
        "--tilts",
        "0",
        "--format",
        "csv",
    )
    assert code == 0
    df = pd.read_csv(io.StringIO(out), index_col=0)
    assert list(df.index) == [5.0, 25.0]
    assert df.loc[5.0, "m_y γ=0"] == pytest.approx(1.7, abs=1e-3)  # mm: P20 lab ranging
    assert df.loc[25.0, "m_x γ=0"] == pytest.approx(25_000 / 206264.806 * 284.06, abs=1e-3)


def test_targets_table_and_inventory():
    code, out, _ = run("targets", "--scanner", "leica-4mm-60urad")
    assert code == 0
    rows = {ln.split()[0]: ln.split()[1:] for ln in out.splitlines() if ln.split()}
    assert rows["flat"] == ["20", "40", "60", "80", "100", "120", "140"]
    assert rows["sphere"] == ["40", "80", "120", "160", "200", "240", "280"]
    assert "cylinder-150" in out and "188" in out  # serves to 187.5 m


def test_scanners_lists_the_catalogue():
    code, out, _ = run("scanners", "-v")
    assert code == 0
    for name in [
        "leica-4mm-60urad",
        "leica-hds3000",
        "faro-focus3d-lab",
        "leica-hds3000-lab",
        "leica-p20-lab",
    ]:
        assert name in out
    assert "source:" in out


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["accuracy", "--scanner", "nope"], "Unknown scanner 'nope'"),
        (["accuracy", "--distances", "10,x"], "comma-separated numbers"),
        (["accuracy", "--distances", "-10"], "argument --distances: must be > 0 and <= 10000 [m]"),
        (["accuracy", "--angles", "100"], "argument --angles: must be >= -90 and <= 90 [deg]"),
        (["targets", "--step-mm-at-10m", "0"], "must be >= 0.01 and <= 1000 [mm]"),
        (["accuracy", "--scanner", "missing.toml"], "does not exist"),
    ],
)
def test_bad_input_exits_2_with_a_message(argv, message):
    code, out, err = run(*argv)
    assert out == ""  # nothing printed on stdout
    assert code == 2
    assert message in err
    assert "Traceback" not in err


def test_python_dash_m_and_default_job():
    proc = subprocess.run(
        [sys.executable, "-m", "planner", "accuracy", "--distances", "10"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert proc.returncode == 0, proc.stderr
    assert "0.6" in proc.stdout


def test_every_command_prints_its_help():
    """``planner CMD --help`` for every command: exit 0 and the options with their units
    (a unit such as "%" in a data class's help once made argparse raise instead)."""
    from planner.app.arguments import build_parser

    commands = build_parser()._subparsers._group_actions[0].choices
    assert {"plan", "report", "serve"} <= set(commands)
    for name in commands:
        code, out, err = run(name, "--help")
        assert code == 0 and "Traceback" not in err, (name, err[-500:])
        assert out.startswith("usage: planner " + name), name
    code, out, _ = run("plan", "--help")
    text = " ".join(out.split())
    assert "Autodesk ReCap asks more than 20 %) [%] (> 0 and <= 100; default 20)" in text
    assert "[mm] (>= 0.01 and <= 1000; default 5)" in text  # each one's range, as checked


def test_plan_help_shows_every_setting_under_its_group():
    """The settings' groups (PlanSettings' fields, one declaration) are the help's sections:
    every setting's option stands under its group's title, none elsewhere."""

    from planner.pipeline.inputs.requirements import SETTING_GROUPS, setting_groups

    assert {f.metadata.get("group") for f in fields(PlanSettings)} == set(SETTING_GROUPS)
    code, out, _ = run("plan", "--help")
    assert code == 0
    sections: dict[str, str] = {}
    title = "options"
    for line in out.splitlines():
        if line and not line.startswith(" ") and line.endswith(":"):
            title = line[:-1]
        sections[title] = sections.get(title, "") + line + "\n"
    flags = {"incidence_noise": "--no-incidence-noise", "beam_footprint": "--no-beam-footprint"}
    flags |= {"registration_error": "--no-registration-error"}
    for key, names in setting_groups().items():
        text = sections[SETTING_GROUPS[key].lower()]
        for name in names:
            flag = flags.get(name, "--" + name.replace("_", "-"))
            assert f"  {flag} " in text or f"  {flag}\n" in text or f"  {flag}," in text, (
                key,
                flag,
            )
    assert "--grid-m" not in sections["registration and targets"]
    assert "--max-z-mm" in sections["requirements"]


def test_cli_defaults_are_the_data_class_defaults(tmp_path):
    code, out, err = run("plan", "--out", str(tmp_path / "p"), "-q")
    assert code == 0, err
    assert f"Scanner {DEFAULT_SCANNER}; required {Requirements().describe()}" in out
