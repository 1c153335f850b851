"""The ground: heights of the terrain a station or target stands on, and the terrain as
triangles that block sight lines.

Heights are metres in the site's height system (the model's or the DTM's vertical datum,
:attr:`planner.site.Site.height_datum`). A site without terrain stands on flat ground at
height 0 (every height above the ground). Two sources:

* :class:`GridTerrain` — a digital terrain model raster (GeoTIFF, :func:`read_terrain`,
  read with ``rasterio``), bilinear between pixel centres, no-data pixels filled from the
  nearest valid one, the edge pixel's height beyond the raster;
* :class:`TinTerrain` — a triangulated relief (a city model's ``TINRelief``, or the
  buildings' ground surfaces when the model has no relief), linear on the Delaunay
  triangulation of its points, the nearest point's height outside them.

>>> t = TinTerrain(np.array([[0, 0, 10], [10, 0, 11], [0, 10, 10], [10, 10, 11]], float), "a slope")
>>> t.ground_z(np.array([[5.0, 5.0], [20.0, 5.0]])).round(3).tolist()
[10.5, 11.0]
"""

from __future__ import annotations

import math
import os

import numpy as np

from planner.errors import InputError
from planner.reading import user_file

__all__ = ["GridTerrain", "Terrain", "TinTerrain", "read_terrain"]

#: Terrain cells finer than this are merged for the scene's triangles [m]: the beam's
#: clearance over the ground is decimetres, and a 0.25 m DTM over a 500 m site would be
#: eight million triangles.
SCENE_CELL_M = 1.0
#: A DTM larger than this is refused [pixels] (after cutting it to the site).
MAX_TERRAIN_PIXELS = 50_000_000


class Terrain:
    """Ground heights of a site [m]; subclasses say how (``source``, in words) and whether
    the heights were measured (a DTM, a model's relief) or assumed from something else
    (``measured`` False: the ground under a model's buildings, joined across the streets)."""

    source: str = ""
    measured: bool = True

    def ground_z(self, xy: np.ndarray) -> np.ndarray:
        """Height of the ground [m] under each of the points ``xy`` (P, 2)."""
        raise NotImplementedError

    def triangles(self, bounds: tuple[float, float, float, float]) -> np.ndarray:
        """The terrain within ``bounds`` (xmin, ymin, xmax, ymax) as triangles (T, 3, 3)."""
        raise NotImplementedError

    @property
    def z_range(self) -> tuple[float, float]:
        """The lowest and highest ground height [m]."""
        raise NotImplementedError


class GridTerrain(Terrain):
    """A DTM raster: heights ``z`` (rows, cols) [m] at pixel centres ``x0 + j·dx``,
    ``y0 + i·dy`` (``dy`` < 0 for a north-up raster); NaN where the raster has no data."""

    def __init__(
        self, z: np.ndarray, x0: float, y0: float, dx: float, dy: float, source: str
    ) -> None:
        z = np.asarray(z, dtype=float)
        from scipy import ndimage  # (scipy's modules load when a terrain is made)

        valid = np.isfinite(z)
        if not valid.any():
            raise InputError(f"{source} holds no height (every pixel is no-data)")
        if not valid.all():  # each no-data pixel takes its nearest valid neighbour's height
            idx = ndimage.distance_transform_edt(
                ~valid, return_distances=False, return_indices=True
            )
            z = z[tuple(idx)]
        self.z, self.x0, self.y0, self.dx, self.dy = z, x0, y0, dx, dy
        self.source = source
        self.share_valid = float(valid.mean())

    def ground_z(self, xy: np.ndarray) -> np.ndarray:
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        from scipy import ndimage

        j = (xy[:, 0] - self.x0) / self.dx
        i = (xy[:, 1] - self.y0) / self.dy
        return ndimage.map_coordinates(self.z, [i, j], order=1, mode="nearest")

    def triangles(self, bounds: tuple[float, float, float, float]) -> np.ndarray:
        step = max(1, math.ceil(SCENE_CELL_M / min(abs(self.dx), abs(self.dy))))
        rows, cols = self.z.shape
        j0, j1 = sorted(((bounds[0] - self.x0) / self.dx, (bounds[2] - self.x0) / self.dx))
        i0, i1 = sorted(((bounds[1] - self.y0) / self.dy, (bounds[3] - self.y0) / self.dy))
        jj = np.arange(max(0, math.floor(j0) - step), min(cols - 1, math.ceil(j1) + step) + 1, step)
        ii = np.arange(max(0, math.floor(i0) - step), min(rows - 1, math.ceil(i1) + step) + 1, step)
        if len(ii) < 2 or len(jj) < 2:
            return np.empty((0, 3, 3))
        gx, gy = np.meshgrid(self.x0 + jj * self.dx, self.y0 + ii * self.dy)
        pts = np.stack([gx, gy, self.z[np.ix_(ii, jj)]], axis=-1)
        return _grid_triangles(pts)

    @property
    def z_range(self) -> tuple[float, float]:
        return float(self.z.min()), float(self.z.max())


