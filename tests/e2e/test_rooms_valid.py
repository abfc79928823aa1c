"""4 seeds each of the built-in rooms (benchmarks/quality.py measures more), checked by the
independent validator (full meshes, manifold3d booleans, plain geometry): no hard violation, no
interpenetration deeper than 1 mm, every object on or against its declared surface within 5 mm,
door clearance zones empty, dining chairs facing their table."""
import pytest

from indoorgen import GenerateConfig, generate
from indoorgen.validate import validate_scene

CASES = [(room, seed) for room in ("living_room", "dining_room") for seed in range(4)]


@pytest.mark.slow
@pytest.mark.parametrize("room,seed", CASES)
def test_generated_room_passes_independent_validation(room, seed):
    gen = generate(seed, GenerateConfig(room_type=room))
    report = validate_scene(gen.scene)
    problems = {k: report[k] for k in ("interpenetrating", "unsupported", "door_zone_blocked",
                                       "chairs_not_facing_table", "hard_violations")}
    assert report["ok"], problems
    assert report["n_hard_violated"] == 0
    assert gen.report["rooms"][f"{room}_0"]["n_violated"] == 0
    # a furnished room, not an empty one: the program's required furniture is there
    assert report["objects"] >= (12 if room == "dining_room" else 20)
