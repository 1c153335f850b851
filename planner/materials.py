"""Facade materials: how bright a surface is to the scanner, whether it returns at all, and
how rough it is — the table shipped as data, and the user's own rows.

The table is ``planner/data/materials.toml`` (one ``[[material]]`` table per material, its
sources in the file's head). A surface's material comes from, in this order: a zone that
names one (a zone table's ``material`` column, ``--zone "...,material=glass"``); its
building (``building:material`` or ``material`` in the site file or a city model's
attributes); else none is known, and the surface is the scanner datasheet's reference
surface (:mod:`planner.signal`) — the figures as published, said in the plan.

A survey day after rain darkens porous materials (:data:`CONDITIONS`); a material that
does not return (glass, polished metal) is not demanded and the plan says where.

>>> t = material_table()
>>> t.find("bricks").name, t["glass"].returns, t["brick-dark"].reflectance_in("wet")
('brick', False, 0.09)
"""

from __future__ import annotations

import difflib
import re
import tomllib
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass
from functools import cache
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from planner.errors import InputError
from planner.ranges import RANGES, check_number
from planner.reading import user_file

if TYPE_CHECKING:
    from planner.site import Building

__all__ = [
    "CONDITIONS",
    "MATERIAL_KEYS",
    "Material",
    "MaterialTable",
    "building_materials",
    "material_named",
    "material_table",
    "read_material_file",
    "reflectances",
    "roughness_mm",
    "silent",
]

#: Attributes naming a building's wall material, in the order they are asked: OpenStreetMap's
#: ``building:material``, the facade's own, then a plain ``material`` (a city model's
#: generic attribute, a site file's property).
MATERIAL_KEYS = ("building:material", "facade:material", "building:facade:material", "material")

#: The survey day's surface condition: dry, or wet after rain (darker porous materials).
CONDITIONS = ("dry", "wet")


@dataclass(frozen=True)
class Material:
    """One facade material of the table (``planner/data/materials.toml`` says what each
    column means and where the figures come from).

    Parameters
    ----------
    name : str
        Its key (lower case, ``-`` between words by convention).
    reflectance, wet_reflectance : float
        Diffuse reflectance at the scanners' near-infrared wavelengths, dry and wet [0–1].
    roughness_mm : float
        The surface's own departure from a plane within a point's footprint [mm].
    returns : bool
        False where the surface gives no usable point (glass, a mirror).
    label : str
        Its name in words.
    aliases : tuple of str
        Other names (OpenStreetMap ``building:material`` values, city-model names).
    """

    name: str
    reflectance: float
    wet_reflectance: float
    roughness_mm: float = 0.0
    returns: bool = True
    label: str = ""
    aliases: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.strip():
            raise InputError('a material needs a name, e.g. name = "sandstone-grey"')
        who = f"material {self.name!r}"
        for key in ("reflectance", "wet_reflectance"):
            object.__setattr__(
                self, key, check_number(getattr(self, key), f"{who}: {key}", RANGES["reflectance"])
            )
        object.__setattr__(
            self,
            "roughness_mm",
            check_number(self.roughness_mm, f"{who}: roughness_mm", RANGES["rms_mm"]),
        )
        if self.wet_reflectance > self.reflectance:
            raise InputError(
                f"{who}: wet_reflectance ({self.wet_reflectance:g}) must not exceed reflectance "
                f"({self.reflectance:g}): water darkens a surface, it does not brighten it"
            )
        if not isinstance(self.returns, bool):
            raise InputError(f"{who}: returns must be true or false")
        if not isinstance(self.aliases, list | tuple) or not all(
            isinstance(a, str) for a in self.aliases
        ):
            raise InputError(f'{who}: aliases must be a list of names, e.g. ["stone"]')
        if not isinstance(self.label, str):
            raise InputError(f"{who}: label must be a text")
        object.__setattr__(self, "aliases", tuple(self.aliases))
        if not self.label:
            object.__setattr__(self, "label", self.name)

    def reflectance_in(self, condition: str) -> float:
        """The reflectance on a survey day of ``condition`` (:data:`CONDITIONS`)."""
        if condition not in CONDITIONS:
            raise InputError(f"condition must be one of {', '.join(CONDITIONS)}; got {condition!r}")
        return self.wet_reflectance if condition == "wet" else self.reflectance


