"""The ``planner`` command line. It parses, calls the package and prints: no science here.

Exit codes (one meaning each): 0 success; 1 plan written, some samples unmet (``plan``
only); 2 bad input or an unusable output place (a message on stderr, nothing written);
3 an internal error (a bug: a one-line message and the log file with the details);
130 stopped by Ctrl+C.

A command imports the part of the package it needs when it runs (the imports inside the
``cmd_*`` functions): ``planner --help``, ``planner scanners`` and a refused input answer in
under a second instead of loading the planner's NumPy/SciPy/shapely/Numba stack (about 1 s
more) first.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import signal
import sys
import tempfile
import time
import traceback
from collections.abc import Callable, Iterator, Sequence
from dataclasses import fields
from pathlib import Path
from typing import Any

import pandas as pd

from planner.errors import InputError, PlannerError
from planner.ranges import argument
from planner.scanner import DEFAULT_SCANNER, Scanner, catalogue, load_scanner
from planner.tables import (
    PAPER_DISTANCES_M,
    PAPER_GAMMAS_DEG,
    PAPER_NUS_DEG,
    SOSSA_DISTANCES_M,
    height_table,
    planimetric_table,
    target_size_table,
)
from planner.targets import recommend_targets
from planner.text import printable

EXIT_OK = 0
EXIT_UNMET = 1
EXIT_BAD_INPUT = 2
EXIT_INTERNAL = 3
EXIT_INTERRUPTED = 130


class _Parser(argparse.ArgumentParser):
    """argparse that reports usage errors with exit code 2 and a one-line hint."""

    def error(self, message: str) -> None:  # type: ignore[override]
        self.print_usage(sys.stderr)
        self.exit(EXIT_BAD_INPUT, f"{self.prog}: error: {message}\n")


def _floats(text: str) -> list[float]:
    try:
        values = [float(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"expected comma-separated numbers such as 10,20,30; got {text!r}"
        ) from None
    if not values:
        raise argparse.ArgumentTypeError("expected at least one number")
    return values


def _floats_in(name: str) -> Callable[[str], list[float]]:
    """Comma-separated numbers, each within ``RANGES[name]`` (:mod:`planner.ranges`)."""
    one = argument(name)

    def parse(text: str) -> list[float]:
        return [one(str(v)) for v in _floats(text)]

    parse.__name__ = name
    return parse


def _fmt(df: pd.DataFrame, fmt: str, decimals: int = 1) -> str:
    if fmt == "csv":
        return df.to_csv(float_format=f"%.{decimals + 2}f")
    return df.to_string(float_format=lambda v: f"{v:.{decimals}f}")


def _flat_columns(df: pd.DataFrame, label: str) -> pd.DataFrame:
    out = df.copy()
    out.columns = [f"{a} {label}={b:g}" for a, b in df.columns]
    return out


def _scanner_arg(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--scanner",
        default=DEFAULT_SCANNER,
        metavar="NAME|FILE.toml",
        help=f"catalogue name ('planner scanners') or a profile file (default {DEFAULT_SCANNER})",
    )


def cmd_scanners(args: argparse.Namespace) -> int:
    from planner.scanner import user_profile_dir, user_profiles

    mine, warnings = user_profiles()
    listed = [(s, "catalogue") for s in catalogue().values()]
    listed += [(s, f"your profile ({user_profile_dir()})") for s in mine.values()]
    rows = [
        {
            "name": s.name,
            "ranging": f"{s.range_rms_mm:g} mm + {s.range_ppm:g} ppm",
            "H angle ″": s.angle_rms_arcsec,
            "V angle ″": s.tilt_rms_arcsec,
            "step@10m mm": s.step_mm_at_10m,
            "range m": f"{s.min_range_m:g}-{s.max_range_m:g}",
            "compensator ″": s.levelling_rms_arcsec if s.is_levelled else "-",
            "from": "catalogue" if origin == "catalogue" else "your profile",
            "label": s.label,
        }
        for s, origin in listed
    ]
    df = pd.DataFrame(rows).set_index("name")
    print(df.to_csv() if args.format == "csv" else df.to_string())
    if args.verbose:
        for s, origin in listed:
            print(f"\n{s.name} ({origin})\n  source: {s.source}\n  notes:  {s.notes}")
            for pr in s.presets:
                mark = " (default)" if pr.name == s.default_preset else ""
                print(f"  preset {pr.name!r}{mark}: step {pr.step_mm_at_10m:g} mm at 10 m")
    for warning in warnings:
        print(f"planner: warning: {warning}", file=sys.stderr)
    return EXIT_OK


def print_accuracy(scanner: Scanner, distances, angles, tilts, station_rms_mm, fmt: str) -> None:
    """Print the Table 1 (m_x, m_y) and Table 2 (m_z) layouts for ``scanner``."""
    t1 = _flat_columns(planimetric_table(scanner, distances, angles, station_rms_mm), "γ")
    t2 = height_table(scanner, distances, tilts)
    t2.columns = [f"m_z ν={v:g}" for v in t2.columns]
    if fmt == "csv":
        print(_fmt(t1.join(t2, how="outer"), "csv"))
        return
    print(
        f"Scanner {scanner.name}: m_S = {scanner.range_rms_mm:g} mm + {scanner.range_ppm:g} ppm, "
        f"m_β = {scanner.angle_rms_arcsec:g}″, m_ν = {scanner.tilt_rms_arcsec:g}″"
    )
    print("\nPlanimetric RMS in the facade frame [mm] (eq. 2, Table 1 layout), D [m] vs γ:")
    print(_fmt(t1, fmt))
    print("\nHeight RMS m_z [mm] (eq. 4 with S_0 = S, m_ν0 = m_ν; Table 2 layout), S [m] vs ν:")
    print(_fmt(t2, fmt))


def cmd_accuracy(args: argparse.Namespace) -> int:
    sc = load_scanner(args.scanner)
    print_accuracy(sc, args.distances, args.angles, args.tilts, args.station_rms_mm, args.format)
    return EXIT_OK


def cmd_targets(args: argparse.Namespace) -> int:
    sc = load_scanner(args.scanner)
    step = args.step_mm_at_10m if args.step_mm_at_10m is not None else sc.step_mm_at_10m
    table = target_size_table(args.distances, step)
    if args.format == "csv":
        print(table.to_csv())
        return EXIT_OK
    print(
        f"Minimum target size [mm] by Sossa's 2d / 4d rule, scan step {step:g} mm at 10 m "
        f"(scanner {sc.name}); columns: distance [m]"
    )
    print(table.to_string(float_format=lambda v: f"{v:.0f}"))
    rec = recommend_targets(max(args.distances), step_mm_at_10m=step)
    print("\nInventory: the farthest each item still qualifies [m]")
    print(
        rec[["name", "type", "size_mm", "max_distance_m"]].to_string(
            index=False, float_format=lambda v: f"{v:.0f}"
        )
    )
    return EXIT_OK


def cmd_figures(args: argparse.Namespace) -> int:
    from planner.app.figures import make_figures

    for path in make_figures(args.out):
        print(path)
    return EXIT_OK


def cmd_audit(args: argparse.Namespace) -> int:
    from pathlib import Path

    from planner.atomic import check_inputs_kept, check_output_file, write_bytes_atomic
    from planner.cityio import read_city_model
    from planner.pipeline.geometry.audit import audit, audit_summary, read_plan_tables
    from planner.site import with_terrain

    out = check_output_file(Path(args.out) if args.out else Path(args.plan) / "audit.csv")
    check_inputs_kept([out], _input_paths(args))
    cov, fac, st = read_plan_tables(args.plan)
    model = read_city_model(args.model, lod=args.lod, crs=args.crs)
    if args.terrain:
        model = with_terrain(model, args.terrain)
    table = audit(model, cov, fac, st)
    write_bytes_atomic(out, table.to_csv(index=False).encode("utf-8"))
    summary = audit_summary(table)
    print(summary.to_string(index=False))
    print(f"audit of {len(table)} samples marked met: {out}")
    return EXIT_OK


class _StderrProgress:
    """Progress on stderr: a bar on a terminal, a line per stage otherwise."""

    def __init__(self, quiet: bool) -> None:
        self.quiet = quiet
        self.tty = sys.stderr.isatty()
        self.last = ""

    def __call__(self, fraction: float, message: str) -> None:
        if self.quiet:
            return
        stage = message.split(" ")[0]
        if self.tty:
            bar = "#" * int(30 * fraction)
            sys.stderr.write(f"\r[{bar:<30}] {100 * fraction:3.0f}% {message[:50]:<50}")
            if fraction >= 1.0:
                sys.stderr.write("\n")
            sys.stderr.flush()
        elif stage != self.last:
            print(f"planner: {message}", file=sys.stderr)
        self.last = stage


def _scheduler(text: str) -> str:
    """``--scheduler``'s address, its form checked where it is read."""
    from planner.pipeline.district.schedule import scheduler_address

    try:
        return scheduler_address(text)
    except InputError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _ids(text: str) -> list[str]:
    ids = [v.strip() for v in text.split(",") if v.strip()]
    if not ids:
        raise argparse.ArgumentTypeError("expected building ids separated by commas")
    return ids


