"""The staged solve (Infinigen Indoors, algorithm 1): per room, anneal the large objects, then the
medium, then the small; each stage sees earlier stages' objects as fixed. Every room's program
gets the circulation constraint here (`solver.circulation`), so every room keeps a walkway.

Rooms are solved independently: each with its own random streams and its own namer, in a state
holding no other room's objects (walls keep rooms apart), so a room's solution never depends on
another's and rooms may be solved in any order or in parallel (`solver.workers`). Once all are
solved, `merge` names every object as one namer counting room after room (in name order) would
have, and puts them back into the state.
"""
from __future__ import annotations

import logging
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field, replace

from tqdm import tqdm

from indoorgen.constraints.bounds import STAGE_ORDER
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.constraints.problem import Problem
from indoorgen.rng import stream
from indoorgen.solver.anneal import AnnealConfig, Annealer, StageStats
from indoorgen.solver.circulation import with_circulation
from indoorgen.solver.repair import own_violation, repair_stage
from indoorgen.solver.state import ObjState, State
from indoorgen.solver.window_dressing import dress_windows

log = logging.getLogger(__name__)

#: the stages in the order they run (large furniture first, so smaller things find it in place)
STAGES = tuple(STAGE_ORDER)
#: annealing steps per stage when the caller gives none
DEFAULT_STEPS = {"large": 350, "medium": 300, "small": 450}
#: solves of a room tried while a hard constraint stays unmet after a stage and its repairs
#: (a medium-stage requirement can hinge on where the large stage put furniture: chairs around
#: a table too near a wall); the best kept, a room none satisfies reported failed. A solve
#: whose stage leaves one of its own requirements unmet stops there (later stages cannot meet
#: it) and the next begins, so most of these cost one stage (a kitchen whose large stage left
#: no place for the fridge); the last always runs every stage
ROOM_ATTEMPTS = 10
#: of those, the most that run every stage and still miss a requirement (a small-stage miss
#: costs a whole solve) before the best is kept
FULL_SOLVES = 3


def make_namer(counts: dict[str, int] | None = None) -> Callable[[str], str]:
    """Names objects `<generator>_<n>`, counting per generator in the order they are created
    (into `counts`, if given, so the caller can read how many names each generator took)."""
    counts = {} if counts is None else counts

    def name(generator: str) -> str:
        counts[generator] = counts.get(generator, 0) + 1
        return f"{generator}_{counts[generator] - 1}"
    return name


@dataclass
class RoomSolution:
    """One room solved on its own: its stages' stats, its objects (names from the room's own
    namer, no collision pieces: they can cross a process boundary), how many names its namer
    gave per generator (deleted objects' names included) and the hard constraints its solve
    left unmet (by name: how far)."""

    room: str
    stats: list[StageStats]
    objects: list[ObjState]
    named: dict[str, int]
    unmet: dict[str, float] = field(default_factory=dict)


class RoomUnmet(Exception):
    """A room's solve left hard constraints unmet (`solve(..., give_up=True)` stops there)."""

    def __init__(self, solution: RoomSolution) -> None:
        super().__init__(f"room {solution.room}: {len(solution.unmet)} hard constraints unmet")
        self.solution = solution

    def reasons(self) -> list[str]:
        """One line per unmet constraint, worded as report.json's `status` words them."""
        return [f"room {self.solution.room}: hard constraint {name} violated ({value:.3g})"
                for name, value in sorted(self.solution.unmet.items())]


def first_unmet(solutions: Iterable[RoomSolution]) -> RoomSolution | None:
    """The first room (in name order) whose solve left a hard constraint unmet, if any."""
    return next((s for s in sorted(solutions, key=lambda s: s.room) if s.unmet), None)


