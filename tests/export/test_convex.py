"""Convex collision pieces of architecture: a wall with a doorway and an L-shaped floor."""
from __future__ import annotations

import numpy as np
import shapely.geometry as sg
import trimesh

from indoorgen.export.convex import MIN_THICKNESS, convex_parts, sound_piece


def _is_convex(m: trimesh.Trimesh) -> bool:
    return bool(np.isclose(m.convex_hull.volume, m.volume, rtol=1e-6))


def test_a_box_is_its_own_piece():
    box = trimesh.creation.box([2, 0.1, 2.5])
    (piece,) = convex_parts(box)
    assert np.isclose(piece.volume, box.volume)


def test_wall_with_a_doorway_keeps_the_opening_free():
    wall = trimesh.creation.box([4, 0.12, 2.5])
    wall.apply_translation([2, 0.06, 1.25])
    doorway = trimesh.creation.box([0.9, 1, 2.1])
    doorway.apply_translation([1.95, 0.06, 1.0])
    solid = wall.difference(doorway, engine="manifold")
    pieces = convex_parts(solid)
    assert len(pieces) >= 3 and all(_is_convex(p) for p in pieces)
    assert np.isclose(sum(p.volume for p in pieces), solid.volume, rtol=1e-3)
    inside = np.array([[1.95, 0.06, 1.0]])  # in the doorway, below the lintel
    assert not any(p.contains(inside)[0] for p in pieces)


def test_l_shaped_floor_splits_into_convex_prisms():
    floor = trimesh.creation.extrude_polygon(sg.box(0, 0, 4, 4).difference(sg.box(2, 2, 5, 5)), 0.1)
    pieces = convex_parts(floor)
    assert len(pieces) == 2 and all(_is_convex(p) for p in pieces)
    assert np.isclose(sum(p.volume for p in pieces), floor.volume)
    assert convex_parts(trimesh.Trimesh()) == []


def test_float_noise_leaves_no_sliver_between_parts():
    """A staircase room's floor whose stairwell edge lies 0.1 um (float noise) inside the room
    edge (a 2-storey home, seed 5) splits into sound parts, not a 0.1 um wide sliver MuJoCo
    refuses to hull ("coplanar vertices")."""
    room = sg.box(3.4999999, 9.9999999, 11.4999999, 12.0000001)
    slab = trimesh.creation.extrude_polygon(room.difference(sg.box(6.1, 10, 9.9, 11)), 0.1)
    pieces = convex_parts(slab)
    assert np.isclose(sum(p.volume for p in pieces), slab.volume, rtol=1e-5)
    for p in pieces:
        assert np.ptp(p.vertices, axis=0).min() >= MIN_THICKNESS
        assert p.area_faces.min() > 0


def test_thin_slab_becomes_a_box_and_a_sliver_is_dropped():
    sheet = trimesh.creation.box([0.4, 0.3, 1e-5])
    box = sound_piece(sheet)
    assert box is not None and len(box.vertices) == 8 and box.is_volume
    assert np.allclose(np.sort(np.ptp(box.vertices, axis=0)), [MIN_THICKNESS, 0.3, 0.4])
    needle = trimesh.creation.box([1.0, 1e-4, 1e-4])
    assert sound_piece(needle) is None
    flat = trimesh.Trimesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], [[0, 1, 2], [1, 3, 2]])
    assert sound_piece(flat) is not None  # a flat quad (no volume at all) becomes a thin box
    cube = trimesh.creation.box([0.1, 0.1, 0.1])
    assert sound_piece(cube) is cube


def test_zero_area_faces_never_survive():
    cube = trimesh.creation.box([0.2, 0.2, 0.2])
    v = np.vstack([cube.vertices, [[0.1, 0.1, 0.1]]])  # a duplicate corner: a zero-area face
    f = np.vstack([cube.faces, [[0, 8, 1]]])
    piece = sound_piece(trimesh.Trimesh(v, f, process=False))
    assert piece is not None and piece.area_faces.min() > 0
    assert np.isclose(piece.volume, cube.volume)


def test_a_many_sided_hull_is_cut_to_the_engines_vertex_cap_keeping_its_base():
    from indoorgen.export.convex import vertex_limited
    vase = trimesh.creation.cylinder(radius=0.05, height=0.34, sections=96)
    vase.apply_translation([0, 0, 0.17])
    piece = vertex_limited(vase, 64)
    assert len(piece.vertices) <= 64 and _is_convex(piece)
    assert np.isclose(piece.volume, vase.volume, rtol=0.03)
    # it still stands on its whole base, not on a point
    base = piece.vertices[np.abs(piece.vertices[:, 2]) < 1e-4]
    assert np.ptp(base[:, 0]) > 0.09 and np.ptp(base[:, 1]) > 0.09
    assert piece.bounds[0, 2] > -1e-4 and piece.bounds[1, 2] < 0.34 + 1e-4
    small = trimesh.creation.box([1, 1, 1])
    assert vertex_limited(small, 64) is small
