"""The command line's commands (``cmd_*``, :func:`run_plan`): each reads its inputs, calls
the package and prints or writes; each returns its exit code (``EXIT_*``).

A command imports the part of the package it needs when it runs (the imports inside the
functions): ``planner --help``, ``planner scanners`` and a refused input answer in under a
second instead of loading the planner's NumPy/SciPy/shapely/Numba stack (about 1 s more)
first.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from collections.abc import Callable
from dataclasses import fields, replace
from pathlib import Path

import pandas as pd

from planner.errors import InputError
from planner.pipeline.inputs.schema import to_csv
from planner.reading import user_file
from planner.scanner import DEFAULT_SCANNER, Scanner, catalogue, load_scanner
from planner.tables import (
    height_table,
    planimetric_table,
    target_size_table,
)
from planner.targets import recommend_targets

EXIT_OK = 0


EXIT_UNMET = 1


EXIT_BAD_INPUT = 2


EXIT_INTERNAL = 3


EXIT_INTERRUPTED = 130


def _fmt(df: pd.DataFrame, fmt: str, decimals: int = 1) -> str:
    if fmt == "csv":
        return df.to_csv(float_format=f"%.{decimals + 2}f")
    return df.to_string(float_format=lambda v: f"{v:.{decimals}f}")


def _flat_columns(df: pd.DataFrame, label: str) -> pd.DataFrame:
    out = df.copy()
    out.columns = [f"{a} {label}={b:g}" for a, b in df.columns]
    return out


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
    write_bytes_atomic(out, to_csv(table).encode("utf-8"))
    summary = audit_summary(table)
    print(summary.to_string(index=False))
    print(f"audit of {len(table)} samples marked met: {out}")
    return EXIT_OK


class _StderrProgress:
    """Progress on stderr: a bar on a terminal (the step, the seconds so far and, once a
    tenth is done, about how many are left at the pace so far), a line per stage otherwise
    (with the seconds so far)."""

    def __init__(self, quiet: bool) -> None:
        self.quiet = quiet
        self.tty = sys.stderr.isatty()
        self.last = ""
        self.t0 = time.monotonic()

    def __call__(self, fraction: float, message: str) -> None:
        if self.quiet:
            return
        stage = message.split(" ")[0]
        took = time.monotonic() - self.t0
        if self.tty:
            from planner.app.wording import time_words

            bar = "#" * int(30 * fraction)
            clock = time_words(took, fraction)
            sys.stderr.write(f"\r[{bar:<30}] {100 * fraction:3.0f}% {message[:44]:<44} {clock:<22}")
            if fraction >= 1.0:
                sys.stderr.write("\n")
            sys.stderr.flush()
        elif stage != self.last:
            print(f"planner: [{took:4.0f} s] {message}", file=sys.stderr)
        self.last = stage


def _where_the_time_went(p, quiet: bool) -> None:
    """The plan's seconds per stage, on stderr (not in the files: they hold what the plan
    is, the same on any machine)."""
    spent = {k: v for k, v in p.timings_s.items() if not k.endswith("_mb")}
    if quiet or not spent:
        return
    total = spent.pop("total", None)
    words = ", ".join(f"{k} {v:.1f} s" for k, v in spent.items() if v >= 0.05)
    print(
        f"planner: where the time went: {words}"
        + (f"; {total:.1f} s in all" if total is not None else ""),
        file=sys.stderr,
    )


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
    if args.materials:
        from planner.materials import read_material_file

        options["materials"] = tuple(read_material_file(args.materials))
    req, settings = requirements_and_settings(options)
    scanner = load_scanner(args.scanner or DEFAULT_SCANNER)
    if args.levelling_rms_arcsec is not None:
        scanner = scanner.with_levelling(args.levelling_rms_arcsec)
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
    if args.surroundings:
        from planner.siteio import with_surroundings

        site = with_surroundings(
            site, args.surroundings, crs=args.crs, default_height_m=args.height
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
    p = user_file(path, what)
    try:
        return p.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        raise InputError(f"{what} {path!r} is not UTF-8 text") from None


#: The options that name a file the command reads.
INPUT_OPTIONS = (
    "site", "zones", "control", "inventory", "materials", "scanner", "terrain", "mesh", "model",
    "surroundings", "reference", "scan", "file",
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


#: The share of ``--time-limit-s`` kept for the plan's documents in district mode: the
#: district's bound on shared stations is given up before it. (A plan itself is decided by
#: work; its documents are whole whatever the clock says.)
DOCUMENT_SHARE = 0.15


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


def _jobs(args: argparse.Namespace, site, scanner, req, settings):
    """The site's jobs (:func:`~planner.pipeline.district.groups.job_groups`), their halo,
    the settings with the budget grown to the jobs' estimated time unless
    ``--time-limit-s`` was given, and the words saying so (said now, on stderr, before the
    plan starts; "" for one job)."""
    from planner.pipeline.district.groups import job_groups, job_sites, jobs_words

    groups, halo = job_groups(site, scanner, req, settings)
    if len(groups) < 2:
        return groups, halo, settings, ""
    given = getattr(args, "time_limit_s", None) is not None
    need = sum(job_sites(site, groups, halo, settings)[1])
    if not given:
        settings = replace(
            settings, time_limit_s=max(settings.time_limit_s, need / (1 - DOCUMENT_SHARE))
        )
    words = jobs_words(site, groups, settings.time_limit_s, given)
    if not args.quiet:
        print(words, file=sys.stderr, flush=True)
    return groups, halo, settings, words


def _one_job(args: argparse.Namespace, scanner, req, settings, district_by: float):
    """How one site (or one job of several) is planned: block by block on Dask where
    :func:`_district` says (its schedule ending by ``until``, or ``district_by``), else in
    this process (decided by work alone)."""

    def one(site, until: float | None, say):
        if _district(args, site, settings):
            from planner.pipeline.district.schedule import plan_district

            return plan_district(
                site,
                scanner,
                req,
                settings,
                block_m=args.block_m,
                scheduler=args.scheduler,
                workers=args.workers,
                memory_limit=args.worker_memory,
                progress=say,
                deadline=district_by if until is None else until,
            )
        from planner.pipeline.engine.planning import plan

        return plan(site, scanner, req, settings, progress=say)

    return one


def make_plan(args: argparse.Namespace, progress: Callable[[float, str], None]):
    """The plan of the options shared by ``plan``, ``report``, ``rehearse`` and ``replan``
    — the one function they use, so that a report shows exactly the plan ``plan`` makes:
    jobs of buildings far apart each planned on its own (:func:`_jobs`), a job in district
    mode where ``plan`` would take it (:func:`_district`). The plan is decided by work, not
    by the clock (:func:`planner.pipeline.engine.planning.plan`); only the district mode
    schedules its blocks on the wall clock (its bound given up by :data:`DOCUMENT_SHARE` of
    ``--time-limit-s`` before the end, counted from the command's start)."""
    from planner.pipeline.district.groups import jobs_plan
    from planner.pipeline.inputs.requirements import WORKER_MEMORY

    started = getattr(args, "started", None) or time.monotonic()
    if args.worker_memory != WORKER_MEMORY:  # checked even where the plan needs no cluster
        from planner.pipeline.district.schedule import memory_bytes  # (Dask: 0.2 s to import)

        memory_bytes(args.worker_memory)
    site, scanner, req, settings = plan_inputs(args)
    groups, halo, settings, words = _jobs(args, site, scanner, req, settings)
    planned_by = started + (1 - DOCUMENT_SHARE) * settings.time_limit_s
    one = _one_job(args, scanner, req, settings, planned_by)
    if len(groups) < 2:
        return one(site, None, progress)
    result = jobs_plan(site, scanner, req, settings, groups, halo, one, progress=progress)
    result.messages.insert(1, words + ".")
    return result


def run_plan(args: argparse.Namespace) -> int:
    """Plan, draw the booklet and write the files (:func:`make_plan`); the booklet is
    always whole."""
    from planner.atomic import check_inputs_kept, check_output_folder
    from planner.pipeline.documents.export import OWNED_FILES, save

    progress = _StderrProgress(args.quiet)
    check_output_folder(args.out)  # before the plan, which can take minutes
    check_inputs_kept([Path(args.out) / name for name in OWNED_FILES], _input_paths(args))
    import ezdxf  # noqa: F401  (the DXF writer's import, 0.7 s, made now: not after planning)

    result = make_plan(args, progress)
    _where_the_time_went(result, args.quiet)
    extra = {}
    if args.booklet:
        from planner.app.booklet import booklet_pdf

        progress(1.0, "field booklet (booklet.pdf)")
        extra["booklet.pdf"] = booklet_pdf(result)
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
    result = make_plan(args, _StderrProgress(args.quiet))
    if args.plan:
        from planner.pipeline.survey.asscanned import check_same_plan

        check_same_plan(result, args.plan)
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
    result = make_plan(args, _StderrProgress(args.quiet))
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
    result = make_plan(args, _StderrProgress(args.quiet))
    if args.plan:
        check_same_plan(result, args.plan)
    r = replan(result, scanned, targets_placed=placed, progress=_StderrProgress(args.quiet))
    files = {"as_scanned.csv": to_csv(r.stations).encode()}
    if report is not None:
        check = compare_links(r.scanned_plan, report)
        files["link_check.csv"] = to_csv(check).encode()
    if args.booklet and len(r.extra):
        from planner.app.booklet import booklet_pdf

        files["booklet.pdf"] = booklet_pdf(r.plan, only=set(r.extra["station_id"]))
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


def cmd_calibrate_signal(args: argparse.Namespace) -> int:
    _profile_name(args)  # a bad name stops here, before any work
    from planner.calibration import signal_calibration
    from planner.signal import DEFAULT_REFERENCE_REFLECTANCE

    r = signal_calibration(args.file, args.reference_reflectance or DEFAULT_REFERENCE_REFLECTANCE)
    print(*r.lines(), sep="\n")
    _print_table(r.residuals.set_index(["reflectance", "incidence_deg"]), 3)
    range_from = None if args.range_from == "none" else args.range_from
    _write_profile(args, signal=r, range_from=range_from)
    return EXIT_OK


def cmd_serve(args: argparse.Namespace) -> int:
    from planner.app.notebooks import notebook_path
    from planner.app.serve import serve

    return serve(notebook_path(args.notebook), args.port, kernel_idle_s=args.kernel_idle_s)
