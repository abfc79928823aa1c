"""The staged solve: every room in name order, each large -> medium -> small, one evaluator per
room; objects are named per generator in creation order; a seed gives the same scene."""
from __future__ import annotations

import pytest

from indoorgen.architecture.room import build_room, rectangle
from indoorgen.assets.cache import AssetCache
from indoorgen.constraints import Problem, scene
from indoorgen.model.scene import Room
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import on_floor, on_top, on_wall
from indoorgen.solver import stages
from indoorgen.solver.stages import DEFAULT_STEPS, STAGES, make_namer, solve
from indoorgen.solver.state import State
from support.solverscene import ROOM, assert_consistent, make_state, snapshot, table_program

FEW = {"large": 40, "medium": 40, "small": 40}


def test_stages_run_large_then_medium_then_small():
    assert STAGES == ("large", "medium", "small")
    assert set(DEFAULT_STEPS) == set(STAGES)


def test_every_room_is_solved_stage_by_stage_in_room_order():
    rooms = {"b_room": build_room(Room("b_room", "living_room", rectangle(4.0, 3.0))),
             "a_room": build_room(Room("a_room", "living_room", rectangle(4.0, 3.0)))}
    st = State(rooms, AssetCache())
    stats, evaluators = solve(st, {"b_room": _program("b_room"), "a_room": _program("a_room")},
                              seed=1, steps=FEW)
    assert [(s.room, s.stage) for s in stats] == [
        (r, s) for r in ("a_room", "b_room") for s in STAGES]
    assert set(evaluators) == {"a_room", "b_room"}
    assert_consistent(st)


def _program(room: str) -> Problem:
    """A table with a plate or two, one picture."""
    r = scene()[S.Room].named(room)
    tables = scene().related_to(r, on_floor)[S.DiningTable]
    return Problem(constraints={
        "a table": tables.count() == 1,
        "plates": tables.all(lambda t: scene()[S.Plate].related_to(t, on_top).count().in_range(1, 2)),
        "art": scene()[S.WallArt].related_to(r, on_wall).count().in_range(1, 1),
    })


def test_each_stage_places_its_own_kind_of_object():
    st = make_state(5.0, 4.0)
    stats, _ = solve(st, {ROOM: table_program()}, seed=2, steps=FEW)
    by_stage = {s.stage: s for s in stats}
    assert all(by_stage[s].violation == 0.0 for s in STAGES)
    stage_of = {tag: ob.stage for ob in st.objects.values() for tag in (S.DiningTable, S.WallArt, S.Plate)
                if tag in ob.tags}
    assert stage_of[S.DiningTable] == "large" and stage_of[S.WallArt] == "medium"
    assert stage_of.get(S.Plate, "small") == "small"
    for ob in st.objects.values():
        parents = {p.parent for p in ob.placements}
        if ob.stage == "small":  # on other objects, placed by an earlier stage
            assert parents and all(st.objects[p].stage == "large" for p in parents)
        else:
            assert parents == {ROOM}


def test_a_seed_gives_the_same_solve():
    runs = []
    for _ in range(2):
        st = make_state(5.0, 4.0)
        stats, _ = solve(st, {ROOM: table_program()}, seed=11, steps=FEW)
        runs.append((snapshot(st), [(s.steps, s.accepted, s.proposed) for s in stats]))
    assert runs[0] == runs[1]


def test_make_namer_counts_per_generator_in_creation_order():
    name = make_namer()
    assert [name("cup"), name("plate"), name("cup"), name("cup")] == ["cup_0", "plate_0", "cup_1",
                                                                       "cup_2"]
    assert make_namer()("cup") == "cup_0"  # each namer counts afresh


