"""The bedroom program (`programs.rooms.bedroom`): what a larger bedroom must hold."""
from __future__ import annotations

import pytest

from indoorgen.constraints import scene
from indoorgen.constraints.bounds import find_bounds, term_stage
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, at_bedside, on_floor, on_wall
from indoorgen.programs.rooms.bedroom import BOOKCASE_AREA, WARDROBE_AREA, bedroom
from support.fakeview import FakeView


@pytest.mark.parametrize("width,depth", [(3.0, 3.0), (3.5, 4.0), (4.5, 4.0), (2.3, 5.3)])
def test_a_larger_bedroom_asks_for_a_wardrobe_and_a_bookcase_once_the_bed_stands(width, depth):
    view = FakeView()
    view.add_room("r", [(0, 0), (width, 0), (width, depth), (0, depth)])
    room = scene()[S.Room].named("r")
    problem = bedroom(room)
    # nothing is asked for before the bed stands (the bed comes first)
    assert not {b.name for b in find_bounds(problem, Evaluator(problem, view))} & {
        "a wardrobe in a larger room", "a bookcase in a larger room"}
    view.add("bed_0", {S.Object, S.Furniture, S.Bed}, center=(1, 1, 0.3), extents=(2, 1.6, 0.6),
             relations=[(on_floor, "r"), (against_wall, "r")], generator="bed",
             params={"drawers": False})
    problem = bedroom(room)
    bounds = {b.name: b for b in find_bounds(problem, Evaluator(problem, view))}
    for name, area in (("a wardrobe in a larger room", WARDROBE_AREA),
                       ("a bookcase in a larger room", BOOKCASE_AREA)):
        b = bounds[name]
        assert b.below == (width * depth > area), name
        assert b.can_add


def test_the_large_furnitures_fronts_are_kept_free_while_the_large_stage_places_it():
    """A constraint counts from the stage of its latest set on: the dresser's, desk's and
    bookcase's fronts must not wait for the nightstands (medium) to be checked."""
    view = FakeView()
    view.add_room("r", [(0, 0), (4.5, 0), (4.5, 4), (0, 4)])
    problem = bedroom(scene()[S.Room].named("r"))
    assert term_stage(problem.constraints["storage fronts free"]) == "large"
    assert term_stage(problem.constraints["room for the desk's chair"]) == "large"
    assert term_stage(problem.constraints["nightstand fronts free"]) == "medium"


def _room_with_bed(width: float, x: float) -> FakeView:
    """A `width` x 4 m room "r" with a bed against a wall, centred at (x, 1)."""
    view = FakeView()
    view.add_room("r", [(0, 0), (width, 0), (width, 4), (0, 4)])
    view.add("bed_0", {S.Object, S.Furniture, S.Bed}, center=(x, 1, 0.3), extents=(2, 1.6, 0.6),
             relations=[(on_floor, "r"), (against_wall, "r")], generator="bed",
             params={"drawers": False})
    return view


def test_the_walls_ask_for_a_shelf():
    view = _room_with_bed(3.5, 1)
    problem = bedroom(scene()[S.Room].named("r"))
    bounds = {b.name: b for b in find_bounds(problem, Evaluator(problem, view))}
    assert bounds["a wall shelf or two"].below and bounds["a wall shelf or two"].can_add
    # a nightstand is wished for (a score term), not required: some beds have no room at the head
    assert not bounds["up to two nightstands at the head"].below


def test_a_desk_asks_for_its_chair_and_a_nightstand_for_its_lamp():
    view = _room_with_bed(4.5, 2)
    view.add("nightstand_0", {S.Object, S.Furniture, S.Nightstand}, center=(0.8, 0.2, 0.25),
             extents=(0.4, 0.4, 0.5), relations=[(on_floor, "r"), (against_wall, "r"),
                                                 (at_bedside, "bed_0")])
    view.add("desk_0", {S.Object, S.Furniture, S.Desk}, center=(4.2, 3, 0.37),
             extents=(0.6, 1.2, 0.75), relations=[(on_floor, "r"), (against_wall, "r")])
    problem = bedroom(scene()[S.Room].named("r"))
    bounds = {b.name: b for b in find_bounds(problem, Evaluator(problem, view))}
    for name in ("a chair at the desk", "a lamp on each nightstand"):
        assert bounds[name].below and bounds[name].can_add, name


@pytest.mark.parametrize("z,ok", [(1.6, True), (1.45, True), (2.3, False), (1.0, False)])
def test_pictures_hang_centred_at_eye_level(z, ok):
    view = FakeView()
    view.add_room("r", [(0, 0), (4.5, 0), (4.5, 4), (0, 4)])
    view.add("art_0", {S.Object, S.WallArt}, center=(3, 0.02, z), extents=(0.03, 0.5, 0.5),
             relations=[(on_wall, "r")])
    problem = bedroom(scene()[S.Room].named("r"))
    rule = problem.constraints["pictures and the mirror centred at eye level"]
    assert (Evaluator(problem, view).value(rule) == 0) == ok
