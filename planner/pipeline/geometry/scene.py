"""The scene: everything a beam meets, and the one place sight lines are answered.

Every sight line of a plan — station → facade sample, station → target, target ↔ target, a
station's ground patches and its sky — is answered by :meth:`Scene.seen` over the whole
site: buildings with their parts, roofs and eaves, the terrain, trees and other
structures. Two engines stand behind it:

* **rays** — the scene as triangles (a city model's surfaces as they are; a footprint
  extruded from its base to its height, the floors over a passage as a slab; a tree as a
  trunk and a crown; the terrain), cast with Intel's Embree (Wald, Woop, Benthin, Johnson
  & Ernst, "Embree: a kernel framework for efficient CPU ray tracing", ACM Transactions on
  Graphics 33(4), 2014, https://doi.org/10.1145/2601097.2601199) through its ``embreex``
  binding: first-hit and occlusion queries, in single precision about a local origin
  (:attr:`Scene.origin`);
* **prisms** — where the site is footprints with heights on flat ground, the exact 2.5-D
  test of :mod:`planner.pipeline.geometry.visibility` (compiled; one clear height per facade column
  serves every sample up it). It gives the same answers as the rays on such a site
  (tests/test_scene.py) and is faster there (benchmarks/RESULTS.md), so ``auto`` takes it.

Heights are in the site's height system; a station stands on the ground
(:meth:`Scene.ground_z`) at the instrument height.
"""

from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor
from functools import cached_property

import numpy as np
import shapely

from planner.citymodel import SEETHROUGH
from planner.errors import InputError
from planner.mesh import cap, crown_triangles, extrude
from planner.pipeline.geometry.visibility import (
    SIGHT_CLEARANCE_M,
    bridge_interval,
    clear_height,
    edges_in_box,
    visible,
)
from planner.pipeline.inputs.requirements import SIGHT_ENGINES as ENGINES
from planner.site import Site

__all__ = ["ENGINES", "TRIANGLE_KINDS", "Scene", "bridge_edges", "footprint_edges"]

#: What each triangle of the scene is (:attr:`Scene.kind` indexes this).
TRIANGLE_KINDS = (
    "wall",
    "roof",
    "ground",
    "ceiling",
    "floor",
    "window",
    "door",
    "installation",
    "terrain",
    "tree",
    "obstacle",
)
#: The scene's terrain reaches this far beyond the buildings [m].
TERRAIN_MARGIN_M = 400.0
#: A tree's trunk, as an obstacle below its crown [m].
TRUNK_RADIUS_M = 0.2
#: The lines beside a sight line that keep its clearance stop this far short of its end
#: (which lies just in front of a surface) [m].
CLEARANCE_SHORT_M = 0.10
#: Rays cast in one call of the engine; larger batches are split over threads.
RAY_BATCH = 65_536


