"""Simulated annealing over one room's objects for one stage (Infinigen Indoors, sec. 3.3, E.3).

Each step picks a move on a schedule (discrete moves fade as the temperature falls, continuous
ones grow), applies it to the `State`, rejects it at once if the result is geometrically invalid
(a relation broken or a collision), and otherwise lets the evaluator score it. Acceptance ranks
total hard-constraint violation first, then applies Metropolis on the soft loss. A rejected move is
undone and the evaluator told which objects to re-check.
"""
from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from indoorgen.assets import factories_with, get_factory
from indoorgen.constraints.bounds import STAGE_ORDER, Bound, find_bounds, term_stage
from indoorgen.constraints.evaluator import Evaluator, Result
from indoorgen.constraints.problem import Problem
from indoorgen.model.frames import yaw_matrix
from indoorgen.rng import child_seed
from indoorgen.solver.placement import placements_hold, sample_point, solve_pose
from indoorgen.solver.state import ObjState, Placement, State

log = logging.getLogger(__name__)

#: a loss improvement smaller than this does not count as progress for early stopping
MIN_GAIN = 1e-3

MOVES_DISCRETE = {"add": 3.0, "delete": 0.6, "resample": 0.8, "reinit": 0.8,
                  "reassign_plane": 0.6, "reassign_parent": 0.5}
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
    room: str
    stage: str
    steps: int = 0
    accepted: int = 0
    proposed: dict = field(default_factory=dict)
    valid: dict = field(default_factory=dict)
    taken: dict = field(default_factory=dict)
    seconds: float = 0.0
    objects: int = 0
    violation: float = 0.0
    loss: float = 0.0
    stopped_early: bool = False

    def to_json(self) -> dict:
        return {"room": self.room, "stage": self.stage, "steps": self.steps,
                "accepted": self.accepted, "proposed": self.proposed, "valid": self.valid,
                "accepted_by_move": self.taken, "seconds": round(self.seconds, 4),
                "objects": self.objects, "violation": self.violation, "loss": self.loss,
                "stopped_early": self.stopped_early}


