"""Field time of the default site's plan at every setting (preset) of three scanners, beside
what their makers state for a full-dome scan. Planned once per scanner at its usual setting
(the stations do not depend on the setting here: no spacing requirement); the route is
timed again at each setting. Writes the ``field-time`` section of benchmarks/RESULTS.md.

Run: ``.venv/bin/python benchmarks/field_time.py``
"""

from __future__ import annotations

from dataclasses import replace

from _results import machine, write_section

from planner.fieldwork import scan_points, scan_time_s
from planner.pipeline.engine.planning import plan
from planner.pipeline.field.route import field_route
from planner.scanner import load_scanner

#: What the makers' datasheets state of a full dome, for the comparison column.
STATED = {
    "leica-rtc360": "full dome + spherical HDR images in under 2 min (datasheet)",
    "leica-blk360": "full dome + HDR images in under 3 min (datasheet, first generation)",
    "faro-focus-premium": "no dome time stated; quality sets each point's observation time",
}


def main() -> None:
    lines = [
        "## Field time per scanner setting (benchmarks/field_time.py)",
        "",
        machine(),
        "The default site planned with each scanner at its usual setting, then the route timed "
        "at every setting: scan = the dome's points at the setting's step over its rate "
        "(shared out by the station's sector where the scanner can scan one), images = the "
        "profile's `imaging_s`. Set-up 5 min a station, 2 min a target placed, 1 min "
        "collected; walking 0.8 m/s. A computed dome time is a lower bound: the head's turn "
        "and the mirror's limits at coarse steps are not modelled (a preset's `scan_s` holds "
        "the maker's figure where one is published).",
        "",
        "| scanner | setting | step at 10 m | full dome (computed) | stations | scanning | "
        "images | field time | maker states |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for name, stated in STATED.items():
        sc = load_scanner(name)
        p = plan(scanner=sc)
        lo, hi = sc.vertical_fov_deg
        for pr in sc.presets:
            st = replace(p.settings, preset=pr.name, step_mm_at_10m=None).for_scanner(
                sc, None, p.solver.reach_m
            )
            r = field_route(p.site, sc, st, p.stations, p.targets, p.coverage, p.links)
            t = r.table
            rate = pr.rate_hz or sc.measurement_rate_hz
            dome_s = float(scan_time_s(scan_points(360.0, hi - lo, pr.step_mm_at_10m), rate))
            mark = " (usual)" if pr.name == sc.default_preset else ""
            row = (
                f"| {sc.label} | {pr.name}{mark} | {pr.step_mm_at_10m:g} mm | {dome_s:.0f} s | "
                f"{len(p.stations)} | {t['scan_min'].sum():.1f} min | "
                f"{t['imaging_min'].sum():.1f} min | {r.total_min / 60:.2f} h | {stated} |"
            )
            print(row, flush=True)
            lines.append(row)
    write_section("field-time", lines)


if __name__ == "__main__":
    main()
