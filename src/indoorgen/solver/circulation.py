"""Circulation as a hard constraint: in every room, a walking agent gets from each door to every
other door and to the front of every large object.

The room's floor is rasterised at `model.walkable.CELL` (the floor slab's top, so a stairwell is
not floor), keeping the cells whose centre lies `clearance` (the agent's radius and a cell) from
its edge; the cells as near any collision piece of a standing object that reaches into the
agent's height band (`model.walkable.BAND`; each piece's bounding box, so never more lenient
than the navigation measure's hulls) are taken out, and the rest is split into 4-connected
components: the centres an agent can reach from one another. The *targets* are

- each door and open connection: the strip in front of it, `APPROACH` beyond the agent's radius
  deep (the navigation measure's test of a door);
- each stair landing (a keep-out zone that belongs to no door);
- each large object whose front matters (`model.walkable.access_points`): its front point, or
  for a bed either side point, within `FRONT_TOLERANCE`; or beside a seat standing on the floor
  that is related to it (the chair at a desk stands where its user would).

A door is reached at its *entry cells*: the cells of its strip, in the empty room, within
`ENTRY_DEPTH` of those nearest the door, where an agent stepping through it first stands (a
strip reached only at its far edge is a door whose way in is blocked).

The violation is the number of targets outside the component that serves the most of them
(weighted by `CIRCULATION_WEIGHT` in the room's problem), so 0 means every door, landing and
front can be reached from every other. *Floor pockets* are a score beside it (`FloorPockets`,
weighed `POCKET_WEIGHT` each): components of at least `POCKET_AREA` of agent centres, on floor
the empty room joins to its doors, that the furniture cuts off and that serve no target (a bed
across the neck of an L-shaped room leaves its arm unreachable though every door is reached).
A score, not a requirement: the navigation report measures the floor they cost, and a home
whose every door and front is reached is not failed for a walled-in corner. Doors or
landings that
even the empty room cannot serve (an architectural fault no furniture can fix) are left out and
logged.

`Circulation` is the constraint node; `with_circulation` adds it to a room's problem (the stage
runner does so for every room). Each evaluation is cached on the solver state by the poses of
the room's standing objects, and each object's raster by its pose, so a move that touches
nothing on the floor costs a key comparison and one that moves a chair re-rasterises one chair.
"""
from __future__ import annotations

import logging
import weakref
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import shapely
import shapely.geometry as sg
from scipy import ndimage

from indoorgen.constraints.logic import Constraint
from indoorgen.constraints.node import Env, EvalContext
from indoorgen.constraints.problem import Problem
from indoorgen.constraints.scalars import Scalar
from indoorgen.model.frames import yaw_matrix
from indoorgen.model.walkable import (
    AGENT_RADIUS,
    APPROACH,
    CELL,
    FRONT_TOLERANCE,
    Grid,
    Patch,
    access_points,
    approach_strip,
    band_boxes,
    door_segment,
    paint,
    patch_values,
)
from indoorgen.solver.state import ObjState, RoomShape, State

log = logging.getLogger(__name__)

#: The name of the circulation constraint in every room's problem.
CIRCULATION = "circulation"
#: What one unreachable target adds to the room's violation: more than one missing object, so
#: the annealer never trades a walkway for a count (a bed that cuts the room is not worth the
#: bed; it waits for a pose that leaves the way through).
CIRCULATION_WEIGHT = 2.0
#: A keep-out zone this close (m) to a door's edge is that door's zone, not a stair landing.
DOOR_ZONE_GAP = 0.05
#: Stages whose objects have fronts the agent must reach (the navigation measure's "large").
FRONT_STAGES = frozenset({"large"})
#: The least area (m^2) of agent centres that counts as a floor pocket: a pocket smaller than
#: this (a corner behind a chair) leaves the navigation measure's reachable share unchanged to
#: a percent in a 15 m^2 room.
POCKET_AREA = 0.2
#: What one floor pocket costs in the room's score: as much as a missing walkway target weighs
#: as a violation.
POCKET_WEIGHT = 2.0
#: The name of the floor-pocket score term in every room's problem.
FLOOR_POCKETS = "no floor walled in"
#: How deep (m) beyond the cells nearest a door its entry cells reach (three cells).
ENTRY_DEPTH = 0.15


