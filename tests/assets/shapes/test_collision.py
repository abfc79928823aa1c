"""Convex collision pieces keep out of the spaces moving parts occupy (a drawer in its carcass,
a lid's skirt in its pot) and of the open space over covered shelves, so a simulator can open
them and what stands on a shelf stays put."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.assets.shapes.collision import (
    SWALLOW_MARGIN,
    SWALLOW_VOLUME,
    box_minus,
    carve_around,
    clear_of,
    convex_pieces,
    free_space_above,
    hollowed,
)
from indoorgen.assets.shapes.primitives import Part, box_between, cylinder


def _overlap(a, b) -> float:
    return (a ^ b).volume()


def _pieces(parts):
    pieces = convex_pieces(parts, decompose=True)
    return [h for link, h in pieces if link == "base"], [h for link, h in pieces if link != "base"]


def test_carcass_pieces_keep_out_of_the_drawer_and_cover_the_carcass():
    """(The empty compartment above the drawer may stay inside a hull: nothing moves there.)"""
    outer = box_between((-0.25, -0.3, 0.0), (0.25, 0.3, 0.6))
    cavity = box_between((-0.23, -0.28, 0.02), (0.3, 0.28, 0.58))  # open at the front (+X)
    carcass = outer - cavity
    drawer = box_between((-0.22, -0.27, 0.03), (0.26, 0.27, 0.3))
    body, moving = _pieces([Part(carcass, "wood"), Part(drawer, "wood", "drawer")])
    assert len(moving) == 1
    for piece in body:
        assert _overlap(piece, drawer) < 1e-7
    # together the pieces hold the whole carcass
    covered = sum(p.volume() for p in body)
    assert covered >= carcass.volume() - 1e-6
    assert abs(sum((p ^ carcass).volume() for p in body) - carcass.volume()) < 1e-6


def test_pot_wall_pieces_keep_out_of_its_lid_skirt():
    pot = cylinder(0.13, 0.08, sections=48) - cylinder(0.126, 0.08, (0, 0, 0.004), sections=48)
    lid = cylinder(0.135, 0.006, (0, 0, 0.081), sections=48)
    skirt = cylinder(0.123, 0.009, (0, 0, 0.072), sections=48) - \
        cylinder(0.12, 0.009, (0, 0, 0.072), sections=48)
    body, moving = _pieces([Part(pot, "metal"), Part(lid, "glass", "lid"),
                            Part(skirt, "glass", "lid")])
    for b in body:
        for m in moving:
            assert _overlap(b, m) < 2e-7  # at most a sliver where a short arc's chord dips in


def test_small_moving_parts_are_left_to_contact_margins():
    """A cap under 10 cm across does not multiply its jar's pieces."""
    jar = cylinder(0.03, 0.1, sections=32) - cylinder(0.027, 0.1, (0, 0, 0.003), sections=32)
    cap = cylinder(0.033, 0.015, (0, 0, 0.09), sections=32) - \
        cylinder(0.031, 0.012, (0, 0, 0.09), sections=32)
    body, moving = _pieces([Part(jar, "glass"), Part(cap, "metal", "lid")])
    assert len(body) == 1 and len(moving) == 1


def test_carve_around_keeps_hulls_clear_of_the_box():
    """A U-shaped part whose hull would swallow the drawer space is cut along the box's faces."""
    u_part = box_between((0.0, 0.0, 0.0), (0.5, 0.5, 0.5)) - box_between((0.1, 0.1, 0.1), (0.6, 0.4, 0.4))
    space = [0.1, 0.1, 0.1, 0.6, 0.4, 0.4]
    assert (u_part.hull() ^ box_between(space[:3], space[3:])).volume() > 0.01
    pieces = carve_around([u_part], [space])
    assert len(pieces) > 1
    inner = box_between(np.add(space[:3], SWALLOW_MARGIN), np.subtract(space[3:], SWALLOW_MARGIN))
    for p in pieces:
        assert (p.hull() ^ inner).volume() <= SWALLOW_VOLUME
    assert sum(p.volume() for p in pieces) == pytest.approx(u_part.volume(), rel=1e-9)


def test_carve_around_leaves_what_is_clear_alone():
    post = box_between((1.0, 1.0, 0.0), (1.1, 1.1, 1.0))
    assert carve_around([post], [[0.0, 0.0, 0.0, 0.5, 0.5, 0.5]]) == [post]


def test_free_space_above_a_covered_shelf_only():
    board = box_between((-0.2, -0.3, 0.6), (0.2, 0.3, 0.62))
    box = free_space_above([board], (-0.2, -0.3, 0.2, 0.3), 0.3, 1.0)
    assert box is not None and box[2] == pytest.approx(0.301) and box[5] == pytest.approx(0.599)
    assert free_space_above([board], (-0.2, -0.3, 0.2, 0.3), 0.61, 1.0) is None  # open above


def _vol(b) -> float:
    return float(np.prod(np.asarray(b[3:]) - np.asarray(b[:3])))


def test_box_minus_leaves_the_boards_around_the_compartments():
    """A cupboard's block less two compartments (one behind the other's shelf, one reaching out
    of the block's front): the pieces fill exactly the rest and none enters a compartment."""
    block = [-0.3, -0.4, 0.0, 0.3, 0.4, 0.9]
    holes = [[-0.28, -0.38, 0.02, 0.3, 0.38, 0.44], [-0.28, -0.38, 0.46, 0.35, 0.38, 0.88]]
    pieces = box_minus(block, holes)
    inside = sum(_vol([*np.maximum(block[:3], h[:3]), *np.minimum(block[3:], h[3:])]) for h in holes)
    assert sum(map(_vol, pieces)) == pytest.approx(_vol(block) - inside)
    for b in pieces:
        for h in holes:
            overlap = np.minimum(b[3:], h[3:]) - np.maximum(b[:3], h[:3])
            assert np.any(overlap <= 1e-9)
    assert box_minus(block, [[1, 1, 1, 2, 2, 2]]) == [block]


def test_hollowed_cuts_only_box_parts_of_the_body():
    block = Part(box_between((-0.3, -0.4, 0.0), (0.3, 0.4, 0.9)), "wood")
    door = Part(box_between((0.3, -0.4, 0.0), (0.32, 0.4, 0.9)), "wood", "door")
    knob = Part(cylinder(0.05, 0.1).translate((0.0, 0.0, 0.3)), "metal")
    hole = [-0.28, -0.38, 0.02, 0.28, 0.38, 0.88]
    out = hollowed([block, door, knob], [hole])
    assert door in out and knob in out
    body = [q for q in out if q.link == "base" and q is not knob]
    assert len(body) == 6  # floor, top, back, front rim, two sides
    assert sum(q.solid.volume() for q in body) == pytest.approx(
        block.solid.volume() - _vol(hole), rel=1e-6)


def test_clear_of_keeps_stowage_out_of_drawers_and_door_racks():
    """A compartment with a rack on its door reaching 8 cm in: the box gives up its front 8 cm;
    one filled by a drawer's bin holds nothing."""
    box = [-0.25, -0.3, 0.1, 0.25, 0.3, 0.5]
    rack = box_between((0.17, -0.28, 0.2), (0.3, 0.28, 0.3))
    assert clear_of(box, [rack]) == pytest.approx([-0.25, -0.3, 0.1, 0.17, 0.3, 0.5])
    bin_ = box_between((-0.24, -0.29, 0.101), (0.26, 0.29, 0.45))
    assert clear_of(box, [bin_]) is None
    shelf_below = box_between((-0.25, -0.3, 0.08), (0.25, 0.3, 0.1))
    assert clear_of(box, [shelf_below]) == box