def _xy(text: str) -> float | tuple[float, float]:
    v = _floats(text)
    if len(v) == 1:
        return v[0]
    if len(v) == 2:
        return (v[0], v[1])
    raise argparse.ArgumentTypeError("expected one number (m_x = m_y) or two (m_x,m_y) in mm")


def plan_inputs(args: argparse.Namespace):
    """Site, scanner, requirements and settings from the options shared by ``plan`` and
    ``report`` — the one function both use, so a report shows exactly the plan ``plan``
    makes. Options not given are None, and the data classes' defaults apply."""
    from planner.pipeline.inputs.requirements import requirements_and_settings
    from planner.pipeline.inputs.resolved import resolve
    from planner.site import SiteLimits
    from planner.siteio import default_site
    from planner.targets import parse_inventory

    if args.mesh_offset and not args.mesh:
        raise InputError("--mesh-offset moves the mesh of --mesh; give the mesh")
    options = dict(vars(args))
    if args.inventory:
        options["inventory"] = parse_inventory(_read_text(args.inventory, "inventory file"))
    req, settings = requirements_and_settings(options)
    scanner = load_scanner(args.scanner or DEFAULT_SCANNER)
    limits = SiteLimits(
        **{f.name: getattr(args, f.name) for f in fields(SiteLimits) if getattr(args, f.name)}
    )
    near = resolve(scanner, req, settings).reach_m  # a problem farther than any station reaches
    site = read_site_args(args, limits, near) if args.site else None
    if site is None:
        site = default_site(buildings=args.buildings, limits=limits)
        if args.terrain or args.lod or args.mesh:
            raise InputError(
                "--terrain, --lod and --mesh need a site file (the default site is footprints "
                "on flat ground)"
            )
    if args.control:
        from dataclasses import replace

        from planner.siteio import read_control

        site = replace(site, control=[*site.control, *read_control(args.control)])
    if args.zones or args.zone:
        from dataclasses import replace

        from planner.zones import parse_zone, read_zones

        zones = list(site.zones)
        if args.zones:
            zones += read_zones(args.zones)
        for n, text in enumerate(args.zone or [], start=1):
            zones.append(parse_zone(text, f"zone{n}"))
        site = replace(site, zones=zones)
    return site, scanner, req, settings


def read_site_args(args: argparse.Namespace, limits, near_m: float):
    """The site named on the command line — footprints or a city model
    (:func:`planner.siteio.read_site`) — on the terrain model given (``--terrain``)."""
    from planner.site import with_terrain
    from planner.siteio import read_site

    site = read_site(
        args.site,
        default_height_m=args.height,
        buildings=args.buildings,
        repair=args.make_valid,
        limits=limits,
        crs=args.crs,
        near_m=near_m,
        lod=args.lod,
        **({"storey_height_m": args.storey_height_m} if args.storey_height_m else {}),
    )
    if args.mesh:
        from planner.cityio import with_mesh

        site = with_mesh(site, args.mesh, offset=args.mesh_offset or (0.0, 0.0, 0.0))
    if args.terrain:
        site = with_terrain(site, args.terrain)
    return site


def _read_text(path: str, what: str) -> str:
    p = Path(path)
    if not p.is_file():
        raise InputError(f"{what} {path!r} does not exist")
    try:
        return p.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        raise InputError(f"{what} {path!r} is not UTF-8 text") from None


#: The options that name a file the command reads.
INPUT_OPTIONS = (
    "site", "zones", "control", "inventory", "scanner", "terrain", "mesh", "model",
    "reference", "scan", "file",
)  # fmt: skip


def _input_paths(args: argparse.Namespace) -> list[str]:
    """Every file the command reads (the options of :data:`INPUT_OPTIONS` given; a plan's
    tables for ``audit``), so that no output is written over one."""
    paths = [getattr(args, name, None) for name in INPUT_OPTIONS]
    if getattr(args, "plan", None):
        paths += [
            str(Path(args.plan) / name) for name in ("coverage.csv", "facades.csv", "stations.csv")
        ]
    return [p for p in paths if isinstance(p, str) and p]


def _district(args: argparse.Namespace, site, settings) -> bool:
    """Whether to plan block by block on Dask: asked for, or (auto) the site is more work
    than one process does well (:func:`planner.pipeline.district.blocks.needs_district`)."""
    from planner.pipeline.district.blocks import needs_district

    if args.district == "off":
        if args.scheduler:
            raise InputError("--scheduler needs the district mode; leave out --district off")
        return False
    return args.district == "on" or bool(args.scheduler) or needs_district(site, settings)


#: The share of ``--time-limit-s`` kept for the plan's documents (its files, the booklet):
#: planning ends before it — or before the files' estimated time, where that is longer.
DOCUMENT_SHARE = 0.15
#: Writing a plan's files takes about this long per coverage row and per station or
#: target on an idle machine [s] (measured on a 50-building town, 11 201 rows, 40
#: stations, 93 targets: 2.75 s, the coverage CSV 0.4 s and the DXF 1.7 s of it, a first
#: use); the booklet ends in time for them, and planning ends in time for a fifth as much
#: again — both stretched by the pace the command gets
#: (:func:`~planner.pipeline.inputs.clock.pace`).
SAVE_S_PER_ROW = 2e-4
SAVE_S_PER_POINT = 4e-3
#: … and per row of the zone table (zones.csv alone: 0.4 s for 60 000 rows) [s].
SAVE_S_PER_ZONE = 1e-5
#: The files' estimated time is reserved this many times over before planning ends.
SAVE_MARGIN = 1.2
#: The booklet is drawn only when this long is left before the files are written: its
#: overview page takes about that (a station's page about 0.5 s) [s].
BOOKLET_OVERVIEW_S = 2.0


