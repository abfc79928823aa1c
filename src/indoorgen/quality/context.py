"""What every layout rule reads: each placed object's world geometry (footprint, heights, front),
each room's outline and floor, and the `Check` record a rule returns per instance.

Geometry comes from the assets' placeholders (boxes and low-poly hulls that enclose the detailed
mesh within 2 cm and share its bounding box), so a whole home is measured in well under a second.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import shapely
import shapely.affinity as sa
import shapely.geometry as sg

from indoorgen.architecture.room import RoomGeometry
from indoorgen.assets.cache import AssetCache
from indoorgen.assets.protocol import Asset
from indoorgen.model.scene import Scene, SceneObject
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from indoorgen.solver.keep_free import BAND_MARGIN, OBSTACLE_BAND

#: how far a free-depth probe looks before it reports "open" (m); larger than any limit checked
PROBE_DEPTH = 3.0
#: obstacles to walking and opening are the parts of objects between these heights above the
#: floor (m): the solver's (`solver.keep_free.OBSTACLE_BAND`), which keeps fronts clear over it
OBSTACLE_LOW, OBSTACLE_HIGH = OBSTACLE_BAND


@dataclass(frozen=True)
class Check:
    """One rule instance: the room, the objects it concerns, the measured value, the limit it is
    held to (a number, a [low, high] pair or a phrase), and whether it passed."""

    room: str
    objects: tuple[str, ...]
    value: float | None
    limit: Any
    ok: bool
    detail: Mapping[str, float] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        """The instance's report record (values rounded to 4 decimals, `detail` when present)."""
        out: dict[str, Any] = {"room": self.room, "objects": list(self.objects),
                               "value": rnd(self.value), "limit": _rnd_limit(self.limit),
                               "ok": bool(self.ok)}
        if self.detail:
            out["detail"] = {k: rnd(v) for k, v in sorted(self.detail.items())}
        return out


def rnd(x: float | None) -> float | None:
    """`x` as a plain float rounded to 4 decimals (None and non-finite values as None)."""
    if x is None or not math.isfinite(float(x)):
        return None
    v = round(float(x), 4)
    return 0.0 if v == 0 else v


def _rnd_limit(limit: Any) -> Any:
    if isinstance(limit, (int, float)) and not isinstance(limit, bool):
        return rnd(limit)
    if isinstance(limit, (list, tuple)):
        return [_rnd_limit(v) for v in limit]
    return limit


@dataclass
class Placed:
    """One object with its world geometry: `footprint` (plan-view hull of the placeholder),
    `bottom`/`top` (world z), `floor` (its room's floor z), the local bounding box `lo`/`hi`."""

    obj: SceneObject
    asset: Asset
    footprint: sg.Polygon
    bottom: float
    top: float
    floor: float
    lo: np.ndarray
    hi: np.ndarray

    @property
    def name(self) -> str:
        """The object's name."""
        return self.obj.name

    @property
    def xy(self) -> np.ndarray:
        """World plan position of the local origin (the bottom-face centre)."""
        return np.asarray(self.obj.pose.position[:2], float)

    @property
    def front(self) -> np.ndarray:
        """World plan unit direction of the object's front (local +X)."""
        return np.asarray(self.obj.pose.front()[:2])

    def has(self, *tags: S) -> bool:
        """Whether the object carries any of `tags`."""
        return any(t.value in self.obj.tags for t in tags)

    def to_local(self, geom: Any) -> Any:
        """A shapely geometry in world plan coordinates expressed in this object's local frame."""
        x, y = self.xy
        moved = sa.translate(geom, -x, -y)
        return sa.rotate(moved, -self.obj.pose.yaw, origin=(0.0, 0.0), use_radians=True)

    def local_point(self, p: np.ndarray) -> np.ndarray:
        """A world plan point in this object's local frame."""
        c, s = math.cos(self.obj.pose.yaw), math.sin(self.obj.pose.yaw)
        d = np.asarray(p, float)[:2] - self.xy
        return np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]])

    def world_point(self, local: Iterable[float]) -> np.ndarray:
        """A local plan point in world coordinates."""
        c, s = math.cos(self.obj.pose.yaw), math.sin(self.obj.pose.yaw)
        u, v = local
        return self.xy + np.array([c * u - s * v, s * u + c * v])

    def footprint_between(self, z0: float, z1: float) -> sg.base.BaseGeometry:
        """The plan-view (world) extent of the object's solid between world heights `z0` and
        `z1`: each convex collision piece of its placeholder cut to that band, as the solver's
        keep-out checks see it (a bed whose headboard alone rises past a sill reaches a window
        with its headboard only)."""
        base = float(self.obj.pose.position[2])
        hulls = []
        for _, piece in self.asset.collision:
            part = piece.slice_plane((0.0, 0.0, z0 - base), (0.0, 0.0, 1.0))
            if len(part.vertices):
                part = part.slice_plane((0.0, 0.0, z1 - base), (0.0, 0.0, -1.0))
            if len(part.vertices) >= 3:
                hulls.append(sg.MultiPoint([tuple(self.world_point(q))
                                            for q in part.vertices[:, :2]]).convex_hull)
        return shapely.union_all(hulls) if hulls else sg.Polygon()

    def surface_height(self, subpart: Subpart, name: str | None = None) -> float | None:
        """Highest world z of the asset's horizontal surfaces with role `subpart` (or named
        `name`); None if there is none."""
        zs = [float(s.origin[2]) for s in self.asset.surfaces
              if (s.subpart == subpart or s.name == name) and abs(s.normal[2]) > 0.99]
        return self.obj.pose.position[2] + max(zs) if zs else None


