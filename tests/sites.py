"""Named test sites (as shapely keeps ``polygon``, ``polygon_with_hole``…), in a local
projected frame offset to realistic UTM-like coordinates."""

from __future__ import annotations

from shapely.geometry import MultiPolygon, Polygon, box

from planner.site import Area, Building, Obstacle, Site

E0, N0 = 500_000.0, 5_400_000.0


def rect(x0: float, y0: float, x1: float, y1: float) -> Polygon:
    return box(E0 + x0, N0 + y0, E0 + x1, N0 + y1)


def poly(coords, holes=()) -> Polygon:
    return Polygon(
        [(E0 + x, N0 + y) for x, y in coords], [[(E0 + x, N0 + y) for x, y in h] for h in holes]
    )


def square_site(size: float = 20.0, height: float = 10.0, **kw) -> Site:
    return Site([Building("sq", rect(0, 0, size, size), height)], **kw)


def l_site(height: float = 12.0) -> Site:
    """An L: 30 × 10 m along x, and a 10 × 20 m wing up the west side."""
    return Site(
        [Building("L", poly([(0, 0), (30, 0), (30, 10), (10, 10), (10, 30), (0, 30)]), height)]
    )


def courtyard_site(court: float = 20.0, height: float = 12.0) -> Site:
    """A 40 × 40 m block with a closed square courtyard of side ``court`` (a hole)."""
    a = (40 - court) / 2
    outer = [(0, 0), (40, 0), (40, 40), (0, 40)]
    hole = [(a, a), (a, a + court), (a + court, a + court), (a + court, a)]
    return Site([Building("court", poly(outer, [hole]), height)])


def multipolygon_site() -> Site:
    return Site([Building("twin", MultiPolygon([rect(0, 0, 10, 10), rect(30, 0, 40, 10)]), 8.0)])


__all__ = [
    "E0",
    "N0",
    "Area",
    "Obstacle",
    "courtyard_site",
    "l_site",
    "multipolygon_site",
    "poly",
    "rect",
    "square_site",
]


#: The paper's scanner and 5 mm / 5 mm: the arguments most plan and report tests share.
PAPER_5MM = ["--scanner", "leica-4mm-60urad", "--max-xy-mm", "5", "--max-z-mm", "5"]


def run_cli(*argv: str) -> tuple[int, str, str]:
    """``planner ARGV`` in this process: (exit code, standard output, standard error)."""
    import io
    from contextlib import redirect_stderr, redirect_stdout

    from planner.app.cli import main

    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        try:
            code = main(list(argv))
        except SystemExit as exc:  # argparse usage errors
            code = int(exc.code or 0)
    return code, out.getvalue(), err.getvalue()


def osm_like_export() -> dict:
    """An OpenStreetMap-style export around the default site, in longitude/latitude
    (RFC 7946 GeoJSON, ids ``way/…``), with the problems real exports have.

    Near the default site's ``main`` (a row across the street to the north):
    ``way/1001`` only ``building:levels`` 4; ``way/1002`` ``height`` "14 m", its shared
    wall with 1001 digitised twice (a 0.3 m overlap); ``way/1003`` no height at all;
    ``way/1004`` overlapping 1003's corner by 8 m² (8 % of it); ``way/1005`` a
    self-intersecting outline; ``way/1006`` a ``building:part`` (a tower) inside 1001.
    Far away (400 m and more east): 30 buildings, 20 without a
    height, 5 by levels only, 3 self-intersecting, 3 overlapping pairs (one drawn twice) and
    an unclosed way tagged as a building.
    """
    import json

    from pyproj import Transformer

    from planner.siteio import default_site  # noqa: F401  (the file below is its source)

    base = json.loads(
        __import__("importlib.resources", fromlist=["files"])
        .files("planner.data")
        .joinpath("default_site.geojson")
        .read_text("utf-8")
    )
    to_ll = Transformer.from_crs("EPSG:25832", "EPSG:4326", always_xy=True)
    x0, y0 = 691000.0, 5335000.0

    def ll(coords):
        return [list(to_ll.transform(x0 + x, y0 + y)) for x, y in coords]

    def building(ident, coords, **tags):
        return {
            "type": "Feature",
            "id": ident,
            "properties": {"@id": ident, "building": "yes", **tags},
            "geometry": {"type": "Polygon", "coordinates": [ll([*coords, coords[0]])]},
        }

    def box_(a, b, c, d):
        return [(a, b), (c, b), (c, d), (a, d)]

    def bowtie(a, b, size):
        return [(a, b), (a + size, b + size), (a + size, b), (a, b + size)]

    feats = []
    for f in base["features"]:
        if f["properties"]["role"] == "boundary":
            continue
        g = f["geometry"]
        rings = [[list(to_ll.transform(x, y)) for x, y in ring] for ring in g["coordinates"]]
        feats.append({**f, "geometry": {"type": "Polygon", "coordinates": rings}})
    feats += [
        building("way/1001", box_(0, 50, 20, 62), **{"building:levels": "4"}),
        building("way/1002", box_(19.7, 50, 35, 62), height="14 m"),
        building("way/1003", box_(35, 50, 50, 62)),
        building("way/1004", box_(48, 58, 60, 66), **{"building:levels": "3"}),
        building("way/1005", bowtie(65, 50, 10), height="9"),
    ]
    far = 0
    for row in range(5):
        for col in range(6):
            x, y = 400 + 30 * col, 40 * row
            ident = f"way/2{far:03d}"
            tags = {}
            if far % 30 < 20:
                pass  # no height at all
            elif far % 30 < 25:
                tags["building:levels"] = str(2 + far % 4)
            else:
                tags["height"] = "11"
            shape = bowtie(x, y, 12) if far in (3, 14, 27) else box_(x, y, x + 15, y + 12)
            feats.append(building(ident, shape, **tags))
            far += 1
    # overlapping pairs far away: a neighbour 2 m into another, one drawn twice, a corner
    feats.append(building("way/3001", box_(400 + 13, 0, 400 + 25, 12), height="10"))
    feats.append(building("way/3002", box_(430, 40, 445, 52), height="10"))  # = way/2007
    feats.append(building("way/3003", box_(460 + 12, 80 + 9, 460 + 20, 80 + 16), height="8"))
    # a building part inside its building near the plan (a tower on way/1001's roof)
    part = building("way/1006", box_(2, 52, 8, 58), height="20")
    del part["properties"]["building"]
    part["properties"]["building:part"] = "yes"
    feats.append(part)
    feats.append(
        {
            "type": "Feature",
            "id": "way/3004",
            "properties": {"@id": "way/3004", "building": "yes"},
            "geometry": {"type": "LineString", "coordinates": ll([(600, 150), (620, 150)])},
        }
    )
    return {"type": "FeatureCollection", "features": feats}


def assert_spaced(p) -> None:
    """No two scanning stations of plan ``p`` closer than its station spacing unless its
    summary names the pair and says why (the crew's one set-up per spot)."""
    import numpy as np

    st = p.scan_stations
    xy = st[["x", "y"]].to_numpy(float)
    ids = st["station_id"].astype(str).tolist()
    line = p.spacing_summary() or ""
    assert line in p.summary()
    for i, j in zip(*np.triu_indices(len(st), 1), strict=True):
        d = float(np.hypot(*(xy[i] - xy[j])))
        if d < p.settings.station_spacing_m:
            named = f"{ids[i]}–{ids[j]} {d:.1f} m" in line or f"{ids[j]}–{ids[i]}" in line
            assert named or " more (" in line, f"{ids[i]}, {ids[j]} {d:.1f} m apart: {line}"