def command_started() -> float:
    """When this process started, on :func:`time.monotonic`'s clock (Linux:
    ``/proc/self/stat``'s start time against the boot-time clock), so that the ``planner``
    command's ``--time-limit-s`` counts the interpreter and the imports too (3 s on a slow
    machine); where that cannot be read, now.

    >>> import time
    >>> 0.0 <= time.monotonic() - command_started() < 600.0
    True
    """
    try:
        stat = Path("/proc/self/stat").read_text()
        ticks = int(stat.rsplit(")", 1)[1].split()[19])  # field 22: start time [ticks]
        age = time.clock_gettime(time.CLOCK_BOOTTIME) - ticks / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError, AttributeError):
        return time.monotonic()
    return time.monotonic() - age if 0.0 <= age < 600.0 else time.monotonic()


def make_plan(args: argparse.Namespace, progress: Callable[[float, str], None]):
    """The plan of the options shared by ``plan`` and ``report`` — the one function both
    use, so that a report shows exactly the plan ``plan`` makes: in district mode where
    ``plan`` would take it (:func:`_district`), ending with the documents' share of
    ``--time-limit-s`` left (:data:`DOCUMENT_SHARE`, or the files' estimated time), counted
    from the command's start. Returns the plan, the command's deadline and the pace it had
    (:func:`~planner.pipeline.inputs.clock.pace`)."""
    from planner.pipeline.district.schedule import memory_bytes
    from planner.pipeline.engine.planning import plan
    from planner.pipeline.geometry.facades import estimate_samples
    from planner.pipeline.inputs.clock import pace

    started = getattr(args, "started", None) or time.monotonic()
    memory_bytes(args.worker_memory)  # checked even where the plan needs no cluster
    site, scanner, req, settings = plan_inputs(args)
    deadline = started + settings.time_limit_s
    rows = estimate_samples(site, settings.sample_spacing_m, settings.sample_height_step_m)
    # the files' time as measured on an idle machine, stretched by the pace this command
    # has had so far (its start, imports and reading: a loaded machine slows all of it)
    slow = pace(time.monotonic() - started, time.process_time())
    files_s = SAVE_S_PER_ROW * rows + SAVE_S_PER_ZONE * len(site.zones)
    reserve = max(DOCUMENT_SHARE * settings.time_limit_s, slow * SAVE_MARGIN * files_s)
    planned_by = deadline - reserve
    if _district(args, site, settings):
        from planner.pipeline.district.schedule import plan_district

        result = plan_district(
            site,
            scanner,
            req,
            settings,
            block_m=args.block_m,
            scheduler=args.scheduler,
            workers=args.workers,
            memory_limit=args.worker_memory,
            progress=progress,
            deadline=planned_by,
        )
    else:
        result = plan(site, scanner, req, settings, progress=progress, deadline=planned_by)
    return result, deadline, slow


def run_plan(args: argparse.Namespace) -> int:
    """Plan, draw the booklet and write the files, all within ``--time-limit-s`` from the
    command's start (reading the site included): planning ends with
    :data:`DOCUMENT_SHARE` of the budget left, and the booklet leaves out the pages there is
    no time for (said in the summary and on its last page)."""
    from planner.atomic import check_inputs_kept, check_output_folder
    from planner.pipeline.documents.export import OWNED_FILES, save

    progress = _StderrProgress(args.quiet)
    check_output_folder(args.out)  # before the plan, which can take minutes
    check_inputs_kept([Path(args.out) / name for name in OWNED_FILES], _input_paths(args))
    import ezdxf  # noqa: F401  (the DXF writer's import, 0.7 s, made now: not after planning)

    result, deadline, slow = make_plan(args, progress)
    site = result.site
    extra = {}
    saving = slow * (
        SAVE_S_PER_ROW * len(result.coverage)
        + SAVE_S_PER_POINT * (len(result.stations) + len(result.targets))
        + SAVE_S_PER_ZONE * len(site.zones)
    )
    if args.booklet and time.monotonic() + BOOKLET_OVERVIEW_S > deadline - saving:
        result.messages.append(
            "Time budget: no field booklet was drawn (no time was left for it); raise "
            "--time-limit-s, or make it from the dashboard."
        )
    elif args.booklet:
        from planner.app.booklet import booklet

        progress(1.0, "field booklet (booklet.pdf)")
        extra["booklet.pdf"], left = booklet(result, deadline - saving)
        if left:
            result.messages.append(
                f"Time budget: the booklet has no page for {len(left)} of "
                f"{len(result.stations)} station(s) ({', '.join(left[:8])}"
                + (" …" if len(left) > 8 else "")
                + "): its last page lists them; raise --time-limit-s for the whole booklet."
            )
    written = save(result, args.out, extra)
    print(result.summary())
    unmet = result.unmet
    if len(unmet):
        shown = 20
        print(
            f"\nUnmet samples ({len(unmet)}"
            + (f", first {shown}" if len(unmet) > shown else "")
            + "):"
        )
        cols = ["building_id", "facade_id", "sample_id", "x", "y", "z", "reason"]
        print(unmet[cols].head(shown).to_string(index=False, float_format=lambda v: f"{v:.2f}"))
        if len(unmet) > shown:
            print(
                f"… all {len(unmet)} in coverage.csv (meets = False) "
                "and plan.geojson (layer 'unmet')"
            )
    print(f"\nWrote {', '.join(p.name for p in written)} to {args.out}")
    return EXIT_OK if result.meets_all else EXIT_UNMET


def cmd_report(args: argparse.Namespace) -> int:
    from planner.app.report import make_report
    from planner.atomic import check_inputs_kept, check_output_file

    out = Path(args.out)
    if out.suffix.lower() not in (".html", ".htm"):
        raise InputError(f"--out must name an .html file; got {args.out!r}")
    check_output_file(out)
    check_inputs_kept([out], _input_paths(args))
    result, _, _ = make_plan(args, _StderrProgress(args.quiet))
    if not args.quiet:
        print("planner: rendering the report …", file=sys.stderr)
    path = make_report(result, out)
    print(f"Wrote {path} ({path.stat().st_size / 1e6:.1f} MB, self-contained)")
    return EXIT_OK


