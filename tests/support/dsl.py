"""Shared pieces of the constraint DSL tests: relations, a dining room view, and evaluating one
node from scratch."""
from __future__ import annotations

import math

from indoorgen.constraints import (
    Problem,
    StableAgainst,
    accessibility_cost,
    focus_score,
    rotational_asymmetry,
    scene,
)
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from support.fakeview import FakeView

on_floor = StableAgainst(Subpart.Bottom, Subpart.Floor)
at_table = StableAgainst(Subpart.Front, Subpart.Side, -0.08, overhang=False)
on_top = StableAgainst(Subpart.Bottom, Subpart.SupportSurface, overhang=False)


def value(view, node):
    """`node`'s value over `view`, from a fresh evaluator."""
    return Evaluator(Problem(), view).value(node)


def dining_view(offset=0.0):
    """A 6 x 5 m room "r" with a square table and four chairs facing it, one per side; chair0
    shifted by `offset` along x."""
    v = FakeView()
    v.add_room("r", [(0, 0), (6, 0), (6, 5), (0, 5)])
    v.add("table", {S.Furniture, S.Table, S.DiningTable}, (3, 2.5, 0.375), extents=(1.2, 1.2, 0.75),
          relations=[(on_floor, "r")])
    spots = [(1, 0), (0, 1), (-1, 0), (0, -1)]
    for i, (dx, dy) in enumerate(spots):
        yaw = math.atan2(-dy, -dx)
        x = 3 + dx + (offset if i == 0 else 0.0)
        v.add(f"chair{i}", {S.Furniture, S.Seating, S.Chair, S.DiningChair}, (x, 2.5 + dy, 0.45),
              yaw=yaw, extents=(0.5, 0.45, 0.9), relations=[(on_floor, "r"), (at_table, "table")])
    return v


def program(room):
    """Tables on the floor with chairs pulled up and cups on them: counts, quantified counts, a
    count bounded by another count, and per-object and set-level score terms."""
    furniture = scene()[S.Furniture].related_to(room, on_floor)
    tables, chairs = furniture[S.Table], furniture[S.Chair]
    cups = scene()[S.Cup]
    return Problem(
        constraints={
            "tables": tables.count().in_range(1, 2),
            "chairs per table": tables.all(lambda t: chairs.related_to(t, at_table).count().in_range(2, 4)),
            "cups": tables.all(lambda t: cups.related_to(t, on_top).count() >= 1),
            "chairs vs tables": chairs.count() <= tables.count() * 4,
        },
        score_terms={
            "sym": tables.mean(lambda t: rotational_asymmetry(chairs.related_to(t, at_table))).minimize(2),
            "face": focus_score(chairs, tables).minimize(1),
            "access": accessibility_cost(tables, furniture - tables).minimize(1),
            "near": chairs.sum(lambda c: c.distance(tables).hinge(0, 0.1)).minimize(1),
        },
    )


def base_view():
    """An empty 8 x 6 m room "r"."""
    v = FakeView()
    v.add_room("r", [(0, 0), (8, 0), (8, 6), (0, 6)])
    return v


def room():
    """The set holding room "r"."""
    return scene()[S.Room].named("r")
