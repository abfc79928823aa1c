"""Plants: foliage above the soil and the floor, small tabletop plants, every style, beyond the
generic contract in test_generators.py."""
from __future__ import annotations

import pytest

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics
from support.assetcheck import (
    assert_clean_variant,
    assert_objects_tagged,
    build,
    choice_cases,
    slot_faces,
    slot_mesh,
    variant,
)

PLANTS = ["potted_plant", "tabletop_plant"]
SEEDS = range(5)


@pytest.mark.parametrize("name,key,value", choice_cases(PLANTS))
def test_every_style_builds_one_clean_shell_per_link(name, key, value):
    assert_clean_variant(name, key, value)


def test_registered_with_tags():
    assert_objects_tagged(PLANTS)
    assert {Semantics.Plant, Semantics.PottedPlant} <= get_factory("potted_plant").tags


@pytest.mark.parametrize("seed", SEEDS)
def test_potted_plant_foliage_grows_above_the_soil_and_floor(seed):
    _, p, _, a = build("potted_plant", seed)
    leaves = slot_mesh(a, "foliage")
    soil = slot_mesh(a, "soil")
    pot = slot_mesh(a, "ceramic")
    assert len(leaves.faces) > 100 and len(soil.faces) > 0
    assert leaves.bounds[0, 2] > 0.005  # nothing droops onto the floor
    # the soil's top lies inside the pot, below the rim
    assert soil.bounds[1, 2] < pot.bounds[1, 2]
    top_of_pot = pot.bounds[1, 2]
    assert leaves.bounds[1, 2] > top_of_pot + 0.4 * p["plant_height"]


@pytest.mark.parametrize("kind", ["succulent", "cactus", "leafy"])
def test_tabletop_plant_is_small(kind):
    f, p, a, _ = variant("tabletop_plant", plant_type=kind)
    assert f.size_class == "small"
    assert a.extents.max() < 0.5
    assert len(slot_faces(a, "foliage")) > 50
    assert a.mesh.body_count == 1
