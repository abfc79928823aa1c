"""Every DSL term evaluated through the expression graph against hand-computed values."""
import math

import pytest
import shapely.geometry as sg

from indoorgen.constraints import (
    Not,
    Problem,
    StableAgainst,
    accessibility_cost,
    angle_alignment_cost,
    area,
    center_of_support_distance,
    distance,
    focus_score,
    freespace_2d,
    height,
    min_distance,
    reflectional_asymmetry,
    rotational_asymmetry,
    scene,
    volume,
)
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.errors import ConstraintError, UnknownGeneratorError
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from support.fakeview import FakeView

on_floor = StableAgainst(Subpart.Bottom, Subpart.Floor)
at_table = StableAgainst(Subpart.Front, Subpart.Side, -0.08, overhang=False)


def value(view, node):
    return Evaluator(Problem(), view).value(node)


def dining_view(offset=0.0):
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


def test_sets_filter_union_difference_related():
    v = dining_view()
    v.add("sofa", {S.Furniture, S.Seating, S.Sofa}, (1, 4, 0.4), relations=[(on_floor, "r")])
    furn = scene()[S.Furniture]
    assert value(v, furn.count()) == 6
    assert value(v, furn[S.Chair].count()) == 4
    assert value(v, furn[Not(S.Chair)].count()) == 2
    assert value(v, furn.excluding(S.Chair, S.Sofa).count()) == 1
    assert value(v, (furn[S.Sofa] | furn[S.Table]).count()) == 2
    assert value(v, (furn - furn[S.Seating]).count()) == 1
    table = furn[S.DiningTable]
    assert value(v, furn.related_to(table, at_table).count()) == 4
    assert value(v, furn.related_to(scene()[S.Room], on_floor).count()) == 6
    assert value(v, scene()[S.Room].named("r").count()) == 1
    assert value(v, furn.related_to(table, ~at_table).count()) == 0


def test_rotational_asymmetry_zero_for_even_chairs_and_grows_when_one_moves():
    chairs = scene()[S.Chair]
    assert value(dining_view(), rotational_asymmetry(chairs)) == pytest.approx(0.0, abs=1e-9)
    a = value(dining_view(0.3), rotational_asymmetry(chairs))
    b = value(dining_view(0.6), rotational_asymmetry(chairs))
    assert 0 < a < b


def test_chairs_face_table_alignment_and_focus():
    v = dining_view()
    chairs, table = scene()[S.Chair], scene()[S.DiningTable]
    assert value(v, angle_alignment_cost(chairs, table)) == pytest.approx(0.0, abs=1e-9)
    assert value(v, focus_score(chairs, table)) == pytest.approx(0.0, abs=1e-9)
    v.move("chair0", yaw=0.0)  # chair0 at +x side now faces away: cost (1 - cos 180)/2 = 1
    assert value(v, angle_alignment_cost(chairs, table)) == pytest.approx(1.0)
    assert value(v, focus_score(chairs, table)) == pytest.approx(1.0)


def test_accessibility_blocker_in_front_costs_more_than_to_the_side():
    def cost(pos):
        v = FakeView()
        v.add("tv", {S.TV}, (0, 0, 1.0), yaw=0.0, extents=(0.1, 1.2, 0.7))
        v.add("box", {S.Furniture}, pos, extents=(0.6, 0.6, 0.6))
        return value(v, accessibility_cost(scene()[S.TV], scene()[S.Furniture]))
    front = cost((2.05, 0.0, 1.0))
    side = cost((0.05 + 2 * math.cos(0.8), 2 * math.sin(0.8), 1.0))
    behind = cost((-2.0, 0.0, 1.0))
    diag = math.sqrt(3 * 0.36)
    # the TV's front plane is x = 0.05; blocker 2 m ahead: cost = 2 / 2^2 * diag
    assert front == pytest.approx(diag / 2)
    assert 0 < side < front
    assert behind == 0.0
    slow = FakeView()
    slow.add("tv", {S.TV}, (0, 0, 1.0), extents=(0.1, 1.2, 0.7))
    slow.add("box", {S.Furniture}, (2.05, 0.0, 1.0), extents=(0.6, 0.6, 0.6))
    assert value(slow, accessibility_cost(scene()[S.TV], scene()[S.Furniture], fast=False)) > front


