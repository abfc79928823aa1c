"""Cardinality bounds: count constraints read into per-context bounds in the current state, and
the stage each context's objects are placed in."""
import math

from indoorgen.constraints import InLine, Problem, SupportedBy, scene
from indoorgen.constraints.bounds import context_of, find_bounds, static_stage, term_stage
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from support.dsl import at_table, base_view, on_floor, on_top, program, room


def test_cardinality_bounds_per_context_and_state_sensitive():
    v = base_view()
    v.add("t0", {S.Furniture, S.Table}, (2, 2, 0.4), relations=[(on_floor, "r")])
    v.add("t1", {S.Furniture, S.Table}, (5, 2, 0.4), relations=[(on_floor, "r")])
    v.add("c0", {S.Furniture, S.Chair}, (2, 3, 0.4), relations=[(on_floor, "r"), (at_table, "t0")])
    ev = Evaluator(program(room()), v)
    ev.evaluate()
    bounds = find_bounds(ev.problem, ev)
    per_table = [b for b in bounds if b.name == "chairs per table"]
    assert sorted((b.parents[1][1], b.count, b.lo, b.hi) for b in per_table) == [
        (("t0",), 1, 2, 4), (("t1",), 0, 2, 4)]
    assert all(S.Chair in b.context.tags and b.can_add and b.below for b in per_table)
    tables = [b for b in bounds if b.name == "tables"][0]
    assert (tables.count, tables.lo, tables.hi, tables.can_add, tables.can_delete) == (2, 1, 2, False, True)
    # chairs <= 4 * tables: an upper bound read from the current state
    cvt = [b for b in bounds if b.name == "chairs vs tables"][0]
    assert (cvt.lo, cvt.hi, cvt.count) == (0, 8, 1)
    cups = [b for b in bounds if b.name == "cups"]
    assert len(cups) == 2 and all(b.lo == 1 and b.hi == math.inf for b in cups)


def test_sum_of_counts_bounds_each_term_by_what_the_others_leave():
    """"a bath or a shower": (baths + showers) in [1, 2]. With neither present both may be
    added and both are below their share; once a bath exists, a shower is optional."""
    def prog(room):
        floor = scene().related_to(room, on_floor)
        baths, showers = floor[S.Bathtub], floor[S.Shower]
        return Problem(constraints={"wet": (baths.count() + showers.count()).in_range(1, 2),
                                    "at most 2": 2 >= baths.count() + showers.count()})  # noqa: SIM300
    v = base_view()
    ev = Evaluator(prog(room()), v)
    ev.evaluate()
    wet = [b for b in find_bounds(ev.problem, ev) if b.name == "wet"]
    assert [(sorted(t.value for t in b.context.tags), b.lo, b.hi, b.below) for b in wet] == [
        (["bathtub"], 1, 2, True), (["shower"], 1, 2, True)]
    v.add("b0", {S.Bathtub}, (1, 1, 0.3), relations=[(on_floor, "r")])
    ev.notify(added=["b0"])
    ev.evaluate()
    bounds = find_bounds(ev.problem, ev)
    bath, shower = [b for b in bounds if b.name == "wet"]
    assert (bath.count, bath.lo, bath.hi, bath.can_delete) == (1, 1, 2, False)
    assert (shower.count, shower.lo, shower.hi, shower.below, shower.can_add) == (0, 0, 1, False, True)
    cap = [b for b in bounds if b.name == "at most 2"]
    assert [(b.lo, b.hi) for b in cap] == [(0, 2), (-1, 1)]


def test_a_set_capped_by_one_constraint_is_not_grown_for_another():
    """"a bath or a shower" with showers barred by a second constraint (a compact shower in a
    large bathroom): only a bath may be added for it, though both are below their share."""
    def prog(room):
        floor = scene().related_to(room, on_floor)
        baths, showers = floor[S.Bathtub], floor[S.Shower]
        return Problem(constraints={"wet": (baths.count() + showers.count()).in_range(1, 2),
                                    "no shower": showers.count() <= 0})
    ev = Evaluator(prog(room()), base_view())
    ev.evaluate()
    wet = [b for b in find_bounds(ev.problem, ev) if b.name == "wet"]
    assert [(sorted(t.value for t in b.context.tags), b.below, b.can_add) for b in wet] == [
        (["bathtub"], True, True), (["shower"], True, False)]
    assert len({b.key for b in find_bounds(ev.problem, ev)}) == 2  # one key per counted set


def test_contexts_and_stages_of_set_chains():
    r = room()
    floor = scene().related_to(r, on_floor)
    tables = floor[S.Table].excluding(S.Desk)
    ctx = context_of(tables)
    assert ctx.tags == {S.Table} and ctx.excluded == {S.Desk} and len(ctx.relations) == 1
    assert context_of(tables | floor[S.Chair]) is None and context_of(r) is None
    plain_beds = floor.of_generator("bed", drawers=False)
    assert context_of(plain_beds).generator == "bed"
    assert context_of(plain_beds).params == (("drawers", False),)
    cups = scene()[S.Cup].related_to(tables, on_top)
    assert static_stage(tables) == "large" and static_stage(cups) == "small"
    assert static_stage(scene()[S.Cup]) is None
    assert term_stage(cups.count() + tables.count()) == "small"


def test_in_line_objects_are_placed_with_their_floor_standing_parent():
    floor = scene().related_to(room(), on_floor)
    sinks = floor[S.KitchenSink]
    beside = floor[S.KitchenCabinet].related_to(sinks, SupportedBy(Subpart.Side, Subpart.Side, 0.05))
    in_line = floor[S.KitchenCabinet].related_to(sinks, InLine(Subpart.Side, Subpart.Side, 0.05))
    assert static_stage(beside) == "medium" and static_stage(in_line) == "large"
