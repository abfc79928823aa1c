"""The annealer's moves (Infinigen Indoors, sec. 3.3): add, delete, resample, reinit, reassign a
plane or a parent, translate, rotate.

Matching sets (`Problem.matching`: the chairs at a table, a bed's nightstands) stay alike: `add`
copies the design (generator, params and material seed) of a member already placed, and
`resample` gives the whole set one new shape at once.

Each move is a function of a `MoveContext` that proposes one change to the state and applies it.
It returns a `MoveOutcome` (what changed, and how to undo it) when the result is geometrically
valid, or None, having changed nothing, when it is not. `MOVES` names them for the schedule.
"""
from __future__ import annotations

import logging
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import TypeVar

import numpy as np
import shapely.geometry as sg

from indoorgen.assets import Asset, Surface, factories_with, get_factory
from indoorgen.constraints.bounds import Bound, Context, find_bounds
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.constraints.problem import Problem
from indoorgen.constraints.relations import Relation
from indoorgen.model.frames import yaw_matrix
from indoorgen.model.tags import Subpart
from indoorgen.rng import child_seed
from indoorgen.solver.placement import (
    SURFACE_GAP,
    free_region,
    headroom,
    placements_hold,
    planar,
    sample_point,
    sample_region,
    snap_object,
    solve_pose,
    surface_offsets,
)
from indoorgen.solver.state import ObjState, Placement, State

log = logging.getLogger(__name__)

_T = TypeVar("_T")


@dataclass
class MoveContext:
    """What a move reads and changes: the state, the room and stage being annealed, the
    evaluator (bounds and parent sets come from it), the stage's random stream, step sizes and
    the current temperature (the run loop lowers it)."""

    state: State
    problem: Problem
    ev: Evaluator
    room: str
    stage: str
    rng: np.random.Generator
    namer: Callable[[str], str]
    #: the constraints this stage enforces (its own and earlier stages')
    active_constraints: frozenset[str]
    #: poses tried when an object is (re)placed from scratch
    init_tries: int
    #: metres of translation step std-dev per unit of temperature
    translate_sigma: float
    #: radians of rotation step std-dev per unit of temperature
    rotate_sigma: float
    temperature: float
    #: tag sets already warned about (no generator has them), so each is logged once
    unknown_tags: set[frozenset] = field(default_factory=set)
    #: generators by (tags, excluded tags): the catalogue does not change during a solve
    _generators: dict[tuple[frozenset, frozenset], list[str]] = field(
        default_factory=dict, init=False, repr=False)
    #: the last bounds found and the evaluator's change count they were found at
    _bounds: tuple[int, list[Bound]] | None = field(default=None, init=False, repr=False)

    def mine(self) -> list[str]:
        """This room's objects of this stage, in name order (what moves may touch)."""
        return self.state.members(self.room, self.stage)

    def bounds(self) -> list[Bound]:
        """The count bounds of this stage's contexts in the current state (what may be added or
        deleted)."""
        if self._bounds is not None and self._bounds[0] == self.ev.changes:
            return self._bounds[1]  # nothing was notified since: the same state, the same bounds
        rooms = frozenset(self.state.rooms)
        found = [b for b in find_bounds(self.problem, self.ev, self.active_constraints)
                 if b.stage(rooms) == self.stage]
        self._bounds = (self.ev.changes, found)
        return found

    def generators(self, tags: frozenset, excluded: frozenset) -> list[str]:
        """Names of the generators with all of `tags` and none of `excluded` (sorted)."""
        key = (frozenset(tags), frozenset(excluded))
        got = self._generators.get(key)
        if got is None:
            got = self._generators[key] = factories_with(tags, excluded)
        return got

    def pick(self, items: Sequence[_T]) -> _T:
        """One of `items`, uniformly at random."""
        return items[int(self.rng.integers(len(items)))]

    def pick_weighted(self, items: Sequence[_T], weights: Sequence[float]) -> _T:
        """One of `items`, drawn with relative `weights` (one uniform draw; equal weights draw
        exactly as `pick` does)."""
        if len(set(weights)) <= 1:
            return self.pick(items)
        cum = np.cumsum(np.asarray(weights, float))
        i = int(np.searchsorted(cum, self.rng.random() * cum[-1], side="right"))
        return items[min(i, len(items) - 1)]


