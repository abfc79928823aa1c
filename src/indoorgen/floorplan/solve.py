"""Simulated annealing of a home's floorplan (Infinigen Indoors, D.4).

Each step picks a storey (or, in a multi-storey home, sometimes the staircase) and one move:

- extrude a wall segment of a room inwards: the room's cells along it go to the rooms across;
- extrude a wall segment outwards: the room takes the cells across the segment;
- swap the rooms of two adjacent spaces;
- move the staircase placeholder one cell along an axis (every storey's staircase room takes
  the cells it now covers).

A wall segment is the maximal straight run of the room's boundary, through the picked cell edge,
with other rooms (not the outside) across it. A move is rejected at once if it leaves a touched
room empty, disconnected, holed or with a broken outline, and after evaluation if it violates a
hard constraint of the program more than the current plan does (graph doors, exterior walls,
widths, areas, staircase); a move that reduces the violation is always taken, otherwise
it is accepted by the Metropolis rule on the program's loss with an exponentially cooling
temperature. The evaluator is told which rooms each move touched, so only their terms recompute.
"""
from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from indoorgen.constraints.evaluator import Evaluator, Result
from indoorgen.constraints.problem import Problem
from indoorgen.constraints.room_terms import STAIR_PLACEHOLDER
from indoorgen.floorplan.grid import OUTSIDE
from indoorgen.floorplan.rules import breaks_rules, grows_oversized, service_areas
from indoorgen.floorplan.view import GridPlan

log = logging.getLogger(__name__)

Change = tuple[int, np.ndarray, np.ndarray, np.ndarray]  # storey, rows, cols, new labels
_DIRS = ((1, 0), (-1, 0), (0, 1), (0, -1))  # (dy, dx)


@dataclass
class FloorplanAnnealConfig:
    """Annealing schedule: `steps_per_storey` steps per storey; temperature from `t_start` to
    `t_end` (exponential); `p_stair` of steps move the staircase in multi-storey homes."""

    steps_per_storey: int = 250
    t_start: float = 0.2
    t_end: float = 0.002
    p_stair: float = 0.08
    check: bool = False
    #: evaluate the program's hard constraints only at the start and the end (valid when the
    #: solver's own rules, checked on every move, imply them, as for the default program)
    constraints_at_ends_only: bool = False


@dataclass
class AnnealStats:
    """What annealing did: steps, acceptance counts by outcome, objective before and after."""

    steps: int = 0
    accepted: int = 0
    invalid: int = 0
    hard: int = 0
    uphill: int = 0
    seconds: float = 0.0
    start: Result | None = None
    end: Result | None = None
    moves: dict[str, list[int]] = field(default_factory=dict)
    history: list[float] = field(default_factory=list)  # loss after every step

    def to_json(self) -> dict:
        """The statistics as JSON (rounded), for reports."""
        return {"steps": self.steps, "accepted": self.accepted,
                "rejected_invalid": self.invalid, "rejected_hard": self.hard,
                "rejected_uphill": self.uphill, "seconds": round(self.seconds, 4),
                "objective_start": round(self.start.loss, 6) if self.start else None,
                "objective_end": round(self.end.loss, 6) if self.end else None,
                "terms_start": {k: round(v, 6) for k, v in self.start.scores.items()}
                if self.start else {},
                "terms_end": {k: round(v, 6) for k, v in self.end.scores.items()}
                if self.end else {},
                "moves": {k: {"proposed": v[0], "accepted": v[1]} for k, v in self.moves.items()}}


# --------------------------------------------------------------------------------------------
# moves


def _stair_room(plan: GridPlan, k: int) -> int:
    """Index of storey k's staircase room, or -1."""
    if not plan.graph.stairs:
        return -1
    return plan.index[plan.graph.stairs[k]][1]


def _boundary_edges(lab: np.ndarray, i: int):
    """Cell edges of room i with another room across: arrays (dir, row, col) in `lab`."""
    m = lab == i
    out = []
    padded = np.full((lab.shape[0] + 2, lab.shape[1] + 2), OUTSIDE, lab.dtype)
    padded[1:-1, 1:-1] = lab
    for d, (dy, dx) in enumerate(_DIRS):
        across = padded[1 + dy:padded.shape[0] - 1 + dy, 1 + dx:padded.shape[1] - 1 + dx]
        r, c = np.nonzero(m & (across != i) & (across != OUTSIDE))
        out.append((np.full(len(r), d), r, c))
    return (np.concatenate([o[0] for o in out]), np.concatenate([o[1] for o in out]),
            np.concatenate([o[2] for o in out]))