@dataclass
class Context:
    """A scene seen by the rules: placed objects by name, rooms' outlines and floors, the
    children of each object (what rests on or hangs from it), and the architecture if any."""

    scene: Scene
    rooms: Mapping[str, RoomGeometry]
    cache: AssetCache
    placed: dict[str, Placed]
    outlines: dict[str, sg.Polygon]
    children: dict[str, list[str]]
    architecture: Any = None

    def in_room(self, room: str, *tags: S) -> list[Placed]:
        """The objects of `room` carrying any of `tags` (all of them if no tag is given)."""
        return [p for p in self.placed.values()
                if p.obj.room == room and (not tags or p.has(*tags))]

    def with_tags(self, *tags: S) -> list[Placed]:
        """Every object carrying any of `tags`, in placement order."""
        return [p for p in self.placed.values() if p.has(*tags)]

    def room_type(self, room: str) -> str:
        """The type of `room`."""
        return self.scene.rooms[room].room_type

    def descendants(self, name: str) -> set[str]:
        """Every object resting on or hanging from `name`, transitively."""
        out: set[str] = set()
        todo = list(self.children.get(name, ()))
        while todo:
            n = todo.pop()
            if n not in out:
                out.add(n)
                todo.extend(self.children.get(n, ()))
        return out

    def pulled_up(self, name: str) -> set[str]:
        """Every object of `name`'s room with a relation to `name` besides resting on it: a
        chair at a desk, a stool at an island (one moves it to open what is behind it, so the
        solver lets it stand in `name`'s clear space)."""
        room = self.placed[name].obj.room
        return {q.name for q in self.in_room(room)
                if q.name != name and any(r.parent == name for r in q.obj.relations)}

    def walls_outside(self, room: str) -> sg.Polygon:
        """The plan region just outside `room`'s outline (a 10 m frame): where its walls stand."""
        poly = self.outlines[room]
        return poly.buffer(10.0, join_style="mitre").difference(poly)

    def obstacles(self, room: str, exclude: set[str]) -> list[Placed]:
        """Objects of `room` that block walking and opening: solid between `OBSTACLE_LOW` and
        `OBSTACLE_HIGH` above the floor, not rugs or small objects, not in `exclude`."""
        return [p for p in self.placed.values()
                if p.obj.room == room and p.name not in exclude
                and not p.has(S.FloorCovering, S.SmallObject)
                and p.bottom < p.floor + OBSTACLE_HIGH and p.top > p.floor + OBSTACLE_LOW]