@dataclass(frozen=True, kw_only=True)
class MoveOutcome:
    """What an applied move did: the objects it changed, added and removed, how to undo it, and
    the parents that gained or lost a related object (`relinked`: a reassigned parent)."""

    changed: tuple[str, ...] = ()
    added: tuple[str, ...] = ()
    removed: tuple[str, ...] = ()
    undo: Callable[[], None]
    relinked: tuple[str, ...] = ()


#: a move: applies one proposal to the context's state, or returns None (nothing changed)
MoveFn = Callable[[MoveContext], MoveOutcome | None]

#: designs and surfaces an add draws while the one drawn has no room for the thing (a box
#: deeper than the wall shelf drawn, a shelf already full)
ADD_DRAWS = 4


# -- shared steps of the moves ------------------------------------------------------------------
def _pick_own(ctx: MoveContext, keep: Callable[[str], bool] | None = None) -> tuple[str, ObjState] | None:
    """One of this stage's objects (those `keep` accepts), with its state; None if there is
    none."""
    mine = ctx.mine() if keep is None else [n for n in ctx.mine() if keep(n)]
    if not mine:
        return None
    name = ctx.pick(mine)
    return name, ctx.state.objects[name]


def _pick_placement(ctx: MoveContext, ob: ObjState) -> tuple[int, Placement]:
    """One of the object's placements, uniformly at random, with its index."""
    i = int(ctx.rng.integers(len(ob.placements)))
    return i, ob.placements[i]


def _surface_names(state: State, o: str, role: Subpart | None) -> list[str]:
    """Names of the surfaces of `o` (a room or an object) that play `role`."""
    return [s.name for s in state.surfaces(o) if s.subpart == role]


def _valid_group(state: State, names: list[str]) -> bool:
    """The first object's relations hold and none of the moved objects collides."""
    return placements_hold(state, names[0]) and not any(state.collides(n) for n in names)


def _carry(state: State, name: str, position: np.ndarray, yaw: float) -> list[str]:
    """Pose `name` and carry what rests on it along rigidly (a TV moves with its stand).
    Returns every object moved."""
    ob = state.objects[name]
    old_pos, old_yaw = ob.position.copy(), ob.yaw
    state.set_pose(name, position, yaw)
    moved = [name]
    rest = state.descendants(name)
    if rest:
        turn = yaw_matrix(yaw - old_yaw)
        for d in rest:
            child = state.objects[d]
            state.set_pose(d, turn @ (child.position - old_pos) + np.asarray(position, float),
                           child.yaw + yaw - old_yaw)
        moved += rest
    return moved


def _pose_undo(state: State, name: str) -> Callable[[], None]:
    """An undo for a pose change of `name` and of everything resting on it."""
    group = [name] + state.descendants(name)
    saved = [(n, state.objects[n].position.copy(), state.objects[n].yaw) for n in group]

    def undo() -> None:
        for n, pos, yaw in saved:
            state.set_pose(n, pos, yaw)
    return undo


def _anchor(state: State, ob: ObjState) -> tuple[Surface, Placement]:
    """The smallest surface the object is attached to (its tabletop rather than the room),
    in world coordinates, and the placement that attaches it there."""
    surfaces = [state.surface_world(p.parent, p.parent_surface) for p in ob.placements]
    i = int(np.argmin([s.polygon.area for s in surfaces]))
    return surfaces[i], ob.placements[i]


def _grid_yaw(ctx: MoveContext, ob: ObjState, anchor: Surface) -> float:
    """A yaw square to the surface `ob` rests on: the surface's own axes (a room's floor:
    the world axes; a shelf or tabletop: its parent's), turned by k quarter turns. On an
    object, half the draws face the same way as the parent (a TV on its stand, books on a
    shelf), since that is what most things on furniture do."""
    base = math.atan2(anchor.u[1], anchor.u[0]) if abs(anchor.normal[2]) > 0.99 else 0.0
    on_object = any(p.parent not in ctx.state.rooms for p in ob.placements)
    k = 0 if on_object and ctx.rng.random() < 0.5 else int(ctx.rng.integers(4))
    return base + k * math.pi / 2


