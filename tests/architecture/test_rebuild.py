"""A saved scene's architecture rebuilt from scene.json (indoorgen.architecture.rebuild)."""
from __future__ import annotations

from indoorgen.architecture.rebuild import scene_architecture
from indoorgen.architecture.room import rectangle
from indoorgen.model.scene import Door, Room, Scene
from support.plans import apartment


def test_a_single_room_is_rebuilt_from_its_polygon():
    room = Room("bedroom_0", "bedroom", rectangle(4.0, 3.5), doors=[Door("door_0", 0, 2.0)])
    rooms, arch = scene_architecture(Scene(seed=0, rooms={room.name: room}))
    assert arch is None and set(rooms) == {"bedroom_0"}
    assert rooms["bedroom_0"].room is room and len(rooms["bedroom_0"].walls) == 4


def test_a_home_is_solidified_again_from_its_floorplan():
    scene = Scene(seed=0, floorplan=apartment())
    rooms, arch = scene_architecture(scene)
    assert arch is not None and set(rooms) == set(arch.rooms)
    assert {r["name"] for r in apartment()["storeys"][0]["rooms"]} == set(rooms)
    assert any(e.generator for e in arch.elements)  # seeded: catalogue doors and windows
