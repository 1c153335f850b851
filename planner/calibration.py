"""From a scanner's calibration measurements to its planning profile.

* :func:`lab_test` — the laboratory uncertainty test of the Belgrade procedure
  ("Laboratory procedure for terrestrial laser scanners calibration", University of
  Belgrade metrological laboratory): a 6-parameter rigid (Helmert) transformation of the
  scanner's target coordinates into the lab frame by least squares, then for target pairs
  the differences of distance, horizontal direction φ = arctan(ΔX/ΔY) and vertical direction
  θ = arctan(ΔZ/√(ΔX²+ΔY²)) between reference and scanner; ``m_r = √(ΣΔ²/n)`` (eq. 1, 3, 5),
  expanded ``M_r = k·m_r`` (eq. 7–8, k = 2) and every pair with ``|Δ| > M_r`` (eq. 9).
* :func:`baseline_calibration` — additive constant k and scale R from distances measured
  on a baseline of known lengths, ``D_ref = D + k + R·D`` (Liu & Zhang, baseline comparison).
* :func:`six_segment_constant` — the additive constant alone from all combinations of
  distances between points of an unknown baseline (Liu & Zhang, Schwendener's method).
* :func:`axis_errors` — collimation c (effect c / cos α) and trunnion-axis tilt i (effect
  i·tan α) from horizontal directions at several vertical angles α (Liu & Zhang, eq. 5–6);
  the model itself is :func:`axis_error_effect`.
* :func:`signal_calibration` — the ranging noise's growth as the returned signal falls,
  ``m_S = m_0·q^(−k)`` with ``q = ρ cos θ / ρ_ref`` (Wujanz et al. 2017, 2018;
  :mod:`planner.signal`), from the residuals of planes of known reflectance scanned at
  several incidences (Schmitz et al. 2019: plane-fit residuals along the normal are the
  ranging noise times cos θ at a lab's short distances).
* :func:`profile_from_calibration` — a :class:`~planner.scanner.Scanner` built from these,
  with the calibration recorded in it.

Units follow the package rule (mm, arc-seconds, metres, degrees).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike

from planner._array import as_float_array
from planner.errors import InputError
from planner.ranges import RANGES
from planner.reading import user_file
from planner.scanner import DEFAULT_SCANNER, Scanner, check_profile_name
from planner.signal import DEFAULT_REFERENCE_REFLECTANCE, MIN_SIGNAL, relative_signal
from planner.units import RHO_ARCSEC

__all__ = [
    "AxisResult",
    "BaselineResult",
    "HelmertResult",
    "LabTest",
    "SignalResult",
    "SixSegmentResult",
    "axis_error_effect",
    "axis_errors",
    "baseline_calibration",
    "helmert6",
    "lab_test",
    "profile_from_calibration",
    "read_points",
    "signal_calibration",
    "simulate_axes",
    "simulate_baseline",
    "simulate_lab",
    "simulate_signal",
    "six_segment_constant",
]

#: Targets whose coordinates spread less than this across their line are collinear [m].
MIN_SPREAD_M = 0.01
#: The Belgrade paper: "angular values are inflated by the very short lab distances"; below this
#: median pair distance the profile carries a warning [m].
SHORT_LAB_DISTANCE_M = 10.0


# -- input ---------------------------------------------------------------------------------
def _columns(df: pd.DataFrame, wanted: Sequence[str], origin: str) -> pd.DataFrame:
    low = {c.strip().lower(): c for c in df.columns}
    missing = [w for w in wanted if w not in low]
    if missing:
        raise InputError(
            f"{origin} lacks the column(s) {', '.join(missing)}; it has {', '.join(df.columns)}"
        )
    out = df.rename(columns={low[w]: w for w in wanted})
    return out


def _numbers(df: pd.DataFrame, cols: Sequence[str], origin: str) -> pd.DataFrame:
    for c in cols:
        vals = pd.to_numeric(df[c], errors="coerce")
        bad = vals.isna() | ~np.isfinite(vals.to_numpy(dtype=float, na_value=np.nan))
        if bad.any():
            row = int(np.flatnonzero(bad.to_numpy())[0])
            raise InputError(
                f"{origin}: column {c!r} has a missing or non-numeric value in row {row + 1} "
                f"({df[c].iloc[row]!r}); every value must be a number"
            )
        df[c] = vals.astype(float)
    return df


def _table(
    data: pd.DataFrame | str | Path, wanted: Sequence[str], origin: str | None = None
) -> pd.DataFrame:
    if isinstance(data, pd.DataFrame):
        df, origin = data.copy(), origin or "the table"
    else:
        p = user_file(data, "calibration table")
        origin = origin or p.name
        head = p.read_bytes()[:4096]
        if not head.strip():
            raise InputError(f"{origin} is empty; it needs a header line and one row per value")
        if b"\x00" in head:
            raise InputError(f"{origin} is a binary file, not a CSV table")
        try:
            df = pd.read_csv(p, sep=None, engine="python", encoding="utf-8-sig")
        except Exception as exc:  # the CSV reader's boundary: any failure is the file's
            first = str(exc).splitlines()[0][:200] if str(exc) else type(exc).__name__
            raise InputError(f"{origin} is not a readable CSV table ({first})") from None
    if df.empty:
        raise InputError(f"{origin} has no rows")
    return _columns(df, wanted, origin)


def table_columns(path: str | Path) -> set[str]:
    """The column names (lower case) of a calibration CSV file — to tell its kind."""
    df = _table(path, [], None)
    return {str(c).strip().lower() for c in df.columns}


def read_points(data: pd.DataFrame | str | Path, origin: str | None = None) -> pd.DataFrame:
    """Target coordinates ``id, x, y, z`` [m] (optional ``sigma_mm``), one row per target."""
    df = _table(data, ["id", "x", "y", "z"], origin)
    origin = origin or (Path(data).name if not isinstance(data, pd.DataFrame) else "the table")
    df = _numbers(df, ["x", "y", "z"], origin)
    df["id"] = df["id"].astype(str).str.strip()
    dup = df["id"][df["id"].duplicated()]
    if len(dup):
        raise InputError(f"{origin}: target id {dup.iloc[0]!r} appears twice")
    return df.set_index("id")


#: A baseline difference (reference − measured) beyond this is a blunder, not a constant [mm].
MAX_BASELINE_DIFFERENCE_MM = 1000.0
#: Calibrated figures beyond these describe no working scanner: the profile is refused.
MAX_PROFILE_RANGE_RMS_MM = 100.0
MAX_PROFILE_ANGLE_RMS_ARCSEC = 3600.0


# -- Helmert -------------------------------------------------------------------------------
def _rotation(omega: float, phi: float, kappa: float) -> np.ndarray:
    co, so = math.cos(omega), math.sin(omega)
    cp, sp = math.cos(phi), math.sin(phi)
    ck, sk = math.cos(kappa), math.sin(kappa)
    rx = np.array([[1, 0, 0], [0, co, -so], [0, so, co]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[ck, -sk, 0], [sk, ck, 0], [0, 0, 1]])
    return rz @ ry @ rx


def _angles(r: np.ndarray) -> tuple[float, float, float]:
    phi = math.asin(-max(-1.0, min(1.0, r[2, 0])))
    omega = math.atan2(r[2, 1], r[2, 2])
    kappa = math.atan2(r[1, 0], r[0, 0])
    return omega, phi, kappa


@dataclass
class HelmertResult:
    """Rigid transformation ``X_lab = R·X_scan + t`` and its least-squares quality."""

    rotation: np.ndarray  # (3, 3)
    translation_m: np.ndarray  # (3,)
    angles_deg: np.ndarray  # ω, φ, κ about x, y, z
    std_errors: dict[str, float]  # translation [mm] and angles [″]
    residuals: pd.DataFrame  # per target: dx, dy, dz, d [mm] (reference − transformed)
    sigma0_mm: float  # a-posteriori RMS of a coordinate
    redundancy: int

    def apply(self, xyz: np.ndarray) -> np.ndarray:
        return np.asarray(xyz) @ self.rotation.T + self.translation_m

    def lines(self) -> list[str]:
        """The transformation in words (the command line and the dashboard print these)."""
        se = self.std_errors
        return [
            f"6-parameter Helmert transformation of {len(self.residuals)} targets (scanner → lab):",
            "  translation [m]: "
            + " ".join(f"{v:.4f}" for v in self.translation_m)
            + " (± "
            + ", ".join(f"{se[k]:.2f}" for k in ("tx_mm", "ty_mm", "tz_mm"))
            + " mm)",
            "  rotation ω, φ, κ [deg]: "
            + " ".join(f"{v:.5f}" for v in self.angles_deg)
            + f" (± {se['omega_arcsec']:.1f}, {se['phi_arcsec']:.1f}, "
            f"{se['kappa_arcsec']:.1f}″)",
            f"  residual RMS of a coordinate σ₀ = {self.sigma0_mm:.2f} mm "
            f"(redundancy {self.redundancy})",
        ]


def _check_geometry(xyz: np.ndarray, what: str) -> None:
    if len(xyz) < 3:
        raise InputError(
            f"{what}: the 6-parameter transformation needs at least 3 common targets "
            f"(not collinear); got {len(xyz)}"
        )
    s = np.linalg.svd(xyz - xyz.mean(axis=0), compute_uv=False)
    if s[1] < MIN_SPREAD_M:
        raise InputError(
            f"{what}: the common targets are collinear (they spread {s[1]:.4f} m "
            "across their line), so the rotation about that line is undetermined; "
            "use targets off the line"
        )


def helmert6(
    ref_xyz: np.ndarray, scan_xyz: np.ndarray, ids: Sequence[str] | None = None
) -> HelmertResult:
    """Least-squares rigid (6-parameter Helmert) transformation of ``scan_xyz`` onto ``ref_xyz``.

    The rotation and translation minimising Σ|X_ref − (R·X_scan + t)|² (closed form by SVD),
    then standard errors from the linearised model: σ₀² = Σv² / (3n − 6), Cov = σ₀²(JᵀJ)⁻¹.
    """
    ref = np.asarray(ref_xyz, dtype=float)
    scan = np.asarray(scan_xyz, dtype=float)
    _check_geometry(ref, "reference targets")
    _check_geometry(scan, "scanner targets")
    cr, cs = ref.mean(axis=0), scan.mean(axis=0)
    h = (scan - cs).T @ (ref - cr)
    u, _, vt = np.linalg.svd(h)
    d = np.sign(np.linalg.det(vt.T @ u.T))
    rot = vt.T @ np.diag([1.0, 1.0, d]) @ u.T
    t = cr - rot @ cs
    fitted = scan @ rot.T + t
    v = ref - fitted
    n = len(ref)
    redundancy = 3 * n - 6
    sigma0 = math.sqrt((v**2).sum() / redundancy) if redundancy > 0 else float("nan")
    # Jacobian of the transformed points with respect to (tx, ty, tz, small rotations)
    rs = scan @ rot.T
    jac = np.zeros((3 * n, 6))
    for k in range(n):
        x, y, z = rs[k]
        jac[3 * k : 3 * k + 3, :3] = np.eye(3)
        jac[3 * k : 3 * k + 3, 3:] = np.array([[0, z, -y], [-z, 0, x], [y, -x, 0]])
    with np.errstate(invalid="ignore"):
        cov = sigma0**2 * np.linalg.pinv(jac.T @ jac)
    se = np.sqrt(np.abs(np.diag(cov)))
    names = ["tx_mm", "ty_mm", "tz_mm", "omega_arcsec", "phi_arcsec", "kappa_arcsec"]
    scale = [1000.0] * 3 + [RHO_ARCSEC] * 3
    std_errors = {k: float(s * f) for k, s, f in zip(names, se, scale, strict=True)}
    res = pd.DataFrame(
        v * 1000.0,
        columns=["dx_mm", "dy_mm", "dz_mm"],
        index=pd.Index(list(ids) if ids is not None else range(n), name="id"),
    )
    res["d_mm"] = np.linalg.norm(v, axis=1) * 1000.0
    return HelmertResult(
        rot, t, np.degrees(_angles(rot)), std_errors, res, sigma0 * 1000.0, redundancy
    )


# -- the lab test --------------------------------------------------------------------------
@dataclass
class LabTest:
    """Result of the Belgrade laboratory uncertainty test."""

    helmert: HelmertResult
    pairs: pd.DataFrame  # one row per target pair: Δ of distance [mm], φ and θ [″], flags
    m_r: dict[str, float]  # distance_mm, horizontal_arcsec, vertical_arcsec
    M_r: dict[str, float]
    k: float
    network: str  # the verdict on the reference network, or "" if not checked
    warnings: list[str] = field(default_factory=list)

    @property
    def significant(self) -> pd.DataFrame:
        """Pairs with at least one |Δ| > M_r (eq. 9 of the Belgrade procedure)."""
        flags = self.pairs[
            ["significant_distance", "significant_horizontal", "significant_vertical"]
        ]
        return self.pairs[flags.any(axis=1)]

    def lines(self) -> list[str]:
        """The transformation, and the heading of :meth:`summary` (command line, dashboard)."""
        return [
            *self.helmert.lines(),
            "",
            f"Uncertainty from {len(self.pairs)} target pairs (Belgrade laboratory procedure, "
            "eq. 1–9):",
        ]

    def summary(self) -> pd.DataFrame:
        rows = [
            (
                "distance",
                "mm",
                self.m_r["distance_mm"],
                self.M_r["distance_mm"],
                int(self.pairs["significant_distance"].sum()),
            ),
            (
                "horizontal direction φ",
                "″",
                self.m_r["horizontal_arcsec"],
                self.M_r["horizontal_arcsec"],
                int(self.pairs["significant_horizontal"].sum()),
            ),
            (
                "vertical direction θ",
                "″",
                self.m_r["vertical_arcsec"],
                self.M_r["vertical_arcsec"],
                int(self.pairs["significant_vertical"].sum()),
            ),
        ]
        return pd.DataFrame(
            rows, columns=["component", "unit", "m_r", f"M_r (k={self.k:g})", "pairs |Δ| > M_r"]
        ).set_index("component")


def _directions(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    d = b - a
    horiz = np.hypot(d[:, 0], d[:, 1])
    dist = np.linalg.norm(d, axis=1)
    phi = np.arctan2(d[:, 0], d[:, 1])  # φ = arctan(ΔX/ΔY), from the Y axis
    theta = np.arctan2(d[:, 2], horiz)  # θ = arctan(ΔZ/√(ΔX²+ΔY²))
    return dist, phi, theta


def lab_test(
    reference: pd.DataFrame | str | Path,
    scan: pd.DataFrame | str | Path,
    *,
    k: float = 2.0,
    pairs: str = "all",
    reference_precision_mm: float | None = None,
    declared_target_precision_mm: float | None = None,
) -> LabTest:
    """The Belgrade laboratory uncertainty test of a scanner.

    Parameters
    ----------
    reference, scan : DataFrame or CSV path
        Targets ``id, x, y, z`` [m] in the lab frame (from a total-station network; an
        optional ``sigma_mm`` column gives each point's precision) and in the scanner frame.
    k : float, default 2
        Coverage factor of the expanded uncertainty M_r = k·m_r (2: 95 %).
    pairs : "all" or "first"
        Every pair of targets, or the first target paired with every other.
    reference_precision_mm, declared_target_precision_mm : float, optional
        The reference network's point precision (default: the largest ``sigma_mm``) and the
        scanner's declared target precision: the network is good enough when the first is at
        most a third of the second (the Belgrade paper: 0.7 mm against 2 mm).
    """
    ref = read_points(
        reference, None if not isinstance(reference, str | Path) else Path(reference).name
    )
    scn = read_points(scan, None if not isinstance(scan, str | Path) else Path(scan).name)
    only_ref = sorted(set(ref.index) - set(scn.index))
    only_scan = sorted(set(scn.index) - set(ref.index))
    common = [i for i in ref.index if i in scn.index]
    if only_ref or only_scan:

        def show(ids):
            return ", ".join(ids[:10]) + (" …" if len(ids) > 10 else "")

        raise InputError(
            "the target ids of the two files do not match: "
            + (f"only in the reference: {show(only_ref)}" if only_ref else "")
            + ("; " if only_ref and only_scan else "")
            + (f"only in the scan: {show(only_scan)}" if only_scan else "")
            + "; give both files the same targets (same ids)"
        )
    if not (isinstance(k, int | float) and math.isfinite(k) and k > 0):
        raise InputError(f"k must be a number > 0; got {k!r}")
    ref_xyz = ref.loc[common, ["x", "y", "z"]].to_numpy()
    scn_xyz = scn.loc[common, ["x", "y", "z"]].to_numpy()
    hm = helmert6(ref_xyz, scn_xyz, common)
    moved = hm.apply(scn_xyz)
    n = len(common)
    if pairs == "all":
        ia, ib = np.triu_indices(n, 1)
    elif pairs == "first":
        ia, ib = np.zeros(n - 1, dtype=int), np.arange(1, n)
    else:
        raise InputError(f"pairs must be 'all' or 'first'; got {pairs!r}")
    d_ref, p_ref, t_ref = _directions(ref_xyz[ia], ref_xyz[ib])
    d_scn, p_scn, t_scn = _directions(moved[ia], moved[ib])
    dd = (d_ref - d_scn) * 1000.0
    dp = (np.angle(np.exp(1j * (p_ref - p_scn)))) * RHO_ARCSEC
    dt = (t_ref - t_scn) * RHO_ARCSEC
    m_r = {
        "distance_mm": float(np.sqrt(np.mean(dd**2))),
        "horizontal_arcsec": float(np.sqrt(np.mean(dp**2))),
        "vertical_arcsec": float(np.sqrt(np.mean(dt**2))),
    }
    M_r = {key: k * v for key, v in m_r.items()}
    table = pd.DataFrame(
        {
            "target_a": np.array(common)[ia],
            "target_b": np.array(common)[ib],
            "distance_m": d_ref,
            "d_distance_mm": dd,
            "d_horizontal_arcsec": dp,
            "d_vertical_arcsec": dt,
            "significant_distance": np.abs(dd) > M_r["distance_mm"],
            "significant_horizontal": np.abs(dp) > M_r["horizontal_arcsec"],
            "significant_vertical": np.abs(dt) > M_r["vertical_arcsec"],
        }
    )
    network = ""
    ref_prec = reference_precision_mm
    if ref_prec is None and "sigma_mm" in [c.lower() for c in ref.columns]:
        col = next(c for c in ref.columns if c.lower() == "sigma_mm")
        ref_prec = float(pd.to_numeric(ref[col], errors="coerce").max())
    if ref_prec is not None and declared_target_precision_mm is not None:
        limit = declared_target_precision_mm / 3.0
        verdict = "good enough" if ref_prec <= limit + 1e-12 else "NOT good enough"
        network = (
            f"reference network {verdict}: point precision {ref_prec:g} mm vs. "
            f"{limit:.2f} mm (a third of the declared {declared_target_precision_mm:g} mm)"
        )
    warnings = []
    median = float(np.median(d_ref))
    if median < SHORT_LAB_DISTANCE_M:
        warnings.append(
            f"the target pairs are short (median {median:.1f} m): angular figures from them are "
            "inflated (the Belgrade paper's own caution: its 1–7 m lab gave 284–1232″ "
            "horizontally); "
            "prefer datasheet or long-range angular figures for planning"
        )
    return LabTest(hm, table, m_r, M_r, float(k), network, warnings)


# -- range constants ------------------------------------------------------------------------
@dataclass
class BaselineResult:
    """Additive constant k [mm] and scale R (``D_ref = D + k + R·D``) with standard errors."""

    k_mm: float
    k_se_mm: float
    scale_ppm: float
    scale_se_ppm: float
    residual_rms_mm: float  # after correcting k and R
    residuals: pd.DataFrame
    n: int
    warnings: list[str] = field(default_factory=list)

    def lines(self) -> list[str]:
        """The result in words (the command line and the dashboard print these)."""
        return [
            f"Baseline comparison of {self.n} distances: D_ref = D + k + R·D",
            f"  k = {self.k_mm:+.2f} mm ± {self.k_se_mm:.2f} mm;  "
            f"R = {self.scale_ppm:+.1f} ppm ± {self.scale_se_ppm:.1f} ppm",
            f"  residual RMS after correction: {self.residual_rms_mm:.2f} mm",
        ]


def baseline_calibration(data: pd.DataFrame | str | Path) -> BaselineResult:
    """Baseline comparison (Liu & Zhang): ``D_ref − D = k + R·D`` by least squares.

    ``data`` has columns ``measured_m`` and ``reference_m`` (one row per distance, at
    least 3 distinct lengths).
    """
    origin = None if isinstance(data, pd.DataFrame) else Path(data).name
    df = _numbers(
        _table(data, ["measured_m", "reference_m"], origin),
        ["measured_m", "reference_m"],
        origin or "the table",
    )
    d = df["measured_m"].to_numpy()
    lv = (df["reference_m"].to_numpy() - d) * 1000.0  # mm
    absurd = np.flatnonzero(np.abs(lv) > MAX_BASELINE_DIFFERENCE_MM)
    if len(absurd):
        i = int(absurd[0])
        raise InputError(
            f"{origin or 'the table'} row {i + 2}: measured {d[i]:g} m against reference "
            f"{df['reference_m'].iloc[i]:g} m differ by {lv[i] / 1000:.3g} m — not the same "
            "distance (a typo, a unit slip, a wrong target?); correct or remove the row"
        )
    if len(d) < 3 or np.ptp(d) < 1.0:
        raise InputError(
            "the baseline comparison needs at least 3 distances spanning more than 1 m "
            f"(k and R are both unknown); got {len(d)} spanning {np.ptp(d):.2f} m"
        )
    a = np.column_stack([np.ones_like(d), d * 1000.0])  # R in mm per mm
    x, *_ = np.linalg.lstsq(a, lv, rcond=None)
    v = lv - a @ x
    dof = len(d) - 2
    s0 = math.sqrt((v**2).sum() / dof) if dof > 0 else float("nan")
    cov = s0**2 * np.linalg.inv(a.T @ a) if dof > 0 else np.full((2, 2), np.nan)
    # outliers: residuals beyond 3 robust standard deviations (MAD), flagged for the user
    mad = 1.4826 * float(np.median(np.abs(v - np.median(v))))
    scale = max(mad, 1e-3)
    outlier = np.abs(v) > 3.0 * scale
    res = df.assign(correction_mm=a @ x, residual_mm=v, outlier=outlier)
    warnings = [
        f"row {i + 2} (measured {d[i]:g} m) is an outlier: residual {v[i]:+.2f} mm against a "
        f"robust spread of {scale:.2f} mm; check it, and remove it if it is a blunder"
        for i in np.flatnonzero(outlier)
    ]
    return BaselineResult(
        k_mm=float(x[0]),
        k_se_mm=float(math.sqrt(cov[0, 0])),
        scale_ppm=float(x[1] * 1e6),
        scale_se_ppm=float(math.sqrt(cov[1, 1]) * 1e6),
        residual_rms_mm=float(np.sqrt(np.mean(v**2))),
        residuals=res,
        n=len(d),
        warnings=warnings,
    )


@dataclass
class SixSegmentResult:
    """Additive constant from all combinations on an unknown baseline."""

    k_mm: float
    k_se_mm: float
    segments_m: pd.Series  # adjusted distances from the first point
    residuals: pd.DataFrame
    sigma0_mm: float

    def lines(self) -> list[str]:
        """The result in words (the command line and the dashboard print these)."""
        return [
            "Six-segment (all-combinations) method: additive constant of the instrument",
            f"  k = {self.k_mm:+.2f} mm ± {self.k_se_mm:.2f} mm;  "
            f"σ₀ of a distance {self.sigma0_mm:.2f} mm",
        ]


def six_segment_constant(data: pd.DataFrame | str | Path) -> SixSegmentResult:
    """Schwendener's six-segment (all-combinations) method (Liu & Zhang, eq. 1–2).

    ``data``: columns ``from, to, distance_m``; points in order along a straight line (their
    order of first appearance, or numeric ids); the model ``D_jk + C + v = x_k − x_j`` with
    x of the first point 0, unknowns C and the other points' positions. The scale error
    hides in the positions and does not bias C.
    """
    origin = None if isinstance(data, pd.DataFrame) else Path(data).name
    df = _table(data, ["from", "to", "distance_m"], origin)
    df = _numbers(df, ["distance_m"], origin or "the table")
    df["from"] = df["from"].astype(str).str.strip()
    df["to"] = df["to"].astype(str).str.strip()
    ids = list(dict.fromkeys(list(df["from"]) + list(df["to"])))
    try:
        ids = sorted(ids, key=float)
    except ValueError:
        pass
    n_pts = len(ids)
    pos = {p: i for i, p in enumerate(ids)}
    m = len(df)
    if n_pts < 3 or m < n_pts:
        raise InputError(
            f"the six-segment method needs at least 3 points and as many distances as "
            f"unknowns ({n_pts}); got {n_pts} points and {m} distances"
        )
    a = np.zeros((m, n_pts))  # unknowns: C, x_1 … x_{N}
    for r, (f, t) in enumerate(zip(df["from"], df["to"], strict=True)):
        i, j = sorted((pos[f], pos[t]))
        if i == j:
            raise InputError(f"row {r + 1}: a distance from point {f!r} to itself")
        a[r, 0] = -1.0
        if j > 0:
            a[r, j] += 1.0
        if i > 0:
            a[r, i] -= 1.0
    obs = df["distance_m"].to_numpy() * 1000.0
    if np.linalg.matrix_rank(a) < n_pts:
        raise InputError(
            "the distances do not tie every point to the others and the constant; "
            "measure all combinations between the points"
        )
    x, *_ = np.linalg.lstsq(a, obs, rcond=None)
    v = a @ x - obs
    dof = m - n_pts
    s0 = math.sqrt((v**2).sum() / dof) if dof > 0 else float("nan")
    cov = s0**2 * np.linalg.inv(a.T @ a) if dof > 0 else np.full((n_pts, n_pts), np.nan)
    segments = pd.Series(
        x[1:] / 1000.0, index=pd.Index(ids[1:], name="to"), name=f"from {ids[0]} [m]"
    )
    return SixSegmentResult(
        float(x[0]), float(math.sqrt(cov[0, 0])), segments, df.assign(residual_mm=v), s0
    )


# -- axis errors ----------------------------------------------------------------------------
@dataclass
class AxisResult:
    """Collimation c and trunnion-axis tilt i [deg] with standard errors."""

    c_deg: float
    c_se_deg: float
    i_deg: float
    i_se_deg: float
    orientation_deg: float | None
    residual_rms_arcsec: float
    residuals: pd.DataFrame

    def lines(self) -> list[str]:
        """The result in words (the command line and the dashboard print these)."""
        out = [
            f"Axis errors from {len(self.residuals)} directions (c / cos α + i·tan α):",
            f"  collimation c = {self.c_deg:.4f}° ± {self.c_se_deg:.4f}°  "
            f"({self.c_deg * 3600:.1f}″)",
            f"  trunnion-axis tilt i = {self.i_deg:.4f}° ± {self.i_se_deg:.4f}°  "
            f"({self.i_deg * 3600:.1f}″)",
        ]
        if self.orientation_deg is not None:
            out.append(
                f"  orientation of the scanner's zero direction: {self.orientation_deg:.4f}°"
            )
        out.append(
            f"  residual RMS of a direction after correction: {self.residual_rms_arcsec:.1f}″"
        )
        return out


def axis_error_effect(c: ArrayLike, i: ArrayLike, alpha_deg: ArrayLike) -> np.ndarray:
    """Effect of collimation c and trunnion-axis tilt i on a horizontal direction at vertical
    angle α — Liu & Zhang, eq. 5–6: ``c / cos α + i·tan α``.

    ``alpha_deg`` in degrees; the effect comes in the unit of ``c`` and ``i`` (the model is
    linear in them: degrees in :func:`axis_errors` and :func:`simulate_axes`, arc-seconds
    for ″). ``axis_error_effect(1, 0, α)`` and ``(0, 1, α)`` are its derivatives by c and i.
    Arrays broadcast; it grows without bound towards α = ±90°.

    Examples
    --------
    >>> axis_error_effect(10.0, 20.0, [0.0, 60.0]).round(4).tolist()  # ″ in, ″ out
    [10.0, 54.641]
    """
    alpha = np.radians(as_float_array(alpha_deg, "alpha_deg"))
    return as_float_array(c, "c") / np.cos(alpha) + as_float_array(i, "i") * np.tan(alpha)


def axis_errors(data: pd.DataFrame | str | Path, *, orientation: bool = True) -> AxisResult:
    """Collimation and trunnion-axis errors from directions at several vertical angles.

    ``data``: columns ``vertical_angle_deg`` (α), ``observed_deg`` (the scanner's horizontal
    direction) and ``reference_deg`` (from a total station). Model (Liu & Zhang, eq. 5–6):
    ``observed − reference = c / cos α + i·tan α`` (+ an orientation constant o when
    ``orientation`` is True: the scanner's and the reference's zero directions differ in
    practice; eq. 6 assumes them equal).
    """
    origin = None if isinstance(data, pd.DataFrame) else Path(data).name
    cols = ["vertical_angle_deg", "observed_deg", "reference_deg"]
    df = _numbers(_table(data, cols, origin), cols, origin or "the table")
    alpha_deg = df["vertical_angle_deg"].to_numpy()
    if (np.abs(df["vertical_angle_deg"]) >= 89).any():
        raise InputError(
            "vertical angles must be within ±89°: c / cos α and i·tan α blow up at the zenith"
        )
    diff = np.angle(np.exp(1j * np.radians(df["observed_deg"] - df["reference_deg"]).to_numpy()))
    # the design matrix: the model's derivatives by c and i (and o)
    cols_a = [axis_error_effect(1.0, 0.0, alpha_deg), axis_error_effect(0.0, 1.0, alpha_deg)]
    cols_a += [np.ones_like(alpha_deg)] if orientation else []
    a = np.column_stack(cols_a)
    need = a.shape[1]
    if len(df) <= need:
        raise InputError(f"the axis-error fit needs more than {need} directions; got {len(df)}")
    if np.linalg.cond(a) > 1e6:
        raise InputError(
            "the vertical angles are too alike to separate c from i"
            + (" and the orientation" if orientation else "")
            + "; observe targets at clearly different heights (e.g. −30° to +60°)"
        )
    x, *_ = np.linalg.lstsq(a, diff, rcond=None)
    v = diff - a @ x
    dof = len(df) - need
    s0 = math.sqrt((v**2).sum() / dof)
    se = np.sqrt(np.diag(s0**2 * np.linalg.inv(a.T @ a)))
    res = df.assign(residual_arcsec=v * RHO_ARCSEC)
    return AxisResult(
        float(np.degrees(x[0])),
        float(np.degrees(se[0])),
        float(np.degrees(x[1])),
        float(np.degrees(se[1])),
        float(np.degrees(x[2])) if orientation else None,
        float(np.sqrt(np.mean(v**2)) * RHO_ARCSEC),
        res,
    )


@dataclass
class SignalResult:
    """The ranging noise by returned signal, ``m_S = m_0·q^(−k)`` (:mod:`planner.signal`):
    ``m0_mm`` on the reference reflectance square to the beam, the exponent k, their
    standard errors, and each plane's residual against the fit."""

    m0_mm: float
    m0_se_mm: float
    k: float
    k_se: float
    reference_reflectance: float
    residuals: pd.DataFrame

    def lines(self) -> list[str]:
        """The result in words (the command line prints these)."""
        return [
            f"Ranging noise by returned signal from {len(self.residuals)} planes: "
            f"m_S = m_0 · q^(−k), q = ρ cos θ / {self.reference_reflectance:g}",
            f"  m_0 = {self.m0_mm:.3f} mm ± {self.m0_se_mm:.3f} mm (the reference surface "
            "square to the beam)",
            f"  k = {self.k:.3f} ± {self.k_se:.3f} (0.5: shot-noise limited; 0: no dependence)",
            "  fit residual RMS: "
            f"{float(np.sqrt(np.mean(self.residuals['misfit_pct'] ** 2))):.1f} %",
        ]


#: A signal calibration's planes must span at least this factor of signal (ρ cos θ).
MIN_SIGNAL_SPAN = 2.0


def signal_calibration(
    data: pd.DataFrame | str | Path,
    reference_reflectance: float = DEFAULT_REFERENCE_REFLECTANCE,
) -> SignalResult:
    """The ranging noise's law of the returned signal from planes of known reflectance.

    ``data``: one row per scanned plane — ``reflectance`` [0–1] (a calibrated plate, e.g.
    Spectralon 10 / 50 / 99 %), ``incidence_deg`` (the beam's angle to the plane's normal)
    and ``residual_rms_mm`` (the RMS of the plane fit's residuals along its normal). At a
    lab's short distances the angular noise's share is negligible, so a residual RMS is the
    ranging RMS times cos θ (Schmitz et al. 2019) and ``log(res / cos θ) = log m_0 − k·log q``
    is fitted by least squares.
    """
    origin = None if isinstance(data, pd.DataFrame) else Path(data).name
    cols = ["reflectance", "incidence_deg", "residual_rms_mm"]
    df = _numbers(_table(data, cols, origin), cols, origin or "the table")
    rho, inc, res = (df[c].to_numpy(float) for c in cols)
    if ((rho <= 0) | (rho > 1)).any():
        raise InputError("reflectance must be > 0 and <= 1 (a fraction: 0.5 for 50 %)")
    if ((inc < 0) | (inc >= 84)).any():
        raise InputError("incidence_deg must be from 0 to below 84 [deg]")
    if (res <= 0).any():
        raise InputError("residual_rms_mm must be > 0 [mm]")
    cos_t = np.cos(np.radians(inc))
    q = relative_signal(rho, cos_t, reference_reflectance)
    if q.max() / q.min() < MIN_SIGNAL_SPAN or len(df) < 3:
        raise InputError(
            "the fit needs at least 3 planes whose signal (reflectance × cos incidence) spans "
            f"a factor of {MIN_SIGNAL_SPAN:g}; scan plates of different reflectance (e.g. 10, "
            "50, 99 %) or one plate at several angles"
        )
    if (q <= MIN_SIGNAL).any():
        raise InputError("a plane returns less than 1 % of the reference's signal; leave it out")
    a = np.column_stack([np.ones_like(q), -np.log(q)])
    y = np.log(res / cos_t)
    x, *_ = np.linalg.lstsq(a, y, rcond=None)
    v = y - a @ x
    dof = max(len(y) - 2, 1)
    cov = (v @ v / dof) * np.linalg.inv(a.T @ a)
    m0 = float(np.exp(x[0]))
    out = df.assign(predicted_mm=np.exp(a @ x) * cos_t, misfit_pct=100.0 * (np.exp(v) - 1.0))
    return SignalResult(
        m0_mm=m0,
        m0_se_mm=m0 * float(np.sqrt(cov[0, 0])),
        k=float(x[1]),
        k_se=float(np.sqrt(cov[1, 1])),
        reference_reflectance=reference_reflectance,
        residuals=out,
    )


# -- the profile ----------------------------------------------------------------------------
def profile_from_calibration(
    name: str,
    *,
    base: Scanner | None = None,
    lab: LabTest | None = None,
    baseline: BaselineResult | None = None,
    axes: AxisResult | None = None,
    signal: SignalResult | None = None,
    range_from: str | None = None,
    angles_from: str | None = None,
    include_scale: bool = False,
) -> tuple[Scanner, list[str]]:
    """A scanner profile from calibration results, and the notes to show the user.

    ``range_from``: "lab" (m_r of distances), "baseline" (residual RMS after k and R) or
    "signal" (m_0 of :func:`signal_calibration`); a ``signal`` result also sets the
    profile's ranging exponent and reference reflectance;
    ``angles_from``: "lab" (m_r of φ and θ) or "axes" (residual RMS of the directions after
    c and i, horizontal only). Figures not chosen come from ``base`` (default:
    :data:`~planner.scanner.DEFAULT_SCANNER`, the Leica class of Voroshilov & Karachentsev).
    ``include_scale`` adds |R| as the ppm part, for data that will not be corrected for
    scale. The calibration is recorded in the profile's ``calibration`` table. ``name`` must
    be able to name a profile file (:func:`~planner.scanner.check_profile_name`).
    """
    name = check_profile_name(name)
    base = base or Scanner.from_name(DEFAULT_SCANNER)
    fig: dict[str, Any] = {
        "range_rms_mm": base.range_rms_mm,
        "range_ppm": base.range_ppm,
        "angle_rms_arcsec": base.angle_rms_arcsec,
        "vertical_angle_rms_arcsec": base.tilt_rms_arcsec,
    }
    record: dict[str, Any] = {"base_profile": base.name}
    notes: list[str] = []
    if range_from == "lab":
        if lab is None:
            raise InputError("range_from='lab' needs a lab test")
        fig["range_rms_mm"], fig["range_ppm"] = lab.m_r["distance_mm"], 0.0
    elif range_from == "baseline":
        if baseline is None:
            raise InputError("range_from='baseline' needs a baseline calibration")
        fig["range_rms_mm"] = baseline.residual_rms_mm
        fig["range_ppm"] = abs(baseline.scale_ppm) if include_scale else 0.0
        notes.append(
            f"correct distances by k = {baseline.k_mm:+.2f} mm and "
            f"R = {baseline.scale_ppm:+.1f} ppm"
            + ("" if include_scale else " (the profile assumes you do)")
        )
    elif range_from == "signal":
        if signal is None:
            raise InputError("range_from='signal' needs a signal calibration")
        fig["range_rms_mm"], fig["range_ppm"] = signal.m0_mm, 0.0
    elif range_from is not None:
        raise InputError(
            f"range_from must be 'lab', 'baseline', 'signal' or None; got {range_from!r}"
        )
    if angles_from == "lab":
        if lab is None:
            raise InputError("angles_from='lab' needs a lab test")
        fig["angle_rms_arcsec"] = lab.m_r["horizontal_arcsec"]
        fig["vertical_angle_rms_arcsec"] = lab.m_r["vertical_arcsec"]
        notes += lab.warnings
    elif angles_from == "axes":
        if axes is None:
            raise InputError("angles_from='axes' needs an axis-error fit")
        fig["angle_rms_arcsec"] = axes.residual_rms_arcsec
        notes.append(
            f"correct horizontal directions for c = {axes.c_deg:.4f}° and i = {axes.i_deg:.4f}°"
        )
    elif angles_from is not None:
        raise InputError(f"angles_from must be 'lab', 'axes' or None; got {angles_from!r}")
    if lab is not None:
        record["lab"] = {
            "k": lab.k,
            "pairs": len(lab.pairs),
            **{f"m_r_{a}": round(b, 4) for a, b in lab.m_r.items()},
            "helmert_sigma0_mm": round(lab.helmert.sigma0_mm, 4),
        }
    if baseline is not None:
        record["baseline"] = {
            "k_mm": round(baseline.k_mm, 4),
            "k_se_mm": round(baseline.k_se_mm, 4),
            "scale_ppm": round(baseline.scale_ppm, 3),
            "scale_se_ppm": round(baseline.scale_se_ppm, 3),
            "residual_rms_mm": round(baseline.residual_rms_mm, 4),
            "n": baseline.n,
        }
    if axes is not None:
        record["axes"] = {
            "c_deg": round(axes.c_deg, 6),
            "c_se_deg": round(axes.c_se_deg, 6),
            "i_deg": round(axes.i_deg, 6),
            "i_se_deg": round(axes.i_se_deg, 6),
            "residual_rms_arcsec": round(axes.residual_rms_arcsec, 3),
        }
    if signal is not None:
        record["signal"] = {
            "m0_mm": round(signal.m0_mm, 4),
            "k": round(signal.k, 4),
            "k_se": round(signal.k_se, 4),
            "reference_reflectance": signal.reference_reflectance,
            "planes": len(signal.residuals),
        }
        if not 0.0 <= signal.k <= RANGES["ranging_exponent"].hi:
            raise InputError(
                f"the signal calibration gives k = {signal.k:.3f}, outside 0 to "
                f"{RANGES['ranging_exponent'].hi:g}; check the planes' reflectances and residuals"
            )
    record["range_from"] = range_from or "base profile"
    record["angles_from"] = angles_from or "base profile"
    for key, unit, limit in (
        ("range_rms_mm", "mm", MAX_PROFILE_RANGE_RMS_MM),
        ("angle_rms_arcsec", "″", MAX_PROFILE_ANGLE_RMS_ARCSEC),
        ("vertical_angle_rms_arcsec", "″", MAX_PROFILE_ANGLE_RMS_ARCSEC),
    ):
        if fig[key] is not None and not fig[key] <= limit:
            raise InputError(
                f"the calibration gives {key} = {fig[key]:.4g} {unit}, beyond any working scanner "
                f"({limit:g} {unit}); check the measurements for blunders before making a profile"
            )
    scanner = Scanner(
        name=name,
        range_rms_mm=fig["range_rms_mm"],
        range_ppm=fig["range_ppm"],
        angle_rms_arcsec=fig["angle_rms_arcsec"],
        vertical_angle_rms_arcsec=fig["vertical_angle_rms_arcsec"],
        step_mm_at_10m=base.step_mm_at_10m,
        min_range_m=base.min_range_m,
        max_range_m=base.max_range_m,
        vertical_fov_deg=base.vertical_fov_deg,
        measurement_rate_hz=base.measurement_rate_hz,
        # m_0 is stated on the calibration's reference; the base's m_S on the base's
        reference_reflectance=(
            signal.reference_reflectance if range_from == "signal" else base.reference_reflectance
        ),
        ranging_exponent=signal.k if signal is not None else base.ranging_exponent,
        range_reflectance=base.range_reflectance,
        dark_range_m=base.dark_range_m,
        dark_reflectance=base.dark_reflectance,
        label=f"{name} (own calibration)",
        source=f"own calibration (tls-planner): ranging from {record['range_from']}, angles from "
        f"{record['angles_from']}; other figures from {base.name}",
        notes="; ".join(notes),
        extra={"calibration": record},
    )
    return scanner, notes


# -- simulation (tests, the shipped example, "what can my test setup resolve?") -------------
def simulate_lab(
    n_targets: int = 60,
    *,
    room_m: tuple[float, float, float] = (9.3, 7.0, 3.3),
    range_rms_mm: float = 1.5,
    angle_rms_arcsec: float = 20.0,
    angles_deg: tuple[float, float, float] = (0.02, -0.03, 37.2),
    translation_m: tuple[float, float, float] = (0.52, -2.28, 1.45),
    seed: int = 2,
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Targets on the walls and ceiling of a room (the Belgrade lab is 9.3 × 7 × 3.3 m) and their
    scanner-frame coordinates from noisy polar measurements (range, horizontal and vertical
    angle with the given RMS) by a scanner at ``translation_m`` rotated by ``angles_deg``.

    Returns ``(reference, scan)`` tables with columns ``id, x, y, z`` [m].
    """
    rng = np.random.default_rng(seed)
    lx, ly, lz = room_m
    pts = []
    for k in range(n_targets):
        wall = k % 5
        u, v = rng.uniform(0.05, 0.95, 2)
        if wall == 0:
            pts.append((u * lx, 0.0, v * lz))
        elif wall == 1:
            pts.append((u * lx, ly, v * lz))
        elif wall == 2:
            pts.append((0.0, u * ly, v * lz))
        elif wall == 3:
            pts.append((lx, u * ly, v * lz))
        else:
            pts.append((u * lx, v * ly, lz))
    ref = np.array(pts) - np.array([lx / 2, ly / 2, 0.0])
    rot = _rotation(*np.radians(angles_deg))
    t = np.array(translation_m)
    local = (ref - t) @ rot  # scanner frame: X_lab = R·X_scan + t
    s = np.linalg.norm(local, axis=1)
    hz = np.arctan2(local[:, 1], local[:, 0])
    vt = np.arcsin(local[:, 2] / s)
    s = s + rng.normal(0, range_rms_mm / 1000, len(s))
    hz = hz + rng.normal(0, angle_rms_arcsec / RHO_ARCSEC, len(s))
    vt = vt + rng.normal(0, angle_rms_arcsec / RHO_ARCSEC, len(s))
    scan = np.column_stack(
        [s * np.cos(vt) * np.cos(hz), s * np.cos(vt) * np.sin(hz), s * np.sin(vt)]
    )
    ids = [f"{k + 1}" for k in range(n_targets)]
    return (
        pd.DataFrame({"id": ids, "x": ref[:, 0], "y": ref[:, 1], "z": ref[:, 2]}),
        pd.DataFrame({"id": ids, "x": scan[:, 0], "y": scan[:, 1], "z": scan[:, 2]}),
    )


def simulate_baseline(
    k_mm: float = 3.9,
    scale_ppm: float = -30.0,
    noise_mm: float = 1.0,
    points_m: Sequence[float] = (0, 5, 10, 20, 30, 40, 50),
    seed: int = 4,
) -> pd.DataFrame:
    """All-combination distances on Liu & Zhang's baseline (points at 0, 5, 10, 20, 30, 40, 50 m)
    as an instrument with additive constant k and scale R measures them:
    ``D = (D_ref − k) / (1 + R)`` plus noise. Columns ``from, to, measured_m, reference_m``."""
    rng = np.random.default_rng(seed)
    rows = []
    for i in range(len(points_m)):
        for j in range(i + 1, len(points_m)):
            ref = points_m[j] - points_m[i]
            meas = (ref - k_mm / 1000) / (1 + scale_ppm * 1e-6) + rng.normal(0, noise_mm / 1000)
            rows.append(
                {"from": str(i + 1), "to": str(j + 1), "measured_m": meas, "reference_m": ref}
            )
    return pd.DataFrame(rows)


def simulate_axes(
    c_deg: float = 0.0075,
    i_deg: float = 0.0461,
    orientation_deg: float = 12.5,
    noise_arcsec: float = 2.0,
    alphas_deg: Sequence[float] = (-30, -15, 0, 10, 20, 35, 50, 60),
    seed: int = 5,
) -> pd.DataFrame:
    """Directions to targets at several vertical angles, affected by collimation c and
    trunnion-axis tilt i (Liu & Zhang's HDS3000 values by default)."""
    rng = np.random.default_rng(seed)
    alpha_deg = np.asarray(alphas_deg, dtype=float)
    reference = np.linspace(10.0, 170.0, len(alpha_deg))
    observed = (
        reference
        + orientation_deg
        + axis_error_effect(c_deg, i_deg, alpha_deg)
        + rng.normal(0, noise_arcsec / 3600, len(alpha_deg))
    )
    return pd.DataFrame(
        {
            "target": [chr(65 + k) for k in range(len(alpha_deg))],
            "vertical_angle_deg": alpha_deg,
            "observed_deg": observed % 360,
            "reference_deg": reference,
        }
    )


def simulate_signal(
    m0_mm: float = 1.0,
    k: float = 0.5,
    reflectances: Sequence[float] = (0.1, 0.5, 0.99),
    incidences_deg: Sequence[float] = (0.0, 30.0, 50.0, 65.0),
    points: int = 2000,
    reference_reflectance: float = DEFAULT_REFERENCE_REFLECTANCE,
    seed: int = 6,
) -> pd.DataFrame:
    """Planes of calibrated reflectance scanned at several incidences, each ``points`` points
    whose offsets along the normal have the RMS ``m_0·q^(−k)·cos θ``; the RMS of each plane's
    offsets is its ``residual_rms_mm`` (the columns :func:`signal_calibration` reads)."""
    rng = np.random.default_rng(seed)
    rows = []
    for rho in reflectances:
        for inc in incidences_deg:
            cos_t = math.cos(math.radians(inc))
            q = float(relative_signal(rho, cos_t, reference_reflectance))
            sigma = m0_mm * q**-k * cos_t
            res = float(np.sqrt(np.mean(rng.normal(0.0, sigma, points) ** 2)))
            rows.append({"reflectance": rho, "incidence_deg": inc, "residual_rms_mm": res})
    return pd.DataFrame(rows)
