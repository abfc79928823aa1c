"""Decor, plants, textiles and household objects: what is specific to each family, beyond the
generic contract of test_generators.py (which runs on every registered generator)."""
from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh

from indoorgen.assets.registry import get_factory
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import build, distances, sample_polygon

GROUP = ["rug_round", "canvas_art", "mirror", "floor_mirror", "potted_plant", "tabletop_plant",
         "aquarium", "curtain", "clock", "table_clock", "balloon", "candle", "towel",
         "folded_clothes", "laptop", "remote", "basket", "storage_box"]
WALL = ["canvas_art", "mirror", "clock", "curtain"]
SEEDS = range(5)
TOL = 1e-3


def _variant(name: str, **over):
    """The seed-0 params with some overridden, and the built asset and placeholder."""
    f = get_factory(name)
    p = f.sample_params(np.random.default_rng(0))
    p.update(over)
    return f, p, f.create(p), f.placeholder(p)


def _slot_faces(a, slot: str) -> np.ndarray:
    return np.nonzero(a.face_slots == a.slots.index(slot))[0] if slot in a.slots else np.zeros(0, int)


def _slot_mesh(a, slot: str) -> trimesh.Trimesh:
    return a.mesh.submesh([_slot_faces(a, slot)], append=True, repair=False)


def _on_mesh(a, surface) -> np.ndarray:
    pts = surface.to_world(sample_polygon(surface.polygon))
    assert len(pts) >= 3
    return distances(a.mesh, pts)


# ------------------------------------------------------------------------------ every style
def _choice_cases():
    out = []
    for name in GROUP:
        f = get_factory(name)
        for k, prm in sorted(f.params.items()):
            if prm.kind == "choice":
                out += [(name, k, c) for c in prm.choices]
            elif prm.kind == "bool":
                out += [(name, k, True), (name, k, False)]
    return out


@pytest.mark.parametrize("name,key,value", _choice_cases())
def test_every_style_builds_one_clean_shell_per_link(name, key, value):
    """Random seeds need not reach every style: build each choice and each flag explicitly."""
    f, p, a, ph = _variant(name, **{key: value})
    m = a.mesh
    assert m.is_watertight and m.is_winding_consistent and m.volume > 0
    assert m.body_count == len(a.links)
    limit = 30000 if f.size_class == "large" else 5000 if f.size_class == "small" else 20000
    assert len(m.faces) <= limit
    assert np.abs(ph.mesh.bounds - m.bounds).max() <= 0.02
    assert abs(m.bounds[0, 2]) < TOL and np.all(np.abs(m.bounds[:, :2].sum(axis=0)) < 2 * TOL)


def test_group_registered_with_tags():
    for name in GROUP:
        f = get_factory(name)
        assert Semantics.Object in f.tags
        if f.size_class == "small":
            assert Semantics.SmallObject in f.tags, name
    for name in WALL:
        assert Semantics.WallMounted in get_factory(name).tags
    assert {Semantics.Plant, Semantics.PottedPlant} <= get_factory("potted_plant").tags
    assert {Semantics.Textile, Semantics.Towel} <= get_factory("towel").tags
    assert {Semantics.Container, Semantics.Basket} <= get_factory("basket").tags
    assert {Semantics.Electronics, Semantics.Laptop} <= get_factory("laptop").tags


# ------------------------------------------------------------------------------ wall-mounted
@pytest.mark.parametrize("name,seed", [(n, s) for n in WALL for s in SEEDS])
def test_wall_objects_back_lies_on_the_mesh(name, seed):
    _, _, _, a = build(name, seed)
    back = a.surface("back")
    assert back.subpart == Subpart.Back and np.allclose(back.normal, (-1, 0, 0))
    assert np.allclose(back.corners()[:, 0], a.mesh.bounds[0, 0], atol=TOL)
    assert _on_mesh(a, back).max() < TOL
    # the back plane really is the rearmost: nothing of the mesh behind it
    assert a.mesh.bounds[0, 0] >= back.origin[0] - 1e-6


def test_round_mirror_back_is_the_disc_not_the_box():
    _, p, a, _ = _variant("mirror", shape="round")
    back = a.surface("back")
    # a disc inscribed in the bbox: about pi/4 of the square
    d = a.extents[1]
    assert 0.7 * d * d < back.polygon.area < 0.8 * d * d
    assert _on_mesh(a, back).max() < TOL
    assert len(_slot_faces(a, "mirror")) > 0


def test_canvas_triptych_is_one_panel_with_grooves():
    _, p, a, _ = _variant("canvas_art", n_panels=3, groove_width=0.03, groove_depth=0.7,
                          center_scale=1.0)
    assert a.mesh.body_count == 1
    w, g = p["panel_width"], p["groove_width"]
    x_front = a.mesh.bounds[1, 0]
    zc = a.extents[2] / 2
    groove_y = [-w / 2 - g / 2, w / 2 + g / 2]
    inside = a.mesh.contains([[x_front - 0.002, y, zc] for y in groove_y]
                             + [[x_front - 0.002, 0.0, zc]])
    assert not inside[0] and not inside[1] and inside[2]
    assert abs(a.extents[1] - (3 * w + 2 * g)) < TOL


