"""Coordinate reference systems (``pyproj``): longitude/latitude input projected to its UTM
zone, CRS labels checked against the coordinates, positions carried to WGS 84 for KML.

The planner computes in a projected CRS in metres; a site's :attr:`~planner.site.Site.crs`
names it and every output states it.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from planner.errors import InputError

__all__ = [
    "check_projected",
    "is_geographic",
    "name_of",
    "split_model_crs",
    "to_wgs84",
    "utm_for",
    "wgs84_to",
]

#: GeoJSON without a ``crs`` member is longitude/latitude on WGS 84 (RFC 7946, sect. 4).
GEOJSON_DEFAULT = "OGC:CRS84"


@lru_cache(maxsize=32)
def _crs(label: str):
    import pyproj  # heavy: only when a CRS is used

    pyproj.network.set_network_enabled(active=False)  # PROJ fetches no grid, whatever the env
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
    units = {(a.unit_name, a.unit_conversion_factor) for a in crs.axis_info[:2]}
    if any(abs(factor - 1.0) > 1e-12 for _, factor in units):
        unit, factor = next(u for u in units if abs(u[1] - 1.0) > 1e-12)
        metric = ""
        if len(xy):
            lon, lat = to_wgs84(label, xy[:1, 0], xy[:1, 1])
            if np.isfinite(lon[0]) and np.isfinite(lat[0]):
                metric = f", e.g. {name_of(utm_for(float(lon[0]), float(lat[0])))}"
        raise InputError(
            f"the CRS {name_of(label)} measures in {unit} (1 {unit} = {factor:.7g} m); the "
            f"planner works in metres (heights too): reproject the file to a CRS in "
            f"metres{metric}, and give its heights in metres"
        )
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


#: The German surveying authorities' (AdV) CRS names, as German CityGML gives them in
#: ``srsName`` (``urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH``) → EPSG codes.
ADV_CRS = {
    "ETRS89_UTM32": "EPSG:25832",
    "ETRS89_UTM33": "EPSG:25833",
    "DE_DHDN_3GK2": "EPSG:31466",
    "DE_DHDN_3GK3": "EPSG:31467",
    "DE_DHDN_3GK4": "EPSG:31468",
    "DE_DHDN_3GK5": "EPSG:31469",
    "DE_DHHN2016_NH": "EPSG:7837",
    "DE_DHHN92_NH": "EPSG:5783",
    "DE_DHHN12_NOH": "EPSG:5784",
}


def split_model_crs(label: str) -> tuple[str | None, str]:
    """A city model's CRS label as ``(horizontal CRS label, its heights in words)``:
    compound CRSs (``EPSG:7415``, OGC compound URNs, the AdV's ``A*B``) split into their
    horizontal and vertical parts.

    >>> split_model_crs("urn:adv:crs:ETRS89_UTM32*DE_DHHN2016_NH")
    ('EPSG:25832', 'DHHN2016 height (EPSG:7837)')
    >>> split_model_crs("https://www.opengis.net/def/crs/EPSG/0/7415")
    ('EPSG:28992', 'NAP height (EPSG:5709)')
    >>> split_model_crs("urn:ogc:def:crs,crs:EPSG:6.12:31467,crs:EPSG:6.12:5783")
    ('EPSG:31467', 'DHHN92 height (EPSG:5783)')
    >>> split_model_crs("EPSG:25832+7837")
    ('EPSG:25832', 'DHHN2016 height (EPSG:7837)')
    """
    import re

    text = label.strip()
    parts: list[str] = []
    if text.lower().startswith("urn:adv:crs:"):
        for name in text[len("urn:adv:crs:") :].split("*"):
            if name not in ADV_CRS:
                raise InputError(
                    f"unknown AdV CRS {name!r} in {label!r}; give the model's CRS (--crs EPSG:…)"
                )
            parts.append(ADV_CRS[name])
    else:  # EPSG:7415, EPSG::7415, EPSG:6.12:25832, .../EPSG/0/7415, EPSG:25832+7837
        codes = re.findall(r"EPSG(?:/[\d.]+/|:[\d.]*:|:)(\d+)((?:\+\d+)*)", text, re.IGNORECASE)
        parts = [f"EPSG:{c}" for first, more in codes for c in [first, *more.split("+")[1:]]]
        parts = parts or [text]
    crs = [_crs(p) for p in parts]
    if len(crs) == 1 and crs[0].is_compound:
        crs = list(crs[0].sub_crs_list)
        parts = [f"EPSG:{c.to_epsg()}" if c.to_epsg() else c.to_wkt() for c in crs]
    horizontal = next((p for p, c in zip(parts, crs, strict=True) if not c.is_vertical), None)
    vertical = next((c for c in crs if c.is_vertical), None)
    if vertical is None:
        datum = "the model's heights (its file names no vertical datum)"
    else:
        code = vertical.to_epsg()
        datum = f"{vertical.name} (EPSG:{code})" if code else vertical.name
    return horizontal, datum
