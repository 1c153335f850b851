"""The plan as one layered GeoJSON FeatureCollection (:func:`geojson`), which plan.geojson is
and the DXF and KML writers (:mod:`planner.pipeline.documents.deliver`) read: every feature's
properties are the plan's own column lists (:mod:`planner.pipeline.inputs.schema`).
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import pandas as pd
import shapely

from planner.pipeline.engine.judge import workbench_of
from planner.pipeline.engine.result import Plan
from planner.pipeline.geometry.facades import on_facade
from planner.pipeline.geometry.scene import Scene
from planner.pipeline.inputs.requirements import REGISTRATION_PROCESSING
from planner.pipeline.inputs.schema import LINK_COLUMNS, STATION_COLUMNS, TARGET_COLUMNS

__all__ = ["geojson", "geometry_json", "wall_rings"]


def geometry_json(geom: Any) -> dict:
    """A shapely geometry as a GeoJSON geometry (coordinates to the millimetre)."""
    return json.loads(shapely.to_geojson(shapely.set_precision(geom, 0.001)))


def _columns(row: Any, columns: Sequence[str], skip: Sequence[str] = ()) -> dict[str, Any]:
    """A table row's columns (one of the column lists) as a feature's properties, those in
    ``skip`` (the geometry's) left out; a list (a target's stations) ";"-joined, as the
    CSV writes it."""
    out = {}
    for c in columns:
        if c in skip:
            continue
        v = getattr(row, c)  # a column the table lacks is a bug: said, not written empty
        out[c] = ";".join(map(str, v)) if isinstance(v, list | tuple) else v
    return out


def _clean(props: dict[str, Any]) -> dict[str, Any]:
    out = {}
    for k, v in props.items():
        if isinstance(v, np.generic):
            v = v.item()
        if isinstance(v, float) and not math.isfinite(v):
            v = None
        elif isinstance(v, float):
            v = round(v, 3)
        out[k] = v
    return out


def _ground_of(p: Plan):
    """The plan's ground heights, a function of points (P, 2)."""
    wb = workbench_of(p)
    return (wb.ctx.scene if wb is not None else Scene(p.site)).ground_z


def wall_rings(p: Plan) -> list[list[np.ndarray]]:
    """Every facade of the plan in 3-D, from its outline on its elevation
    (``outline_wkt``): per facade its rings (exterior first), each (n, 3) [m] in the site's
    CRS and height system."""
    out = []
    for r in p.facades.itertuples():
        rings = []
        for poly in shapely.get_parts(shapely.from_wkt(r.outline_wkt)):
            for ring in [poly.exterior, *poly.interiors]:
                uh = np.asarray(ring.coords)
                n = len(uh)
                xy, z = on_facade(
                    np.tile([r.x0, r.y0], (n, 1)),
                    np.tile([r.x1, r.y1], (n, 1)),
                    np.full(n, r.normal_z),
                    np.full(n, r.z0),
                    np.full(n, r.base_z),
                    uh[:, 0],
                    uh[:, 1],
                )
                rings.append(np.column_stack([xy, z]))
        out.append(rings)
    return out


def geojson(p: Plan) -> dict:
    """Buildings, obstacles, no-go areas, facades, stations, links, targets and unmet samples
    as one GeoJSON FeatureCollection (a ``layer`` property on every feature). A 3-D site's
    points carry their height in the site's system (and their ground's)."""
    ground = _ground_of(p) if p.site.is_3d else None
    feats = [
        *_site_features(p),
        *_facade_features(p),
        *_station_features(p),
        *_link_features(p),
        *_target_features(p, ground),
        *_route_features(p),
        *_unmet_features(p, ground),
    ]
    out: dict[str, Any] = {
        "type": "FeatureCollection",
        "name": f"tls-planner plan: {p.site.name}",
        "accuracy_model": p.settings.model_description(),
    }
    if (model := p.registration_model()) is not None:  # and what it assumes of the software
        processing = REGISTRATION_PROCESSING[p.settings.registration_processing]
        out["registration_model"] = f"{model}, {processing}"
    if p.site.crs:
        out["crs"] = {"type": "name", "properties": {"name": p.site.crs}}
    out["features"] = feats
    return out


def _feature(geom: dict, **props: Any) -> dict:
    """A GeoJSON feature, its properties made plain (:func:`_clean`)."""
    return {"type": "Feature", "geometry": geom, "properties": _clean(props)}


def _grounds(points: pd.DataFrame, ground: Any) -> list[dict[str, float]]:
    """Each point's ground height as a feature property (``ground_z``), where the plan has
    heights (``ground``: :func:`_ground_of`); else none."""
    if ground is None:
        return [{}] * len(points)
    return [{"ground_z": float(z)} for z in ground(points[["x", "y"]].to_numpy(float))]


