"""Properties specific to tableware, kitchenware, food and book groups (the generic contract is
tests/assets/test_generators.py)."""
from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh

from indoorgen.assets.base import factories_with, get_factory
from indoorgen.assets.generators import food
from indoorgen.assets.shapes import vessels
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import build, distances, sample_polygon

MINE = ["bowl", "mug", "wineglass", "glass_tumbler", "wine_bottle", "beer_bottle", "soda_bottle",
        "jar", "can", "food_box", "food_bag", "fruit_bowl", "cooking_pot", "frying_pan",
        "pot_lid", "knife", "fork", "spoon", "chopsticks", "spatula", "cutting_board",
        "book_stack", "leaning_books"]
#: vessels whose `interior` surface is their inner floor, reachable from above
VESSELS = ["bowl", "mug", "glass_tumbler", "jar", "cooking_pot", "frying_pan"]  # not fruit_bowl: fruit fill it
UTENSILS = ["knife", "fork", "spoon", "chopsticks", "spatula"]
SEEDS = range(5)


def _create(name: str, **overrides):
    """The asset of seed 0's params with `overrides` applied."""
    f = get_factory(name)
    p = f.sample_params(np.random.default_rng(0))
    p.update(overrides)
    return f, p, f.create(p)


def _first_hit_down(mesh: trimesh.Trimesh, x: float, y: float) -> float:
    """Height of the first surface a ray going straight down at (x, y) meets (-inf if none)."""
    top = mesh.bounds[1][2] + 0.1
    locs, _, _ = mesh.ray.intersects_location([[x, y, top]], [[0, 0, -1.0]])
    return float(locs[:, 2].max()) if len(locs) else -math.inf


def _arrays(solid) -> tuple[np.ndarray, np.ndarray]:
    m = solid.to_mesh()
    return np.asarray(m.vert_properties)[:, :3], np.asarray(m.tri_verts)


def _offset(f, p) -> np.ndarray:
    """The translation from a generator's design frame to the asset frame."""
    return f._layout(p)[1]


# ------------------------------------------------------------------------------- catalogue
def test_catalogue_lists_every_kind():
    for name in MINE:
        f = get_factory(name)
        assert f.size_class == "small" and Semantics.SmallObject in f.tags, name
    bottles = set(factories_with([Semantics.Bottle]))
    assert {"wine_bottle", "beer_bottle", "soda_bottle"} <= bottles
    assert set(UTENSILS[:4]) <= set(factories_with([Semantics.Cutlery]))
    assert "fruit_bowl" in factories_with([Semantics.FruitBowl, Semantics.Food])
    assert {"book_stack", "leaning_books"} <= set(factories_with([Semantics.Book]))


# ------------------------------------------------------------------------------- vessels
@pytest.mark.parametrize("name,seed", [(n, s) for n in VESSELS for s in SEEDS])
def test_vessel_interior_is_the_open_inner_floor(name, seed):
    """The interior surface lies on the inner floor, above the underside, and a ray dropped
    into the vessel's mouth reaches it (the cavity is open, not sealed)."""
    f, p, _, a = build(name, seed)
    body = a.link_mesh("base")
    s = a.surface("interior")
    assert s.subpart == Subpart.Interior and np.allclose(s.normal, (0, 0, 1))
    pts = s.to_world(sample_polygon(s.polygon))
    if name == "fruit_bowl":  # fruits cover parts of the floor: check the bowl on its own
        body = trimesh.Trimesh(*_arrays(f.parts(p, True)[0].solid))
        body.apply_translation(_offset(f, p))
    assert distances(body, pts).max() < 1e-3
    assert 0.003 < s.origin[2] < 0.5 * a.extents[2] + 0.02
    if name != "fruit_bowl":  # fruits may cover the centre
        assert abs(_first_hit_down(body, s.origin[0], s.origin[1]) - s.origin[2]) < 1e-3


@pytest.mark.parametrize("name", ["bowl", "mug", "wineglass", "glass_tumbler", "jar"])
def test_vessels_are_thin_walled(name):
    """Much less material than the solid of the same outline: really hollow."""
    for seed in SEEDS:
        _, _, ph, a = build(name, seed)
        base = a.link_mesh("base")
        assert base.volume < 0.45 * ph.mesh.convex_hull.volume, (seed, base.volume)


