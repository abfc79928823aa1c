"""Warehouse generators: pallet rack levels and pallet decks, beyond the generic contract in
test_generators.py."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg
import trimesh

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import TOL, as_manifold, build, distances, make, surface_gap

SEEDS = range(6)


def test_tags():
    assert {Semantics.Warehouse, Semantics.PalletRack, Semantics.Shelf} <= get_factory("pallet_rack").tags
    assert {Semantics.Warehouse, Semantics.Pallet} <= get_factory("wooden_pallet").tags


@pytest.mark.parametrize("seed", SEEDS)
def test_pallet_rack_levels(seed):
    f, p, _, a = build("pallet_rack", seed)
    levels = [s for s in a.surfaces if s.name.startswith("level_")]
    n_levels = len({s.name.split("_")[1] for s in levels})
    assert 2 <= n_levels <= p["n_levels"]
    assert len(levels) == n_levels * p["n_bays"]
    assert a.extents[2] <= 6.0 + 1e-9
    zs = sorted({round(float(s.origin[2]), 6) for s in levels})
    assert abs(zs[0] - p["first_level"]) < 1e-6
    assert np.allclose(np.diff(zs), p["level_spacing"])
    for s in levels:
        assert surface_gap(a, s) < TOL
        # room for a 1.2 x 0.8 m pallet on each bay
        x0, y0, x1, y1 = s.polygon.bounds
        assert x1 - x0 >= min(0.75, p["depth"] - 0.05) and y1 - y0 >= 1.2


@pytest.mark.parametrize("style", ["block", "stringer"])
@pytest.mark.parametrize("seed", range(4))
def test_wooden_pallet_deck(style, seed):
    f, p, a = make("wooden_pallet", seed, style=style)
    d, w, h = a.extents
    assert abs(d - p["width"]) < TOL and abs(w - p["length"]) < TOL and 0.09 < h < 0.2
    top = a.surface("top")
    assert top.subpart == Subpart.SupportSurface and abs(top.origin[2] - h) < TOL
    assert surface_gap(a, top) < TOL
    holes = list(top.polygon.interiors)
    assert len(holes) == p["n_top_boards"] - 1
    for hole in holes:  # the gaps between deck boards are open
        c = np.asarray(sg.Polygon(hole).centroid.coords)
        assert distances(a.mesh, top.to_world(c))[0] > 0.005
    # a forklift fork (10 cm wide, 4 cm high) passes right through the pallet under the deck:
    # along Y between the blocks, or along X between the stringers
    t, hb = p["deck_thickness"], p["block_height"]
    if style == "block":
        bx = min(0.145, d * 0.16)
        fork = trimesh.creation.box((0.1, w + 0.2, 0.04))
        fork.apply_translation(((-d / 2 + bx / 2) / 2, 0.0, t + hb / 2))
    else:
        z0 = t if p["bottom_deck"] else 0.0
        fork = trimesh.creation.box((d + 0.2, 0.1, 0.04))
        fork.apply_translation((0.0, (-w / 2 + 0.019) / 2, z0 + hb / 2))
    assert (as_manifold(a.mesh) ^ as_manifold(fork)).volume() < 1e-9
