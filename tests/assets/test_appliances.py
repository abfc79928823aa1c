"""Appliance and kitchen generators: properties specific to fridges, ovens, sinks, cabinets...
(the generic asset contract runs on them in test_generators.py)."""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely.geometry as sg
import trimesh

from indoorgen.assets.base import get_factory
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import build, distances, sample_polygon

GROUP = ["fridge", "beverage_fridge", "dishwasher", "microwave", "oven", "cooktop", "range",
         "monitor", "kitchen_sink", "washing_machine", "range_hood", "kitchen_base_cabinet",
         "kitchen_wall_cabinet", "countertop_run", "kitchen_island"]
SEEDS = range(6)
TOL = 1e-3


def _make(name: str, **over):
    """Create `name` with its seed-0 params overridden."""
    f = get_factory(name)
    p = f.sample_params(np.random.default_rng(0))
    p.update(over)
    return f, p, f.create(p)


def _on_mesh(a, s) -> np.ndarray:
    """Distances from a surface's sample points to the mesh."""
    return distances(a.mesh, s.to_world(sample_polygon(s.polygon)))


def _open_pose(a):
    return {j.name: j.upper for j in a.joints}


def _faces_of_slot(a, slot: str) -> np.ndarray:
    return np.nonzero(a.face_slots == a.slots.index(slot))[0] if slot in a.slots else np.zeros(0, int)


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
        "monitor": {Semantics.Electronics, Semantics.Monitor},
        "kitchen_sink": {Semantics.KitchenSink},
        "washing_machine": {Semantics.Appliance, Semantics.WashingMachine},
        "range_hood": {Semantics.RangeHood, Semantics.WallMounted},
        "kitchen_base_cabinet": {Semantics.Cabinet, Semantics.KitchenCabinet, Semantics.Countertop},
        "kitchen_wall_cabinet": {Semantics.KitchenCabinet, Semantics.WallCabinet, Semantics.WallMounted},
        "countertop_run": {Semantics.KitchenCabinet, Semantics.Countertop},
        "kitchen_island": {Semantics.KitchenIsland, Semantics.Countertop},
    }[name]
    assert expected <= f.tags
    if name == "beverage_fridge":  # never chosen as a kitchen's (full-size) fridge
        assert Semantics.Fridge not in f.tags


# ------------------------------------------------------------------------- interior surfaces
@pytest.mark.parametrize("name,seed", [(n, s) for n in ("fridge", "beverage_fridge", "dishwasher", "oven",
                                                        "range", "microwave", "kitchen_base_cabinet",
                                                        "kitchen_wall_cabinet", "countertop_run")
                                       for s in SEEDS])
def test_interior_surfaces_are_shelves_inside(name, seed):
    """Interior surfaces face up, lie inside the body and on a shelf; a wire rack's surface is
    the tops of its bars (a polygon with a hole per slot) across the whole rack, not one bar."""
    f, p, _, a = build(name, seed)
    inner = a.surfaces_of(Subpart.Interior)
    if name not in ("kitchen_base_cabinet", "countertop_run", "kitchen_wall_cabinet"):
        assert inner, "no interior surfaces"
    lo, hi = a.mesh.bounds
    for s in inner:
        assert np.allclose(s.normal, (0, 0, 1))
        c = s.corners()
        assert (c >= lo - TOL).all() and (c <= hi + TOL).all()
        assert _on_mesh(a, s).max() < TOL, s.name
        x0, y0, x1, y1 = s.polygon.bounds
        assert (x1 - x0) * (y1 - y0) > 0.03  # a whole shelf (> 0.03 m^2)
        if s.polygon.interiors:  # a rack: its bars cover a fair part of it
            assert s.polygon.area > 0.1 * (x1 - x0) * (y1 - y0)


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
    f, p, a = _make("fridge", style=style)
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
    _, p, a = _make("fridge")
    top = a.surface("top")
    assert top.subpart == Subpart.SupportSurface
    assert abs(top.origin[2] - p["height"]) < TOL
    assert _on_mesh(a, top).max() < TOL


