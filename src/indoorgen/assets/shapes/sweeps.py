"""Swept solids: lofts through rings of points, round tubes along (filleted) polylines, and the
boxes that stand in for tubes in placeholders.

`loft` closes a solid through consistently ordered rings (leaves, stems, woven baskets); `tube`
sweeps a circle along a polyline by parallel transport (bentwood and tubular-steel frames, rods
between any two points); `tube_boxes` and `rod_between(detail=False)` give boxes with the exact
extents of the tube's end rings, so a placeholder contains the tube and matches its bounds.
"""
from __future__ import annotations

import math

import manifold3d as m3d
import numpy as np
from numpy.typing import ArrayLike

from indoorgen.assets.shapes.primitives import box_between


def unit_rows(v: np.ndarray) -> np.ndarray:
    """Each row (last axis) of `v` scaled to unit length."""
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def xz_extrude(cs: m3d.CrossSection, y0: float, y1: float) -> m3d.Manifold:
    """Extrude a side profile drawn in (x, z) from y0 to y1 along Y."""
    m = m3d.Manifold.extrude(cs, y1 - y0)
    # (a, b, h) -> (x=a, y=y1-h, z=b): a proper rotation (det +1)
    return m.transform(np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, -1.0, y1],
                                 [0.0, 1.0, 0.0, 0.0]]))


def dedupe_points(points: ArrayLike) -> np.ndarray:
    """The points (N, 3) without those repeating their predecessor (zero-length segments)."""
    arr = np.asarray(points, float)
    keep = np.r_[True, np.linalg.norm(np.diff(arr, axis=0), axis=1) > 1e-6]
    return arr[keep]


def polyline_tangents(pts: np.ndarray) -> np.ndarray:
    """Unit tangents at a polyline's points: its end segments' directions at the ends, the
    bisector of the two neighbouring segments at every interior point."""
    seg = unit_rows(np.diff(pts, axis=0))
    tang = np.empty_like(pts)
    tang[0], tang[-1] = seg[0], seg[-1]
    tang[1:-1] = unit_rows(seg[:-1] + seg[1:])
    return tang


def fillet_path(points: ArrayLike, radius: float, segments: int = 5) -> np.ndarray:
    """The polyline `points` (N, 3) with every interior corner rounded by a circular arc of
    `radius` (shrunk where the neighbouring segments are too short), sampled with `segments`
    steps per arc: the centre line of a bent tube."""
    pts = np.asarray(points, float)
    if len(pts) < 3:
        return pts
    b = pts[1:-1]
    u, v = pts[:-2] - b, pts[2:] - b
    lu, lv = np.linalg.norm(u, axis=1), np.linalg.norm(v, axis=1)
    u, v = u / lu[:, None], v / lv[:, None]
    ang = np.arccos(np.clip(np.einsum("ij,ij->i", u, v), -1.0, 1.0))  # interior angles
    bent = ang < math.pi - 1e-3
    half = np.where(bent, ang / 2, 0.25)
    t = np.minimum(np.minimum(radius / np.tan(half), 0.5 * lu), 0.5 * lv)
    r = t * np.tan(half)
    bis = unit_rows(np.where(bent[:, None], u + v, 1.0))
    centre = b + bis * (r / np.sin(half))[:, None]
    e0, e1 = b + u * t[:, None] - centre, b + v * t[:, None] - centre
    w = np.arccos(np.clip(np.einsum("ij,ij->i", e0, e1) / np.maximum(r * r, 1e-18), -1.0, 1.0))
    w = np.maximum(w, 1e-9)
    sp = np.linspace(0.0, 1.0, segments + 1)[None, :, None]
    arcs = ((np.sin((1 - sp) * w[:, None, None]) * e0[:, None, :]
             + np.sin(sp * w[:, None, None]) * e1[:, None, :]) / np.sin(w)[:, None, None]
            + centre[:, None, :])
    arcs = np.where(bent[:, None, None], arcs, b[:, None, :])
    return dedupe_points(np.vstack([pts[:1], arcs.reshape(-1, 3), pts[-1:]]))


