"""Storage: surfaces where they should be and fronts that really move (cabinets, wardrobes,
dressers, nightstands, shelves), beyond the generic contract in test_generators.py."""
from __future__ import annotations

import math

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import TOL, as_manifold, build, distances, make, point_inside, surface_gap

STORAGE = ["cabinet", "wardrobe", "dresser", "nightstand", "cell_shelf", "wall_shelf",
           "corner_shelf", "shoe_rack"]
SEEDS = range(6)


def test_tags():
    for name in STORAGE:
        assert Semantics.Storage in get_factory(name).tags
    assert Semantics.WallMounted in get_factory("wall_shelf").tags


@pytest.mark.parametrize("seed", SEEDS)
def test_cabinet_doors_shelves_and_top(seed):
    f, p, _, a = build("cabinet", seed)
    d, w, h = a.extents
    top = a.surface("top")
    assert top.subpart == Subpart.SupportSurface and abs(top.origin[2] - h) < TOL
    assert surface_gap(a, top) < TOL
    doors = [j for j in a.joints if j.kind == "revolute"]
    assert len(doors) == (1 if p["width"] < 0.5 else p["n_doors"])
    drawers = [j for j in a.joints if j.kind == "prismatic"]
    assert len(drawers) == (len(doors) if p["drawer_row"] else 0)
    interior = a.surfaces_of(Subpart.Interior)
    assert len(interior) >= 1
    zs = sorted(s.origin[2] for s in interior)
    assert all(b - a_ >= 0.18 for a_, b in zip(zs, zs[1:], strict=False))  # shelves keep 18 cm apart
    for s in interior:
        assert np.allclose(s.normal, (0, 0, 1)) and 0 < s.origin[2] < h
        assert surface_gap(a, s) < TOL


@pytest.mark.parametrize("seed", SEEDS)
def test_cabinet_open_doors_expose_the_shelves(seed):
    """Fully open, no door leaf is in front of the compartment any more."""
    _, p, _, a = build("cabinet", seed)
    opened = a.posed({j.name: j.upper for j in a.joints})
    d, w, h = a.extents
    s = a.surfaces_of(Subpart.Interior)[0]
    # a ray from the compartment floor straight out of the front (a quarter of the width off
    # the middle, where two doors meet) meets nothing
    origin = s.origin + np.array([0.0, w / 4, 0.05])
    hits = opened.ray.intersects_location([origin], [[1.0, 0.0, 0.0]])[0]
    assert len(hits) == 0
    closed_hits = a.mesh.ray.intersects_location([origin], [[1.0, 0.0, 0.0]])[0]
    assert len(closed_hits) > 0  # closed, the door is in the way


@pytest.mark.parametrize("seed", range(10))
def test_wardrobe_doors(seed):
    f, p, _, a = build("wardrobe", seed)
    doors = [j for j in a.joints if j.child.startswith("door")]
    if p["door_type"] == "sliding":
        assert len(doors) == 2 and all(j.kind == "prismatic" for j in doors)
        axes = sorted(float(j.axis[1]) for j in doors)
        assert axes == [-1.0, 1.0] and all(abs(j.axis[0]) < 1e-9 for j in doors)
        # the panels run on separate tracks: they pass each other without touching
        m0, m1 = (a.link_mesh(j.child) for j in doors)
        assert m0.bounds[1][0] < m1.bounds[0][0] or m1.bounds[1][0] < m0.bounds[0][0]
        j0 = doors[0]
        moved = m0.copy()
        moved.apply_transform(j0.transform(j0.upper))
        assert (as_manifold(moved) ^ as_manifold(m1)).volume() < 1e-9
    else:
        n = f._n_doors(p)
        assert 2 <= n <= 4 and len(doors) == n and all(j.kind == "revolute" for j in doors)
        assert 0.3 - 1e-9 <= p["width"] / n <= 0.65 + 1e-9
    drawers = [j for j in a.joints if j.child.startswith("drawer")]
    assert len(drawers) == p["drawer_rows"] * (3 if p["width"] > 1.3 else 2)
    interior = a.surfaces_of(Subpart.Interior)
    assert interior and all(surface_gap(a, s) < TOL for s in interior)
    # the hat shelf over the hanging rail sits shelf_drop below the carcass top
    H = a.extents[2]
    target = H - p["board_thickness"] - p["shelf_drop"]
    assert min(abs(s.origin[2] - target) for s in interior) < TOL


