"""Surface helpers: upward supports, mirrored bottoms, side facets all round."""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.assets.shapes.surfaces import (
    bottom_rect,
    polygon_side_surfaces,
    rect_side_surfaces,
    support_polygon,
    support_rect,
)
from indoorgen.model.tags import Subpart


def test_support_rect_faces_up_and_is_never_empty():
    s = support_rect("top", (0.1, 0.0, 0.7), 0.3, 0.0)
    assert s.subpart == Subpart.SupportSurface and np.allclose(s.normal, (0, 0, 1))
    assert s.polygon.area > 0  # a zero half-width is widened to 5 mm
    assert np.allclose(s.corners()[:, 2], 0.7)


def test_bottom_polygon_is_mirrored_so_it_maps_back_onto_itself():
    tri = sg.Polygon([(0.0, 0.0), (0.2, 0.0), (0.0, 0.1)])
    s = support_polygon("bottom", (0, 0, 0), tri, subpart=Subpart.Bottom, up=False)
    assert np.allclose(s.normal, (0, 0, -1))
    assert sg.Polygon(s.corners()[:, :2]).equals(tri)
    assert np.allclose(bottom_rect((0, 0, 0), 0.2, 0.1).normal, (0, 0, -1))


def test_rect_side_surfaces_face_out():
    sides = rect_side_surfaces(0.8, 0.6, 0.75)
    assert [s.name for s in sides] == ["side_0", "side_1", "side_2", "side_3"]
    for s in sides:
        assert s.subpart == Subpart.Side
        assert np.dot(s.origin[:2], s.normal[:2]) > 0
        assert s.origin[2] == pytest.approx(0.375)


@pytest.mark.parametrize("n", [4, 5, 8])
def test_polygon_sides_circumscribe_the_circle(n):
    sides = polygon_side_surfaces(0.5, n, 0.75)
    assert len(sides) == n
    for s in sides:
        assert np.linalg.norm(s.origin[:2]) == pytest.approx(0.5)
        assert s.polygon.bounds[2] == pytest.approx(0.5 * math.tan(math.pi / n))