def _key(name: str) -> str:
    """A name as the table matches it: lower case, words joined by ``_``."""
    return re.sub(r"[\s\-]+", "_", str(name).strip().lower())


class MaterialTable(Mapping[str, Material]):
    """The materials by name, found by name or alias (:meth:`find`)."""

    def __init__(self, materials: Iterable[Material]) -> None:
        self._by_name: dict[str, Material] = {}
        for m in materials:
            self._by_name[m.name] = m  # a later row (the user's) replaces an earlier one
        self._by_key: dict[str, str] = {}
        for m in self._by_name.values():  # aliases first (a later row's win), then names
            for a in m.aliases:
                self._by_key[_key(a)] = m.name
        for m in self._by_name.values():
            self._by_key[_key(m.name)] = m.name

    def __getitem__(self, name: str) -> Material:
        return self._by_name[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._by_name)

    def __len__(self) -> int:
        return len(self._by_name)

    def find(self, name: str, where: str = "") -> Material:
        """The material called ``name`` or known by it (an alias, any case, ``-``, ``_`` or
        spaces between words); an InputError naming ``where`` and the closest names
        otherwise."""
        hit = self._by_key.get(_key(name))
        if hit is not None:
            return self._by_name[hit]
        close = difflib.get_close_matches(_key(name), list(self._by_key), n=3, cutoff=0.6)
        hint = (
            f"; did you mean {', '.join(sorted({self._by_key[c] for c in close}))}?"
            if close
            else ""
        )
        raise InputError(
            f"unknown material {name!r}{f' ({where})' if where else ''}{hint} The table has: "
            f"{', '.join(self._by_name)}; add your own row with --materials FILE "
            "(the format of planner/data/materials.toml)"
        )

    def with_rows(self, rows: Iterable[Material]) -> MaterialTable:
        """This table with ``rows`` added (a row of a name already in it replaces it)."""
        return MaterialTable([*self._by_name.values(), *rows])


#: A user's material table larger than this is refused before it is read [bytes].
MAX_TABLE_BYTES = 1_000_000


def _parse(text: str, origin: str) -> list[Material]:
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{origin} is not valid TOML: {exc}") from None
    except RecursionError:
        raise InputError(f"{origin} is nested too deeply to be a material table") from None
    rows = data.get("material")
    if not isinstance(rows, list) or not rows or not all(isinstance(r, dict) for r in rows):
        raise InputError(
            f"{origin} has no [[material]] tables (each with name, reflectance, "
            "wet_reflectance and optionally roughness_mm, returns, label, aliases)"
        )
    out = []
    known = {
        "name",
        "reflectance",
        "wet_reflectance",
        "roughness_mm",
        "returns",
        "label",
        "aliases",
    }
    for i, row in enumerate(rows, start=1):
        unknown = sorted(set(row) - known)
        if unknown:
            raise InputError(
                f"{origin}: material {i} ({row.get('name', '?')!r}) has unknown keys "
                f"{', '.join(unknown)}; known: {', '.join(sorted(known))}"
            )
        missing = [k for k in ("name", "reflectance") if k not in row]
        if missing:
            raise InputError(f"{origin}: material {i} has no {' and no '.join(missing)}")
        row = dict(row)
        row.setdefault("wet_reflectance", row["reflectance"])
        try:
            out.append(Material(**row))
        except InputError as exc:
            raise InputError(f"{origin}: {exc}") from None
    return out


def read_material_file(path: str | Path) -> list[Material]:
    """A user's material rows from a TOML file of the shipped table's format (a row without
    ``wet_reflectance`` keeps its reflectance wet)."""
    p = user_file(path, "material file")
    if p.stat().st_size > MAX_TABLE_BYTES:
        raise InputError(
            f"material file {p.name} is {p.stat().st_size / 1e6:.1f} MB; a material table is "
            f"at most {MAX_TABLE_BYTES / 1e6:g} MB"
        )
    try:
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"cannot read material file {p.name}: {exc}") from None
    return _parse(text, p.name)


@cache
def _shipped() -> MaterialTable:
    text = resources.files("planner.data").joinpath("materials.toml").read_text(encoding="utf-8")
    return MaterialTable(_parse(text, "planner/data/materials.toml"))


