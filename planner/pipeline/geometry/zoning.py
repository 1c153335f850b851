"""Zones applied to the facades: where each zone lies, finer samples inside it, and the
requirement of every sample (:mod:`planner.zones` defines the zones themselves).

:func:`apply_zones` checks every zone against the facades (a zone outside its facade, on
an unknown facade, with a bad requirement: an InputError saying which and how to fix it),
replaces the samples inside a zone that asks for a finer spacing by finer ones (a finer
zone overriding a coarser one where they overlap), and returns the per-sample limits of
every check of :data:`~planner.pipeline.inputs.requirements.CHECKS` and the stations each sample
needs: the zone's requirement inside a zone (the strictest where zones overlap), the
site-wide one elsewhere.

It also decides every sample's material (:func:`sample_materials`: the most specific zone
naming one, else its building's, else the plan's default) and leaves out the samples on a
material that returns no point (glass, a mirror), saying where.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np
import shapely

from planner.errors import InputError
from planner.materials import MaterialTable, building_materials, material_table
from planner.materials import silent as no_return
from planner.pipeline.geometry.facades import FacadeSet, keep_samples, sample_flags
from planner.pipeline.inputs.requirements import CHECKS, Requirements
from planner.pipeline.inputs.resolved import zone_requirement
from planner.site import Site
from planner.zones import Zone

if TYPE_CHECKING:
    from planner.pipeline.geometry.scene import Scene

__all__ = ["SampleRequirements", "ZoneTable", "along_m", "apply_zones"]

#: The plan's messages name this many zones' looser limits at most.
LISTED_LOOSER = 20
#: A zone may reach this far past its facade's end or top (digitising) [m].
ZONE_TOLERANCE_M = 0.05


@dataclass
class SampleRequirements:
    """Every sample's requirement: per check key the (N,) limits (±inf: none), the (N,)
    stations it needs, and the zones it lies in (";"-joined ids, "" for none)."""

    limits: dict[str, np.ndarray]
    stations: np.ndarray
    zone_ids: np.ndarray
    #: (N,) each sample's material (a name of the material table; "" none known)
    material: np.ndarray | None = None

    def __post_init__(self) -> None:
        if self.material is None:
            self.material = np.full(len(self.stations), "", dtype=object)

    @classmethod
    def uniform(cls, req: Requirements, n: int) -> SampleRequirements:
        """The site-wide requirement at all ``n`` samples."""
        limits = {}
        for c in CHECKS:
            limit = c.limit_of(req)
            limits[c.key] = np.full(n, c.no_limit() if limit is None else float(limit))
        return cls(limits, np.full(n, req.stations_per_sample), np.full(n, "", dtype=object))

    def subset(self, keep: np.ndarray) -> SampleRequirements:
        """The requirements of the samples ``keep`` (N,) bool."""
        return SampleRequirements(
            {k: v[keep] for k, v in self.limits.items()},
            self.stations[keep],
            self.zone_ids[keep],
            self.material[keep],
        )


@dataclass
class ZoneTable:
    """The zones as applied: each zone's requirement and its samples."""

    zones: list[Zone]
    requirements: list[Requirements]
    members: list[np.ndarray]  # the indices of each zone's samples
    messages: list[str]


def along_m(fac: FacadeSet, samples: np.ndarray | None = None) -> np.ndarray:
    """Distance of samples from their facade's start, along it [m]."""
    return fac.along_m(samples)


