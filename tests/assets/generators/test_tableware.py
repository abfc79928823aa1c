"""Tableware generators (generators/tableware/): hollow bowls, cups and glasses, capped or open
bottles (the generic asset contract runs on them in test_generators.py)."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.assets.catalogue import factories_with
from indoorgen.model.tags import Semantics
from support.assetcheck import build, make
from support.generatorcheck import (
    check_material_choices,
    check_open_inner_floor,
    check_small_objects,
    check_thin_walled,
    first_hit_down,
)

NAMES = ["plate", "cup", "bowl", "mug", "wineglass", "glass_tumbler", "wine_bottle", "beer_bottle",
         "soda_bottle"]
SEEDS = range(5)


def test_catalogue_lists_every_kind():
    check_small_objects(NAMES)
    assert {"wine_bottle", "beer_bottle", "soda_bottle"} <= set(factories_with([Semantics.Bottle]))


def test_material_choices_name_real_materials():
    check_material_choices(NAMES)


@pytest.mark.parametrize("name,seed", [(n, s) for n in ("bowl", "mug", "glass_tumbler") for s in SEEDS])
def test_vessel_interior_is_the_open_inner_floor(name, seed):
    """The interior surface lies on the inner floor, above the underside, and a ray dropped
    into the vessel's mouth reaches it (the cavity is open, not sealed)."""
    check_open_inner_floor(build(name, seed)[3])


@pytest.mark.parametrize("name", ["bowl", "mug", "wineglass", "glass_tumbler"])
def test_vessels_are_thin_walled(name):
    """Much less material than the solid of the same outline: really hollow."""
    for seed in SEEDS:
        _, _, ph, a = build(name, seed)
        check_thin_walled(ph, a)


@pytest.mark.parametrize("name,closure", [("wine_bottle", "cork"), ("wine_bottle", "open"),
                                          ("beer_bottle", "crown"), ("beer_bottle", "open"),
                                          ("soda_bottle", "screwcap"), ("soda_bottle", "open")])
def test_bottles_capped_solid_open_hollow(name, closure):
    _, p, a = make(name, 0, closure=closure, label=False)
    hull = a.mesh.convex_hull.volume
    if closure == "open":
        assert a.mesh.volume < 0.3 * hull
        # a ray down the neck reaches the floor near the bottom
        assert first_hit_down(a.mesh, 0.0, 0.0) < 0.05
    else:
        assert a.mesh.volume > 0.85 * hull
        assert first_hit_down(a.mesh, 0.0, 0.0) >= a.extents[2] - 1e-3


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
