"""Bathroom generators (generators/bathroom/): what the generic contract cannot know about them
(hollow bowls and tubs, surfaces at their declared heights, toilet seat and lid hinges, wall
mounting)."""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import build, make
from support.generatorcheck import check_wall_back, on_mesh

FIXTURES = ["bathroom_sink_pedestal", "vanity", "countertop_basin", "bathtub_alcove",
            "bathtub_freestanding", "bathtub_corner", "toilet", "shower_enclosure"]
WALL = ["towel_bar", "towel_ring", "toilet_roll_holder", "robe_hook", "bathroom_mirror_cabinet"]
SEEDS = range(6)
TOL = 1e-3


def hollow_above(asset, surface, height: float = 0.04) -> bool:
    """Whether the space `height` above the middle of a surface is outside the solid (a real
    hollow, not a filled basin)."""
    c = surface.polygon.representative_point()
    q = surface.to_world(np.array([[c.x, c.y]]))[0] + (0.0, 0.0, height)
    return not bool(asset.link_mesh("base").contains([q])[0])


# --------------------------------------------------------------------------- registration
@pytest.mark.parametrize("name", FIXTURES + WALL)
def test_bathroom_tags(name):
    f = get_factory(name)
    assert {Semantics.Object, Semantics.BathroomFixture} <= f.tags
    wall = name in WALL
    assert (Semantics.WallMounted in f.tags) == wall
    assert f.size_class == ("medium" if wall else "small" if name == "countertop_basin" else "large")


# ----------------------------------------------------------------------------- wall mounts
@pytest.mark.parametrize("name,seed", [(n, s) for n in WALL for s in SEEDS])
def test_wall_mounted_back_lies_on_mesh(name, seed):
    check_wall_back(build(name, seed)[3])


@pytest.mark.parametrize("seed", SEEDS)
def test_wall_hung_toilet_hangs_from_its_back(seed):
    _, p, a = make("toilet", seed, style="wall_hung")
    back = a.surface("back")
    assert on_mesh(a, back) < TOL
    assert np.allclose(back.corners()[:, 0], a.mesh.bounds[0][0], atol=TOL)
    # nothing of it reaches the floor under its back: it is cantilevered off the wall
    low = a.mesh.vertices[a.mesh.vertices[:, 2] < 0.01]
    assert low[:, 0].min() > a.mesh.bounds[0][0] + 0.05


# --------------------------------------------------------------------------------- toilets
@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("style", ["two_piece", "one_piece", "wall_hung"])
def test_toilet_seat_and_lid_hinge_at_the_back(style, seed):
    _, p, a = make("toilet", seed, style=style)
    joints = {j.name: j for j in a.joints}
    assert set(joints) == {"seat_joint", "lid_joint"}
    lo, hi = a.mesh.bounds
    for name, link in (("seat_joint", "seat"), ("lid_joint", "lid")):
        j = joints[name]
        assert j.kind == "revolute" and j.child == link
        assert abs(abs(j.axis[1]) - 1) < 1e-9  # about a Y axis
        assert j.origin[0] < (lo[0] + hi[0]) / 2  # at the back half
        assert math.radians(90) <= j.upper <= math.radians(110)
        closed = a.link_mesh(link)
        moved = closed.copy()
        moved.apply_transform(j.transform(j.upper))
        # opened, it stands up: its top rises by most of its length, and it stays behind the
        # hinge's front (it leans back towards the cistern, not forward over the bowl)
        assert moved.bounds[1][2] - closed.bounds[1][2] > 0.3
        assert moved.bounds[1][0] < j.origin[0] + 0.05
    # the lid rests on the seat: it lies above it, and opens behind it
    seat, lid = a.link_mesh("seat"), a.link_mesh("lid")
    assert lid.bounds[0][2] >= seat.bounds[1][2] - 1e-6
    assert joints["lid_joint"].origin[0] < joints["seat_joint"].origin[0]