def cmd_rehearse(args: argparse.Namespace) -> int:
    """The plan's simulated scans (E57, LAZ) and its HELIOS++ survey, written as one set."""
    from planner.atomic import check_inputs_kept, check_output_folder, replace_folder_files
    from planner.pipeline.geometry.scene import Scene
    from planner.pipeline.survey.helios import FILES as HELIOS_FILES
    from planner.pipeline.survey.helios import helios_files
    from planner.pipeline.survey.pointclouds import e57_bytes, laz_bytes, legend_csv
    from planner.pipeline.survey.rehearsal import estimate, rehearse

    check_output_folder(args.out)
    owned = ("scans.e57", "scans.laz", "scans_legend.csv", *HELIOS_FILES)
    check_inputs_kept([Path(args.out) / n for n in owned], _input_paths(args))
    result, _, _ = make_plan(args, _StderrProgress(args.quiet))
    scene = Scene(result.site, "rays")
    size = estimate(result, args.beams_per_station, scene)
    t0 = time.monotonic()
    if not args.quiet:
        print(
            f"planner: simulating {int(size['stations'])} scans at {size['step_mm_at_10m']:.1f} "
            f"mm at 10 m: about {size['points'] / 1e6:.1f} million points (E57 about "
            f"{size['e57_bytes'] / 1e6:.0f} MB, LAZ about {size['laz_bytes'] / 1e6:.0f} MB), "
            f"about {size['seconds']:.0f} s; --beams-per-station to change",
            file=sys.stderr,
        )
    reh = rehearse(
        result,
        beams_per_station=args.beams_per_station,
        seed=args.seed,
        scene=scene,
        progress=_StderrProgress(args.quiet),
    )
    files = {"scans_legend.csv": legend_csv(reh).encode()}
    if not args.quiet:
        print("planner: writing scans.e57 and scans.laz …", file=sys.stderr)
    files["scans.e57"] = e57_bytes(reh)
    files["scans.laz"] = laz_bytes(reh)
    files.update(helios_files(result, scene))
    written = replace_folder_files(args.out, files, owned=owned)
    for note in reh.notes:
        print(note)
    print(
        f"{len(reh.scans)} simulated scans, {reh.n_points:,} points "
        f"({time.monotonic() - t0:.0f} s): scans.e57 {len(files['scans.e57']) / 1e6:.1f} MB "
        f"(one scan per station, its pose), scans.laz {len(files['scans.laz']) / 1e6:.1f} MB "
        "(site CRS; rms_mm, incidence_deg, surface), scans_legend.csv; the HELIOS++ survey "
        "helios_survey.xml with its scene and scanner."
    )
    print(f"Wrote {', '.join(p.name for p in written)} to {args.out}")
    return EXIT_OK


def cmd_replan(args: argparse.Namespace) -> int:
    """The plan re-made from the stations as scanned: the extra stations for what is left."""
    from planner.atomic import check_inputs_kept, check_output_folder
    from planner.pipeline.documents.export import OWNED_FILES, save
    from planner.pipeline.survey.asscanned import (
        check_same_plan,
        compare_links,
        read_link_report,
        read_targets_placed,
        replan,
    )
    from planner.pipeline.survey.pointclouds import read_poses

    check_output_folder(args.out)
    extra_names = ("as_scanned.csv", "link_check.csv")
    inputs = [*_input_paths(args), args.as_scanned, args.targets_placed, args.link_report]
    check_inputs_kept([Path(args.out) / n for n in (*OWNED_FILES, *extra_names)], inputs)
    scanned = read_poses(args.as_scanned)
    placed = report = None
    if args.targets_placed:
        placed = read_targets_placed(args.targets_placed)
    if args.link_report:
        report = read_link_report(args.link_report)
    args.district = "off"  # one network: the re-plan works on its workbench
    result, _, _ = make_plan(args, _StderrProgress(args.quiet))
    if args.plan:
        check_same_plan(result, args.plan)
    r = replan(result, scanned, targets_placed=placed, progress=_StderrProgress(args.quiet))
    files = {"as_scanned.csv": r.stations.to_csv(index=False).encode()}
    if report is not None:
        check = compare_links(r.scanned_plan, report)
        files["link_check.csv"] = check.to_csv(index=False).encode()
    if args.booklet and len(r.extra):
        from planner.app.booklet import booklet

        files["booklet.pdf"], _ = booklet(r.plan, only=set(r.extra["station_id"]))
    written = save(r.plan, args.out, files, owned=extra_names)
    print(r.summary())
    if report is not None:
        print("\nLinks as registered against the plan:")
        print(check.to_string(index=False, float_format=lambda v: f"{v:.2f}"))
    print(f"\nWrote {', '.join(p.name for p in written)} to {args.out}")
    return EXIT_OK if r.plan.meets_all else EXIT_UNMET


def _print_table(df: pd.DataFrame, decimals: int = 3) -> None:
    print(df.to_string(float_format=lambda v: f"{v:.{decimals}f}"))


def _profile_name(args: argparse.Namespace) -> str | None:
    """The name of the profile to write, checked before any work (None: none is written)."""
    from planner.scanner import check_profile_name, installed_profile_path

    if not args.profile_out and not args.install:
        return None
    if args.profile_out:
        from planner.atomic import check_inputs_kept

        check_inputs_kept([args.profile_out], [*_input_paths(args), args.base_scanner])
    name = args.name or (Path(args.profile_out).stem if args.profile_out else None)
    if not name:
        raise InputError("--install needs a profile name: give --name NAME")
    if args.install:
        installed_profile_path(name)  # a reserved name stops here
    return check_profile_name(name)


def _write_profile(args: argparse.Namespace, **results) -> None:
    from planner.calibration import profile_from_calibration
    from planner.scanner import installed_profile_path, user_profile_dir

    name = _profile_name(args)
    if name is None:
        return
    scanner, notes = profile_from_calibration(name, base=load_scanner(args.base_scanner), **results)
    path = scanner.save(args.profile_out or installed_profile_path(name))
    if args.install and args.profile_out:
        scanner.save(installed_profile_path(name))
    if args.install:
        print(f"installed as {name!r} in {user_profile_dir()} (use --scanner {name})")
    print(
        f"\nProfile {scanner.name!r} written to {path}: ranging {scanner.range_rms_mm:.2f} mm + "
        f"{scanner.range_ppm:.1f} ppm, angles {scanner.angle_rms_arcsec:.1f}″ H, "
        f"{scanner.tilt_rms_arcsec:.1f}″ V (use it with --scanner {path})"
    )
    for note in notes:
        print(f"note: {note}")


def cmd_calibrate_lab(args: argparse.Namespace) -> int:
    _profile_name(args)  # a bad name stops here, before any work
    from planner.calibration import lab_test

    t = lab_test(
        args.reference,
        args.scan,
        k=args.k,
        pairs=args.pairs,
        reference_precision_mm=args.reference_precision_mm,
        declared_target_precision_mm=args.declared_precision_mm,
    )
    print(*t.lines(), sep="\n")
    _print_table(t.summary())
    sig = t.significant
    print(f"\nPairs with a significant difference (|Δ| > M_r): {len(sig)}")
    if len(sig):
        cols = [
            "target_a",
            "target_b",
            "distance_m",
            "d_distance_mm",
            "d_horizontal_arcsec",
            "d_vertical_arcsec",
        ]
        _print_table(sig[cols].head(30).set_index(["target_a", "target_b"]), 2)
    if t.network:
        print(f"\n{t.network}")
    for warning in t.warnings:
        print(f"warning: {warning}")
    range_from = None if args.range_from == "none" else args.range_from
    angles_from = None if args.angles_from == "none" else args.angles_from
    _write_profile(args, lab=t, range_from=range_from, angles_from=angles_from)
    return EXIT_OK


def cmd_calibrate_baseline(args: argparse.Namespace) -> int:
    _profile_name(args)  # a bad name stops here, before any work
    from planner.calibration import baseline_calibration, six_segment_constant, table_columns

    if {"from", "to", "distance_m"} <= table_columns(args.file):
        r = six_segment_constant(args.file)
        print(*r.lines(), sep="\n")
        print("  adjusted distances from the first point [m]:")
        _print_table(r.segments_m.to_frame(), 4)
        if args.profile_out:
            raise InputError(
                "the six-segment method gives the additive constant only, no profile; "
                "use a baseline comparison (measured_m, reference_m) for --profile-out"
            )
        return EXIT_OK
    r = baseline_calibration(args.file)
    print(*r.lines(), sep="\n")
    _print_table(r.residuals.set_index("measured_m"), 4)
    for warning in r.warnings:
        print(f"warning: {warning}")
    _write_profile(args, baseline=r, range_from="baseline", include_scale=args.include_scale)
    return EXIT_OK