def solve_room(state: State, room: str, problem: Problem, seed: int, *,
               config: AnnealConfig | None = None, steps: dict[str, int] | None = None
               ) -> RoomSolution:
    """Solve one room's problem (circulation added), stage by stage, then take its objects out
    of `state` (which must hold no object of this room to start with) into the solution."""
    config = config or AnnealConfig()
    problem = with_circulation(problem, room)
    steps = {**DEFAULT_STEPS, **(steps or {})}
    named: dict[str, int] = {}
    namer = make_namer(named)
    best: tuple[list[StageStats], list[ObjState], dict[str, float]] | None = None
    full = 0
    for attempt in range(ROOM_ATTEMPTS):
        last = attempt == ROOM_ATTEMPTS - 1
        ev = Evaluator(problem, state, check=config.check)
        stats = []
        for stage in STAGES:
            rng = stream(seed, "room", room, "solve", stage, *((attempt,) if attempt else ()))
            st = Annealer(state, problem, ev, room, stage, rng, config, namer).run(steps[stage])
            st = repair_stage(state, problem, ev, room, stage, seed, config, namer, steps[stage],
                              st, attempt)
            log.info("%s/%s: %d objects, violation %.3g, loss %.3g in %.2fs", room, stage,
                     st.objects, st.violation, st.loss, st.seconds)
            stats.append(st)
            if (stage != STAGES[-1] and not last
                    and own_violation(ev.evaluate(), problem, stage) > 1e-9):
                break  # later stages cannot meet this stage's requirement: start again
        complete = len(stats) == len(STAGES)
        if complete and problem.window_dressing:  # hung once the furniture stands
            dress_windows(state, room, problem.window_dressing,
                          stream(seed, "room", room, "solve", "windows",
                                 *((attempt,) if attempt else ())), namer)
        mine = [n for n, ob in state.objects.items() if ob.room == room]
        objects = [_detached(state.objects[n]) for n in mine] if complete else []
        unmet = {k: v for k, v in ev.evaluate().violations.items() if v > 1e-9}
        for n in reversed(mine):
            state.remove(n)
        if not complete:
            log.info("%s: %s stage unmet, solved again (attempt %d): %s", room, stats[-1].stage,
                     attempt + 1, ", ".join(sorted(unmet)))
            continue
        if best is None or (stats[-1].violation, stats[-1].loss) < \
                (best[0][-1].violation, best[0][-1].loss):
            best = stats, objects, unmet
        full += 1
        if best[0][-1].violation <= 1e-9 or full == FULL_SOLVES:
            break
        log.info("%s: solved again (attempt %d), violation %.3g (%s)", room, attempt + 1,
                 stats[-1].violation, ", ".join(sorted(unmet)))
    assert best is not None
    return RoomSolution(room, best[0], best[1], named, best[2])


def _detached(ob: ObjState) -> ObjState:
    """A copy of `ob` without what belongs to one process's solve (collision pieces, the counted
    context it was added to): what `merge` needs, picklable."""
    assert not ob.rough  # a pose found clear gave it its placeholder (`State.collides`)
    return replace(ob, cobjs=[], boxes=None, n_solid=0, free_pending=False, context=None,
                   env={}, placements=[replace(p) for p in ob.placements])


def merge(state: State, solutions: Iterable[RoomSolution]) -> list[StageStats]:
    """Put every room's objects into `state` under their final names: counted per generator
    room after room in name order, as one namer would have named them. Returns every stage's
    stats, rooms in name order."""
    offset: dict[str, int] = {}
    stats: list[StageStats] = []
    for sol in sorted(solutions, key=lambda s: s.room):
        def final(name: str, sol: RoomSolution = sol) -> str:
            gen, _, n = name.rpartition("_")
            return f"{gen}_{offset.get(gen, 0) + int(n)}"
        local = {ob.name for ob in sol.objects}
        for ob in sol.objects:
            ob.name = final(ob.name)
            for p in ob.placements:
                if p.parent in local:
                    p.parent = final(p.parent)
            ob.asset = state.cache.adopt_placeholder(ob.generator, ob.params, ob.asset)
            state.add(ob)
        for gen, k in sol.named.items():
            offset[gen] = offset.get(gen, 0) + k
        stats.extend(sol.stats)
    return stats


def evaluators_for(state: State, problems: dict[str, Problem], *, check: bool = False
                   ) -> dict[str, Evaluator]:
    """An evaluator per room of its problem with circulation added, over the merged state."""
    return {room: Evaluator(with_circulation(p, room), state, check=check)
            for room, p in sorted(problems.items())}


def solve(state: State, problems: dict[str, Problem], seed: int, *,
          config: AnnealConfig | None = None, steps: dict[str, int] | None = None,
          progress: bool = False, give_up: bool = False
          ) -> tuple[list[StageStats], dict[str, Evaluator]]:
    """Solve every room's problem, with its circulation constraint added, one room after the
    other in this process (name order), and put the results into `state`. The evaluators
    returned evaluate those extended problems. With `give_up`, the first room left with a hard
    constraint unmet raises RoomUnmet (the caller has a better use for the time)."""
    config = config or AnnealConfig()
    solutions = []
    for room in tqdm(sorted(problems), desc="solving", unit="room", disable=not progress,
                     leave=False):
        solutions.append(solve_room(state, room, problems[room], seed, config=config,
                                    steps=steps))
        if give_up and solutions[-1].unmet:
            raise RoomUnmet(solutions[-1])
    stats = merge(state, solutions)
    return stats, evaluators_for(state, problems, check=config.check)
