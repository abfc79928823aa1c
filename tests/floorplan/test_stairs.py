"""Stairs in the staircase placeholder and where a staircase room's doors may open
(indoorgen.floorplan.stairs)."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.floorplan.grid import make_grid
from indoorgen.floorplan.stairs import (
    LANDING,
    flight_mask,
    flights,
    landing_points,
    stair_door_ok,
)

#: A 2 x 6 m placeholder along x: lane 0 is y 0-1, lane 1 is y 1-2.
PLACEHOLDER = sg.box(0.0, 0.0, 6.0, 2.0)
STAIRCASE = PLACEHOLDER


def test_flights_leave_landings_at_both_ends_and_switch_back():
    lower, upper = flights(PLACEHOLDER, 3)
    for st in (lower, upper):
        poly = st.shape()
        assert PLACEHOLDER.contains(poly)
        x0, _, x1, _ = poly.bounds
        assert x0 == pytest.approx(LANDING) and x1 == pytest.approx(6.0 - LANDING)
        assert poly.area == pytest.approx((6.0 - 2 * LANDING) * 1.0)
    # the second flight climbs the other lane the other way, from where the first arrives
    assert lower.shape().bounds[1] == 0.0 and upper.shape().bounds[1] == 1.0
    assert lower.frame()[1][0] == 1.0 and upper.frame()[1][0] == -1.0
    head = landing_points([lower], 1)[0]
    foot = landing_points([upper], 1)[0]
    assert head[0] > 6.0 - LANDING and foot[0] > 6.0 - LANDING


def test_no_door_opens_over_a_stairwell_or_onto_the_flight():
    stairs = flights(PLACEHOLDER, 2)
    along = np.array([1.0, 0.0])
    for level in (0, 1):  # the flight on storey 0, its stairwell on storey 1
        # in the wall beside lane 0, halfway along: straight onto the flight or into the well
        assert not stair_door_ok(STAIRCASE, stairs, level, np.array([3.0, 0.0]), along, 0.9, 0.12)
        # in the wall beside lane 1: a free 1 m lane leads to both landings
        assert stair_door_ok(STAIRCASE, stairs, level, np.array([3.0, 2.0]), along, 0.9, 0.12)
    # the end wall past the flight's head: on the landing itself
    assert stair_door_ok(STAIRCASE, stairs, 1, np.array([6.0, 1.0]), np.array([0.0, 1.0]), 0.9,
                         0.12)


def test_a_door_cut_off_from_the_landings_is_refused():
    stairs = flights(PLACEHOLDER, 2)
    # a staircase room only as wide as the flight: nothing beside the stairwell to walk on
    narrow = sg.box(0.0, 0.0, 6.0, 1.0)
    assert not stair_door_ok(narrow, stairs, 1, np.array([0.0, 0.5]), np.array([0.0, 1.0]), 0.9,
                             0.12)
    assert stair_door_ok(narrow, stairs, 1, np.array([6.0, 0.5]), np.array([0.0, 1.0]), 0.8,
                         0.12)


def test_flight_mask_covers_the_flight_cells_only():
    grid = make_grid(sg.box(0.0, 0.0, 8.0, 4.0))
    (st,) = flights(PLACEHOLDER, 2)
    for level in (0, 1):
        m = flight_mask(grid, [st], level)
        ys, xs = np.nonzero(m)
        assert (ys.min(), ys.max()) == (0, 1)   # lane 0 only: y 0-1 m
        assert (xs.min(), xs.max()) == (2, 9)   # x 1.1-4.9 m touches cells 2..9
    assert not flight_mask(grid, [st], 2).any()
