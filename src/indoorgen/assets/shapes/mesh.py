"""Parts to meshes: `union` (manifold3d boolean, watertight, material slot kept per face),
`concat` (no booleans, for placeholders), per-link unions and box UVs.

Part identity survives the union through manifold3d's originalID (each part is made
`as_original()`, and the result's `run_original_id`/`run_index` say which triangles came from
which part), so every output face keeps its part's material slot.
"""
from __future__ import annotations

from collections.abc import Iterable, Sequence

import manifold3d as m3d
import numpy as np
import trimesh

from indoorgen.assets.shapes.primitives import Part

#: edges shorter than this (m) are collapsed after a boolean union, removing slivers
SIMPLIFY_TOL = 1e-5


# --------------------------------------------------------------------------------- to meshes
def _mesh_arrays(man: m3d.Manifold) -> tuple[np.ndarray, np.ndarray]:
    g = man.to_mesh64()
    return (np.asarray(g.vert_properties, float)[:, :3],
            np.asarray(g.tri_verts, np.int64).reshape(-1, 3))


def _slot_table(parts: Sequence[Part], slots: Sequence[str] | None) -> list[str]:
    out: list[str] = [] if slots is None else list(slots)
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
            done.update((int(k), int(n)))
    return faces, face_slots


def solid_union(solids: Iterable[m3d.Manifold]) -> m3d.Manifold:
    """Union of bare manifolds (no slot tracking), e.g. to build a cutter or a compound part."""
    solids = [s for s in solids if not s.is_empty()]
    return m3d.Manifold.batch_boolean(solids, m3d.OpType.Add)


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
    joined = trimesh.util.concatenate(meshes)
    assert isinstance(joined, trimesh.Trimesh)  # concatenating Trimeshes gives a Trimesh
    return joined, np.concatenate(fslots), table, links, np.concatenate(flinks)


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


def manifold_to_trimesh(man: m3d.Manifold) -> trimesh.Trimesh:
    """A manifold as an unprocessed trimesh (vertices and faces as manifold3d made them)."""
    v, f = _mesh_arrays(man)
    return trimesh.Trimesh(v, f, process=False)