@dataclass
class Target:
    """Somewhere the agent must get to: a name for reports and the cells (any one suffices)."""

    name: str
    patches: list[Patch]


@dataclass
class RoomFloor:
    """What does not change while a room is furnished: its grid, the centres an agent can
    occupy in the empty room, the doors and landings to connect, and those the empty room
    cannot serve."""

    grid: Grid
    centres: np.ndarray
    targets: list[Target]
    unservable: list[str]
    served: np.ndarray


@dataclass
class Walkway:
    """One evaluation of a room's circulation: the violation and the targets it counts."""

    violation: int
    unreachable: list[str]
    unservable: list[str] = field(default_factory=list)
    pockets: list[str] = field(default_factory=list)

    def to_json(self) -> dict[str, Any]:
        """The room's `circulation` record in report.json."""
        return {"violation": self.violation, "unreachable": list(self.unreachable),
                "unservable_by_architecture": list(self.unservable),
                "floor_pockets": list(self.pockets)}


def floor_polygon(shape: RoomShape) -> sg.base.BaseGeometry:
    """The room's walkable floor: its polygon, less any hole in its floor slab (a stairwell)."""
    poly = sg.Polygon(shape.room.polygon)
    slab = getattr(shape, "floor", None)
    if slab is None:
        return poly
    top = np.asarray(slab.face_normals)[:, 2] > 0.99
    if not top.any():
        return poly
    tris = np.asarray(slab.vertices)[np.asarray(slab.faces)[top]][:, :, :2]
    surface = shapely.union_all(shapely.polygons(tris)).buffer(1e-6)
    return poly.intersection(surface)


def static_targets(shape: RoomShape, grid: Grid, radius: float,
                   centres: np.ndarray | None = None) -> list[Target]:
    """The room's doors and open connections (the strip in front of each; with the empty
    room's `centres`, its entry cells there) and its stair landings (keep-out zones beside no
    door)."""
    room = shape.room
    poly = np.asarray(room.polygon, float)
    out, mids = [], []
    for d in room.doors:
        seg, inward = door_segment(poly, d.wall, d.offset, d.width)
        mids.append(sg.Point(seg.mean(axis=0)))
        strip = grid.patches([approach_strip(seg, inward, radius + APPROACH)])
        if centres is not None:
            strip = [entry_cells(grid, p, centres, seg) for p in strip]
        out.append(Target(f"door {d.name}", strip))
    landings = [z for z in shape.door_zones
                if not z.is_empty and all(z.distance(m) > DOOR_ZONE_GAP for m in mids)]
    out += [Target(f"stair landing {k}", grid.patches([z])) for k, z in enumerate(landings)]
    return out


def entry_cells(grid: Grid, patch: Patch, centres: np.ndarray, segment: np.ndarray) -> Patch:
    """The cells of a door's strip `patch` that are agent centres in the empty room and lie
    within `ENTRY_DEPTH` of the nearest of them to the door's `segment` (the strip unchanged
    when none is a centre)."""
    i0, j0, m = patch
    free = m & centres[i0:i0 + m.shape[0], j0:j0 + m.shape[1]]
    if not free.any():
        return patch
    ii, jj = np.nonzero(free)
    depth = shapely.distance(shapely.points(grid.x0 + (j0 + jj + 0.5) * grid.cell,
                                            grid.y0 + (i0 + ii + 0.5) * grid.cell),
                             sg.LineString(np.asarray(segment, float)))
    keep = depth <= depth.min() + ENTRY_DEPTH + 1e-9
    entry = np.zeros_like(m)
    entry[ii[keep], jj[keep]] = True
    return i0, j0, entry


