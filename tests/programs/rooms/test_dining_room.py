"""The dining room program: a small room seats two, a room for four seats four."""
from __future__ import annotations

import pytest

from indoorgen.constraints import scene
from indoorgen.constraints.bounds import find_bounds
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import on_floor
from indoorgen.programs.rooms.dining_room import dining_room
from support.fakeview import FakeView


@pytest.mark.parametrize("size, chairs", [((2.4, 2.9), 2), ((3.0, 3.4), 4), ((4.0, 4.5), 4)])
def test_the_chairs_asked_for_follow_the_room(size, chairs):
    w, d = size
    view = FakeView()
    view.add_room("r", [(0, 0), (w, 0), (w, d), (0, d)])
    view.add("table_0", {S.Object, S.Furniture, S.Table, S.DiningTable},
             center=(w / 2, d / 2, 0.375), extents=(0.9, 1.2, 0.75),
             relations=[(on_floor, "r")], generator="dining_table_rect", params={})
    problem = dining_room(scene()[S.Room].named("r"))
    bounds = [b for b in find_bounds(problem, Evaluator(problem, view))
              if b.name.startswith(("chairs at each table", "four chairs"))]
    assert max(b.lo for b in bounds) == chairs
