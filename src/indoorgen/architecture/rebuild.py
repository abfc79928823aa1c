"""The architecture of a saved scene, rebuilt from what scene.json records: a whole home's from
its floorplan (solidified again, each door's leaf where scene.json's `doors` records it; a scene
saved before doors opened has them shut), a single room's from its polygon. Validation and
re-export use this, so neither has to store meshes."""
from __future__ import annotations

from indoorgen.architecture.room import RoomGeometry, build_room
from indoorgen.architecture.solidify import Architecture, room_geometries, solidify
from indoorgen.model.floorplan_io import from_json
from indoorgen.model.scene import Scene


def scene_architecture(scene: Scene, doors: str | None = None
                       ) -> tuple[dict[str, RoomGeometry], Architecture | None]:
    """(room geometry by room name, the solidified home or None for a single room); `doors`
    (a mode of `architecture.doors.DOOR_MODES`) re-stands a home's leaves instead of using
    the recorded values."""
    if scene.floorplan is not None:
        states = doors or (scene.doors if scene.doors is not None else "closed")
        arch = solidify(from_json(scene.floorplan), seed=scene.seed, doors=states)
        return room_geometries(arch), arch
    return {n: build_room(r) for n, r in scene.rooms.items()}, None