def test_sizes_distances_and_support():
    v = FakeView()
    v.add_room("r", [(0, 0), (4, 0), (4, 3), (0, 3)])
    v.add("a", {S.Furniture}, (1, 1, 0.5), extents=(1, 2, 0.5))
    v.add("b", {S.Furniture}, (3, 1, 0.5), extents=(1, 1, 1))
    v.add("p", {S.Plate}, (1.2, 1.0, 0.76), extents=(0.2, 0.2, 0.02),
          support=sg.box(0.5, 0.0, 1.5, 2.0))
    f = scene()[S.Furniture]
    assert value(v, volume(f)) == pytest.approx(1.0 + 1.0)
    assert value(v, volume(f, dims=(0, 1))) == pytest.approx(2.0 + 1.0)
    assert value(v, area(f)) == pytest.approx(2 * 1 + 1 * 1)
    assert value(v, distance(f[S.Furniture].named("a"), scene().named("b"))) == pytest.approx(1.0)
    assert value(v, distance(scene().named("b"), scene()[S.Room])) == pytest.approx(0.5)
    assert value(v, min_distance(scene().named("a"), scene().named("b"))) == pytest.approx(1.0)
    assert value(v, freespace_2d(scene().named("a"), scene()[S.Plate])) == pytest.approx(2 - 0.04)
    assert value(v, center_of_support_distance(scene()[S.Plate])) == pytest.approx(0.2)
    assert value(v, height(scene().named("b"))) == pytest.approx(0.5)


def test_reflectional_asymmetry_of_nightstands():
    v = FakeView()
    v.add("bed", {S.Furniture}, (0, 0, 0.3), yaw=0.0, extents=(2, 1.6, 0.6))
    v.add("n1", {S.SideTable}, (-0.7, 1.1, 0.3), yaw=0.0, extents=(0.4, 0.4, 0.5))
    v.add("n2", {S.SideTable}, (-0.7, -1.1, 0.3), yaw=0.0, extents=(0.4, 0.4, 0.5))
    term = reflectional_asymmetry(scene()[S.SideTable], scene().named("bed"))
    assert value(v, term) == pytest.approx(0.0, abs=1e-9)
    v.move("n2", center=(0.2, -1.1, 0.3))
    assert value(v, term) > 0.0


def test_arithmetic_and_constraint_degrees():
    v = dining_view()
    n = scene()[S.Chair].count()  # 4
    assert value(v, n + 1) == 5 and value(v, 2 * n - 1) == 7 and value(v, n / 2) == 2
    assert value(v, n ** 2) == 16 and value(v, abs(n - 10)) == 6 and value(v, -n) == -4
    assert value(v, (n - 4).safediv(0, default=7.0)) == 7.0
    assert value(v, n.log()) == pytest.approx(math.log(4))
    assert value(v, n.clip(0, 3)) == 3
    assert value(v, n.hinge(1, 2)) == 2 and value(v, n.hinge(6, 8)) == 2 and value(v, n.hinge(3, 5)) == 0
    assert value(v, n.in_range(2, 3)) == 1.0 and value(v, n.in_range(4, 8)) == 0.0
    assert value(v, n <= 2) == 2 and value(v, n >= 6) == 2 and value(v, n == 4) == 0
    assert value(v, n < 4) > 0 and value(v, n > 3) == 0
    assert value(v, (n <= 2) & (n >= 6)) == 4
    assert value(v, (n <= 2) | (n >= 6)) == 2
    assert value(v, ~(n == 4)) == 1.0 and value(v, ~(n == 3)) == 0.0
    tables = scene()[S.DiningTable]
    chairs = scene()[S.Chair]
    assert value(v, tables.all(lambda t: chairs.related_to(t, at_table).count().in_range(6, 8))) == 2
    assert value(v, chairs.sum(lambda c: c.count())) == 4
    assert value(v, chairs.mean(lambda c: height(c))) == pytest.approx(0.45)
    # chair centre 1 m from the table centre: 1 - 0.6 (table half) - 0.25 (chair half depth)
    assert value(v, chairs.max(lambda c: c.distance(tables))) == pytest.approx(0.15, abs=1e-6)


def test_bad_programs_raise_constraint_errors():
    n = scene().count()
    with pytest.raises(ConstraintError, match="in_range"):
        n.in_range(5, 2)
    with pytest.raises(ConstraintError):
        n.hinge(3, 1)
    with pytest.raises(ConstraintError):
        Problem(constraints={"x": n})
    with pytest.raises(ConstraintError):
        Problem(score_terms={"x": n})
    with pytest.raises(UnknownGeneratorError, match="no_such_thing"):
        scene().of_generator("no_such_thing")


def test_problem_result_loss_and_violations():
    v = dining_view()
    chairs = scene()[S.Chair]
    p = Problem(constraints={"few": chairs.count() <= 3, "ok": chairs.count() >= 1},
                score_terms={"many": chairs.count().maximize(2.0),
                             "sym": rotational_asymmetry(chairs).minimize(1.0)})
    r = Evaluator(p, v).evaluate()
    assert r.violations == {"few": 1.0, "ok": 0.0}
    assert r.n_violated == 1 and r.violation == 1.0
    assert r.loss == pytest.approx(-8.0)
