"""Primitives keep exact bounding boxes; circumscribed round solids contain the true circle and
share its bounds; rounded slabs and their plan polygon agree; `board` and the overlaps."""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.assets.shapes.primitives import (
    OVERLAP,
    SMALL_OVERLAP,
    Part,
    bevel_box,
    board,
    box,
    box_between,
    circle_polygon,
    cylinder,
    lathe,
    panel,
    rod,
    rounded_rect_polygon,
    rounded_slab,
    tapered_box,
    torus,
)


def bounds(solid) -> np.ndarray:
    return np.asarray(solid.bounding_box(), float).reshape(2, 3)


def test_box_and_box_between_are_exact():
    assert np.allclose(bounds(box((0.4, 0.2, 0.1), (1.0, 2.0, 3.0))),
                       [(0.8, 1.9, 2.95), (1.2, 2.1, 3.05)])
    b = box_between(np.array([-0.1, 0.0, 0.2]), (0.3, 0.5, 0.4))  # arrays and tuples alike
    assert np.allclose(bounds(b), [(-0.1, 0.0, 0.2), (0.3, 0.5, 0.4)])
    assert b.volume() == pytest.approx(0.4 * 0.5 * 0.2)


def test_board_is_a_box_part():
    part = board((0, 0, 0), (0.1, 0.2, 0.3), "metal", "drawer_0")
    assert isinstance(part, Part) and (part.slot, part.link) == ("metal", "drawer_0")
    assert np.allclose(bounds(part.solid), [(0, 0, 0), (0.1, 0.2, 0.3)])
    assert (board((0, 0, 0), (1, 1, 1)).slot, board((0, 0, 0), (1, 1, 1)).link) == ("wood", "base")


@pytest.mark.parametrize("radius,segments", [(0.01, 1), (0.02, 2), (0.5, 3)])
def test_bevel_box_keeps_its_box_and_fits_in_it(radius, segments):
    ext, ctr = (0.3, 0.2, 0.1), (0.05, -0.1, 0.4)
    bev, plain = bevel_box(ext, ctr, radius, segments), box(ext, ctr)
    assert np.allclose(bounds(bev), bounds(plain), atol=1e-9)
    assert bev.volume() < plain.volume()
    assert (bev - plain).volume() < 1e-12  # the rounding only removes material


def test_tapered_box_spans_its_two_sections():
    t = tapered_box((0.02, 0.02), (0.04, 0.04), 0.0, 0.7, (0.1, 0.2))
    assert np.allclose(bounds(t), [(0.08, 0.18, 0.0), (0.12, 0.22, 0.7)])


@pytest.mark.parametrize("sections", [6, 8, 13, 32])
def test_cylinder_bounds_are_exact_both_ways(sections):
    for circ in (False, True):
        c = cylinder(0.25, 0.5, (1.0, 0.0, 0.2), sections, circumscribed=circ)
        assert np.allclose(bounds(c), [(0.75, -0.25, 0.2), (1.25, 0.25, 0.7)], atol=1e-9)


@pytest.mark.parametrize("sections", [8, 16, 32])
def test_circumscribed_cylinder_contains_the_true_circle(sections):
    r = 0.2
    fine = cylinder(r, 0.1, sections=512)
    cheap = cylinder(r, 0.1, sections=sections, circumscribed=True)
    inscribed = cylinder(r, 0.1, sections=sections)
    assert (fine - cheap).volume() < 1e-9  # nothing of the (near) true disc sticks out
    assert (fine - inscribed).volume() > 1e-6  # while the plain polygon is inside the circle
    # its edges touch the circle: the area is that of the regular polygon around it
    n = max(4, math.ceil(sections / 4) * 4)
    assert cheap.volume() == pytest.approx(n * r * r * math.tan(math.pi / n) * 0.1, rel=1e-9)


def test_cone_frustum_and_rod():
    cone = cylinder(0.1, 0.3, radius_top=0.05)
    assert np.allclose(bounds(cone), [(-0.1, -0.1, 0.0), (0.1, 0.1, 0.3)])
    r = rod((0, 0, 0), (0.3, 0.4, 0.0), 0.01, 16)
    assert r.volume() == pytest.approx(math.pi * 0.01 ** 2 * 0.5, rel=0.03)
    down = rod((0, 0, 1), (0, 0, 0), 0.02)  # anti-parallel to the cylinder's own axis
    assert np.allclose(bounds(down)[:, 2], (0.0, 1.0))


def test_lathe_either_orientation_and_circumscribed_bounds():
    profile = [(0.0, 0.0), (0.1, 0.0), (0.1, 0.2), (0.0, 0.2)]
    a, b = lathe(profile, 16), lathe(profile[::-1], 16)
    assert a.volume() == pytest.approx(b.volume()) and a.volume() > 0
    c = lathe(profile, 16, circumscribed=True)
    assert np.allclose(bounds(c), [(-0.1, -0.1, 0.0), (0.1, 0.1, 0.2)], atol=1e-9)
    assert (lathe(profile, 256) - c).volume() < 1e-9


def test_torus_and_panel():
    t = torus(0.2, 0.02, (0, 0, 1.0))
    assert np.allclose(bounds(t), [(-0.22, -0.22, 0.98), (0.22, 0.22, 1.02)], atol=1e-9)
    for axis, ext in (("x", (0.01, 0.5, 0.3)), ("y", (0.5, 0.01, 0.3)), ("z", (0.5, 0.3, 0.01))):
        p = panel(0.5, 0.3, 0.01, normal_axis=axis)
        assert np.allclose(bounds(p)[1] - bounds(p)[0], ext)


def test_rounded_slab_and_its_plan_polygon():
    slab = rounded_slab(0.6, 0.4, 0.1, 0.14, 0.05, center=(0.2, 0.0))
    assert np.allclose(bounds(slab), [(-0.1, -0.2, 0.1), (0.5, 0.2, 0.14)], atol=1e-9)
    plan = rounded_rect_polygon(0.6, 0.4, 0.05, 0.0, center=(0.2, 0.0))
    assert plan.area == pytest.approx(slab.volume() / 0.04, rel=2e-3)
    inset = rounded_rect_polygon(0.6, 0.4, 0.05, 0.02, center=(0.2, 0.0))
    assert plan.buffer(-0.0199).contains(inset) and inset.area < plan.area
    disc = rounded_rect_polygon(0.3, 0.3, 1.0, 0.01)  # the corner radius is capped: a disc
    assert disc.area == pytest.approx(math.pi * 0.14 ** 2, rel=1e-2)


def test_circle_polygon_lies_inside_discs_built_alike():
    poly = circle_polygon(0.1, 32, (0.5, 0.0))
    assert isinstance(poly, sg.Polygon) and len(poly.exterior.coords) == 33
    assert np.allclose(poly.exterior.coords[0], (0.6, 0.0))
    assert sg.Point(0.5, 0.0).buffer(0.1, 256).contains(poly.buffer(-1e-9))


def test_overlaps():
    assert OVERLAP == 0.002 and SMALL_OVERLAP == OVERLAP / 2
