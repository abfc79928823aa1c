"""Independent checks of a floorplan (indoorgen.floorplan.check) on broken copies of a sound
hand-drawn plan."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.floorplan.check import floorplan_problems, home_problems, narrow_area
from indoorgen.floorplan.grid import square_pieces
from indoorgen.model.floorplan import Floorplan
from indoorgen.model.floorplan_io import from_json
from indoorgen.model.polygons import polygon_pieces
from support.plans import apartment


def _plan(mutate=None) -> Floorplan:
    d = apartment()
    if mutate is not None:
        mutate(d)
    return from_json(d)


def test_the_apartment_is_sound():
    fp = _plan()
    assert floorplan_problems(fp, [fp.storeys[0].contour()]) == []


@pytest.mark.parametrize("mutate, needle", [
    (lambda d: d["storeys"][0]["doors"][0].update(width=0.6), "d0 is 0.60 m wide"),
    (lambda d: d["storeys"][0]["doors"][2].update(center=[8.75, 6.0]), "d2 is not on a wall"),
    (lambda d: d["storeys"][0]["doors"].pop(2), "bedroom_1 cannot be reached"),
    (lambda d: d.update(entrance=None), "no entrance"),
    (lambda d: d["storeys"][0]["rooms"][3].update(type="closet"), "the home has no bathroom"),
    # a third door into the 2.5 x 3 m bedroom: three doors need 10 m^2 (least_area)
    (lambda d: d["storeys"][0]["doors"].extend([
        {"name": "d3", "rooms": ["bathroom_0", "bedroom_1"], "center": [7.5, 6.5], "width": 0.8,
         "height": 2.05},
        {"name": "d4", "rooms": ["kitchen_0", "bedroom_1"], "center": [9.2, 5.0], "width": 0.9,
         "height": 2.05}]),
     "bedroom_1 (7.5 m^2) is smaller than 10.0 m^2 for 3 doors"),
])
def test_broken_plans_are_reported(mutate, needle):
    assert any(needle in p for p in floorplan_problems(_plan(mutate))), needle


def _garage_with(d: dict, door: dict | None) -> None:
    d["storeys"][0]["rooms"][4]["type"] = "garage"   # bedroom_1: 2.5 x 3 m, east wall outside
    if door is not None:
        d["vehicle_doors"] = [door]


@pytest.mark.parametrize("mutate, needle", [
    # the only bathroom opens off a bedroom
    (lambda d: d["storeys"][0]["doors"][1].update(rooms=["bedroom_0", "bathroom_0"],
                                                  center=[5.0, 6.5]),
     "every bathroom is behind a bedroom"),
    (lambda d: _garage_with(d, None), "bedroom_1 has no vehicle door"),
    (lambda d: _garage_with(d, {"room": "bedroom_1", "center": [8.75, 5.0], "width": 2.4,
                                "height": 2.1}), "vehicle door is not on an outside wall"),
    # a balcony with only its short north side outside
    (lambda d: d["storeys"][0]["rooms"][3].update(type="balcony"),
     "bathroom_0 is inside the outline"),
    (lambda d: (d["storeys"][0]["rooms"][3].update(type="balcony"),
                d["storeys"][0]["doors"][1].update(rooms=["kitchen_0", "bathroom_0"],
                                                   center=[6.75, 5.0])),
     "bathroom_0 is entered from ['kitchen_0'], not a living room or bedroom"),
    (lambda d: d.update(entrance={"room": "kitchen_0", "center": [10, 2.5]}),
     "front door opens into a kitchen"),
])
def test_what_a_person_would_question_is_reported(mutate, needle):
    assert any(needle in p for p in home_problems(_plan(mutate))), needle


def test_a_garage_with_a_vehicle_door_on_its_outside_wall_passes():
    fp = _plan(lambda d: _garage_with(d, {"room": "bedroom_1", "center": [10.0, 6.5],
                                          "width": 2.4, "height": 2.1}))
    assert not [p for p in home_problems(fp) if "bedroom_1" in p]


def test_required_counts_and_outline_are_checked():
    fp = _plan()
    problems = floorplan_problems(fp, [sg.box(0, 0, 10, 9)], counts={"bedroom": 3})
    assert any("differ from its outline" in p for p in problems)
    assert any("2 bedroom rooms, required 3" in p for p in problems)


def test_narrow_area():
    assert narrow_area(sg.box(0, 0, 4, 4), 1.2) == pytest.approx(0.0)
    assert narrow_area(sg.box(0, 0, 4, 1), 1.2) == pytest.approx(4.0)


# 2-storey home 5's upstairs hallway: a 1.5 m corridor and a 2.5 m lobby that meet only across
# one 0.5 m cell corner to corner; no part of it is narrow, but an agent cannot get from one
# part to the other
NECKED_HALL = sg.Polygon([(3.5, 7.0), (3.5, 10.5), (2.5, 10.5), (2.5, 12.5), (0.0, 12.5),
                          (0.0, 10.0), (2.0, 10.0), (2.0, 7.0)])


def test_a_neck_between_wide_parts_is_found_on_polygons_and_grids():
    assert narrow_area(NECKED_HALL, 1.2) < 0.01
    assert polygon_pieces(NECKED_HALL, 1.2) == 2
    assert polygon_pieces(sg.box(0, 0, 4, 1.5), 1.2) == 1
    cells = np.zeros((12, 8), bool)  # the same hall on the 0.5 m planning grid
    cells[0:7, 4:7] = True
    cells[6:11, 0:5] = True
    assert square_pieces(cells, 3) == 2
    cells[7:10, 5:7] = True  # widen the lobby over the corridor
    assert square_pieces(cells, 3) == 1
