"""Food generators (generators/food.py): cans, boxes and bags, and fruit settled into a bowl
(the generic asset contract runs on them in test_generators.py)."""
from __future__ import annotations

import numpy as np

from indoorgen.assets.catalogue import factories_with, get_factory
from indoorgen.assets.generators import food
from indoorgen.assets.shapes import vessels
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import build, make
from support.generatorcheck import check_material_choices, check_small_objects

NAMES = ["can", "food_box", "food_bag", "fruit_bowl"]
SEEDS = range(5)


def test_catalogue_lists_every_kind():
    check_small_objects(NAMES)
    assert "fruit_bowl" in factories_with([Semantics.FruitBowl, Semantics.Food])


def test_material_choices_name_real_materials():
    check_material_choices(NAMES)


def test_drink_can_rests_on_a_ring():
    _, p, a = make("can", 0, kind="drink")
    assert a.extents[0] / 2 <= 0.034 + 1e-6
    up = a.mesh.ray.intersects_location([[0, 0, -0.1]], [[0, 0, 1.0]])[0]
    assert up[:, 2].min() > 0.005  # the base is domed
    assert a.mesh.volume > 0.8 * a.mesh.convex_hull.volume  # closed and full


# ---------------------------------------------------------------------------- fruit bowls
def test_a_fruit_dropped_in_the_middle_lands_on_the_floor():
    f = get_factory("fruit_bowl")
    p = f.resolve({"foot_ring": False})
    surf, opening = food._inner_surface(p)
    floor = vessels.bowl_vessel(p).floor_z
    r = 0.04
    z = food._drop(np.array([[0, 0, 0, r]]), np.zeros((1, 2)), surf, np.zeros((0, 4)))
    assert abs(z[0] - (floor + r)) < 1e-6
    # on top of a fruit already there, it lands at the sum of the radii
    z = food._drop(np.array([[0, 0, 0, r]]), np.zeros((1, 2)), surf,
                   np.array([[0, 0, floor + r, r]]))
    assert abs(z[0] - (floor + 3 * r)) < 1e-6


def test_fruits_lie_in_the_bowl():
    for seed in SEEDS:
        f, p, _, a = build("fruit_bowl", seed)
        fruit = a.mesh.triangles[a.face_slots == a.slots.index("food")].reshape(-1, 3)
        assert len(fruit)
        assert np.linalg.norm(fruit[:, :2], axis=1).max() <= p["radius"] + 1e-3
        _, offset, _ = f._layout(f.resolve(p))  # design frame -> asset frame
        floor = vessels.bowl_vessel(p).floor_z + offset[2]  # the inner floor, under fruit
        assert fruit[:, 2].min() > floor - 0.005
        assert 3 <= len(f._fruits(p)) <= p["n_fruits"]


# ----------------------------------------------------------------------------- packaging
def test_food_box_top_is_its_upper_face():
    for lying in (False, True):
        _, p, a = make("food_box", 0, lying=lying, feature="plain")
        top = a.surface("top")
        assert top.subpart == Subpart.SupportSurface
        assert abs(top.origin[2] - (p["depth"] if lying else p["height"])) < 1e-6
        assert abs(a.extents[2] - top.origin[2]) < 1e-6
        assert top.polygon.area > 0.8 * (a.extents[0] - 0.01) * (a.extents[1] - 0.01)


def test_pillow_bag_lies_flat_and_is_sealed_at_both_ends():
    _, p, a = make("food_bag", 0, style="pillow")
    assert abs(a.extents[0] - p["length"]) < 1e-6
    assert a.extents[2] < min(p["thickness"], 0.6 * p["width"])
    low = a.mesh.vertices[a.mesh.vertices[:, 2] < 1e-6]
    assert np.ptp(low[:, 0]) > 0.2 * p["length"]  # a flat patch where it is squashed
