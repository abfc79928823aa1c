"""Every built-in room program furnishes a room that passes the independent validator, with
the objects its program asks for."""
import collections

import pytest

from indoorgen import GenerateConfig, generate
from indoorgen.programs import ROOM_PROGRAMS
from indoorgen.validate import validate_scene

#: per room type, tags that must be present after solving (the program's hard minimums)
REQUIRED = {
    "bedroom": ["bed", "nightstand"],
    "kitchen": ["fridge", "range", "kitchen_cabinet"],
    "bathroom": ["toilet", "bathroom_sink", "toilet_roll_holder"],
    "office": ["desk", "office_chair", "bookcase", "book"],
    "utility": ["washing_machine"],
    "garage": ["shelf", "box"],
    "balcony": ["seating", "potted_plant"],
    "warehouse": ["pallet_rack", "pallet", "box"],
    "closet": ["storage"],
    "hallway": ["ceiling_mounted"],
    "staircase_room": ["ceiling_mounted"],
}
OTHERS = sorted(set(ROOM_PROGRAMS) - {"living_room", "dining_room"})


def test_every_program_is_tested():
    assert set(REQUIRED) == set(OTHERS)


@pytest.mark.slow
@pytest.mark.parametrize("room", OTHERS)
def test_room_type_is_furnished_and_valid(room):
    gen = generate(0, GenerateConfig(room_type=room))
    report = validate_scene(gen.scene)
    assert report["ok"], {k: report[k] for k in ("interpenetrating", "unsupported",
                                                 "door_zone_blocked", "hard_violations")}
    tags = collections.Counter(t for o in gen.scene.objects.values() for t in o.tags)
    missing = [t for t in REQUIRED[room] if not tags[t]]
    assert not missing, (missing, sorted(tags))
