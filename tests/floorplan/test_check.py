"""Independent checks of a floorplan (indoorgen.floorplan.check) on broken copies of a sound
hand-drawn plan."""
from __future__ import annotations

import pytest
import shapely.geometry as sg

from indoorgen.floorplan.check import floorplan_problems, narrow_area
from indoorgen.model.floorplan import Floorplan
from indoorgen.model.floorplan_io import from_json
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
])
def test_broken_plans_are_reported(mutate, needle):
    assert any(needle in p for p in floorplan_problems(_plan(mutate))), needle


def test_required_counts_and_outline_are_checked():
    fp = _plan()
    problems = floorplan_problems(fp, [sg.box(0, 0, 10, 9)], counts={"bedroom": 3})
    assert any("differ from its outline" in p for p in problems)
    assert any("2 bedroom rooms, required 3" in p for p in problems)


def test_narrow_area():
    assert narrow_area(sg.box(0, 0, 4, 4), 1.2) == pytest.approx(0.0)
    assert narrow_area(sg.box(0, 0, 4, 1), 1.2) == pytest.approx(4.0)