def _place(ctx: MoveContext, ob: ObjState, tries: int | None = None) -> list[str]:
    """Sample poses on the object's planes until one is valid (the object is in state,
    whatever rests on it moves along). Returns the objects moved; empty if none was valid."""
    return _place_on(ctx, ob, tries) or []


def _place_on(ctx: MoveContext, ob: ObjState, tries: int | None = None) -> list[str] | None:
    """`_place`, telling apart a surface with no room left for the object (None: it fits at no
    quarter turn beside what is already there) from poses tried and found invalid (empty)."""
    st = ctx.state
    anchor, placement = _anchor(st, ob)
    child = ob.asset.surface(placement.child_surface)
    half = 0.5 * min(child.polygon.bounds[2] - child.polygon.bounds[0],
                     child.polygon.bounds[3] - child.polygon.bounds[1])
    spots = _SurfaceSpots(ctx, ob, anchor, placement) if _on_furniture(st, ob, anchor) else None
    for _ in range(tries or ctx.init_tries):
        yaw = _grid_yaw(ctx, ob, anchor)
        if spots is None:
            q = sample_point(anchor, ctx.rng, margin=half)
        else:
            spot = spots.sample(yaw)
            if spot is None:
                return None
            q, yaw = spot
        res = solve_pose(st, ob.asset, ob.placements, q - yaw_matrix(yaw) @ child.origin, yaw)
        if res is None:
            return []
        if abs(res[1] - yaw) > 1e-9:  # a wall or table side fixed the yaw: aim again
            res = solve_pose(st, ob.asset, ob.placements, q - yaw_matrix(res[1]) @ child.origin,
                             res[1])
            if res is None:
                return []
        moved = _carry(st, ob.name, res[0], res[1])
        if _valid_group(st, moved):
            return moved
    return []


def _on_furniture(state: State, ob: ObjState, anchor: Surface) -> bool:
    """Does the object rest by one relation alone on a level surface of another object (a
    shelf, a tabletop, a cupboard's floor), where `_SurfaceSpots` finds it room? Not a rail:
    what hangs from one (a coat on its hanger) does not fit its outline on the rail's top."""
    return len(ob.placements) == 1 and ob.placements[0].parent not in state.rooms \
        and anchor.normal[2] > 0.99 and anchor.subpart != Subpart.Rail


class _SurfaceSpots:
    """Where on a piece of furniture's surface an object fits (`free_region`): on the surface,
    clear of what already stands there; worked out once per quarter turn of the object."""

    def __init__(self, ctx: MoveContext, ob: ObjState, anchor: Surface, placement: Placement):
        st = ctx.state
        self.ctx, self.anchor = ctx, anchor
        self.base = math.atan2(anchor.u[1], anchor.u[0])
        self.origin = ob.asset.surface(placement.child_surface).origin
        self.hull = st.cache.hull_2d(ob.generator, ob.params)
        own = {ob.name, *st.descendants(ob.name)}
        others = sorted(n for n in st.children(placement.parent) if n not in own and any(
            p.parent == placement.parent and p.parent_surface == placement.parent_surface
            for p in st.objects[n].placements))
        self.taken = [surface_offsets(anchor, np.asarray(st.footprint(n).exterior.coords)[:-1]
                                      - anchor.origin[:2]) for n in others]
        self.regions: dict[int, sg.Polygon | sg.MultiPolygon] = {}
        mesh = ob.asset.mesh
        self.fits_under = float(mesh.bounds[1][2] - mesh.bounds[0][2]) + SURFACE_GAP <= headroom(
            st, placement.parent, placement.parent_surface)

    def region(self, yaw: float) -> sg.Polygon | sg.MultiPolygon:
        """Where the object's surface origin may go at `yaw` (a quarter turn off the surface's
        axes), in the surface's 2D coordinates."""
        k = round((yaw - self.base) / (math.pi / 2)) % 4
        got = self.regions.get(k)
        if got is None:
            r = yaw_matrix(yaw)
            offsets = self.hull @ r[:2, :2].T - (r @ self.origin)[:2]
            got = self.regions[k] = free_region(self.anchor, surface_offsets(self.anchor, offsets),
                                                self.taken)
        return got

    def sample(self, yaw: float) -> tuple[np.ndarray, float] | None:
        """A world point where the object fits at `yaw`, or else at the next quarter turn that
        fits, with that yaw; None if it fits at none."""
        if not self.fits_under:
            return None
        for k in range(4):
            turned = yaw + k * math.pi / 2
            q = sample_region(self.region(turned), self.ctx.rng)
            if q is not None:
                return self.anchor.to_world(q[None])[0], turned
        return None