def _grid_triangles(pts: np.ndarray) -> np.ndarray:
    """Two triangles (facing up) per cell of a grid of points (rows, cols, 3)."""
    a, b = pts[:-1, :-1].reshape(-1, 3), pts[:-1, 1:].reshape(-1, 3)
    c, d = pts[1:, 1:].reshape(-1, 3), pts[1:, :-1].reshape(-1, 3)
    tri = np.concatenate([np.stack([a, b, c], axis=1), np.stack([a, c, d], axis=1)])
    return _facing_up(tri)


def _facing_up(tri: np.ndarray) -> np.ndarray:
    """``tri`` (T, 3, 3) with every downward-facing triangle reversed in place."""
    down = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])[:, 2] < 0
    tri[down] = tri[down][:, ::-1]
    return tri


class TinTerrain(Terrain):
    """A triangulated relief from its points (P, 3) [m]: heights linear on their Delaunay
    triangulation, the nearest point's outside it; ``triangles`` (T, 3, 3) the relief's own
    faces where it has them (else the Delaunay triangles)."""

    def __init__(
        self,
        points: np.ndarray,
        source: str,
        faces: np.ndarray | None = None,
        *,
        measured: bool = True,
    ) -> None:
        from scipy.interpolate import LinearNDInterpolator, NearestNDInterpolator

        pts = np.asarray(points, dtype=float).reshape(-1, 3)
        if len(pts) == 0:
            raise InputError(f"{source}: no terrain points")
        xy, inverse = np.unique(np.round(pts[:, :2], 3), axis=0, return_inverse=True)
        z = np.bincount(inverse.ravel(), pts[:, 2]) / np.bincount(inverse.ravel())
        self.points = np.column_stack([xy, z])
        self.source, self.measured = source, measured
        from scipy.spatial import QhullError

        self._nearest = NearestNDInterpolator(xy, z)
        self._linear = None
        if len(xy) >= 3 and np.linalg.matrix_rank(xy - xy.mean(axis=0)) == 2:
            try:
                self._linear = LinearNDInterpolator(xy, z)
            except QhullError:
                raise InputError(f"{source}: its points cannot be triangulated") from None
        self.faces = None if faces is None else np.asarray(faces, dtype=float).reshape(-1, 3, 3)

    def ground_z(self, xy: np.ndarray) -> np.ndarray:
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        out = np.full(len(xy), np.nan) if self._linear is None else self._linear(xy)
        gap = ~np.isfinite(out)
        if gap.any():
            out[gap] = self._nearest(xy[gap])
        return out

    def triangles(self, bounds: tuple[float, float, float, float]) -> np.ndarray:
        tri = self.faces
        if tri is None:
            if self._linear is None:
                return np.empty((0, 3, 3))
            simplices = self._linear.tri.simplices
            tri = self.points[simplices]
        lo, hi = tri[:, :, :2].min(axis=1), tri[:, :, :2].max(axis=1)
        keep = (hi[:, 0] >= bounds[0]) & (lo[:, 0] <= bounds[2])
        keep &= (hi[:, 1] >= bounds[1]) & (lo[:, 1] <= bounds[3])
        return _facing_up(tri[keep].copy())

    @property
    def z_range(self) -> tuple[float, float]:
        return float(self.points[:, 2].min()), float(self.points[:, 2].max())


