"""PartsFactory: placeholders carry the full asset's joints, and each moving link's box holds
that link of the detailed mesh (what the solver sweeps to keep a door's or drawer's path free)."""
from __future__ import annotations

import numpy as np
import pytest
import shapely.geometry as sg

from indoorgen.assets.catalogue import get_factory
from indoorgen.assets.shapes.surfaces import support_polygon

ARTICULATED = ("dresser", "fridge", "kitchen_sink", "toilet", "countertop_run", "wardrobe")


@pytest.mark.parametrize("name", ARTICULATED)
@pytest.mark.parametrize("seed", [0, 1])
def test_placeholder_joints_and_link_boxes_match_the_full_asset(name, seed):
    f = get_factory(name)
    p = f.sample_params(np.random.default_rng(seed))
    full, ph = f.create(dict(p)), f.placeholder(dict(p))
    assert [(j.name, j.kind, j.child) for j in ph.joints] == \
        [(j.name, j.kind, j.child) for j in full.joints]
    for a, b in zip(ph.joints, full.joints, strict=True):
        assert np.allclose(a.origin, b.origin) and np.allclose(a.axis, b.axis)
        assert (a.lower, a.upper) == (b.lower, b.upper)
    boxes = f.link_boxes(dict(p))
    assert set(boxes) == {j.child for j in full.joints}
    for link, (lo, hi) in boxes.items():
        v = full.mesh.vertices[np.unique(full.mesh.faces[full.link_faces(link)])]
        assert (v >= lo - 1e-6).all() and (v <= hi + 1e-6).all()
        assert np.allclose(v.min(axis=0), lo, atol=0.01) and np.allclose(v.max(axis=0), hi, atol=0.01)


def test_a_sink_whose_bowl_nearly_fills_its_counter_builds():
    # the counter round a bowl 99% of the sink's width once came in pieces (a MultiPolygon):
    # the full asset must still build (home seed 0 with 600 large steps crashed on this)
    f = get_factory("kitchen_sink")
    p = {**f.sample_params(np.random.default_rng(0)), "bowls": "single", "mount": "drop_in",
         "bowl_width_frac": 0.9942, "width": 0.6354, "depth": 0.6041, "overhang": 0.0315}
    full = f.create(dict(p))
    # the counter is the larger strip: one polygon, whose corners the solver can take
    assert full.collision and all(s.polygon.geom_type == "Polygon" for s in full.surfaces)
    assert all(s.corners().shape[1] == 3 for s in full.surfaces)
    # and a surface in pieces still has corners bounding every piece
    two = support_polygon("top", (0, 0, 0.9), sg.box(0, 0, 1, 0.2).union(sg.box(0, 0.5, 1, 0.7)))
    lo, hi = two.corners().min(axis=0), two.corners().max(axis=0)
    assert np.allclose(lo, [0, 0, 0.9]) and np.allclose(hi, [1, 0.7, 0.9])
