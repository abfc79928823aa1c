"""Shared mesh parts, so that each generator is a short list of named, material-tagged pieces.

Every builder here returns a `manifold3d.Manifold` (cheap to make: microseconds), and a generator
tags each piece with a material slot as a `Part`. Two ways to turn a list of parts into a mesh:

* `union(parts)` - a manifold3d boolean union: one watertight, self-intersection-free mesh for
  the detailed `create` mesh. Part identity survives the union through manifold3d's originalID
  (each part is made `as_original()`, and the result's `run_original_id`/`run_index` say which
  triangles came from which part), so every output face keeps its part's material slot.
* `concat(parts)` - a plain concatenation of the parts' vertex/face arrays (no booleans): cheap,
  for placeholders. Each shell is closed, shells may overlap.

Round things come in two flavours: `circumscribed=False` (the default, for detailed meshes) puts
polygon vertices on the true circle, with one on each of +-X and +-Y when `sections` is a multiple
of 4, so the bounding box is exact; `circumscribed=True` (for placeholders) scales the polygon
out by 1/cos(pi/n) and turns it half a step so that its edge midpoints touch the circle on the
axes: the low-poly solid contains the true circle and still has the exact bounding box.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable, Sequence

import manifold3d as m3d
import numpy as np
import trimesh

Vec3 = Sequence[float]
#: edges shorter than this (m) are collapsed after a boolean union, removing slivers
SIMPLIFY_TOL = 1e-5


@dataclass(frozen=True)
class Part:
    """One solid piece of an asset, the name of its material slot ("wood", "metal"...) and the
    link it belongs to: "base" for the fixed body, another name for a part that moves on a joint
    (a door leaf, a drawer). Parts of one link are unioned into one closed shell."""

    solid: m3d.Manifold
    slot: str
    link: str = "base"


def _round_sections(sections: int) -> int:
    return max(4, int(math.ceil(sections / 4.0)) * 4)


# ----------------------------------------------------------------------------------- primitives
def box(extents: Vec3, center: Vec3 = (0.0, 0.0, 0.0)) -> m3d.Manifold:
    """An axis-aligned box of size `extents` (x, y, z) centred on `center`."""
    return m3d.Manifold.cube(tuple(float(e) for e in extents), True).translate(
        tuple(float(c) for c in center))


def box_between(lo: Vec3, hi: Vec3) -> m3d.Manifold:
    """An axis-aligned box spanning corner `lo` to corner `hi`."""
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    return box(hi - lo, (lo + hi) / 2)


def _octant_dirs(segments: int) -> np.ndarray:
    """Unit directions covering the +++ octant of a sphere (including its three axis poles)."""
    out = []
    for i in range(segments + 1):
        phi = (math.pi / 2) * i / segments  # from +Z down to the equator
        for j in range(segments + 1):
            th = (math.pi / 2) * j / segments
            out.append((math.sin(phi) * math.cos(th), math.sin(phi) * math.sin(th), math.cos(phi)))
    return np.unique(np.round(np.array(out), 12), axis=0)


def bevel_box(extents: Vec3, center: Vec3 = (0.0, 0.0, 0.0), radius: float = 0.01,
              segments: int = 2) -> m3d.Manifold:
    """A box with every edge rounded by `radius` (segments=1 gives a chamfer), as the convex hull
    of eight corner sphere patches. Its bounding box is exactly `extents` (the rounding only
    removes material), so a plain `box` of the same size contains it (used by placeholders)."""
    ext = np.asarray(extents, float)
    r = float(min(radius, 0.49 * ext.min()))
    if r <= 1e-5:
        return box(ext, center)
    dirs = _octant_dirs(max(1, segments))
    pts = []
    inner = ext / 2 - r
    for sx in (-1, 1):
        for sy in (-1, 1):
            for sz in (-1, 1):
                s = np.array([sx, sy, sz], float)
                pts.append(inner * s + r * dirs * s)
    return m3d.Manifold.hull_points(np.vstack(pts)).translate(tuple(float(c) for c in center))


def tapered_box(bottom_xy: tuple[float, float], top_xy: tuple[float, float], z0: float, z1: float,
                center_xy: tuple[float, float] = (0.0, 0.0)) -> m3d.Manifold:
    """A square-section frustum (a tapered leg): bottom size `bottom_xy` at z0, top size `top_xy`
    at z1, centred on `center_xy`."""
    cx, cy = center_xy
    pts = []
    for (sx, sy), z in ((bottom_xy, z0), (top_xy, z1)):
        for a in (-0.5, 0.5):
            for b in (-0.5, 0.5):
                pts.append((cx + a * sx, cy + b * sy, z))
    return m3d.Manifold.hull_points(np.array(pts, float))


def cylinder(radius: float, height: float, center: Vec3 = (0.0, 0.0, 0.0), sections: int = 32,
             radius_top: float | None = None, circumscribed: bool = False) -> m3d.Manifold:
    """A Z-axis cylinder (or cone frustum if `radius_top` is given) whose BOTTOM centre is
    `center`. See the module docstring for `circumscribed`."""
    n = _round_sections(sections)
    rt = radius if radius_top is None else radius_top
    k = 1.0 / math.cos(math.pi / n) if circumscribed else 1.0
    c = m3d.Manifold.cylinder(float(height), float(radius * k), float(rt * k), n)
    if circumscribed:
        c = c.rotate((0.0, 0.0, 180.0 / n))
    return c.translate(tuple(float(v) for v in center))


def rod(p0: Vec3, p1: Vec3, radius: float, sections: int = 12) -> m3d.Manifold:
    """A cylinder of `radius` from point p0 to point p1 (any direction)."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    d = p1 - p0
    length = float(np.linalg.norm(d))
    c = m3d.Manifold.cylinder(length, float(radius), -1.0, _round_sections(sections))
    z = np.array([0.0, 0.0, 1.0])
    dn = d / length
    axis = np.cross(z, dn)
    s, cth = np.linalg.norm(axis), float(np.dot(z, dn))
    if s < 1e-12:
        rot = np.eye(3) if cth > 0 else np.diag([1.0, -1.0, -1.0])
    else:
        k = axis / s
        kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
        rot = np.eye(3) + s * kx + (1 - cth) * kx @ kx
    mat = np.hstack([rot, p0[:, None]])
    return c.transform(mat)


