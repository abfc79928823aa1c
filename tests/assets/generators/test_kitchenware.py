"""Kitchenware generators (generators/kitchenware/): pots and pans with lids and handles, jars,
utensils lying flat, cutting boards, and what stands out on a counter: kettles, toasters, knife
blocks, utensil crocks (the generic asset contract runs on them in
test_generators.py)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from indoorgen.assets.catalogue import factories_with
from indoorgen.model.tags import Semantics
from support.assetcheck import build, distances, make, sample_polygon
from support.generatorcheck import (
    check_material_choices,
    check_open_inner_floor,
    check_small_objects,
    check_thin_walled,
    design_offset,
    first_hit_down,
)

NAMES = ["cooking_pot", "frying_pan", "pot_lid", "jar", "knife", "fork", "spoon", "chopsticks",
         "spatula", "cutting_board"]
UTENSILS = ["knife", "fork", "spoon", "chopsticks", "spatula"]
SEEDS = range(5)


def test_catalogue_lists_every_kind():
    check_small_objects(NAMES)
    assert set(UTENSILS[:4]) <= set(factories_with([Semantics.Cutlery]))


def test_material_choices_name_real_materials():
    check_material_choices(NAMES)


@pytest.mark.parametrize("name,seed", [(n, s) for n in ("jar", "cooking_pot", "frying_pan") for s in SEEDS])
def test_vessel_interior_is_the_open_inner_floor(name, seed):
    """The interior surface lies on the inner floor, above the underside, and a ray dropped
    into the vessel's mouth reaches it (the cavity is open, not sealed)."""
    check_open_inner_floor(build(name, seed)[3])


def test_jar_is_thin_walled():
    for seed in SEEDS:
        _, _, ph, a = build("jar", seed)
        check_thin_walled(ph, a)


@pytest.mark.parametrize("name", ["jar", "cooking_pot"])
def test_lid_lifts_straight_off(name):
    extra = {"has_lid": True} if name == "cooking_pot" else {}
    f, p, a = make(name, 0, **extra)
    (j,) = a.joints
    assert j.kind == "prismatic" and np.allclose(j.axis, (0, 0, 1)) and j.child == "lid"
    body, lid = a.link_mesh("base"), a.link_mesh("lid")
    rim = body.bounds[1][2]
    opened = lid.copy()
    opened.apply_transform(j.transform(j.upper))
    assert opened.bounds[0][2] > rim + 0.02  # lifted clear of the rim
    # closed, the lid covers the opening: a ray down the axis meets the lid first
    assert first_hit_down(a.mesh, 0.0, 0.0) > rim


def test_pot_handles():
    _, p, a = make("cooking_pot", 0, handle_style="loops", has_lid=False)
    lo, hi = a.mesh.bounds
    assert hi[1] > p["radius"] + 0.02 and lo[1] < -p["radius"] - 0.02  # both sides
    assert abs(hi[1] + lo[1]) < 1e-3
    _, p, a = make("cooking_pot", 0, handle_style="long", has_lid=False)
    assert a.extents[0] > 2 * p["radius"] + 0.1  # a saucepan handle along +X
    _, p, a = make("frying_pan", 0, helper_handle=False)
    assert a.extents[0] > 2 * p["radius"] + 0.8 * p["handle_length"]


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
    f, p, a = make("fork", 0, tines=tines)
    x = p["head_length"] * 0.85 + design_offset(f, p)[0]
    sec = a.mesh.section(plane_origin=(x, 0, 0), plane_normal=(1, 0, 0))
    assert len(sec.to_2D()[0].polygons_full) == tines


def test_chopsticks_are_a_pair():
    f, p, a = make("chopsticks", 0, rest=False)
    x = 0.9 * p["length"] + design_offset(f, p)[0]
    sec = a.mesh.section(plane_origin=(x, 0, 0), plane_normal=(1, 0, 0))
    assert len(sec.to_2D()[0].polygons_full) == 2
    f, p, a = make("chopsticks", 0, rest=True)
    tip = a.mesh.vertices[a.mesh.vertices[:, 0] > a.mesh.bounds[1][0] - 0.01]
    assert tip[:, 2].min() > 0.008  # the tips are raised on the rest


def test_spoon_bowl_is_hollow():
    f, p, a = make("spoon", 0)
    ax, _, c, t = f._dims(p)
    x = ax + design_offset(f, p)[0]
    floor = first_hit_down(a.mesh, x, 0.0)  # the inside of the bowl, one wall above the table
    assert abs(floor - t) < 1e-3 and floor < c - 0.002


# ----------------------------------------------------------------------------- boards
@pytest.mark.parametrize("style", ["rect", "rounded", "paddle"])
def test_cutting_board_top_and_hole(style):
    f, p, a = make("cutting_board", 0, style=style, handle_hole=True, juice_groove=True)
    top = a.surface("top")
    assert abs(top.origin[2] - p["thickness"]) < 1e-9 and abs(a.extents[2] - p["thickness"]) < 1e-6
    pts = top.to_world(sample_polygon(top.polygon))
    assert distances(a.mesh, pts).max() < 1e-3
    c = np.asarray(f._hole(p).centroid.coords[0]) + design_offset(f, p)[:2]
    assert first_hit_down(a.mesh, c[0], c[1]) == -math.inf  # the hole goes through


# ------------------------------------------------------------------ what stands on a counter
COUNTER_KIT = ["kettle", "toaster", "knife_block", "utensil_crock"]


def test_counter_kit_is_small_and_names_real_materials():
    check_small_objects(COUNTER_KIT)
    check_material_choices(COUNTER_KIT)


@pytest.mark.parametrize("seed", range(3))
def test_counter_kit_has_believable_sizes(seed):
    """Each fits under a wall cabinet (0.45-0.6 m over the counter) and on a 0.6 m counter."""
    for name in COUNTER_KIT:
        _, _, a = make(name, seed)
        d, w, h = a.extents
        assert 0.05 <= h <= 0.45 and max(d, w) <= 0.45, (name, a.extents)


@pytest.mark.parametrize("rows", [1, 2])
def test_toaster_slots_open_into_the_body(rows):
    """Bread goes in from the top: a ray dropped down a slot meets the body well below its top."""
    f, p, a = make("toaster", 0, rows=rows)
    top = a.mesh.bounds[1][2]
    off = design_offset(f, p)
    d = p["depth"]
    x = (0 - (rows - 1) / 2) * d / (rows + 0.6) + off[0]
    assert top - first_hit_down(a.mesh, x, off[1]) > 0.05


def test_utensils_stand_out_of_the_crock():
    """The utensils rise well above the crock's rim."""
    _, p, a = make("utensil_crock", 1)
    assert a.extents[2] > p["height"] + 0.1
