"""Mesh pieces every exporter needs: per-corner normals and UVs, sub-meshes by link and by
material slot, and welding face-varying data into indexed vertices (OBJ, glTF, MuJoCo)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from indoorgen.assets.protocol import Asset
from indoorgen.assets.shapes.mesh import box_uv

#: corners whose vertex normal deviates more than this from the face normal get the face normal
CREASE_DEG = 35.0


@dataclass
class Piece:
    """Indexed triangles with per-vertex UVs (metres) and normals, ready for a file format."""

    vertices: np.ndarray  # (V, 3) float
    uv: np.ndarray        # (V, 2) float, metres
    normals: np.ndarray   # (V, 3) float, unit
    faces: np.ndarray     # (F, 3) int

    def transformed(self, m: np.ndarray) -> Piece:
        """The piece under the 4x4 rigid transform `m`."""
        return Piece(self.vertices @ m[:3, :3].T + m[:3, 3], self.uv, self.normals @ m[:3, :3].T,
                     self.faces)


def corner_normals(mesh: trimesh.Trimesh, crease_deg: float = CREASE_DEG) -> np.ndarray:
    """Normals per face corner (F, 3, 3): the smooth vertex normal where the surface is smooth,
    the face normal across creases (box edges stay sharp, lathed shapes look round)."""
    if len(mesh.faces) == 0:
        return np.zeros((0, 3, 3))
    fn = np.asarray(mesh.face_normals, float)
    vn = np.asarray(mesh.vertex_normals, float)[mesh.faces]
    cos = np.einsum("fij,fj->fi", vn, fn)
    sharp = cos < np.cos(np.radians(crease_deg))
    out = np.where(sharp[..., None], fn[:, None, :], vn)
    n = np.linalg.norm(out, axis=-1, keepdims=True)
    return out / np.where(n < 1e-12, 1.0, n)


def corner_uv(asset: Asset) -> np.ndarray:
    """The asset's per-corner UVs in metres (box projection when it has none)."""
    if asset.corner_uv is not None and len(asset.corner_uv) == len(asset.mesh.faces):
        return np.asarray(asset.corner_uv, float)
    return box_uv(asset.mesh.vertices, asset.mesh.faces)


def mesh_uv(mesh: trimesh.Trimesh) -> np.ndarray:
    """Box-projected per-corner UVs (metres) of a plain mesh (architecture)."""
    return box_uv(mesh.vertices, mesh.faces)


def face_slot_names(asset: Asset) -> np.ndarray:
    """The slot index of every face (0 when the asset has a single slot)."""
    if asset.face_slots is None:
        return np.zeros(len(asset.mesh.faces), int)
    return np.asarray(asset.face_slots, int)