def _best(targets: list[Target], labels: np.ndarray) -> tuple[int, list[str], int, set[int]]:
    """The component serving most targets: the count of the others, their names, its label
    (0 when no target is served) and the labels of the components those others reach (they
    are counted already)."""
    hit = [{int(v) for p in t.patches for v in np.unique(patch_values(labels, p)) if v}
           for t in targets]
    counts: dict[int, int] = {}
    for h in hit:
        for lab in h:
            counts[lab] = counts.get(lab, 0) + 1
    if not counts:
        return len(targets), [t.name for t in targets], 0, set()
    best = min(counts, key=lambda lab: (-counts[lab], lab))
    missed = [(t.name, h) for t, h in zip(targets, hit, strict=True) if best not in h]
    return (len(missed), [n for n, _ in missed], best,
            {lab for _, h in missed for lab in h})


def pockets(labels: np.ndarray, served: np.ndarray, skip: set[int], grid: Grid) -> list[str]:
    """The floor pockets (see the module) among the components `labels`, on the `served`
    floor, but those in `skip` (the walkway's, and those holding a target it misses): a name
    for each."""
    sizes = np.bincount(labels[served], minlength=int(labels.max()) + 1)
    sizes[0] = 0
    sizes[sorted(skip)] = 0
    out = []
    for lab in np.flatnonzero(sizes * grid.cell ** 2 >= POCKET_AREA):
        ii, jj = np.nonzero(labels == lab)
        x = grid.x0 + (float(jj.mean()) + 0.5) * grid.cell
        y = grid.y0 + (float(ii.mean()) + 0.5) * grid.cell
        out.append(f"floor pocket of {sizes[lab] * grid.cell ** 2:.2f} m^2 at "
                   f"({x:.1f}, {y:.1f})")
    return out


def clearance(radius: float, cell: float) -> float:
    """How near a wall or an object's box an agent's centre may come in this term: its radius
    and a cell, measured exactly from each cell's centre. The navigation measure erodes its own
    raster (which may lie up to half a cell past an edge) by the radius and half a cell, so a
    cell this term allows is allowed there on any alignment of its grid, and a path one cell
    wide here is not lost to the measure's different cells."""
    return radius + cell


def room_floor(shape: RoomShape, radius: float = AGENT_RADIUS, cell: float = CELL) -> RoomFloor:
    """The fixed part of a room's circulation, with the doors and landings the empty room can
    serve as targets (the others are reported, not counted)."""
    grid = Grid.covering(sg.Polygon(shape.room.polygon).bounds, cell)
    centres = grid.rasterise([floor_polygon(shape).buffer(-clearance(radius, cell))])
    targets = static_targets(shape, grid, radius, centres)
    labels = ndimage.label(centres)[0]
    _, missed, best, _ = _best(targets, labels)
    if missed:
        log.warning("room %s: %s cannot be reached even in the empty room", shape.room.name,
                    ", ".join(missed))
    served = labels == best if best else np.zeros_like(centres)
    return RoomFloor(grid, centres, [t for t in targets if t.name not in missed], missed,
                     served)


def standing(state: State, room: str) -> list[str]:
    """The room's objects with a placement on the room itself (on its floor, against a wall:
    a dining chair stands on the floor though pulled up to its table), by name: what can
    block the agent. Things resting only on other objects lie within them."""
    out = []
    for stage in ("large", "medium", "small"):
        for n in state.members(room, stage):
            ob = state.objects[n]
            if any(p.parent in state.rooms for p in ob.placements):
                out.append(n)
    return sorted(out)


def _pose_key(ob: ObjState) -> tuple[Any, ...]:
    return (id(ob.asset), *np.round(ob.position, 6).tolist(), round(float(ob.yaw), 6))


