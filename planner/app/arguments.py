"""The command line's parser (:func:`build_parser`): one function per command, and the plan
options made from the data classes' fields (name, unit, help, default), so that the
commands and the data classes cannot drift apart. A bad option is exit 2 with argparse's
message.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from dataclasses import fields

from planner.app.commands import (
    EXIT_BAD_INPUT,
    cmd_accuracy,
    cmd_audit,
    cmd_calibrate_axes,
    cmd_calibrate_baseline,
    cmd_calibrate_lab,
    cmd_calibrate_signal,
    cmd_figures,
    cmd_rehearse,
    cmd_replan,
    cmd_report,
    cmd_scanners,
    cmd_serve,
    cmd_targets,
    run_plan,
)
from planner.errors import InputError
from planner.ranges import argument
from planner.scanner import DEFAULT_SCANNER
from planner.tables import (
    PAPER_DISTANCES_M,
    PAPER_GAMMAS_DEG,
    PAPER_NUS_DEG,
    SOSSA_DISTANCES_M,
)


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


def _scanner_arg(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "--scanner",
        default=DEFAULT_SCANNER,
        metavar="NAME|FILE.toml",
        help=f"catalogue name ('planner scanners') or a profile file (default {DEFAULT_SCANNER})",
    )


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
        "--levelling-rms-arcsec",
        metavar="ARCSEC",
        type=argument("levelling_rms_arcsec"),
        default=None,
        help="the scanner's levelling (its compensator's accuracy per axis) [″], where the "
        "profile gives none or your own test gives better: the heights far from the datum "
        "scan lean by it",
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
        "--surroundings",
        default=None,
        metavar="FILE",
        help="what stands around the site, from a second site file in its CRS (footprints "
        "with heights, trees, obstacles, no-go areas; e.g. an OpenStreetMap export beside a "
        "city model that holds only its buildings): blocks the beam and keeps stations out, "
        "never planned; a building that is one of the site's is left out, and said",
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
    from planner.materials import CONDITIONS
    from planner.pipeline.inputs.requirements import METHODS, MODELS

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
    group["model"].add_argument(
        "--surface-condition",
        choices=CONDITIONS,
        default=None,
        help="the survey day: dry (default), or wet after rain (porous walls darker: noisier "
        "ranging, shorter reach)",
    )
    group["model"].add_argument(
        "--materials",
        default=None,
        metavar="FILE",
        help="your own facade materials added to the shipped table (TOML, [[material]] tables "
        "with name, reflectance, wet_reflectance, roughness_mm, returns, aliases: the format "
        "of planner/data/materials.toml)",
    )
    group["model"].add_argument(
        "--default-material",
        default=None,
        metavar="NAME",
        help="the material of walls no site, model or zone names (default: the scanner "
        "datasheet's reference surface, the figures as published)",
    )
    _registration_arguments(group["registration"])


def _registration_arguments(group: argparse._ArgumentGroup) -> None:
    """How the scans are registered and what the registration assumes."""
    from planner.pipeline.inputs.requirements import (
        HEIGHT_CONTROL,
        LINK_CHECKS,
        REGISTRATION_MODES,
        REGISTRATION_PROCESSING,
        TILT_READINGS,
    )

    group.add_argument(
        "--registration",
        choices=REGISTRATION_MODES,
        default=None,
        help="how the scans are registered: targets, cloud (cloud to cloud on the surfaces "
        "the scans share), hybrid (cloud links, targets where a link is weak), or auto: the "
        "scanner profile's usual workflow, else targets (default)",
    )
    group.add_argument(
        "--registration-processing",
        choices=REGISTRATION_PROCESSING,
        default=None,
        help="what the promised registration error assumes of the registration software: "
        + "; or ".join(f"{k}, {v}" for k, v in REGISTRATION_PROCESSING.items())
        + " (default adjustment)",
    )
    group.add_argument(
        "--link-check",
        choices=LINK_CHECKS,
        default=None,
        help="how the plan checks each cloud-to-cloud link it relies on: "
        + "; or ".join(f"{k}, {v}" for k, v in LINK_CHECKS.items()).replace("%", "%%")
        + " (default rehearse)",
    )
    group.add_argument(
        "--height-control",
        choices=HEIGHT_CONTROL,
        default=None,
        help="; or ".join(f"{k}: {v}" for k, v in HEIGHT_CONTROL.items()) + " (default level)",
    )
    group.add_argument(
        "--tilt-readings",
        choices=TILT_READINGS,
        default=None,
        help="for a scanner that records its tilt with every scan and has no compensator "
        "(its profile's tilt_sensor_rms_arcsec), which readings hold the network's vertical: "
        + "; or ".join(f"{k}, {v}" for k, v in TILT_READINGS.items())
        + " (default every-scan, with the adjustment)",
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
    p.set_defaults(func=_serve_by_default)
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


def _serve_by_default(args: argparse.Namespace) -> int:
    """The main job, ``planner`` without a command: serve the station-planner dashboard
    (it opens on the default site) with the serve command's defaults."""
    serve = build_parser().parse_args(["serve"])
    return serve.func(serve)


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
    _plan_folder_argument(rp, "to report")
    rp.set_defaults(func=cmd_report)


def _plan_folder_argument(parser: argparse.ArgumentParser, which: str) -> None:
    """``--plan DIR``: the folder of the plan a command works from (``planner plan``'s
    ``--out``); the plan made again from the options must be that one."""
    parser.add_argument(
        "--plan",
        metavar="DIR",
        help=f"the folder of the plan {which} (planner plan's --out): the plan made again "
        "from the options must be that one (its stations.csv), else exit 2 — the same "
        "options give the same plan on any machine",
    )


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
    _plan_folder_argument(rr, "the crew followed")
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
    _calibrate_signal_command(csub)


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


def _calibrate_signal_command(csub: argparse._SubParsersAction) -> None:
    sg = csub.add_parser(
        "signal", help="the ranging noise by returned signal, from planes of known reflectance"
    )
    sg.add_argument(
        "file",
        metavar="FILE.csv",
        help="one plane per row: reflectance (0-1), incidence_deg, residual_rms_mm (the plane "
        "fit's residual RMS along its normal)",
    )
    sg.add_argument(
        "--reference-reflectance",
        type=argument("reflectance"),
        default=None,
        help="the reflectance m_0 is stated on (default 0.8, as datasheets state theirs)",
    )
    sg.add_argument(
        "--range-from",
        choices=["signal", "none"],
        default="none",
        help="carry m_0 into the profile as its ranging RMS, or keep the base's (default): "
        "the exponent and reference reflectance are carried either way",
    )
    _profile_options(sg)
    sg.set_defaults(func=cmd_calibrate_signal)


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
