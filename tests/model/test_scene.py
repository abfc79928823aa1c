"""scene.json records of the data model."""
from __future__ import annotations

from indoorgen.model.scene import Room


def test_scene_room_json_is_unchanged_for_single_rooms():
    """`Room.elevation` is written only when set, so single-room scene.json stays as before."""
    r = Room("living_room_0", "living_room", [(0, 0), (4, 0), (4, 3), (0, 3)])
    assert set(r.to_json()) == {"name", "type", "polygon", "height", "wall_thickness",
                                "storey", "doors"}
    up = Room("bedroom_2", "bedroom", [(0, 0), (4, 0), (4, 3), (0, 3)], storey=1, elevation=3.0)
    assert up.to_json()["elevation"] == 3.0
    assert Room.from_json(up.to_json()) == up and Room.from_json(r.to_json()) == r