@pytest.mark.parametrize("seed", SEEDS)
def test_toilet_bowl_is_hollow(seed):
    _, p, a = make("toilet", seed)
    seat, base = a.link_mesh("seat"), a.link_mesh("base")
    # the middle of the seat's opening, 5 cm below the rim, is inside the bowl's hollow
    cx = (seat.bounds[0][0] + seat.bounds[1][0]) / 2 + 0.02
    assert not base.contains([[cx, 0.0, seat.bounds[0][2] - 0.05]])[0]
    if p["style"] != "wall_hung":  # and the bowl stands on a solid foot under it
        assert base.contains([[cx, 0.0, 0.05]])[0]


# ----------------------------------------------------------------------- basins and tubs
@pytest.mark.parametrize("name,seed", [(n, s) for n in ("bathtub_alcove", "bathtub_freestanding",
                                                      "bathtub_corner", "countertop_basin")
                                       for s in SEEDS])
def test_basin_floor_is_an_interior_surface_of_a_real_hollow(name, seed):
    _, p, _, a = build(name, seed)
    floor = a.surface("basin")
    assert floor.subpart == Subpart.Interior and np.allclose(floor.normal, (0, 0, 1))
    assert on_mesh(a, floor) < TOL
    assert hollow_above(a, floor)
    height = a.extents[2]
    assert floor.origin[2] < 0.5 * height  # well below the rim
    if name.startswith("bathtub"):
        assert floor.polygon.area > 0.15  # room to sit in
        assert height - floor.origin[2] > 0.25  # deep enough to bathe


@pytest.mark.parametrize("name,seed", [(n, s) for n in ("bathtub_alcove", "bathtub_corner") for s in SEEDS])
def test_tub_rim_is_a_support_surface_at_the_rim_height(name, seed):
    _, p, _, a = build(name, seed)
    rim = a.surface("rim")
    assert rim.subpart == Subpart.SupportSurface
    assert abs(rim.origin[2] - p["height"]) < TOL
    assert on_mesh(a, rim) < TOL
    # the rim surrounds the hollow: its polygon has a hole over the basin's floor
    floor = a.surface("basin")
    c = floor.polygon.centroid
    assert not rim.polygon.contains(c) and rim.polygon.convex_hull.contains(c)


@pytest.mark.parametrize("seed", SEEDS)
def test_pedestal_sink_bowl_and_deck(seed):
    _, p, _, a = build("bathroom_sink_pedestal", seed)
    decks = [s for s in a.surfaces if s.name.startswith("deck_")]
    assert decks
    for d in decks:
        assert abs(d.origin[2] - p["height"]) < TOL and on_mesh(a, d) < TOL
    # the bowl: 5 cm under the rim, in front of the deck and in the middle, is empty
    lo, hi = a.mesh.bounds
    q = np.array([[lo[0] + p["deck_depth"] + 0.1, 0.0, p["height"] - 0.05]])
    assert not a.link_mesh("base").contains(q)[0]
    assert a.surface("bottom").polygon.area < 0.1  # it stands on its pedestal's foot


@pytest.mark.parametrize("seed", SEEDS)
def test_vanity_countertop_and_fronts(seed):
    _, p, _, a = build("vanity", seed)
    top = a.surface("countertop")
    assert top.subpart == Subpart.SupportSurface
    assert abs(top.origin[2] - p["height"]) < TOL
    assert on_mesh(a, top) < TOL
    assert a.joints  # doors and/or drawers
    for j in a.joints:
        if j.kind == "prismatic":
            assert np.allclose(j.axis, (1, 0, 0)) and j.upper > 0.25  # drawers pull out
        else:
            assert abs(abs(j.axis[2]) - 1) < 1e-9  # doors swing about vertical hinges
    # a tap stands on the countertop
    metal = a.mesh.vertices[a.mesh.faces[a.face_slots == a.slots.index("metal")].ravel()]
    assert (metal[:, 2] > p["height"] + 0.1).any()


