"""Zones: where the client asks for more (or less) than the site-wide requirement.

A zone is a whole building, a whole facade, or a part of a facade — an along-facade range
and a height range, or a polygon drawn on the facade's elevation (along-facade distance
from the facade's start, height above the ground) — with its own requirement (any of
:data:`ZONE_KEYS`) and, optionally, its own finer sample spacing. Places no zone covers
keep the site-wide requirement; where zones overlap the strictest applies.

Zones come from a zone table beside the site file (:func:`read_zones`), from a building's
properties in the site file (``max_xy_mm``, ``max_z_mm``, ``class``… on the building
feature), or from the command line (:func:`parse_zone`, ``--zone``); all three are read by
the same row parser. Voroshilov & Karachentsev list "greater detail and accuracy on
chosen fragments of the zones" among what a choice of stations must weigh.

Examples
--------
>>> z = parse_zone("facade=main-f00, from=4, to=10, z=0-6, max_xy_mm=2, sample_spacing_m=0.5")
>>> z.facade_id, z.along_m, z.height_m, z.requirement, z.sample_spacing_m
('main-f00', (4.0, 10.0), (0.0, 6.0), {'max_xy_mm': 2.0}, 0.5)
"""

from __future__ import annotations

import csv
import difflib
import io
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import shapely
from shapely.geometry import Polygon

from planner.errors import InputError
from planner.reading import user_file

__all__ = ["ZONE_KEYS", "Zone", "parse_zone", "read_zones", "zone_from_row"]

#: What a zone may require (the names of :class:`planner.pipeline.inputs.requirements.Requirements`
#: fields; ``class`` is accepted for ``accuracy_class``).
ZONE_KEYS = (
    "max_xy_mm",
    "max_z_mm",
    "max_gamma_deg",
    "max_incidence_deg",
    "max_spacing_mm",
    "min_range_m",
    "max_range_m",
    "stations_per_sample",
    "accuracy_class",
)
#: Where a zone lies and how it is sampled (the other columns of a zone table).
PLACE_KEYS = (
    "id",
    "building_id",
    "facade_id",
    "from_m",
    "to_m",
    "z_from_m",
    "z_to_m",
    "elevation_wkt",
    "sample_spacing_m",
    "sample_height_step_m",
    "material",
)
#: Short forms accepted in tables, site properties and on the command line.
ALIASES = {
    "class": "accuracy_class",
    "building": "building_id",
    "facade": "facade_id",
    "from": "from_m",
    "to": "to_m",
    "z_from": "z_from_m",
    "z_to": "z_to_m",
    "elevation": "elevation_wkt",
    "spacing": "sample_spacing_m",
    "zone": "id",
    "zone_id": "id",
}


