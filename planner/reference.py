"""The papers: how they are cited, their printed tables, and the tables' comparison with the
formulas.

:data:`REFERENCES` is the one place a citation is written; code, reports and messages use
it (or its short key in a docstring). The printed tables are transcribed once and used by
the tests, the figures and the accuracy notebook, so that a misprint is recorded in one
place. Printed values are as in the papers (decimal commas read as points). Where a venue,
year or DOI is not printed in the copy the project worked from, the citation says so rather
than guess.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from planner.scanner import DEFAULT_SCANNER, Scanner
from planner.tables import height_table, planimetric_table, target_size_table

__all__ = [
    "REFERENCES",
    "SOSSA_TABLE2",
    "VOROSHILOV_TABLE1",
    "VOROSHILOV_TABLE2",
    "compare_sossa_table2",
    "compare_table1",
    "compare_table2",
]

#: Full citations by short key (the key is what docstrings use: "Voroshilov & Karachentsev").
REFERENCES: dict[str, str] = {
    "voroshilov": (
        'A. P. Voroshilov, Yu. A. Karachentsev, "Choice of station location at surface laser '
        'scanning of buildings and constructions" (in Russian: «Выбор местоположения станций '
        "при наземном лазерном сканировании зданий и сооружений»), eq. 1–4, Tables 1–2; "
        "journal and year are not printed in the copy used"
    ),
    "sossa": (
        'B. R. Sossa, "Determination of optimal type and size of plane-based targets used in '
        'terrestrial laser scanners calibration" (in Ukrainian), Inzhenerna heodeziia '
        "(Engineering Geodesy), issue 65, 2018, ISSN 0130-6014, Tables 1–2"
    ),
    "belgrade": (
        '"Laboratory procedure for terrestrial laser scanners calibration" (in Serbian), '
        "Metrology Laboratory, Faculty of Civil Engineering, University of Belgrade, eq. 1–9 and "
        "Table 3; authors and venue are not printed in the copy used"
    ),
    "liu-zhang": (
        'Liu Chun, Zhang Yunling (Tongji University), "Calibration and accuracy assessment of '
        'terrestrial 3-D laser scanners" (in Chinese: «地面三维激光扫描仪的检校与精度评估»), '
        "baseline and six-segment models, eq. 5–6 (axis errors), Leica HDS3000 figures; venue "
        "and year are not printed in the copy used"
    ),
    "xia2020": (
        'Xia Guisuo, Niu Zhisheng, Liu Fang, Fu Yanjun, "Error analysis and calibration of '
        'terrestrial 3D laser scanner", Chinese Journal of Sensors and Actuators 33(11), 2020, '
        "doi:10.3969/j.issn.1004-1699.2020.11.014"
    ),
    "checkerboard-scene": (
        'Laserscanning Europe, "Principle of detection of checkerboard targets in FARO Scene": '
        "an incidence of at most 45°, at least 4 scan points on each quadrant; "
        "https://www.laserscanning-europe.com/en/principle-detection-checkerboard-targets-faro-scene"
    ),
    "ghilani": (
        "C. D. Ghilani, Adjustment Computations: Spatial Data Analysis, 6th ed., Wiley, 2017: "
        "least squares, the propagation of covariances, three-dimensional conformal "
        "(rigid-body) coordinate transformations"
    ),
    "al-sharadqah-chernov": (
        'A. Al-Sharadqah, N. Chernov, "Error analysis for circle fitting algorithms", '
        "Electronic Journal of Statistics 3:886–911, 2009, doi:10.1214/09-EJS419: the "
        "second-order error analysis of geometric fits (their bias), carried out by the "
        "planner for a sphere of known radius"
    ),
    "triggs2000": (
        'B. Triggs, P. McLauchlan, R. Hartley, A. Fitzgibbon, "Bundle adjustment — a modern '
        'synthesis", Vision Algorithms: Theory and Practice, LNCS 1883, Springer, 2000, '
        "doi:10.1007/3-540-44480-7_21: targets and poses adjusted together"
    ),
    "segal2009": (
        'A. Segal, D. Haehnel, S. Thrun, "Generalized-ICP", Robotics: Science and Systems V, '
        "2009, doi:10.15607/RSS.2009.V.021: the registration each cloud link is rehearsed with"
    ),
    "koide2024": (
        'K. Koide, "small_gicp: Efficient and parallel algorithms for point cloud '
        'registration", Journal of Open Source Software 9(100):6948, 2024, '
        "doi:10.21105/joss.06948: the implementation of it the planner runs"
    ),
    "deformation-tls": (
        '"Experimental study of the deformation accuracy of terrestrial 3-D laser scanners" '
        "(in Chinese: «地面三维激光扫描仪变形精度试验研究»): Leica ScanStation2 modelled surface "
        "±2 mm, target acquisition ±1.5 mm at 50 m; authors and venue are not printed in the "
        "copy used"
    ),
}

_D = [10, 20, 30, 40, 50, 60, 80, 100, 120]

#: Voroshilov & Karachentsev, Table 1 as printed: m_x, m_y [mm] vs D [m] for γ = 0°, 30°, 60°.
VOROSHILOV_TABLE1 = pd.DataFrame(
    {
        ("m_x", 0): [0.6, 1.2, 1.8, 2.4, 3.0, 3.6, 4.8, 6.0, 7.2],
        ("m_x", 30): [2.1, 2.2, 2.5, 2.9, 3.3, 3.7, 4.6, 5.6, 6.6],
        ("m_x", 60): [3.5, 3.5, 3.6, 3.7, 3.8, 3.9, 4.2, 4.6, 5.0],
        ("m_y", 0): [4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 4.0],
        ("m_y", 30): [3.5, 3.5, 3.6, 3.7, 3.8, 3.9, 4.2, 4.6, 5.0],
        ("m_y", 60): [2.0, 2.1, 2.2, 2.3, 2.5, 2.7, 3.1, 3.6, 4.1],
    },
    index=pd.Index(_D, name="D_m"),
)
VOROSHILOV_TABLE1.columns = pd.MultiIndex.from_tuples(
    VOROSHILOV_TABLE1.columns, names=["rms", "gamma_deg"]
)

#: Voroshilov & Karachentsev, Table 2 as printed: m_z [mm] vs S [m] for ν = 0°, 30°, 60°, 90°.
VOROSHILOV_TABLE2 = pd.DataFrame(
    {
        0: [0.8, 1.7, 2.5, 3.4, 4.2, 5.1, 6.8, 8.4, 10.0],
        30: [2.2, 2.5, 3.1, 3.8, 4.4, 5.2, 6.6, 8.2, 9.7],
        60: [3.6, 3.7, 4.0, 4.4, 4.8, 5.3, 6.4, 7.6, 8.8],
        90: [4.0, 4.2, 4.4, 4.7, 5.0, 5.4, 6.2, 7.2, 8.2],
    },
    index=pd.Index(_D, name="S_m"),
)
VOROSHILOV_TABLE2.columns.name = "nu_deg"

#: Sossa, Table 2 as printed (step 2 mm at 10 m): d and minimum sizes [mm] vs distance [m].
SOSSA_TABLE2 = pd.DataFrame(
    [
        [10, 20, 30, 40, 50, 60, 70],
        [20, 40, 60, 80, 100, 120, 140],
        [40, 80, 120, 160, 200, 240, 280],
        [40, 80, 120, 160, 200, 240, 280],
    ],
    index=pd.Index(["d", "flat", "sphere", "cylinder"], name="mm"),
    columns=pd.Index([50, 100, 150, 200, 250, 300, 350], name="distance_m"),
    dtype=float,
)

#: Table 1 is printed to 0.1 mm: half a unit plus 0.01 mm for the hand arithmetic.
TABLE1_TOLERANCE_MM = 0.06
#: Table 2 was rounded both up and down (3.53 → 3.6, 0.85 → 0.8): one printed unit.
TABLE2_TOLERANCE_MM = 0.10


def _compare(printed: pd.DataFrame, computed: pd.DataFrame, tol: float) -> pd.DataFrame:
    out = pd.DataFrame(
        {
            "printed_mm": printed.stack(list(range(printed.columns.nlevels)), future_stack=True),
            "computed_mm": computed.stack(list(range(computed.columns.nlevels)), future_stack=True),
        }
    )
    out["diff_mm"] = out["computed_mm"] - out["printed_mm"]
    out["misprint"] = np.abs(out["diff_mm"]) > tol
    return out


def compare_table1(scanner: Scanner | None = None) -> pd.DataFrame:
    """Voroshilov & Karachentsev's Table 1, printed vs eq. 2, one row per cell, misprints flagged.

    The whole m_y(γ = 60°) column is a misprint: the paper printed
    cos γ·√(m_S² + (D·m_β/ρ)²), i.e. used cos²γ where eq. 2 has sin²γ.
    """
    sc = scanner or Scanner.from_name(DEFAULT_SCANNER)
    computed = planimetric_table(sc, _D, [0, 30, 60])
    return _compare(VOROSHILOV_TABLE1, computed, TABLE1_TOLERANCE_MM)


def compare_table2(scanner: Scanner | None = None) -> pd.DataFrame:
    """Voroshilov & Karachentsev's Table 2, printed vs eq. 4 (S_0 = S, m_ν0 = m_ν), misprints
    flagged.

    Two cells of the ν = 0° column are slips: 8.4 mm at 100 m and 10.0 mm at 120 m, where
    eq. 4 gives 8.50 and 10.20 mm.
    """
    sc = scanner or Scanner.from_name(DEFAULT_SCANNER)
    computed = height_table(sc, _D, [0, 30, 60, 90])
    return _compare(VOROSHILOV_TABLE2, computed, TABLE2_TOLERANCE_MM)


def compare_sossa_table2() -> pd.DataFrame:
    """Sossa's Table 2, printed vs the 2d / 4d rule (no misprints)."""
    return _compare(SOSSA_TABLE2, target_size_table(list(SOSSA_TABLE2.columns), 2.0), 1e-9)
