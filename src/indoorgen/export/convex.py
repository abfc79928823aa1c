"""Convex collision pieces of architecture (walls with door holes, L-shaped floors, stairs).

Simulators collide convex shapes (MuJoCo hulls every mesh geom), so a wall with a door opening
must go out as pieces or the doorway would be blocked. Architecture is made of vertical
extrusions, so the solid is cut into horizontal bands at every distinct vertex height: a band
whose cross-section does not change is a prism over a 2D polygon, split into convex parts
(ear-clipping triangulation, then merging neighbours while the union stays convex); a band whose
section changes (a stair flight's sloped underside) goes out as the hull of its two end
sections.

Every piece any simulator exporter writes passes `sound_piece` first: sections are snapped to a
10 um grid (float noise otherwise leaves 0.1 um wide slivers between two ear-clipped parts,
whose hull MuJoCo refuses as "coplanar"), a piece thinner than `MIN_THICKNESS` becomes a box
that thick (a slab) or is dropped (a sliver or needle, thin across two directions), and no
zero-area face reaches a file.
"""
from __future__ import annotations

import itertools
import logging

import numpy as np
import shapely
import shapely.geometry as sg
import trimesh
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree
from shapely.ops import unary_union

from indoorgen.export.meshes import unique_rows

log = logging.getLogger(__name__)

#: heights closer than this are one level (m)
LEVEL_TOL = 1e-3
#: cut points closer than this are one point (m)
WELD = 1e-6
#: thinnest band kept (m)
MIN_BAND = 1e-3
#: grid the cross-sections are snapped to (m): far finer than any architectural feature
GRID = 1e-5
#: thinnest collision piece written (m): thinner slabs are thickened to this, thinner
#: slivers dropped. Simulators hull every piece (MuJoCo with qhull) and refuse a flat one.
MIN_THICKNESS = 1e-3
#: smallest face area a piece may keep (m^2): zero-area faces are dropped
MIN_FACE_AREA = 1e-12


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
        out = [hull] if not out else out[:max_pieces]
    return sound_pieces(out)


def box_bounds(piece: trimesh.Trimesh) -> tuple[np.ndarray, np.ndarray] | None:
    """(centre, size) of `piece` if it is an axis-aligned box (8 corners filling their
    bounds), else None: simulators collide such a piece as a box primitive."""
    v = np.asarray(piece.vertices, float)
    if len(v) != 8:
        return None
    lo, hi = v.min(axis=0), v.max(axis=0)
    size = hi - lo
    # a convex solid inside its bounds that fills them is those bounds
    if np.any(size <= 0) or abs(abs(piece.volume) - np.prod(size)) > 1e-9 + 1e-6 * np.prod(size):
        return None
    return (lo + hi) / 2, size


def vertex_limited(piece: trimesh.Trimesh, limit: int) -> trimesh.Trimesh:
    """`piece` as a convex hull of at most `limit` of its vertices: itself when it has no more,
    else the hull of its extreme points along each axis and, one at a time, the vertex farthest
    from those chosen (farthest-point sampling keeps points all round the base a thing stands
    on). Engines that cap a hull's vertices themselves may cut its base off: Newton's cap turned
    a vase's hull into one starting 7 cm up, and the vase fell that far."""
    v = unique_rows(np.asarray(piece.vertices, float))[0]
    if len(v) <= limit:
        return piece
    chosen = list(dict.fromkeys(np.concatenate([v.argmin(axis=0), v.argmax(axis=0)]).tolist()))
    gap = np.min(np.linalg.norm(v[:, None] - v[chosen][None], axis=2), axis=1)
    while len(chosen) < limit:
        i = int(gap.argmax())
        chosen.append(i)
        gap = np.minimum(gap, np.linalg.norm(v - v[i], axis=1))
    return sound_piece(trimesh.convex.convex_hull(v[chosen])) or piece


def sound_pieces(pieces: list[trimesh.Trimesh]) -> list[trimesh.Trimesh]:
    """`pieces` each made sound by `sound_piece`, slivers left out."""
    return [p for p in map(sound_piece, pieces) if p is not None]