@pytest.mark.parametrize("seed", range(10))
def test_dresser_drawers(seed):
    f, p, _, a = build("dresser", seed)
    case = f.layout(p)
    assert all(j.kind == "prismatic" and np.allclose(j.axis, (1, 0, 0)) for j in a.joints)
    n_cells = len([c for c in case.cells if c.kind == "drawer"])
    assert len(a.joints) == n_cells >= 3
    for j in a.joints:
        assert j.upper >= 0.8 * (p["depth"] - 0.03) - 1e-9  # opens most of its depth
    top = a.surface("top")
    assert abs(top.origin[2] - a.extents[2]) < TOL and surface_gap(a, top) < TOL
    # each drawer is a box: pulled out, its floor is reachable from above (open-topped)
    j = a.joints[0]
    opened = a.posed({j.name: j.upper})
    child = a.link_mesh(j.child)
    lo, hi = child.bounds
    probe = np.array([[hi[0] - 0.12 + j.upper, (lo[1] + hi[1]) / 2, hi[2] + 0.5]])
    hit = opened.ray.intersects_location(probe, [[0.0, 0.0, -1.0]])[0]
    assert len(hit) and hit[:, 2].max() < hi[2] - 0.01


@pytest.mark.parametrize("layout", ["drawer_shelf", "two_drawers", "drawer_door", "open",
                                    "three_drawers"])
def test_nightstand_layouts(layout):
    f, p, a = make("nightstand", 3, layout=layout, height=0.65)
    kinds = sorted(j.kind for j in a.joints)
    expected = {"drawer_shelf": ["prismatic"], "two_drawers": ["prismatic"] * 2,
                "drawer_door": ["prismatic", "revolute"], "open": [],
                "three_drawers": ["prismatic"] * 3}[layout]
    assert kinds == expected
    shelves = [s for s in a.surfaces if s.name.startswith("shelf_")]
    assert len(shelves) == {"drawer_shelf": 1, "open": 2}.get(layout, 0)
    for s in shelves + a.surfaces_of(Subpart.Interior) + [a.surface("top")]:
        assert surface_gap(a, s) < TOL
    assert len(a.surfaces_of(Subpart.Interior)) == (1 if layout == "drawer_door" else 0)


@pytest.mark.parametrize("seed", SEEDS)
def test_cell_shelf_cells(seed):
    f, p, _, a = build("cell_shelf", seed)
    nr, nc = p["n_rows"], p["n_cols"]
    cells = [s for s in a.surfaces if s.name.startswith("cell_")]
    assert len(cells) == nr * nc
    assert all(s.subpart == Subpart.SupportSurface for s in cells)
    zs = sorted({round(float(s.origin[2]), 6) for s in cells})
    assert len(zs) == nr
    assert np.allclose(np.diff(zs), p["cell_size"] + p["inner_thickness"], atol=1e-6)
    for s in cells:
        assert surface_gap(a, s) < TOL
        # a cube of cell_size is free above every cell floor
        hit = a.mesh.ray.intersects_location([s.origin + (0, 0, 0.001)], [[0.0, 0.0, 1.0]])[0]
        assert abs(hit[:, 2].min() - s.origin[2] - p["cell_size"]) < TOL


@pytest.mark.parametrize("style", ["floating", "bracketed", "boxed"])
@pytest.mark.parametrize("n_boards", [1, 3])
def test_wall_shelf_back_on_wall(style, n_boards):
    f, p, a = make("wall_shelf", 1, style=style, n_boards=n_boards, edge_radius=0.004)
    back = a.surface("back")
    d = a.extents[0]
    assert np.allclose(back.normal, (-1, 0, 0)) and np.allclose(back.corners()[:, 0], -d / 2)
    assert surface_gap(a, back) < TOL
    shelves = [s for s in a.surfaces if s.name.startswith("shelf_")]
    assert len(shelves) == n_boards + (1 if style == "boxed" else 0)
    zs = sorted(s.origin[2] for s in shelves)
    assert abs(zs[-1] - a.extents[2]) < TOL  # the top board is the top
    assert all(b - a_ >= p["spacing"] for a_, b in zip(zs, zs[1:], strict=False))
    assert all(surface_gap(a, s) < TOL for s in shelves)


