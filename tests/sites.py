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


def run_cli(*argv: str) -> tuple[int, str, str]:
    """``planner ARGV`` in this process: (exit code, standard output, standard error)."""
    import io
    from contextlib import redirect_stderr, redirect_stdout

    from planner.app.cli import main

    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        try:
            code = main(list(argv))
        except SystemExit as exc:
            code = int(exc.code or 0)
    return code, out.getvalue(), err.getvalue()
