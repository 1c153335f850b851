"""The plan as a HELIOS++ survey, for users of that scan simulator.

HELIOS++ (Winiwarter, Esmorís Pena, Weiser, Anders, Martínez Sánchez, Searle & Höfle,
"Virtual laser scanning with HELIOS++: A novel take on ray tracing-based simulation of
topographic full-waveform 3D laser scanning", Remote Sensing of Environment 269, 2022,
https://doi.org/10.1016/j.rse.2021.112772) reads a survey as XML: the scene (parts loaded
from OBJ files), the platform (a tripod for terrestrial scanning), the scanner, and one
*leg* per station with the scanner's settings. The files written here:

* ``helios_scene.obj`` — the plan's scene (buildings, terrain, trees; the flat ground as a
  square where the site has no terrain) in a local frame about :attr:`Scene.origin`
  (single-precision loaders keep millimetres there; the origin is written in every file);
* ``helios_scene.xml`` — the scene, one part from that OBJ;
* ``helios_scanner.xml`` — the plan's scanner as a HELIOS++ scanner (accuracy, beam
  divergence, pulse rate, range, a rotating head about the vertical);
* ``helios_survey.xml`` — a leg per scanning station (its position in the local frame, on
  the ground; the scanner's vertical field, a full turn of the head, the preset's angular
  step), referring to HELIOS++'s own ``data/platforms.xml#tripod``.

HELIOS++ publishes no XML schema; :func:`check_survey` checks the files against the
elements and attributes of HELIOS++'s own demonstration surveys and scanners (its
``data/surveys/toyblocks/tls_toyblocks.xml`` and ``data/scanners_tls.xml``: a 4 ns pulse
and a head turning at most 360°/s as there) and every reference among them;
:func:`read_survey` reads a survey back. The files have not been run in HELIOS++ here.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from planner.errors import InputError
from planner.pipeline.engine.result import Plan
from planner.pipeline.geometry.scene import Scene
from planner.pipeline.survey.rehearsal import station_centres
from planner.scanner import Scanner

__all__ = ["FILES", "check_survey", "helios_files", "read_survey"]

FILES = ("helios_survey.xml", "helios_scene.xml", "helios_scanner.xml", "helios_scene.obj")
#: The tripod platform HELIOS++ ships (its mount height is HELIOS++'s, said in the survey).
PLATFORM = "data/platforms.xml#tripod"
#: The pulse rate written where the profile gives no measurement rate [Hz].
DEFAULT_PULSE_HZ = 100_000
#: The beam divergence written where the profile gives none [mrad] (HELIOS++'s own
#: terrestrial scanners, data/scanners_tls.xml, take 0.3 mrad).
DEFAULT_DIVERGENCE_MRAD = 0.3
_ID = "tls_planner"


def _obj(plan: Plan, scene: Scene) -> bytes:
    tri = scene.mesh[0] - scene.origin
    if plan.site.terrain is None:  # the flat ground, as far as the scanner reaches
        r = plan.scanner.max_range_m + float(np.ptp(tri[..., :2])) if len(tri) else 500.0
        z = -scene.origin[2]
        c = [[-r, -r, z], [r, -r, z], [r, r, z], [-r, r, z]]
        ground = np.array([[c[0], c[1], c[2]], [c[0], c[2], c[3]]])
        tri = np.concatenate([tri, ground]) if len(tri) else ground
    o = scene.origin
    lines = [
        "# tls-planner scene for HELIOS++",
        f"# local frame: site CRS minus origin E {o[0]:.3f} N {o[1]:.3f} H {o[2]:.3f} m",
    ]
    lines += [f"v {x:.4f} {y:.4f} {z:.4f}" for x, y, z in tri.reshape(-1, 3)]
    lines += [f"f {3 * k + 1} {3 * k + 2} {3 * k + 3}" for k in range(len(tri))]
    return ("\n".join(lines) + "\n").encode()


def _xml(root: ET.Element, comment: str) -> bytes:
    ET.indent(root)
    body = ET.tostring(root, encoding="unicode")
    comment = comment.replace("--", "–")  # not allowed inside an XML comment
    return f'<?xml version="1.0" encoding="UTF-8"?>\n<!-- {comment} -->\n{body}\n'.encode()


def helios_files(plan: Plan, scene: Scene | None = None) -> dict[str, bytes]:
    """The four files of the survey (module text), by name."""
    scene = scene or Scene(plan.site, "rays")
    o = scene.origin
    where = f"tls-planner; local frame = site CRS minus (E {o[0]:.3f}, N {o[1]:.3f}, H {o[2]:.3f})"
    return {
        "helios_survey.xml": _survey_xml(plan, o, where),
        "helios_scene.xml": _scene_xml(where),
        "helios_scanner.xml": _scanner_xml(plan.scanner, where),
        "helios_scene.obj": _obj(plan, scene),
    }


def _scene_xml(where: str) -> bytes:
    """The scene: the OBJ beside it."""
    doc = ET.Element("document")
    sn = ET.SubElement(doc, "scene", id=_ID, name="tls-planner site")
    part = ET.SubElement(sn, "part")
    f = ET.SubElement(part, "filter", type="objloader")
    ET.SubElement(f, "param", type="string", key="filepath", value="helios_scene.obj")
    return _xml(doc, where)


def _scanner_xml(sc: Scanner, where: str) -> bytes:
    """The scanner from its profile: accuracy, divergence, pulse rate, range, field."""
    doc = ET.Element("document")
    lo, hi = sc.vertical_fov_deg
    scanner = ET.SubElement(
        doc,
        "scanner",
        id=_ID,
        name=sc.label,
        accuracy_m=f"{sc.range_rms_mm / 1000:.5f}",
        beamDivergence_rad=f"{(sc.beam_divergence_mrad or DEFAULT_DIVERGENCE_MRAD) / 1e3:.6f}",
        optics="rotating",
        pulseFreqs_Hz=str(int(sc.measurement_rate_hz or DEFAULT_PULSE_HZ)),
        pulseLength_ns="4",
        rangeMin_m=f"{sc.min_range_m:g}",
        rangeMax_m=f"{sc.max_range_m:g}",
        scanAngleMax_deg=f"{max(abs(lo), abs(hi)):g}",
        scanAngleEffectiveMax_deg=f"{max(abs(lo), abs(hi)):g}",
        scanFreqMin_Hz="0",
        scanFreqMax_Hz="200",
        headRotatePerSecMax_deg="360",
    )
    origin = ET.SubElement(scanner, "beamOrigin", x="0", y="0", z="0")
    ET.SubElement(origin, "rot", axis="x", angle_deg="0")
    ET.SubElement(scanner, "headRotateAxis", x="0", y="0", z="1")
    return _xml(doc, f"{where}; figures from the profile ({sc.source})")


def _survey_xml(plan: Plan, o: np.ndarray, where: str) -> bytes:
    """One leg per scanning station: the tripod on the ground below the scanner's centre,
    the scanner's vertical field, a full head turn at the preset's angular step."""
    sc, st = plan.scanner, plan.settings
    lo, hi = sc.vertical_fov_deg
    step_deg = np.degrees(st.scan_step_mm(sc) / 1e4)
    doc = ET.Element("document")
    survey = ET.SubElement(
        doc,
        "survey",
        name="tls_planner_plan",
        scene=f"helios_scene.xml#{_ID}",
        platform=PLATFORM,
        scanner=f"helios_scanner.xml#{_ID}",
    )
    ids, xyz = station_centres(plan)
    height = plan.stations.set_index("station_id")["instrument_height_m"]
    for sid, p in zip(ids, xyz, strict=True):
        leg = ET.SubElement(survey, "leg")
        leg.append(ET.Comment(f" {sid} "))
        x, y, z = p - o
        ET.SubElement(
            leg,
            "platformSettings",
            x=f"{x:.4f}",
            y=f"{y:.4f}",
            z=f"{z - float(height[sid]):.4f}",
            onGround="true",
        )
        ET.SubElement(
            leg,
            "scannerSettings",
            active="true",
            pulseFreq_hz=str(int(sc.measurement_rate_hz or DEFAULT_PULSE_HZ)),
            verticalAngleMin_deg=f"{lo:g}",
            verticalAngleMax_deg=f"{hi:g}",
            headRotateStart_deg="0",
            headRotateStop_deg="360",
            horizontalResolution_deg=f"{step_deg:.6f}",
            verticalResolution_deg=f"{step_deg:.6f}",
        )
    return _xml(
        doc,
        f"{where}; run from the HELIOS++ folder (the tripod is its data/platforms.xml's, "
        f"mounting the scanner at its own height; the plan's is {st.instrument_height_m:g} m)",
    )


#: What HELIOS++'s loader reads of each element: (path, required attributes).
_REQUIRED = {
    "survey": ("survey", ("name", "scene", "platform", "scanner")),
    "leg": ("survey/leg/platformSettings", ("x", "y", "z", "onGround")),
    "settings": (
        "survey/leg/scannerSettings",
        ("active", "pulseFreq_hz", "headRotateStart_deg", "headRotateStop_deg"),
    ),
    "scene": ("scene", ("id",)),
    "scanner": (
        "scanner",
        ("id", "accuracy_m", "beamDivergence_rad", "optics", "pulseFreqs_Hz", "rangeMin_m"),
    ),
}


def _parse(data: bytes, name: str) -> ET.Element:
    if b"<!DOCTYPE" in data or b"<!ENTITY" in data:
        raise InputError(f"{name}: a document type or entity; not a HELIOS++ file of the planner")
    try:
        parser = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True))
        parser.feed(data)
        return parser.close()
    except ET.ParseError as exc:
        raise InputError(f"{name}: not well-formed XML ({exc})") from None


def check_survey(files: dict[str, bytes]) -> list[str]:
    """The faults of a survey's files against what HELIOS++ reads (empty: none): each
    element's required attributes, numbers where numbers go, and every reference (scene
    and scanner ids, the OBJ file) resolved among ``files``."""
    faults: list[str] = []
    roots = {n: _parse(files[n], n) for n in FILES[:3] if n in files}
    faults += [f"{n} is missing" for n in FILES if n not in files]
    for key, (path, attrs) in _REQUIRED.items():
        name = "helios_survey.xml" if key in ("survey", "leg", "settings") else f"helios_{key}.xml"
        if name not in roots:
            continue
        found = roots[name].findall(path)
        if not found:
            faults.append(f"{name}: no <{path}>")
        for el in found:
            faults += [f"{name}: <{el.tag}> lacks {a}" for a in attrs if a not in el.attrib]
            for a, v in el.attrib.items():
                if a.endswith(("_m", "_deg", "_hz", "_Hz", "_rad", "_ns")) or a in "xyz":
                    try:
                        float(v.split(",")[0])
                    except ValueError:
                        faults.append(f"{name}: <{el.tag} {a}={v!r}> is not a number")
    if "helios_survey.xml" in roots:
        s = roots["helios_survey.xml"].find("survey")
        for ref, file_name, tag in (
            ("scene", "helios_scene.xml", "scene"),
            ("scanner", "helios_scanner.xml", "scanner"),
        ):
            target = (s.get(ref) or "#") if s is not None else "#"
            file_part, _, ident = target.partition("#")
            if file_part != file_name:
                faults.append(f"survey's {ref} refers to {file_part!r}, not {file_name}")
            elif file_name in roots and roots[file_name].find(f"{tag}[@id='{ident}']") is None:
                faults.append(f"{file_name} has no {tag} {ident!r}")
    if "helios_scene.xml" in roots:
        for p in roots["helios_scene.xml"].iter("param"):
            if p.get("key") == "filepath" and p.get("value") not in files:
                faults.append(f"the scene's OBJ {p.get('value')!r} is not among the files")
    return faults


def read_survey(path: str | Path) -> list[dict]:
    """The legs of a HELIOS++ survey file: each one's station (from its comment), position
    in the survey's frame [m] and scanner settings."""
    root = _parse(Path(path).read_bytes(), str(path))
    legs = []
    for leg in root.iter("leg"):
        ps, ss = leg.find("platformSettings"), leg.find("scannerSettings")
        if ps is None or ss is None:
            raise InputError(f"{path}: a leg without platformSettings or scannerSettings")
        note = next((c.text.strip() for c in leg if c.tag is ET.Comment and c.text), "")
        legs.append(
            {
                "station_id": note,
                "xyz": np.array([float(ps.get(k, "nan")) for k in "xyz"]),
                **dict(ss.attrib),
            }
        )
    return legs