class Scene:
    """Everything a beam meets on ``site`` and the sight lines through it (module text).

    Parameters
    ----------
    site : Site
    engine : {"auto", "rays", "prisms"}
        ``prisms`` only for a site of footprints on flat ground.
    """

    def __init__(self, site: Site, engine: str = "auto") -> None:
        if engine not in ENGINES:
            raise InputError(f"sight engine must be one of {', '.join(ENGINES)}; got {engine!r}")
        if engine == "prisms" and site.is_3d:
            raise InputError(
                "the prism engine answers footprints with heights on flat ground only; this "
                "site has 3-D buildings, a terrain or trees with crowns (use rays)"
            )
        self.site = site
        self.prisms = engine == "prisms" or (engine == "auto" and not site.is_3d)
        self.edges, self.edge_heights = footprint_edges(site)
        self.bridges = bridge_edges(site)

    def __getstate__(self) -> dict:
        """A scene pickles without its ray engines (a plan goes to a Dask worker, the
        report, the dashboard's thread): they are made again when first cast."""
        state = self.__dict__.copy()
        state.pop("_embree", None)
        state.pop("_embree_buildings", None)
        return state

    @property
    def engine(self) -> str:
        """The engine answering the sight lines: ``prisms`` or ``rays``."""
        return "prisms" if self.prisms else "rays"

    # -- the ground ---------------------------------------------------------------------------
    def ground_z(self, xy: np.ndarray) -> np.ndarray:
        """Height of the ground [m] under each point ``xy`` (P, 2) (0 on flat ground:
        :meth:`~planner.site.Site.ground_z`)."""
        return self.site.ground_z(xy)

    def above_ground(self, xy: np.ndarray, height_m: float) -> np.ndarray:
        """Heights [m] ``height_m`` above the ground at ``xy`` (P, 2): where an instrument or
        a target on a stand is (exactly ``height_m`` on flat ground)."""
        return self.ground_z(xy) + height_m

    # -- the mesh -----------------------------------------------------------------------------
    @cached_property
    def mesh(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[str]]:
        """The scene's triangles (T, 3, 3) [m], each one's owner (index into the ids, the
        last list) and kind (index into :data:`TRIANGLE_KINDS`)."""
        site = self.site
        tri, owner, kind, ids = [], [], [], []
        code = {k: i for i, k in enumerate(TRIANGLE_KINDS)}

        def add(t: np.ndarray, who: str, k: str | np.ndarray) -> None:
            if not len(t):
                return
            if not ids or ids[-1] != who:
                ids.append(who)
            tri.append(t)
            owner.append(np.full(len(t), len(ids) - 1))
            kind.append(np.full(len(t), code[k]) if isinstance(k, str) else k)

        cut = shapely.union_all([p.geometry for p in site.passages]) if site.passages else None
        for b in site.buildings:
            if b.surfaces:
                for s in b.surfaces:
                    if s.kind in SEETHROUGH:
                        continue
                    add(s.triangles, b.id, s.kind if s.kind in code else "wall")
                continue
            foot = b.footprint
            base = float(b.base_z or 0.0)
            if cut is not None and foot.intersects(cut):  # the floors over a gateway
                foot = foot.difference(cut)
                for p in site.passages_through([b]):
                    part = b.footprint.intersection(p.geometry)
                    if part.area > 0:
                        add(extrude(part, base + p.clear_height_m, b.top_z), b.id, "wall")
            add(extrude(foot, base, b.top_z, top=False, bottom=False), b.id, "wall")
            add(cap(foot, b.top_z), b.id, "roof")
            add(cap(foot, base)[:, ::-1], b.id, "ground")
        for o in site.obstacles:
            if o.mesh is not None:
                add(
                    np.asarray(o.mesh, dtype=float),
                    o.id,
                    "tree" if o.kind == "tree" else "obstacle",
                )
                continue
            ground = site.ground_under(o.geometry)
            if o.crown_base_m > 0:
                c = o.geometry.centroid
                r = max(float(np.sqrt(o.geometry.area / np.pi)), TRUNK_RADIUS_M)
                trunk = shapely.Point(c.x, c.y).buffer(TRUNK_RADIUS_M, quad_segs=2)
                add(extrude(trunk, ground, ground + o.crown_base_m), o.id, "tree")
                crown = crown_triangles((c.x, c.y), r, ground + o.crown_base_m, ground + o.height_m)
                add(crown, o.id, "tree")
                continue
            add(
                extrude(o.geometry, ground, ground + o.height_m),
                o.id,
                "tree" if o.kind == "tree" else "obstacle",
            )
        if site.terrain is not None:
            x0, y0, x1, y1 = self._extent()
            m = TERRAIN_MARGIN_M
            add(site.terrain.triangles((x0 - m, y0 - m, x1 + m, y1 + m)), "terrain", "terrain")
        if not tri:
            return np.empty((0, 3, 3)), np.empty(0, np.int64), np.empty(0, np.int64), ids
        return np.concatenate(tri), np.concatenate(owner), np.concatenate(kind), ids

    def _extent(self) -> tuple[float, float, float, float]:
        geoms = [b.footprint for b in self.site.buildings] + [
            o.geometry for o in self.site.obstacles
        ]
        return tuple(shapely.union_all(geoms).bounds)  # type: ignore[return-value]

    @cached_property
    def origin(self) -> np.ndarray:
        """The local origin the engine casts about (single precision keeps millimetres
        within kilometres of it) [m]."""
        x0, y0, x1, y1 = self._extent()
        z = min((float(b.base_z or 0.0) for b in self.site.buildings), default=0.0)
        return np.array([(x0 + x1) / 2, (y0 + y1) / 2, z])

    @cached_property
    def _embree(self):
        return self._engine(np.ones(len(self.mesh[0]), dtype=bool))

    @cached_property
    def _embree_buildings(self):
        """The buildings alone (for :meth:`inside`: the terrain passes under them)."""
        owners = np.asarray(self.mesh[3], dtype=object)[self.mesh[1]] if len(self.mesh[0]) else []
        return self._engine(np.isin(owners, [b.id for b in self.site.buildings]))

    def _engine(self, keep: np.ndarray):
        """An Embree scene of the mesh's triangles ``keep`` (in single precision about
        :attr:`origin`), its triangles' indices into the mesh."""
        from embreex import mesh_construction, rtcore_scene

        scene = rtcore_scene.EmbreeScene()
        which = np.flatnonzero(keep)
        if len(which):
            tri = self.mesh[0][which]
            mesh_construction.TriangleMesh(scene, (tri - self.origin).astype(np.float32))
        return scene, which

    # -- sight lines --------------------------------------------------------------------------
    def seen(
        self,
        src: np.ndarray,
        dst: np.ndarray,
        groups: tuple[np.ndarray, np.ndarray] | None = None,
    ) -> np.ndarray:
        """Whether each sight line ``src`` → ``dst`` ((P, 3) each, or one end (3,)
        broadcast) [m] is free: nothing of the scene between its ends. ``groups``: the
        lines in groups, each tested against the footprint edges in its box only (the
        prism engine's speed-up, :func:`~planner.pipeline.geometry.visibility.clear_height`)."""
        src, dst = np.broadcast_arrays(
            np.asarray(src, float).reshape(-1, 3), np.asarray(dst, float).reshape(-1, 3)
        )
        if not len(src):
            return np.zeros(0, dtype=bool)
        if self.prisms:
            # the edges within the lines' reach: one box round the groups' (or the lines)
            if groups is not None:
                lo_xy, hi_xy = groups[1][:, :2].min(axis=0), groups[1][:, 2:].max(axis=0)
            else:
                lo_xy = np.minimum(src[:, :2].min(axis=0), dst[:, :2].min(axis=0))
                hi_xy = np.maximum(src[:, :2].max(axis=0), dst[:, :2].max(axis=0))
            near = edges_in_box(self.edges, (*lo_xy, *hi_xy))
            zc = clear_height(
                src[:, :2],
                src[:, 2],
                dst[:, :2],
                self.edges[near],
                self.edge_heights[near],
                groups=groups,
            )
            lo = up = None
            b_edges, bottoms, tops = self.bridges
            crossed = edges_in_box(b_edges, (*lo_xy, *hi_xy)) if len(b_edges) else []
            if np.any(crossed):
                lo, up = bridge_interval(
                    src[:, :2],
                    src[:, 2],
                    dst[:, :2],
                    b_edges[crossed],
                    bottoms[crossed],
                    tops[crossed],
                )
            return visible(dst[:, 2], zc, lo, up)
        return ~self.occluded(src, dst - src, clearance_m=SIGHT_CLEARANCE_M)

    def occluded(self, org: np.ndarray, vec: np.ndarray, clearance_m: float = 0.0) -> np.ndarray:
        """Whether anything of the mesh lies on each segment ``org`` → ``org + vec``
        ((P, 3) each [m]), by the ray engine. With a ``clearance_m``, four more segments run
        beside each one at that distance (left, right, above, below; ending
        :data:`CLEARANCE_SHORT_M` short of its end, which lies on a surface), and a segment
        is blocked where any is: a line passing an edge closer than the clearance is
        blocked, as the prism test's is."""
        length = np.linalg.norm(vec, axis=1)
        ok = length > 0
        out = np.zeros(len(org), dtype=bool)
        if not ok.any() or not len(self.mesh[0]):
            return out
        o64 = org[ok] - self.origin
        u = vec[ok] / length[ok, None]
        t = length[ok]
        hit = (
            self._cast(
                self._embree,
                o64.astype(np.float32),
                u.astype(np.float32),
                t.astype(np.float32),
                "OCCLUDED",
            )
            == 0
        )
        if clearance_m > 0 and not hit.all():  # the lines beside the ones still clear
            free = np.flatnonzero(~hit)
            side = np.cross(u[free], [0.0, 0.0, 1.0])
            flat = np.linalg.norm(side, axis=1) < 1e-9  # a vertical line
            side[flat] = [1.0, 0.0, 0.0]
            side /= np.linalg.norm(side, axis=1)[:, None]
            up = np.cross(side, u[free])
            short = np.maximum(t[free] - CLEARANCE_SHORT_M, 0.0)
            o4 = np.concatenate([o64[free] + clearance_m * a for a in (side, -side, up, -up)])
            beside = self._cast(
                self._embree,
                o4.astype(np.float32),
                np.concatenate([u[free]] * 4).astype(np.float32),
                np.concatenate([short] * 4).astype(np.float32),
                "OCCLUDED",
            )
            hit[free] = (beside == 0).reshape(4, -1).any(axis=0)
        out[ok] = hit
        return out

    def first_hit(
        self,
        org: np.ndarray,
        direction: np.ndarray,
        max_m: float | np.ndarray = np.inf,
        buildings_only: bool = False,
    ) -> tuple[np.ndarray, np.ndarray]:
        """The first surface each ray meets: its distance [m] (inf: none within ``max_m``)
        and the triangle's index into :attr:`mesh` (-1: none). ``direction`` need not be a
        unit vector; ``buildings_only``: the buildings' surfaces alone."""
        org = np.asarray(org, float).reshape(-1, 3)
        d = np.asarray(direction, float).reshape(-1, 3)
        n = np.linalg.norm(d, axis=1)
        d = d / np.where(n > 0, n, 1.0)[:, None]
        dist = np.full(len(org), np.inf)
        tri = np.full(len(org), -1, dtype=np.int64)
        if not len(org) or not len(self.mesh[0]):
            return dist, tri
        far = np.broadcast_to(np.minimum(np.asarray(max_m, float), 1e7), (len(org),))
        engine = self._embree_buildings if buildings_only else self._embree
        res = self._cast(
            engine,
            (org - self.origin).astype(np.float32),
            d.astype(np.float32),
            far.astype(np.float32),
            "INTERSECT",
        )
        hit = res["primID"] >= 0
        dist[hit] = res["tfar"][hit]
        tri[hit] = engine[1][res["primID"][hit]]
        return dist, tri

    @staticmethod
    def _cast(engine, o: np.ndarray, d: np.ndarray, t: np.ndarray, query: str):
        """Embree's query over the rays, in batches on up to two threads (the engine
        releases the interpreter while it casts)."""
        scene, _ = engine
        n = len(o)

        def run(s: slice):
            if query == "OCCLUDED":
                return scene.run(o[s], d[s], dists=t[s].copy(), query=query)
            return scene.run(o[s], d[s], dists=t[s].copy(), query=query, output=1)

        cuts = [slice(a, min(a + RAY_BATCH, n)) for a in range(0, n, RAY_BATCH)]
        if len(cuts) == 1 or (os.cpu_count() or 1) < 2:
            parts = [run(s) for s in cuts]
        else:
            with ThreadPoolExecutor(2) as pool:
                parts = list(pool.map(run, cuts))
        if query == "OCCLUDED":
            return np.concatenate(parts)
        return {k: np.concatenate([p[k] for p in parts]) for k in ("tfar", "primID")}

    def inside(self, xyz: np.ndarray) -> np.ndarray:
        """For each point (P, 3) [m], the id of the building it is inside ("" where it is in
        the open): the first building surface straight below it is that building's ground
        face (the terrain, which may pass under a building on a slope, is not counted)."""
        xyz = np.asarray(xyz, float).reshape(-1, 3)
        out = np.full(len(xyz), "", dtype=object)
        if not len(xyz):
            return out
        down = np.array([0.0, 0.0, -1.0]) + np.zeros((len(xyz), 3))
        _, tri = self.first_hit(xyz, down, 1e4, buildings_only=True)
        _, owner, kind, ids = self.mesh
        below = tri >= 0
        ground = np.zeros(len(xyz), dtype=bool)
        ground[below] = kind[tri[below]] == TRIANGLE_KINDS.index("ground")
        out[ground] = np.asarray(ids, dtype=object)[owner[tri[ground]]]
        return out

    @property
    def n_triangles(self) -> int:
        return len(self.mesh[0])


