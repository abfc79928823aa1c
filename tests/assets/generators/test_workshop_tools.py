"""Workshop tools (generators/workshop/tools.py): the toolbox's hinged lid and handle, the paint
tin's bail, lid and underside, beyond the generic contract in test_generators.py."""
from __future__ import annotations

import math

import numpy as np
import pytest

from indoorgen.assets.catalogue import factories_with, get_factory
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import (
    TOL,
    assert_clean_variant,
    build,
    choice_cases,
    make,
    support_surfaces,
    surface_gap,
)
from support.generatorcheck import check_material_choices, check_small_objects, design_offset, first_hit_down

NAMES = ["toolbox", "paint_can"]
SEEDS = range(6)


def test_tags():
    check_small_objects(NAMES)
    check_material_choices(NAMES)
    assert {Semantics.Container, Semantics.Toolbox} <= get_factory("toolbox").tags
    assert {Semantics.Container, Semantics.PaintCan} <= get_factory("paint_can").tags
    assert factories_with([Semantics.Toolbox]) == ["toolbox"]
    assert factories_with([Semantics.PaintCan]) == ["paint_can"]
    # painted steel is the common metal toolbox; a tin's label is paper more often than not
    metal = get_factory("toolbox").material_choices["metal"]
    assert max(metal, key=metal.get) == "painted_metal"
    label = get_factory("paint_can").material_choices["label"]
    assert max(label, key=label.get) == "paper"


@pytest.mark.parametrize("name,key,value", choice_cases(NAMES))
def test_every_style_builds_clean(name, key, value):
    assert_clean_variant(name, key, value)


# ----------------------------------------------------------------------------------- toolbox
@pytest.mark.parametrize("seed", SEEDS)
def test_toolbox_extents(seed):
    f, p, _, a = build("toolbox", seed)
    d, w, h = a.extents
    assert abs(d - (p["depth"] + f.LATCH_T)) < TOL  # the latches stand proud of the front
    assert abs(w - p["length"]) < TOL
    assert abs(h - (p["height"] + p["handle_height"] + f.GRIP_R)) < TOL
    assert 0.15 <= d - f.LATCH_T <= 0.25 and 0.3 <= w <= 0.6
    # the lid's top is at `height`: the body (box and latch plates) stays below it
    assert a.link_mesh("base").bounds[1][2] < p["height"] - p["lid_frac"] * p["height"]


@pytest.mark.parametrize("style", ["metal", "plastic"])
@pytest.mark.parametrize("seed", range(4))
def test_toolbox_lid_hinges_at_the_back_and_opens_clear(style, seed):
    f, p, a = make("toolbox", seed, style=style)
    (j,) = a.joints
    assert j.kind == "revolute" and j.child == "lid" and j.parent == "base"
    assert abs(abs(j.axis[1]) - 1.0) < 1e-9 and math.radians(100) <= j.upper <= math.radians(110)
    body, lid = a.link_mesh("base"), a.link_mesh("lid")
    back, rim = body.bounds[0][0], body.bounds[1][2]
    # the hinge runs along the back edge of the rim
    assert abs(j.origin[0] - back) < TOL and 0.0 <= j.origin[2] - rim < 0.005
    # the handle is on the lid: the lid is the top of the closed toolbox
    assert abs(lid.bounds[1][2] - a.mesh.bounds[1][2]) < 1e-9
    front = lid.vertices[:, 0] > lid.bounds[1][0] - 0.01  # the lid's front edge
    half = lid.copy()
    half.apply_transform(j.transform(j.upper / 2))
    assert half.vertices[front, 2].min() > lid.vertices[front, 2].min() + 0.05  # swung up
    opened = lid.copy()
    opened.apply_transform(j.transform(j.upper))
    # fully open, the whole lid (handle and catches too) has gone over behind the back edge,
    # above the floor, and the front edge moved up and back
    assert opened.bounds[1][0] <= back + TOL
    assert opened.bounds[0][2] > 0.0
    assert opened.vertices[front, 0].max() < lid.vertices[front, 0].min() - p["depth"]
    assert opened.vertices[front, 2].min() > rim
    # the box stands open: a ray down its middle reaches its floor
    posed = a.posed({j.name: j.upper})
    c = body.bounds.mean(axis=0)
    assert abs(first_hit_down(posed, c[0], c[1]) - p["wall_thickness"]) < TOL
    # shut, the lid covers the box: the same ray meets the grip first
    assert first_hit_down(a.mesh, c[0], c[1]) > rim


