"""The staged solve (Infinigen Indoors, algorithm 1): per room, anneal the large objects, then the
medium, then the small; each stage sees earlier stages' objects as fixed. Every room's program
gets the circulation constraint here (`solver.circulation`), so every room keeps a walkway."""
from __future__ import annotations

import logging
from collections.abc import Callable

from tqdm import tqdm

from indoorgen.constraints.bounds import STAGE_ORDER
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.constraints.problem import Problem
from indoorgen.rng import stream
from indoorgen.solver.anneal import AnnealConfig, Annealer, StageStats
from indoorgen.solver.circulation import with_circulation
from indoorgen.solver.state import State

log = logging.getLogger(__name__)

#: the stages in the order they run (large furniture first, so smaller things find it in place)
STAGES = tuple(STAGE_ORDER)
#: annealing steps per stage when the caller gives none
DEFAULT_STEPS = {"large": 350, "medium": 300, "small": 450}


def make_namer() -> Callable[[str], str]:
    """Names objects `<generator>_<n>`, counting per generator in the order they are created."""
    counts: dict[str, int] = {}

    def name(generator: str) -> str:
        counts[generator] = counts.get(generator, 0) + 1
        return f"{generator}_{counts[generator] - 1}"
    return name


def solve(state: State, problems: dict[str, Problem], seed: int, *,
          config: AnnealConfig | None = None, steps: dict[str, int] | None = None,
          progress: bool = False) -> tuple[list[StageStats], dict[str, Evaluator]]:
    """Solve every room's problem, with its circulation constraint added, in turn, stage by
    stage, mutating `state`. The evaluators returned evaluate those extended problems."""
    config = config or AnnealConfig()
    problems = {room: with_circulation(p, room) for room, p in problems.items()}
    steps = {**DEFAULT_STEPS, **(steps or {})}
    namer = make_namer()
    stats: list[StageStats] = []
    evaluators: dict[str, Evaluator] = {}
    jobs = [(room, stage) for room in sorted(problems) for stage in STAGES]
    bar = tqdm(jobs, desc="solving", unit="stage", disable=not progress, leave=False)
    for room, stage in bar:
        ev = evaluators.get(room)
        if ev is None:
            ev = evaluators[room] = Evaluator(problems[room], state, check=config.check)
        bar.set_postfix_str(f"{room}: {stage}")
        rng = stream(seed, "room", room, "solve", stage)
        st = Annealer(state, problems[room], ev, room, stage, rng, config, namer).run(steps[stage])
        log.info("%s/%s: %d objects, violation %.3g, loss %.3g in %.2fs", room, stage,
                 st.objects, st.violation, st.loss, st.seconds)
        stats.append(st)
    return stats, evaluators
