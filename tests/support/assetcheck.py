"""Helpers for asset tests: cached builds and exact point-to-mesh distances."""
from __future__ import annotations

from functools import lru_cache

import numpy as np
import shapely.geometry as sg
import trimesh

from indoorgen.assets.base import get_factory


@lru_cache(maxsize=None)
def build(name: str, seed: int):
    f = get_factory(name)
    p = f.sample_params(np.random.default_rng(seed))
    return f, p, f.placeholder(p), f.create(p)


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


