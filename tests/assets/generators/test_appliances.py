"""Appliance generators (generators/appliances/): properties specific to fridges, dishwashers,
ovens, hobs, hoods, microwaves and washing machines (the generic asset contract runs on them in
test_generators.py)."""
from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import build, make
from support.generatorcheck import check_interior_shelves, check_wall_back, faces_of_slot, on_mesh

GROUP = ["fridge", "beverage_fridge", "dishwasher", "microwave", "oven", "cooktop", "range",
         "washing_machine", "range_hood"]
SEEDS = range(6)
TOL = 1e-3


# --------------------------------------------------------------------------------- registry
@pytest.mark.parametrize("name", GROUP)
def test_registered_with_tags(name):
    f = get_factory(name)
    assert Semantics.Object in f.tags
    expected = {
        "fridge": {Semantics.Appliance, Semantics.Fridge},
        "beverage_fridge": {Semantics.Appliance, Semantics.BeverageFridge},
        "dishwasher": {Semantics.KitchenAppliance, Semantics.Dishwasher},
        "microwave": {Semantics.KitchenAppliance, Semantics.Microwave},
        "oven": {Semantics.KitchenAppliance, Semantics.Oven},
        "cooktop": {Semantics.KitchenAppliance, Semantics.Cooktop},
        "range": {Semantics.KitchenAppliance, Semantics.Range},
        "washing_machine": {Semantics.Appliance, Semantics.WashingMachine},
        "range_hood": {Semantics.RangeHood, Semantics.WallMounted},
    }[name]
    assert expected <= f.tags
    if name == "beverage_fridge":  # never chosen as a kitchen's (full-size) fridge
        assert Semantics.Fridge not in f.tags


# ------------------------------------------------------------------------- interior surfaces
@pytest.mark.parametrize("name,seed", [(n, s) for n in ("fridge", "beverage_fridge", "dishwasher", "oven",
                                                        "range", "microwave")
                                       for s in SEEDS])
def test_interior_surfaces_are_shelves_inside(name, seed):
    """Interior surfaces face up, lie inside the body and on a shelf; a wire rack's surface is
    the tops of its bars (a polygon with a hole per slot) across the whole rack, not one bar."""
    check_interior_shelves(build(name, seed)[3])


@pytest.mark.parametrize("seed", SEEDS)
def test_interior_surfaces_are_closed_in_by_doors(seed):
    """A fridge's shelves are behind its doors: every interior surface lies behind the front
    plane of the cabinet, inside the cabinet's width."""
    _, p, _, a = build("fridge", seed)
    lo, hi = a.mesh.bounds
    front_cabinet = lo[0] + p["depth"]
    for s in a.surfaces_of(Subpart.Interior):
        c = s.corners()
        assert (c[:, 0] < front_cabinet).all()
        assert (np.abs(c[:, 1]) < p["width"] / 2).all()


# ----------------------------------------------------------------------------------- fridges
@pytest.mark.parametrize("style", ["single", "top_freezer", "bottom_freezer", "french"])
def test_fridge_doors_swing_open(style):
    f, p, a = make("fridge", 0, style=style)
    revolute = [j for j in a.joints if j.kind == "revolute"]
    assert len(revolute) == {"single": 1, "top_freezer": 2, "bottom_freezer": 2, "french": 2}[style]
    assert len([j for j in a.joints if j.kind == "prismatic"]) == (1 if style == "french" else 0)
    front = a.mesh.bounds[0][0] + p["depth"]
    for j in revolute:
        assert np.allclose(np.abs(j.axis), (0, 0, 1))  # vertical hinges
        assert math.radians(90) <= j.upper <= math.radians(110)
        door = a.link_mesh(j.child)
        # closed: the leaf stands in front of the cabinet; open: it has swung out to the side,
        # its far edge now more than half its width in front of the cabinet
        assert door.bounds[0][0] > front - 0.1
        moved = trimesh.transform_points(door.vertices, j.transform(j.upper))
        width = np.ptp(door.vertices[:, 1])
        assert moved[:, 0].max() - front > 0.5 * width
    # shelves: one per n_shelves in the fridge compartment plus each compartment's floor
    n_comp = 1 if style == "single" else 2
    n_inner = len(a.surfaces_of(Subpart.Interior))
    assert n_inner >= p["n_shelves"] + n_comp


def test_fridge_top_is_a_support_surface():
    _, p, a = make("fridge", 0)
    top = a.surface("top")
    assert top.subpart == Subpart.SupportSurface
    assert abs(top.origin[2] - p["height"]) < TOL
    assert on_mesh(a, top) < TOL


@pytest.mark.parametrize("shelves", ["wire", "glass"])
def test_beverage_fridge_glass_door_shows_the_shelves(shelves):
    _, p, a = make("beverage_fridge", 0, shelf_style=shelves)
    door = a.link_mesh("door")
    glass = np.intersect1d(faces_of_slot(a, "glass"), a.link_faces("door"))
    # most of the door's front is glass
    area = a.mesh.area_faces[glass].sum() / 2  # two sides of the pane
    d = door.extents
    assert area > 0.4 * d[1] * d[2]
    levels = [s for s in a.surfaces_of(Subpart.Interior)]
    assert len(levels) == p["n_shelves"] + 1


