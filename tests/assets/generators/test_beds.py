"""Beds and bunk beds: mattress surfaces, sizes, under-bed drawers, the bunk's guard and
ladder, beyond the generic contract in test_generators.py."""
from __future__ import annotations

import numpy as np
import pytest
import trimesh

from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from support.assetcheck import (
    TOL,
    assert_furniture_tags,
    assert_on_mesh,
    build,
    make,
    point_inside,
    support_surfaces,
)


@pytest.mark.parametrize("name,must,must_not", [
    ("bed", {S.Bed}, {S.BunkBed}),
    ("bunk_bed", {S.Bed, S.BunkBed}, set()),
])
def test_tags(name, must, must_not):
    assert_furniture_tags(name, must, must_not)


@pytest.mark.parametrize("frame", ["panel", "slatted", "platform", "upholstered"])
@pytest.mark.parametrize("blanket", ["spread", "folded", "none"])
def test_bed_mattress_surface(frame, blanket):
    f, p, a = make("bed", 6, frame_style=frame, blanket=blanket)
    top = p["frame_height"] - 0.06 + p["mattress_thickness"]
    m = a.surface("mattress")
    assert m.subpart == Subpart.SupportSurface
    expect = top + (0.015 if blanket == "spread" else 0.0)
    assert abs(m.origin[2] - expect) < TOL
    assert_on_mesh(a, m)
    if blanket == "folded":
        assert_on_mesh(a, a.surface("blanket"))
    # the headboard stands headboard_height above the mattress, against the back
    assert a.extents[2] >= top + p["headboard_height"] - TOL
    assert m.corners()[:, 0].min() > -a.extents[0] / 2 + 0.3  # pillows between it and the head


@pytest.mark.parametrize("size,width", [("single", 0.9), ("double", 1.4), ("queen", 1.6),
                                        ("king", 1.8)])
def test_bed_sizes(size, width):
    f, p, a = make("bed", 3, size=size, frame_style="panel")
    assert width + 0.05 < a.extents[1] < width + 0.2
    assert 1.95 < a.extents[0] < 2.3


@pytest.mark.parametrize("frame", ["panel", "slatted", "platform", "upholstered"])
def test_bed_drawers_slide_out_sideways(frame):
    f, p, a = make("bed", 8, frame_style=frame, drawers=True, blanket="spread")
    assert len(a.joints) == 4
    sides = []
    for j in a.joints:
        assert j.kind == "prismatic" and abs(abs(j.axis[1]) - 1) < 1e-9
        assert j.upper > 0.2
        child = a.link_mesh(j.child)
        opened = trimesh.transform_points(child.vertices, j.transform(j.upper))
        # it leaves the bed's footprint, below the mattress
        assert np.abs(opened[:, 1]).max() > a.extents[1] / 2 + 0.15
        assert child.bounds[1][2] < p["frame_height"] - 0.06
        sides.append(np.sign(j.axis[1]))
    assert sorted(sides) == [-1, -1, 1, 1]


def test_bed_without_drawers_is_one_shell():
    f, p, a = make("bed", 8, drawers=False)
    assert a.joints == [] and a.links == ["base"] and a.mesh.body_count == 1


@pytest.mark.parametrize("seed", range(4))
def test_bunk_bed_two_mattresses(seed):
    f, p, _, a = build("bunk_bed", seed)
    sup = support_surfaces(a)
    lo, hi = sup["mattress_lower"], sup["mattress_upper"]
    assert abs(hi.origin[2] - lo.origin[2] - (p["upper_height"] - p["lower_height"])) < TOL
    assert abs(lo.origin[2] - (p["lower_height"] + p["mattress_thickness"])) < TOL
    for s in (lo, hi):
        assert_on_mesh(a, s)
    # guard rails stand guard_height above the upper mattress
    assert abs(a.extents[2] - (hi.origin[2] + p["guard_height"])) < TOL
    # the ladder: at the front (+X) of its side's end, from the floor up to the upper deck
    v = a.mesh.vertices
    sign = 1.0 if p["ladder_side"] == "left" else -1.0
    x_front = a.mesh.bounds[1][0] - (0.35 if p["ladder_style"] == "angled" else 0.0)
    y = sign * v[:, 1]
    ladder = v[(v[:, 0] > x_front - 0.02) & (y > p["mattress_length"] / 2 - 0.5) &
               (y < p["mattress_length"] / 2 - 0.04)]
    assert ladder[:, 2].min() < 1e-6 and ladder[:, 2].max() > p["upper_height"]


def test_bunk_bed_guard_open_at_the_ladder():
    f, p, a = make("bunk_bed", 1, ladder_side="left", ladder_style="vertical", post_thickness=0.08)
    z = a.extents[2] - 0.045  # through the guard's top rail
    x = p["mattress_width"] / 2 + 0.01 + 0.015  # in the front guard's plane (frame symmetric in X)
    yl = p["mattress_length"] / 2 - 0.25
    back = -x
    inside = point_inside(a, [(x, yl, z), (x, -yl, z), (back, yl, z), (back, -yl, z)])
    assert list(inside) == [False, True, True, True]  # open by the ladder only