@dataclass(frozen=True, kw_only=True)
class Zone:
    """A place with its own requirement (module docstring).

    Parameters
    ----------
    id : str
        A name for messages and reports.
    building_id, facade_id : str, optional
        The building, or the facade (``<building>-f<NN>``, as the plan's facades.csv names
        them) the zone is on; exactly one.
    along_m : (float, float), optional
        From / to along the facade, from its start [m] (facade zones only).
    height_m : (float, float), optional
        From / to height above the ground [m].
    elevation : Polygon, optional
        The zone drawn on the facade's elevation, in (along [m], height [m]); instead of the
        ranges.
    requirement : dict
        The requirement inside (keys of :data:`ZONE_KEYS`); the rest is the site-wide one.
        Its values are checked by the requirement's own rules when the zone is applied.
    sample_spacing_m, sample_height_step_m : float, optional
        Finer samples inside the zone [m].
    material : str, optional
        What the surface inside is made of (a name or alias of the material table,
        :mod:`planner.materials`; checked when the zone is applied): a glass shopfront, a
        slate-hung storey.
    """

    id: str
    building_id: str | None = None
    facade_id: str | None = None
    along_m: tuple[float, float] | None = None
    height_m: tuple[float, float] | None = None
    elevation: Polygon | None = None
    requirement: dict[str, Any] = field(default_factory=dict)
    sample_spacing_m: float | None = None
    sample_height_step_m: float | None = None
    material: str | None = None

    def __post_init__(self) -> None:
        who = f"zone {self.id!r}"
        if (self.building_id is None) == (self.facade_id is None):
            raise InputError(
                f"{who}: give a building_id or a facade_id (one of them) to say where it is"
            )
        if self.facade_id is None and (self.along_m is not None or self.elevation is not None):
            raise InputError(
                f"{who}: an along-facade range or an elevation polygon needs a facade_id "
                "(a building's zone covers its whole height range on every facade)"
            )
        if self.elevation is not None and (self.along_m or self.height_m):
            raise InputError(f"{who}: give the ranges or the elevation polygon, not both")
        for name in ("along_m", "height_m"):
            rng = getattr(self, name)
            if rng is None:
                continue
            lo, hi = (float(v) for v in rng)
            if not (math.isfinite(lo) and math.isfinite(hi)) or lo < 0 or hi <= lo:
                what = "along the facade" if name == "along_m" else "in height"
                raise InputError(
                    f"{who}: the range {what} must run from a number >= 0 to a larger one "
                    f"[m]; got {lo:g} to {hi:g}"
                )
            object.__setattr__(self, name, (lo, hi))
        if self.elevation is not None:
            e = self.elevation
            if not isinstance(e, Polygon) or e.is_empty or not e.is_valid or e.area <= 0:
                raise InputError(
                    f"{who}: the elevation polygon must be a valid POLYGON in (along [m], "
                    "height [m]) with an area"
                )
        for name in ("sample_spacing_m", "sample_height_step_m"):
            v = getattr(self, name)
            if v is not None and (isinstance(v, bool) or not 0.05 <= float(v) <= 100):
                raise InputError(f"{who}: {name} must be from 0.05 to 100 [m]; got {v!r}")
        unknown = [k for k in self.requirement if k not in ZONE_KEYS]
        if unknown:
            raise InputError(f"{who}: {_unknown(unknown[0])}")
        if self.material is not None and (
            not isinstance(self.material, str) or not self.material.strip()
        ):
            raise InputError(f"{who}: material must be a name, e.g. material=glass")
        if not self.requirement and self.sample_spacing_m is None and self.material is None:
            raise InputError(
                f"{who} sets no requirement, no sample spacing and no material; give e.g. "
                "max_xy_mm=2, sample_spacing_m=0.5 or material=glass"
            )

    @property
    def is_part(self) -> bool:
        """Whether the zone is part of a facade (not a whole building or facade)."""
        return self.along_m is not None or self.height_m is not None or self.elevation is not None

    def describe(self) -> str:
        """Where the zone is, in words."""
        where = f"facade {self.facade_id}" if self.facade_id else f"building {self.building_id}"
        if self.along_m:
            where += f", {self.along_m[0]:g}–{self.along_m[1]:g} m along"
        if self.height_m:
            where += f", {self.height_m[0]:g}–{self.height_m[1]:g} m high"
        if self.elevation is not None:
            where += ", a polygon on its elevation"
        return where


def _unknown(key: str) -> str:
    known = list(ZONE_KEYS) + list(PLACE_KEYS) + list(ALIASES)
    close = difflib.get_close_matches(key, known, n=1)
    hint = f" (did you mean {close[0]!r}?)" if close else ""
    return (
        f"unknown key {key!r}{hint}; a zone takes {', '.join(PLACE_KEYS)} and the requirements "
        f"{', '.join(ZONE_KEYS)} (or 'class')"
    )


def _float(value: Any, key: str, who: str) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{who}: {key} must be a number; got {value!r}") from None
    if not math.isfinite(v):
        raise InputError(f"{who}: {key} must be a finite number; got {value!r}")
    return v


def _range(lo: Any, hi: Any, key: str, who: str) -> tuple[float, float] | None:
    if lo in (None, "") and hi in (None, ""):
        return None
    if lo in (None, "") or hi in (None, ""):
        raise InputError(f"{who}: give both ends of the {key} range (from and to) [m]")
    return (_float(lo, key, who), _float(hi, key, who))