# ----------------------------------------------------------------------- drop-down doors
@pytest.mark.parametrize("name", ["dishwasher", "oven", "range"])
def test_drop_down_door(name):
    _, p, a = make(name, 0)
    doors = [j for j in a.joints if j.child.startswith("door")]
    assert doors
    for j in doors:
        assert j.kind == "revolute" and np.allclose(np.abs(j.axis), (0, 1, 0))
        assert abs(j.upper - math.radians(90)) < 1e-9
        door = a.link_mesh(j.child)
        assert abs(j.origin[2] - door.bounds[0][2]) < 0.01  # hinged along its lower edge
        moved = trimesh.transform_points(door.vertices, j.transform(j.upper))
        # open flat: the leaf lies low (below the hinge plus its thickness and handle)
        # and reaches forward by about its height
        assert moved[:, 2].max() < j.origin[2] + 0.09
        assert moved[:, 0].max() - j.origin[0] > 0.8 * np.ptp(door.vertices[:, 2]) - 0.06


def test_dishwasher_control_strip():
    for panel in ("visible", "integrated"):
        _, p, a = make("dishwasher", 0, panel=panel, n_buttons=5)
        door = a.link_faces("door")
        buttons = np.intersect1d(door,
                                 np.concatenate([faces_of_slot(a, "metal"), faces_of_slot(a, "plastic")]))
        top = a.mesh.triangles_center[buttons]
        assert (top[:, 2] > a.mesh.bounds[1][2] - 0.1).any()


@pytest.mark.parametrize("cavities,n", [("single", 1), ("double", 2)])
def test_oven_cavities(cavities, n):
    _, p, a = make("oven", 0, cavities=cavities, n_racks=2)
    assert len(a.joints) == n
    assert len(a.surfaces_of(Subpart.Interior)) == n * 3  # floor and two racks per cavity
    assert len(faces_of_slot(a, "glass")) > 0


# ------------------------------------------------------------------------------ hobs
@pytest.mark.parametrize("style", ["glass", "gas"])
def test_cooktop_surfaces(style):
    f, p, a = make("cooktop", 0, style=style, n_burners=4)
    assert f.size_class == "small"
    sup = a.surfaces_of(Subpart.SupportSurface)
    assert sup
    h = a.extents[2]
    for s in sup:
        assert on_mesh(a, s) < TOL
        if style == "gas":
            assert abs(s.origin[2] - h) < TOL  # grate tops are the highest thing
    if style == "gas":
        assert len(sup) in (1, 4)
    # rests flat on the counter
    assert on_mesh(a, a.surface("bottom")) < TOL


@pytest.mark.parametrize("hob", ["glass", "gas"])
def test_range_hob_at_declared_height(hob):
    _, p, a = make("range", 0, hob=hob)
    sup = a.surfaces_of(Subpart.SupportSurface)
    zs = {round(s.origin[2], 4) for s in sup}
    expect = p["height"] + (0.035 if hob == "gas" else 0.0)
    assert all(abs(z - expect) < TOL for z in zs)
    for s in sup:
        assert on_mesh(a, s) < TOL


# ---------------------------------------------------------------------- wall-mounted things
@pytest.mark.parametrize("seed", SEEDS)
def test_range_hood_back_lies_on_mesh(seed):
    check_wall_back(build("range_hood", seed)[3], min_area=0.05)


@pytest.mark.parametrize("name,seed", [(n, s) for n in ("fridge", "beverage_fridge", "dishwasher", "range")
                                       for s in SEEDS])
def test_against_the_wall_back_is_flat(name, seed):
    """Floor units that stand against a wall have a flat back on the bounding box's back."""
    _, _, _, a = build(name, seed)
    assert on_mesh(a, a.surface("back")) < TOL


def test_range_hood_lights_shine_down():
    for style in ("chimney_box", "chimney_pyramid", "under_cabinet"):
        _, p, a = make("range_hood", 0, style=style, n_lights=2)
        em = faces_of_slot(a, "emissive")
        assert len(em)
        n = a.mesh.face_normals[em]
        assert (n[:, 2] < -0.99).any()
        assert a.mesh.triangles_center[em][:, 2].max() < 0.01  # in the underside


# ------------------------------------------------------------------------------ misc
def test_microwave_door_and_turntable():
    f, p, a = make("microwave", 0)
    assert f.size_class == "medium"
    (j,) = a.joints
    assert j.kind == "revolute" and np.allclose(j.axis, (0, 0, -1))
    assert abs(j.origin[1] - a.mesh.bounds[0][1]) < 0.005  # hinged on the left side
    turntable = a.surface("interior_0")
    assert turntable.subpart == Subpart.Interior and on_mesh(a, turntable) < TOL


def test_washing_machine_round_door_and_drawer():
    _, p, a = make("washing_machine", 0)
    kinds = {j.child: j.kind for j in a.joints}
    assert kinds == {"door": "revolute", "drawer": "prismatic"}
    door = a.link_mesh("door").extents
    assert abs(door[1] - door[2]) < 0.03  # round, not rectangular (grip aside)
    glass = faces_of_slot(a, "glass")
    assert np.isin(glass, a.link_faces("door")).all()
