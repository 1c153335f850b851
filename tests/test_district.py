"""District mode: blocks with a halo planned on a tiny Dask cluster and stitched into one
plan — a valid cover, ids unique and consistent, the bound honest against the
single-process plan."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pandas as pd
import pytest
from sites import rect
from sites import run_cli as cli

from planner.errors import InputError
from planner.pipeline.district.blocks import block_region, block_site, partition
from planner.pipeline.district.schedule import local_cluster, plan_district
from planner.pipeline.district.stitch import stitch
from planner.pipeline.engine.judge import workbench_of
from planner.pipeline.engine.planning import plan
from planner.pipeline.inputs.requirements import PlanSettings, Requirements
from planner.scanner import load_scanner
from planner.site import Building, Passage, Site
from planner.synthetic import town

#: No level run (height control "none"): these tests are of the district's datum and seams
#: as the blocks' networks lean (a level run in every block holds each one's own vertical:
#: tests/test_height_control.py).
SETTINGS = PlanSettings(
    grid_m=4, sample_spacing_m=4, sample_height_step_m=4, time_limit_s=300, height_control="none"
)
#: The paper's scanner with a compensator (1.5″): without one the district's frame leans
#: with one datum's tilt, 6 mm at 100 m, and the far blocks' heights could not meet 5 mm.
#: The blocks planned in this process (``blockwise``) use the paper's own scanner, without.
UNLEVELLED = load_scanner("leica-4mm-60urad")
SCANNER = replace(
    load_scanner("leica-4mm-60urad"), name="leica-4mm-60urad-levelled", levelling_rms_arcsec=1.5
)


@pytest.fixture(scope="module")
def district():
    site = town(12, seed=0)
    return site, partition(site, 80.0)


def test_partition_puts_every_planned_building_in_one_block(district):
    site, blocks = district
    assert len(blocks) >= 2
    ids = [b for blk in blocks for b in blk.buildings]
    assert sorted(ids) == sorted(b.id for b in site.planned)


def test_a_block_site_keeps_its_halo_as_blockers(district):
    site, blocks = district
    sub = block_site(site, blocks[0], halo_m=60.0)
    assert {b.id for b in sub.planned} == set(blocks[0].buildings)
    others = {b.id for b in sub.buildings if not b.planned}
    assert others and others.isdisjoint(blocks[0].buildings)
    assert block_site(site, blocks[0], halo_m=0.0).buildings != sub.buildings


def test_a_block_site_keeps_a_passage_with_its_building():
    """A gateway drawn a little beyond its building's walls reaches into the halo of a
    block the building is not in: that block's site leaves it out (it would be a passage
    through nothing, an error), a block that holds the building keeps it."""
    near, far = (
        Building("near", rect(0, 0, 20, 20), 10.0),
        Building("far", rect(100, 0, 120, 20), 10.0),
    )
    gate = Passage("gate", rect(95, 8, 125, 12), 3.0)  # 5 m beyond either wall
    site = Site([near, far], passages=[gate])
    block = next(b for b in partition(site, 80.0) if b.buildings == ("near",))
    assert gate.geometry.intersects(block_region(block, 77.0))  # in the halo, its building not
    assert block_site(site, block, 77.0).passages == []
    assert block_site(site, block, 85.0).passages == [gate]  # the building in the halo
    # a seam's context over a region holding the gateway's end but not its building
    from planner.pipeline.network.seams import context_of

    make = context_of(site, UNLEVELLED, Requirements(), SETTINGS, 60.0)
    assert make(rect(15, 0, 99, 20)).site.passages == []
    assert make(rect(15, 0, 101, 20)).site.passages == [gate]


@pytest.fixture(scope="module")
def stitched(district):
    site, _ = district
    return plan_district(site, SCANNER, settings=SETTINGS, block_m=80.0, workers=1)


def test_stitched_plan_is_a_valid_cover(stitched, district):
    site, blocks = district
    p = stitched
    assert p.solver.blocks == len(blocks)
    assert p.stations["station_id"].is_unique and p.targets["target_id"].is_unique
    ids = set(p.stations["station_id"])
    assert all(s in ids for sids in p.targets["station_ids"] for s in sids)
    assert set(p.links["station_b"]) <= ids
    assert set(p.links["station_a"]) <= ids | {"control"}
    cov = p.scanned
    assert set(cov["building_id"]) == {b.id for b in site.planned}
    assert cov["sample_id"].is_unique
    # every sample some station can meet is met (the rest say why)
    coverable = cov[cov["stations_meeting"] > 0]
    assert coverable["meets"].mean() > 0.97
    assert (cov.loc[~cov["meets"], "reason"] != "").all()
    assert set(cov.loc[cov["meets"], "station_id"]) <= ids
    assert len(p.route.table) == len(p.stations)
    # a levelled scanner's frame does not lean: a note of samples the frame takes over, if
    # any, names no datum
    assert not [m for m in p.messages if "common frame" in m and "datum" in m]


def test_stitched_matches_the_single_process_plan_within_its_bound(stitched, district):
    site, _ = district
    whole = plan(site, SCANNER, settings=SETTINGS)
    s, w = stitched.solver, whole.solver
    assert s.lower_bound <= w.objective  # the district's bound is a true bound
    # the blocks' covers meet every sample the scanner can; the stations removed on block
    # edges after that only had to keep the samples met with registration, which a
    # neighbour's station meets: the count to compare with the whole's cover is the one
    # before they went
    cover = s.objective + s.redundant_removed
    assert w.lower_bound <= cover
    assert abs(cover - w.objective) <= cover - s.lower_bound
    assert s.lower_bound <= s.block_bound_sum
    assert 0 < s.shared_bound <= s.lower_bound + 1 - 1e-6


def test_unreachable_scheduler_is_exit_2(tmp_path, monkeypatch):
    from planner.pipeline.district import schedule

    monkeypatch.setattr(schedule, "SCHEDULER_TIMEOUT_S", 0.5)  # nothing answers on port 9
    code, _, err = cli(
        "plan", "--scheduler", "tcp://127.0.0.1:9", "--out", str(tmp_path / "p"), "-q"
    )
    assert code == 2 and "cannot reach a Dask scheduler" in err
    assert not (tmp_path / "p").exists()


def test_a_worker_that_dies_is_exit_2_and_nothing_written(tmp_path):
    """A worker that dies while planning a block (as Dask's nanny stops one past its memory
    limit) is an exit-2 message naming the block, and nothing is written."""
    import dask
    from dask.distributed import Client, LocalCluster

    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
        cluster = LocalCluster(
            n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None
        )
    with cluster, Client(cluster) as client:
        client.run(  # in the worker's process: planning a block ends it
            exec,
            "import os, planner.pipeline.district.blocks as d\n"
            "d.plan_block = lambda *a, **k: os._exit(1)",
        )
        out = tmp_path / "p"
        code, _, err = cli("plan", "--scheduler", cluster.scheduler_address, "--out", str(out))
    assert code == 2, err
    assert "the worker planning block K01 (1 building) died" in err
    assert "the cluster's limit" in err and "Traceback" not in err
    assert not out.exists()


def test_a_worker_that_dies_on_the_bound_leaves_the_plan_standing(tmp_path):
    """The bound's LPs run after the blocks are planned: a worker dying there costs the
    shared-station bound (the far-apart one stays), not the plan."""
    import dask
    from dask.distributed import Client, LocalCluster

    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
        cluster = LocalCluster(
            n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None
        )
    with cluster, Client(cluster) as client:
        client.run(
            exec,
            "import os, planner.pipeline.district.bounds as d\n"
            "d.shared_bound = lambda *a, **k: os._exit(1)",
        )
        out = tmp_path / "p"
        code, _, err = cli("plan", "--scheduler", cluster.scheduler_address, "--out", str(out))
    assert code in (0, 1), err
    assert "Traceback" not in err
    summary = (out / "summary.txt").read_text()
    assert "bound on shared stations was not computed" in summary


@pytest.mark.parametrize(
    ("option", "message"),
    [
        (("--workers", "0"), "argument --workers: must be a whole number >= 1"),
        (("--worker-memory", "lots"), "worker memory 'lots' is not a size"),
        (("--worker-memory", "100MB"), "at least 256 MB"),
    ],
)
def test_bad_cluster_options_are_exit_2(tmp_path, option, message):
    code, _, err = cli("plan", "--district", "on", *option, "--out", str(tmp_path / "p"))
    assert code == 2 and message in err, err
    assert not (tmp_path / "p").exists()


def test_block_size_is_checked(district):
    with pytest.raises(InputError, match="must be >= 20"):
        partition(district[0], 5.0)


def test_a_crowded_block_is_split_until_it_fits():
    site = town(60, seed=1)
    blocks = partition(site, 250.0, max_buildings=8)
    assert max(len(b.buildings) for b in blocks) <= 8
    ids = [b for blk in blocks for b in blk.buildings]
    assert sorted(ids) == sorted(b.id for b in site.planned)  # each exactly once
    assert len(partition(site, 250.0, max_buildings=1000)) < len(blocks)


def test_local_workers_keep_the_dynamic_mmap_threshold():
    """Dask's MALLOC_TRIM_THRESHOLD_ alone turns glibc's dynamic mmap threshold off and
    slowed the evaluation 2.5 times; the local workers get a fixed 64 MB threshold too."""
    import os

    from dask.distributed import Client

    with local_cluster(1, "1GB") as cluster, Client(cluster) as client:
        env = client.run(lambda: os.environ.get("MALLOC_MMAP_THRESHOLD_"))
    assert list(env.values()) == [str(64 * 2**20)]


def _table(rows):
    """A meeting table from (facade, sample, station, own) rows on distinct points."""
    from planner.pipeline.inputs.schema import MEETING_COLUMNS, METRIC_KEYS

    out = pd.DataFrame(
        [
            {"facade_id": f, "sample_id": s, "x": float(int(s[1:])), "y": 0.0, "z": 1.0}
            | {"station_id": st, "own": own, "needed": 1.0 if own else np.nan}
            for f, s, st, own in rows
        ]
    )
    for k in METRIC_KEYS:
        out[k] = 1.0
    return out[MEETING_COLUMNS + list(METRIC_KEYS)]


def test_a_station_another_block_makes_redundant_is_found():
    from planner.pipeline.district.stitch import redundant_stations

    stations = pd.DataFrame(
        {"station_id": ["K1-S01", "K1-S02", "K2-S01"], "purpose": ["cover"] * 3}
    )
    coverage = pd.DataFrame(
        {
            "facade_id": ["a", "a", "b"],
            "sample_id": ["s1", "s2", "s3"],
            "x": [1.0, 2.0, 3.0],
            "y": 0.0,
            "z": 1.0,
            "station_id": ["K1-S01", "K1-S02", "K2-S01"],
            "meets": True,
            "party_wall": False,
            "zone": "",
        }
    )
    meeting = _table(
        [
            ("a", "s1", "K1-S01", True),
            ("a", "s2", "K1-S02", True),
            ("b", "s3", "K2-S01", True),
            ("a", "s1", "K2-S01", False),  # K2-S01 also meets K1's s1
        ]
    )
    links = pd.DataFrame({"station_a": ["K1-S02"], "station_b": ["K1-S01"]})
    assert redundant_stations(stations, coverage, links, meeting) == ["K1-S01"]
    # a station others are registered to stays
    parent = pd.DataFrame({"station_a": ["K1-S01"], "station_b": ["K1-S02"]})
    assert redundant_stations(stations, coverage, parent, meeting) == []
    # the other block's view must be of the same point
    moved = meeting.copy()
    moved.loc[3, "x"] += 0.01
    assert redundant_stations(stations, coverage, links, moved) == []
    # … and that view is not one a moved sample can be given either
    from planner.pipeline.district.stitch import _counting_pairs

    assert len(_counting_pairs(coverage, moved)) == 3
    assert len(_counting_pairs(coverage, meeting)) == 4
    # and outside zones (a zone's requirement is its own block's)
    zoned = coverage.assign(zone=["Z1", "", ""])
    assert redundant_stations(stations, zoned, links, meeting) == []
    # two stations of two blocks, each meeting the other's sample too: one goes, never both
    both = _table(
        [
            ("a", "s1", "K1-S01", True),
            ("a", "s1", "K2-S01", False),
            ("b", "s3", "K2-S01", True),
            ("b", "s3", "K1-S01", False),
        ]
    )
    assert redundant_stations(stations, coverage, links, both) == ["K1-S01"]
    # a station an unmet sample is scanned from stays (its values are that sample's best)
    unmet = pd.concat([coverage, coverage.iloc[[0]].assign(sample_id="s9", meets=False)])
    assert redundant_stations(stations, unmet, links, meeting) == []
    wall = unmet.assign(party_wall=[False, False, False, True])  # not scanned: pins nothing
    assert redundant_stations(stations, wall, links, meeting) == ["K1-S01"]


@pytest.fixture(scope="module")
def blockwise(district):
    """The blocks of the small district planned in this process, with their meeting tables."""
    from planner.pipeline.district.blocks import block_region, meeting_table
    from planner.pipeline.inputs.resolved import reach_m

    site, blocks = district
    req = Requirements()
    halo = reach_m(UNLEVELLED, req, SETTINGS)
    plans = [plan(block_site(site, b, halo), UNLEVELLED, req, SETTINGS) for b in blocks]
    tables = [meeting_table(p, block_region(b, halo)) for p, b in zip(plans, blocks, strict=True)]
    return site, blocks, plans, tables, halo


def test_the_meeting_table_agrees_with_the_coverage(blockwise):
    import shapely

    from planner.pipeline.district.blocks import block_region

    _, blocks, plans, tables, halo = blockwise
    assert any((~t["own"]).any() for t in tables)  # stations do meet samples across edges
    for b, p, t in zip(blocks, plans, tables, strict=True):
        # another block's samples only where no building outside this block's site can block
        other = t[~t["own"]]
        assert shapely.contains_xy(block_region(b, halo), other["x"], other["y"]).all()
        own = t[t["own"]]
        counts = own.groupby(["facade_id", "sample_id"]).size()
        cov = p.scanned.set_index(["facade_id", "sample_id"])
        met = cov[cov["meets"]]
        assert (counts.reindex(met.index).fillna(0) == met["stations_meeting"]).all()
        assert not t[~t["own"]]["facade_id"].isin(cov.index.get_level_values(0)).any()


def test_stitching_removes_redundant_stations_and_keeps_every_sample(blockwise):
    site, blocks, plans, tables, halo = blockwise
    req = Requirements()
    plain = stitch(site, UNLEVELLED, req, SETTINGS, blocks, plans, halo)
    lean = stitch(site, UNLEVELLED, req, SETTINGS, blocks, plans, halo, tables)
    removed = lean.solver.redundant_removed
    assert removed >= 1
    assert len(lean.stations) == len(plain.stations) - removed
    assert lean.solver.objective == plain.solver.objective - removed
    a, b = plain.scanned.set_index("sample_id"), lean.scanned.set_index("sample_id")
    assert (a["meets"] == b.loc[a.index, "meets"]).all()  # nothing met is lost
    ids = set(lean.stations["station_id"])
    assert set(b["station_id"]) <= ids | {""}
    # an unmet sample keeps its station and values, and its reason names stations of the plan
    unmet = ~a["meets"] & ~a["party_wall"]
    assert unmet.sum() > 0
    for k in ("station_id", "m_x_mm", "m_z_mm", "reason"):
        pd.testing.assert_series_equal(a.loc[unmet, k], b.loc[a.index[unmet], k])
    assert set(b["reason"].str.extractall(r"station ([A-Z]\S*\d)")[0]) <= ids
    # a reason naming a block's station names it by its id in the whole plan
    import copy

    from planner.pipeline.engine.tables import REASON_DATA, Reason

    first = copy.copy(plans[0])
    first.coverage = first.coverage.copy()
    first.coverage.at[0, REASON_DATA] = Reason(
        "a (station {0}) = b; its station {1} cannot; no station S09 meets", ("S01", "S02")
    )
    named = stitch(site, UNLEVELLED, req, SETTINGS, blocks, [first, *plans[1:]], halo)
    key = blocks[0].key
    assert named.coverage.loc[0, "reason"] == (  # the words themselves are not read
        f"a (station {key}-S01) = b; its station {key}-S02 cannot; no station S09 meets"
    )
    assert REASON_DATA not in named.coverage  # the files never had it
    assert set(lean.links["station_b"]) <= ids and set(lean.links["station_a"]) <= ids | {"control"}
    assert all(s in ids for sids in lean.targets["station_ids"] for s in sids)
    # a moved sample's metrics are its new station's, within its limit
    moved = b[b["station_id"] != a.loc[b.index, "station_id"]]
    assert len(moved) > 0
    assert (moved.loc[moved["meets"], "m_z_mm"] <= req.max_z_mm + 1e-9).all()
    assert any("removed as redundant" in m for m in lean.messages)
    assert len(lean.route.table) == len(lean.stations)


def test_meeting_reach_is_the_farthest_meeting_pair(blockwise):
    from planner.pipeline.district.blocks import meeting_reach

    _, _, plans, _, halo = blockwise
    for p in plans:
        wb = workbench_of(p)
        i, j = np.nonzero(wb.evaluation.ok.toarray())
        farthest = np.hypot(*(wb.facades.xy[i] - wb.pool[j]).T).max()
        assert meeting_reach(p, rows_per_chunk=7) == pytest.approx(farthest, abs=1e-9)  # m
        assert 0 < farthest <= halo


def test_shared_prices_split_a_candidate_between_the_blocks_holding_it():
    from planner.pipeline.district.bounds import shared_prices

    a = np.array([[0.0, 0.0], [2.0, 0.0], [4.0, 0.0]])
    b = np.array([[4.0, 0.0], [6.0, 0.0]])
    c = np.array([[4.0004, 0.0], [2.0, 0.0]])  # the same grid points, to the millimetre
    pa, pb, pc = shared_prices([a, b, c])
    assert pa.tolist() == [1.0, 0.5, pytest.approx(1 / 3)]
    assert pb.tolist() == [pytest.approx(1 / 3), 1.0]
    assert pc.tolist() == [pytest.approx(1 / 3), 0.5]
    assert [len(p) for p in shared_prices([a, np.empty((0, 2))])] == [3, 0]


def _fewest(ok: np.ndarray, demand: np.ndarray) -> float:
    """The fewest columns covering ``ok`` (integer program)."""
    from scipy.optimize import LinearConstraint, milp

    res = milp(
        np.ones(ok.shape[1]),
        constraints=LinearConstraint(ok, demand, np.inf),
        integrality=1,
        bounds=(0, 1),
    )
    assert res.status == 0
    return float(res.fun)


def test_shared_bounds_add_up_to_a_bound_of_the_whole():
    """Random sites cut into four strips (samples in strips, candidates anywhere, a sample
    met by some candidates within the reach): each strip's cover, its candidates priced
    1 / (the strips whose samples they meet), relaxed to an LP. The sum never exceeds the
    whole's optimum and comes nearer to it than the sum over strips farther apart than twice
    the reach; the plain sum of the strips' fewest stations exceeds it (the negative control:
    a station serves two strips)."""
    import scipy.sparse as sp

    from planner.pipeline.district.bounds import shared_prices
    from planner.pipeline.optimise.cover import lp_bound

    rng = np.random.default_rng(3)
    reach, edges = 18.0, np.array([0.0, 50.0, 100.0, 150.0, 200.0])
    ratios, plain_exceeds = [], 0
    for _ in range(25):
        smp = rng.uniform(0, 200, (60, 2)) * [1, 0.5]
        cand = rng.uniform(-reach, 200 + reach, (70, 2)) * [1, 0.5]
        near = np.linalg.norm(smp[:, None] - cand[None], axis=2) <= reach
        ok = near & (rng.uniform(size=near.shape) < 0.6)  # some views blocked
        keep = ok.any(axis=1)
        smp, ok = smp[keep], ok[keep]
        demand = np.minimum(1 + (rng.uniform(size=len(smp)) < 0.2), ok.sum(axis=1))
        strip = np.searchsorted(edges, smp[:, 0], side="right") - 1
        used = [np.flatnonzero(ok[strip == k].any(axis=0)) for k in range(4)]
        prices = shared_prices([cand[u] for u in used])
        shared, fewest = 0.0, np.zeros(4)
        for k in range(4):
            sub = ok[strip == k][:, used[k]]
            if len(sub):
                shared += lp_bound(sp.csr_matrix(sub), demand[strip == k], prices[k], 10.0)
                fewest[k] = _fewest(sub.astype(float), demand[strip == k])
        whole = _fewest(ok.astype(float), demand)
        assert shared <= whole + 1e-6
        far = max(fewest[0] + fewest[2], fewest[0] + fewest[3], fewest[1] + fewest[3])
        ratios.append((shared / whole, far / whole))
        plain_exceeds += fewest.sum() > whole
    shared_mean, far_mean = np.mean(ratios, axis=0)  # 0.97 and 0.62 of the optimum
    assert shared_mean > 0.9  # a useful bound, not only a true one …
    assert shared_mean > far_mean + 0.25  # … stronger than the far-apart strips' sum
    assert plain_exceeds >= 15  # 23 of the 25


def test_blocks_farther_apart_than_their_meeting_reaches_add_their_bounds():
    """Two blocks 100 m apart with a reach of 80 m: only if each block's candidates meet its
    samples within 30 m (not 60 m) can no station serve both, and their bounds add up."""
    from types import SimpleNamespace

    from shapely.geometry import box

    from planner.pipeline.district.blocks import Block
    from planner.pipeline.district.bounds import honest_bound

    blocks = [Block("K01", ("a",), box(0, 0, 10, 10)), Block("K02", ("b",), box(110, 0, 120, 10))]

    def plans(meet_m):
        return [
            SimpleNamespace(solver=SimpleNamespace(lower_bound=b, meeting_reach_m=meet_m))
            for b in (7, 5)
        ]

    assert honest_bound(blocks, plans(30.0), 80.0) == 12
    assert honest_bound(blocks, plans(60.0), 80.0) == 7
    assert honest_bound(blocks, plans(np.inf), 80.0) == 7  # never beyond the reach
    assert honest_bound(blocks, plans(30.0), 40.0) == 12


def test_auto_plans_block_by_block_only_when_one_process_is_not_enough():
    """The work estimate decides, not a block line: the default site (about 1 000 samples)
    and a 10-building city block in one process, the 50-building town on Dask."""
    from planner.pipeline.district.blocks import needs_district
    from planner.siteio import default_site

    st = PlanSettings()
    assert not needs_district(default_site(), st)
    small = town(10, seed=0)
    assert not needs_district(small, st)
    assert needs_district(town(50, seed=0), st)
    # a block line through the middle of a small site does not make it a district
    assert len(partition(small, 20.0)) > 1 and not needs_district(small, st)


def test_the_blocks_networks_are_tied_into_one_across_their_seams(blockwise):
    """Each block keeps its network's frame (keep_frame); the stitch ties the blocks where a
    station of each sees three common targets, and every sample of a block tied through a
    seam carries the seam's error on top of its own: larger registration errors, never
    smaller; the seams are links of the plan. Negative control: without the frames kept,
    the blocks stay apart and nothing changes."""

    from planner.pipeline.district.blocks import keep_frame

    site, blocks, plans, _tables, halo = blockwise
    req = Requirements()
    apart = stitch(site, UNLEVELLED, req, SETTINGS, blocks, plans, halo)
    frames = [keep_frame(p) for p in plans]
    one = stitch(site, UNLEVELLED, req, SETTINGS, blocks, plans, halo, frames=frames)
    note = next(m for m in one.messages if m.startswith("District network:"))
    assert f"{len(blocks)} of {len(blocks)} blocks tied into one frame" in note
    assert not any(m.startswith("District network:") for m in apart.messages)
    seams = one.links[one.links["station_a"].str[:3] != one.links["station_b"].str[:3]]
    assert len(seams) == len(blocks) - 1 and (seams["common_targets"] >= 3).all()
    assert (seams["link_rms_mm"] > 0).all()
    # a seam is a link like the others in links.csv: by targets, its weakest direction said
    assert (seams["kind"] == "targets").all() and (seams["weakest_direction"] != "").all()
    a, b = apart.scanned.set_index("sample_id"), one.scanned.set_index("sample_id")
    for c in "xyz":
        grown = b[f"reg_m_{c}_mm"] - a.loc[b.index, f"reg_m_{c}_mm"]
        assert (grown.dropna() >= -1e-9).all()  # mm: the seams only add
        assert (grown.dropna() > 1e-3).any()
    assert list(one.coverage.columns) == list(apart.coverage.columns)  # nothing hidden
    lost = a["meets"] & ~b.loc[a.index, "meets"]
    assert b.loc[a.index[lost], "reason"].str.contains("once its block is tied").all()


def test_one_datums_tilt_leans_the_whole_district(blockwise):
    """A scanner without a compensator: each block's network leans with its own datum's
    tilt, but stitched into one frame only one datum's counts — the root block's, carried
    to every block however far. Every sample of the other block is at least as uncertain in
    height as the lean at its distance from that datum; within its own block, about its
    own datum, many were less."""

    from planner.pipeline.district.blocks import keep_frame

    site, blocks, plans, _tables, halo = blockwise
    frames = [keep_frame(q) for q in plans]  # as a worker does
    p = stitch(site, UNLEVELLED, Requirements(), SETTINGS, blocks, plans, halo, frames=frames)
    root = max(range(len(plans)), key=lambda k: len(plans[k].stations))
    datum = frames[root].datum  # the root block's datum (x, y, z)
    key = blocks[root].key
    cov = p.scanned[~p.scanned["station_id"].str.startswith(key) & (p.scanned["station_id"] != "")]
    assert len(cov) > 50
    far = np.hypot(cov["x"] - datum[0], cov["y"] - datum[1]).to_numpy()
    lean = far * 1000 * UNLEVELLED.initial_tilt_rms_arcsec / 206264.806  # mm
    assert (cov["reg_m_z_mm"].to_numpy() >= lean * (1 - 1e-6)).all()
    # before the stitch, within its own block, a sample leaned about its own datum
    own = pd.concat([q.scanned for k, q in enumerate(plans) if k != root])
    own = own.set_index("sample_id").loc[cov["sample_id"], "reg_m_z_mm"].to_numpy()
    assert (own < lean).mean() > 0.3
    # the samples the common frame takes over are counted, and the remedy said
    lost = p.scanned["reason"].str.startswith("the registration error takes it over once")
    said = [m for m in p.messages if "exceed a limit in the common frame" in m]
    assert lost.sum() > 50  # (450: the far block's heights)
    assert len(said) == 1 and f": {int(lost.sum())} sample(s)" in said[0], said
    assert f"datum station of block {key}" in said[0] and "--control" in said[0]


def test_a_block_task_keeps_its_frame_and_lets_its_workbench_go(district):
    """What a worker keeps of a block until the stitch: the plan, its meeting table, its
    cover and its frame (with a limit per sample, in the coverage's order) — not the
    workbench the plan was made from (memory: a worker plans many blocks)."""
    import gc

    from planner.pipeline.district.blocks import plan_block
    from planner.pipeline.inputs.resolved import reach_m

    site, blocks = district
    halo = reach_m(UNLEVELLED, Requirements(), SETTINGS)
    b = min(blocks, key=lambda b: len(b.buildings))
    p, table, _cover, frame = plan_block(
        block_site(site, b, halo), UNLEVELLED, Requirements(), SETTINGS, block_region(b, halo)
    )
    gc.collect()
    assert workbench_of(p) is None and p.network is None
    assert frame.limits.shape == (len(p.coverage), 3)
    assert (frame.limits > 0).all()  # mm: every sample's limits
    assert len(frame.xyz) == len(p.scan_stations) and len(table) > 0