class _RoomCache:
    """A room's fixed floor, each standing object's raster by pose, and the last result.
    `margin`: how near an object's box an agent's centre may come (`clearance`)."""

    def __init__(self, fixed: RoomFloor, radius: float, cell: float):
        self.fixed, self.radius, self.margin = fixed, radius, clearance(radius, cell)
        self.patches: dict[str, tuple[tuple[Any, ...], list[Patch], Target | None]] = {}
        self.reach: dict[str, tuple[tuple[Any, ...], list[Patch]]] = {}
        self.last: tuple[tuple[Any, ...], Walkway] | None = None
        self.evaluations = 0

    def object_patches(self, ob: ObjState, floor_z: float) -> tuple[list[Patch], Target | None]:
        """The centres `ob` keeps the agent from at its pose (within the agent's radius of its
        collision pieces' boxes that reach into the band) and, for a large object whose front
        matters, the cells in front of it (both cached by pose)."""
        key = _pose_key(ob)
        got = self.patches.get(ob.name)
        if got is not None and got[0] == key:
            return got[1], got[2]
        assert ob.boxes is not None  # the state sets them when the object is added
        rotation = yaw_matrix(ob.yaw)[:2, :2]
        position = np.asarray(ob.position[:2], float)
        # its solid pieces only: the space it keeps free (a door's sweep, a clear front) is
        # where an agent stands to use it
        boxes = band_boxes(ob.boxes[:ob.n_solid], float(ob.position[2]) - floor_z)
        patches = self.fixed.grid.near_boxes(boxes, rotation, position, self.margin)
        front = None
        if ob.stage in FRONT_STAGES:
            local = access_points([getattr(t, "value", t) for t in ob.tags],
                                  ob.asset.mesh.bounds, self.radius)
            if local:
                discs = [self.fixed.grid.disc(rotation @ p + position, FRONT_TOLERANCE)
                         for p in local]
                front = Target(f"front of {ob.name}", [d for d in discs if d is not None])
        self.patches[ob.name] = (key, patches, front)
        return patches, front


    def beside(self, ob: ObjState, floor_z: float) -> list[Patch]:
        """The cells within `FRONT_TOLERANCE` of the centres `ob` keeps the agent from: where
        an agent stands to reach it (cached by pose)."""
        key = _pose_key(ob)
        got = self.reach.get(ob.name)
        if got is not None and got[0] == key:
            return got[1]
        assert ob.boxes is not None  # the state sets them when the object is added
        boxes = band_boxes(ob.boxes, float(ob.position[2]) - floor_z)
        patches = self.fixed.grid.near_boxes(boxes, yaw_matrix(ob.yaw)[:2, :2],
                                             np.asarray(ob.position[:2], float),
                                             self.margin + FRONT_TOLERANCE)
        self.reach[ob.name] = (key, patches)
        return patches


def room_cache(shape: RoomShape, radius: float = AGENT_RADIUS, cell: float = CELL
               ) -> _RoomCache:
    """An empty cache of a room's circulation: its fixed floor, for `walkway` to fill."""
    return _RoomCache(room_floor(shape, radius, cell), radius, cell)


def walkway(state: State, room: str, radius: float = AGENT_RADIUS, cell: float = CELL,
            cache: _RoomCache | None = None) -> Walkway:
    """The circulation of `room` in the state's current arrangement (`cache`: what an earlier
    evaluation of this room and state kept, made with the same radius and cell)."""
    cache = cache or room_cache(state.rooms[room], radius, cell)
    names = standing(state, room)
    key = tuple(_pose_key(state.objects[n]) + (n,) for n in names)
    if cache.last is not None and cache.last[0] == key:
        return cache.last[1]
    cache.evaluations += 1
    fixed = cache.fixed
    floor_z = float(getattr(state.rooms[room], "elevation", 0.0))
    blocked = np.zeros(fixed.grid.shape, bool)
    targets = list(fixed.targets)
    here = set(names)
    for n in names:
        patches, front = cache.object_patches(state.objects[n], floor_z)
        paint(blocked, patches)
        if front is not None:
            # a chair pulled up to a desk stands where its user does: reaching it will do
            seats = sorted(c for c in state.children(n) if c in here)
            targets.append(Target(front.name, front.patches + [
                p for c in seats for p in cache.beside(state.objects[c], floor_z)]))
    labels = ndimage.label(fixed.centres & ~blocked)[0]
    count, missed, best, counted = _best(targets, labels)
    cut_off = pockets(labels, fixed.served, counted | {best}, fixed.grid) if best else []
    result = Walkway(count, missed, list(fixed.unservable), cut_off)
    cache.last = (key, result)
    return result


