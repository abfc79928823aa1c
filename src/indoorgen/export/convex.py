"""Convex collision pieces of architecture (walls with door holes, L-shaped floors, stairs).

Simulators collide convex shapes (MuJoCo hulls every mesh geom), so a wall with a door opening
must go out as pieces or the doorway would be blocked. Architecture is made of vertical
extrusions, so the solid is cut into horizontal bands at every distinct vertex height: a band
whose cross-section does not change is a prism over a 2D polygon, split into convex parts
(ear-clipping triangulation, then merging neighbours while the union stays convex); a band whose
section changes (a stair flight's sloped underside) goes out as the hull of its two end
sections.
"""
from __future__ import annotations

import itertools
import logging

import numpy as np
import shapely
import shapely.geometry as sg
import trimesh
from shapely.ops import unary_union

log = logging.getLogger(__name__)

#: heights closer than this are one level (m)
LEVEL_TOL = 1e-3
#: thinnest band kept (m)
MIN_BAND = 1e-3


def convex_parts(mesh: trimesh.Trimesh, max_pieces: int = 256) -> list[trimesh.Trimesh]:
    """Convex meshes whose union is (close to) the closed solid `mesh`."""
    if len(mesh.faces) == 0:
        return []
    hull = mesh.convex_hull
    if mesh.is_volume and abs(hull.volume - mesh.volume) <= 1e-3 * max(hull.volume, 1e-9):
        return [hull]
    z = np.sort(np.asarray(mesh.vertices)[:, 2])
    levels = [z[0]]
    for v in z[1:]:
        if v - levels[-1] > LEVEL_TOL:
            levels.append(v)
    out: list[trimesh.Trimesh] = []
    for z0, z1 in itertools.pairwise(levels):
        if z1 - z0 < MIN_BAND:
            continue
        eps = min(1e-4, (z1 - z0) / 4)
        lo, hi = _section(mesh, z0 + eps), _section(mesh, z1 - eps)
        if lo.is_empty and hi.is_empty:
            continue
        if abs(lo.area - hi.area) <= 1e-3 * max(lo.area, hi.area) and \
                lo.symmetric_difference(hi).area <= 1e-3 * max(lo.area, 1e-9):
            for poly in _convex_polygons(lo):
                out.append(_prism(poly, z0, z1))
        else:
            rings = [_ring_points(lo, z0), _ring_points(hi, z1)]
            pts = np.concatenate([p for p in rings if len(p)])
            if len(pts) >= 4:
                try:
                    out.append(trimesh.convex.convex_hull(pts))
                except Exception:  # degenerate (flat) band
                    log.debug("skipping a flat band at z=%.3f", z0)
    if not out or len(out) > max_pieces:
        log.debug("convex_parts: %d pieces; falling back to the hull", len(out))
        return [hull] if not out else out[:max_pieces]
    return out


def _section(mesh: trimesh.Trimesh, z: float) -> sg.base.BaseGeometry:
    """The solid's cross-section at height z (even-odd fill of the cut rings)."""
    segs = trimesh.intersections.mesh_plane(mesh, [0.0, 0.0, 1.0], [0.0, 0.0, z])
    if len(segs) == 0:
        return sg.Polygon()
    segs = np.round(np.asarray(segs)[:, :, :2], 7)
    segs = segs[np.abs(segs[:, 0] - segs[:, 1]).max(axis=1) > 0]
    faces = list(shapely.polygonize(shapely.linestrings(segs)).geoms)
    if not faces:
        return sg.Polygon()
    shells = [sg.Polygon(f.exterior) for f in faces]
    keep = []
    for i, f in enumerate(faces):
        p = f.representative_point()
        depth = sum(1 for j, s in enumerate(shells) if j != i and s.area > f.area and s.contains(p))
        if depth % 2 == 0:
            keep.append(f)
    return unary_union(keep)


def _ring_points(geom, z: float) -> np.ndarray:
    if geom.is_empty:
        return np.zeros((0, 3))
    xy = np.asarray(shapely.get_coordinates(geom))
    return np.column_stack([xy, np.full(len(xy), z)])


