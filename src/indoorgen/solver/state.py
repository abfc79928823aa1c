"""The solver's state: rooms, objects, their poses and plane assignments, and collision.

`State` is also the `ObjectView` the constraint evaluator reads: tags, relations and the few
geometric facts the DSL's terms need, each cached per object until the object moves.
"""
from __future__ import annotations

import bisect
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, Protocol

import fcl
import numpy as np
import shapely
import shapely.geometry as sg
import trimesh

from indoorgen.assets import Asset, Surface, get_factory
from indoorgen.assets.cache import AssetCache, convex_shape, mesh_bvh, params_key
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.constraints.bounds import Context
from indoorgen.constraints.relations import Relation, parse_relation
from indoorgen.model.frames import yaw_matrix
from indoorgen.model.scene import Room, Scene
from indoorgen.model.tags import Semantics, Subpart
from indoorgen.solver.broadphase import (
    DOOR_ZONE,
    PIECE_SOLID,
    SCREEN_ZONE,
    SOLID,
    WINDOW_ZONE,
    Broadphase,
    world_boxes,
)
from indoorgen.solver.keep_free import (
    SCREEN_LIFT,
    SCREEN_STANDS,
    WINDOW_DRESSINGS,
    WINDOW_SCREENS,
    WINDOW_TALL,
    keep_free_volumes,
    window_volume,
    yields,
)

#: height of door clearance keep-out volumes (m)
DOOR_ZONE_HEIGHT = 2.0


class RoomShape(Protocol):
    """What the solver reads of one room's architecture (the floorplan's room geometry provides
    it; a home's rooms also carry an `elevation`, the height of their floor, and `windows`, each
    window's world box (2, 3), before which the solver keeps a zone free)."""

    room: Room
    surfaces: list[Surface]
    door_zones: list[sg.Polygon]

    def collision_meshes(self) -> list[trimesh.Trimesh]:
        """Every solid the solver must not penetrate: walls, floor and ceiling slabs."""
        ...


@dataclass
class Placement:
    """One planar relation of an object: its `child_surface` against `parent_surface` of
    `parent` (a room or an object)."""

    relation: Relation
    parent: str
    child_surface: str
    parent_surface: str


@dataclass
class ObjState:
    """One object being solved: what it is (generator, params, the seed they came from, tags),
    where it belongs (room, stage), its placeholder asset, relations and pose, and its collision
    pieces as registered in the room's broadphase."""

    name: str
    generator: str
    params: dict[str, Any]
    seed: int
    tags: frozenset
    room: str
    stage: str
    asset: Asset
    placements: list[Placement]
    position: np.ndarray
    yaw: float
    #: the counted context the object was added to (its parent choices come from it), if any
    context: Context | None = None
    #: the loop variables bound when it was added (to re-evaluate the context's parent sets)
    env: dict = field(default_factory=dict)
    cobjs: list[fcl.CollisionObject] = field(default_factory=list)
    #: local bounding boxes (k, 2, 3) of the collision pieces behind `cobjs`: the solid pieces
    #: first, then the keep-free ones
    boxes: np.ndarray | None = None
    #: how many of `boxes` are solid (what stands in the way of a walking agent)
    n_solid: int = 0
    #: are its keep-free pieces still to be built (`State.collides` builds them)?
    free_pending: bool = False
    #: is `asset` still the rough placeholder (`AssetCache.trial_placeholder`: its body not
    #: yet hollowed where things are put away), to be swapped for the placeholder by
    #: `State.collides` once its pieces are found clear?
    rough: bool = False