def cmd_calibrate_axes(args: argparse.Namespace) -> int:
    _profile_name(args)  # a bad name stops here, before any work
    from planner.calibration import axis_errors

    r = axis_errors(args.file, orientation=not args.no_orientation)
    print(*r.lines(), sep="\n")
    _write_profile(args, axes=r, angles_from="axes")
    return EXIT_OK


def cmd_serve(args: argparse.Namespace) -> int:
    from planner.app.notebooks import notebook_path
    from planner.app.serve import serve

    return serve(notebook_path(args.notebook), args.port, kernel_idle_s=args.kernel_idle_s)


def cmd_default(args: argparse.Namespace) -> int:
    """The main job: serve the station-planner dashboard (it opens on the default site)."""
    serve = build_parser().parse_args(["serve"])
    return serve.func(serve)


def _plan_arguments(pl: argparse.ArgumentParser) -> None:
    """The site, scanner, requirement and setting options shared by plan and report. The
    requirement and setting options are made from the data classes' fields (name, unit,
    help, default), so both commands and the data classes cannot drift apart."""
    _site_arguments(pl)
    req, group = _data_class_arguments(pl)
    req.add_argument(
        "--class",
        dest="accuracy_class",
        default=None,
        metavar="CLASS",
        help="an accuracy class instead of --max-xy-mm/--max-z-mm: DIN 18710-1 OGL0-5 "
        "(position) / OGH0-5 (height), e.g. OGL4/OGH3, or USIBD LOA20-50 (at 95 %%)",
    )
    _setting_arguments(group)
    _site_limit_arguments(pl)
    req.add_argument(
        "--zones",
        metavar="ZONES.csv",
        default=None,
        help="requirements per building, facade or part of a facade: a table with "
        "id, facade_id (or building_id), from_m, to_m, z_from_m, z_to_m (or elevation_wkt), "
        "and max_xy_mm, max_z_mm, class, max_spacing_mm, stations_per_sample, sample_spacing_m…",
    )
    req.add_argument(
        "--zone",
        action="append",
        default=None,
        metavar="KEY=VALUE,...",
        help="one zone without a file (repeatable), e.g. "
        "facade=main-f00,from=4,to=10,z=0-6,max_xy_mm=3,sample_spacing_m=0.5",
    )
    group["registration"].add_argument(
        "--control",
        metavar="CONTROL.csv",
        default=None,
        help="control points with known coordinates (site CRS): id,x,y,z[,rms_mm]; stations "
        "that see three of them are tied to the site network (the datum)",
    )
    group["registration"].add_argument(
        "--inventory",
        metavar="FILE",
        default=None,
        help="the targets you own, one per line: name, type (flat/sphere/cylinder), size in mm",
    )
    pl.add_argument("-q", "--quiet", action="store_true", help="no progress messages")


def _site_arguments(pl: argparse.ArgumentParser) -> None:
    """The site file, how to read it, the buildings to plan and the scanner."""
    pl.add_argument(
        "site",
        nargs="?",
        metavar="SITE_FILE",
        help="footprints (.geojson, .wkt, .csv, .gpkg, .shp, .kml or .kmz; longitude/latitude "
        "is projected to its UTM zone) or a 3-D city model (CityJSON .json/.city.json, "
        "CityJSON Sequence .city.jsonl, CityGML .gml/.xml); default: the built-in site",
    )
    pl.add_argument(
        "--lod",
        default=None,
        metavar="LOD",
        help="the city model's level of detail to plan on, e.g. 2 or 2.2 (default: the finest "
        "each building has)",
    )
    pl.add_argument(
        "--mesh",
        default=None,
        metavar="MESH",
        help="the buildings' 3-D shape as a plain mesh (OBJ, PLY, glTF/GLB, STL, OFF; an IFC "
        "model exported as a mesh) in the site's CRS: each triangle joins the footprint it "
        "lies on (the site file gives the buildings and their ids)",
    )
    pl.add_argument(
        "--mesh-offset",
        type=_floats_in("offset_m"),
        default=None,
        metavar="E,N,H",
        help="added to the mesh's coordinates (a mesh in local coordinates) [m]",
    )
    pl.add_argument(
        "--terrain",
        default=None,
        metavar="DTM.tif",
        help="a terrain model (GeoTIFF) in the site's CRS: stations and targets stand on it, "
        "it blocks sight lines, heights are in its vertical datum (default: the model's "
        "relief, else flat ground)",
    )
    pl.add_argument(
        "--crs",
        default=None,
        metavar="CRS",
        help="CRS of the site file's coordinates, e.g. EPSG:25832 or EPSG:4326 (CSV and WKT "
        "carry none; GeoJSON without one is longitude/latitude)",
    )
    _reading_arguments(pl)


def _reading_arguments(pl: argparse.ArgumentParser) -> None:
    """How to read the site (heights, buildings to plan, repairs) and the scanner."""
    pl.add_argument(
        "--height",
        type=argument("height_m"),
        default=None,
        metavar="H",
        help="height [m] for buildings and obstacles that have none (nor building:levels)",
    )
    pl.add_argument(
        "--storey-height-m",
        type=argument("storey_height_m"),
        default=None,
        metavar="M",
        help="storey height for buildings known only by their number of storeys "
        "('building:levels', as OpenStreetMap gives it) (default 3 m)",
    )
    pl.add_argument(
        "--buildings",
        type=_ids,
        default=None,
        metavar="ID,ID,...",
        help="ids of the buildings to plan; all others only block the beam",
    )
    pl.add_argument(
        "--make-valid",
        action="store_true",
        help="repair the site instead of stopping: invalid outlines (repeated vertices, "
        "make_valid) and overlapping buildings (shared walls snapped, small overlaps clipped "
        "from the smaller); every repair is listed in site_repairs.csv",
    )
    pl.add_argument(
        "--scanner",
        default=None,
        metavar="NAME|FILE.toml",
        help=f"catalogue name ('planner scanners') or a profile file (default {DEFAULT_SCANNER})",
    )


def _data_class_arguments(
    pl: argparse.ArgumentParser,
) -> tuple[argparse._ArgumentGroup, dict[str, argparse._ArgumentGroup]]:
    """An option for every field of :class:`Requirements` and :class:`PlanSettings`, in the
    requirements group or its settings group (both returned)."""
    from planner.pipeline.inputs.requirements import (
        SETTING_GROUPS,
        PlanSettings,
        Requirements,
        field_specs,
    )

    req = pl.add_argument_group("requirements")
    group = {key: pl.add_argument_group(title.lower()) for key, title in SETTING_GROUPS.items()}
    pairs = {"max_xy_mm": "X[,Y]", "station_rms_mm": "MXC[,MYC]"}
    for cls in (Requirements, PlanSettings):
        for name, spec in field_specs(cls).items():
            kind = _xy if name in pairs else int if isinstance(spec.default, int) else float
            default = "none" if spec.default is None else f"{spec.default:g}"
            (group[spec.group] if spec.group else req).add_argument(
                spec.flag,
                type=kind,
                default=None,
                metavar=pairs.get(name, name.rsplit("_", 1)[-1].upper()),
                help=_argparse_text(
                    f"{spec.help} [{spec.unit}] ({spec.rule()}; default {default})"
                ),
            )
    return req, group