def _convex_polygons(geom) -> list[sg.Polygon]:
    """Convex polygons covering `geom` (a polygon or multipolygon, holes allowed)."""
    polys = [g for g in getattr(geom, "geoms", [geom]) if isinstance(g, sg.Polygon) and
             g.area > 1e-8]
    out = []
    for p in polys:
        p = p.buffer(0)
        if p.convex_hull.area - p.area <= 1e-6 * max(p.area, 1e-9) + 1e-9:
            out.append(p)
            continue
        out.extend(_hertel_mehlhorn(p))
    return out


def _hertel_mehlhorn(poly: sg.Polygon) -> list[sg.Polygon]:
    """Hertel-Mehlhorn: ear-clip `poly`, then drop every diagonal whose removal keeps both of
    its end angles convex. At most 4x the minimal number of convex parts."""
    verts, faces = trimesh.creation.triangulate_polygon(poly, engine="earcut")
    verts = np.asarray(verts, float)
    faces = np.asarray(faces, int)
    if len(faces) == 0:
        return []
    a, b, c = verts[faces[:, 0]], verts[faces[:, 1]], verts[faces[:, 2]]
    cw = ((b - a)[:, 0] * (c - a)[:, 1] - (b - a)[:, 1] * (c - a)[:, 0]) < 0
    faces[cw] = faces[cw][:, ::-1]
    pieces: dict[int, list[int]] = {i: list(map(int, f)) for i, f in enumerate(faces)}
    owner: dict[tuple[int, int], int] = {}
    for i, f in pieces.items():
        for k in range(3):
            owner[(f[k], f[(k + 1) % 3])] = i
    diagonals = [e for e in owner if (e[1], e[0]) in owner and e[0] < e[1]]

    def convex_at(prev: int, v: int, nxt: int) -> bool:
        d1, d2 = verts[v] - verts[prev], verts[nxt] - verts[v]
        return d1[0] * d2[1] - d1[1] * d2[0] >= -1e-12

    for ea, eb in diagonals:
        p, q = owner.get((ea, eb)), owner.get((eb, ea))
        if p is None or q is None or p == q:
            continue
        cp, cq = pieces[p], pieces[q]
        i = cp.index(eb)
        rp = cp[i:] + cp[:i]            # b ... a
        j = cq.index(ea)
        rq = cq[j:] + cq[:j]            # a ... b
        if rp[-1] != ea or rq[-1] != eb:
            continue
        merged = rp + rq[1:-1]
        n = len(merged)
        ia = len(rp) - 1
        if not (convex_at(merged[ia - 1], ea, merged[(ia + 1) % n]) and
                convex_at(merged[-1], eb, merged[1 % n])):
            continue
        pieces[p] = merged
        del pieces[q]
        del owner[(ea, eb)], owner[(eb, ea)]
        for k in range(n):
            e = (merged[k], merged[(k + 1) % n])
            owner[e] = p
    return [sg.Polygon(verts[c]) for c in pieces.values()]


def _prism(poly: sg.Polygon, z0: float, z1: float) -> trimesh.Trimesh:
    """The closed prism over convex `poly` from z0 to z1 (outward normals)."""
    xy = np.asarray(sg.polygon.orient(poly, 1.0).exterior.coords)[:-1]
    n = len(xy)
    verts = np.concatenate([np.column_stack([xy, np.full(n, z0)]),
                            np.column_stack([xy, np.full(n, z1)])])
    i = np.arange(1, n - 1)
    bottom = np.column_stack([np.zeros(n - 2, int), i + 1, i])
    top = np.column_stack([np.full(n - 2, n), n + i, n + i + 1])
    k = np.arange(n)
    k1 = (k + 1) % n
    sides = np.concatenate([np.column_stack([k, k1, n + k1]), np.column_stack([k, n + k1, n + k])])
    return trimesh.Trimesh(verts, np.concatenate([bottom, top, sides]), process=False)
