"""Parts to meshes: `union` keeps each face's material slot and makes one watertight shell,
`concat` keeps every part, `union_links` gives one shell per link, `box_uv` projects in metres."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.assets.shapes.mesh import (
    box_uv,
    collapse_short_edges,
    concat,
    link_names,
    manifold_to_trimesh,
    solid_union,
    union,
    union_links,
)
from indoorgen.assets.shapes.primitives import Part, box_between, cylinder

SEAT = Part(box_between((-0.2, -0.2, 0.4), (0.2, 0.2, 0.45)), "fabric")
LEG = Part(box_between((-0.02, -0.02, 0.0), (0.02, 0.02, 0.402)), "wood")
DRAWER = Part(box_between((0.3, -0.1, 0.0), (0.5, 0.1, 0.1)), "front", "drawer_0")


def test_union_keeps_per_face_slots():
    mesh, face_slots, slots = union([SEAT, LEG], ["wood", "fabric", "metal"])
    assert slots == ["wood", "fabric", "metal"]
    assert mesh.is_watertight and mesh.body_count == 1 and len(face_slots) == len(mesh.faces)
    centres = mesh.triangles_center
    # faces of the seat's top are fabric, of the leg's foot wood; no face is metal
    assert np.all(face_slots[centres[:, 2] > 0.449] == slots.index("fabric"))
    assert np.all(face_slots[centres[:, 2] < 0.001] == slots.index("wood"))
    assert slots.index("metal") not in set(face_slots.tolist())
    assert mesh.volume == pytest.approx(0.4 * 0.4 * 0.05 + 0.04 * 0.04 * 0.4, rel=1e-6)


def test_union_adds_unlisted_slots_and_subtracts():
    hole = box_between((-0.05, -0.05, 0.3), (0.05, 0.05, 0.5))
    mesh, face_slots, slots = union([SEAT], ["wood"], subtract=[hole])
    assert slots == ["wood", "fabric"]
    assert np.all(face_slots == 1)  # the cut's walls take the slot of what they cut into
    assert mesh.volume == pytest.approx(0.4 * 0.4 * 0.05 - 0.1 * 0.1 * 0.05, rel=1e-6)


def test_concat_keeps_every_part_without_booleans():
    mesh, face_slots, slots = concat([SEAT, LEG])
    assert slots == ["fabric", "wood"] and mesh.body_count == 2
    assert len(mesh.faces) == 24 and np.array_equal(np.bincount(face_slots), [12, 12])


def test_union_links_gives_one_shell_per_link_base_first():
    parts = [DRAWER, SEAT, LEG]
    assert link_names(parts) == ["base", "drawer_0"]
    mesh, face_slots, slots, links, face_links = union_links(parts, ["wood"])
    assert links == ["base", "drawer_0"] and mesh.body_count == 2
    assert face_links[0] == 0 and set(face_links.tolist()) == {0, 1}
    drawer_faces = mesh.triangles_center[face_links == 1]
    assert np.all(drawer_faces[:, 0] > 0.29)
    assert set(face_slots[face_links == 1].tolist()) == {slots.index("front")}


def test_solid_union_and_manifold_to_trimesh():
    u = solid_union([SEAT.solid, LEG.solid, box_between((0, 0, 0), (0, 0, 0))])
    m = manifold_to_trimesh(u)
    assert m.is_watertight and m.volume == pytest.approx(u.volume())


def test_collapse_short_edges_keeps_a_closed_mesh_closed():
    m = manifold_to_trimesh(cylinder(0.1, 0.1, sections=16))
    v, f, keep = collapse_short_edges(np.asarray(m.vertices), np.asarray(m.faces), 1e-9)
    assert keep.all() and len(f) == len(m.faces)
    verts = np.vstack([m.vertices, m.vertices[:1] + 1e-8])
    assert collapse_short_edges(verts, np.asarray(m.faces), 1e-6)[2].all()


def test_box_uv_projects_each_face_along_its_main_axis_in_metres():
    m = manifold_to_trimesh(box_between((0, 0, 0), (2.0, 1.0, 0.5)))
    uv = box_uv(m.vertices, m.faces)
    assert uv.shape == (len(m.faces), 3, 2)
    normals = np.abs(m.face_normals).argmax(axis=1)
    keep = np.array([[1, 2], [0, 2], [0, 1]])[normals]
    tri = m.triangles
    assert np.allclose(uv, np.take_along_axis(tri, keep[:, None, :].repeat(3, axis=1), axis=2))
    assert np.allclose(box_uv(m.vertices, m.faces, 2.0), 2 * uv)
