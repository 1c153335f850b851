"""The calibration dashboard (planner/app/calibration_view.py) driven from Python: the example
data give the same figures as the calibration functions; an upload replaces one step; a bad
file replaces that step's result with an error and withdraws the profile that depends on it;
Install writes the profile where the planner finds it by name, and never replaces an
installed file without a second click."""

from __future__ import annotations

import datetime
import html

import pytest

from planner.app.calibration_plots import example_path
from planner.app.calibration_view import CalibrationDashboard
from planner.calibration import axis_errors, baseline_calibration
from planner.scanner import Scanner


@pytest.fixture
def ui(tmp_path, monkeypatch):
    monkeypatch.setenv("TLS_PLANNER_PROFILES", str(tmp_path / "profiles"))
    return CalibrationDashboard()


def _upload(ui: CalibrationDashboard, slot: str, name: str, data: bytes) -> None:
    ui.slots[slot].upload.value = (
        {
            "name": name,
            "type": "text/csv",
            "size": len(data),
            "content": data,
            "last_modified": datetime.datetime(2026, 1, 1),
        },
    )


def _text(out) -> str:
    """Everything an Output shows as text (widgets by their HTML value)."""
    from ipywidgets.widgets.widget import _instances

    parts = []
    for item in out.outputs:
        data = item.get("data", {})
        view = data.get("application/vnd.jupyter.widget-view+json")
        if view:
            parts.append(_instances[view["model_id"]].value)
        else:
            parts.append(data.get("text/html", "") + data.get("text/plain", ""))
    return html.unescape("\n".join(parts))


def _images(out) -> int:
    return sum("image/png" in item.get("data", {}) for item in out.outputs)


def test_the_example_gives_the_calibration_functions_figures_and_each_plot_once(ui):
    assert sorted(ui.results) == ["axes", "distances", "lab"]
    for out in ui.outs.values():
        assert _images(out) == 1  # the residual plot, shown once
    baseline = baseline_calibration(example_path("baseline.csv"))
    axes = axis_errors(example_path("axes.csv"))
    assert ui.scanner.range_rms_mm == pytest.approx(baseline.residual_rms_mm, abs=1e-6)  # mm
    assert ui.scanner.angle_rms_arcsec == pytest.approx(axes.residual_rms_arcsec, abs=1e-6)  # ″
    assert f"k = {baseline.k_mm:+.2f} mm" in _text(ui.outs["distances"])
    assert "Example data" in _text(ui.outs["axes"])
    assert 'download="my-scanner.toml"' in ui.download.value
    assert not ui.install.disabled


def test_an_upload_replaces_its_step_and_a_bad_one_withdraws_the_profile(ui):
    # the six-segment file in the distances slot: k only, and ranging cannot come from it
    _upload(ui, "distances", "six.csv", example_path("six_segment.csv").read_bytes())
    assert "six.csv" in ui.slots["distances"].name.value
    assert "Six-segment" in _text(ui.outs["distances"])
    assert ui.scanner is None and ui.download.value == "" and ui.install.disabled
    assert "six-segment file gives the additive constant only" in _text(ui.profile_out)
    ui.range_from.value = "lab"
    assert ui.scanner is not None
    assert ui.scanner.range_rms_mm == pytest.approx(ui.results["lab"].m_r["distance_mm"], abs=1e-6)

    _upload(ui, "axes", "broken.csv", b"angle;value\n1;2\n")
    shown = _text(ui.outs["axes"])
    assert "Cannot calibrate" in shown and "vertical_angle_deg" in shown
    assert _images(ui.outs["axes"]) == 0  # the old plot is gone with the old result
    assert "axes" not in ui.results
    assert ui.scanner is None and ui.install.disabled
    assert "axis directions file" in _text(ui.profile_out)

    # a distances file that fails: the profile names that file, not the six-segment case
    ui.range_from.value = "baseline"
    _upload(ui, "distances", "broken.csv", b"x;y\n1;2\n")
    assert "distances file, which gave no result" in _text(ui.profile_out)

    ui.use_example()
    assert sorted(ui.results) == ["axes", "distances", "lab"]
    assert "example: axes.csv" in ui.slots["axes"].name.value
    assert ui.scanner is not None


def test_install_finds_the_profile_by_name_and_asks_before_replacing(ui, tmp_path):
    ui.name.value = "my-p20"
    ui.install_profile()
    path = tmp_path / "profiles" / "my-p20.toml"
    assert path.is_file() and "Installed 'my-p20'" in ui.install_status.value
    again = Scanner.from_name("my-p20")
    assert again.range_rms_mm == pytest.approx(ui.scanner.range_rms_mm, abs=1e-9)  # mm

    before = path.read_text()
    ui.include_scale.value = True  # another profile of the same name
    ui.install_profile()
    assert "installed already" in ui.install_status.value and path.read_text() == before
    ui.install_profile()
    assert "Installed" in ui.install_status.value and path.read_text() != before

    ui.name.value = "leica-p20-lab"  # a catalogue name is reserved
    ui.install_profile()
    assert "reserved" in html.unescape(ui.install_status.value)
    assert not (tmp_path / "profiles" / "leica-p20-lab.toml").exists()

    ui.name.value = "../evil"
    assert ui.scanner is None and "cannot name a scanner profile" in _text(ui.profile_out)
