"""Hand-built scenes for the quality tests: one rectangular room (wall_0 along y = 0, its inner
face looking +y; wall_1 along x = width), objects put at given poses with their declared parent
surface, and the report or rule context over them."""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from indoorgen.architecture.room import build_room, rectangle
from indoorgen.assets import get_factory
from indoorgen.assets.cache import AssetCache
from indoorgen.model.scene import Pose, RelationInstance, Room, Scene, SceneObject
from indoorgen.quality.context import Context, build_context
from indoorgen.quality.layout import quality_report

ROOM = "room_0"
#: yaw turning an object's front to +y, -y, +x, -x
FACE_UP, FACE_DOWN, FACE_RIGHT, FACE_LEFT = math.pi / 2, -math.pi / 2, 0.0, math.pi


def new_scene(room_type: str = "living_room", width: float = 6.0, depth: float = 5.0) -> Scene:
    """An empty scene of one `width` x `depth` room of `room_type` called `ROOM`."""
    room = Room(ROOM, room_type, rectangle(width, depth), 2.7, 0.12)
    return Scene(seed=0, rooms={ROOM: room})


def put(sc: Scene, generator: str, x: float, y: float, yaw: float = 0.0, *, z: float = 0.0,
        parent: str = "floor", seed: int = 0, name: str | None = None,
        params: dict[str, Any] | None = None, joints: bool = False) -> str:
    """Add a `generator` object at (x, y, z) turned by `yaw`, resting on `parent` ("floor",
    "wall_<i>" of the room, or an object name: its top). `joints`: draw params that articulate."""
    fac = get_factory(generator)
    if params is None:
        draws = (fac.sample_params(np.random.default_rng(seed + k)) for k in range(40))
        params = next(p for p in draws if not joints or fac.joints(fac.resolve(p)))  # type: ignore[attr-defined]
    name = name or f"{generator}_{len(sc.objects)}"
    if parent == "floor":
        rel = RelationInstance("StableAgainst(bottom,floor,0)", ROOM, "bottom", "floor")
    elif parent.startswith("wall_"):
        rel = RelationInstance("StableAgainst(back,wall,0)", ROOM, "back", parent)
    else:
        rel = RelationInstance("StableAgainst(bottom,support_surface,0)", parent, "bottom", "top")
    sc.add_object(SceneObject(name, generator, dict(params), seed, Pose((x, y, z), yaw),
                              sorted(t.value for t in fac.tags), ROOM, [rel]))
    return name


def report(sc: Scene) -> dict[str, Any]:
    """The quality report of `sc` (a single room, no architecture)."""
    return quality_report(sc, {n: build_room(r) for n, r in sc.rooms.items()}, AssetCache())


def context(sc: Scene) -> Context:
    """The rules' view of `sc`."""
    return build_context(sc, {n: build_room(r) for n, r in sc.rooms.items()}, AssetCache())


def size(generator: str, seed: int = 0) -> np.ndarray:
    """Bounding-box size (x, y, z) of `generator`'s placeholder for params drawn from `seed`."""
    fac = get_factory(generator)
    return AssetCache().placeholder(generator, fac.sample_params(np.random.default_rng(seed))).extents
