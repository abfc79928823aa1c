"""Every built-in room program: a `Problem` whose object sets name things some generator makes,
which evaluates on an empty room (every lower count bound violated, nothing else wrong)."""
import math

import pytest

from indoorgen.assets import factories_with, factory_names
from indoorgen.constraints import Problem, scene
from indoorgen.constraints.bounds import STAGE_ORDER, context_of, find_bounds, term_stage
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.constraints.node import Node
from indoorgen.errors import UnknownRoomTypeError
from indoorgen.model.tags import Semantics as S
from indoorgen.pipeline import GenerateConfig, generate
from indoorgen.programs import ROOM_PROGRAMS, get_program
from indoorgen.quality.layout import quality_report
from support.fakeview import FakeView


def _nodes(problem: Problem) -> list[Node]:
    """Every node reachable from the problem's constraints and score terms."""
    seen, out = set(), []
    stack = list(problem.constraints.values()) + [t.expr for t in problem.score_terms.values()]
    while stack:
        n = stack.pop()
        if n.uid not in seen:
            seen.add(n.uid)
            out.append(n)
            stack.extend(n.children)
    return out


def _empty_room():
    view = FakeView()
    view.add_room("r", [(0, 0), (5, 0), (5, 4), (0, 4)])
    return view, scene()[S.Room].named("r")


@pytest.mark.parametrize("room_type", sorted(ROOM_PROGRAMS))
def test_program_sets_name_real_generators(room_type):
    _, room = _empty_room()
    problem = get_program(room_type)(room)
    assert isinstance(problem, Problem) and problem.constraints and problem.score_terms
    names = set(factory_names())
    contexts = [c for c in map(context_of, _nodes(problem)) if c is not None and c.tags]
    assert contexts
    for ctx in contexts:
        makers = factories_with(ctx.tags, ctx.excluded)
        assert makers, f"{room_type}: no generator is {sorted(t.value for t in ctx.tags)}"
        if ctx.generator is not None:
            assert ctx.generator in names and ctx.generator in makers


@pytest.mark.parametrize("room_type", sorted(ROOM_PROGRAMS))
def test_program_evaluates_on_an_empty_room(room_type):
    view, room = _empty_room()
    problem = get_program(room_type)(room)
    ev = Evaluator(problem, view)
    result = ev.evaluate()
    assert set(result.violations) == set(problem.constraints)
    assert set(result.scores) == set(problem.score_terms)
    assert all(math.isfinite(x) for x in [*result.violations.values(), *result.scores.values()])
    # an empty room only misses what it must hold: each violated constraint has a count bound
    bounds = find_bounds(problem, ev)
    below = {b.name for b in bounds if b.below}
    assert {n for n, x in result.violations.items() if x > 0} <= below
    assert any(b.can_add for b in bounds)


def test_unknown_room_type_lists_the_valid_ones():
    with pytest.raises(UnknownRoomTypeError, match="bedroom"):
        get_program("ballroom")


@pytest.mark.parametrize("room_type", sorted(ROOM_PROGRAMS))
def test_every_count_is_enforced_in_the_stage_that_adds_its_objects(room_type):
    """A count whose objects are added in one stage but which only counts from a later one is
    never met (its objects can no longer be added): a wall accessory's set chained wall-first,
    then pinned to a height over the floor, once was."""
    view, room = _empty_room()
    problem = get_program(room_type)(room)
    ev = Evaluator(problem, view)
    rooms = frozenset({"r"})
    for b in find_bounds(problem, ev):
        if not all(ps and set(ps) <= rooms for _, ps in b.parents):
            continue  # placed on objects: none exist in an empty room to judge the stage by
        active = term_stage(problem.constraints[b.name])
        assert STAGE_ORDER[active] <= STAGE_ORDER[b.stage(rooms)], (b.name, active, b.stage(rooms))


#: the arrangement rules each rewritten room program is written to meet (quality/arrangement.py)
ARRANGED = {
    "living_room": ("tv_faces_seating", "coffee_table_in_front_of_sofa"),
    "bedroom": ("nightstand_by_bed", "bed_head_to_wall", "matching_sets"),
    "dining_room": ("dining_chairs_face_table", "matching_sets"),
}


@pytest.mark.slow
@pytest.mark.parametrize("room_type", sorted(ARRANGED))
def test_furnished_rooms_meet_their_arrangement_rules(room_type):
    """A user's `generate --room TYPE`: the room holds what its program names, arranged as the
    quality report's layout rules measure it, with every hard constraint met."""
    g = generate(2, GenerateConfig(room_type=room_type))
    assert all(r.violation == 0 for r in g.results.values())
    rules = quality_report(g.scene, g.rooms, g.cache, g.architecture)["rules"]
    for name in ARRANGED[room_type] + ("front_clearance", "reach", "joint_sweep"):
        assert rules[name]["passed"] == rules[name]["checked"], (name, rules[name]["instances"])
    for name in ARRANGED[room_type]:
        # a bedroom with one nightstand is a fine bedroom: it has no set to match
        assert rules[name]["checked"] > 0 or name == "matching_sets" and room_type == "bedroom", name