def apply_zones(
    site: Site,
    fac: FacadeSet,
    req: Requirements,
    scene: Scene | None = None,
    materials: MaterialTable | None = None,
    default_material: str | None = None,
) -> tuple[FacadeSet, SampleRequirements, ZoneTable]:
    """The facades with finer samples where zones ask for them, every sample's requirement
    and material, and the zones as applied (module docstring); the samples on a material
    that returns no point are left out. Heights in zones are above the building's base;
    ``scene`` tells the new samples of a 3-D building's walls that are party walls;
    ``materials`` the table (default the shipped one), ``default_material`` the material of
    walls no source names (None: the datasheet's reference surface)."""
    messages: list[str] = []
    zones, facades = [], []
    for z in site.zones:
        f = _facades_of(z, fac, site)
        if not len(f):
            messages.append(
                f"Zone {z.id!r} is on building {z.building_id!r}, which is not planned: "
                "ignored (plan the building with --buildings to use it)"
            )
            continue
        zones.append(z)
        facades.append(f)
    made: dict[tuple, Requirements] = {}  # one Requirements per distinct zone requirement
    reqs = []
    for z in zones:
        key = tuple(sorted((k, repr(v)) for k, v in z.requirement.items()))
        if key not in made:
            made[key] = zone_requirement(z, req)
        reqs.append(made[key])
    # finer samples: the coarsest zone first, so that a finer one overrides it
    order = sorted(
        (i for i, z in enumerate(zones) if z.sample_spacing_m is not None),
        key=lambda i: -zones[i].sample_spacing_m,
    )
    for i in order:
        fac = _refine(site, fac, zones[i], facades[i], i, scene)
    n = len(fac.z)
    u = along_m(fac)
    on_facade = fac.per_facade(fac.facade)
    members = [_inside(z, fac, f, u, on_facade) for z, f in zip(zones, facades, strict=True)]
    looser: list[str] = []
    for z, zr, idx in zip(zones, reqs, members, strict=True):
        if not len(idx):
            raise InputError(
                f"zone {z.id!r} ({z.describe()}) holds no facade sample; make it larger than "
                "the sample spacing or give it a finer sample_spacing_m"
            )
        looser += _looser(z, zr, req)
    messages += looser[:LISTED_LOOSER] + (
        [f"… and {len(looser) - LISTED_LOOSER} more zone requirements looser than the site-wide"]
        if len(looser) > LISTED_LOOSER
        else []
    )
    out = SampleRequirements.uniform(req, n)
    # where zones overlap the strictest wins, whatever their order: zones of one requirement
    # are applied together
    covered = np.zeros(n, dtype=bool)
    groups: dict[int, tuple[Requirements, list[np.ndarray]]] = {}
    for zr, idx in zip(reqs, members, strict=True):
        groups.setdefault(id(zr), (zr, []))[1].append(idx)
    for zr, parts in groups.values():
        idx = parts[0] if len(parts) == 1 else np.unique(np.concatenate(parts))  # ascending
        first, again = idx[~covered[idx]], idx[covered[idx]]
        for c in CHECKS:
            limit = c.limit_of(zr)
            value = c.no_limit() if limit is None else float(limit)
            own = out.limits[c.key]
            # the zone replaces the site-wide limit; where zones overlap the strictest wins
            own[first] = value
            if len(again):
                pick = np.minimum if c.sense == "max" else np.maximum
                own[again] = pick(own[again], value)
        out.stations[first] = zr.stations_per_sample
        out.stations[again] = np.maximum(out.stations[again], zr.stations_per_sample)
        covered[idx] = True
    out.zone_ids[:] = _joined_ids([z.id for z in zones], members, n)
    table = material_table() if materials is None else materials
    out.material = sample_materials(site, fac, zones, members, table, default_material, messages)
    fac, out, members = _without_silent(fac, out, members, table, messages)
    return fac, out, ZoneTable(zones, reqs, members, messages)


def _without_silent(
    fac: FacadeSet,
    out: SampleRequirements,
    members: list[np.ndarray],
    table: MaterialTable,
    messages: list[str],
) -> tuple[FacadeSet, SampleRequirements, list[np.ndarray]]:
    """The samples, their requirements and the zones' members without the samples on a
    material that returns no point (said in ``messages``)."""
    silent = no_return(out.material, table)
    if not silent.any():
        return fac, out, members
    messages.append(_silent_words(fac, out.material, silent, table))
    new = np.cumsum(~silent) - 1
    members = [new[m[~silent[m]]] for m in members]
    return keep_samples(fac, ~silent), out.subset(~silent), members


#: The plan's message names this many facades whose samples return no point, at most.
LISTED_SILENT = 8


def sample_materials(
    site: Site,
    fac: FacadeSet,
    zones: list[Zone],
    members: list[np.ndarray],
    table: MaterialTable,
    default: str | None = None,
    messages: list[str] | None = None,
) -> np.ndarray:
    """(N,) each sample's material, a name of ``table`` ("" none known): the most specific
    zone naming one (part of a facade, then a facade, then a building; the later of two
    alike), else its building's (a name the table does not know is said in ``messages``
    and taken as unknown), else ``default``. A zone's or the default's unknown name is an
    InputError (the user typed it)."""
    own, unknown = building_materials(site.planned, table, default)
    base = "" if default is None else table.find(default).name
    out = np.array([own.get(str(b), base) for b in fac.building_id[fac.facade]], dtype=object)
    rank = [(2 if z.is_part else 0 if z.building_id else 1, i) for i, z in enumerate(zones)]
    for _, i in sorted(rank):
        z = zones[i]
        if z.material is not None:
            out[members[i]] = table.find(z.material, f"zone {z.id!r}").name
    if unknown and messages is not None:
        said = "; ".join(
            f"{m!r} ({', '.join(ids[:3])}{' …' if len(ids) > 3 else ''})"
            for m, ids in unknown.items()
        )
        messages.append(
            f"Materials the table does not know: {said} — planned as "
            f"{'the default ' + base if base else 'the scanner datasheet’s reference surface'}; "
            "add a row with --materials FILE"
        )
    return out


