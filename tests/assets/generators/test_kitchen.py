"""Kitchen generators (generators/kitchen/): cabinets, runs and islands under a countertop, wall
cabinets and the sink (the generic asset contract runs on them in test_generators.py)."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg
import trimesh

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import build, distances, make
from support.generatorcheck import (
    check_interior_shelves,
    check_wall_back,
    design_offset,
    first_hit_down,
    on_mesh,
)

SEEDS = range(6)
TOL = 1e-3


@pytest.mark.parametrize("name", ["kitchen_base_cabinet", "kitchen_wall_cabinet", "countertop_run",
                                  "kitchen_island", "kitchen_sink"])
def test_registered_with_tags(name):
    f = get_factory(name)
    assert Semantics.Object in f.tags
    expected = {
        "kitchen_sink": {Semantics.KitchenSink, Semantics.Countertop},
        "kitchen_base_cabinet": {Semantics.Cabinet, Semantics.KitchenCabinet, Semantics.Countertop},
        "kitchen_wall_cabinet": {Semantics.KitchenCabinet, Semantics.WallCabinet, Semantics.WallMounted},
        "countertop_run": {Semantics.KitchenCabinet, Semantics.Countertop},
        "kitchen_island": {Semantics.KitchenIsland, Semantics.Countertop},
    }[name]
    assert expected <= f.tags


@pytest.mark.parametrize("name,seed", [(n, s) for n in ("kitchen_base_cabinet", "kitchen_wall_cabinet",
                                                        "countertop_run", "kitchen_sink")
                                       for s in SEEDS])
def test_interior_surfaces_are_shelves_inside(name, seed):
    """Shelves behind doors (a drawer stack has none) face up, lie inside the carcass and on a
    board, and are whole shelves."""
    check_interior_shelves(build(name, seed)[3], required=False)


@pytest.mark.parametrize("seed", SEEDS)
def test_wall_cabinet_back_lies_on_mesh(seed):
    check_wall_back(build("kitchen_wall_cabinet", seed)[3], min_area=0.05)


@pytest.mark.parametrize("name,seed", [(n, s) for n in ("kitchen_base_cabinet", "countertop_run",
                                                        "kitchen_sink")
                                       for s in SEEDS])
def test_against_the_wall_back_is_flat(name, seed):
    """Floor units that stand against a wall have a flat back on the bounding box's back."""
    _, _, _, a = build(name, seed)
    assert on_mesh(a, a.surface("back")) < TOL


# -------------------------------------------------------------------------------- cabinets
@pytest.mark.parametrize("seed", SEEDS)
def test_base_cabinet_countertop_and_toe_kick(seed):
    _, p, _, a = build("kitchen_base_cabinet", seed)
    top = a.surface("top")
    assert top.subpart == Subpart.SupportSurface
    assert abs(top.origin[2] - p["height"]) < TOL and abs(a.extents[2] - p["height"]) < TOL
    assert on_mesh(a, top) < TOL
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
    _, p, a = make("kitchen_base_cabinet", 0, layout=layout, n_drawers=3, width=0.8)
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
    assert on_mesh(a, top) < TOL
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
    _, p, a = make("kitchen_wall_cabinet", 0, door_type="flap_up")
    (j,) = a.joints
    flap = a.link_mesh(j.child)
    assert np.allclose(np.abs(j.axis), (0, 1, 0)) and abs(j.origin[2] - a.mesh.bounds[1][2]) < 0.01
    moved = trimesh.transform_points(flap.vertices, j.transform(j.upper))
    assert moved[:, 2].min() > flap.bounds[0][2] + 0.5 * np.ptp(flap.vertices[:, 2])


# ----------------------------------------------------------------------------------- sink
@pytest.mark.parametrize("bowls,mount", [("single", "undermount"), ("double", "drop_in"),
                                         ("double", "undermount"), ("single", "drop_in")])