@pytest.mark.parametrize("seed", SEEDS)
def test_corner_shelf_fits_a_corner(seed):
    f, p, _, a = build("corner_shelf", seed)
    d, w, h = a.extents
    assert abs(d - p["size"]) < TOL and abs(w - p["size"]) < TOL
    back, side = a.surface("back"), a.surface("side_left")
    assert np.allclose(side.normal, (0, 1, 0))
    assert surface_gap(a, back) < TOL and surface_gap(a, side) < TOL  # flat against both walls
    shelves = sorted((s for s in a.surfaces if s.name.startswith("shelf_")), key=lambda s: s.origin[2])
    assert len(shelves) == p["n_levels"]
    assert np.allclose(np.diff([s.origin[2] for s in shelves]), p["level_spacing"])
    for s in shelves:
        assert surface_gap(a, s) < TOL
        # every shelf lies in the corner's half: beyond the diagonal there is nothing
        c = s.corners()
        assert ((c[:, 0] + d / 2) + (w / 2 - c[:, 1]) <= p["size"] * math.sqrt(2) + 1e-6).all()
    # the open front corner (+X, -Y) is empty
    probe = np.array([[d / 2 - 0.01, -w / 2 + 0.01, h / 2]])
    assert distances(a.mesh, probe)[0] > 0.005


@pytest.mark.parametrize("tier_style", ["slats", "solid"])
@pytest.mark.parametrize("seed", range(3))
def test_shoe_rack_tiers(tier_style, seed):
    f, p, a = make("shoe_rack", seed, tier_style=tier_style)
    tiers = sorted((s for s in a.surfaces if s.name.startswith("tier_")), key=lambda s: s.origin[2])
    assert len(tiers) == p["n_tiers"]
    assert np.allclose(np.diff([s.origin[2] for s in tiers]), p["tier_spacing"])
    for s in tiers:
        assert surface_gap(a, s) < TOL
        holes = list(s.polygon.interiors)
        assert len(holes) == (p["n_slats"] - 1 if tier_style == "slats" else 0)
        for hole in holes:  # the holes really are gaps between slats
            c = np.asarray(sg.Polygon(hole).centroid.coords)
            assert distances(a.mesh, s.to_world(c))[0] > 0.005


@pytest.mark.parametrize("name", ["cabinet", "wardrobe", "dresser", "nightstand", "corner_shelf"])
@pytest.mark.parametrize("seed", range(4))
def test_case_backs_stand_against_the_wall(name, seed):
    """The `back` of case furniture is its flat carcass back, at the bbox back."""
    _, _, _, a = build(name, seed)
    back = a.surface("back")
    assert np.allclose(back.corners()[:, 0], -a.extents[0] / 2, atol=TOL)
    assert surface_gap(a, back) < TOL


@pytest.mark.parametrize("seed", SEEDS)
def test_tool_chest_drawers_graduated(seed):
    """A tool chest's drawers all slide out, the shallow ones on top; it stands on casters."""
    f, p, _, a = build("tool_chest", seed)
    assert {Semantics.Storage, Semantics.ToolChest} <= f.tags
    assert a.joints and all(j.kind == "prismatic" and np.allclose(j.axis, (1, 0, 0))
                            for j in a.joints)
    heights = {}
    for j in a.joints:
        lo, hi = a.link_mesh(j.child).bounds
        heights[round(float(lo[2]), 4)] = float(hi[2] - lo[2])
    by_z = [heights[z] for z in sorted(heights)]
    assert (np.diff(by_z) <= 1e-6).all()  # deeper towards the floor
    assert by_z[-1] >= 0.06
    top = a.surface("top")
    assert abs(top.origin[2] - a.extents[2]) < TOL and surface_gap(a, top) < TOL
    # casters: the floor under the middle of the case is open
    assert not point_inside(a, [(0.0, 0.0, 0.02)])[0]


@pytest.mark.parametrize("seed", SEEDS)
def test_storage_rack_shelves(seed):
    """A steel rack's shelves are evenly spaced, each a support surface on its board with room
    for a storage box above it."""
    f, p, _, a = build("storage_rack", seed)
    assert {Semantics.Shelf, Semantics.StorageRack} <= f.tags
    shelves = sorted((s for s in a.surfaces if s.subpart == Subpart.SupportSurface),
                     key=lambda s: s.origin[2])
    assert shelves[-1].name == "top" and len(shelves) >= 3
    zs = np.array([s.origin[2] for s in shelves])
    assert np.allclose(np.diff(zs), np.diff(zs)[0], atol=1e-6)
    assert a.extents[2] - 0.01 <= zs[-1] <= a.extents[2]
    for s in shelves:
        assert surface_gap(a, s) < TOL
    for s in shelves[:-1]:  # nothing in the way of a 0.25 m box above each lower shelf
        hit = a.mesh.ray.intersects_location([s.origin + (0, 0, 0.001)], [[0.0, 0.0, 1.0]])[0]
        assert hit[:, 2].min() - s.origin[2] >= 0.25
