"""Every scanner of the catalogue plans the default site under every model switch, and the
plan's numbers are those its profile gives.

The scanners are read from the catalogue when the tests are collected, so a profile added to
``planner/data/scanners.toml`` is planned here without touching this file.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest

from planner.accuracy import height_rms, planimetric_rms
from planner.accuracy3d import footprint_mm, point_rms_3d
from planner.pipeline.engine.planning import plan
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.scanner import Scanner, catalogue
from planner.siteio import default_site
from planner.spacing import facade_spacing_kernel

#: Each switch of the accuracy model is planned both ways for every scanner: all on, all
#: off, and the paper's own model with the registration error.
SWITCHES = {
    "3d, incidence, footprint, registration": {},
    "3d, none of the three": {
        "incidence_noise": False,
        "beam_footprint": False,
        "registration_error": False,
    },
    "paper, registration": {"model": "paper"},
}
#: Samples and candidates coarser than the default (the checks are per sample: a quarter of
#: the samples checks the same formulas, in a quarter of the time); cloud links by the model
#: alone (their rehearsal: tests/test_linkcheck.py).
COARSE = {
    "sample_spacing_m": 4.0,
    "sample_height_step_m": 4.0,
    "grid_m": 3.0,
    "link_check": "model",
}


@functools.cache
def _plan(name: str, switches: str):
    """The default site planned with scanner ``name`` under ``switches`` (once for the
    module: the footprint's test reads the plans of the first two)."""
    st = PlanSettings(**SWITCHES[switches], **COARSE)
    return plan(default_site(), Scanner.from_name(name), Requirements(), st), st


@pytest.mark.parametrize("switches", list(SWITCHES), ids=list(SWITCHES))
@pytest.mark.parametrize("name", sorted(catalogue()))
def test_every_catalogue_scanner_plans_the_default_site(name, switches):
    sc = Scanner.from_name(name)
    p, st = _plan(name, switches)
    cov = p.coverage[p.coverage["station_id"] != ""]
    assert len(p.stations) >= 1
    assert len(cov) > 100  # the stations scan the building
    s = cov["slope_distance_m"].to_numpy()
    g = cov["gamma_deg"].to_numpy()
    nu = cov["nu_deg"].to_numpy()
    assert np.all((s >= sc.min_range_m) & (s <= sc.max_range_m))
    lo, hi = sc.vertical_fov_deg
    assert np.all((nu >= lo - 1e-6) & (nu <= hi + 1e-6))
    got = [cov[f"scanner_m_{c}_mm"].to_numpy() for c in "xyz"]
    # the axis tilt is the registration's part when that is computed (heights against true
    # vertical: each scan's own tilt, or the datum's turning the network), else the scan's
    tilt = 0.0 if st.computes_registration else sc.initial_tilt_rms_arcsec
    if st.model == "3d":  # the profile's figures through the 3-D model
        want = point_rms_3d(
            s, g, nu, sc, incidence_noise=st.incidence_noise, axis_tilt_rms_arcsec=tilt
        )
    else:  # eq. 2 (ranging at the slope distance) and eq. 4
        d = cov["distance_m"].to_numpy()
        want = (
            *planimetric_rms(d, g, sc, ranging_distance_m=s),
            height_rms(s, nu, sc, initial_tilt_rms_arcsec=tilt),
        )
    for c, a, b in zip("xyz", got, want, strict=True):
        assert a == pytest.approx(b, abs=1e-6), f"m_{c}"  # mm
    reg = [cov[f"reg_m_{c}_mm"].to_numpy() for c in "xyz"]
    total = [cov[f"m_{c}_mm"].to_numpy() for c in "xyz"]
    for c, a, r, t in zip("xyz", got, reg, total, strict=True):
        if st.computes_registration:
            tied = np.isfinite(r)
            assert tied.sum() > 100  # samples whose registration is known
            assert t[tied] == pytest.approx(np.hypot(a[tied], r[tied]), abs=1e-6), f"m_{c}"
        else:
            assert t == pytest.approx(a, abs=1e-6), f"m_{c}"  # mm
    met = cov["meets"].to_numpy()
    for c, t in zip("xyz", total, strict=True):
        assert np.all(t[met] <= 5.0 + 1e-9), f"m_{c}"  # the default requirement, mm


@pytest.mark.parametrize(
    "name", sorted(n for n, sc in catalogue().items() if sc.beam_divergence_mrad)
)
def test_the_beam_footprint_grows_with_distance_as_the_profile_says(name):
    """Where the footprint is coarser than the point spacing it is the spacing reported, and
    footprint × cos θ against the slope distance is a line: the profile's exit diameter
    [mm] plus its divergence [mrad = mm/m]; with the footprint switched off, the spacing."""
    sc = Scanner.from_name(name)
    on, off = list(SWITCHES)[:2]  # the footprint on, and off
    p = _plan(name, on)[0]
    cov = p.coverage[p.coverage["station_id"] != ""]
    s = cov["slope_distance_m"].to_numpy()
    cos_t = np.cos(np.radians(cov["incidence_deg"].to_numpy()))
    spacing = facade_spacing_kernel(
        cov["distance_m"].to_numpy(),
        s,
        np.cos(np.radians(cov["gamma_deg"].to_numpy())),
        sc.step_mm_at_10m,
    )
    foot = footprint_mm(s, sc, cos_t)
    assert cov["spacing_mm"].to_numpy() == pytest.approx(np.maximum(spacing, foot), rel=1e-9)
    wide = foot > spacing
    assert wide.sum() >= 5, "the footprint is never the coarser here"
    width = cov["spacing_mm"].to_numpy()[wide] * np.clip(cos_t[wide], 0.1, 1.0)
    slope, exit_mm = np.polyfit(s[wide], width, 1)
    assert slope == pytest.approx(sc.beam_divergence_mrad, abs=1e-6)  # mm per m
    assert exit_mm == pytest.approx(sc.beam_exit_mm or 0.0, abs=1e-4)  # mm
    c2 = _plan(name, off)[0].coverage
    c2 = c2[c2["station_id"] != ""]
    assert c2["spacing_mm"].to_numpy() == pytest.approx(
        facade_spacing_kernel(
            c2["distance_m"].to_numpy(),
            c2["slope_distance_m"].to_numpy(),
            np.cos(np.radians(c2["gamma_deg"].to_numpy())),
            sc.step_mm_at_10m,
        ),
        rel=1e-9,
    )