def _setting_arguments(group: dict[str, argparse._ArgumentGroup]) -> None:
    """The settings that are not plain numbers: choices and switches (in the order of the
    command line's help)."""
    _model_arguments(group)
    _sampling_arguments(group)
    _switch_arguments(group)


def _model_arguments(group: dict[str, argparse._ArgumentGroup]) -> None:
    """The optimiser, the accuracy model and the registration."""
    from planner.pipeline.inputs.requirements import (
        METHODS,
        MODELS,
        REGISTRATION_MODES,
        REGISTRATION_PROCESSING,
    )

    group["solver"].add_argument(
        "--method", choices=METHODS, default=None, help="station optimiser"
    )
    group["model"].add_argument(
        "--model",
        choices=MODELS,
        default=None,
        help="accuracy model: 3d, the full 3-D propagation (default), or paper, eq. 2 and 4 "
        "of Voroshilov & Karachentsev",
    )
    group["registration"].add_argument(
        "--registration",
        choices=REGISTRATION_MODES,
        default=None,
        help="how the scans are registered: targets, cloud (cloud to cloud on the surfaces "
        "the scans share), hybrid (cloud links, targets where a link is weak), or auto: the "
        "scanner profile's usual workflow, else targets (default)",
    )
    group["registration"].add_argument(
        "--registration-processing",
        choices=REGISTRATION_PROCESSING,
        default=None,
        help="what the promised registration error assumes of the registration software: "
        + "; or ".join(f"{k}, {v}" for k, v in REGISTRATION_PROCESSING.items())
        + " (default adjustment)",
    )


def _sampling_arguments(group: dict[str, argparse._ArgumentGroup]) -> None:
    """What is demanded, how sight lines are answered, the scanner's setting, imaging."""
    from planner.pipeline.inputs.requirements import SIGHT_ENGINES

    group["sampling"].add_argument(
        "--demand-roofs",
        action="store_true",
        default=None,
        help="demand a city model's roofs too (they need an elevated station); walls and "
        "doors are always demanded, windows (glass) never",
    )
    group["sampling"].add_argument(
        "--sight-engine",
        choices=SIGHT_ENGINES,
        default=None,
        help="how sight lines are answered: rays cast on the scene's triangles, or the exact "
        "prism test of footprints on flat ground; auto (default) takes prisms where the "
        "site allows",
    )
    group["sampling"].add_argument(
        "--preset",
        default=None,
        metavar="NAME",
        help="the scanner's resolution / quality setting by the maker's name ('planner "
        "scanners --verbose' lists them); default the coarsest that meets --max-spacing-mm, "
        "else the scanner's usual one. --step-mm-at-10m wins",
    )
    group["field"].add_argument(
        "--imaging",
        action=argparse.BooleanOptionalAction,
        default=None,
        help="each station also takes its HDR images (counted in the field time; default on)",
    )


def _switch_arguments(group: dict[str, argparse._ArgumentGroup]) -> None:
    """The model's terms and the registration error, each switched off."""
    group["model"].add_argument(
        "--no-incidence-noise",
        dest="incidence_noise",
        action="store_false",
        default=None,
        help="3-D model without the ranging noise's growth with incidence",
    )
    group["model"].add_argument(
        "--no-beam-footprint",
        dest="beam_footprint",
        action="store_false",
        default=None,
        help="3-D model without the beam footprint in the spacing check",
    )
    group["registration"].add_argument(
        "--no-registration-error",
        dest="registration_error",
        action="store_false",
        default=None,
        help="judge samples by the scanner's error alone (the paper's eq. 2 and 4 without "
        "m_xc, m_yc); the registration network is still planned",
    )


def _site_limit_arguments(pl: argparse.ArgumentParser) -> None:
    """The site's size limits (a unit slip is refused)."""
    from planner.site import SiteLimits

    limits = pl.add_argument_group("site limits (a unit slip is refused)")
    for f in fields(SiteLimits):
        limits.add_argument(
            "--" + f.name.replace("_", "-"),
            type=argument("site_limit_m"),
            default=None,
            metavar="M",
            help=f"refuse a site beyond this (default {f.default:g} m): raise it for a real one",
        )


def _district_arguments(pl: argparse.ArgumentParser) -> None:
    """The district mode's options, shared by plan and report (a report shows the plan
    ``plan`` makes, in district mode where it takes it)."""
    from planner.pipeline.inputs.requirements import (
        DEFAULT_BLOCK_M,
        DISTRICT_SAMPLES,
        WORKER_MEMORY,
    )

    pl.add_argument(
        "--district",
        choices=["auto", "on", "off"],
        default="auto",
        help="plan block by block on Dask (auto: when the facades need more than "
        f"{DISTRICT_SAMPLES:,} samples)",
    )
    pl.add_argument(
        "--block-m",
        type=argument("block_m"),
        default=DEFAULT_BLOCK_M,
        metavar="M",
        help=f"side of a district block [m] (default {DEFAULT_BLOCK_M:g})",
    )
    pl.add_argument(
        "--workers",
        type=argument("workers"),
        default=2,
        metavar="N",
        help="worker processes of the local Dask cluster (default 2)",
    )
    pl.add_argument(
        "--worker-memory",
        default=WORKER_MEMORY,
        metavar="SIZE",
        help=f"memory of each local worker, e.g. 3GB (default {WORKER_MEMORY}); a worker "
        "that needs more is stopped and the plan not written",
    )
    pl.add_argument(
        "--scheduler",
        type=_scheduler,
        default=None,
        metavar="ADDRESS",
        help="an existing Dask cluster's scheduler, e.g. tcp://10.0.0.5:8786 (its workers "
        "need tls-planner installed); default: a local cluster",
    )


def _argparse_text(text: str) -> str:
    """Plain text (a data class's help, unit "%") as argparse help, which formats ``%``."""
    return text.replace("%", "%%")


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(
        prog="planner", description="Plan terrestrial laser scanner stations around buildings."
    )
    p.set_defaults(func=cmd_default)
    sub = p.add_subparsers(title="commands", parser_class=_Parser)
    for add in (
        _scanners_command,
        _accuracy_command,
        _targets_command,
        _plan_command,
        _report_command,
        _rehearse_command,
        _replan_command,
        _serve_command,
        _calibrate_command,
        _audit_command,
        _figures_command,
    ):
        add(sub)
    return p


def _scanners_command(sub: argparse._SubParsersAction) -> None:
    s = sub.add_parser("scanners", help="list the scanner catalogue")
    s.add_argument("--format", choices=["text", "csv"], default="text")
    s.add_argument("-v", "--verbose", action="store_true", help="also print sources and notes")
    s.set_defaults(func=cmd_scanners)