def zone_from_row(row: Mapping[str, Any], default_id: str) -> Zone:
    """A zone from one table row, site-file properties or command-line pairs: keys as in
    :data:`PLACE_KEYS` and :data:`ZONE_KEYS` (short forms of :data:`ALIASES` accepted;
    ``z=0-6`` for a height range); empty cells are not given."""
    data: dict[str, Any] = {}
    for raw, value in row.items():
        if raw is None:
            raise InputError(f"zone {default_id!r}: a row has more cells than the header")
        key = ALIASES.get(str(raw).strip().lower(), str(raw).strip().lower())
        if isinstance(value, str):
            value = value.strip()
        if value in (None, ""):
            continue
        if key == "z":  # z=0-6
            lo, sep, hi = str(value).partition("-")
            if not sep:
                raise InputError(
                    f"zone {default_id!r}: z must be a range like 0-6 [m]; got {value!r}"
                )
            data["z_from_m"], data["z_to_m"] = lo, hi
            continue
        if key not in ZONE_KEYS and key not in PLACE_KEYS:
            raise InputError(f"zone {default_id!r}: {_unknown(key)}")
        data[key] = value
    zid = str(data.pop("id", default_id))
    who = f"zone {zid!r}"
    requirement: dict[str, Any] = {}
    for key in ZONE_KEYS:
        if key not in data:
            continue
        v = data.pop(key)
        if key == "accuracy_class":
            requirement[key] = str(v)
        elif key == "stations_per_sample":
            f = _float(v, key, who)
            if f != int(f):
                raise InputError(f"{who}: stations_per_sample must be a whole number; got {v!r}")
            requirement[key] = int(f)
        elif key == "max_xy_mm" and isinstance(v, str) and "," in v:
            x, y = v.split(",", 1)
            requirement[key] = (_float(x, key, who), _float(y, key, who))
        else:
            requirement[key] = v if isinstance(v, tuple | list) else _float(v, key, who)
    elevation = None
    if "elevation_wkt" in data:
        try:
            elevation = shapely.from_wkt(str(data.pop("elevation_wkt")))
        except shapely.errors.GEOSException:
            raise InputError(
                f"{who}: elevation_wkt is not WKT; give POLYGON ((along height, …)) [m]"
            ) from None
    spacing = {
        k: _float(data.pop(k), k, who)
        for k in ("sample_spacing_m", "sample_height_step_m")
        if k in data
    }
    if "sample_spacing_m" in spacing and "sample_height_step_m" not in spacing:
        spacing["sample_height_step_m"] = spacing["sample_spacing_m"]
    return Zone(
        id=zid,
        building_id=str(data["building_id"]) if "building_id" in data else None,
        facade_id=str(data["facade_id"]) if "facade_id" in data else None,
        along_m=_range(data.get("from_m"), data.get("to_m"), "along-facade", who),
        height_m=_range(data.get("z_from_m"), data.get("z_to_m"), "height", who),
        elevation=elevation,
        requirement=requirement,
        material=str(data["material"]) if "material" in data else None,
        **spacing,
    )


def parse_zone(text: str, default_id: str = "zone") -> Zone:
    """A zone from ``key=value`` pairs separated by commas (the command line's ``--zone``);
    a pair ``max_xy_mm=2,3`` keeps its comma inside."""
    row: dict[str, str] = {}
    last = None
    for part in str(text).split(","):
        if "=" in part:
            key, _, value = part.partition("=")
            last = key.strip()
            row[last] = value.strip()
        elif last is not None and part.strip():  # the second value of a pair
            row[last] += "," + part.strip()
        elif part.strip():
            raise InputError(
                f"--zone {text!r}: {part.strip()!r} is not key=value; e.g. "
                "facade=main-f00,from=4,to=10,z=0-6,max_xy_mm=2"
            )
    if not row:
        raise InputError("--zone is empty; e.g. facade=main-f00,from=4,to=10,max_xy_mm=2")
    return zone_from_row(row, default_id)


#: A zone table larger than this is not a zone table [bytes].
MAX_TABLE_BYTES = 16 * 1024 * 1024


def read_zones(path: str | Path) -> list[Zone]:
    """Zones from a CSV table, one per row (columns: :data:`PLACE_KEYS` and
    :data:`ZONE_KEYS`; ``id`` defaults to ``Z<row>``)."""
    p = user_file(path, "zone table")
    if p.stat().st_size > MAX_TABLE_BYTES:
        raise InputError(f"zone table {p.name} is larger than 16 MB; is it the right file?")
    try:
        text = p.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        raise InputError(f"zone table {p.name} is not UTF-8 text") from None
    try:
        rows = list(csv.DictReader(io.StringIO(text)))
    except csv.Error as exc:
        raise InputError(f"zone table {p.name}: not a CSV table ({exc})") from None
    if not rows:
        raise InputError(
            f"zone table {p.name} has no zones (header: id,facade_id,from_m,to_m,z_from_m,"
            "z_to_m,max_xy_mm,…)"
        )
    zones = []
    for n, row in enumerate(rows, start=1):
        try:
            zones.append(zone_from_row(row, f"Z{n}"))
        except InputError as exc:
            raise InputError(f"{p.name} line {n + 1}: {exc}") from None
    return zones