def test_curtain_hangs_to_its_hem_and_covers_its_share():
    for cov in (0.4, 1.0):
        _, p, a, _ = _variant("curtain", coverage=cov, n_panels=1)
        fab = _slot_mesh(a, "fabric")
        assert abs(fab.bounds[0, 2]) < TOL  # the hem is the bottom
        span = fab.bounds[1, 1] - fab.bounds[0, 1]
        assert abs(span - cov * p["width"]) < 0.01
        assert fab.bounds[1, 2] > 0.95 * p["drop"]


# ------------------------------------------------------------------------------ floor decor
def test_rug_fringe_extends_the_rug():
    _, p, a, _ = _variant("rug_round", shape="round", edge="fringe")
    assert abs(a.extents[1] - (p["diameter"] + 2 * p["fringe_length"])) < 0.005
    _, p2, a2, _ = _variant("rug_round", shape="round", edge="plain")
    assert abs(a2.extents[1] - p2["diameter"]) < 0.002
    # the tassels lie 1 mm off the floor: only the pile touches z=0
    low = a.mesh.vertices[a.mesh.vertices[:, 2] < 1e-6]
    assert np.linalg.norm(low[:, :2], axis=1).max() < p["diameter"] / 2 + TOL


@pytest.mark.parametrize("seed", SEEDS)
def test_potted_plant_foliage_grows_above_the_soil_and_floor(seed):
    _, p, _, a = build("potted_plant", seed)
    leaves = _slot_mesh(a, "foliage")
    soil = _slot_mesh(a, "soil")
    pot = _slot_mesh(a, "ceramic")
    assert len(leaves.faces) > 100 and len(soil.faces) > 0
    assert leaves.bounds[0, 2] > 0.005  # nothing droops onto the floor
    # the soil's top lies inside the pot, below the rim
    assert soil.bounds[1, 2] < pot.bounds[1, 2]
    top_of_pot = pot.bounds[1, 2]
    assert leaves.bounds[1, 2] > top_of_pot + 0.4 * p["plant_height"]


@pytest.mark.parametrize("kind", ["succulent", "cactus", "leafy"])
def test_tabletop_plant_is_small(kind):
    f, p, a, _ = _variant("tabletop_plant", plant_type=kind)
    assert f.size_class == "small"
    assert a.extents.max() < 0.5
    assert len(_slot_faces(a, "foliage")) > 50
    assert a.mesh.body_count == 1


def test_aquarium_lid_top_is_the_support_surface_and_water_is_inside():
    for style in ("tank", "on_stand"):
        _, p, a, _ = _variant("aquarium", style=style, lid_style="hood")
        top = a.surface("top")
        assert top.subpart == Subpart.SupportSurface and np.allclose(top.normal, (0, 0, 1))
        assert abs(top.origin[2] - a.extents[2]) < TOL
        assert _on_mesh(a, top).max() < TOL
        water, glass = _slot_mesh(a, "water"), _slot_mesh(a, "glass")
        assert len(water.faces) and len(_slot_faces(a, "stone"))
        assert water.bounds[1, 2] < glass.bounds[1, 2]  # below the rim
        assert np.all(water.bounds[0, :2] >= glass.bounds[0, :2] - 1e-6)
        assert np.all(water.bounds[1, :2] <= glass.bounds[1, :2] + 1e-6)
        if style == "on_stand":
            assert len(a.joints) == 2 and all(j.kind == "revolute" for j in a.joints)
            assert glass.bounds[0, 2] > 0.55  # the tank stands on the cabinet
            (inner,) = a.surfaces_of(Subpart.Interior)
            assert _on_mesh(a, inner).max() < TOL and inner.origin[2] < 0.1
        else:
            assert not a.joints


# ------------------------------------------------------------------------------ small decor
def test_balloons_do_not_touch_each_other():
    for n in range(1, 6):
        _, p, a, _ = _variant("balloon", n_balloons=n, spread=0.0)
        bodies = _slot_mesh(a, "plastic").split(only_watertight=False)
        assert len(bodies) == n
        assert a.mesh.body_count == 1  # strings tie them all to the weight


def test_lit_candle_has_an_emissive_flame_on_top():
    for style in ("pillar", "taper", "tealight", "jar"):
        _, p, a, _ = _variant("candle", style=style, lit=True)
        flame = _slot_faces(a, "emissive")
        assert len(flame)
        wax_top = a.mesh.triangles[_slot_faces(a, "wax")][..., 2].max()
        assert a.mesh.triangles[flame][..., 2].max() > wax_top + 0.02
        if style != "jar":  # (a jar may be taller than its flame)
            assert abs(a.mesh.triangles[flame][..., 2].max() - a.extents[2]) < TOL
        _, _, dark, _ = _variant("candle", style=style, lit=False)
        assert len(_slot_faces(dark, "emissive")) == 0
        assert a.surface("bottom").subpart == Subpart.Bottom


