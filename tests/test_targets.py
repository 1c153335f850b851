"""Sossa's 2d / 4d rule beyond the tables: inverse, inventory, incidence."""

from __future__ import annotations

import numpy as np
import pytest

from planner import (
    DEFAULT_INVENTORY,
    InputError,
    Scanner,
    TargetItem,
    max_target_distance_m,
    min_target_size_mm,
    point_spacing_mm,
    recommend_targets,
)
from planner.targets import choose_target


def test_scanner_step_is_used_and_finer_steps_scale_distances():
    hds = Scanner.from_name("leica-hds3000")  # 1 mm at 10 m
    assert point_spacing_mm(50.0, hds) == pytest.approx(5.0)  # mm
    assert min_target_size_mm(50.0, "sphere", scanner=hds) == pytest.approx(20.0)  # mm
    # "with a finer scan step the usable distances grow in proportion"
    assert max_target_distance_m(200, "sphere", step_mm_at_10m=1.0) == pytest.approx(
        2 * max_target_distance_m(200, "sphere", step_mm_at_10m=2.0)
    )


def test_inverse_rule_and_the_papers_practice():
    # 2 mm step: a 150 mm cylinder serves to 187.5 m ("not beyond ~150–200 m"),
    # a 200 mm sphere to 250 m, a 400 mm sphere to 500 m.
    assert max_target_distance_m(150, "cylinder") == pytest.approx(187.5)  # m
    assert max_target_distance_m(200, "sphere") == pytest.approx(250.0)  # m
    assert max_target_distance_m(400, "sphere") == pytest.approx(500.0)  # m


def test_flat_70mm_claim_of_the_text_disagrees_with_its_table():
    """Sossa's text says flat surfaces of >= 70 mm side serve the whole range to 350 m; the
    paper's own Table 2 asks 2d = 140 mm at 350 m. The rule wins: 70 mm serves to 175 m."""
    assert min_target_size_mm(350, "flat") == pytest.approx(140.0)  # mm
    assert max_target_distance_m(70, "flat") == pytest.approx(175.0)  # m


def test_oblique_flat_target_needs_more():
    assert min_target_size_mm(100, "flat", incidence_deg=60) == pytest.approx(80.0)  # 40/cos 60
    assert min_target_size_mm(100, "sphere", incidence_deg=60) == pytest.approx(80.0)  # isotropic
    assert max_target_distance_m(80, "flat", incidence_deg=60) == pytest.approx(100.0)
    with pytest.raises(InputError, match="incidence_deg"):
        min_target_size_mm(100, "flat", incidence_deg=120)


def test_recommendation_for_a_distance():
    rec = recommend_targets(200.0)
    by_name = rec.set_index("name")
    assert by_name.loc["sphere-200", "qualifies"]  # 160 mm needed
    assert not by_name.loc["cylinder-150", "qualifies"]  # 160 mm needed
    assert not by_name.loc["flat-70", "qualifies"]  # 80 mm needed
    assert by_name.loc["flat-70", "min_size_mm"] == pytest.approx(80.0)
    assert rec["qualifies"].tolist() == sorted(rec["qualifies"], reverse=True)
    custom = recommend_targets(30.0, [("b-w-6in", "flat", 152.4)], step_mm_at_10m=3.0)
    assert custom.loc[0, "max_distance_m"] == pytest.approx(254.0)  # 152.4·10/(2·3)


def test_choose_target_picks_the_smallest_that_fits():
    assert choose_target(150.0, "sphere").name == "sphere-200"
    assert choose_target(250.0, "sphere").name == "sphere-400"
    assert choose_target(500.0, "sphere") is None
    assert len(DEFAULT_INVENTORY) == 4


def test_bad_target_input():
    with pytest.raises(InputError, match="flat, sphere, cylinder"):
        min_target_size_mm(10, "cone")
    with pytest.raises(InputError, match="size_mm must be >= 1"):
        TargetItem("x", "flat", -3)
    with pytest.raises(InputError, match="inventory is empty"):
        recommend_targets(10, [])
    with pytest.raises(InputError, match="step_mm_at_10m must be one number > 0"):
        point_spacing_mm(10, step_mm_at_10m=0)
    with pytest.raises(InputError, match="give a scanner or step_mm_at_10m"):
        point_spacing_mm(10)
    np.testing.assert_array_equal(point_spacing_mm([np.nan], step_mm_at_10m=2), [np.nan])