def bridge_edges(site: Site) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Every ring edge of the floors above the passages (:attr:`Site.bridges`): ``(M, 4)``
    as x0, y0, x1, y1, with the bottom and top of the floors [m]."""
    segs, bottoms, tops = [np.empty((0, 4))], [np.empty(0)], [np.empty(0)]
    for _, geom, bottom, top in site.bridges:
        e = _ring_edges(geom)
        segs.append(e)
        bottoms.append(np.full(len(e), bottom))
        tops.append(np.full(len(e), top))
    return np.vstack(segs), np.concatenate(bottoms), np.concatenate(tops)


def _ring_edges(geom) -> np.ndarray:
    """Every ring edge of a polygon or multipolygon, ``(M, 4)`` as x0, y0, x1, y1."""
    segs = [np.empty((0, 4))]
    for poly in shapely.get_parts(geom):
        for ring in [poly.exterior, *poly.interiors]:
            xy = np.asarray(ring.coords)[:, :2]
            segs.append(np.hstack([xy[:-1], xy[1:]]))
    return np.vstack(segs)


def footprint_edges(site: Site) -> tuple[np.ndarray, np.ndarray]:
    """Every ring edge of every blocker: ``(M, 4)`` as x0, y0, x1, y1, and its height."""
    segs, heights = [np.empty((0, 4))], [np.empty(0)]
    for _, geom, h in site.blockers:
        e = _ring_edges(geom)
        segs.append(e)
        heights.append(np.full(len(e), h))
    return np.vstack(segs), np.concatenate(heights)