def _silent_words(
    fac: FacadeSet, material: np.ndarray, silent: np.ndarray, table: MaterialTable
) -> str:
    """The samples left out because their surface returns no point, in words."""
    f = fac.facade_id[fac.facade[silent]]
    names, counts = np.unique(f, return_counts=True)
    order = np.argsort(-counts, kind="stable")[:LISTED_SILENT]
    kinds = sorted({table[m].label for m in material[silent]})
    more = len(names) - len(order)
    return (
        f"Not demanded: {int(silent.sum())} samples on {' and '.join(kinds)}, which "
        f"{'return' if len(kinds) > 1 else 'returns'} no usable point "
        f"({', '.join(f'{names[k]} {counts[k]}' for k in order)}"
        + (f", … {more} more facades" if more > 0 else "")
        + "); scan their frames and reveals at the spacing you need, or name another material"
    )


def _joined_ids(ids: list[str], members: list[np.ndarray], n: int) -> np.ndarray:
    """(n,) the ";"-joined ids of the zones each sample lies in, in the zones' order."""
    out = np.full(n, "", dtype=object)
    if not members:
        return out
    sample = np.concatenate(members)
    zone = np.repeat(np.arange(len(members)), [len(m) for m in members])
    order = np.lexsort((zone, sample))
    sample, zone = sample[order], zone[order]
    starts = np.flatnonzero(np.r_[True, sample[1:] != sample[:-1]])
    for k, lo in enumerate(starts):
        hi = starts[k + 1] if k + 1 < len(starts) else len(sample)
        out[sample[lo]] = ";".join(ids[j] for j in zone[lo:hi])
    return out


def _facades_of(z: Zone, fac: FacadeSet, site: Site) -> np.ndarray:
    """The facade indices a zone covers (checked against the facades)."""
    if z.facade_id is not None:
        hit = np.flatnonzero(fac.facade_id == z.facade_id)
        if not len(hit):
            bid = z.facade_id.rsplit("-f", 1)[0]
            own = [str(f) for f in fac.facade_id if str(f).startswith(f"{bid}-f")]
            if not own:
                raise InputError(
                    f"zone {z.id!r} is on facade {z.facade_id!r} of building {bid!r}, which is "
                    "not planned; plan it (--buildings) or remove the zone"
                )
            raise InputError(
                f"zone {z.id!r}: building {bid!r} has no facade {z.facade_id!r}; its facades "
                f"are {', '.join(own)} (as facades.csv of a plan names them)"
            )
        f = int(hit[0])
        length = float(fac.length_m[f])
        height = float(fac.z0[f] - fac.base_z[f] + fac.height_m[f])  # its top, above the base
        if z.along_m is not None and z.along_m[1] > length + ZONE_TOLERANCE_M:
            raise InputError(
                f"zone {z.id!r} runs to {z.along_m[1]:g} m along facade {z.facade_id}, which "
                f"is {length:.2f} m long; measure from the facade's start (x0, y0 in "
                "facades.csv)"
            )
        if z.height_m is not None and z.height_m[0] >= height:
            raise InputError(
                f"zone {z.id!r} starts at {z.height_m[0]:g} m, above facade {z.facade_id} "
                f"({height:g} m high)"
            )
        if z.height_m is not None and z.height_m[1] > height + ZONE_TOLERANCE_M:
            raise InputError(
                f"zone {z.id!r} reaches {z.height_m[1]:g} m, above facade {z.facade_id} "
                f"({height:g} m high); end it at the top or below"
            )
        if z.elevation is not None:
            x0, z0, x1, z1 = z.elevation.bounds
            if (
                x0 < -ZONE_TOLERANCE_M
                or x1 > length + ZONE_TOLERANCE_M
                or z0 < -ZONE_TOLERANCE_M
                or (z1 > height + ZONE_TOLERANCE_M)
            ):
                raise InputError(
                    f"zone {z.id!r}: its elevation polygon ({x0:g}–{x1:g} m along, {z0:g}–"
                    f"{z1:g} m high) is not within facade {z.facade_id} ({length:.2f} m × "
                    f"{height:g} m)"
                )
        return np.array([f])
    planned = {b.id for b in site.planned}
    if z.building_id not in planned:
        return np.empty(0, dtype=np.int64)
    return np.flatnonzero(fac.building_id == z.building_id)


def _inside(
    z: Zone, fac: FacadeSet, facades: np.ndarray, u: np.ndarray, on_facade: list[np.ndarray]
) -> np.ndarray:
    """The indices of the samples inside the zone (ascending); ``on_facade``: each facade's
    samples (:meth:`FacadeSet.per_facade`)."""
    tol = 1e-6
    idx = np.sort(np.concatenate([on_facade[f] for f in facades]))
    if z.along_m is not None:
        idx = idx[(u[idx] >= z.along_m[0] - tol) & (u[idx] <= z.along_m[1] + tol)]
    h = fac.z[idx] - fac.base_z[fac.facade[idx]]  # above the building's base
    if z.height_m is not None:
        keep = (h >= z.height_m[0] - tol) & (h <= z.height_m[1] + tol)
        idx, h = idx[keep], h[keep]
    if z.elevation is not None:
        idx = idx[shapely.contains_xy(z.elevation.buffer(tol), u[idx], h)]
    return idx