def tube_rings(path: ArrayLike, radius: float, sections: int = 12) -> np.ndarray:
    """The vertex rings (len(path), sections, 3) of `tube(path, radius, sections)`: circles of
    `radius` perpendicular to the path, carried along by parallel transport (no twist)."""
    pts = np.asarray(path, float)
    n = max(4, int(math.ceil(sections / 4.0)) * 4)
    tang = polyline_tangents(pts)
    ref = np.array([0.0, 0.0, 1.0]) if abs(tang[0][2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    nrm = np.empty_like(pts)
    cur = np.cross(tang[0], ref)
    for i in range(len(pts)):  # parallel transport of the ring's reference direction
        cur = cur - np.dot(cur, tang[i]) * tang[i]
        cur = cur / np.linalg.norm(cur)
        nrm[i] = cur
    bin_ = np.cross(tang, nrm)
    a = 2 * np.pi * np.arange(n) / n
    return (pts[:, None, :] + radius * (np.cos(a)[None, :, None] * nrm[:, None, :]
                                        + np.sin(a)[None, :, None] * bin_[:, None, :]))


def tube(path: ArrayLike, radius: float, sections: int = 12) -> m3d.Manifold:
    """A round tube of `radius` swept along the polyline `path` (use `fillet_path` for bends),
    with flat end caps perpendicular to the path."""
    pts = np.asarray(path, float)
    rings = tube_rings(pts, radius, sections)
    m, n = rings.shape[:2]
    verts = np.vstack([rings.reshape(-1, 3), pts[0], pts[-1]])
    i = np.arange(m - 1)[:, None]
    k = np.arange(n)[None, :]
    q0, q1 = i * n + k, i * n + (k + 1) % n
    q2, q3 = (i + 1) * n + (k + 1) % n, (i + 1) * n + k
    side = np.concatenate([np.stack([q0, q1, q2], -1).reshape(-1, 3),
                           np.stack([q0, q2, q3], -1).reshape(-1, 3)])
    s_c, e_c = m * n, m * n + 1
    kk = np.arange(n)
    cap0 = np.stack([np.full(n, s_c), (kk + 1) % n, kk], -1)
    cap1 = np.stack([np.full(n, e_c), (m - 1) * n + kk, (m - 1) * n + (kk + 1) % n], -1)
    faces = np.vstack([side, cap0, cap1])
    mesh = m3d.Mesh(vert_properties=np.asarray(verts, np.float32),
                    tri_verts=np.asarray(faces, np.uint32))
    return m3d.Manifold(mesh)


def tube_boxes(path: ArrayLike, radius: float, n_boxes: int = 4
               ) -> list[m3d.Manifold]:
    """Placeholder boxes that together contain `tube(path, radius)`: the path split into
    `n_boxes` runs, each boxed with the exact extents of its end rings."""
    pts = np.asarray(path, float)
    tang = polyline_tangents(pts)
    half = radius * np.sqrt(np.clip(1.0 - tang ** 2, 0.0, 1.0))
    lo, hi = pts - half, pts + half
    cuts = np.unique(np.linspace(0, len(pts) - 1, min(n_boxes, len(pts) - 1) + 1).round().astype(int))
    return [box_between(lo[a:b + 1].min(axis=0), hi[a:b + 1].max(axis=0))
            for a, b in zip(cuts[:-1], cuts[1:], strict=True)]


def rod_between(p0: ArrayLike, p1: ArrayLike, radius: float, detail: bool,
                sections: int = 12) -> m3d.Manifold:
    """A round rod from p0 to p1, or (detail=False) the box of its bounding box."""
    path = np.array([p0, p1], float)
    if detail:
        return tube(path, radius, sections)
    return tube_boxes(path, radius, 1)[0]


def loft(rings: np.ndarray, start: np.ndarray | None = None, end: np.ndarray | None = None
         ) -> m3d.Manifold:
    """A closed solid through `rings` (n, k, 3): ring i joined to ring i+1 by k quads, both ends
    closed by a fan to an apex (`start` / `end`, default the ring's centroid). Rings must be
    consistently ordered and the sweep must not cross itself; the winding is fixed from the
    signed volume, so either ring direction works."""
    rings = np.asarray(rings, float)
    n, k, _ = rings.shape
    a0 = rings[0].mean(axis=0) if start is None else np.asarray(start, float)
    a1 = rings[-1].mean(axis=0) if end is None else np.asarray(end, float)
    verts = np.vstack([rings.reshape(-1, 3), a0, a1])
    i = (np.arange(n - 1) * k)[:, None]
    j = np.arange(k)[None, :]
    jn = (j + 1) % k
    q00, q01 = (i + j).ravel(), (i + jn).ravel()
    q10, q11 = q00 + k, q01 + k
    js, jns = j.ravel(), jn.ravel()
    ia0, ia1, last = n * k, n * k + 1, (n - 1) * k
    tris = np.vstack([np.c_[q00, q01, q11], np.c_[q00, q11, q10],
                      np.c_[np.full(k, ia0), jns, js],
                      np.c_[np.full(k, ia1), last + js, last + jns]])
    tv = verts[tris]
    vol = np.einsum("ij,ij->i", tv[:, 0], np.cross(tv[:, 1], tv[:, 2])).sum()
    if vol < 0:
        tris = tris[:, ::-1]
    mesh = m3d.Mesh(vert_properties=np.ascontiguousarray(verts, np.float32),
                    tri_verts=np.ascontiguousarray(tris, np.uint32))
    return m3d.Manifold(mesh)
