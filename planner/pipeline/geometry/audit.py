"""A plan audited against a 3-D model of the buildings: what it promises that the real
building does not give.

A plan made from footprints puts a wall over every footprint edge up to the building's
highest point and samples on it; the real building (a city model) has pitched roofs,
set-back storeys, eaves and dormers. Every sample the plan marks met is cast against the
model:

* **no wall** — there is no wall where the plan puts the sample: a ray cast back at the
  sample's place along its facade's normal (from :data:`PROBE_M` in front, up to
  :data:`WALL_TOLERANCE_M` behind it) meets no wall of the model within
  :data:`WALL_TOLERANCE_M` of it (above the eaves under a pitched roof, beside a set-back
  storey, in a gable's corner), or meets glass;
* **hidden** — the wall is there, but the sight line from the sample's station to the
  model's wall is blocked by the model (eaves, a roof, a dormer, another part, a tree, the
  terrain);
* **seen** — the wall is there and the station sees it.

Heights: a plan made on flat ground (heights above the ground) is carried onto the model
by each building's base (its heights measured from the model's ground under the building),
its stations onto the model's terrain; a plan made from the model is audited as it is.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import shapely

from planner.errors import InputError
from planner.pipeline.geometry.facades import SIGHT_OFFSET_M
from planner.pipeline.geometry.scene import TRIANGLE_KINDS, Scene
from planner.site import Site

__all__ = [
    "AUDIT_STATUSES",
    "audit",
    "audit_plan",
    "audit_summary",
    "model_base",
    "read_plan_tables",
]

#: What the audit says of a sample (the ``status`` column), in the order the summary lists.
AUDIT_STATUSES = ("seen", "hidden", "no wall")
#: A model wall this close to where the plan puts a sample is its wall [m] (footprints and
#: models of one building differ by decimetres).
WALL_TOLERANCE_M = 0.3
#: The probe ray starts this far in front of the sample [m] (close: a balcony or an eave in
#: front of the wall is not taken for it).
PROBE_M = 0.35
_WALL_KINDS = [TRIANGLE_KINDS.index(k) for k in ("wall", "door")]


def audit(
    model: Site,
    coverage: pd.DataFrame,
    facades: pd.DataFrame,
    stations: pd.DataFrame,
    *,
    above_ground: bool | None = None,
    scene: Scene | None = None,
) -> pd.DataFrame:
    """Every sample marked met in ``coverage`` (a plan's coverage table, with its facades
    and stations tables) cast against ``model``: ``sample_id``, ``building_id``,
    ``station_id``, ``status`` (:data:`AUDIT_STATUSES`) and where the model's wall is
    (``wall_x``, ``wall_y``, ``wall_z``; NaN with no wall). ``above_ground``: the plan's
    heights are above flat ground (default: when its stations stand at ground height 0 and
    the model's ground is not at 0)."""
    met = coverage[coverage["meets"].astype(bool) & (coverage["station_id"] != "")]
    _check_overlap(model, coverage)
    scene = scene or Scene(model, "rays")
    fac = facades.set_index("facade_id").loc[met["facade_id"]]
    along = np.column_stack([fac["x1"] - fac["x0"], fac["y1"] - fac["y0"]])
    along /= np.maximum(np.linalg.norm(along, axis=1), 1e-12)[:, None]
    nz = fac["normal_z"].to_numpy(float) if "normal_z" in fac else np.zeros(len(fac))
    c = np.sqrt(np.clip(1 - nz**2, 0, 1))
    normal = np.column_stack([along[:, 1] * c, -along[:, 0] * c, nz])
    st = stations.set_index("station_id").loc[met["station_id"]]
    s_xy = st[["x", "y"]].to_numpy(float)
    ground = st["ground_z"].to_numpy(float) if "ground_z" in st else np.zeros(len(st))
    if above_ground is None:
        bases = [b.base_z or 0.0 for b in model.buildings]
        above_ground = bool(
            np.allclose(ground, 0.0) and (model.terrain is not None or np.abs(bases).max() > 0.5)
        )
    p = met[["x", "y", "z"]].to_numpy(float).copy()
    if above_ground:  # heights above the ground, onto the model
        p[:, 2] += model_base(model, met["building_id"].to_numpy(object), p[:, :2])
        s_z = scene.ground_z(s_xy) + st["instrument_height_m"].to_numpy(float)
    else:
        s_z = ground + st["instrument_height_m"].to_numpy(float)
    station = np.column_stack([s_xy, s_z])
    # is the wall there? a ray back at the sample along its normal
    t, tri = scene.first_hit(
        p + PROBE_M * normal, -normal, PROBE_M + WALL_TOLERANCE_M, buildings_only=True
    )
    kinds = np.full(len(p), -1)
    kinds[tri >= 0] = scene.mesh[2][tri[tri >= 0]]
    wall = (np.abs(t - PROBE_M) <= WALL_TOLERANCE_M) & np.isin(kinds, _WALL_KINDS)
    at = p + (PROBE_M - np.where(wall, t, PROBE_M))[:, None] * normal
    status = np.full(len(p), "no wall", dtype=object)
    if wall.any():
        seen = scene.seen(station[wall], at[wall] + SIGHT_OFFSET_M * normal[wall])
        status[np.flatnonzero(wall)] = np.where(seen, "seen", "hidden")
    out = pd.DataFrame(
        {
            "sample_id": met["sample_id"].to_numpy(),
            "building_id": met["building_id"].to_numpy(),
            "facade_id": met["facade_id"].to_numpy(),
            "station_id": met["station_id"].to_numpy(),
            "status": status,
            "wall_x": np.where(wall, at[:, 0], np.nan),
            "wall_y": np.where(wall, at[:, 1], np.nan),
            "wall_z": np.where(wall, at[:, 2], np.nan),
        }
    )
    return out


def _check_overlap(model: Site, coverage: pd.DataFrame) -> None:
    """A plan whose samples lie nowhere near the model's buildings is another site, or in
    another CRS: said, not audited as all "no wall"."""
    if not len(coverage):
        return
    x0, y0, x1, y1 = shapely.union_all([b.footprint for b in model.buildings]).bounds
    x, y = coverage["x"].to_numpy(float), coverage["y"].to_numpy(float)
    near = (x >= x0 - 50) & (x <= x1 + 50) & (y >= y0 - 50) & (y <= y1 + 50)
    if near.mean() < 0.5:
        raise InputError(
            f"the plan's samples (about {np.median(x):.0f}, {np.median(y):.0f}) are not on the "
            f"model's buildings ({x0:.0f}–{x1:.0f}, {y0:.0f}–{y1:.0f}); is it the plan of "
            "this site, in the model's CRS (--crs)?"
        )


def model_base(model: Site, building_ids: np.ndarray, xy: np.ndarray) -> np.ndarray:
    """The model's base [m] under each point of a plan made on flat ground (its heights
    above the ground), to carry it onto the model: the base of the point's building by id,
    else the model's ground there."""
    base = {b.id: float(b.base_z or 0.0) for b in model.buildings}
    out = np.array([base.get(str(b), np.nan) for b in building_ids], dtype=float)
    gap = ~np.isfinite(out)
    if gap.any():
        scene_ground = model.terrain.ground_z(xy[gap]) if model.terrain is not None else 0.0
        out[gap] = scene_ground
    return out


def audit_summary(table: pd.DataFrame) -> pd.DataFrame:
    """Per building (and in all): samples marked met, and how many of them the model shows
    seen, hidden and without a wall, with their shares [%]."""
    counts = pd.crosstab(table["building_id"], table["status"]).reindex(
        columns=list(AUDIT_STATUSES), fill_value=0
    )
    counts.loc["all"] = counts.sum()
    out = pd.DataFrame({"marked_met": counts.sum(axis=1)})
    for s in AUDIT_STATUSES:
        out[s] = counts[s]
        out[f"{s}_pct"] = (
            100.0 * counts[s] / out["marked_met"].where(out["marked_met"] > 0)
        ).round(1)
    return out.reset_index().rename(columns={"index": "building_id"})


def audit_plan(plan, model: Site) -> pd.DataFrame:
    """:func:`audit` of a :class:`~planner.pipeline.engine.result.Plan` against ``model``."""
    return audit(
        model,
        plan.coverage,
        plan.facades,
        plan.stations,
        above_ground=not plan.site.is_3d and not _same_heights(plan.site, model),
    )


def _same_heights(site: Site, model: Site) -> bool:
    """Whether a site's heights already are the model's (its buildings' bases match)."""
    base = {b.id: b.base_z for b in model.buildings}
    mine = [(base.get(b.id), b.base_z) for b in site.buildings if b.id in base]
    return bool(mine) and all(abs((a or 0.0) - (b or 0.0)) < 0.5 for a, b in mine)


def read_plan_tables(folder: str | Path) -> tuple[pd.DataFrame, pd.DataFrame, pd.DataFrame]:
    """The coverage, facades and stations tables of a plan's folder (``planner plan
    --out``)."""
    d = Path(folder)
    tables = []
    for name in ("coverage.csv", "facades.csv", "stations.csv"):
        f = d / name
        if not f.is_file():
            raise InputError(
                f"{d} holds no {name}: give the folder a plan was written to (planner plan --out)"
            )
        tables.append(pd.read_csv(f, keep_default_na=False, na_values=[""]))
    cov, fac, st = tables
    need = {"coverage.csv": (cov, ("sample_id", "facade_id", "x", "y", "z", "station_id", "meets"))}
    need["facades.csv"] = (fac, ("facade_id", "x0", "y0", "x1", "y1"))
    need["stations.csv"] = (st, ("station_id", "x", "y", "instrument_height_m"))
    for name, (t, cols) in need.items():
        missing = [c for c in cols if c not in t.columns]
        if missing:
            raise InputError(
                f"{d / name} lacks the column(s) {', '.join(missing)}; write the plan again"
            )
    cov["station_id"] = cov["station_id"].fillna("").astype(str)
    cov["meets"] = cov["meets"].astype(str).str.lower().isin(["true", "1"])
    return cov, fac, st