def is_wall_hung(obj: SceneObject) -> bool:
    """Whether `obj` hangs from a wall of its room (its first relation's parent surface)."""
    return bool(obj.relations) and obj.relations[0].parent == obj.room \
        and obj.relations[0].parent_surface.startswith("wall_")


def on_floor(obj: SceneObject) -> bool:
    """Whether `obj` stands on its room's floor."""
    return bool(obj.relations) and obj.relations[0].parent == obj.room \
        and obj.relations[0].parent_surface == "floor"


def build_context(scene: Scene, rooms: Mapping[str, RoomGeometry], cache: AssetCache,
                  architecture: Any = None) -> Context:
    """Every object's placeholder geometry in the world, and each room's outline."""
    placed: dict[str, Placed] = {}
    children: dict[str, list[str]] = {}
    for n, o in scene.objects.items():
        asset = cache.placeholder(o.generator, o.params)
        hull = cache.hull_2d(o.generator, o.params)
        c, s = math.cos(o.pose.yaw), math.sin(o.pose.yaw)
        pts = hull @ np.array([[c, s], [-s, c]]) + np.asarray(o.pose.position[:2])
        lo, hi = (np.asarray(b, float) for b in asset.mesh.bounds)
        z = o.pose.position[2]
        floor = scene.rooms[o.room].elevation if o.room in scene.rooms else 0.0
        placed[n] = Placed(o, asset, sg.Polygon(pts), z + lo[2], z + hi[2], floor, lo, hi)
        if o.parent in scene.objects:
            children.setdefault(o.parent, []).append(n)
    outlines = {n: sg.Polygon(r.polygon) for n, r in scene.rooms.items()}
    return Context(scene, rooms, cache, placed, outlines, children, architecture)


def free_depth(ctx: Context, p: Placed, half_width: float | None = None,
               start: float | None = None, exclude: set[str] | None = None) -> float:
    """Free depth (m) in front of `p`: from its front face (or local x `start`) along its front,
    over a band of `half_width` either side of its centreline (default: its own width), to the
    first wall or obstacle footprint; `PROBE_DEPTH` when open that far."""
    hw = (p.hi[1] - p.lo[1]) / 2 - BAND_MARGIN if half_width is None else half_width
    x0 = p.hi[0] if start is None else start
    cy = (p.hi[1] + p.lo[1]) / 2
    band = sg.box(x0, cy - hw, x0 + PROBE_DEPTH, cy + hw)
    skip = {p.name} | ctx.descendants(p.name) | (exclude or set())
    blockers: list[Any] = [ctx.walls_outside(p.obj.room)]
    blockers += [q.footprint for q in ctx.obstacles(p.obj.room, skip)]
    depth = PROBE_DEPTH
    for geom in blockers:
        hit = p.to_local(geom).intersection(band)
        if not hit.is_empty and hit.area > 1e-8:
            depth = min(depth, hit.bounds[0] - x0)
    return max(depth, 0.0)


def angle_deg(a: np.ndarray, b: np.ndarray) -> float:
    """Angle between plan vectors `a` and `b` in degrees (0..180)."""
    na, nb = np.linalg.norm(a), np.linalg.norm(b)
    if na < 1e-12 or nb < 1e-12:
        return 0.0
    return math.degrees(math.acos(float(np.clip(np.dot(a, b) / (na * nb), -1.0, 1.0))))


def nearest(p: Placed, others: Iterable[Placed]) -> Placed | None:
    """The object of `others` whose footprint is nearest to `p`'s (None if there is none)."""
    best = min(others, key=lambda q: (p.footprint.distance(q.footprint), q.name), default=None)
    return best


#: a rule: (context) -> its instances; registered with `rule`
RuleFn = Callable[[Context], list[Check]]
#: every rule by name: (function, hard)
RULES: dict[str, tuple[RuleFn, bool]] = {}


def rule(name: str, *, hard: bool = False) -> Callable[[RuleFn], RuleFn]:
    """Register a layout rule under `name` (hard: a failed instance fails the scene)."""
    def deco(fn: RuleFn) -> RuleFn:
        RULES[name] = (fn, hard)
        return fn
    return deco