def lathe(profile: Sequence[tuple[float, float]], sections: int = 48,
          circumscribed: bool = False) -> m3d.Manifold:
    """Revolve a closed 2D profile of (radius, z) points (counter-clockwise or not; radius >= 0)
    about the Z axis: cups, plates, vases and lamp shades. A profile that is a ring (not
    touching the axis) gives a tube; one with a notch gives a hollow vessel."""
    pts = np.asarray(profile, float)
    n = _round_sections(sections)
    if circumscribed:
        pts = pts * np.array([1.0 / math.cos(math.pi / n), 1.0])
    cs = m3d.CrossSection([pts], m3d.FillRule.Positive if _area(pts) > 0 else m3d.FillRule.Negative)
    out = m3d.Manifold.revolve(cs, n)
    if circumscribed:
        out = out.rotate((0.0, 0.0, 180.0 / n))
    return out


def _area(pts: np.ndarray) -> float:
    x, y = pts[:, 0], pts[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def torus(major: float, minor: float, center: Vec3 = (0.0, 0.0, 0.0), sections: int = 32,
          tube_sections: int = 12) -> m3d.Manifold:
    """A torus in the XY plane around `center` (rotate it for handles)."""
    cs = m3d.CrossSection.circle(float(minor), _round_sections(tube_sections)).translate(
        (float(major), 0.0))
    return m3d.Manifold.revolve(cs, _round_sections(sections)).translate(
        tuple(float(c) for c in center))


def panel(width: float, height: float, thickness: float, center: Vec3 = (0.0, 0.0, 0.0),
          normal_axis: str = "x") -> m3d.Manifold:
    """A thin board of `thickness` along `normal_axis` ("x", "y" or "z"); width runs along the
    next axis, height along the one after (x: width=Y, height=Z; y: width=X, height=Z;
    z: width=X, height=Y)."""
    ext = {"x": (thickness, width, height), "y": (width, thickness, height),
           "z": (width, height, thickness)}[normal_axis]
    return box(ext, center)


def frame(outer_w: float, outer_h: float, border: float, depth: float,
          center: Vec3 = (0.0, 0.0, 0.0)) -> m3d.Manifold:
    """A rectangular picture-frame ring lying in the YZ plane (depth along X): outer size
    outer_w (Y) x outer_h (Z), members `border` wide."""
    outer = box((depth, outer_w, outer_h), center)
    inner = box((depth * 2 + 0.01, outer_w - 2 * border, outer_h - 2 * border), center)
    return outer - inner


def legs(footprint: tuple[float, float], inset: float, thickness: float, z0: float, z1: float,
         taper: float = 1.0, round_legs: bool = False, circumscribed: bool = False,
         sections: int = 16) -> list[m3d.Manifold]:
    """Four legs under a rectangle `footprint` = (depth X, width Y): each leg's outer faces are
    `inset` from the footprint's edges; legs run from z0 (floor) to z1. `taper` < 1 shrinks the
    foot (tapered leg, outer faces kept vertical... approximately: the taper is about the leg
    axis). `round_legs` makes cylinders of diameter `thickness`."""
    d, w = footprint
    cx = d / 2 - inset - thickness / 2
    cy = w / 2 - inset - thickness / 2
    out = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            c = (sx * cx, sy * cy)
            if round_legs:
                r = thickness / 2
                out.append(cylinder(r, z1 - z0, (c[0], c[1], z0), sections,
                                    radius_top=None, circumscribed=circumscribed)
                           if taper >= 0.999 else
                           cylinder(r * taper, z1 - z0, (c[0], c[1], z0), sections, radius_top=r,
                                    circumscribed=circumscribed))
            elif taper >= 0.999:
                out.append(box((thickness, thickness, z1 - z0), (c[0], c[1], (z0 + z1) / 2)))
            else:
                tb = thickness * taper
                out.append(tapered_box((tb, tb), (thickness, thickness), z0, z1, c))
    return out


# --------------------------------------------------------------------------------- to meshes
def _mesh_arrays(man: m3d.Manifold) -> tuple[np.ndarray, np.ndarray]:
    g = man.to_mesh64()
    return (np.asarray(g.vert_properties, float)[:, :3],
            np.asarray(g.tri_verts, np.int64).reshape(-1, 3))


def _slot_table(parts: Sequence[Part], slots: Sequence[str] | None) -> list[str]:
    if slots is not None:
        out = list(slots)
        for p in parts:
            if p.slot not in out:
                out.append(p.slot)
        return out
    out: list[str] = []
    for p in parts:
        if p.slot not in out:
            out.append(p.slot)
    return out


def concat(parts: Iterable[Part], slots: Sequence[str] | None = None
           ) -> tuple[trimesh.Trimesh, np.ndarray, list[str]]:
    """Concatenate parts without booleans (cheap; for placeholders). Returns the mesh, the
    per-face slot indices and the slot names."""
    parts = [p for p in parts if not p.solid.is_empty()]
    table = _slot_table(parts, slots)
    vs, fs, ss = [], [], []
    off = 0
    for p in parts:
        v, f = _mesh_arrays(p.solid)
        vs.append(v)
        fs.append(f + off)
        ss.append(np.full(len(f), table.index(p.slot), np.int64))
        off += len(v)
    mesh = trimesh.Trimesh(np.vstack(vs), np.vstack(fs), process=False)
    return mesh, np.concatenate(ss), table


def union(parts: Iterable[Part], slots: Sequence[str] | None = None,
          subtract: Iterable[m3d.Manifold] = ()) -> tuple[trimesh.Trimesh, np.ndarray, list[str]]:
    """Boolean-union the parts (then subtract `subtract`) into one watertight mesh, keeping
    each face's material slot via manifold3d's originalID. Faces created by `subtract` cuts take
    the slot of the part they were cut into (the cut solids are marked as that part). Returns
    the mesh, the per-face slot indices and the slot names."""
    parts = [p for p in parts if not p.solid.is_empty()]
    table = _slot_table(parts, slots)
    id_slot: dict[int, int] = {}
    tagged = []
    for p in parts:
        s = p.solid.as_original()
        id_slot[s.original_id()] = table.index(p.slot)
        tagged.append(s)
    solid = m3d.Manifold.batch_boolean(tagged, m3d.OpType.Add)
    cuts = [c for c in subtract if not c.is_empty()]
    if cuts:
        solid = m3d.Manifold.batch_boolean([solid] + cuts, m3d.OpType.Subtract)
    # booleans can leave zero-area slivers (collinear triangles where faces were cut along a
    # shared edge); simplify collapses edges shorter than the tolerance, keeping it manifold
    solid = solid.simplify(SIMPLIFY_TOL)
    g = solid.to_mesh64()
    verts = np.asarray(g.vert_properties, float)[:, :3]
    faces = np.asarray(g.tri_verts, np.int64).reshape(-1, 3)
    face_slots = np.zeros(len(faces), np.int64)
    run_index = np.asarray(g.run_index, np.int64) // 3
    run_ids = np.asarray(g.run_original_id, np.int64)
    default = table.index(parts[0].slot) if parts else 0
    for i, oid in enumerate(run_ids):
        face_slots[run_index[i]:run_index[i + 1]] = id_slot.get(int(oid), default)
    verts, faces, keep = collapse_short_edges(verts, faces, SIMPLIFY_TOL)
    face_slots = face_slots[keep]
    faces, face_slots = flip_caps(verts, faces, face_slots)
    mesh = trimesh.Trimesh(verts, faces, process=False)
    return mesh, face_slots, table


def collapse_short_edges(verts: np.ndarray, faces: np.ndarray, tol: float = 1e-6
                         ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Merge the two ends of every edge shorter than `tol` and drop the triangles that become
    degenerate (an edge collapse: each removed needle's two other edges pair up, so a closed
    mesh stays closed). Returns (vertices, faces, mask of the kept input faces). Booleans leave
    a few such needles, which `Manifold.simplify` does not always remove."""
    e = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    short = np.linalg.norm(verts[e[:, 0]] - verts[e[:, 1]], axis=1) < tol
    if not short.any():
        return verts, faces, np.ones(len(faces), bool)
    parent = np.arange(len(verts))

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for a, b in e[short]:
        ra, rb = find(int(a)), find(int(b))
        if ra != rb:
            parent[max(ra, rb)] = min(ra, rb)
    root = np.array([find(i) for i in range(len(verts))])
    f = root[faces]
    keep = (f[:, 0] != f[:, 1]) & (f[:, 1] != f[:, 2]) & (f[:, 2] != f[:, 0])
    f = f[keep]
    used, inv = np.unique(f, return_inverse=True)
    return verts[used], inv.reshape(-1, 3), keep


def flip_caps(verts: np.ndarray, faces: np.ndarray, face_slots: np.ndarray,
              min_area: float = 1e-11) -> tuple[np.ndarray, np.ndarray]:
    """Remove zero-area "cap" triangles (a vertex lying on the opposite edge), which booleans of
    boards meeting at T-junctions leave behind. A cap (a, b, c) with c on edge ab and its
    neighbour (b, a, d) across that edge become (c, a, d) and (b, c, d): the neighbour split at c.
    The mesh stays closed and consistently wound; slots follow the neighbour."""
    faces = faces.copy()
    for _ in range(8):
        tri = verts[faces]
        area = 0.5 * np.linalg.norm(np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0]), axis=1)
        caps = np.nonzero(area < min_area)[0]
        if not len(caps):
            break
        owner = {(int(f[i]), int(f[(i + 1) % 3])): k for k, f in enumerate(faces) for i in range(3)}
        done: set[int] = set()
        for k in caps:
            if k in done:
                continue
            f = faces[k]
            # the longest edge is the one the third vertex lies on
            lengths = [np.linalg.norm(verts[f[(i + 1) % 3]] - verts[f[i]]) for i in range(3)]
            i = int(np.argmax(lengths))
            a, b, c = int(f[i]), int(f[(i + 1) % 3]), int(f[(i + 2) % 3])
            n = owner.get((b, a))
            if n is None or n in done:
                continue
            g = faces[n]
            d = next((int(v) for v in g if v not in (a, b)), None)
            if d is None or d == c:  # a degenerate neighbour: leave this cap alone
                continue
            faces[k] = (c, a, d)
            faces[n] = (b, c, d)
            face_slots[k] = face_slots[n]
            done.update((k, n))
    return faces, face_slots


def solid_union(solids: Iterable[m3d.Manifold]) -> m3d.Manifold:
    """Union of bare manifolds (no slot tracking), e.g. to build a cutter or a compound part."""
    solids = [s for s in solids if not s.is_empty()]
    return m3d.Manifold.batch_boolean(solids, m3d.OpType.Add)


def circle_polygon(radius: float, sections: int = 32, center: tuple[float, float] = (0.0, 0.0)):
    """A shapely polygon inscribed in a circle (vertices on it, one on +X), so that it lies inside
    any mesh disc of the same radius built with a multiple of `sections` segments."""
    import shapely.geometry as sg

    n = _round_sections(sections)
    a = np.arange(n) * 2 * math.pi / n
    return sg.Polygon(np.c_[center[0] + radius * np.cos(a), center[1] + radius * np.sin(a)])


# ------------------------------------------------------------------------ links, UVs, collision
def link_names(parts: Iterable[Part]) -> list[str]:
    """The links the parts use, "base" first, the rest in order of appearance."""
    out = ["base"]
    for p in parts:
        if p.link not in out:
            out.append(p.link)
    return out


def union_links(parts: Sequence[Part], slots: Sequence[str] | None = None,
                subtract: Iterable[m3d.Manifold] = ()
                ) -> tuple[trimesh.Trimesh, np.ndarray, list[str], list[str], np.ndarray]:
    """`union` per link, concatenated: one closed shell per link. Returns the mesh, per-face slot
    indices, slot names, link names and per-face link indices. `subtract` cuts the base only."""
    parts = [p for p in parts if not p.solid.is_empty()]
    table = _slot_table(parts, slots)
    links = link_names(parts)
    meshes, fslots, flinks = [], [], []
    for li, link in enumerate(links):
        mine = [p for p in parts if p.link == link]
        if not mine:
            continue
        mesh, fs, _ = union(mine, table, subtract if link == "base" else ())
        meshes.append(mesh)
        fslots.append(fs)
        flinks.append(np.full(len(mesh.faces), li, np.int64))
    if len(meshes) == 1:
        return meshes[0], fslots[0], table, links, flinks[0]
    mesh = trimesh.util.concatenate(meshes)
    return mesh, np.concatenate(fslots), table, links, np.concatenate(flinks)


def box_uv(vertices: np.ndarray, faces: np.ndarray, scale: float = 1.0) -> np.ndarray:
    """Texture coordinates per face corner (F, 3, 2) by box projection: each face is projected
    along the axis its normal is closest to, in metres times `scale`. Tileable materials then
    map at true scale on every face with no stretching beyond 45 degree slopes."""
    tri = np.asarray(vertices, float)[np.asarray(faces)]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    axis = np.argmax(np.abs(n), axis=1)
    # the two coordinates kept for each projection axis (x -> (y, z), y -> (x, z), z -> (x, y))
    keep = np.array([[1, 2], [0, 2], [0, 1]])[axis]
    rows = np.arange(len(tri))[:, None, None]
    uv = tri[rows, np.arange(3)[None, :, None], keep[:, None, :]]
    return uv * scale


def convex_pieces(parts: Sequence[Part], max_pieces: int = 48, decompose: bool = False,
                  keep_free: Sequence[Sequence[float]] = ()) -> list[tuple[str, m3d.Manifold]]:
    """Convex collision pieces (link, hull) for simulators: the convex hull of each part, since
    generators build objects from simple parts. With `decompose`, a part that is far from
    convex (a hollow carcass, a bowl, an L-shaped board) is first cut into nearly convex
    pieces, so that what goes inside it (a drawer, a lid, an apple) is not inside its collision
    shape. With `decompose`, the body's hulls also keep out of the `keep_free` boxes (the space
    over each inner shelf or cell, where the solver puts things). Beyond `max_pieces` per link
    (foliage, many slats), neighbouring pieces are grouped by their centres and each group
    hulled."""
    out: list[tuple[str, m3d.Manifold]] = []
    for link in link_names(parts):
        mine = [p.solid for p in parts if p.link == link and not p.solid.is_empty()]
        limit = max_pieces
        if decompose:
            carved = _carve_link(link, mine, parts, keep_free)
            if len(carved) != len(mine):
                limit = 2 * max_pieces  # grouping would hull the cuts back together
            mine = [piece for solid in carved for piece in convex_split(solid)]
        if len(mine) > limit:
            centres = np.array([(np.asarray(s.bounding_box()[:3]) + s.bounding_box()[3:]) / 2
                                for s in mine])
            groups = _group_by_position(centres, limit)
            mine = [solid_union([mine[i] for i in g]) for g in groups]
        out.extend((link, s.hull()) for s in mine)
    return out


def carve_around(solids: list[m3d.Manifold], boxes: Sequence[Sequence[float]],
                 shapes: Sequence[m3d.Manifold] | None = None) -> list[m3d.Manifold]:
    """Cut each solid whose convex hull would swallow part of one of `boxes` (the bounding boxes
    of the object's moving parts at rest: a drawer in its carcass, a bin inside a fridge) along
    that box's six face planes. The pieces outside the box then have hulls that keep out of it,
    so a simulator lets the drawer slide; what lies inside the box is usually nothing (the
    cavity) or thin. With `shapes` (one solid per box), a hull must swallow part of the shape
    itself, not merely of its box, to be cut."""
    for i, box in enumerate(boxes):
        lo, hi = np.asarray(box[:3], float), np.asarray(box[3:], float)
        if np.any(hi - lo <= 2 * SWALLOW_MARGIN):
            continue
        inner = box_between(lo + SWALLOW_MARGIN, hi - SWALLOW_MARGIN)
        if shapes is not None:
            inner = inner ^ shapes[i]
        out = []
        for solid in solids:
            if (solid.hull() ^ inner).volume() <= SWALLOW_VOLUME:
                out.append(solid)
                continue
            rest = solid  # what is left on the box's side of every plane cut so far
            for axis in range(3):
                for cut, keep_low in ((lo[axis], True), (hi[axis], False)):
                    beyond, rest = _split(rest, axis, cut, keep_low)
                    if beyond is not None and beyond.volume() > 1e-9:
                        out.append(beyond)  # wholly beyond one face of the box: safe whole
            # inside the box's slab: separate bits go out one by one, and a bit that still
            # wraps round the moving part (a pot's rim round its lid's skirt) in short pieces
            for bit in rest.decompose():
                out.extend(p for p in _unwrap(bit, inner) if p.volume() > 1e-9)
        solids = out
    return solids


def _unwrap(solid: m3d.Manifold, keep_out: m3d.Manifold, depth: int = 4
            ) -> list[m3d.Manifold]:
    """`solid` halved across its longest side until no piece's hull takes more than
    SWALLOW_VOLUME of `keep_out` or the piece is nearly convex (at most 2**depth pieces): a
    ring cut into short arcs."""
    hull = solid.hull()
    if depth == 0 or solid.volume() >= CONVEX_FILL * hull.volume() or \
            (hull ^ keep_out).volume() <= SWALLOW_VOLUME:
        return [solid]  # (a convex bit inside the box, a post, stays whole: cutting won't help)
    bb = np.asarray(solid.bounding_box(), float)
    axis = int(np.argmax(bb[3:] - bb[:3]))
    low, high = _split(solid, axis, (bb[axis] + bb[axis + 3]) / 2, True)
    if low is None:
        return [solid]
    return [p for half in (low, high) for p in _unwrap(half, keep_out, depth - 1)]


def _split(solid: m3d.Manifold, axis: int, cut: float, beyond_low: bool
           ) -> tuple[m3d.Manifold | None, m3d.Manifold]:
    """(the part of `solid` beyond the plane x_axis = cut, the rest): beyond is the low side
    when `beyond_low`, else the high side; None when the plane misses the solid."""
    bb = np.asarray(solid.bounding_box(), float)
    if not bb[axis] < cut < bb[axis + 3]:
        return None, solid
    on_axis = np.arange(3) == axis
    lo, hi = bb[:3] - 1, bb[3:] + 1
    low = solid ^ box_between(lo, np.where(on_axis, cut, hi))
    high = solid ^ box_between(np.where(on_axis, cut, lo), hi)
    return (low, high) if beyond_low else (high, low)


def free_space_above(solids: Sequence[m3d.Manifold], rect: Sequence[float], z: float,
                     top: float) -> list[float] | None:
    """The box (x0, y0, z0, x1, y1, z1) of open space over the horizontal rectangle
    rect = (x0, y0, x1, y1) at height z, up to the first solid above the rectangle's middle
    (below `top`): a shelf or cell under a board. None where nothing covers it (a basin, a
    plate: open above, where a hull over the rim is what simulators expect) or less than 1 cm
    is free."""
    x0, y0, x1, y1 = (float(v) for v in rect)
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    column = box_between((cx - 1e-3, cy - 1e-3, z + 1e-3), (cx + 1e-3, cy + 1e-3, top + 1.0))
    ceiling = top
    for solid in solids:
        hit = solid ^ column
        if not hit.is_empty():
            ceiling = min(ceiling, float(hit.bounding_box()[2]))
    if ceiling >= top - 1e-3 or ceiling - z < 0.01 or x1 - x0 < 0.01 or y1 - y0 < 0.01:
        return None
    return [x0 + 2e-3, y0 + 2e-3, z + 1e-3, x1 - 2e-3, y1 - 2e-3, ceiling - 1e-3]


def _carve_worthy(solid: m3d.Manifold) -> bool:
    """Whether a moving part is big enough to carve collision pieces around (MIN_CARVE across):
    a jar's cap or a knob is left to the simulator's contact margins."""
    if solid.is_empty():
        return False
    bb = np.asarray(solid.bounding_box(), float)
    return float(np.max(bb[3:] - bb[:3])) >= MIN_CARVE


#: moving parts smaller than this (m) get no carving (see `_carve_worthy`)
MIN_CARVE = 0.1
#: a moving part counts as swallowed by a hull that takes more than this of it (m^3, 1 cm^3),
#: once its box is shrunk by SWALLOW_MARGIN (so that parts merely touching do not count)
SWALLOW_VOLUME = 1e-6
SWALLOW_MARGIN = 1e-3

def _carve_link(link: str, solids: list[m3d.Manifold], parts: Sequence[Part],
                keep_free: Sequence[Sequence[float]]) -> list[m3d.Manifold]:
    """One link's solids cut so that their hulls keep clear of the other side: the body's out
    of the moving parts' boxes and the `keep_free` boxes, a moving part's (when big enough)
    out of the body (a lid's rim inside its pot)."""
    if link == "base":
        moving = [p.solid for p in parts if p.link != "base" and _carve_worthy(p.solid)]
        return carve_around(solids, [m.bounding_box() for m in moving] + list(keep_free))
    body = [p.solid for p in parts if p.link == "base" and not p.solid.is_empty()]
    big = [s for s in solids if _carve_worthy(s)]
    return carve_around(big, [b.bounding_box() for b in body], body) + \
        [s for s in solids if not _carve_worthy(s)]


#: a piece whose volume fills at least this share of its convex hull counts as convex
CONVEX_FILL = 0.85
#: parts whose hull is smaller than this (m^3, 10 litres) keep their hull: a leaf, a pot, a vase
MIN_SPLIT_VOLUME = 0.01


def convex_split(solid: m3d.Manifold, depth: int = 3) -> list[m3d.Manifold]:
    """Cut a solid into pieces that each nearly fill their convex hull: recursively split it by
    the axis-aligned plane through the middle of its bounding box (along x, y or z) that leaves
    the least empty hull volume, up to `depth` times (at most 2**depth pieces). Small solids
    (hull under MIN_SPLIT_VOLUME) stay whole."""
    vol = solid.volume()
    if vol <= 0:
        return []
    hull_vol = solid.hull().volume()
    if depth == 0 or vol >= CONVEX_FILL * hull_vol or hull_vol < MIN_SPLIT_VOLUME:
        return [solid]
    lo = np.asarray(solid.bounding_box()[:3], float)
    hi = np.asarray(solid.bounding_box()[3:], float)
    best, best_waste = None, hull_vol - vol
    for axis in range(3):
        if hi[axis] - lo[axis] < 1e-3:
            continue
        cut = (lo[axis] + hi[axis]) / 2
        on_axis = np.arange(3) == axis
        halves = [solid ^ box_between(lo - 1, np.where(on_axis, cut, hi + 1)),
                  solid ^ box_between(np.where(on_axis, cut, lo - 1), hi + 1)]
        if min(h.volume() for h in halves) <= 1e-12:
            continue
        waste = sum(h.hull().volume() - h.volume() for h in halves)
        if waste < best_waste:
            best, best_waste = halves, waste
    if best is None:
        return [solid]
    return [piece for h in best for piece in convex_split(h, depth - 1)]


def _group_by_position(points: np.ndarray, k: int) -> list[list[int]]:
    """Split points into at most k spatially compact groups by recursive median cuts along the
    longest axis (deterministic, no RNG)."""
    groups = [list(range(len(points)))]
    while len(groups) < k:
        i = max(range(len(groups)), key=lambda g: len(groups[g]))
        g = groups[i]
        if len(g) < 2:
            break
        pts = points[g]
        ax = int(np.argmax(pts.max(axis=0) - pts.min(axis=0)))
        order = [g[j] for j in np.argsort(pts[:, ax], kind="stable")]
        half = len(order) // 2
        groups[i:i + 1] = [order[:half], order[half:]]
    return groups


def manifold_to_trimesh(man: m3d.Manifold) -> trimesh.Trimesh:
    v, f = _mesh_arrays(man)
    return trimesh.Trimesh(v, f, process=False)


# --------------------------------------------------------------------------- moving parts
#: clearance between a moving part and the body it moves against (m)
MOVING_GAP = 0.002


def bar_handle(center: Vec3, length: float, vertical: bool, standoff: float = 0.03,
               thickness: float = 0.012) -> m3d.Manifold:
    """A bar handle on a +X-facing front: a bar `length` long (vertical or horizontal) held
    `standoff` proud of the front by two posts; `center` is on the front face. The posts sink
    1 mm into the front so that the handle unions with it into one shell."""
    cx, cy, cz = (float(c) for c in center)
    t, half = thickness, length / 2
    xb0, xb1 = cx + standoff - t, cx + standoff
    if vertical:
        bar = box_between((xb0, cy - t / 2, cz - half), (xb1, cy + t / 2, cz + half))
        ends = [(cy, cz - 0.8 * half), (cy, cz + 0.8 * half)]
    else:
        bar = box_between((xb0, cy - half, cz - t / 2), (xb1, cy + half, cz + t / 2))
        ends = [(cy - 0.8 * half, cz), (cy + 0.8 * half, cz)]
    posts = [box_between((cx - 0.001, y - t / 2, z - t / 2), (xb0 + 0.001, y + t / 2, z + t / 2))
             for y, z in ends]
    return solid_union([bar] + posts)


def knob(center: Vec3, radius: float = 0.015, standoff: float = 0.025) -> m3d.Manifold:
    """A round knob on a +X-facing front at `center`."""
    cx, cy, cz = (float(c) for c in center)
    stem = rod((cx - 0.001, cy, cz), (cx + standoff * 0.6, cy, cz), radius * 0.45, 12)
    head = rod((cx + standoff * 0.5, cy, cz), (cx + standoff, cy, cz), radius, 16)
    return solid_union([stem, head])


def hinged_door(front_x: float, y0: float, y1: float, z0: float, z1: float, thickness: float,
                hinge: str, link: str, handle: str = "bar", slot: str = "front",
                handle_slot: str = "metal", gap: float = MOVING_GAP
                ) -> tuple[list[Part], "DoorJoint"]:
    """A door leaf covering the opening y0..y1, z0..z1 of a +X-facing front whose face is at
    `front_x`, hinged on its `hinge` side ("left" = low y, "right" = high y, "bottom" = a
    drop-down flap like an oven door, "top" = a lift-up flap). The leaf stands `gap` in front of
    the face, so it swings outward without touching the body. Returns its parts (on `link`) and
    the joint description (axis through the leaf's outer hinge edge, 0 = shut)."""
    x0, x1 = front_x + gap, front_x + gap + thickness
    leaf = box_between((x0, y0, z0), (x1, y1, z1))
    parts = [Part(leaf, slot, link)]
    w, h = y1 - y0, z1 - z0
    if hinge in ("left", "right"):
        yh = y1 - min(0.05, w * 0.2) if hinge == "left" else y0 + min(0.05, w * 0.2)
        zc = z0 + h * (0.5 if h < 0.5 else 0.75 if z0 < 0.5 else 0.2)
        zc = min(max(zc, z0 + 0.06), z1 - 0.06)
        hl = min(0.14, h * 0.4)
        grip = (x1, yh, zc)
        vertical = True
    else:
        zh = z1 - min(0.05, h * 0.2) if hinge == "bottom" else z0 + min(0.05, h * 0.2)
        grip = (x1, (y0 + y1) / 2, zh)
        hl = min(0.3, w * 0.6)
        vertical = False
    if handle == "bar":
        parts.append(Part(bar_handle(grip, hl, vertical), handle_slot, link))
    elif handle == "knob":
        parts.append(Part(knob(grip), handle_slot, link))
    return parts, hinge_motion(hinge, x1, y0, y1, z0, z1, link)


def drawer(front_x: float, y0: float, y1: float, z0: float, z1: float, depth: float,
           thickness: float, link: str, board: float = 0.012, handle: str = "bar",
           slot: str = "front", box_slot: str = "wood", handle_slot: str = "metal",
           gap: float = MOVING_GAP) -> tuple[list[Part], "DoorJoint"]:
    """A drawer for the opening y0..y1, z0..z1 of a +X-facing front at `front_x`: a front panel
    `gap` proud of the face plus an open-topped box `depth` deep that slides inside the opening
    with `gap` clearance all round. Returns its parts (on `link`) and a prismatic joint along +X
    (0 = shut; open it at most `depth` minus a little so it stays in its runners)."""
    fx0, fx1 = front_x + gap, front_x + gap + thickness
    parts = [Part(box_between((fx0, y0, z0), (fx1, y1, z1)), slot, link)]
    # the box inside the opening, clear of it by 2*gap on each side, below and above
    by0, by1, bz0 = y0 + 2 * gap, y1 - 2 * gap, z0 + 2 * gap
    bz1 = max(bz0 + 0.03, z1 - 0.02)
    bx0, bx1 = front_x - depth, fx0 + 0.001
    b = board
    shell = [box_between((bx0, by0, bz0), (bx1, by1, bz0 + b)),                # bottom
             box_between((bx0, by0, bz0), (bx0 + b, by1, bz1)),                # back
             box_between((bx0, by0, bz0), (bx1, by0 + b, bz1)),                # sides
             box_between((bx0, by1 - b, bz0), (bx1, by1, bz1))]
    parts.append(Part(solid_union(shell), box_slot, link))
    grip = (fx1, (y0 + y1) / 2, (z0 + z1) / 2)
    if handle == "bar":
        parts.append(Part(bar_handle(grip, min(0.16, (y1 - y0) * 0.5), False), handle_slot, link))
    elif handle == "knob":
        parts.append(Part(knob(grip), handle_slot, link))
    return parts, DoorJoint("prismatic", np.array([1.0, 0.0, 0.0]), np.array(grip), link)


@dataclass(frozen=True)
class DoorJoint:
    """How a moving part built here moves (kind, axis, origin, link); the generator adds the
    joint's name and range when it turns this into an `assets.base.Joint`."""

    kind: str
    axis: np.ndarray
    origin: np.ndarray
    link: str


def hinge_motion(hinge: str, x1: float, y0: float, y1: float, z0: float, z1: float,
                 link: str) -> DoorJoint:
    """The revolute motion of a leaf whose outer face is at `x1`, covering y0..y1, z0..z1,
    hinged on its `hinge` side ("left" = low y, "right" = high y, "bottom" drop-down, "top"
    lift-up): the axis runs along the leaf's outer hinge edge, so it swings away from the body."""
    if hinge == "left":
        axis, origin = (0.0, 0.0, -1.0), (x1, y0, z0)
    elif hinge == "right":
        axis, origin = (0.0, 0.0, 1.0), (x1, y1, z0)
    elif hinge == "bottom":
        axis, origin = (0.0, 1.0, 0.0), (x1, y0, z0)
    elif hinge == "top":
        axis, origin = (0.0, -1.0, 0.0), (x1, y0, z1)
    else:
        raise ValueError(f"hinge must be left, right, bottom or top, got {hinge!r}")
    return DoorJoint("revolute", np.array(axis), np.array(origin), link)


def slide_motion(link: str, origin: Sequence[float]) -> DoorJoint:
    """A prismatic motion along +X (a drawer pulled out)."""
    return DoorJoint("prismatic", np.array([1.0, 0.0, 0.0]), np.asarray(origin, float), link)


# ----------------------------------------------------------------------------------- cabinets
def carcass(depth: float, width: float, z0: float, z1: float, board: float,
            back: float = 0.006, shelves: Sequence[float] = (), dividers: Sequence[float] = (),
            slot: str = "wood", back_slot: str | None = None, top: bool = True) -> list[Part]:
    """An open-fronted cabinet box spanning x in [-depth/2, depth/2] (front at +depth/2), y in
    [-width/2, width/2], z in [z0, z1]: two sides, a bottom, a top (unless `top` is False,
    e.g. under a countertop), a back panel `back` thick, fixed shelves whose upper faces are at
    the heights in `shelves`, and full-height vertical dividers centred on the y values in
    `dividers`. Boards overlap by 1 mm so the union is one shell."""
    d2, w2, t, o = depth / 2, width / 2, board, 0.001
    bs = back_slot or slot
    solids = [
        Part(box_between((-d2, -w2, z0), (d2, -w2 + t, z1)), slot),            # sides
        Part(box_between((-d2, w2 - t, z0), (d2, w2, z1)), slot),
        Part(box_between((-d2, -w2 + t - o, z0), (d2, w2 - t + o, z0 + t)), slot),  # bottom
        Part(box_between((-d2, -w2 + t - o, z0 + t - o), (-d2 + back, w2 - t + o, z1 - (t if top else 0) + o)), bs),
    ]
    if top:
        solids.append(Part(box_between((-d2, -w2 + t - o, z1 - t), (d2, w2 - t + o, z1)), slot))
    for zs in shelves:
        solids.append(Part(box_between((-d2 + back - o, -w2 + t - o, zs - t),
                                       (d2 - 0.01, w2 - t + o, zs)), slot))
    for yd in dividers:
        solids.append(Part(box_between((-d2 + back - o, yd - t / 2, z0 + t - o),
                                       (d2, yd + t / 2, z1 - (t if top else 0) + o)), slot))
    return solids


@dataclass(frozen=True)
class Front:
    """One cell of a cabinet front: the opening y0..y1, z0..z1 and what closes it: "left" or
    "right" (a door hinged on that side), "flap_down" / "flap_up" (hinged at the bottom / top),
    "drawer", or "open" (nothing)."""

    y0: float
    y1: float
    z0: float
    z1: float
    kind: str


def cabinet_fronts(front_x: float, cells: Sequence[Front], depth: float, *, thickness: float = 0.018,
                   handle: str = "bar", prefix: str = "", slot: str = "front",
                   handle_slot: str = "metal", reveal: float = 0.002
                   ) -> list[tuple[list[Part], DoorJoint]]:
    """Doors, flaps and drawers for the `cells` of a +X front at `front_x`, each on its own link
    (`door_0`, `drawer_1`...); each cell is shrunk by `reveal` on every edge so neighbours never
    touch. Drawer boxes reach `depth` behind the front. Returns (parts, motion) per moving cell."""
    out = []
    for i, c in enumerate(cells):
        y0, y1, z0, z1 = c.y0 + reveal, c.y1 - reveal, c.z0 + reveal, c.z1 - reveal
        if c.kind == "open":
            continue
        if c.kind == "drawer":
            out.append(drawer(front_x, y0, y1, z0, z1, depth, thickness, f"{prefix}drawer_{i}",
                              handle=handle, slot=slot, handle_slot=handle_slot))
        else:
            hinge = {"left": "left", "right": "right", "flap_down": "bottom", "flap_up": "top"}.get(c.kind)
            if hinge is None:
                raise ValueError(f"unknown front kind {c.kind!r}")
            out.append(hinged_door(front_x, y0, y1, z0, z1, thickness, hinge, f"{prefix}door_{i}",
                                   handle=handle, slot=slot, handle_slot=handle_slot))
    return out


#: how far cabinet fronts and their handles stand proud of the carcass (gap + leaf + bar handle)
FRONT_PROUD = MOVING_GAP + 0.018 + 0.03