def propose_extrude(plan: GridPlan, rng: np.random.Generator, k: int, outward: bool
                    ) -> list[Change] | None:
    """Move one wall segment of a random room of storey k by one cell."""
    names = plan.names[k]
    i = int(rng.integers(len(names)))
    lab = plan.labels[k]
    ny, nx = lab.shape
    d, r, c = _boundary_edges(lab, i)
    if len(d) == 0:
        return None
    j = int(rng.integers(len(d)))
    dy, dx = _DIRS[d[j]]
    y, x = int(r[j]), int(c[j])
    ty, tx = (0, 1) if dy != 0 else (1, 0)  # direction along the wall

    def ok(yy: int, xx: int) -> bool:
        if not (0 <= yy < ny and 0 <= xx < nx and 0 <= yy + dy < ny and 0 <= xx + dx < nx):
            return False
        a = lab[yy + dy, xx + dx]
        return lab[yy, xx] == i and a != i and a != OUTSIDE

    cells = [(y, x)]
    for sgn in (1, -1):
        yy, xx = y + sgn * ty, x + sgn * tx
        while ok(yy, xx):
            cells.append((yy, xx))
            yy, xx = yy + sgn * ty, xx + sgn * tx
    ys = np.array([p[0] for p in cells])
    xs = np.array([p[1] for p in cells])
    if outward:
        rows, cols = ys + dy, xs + dx
        new = np.full(len(rows), i)
    else:
        rows, cols = ys, xs
        new = lab[ys + dy, xs + dx].copy()
    stair = plan.stair_mask()
    if stair is not None and stair[rows, cols].any():
        return None  # the placeholder stays with the staircase room
    return [(k, rows, cols, new)]


def propose_swap(plan: GridPlan, rng: np.random.Generator, k: int) -> list[Change] | None:
    """Swap the rooms of two adjacent spaces of storey k (never the staircase room)."""
    names = plan.names[k]
    s = _stair_room(plan, k)
    choices = [i for i in range(len(names)) if i != s]
    if len(choices) < 2:
        return None
    i = choices[int(rng.integers(len(choices)))]
    lab = plan.labels[k]
    m = lab == i
    nb = set()
    for dy, dx in _DIRS:
        rr = np.clip(np.nonzero(m)[0] + dy, 0, lab.shape[0] - 1)
        cc = np.clip(np.nonzero(m)[1] + dx, 0, lab.shape[1] - 1)
        nb |= set(lab[rr, cc].tolist())
    choices = sorted(x for x in nb if x not in (i, s, OUTSIDE))
    if not choices:
        return None
    j = choices[int(rng.integers(len(choices)))]
    ri, ci = np.nonzero(lab == i)
    rj, cj = np.nonzero(lab == j)
    return [(k, np.concatenate([ri, rj]), np.concatenate([ci, cj]),
             np.concatenate([np.full(len(ri), j), np.full(len(rj), i)]))]


def propose_stair(plan: GridPlan, rng: np.random.Generator
                  ) -> tuple[list[Change], tuple[int, int, int, int]] | None:
    """Shift the staircase placeholder one cell; each storey's staircase room takes the cells
    it newly covers."""
    assert plan.stair_rect is not None  # only multi-storey homes move their staircase
    iy0, ix0, iy1, ix1 = plan.stair_rect
    dy, dx = _DIRS[int(rng.integers(4))]
    rect = (iy0 + dy, ix0 + dx, iy1 + dy, ix1 + dx)
    ny, nx = plan.grids[0].shape
    if rect[0] < 0 or rect[1] < 0 or rect[2] > ny or rect[3] > nx:
        return None
    changes = []
    for k, g in enumerate(plan.grids):
        if not g.full[rect[0]:rect[2], rect[1]:rect[3]].all():
            return None
        s = _stair_room(plan, k)
        sub = plan.labels[k][rect[0]:rect[2], rect[1]:rect[3]]
        r, c = np.nonzero(sub != s)
        if len(r):
            changes.append((k, r + rect[0], c + rect[1], np.full(len(r), s)))
    return changes, rect