@pytest.mark.parametrize("shelves", ["wire", "glass"])
def test_beverage_fridge_glass_door_shows_the_shelves(shelves):
    _, p, a = _make("beverage_fridge", shelf_style=shelves)
    door = a.link_mesh("door")
    glass = np.intersect1d(_faces_of_slot(a, "glass"), a.link_faces("door"))
    # most of the door's front is glass
    area = a.mesh.area_faces[glass].sum() / 2  # two sides of the pane
    d = door.extents
    assert area > 0.4 * d[1] * d[2]
    levels = [s for s in a.surfaces_of(Subpart.Interior)]
    assert len(levels) == p["n_shelves"] + 1


# ----------------------------------------------------------------------- drop-down doors
@pytest.mark.parametrize("name", ["dishwasher", "oven", "range"])
def test_drop_down_door(name):
    _, p, a = _make(name)
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
        _, p, a = _make("dishwasher", panel=panel, n_buttons=5)
        door = a.link_faces("door")
        buttons = np.intersect1d(door,
                                 np.concatenate([_faces_of_slot(a, "metal"), _faces_of_slot(a, "plastic")]))
        top = a.mesh.triangles_center[buttons]
        assert (top[:, 2] > a.mesh.bounds[1][2] - 0.1).any()


@pytest.mark.parametrize("cavities,n", [("single", 1), ("double", 2)])
def test_oven_cavities(cavities, n):
    _, p, a = _make("oven", cavities=cavities, n_racks=2)
    assert len(a.joints) == n
    assert len(a.surfaces_of(Subpart.Interior)) == n * 3  # floor and two racks per cavity
    assert len(_faces_of_slot(a, "glass")) > 0


# ------------------------------------------------------------------------------ hobs
@pytest.mark.parametrize("style", ["glass", "gas"])
def test_cooktop_surfaces(style):
    f, p, a = _make("cooktop", style=style, n_burners=4)
    assert f.size_class == "small"
    sup = a.surfaces_of(Subpart.SupportSurface)
    assert sup
    h = a.extents[2]
    for s in sup:
        assert _on_mesh(a, s).max() < TOL
        if style == "gas":
            assert abs(s.origin[2] - h) < TOL  # grate tops are the highest thing
    if style == "gas":
        assert len(sup) in (1, 4)
    # rests flat on the counter
    assert _on_mesh(a, a.surface("bottom")).max() < TOL


@pytest.mark.parametrize("hob", ["glass", "gas"])
def test_range_hob_at_declared_height(hob):
    _, p, a = _make("range", hob=hob)
    sup = a.surfaces_of(Subpart.SupportSurface)
    zs = {round(s.origin[2], 4) for s in sup}
    expect = p["height"] + (0.035 if hob == "gas" else 0.0)
    assert all(abs(z - expect) < TOL for z in zs)
    for s in sup:
        assert _on_mesh(a, s).max() < TOL


# ---------------------------------------------------------------------- wall-mounted things
@pytest.mark.parametrize("name,seed",
                         [(n, s) for n in ("range_hood", "kitchen_wall_cabinet") for s in SEEDS])
def test_wall_mounted_back_lies_on_mesh(name, seed):
    _, _, _, a = build(name, seed)
    back = a.surface("back")
    assert np.allclose(back.normal, (-1, 0, 0))
    assert np.allclose(back.corners()[:, 0], a.mesh.bounds[0][0], atol=TOL)
    assert _on_mesh(a, back).max() < TOL
    assert back.polygon.area > 0.05


@pytest.mark.parametrize("name,seed", [(n, s) for n in ("kitchen_base_cabinet", "countertop_run", "fridge",
                                                        "beverage_fridge", "dishwasher", "range")
                                       for s in SEEDS])
def test_against_the_wall_back_is_flat(name, seed):
    """Floor units that stand against a wall have a flat back on the bounding box's back."""
    _, _, _, a = build(name, seed)
    assert _on_mesh(a, a.surface("back")).max() < TOL


