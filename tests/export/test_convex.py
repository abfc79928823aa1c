"""Convex collision pieces of architecture: a wall with a doorway and an L-shaped floor."""
from __future__ import annotations

import numpy as np
import shapely.geometry as sg
import trimesh

from indoorgen.export.convex import convex_parts


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