def test_rooms_are_solved_apart_and_named_as_one_namer_would():
    """Each room is solved in a state holding no other room's objects, with its own namer; the
    merge then numbers every generator's objects room after room, so names stay unique."""
    rooms = {r: build_room(Room(r, "living_room", rectangle(4.0, 3.0))) for r in ("a_room", "b_room")}
    st = State(rooms, AssetCache())
    solve(st, {r: _program(r) for r in rooms}, seed=3, steps=FEW)
    alone = State({"b_room": rooms["b_room"]}, AssetCache())
    solve(alone, {"b_room": _program("b_room")}, seed=3, steps=FEW)
    assert_consistent(st)
    # b_room's solution does not depend on a_room: the same poses as when solved alone
    poses = sorted((o.generator, tuple(o.position.round(9)), o.yaw)
                   for o in st.objects.values() if o.room == "b_room")
    assert poses == sorted((o.generator, tuple(o.position.round(9)), o.yaw)
                           for o in alone.objects.values())
    by_gen: dict[str, list[int]] = {}
    for name, ob in st.objects.items():
        assert name.startswith(ob.generator + "_")
        by_gen.setdefault(ob.generator, []).append(int(name.rpartition("_")[2]))
        for p in ob.placements:  # parents renamed with their children
            assert p.parent in st.rooms or st.objects[p.parent].room == ob.room
    assert all(len(set(ns)) == len(ns) for ns in by_gen.values())


def test_a_stage_left_unmet_starts_the_room_again_and_the_last_solve_runs_every_stage(
        monkeypatch):
    # two dining tables in a 1.6 x 1.6 m room: the large stage can never meet it
    room = scene()[S.Room].named(ROOM)
    tables = scene().related_to(room, on_floor)[S.DiningTable]
    problem = Problem(constraints={
        "two tables": tables.count() == 2,
        "art": scene()[S.WallArt].related_to(room, on_wall).count().in_range(1, 1)})
    solved: list[tuple[str, int]] = []  # (stage, the room's solve it belongs to)
    real_repair = stages.repair_stage

    def repair(*args, **kwargs):
        solved.append((args[4], args[-1]))
        return real_repair(*args, **kwargs)

    monkeypatch.setattr(stages, "repair_stage", repair)
    stats, _ = solve(make_state(1.6, 1.6), {ROOM: problem}, seed=3, steps=FEW)
    last = stages.ROOM_ATTEMPTS - 1
    # every solve stops at its unmet large stage but the last, which runs every stage; each
    # solve's repairs draw their own random streams (the solve's number)
    assert solved == [("large", k) for k in range(last)] + [(s, last) for s in STAGES]
    assert [s.stage for s in stats] == list(STAGES)
    assert stats[0].violation > 0


def test_giving_up_stops_at_the_first_room_left_unmet_naming_its_constraints(monkeypatch):
    # five dining tables in a 1.6 x 1.6 m room can never stand (two small ones can, built by
    # the repair's constructive passes); the other room is fine. However many times the room
    # is solved again it stays unmet, so three solves tell what ten would
    monkeypatch.setattr(stages, "ROOM_ATTEMPTS", 3)
    rooms = {"a_room": build_room(Room("a_room", "living_room", rectangle(1.6, 1.6))),
             "b_room": build_room(Room("b_room", "living_room", rectangle(4.0, 3.0)))}
    r = scene()[S.Room].named("a_room")
    impossible = Problem(constraints={
        "five tables": scene().related_to(r, on_floor)[S.DiningTable].count() == 5})
    problems = {"a_room": impossible, "b_room": _program("b_room")}
    tiny = {"large": 20, "medium": 5, "small": 5}
    with pytest.raises(stages.RoomUnmet) as caught:
        solve(State(rooms, AssetCache()), problems, seed=3, steps=tiny, give_up=True)
    assert caught.value.solution.room == "a_room"
    assert [line.split(" violated")[0] for line in caught.value.reasons()] == [
        "room a_room: hard constraint five tables"]
    # without giving up every room is solved, and the unmet one recorded as unmet
    stats, evaluators = solve(State(rooms, AssetCache()), problems, seed=3, steps=tiny)
    assert {s.room for s in stats} == {"a_room", "b_room"}
    assert evaluators["a_room"].evaluate().violations["five tables"] > 0
