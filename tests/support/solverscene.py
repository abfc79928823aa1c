"""Small solver scenes for the solver's tests, built by hand: one rectangular room (wall_0 runs
along y = 0, its inner face looking +y), objects put on their planes directly, a move context
over a tiny program, and a check that a `State`'s indexes and broadphase agree with its objects."""
from __future__ import annotations

import numpy as np

from indoorgen.architecture.room import build_room, rectangle
from indoorgen.assets import get_factory
from indoorgen.assets.cache import AssetCache
from indoorgen.constraints import Problem, scene
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.model.frames import yaw_matrix
from indoorgen.model.scene import Door, Room
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import on_floor, on_top, on_wall
from indoorgen.solver.broadphase import world_boxes
from indoorgen.solver.moves import MoveContext
from indoorgen.solver.placement import solve_pose
from indoorgen.solver.stages import make_namer
from indoorgen.solver.state import ObjState, Placement, State

ROOM = "room_0"


def make_state(width: float = 4.0, depth: float = 3.0, doors: tuple[Door, ...] = ()) -> State:
    """An empty State of one `width` x `depth` room called `ROOM`."""
    room = Room(ROOM, "living_room", rectangle(width, depth), 2.7, 0.12, doors=list(doors))
    return State({ROOM: build_room(room)}, AssetCache())


def put(state: State, generator: str, placements: list[Placement], at: tuple[float, ...],
        yaw: float = 0.0, *, stage: str = "large", seed: int = 0, name: str | None = None) -> str:
    """Add a `generator` object (params drawn from `seed`) snapped onto its planes near `at`
    ((x, y) or (x, y, z))."""
    fac = get_factory(generator)
    params = fac.sample_params(np.random.default_rng(seed))
    asset = state.cache.placeholder(generator, params)
    name = name or f"{generator}_{len(state.objects)}"
    state.add(ObjState(name, generator, params, seed, frozenset(fac.tags), ROOM, stage, asset,
                       placements, np.zeros(3), 0.0))
    res = solve_pose(state, asset, placements, np.array([*at, 0.0][:3], float), yaw)
    assert res is not None, (generator, placements)
    state.set_pose(name, res[0], res[1])
    return name


def floor(child: str = "bottom") -> list[Placement]:
    """Standing on the room's floor."""
    return [Placement(on_floor, ROOM, child, "floor")]


def wall(i: int = 0) -> list[Placement]:
    """Hanging flat on wall `i`."""
    return [Placement(on_wall, ROOM, "back", f"wall_{i}")]


def top_of(parent: str, surface: str = "top") -> list[Placement]:
    """Resting on `parent`'s support surface."""
    return [Placement(on_top, parent, "bottom", surface)]


def table_program() -> Problem:
    """One or two tables on the floor, up to three plates on each, one or two pictures."""
    room = scene()[S.Room].named(ROOM)
    tables = scene().related_to(room, on_floor)[S.DiningTable]
    plates = scene()[S.Plate]
    art = scene()[S.WallArt].related_to(room, on_wall)
    return Problem(constraints={
        "tables": tables.count().in_range(1, 2),
        "plates": tables.all(lambda t: plates.related_to(t, on_top).count().in_range(0, 3)),
        "art": art.count().in_range(1, 2),
    })


def move_context(state: State, stage: str, seed: int = 0, problem: Problem | None = None,
                 temperature: float = 0.1) -> MoveContext:
    """A move context for `stage` of `ROOM` over `problem` (default: `table_program`)."""
    problem = problem or table_program()
    return MoveContext(state, problem, Evaluator(problem, state), ROOM, stage,
                       np.random.default_rng(seed), make_namer(), frozenset(problem.constraints),
                       init_tries=20, translate_sigma=2.0, rotate_sigma=6.0, temperature=temperature)


def snapshot(state: State) -> dict:
    """Everything a move may change, by object: pose, params, placements, stage."""
    return {n: (ob.position.tolist(), ob.yaw, repr(sorted(ob.params.items())),
                [(repr(p.relation), p.parent, p.child_surface, p.parent_surface)
                 for p in ob.placements], ob.stage)
            for n, ob in state.objects.items()}


def assert_consistent(state: State) -> None:
    """The state's indexes (ids, stage members, children) and each room's broadphase agree with
    the objects: every object's collision pieces are where its pose puts them."""
    assert state.all_ids() == frozenset(state.rooms) | frozenset(state.objects)
    stages = {(ob.room, ob.stage) for ob in state.objects.values()}
    for room, stage in stages:
        assert state.members(room, stage) == sorted(
            n for n, ob in state.objects.items() if (ob.room, ob.stage) == (room, stage))
    for parent in set(state.objects) | set(state.rooms):
        assert state.children(parent) == {n for n, ob in state.objects.items()
                                          if any(p.parent == parent for p in ob.placements)}
    for room, bp in state.broadphase.items():
        mine = {n for n, ob in state.objects.items() if ob.room == room}
        assert set(bp._pieces) == mine == set(bp._names)
        for n in mine:
            ob = state.objects[n]
            pieces, boxes, _, _ = bp._pieces[n]
            r = yaw_matrix(ob.yaw)
            np.testing.assert_allclose(boxes, world_boxes(ob.boxes, r, ob.position), atol=1e-12)
            for c in pieces:
                np.testing.assert_allclose(c.getTranslation(), ob.position, atol=1e-12)
                np.testing.assert_allclose(c.getRotation(), r, atol=1e-12)
            np.testing.assert_allclose(bp._union[bp._row[n]][:3], boxes[:, :3].min(axis=0))


def child_frame(state: State, child: str, parent: str) -> tuple[np.ndarray, float]:
    """Where `child` sits in `parent`'s frame (position, yaw): unchanged when a move carries it."""
    c, p = state.objects[child], state.objects[parent]
    return yaw_matrix(-p.yaw) @ (c.position - p.position), (c.yaw - p.yaw) % (2 * np.pi)