@pytest.mark.parametrize("name,closure", [("wine_bottle", "cork"), ("wine_bottle", "open"),
                                          ("beer_bottle", "crown"), ("beer_bottle", "open"),
                                          ("soda_bottle", "screwcap"), ("soda_bottle", "open")])
def test_bottles_capped_solid_open_hollow(name, closure):
    _, p, a = _create(name, closure=closure, label=False)
    hull = a.mesh.convex_hull.volume
    if closure == "open":
        assert a.mesh.volume < 0.3 * hull
        # a ray down the neck reaches the floor near the bottom
        assert _first_hit_down(a.mesh, 0.0, 0.0) < 0.05
    else:
        assert a.mesh.volume > 0.85 * hull
        assert _first_hit_down(a.mesh, 0.0, 0.0) >= a.extents[2] - 1e-3


def test_mug_handle_sticks_out_on_plus_y():
    for seed in SEEDS:
        f, p, _, a = build("mug", seed)
        rmax = max(q[0] for q in f._outer(p))
        assert a.extents[1] - 2 * rmax > 2 * p["handle_thickness"] + 0.005  # room for fingers
        assert abs(a.extents[0] - 2 * rmax) < 1e-3
        side = a.mesh.vertices[a.mesh.vertices[:, 1] > a.mesh.bounds[1][1] - 0.003]
        assert side[:, 2].min() > 0.1 * p["height"]  # the handle, not the body, on +Y


def test_wineglass_has_stem_thinner_than_foot_and_bowl():
    for seed in SEEDS:
        f, p, _, a = build("wineglass", seed)
        z_stem = f._dims(p)[0] - 0.01
        sec = a.mesh.section(plane_origin=(0, 0, z_stem), plane_normal=(0, 0, 1))
        r = np.linalg.norm(sec.vertices[:, :2], axis=1).max()
        assert r <= p["stem_radius"] + 1e-4
        assert a.extents[0] / 2 >= max(p["foot_radius"], p["bowl_radius"] * 0.6) - 1e-3


@pytest.mark.parametrize("name", ["jar", "cooking_pot"])
def test_lid_lifts_straight_off(name):
    extra = {"has_lid": True} if name == "cooking_pot" else {}
    f, p, a = _create(name, **extra)
    (j,) = a.joints
    assert j.kind == "prismatic" and np.allclose(j.axis, (0, 0, 1)) and j.child == "lid"
    body, lid = a.link_mesh("base"), a.link_mesh("lid")
    rim = body.bounds[1][2]
    opened = lid.copy()
    opened.apply_transform(j.transform(j.upper))
    assert opened.bounds[0][2] > rim + 0.02  # lifted clear of the rim
    # closed, the lid covers the opening: a ray down the axis meets the lid first
    assert _first_hit_down(a.mesh, 0.0, 0.0) > rim


def test_pot_handles():
    _, p, a = _create("cooking_pot", handle_style="loops", has_lid=False)
    lo, hi = a.mesh.bounds
    assert hi[1] > p["radius"] + 0.02 and lo[1] < -p["radius"] - 0.02  # both sides
    assert abs(hi[1] + lo[1]) < 1e-3
    _, p, a = _create("cooking_pot", handle_style="long", has_lid=False)
    assert a.extents[0] > 2 * p["radius"] + 0.1  # a saucepan handle along +X
    _, p, a = _create("frying_pan", helper_handle=False)
    assert a.extents[0] > 2 * p["radius"] + 0.8 * p["handle_length"]


def test_drink_can_rests_on_a_ring():
    _, p, a = _create("can", kind="drink")
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
        _, p, a = _create("food_box", lying=lying, feature="plain")
        top = a.surface("top")
        assert top.subpart == Subpart.SupportSurface
        assert abs(top.origin[2] - (p["depth"] if lying else p["height"])) < 1e-6
        assert abs(a.extents[2] - top.origin[2]) < 1e-6
        assert top.polygon.area > 0.8 * (a.extents[0] - 0.01) * (a.extents[1] - 0.01)


