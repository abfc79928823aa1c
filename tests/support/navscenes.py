"""Hand-built scenes for the navigation measures: rectangular rooms with doors, and box objects
whose placeholders a `BoxCache` builds from their `size` parameter (no generator needed)."""
from __future__ import annotations

from typing import Any

import trimesh

from indoorgen.architecture.room import RoomGeometry, build_room
from indoorgen.assets.cache import AssetCache
from indoorgen.assets.protocol import Asset
from indoorgen.model.scene import Door, Pose, Room, Scene, SceneObject


class BoxCache(AssetCache):
    """An asset cache whose every placeholder is a box of `params["size"]` (x, y, z), in the
    asset frame (origin at the centre of its bottom face)."""

    def placeholder(self, generator: str, params: dict[str, Any]) -> Asset:
        """A box asset with itself as its one convex collision piece."""
        sx, sy, sz = params["size"]
        mesh = trimesh.creation.box((sx, sy, sz))
        mesh.apply_translation((0.0, 0.0, sz / 2))
        return Asset(mesh, [], collision=[("base", mesh)])


def rect_room(name: str, x0: float, y0: float, x1: float, y1: float,
              doors: tuple[tuple[str, int, float, float], ...] = (), *, storey: int = 0,
              elevation: float = 0.0) -> Room:
    """A rectangular room [x0, x1] x [y0, y1] (walls 0..3: bottom, right, top, left) with doors
    given as (name, wall, offset along the wall, width)."""
    return Room(name, "living_room", [(x0, y0), (x1, y0), (x1, y1), (x0, y1)], height=2.5,
                storey=storey, elevation=elevation,
                doors=[Door(n, w, off, width) for n, w, off, width in doors])


def box(name: str, room: str, x: float, y: float, size: tuple[float, float, float], *,
        z: float = 0.0, yaw: float = 0.0, tags: tuple[str, ...] = ("furniture",),
        stage: str = "large") -> SceneObject:
    """A box object of `size` whose bottom centre stands at (x, y, z), front along yaw."""
    return SceneObject(name, "box", {"size": list(size)}, 0, Pose((x, y, z), yaw), list(tags),
                       room, stage=stage)


def scene_of(rooms: list[Room], objects: list[SceneObject] = ()) -> tuple[Scene, dict[str, RoomGeometry]]:
    """A scene holding `rooms` and `objects`, and each room's geometry."""
    sc = Scene(seed=0, config={})
    for r in rooms:
        sc.rooms[r.name] = r
    for o in objects:
        sc.add_object(o)
    return sc, {r.name: build_room(r) for r in rooms}