@pytest.mark.parametrize("seed", SEEDS)
def test_toolbox_underside_and_no_top_support(seed):
    f, p, _, a = build("toolbox", seed)
    bottom = a.surface("bottom")
    assert bottom.subpart == Subpart.Bottom and surface_gap(a, bottom) < TOL
    x0, y0, x1, y1 = bottom.polygon.bounds
    scale = p["taper"] if p["style"] == "plastic" else 1.0
    assert abs((x1 - x0) - scale * p["depth"]) < 0.002 and abs((y1 - y0) - scale * p["length"]) < 0.002
    assert not support_surfaces(a)  # the handle stands on the lid: nothing is put there
    assert a.surface("top").subpart == Subpart.Top


def test_plastic_toolbox_tapers():
    f, p, a = make("toolbox", 0, style="plastic", taper=0.9)
    body = a.link_mesh("base")
    low = body.vertices[body.vertices[:, 2] < 1e-6]
    assert np.ptp(low[:, 1]) < 0.91 * p["length"]  # the foot is smaller than the rim


# ---------------------------------------------------------------------------------- paint can
def _axis(f, p) -> np.ndarray:
    """The can's axis (x, y) in the asset frame."""
    return design_offset(f, p)[:2]


@pytest.mark.parametrize("seed", SEEDS)
def test_paint_can_extents(seed):
    f, p, _, a = build("paint_can", seed)
    d, w, h = a.extents
    R, wire = p["radius"], p["wire_radius"]
    ears = R + f.EAR + wire + 0.0015
    assert abs(w - 2 * ears) < TOL  # the ear lugs are the widest part
    assert 2 * 0.05 < d <= 2 * ears + TOL
    if p["bail_up"]:
        assert abs(h - (p["height"] - p["rim_height"] - f.EAR_HALF[1] + R + f.EAR + wire)) < TOL
        assert h > p["height"] + 0.01
    else:
        assert abs(h - p["height"]) < TOL
    assert 0.08 <= p["height"] <= 0.25 and 0.05 <= R <= 0.12


@pytest.mark.parametrize("seed", range(4))
def test_folded_bail_stays_in_the_footprint(seed):
    f, p, a = make("paint_can", seed, bail_up=False)
    R, wire = p["radius"], p["wire_radius"]
    ears = R + f.EAR + wire + 0.0015
    # in plan nothing reaches further from the axis than the ear lugs do
    rel = a.mesh.vertices[:, :2] - _axis(f, p)
    assert np.abs(rel).max() <= ears + 1e-6
    assert a.mesh.bounds[1][2] <= p["height"] + 1e-6  # nothing over the rim
    # the bail is there: wire round the front, clear of the wall, at the ears' height
    bail = np.asarray(f.bail(p).to_mesh().vert_properties)[:, :3] + design_offset(f, p)
    rb = np.linalg.norm(bail[:, :2] - _axis(f, p), axis=1)
    assert rb.min() > R + f.CHIME and rb.max() <= R + f.EAR + wire + 1e-6
    assert bail[:, 2].max() < p["height"] - p["rim_height"]
    assert np.ptp(bail[:, 0]) > R  # it reaches round the front, not just the ears
    r = np.linalg.norm(rel, axis=1)
    front = a.mesh.vertices[r > R + f.CHIME + 0.002]
    assert len(front) and front[:, 0].max() > _axis(f, p)[0] + R


@pytest.mark.parametrize("seed", range(4))
def test_bail_up_stands_over_the_lid(seed):
    f, p, a = make("paint_can", seed, bail_up=True)
    cx, cy = _axis(f, p)
    assert first_hit_down(a.mesh, cx, cy) > p["height"] + 0.01  # the wire is above the lid
    assert not support_surfaces(a)  # the bail crosses the lid: nothing stands there


@pytest.mark.parametrize("seed", SEEDS)
def test_paint_can_bottom_and_lid(seed):
    f, p, _, a = build("paint_can", seed)
    bottom = a.surface("bottom")
    assert bottom.subpart == Subpart.Bottom and surface_gap(a, bottom) < TOL
    assert f.bottom_is_solid(p)
    x0, y0, x1, y1 = bottom.polygon.bounds
    assert abs((x1 - x0) / 2 - (p["radius"] + f.CHIME)) < 0.002
    assert np.allclose(bottom.origin[:2], _axis(f, p), atol=1e-9)  # centred on the can
    if p["bail_up"]:
        return
    top = a.surface("top")
    assert top.subpart == Subpart.SupportSurface and surface_gap(a, top) < TOL
    # on the lid pressed in below the rim, inside it
    assert abs(top.origin[2] - (p["height"] - p["lid_recess"])) < 1e-9
    assert top.polygon.bounds[2] < p["radius"] - f.RIM_W
