"""What is wrong with a site file, all at once, and what was repaired.

A real export (OpenStreetMap, a city's cadastre) has many problems at once: buildings
without heights, self-intersecting outlines, buildings drawn twice or overlapping their
neighbours. The site reports them together — a count per kind, the first few features and
the fix — never one per run (:class:`SiteProblems`). A problem only in features far from
the buildings to plan (farther than :attr:`planner.site.SiteLimits.near_m`, beyond any
station's reach) cannot change the plan: the feature is repaired or left out, and that is
noted (:class:`SiteNote`), not refused. What a repair did, feature by feature or pair by
pair, is the table :data:`NOTE_COLUMNS` (``site_repairs.csv`` beside the plan); the plan's
summary gives one line per kind.

Overlapping buildings (:func:`resolve_overlaps`, with the explicit repair): a thin overlap
along a shared wall (digitising noise) is snapped — the smaller building's vertices moved
onto the larger's outline, then the overlap cut from it — so that the wall is one party
wall; a small overlap is clipped from the smaller building; a large one (a building drawn
twice, a building part inside its building) is reported and left to the user.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd
import shapely
from shapely.geometry import MultiPolygon, Polygon
from shapely.geometry.base import BaseGeometry

from planner.errors import InputError

__all__ = [
    "NOTE_COLUMNS",
    "SiteNote",
    "SiteProblem",
    "SiteProblems",
    "near_mask",
    "notes_summary",
    "notes_table",
    "resolve_overlaps",
]

#: An overlap thinner than this (its area over half its perimeter) lies along a shared wall
#: digitised twice: snapped [m].
SNAP_M = 0.5
#: An overlap up to this share of the smaller building's area is clipped from it; a larger
#: one is left to the user.
CLIP_SHARE = 0.10
#: How many features a message names per kind before "and N more".
SHOWN = 3

#: Every kind of problem: how a message counts it (one, many).
PROBLEM_KINDS = {
    "role": ("feature with an unknown role", "features with an unknown role"),
    "geometry": ("feature without a usable outline", "features without a usable outline"),
    "extent": ("feature out of any real extent", "features out of any real extent"),
    "id": ("duplicate id", "duplicate ids"),
    "height": ("bad height", "bad heights"),
    "no-height": ("building without a height", "buildings without a height"),
    "edge": ("outline with a zero-length edge", "outlines with a zero-length edge"),
    "outline": ("invalid outline", "invalid outlines"),
    "overlap": ("pair of overlapping buildings", "pairs of overlapping buildings"),
    "obstacle-overlap": (
        "obstacle overlapping a building",
        "obstacles overlapping buildings",
    ),
    "boundary": ("building outside the boundary", "buildings outside the boundary"),
    "site": ("problem with the site as a whole", "problems with the site as a whole"),
    "control": ("control point problem", "control point problems"),
    "zone": ("zone problem", "zone problems"),
    "passage": ("passage problem", "passage problems"),
}


@dataclass(frozen=True)
class SiteProblem:
    """One problem that stops the plan: what is wrong (naming the features) and the fix."""

    kind: str  # a key of PROBLEM_KINDS
    ids: tuple[str, ...]
    text: str
    fix: str = ""

    def __str__(self) -> str:
        return f"{self.text}; {self.fix}" if self.fix else self.text


class SiteProblems(InputError):
    """Every problem found in a site, reported together: a count per kind, the first
    :data:`SHOWN` features of each and the fix."""

    def __init__(self, problems: Sequence[SiteProblem], origin: str = "") -> None:
        self.problems = list(problems)
        self.origin = origin
        super().__init__(problems_message(self.problems, origin))


def problems_message(problems: Sequence[SiteProblem], origin: str = "") -> str:
    """One problem as its sentence; several as a line per kind."""
    where = f"{origin}: " if origin else ""
    if len(problems) == 1:
        return where + str(problems[0])
    kinds: dict[str, list[SiteProblem]] = {}
    for p in problems:
        kinds.setdefault(p.kind, []).append(p)
    lines = [
        f"{where}the site has {len(problems)} problems, in the buildings to plan or near them "
        "(nothing was planned):"
    ]
    for kind, group in kinds.items():
        one, many = PROBLEM_KINDS.get(kind, (kind, kind))
        shown = "; ".join(p.text for p in group[:SHOWN])
        more = f"; and {len(group) - SHOWN} more" if len(group) > SHOWN else ""
        fix = f" — {group[0].fix}" if group[0].fix else ""
        lines.append(f"  {len(group)} {one if len(group) == 1 else many}: {shown}{more}{fix}")
    return "\n".join(lines)


@dataclass(frozen=True)
class SiteNote:
    """A repair made, or a problem let pass because it cannot change the plan, for one
    feature or one pair: a row of ``site_repairs.csv``."""

    kind: str  # what was found, e.g. "overlap", "no-height", "outline"
    ids: tuple[str, ...]
    action: str  # what was done, e.g. "snapped", "clipped", "left", "levels", "default"
    detail: str = ""
    area_m2: float = math.nan
    x: float = math.nan
    y: float = math.nan

    def words(self) -> str:
        """This note in the summary's words, for its features (a map's hover)."""
        one = NOTE_WORDS.get((self.kind, self.action), (f"{self.kind}: {self.action}",))[0]
        return f"{' and '.join(self.ids)}: {one}" + (f" ({self.detail})" if self.detail else "")

    @property
    def key(self) -> tuple[str, tuple[str, ...], str]:
        return (self.kind, self.ids, self.action)


#: The columns of ``site_repairs.csv``.
NOTE_COLUMNS = ["kind", "feature_ids", "action", "area_m2", "x", "y", "detail"]

#: How the summary says each (kind, action), for one and for many (a count is put in front).
NOTE_WORDS = {
    ("no-height", "levels"): (
        "building height taken from building:levels × the storey height",
        "building heights taken from building:levels × the storey height",
    ),
    ("no-height", "default"): (
        "building without a height given the default height",
        "buildings without a height given the default height",
    ),
    ("no-height", "far"): (
        "building without a height, far from the planned ones, given",
        "buildings without a height, far from the planned ones, given",
    ),
    ("height", "far"): (
        "bad height, far from the planned buildings, replaced",
        "bad heights, far from the planned buildings, replaced",
    ),
    ("outline", "repaired"): (
        "outline repaired (repeated vertices, make_valid)",
        "outlines repaired (repeated vertices, make_valid)",
    ),
    ("outline", "thinned"): (
        "dense outline thinned (vertices within 1 cm of a straight line dropped)",
        "dense outlines thinned (vertices within 1 cm of a straight line dropped)",
    ),
    ("outline", "far"): (
        "invalid outline, far from the planned buildings, repaired",
        "invalid outlines, far from the planned buildings, repaired",
    ),
    ("edge", "far"): (
        "outline with a zero-length edge, far from the planned buildings, repaired",
        "outlines with a zero-length edge, far from the planned buildings, repaired",
    ),
    ("geometry", "dropped"): (
        "feature without a usable outline, far from the planned buildings, left out",
        "features without a usable outline, far from the planned buildings, left out",
    ),
    ("extent", "dropped"): (
        "feature larger than a real building, far from the planned ones, left out",
        "features larger than a real building, far from the planned ones, left out",
    ),
    ("overlap", "snapped"): (
        "overlapping pair along a shared wall, snapped",
        "overlapping pairs along a shared wall, snapped",
    ),
    ("overlap", "clipped"): (
        "small overlap, clipped from the smaller building",
        "small overlaps, clipped from the smaller building",
    ),
    ("overlap", "left"): (
        "overlapping pair, far from the planned buildings, left as it is",
        "overlapping pairs, far from the planned buildings, left as they are",
    ),
    ("obstacle-overlap", "left"): (
        "obstacle overlapping a building, far from the planned ones, left",
        "obstacles overlapping buildings, far from the planned ones, left",
    ),
    ("part", "dropped"): (
        "building part inside its building's outline, left out",
        "building parts inside their buildings' outlines, left out",
    ),
    ("other", "dropped"): (
        "feature that is not a building (a road, a path), left out",
        "features that are not buildings (roads, paths), left out",
    ),
    ("id", "renamed"): (
        "duplicate id, far from the planned buildings, renamed",
        "duplicate ids, far from the planned buildings, renamed",
    ),
}


def notes_table(notes: Sequence[SiteNote]) -> pd.DataFrame:
    """The notes as the rows of ``site_repairs.csv`` (:data:`NOTE_COLUMNS`)."""
    return pd.DataFrame(
        [
            {
                "kind": n.kind,
                "feature_ids": ";".join(n.ids),
                "action": n.action,
                "area_m2": n.area_m2,
                "x": n.x,
                "y": n.y,
                "detail": n.detail,
            }
            for n in notes
        ],
        columns=NOTE_COLUMNS,
    )


def notes_summary(notes: Sequence[SiteNote], file_name: str = "site_repairs.csv") -> list[str]:
    """One line per kind of note (a count and the first ids), for the summary."""
    groups: dict[tuple[str, str], list[SiteNote]] = {}
    for n in notes:
        groups.setdefault((n.kind, n.action), []).append(n)
    out = []
    for (kind, action), group in groups.items():
        one, many = NOTE_WORDS.get((kind, action), (f"{kind}: {action}", f"{kind}: {action}"))
        words = one if len(group) == 1 else many
        ids = ", ".join(" and ".join(n.ids) for n in group[:SHOWN])
        more = f" and {len(group) - SHOWN} more" if len(group) > SHOWN else ""
        extra = f" {group[0].detail}" if action in ("far", "default") and group[0].detail else ""
        out.append(f"Site: {len(group)} {words}{extra} ({ids}{more}; each in {file_name}).")
    return out


def near_mask(
    planned: Sequence[BaseGeometry], geoms: Sequence[BaseGeometry | None], near_m: float
) -> np.ndarray:
    """Which of ``geoms`` lie within ``near_m`` of a ``planned`` footprint (a geometry
    that is None or empty is never near)."""
    out = np.zeros(len(geoms), dtype=bool)
    usable = [g for g in planned if g is not None and not g.is_empty]
    if not usable:
        return out
    tree = shapely.STRtree(usable)
    idx = [i for i, g in enumerate(geoms) if g is not None and not g.is_empty]
    if not idx:
        return out
    hits = tree.query([geoms[i] for i in idx], predicate="dwithin", distance=near_m)
    out[np.asarray(idx)[np.unique(hits[0])]] = True
    return out


def _polygonal(geom: BaseGeometry) -> Polygon | MultiPolygon:
    """The polygonal part of a geometry (an overlay can leave lines and points)."""
    polys = [
        g
        for g in shapely.get_parts(shapely.make_valid(geom))
        if isinstance(g, Polygon) and not g.is_empty
    ]
    if not polys:
        return Polygon()
    return polys[0] if len(polys) == 1 else MultiPolygon(polys)


def overlap_width_m(overlap: BaseGeometry) -> float:
    """The mean width of an overlap [m]: its area over half its perimeter (a sliver of
    length L and width w: L·w / L)."""
    half = overlap.length / 2.0
    return float(overlap.area / half) if half > 0 else 0.0


def resolve_overlaps(
    ids: Sequence[str],
    geoms: Sequence[BaseGeometry],
    tolerance_m2: float,
) -> tuple[list[BaseGeometry], list[SiteNote]]:
    """Overlapping buildings repaired pair by pair (the module's text): thin overlaps along
    a shared wall snapped, small ones clipped from the smaller building; large ones are
    left as they are (the site then names them). Returns the new footprints and a note per
    pair repaired."""
    out = list(geoms)
    notes: list[SiteNote] = []
    tree = shapely.STRtree(out)
    pairs = tree.query(out, predicate="intersects")
    for i, j in sorted({(min(a, b), max(a, b)) for a, b in pairs.T if a != b}):
        inter = shapely.intersection(out[i], out[j])
        area = float(inter.area)
        if area <= tolerance_m2:
            continue
        small, large = (i, j) if out[i].area <= out[j].area else (j, i)
        c = inter.representative_point()
        pair = (ids[small], ids[large])
        width = overlap_width_m(inter)
        if width <= SNAP_M:
            action = "snapped"
            moved = shapely.snap(out[small], out[large], SNAP_M)
            new = _polygonal(shapely.difference(_polygonal(moved), out[large]))
            detail = f"overlap {width:.2f} m wide along the shared wall"
        elif area <= CLIP_SHARE * out[small].area:
            action = "clipped"
            new = _polygonal(shapely.difference(out[small], out[large]))
            detail = f"{100 * area / out[small].area:.1f} % of {ids[small]} cut off"
        else:  # a building drawn twice, or a part inside its building: the user's call
            continue
        if new.is_empty or new.area < 0.5 * out[small].area:
            continue
        out[small] = new
        notes.append(SiteNote("overlap", pair, action, detail, area, c.x, c.y))
    return out, notes