def _draw_placements(ctx: MoveContext, asset: Asset,
                     parents: tuple[tuple[Relation, tuple[str, ...]], ...],
                     tries: int = 12) -> list[Placement] | None:
    """Choose, for each relation, a parent, a parent surface and a child surface, such that
    all the planes can hold at once (two walls of a corner for a bath, not two opposite
    walls). None if no compatible choice turned up in `tries` draws."""
    for _ in range(tries if len(parents) > 1 else 1):
        placements = []
        for rel, parent_ids in parents:
            parent = ctx.pick(list(parent_ids))
            ps = _surface_names(ctx.state, parent, planar(rel).parent)
            cs = [s.name for s in asset.surfaces if s.subpart == planar(rel).child]
            if not ps or not cs:
                return None
            placements.append(Placement(rel, parent, ctx.pick(cs), ctx.pick(ps)))
        if len(placements) == 1 or \
                solve_pose(ctx.state, asset, placements, np.zeros(3), 0.0) is not None:
            return placements
    return None


def _try_pose(ctx: MoveContext, name: str, position: np.ndarray, yaw: float) -> MoveOutcome | None:
    """Move `name` (and what rests on it) to the pose nearest (position, yaw) on its planes;
    the move's outcome, or None (and nothing changed) if that pose is invalid."""
    res = snap_object(ctx.state, name, position, yaw)
    if res is None:
        return None
    undo = _pose_undo(ctx.state, name)
    moved = _carry(ctx.state, name, res[0], res[1])
    if not _valid_group(ctx.state, moved):
        undo()
        return None
    return MoveOutcome(changed=tuple(moved), undo=undo)


def _replace_placement(ctx: MoveContext, name: str, i: int, new: Placement) -> MoveOutcome | None:
    """Put placement `i` of `name` to `new` and find the object a valid pose there (what rests
    on it moves along); None, with everything restored, if no pose was valid."""
    st = ctx.state
    ob = st.objects[name]
    old_pl, undo_pose = list(ob.placements), _pose_undo(st, name)
    st.set_placements(name, ob.placements[:i] + [new] + ob.placements[i + 1:])

    def undo() -> None:
        st.set_placements(name, old_pl)
        undo_pose()
    moved = _place(ctx, ob, tries=4)
    if not moved:
        undo()
        return None
    relinked = tuple({p.parent for p in old_pl} ^ {p.parent for p in ob.placements})
    return MoveOutcome(changed=tuple(moved), undo=undo, relinked=relinked)


def _matching_members(ctx: MoveContext) -> list[list[str]]:
    """The members of each of the problem's matching sets in this room and stage, in name
    order (sets in name order)."""
    out = []
    for _, node in sorted(ctx.problem.matching.items()):
        members = ctx.ev.value(node)
        out.append([m for m in sorted(members) if m in ctx.state.objects
                    and ctx.state.objects[m].room == ctx.room
                    and ctx.state.objects[m].stage == ctx.stage])
    return out


def _design_to_copy(ctx: MoveContext, context: Context, gens: list[str]) -> ObjState | None:
    """A placed member of a matching set whose design a new object of `context` takes: the
    first member (by name) of the first set holding one that fits the context."""
    for members in _matching_members(ctx):
        for m in members:
            ob = ctx.state.objects[m]
            if ob.generator in gens and context.tags <= ob.tags and not context.excluded & ob.tags:
                return ob
    return None


def _resample_group(ctx: MoveContext, name: str) -> list[str]:
    """The objects a resample of `name` changes together: its matching set (in this room and
    stage), or `name` alone."""
    for members in _matching_members(ctx):
        if name in members:
            return members
    return [name]