def test_pillow_bag_lies_flat_and_is_sealed_at_both_ends():
    _, p, a = _create("food_bag", style="pillow")
    assert abs(a.extents[0] - p["length"]) < 1e-6
    assert a.extents[2] < min(p["thickness"], 0.6 * p["width"])
    low = a.mesh.vertices[a.mesh.vertices[:, 2] < 1e-6]
    assert np.ptp(low[:, 0]) > 0.2 * p["length"]  # a flat patch where it is squashed


# ---------------------------------------------------------------------------- utensils
@pytest.mark.parametrize("name", UTENSILS)
def test_utensils_lie_flat(name):
    for seed in SEEDS:
        _, _, _, a = build(name, seed)
        assert a.extents[2] < 0.045 and a.extents[0] > 2 * a.extents[1]
        low = a.mesh.vertices[a.mesh.vertices[:, 2] < 1e-6]
        assert np.ptp(low[:, 0]) > 0.5 * a.extents[0]  # resting at both ends


@pytest.mark.parametrize("tines", [2, 3, 4])
def test_fork_has_its_tines(tines):
    f, p, a = _create("fork", tines=tines)
    x = p["head_length"] * 0.85 + _offset(f, p)[0]
    sec = a.mesh.section(plane_origin=(x, 0, 0), plane_normal=(1, 0, 0))
    assert len(sec.to_2D()[0].polygons_full) == tines


def test_chopsticks_are_a_pair():
    f, p, a = _create("chopsticks", rest=False)
    x = 0.9 * p["length"] + _offset(f, p)[0]
    sec = a.mesh.section(plane_origin=(x, 0, 0), plane_normal=(1, 0, 0))
    assert len(sec.to_2D()[0].polygons_full) == 2
    f, p, a = _create("chopsticks", rest=True)
    tip = a.mesh.vertices[a.mesh.vertices[:, 0] > a.mesh.bounds[1][0] - 0.01]
    assert tip[:, 2].min() > 0.008  # the tips are raised on the rest


def test_spoon_bowl_is_hollow():
    f, p, a = _create("spoon")
    ax, _, c, t = f._dims(p)
    x = ax + _offset(f, p)[0]
    floor = _first_hit_down(a.mesh, x, 0.0)  # the inside of the bowl, one wall above the table
    assert abs(floor - t) < 1e-3 and floor < c - 0.002


# ----------------------------------------------------------------------------- boards
@pytest.mark.parametrize("style", ["rect", "rounded", "paddle"])
def test_cutting_board_top_and_hole(style):
    f, p, a = _create("cutting_board", style=style, handle_hole=True, juice_groove=True)
    top = a.surface("top")
    assert abs(top.origin[2] - p["thickness"]) < 1e-9 and abs(a.extents[2] - p["thickness"]) < 1e-6
    pts = top.to_world(sample_polygon(top.polygon))
    assert distances(a.mesh, pts).max() < 1e-3
    c = np.asarray(f._hole(p).centroid.coords[0]) + _offset(f, p)[:2]
    assert _first_hit_down(a.mesh, c[0], c[1]) == -math.inf  # the hole goes through


# ----------------------------------------------------------------------------- books
def test_book_stack_top_is_the_top_cover():
    for seed in SEEDS:
        f, p, _, a = build("book_stack", seed)
        specs = f._specs(p)
        expect = sum(s.params["thickness"] for s in specs) - (len(specs) - 1) * 0.001
        top = a.surface("top")
        assert abs(top.origin[2] - expect) < 1e-9
        assert abs(a.extents[2] - expect) < 1e-6
        assert distances(a.mesh, top.to_world(sample_polygon(top.polygon))).max() < 1e-3


def test_leaning_book_leans_against_the_row():
    for seed in SEEDS:
        f, p, _, a = build("leaning_books", seed)
        books = f._books(p)
        upright = sum(b["thickness"] for b in books[:-1])
        assert a.extents[2] <= max(b["height"] for b in books) + 1e-6
        # the leaning book takes more room than it would upright
        assert a.extents[1] > upright + books[-1]["thickness"]
        assert a.mesh.body_count == 1


def test_material_choices_name_real_materials():
    from indoorgen.assets.materials.base import material_names

    known = set(material_names())
    for name in MINE:
        f = get_factory(name)
        for slot, choices in f.material_choices.items():
            assert slot in f.slots, (name, slot)
            assert set(choices) <= known, (name, set(choices) - known)
