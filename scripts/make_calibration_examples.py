"""Regenerate planner/data/calibration/ (the calibration notebook's example data).

    .venv/bin/python scripts/make_calibration_examples.py

Synthetic measurements with known parameters (see the README written beside them), made
by the simulators of planner.calibration; deterministic (fixed seeds).
"""

from pathlib import Path

from planner.calibration import simulate_axes, simulate_baseline, simulate_lab, simulate_signal

OUT = Path(__file__).resolve().parent.parent / "planner" / "data" / "calibration"

ref, scan = simulate_lab(n_targets=60, range_rms_mm=1.5, angle_rms_arcsec=20.0)
ref.assign(sigma_mm=0.5).round(5).to_csv(OUT / "lab_reference.csv", index=False)
scan.round(5).to_csv(OUT / "lab_scan.csv", index=False)
base = simulate_baseline(k_mm=3.9, scale_ppm=-30.0, noise_mm=1.0)
base[["measured_m", "reference_m"]].round(5).to_csv(OUT / "baseline.csv", index=False)
six = simulate_baseline(k_mm=-1.5, scale_ppm=20.0, noise_mm=0.5, seed=9)
six.rename(columns={"measured_m": "distance_m"})[["from", "to", "distance_m"]].round(5).to_csv(
    OUT / "six_segment.csv", index=False
)
simulate_axes(
    c_deg=0.0075,
    i_deg=0.0461,
    noise_arcsec=2.0,
    alphas_deg=[-35, -25, -15, -5, 5, 15, 25, 35, 45, 55, 65, 70],
).round(6).to_csv(OUT / "axes.csv", index=False)
simulate_signal(m0_mm=0.8, k=0.55, points=1500).round(4).to_csv(OUT / "signal.csv", index=False)
print(f"wrote {OUT}")