# -- the moves -----------------------------------------------------------------------------------
def add(ctx: MoveContext) -> MoveOutcome | None:
    """Add a new object to a context a bound lets grow (preferring one below its minimum), on
    planes of parents it may attach to."""
    bounds = [b for b in ctx.bounds() if b.can_add]
    if not bounds:
        return None
    below = [b for b in bounds if b.below]
    return add_to(ctx, ctx.pick(below if below and ctx.rng.random() < 0.85 else bounds))


def add_to(ctx: MoveContext, b: Bound, tries: int | None = None) -> MoveOutcome | None:
    """Add a new object to the context of bound `b`, trying `tries` poses (default: the
    context's `init_tries`); None, with nothing changed, if no pose was valid."""
    gens = ctx.generators(b.context.tags, b.context.excluded)
    if b.context.generator is not None:
        gens = [g for g in gens if g == b.context.generator]
    if not gens:
        if b.context.tags not in ctx.unknown_tags:
            ctx.unknown_tags.add(b.context.tags)
            log.warning("no generator has tags %s", sorted(map(str, b.context.tags)))
        return None
    like = _design_to_copy(ctx, b.context, gens) if ctx.problem.matching else None
    # a thing too big for the shelf drawn, or a shelf already full: another draw of design
    # and shelf (a copied design keeps its design)
    for _ in range(1 if like is not None else ADD_DRAWS):
        if like is not None:
            gen, seed, params = like.generator, like.seed, dict(like.params)
            fac = get_factory(gen)
        else:
            gen = ctx.pick_weighted(gens, [get_factory(g).frequency for g in gens])
            fac = get_factory(gen)
            seed = child_seed(ctx.rng)
            params = {**fac.sample_params(np.random.default_rng(seed)), **dict(b.context.params)}
        asset, rough = ctx.state.cache.trial_placeholder(gen, params)
        placements = _draw_placements(ctx, asset, b.parents)
        if placements is None:
            return None
        ob = ObjState(ctx.namer(gen), gen, params, seed, frozenset(fac.tags), ctx.room,
                      ctx.stage, asset, placements, np.zeros(3), 0.0,
                      context=b.context, env=dict(b.env), rough=rough)
        ctx.state.add(ob)
        moved = _place_on(ctx, ob, tries)
        if moved:
            return MoveOutcome(added=(ob.name,), undo=_remover(ctx.state, ob.name))
        ctx.state.remove(ob.name)
        if moved is not None:  # there was room, but every pose tried was invalid
            return None
    return None


def _remover(state: State, name: str) -> Callable[[], None]:
    """An undo for the addition of `name`."""
    def undo() -> None:
        state.remove(name)
    return undo


def delete(ctx: MoveContext) -> MoveOutcome | None:
    """Delete an object nothing rests on, unless a count it belongs to is at its minimum."""
    mine = ctx.mine()
    if not mine:
        return None
    kept = {n for b in ctx.bounds() if not b.can_delete for n in b.members}
    ok = [n for n in mine if not ctx.state.children(n) and n not in kept]
    if not ok:
        return None
    name = ctx.pick(ok)
    ob = ctx.state.remove(name)

    def undo() -> None:
        ctx.state.add(ob)
    return MoveOutcome(removed=(name,), undo=undo)


def translate(ctx: MoveContext) -> MoveOutcome | None:
    """Shift an object within its degrees of freedom by a step that shrinks with the
    temperature."""
    picked = _pick_own(ctx)
    if picked is None:
        return None
    name, ob = picked
    res = snap_object(ctx.state, name, ob.position, ob.yaw)
    if res is None:
        return None
    sigma = ctx.translate_sigma * ctx.temperature
    step = res[2].projection @ ctx.rng.normal(0.0, sigma, 3)
    return _try_pose(ctx, name, ob.position + step, ob.yaw)


