"""Helpers for asset tests: cached builds and exact point-to-mesh distances."""
from __future__ import annotations

from functools import lru_cache

import numpy as np
import shapely.geometry as sg
import trimesh

from indoorgen.assets.registry import get_factory


@lru_cache(maxsize=None)
def build(name: str, seed: int):
    f = get_factory(name)
    p = f.sample_params(np.random.default_rng(seed))
    return f, p, f.placeholder(p), f.create(p)


def make(name: str, seed: int, **overrides):
    """A generator's params for `seed` with some overridden, and the detailed asset."""
    f = get_factory(name)
    p = f.sample_params(np.random.default_rng(seed))
    p.update(overrides)
    return f, p, f.create(p)


def distances(mesh: trimesh.Trimesh, pts: np.ndarray) -> np.ndarray:
    """Exact distance from each point to the mesh surface (brute force over nearby triangles)."""
    tris = mesh.triangles
    lo, hi = tris.min(axis=1), tris.max(axis=1)
    out = np.empty(len(pts))
    for i, q in enumerate(pts):
        near = np.all((lo <= q + 2e-3) & (hi >= q - 2e-3), axis=1)
        if not near.any():
            out[i] = np.inf
            continue
        t = tris[near]
        cp = trimesh.triangles.closest_point(t, np.repeat(q[None], len(t), axis=0))
        out[i] = np.linalg.norm(cp - q, axis=1).min()
    return out


def sample_polygon(poly: sg.Polygon) -> np.ndarray:
    """Deterministic points inside a polygon: a representative point, the centroid, points
    90% of the way to each vertex and a small grid."""
    c = np.asarray(poly.representative_point().coords[0])
    pts = [c, np.asarray(poly.centroid.coords[0])]
    verts = np.asarray(poly.exterior.coords)[:-1]
    step = max(1, len(verts) // 8)
    pts += [c + 0.9 * (v - c) for v in verts[::step]]
    x0, y0, x1, y1 = poly.bounds
    for a in (0.2, 0.5, 0.8):
        for b in (0.2, 0.5, 0.8):
            pts.append(np.array([x0 + a * (x1 - x0), y0 + b * (y1 - y0)]))
    return np.array([q for q in pts if poly.contains(sg.Point(q))])


def to_local(surface, pts3: np.ndarray) -> np.ndarray:
    d = pts3 - surface.origin
    return np.c_[d @ surface.u, d @ surface.v]




def part_signature(factory, params) -> tuple:
    """A cheap fingerprint of the detailed design of `params`: every piece's bounding box,
    volume, size, link and material slot, and every named surface (no booleans, so comparing
    many variants stays fast)."""
    p = factory.resolve(params)
    parts = factory.parts(p, True)
    pieces = tuple(sorted((tuple(np.round(q.solid.bounding_box(), 6)), round(q.solid.volume(), 10),
                           q.solid.num_tri(), q.link, q.slot) for q in parts))
    surfaces = tuple(sorted((s.name, tuple(np.round(s.origin, 6)), tuple(np.round(s.polygon.bounds, 6)))
                            for s in factory.extra_surfaces(p)))
    return pieces, surfaces


def param_values(prm) -> list:
    """The values a parameter is moved through: its range's ends, both booleans, every choice."""
    if prm.kind == "float":
        return [prm.low, (prm.low + prm.high) / 2, prm.high]
    if prm.kind == "int":
        return [int(prm.low), int(prm.high)]
    if prm.kind == "bool":
        return [False, True]
    return list(prm.choices)


def inert_params(factory, n_bases: int = 16) -> list[str]:
    """Parameters that never change the design (geometry, materials or surfaces), whatever the
    design around them:
    each is moved through its values on a few base designs (sampled ones, and the first of
    them with every number at its low and at its high end)."""
    bases = [factory.sample_params(np.random.default_rng(s)) for s in range(n_bases - 2)]
    for end in ("low", "high"):
        bases.append(dict(bases[0], **{k: (getattr(q, end) if q.kind == "float"
                                           else int(getattr(q, end)))
                                       for k, q in factory.params.items()
                                       if q.kind in ("float", "int")}))
    inert = []
    for k, prm in factory.params.items():
        if not any(len({part_signature(factory, dict(b, **{k: v}))
                        for v in param_values(prm)}) > 1 for b in bases):
            inert.append(k)
    return inert
