"""What every room program asks of its ceiling lights: headroom over the floor, and in a dining
room, the light hung over the table's middle (where it may hang lower)."""
from __future__ import annotations

import pytest

from indoorgen.constraints import scene
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.tags import Semantics as S
from indoorgen.programs import ROOM_PROGRAMS, get_program
from indoorgen.programs.relations import on_ceiling, on_floor
from support.fakeview import FakeView

PENDANT_HEIGHT = 0.9


def _room_with_a_pendant(bottom: float, light_xy=(2.0, 2.0), table_xy=None) -> tuple:
    view = FakeView()
    view.add_room("r", [(0, 0), (4, 0), (4, 4), (0, 4)])
    view.add("pendant_0", {S.Object, S.Lighting, S.CeilingMounted, S.PendantLight},
             center=(*light_xy, bottom + PENDANT_HEIGHT / 2), extents=(0.4, 0.4, PENDANT_HEIGHT),
             relations=[(on_ceiling, "r")])
    if table_xy is not None:
        view.add("table_0", {S.Object, S.Furniture, S.Table, S.DiningTable},
                 center=(*table_xy, 0.375), extents=(1.6, 0.9, 0.75), relations=[(on_floor, "r")])
    return view, scene()[S.Room].named("r")


@pytest.mark.parametrize("room_type", sorted(ROOM_PROGRAMS))
def test_every_room_keeps_its_lights_clear_of_heads(room_type):
    view, room = _room_with_a_pendant(1.3)
    violations = Evaluator(get_program(room_type)(room), view).evaluate().violations
    assert violations["lights clear of heads"] > 0  # 1.3 m: under every room's least height
    view, room = _room_with_a_pendant(2.05)
    violations = Evaluator(get_program(room_type)(room), view).evaluate().violations
    assert violations["lights clear of heads"] == 0


@pytest.mark.parametrize("light_xy,bottom,over_ok,height_ok", [
    ((2.0, 2.0), 1.6, True, True),     # over the table's middle, low: a dining pendant
    ((2.0, 3.5), 2.05, False, True),   # over the floor beside the table
    ((2.0, 2.0), 1.3, True, False),    # over the table, but low enough to knock
])
def test_the_dining_light_hangs_over_the_table(light_xy, bottom, over_ok, height_ok):
    view, room = _room_with_a_pendant(bottom, light_xy, table_xy=(2.0, 2.0))
    violations = Evaluator(get_program("dining_room")(room), view).evaluate().violations
    assert (violations["the light over the table"] == 0) == over_ok
    assert (violations["lights clear of heads"] == 0) == height_ok