def rotate(ctx: MoveContext) -> MoveOutcome | None:
    """Turn an object that may turn: square to its support now and then, else by a step that
    shrinks with the temperature."""
    picked = _pick_own(ctx)
    if picked is None:
        return None
    name, ob = picked
    res = snap_object(ctx.state, name, ob.position, ob.yaw)
    if res is None or not res[2].rotates:
        return None
    if ctx.rng.random() < 0.3:  # snap square to the supporting surface
        new_yaw = _grid_yaw(ctx, ob, _anchor(ctx.state, ob)[0])
    else:
        new_yaw = ob.yaw + float(ctx.rng.normal(0.0, ctx.rotate_sigma * ctx.temperature))
    return _try_pose(ctx, name, ob.position, new_yaw)


def reinit(ctx: MoveContext) -> MoveOutcome | None:
    """Place an object afresh at a random pose on its planes."""
    picked = _pick_own(ctx)
    if picked is None:
        return None
    name, ob = picked
    undo = _pose_undo(ctx.state, name)
    moved = _place(ctx, ob, tries=3)
    if not moved:
        undo()
        return None
    return MoveOutcome(changed=tuple(moved), undo=undo)


def resample(ctx: MoveContext) -> MoveOutcome | None:
    """Give an object new generator params (a new shape) where it stands; a member of a
    matching set changes with its whole set. Only objects nothing rests on: new params mean new
    surfaces."""
    st = ctx.state
    picked = _pick_own(ctx, lambda n: not st.children(n))
    if picked is None:
        return None
    name, ob = picked
    group = _resample_group(ctx, name) if ctx.problem.matching else [name]
    if any(st.children(n) for n in group):
        return None
    saved = [(n, st.objects[n].params, st.objects[n].seed, st.objects[n].position.copy(),
              st.objects[n].yaw) for n in group]
    params = get_factory(ob.generator).sample_params(ctx.rng)
    if ob.context is not None:
        params.update(ob.context.params)

    def undo() -> None:
        for n, old_params, old_seed, old_pos, old_yaw in saved:
            st.objects[n].seed = old_seed
            st.set_asset(n, old_params)
            st.set_pose(n, old_pos, old_yaw)
    for n in group:
        st.objects[n].seed = ob.seed
        st.set_asset(n, dict(params))
    for n in group:
        member = st.objects[n]
        res = snap_object(st, n, member.position, member.yaw)
        if res is None:
            undo()
            return None
        st.set_pose(n, res[0], res[1])
    if not all(_valid_group(st, [n]) for n in group):
        undo()
        return None
    return MoveOutcome(changed=tuple(group), undo=undo)


def reassign_plane(ctx: MoveContext) -> MoveOutcome | None:
    """Move one of an object's placements to another surface of the same role of the same
    parent (another wall, another shelf)."""
    picked = _pick_own(ctx)
    if picked is None:
        return None
    name, ob = picked
    i, p = _pick_placement(ctx, ob)
    alts = [n for n in _surface_names(ctx.state, p.parent, planar(p.relation).parent)
            if n != p.parent_surface]
    if not alts:
        return None
    return _replace_placement(ctx, name, i,
                              Placement(p.relation, p.parent, p.child_surface, ctx.pick(alts)))


def reassign_parent(ctx: MoveContext) -> MoveOutcome | None:
    """Move one of an object's placements to another parent its context allows (a cup to
    another table)."""
    picked = _pick_own(ctx, lambda n: ctx.state.objects[n].context is not None)
    if picked is None:
        return None
    name, ob = picked
    assert ob.context is not None  # _pick_own kept only objects with a context
    i, p = _pick_placement(ctx, ob)
    sets = [ctx.ev.value(node, ob.env) for rel, node in ob.context.relations if rel == p.relation]
    cands = sorted(frozenset.intersection(*sets) - {p.parent, name}) if sets else []
    if not cands:
        return None
    parent = ctx.pick(cands)
    alts = _surface_names(ctx.state, parent, planar(p.relation).parent)
    if not alts:
        return None
    return _replace_placement(ctx, name, i,
                              Placement(p.relation, parent, p.child_surface, ctx.pick(alts)))


#: every move by the name the annealing schedule uses
MOVES: dict[str, MoveFn] = {
    "add": add, "delete": delete, "resample": resample, "reinit": reinit,
    "reassign_plane": reassign_plane, "reassign_parent": reassign_parent,
    "translate": translate, "rotate": rotate,
}
