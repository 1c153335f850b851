"""What counting the registration error changes (run by hand; never part of the tests).

    .venv/bin/python benchmarks/registration.py            # writes its section of RESULTS.md
    .venv/bin/python benchmarks/registration.py --no-write

For the default site and a perimeter block of ten buildings (``planner.synthetic.town``):

* the plan judged by the scanner's error alone (``registration_error=False``, the old
  judgement): stations, targets, samples it says meet — and how many truly meet once the
  registration error of its own network is added;
* the plan with the registration error counted (the default): stations by purpose,
  targets, samples meeting the total, the worst predicted registration RMS and where, the
  weakest link, and the time the plan takes.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _results import machine, write_section


def _truly_met(p) -> int:
    """Samples of plan ``p`` meeting the requirements once its network's registration
    error is added to the scanner's (judged exactly as the planner judges)."""
    from planner.pipeline.evaluation.evaluate import Context, assign_stations
    from planner.pipeline.geometry.facades import build_facades

    st = p.settings
    ctx = Context.build(
        p.site,
        build_facades(p.site, st.sample_spacing_m, st.sample_height_step_m),
        p.scanner,
        p.requirements,
        st,
        p.solver.reach_m,
    )
    judged = assign_stations(ctx, p.stations[["x", "y"]].to_numpy(), p.network.registration())
    demanded = ~ctx.facades.party_wall
    return int(((judged.n_meeting >= p.requirements.stations_per_sample) & demanded).sum())


def run(name: str, site) -> list[str]:
    from planner.pipeline.engine.planning import plan
    from planner.pipeline.inputs.requirements import PlanSettings

    old = plan(site, settings=PlanSettings(registration_error=False))
    t0 = time.perf_counter()
    new = plan(site)
    seconds = time.perf_counter() - t0
    n = len(new.scanned)
    reg = new.scanned[["reg_m_x_mm", "reg_m_y_mm", "reg_m_z_mm"]]
    worst = reg.max(axis=1)
    i = worst.idxmax()
    where = new.coverage.loc[i]
    weak = new.links.loc[new.links["link_rms_mm"].idxmax()]
    purposes = ", ".join(f"{v} {k}" for k, v in new.stations["purpose"].value_counts().items())
    return [
        f"| {name} | scanner alone (old judgement) | {len(old.stations)} | {len(old.targets)} | "
        f"{int(old.scanned['meets'].sum())} of {n} | {_truly_met(old)} of {n} | – | – |",
        f"| {name} | scanner ⊕ registration | {len(new.stations)} ({purposes}) | "
        f"{len(new.targets)} | {int(new.scanned['meets'].sum())} of {n} | "
        f"{int(new.scanned['meets'].sum())} of {n} | {worst[i]:.1f} mm at {where['sample_id']} "
        f"from {where['station_id']}; weakest link {weak['station_a']}→{weak['station_b']} "
        f"{weak['link_rms_mm']:.1f} mm | {seconds:.1f} s |",
    ]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--no-write", action="store_true")
    args = ap.parse_args()
    from planner.siteio import default_site
    from planner.synthetic import town

    rows = run("default site", default_site()) + run("block of 10 (town(10, seed=0))", town(10))
    lines = [
        "## Registration in the accuracy promise (`benchmarks/registration.py`)",
        "",
        machine(),
        "",
        "| site | judged by | stations | targets | samples meeting (as the plan says) | "
        "truly meeting (scanner ⊕ its network's registration) | worst registration RMS | "
        "plan time |",
        "|---|---|---|---|---|---|---|---|",
        *rows,
    ]
    print("\n".join(lines))
    if not args.no_write:
        write_section("registration", lines)


if __name__ == "__main__":
    main()
