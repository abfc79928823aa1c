"""Prisms, cuts and meshes (indoorgen.architecture.solids)."""
from __future__ import annotations

import manifold3d
import pytest
import shapely.geometry as sg

from indoorgen.architecture.solids import checked_mesh, extrude_outline, extrude_region, subtract, to_trimesh


def test_extrude_outline_either_orientation():
    square = [(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0)]
    for pts in (square, square[::-1]):
        mesh = to_trimesh(extrude_outline(pts, 1.0, 3.0))
        assert mesh.is_watertight and mesh.volume == pytest.approx(4.0)
        assert mesh.bounds[0][2] == pytest.approx(1.0) and mesh.bounds[1][2] == pytest.approx(3.0)


def test_extrude_region_keeps_holes_and_pieces():
    ring = sg.box(0, 0, 4, 4).difference(sg.box(1, 1, 3, 3))
    assert to_trimesh(extrude_region(ring, 0.0, 1.0)).volume == pytest.approx(12.0)
    two = sg.MultiPolygon([sg.box(0, 0, 1, 1), sg.box(2, 0, 3, 1)])
    assert to_trimesh(extrude_region(two, 0.0, 2.0)).volume == pytest.approx(4.0)
    assert extrude_region(sg.Polygon(), 0.0, 1.0).is_empty()


def test_subtract_and_checked_mesh():
    block = extrude_region(sg.box(0, 0, 2, 2), 0.0, 2.0)
    cut = extrude_region(sg.box(0.5, -1, 1.5, 3), 0.5, 1.5)
    assert subtract(block, []) is block
    mesh = checked_mesh(subtract(block, [cut]), "block")
    assert mesh.is_watertight and mesh.volume == pytest.approx(8.0 - 2.0)
    assert isinstance(block, manifold3d.Manifold)