@pytest.mark.parametrize("seed", SEEDS)
def test_undermount_basins_are_cut_into_the_top(seed):
    _, p, a = make("vanity", seed, basin_type="undermount", width=1.4, n_basins=2)
    top = a.surface("countertop")
    base = a.link_mesh("base")
    # the countertop surface leaves out the openings, and under each there is the bowl's hollow
    holes = [sg.Polygon(r) for r in top.polygon.interiors]
    empty = [h for h in holes if not base.contains(
        [top.to_world(np.array([[h.centroid.x, h.centroid.y]]))[0] - (0.0, 0.0, 0.05)])[0]]
    assert len(empty) >= 2
    for h in empty:
        assert h.area > 0.05  # a washbasin, not a tap hole


# -------------------------------------------------------------------------------- showers
@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("layout", ["corner_square", "quadrant", "walk_in"])
def test_shower_tray_doors_and_glass(layout, seed):
    _, p, a = make("shower_enclosure", seed, layout=layout)
    tray = a.surface("tray")
    assert tray.subpart == Subpart.Interior and on_mesh(a, tray) < TOL
    assert abs(tray.origin[2] - (p["tray_height"] - 0.008)) < TOL
    assert a.extents[2] >= p["tray_height"] + p["glass_height"] - TOL
    assert on_mesh(a, a.surface("back")) < TOL
    if layout == "walk_in":
        assert not a.joints
        return
    assert len(a.joints) == (2 if layout == "quadrant" else 1)
    glass = a.slots.index("glass")
    for j in a.joints:
        door = a.link_faces(j.child)
        area = a.mesh.area_faces[door]
        assert area[a.face_slots[door] == glass].sum() > 0.8 * area.sum()  # a glass leaf
        if layout == "quadrant":  # curved leaves turn about the quadrant's vertical axis
            assert j.kind == "revolute" and abs(abs(j.axis[2]) - 1) < 1e-9


# ---------------------------------------------------------------------------- wall fittings
@pytest.mark.parametrize("seed", SEEDS)
def test_mirror_cabinet_shelves_and_doors(seed):
    _, p, _, a = build("bathroom_mirror_cabinet", seed)
    interiors = [s for s in a.surfaces if s.subpart == Subpart.Interior]
    assert 2 <= len(interiors) <= int(p["n_shelves"]) + 1  # the floor and >= 1 shelf
    for s in interiors:
        assert on_mesh(a, s) < TOL
    zs = sorted(s.origin[2] for s in interiors)
    assert min(np.diff(zs)) >= 0.12  # room for bottles between shelves
    assert 1 <= len(a.joints) <= 3 and all(j.kind == "revolute" for j in a.joints)
    mirror = a.slots.index("mirror")
    assert all((a.face_slots[a.link_faces(j.child)] == mirror).any() for j in a.joints)
    if p["open_shelf"]:
        assert on_mesh(a, a.surface("shelf")) < TOL


@pytest.mark.parametrize("seed", SEEDS)
def test_towel_hangs_over_the_bar(seed):
    _, p, a = make("towel_bar", seed, towel=True)
    fabric = a.mesh.faces[a.face_slots == a.slots.index("fabric")]
    assert len(fabric)
    z = a.mesh.vertices[fabric.ravel(), 2]
    bar_z = a.mesh.vertices[a.mesh.faces[a.face_slots == a.slots.index("metal")].ravel(), 2]
    assert abs((bar_z.max() + bar_z.min()) / 2 - z.max()) < 0.05  # over the bar
    assert abs(z.max() - z.min() - p["towel_drop"]) < 0.03


@pytest.mark.parametrize("seed", SEEDS)
def test_toilet_roll_sits_on_its_spindle(seed):
    _, p, a = make("toilet_roll_holder", seed, roll=True)
    paper = a.mesh.vertices[a.mesh.faces[a.face_slots == a.slots.index("paper")].ravel()]
    width = paper[:, 1].max() - paper[:, 1].min()
    assert abs(width - p["roll_width"]) < 1e-3
    assert abs((paper[:, 2].max() - paper[:, 2].min()) / 2 - p["roll_radius"]) < 2e-3
    assert paper[:, 0].min() > a.mesh.bounds[0][0] + 0.005  # clear of the wall


# ------------------------------------------------------------------------- every param matters


