"""Swept solids: filleted paths keep their ends and round their corners, tubes are closed and
their placeholder boxes contain them with the same bounds, lofts close either ring direction."""
from __future__ import annotations

import math

import numpy as np
import pytest

from indoorgen.assets.shapes.sweeps import (
    dedupe_points,
    fillet_path,
    loft,
    polyline_tangents,
    rod_between,
    tube,
    tube_boxes,
    tube_rings,
    unit_rows,
)

L_PATH = [(0.0, 0.0, 0.0), (0.5, 0.0, 0.0), (0.5, 0.0, 0.4)]


def bounds(solid) -> np.ndarray:
    return np.asarray(solid.bounding_box(), float).reshape(2, 3)


def polygon_area(n: int, r: float) -> float:
    """The area of a regular n-gon with its vertices on a circle of radius r."""
    return n / 2 * r * r * math.sin(2 * math.pi / n)


def test_unit_rows_and_dedupe():
    assert np.allclose(np.linalg.norm(unit_rows(np.array([[3.0, 4.0, 0.0], [0.0, 0.0, 2.0]])), axis=1), 1)
    pts = dedupe_points([(0, 0, 0), (0, 0, 0), (1, 0, 0), (1, 0, 1e-9), (1, 1, 0)])
    assert len(pts) == 3


def test_tangents_bisect_the_corners():
    t = polyline_tangents(np.array(L_PATH, float))
    assert np.allclose(t[0], (1, 0, 0)) and np.allclose(t[-1], (0, 0, 1))
    assert np.allclose(t[1], (math.sqrt(0.5), 0, math.sqrt(0.5)))


def test_fillet_path_keeps_its_ends_and_rounds_the_corner():
    path = fillet_path(L_PATH, 0.1, 6)
    assert np.allclose(path[0], L_PATH[0]) and np.allclose(path[-1], L_PATH[-1])
    assert len(path) == 2 + 7
    corner = np.array(L_PATH[1])
    centre = corner + np.array([-0.1, 0.0, 0.1])  # the arc's centre, 0.1 from both legs
    arc = path[1:-1]
    assert np.allclose(np.linalg.norm(arc - centre, axis=1), 0.1)
    assert np.all(np.linalg.norm(path - corner, axis=1) > 0.04)  # the sharp corner is gone
    assert np.array_equal(fillet_path(L_PATH[:2], 0.1), np.array(L_PATH[:2], float))


def test_tube_rings_are_round_and_square_to_the_path():
    path = fillet_path(L_PATH, 0.1, 6)
    rings = tube_rings(path, 0.02, 10)
    assert rings.shape == (len(path), 12, 3)  # sections rounded up to a multiple of 4
    tang = polyline_tangents(path)
    for ring, p, t in zip(rings, path, tang, strict=True):
        assert np.allclose(np.linalg.norm(ring - p, axis=1), 0.02)
        assert np.allclose((ring - p) @ t, 0.0, atol=1e-12)


def test_tube_is_closed_and_its_boxes_contain_it_with_the_same_bounds():
    path = fillet_path(L_PATH, 0.1, 6)
    t = tube(path, 0.02, 16)
    assert t.status().name == "NoError" and t.genus() == 0
    length = 0.4 + 0.3 + math.pi / 2 * 0.1  # two straight legs and a quarter circle
    assert t.volume() == pytest.approx(polygon_area(16, 0.02) * length, rel=0.01)
    boxes = tube_boxes(path, 0.02, 3)
    assert len(boxes) == 3
    lo = np.min([bounds(b)[0] for b in boxes], axis=0)
    hi = np.max([bounds(b)[1] for b in boxes], axis=0)
    assert np.allclose(bounds(t), [lo, hi], atol=1e-6)
    union = boxes[0] + boxes[1] + boxes[2]
    assert (t - union).volume() < 1e-10


def test_rod_between_and_its_placeholder_box():
    fine = rod_between((0, 0, 0), np.array([0.3, 0.0, 0.4]), 0.01, True)
    cheap = rod_between((0, 0, 0), (0.3, 0.0, 0.4), 0.01, False)
    assert np.allclose(bounds(fine), bounds(cheap), atol=1e-6)
    assert (fine - cheap).volume() < 1e-12
    assert fine.volume() == pytest.approx(polygon_area(12, 0.01) * 0.5, rel=1e-6)


def test_loft_closes_either_ring_direction():
    a = np.linspace(0, 2 * math.pi, 8, endpoint=False)
    ring = np.c_[0.1 * np.cos(a), 0.1 * np.sin(a), np.zeros(8)]
    rings = np.stack([ring + (0, 0, z) for z in (0.0, 0.1, 0.2)])
    ccw, cw = loft(rings), loft(rings[:, ::-1])
    assert ccw.volume() == pytest.approx(cw.volume()) and ccw.volume() > 0
    assert ccw.volume() == pytest.approx(polygon_area(8, 0.1) * 0.2, rel=1e-6)  # flat ends
    tip = loft(rings, end=np.array([0.0, 0.0, 0.3]))  # a pointed end
    assert bounds(tip)[1, 2] == pytest.approx(0.3)