def sound_piece(piece: trimesh.Trimesh) -> trimesh.Trimesh | None:
    """`piece` as a convex collision piece every simulator accepts: itself when it is at least
    `MIN_THICKNESS` thick across every direction and has no zero-area face; the hull of its
    vertices when it only has degenerate faces; a box `MIN_THICKNESS` thick over its outline
    when it is a thin slab; None when it is a sliver (thin across two directions) or empty."""
    v, inverse = unique_rows(np.round(np.asarray(piece.vertices, float), 9))
    if len(v) < 3:
        return None
    faces = inverse.reshape(-1)[np.asarray(piece.faces, int)] if len(piece.faces) else \
        np.zeros((0, 3), int)
    normal, width = _thinnest(v, faces)
    if width < MIN_THICKNESS:
        return _slab_box(v, normal)
    if len(v) == len(piece.vertices) and len(faces) and \
            np.asarray(piece.area_faces).min() > MIN_FACE_AREA:
        return piece
    hull = trimesh.convex.convex_hull(v)
    return hull.submesh([np.flatnonzero(hull.area_faces > MIN_FACE_AREA)], append=True)


def _thinnest(v: np.ndarray, faces: np.ndarray) -> tuple[np.ndarray, float]:
    """The direction across which points `v` (N, 3) are thinnest, and their width across it:
    over the normals of the (convex) faces `faces` (F, 3) indexing `v` (a convex solid is
    thinnest across one of them, or close), or the normal of the points' best-fit plane when
    they have no face with area."""
    centred = v - v.mean(axis=0)
    plane = np.linalg.svd(centred, full_matrices=False)[2][-1]
    flat = float(np.ptp(centred @ plane))
    tri = v[faces] if len(faces) else np.zeros((0, 3, 3))
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    length = np.linalg.norm(n, axis=1)
    n = n[length > 2 * MIN_FACE_AREA] / length[length > 2 * MIN_FACE_AREA, None]
    if flat < MIN_THICKNESS or len(n) == 0:
        return plane, flat
    widths = np.ptp(centred @ n.T, axis=0)
    k = int(np.argmin(widths))
    return n[k], float(widths[k])


def _slab_box(v: np.ndarray, normal: np.ndarray) -> trimesh.Trimesh | None:
    """The box `MIN_THICKNESS` thick around thin points `v` (N, 3), across `normal`, over their
    smallest enclosing rectangle in the plane; None if that rectangle is thin too (a sliver)."""
    axis = int(np.argmin(np.abs(normal)))
    u = np.cross(normal, np.eye(3)[axis])
    u /= np.linalg.norm(u)
    w = np.cross(normal, u)
    xy = np.column_stack([v @ u, v @ w])
    rect = sg.MultiPoint(xy).minimum_rotated_rectangle
    if not isinstance(rect, sg.Polygon):
        return None
    corners = np.asarray(rect.exterior.coords)[:4]
    sides = np.linalg.norm(np.diff(np.vstack([corners, corners[:1]]), axis=0), axis=1)
    if sides.min() < MIN_THICKNESS:
        return None
    mid = float(np.mean([(v @ normal).min(), (v @ normal).max()]))
    half = MIN_THICKNESS / 2
    base = corners[:, :1] * u + corners[:, 1:] * w
    pts = np.concatenate([base + (mid - half) * normal, base + (mid + half) * normal])
    return trimesh.convex.convex_hull(pts)


def _section(mesh: trimesh.Trimesh, z: float) -> sg.base.BaseGeometry:
    """The solid's cross-section at height z (even-odd fill of the cut rings)."""
    segs = trimesh.intersections.mesh_plane(mesh, [0.0, 0.0, 1.0], [0.0, 0.0, z])
    if len(segs) == 0:
        return sg.Polygon()
    segs = _weld(np.asarray(segs)[:, :, :2])
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
    return shapely.set_precision(unary_union(keep), GRID)


def _weld(segs: np.ndarray) -> np.ndarray:
    """Segments (N, 2, 2) with endpoints closer than `WELD` made one point, so that the cut
    rings close: endpoints interpolated on either side of a rounding boundary would otherwise
    leave a ring open and its face out of the section."""
    pts = segs.reshape(-1, 2)
    pairs = cKDTree(pts).query_pairs(WELD, output_type="ndarray")
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])) if len(pairs) else
                       ([], ([], [])), shape=(len(pts), len(pts)))
    _, label = connected_components(graph, directed=False)
    _, first = np.unique(label, return_index=True)   # each point's group's first point
    return pts[first[label]].reshape(segs.shape)


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
    xy = np.asarray(sg.polygon.orient(poly.simplify(GRID), 1.0).exterior.coords)[:-1]
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