class State:
    """Rooms and objects being solved, with a broadphase per room over the placeholders' solid
    convex pieces."""

    def __init__(self, rooms: Mapping[str, RoomShape], cache: AssetCache):
        self.rooms = rooms
        self.cache = cache
        self.objects: dict[str, ObjState] = {}
        self._room_tags = {n: frozenset({Semantics.Room, g.room.room_type}) for n, g in rooms.items()}
        self._room_surfaces = {n: {s.name: s for s in g.surfaces} for n, g in rooms.items()}
        # rooms never change: their outlines are built once (terms ask for them every step)
        self._room_polygons = {n: sg.Polygon(g.room.polygon) for n, g in rooms.items()}
        self._room_rings = {n: p.exterior for n, p in self._room_polygons.items()}
        self._ids = frozenset(rooms)
        self._geo: dict[str, dict] = {}
        self._children: dict[str, set[str]] = {}
        self._members: dict[tuple[str, str], list[str]] = {}  # (room, stage) -> sorted names
        # one broadphase per room: walls keep rooms apart, so an object only ever meets its own
        # room's objects and the (shared) architecture; this keeps each query small in a home
        self.static: list[fcl.CollisionObject] = []
        static_boxes: list[np.ndarray] = []
        kinds: list[int] = []
        # of each static piece: SOLID, DOOR_ZONE, WINDOW_ZONE or SCREEN_ZONE
        self.static_kinds = kinds

        def fixed(shape: fcl.CollisionGeometry, mesh: trimesh.Trimesh, kind: int) -> None:
            self.static.append(fcl.CollisionObject(shape, fcl.Transform()))
            static_boxes.append(np.asarray(mesh.bounds, float).ravel())
            kinds.append(kind)
        for g in rooms.values():
            for m in g.collision_meshes():
                fixed(mesh_bvh(m), m, SOLID)
            for zone in g.door_zones:  # solid keep-out prisms: nothing may stand inside them
                z0 = float(getattr(g, "elevation", 0.0))  # a home's upper storeys stand higher
                for piece in keep_out_prisms(zone, z0, z0 + DOOR_ZONE_HEIGHT):
                    fixed(convex_shape(piece), piece, DOOR_ZONE)
            for bounds in getattr(g, "windows", ()):  # a home's rooms know their windows
                piece = window_volume(bounds)
                fixed(convex_shape(piece), piece, WINDOW_ZONE)
                below = window_volume(bounds, float(getattr(g, "elevation", 0.0)) + SCREEN_LIFT)
                fixed(convex_shape(below), below, SCREEN_ZONE)
        self.broadphase: dict[str, Broadphase] = {
            room: Broadphase(self.static, np.array(static_boxes).reshape(-1, 6), np.array(kinds, int))
            for room in rooms}
        # (generator, params) -> keep-free volumes as fcl solids, their local boxes and kinds
        self._free: dict[tuple, tuple[list[fcl.Convex], np.ndarray, np.ndarray]] = {}

    # -- ObjectView ------------------------------------------------------------------------
    def all_ids(self) -> frozenset[str]:
        """Every room and object name."""
        return self._ids

    def tags(self, o: str) -> frozenset:
        """Semantic tags of a room (Room and its type) or object (its generator's)."""
        return self._room_tags[o] if o in self.rooms else self.objects[o].tags

    def generator(self, o: str) -> str:
        """The generator that made object `o` ("" for a room)."""
        return "" if o in self.rooms else self.objects[o].generator

    def params(self, o: str) -> dict[str, Any]:
        """The generator params of object `o` (empty for a room)."""
        return {} if o in self.rooms else self.objects[o].params

    def relations(self, o: str) -> list[tuple[Relation, str]]:
        """(relation, parent) of each of the object's placements (none for a room)."""
        if o in self.rooms:
            return []
        return [(p.relation, p.parent) for p in self.objects[o].placements]

    def _cached(self, o: str, what: str, fn: Callable[[], Any]) -> Any:
        d = self._geo.setdefault(o, {})
        v = d.get(what)
        if v is None:
            v = d[what] = fn()
        return v

    def center(self, o: str) -> np.ndarray:
        """World centre of the object's placeholder bounds (a room's: its polygon's centroid at
        half height)."""
        if o in self.rooms:
            g = self.rooms[o]
            c = self._room_polygons[o].centroid
            return np.array([c.x, c.y, g.room.height / 2])

        def f():
            ob = self.objects[o]
            b = ob.asset.mesh.bounds
            return yaw_matrix(ob.yaw) @ ((b[0] + b[1]) / 2) + ob.position
        return self._cached(o, "center", f)

    def front(self, o: str) -> np.ndarray:
        """Unit vector the object faces (its local +X); +X for a room."""
        if o in self.rooms:
            return np.array([1.0, 0.0, 0.0])
        y = self.objects[o].yaw
        return np.array([math.cos(y), math.sin(y), 0.0])

    def side_axis(self, o: str) -> np.ndarray:
        """Unit vector to the object's left (its local +Y); +Y for a room."""
        if o in self.rooms:
            return np.array([0.0, 1.0, 0.0])
        y = self.objects[o].yaw
        return np.array([-math.sin(y), math.cos(y), 0.0])

    def front_point(self, o: str) -> np.ndarray:
        """Middle of the object's front face (a room: its centre)."""
        if o in self.rooms:
            return self.center(o)
        ob = self.objects[o]
        b = ob.asset.mesh.bounds
        return yaw_matrix(ob.yaw) @ np.array([b[1][0], 0.0, (b[0][2] + b[1][2]) / 2]) + ob.position

    def floor_z(self, o: str) -> float:
        """Height of the floor of the room `o` is in (or is): a home's upper storeys stand
        higher than z = 0."""
        room = o if o in self.rooms else self.objects[o].room
        return float(getattr(self.rooms[room], "elevation", 0.0))

    def yaw(self, o: str) -> float:
        """The object's turn about +Z (0 for a room)."""
        return 0.0 if o in self.rooms else float(self.objects[o].yaw)

    def extents(self, o: str) -> np.ndarray:
        """Size of the object's placeholder bounds in its own frame (a room: its plan bounds and
        height)."""
        if o in self.rooms:
            g = self.rooms[o]
            x0, y0, x1, y1 = self._room_polygons[o].bounds
            return np.array([x1 - x0, y1 - y0, g.room.height])
        b = self.objects[o].asset.mesh.bounds
        return b[1] - b[0]

    def footprint(self, o: str) -> sg.Polygon:
        """Plan-view outline of the object (its placeholder's 2D hull, posed) or the room."""
        if o in self.rooms:
            return self._room_polygons[o]

        def f():
            ob = self.objects[o]
            hull = self.cache.hull_2d(ob.generator, ob.params)
            r = yaw_matrix(ob.yaw)[:2, :2]
            return sg.Polygon(hull @ r.T + ob.position[:2])
        return self._cached(o, "footprint", f)

    def outline(self, o: str) -> sg.Polygon | sg.LinearRing:
        """What distances are measured to: a room's walls (its boundary ring), an object's
        footprint."""
        if o in self.rooms:
            return self._room_rings[o]
        return self.footprint(o)

    def world_mesh(self, o: str) -> trimesh.Trimesh:
        """The object's placeholder mesh, posed in world coordinates."""
        def f() -> trimesh.Trimesh:
            ob = self.objects[o]
            m = ob.asset.mesh.copy()
            t = np.eye(4)
            t[:3, :3] = yaw_matrix(ob.yaw)
            t[:3, 3] = ob.position
            m.apply_transform(t)
            return m
        return self._cached(o, "mesh", f)

    def support_polygon(self, o: str) -> sg.Polygon | None:
        """Plan-view polygon of the surface the object rests on, if that is another object's
        support surface (a tabletop, a shelf); else None."""
        if o in self.rooms:
            return None
        for p in self.objects[o].placements:
            role = getattr(p.relation, "parent", None)
            if p.parent not in self.rooms and role is not None and role.value == "support_surface":
                s = self.surface_world(p.parent, p.parent_surface)
                return sg.Polygon(s.corners()[:, :2])
        return None

    # -- surfaces ---------------------------------------------------------------------------
    def surfaces(self, o: str) -> list[Surface]:
        """All surfaces of `o` in world coordinates."""
        if o in self.rooms:
            return list(self._room_surfaces[o].values())
        ob = self.objects[o]
        r = yaw_matrix(ob.yaw)
        return [s.transformed(r, ob.position) for s in ob.asset.surfaces]

    def surface_world(self, o: str, name: str) -> Surface:
        """Surface `name` of `o` in world coordinates."""
        if o in self.rooms:
            return self._room_surfaces[o][name]
        ob = self.objects[o]
        return ob.asset.surface(name).transformed(yaw_matrix(ob.yaw), ob.position)

    # -- mutation ---------------------------------------------------------------------------
    def _transform(self, ob: ObjState) -> fcl.Transform:
        return fcl.Transform(yaw_matrix(ob.yaw), np.asarray(ob.position, float))

    def _boxes(self, ob: ObjState) -> np.ndarray:
        """World boxes of the object's collision pieces at its current pose."""
        assert ob.boxes is not None  # set by _register before any pose change
        return world_boxes(ob.boxes, yaw_matrix(ob.yaw), np.asarray(ob.position, float))

    def _keep_free(self, ob: ObjState, build: bool = True
                   ) -> tuple[list[fcl.Convex], np.ndarray, np.ndarray] | None:
        """The object's keep-free volumes (joint sweeps, use zones) as fcl solids with their
        local boxes, built once per (generator, params); None if `build` is False and they are
        not built yet and costly (a moving link's box needs the detailed parts)."""
        key = params_key(ob.generator, ob.params)
        got = self._free.get(key)
        if got is None:
            fac = get_factory(ob.generator)
            costly = isinstance(fac, PartsFactory) and bool(ob.asset.joints)
            if costly and not build:
                return None
            links = fac.link_boxes(ob.params) if isinstance(fac, PartsFactory) and costly else {}
            got = self._free[key] = keep_free_volumes(ob.asset, ob.tags, fac.size_class, links)
        return got

    def _register(self, ob: ObjState, build: bool = False) -> None:
        """Put the object's pieces in its room's broadphase: its solid pieces, and its keep-free
        pieces if built (else `collides` builds them once the solid pieces are found clear:
        most poses an add tries collide anyway)."""
        tf = self._transform(ob)
        solid = self.cache.placeholder_convex(ob.generator, ob.params, ob.rough)
        got = self._keep_free(ob, build)
        ob.free_pending = got is None
        free, free_boxes, free_kinds = got if got is not None else \
            ([], np.zeros((0, 2, 3)), np.zeros(0, int))
        ob.cobjs = [fcl.CollisionObject(shape, tf) for shape in [*solid, *free]]
        solid_boxes = self.cache.placeholder_boxes(ob.generator, ob.params, ob.rough)
        ob.boxes, ob.n_solid = np.concatenate([solid_boxes, free_boxes]), len(solid_boxes)
        kinds = np.concatenate([np.full(len(solid), PIECE_SOLID), free_kinds])
        self.broadphase[ob.room].add(ob.name, ob.cobjs, self._boxes(ob), kinds, yields(ob.tags))

    def _unregister(self, ob: ObjState) -> None:
        self.broadphase[ob.room].remove(ob.name)

    def add(self, ob: ObjState) -> None:
        """Put an object into the scene: its relations, stage membership and collision pieces."""
        self.objects[ob.name] = ob
        self._ids = self._ids | {ob.name}
        bisect.insort(self._members.setdefault((ob.room, ob.stage), []), ob.name)
        self._link(ob)
        self._register(ob)

    def remove(self, name: str) -> ObjState:
        """Take an object out of the scene (everything `add` recorded) and return it, so it can
        be added back unchanged."""
        ob = self.objects.pop(name)
        self._ids = self._ids - {name}
        self._members[(ob.room, ob.stage)].remove(name)
        self._geo.pop(name, None)
        self._unlink(ob)
        self._unregister(ob)
        return ob

    def members(self, room: str, stage: str) -> list[str]:
        """Names of the objects of `room` placed in `stage`, sorted (kept up to date on add and
        remove, so a move does not scan the whole scene)."""
        return self._members.get((room, stage), [])

    def _link(self, ob: ObjState) -> None:
        for p in ob.placements:
            self._children.setdefault(p.parent, set()).add(ob.name)

    def _unlink(self, ob: ObjState) -> None:
        for p in ob.placements:
            self._children.get(p.parent, set()).discard(ob.name)

    def set_placements(self, name: str, placements: list[Placement]) -> None:
        """Replace an object's relations (keeping the parent -> children index right)."""
        ob = self.objects[name]
        self._unlink(ob)
        ob.placements = list(placements)
        self._link(ob)

    def children(self, name: str) -> set[str]:
        """Objects that rest on, hang from or otherwise relate to `name` directly."""
        return self._children.get(name, set())

    def descendants(self, name: str) -> list[str]:
        """Everything that rests on `name`, directly or through others, parents first."""
        out, stack = [], sorted(self.children(name))
        while stack:
            n = stack.pop(0)
            if n not in out:
                out.append(n)
                stack.extend(sorted(self.children(n)))
        return out

    def set_pose(self, name: str, position: np.ndarray, yaw: float) -> None:
        """Pose one object (alone: see `moves` for carrying what rests on it), keeping its
        cached geometry and broadphase boxes in step."""
        ob = self.objects[name]
        ob.position = np.asarray(position, float)
        ob.yaw = float(yaw)
        self._geo.pop(name, None)
        tf = self._transform(ob)
        for c in ob.cobjs:
            c.setTransform(tf)
        self.broadphase[ob.room].move(name, self._boxes(ob))

    def set_asset(self, name: str, params: dict[str, Any]) -> None:
        """Swap an object's params (and so its placeholder and collision pieces), keeping its
        pose (the rough placeholder until `collides` finds it clear, as for an object added)."""
        ob = self.objects[name]
        self._unregister(ob)
        ob.params = params
        ob.asset, ob.rough = self.cache.trial_placeholder(ob.generator, params)
        self._geo.pop(name, None)
        self._register(ob)

    def collides(self, name: str) -> bool:
        """Does object `name`'s placeholder (its solid convex pieces) overlap anything else:
        other objects of its room, walls, floor, ceiling, door keep-out zones, window keep-out
        zones if it is tall or wall-hung? Or do its keep-free pieces (the sweeps of its moving
        parts, its clear space) reach into a wall or into an object not resting on or under it?"""
        ob = self.objects[name]
        bp, windows = self.broadphase[ob.room], self._window_bound(ob)
        screens = bool(SCREEN_STANDS & ob.tags)
        if ob.free_pending or ob.rough:
            if bp.collides(name, windows=windows, screens=screens, carries=self._carries):
                return True
            self._unregister(ob)
            if ob.rough:  # clear: the pose is worth the placeholder's hollows
                ob.asset, ob.rough = self.cache.placeholder(ob.generator, ob.params), False
                self._geo.pop(name, None)
            self._register(ob, build=True)
        return bp.collides(name, windows=windows, screens=screens, carries=self._carries)

    def _carries(self, a: str, b: str) -> bool:
        """Does `b` belong in `a`'s keep-free space: resting on, in or from `a` (by its bottom: a
        cup on a shelf, a wall cabinet over a counter), directly or through others, or pulled up
        to it (a chair at a desk stands before its drawers; one pushes it back to open them)?"""
        seen, todo = set(), [b]
        while todo:
            n = todo.pop()
            for p in self.objects[n].placements if n in self.objects else ():
                if n == b and p.parent == a:
                    return True
                if getattr(p.relation, "child", None) != Subpart.Bottom:
                    continue
                if p.parent == a:
                    return True
                if p.parent not in seen and p.parent in self.objects:
                    seen.add(p.parent)
                    todo.append(p.parent)
        return False

    def window_bound(self, name: str) -> bool:
        """Must object `name` keep out of window zones (see `_window_bound`)?"""
        return self._window_bound(self.objects[name])

    def _window_bound(self, ob: ObjState) -> bool:
        """Must the object keep out of window zones: furniture standing on the floor taller than
        `WINDOW_TALL`, anything hung on a wall but a window dressing, or a screen wherever it
        stands (the report's window rule)?"""
        if WINDOW_SCREENS & ob.tags:
            return True
        if not ob.placements or ob.placements[0].parent != ob.room:
            return False
        surface = ob.placements[0].parent_surface
        if surface == "floor":  # its top over the floor, as the rule measures it
            top = float(ob.position[2] + ob.asset.mesh.bounds[1][2]) - self.floor_z(ob.name)
            return top > WINDOW_TALL
        return surface.startswith("wall_") and not WINDOW_DRESSINGS & ob.tags