def unique_rows(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """What `np.unique(rows, axis=0, return_inverse=True)` gives (the distinct rows in
    lexicographic order, and each row's index among them), about four times faster: rows are
    told apart as byte strings, and only the few distinct ones sorted."""
    rows = np.asarray(rows)
    if len(rows) == 0:
        return rows.copy(), np.zeros(0, np.int64)
    first, inverse = _distinct_rows(rows)
    order = np.lexsort(rows[first].T[::-1])
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    return rows[first[order]] + 0, rank[inverse]


def _distinct_rows(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(the index of one row of each distinct value, each row's index among those), rows
    compared as opaque byte strings (+ 0.0 first: -0.0 and 0.0 are one value, their bytes
    differ)."""
    flat = np.ascontiguousarray(np.asarray(rows).reshape(len(rows), -1))
    if flat.dtype.kind == "f":
        flat = flat + flat.dtype.type(0.0)
    key = flat.view(np.dtype((np.void, flat.dtype.itemsize * flat.shape[1]))).ravel()
    _, first, inverse = np.unique(key, return_index=True, return_inverse=True)
    return first, inverse.reshape(-1)


def weld(tri: np.ndarray, uv: np.ndarray, nrm: np.ndarray, decimals: int = 6) -> Piece:
    """Indexed vertices from corner arrays tri (F,3,3), uv (F,3,2), nrm (F,3,3): corners with
    equal position, UV and normal share one vertex."""
    f = len(tri)
    if f == 0:
        return Piece(np.zeros((0, 3)), np.zeros((0, 2)), np.zeros((0, 3)), np.zeros((0, 3), int))
    rows = np.concatenate([tri.reshape(-1, 3), uv.reshape(-1, 2), nrm.reshape(-1, 3)], axis=1)
    first, inverse = _distinct_rows(np.round(rows, decimals))
    v = rows[first]
    return Piece(v[:, :3], v[:, 3:5], v[:, 5:8], inverse.reshape(f, 3).astype(np.int64))


def face_pieces(mesh: trimesh.Trimesh, uv: np.ndarray, faces: np.ndarray,
                normals: np.ndarray | None = None) -> Piece:
    """The faces `faces` (indices) of `mesh` as a welded `Piece`."""
    normals = corner_normals(mesh) if normals is None else normals
    tri = np.asarray(mesh.vertices, float)[np.asarray(mesh.faces)[faces]]
    return weld(tri, uv[faces], normals[faces])


def asset_slot_pieces(asset: Asset, link: str) -> list[tuple[str, Piece]]:
    """(slot name, Piece) for each material slot of one link's faces (asset frame, closed
    pose)."""
    faces = asset.link_faces(link)
    if len(faces) == 0:
        return []
    uv = corner_uv(asset)
    normals = corner_normals(asset.mesh)
    fs = face_slot_names(asset)[faces]
    out = []
    for si in np.unique(fs):
        sel = faces[fs == si]
        slot = asset.slots[int(si)] if int(si) < len(asset.slots) else "body"
        out.append((slot, face_pieces(asset.mesh, uv, sel, normals)))
    return out


def mesh_piece(mesh: trimesh.Trimesh) -> Piece:
    """A whole plain mesh as one Piece with box UVs."""
    return face_pieces(mesh, mesh_uv(mesh), np.arange(len(mesh.faces)))


def joint_frames(asset: Asset) -> dict[str, np.ndarray]:
    """Each link's frame origin in the asset frame: the base at 0, a moving link at its
    joint's origin (so its joint turns about the link frame's origin)."""
    frames = {"base": np.zeros(3)}
    for link in asset.links:
        frames.setdefault(link, np.zeros(3))
    for j in asset.joints:
        frames[j.child] = np.asarray(j.origin, float)
    return frames


def tangents(piece: Piece) -> np.ndarray:
    """Per-vertex tangents (V, 4) of `piece` for normal mapping: xyz the unit direction of
    increasing u, orthogonal to the normal; w = +1 or -1, the handedness that makes
    cross(normal, xyz) * w point along increasing v (glTF's convention). Where the UVs give no
    direction (degenerate mapping), any unit vector orthogonal to the normal."""
    v, f, uv, n = piece.vertices, piece.faces, piece.uv, piece.normals
    e1, e2 = v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]]
    d1, d2 = uv[f[:, 1]] - uv[f[:, 0]], uv[f[:, 2]] - uv[f[:, 0]]
    det = d1[:, 0] * d2[:, 1] - d2[:, 0] * d1[:, 1]
    inv = np.where(np.abs(det) < 1e-12, 0.0, 1.0 / np.where(det == 0.0, 1.0, det))[:, None]
    t_face = (e1 * d2[:, 1:2] - e2 * d1[:, 1:2]) * inv
    b_face = (e2 * d1[:, 0:1] - e1 * d2[:, 0:1]) * inv
    t = np.zeros_like(v)
    b = np.zeros_like(v)
    for k in range(3):
        np.add.at(t, f[:, k], t_face)
        np.add.at(b, f[:, k], b_face)
    t = t - n * np.einsum("ij,ij->i", n, t)[:, None]
    length = np.linalg.norm(t, axis=1)
    flat = length < 1e-9
    if flat.any():  # any direction across the normal: cross with the axis least along it
        axis = np.eye(3)[np.argmin(np.abs(n[flat]), axis=1)]
        t[flat] = np.cross(n[flat], axis)
        length[flat] = np.linalg.norm(t[flat], axis=1)
    lost = length < 1e-9  # no normal to be across (a zero normal): any unit direction will do
    t[lost], length[lost] = (1.0, 0.0, 0.0), 1.0
    t = t / length[:, None]
    w = np.where(np.einsum("ij,ij->i", np.cross(n, t), b) < 0.0, -1.0, 1.0)
    return np.concatenate([t, w[:, None]], axis=1)
