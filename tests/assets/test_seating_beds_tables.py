"""Seating, beds and tables: what is specific to each family, beyond the generic contract in
test_generators.py (which runs on these generators too)."""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
import pytest
import trimesh

from indoorgen.assets.registry import get_factory
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from support.assetcheck import build, distances, sample_polygon

TOL = 1e-3


@lru_cache(maxsize=None)
def _make(name: str, seed: int, **over):
    f = get_factory(name)
    p = f.sample_params(np.random.default_rng(seed))
    p.update(over)
    return f, p, f.create(p)


def make(name: str, seed: int = 0, **over):
    return _make(name, seed, **over)


def assert_on_mesh(asset, surface):
    pts = surface.to_world(sample_polygon(surface.polygon))
    assert len(pts) >= 3
    assert distances(asset.mesh, pts).max() < TOL, surface.name


def supports(asset):
    return {s.name: s for s in asset.surfaces if s.subpart == Subpart.SupportSurface}


def point_inside(asset, pts) -> np.ndarray:
    return asset.mesh.contains(np.atleast_2d(np.asarray(pts, float)))


# ------------------------------------------------------------------------------------ tags
@pytest.mark.parametrize("name,must,must_not", [
    ("side_chair", {S.Seating, S.Chair, S.SideChair}, {S.DiningChair}),
    ("upholstered_chair", {S.Seating, S.Chair, S.UpholsteredChair}, set()),
    ("office_chair", {S.Seating, S.Chair, S.OfficeChair}, set()),
    ("bar_stool", {S.Seating, S.Stool, S.BarStool}, {S.Chair}),
    ("stool", {S.Seating, S.Stool}, {S.Chair, S.BarStool}),
    ("sofa_l_shaped", {S.Seating, S.Sofa, S.SectionalSofa}, set()),
    ("bench", {S.Seating, S.Bench}, {S.Chair}),
    ("bed", {S.Bed}, {S.BunkBed}),
    ("bunk_bed", {S.Bed, S.BunkBed}, set()),
    ("dining_table_oval", {S.Table, S.DiningTable}, set()),
    ("desk", {S.Table, S.Desk}, {S.DiningTable}),
    ("console_table", {S.Table, S.ConsoleTable}, {S.DiningTable}),
])
def test_tags(name, must, must_not):
    tags = get_factory(name).tags
    assert {S.Object, S.Furniture} | must <= tags
    assert not (must_not & tags)
    assert get_factory(name).size_class == "large"


# ------------------------------------------------------------------------------------ seating
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
    sup = supports(a)
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
    sup = supports(a)
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


# ------------------------------------------------------------------------------------- beds
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
    sup = supports(a)
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


# ------------------------------------------------------------------------------------ tables
@pytest.mark.parametrize("seed", range(6))
def test_oval_table_sides_tangent(seed):
    f, p, _, a = build("dining_table_oval", seed)
    sides = [s for s in a.surfaces if s.name.startswith("side_") and s.name[5:].isdigit()]
    n = len(sides)
    assert n >= 4 and n % 2 == 0 and [s.name for s in sides] == [f"side_{i}" for i in range(n)]
    w, l, h = a.extents
    assert abs(w - p["width"]) < TOL and abs(l - p["length"]) < TOL
    top_z = a.mesh.vertices[:, 2] > h - p["top_thickness"] - 1e-6
    rim = a.mesh.vertices[top_z]
    for s in sides:
        assert s.subpart == Subpart.Side and abs(s.normal[2]) < 1e-9
        c = s.corners()
        assert abs(c[:, 2].min()) < 1e-9 and abs(c[:, 2].max() - h) < TOL
        # a tangent plane: the top reaches it (within a facet's chord) and never passes it
        reach = (rim @ s.normal).max()
        assert reach <= s.origin @ s.normal + TOL
        assert reach >= s.origin @ s.normal - 0.005
        assert s.polygon.bounds[2] - s.polygon.bounds[0] >= 0.45
    assert_on_mesh(a, a.surface("top"))
    # facets face every way round
    ang = sorted(np.degrees(np.arctan2(s.normal[1], s.normal[0])) % 360 for s in sides)
    assert max(np.diff(ang + [ang[0] + 360])) < 120


@pytest.mark.parametrize("base", ["legs", "single_pedestal", "double_pedestal"])
def test_desk_drawers_and_top(base):
    f, p, a = make("desk", 2, base_style=base, width=1.6, pedestal_width=0.4, n_drawers=3,
                   center_drawer=True, hutch=True)
    peds = {"legs": 0, "single_pedestal": 1, "double_pedestal": 2}[base]
    assert len(a.joints) == 3 * peds + 1
    for j in a.joints:
        assert j.kind == "prismatic" and np.allclose(j.axis, (1, 0, 0)) and j.upper > 0.15
    top, hutch = a.surface("top"), a.surface("hutch_top")
    assert abs(top.origin[2] - p["height"]) < TOL
    assert abs(hutch.origin[2] - p["height"] - p["hutch_height"]) < TOL
    assert_on_mesh(a, top)
    assert_on_mesh(a, hutch)
    front = a.surface("side_0")
    assert front.subpart == Subpart.Side and np.allclose(front.normal, (1, 0, 0))
    assert abs(front.origin[0] - a.extents[0] / 2) < TOL
    # knee space: nothing between the supports under the top, where the pedestals are solid
    side = 1.0 if p["pedestal_side"] == "left" else -1.0
    yk = -side * p["pedestal_width"] / 2 if base == "single_pedestal" else 0.0
    assert not point_inside(a, [(0.0, yk, 0.3)])[0]
    yp = 0.8 - p["pedestal_width"] / 2  # pedestals' centres (width 1.6): drawers stacked there
    for j in a.joints:
        c = a.link_mesh(j.child).bounds.mean(axis=0)
        if j.child.startswith("c_"):
            assert abs(c[1] - yk) < 0.05 and c[2] > p["height"] - 0.15
        else:
            assert abs(abs(c[1]) - yp) < 0.02
            assert base == "double_pedestal" or np.sign(c[1]) == side


def test_narrow_double_pedestal_desk_keeps_knee_space():
    f, p, a = make("desk", 0, base_style="double_pedestal", width=1.0, pedestal_width=0.45)
    assert len([j for j in a.joints if j.child.startswith("p1_")]) == 0  # one pedestal only


@pytest.mark.parametrize("legs_style", ["straight", "round", "panel"])
@pytest.mark.parametrize("n", [0, 2])
def test_console_table(legs_style, n):
    f, p, a = make("console_table", 3, leg_style=legs_style, n_drawers=n, lower_shelf=True)
    assert len(a.joints) == n
    assert all(np.allclose(j.axis, (1, 0, 0)) for j in a.joints)
    assert abs(a.surface("top").origin[2] - p["height"]) < TOL
    shelf = a.surface("shelf")
    assert abs(shelf.origin[2] - p["shelf_height"]) < TOL
    assert_on_mesh(a, shelf)
    assert a.extents[0] <= 0.45 + TOL  # a console is narrow