def _accuracy_command(sub: argparse._SubParsersAction) -> None:
    a = sub.add_parser("accuracy", help="m_x, m_y (Table 1) and m_z (Table 2) for a scanner")
    _scanner_arg(a)
    a.add_argument(
        "--distances",
        type=_floats_in("distance_m"),
        default=list(PAPER_DISTANCES_M),
        metavar="D,D,...",
        help="horizontal / slope distances [m]",
    )
    a.add_argument(
        "--angles",
        type=_floats_in("angle_deg"),
        default=list(PAPER_GAMMAS_DEG),
        metavar="G,G,...",
        help="deviation angles γ from the facade normal [deg]",
    )
    a.add_argument(
        "--tilts",
        type=_floats_in("angle_deg"),
        default=list(PAPER_NUS_DEG),
        metavar="N,N,...",
        help="beam tilts ν [deg]",
    )
    a.add_argument(
        "--station-rms-mm",
        type=argument("rms_mm"),
        default=0.0,
        help="station / registration RMS m_xc = m_yc [mm]",
    )
    a.add_argument("--format", choices=["text", "csv"], default="text")
    a.set_defaults(func=cmd_accuracy)


def _targets_command(sub: argparse._SubParsersAction) -> None:
    t = sub.add_parser("targets", help="minimum target sizes (Sossa's Table 2 layout)")
    _scanner_arg(t)
    t.add_argument(
        "--distances",
        type=_floats_in("distance_m"),
        default=list(SOSSA_DISTANCES_M),
        metavar="D,D,...",
    )
    t.add_argument(
        "--step-mm-at-10m",
        type=argument("step_mm_at_10m"),
        default=None,
        help="scan step at 10 m [mm]; default the scanner's",
    )
    t.add_argument("--format", choices=["text", "csv"], default="text")
    t.set_defaults(func=cmd_targets)


def _plan_command(sub: argparse._SubParsersAction) -> None:
    pl = sub.add_parser(
        "plan",
        help="plan stations and targets for a site",
        description="Exit codes: 0 every requirement met; 1 plan written but some samples unmet "
        "(listed); 2 bad input (message, nothing written).",
    )
    _plan_arguments(pl)
    pl.add_argument("--out", required=True, metavar="DIR", help="folder for the plan's files")
    _district_arguments(pl)
    pl.add_argument(
        "--booklet",
        action=argparse.BooleanOptionalAction,
        default=False,
        help="also draw the field booklet (booklet.pdf: the overview map and a page per "
        "station, about 0.3 s a page); default: not drawn (the dashboard draws it on demand)",
    )
    pl.set_defaults(func=run_plan)


def _report_command(sub: argparse._SubParsersAction) -> None:
    rp = sub.add_parser(
        "report",
        help="render the static HTML report of a plan",
        description="Renders one self-contained HTML file of the plan (tables, figures "
        "embedded, no code, opens offline).",
    )
    _plan_arguments(rp)
    _district_arguments(rp)
    rp.add_argument("--out", required=True, metavar="REPORT.html", help="the HTML file to write")
    rp.set_defaults(func=cmd_report)


def _rehearse_command(sub: argparse._SubParsersAction) -> None:
    rh = sub.add_parser(
        "rehearse",
        help="the plan's scans simulated as point clouds (E57, LAZ) and a HELIOS++ survey",
        description="Plans the site as `plan` does, then simulates every station's scan "
        "(the scene ray-cast on the scanner's grid, noise by the plan's model, targets as "
        "geometry) and writes scans.e57 (one scan per station with its pose), scans.laz "
        "(site CRS, predicted RMS per point), scans_legend.csv and the HELIOS++ survey "
        "(helios_*.xml, helios_scene.obj). The size is said before writing.",
    )
    _plan_arguments(rh)
    rh.add_argument("--out", required=True, metavar="DIR", help="folder for the clouds")
    _district_arguments(rh)
    from planner.pipeline.survey.rehearsal import DEFAULT_BEAMS_PER_STATION

    rh.add_argument(
        "--beams-per-station",
        type=argument("beams_per_station"),
        default=DEFAULT_BEAMS_PER_STATION,
        help="beams cast per station at most, 1,000 to 100,000,000: the preset's step is "
        f"thinned to it (default {DEFAULT_BEAMS_PER_STATION:,}; about 5 beams in 10 return)",
    )
    rh.add_argument(
        "--seed", type=argument("seed"), default=1, help="the noise's random seed (default 1)"
    )
    rh.set_defaults(func=cmd_rehearse)


def _replan_command(sub: argparse._SubParsersAction) -> None:
    rr = sub.add_parser(
        "replan",
        help="re-plan from the stations as scanned: the extra stations for what is left",
        description="Plans the site as `plan` does (give the same options), takes the "
        "stations as scanned (--as-scanned: the registered project's E57, scans named by "
        "station id, or a CSV station_id,x,y), judges every sample with them and proposes "
        "the fewest extra stations, each with its reason. Exit codes: 0 every requirement "
        "met with the extra stations; 1 some samples unmet; 2 bad input.",
    )
    _plan_arguments(rr)
    rr.add_argument("--out", required=True, metavar="DIR", help="folder for the new plan")
    _district_arguments(rr)
    rr.add_argument(
        "--as-scanned",
        required=True,
        metavar="FILE",
        help="the stations as scanned: an .e57 of the registered scans (their poses) or a "
        ".csv with station_id, x, y",
    )
    rr.add_argument(
        "--plan",
        metavar="DIR",
        help="the folder of the plan the crew followed (planner plan's --out): the plan made "
        "again from the options must be that one (its stations.csv), else exit 2",
    )
    rr.add_argument(
        "--targets-placed",
        metavar="CSV",
        help="the targets as placed (target_id, x, y); a planned target not listed was not "
        "set up. Default: as planned",
    )
    rr.add_argument(
        "--link-report",
        metavar="CSV",
        help="the registration program's link report (from, to, error [mm]; overlap "
        "optional): compared with the plan's predicted link errors (link_check.csv)",
    )
    rr.add_argument(
        "--booklet",
        action=argparse.BooleanOptionalAction,
        default=False,
        help="also draw the booklet's pages for the extra stations (booklet.pdf)",
    )
    rr.set_defaults(func=cmd_replan)


def _serve_command(sub: argparse._SubParsersAction) -> None:
    from planner.app.notebooks import DASHBOARDS

    sv = sub.add_parser("serve", help="serve the station-planner dashboard with Voilà on 127.0.0.1")
    sv.add_argument(
        "--port", type=argument("port"), default=8866, help="port on 127.0.0.1 (default 8866)"
    )
    sv.add_argument(
        "--kernel-idle-s",
        type=argument("kernel_idle_s"),
        default=600.0,
        metavar="S",
        help="shut down the kernel of a closed page after this long (default 600 s)",
    )
    sv.add_argument(
        "--notebook",
        default="station_planner.ipynb",
        choices=DASHBOARDS,
        help="which dashboard (default: the station planner)",
    )
    sv.set_defaults(func=cmd_serve)


def _calibrate_command(sub: argparse._SubParsersAction) -> None:
    cal = sub.add_parser("calibrate", help="turn calibration measurements into a scanner profile")
    csub = cal.add_subparsers(title="methods", parser_class=_Parser, required=True)

    _calibrate_lab_command(csub)
    _calibrate_baseline_command(csub)
    _calibrate_axes_command(csub)


def _profile_options(p: argparse.ArgumentParser) -> None:
    """The options every calibration method shares: where the profile goes."""
    p.add_argument("--profile-out", metavar="FILE.toml", help="write a scanner profile")
    p.add_argument(
        "--install",
        action="store_true",
        help="also install the profile in your profile folder, to use it by name "
        "($TLS_PLANNER_PROFILES or ~/.tls-planner/scanners)",
    )
    p.add_argument("--name", help="profile name (default: the file's stem)")
    p.add_argument(
        "--base-scanner",
        default=DEFAULT_SCANNER,
        metavar="NAME|FILE.toml",
        help="profile giving the figures not calibrated (step, ranges, field of view)",
    )


