"""Seating: what is specific to chairs, stools, sofas and benches beyond the generic contract
in test_generators.py (which runs on these generators too)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from indoorgen.model.tags import Semantics as S
from support.assetcheck import (
    TOL,
    assert_furniture_tags,
    assert_on_mesh,
    make,
    point_inside,
    support_surfaces,
)


@pytest.mark.parametrize("name,must,must_not", [
    ("side_chair", {S.Seating, S.Chair, S.SideChair}, {S.DiningChair}),
    ("upholstered_chair", {S.Seating, S.Chair, S.UpholsteredChair}, set()),
    ("office_chair", {S.Seating, S.Chair, S.OfficeChair}, set()),
    ("bar_stool", {S.Seating, S.Stool, S.BarStool}, {S.Chair}),
    ("stool", {S.Seating, S.Stool}, {S.Chair, S.BarStool}),
    ("sofa_l_shaped", {S.Seating, S.Sofa, S.SectionalSofa}, set()),
    ("bench", {S.Seating, S.Bench}, {S.Chair}),
])
def test_tags(name, must, must_not):
    assert_furniture_tags(name, must, must_not)


@pytest.mark.parametrize("style", ["windsor", "bentwood", "cantilever", "shell"])
def test_side_chair_styles_seat(style):
    f, p, a = make("side_chair", 3, style=style)
    seat = a.surface("seat")
    assert abs(seat.origin[2] - p["seat_height"]) < TOL
    assert_on_mesh(a, seat)
    assert a.mesh.is_watertight and a.mesh.body_count == 1
    # the back rises above the seat by its height
    assert a.extents[2] >= p["seat_height"] + p["back_height"] - 0.03


def test_cantilever_has_no_back_legs():
    """A cantilever chair stands on its runners only: nothing holds up the rear of the seat
    between the floor tubes and the seat rails, where a Windsor chair has its back legs."""
    def rear_support(style):
        _, p, a = make("side_chair", 5, style=style)
        x_rear = a.mesh.bounds[0][0] + 0.35 * a.extents[0]
        n = 0
        for z in np.linspace(0.08, p["seat_height"] - 0.1, 4):  # horizontal sections
            cut = a.mesh.section(plane_origin=(0, 0, z), plane_normal=(0, 0, 1))
            if cut is not None:
                n += int((cut.vertices[:, 0] < x_rear).sum())
        return n

    assert rear_support("cantilever") == 0
    assert rear_support("windsor") > 0


@pytest.mark.parametrize("arms,extra", [("none", 0.0), ("padded", 0.16)])
def test_upholstered_chair_arms_widen_it(arms, extra):
    f, p, a = make("upholstered_chair", 1, arms=arms)
    assert abs(a.extents[1] - (p["seat_width"] + extra)) < 0.01
    seat = a.surface("seat")
    assert abs(seat.origin[2] - p["seat_height"]) < TOL
    assert_on_mesh(a, seat)


def test_office_chair_swivels_about_its_column():
    f, p, a = make("office_chair", 2, armrests=True, headrest=True)
    (j,) = a.joints
    assert j.kind == "revolute" and np.allclose(j.axis, (0, 0, 1))
    # the axis runs up the gas spring: the top of the base link is the column's round end
    base = a.link_mesh("base")
    cut = base.section(plane_origin=(0, 0, base.bounds[1][2] - 0.005), plane_normal=(0, 0, 1))
    assert np.allclose(cut.vertices[:, :2].mean(axis=0), j.origin[:2], atol=TOL)
    assert np.linalg.norm(cut.vertices[:, :2] - j.origin[:2], axis=1).max() < 0.03
    assert j.lower <= -math.pi + 1e-9 and j.upper >= math.pi - 1e-9
    seat = a.link_mesh("seat")
    # the base stands on five casters, the seat link is above the gas spring
    assert base.bounds[0][2] < 1e-6 and seat.bounds[0][2] > 0.15
    feet = base.vertices[base.vertices[:, 2] < 1e-6] - j.origin
    ang = np.degrees(np.arctan2(feet[:, 1], feet[:, 0]))
    assert len(np.unique(np.round((ang - 36.0) / 72.0) % 5)) == 5  # casters every 72 degrees
    # turned half a turn, the back (at -X) comes round to +X
    posed = a.posed({"swivel": math.pi})
    back_x = seat.vertices[seat.vertices[:, 2] > p["seat_height"] + 0.1][:, 0].mean()
    idx = np.unique(a.mesh.faces[a.link_faces("seat")])
    moved = posed.vertices[idx]
    moved_back_x = moved[moved[:, 2] > p["seat_height"] + 0.1][:, 0].mean()
    assert back_x < -0.1 and moved_back_x > 0.1
    assert abs(a.surface("seat").origin[2] - p["seat_height"]) < TOL


@pytest.mark.parametrize("base", ["legs4", "legs3", "pedestal"])
def test_bar_stool_seat_and_footrest(base):
    f, p, a = make("bar_stool", 4, base_style=base, back=False)
    seat = a.surface("seat")
    assert p["seat_height"] >= 0.6 and abs(seat.origin[2] - p["seat_height"]) < TOL
    assert_on_mesh(a, seat)
    # a footrest ring at its height, well outside the legs' / column's centre
    v = a.mesh.vertices
    ring = v[np.abs(v[:, 2] - p["footrest_height"]) < 0.012]
    assert np.hypot(ring[:, 0], ring[:, 1]).max() > 0.1


def test_bar_stool_back_keeps_seat_clear():
    f, p, a = make("bar_stool", 2, back=True, seat_shape="round")
    assert a.extents[2] > p["seat_height"] + p["back_height"] - 0.02
    assert_on_mesh(a, a.surface("seat"))


@pytest.mark.parametrize("style", ["legged", "ottoman", "pouf"])
@pytest.mark.parametrize("shape", ["round", "square"])
def test_stool_family(style, shape):
    f, p, a = make("stool", 1, style=style, shape=shape, tufted=True)
    seat = a.surface("seat")
    assert abs(seat.origin[2] - p["height"]) < TOL
    assert_on_mesh(a, seat)
    if style != "legged":  # buttons stand proud of the top; the surface leaves them out
        assert seat.polygon.interiors
        assert p["height"] + 0.002 < a.extents[2] < p["height"] + 0.006
    else:
        assert abs(a.extents[2] - p["height"]) < TOL
    low = a.mesh.vertices[a.mesh.vertices[:, 2] < 1e-6]
    if style == "pouf":  # sits on the floor on its whole base
        assert np.ptp(low[:, 0]) > 0.5 * p["size"]


@pytest.mark.parametrize("side,sign", [("left", 1.0), ("right", -1.0)])
def test_sofa_l_shaped_chaise_side(side, sign):
    f, p, a = make("sofa_l_shaped", 0, chaise_side=side, n_cushions=3)
    sup = support_surfaces(a)
    seats = [sup[f"seat_{i}"] for i in range(3)]
    chaise = sup["chaise"]
    for s in seats + [chaise]:
        assert abs(s.origin[2] - p["seat_height"]) < TOL
        assert_on_mesh(a, s)
    assert np.sign(chaise.origin[1]) == sign
    assert chaise.corners()[:, 0].max() > max(s.corners()[:, 0].max() for s in seats) + 0.3
    # an L: the chaise fills the front corner on its side, the other front corner is empty
    L, W = a.extents[0], a.extents[1]
    probe = lambda s: (L / 2 - 0.08, s * (W / 2 - 0.15), p["seat_height"] - 0.05)  # noqa: E731
    assert point_inside(a, [probe(sign)])[0]
    assert not point_inside(a, [probe(-sign)])[0]


@pytest.mark.parametrize("style,back", [("slatted", False), ("slatted", True), ("solid", True),
                                        ("upholstered", False)])
def test_bench_seat_surfaces(style, back):
    f, p, a = make("bench", 2, style=style, back=back, n_slats=5)
    sup = support_surfaces(a)
    if style == "slatted":  # one surface per slat, those under the back left out
        assert all(n.startswith("seat_") for n in sup)
        assert len(sup) == 5 if not back else 3 <= len(sup) <= 5
    else:
        assert list(sup) == ["seat"]
    if back:  # clear of the back posts standing on the seat's rear
        x_rear = a.mesh.bounds[1][0] - p["depth"]
        assert min(s.corners()[:, 0].min() for s in sup.values()) > x_rear + 0.06
    for s in sup.values():
        assert abs(s.origin[2] - p["seat_height"]) < TOL
        assert_on_mesh(a, s)
