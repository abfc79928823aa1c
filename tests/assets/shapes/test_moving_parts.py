"""Moving parts: doors and drawers on their own links with motions that swing or slide them
away from the body, cabinet fronts shrunk by the reveal, and the front constants agreeing."""
from __future__ import annotations

import math

import numpy as np
import pytest

from indoorgen.assets.shapes.moving_parts import (
    DOOR_OPEN,
    FRONT_PROUD,
    FRONT_T,
    HANDLE_STANDOFF,
    MOVING_GAP,
    REVEAL,
    Front,
    bar_handle,
    cabinet_fronts,
    drawer,
    hinge_motion,
    hinged_door,
    knob,
    slide_motion,
)


def bounds(solid) -> np.ndarray:
    return np.asarray(solid.bounding_box(), float).reshape(2, 3)


def test_constants():
    assert pytest.approx(MOVING_GAP + FRONT_T + HANDLE_STANDOFF["bar"]) == FRONT_PROUD
    assert pytest.approx(math.radians(100)) == DOOR_OPEN and REVEAL > 0


def test_handles_stand_proud_by_their_standoff():
    bar = bar_handle((0.3, 0.0, 0.5), 0.12, vertical=True)
    assert bounds(bar)[1, 0] == pytest.approx(0.3 + HANDLE_STANDOFF["bar"])
    assert bounds(bar)[1, 2] - bounds(bar)[0, 2] == pytest.approx(0.12)
    k = knob((0.3, 0.0, 0.5))
    assert bounds(k)[1, 0] == pytest.approx(0.3 + HANDLE_STANDOFF["knob"])


@pytest.mark.parametrize("hinge,axis", [("left", (0, 0, -1)), ("right", (0, 0, 1)),
                                        ("bottom", (0, 1, 0)), ("top", (0, -1, 0))])
def test_hinged_door_swings_outwards(hinge, axis):
    parts, m = hinged_door(0.2, -0.3, 0.3, 0.1, 0.9, FRONT_T, hinge, "door_0")
    assert {p.link for p in parts} == {"door_0"} and m.kind == "revolute"
    assert np.allclose(m.axis, axis)
    leaf = bounds(parts[0].solid)
    assert leaf[0, 0] == pytest.approx(0.2 + MOVING_GAP)
    assert np.allclose(m.origin[0], 0.2 + MOVING_GAP + FRONT_T)
    with pytest.raises(ValueError):
        hinge_motion("sideways", 0.0, 0.0, 1.0, 0.0, 1.0, "door")


def test_drawer_slides_out_along_x_inside_its_opening():
    parts, m = drawer(0.25, -0.2, 0.2, 0.3, 0.5, 0.4, FRONT_T, "drawer_0")
    assert m.kind == "prismatic" and np.allclose(m.axis, (1, 0, 0))
    box = bounds(parts[1].solid)
    assert box[0, 0] == pytest.approx(0.25 - 0.4)
    assert box[0, 1] >= -0.2 + MOVING_GAP and box[1, 1] <= 0.2 - MOVING_GAP
    assert np.allclose(slide_motion("x", (1, 2, 3)).axis, (1, 0, 0))


def test_cabinet_fronts_link_each_cell_and_keep_a_reveal():
    cells = [Front(-0.4, 0.0, 0.1, 0.7, "left"), Front(0.0, 0.4, 0.1, 0.7, "right"),
             Front(-0.4, 0.4, 0.7, 0.9, "drawer"), Front(-0.4, 0.4, 0.0, 0.1, "open")]
    fronts = cabinet_fronts(0.3, cells, 0.5, prefix="u_")
    assert [m.link for _, m in fronts] == ["u_door_0", "u_door_1", "u_drawer_2"]
    y0 = bounds(fronts[0][0][0].solid)[0, 1]
    y1 = bounds(fronts[1][0][0].solid)[0, 1]
    assert y0 == pytest.approx(-0.4 + REVEAL) and y1 == pytest.approx(0.0 + REVEAL)
    with pytest.raises(ValueError):
        cabinet_fronts(0.3, [Front(0, 1, 0, 1, "sideways")], 0.5)