def read_terrain(
    path: str | os.PathLike, bounds: tuple[float, float, float, float] | None = None
) -> tuple[GridTerrain, str | None]:
    """A DTM GeoTIFF as :class:`GridTerrain` and its CRS (as text, or None), cut to
    ``bounds`` (xmin, ymin, xmax, ymax) [m] where given. Only the GeoTIFF driver opens it
    (a file that is really something else, a virtual raster or a URL, is refused)."""
    p = user_file(path, "terrain file")
    if p.suffix.lower() not in (".tif", ".tiff"):
        raise InputError(f"{p.name}: a terrain model is read from a GeoTIFF (.tif, .tiff)")
    import rasterio  # heavy (GDAL): only when a terrain is given
    from rasterio.errors import RasterioError, WindowError
    from rasterio.windows import from_bounds

    from planner.gdalio import CONFIG as GDAL_CONFIG  # nothing fetched, nothing written

    try:
        with (
            rasterio.Env(GDAL_DISABLE_READDIR_ON_OPEN="EMPTY_DIR", **GDAL_CONFIG),
            rasterio.open(p, driver="GTiff") as src,
        ):
            t = src.transform
            if t.b or t.d:
                raise InputError(f"{p.name} is a rotated raster; warp it north-up first (gdalwarp)")
            window = None
            if bounds is not None:
                window = (
                    from_bounds(*bounds, transform=src.transform).round_offsets().round_lengths()
                )
                whole = rasterio.windows.Window(0, 0, src.width, src.height)
                try:
                    window = window.intersection(whole)
                except WindowError:
                    raise InputError(
                        f"{p.name} does not cover the site (its extent "
                        f"{tuple(round(v) for v in src.bounds)}); give the terrain model of "
                        "the site, in the site's CRS"
                    ) from None
            shape = (window.height, window.width) if window is not None else (src.height, src.width)
            if shape[0] * shape[1] > MAX_TERRAIN_PIXELS:
                raise InputError(
                    f"{p.name}: {shape[0] * shape[1]:,} pixels over the site, more than "
                    f"{MAX_TERRAIN_PIXELS:,}; resample it coarser (1 m is plenty)"
                )
            z = src.read(1, window=window, masked=True).astype(float).filled(np.nan)
            t = src.window_transform(window) if window is not None else src.transform
            crs = src.crs.to_string() if src.crs else None
            _heights_in_metres(src.crs.to_wkt() if src.crs else None, p.name)
    except InputError:
        raise
    except (RasterioError, ValueError) as exc:
        raise InputError(f"{p.name}: cannot read it as a GeoTIFF terrain model ({exc})") from None
    if z.shape[0] < 2 or z.shape[1] < 2:
        raise InputError(
            f"{p.name} has {z.shape[0]} × {z.shape[1]} pixels over the site; a terrain model "
            "needs at least 2 × 2 (give the site's)"
        )
    z[(z < -1000) | (z > 9000)] = np.nan  # no-data values the file does not declare
    grid = GridTerrain(z, t.c + t.a / 2, t.f + t.e / 2, t.a, t.e, f"terrain model {p.name}")
    return grid, crs


def _heights_in_metres(wkt: str | None, name: str) -> None:
    """An InputError where the raster's CRS gives its heights in another unit than metres
    (a vertical CRS in feet: heights read as metres would be 3.3 times too large)."""
    if not wkt:
        return
    import pyproj

    try:
        crs = pyproj.CRS.from_wkt(wkt)
    except pyproj.exceptions.CRSError:
        return  # no vertical part known: the heights are taken as metres
    parts = crs.sub_crs_list if crs.is_compound else [crs]
    for part in parts:
        for axis in part.axis_info:
            if axis.direction == "up" and abs(axis.unit_conversion_factor - 1.0) > 1e-9:
                raise InputError(
                    f"{name}: its heights are in {axis.unit_name} ({part.name}); the planner "
                    "reads heights in metres — convert the raster to a vertical CRS in metres "
                    "first (e.g. gdal_calc.py, or gdalwarp to a CRS whose heights are metres)"
                )