def _calibrate_lab_command(csub: argparse._SubParsersAction) -> None:
    lab = csub.add_parser("lab", help="laboratory uncertainty test (Helmert, m_r, M_r)")
    lab.add_argument("reference", metavar="REF.csv", help="lab-frame targets: id,x,y,z[,sigma_mm]")
    lab.add_argument("scan", metavar="SCAN.csv", help="scanner-frame targets: id,x,y,z")
    lab.add_argument(
        "--k",
        type=argument("coverage_factor"),
        default=2.0,
        help="coverage factor of M_r (default 2)",
    )
    lab.add_argument("--pairs", choices=["all", "first"], default="all")
    lab.add_argument("--reference-precision-mm", type=argument("rms_mm"), default=None)
    lab.add_argument(
        "--declared-precision-mm",
        type=argument("rms_mm"),
        default=None,
        help="the scanner's declared target precision, to check the reference network",
    )
    lab.add_argument(
        "--range-from",
        choices=["lab", "none"],
        default="lab",
        help="carry the distance m_r into the profile (default) or keep the base's",
    )
    lab.add_argument(
        "--angles-from",
        choices=["lab", "none"],
        default="none",
        help="carry the angular m_r (inflated at short lab distances) or keep the base's",
    )
    _profile_options(lab)
    lab.set_defaults(func=cmd_calibrate_lab)


def _calibrate_baseline_command(csub: argparse._SubParsersAction) -> None:
    bl = csub.add_parser("baseline", help="additive constant and scale from a baseline")
    bl.add_argument(
        "file",
        metavar="FILE.csv",
        help="measured_m,reference_m (baseline comparison) or from,to,distance_m (six-segment)",
    )
    bl.add_argument(
        "--include-scale",
        action="store_true",
        help="put |R| into the profile's ppm part (for data not corrected for scale)",
    )
    _profile_options(bl)
    bl.set_defaults(func=cmd_calibrate_baseline)


def _calibrate_axes_command(csub: argparse._SubParsersAction) -> None:
    ax = csub.add_parser("axes", help="collimation and trunnion-axis errors")
    ax.add_argument(
        "file", metavar="FILE.csv", help="vertical_angle_deg,observed_deg,reference_deg"
    )
    ax.add_argument(
        "--no-orientation",
        action="store_true",
        help="no orientation unknown (the paper's eq. 6: both zero directions equal)",
    )
    _profile_options(ax)
    ax.set_defaults(func=cmd_calibrate_axes)


def _audit_command(sub: argparse._SubParsersAction) -> None:
    au = sub.add_parser(
        "audit",
        help="audit a plan against a 3-D city model: which samples it marks met are seen, "
        "hidden by the real building, or have no wall there",
        description="Casts every sample a plan marks met against the model. Writes "
        "audit.csv into the plan's folder (or --out) and prints the count per building. "
        "Exit codes: 0 done; 2 bad input.",
    )
    au.add_argument("model", metavar="MODEL", help="the city model (CityJSON or CityGML)")
    au.add_argument("--plan", required=True, metavar="DIR", help="the plan's folder")
    au.add_argument("--lod", default=None, metavar="LOD", help="the model's level of detail")
    au.add_argument("--crs", default=None, metavar="CRS", help="the model's CRS if it names none")
    au.add_argument("--terrain", default=None, metavar="DTM.tif", help="a terrain model")
    au.add_argument("--out", default=None, metavar="FILE.csv", help="default DIR/audit.csv")
    au.set_defaults(func=cmd_audit)


def _figures_command(sub: argparse._SubParsersAction) -> None:
    f = sub.add_parser("figures", help="regenerate the figures in figures/")
    f.add_argument("--out", default="figures", help="output folder (default figures/)")
    f.set_defaults(func=cmd_figures)


def _log_internal_error(exc: BaseException) -> Path | None:
    """Write the traceback of an unexpected error to a log file; its path, or None."""
    try:
        fd, name = tempfile.mkstemp(
            prefix=f"tls-planner-error-{time.strftime('%Y%m%d-%H%M%S')}-", suffix=".log"
        )
        with open(fd, "w", encoding="utf-8") as fh:
            fh.write(f"planner {' '.join(sys.argv[1:])}\n\n")
            fh.write("".join(traceback.format_exception(exc)))
        return Path(name)
    except OSError:
        return None


@contextlib.contextmanager
def _stop_on_signals():
    """SIGTERM and SIGHUP end the command like Ctrl+C does: as an exception, so that every
    temporary file is removed on the way out (exit code 128 + the signal's number)."""

    def stop(signum: int, _frame: object) -> None:
        raise SystemExit(128 + signum)

    previous = {}
    for sig in (signal.SIGTERM, signal.SIGHUP):
        with contextlib.suppress(ValueError, OSError):  # not the main thread: leave it be
            previous[sig] = signal.signal(sig, stop)
    try:
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)


class _PrintableStream:
    """A text stream that writes user text as :func:`planner.text.printable` shows it: an
    id's ESC never reaches the terminal, a file name that is not UTF-8 prints as its bytes."""

    def __init__(self, stream: Any) -> None:
        self._stream = stream

    def write(self, text: str) -> int:
        # a line's leading carriage return is the progress bar's own (it redraws its line)
        lead = "\r" if text.startswith("\r") else ""
        return self._stream.write(lead + printable(text[len(lead) :], keep="\n\t"))

    def __getattr__(self, name: str) -> Any:
        return getattr(self._stream, name)


@contextlib.contextmanager
def _printable_output() -> Iterator[None]:
    """stdout and stderr as :class:`_PrintableStream` for the command's run."""
    out, err = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = _PrintableStream(out), _PrintableStream(err)
    try:
        yield
    finally:
        sys.stdout, sys.stderr = out, err


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command; the one boundary that turns every error into a message and an exit
    code (never a traceback): bad input 2, an unusable output place 2, a bug 3."""
    with _printable_output():
        return _main(argv)


def _main(argv: Sequence[str] | None) -> int:
    # the command's start: the process's when this process is the command (argv from its
    # command line), else now (called in a running program)
    started = command_started() if argv is None else time.monotonic()
    args = build_parser().parse_args(argv)
    args.started = started
    func: Callable[[argparse.Namespace], int] = args.func
    try:
        with _stop_on_signals():
            return func(args)
    except PlannerError as exc:
        print(f"planner: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except OSError as exc:
        if isinstance(exc, BrokenPipeError):
            return EXIT_OK
        where = f" {exc.filename!r}" if exc.filename else ""
        print(
            f"planner: error: cannot use{where}: {exc.strerror or exc}; check the path, the "
            "permissions and the free disk space",
            file=sys.stderr,
        )
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        print("planner: stopped", file=sys.stderr)
        return EXIT_INTERRUPTED
    except Exception as exc:  # a bug: one line, and the details in a log file
        log = _log_internal_error(exc)
        print(
            f"planner: internal error ({type(exc).__name__}: {str(exc)[:200]}); this is a bug"
            + (f" — details in {log}" if log else ""),
            file=sys.stderr,
        )
        return EXIT_INTERNAL