def _site_features(p: Plan) -> list[dict]:
    """Buildings, obstacles, no-go areas and passages."""
    feats: list[dict] = []
    for b in p.site.buildings:
        feats.append(
            _feature(
                geometry_json(b.footprint),
                layer="building",
                building_id=b.id,
                height_m=b.height_m,
                planned=b.planned,
                name=b.name,
            )
        )
    for o in p.site.obstacles:
        feats.append(
            _feature(
                geometry_json(o.geometry),
                layer="obstacle",
                obstacle_id=o.id,
                kind=o.kind,
                height_m=o.height_m,
            )
        )
    for a in p.site.no_go:
        feats.append(_feature(geometry_json(a.geometry), layer="no-go", area_id=a.id))
    for g in p.site.passages:
        feats.append(
            _feature(
                geometry_json(g.geometry),
                layer="passage",
                passage_id=g.id,
                clear_height_m=g.clear_height_m,
            )
        )
    return feats


def _facade_features(p: Plan) -> list[dict]:
    """Each facade as its ground line, and (3-D) as its wall's outline."""
    feats: list[dict] = []
    for r in p.facades.itertuples():
        feats.append(
            _feature(
                {"type": "LineString", "coordinates": [[r.x0, r.y0], [r.x1, r.y1]]},
                layer="facade",
                building_id=r.building_id,
                facade_id=r.facade_id,
                length_m=r.length_m,
                samples=r.samples,
                party_wall_samples=r.party_wall_samples,
                met=r.met,
                unmet=r.unmet,
                stations=r.stations,
                materials=getattr(r, "materials", ""),
            )
        )
    three_d = p.site.is_3d  # heights in the site's system: 3-D coordinates, ground said
    if three_d:
        for f, shape in enumerate(wall_rings(p)):
            r = p.facades.iloc[f]
            feats.append(
                _feature(
                    {
                        "type": "Polygon",
                        "coordinates": [np.round(ring, 3).tolist() for ring in shape],
                    },
                    layer="wall",
                    building_id=r.building_id,
                    facade_id=r.facade_id,
                    met=r.met,
                    unmet=r.unmet,
                )
            )
    return feats


def _station_features(p: Plan) -> list[dict]:
    """Each station (3-D: at its scanner's centre, with its ground)."""
    three_d = p.site.is_3d
    feats: list[dict] = []
    for r in p.stations.itertuples():
        extra = {}
        coords = [r.x, r.y]
        if three_d:  # the scanner's centre
            coords.append(round(r.ground_z + r.instrument_height_m, 3))
            extra["ground_z"] = r.ground_z
        feats.append(
            _feature(
                {"type": "Point", "coordinates": coords},
                layer="station",
                **_columns(r, STATION_COLUMNS, ("x", "y", "ground_z")),
                samples_met=r.samples_met,
                **extra,
            )
        )
    return feats


def _link_features(p: Plan) -> list[dict]:
    """Each link between two stations (a line), or to the control points it uses."""
    st = p.stations.set_index("station_id")
    feats: list[dict] = []
    tg = p.targets.set_index("target_id")
    for r in p.links.itertuples():
        b = st.loc[r.station_b]
        if r.station_a == "control":  # tied to the control points it uses: a line to each
            ends = [tg.loc[t] for t in r.target_ids.split(";") if t in tg.index]
            geom = {
                "type": "MultiLineString",
                "coordinates": [[[b.x, b.y], [c.x, c.y]] for c in ends],
            }
        else:
            a = st.loc[r.station_a]
            geom = {"type": "LineString", "coordinates": [[a.x, a.y], [b.x, b.y]]}
        feats.append(_feature(geom, layer="link", **_columns(r, LINK_COLUMNS)))
    return feats


def _target_features(p: Plan, ground: Any) -> list[dict]:
    """Each target at its centre (3-D: with its ground)."""
    feats: list[dict] = []
    for r, extra in zip(p.targets.itertuples(), _grounds(p.targets, ground), strict=True):
        feats.append(
            _feature(
                {"type": "Point", "coordinates": [r.x, r.y, r.z]},
                layer="target",
                **extra,
                **_columns(r, TARGET_COLUMNS, ("x", "y", "z")),
            )
        )
    return feats


def _route_features(p: Plan) -> list[dict]:
    """The walk between consecutive stations."""
    feats: list[dict] = []
    if p.route is not None:
        t = p.route.table
        for n, leg in enumerate(p.route.legs[1:], start=1):
            if len(leg) < 2:  # a job's first station: the crew's travel, not a walk
                continue
            feats.append(
                _feature(
                    {"type": "LineString", "coordinates": np.round(leg, 3).tolist()},
                    layer="route",
                    order=int(t["order"].iloc[n]),
                    station_a=t["station_id"].iloc[n - 1],
                    station_b=t["station_id"].iloc[n],
                    walk_m=float(t["walk_m"].iloc[n]),
                    session=int(t["session"].iloc[n]),
                    walk_note=t["walk_note"].iloc[n],
                )
            )
    return feats


def _unmet_features(p: Plan, ground: Any) -> list[dict]:
    """Each sample not met, with the reason."""
    feats: list[dict] = []
    unmet = p.unmet
    for r, extra in zip(unmet.itertuples(), _grounds(unmet, ground), strict=True):
        feats.append(
            _feature(
                {"type": "Point", "coordinates": [r.x, r.y, r.z]},
                layer="unmet",
                **extra,
                building_id=r.building_id,
                facade_id=r.facade_id,
                sample_id=r.sample_id,
                reason=r.reason,
            )
        )
    return feats
