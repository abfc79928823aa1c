"""Rooms solved in parallel processes give the scene solving them one after the other gives,
byte for byte: the same objects, poses and names."""
from __future__ import annotations

import pytest

from indoorgen.pipeline import HomeConfig, generate_home

#: a small home, few steps: what matters is that the rooms are many and solved apart (a seed
#: whose rooms meet their requirements at the first solve: with so few steps, others solve some
#: rooms again and again, which tests nothing more)
SMALL_HOME = "bedroom=1,bathroom=1,kitchen=1"
STEPS = {"large": 40, "medium": 30, "small": 30}


@pytest.mark.slow
def test_two_workers_give_the_scene_one_gives():
    scenes = [generate_home(6, HomeConfig(rooms=SMALL_HOME, area=60.0, steps=STEPS,
                                          preset="fast", workers=k))
              for k in (1, 2)]
    one, two = (g.scene for g in scenes)
    assert len(one.rooms) > 2 and len(one.objects) > 10
    assert two.dumps() == one.dumps()
    # the detailed assets built in the workers are the ones this process would have built
    for name, ob in one.objects.items():
        a, b = scenes[0].cache.full(ob.generator, ob.params), scenes[1].cache.full(
            ob.generator, ob.params)
        assert (a.mesh.vertices == b.mesh.vertices).all(), name
    assert scenes[1].report["rooms"].keys() == scenes[0].report["rooms"].keys()
    for room, rep in scenes[0].report["rooms"].items():
        assert scenes[1].report["rooms"][room]["violations"] == rep["violations"]


def test_workers_must_be_a_positive_count():
    from indoorgen.errors import ConfigError
    with pytest.raises(ConfigError, match="workers"):
        generate_home(0, HomeConfig(workers=0))
