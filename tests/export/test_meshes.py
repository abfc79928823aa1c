"""Mesh pieces for the file formats: welded vertices, crease-aware normals, transforms."""
from __future__ import annotations

import numpy as np
import trimesh

from indoorgen.export.meshes import corner_normals, mesh_piece, tangents, unique_rows, weld


def test_weld_shares_equal_corners_only():
    tri = np.array([[[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0], [0, 1, 0]]], float)
    uv = tri[:, :, :2].copy()
    nrm = np.tile([0.0, 0.0, 1.0], (2, 3, 1))
    p = weld(tri, uv, nrm)
    assert len(p.vertices) == 4 and p.faces.shape == (2, 3)
    assert np.allclose(p.vertices[p.faces], tri)
    uv[1, 0] += 0.5  # a UV seam: the shared corner splits
    assert len(weld(tri, uv, nrm).vertices) == 5
    assert len(weld(tri[:0], uv[:0], nrm[:0]).vertices) == 0


def test_box_edges_stay_sharp_and_a_sphere_smooth():
    box = trimesh.creation.box([1, 1, 1])
    n = corner_normals(box)
    assert np.allclose(n, np.repeat(box.face_normals[:, None, :], 3, axis=1))
    ball = trimesh.creation.icosphere(3)
    n = corner_normals(ball)
    assert np.allclose(n, ball.vertex_normals[ball.faces])


def test_piece_transformed_moves_vertices_and_turns_normals():
    p = mesh_piece(trimesh.creation.box([1, 2, 3]))
    m = trimesh.transformations.rotation_matrix(np.pi / 2, [0, 0, 1])
    m[:3, 3] = [5, 0, 0]
    q = p.transformed(m)
    assert np.allclose(q.vertices, p.vertices @ m[:3, :3].T + [5, 0, 0])
    assert np.allclose(np.linalg.norm(q.normals, axis=1), 1) and np.array_equal(q.faces, p.faces)


def test_tangents_follow_u_across_the_normal_with_v_handedness():
    box = trimesh.creation.box([2.0, 1.0, 0.5])
    piece = mesh_piece(box)
    t = tangents(piece)
    assert t.shape == (len(piece.vertices), 4)
    assert np.allclose(np.linalg.norm(t[:, :3], axis=1), 1.0)
    assert np.allclose(np.einsum("ij,ij->i", t[:, :3], piece.normals), 0.0, atol=1e-9)
    assert set(np.unique(t[:, 3])) <= {-1.0, 1.0}
    # on each face, moving along the tangent raises u, along cross(n, t) * w raises v
    f = piece.faces
    e = piece.vertices[f[:, 1]] - piece.vertices[f[:, 0]]
    du = piece.uv[f[:, 1], 0] - piece.uv[f[:, 0], 0]
    dv = piece.uv[f[:, 1], 1] - piece.uv[f[:, 0], 1]
    tf = t[f[:, 0]]
    bf = np.cross(piece.normals[f[:, 0]], tf[:, :3]) * tf[:, 3:]
    assert np.allclose(np.einsum("ij,ij->i", e, tf[:, :3]), du, atol=1e-9)
    assert np.allclose(np.einsum("ij,ij->i", e, bf), dv, atol=1e-9)


def test_unique_rows_is_numpys_unique_by_rows():
    rng = np.random.default_rng(1)
    for dtype in (np.float32, float, np.int64):
        for n in (0, 1, 7, 500):
            rows = (rng.integers(-3, 3, (n, 3)) / 2).astype(dtype)
            if n > 2:  # -0.0 and 0.0 are one value, though their bytes differ
                rows[0], rows[1] = [-0.0, 1, 2], [0.0, 1, 2]
            want, want_inverse = np.unique(rows, axis=0, return_inverse=True)
            got, inverse = unique_rows(rows)
            assert got.dtype == rows.dtype and got.shape == want.shape
            assert (got == want).all() and (inverse == want_inverse.reshape(-1)).all()
            assert (got[inverse] == rows).all()