def keep_out_prisms(zone: sg.Polygon, z0: float, z1: float) -> list[trimesh.Trimesh]:
    """Convex prisms from z0 to z1 covering a keep-out polygon (the polygon itself when convex,
    else its triangles)."""
    if zone.is_empty or zone.area < 1e-9:
        return []
    pieces = [zone] if zone.convex_hull.area - zone.area < 1e-9 else \
        [t for t in shapely.delaunay_triangles(zone).geoms if zone.contains(t.representative_point())]
    out = []
    for p in pieces:
        xy = np.asarray(p.exterior.coords)[:-1]
        pts = np.vstack([np.c_[xy, np.full(len(xy), z0)], np.c_[xy, np.full(len(xy), z1)]])
        out.append(trimesh.convex.convex_hull(pts))
    return out


def state_from_scene(scene: Scene, rooms: Mapping[str, RoomShape], cache: AssetCache) -> State:
    """Rebuild a solver state (placeholders, poses, relations) from a saved Scene, so a scene
    can be re-evaluated or validated without re-solving."""
    st = State(rooms, cache)
    for o in scene.objects.values():
        fac = get_factory(o.generator)
        ob = ObjState(o.name, o.generator, dict(o.params), o.seed, frozenset(fac.tags), o.room,
                      o.stage, cache.placeholder(o.generator, o.params),
                      [Placement(parse_relation(r.relation), r.parent, r.child_surface,
                                 r.parent_surface) for r in o.relations],
                      np.array(o.pose.position, float), float(o.pose.yaw))
        st.add(ob)
    return st