def test_clock_hands_point_at_the_time():
    # 3 o'clock: the hour hand points to +Y (the viewer's right), the minute hand up
    _, p, a, _ = _variant("clock", shape="round", time=3.0, markers="none")
    metal = _slot_mesh(a, "metal")
    c = np.array([0.0, 0.0, a.extents[2] / 2])
    rel = metal.vertices - c
    r = p["diameter"] / 2 - p["rim_width"]
    slack = 0.02  # hand widths and the centre cap
    assert rel[:, 1].max() > 0.4 * r and rel[:, 1].min() > -0.12 * r - slack
    assert rel[:, 2].max() > 0.7 * r and rel[:, 2].min() > -0.15 * r - slack
    # far up there is only the (vertical) minute hand; far right only the hour hand
    assert np.abs(rel[rel[:, 2] > 0.55 * r, 1]).max() < slack
    assert np.abs(rel[rel[:, 1] > 0.3 * r, 2]).max() < slack


# ------------------------------------------------------------------------------ household
@pytest.mark.parametrize("seed", SEEDS)
def test_laptop_lid_closes_onto_the_base_and_opens_its_screen_forward(seed):
    _, p, _, a = build("laptop", seed)
    (j,) = a.joints
    assert j.child == "lid" and j.kind == "revolute"
    assert abs(j.lower + math.radians(p["open_angle"])) < 1e-9
    lid = a.link_mesh("lid")
    base = a.link_mesh("base")
    shut = trimesh.transform_points(lid.vertices, j.transform(j.lower))
    assert shut[:, 2].min() > base.bounds[1, 2]  # resting clear above the keys
    assert shut[:, 2].max() - base.bounds[1, 2] < 0.015  # but right on the base
    # opened to 100 degrees, the screen faces the user (+X)
    screen = _slot_faces(a, "screen")
    opened = a.posed({j.name: math.radians(100) - math.radians(p["open_angle"])})
    n = opened.face_normals[screen]
    w = opened.area_faces[screen]
    assert (n[:, 0] * w).sum() / w.sum() > 0.8


def test_remote_buttons_on_top():
    _, p, a, _ = _variant("remote", dpad=True, n_button_rows=5)
    rubber = _slot_mesh(a, "rubber")
    body = _slot_mesh(a, "plastic")
    assert len(rubber.split(only_watertight=False)) >= 1 + 2 + 3  # power, d-pad, rows
    assert rubber.bounds[1, 2] > body.bounds[1, 2]
    assert _on_mesh(a, a.surface("bottom")).max() < TOL


@pytest.mark.parametrize("style", ["folded", "rolled"])
def test_towel_layers(style):
    for n in (1, 2, 3):
        _, p, a, _ = _variant("towel", style=style, n_towels=n)
        assert a.mesh.body_count == 1
        if style == "folded":
            assert abs(a.extents[2] - n * p["n_layers"] * p["layer_thickness"] + (n - 1) * 0.001) < TOL
        else:
            # the roll's end lies flat: a flat patch of the mesh on the surface
            down = (a.mesh.face_normals[:, 2] < -0.99) & (a.mesh.triangles_center[:, 2] < 1e-6)
            assert a.mesh.area_faces[down].sum() > 0.5 * p["width"] * min(p["tail_length"], 0.02)


def test_folded_clothes_stack_height():
    for n in (1, 3, 5):
        _, p, a, _ = _variant("folded_clothes", n_items=n, size_jitter=0.0, garment="tshirt",
                              mixed=False)
        h = n * p["item_thickness"] - (n - 1) * 0.001
        assert h - TOL < a.extents[2] < h + 0.006


@pytest.mark.parametrize("name,seed", [(n, s) for n in ("basket", "storage_box") for s in SEEDS])
def test_container_interior_is_its_floor(name, seed):
    _, _, _, a = build(name, seed)
    inner = a.surfaces_of(Subpart.Interior)
    assert [s.name for s in inner] == ["interior_0"]
    s = inner[0]
    assert np.allclose(s.normal, (0, 0, 1)) and s.origin[2] < 0.05
    assert _on_mesh(a, s).max() < TOL
    # open space above the floor: a point 3 cm up is not inside the solid
    c = s.to_world(np.array([s.polygon.representative_point().coords[0]]))[0]
    assert not a.mesh.contains([c + [0, 0, 0.03]])[0]


@pytest.mark.parametrize("lid", ["lift_off", "hinged"])
def test_storage_box_lid(lid):
    _, p, a, _ = _variant("storage_box", lid_style=lid)
    (j,) = a.joints
    assert j.child == "lid"
    assert j.kind == ("prismatic" if lid == "lift_off" else "revolute")
    top = a.surface("top")
    assert top.subpart == Subpart.SupportSurface and _on_mesh(a, top).max() < TOL
    assert abs(a.link_mesh("lid").bounds[1, 2] - top.origin[2]) < 0.01
    opened = a.posed({j.name: j.upper})
    assert opened.bounds[1, 2] > a.mesh.bounds[1, 2] + 0.1
