"""Simulated annealing over one room's objects for one stage (Infinigen Indoors, sec. 3.3, E.3).

Each step picks a move on a schedule (discrete moves fade as the temperature falls, continuous
ones grow), applies it to the `State` (see `moves`: a geometrically invalid proposal - a relation
broken or a collision - is refused at once), and lets the evaluator score the result. Acceptance
ranks total hard-constraint violation first, then applies Metropolis on the soft loss. A rejected
move is undone and the evaluator told which objects to re-check.
"""
from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from indoorgen.constraints.bounds import STAGE_ORDER, term_stage
from indoorgen.constraints.evaluator import Evaluator, Result
from indoorgen.constraints.problem import Problem
from indoorgen.solver.moves import MOVES, MoveContext
from indoorgen.solver.state import State

#: a loss improvement smaller than this does not count as progress for early stopping
MIN_GAIN = 1e-3

#: weights of the discrete moves at the start of the schedule (they fade to a fifth)
MOVES_DISCRETE = {"add": 3.0, "delete": 0.6, "resample": 0.8, "reinit": 0.8,
                  "reassign_plane": 0.6, "reassign_parent": 0.5}
#: weights of the continuous moves at the end of the schedule (they start at a fifth)
MOVES_CONTINUOUS = {"translate": 3.0, "rotate": 1.2}


@dataclass
class AnnealConfig:
    """Annealing settings; defaults follow the paper (0.25 -> 0.001, 20 pose tries)."""

    t_start: float = 0.25
    t_end: float = 0.001
    init_tries: int = 20
    translate_sigma: float = 2.0   # metres of step std-dev per unit of temperature
    rotate_sigma: float = 6.0      # radians of step std-dev per unit of temperature
    check: bool = False            # verify incremental evaluation against full every step
    moves: dict[str, float] | None = None  # fixed move weights (benchmarks), else the schedule
    patience: float = 0.2          # stop once this fraction of the steps brought no gain


@dataclass
class StageStats:
    """What one stage of one room did: steps, moves proposed / valid / accepted by name, time,
    objects placed and the final violation and loss (reported in the generation report)."""

    room: str
    stage: str
    steps: int = 0
    accepted: int = 0
    proposed: dict[str, int] = field(default_factory=dict)
    valid: dict[str, int] = field(default_factory=dict)
    taken: dict[str, int] = field(default_factory=dict)
    seconds: float = 0.0
    objects: int = 0
    violation: float = 0.0
    loss: float = 0.0
    stopped_early: bool = False
    #: fresh solves of the stage tried after it (`solver.repair`)
    repairs: int = 0

    def to_json(self) -> dict:
        """The stats as a JSON-ready dict (`taken` is reported as `accepted_by_move`)."""
        return {"room": self.room, "stage": self.stage, "steps": self.steps,
                "accepted": self.accepted, "proposed": self.proposed, "valid": self.valid,
                "accepted_by_move": self.taken, "seconds": round(self.seconds, 4),
                "objects": self.objects, "violation": self.violation, "loss": self.loss,
                "stopped_early": self.stopped_early, "repairs": self.repairs}


def temperature_at(config: AnnealConfig, frac: float) -> float:
    """The temperature a fraction `frac` (0 -> 1) through the run: geometric from `t_start` to
    `t_end`."""
    return config.t_start * (config.t_end / config.t_start) ** frac


def move_weights(config: AnnealConfig, frac: float) -> tuple[list[str], np.ndarray]:
    """Move names and their probabilities a fraction `frac` through the run: the config's fixed
    weights if it has any, else discrete moves fading and continuous ones growing."""
    if config.moves:
        names = sorted(config.moves)
        w = np.array([config.moves[n] for n in names], float)
        return names, w / w.sum()
    names = list(MOVES_DISCRETE) + list(MOVES_CONTINUOUS)
    w = np.array([v * (1.0 - 0.8 * frac) for v in MOVES_DISCRETE.values()]
                 + [v * (0.2 + 0.8 * frac) for v in MOVES_CONTINUOUS.values()])
    return names, w / w.sum()


def accept(old: Result, new: Result, temperature: float, rng: np.random.Generator) -> bool:
    """Fewer total violations always win; equal violations go to Metropolis on the loss."""
    if new.violation < old.violation - 1e-9:
        return True
    if new.violation > old.violation + 1e-9:
        return False
    if new.loss <= old.loss:
        return True
    return bool(rng.random() < math.exp((old.loss - new.loss) / temperature))


class Annealer:
    """Runs one stage of one room. Holds the stage's moves' context (random stream, temperature)
    and the running result."""

    def __init__(self, state: State, problem: Problem, ev: Evaluator, room: str, stage: str,
                 rng: np.random.Generator, config: AnnealConfig, namer: Callable[[str], str]):
        self.ev, self.cfg = ev, config
        upto = STAGE_ORDER[stage]
        active_constraints = frozenset(n for n, c in problem.constraints.items()
                                       if STAGE_ORDER[term_stage(c)] <= upto)
        ev.set_active(set(active_constraints) | {n for n, t in problem.score_terms.items()
                                                 if STAGE_ORDER[term_stage(t.expr)] <= upto})
        self.ctx = MoveContext(state, problem, ev, room, stage, rng, namer, active_constraints,
                               init_tries=config.init_tries, translate_sigma=config.translate_sigma,
                               rotate_sigma=config.rotate_sigma, temperature=config.t_start)
        self.result: Result = ev.evaluate()
        self.stats = StageStats(room, stage)

    def run(self, steps: int) -> StageStats:
        """Anneal for at most `steps` steps (fewer once nothing improves); returns the stats."""
        t0 = time.perf_counter()
        cfg, st, ctx = self.cfg, self.stats, self.ctx
        best = (self.result.violation, self.result.loss)
        last_gain = 0
        patience = max(40, int(cfg.patience * steps))
        for step in range(steps):
            stalled = step - last_gain
            # converged (nothing improved for a while), or stuck on a constraint this room
            # cannot meet (twice as long without any gain): more steps would change nothing
            if stalled > patience and (self.result.violation == 0 or stalled > 2 * patience):
                st.stopped_early = True
                break
            frac = step / max(1, steps - 1)
            ctx.temperature = temperature_at(cfg, frac)
            names, w = move_weights(cfg, frac)
            move = names[int(ctx.rng.choice(len(names), p=w))]
            st.proposed[move] = st.proposed.get(move, 0) + 1
            out = MOVES[move](ctx)
            st.steps += 1
            if out is None:
                continue
            st.valid[move] = st.valid.get(move, 0) + 1
            self.ev.notify(out.changed, added=out.added, removed=out.removed, relinked=out.relinked)
            new = self.ev.evaluate()
            if accept(self.result, new, ctx.temperature, ctx.rng):
                self.result = new
                if (new.violation, new.loss + MIN_GAIN) < best:
                    best, last_gain = (new.violation, new.loss), step
                st.accepted += 1
                st.taken[move] = st.taken.get(move, 0) + 1
            else:
                out.undo()
                self.ev.notify(out.changed, added=out.removed, removed=out.added,
                               relinked=out.relinked)
        self.result = self.ev.evaluate()
        st.seconds = time.perf_counter() - t0
        st.objects = len(ctx.mine())
        st.violation = self.result.violation
        st.loss = self.result.loss
        return st