def test_sink_bowls_are_hollow(bowls, mount):
    """Each basin is open from above: its floor is a wall thickness above its bottom, its mouth
    open air and not part of the countertop surface, which lies at countertop height."""
    f, p, a = make("kitchen_sink", 0, bowls=bowls, mount=mount)
    q = f.resolve(p)
    offset = design_offset(f, q)
    L = f._sink_layout(q)
    assert len(L["cav"]) == (2 if bowls == "double" else 1)
    top = a.surface("top")
    assert abs(top.origin[2] - p["height"]) < TOL
    assert on_mesh(a, top) < TOL
    for ya, yb in L["cav"]:
        c = np.array([(L["bx0"] + L["bx1"]) / 2 + 0.08, (ya + yb) / 2, 0.0]) + offset
        assert distances(a.mesh, np.array([[c[0], c[1], L["z0"] + f.WALL]])).min() < TOL
        assert abs(first_hit_down(a.mesh, c[0], c[1]) - (L["z0"] + f.WALL)) < TOL
        assert distances(a.mesh, np.array([[c[0], c[1], top.origin[2]]])).min() > 0.03
        assert not top.polygon.contains(sg.Point(c[0] - top.origin[0], c[1] - top.origin[1]))


@pytest.mark.parametrize("seed", SEEDS)
def test_sink_base_stands_on_the_floor_at_base_cabinet_height(seed):
    """The sink is a floor unit: its plinth rests on the floor (solid bottom on the mesh), and its
    countertop has the height, depth and overhang of a base cabinet with the same params."""
    _, p, _, a = build("kitchen_sink", seed)
    assert abs(a.mesh.bounds[0][2]) < TOL
    assert on_mesh(a, a.surface("bottom")) < TOL
    shared = {k: p[k] for k in ("depth", "height", "countertop_thickness", "overhang",
                                "toe_kick_height", "handle", "front_style")}
    _, _, cab = make("kitchen_base_cabinet", seed, width=p["width"], layout="doors",
                     toe_kick_depth=0.06, **shared)
    top, ctop = a.surface("top"), cab.surface("top")
    assert abs(top.origin[2] - ctop.origin[2]) < TOL and abs(top.origin[2] - p["height"]) < TOL
    # the fronts line up: the countertop's front edge and the doors' faces match the cabinet's
    assert abs(top.corners()[:, 0].max() - ctop.corners()[:, 0].max()) < TOL
    assert abs(a.mesh.bounds[1][0] - cab.mesh.bounds[1][0]) < TOL
    # the carcass bottom is an interior surface under the basin, with no shelf above it
    (inner,) = a.surfaces_of(Subpart.Interior)
    assert inner.origin[2] < p["toe_kick_height"] + 0.03


@pytest.mark.parametrize("seed", SEEDS)
def test_sink_doors_open(seed):
    """A pair of side-hinged doors; opened, each leaf swings out in front of the carcass."""
    _, p, _, a = build("kitchen_sink", seed)
    assert sorted(j.kind for j in a.joints) == ["revolute", "revolute"]
    front = a.mesh.bounds[1][0]
    for j in a.joints:
        leaf = a.link_mesh(j.child)
        moved = trimesh.transform_points(leaf.vertices, j.transform(j.upper))
        assert moved[:, 0].max() > front + 0.2
        assert abs(np.ptp(moved[:, 2]) - np.ptp(leaf.vertices[:, 2])) < TOL


@pytest.mark.parametrize("seed", range(4))
def test_sink_counter_is_one_piece_however_wide_the_basin(seed):
    """A basin nearly as wide as the unit leaves the counter one surface (the larger strip),
    never a MultiPolygon the solver cannot take corners of (a home once crashed on one)."""
    _, _, a = make("kitchen_sink", seed, bowl_width_frac=1.0)
    top = a.surface("top")
    assert isinstance(top.polygon, sg.Polygon) and top.polygon.area > 0
    assert top.corners().shape[1] == 3