def test_range_hood_lights_shine_down():
    for style in ("chimney_box", "chimney_pyramid", "under_cabinet"):
        _, p, a = _make("range_hood", style=style, n_lights=2)
        em = _faces_of_slot(a, "emissive")
        assert len(em)
        n = a.mesh.face_normals[em]
        assert (n[:, 2] < -0.99).any()
        assert a.mesh.triangles_center[em][:, 2].max() < 0.01  # in the underside


# -------------------------------------------------------------------------------- cabinets
@pytest.mark.parametrize("seed", SEEDS)
def test_base_cabinet_countertop_and_toe_kick(seed):
    _, p, _, a = build("kitchen_base_cabinet", seed)
    top = a.surface("top")
    assert top.subpart == Subpart.SupportSurface
    assert abs(top.origin[2] - p["height"]) < TOL and abs(a.extents[2] - p["height"]) < TOL
    assert _on_mesh(a, top).max() < TOL
    # the plinth is set back: nothing below the toe-kick height in front of it (z < 1 mm: floor)
    lo = a.mesh.bounds[0]
    carcass_front = lo[0] + p["depth"]
    v = a.mesh.vertices
    low = v[v[:, 2] < p["toe_kick_height"] - 0.002]
    assert low[:, 0].max() <= carcass_front - p["toe_kick_depth"] + TOL
    # the countertop overhangs the carcass by `overhang`
    assert abs(top.corners()[:, 0].max() + 0.02 - (carcass_front + p["overhang"])) < TOL


@pytest.mark.parametrize("layout", ["doors", "drawers", "drawer_doors"])
def test_base_cabinet_fronts(layout):
    _, p, a = _make("kitchen_base_cabinet", layout=layout, n_drawers=3, width=0.8)
    kinds = sorted(j.kind for j in a.joints)
    want = {"doors": ["revolute"] * 2, "drawers": ["prismatic"] * 3,
            "drawer_doors": ["prismatic"] + ["revolute"] * 2}[layout]
    assert kinds == want
    for j in a.joints:
        if j.kind == "prismatic":
            assert np.allclose(j.axis, (1, 0, 0)) and 0.3 < j.upper < p["depth"]
    has_doors = layout != "drawers"
    assert bool(a.surfaces_of(Subpart.Interior)) == has_doors


@pytest.mark.parametrize("seed", SEEDS)
def test_countertop_run_is_one_continuous_top(seed):
    _, p, _, a = build("countertop_run", seed)
    top = a.surface("top")
    w = a.extents[1]
    x0, y0, x1, y1 = top.polygon.bounds
    assert (y1 - y0) > w - 0.05  # spans the whole run
    units = {link.split("_")[0] for link in a.links[1:]}
    assert len(units) <= p["n_units"]
    assert _on_mesh(a, top).max() < TOL
    # points all along the run's length at countertop height are on the mesh (no seams)
    ys = np.linspace(-w / 2 + 0.03, w / 2 - 0.03, 25)
    pts = np.c_[np.full(25, top.origin[0]), ys, np.full(25, top.origin[2])]
    assert distances(a.mesh, pts).max() < TOL


@pytest.mark.parametrize("seed", SEEDS)
def test_kitchen_island_seating_overhang(seed):
    _, p, _, a = build("kitchen_island", seed)
    lo, hi = a.mesh.bounds
    H, ct = p["height"], p["countertop_thickness"]
    assert abs(hi[2] - H) < TOL
    # knee space under the seating side: open between the floor and the countertop, away
    # from the ends
    x_panel = lo[0] + p["seating_overhang"]
    w = a.extents[1]
    g = np.stack(np.meshgrid(np.linspace(lo[0] + 0.02, x_panel - 0.02, 4),
                             np.linspace(-w / 2 + 0.12, w / 2 - 0.12, 7),
                             np.linspace(0.15, H - ct - 0.08, 5)), -1).reshape(-1, 3)
    assert not a.mesh.contains(g).any()
    assert (trimesh.proximity.closest_point(a.mesh, g)[1] > 0.005).all()
    # the countertop covers it
    top = a.surface("top")
    assert top.corners()[:, 0].min() < lo[0] + 0.03
    # legs or waterfall slabs stand at the ends of the overhang
    y_end = w / 2 - (ct / 2 if p["end_style"] == "waterfall" else 0.06)
    ends = np.array([[lo[0] + 0.06, s * y_end, H / 2] for s in (-1, 1)])
    if p["end_style"] == "plain":
        assert not a.mesh.contains(ends).any()
    else:
        assert a.mesh.contains(ends).all()