def apply(plan: GridPlan, changes: list[Change]) -> tuple[list[Any], set[str]]:
    """Write `changes` into the plan; returns the undo changes and the rooms touched. The undo
    list ends with a snapshot of the view's caches, so a revert needs no recomputation."""
    undo: list[Any] = []
    touched: set[str] = set()
    snapshot = plan.snapshot()
    for k, rows, cols, new in changes:
        old = plan.labels[k][rows, cols].copy()
        undo.append((k, rows, cols, old))
        names = plan.names[k]
        touched |= {names[v] for v in np.unique(np.concatenate([old, new])).tolist() if v >= 0}
        plan.labels[k][rows, cols] = new
    plan.invalidate(touched)
    undo.append(snapshot)
    return undo, touched


def valid(plan: GridPlan, rooms: set[str]) -> bool:
    """Every room in `rooms` is one simple polygon (non-empty, connected, without holes)."""
    return all(plan.outline_points(r) is not None for r in sorted(rooms))


# --------------------------------------------------------------------------------------------
# annealing


def anneal(plan: GridPlan, problem: Problem, rng: np.random.Generator,
           config: FloorplanAnnealConfig | None = None) -> AnnealStats:
    """Anneal `plan` in place under `problem`. A plan that starts violating some hard
    constraint is driven towards satisfying it; one that satisfies them keeps doing so."""
    cfg = config or FloorplanAnnealConfig()
    t_start = time.perf_counter()
    ev = Evaluator(problem, plan, check=cfg.check)
    cur = ev.evaluate()
    stats = AnnealStats(start=cur)
    if cfg.constraints_at_ends_only and cur.violation <= 1e-9:
        ev.set_active(set(problem.score_terms))
    n_storeys = len(plan.grids)
    n_steps = cfg.steps_per_storey * n_storeys
    loss, violation = cur.loss, cur.violation
    for step in range(n_steps):
        stats.history.append(loss)
        temp = cfg.t_start * (cfg.t_end / cfg.t_start) ** (step / max(1, n_steps - 1))
        rect = None
        if plan.stair_rect is not None and rng.random() < cfg.p_stair:
            kind = "stair"
            got = propose_stair(plan, rng)
            changes, rect = got if got is not None else (None, None)
        else:
            k = int(rng.integers(n_storeys))
            u = rng.random()
            if u < 0.4:
                kind, changes = "extrude_in", propose_extrude(plan, rng, k, outward=False)
            elif u < 0.8:
                kind, changes = "extrude_out", propose_extrude(plan, rng, k, outward=True)
            else:
                kind, changes = "swap", propose_swap(plan, rng, k)
        stats.steps += 1
        counts = stats.moves.setdefault(kind, [0, 0])
        counts[0] += 1
        if not changes and rect is None:
            stats.invalid += 1
            continue
        old_rect = plan.stair_rect
        sizes = service_areas(plan)
        if rect is not None:
            plan.stair_rect = rect
        undo, touched = apply(plan, changes or [])
        if rect is not None:
            touched |= set(plan.graph.stairs)
            plan.invalidate(touched)
        if not valid(plan, touched):
            stats.invalid += 1
            _revert(plan, undo, old_rect, touched, None)
            continue
        if violation <= 1e-9 and (breaks_rules(plan, touched)
                                  or grows_oversized(plan, touched, sizes)):
            stats.hard += 1
            _revert(plan, undo, old_rect, touched, None)
            continue
        changed = sorted(touched) + ([STAIR_PLACEHOLDER] if rect is not None else [])
        ev.notify(changed)
        res = ev.evaluate()
        if res.violation > violation + 1e-9:
            stats.hard += 1
            _revert(plan, undo, old_rect, touched, ev, changed)
            continue
        delta = res.loss - loss
        if (res.violation < violation - 1e-9 or delta <= 0
                or rng.random() < math.exp(-delta / temp)):
            loss, violation = res.loss, res.violation
            stats.accepted += 1
            counts[1] += 1
        else:
            stats.uphill += 1
            _revert(plan, undo, old_rect, touched, ev, changed)
    ev.set_active(None)
    stats.end = ev.evaluate()
    stats.seconds = time.perf_counter() - t_start
    log.debug("floorplan annealing: %s", stats.to_json())
    return stats


def _revert(plan: GridPlan, undo: list, rect, touched: set[str], ev: Evaluator | None,
            changed: list[str] | None = None) -> None:
    *cells, snapshot = undo
    for k, rows, cols, old in reversed(cells):
        plan.labels[k][rows, cols] = old
    plan.stair_rect = rect
    plan.restore(snapshot)
    if ev is not None:
        ev.notify(changed or sorted(touched))