def material_table(rows: Iterable[Material] = ()) -> MaterialTable:
    """The shipped table with the user's ``rows`` added."""
    rows = tuple(rows)
    return _shipped().with_rows(rows) if rows else _shipped()


def material_named(attributes: dict[str, Any]) -> str:
    """The wall material a source's attributes name (:data:`MATERIAL_KEYS`, first found),
    "" where none does."""
    for k in MATERIAL_KEYS:
        v = attributes.get(k)
        if isinstance(v, str) and v.strip():
            return v.strip()
    return ""


def _per_material(
    names: np.ndarray, table: MaterialTable, value: Callable[[Material], Any], missing: Any
) -> np.ndarray:
    """(N,) ``value`` of each surface's material (names of ``table``), ``missing`` where the
    name is "" (none known): one look-up per material, not per surface."""
    names = np.asarray(names, dtype=object)
    out = np.full(len(names), missing)
    for name in set(names.tolist()) - {""}:
        out[names == name] = value(table[name])
    return out


def reflectances(names: np.ndarray, table: MaterialTable, condition: str = "dry") -> np.ndarray:
    """(N,) the reflectance of each surface named in ``names`` (names of ``table``) on a
    survey day of ``condition``; NaN where the name is "" (no material known: the
    scanner datasheet's reference surface, :mod:`planner.signal`).

    >>> reflectances(np.array(["brick", ""], dtype=object), material_table(), "wet").tolist()
    [0.24, nan]
    """
    return _per_material(names, table, lambda m: m.reflectance_in(condition), np.nan)


def silent(names: np.ndarray, table: MaterialTable) -> np.ndarray:
    """(N,) whether each named surface returns no point (glass, a mirror); False where no
    material is known.

    >>> silent(np.array(["glass", "brick", ""], dtype=object), material_table()).tolist()
    [True, False, False]
    """
    return _per_material(names, table, lambda m: not m.returns, False)


def building_materials(
    buildings: Iterable[Building], table: MaterialTable, default: str | None = None
) -> tuple[dict[str, str], dict[str, list[str]]]:
    """Each building's wall material, a name of ``table``: its own where the table knows it,
    else ``default`` ("" for none: the datasheet's reference surface); and the names the
    table does not know, with their buildings (to be said). The default's unknown name is an
    InputError (the user typed it)."""
    base = "" if default is None else table.find(default, "the default material").name
    own: dict[str, str] = {}
    unknown: dict[str, list[str]] = {}
    for b in buildings:
        own[b.id] = base
        if b.material:
            try:
                own[b.id] = table.find(b.material, f"building {b.id}").name
            except InputError:
                unknown.setdefault(b.material, []).append(b.id)
    return own, unknown


def walls_words(
    names: np.ndarray, table: MaterialTable, condition: str, reference_reflectance: float
) -> str:
    """What the planned walls are made of, in words: each material's share of the samples
    and its reflectance on the survey day; the samples with none known are the scanner
    datasheet's reference surface.

    >>> w = walls_words(np.array(["brick", "", ""], dtype=object), material_table(), "wet", 0.8)
    >>> w[:48], w[-33:]
    ('Walls (wet day): no material known on 2 samples ', '80%); red brick 24% on 1 samples.')
    """
    names = np.asarray(names, dtype=object)
    if not len(names):
        return f"Walls ({condition} day): no sample left to demand."
    kinds, counts = np.unique(names.astype(str), return_counts=True)
    order = np.argsort(-counts, kind="stable")
    parts = []
    for k in order:
        if kinds[k] == "":
            parts.append(
                f"no material known on {counts[k]} samples (the scanner datasheet’s reference "
                f"surface, {reference_reflectance:.0%})"
            )
        else:
            m = table[kinds[k]]
            parts.append(f"{m.label} {m.reflectance_in(condition):.0%} on {counts[k]} samples")
    return f"Walls ({condition} day): {'; '.join(parts)}."


def roughness_mm(names: np.ndarray, table: MaterialTable) -> np.ndarray:
    """(N,) each named surface's roughness [mm] (0 where none is known).

    >>> roughness_mm(np.array(["brick", ""], dtype=object), material_table()).tolist()
    [1.0, 0.0]
    """
    return _per_material(names, table, lambda m: m.roughness_mm, 0.0)
