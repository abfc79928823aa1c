"""Small valid data files for reader tests: a scene.json with one empty room."""
from __future__ import annotations

from typing import Any

from indoorgen.model.scene import Door, Room, Scene


def minimal_scene(seed: int = 0) -> dict[str, Any]:
    """A valid scene.json object: one empty 4 x 3 m living room with one door."""
    room = Room("living_room_0", "living_room", [(0, 0), (4, 0), (4, 3), (0, 3)],
                doors=[Door("door_0", 0, 2.0)])
    return Scene(seed=seed, rooms={room.name: room}).to_json()