def test_wall_cabinet_flap_lifts_up():
    _, p, a = _make("kitchen_wall_cabinet", door_type="flap_up")
    (j,) = a.joints
    flap = a.link_mesh(j.child)
    assert np.allclose(np.abs(j.axis), (0, 1, 0)) and abs(j.origin[2] - a.mesh.bounds[1][2]) < 0.01
    moved = trimesh.transform_points(flap.vertices, j.transform(j.upper))
    assert moved[:, 2].min() > flap.bounds[0][2] + 0.5 * np.ptp(flap.vertices[:, 2])


# ----------------------------------------------------------------------------------- sink
@pytest.mark.parametrize("bowls,mount", [("single", "undermount"), ("double", "drop_in"),
                                         ("double", "undermount"), ("single", "drop_in")])
def test_sink_bowls_are_hollow(bowls, mount):
    f, p, a = _make("kitchen_sink", bowls=bowls, mount=mount)
    q = f.resolve(p)
    offset = f._layout(q)[1]  # design frame -> asset frame
    L = f._sink_layout(q)
    assert len(L["cav"]) == (2 if bowls == "double" else 1)
    top = a.surface("top")
    assert abs(top.origin[2] - (p["bowl_depth"] + p["countertop_thickness"])) < TOL
    assert _on_mesh(a, top).max() < TOL
    for ya, yb in L["cav"]:
        c = np.array([(L["bx0"] + L["bx1"]) / 2 + 0.08, (ya + yb) / 2, 0.0]) + offset
        # the bowl's floor is its wall thickness above the bottom; its mouth is open air,
        # and not part of the countertop surface
        assert distances(a.mesh, np.array([[c[0], c[1], f.WALL]])).min() < TOL
        assert distances(a.mesh, np.array([[c[0], c[1], top.origin[2]]])).min() > 0.03
        assert not top.polygon.contains(sg.Point(c[0] - top.origin[0], c[1] - top.origin[1]))
    solid = np.prod(a.extents[:2]) * (p["bowl_depth"] + p["countertop_thickness"])
    assert a.mesh.volume < 0.5 * solid


# ------------------------------------------------------------------------------ misc
def test_microwave_door_and_turntable():
    f, p, a = _make("microwave")
    assert f.size_class == "medium"
    (j,) = a.joints
    assert j.kind == "revolute" and np.allclose(j.axis, (0, 0, -1))
    assert abs(j.origin[1] - a.mesh.bounds[0][1]) < 0.005  # hinged on the left side
    turntable = a.surface("interior_0")
    assert turntable.subpart == Subpart.Interior and _on_mesh(a, turntable).max() < TOL


def test_washing_machine_round_door_and_drawer():
    _, p, a = _make("washing_machine")
    kinds = {j.child: j.kind for j in a.joints}
    assert kinds == {"door": "revolute", "drawer": "prismatic"}
    door = a.link_mesh("door").extents
    assert abs(door[1] - door[2]) < 0.03  # round, not rectangular (grip aside)
    glass = _faces_of_slot(a, "glass")
    assert np.isin(glass, a.link_faces("door")).all()


@pytest.mark.parametrize("seed", SEEDS)
def test_monitor_screen_faces_front(seed):
    _, p, _, a = build("monitor", seed)
    screen = _faces_of_slot(a, "screen")
    n = a.mesh.face_normals[screen]
    area = a.mesh.area_faces[screen]
    front = area[n[:, 0] > math.cos(math.radians(p["tilt"] + 1))].sum()
    assert front > 0.4 * area.sum()
    assert abs(a.extents[1] - p["screen_width"]) < TOL
