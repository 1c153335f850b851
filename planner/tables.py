"""The papers' tables, rebuilt from the formulas for any scanner (pandas DataFrames).

Used by the command line, the notebooks and the figures; no science lives here.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from planner.accuracy import height_rms, planimetric_rms
from planner.scanner import Scanner
from planner.spacing import point_spacing_mm
from planner.targets import SOSSA_STEP_MM_AT_10M, TARGET_TYPES, min_target_size_mm

__all__ = [
    "PAPER_DISTANCES_M",
    "PAPER_GAMMAS_DEG",
    "PAPER_NUS_DEG",
    "SOSSA_DISTANCES_M",
    "height_table",
    "planimetric_table",
    "target_size_table",
]

#: Rows of Tables 1–2 of Voroshilov & Karachentsev [m].
PAPER_DISTANCES_M: tuple[float, ...] = (10, 20, 30, 40, 50, 60, 80, 100, 120)
PAPER_GAMMAS_DEG: tuple[float, ...] = (0, 30, 60)
PAPER_NUS_DEG: tuple[float, ...] = (0, 30, 60, 90)
#: Columns of Sossa's Tables 1–2 [m].
SOSSA_DISTANCES_M: tuple[float, ...] = (50, 100, 150, 200, 250, 300, 350)


def planimetric_table(
    scanner: Scanner,
    distances_m: Sequence[float] = PAPER_DISTANCES_M,
    gammas_deg: Sequence[float] = PAPER_GAMMAS_DEG,
    station_rms_mm: float | tuple[float, float] = 0.0,
) -> pd.DataFrame:
    """m_x and m_y [mm] vs D (rows) and γ (columns) — the layout of Table 1 of Voroshilov &
    Karachentsev.

    Columns are a MultiIndex ``(component, γ)`` with component ``m_x`` or ``m_y``.
    """
    d = np.asarray(distances_m, dtype=float)[:, None]
    g = np.asarray(gammas_deg, dtype=float)[None, :]
    m_x, m_y = planimetric_rms(d, g, scanner, station_rms_mm)
    cols = pd.MultiIndex.from_product(
        [["m_x", "m_y"], list(gammas_deg)], names=["rms", "gamma_deg"]
    )
    df = pd.DataFrame(
        np.hstack([m_x, m_y]), index=pd.Index(list(distances_m), name="D_m"), columns=cols
    )
    return df


def height_table(
    scanner: Scanner,
    slope_distances_m: Sequence[float] = PAPER_DISTANCES_M,
    nus_deg: Sequence[float] = PAPER_NUS_DEG,
) -> pd.DataFrame:
    """m_z [mm] vs S (rows) and ν (columns) — the layout of Table 2 of Voroshilov & Karachentsev."""
    s = np.asarray(slope_distances_m, dtype=float)[:, None]
    nu = np.asarray(nus_deg, dtype=float)[None, :]
    m_z = height_rms(s, nu, scanner)
    return pd.DataFrame(
        m_z,
        index=pd.Index(list(slope_distances_m), name="S_m"),
        columns=pd.Index(list(nus_deg), name="nu_deg"),
    )


def target_size_table(
    distances_m: Sequence[float] = SOSSA_DISTANCES_M,
    step_mm_at_10m: float = SOSSA_STEP_MM_AT_10M,
) -> pd.DataFrame:
    """Point spacing d and minimum target sizes [mm] vs distance — Sossa's Table 2 layout.

    Rows ``d``, ``flat``, ``sphere``, ``cylinder``; one column per distance [m].
    """
    rows = {"d": point_spacing_mm(list(distances_m), step_mm_at_10m=step_mm_at_10m)}
    for t in TARGET_TYPES:
        rows[t] = min_target_size_mm(list(distances_m), t, step_mm_at_10m=step_mm_at_10m)
    df = pd.DataFrame(rows, index=pd.Index(list(distances_m), name="distance_m")).T
    df.index.name = "mm"
    return df