def _refine(
    site: Site, fac: FacadeSet, z: Zone, facades: np.ndarray, number: int, scene: Scene | None
) -> FacadeSet:
    """``fac`` with the samples inside zone ``z`` replaced by a grid at the zone's spacing
    (new columns on its facades, rows over its height range, on the facade's outline)."""
    u = along_m(fac)
    drop = np.zeros(len(fac.z), dtype=bool)
    drop[_inside(z, fac, facades, u, fac.per_facade(fac.facade))] = True
    new_cols_f, new_cols_u, new_s = [], [], []  # samples: (facade, column, u, h, id)
    n_cols = len(fac.col_facade)
    for f in facades:
        length = float(fac.length_m[f])
        foot = float(fac.z0[f] - fac.base_z[f])
        top = foot + float(fac.height_m[f])
        if z.elevation is not None:
            a0, h0, a1, h1 = z.elevation.bounds
        else:
            a0, a1 = z.along_m or (0.0, length)
            h0, h1 = z.height_m or (foot, top)
        a1, h1 = min(a1, length), min(h1, top)
        nu = max(1, round((a1 - a0) / z.sample_spacing_m))
        nz = max(1, round((h1 - h0) / z.sample_height_step_m))
        us = a0 + (np.arange(nu) + 0.5) * (a1 - a0) / nu
        zs = h0 + (np.arange(nz) + 0.5) * (h1 - h0) / nz
        shape = fac.outline[f]
        for ci, uu in enumerate(us):
            pts = zs[shapely.contains_xy(shape, np.full(len(zs), uu), zs)]
            if z.elevation is not None:
                pts = pts[shapely.contains_xy(z.elevation, np.full(len(pts), uu), pts)]
            if not len(pts):
                continue
            col = n_cols + len(new_cols_f)
            new_cols_f.append(f)
            new_cols_u.append(uu)
            for ri, hh in enumerate(pts):
                new_s.append((f, col, uu, hh, f"{fac.facade_id[f]}-z{number}-{ci:03d}-{ri:02d}"))
    if not new_s:
        return fac
    keep = ~drop
    s_f = np.array([s[0] for s in new_s], dtype=np.int64)
    s_c = np.array([s[1] for s in new_s], dtype=np.int64)
    s_xy, s_z = fac.place(s_f, np.array([s[2] for s in new_s]), np.array([s[3] for s in new_s]))
    cols_f = np.array(new_cols_f, dtype=np.int64)
    col_xy = np.vstack(
        [
            fac.col_xy,
            fac.place(cols_f, np.array(new_cols_u), fac.z0[cols_f] - fac.base_z[cols_f])[0],
        ]
    )
    wall, party = sample_flags(site, fac, s_f, s_xy, s_z, scene)
    s_f, s_c, s_z, s_xy, party = s_f[wall], s_c[wall], s_z[wall], s_xy[wall], party[wall]
    new_ids = np.array([s[4] for s in new_s], dtype=object)[wall]
    return replace(
        fac,
        col_facade=np.concatenate([fac.col_facade, cols_f]),
        col_xy=col_xy,
        facade=np.concatenate([fac.facade[keep], s_f]),
        column=np.concatenate([fac.column[keep], s_c]),
        xy=np.vstack([fac.xy[keep], s_xy]),
        z=np.concatenate([fac.z[keep], s_z]),
        sample_id=np.concatenate([fac.sample_id[keep], new_ids]),
        party_wall=np.concatenate([fac.party_wall[keep], party]),
    )


def _looser(z: Zone, zr: Requirements, site_req: Requirements) -> list[str]:
    """A message for every limit of the zone looser than the site-wide one (allowed)."""
    out = []
    for c in CHECKS:
        mine, site_wide = c.limit_of(zr), c.limit_of(site_req)
        if mine is None or site_wide is None:
            continue
        looser = mine > site_wide if c.sense == "max" else mine < site_wide
        if looser:
            out.append(
                f"Zone {z.id!r} asks {c.text(mine)}, looser than the site-wide "
                f"{c.text(site_wide)}: its samples are judged by the zone's limit"
            )
    if zr.stations_per_sample < site_req.stations_per_sample:
        out.append(
            f"Zone {z.id!r} asks {zr.stations_per_sample} station(s) per sample, fewer than the "
            f"site-wide {site_req.stations_per_sample}"
        )
    return out
