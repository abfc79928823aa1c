"""Repairing a stage that ended with one of its own hard constraints unmet.

Annealing adds objects in whatever order its draws give; in a small or crowded room the objects
placed first can take every spot a required one needs (a toilet and a basin in the corners a
bath needs, a bookcase on the wall the sofa must stand against). When a stage ends with a
violated hard constraint of its own, the stage is solved again from a clean slate: its objects
are taken out, the objects its count bounds require are placed first, the most constrained
first (a bath held by two walls before a toilet held by one) with many poses tried each, a pose
that blocks the walkway drawn again; a placing that leaves the requirements unmet is built
again from scratch (it is cheap beside an anneal), then the stage is annealed around them. The
attempt with fewer violations (then the lower loss) is kept; nothing is relaxed: a room whose
requirement cannot be met stays failed.
"""
from __future__ import annotations

import logging
from collections.abc import Callable

from indoorgen.constraints.bounds import STAGE_ORDER, BoundKey, term_stage
from indoorgen.constraints.evaluator import Evaluator, Result
from indoorgen.constraints.problem import Problem
from indoorgen.rng import stream
from indoorgen.solver.anneal import AnnealConfig, Annealer, StageStats
from indoorgen.solver.moves import MoveContext, add_to
from indoorgen.solver.state import ObjState, State

log = logging.getLogger(__name__)

#: fresh solves of a stage tried after the first leaves one of its own hard constraints unmet
REPAIR_ATTEMPTS = 2
#: draws (generator, parent planes) per required object in the constructive pass, and poses
#: tried per draw
CONSTRUCT_DRAWS = 8
CONSTRUCT_TRIES = 30
#: constructive passes tried before annealing while one leaves the stage's own requirements
#: unmet (a pass takes 0.15-0.2 s in a kitchen, an anneal after it 3 s: a galley kitchen's
#: sink and cooker set where no fridge fits beside a unit is built again, not annealed)
CONSTRUCT_PASSES = 6


def own_violation(result: Result, problem: Problem, stage: str) -> float:
    """The violation of the hard constraints placed in `stage` (earlier stages' constraints
    are fixed by then: solving this stage again cannot meet them)."""
    return float(sum(v for n, v in result.violations.items()
                     if n in problem.constraints
                     and STAGE_ORDER[term_stage(problem.constraints[n])] == STAGE_ORDER[stage]))


def construct(ctx: MoveContext) -> list[str]:
    """Place the objects the stage's count bounds require (bounds below their minimum), the
    most constrained context first (most relations), each with many poses tried, preferring
    one that lowers the stage's violation (not one that blocks the walkway). Returns the
    objects added; the evaluator is told of each."""
    added: list[str] = []
    failed: set[BoundKey] = set()
    for _ in range(4 * len(ctx.bounds()) + 1):
        below = [b for b in ctx.bounds() if b.can_add and b.below and b.key not in failed]
        if not below:
            break
        most = max(len(b.parents) for b in below)
        b = ctx.pick([b for b in below if len(b.parents) == most])
        before = ctx.ev.evaluate().violation
        placed, valid = None, False
        for _ in range(CONSTRUCT_DRAWS):
            out = add_to(ctx, b, CONSTRUCT_TRIES)
            if out is None:
                continue
            valid = True
            ctx.ev.notify(added=out.added)
            if ctx.ev.evaluate().violation < before - 1e-9:
                placed = out
                break
            # it met its bound only to break another (stood in the walkway, closed a
            # neighbour's front): another draw
            out.undo()
            ctx.ev.notify(added=out.removed, removed=out.added)
        if placed is None and valid:
            # no pose helps at once: one placed anyway, for the anneal to move (a fridge in a
            # small kitchen's walkway until its run shifts)
            placed = add_to(ctx, b, CONSTRUCT_TRIES)
            if placed is not None:
                ctx.ev.notify(added=placed.added)
        if placed is None:
            failed.add(b.key)
        else:
            added += placed.added
    return added


def build_required(ctx: MoveContext) -> None:
    """`construct` the stage's required objects, again from scratch (up to CONSTRUCT_PASSES
    passes) while a pass leaves one of the stage's own hard constraints unmet; keeps the first
    pass that meets them all, else the one that came nearest."""
    best: tuple[float, list[ObjState]] | None = None
    for _ in range(CONSTRUCT_PASSES):
        construct(ctx)
        unmet = own_violation(ctx.ev.evaluate(), ctx.problem, ctx.stage)
        if unmet <= 1e-9:
            return
        built = _take_out(ctx.state, ctx.ev, ctx.room, ctx.stage)
        if best is None or unmet < best[0]:
            best = unmet, built
    assert best is not None
    _put_back(ctx.state, ctx.ev, best[1])


def _take_out(state: State, ev: Evaluator, room: str, stage: str) -> list[ObjState]:
    """Remove the room's objects of `stage` from the state (telling the evaluator)."""
    names = list(state.members(room, stage))
    obs = [state.remove(n) for n in names]
    if names:
        ev.notify(removed=names)
    return obs


def _put_back(state: State, ev: Evaluator, obs: list[ObjState]) -> None:
    """Add objects taken out by `_take_out` back unchanged (telling the evaluator)."""
    for ob in obs:
        state.add(ob)
    if obs:
        ev.notify(added=[ob.name for ob in obs])


def repair_stage(state: State, problem: Problem, ev: Evaluator, room: str, stage: str,
                 seed: int, config: AnnealConfig, namer: Callable[[str], str], steps: int,
                 first: StageStats, room_attempt: int = 0) -> StageStats:
    """Solve `stage` of `room` again (up to REPAIR_ATTEMPTS times, each from its own random
    stream, drawn afresh for each of the room's whole solves `room_attempt`) while one of its
    own hard constraints is unmet, keeping the best solve. Returns the kept solve's stats
    (`repairs`: the attempts made, `seconds`: all of them)."""
    best = first
    seconds, attempts = first.seconds, 0
    for attempt in range(1, REPAIR_ATTEMPTS + 1):
        if own_violation(ev.evaluate(), problem, stage) <= 1e-9:
            break
        attempts = attempt
        kept = _take_out(state, ev, room, stage)
        rng = stream(seed, "room", room, "repair", stage, attempt,
                     *((room_attempt,) if room_attempt else ()))
        annealer = Annealer(state, problem, ev, room, stage, rng, config, namer)
        build_required(annealer.ctx)
        annealer.result = ev.evaluate()
        st = annealer.run(steps)
        log.info("%s/%s: repair %d: violation %.3g, loss %.3g in %.2fs", room, stage, attempt,
                 st.violation, st.loss, st.seconds)
        seconds += st.seconds
        if (st.violation, st.loss) < (best.violation, best.loss):
            best = st
        else:
            _take_out(state, ev, room, stage)
            _put_back(state, ev, kept)
    best.repairs, best.seconds = attempts, seconds
    return best