class Circulation(Constraint):
    """Violated by `CIRCULATION_WEIGHT` times the number of doors, landings and large objects'
    fronts a walking agent of `radius` cannot reach from the rest in room `room` (see the
    module). Keeps, per solver state it is evaluated on, the room's caches (they go when the
    state goes)."""

    def __init__(self, room: str, radius: float = AGENT_RADIUS, cell: float = CELL):
        super().__init__()
        self.room, self.radius, self.cell = room, radius, cell
        self._caches: weakref.WeakKeyDictionary[State, _RoomCache] = weakref.WeakKeyDictionary()

    def walkway(self, state: State) -> Walkway:
        """The room's circulation in the state's current arrangement, from cache if unchanged."""
        cache = self._caches.get(state)
        if cache is None:
            cache = self._caches[state] = room_cache(state.rooms[self.room], self.radius,
                                                     self.cell)
        return walkway(state, self.room, self.radius, self.cell, cache)

    def compute(self, ev: EvalContext, env: Env) -> float:
        """The weighted count of unreachable targets in the room's current arrangement."""
        return CIRCULATION_WEIGHT * self.watched(ev).violation

    def watched(self, ev: EvalContext) -> Walkway:
        """The room's walkway in the evaluated state, watching every object in the room."""
        state = ev.view
        if not isinstance(state, State):
            raise TypeError(f"circulation needs the solver's State, got {type(state).__name__}")
        ev.watch_membership()
        # what can block the agent stands on the room itself: a thing moved on a shelf
        # changes nothing here, and one given another parent (off the floor or onto it, to
        # another desk: a pulled-up chair) is named by `notify(relinked=...)`
        names = standing(state, self.room)
        ev.watch(names)
        ev.watch_children([*state.rooms, *names])
        return self.walkway(state)

    def label(self) -> str:
        """`circulation(room)`."""
        return f"circulation({self.room})"


class FloorPockets(Scalar):
    """The number of floor pockets (see the module) in the room of `circulation`, from its
    cached walkway."""

    def __init__(self, circulation: Circulation):
        super().__init__()
        self.circulation = circulation

    def compute(self, ev: EvalContext, env: Env) -> float:
        """How many pockets of floor the room's furniture walls in."""
        return float(len(self.circulation.watched(ev).pockets))

    def label(self) -> str:
        """`floor_pockets(room)`."""
        return f"floor_pockets({self.circulation.room})"


def with_circulation(problem: Problem, room: str) -> Problem:
    """`problem` with the room's circulation constraint (named `CIRCULATION`) and its floor
    pockets' score (`FLOOR_POCKETS`) added."""
    node = Circulation(room)
    return problem + Problem({CIRCULATION: node},
                             {FLOOR_POCKETS: FloorPockets(node).minimize(POCKET_WEIGHT)})


def circulation_report(problem: Problem, state: State, room: str) -> dict[str, Any] | None:
    """The `circulation` record of `room` (see `Walkway.to_json`) if `problem` holds the
    circulation constraint, else None."""
    node = problem.constraints.get(CIRCULATION)
    if not isinstance(node, Circulation):
        return None
    return node.walkway(state).to_json()