class Annealer:
    """Runs one stage of one room. Holds the stage's random stream and running result."""

    def __init__(self, state: State, problem: Problem, ev: Evaluator, room: str, stage: str,
                 rng: np.random.Generator, config: AnnealConfig, namer: Callable[[str], str]):
        self.state, self.problem, self.ev = state, problem, ev
        self.room, self.stage, self.rng, self.cfg = room, stage, rng, config
        self.namer = namer
        upto = STAGE_ORDER[stage]
        self.active_constraints = {n for n, c in problem.constraints.items()
                                   if STAGE_ORDER[term_stage(c)] <= upto}
        active = self.active_constraints | {n for n, t in problem.score_terms.items()
                                            if STAGE_ORDER[term_stage(t.expr)] <= upto}
        ev.set_active(active)
        self.result: Result = ev.evaluate()
        self.stats = StageStats(room, stage)
        self._unknown_tags: set = set()

    # -- helpers ---------------------------------------------------------------------------
    def _mine(self) -> list[str]:
        """This room's objects of this stage, in name order (what moves may touch)."""
        return self.state.members(self.room, self.stage)

    def _bounds(self) -> list[Bound]:
        rooms = frozenset(self.state.rooms)
        return [b for b in find_bounds(self.problem, self.ev, self.active_constraints)
                if b.stage(rooms) == self.stage]

    def _pick(self, items):
        return items[int(self.rng.integers(len(items)))]

    def _valid(self, name: str) -> bool:
        return placements_hold(self.state, name) and not self.state.collides(name)

    def _place(self, ob: ObjState, tries: int | None = None) -> list[str]:
        """Sample poses on the object's planes until one is valid (the object is in state,
        whatever rests on it moves along). Returns the objects moved; empty if none was
        valid."""
        st = self.state
        anchor, placement = self._anchor(ob)
        child = ob.asset.surface(placement.child_surface)
        half = 0.5 * min(child.polygon.bounds[2] - child.polygon.bounds[0],
                         child.polygon.bounds[3] - child.polygon.bounds[1])
        for _ in range(tries or self.cfg.init_tries):
            yaw = self._grid_yaw(ob, anchor)
            q = sample_point(anchor, self.rng, margin=half)
            r = np.array([[math.cos(yaw), -math.sin(yaw), 0], [math.sin(yaw), math.cos(yaw), 0],
                          [0, 0, 1.0]])
            res = solve_pose(st, ob.asset, ob.placements, q - r @ child.origin, yaw)
            if res is None:
                return []
            if abs(res[1] - yaw) > 1e-9:  # a wall or table side fixed the yaw: aim again
                res = solve_pose(st, ob.asset, ob.placements, q - yaw_matrix(res[1]) @ child.origin,
                                 res[1])
                if res is None:
                    return []
            moved = self._move(ob.name, res[0], res[1])
            if self._valid_group(moved):
                return moved
        return []

    def _grid_yaw(self, ob: ObjState, anchor) -> float:
        """A yaw square to the surface `ob` rests on: the surface's own axes (a room's floor:
        the world axes; a shelf or tabletop: its parent's), turned by k quarter turns. On an
        object, half the draws face the same way as the parent (a TV on its stand, books on a
        shelf), since that is what most things on furniture do."""
        base = math.atan2(anchor.u[1], anchor.u[0]) if abs(anchor.normal[2]) > 0.99 else 0.0
        on_object = any(p.parent not in self.state.rooms for p in ob.placements)
        if on_object and self.rng.random() < 0.5:
            k = 0
        else:
            k = int(self.rng.integers(4))
        return base + k * math.pi / 2

    def _anchor(self, ob: ObjState):
        """The smallest surface the object is attached to (its tabletop rather than the room),
        in world coordinates, and the placement that attaches it there."""
        surfaces = [self.state.surface_world(p.parent, p.parent_surface) for p in ob.placements]
        i = int(np.argmin([s.polygon.area for s in surfaces]))
        return surfaces[i], ob.placements[i]

    def _draw_placements(self, asset, parents, tries: int = 12) -> list[Placement] | None:
        """Choose, for each relation, a parent, a parent surface and a child surface, such that
        all the planes can hold at once (two walls of a corner for a bath, not two opposite
        walls). None if no compatible choice turned up in `tries` draws."""
        for _ in range(tries if len(parents) > 1 else 1):
            placements = []
            for rel, parent_ids in parents:
                parent = self._pick(list(parent_ids))
                ps = [s.name for s in self.state.surfaces(parent) if s.subpart == rel.parent]
                cs = [s.name for s in asset.surfaces if s.subpart == rel.child]
                if not ps or not cs:
                    return None
                placements.append(Placement(rel, parent, self._pick(cs), self._pick(ps)))
            if len(placements) == 1 or \
                    solve_pose(self.state, asset, placements, np.zeros(3), 0.0) is not None:
                return placements
        return None

    # -- moves: each returns (changed, added, removed, undo, relinked) or None when invalid --
    #    relinked: parents that gained or lost a related object (a reassigned parent)
    def move_add(self):
        bounds = [b for b in self._bounds() if b.can_add]
        if not bounds:
            return None
        below = [b for b in bounds if b.below]
        b = self._pick(below if below and self.rng.random() < 0.85 else bounds)
        gens = factories_with(b.context.tags, b.context.excluded)
        if b.context.generator is not None:
            gens = [g for g in gens if g == b.context.generator]
        if not gens:
            if b.context.tags not in self._unknown_tags:
                self._unknown_tags.add(b.context.tags)
                log.warning("no generator has tags %s", sorted(map(str, b.context.tags)))
            return None
        gen = self._pick(gens)
        fac = get_factory(gen)
        seed = child_seed(self.rng)
        params = fac.sample_params(np.random.default_rng(seed))
        asset = self.state.cache.placeholder(gen, params)
        placements = self._draw_placements(asset, b.parents)
        if placements is None:
            return None
        ob = ObjState(self.namer(gen), gen, params, seed, frozenset(fac.tags), self.room,
                      self.stage, asset, placements, np.zeros(3), 0.0, bound=b.name,
                      context=b.context, env=dict(b.env))
        self.state.add(ob)
        if not self._place(ob):
            self.state.remove(ob.name)
            return None
        name = ob.name
        return (), (name,), (), lambda: self.state.remove(name), ()

    def move_delete(self):
        mine = self._mine()
        if not mine:
            return None
        # an object may go unless a count it belongs to is already at its minimum
        kept = {n for b in self._bounds() if not b.can_delete for n in b.members}
        ok = [n for n in mine if not self.state.children(n) and n not in kept]
        if not ok:
            return None
        name = self._pick(ok)
        ob = self.state.remove(name)

        def undo():
            self.state.add(ob)
        return (), (), (name,), undo, ()

    def _pose_undo(self, name: str):
        """An undo for a pose change of `name` and of everything resting on it."""
        group = [name] + self.state.descendants(name)
        saved = [(n, self.state.objects[n].position.copy(), self.state.objects[n].yaw)
                 for n in group]

        def undo():
            for n, pos, yaw in saved:
                self.state.set_pose(n, pos, yaw)
        return undo

    def _move(self, name: str, position: np.ndarray, yaw: float) -> list[str]:
        """Pose `name` and carry what rests on it along rigidly (a TV moves with its stand).
        Returns every object moved."""
        st = self.state
        ob = st.objects[name]
        old_pos, old_yaw = ob.position.copy(), ob.yaw
        st.set_pose(name, position, yaw)
        moved = [name]
        rest = st.descendants(name)
        if rest:
            turn = yaw_matrix(yaw - old_yaw)
            for d in rest:
                child = st.objects[d]
                st.set_pose(d, turn @ (child.position - old_pos) + np.asarray(position, float),
                            child.yaw + yaw - old_yaw)
            moved += rest
        return moved

    def _valid_group(self, names: list[str]) -> bool:
        """The first object's relations hold and none of the moved objects collides."""
        return placements_hold(self.state, names[0]) and \
            not any(self.state.collides(n) for n in names)

    def move_translate(self):
        mine = self._mine()
        if not mine:
            return None
        name = self._pick(mine)
        ob = self.state.objects[name]
        res = solve_pose(self.state, ob.asset, ob.placements, ob.position, ob.yaw)
        if res is None:
            return None
        _, _, dof = res
        sigma = self.cfg.translate_sigma * self.temperature
        step = dof.projection @ self.rng.normal(0.0, sigma, 3)
        return self._try_pose(name, ob.position + step, ob.yaw)

    def _try_pose(self, name: str, position: np.ndarray, yaw: float):
        """Move `name` (and what rests on it) to the pose nearest (position, yaw) on its planes;
        the move's outcome, or None (and nothing changed) if that pose is invalid."""
        ob = self.state.objects[name]
        res = solve_pose(self.state, ob.asset, ob.placements, position, yaw)
        if res is None:
            return None
        undo = self._pose_undo(name)
        moved = self._move(name, res[0], res[1])
        if not self._valid_group(moved):
            undo()
            return None
        return tuple(moved), (), (), undo, ()

    def move_rotate(self):
        mine = [n for n in self._mine()]
        if not mine:
            return None
        name = self._pick(mine)
        ob = self.state.objects[name]
        res = solve_pose(self.state, ob.asset, ob.placements, ob.position, ob.yaw)
        if res is None or not res[2].rotates:
            return None
        if self.rng.random() < 0.3:  # snap square to the supporting surface
            new_yaw = self._grid_yaw(ob, self._anchor(ob)[0])
        else:
            new_yaw = ob.yaw + float(self.rng.normal(0.0, self.cfg.rotate_sigma * self.temperature))
        return self._try_pose(name, ob.position, new_yaw)

    def move_reinit(self):
        mine = self._mine()
        if not mine:
            return None
        name = self._pick(mine)
        ob = self.state.objects[name]
        undo = self._pose_undo(name)
        moved = self._place(ob, tries=3)
        if not moved:
            undo()
            return None
        return tuple(moved), (), (), undo, ()

    def move_resample(self):
        # new params mean new surfaces: whatever rests on an object keeps it as it is
        mine = [n for n in self._mine() if not self.state.children(n)]
        if not mine:
            return None
        name = self._pick(mine)
        ob = self.state.objects[name]
        fac = get_factory(ob.generator)
        old_params, old_pos, old_yaw = ob.params, ob.position.copy(), ob.yaw
        params = fac.sample_params(self.rng)
        self.state.set_asset(name, params)

        def undo():
            self.state.set_asset(name, old_params)
            self.state.set_pose(name, old_pos, old_yaw)
        res = solve_pose(self.state, ob.asset, ob.placements, ob.position, ob.yaw)
        if res is None:
            undo()
            return None
        self.state.set_pose(name, res[0], res[1])
        if not self._valid(name):
            undo()
            return None
        return (name,), (), (), undo, ()

    def _replace_placement(self, name: str, i: int, new: Placement):
        ob = self.state.objects[name]
        old_pl, undo_pose = list(ob.placements), self._pose_undo(name)
        self.state.set_placements(name, ob.placements[:i] + [new] + ob.placements[i + 1:])

        def undo():
            self.state.set_placements(name, old_pl)
            undo_pose()
        moved = self._place(ob, tries=4)
        if not moved:
            undo()
            return None
        relinked = tuple({p.parent for p in old_pl} ^ {p.parent for p in ob.placements})
        return tuple(moved), (), (), undo, relinked

    def move_reassign_plane(self):
        mine = self._mine()
        if not mine:
            return None
        name = self._pick(mine)
        ob = self.state.objects[name]
        i = int(self.rng.integers(len(ob.placements)))
        p = ob.placements[i]
        alts = [s.name for s in self.state.surfaces(p.parent)
                if s.subpart == p.relation.parent and s.name != p.parent_surface]
        if not alts:
            return None
        return self._replace_placement(
            name, i, Placement(p.relation, p.parent, p.child_surface, self._pick(alts)))

    def move_reassign_parent(self):
        mine = [n for n in self._mine() if self.state.objects[n].context is not None]
        if not mine:
            return None
        name = self._pick(mine)
        ob = self.state.objects[name]
        i = int(self.rng.integers(len(ob.placements)))
        p = ob.placements[i]
        sets = [self.ev.value(node, ob.env) for rel, node in ob.context.relations
                if rel == p.relation]
        cands = sorted(frozenset.intersection(*sets) - {p.parent, name}) if sets else []
        if not cands:
            return None
        parent = self._pick(cands)
        alts = [s.name for s in self.state.surfaces(parent) if s.subpart == p.relation.parent]
        if not alts:
            return None
        return self._replace_placement(
            name, i, Placement(p.relation, parent, p.child_surface, self._pick(alts)))

    # -- the loop -----------------------------------------------------------------------------
    def _weights(self, frac: float) -> tuple[list[str], np.ndarray]:
        if self.cfg.moves:
            names = sorted(self.cfg.moves)
            w = np.array([self.cfg.moves[n] for n in names], float)
            return names, w / w.sum()
        names = list(MOVES_DISCRETE) + list(MOVES_CONTINUOUS)
        w = [v * (1.0 - 0.8 * frac) for v in MOVES_DISCRETE.values()] + \
            [v * (0.2 + 0.8 * frac) for v in MOVES_CONTINUOUS.values()]
        w = np.array(w)
        return names, w / w.sum()

    def accept(self, old: Result, new: Result) -> bool:
        """Fewer total violations always win; equal violations go to Metropolis on the loss."""
        if new.violation < old.violation - 1e-9:
            return True
        if new.violation > old.violation + 1e-9:
            return False
        if new.loss <= old.loss:
            return True
        return bool(self.rng.random() < math.exp((old.loss - new.loss) / self.temperature))

    def run(self, steps: int) -> StageStats:
        t0 = time.perf_counter()
        cfg, st = self.cfg, self.stats
        self.temperature = cfg.t_start
        best = (self.result.violation, self.result.loss)
        last_gain = 0
        patience = max(40, int(cfg.patience * steps))
        for step in range(steps):
            stalled = step - last_gain
            # converged (nothing improved for a while), or stuck on a constraint this room
            # cannot meet (twice as long without any gain): more steps would change nothing
            if stalled > patience and (self.result.violation == 0 or stalled > 2 * patience):
                st.stopped_early = True
                break  # converged: nothing has improved for a while
            frac = step / max(1, steps - 1)
            self.temperature = cfg.t_start * (cfg.t_end / cfg.t_start) ** frac
            names, w = self._weights(frac)
            move = names[int(self.rng.choice(len(names), p=w))]
            st.proposed[move] = st.proposed.get(move, 0) + 1
            out = getattr(self, "move_" + move)()
            st.steps += 1
            if out is None:
                continue
            st.valid[move] = st.valid.get(move, 0) + 1
            changed, added, removed, undo, relinked = out
            self.ev.notify(changed, added=added, removed=removed, relinked=relinked)
            new = self.ev.evaluate()
            if self.accept(self.result, new):
                self.result = new
                if (new.violation, new.loss + MIN_GAIN) < best:
                    best, last_gain = (new.violation, new.loss), step
                st.accepted += 1
                st.taken[move] = st.taken.get(move, 0) + 1
            else:
                undo()
                self.ev.notify(changed, added=removed, removed=added, relinked=relinked)
        self.result = self.ev.evaluate()
        st.seconds = time.perf_counter() - t0
        st.objects = len(self._mine())
        st.violation = self.result.violation
        st.loss = self.result.loss
        return st
