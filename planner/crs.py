"""Coordinate reference systems (``pyproj``): longitude/latitude input projected to its UTM
zone, CRS labels checked against the coordinates, positions carried to WGS 84 for KML.

The planner computes in a projected CRS in metres; a site's :attr:`~planner.site.Site.crs`
names it and every output states it.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from planner.errors import InputError

__all__ = ["check_projected", "is_geographic", "name_of", "to_wgs84", "utm_for", "wgs84_to"]

#: GeoJSON without a ``crs`` member is longitude/latitude on WGS 84 (RFC 7946, sect. 4).
GEOJSON_DEFAULT = "OGC:CRS84"


@lru_cache(maxsize=32)
def _crs(label: str):
    import pyproj  # heavy: only when a CRS is used

    try:
        return pyproj.CRS.from_user_input(label)
    except pyproj.exceptions.CRSError as exc:
        raise InputError(
            f"unknown CRS {label!r} ({str(exc).splitlines()[0]}); give an EPSG code such as "
            "EPSG:25832 or EPSG:4326"
        ) from None


def is_geographic(label: str | None) -> bool:
    """Whether ``label`` names longitude/latitude degrees."""
    return bool(label) and _crs(label).is_geographic


def name_of(label: str) -> str:
    """'EPSG:25832 (ETRS89 / UTM zone 32N)', or the label with its name."""
    crs = _crs(label)
    code = crs.to_epsg()
    return f"EPSG:{code} ({crs.name})" if code else f"{label} ({crs.name})"


def utm_for(lon: float, lat: float) -> str:
    """The WGS 84 UTM zone holding (lon, lat), as 'EPSG:326NN' / 'EPSG:327NN'."""
    from pyproj.aoi import AreaOfInterest
    from pyproj.database import query_utm_crs_info

    found = query_utm_crs_info(
        datum_name="WGS 84", area_of_interest=AreaOfInterest(lon, lat, lon, lat)
    )
    if not found:
        raise InputError(f"no UTM zone holds longitude {lon:g}, latitude {lat:g}")
    return f"EPSG:{found[0].code}"


@lru_cache(maxsize=32)
def _transformer(src: str, dst: str):
    """The transformation ``src`` → ``dst`` (made once: making one takes milliseconds, and
    a plan's KML transforms every outline on its own)."""
    from pyproj import Transformer

    return Transformer.from_crs(_crs(src), _crs(dst), always_xy=True)


def wgs84_to(dst: str):
    """A function (x, y arrays of longitude/latitude) → (x, y) in ``dst``."""
    return _transformer("OGC:CRS84", dst).transform


def to_wgs84(label: str, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Longitude and latitude [deg] of positions in the CRS ``label``."""
    lon, lat = _transformer(label, "OGC:CRS84").transform(np.asarray(x), np.asarray(y))
    return np.asarray(lon), np.asarray(lat)


def check_projected(label: str, xy: np.ndarray) -> None:
    """A projected CRS label whose area of use is nowhere near the coordinates is an error
    (a wrong label would put every output in the wrong place)."""
    crs = _crs(label)
    if crs.is_geographic:
        return
    if not crs.is_projected:
        raise InputError(f"the CRS {name_of(label)} is not projected in metres; reproject")
    area = crs.area_of_use
    if area is None or not len(xy):
        return
    centre = xy.mean(axis=0)
    lon, lat = to_wgs84(label, centre[:1], centre[1:])
    margin = 2.0  # deg: zones are used a little beyond their edges
    inside = (
        np.isfinite(lon[0])
        and area.west - margin <= lon[0] <= area.east + margin
        and area.south - margin <= lat[0] <= area.north + margin
    )
    if not inside:
        raise InputError(
            f"the coordinates (e.g. {centre[0]:.1f}, {centre[1]:.1f}) are not in the area of "
            f"{name_of(label)} ({area.name}); fix the CRS label (--crs) or the coordinates"
        )
