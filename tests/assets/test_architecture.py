"""Doors, windows, staircases and railings: what the generic contract cannot know about them
(openings in the wall plane, leaves swinging into +X, sashes opening outward, uniform risers,
goings, landings and balustrade dimensions)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from indoorgen.assets.base import get_factory
from indoorgen.assets.shapes.architectural import opening_size
from indoorgen.assets.generators.stairs import RISER_MAX, RISER_MIN, riser_count
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import build, make

DOORS = ["interior_door", "sliding_door", "exterior_door"]
WINDOWS = ["window", "bay_window"]
OPENINGS = DOORS + WINDOWS
ALL = OPENINGS + ["staircase", "stair_railing"]
SEEDS = range(8)
TOL = 1e-3


def link_vertices(asset, link: str, values: dict | None = None) -> np.ndarray:
    """The vertices of one link, posed with joint `values` (closed when None)."""
    mesh = asset.posed(values or {})
    return mesh.vertices[np.unique(mesh.faces[asset.link_faces(link)])]


# ------------------------------------------------------------------------------ declarations
def test_tags():
    for name in ALL:
        f = get_factory(name)
        assert {Semantics.Object, Semantics.Architecture} <= f.tags and f.size_class == "large"
    for name in DOORS:
        assert Semantics.Door in get_factory(name).tags
    assert Semantics.InteriorDoor in get_factory("interior_door").tags
    assert Semantics.InteriorDoor in get_factory("sliding_door").tags
    assert Semantics.ExteriorDoor in get_factory("exterior_door").tags
    for name in WINDOWS:
        assert Semantics.Window in get_factory(name).tags
    assert Semantics.Staircase in get_factory("staircase").tags
    assert Semantics.Railing in get_factory("stair_railing").tags


# ----------------------------------------------------------------------------- openings
@pytest.mark.parametrize("name,seed", [(n, s) for n in OPENINGS for s in SEEDS])
def test_opening_surface_is_the_rough_opening(name, seed):
    """`opening` is the rectangle opening_size() gives, standing on z=0 in the wall's centre
    plane: the lining (or jambs) reach exactly the wall's two faces, half the wall thickness
    either side of it, within the opening."""
    f, p, ph, a = build(name, seed)
    s = a.surface("opening")
    assert s.subpart == Subpart.Wall and np.allclose(s.normal, (1, 0, 0)) and np.allclose(s.u, (0, 1, 0))
    x0, y0, x1, y1 = s.polygon.bounds
    w, h = opening_size(p)
    assert abs((x1 - x0) - w) < 1e-9 and abs((y1 - y0) - h) < 1e-9
    assert abs(s.corners()[:, 2].min()) < 1e-9
    assert np.allclose(ph.surface("opening").origin, s.origin)
    ox, oy = s.origin[0], s.origin[1]
    v = a.link_mesh("base").vertices
    inside = np.abs(v[:, 1] - oy) < w / 2 + 1e-6
    for face in (-1, 1):
        assert (np.abs(v[inside, 0] - (ox + face * p["wall_thickness"] / 2)) < 1e-6).any(), face
    if name in ("interior_door", "exterior_door", "window"):
        assert abs(ox) < TOL  # symmetric: the origin is on the wall's centre plane


def test_opening_size_adds_side_lites():
    base = {"width": 0.9, "height": 2.1}
    assert opening_size(base) == (0.9, 2.1)
    assert opening_size({**base, "sidelites": "both", "sidelite_width": 0.3}) == pytest.approx((1.5, 2.1))
    assert opening_size({**base, "sidelites": "left", "sidelite_width": 0.3}) == pytest.approx((1.2, 2.1))


@pytest.mark.parametrize("name,seed", [(n, s) for n in ("interior_door", "exterior_door") for s in SEEDS])
def test_hinged_leaf_swings_into_plus_x(name, seed):
    """The leaf sits in the opening with a handle on both faces (reaching equally far), and
    its joint turns it 90-100 degrees into +X about its hinge edge."""
    _, p, _, a = build(name, seed)
    (j,) = a.joints
    assert j.kind == "revolute" and j.child == "leaf" and math.radians(90) <= j.upper <= math.radians(100)
    s = a.surface("opening")
    half = s.polygon.bounds[2]
    closed = link_vertices(a, "leaf")
    lo, hi = closed.min(axis=0), closed.max(axis=0)
    assert s.origin[1] - half < lo[1] and hi[1] < s.origin[1] + half  # within the opening
    assert abs((lo[0] + hi[0]) / 2 - s.origin[0]) < TOL  # handles on both faces, symmetric
    assert hi[0] - s.origin[0] > p["leaf_thickness"] / 2 + 0.05
    # a vertical axis along the leaf's +X hinge edge
    assert abs(abs(j.axis[2]) - 1) < 1e-9
    assert np.linalg.norm(closed[:, :2] - j.origin[:2], axis=1).min() < 0.004  # eased corner
    opened = link_vertices(a, "leaf", {j.name: math.pi / 2})
    width = hi[1] - lo[1]
    assert opened[:, 0].max() > s.origin[0] + 0.8 * width  # swung out into +X
    assert opened[:, 1].max() - opened[:, 1].min() < 0.25  # now edge-on to the wall


@pytest.mark.parametrize("seed", SEEDS)
def test_sliding_door_clears_the_opening(seed):
    """The leaf hangs on the +X face and slides along Y far enough to clear the opening."""
    _, p, _, a = build("sliding_door", seed)
    (j,) = a.joints
    assert j.kind == "prismatic" and abs(abs(j.axis[1]) - 1) < 1e-9
    s = a.surface("opening")
    closed = link_vertices(a, "leaf")
    assert closed[:, 0].min() > s.origin[0] + p["wall_thickness"] / 2  # in front of the wall
    oy0, oy1 = s.origin[1] - p["width"] / 2, s.origin[1] + p["width"] / 2
    assert closed[:, 1].min() < oy0 and closed[:, 1].max() > oy1  # covers it when shut
    opened = link_vertices(a, "leaf", {j.name: j.upper})
    lo, hi = opened[:, 1].min(), opened[:, 1].max()
    assert hi < oy0 + 0.03 or lo > oy1 - 0.03  # leaves the opening clear


# ------------------------------------------------------------------------------- windows
@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("style", ["casement", "awning", "sliding", "fixed"])
def test_window_sashes(style, seed):
    """Hinged sashes open outward (-X); sliding sashes move along Y only; fixed windows have
    no joints. Every pane is a thin glass solid in the wall's plane."""
    _, p, a = make("window", seed, style=style)
    if style == "fixed":
        assert not a.joints
    else:
        assert a.joints
    for j in a.joints:
        closed = link_vertices(a, j.child)
        opened = link_vertices(a, j.child, {j.name: j.upper})
        if style == "sliding":
            assert j.kind == "prismatic" and abs(abs(j.axis[1]) - 1) < 1e-9
            assert np.allclose(opened[:, [0, 2]], closed[:, [0, 2]])
        else:
            assert j.kind == "revolute"
            assert opened[:, 0].min() < closed[:, 0].min() - 0.1  # out, not into the room
    glass = a.slots.index("glass")
    for link in a.links:
        faces = a.link_faces(link)
        pane = a.mesh.vertices[np.unique(a.mesh.faces[faces[a.face_slots[faces] == glass]])]
        if len(pane):
            assert np.ptp(pane[:, 0]) < 0.01


@pytest.mark.parametrize("seed", SEEDS)
def test_window_sill_projects_into_the_room(seed):
    _, p, _, a = build("window", seed)
    sill = a.surface("sill")
    assert sill.subpart == Subpart.SupportSurface and np.allclose(sill.normal, (0, 0, 1))
    x_max = sill.corners()[:, 0].max()
    assert x_max > a.surface("opening").origin[0] + p["wall_thickness"] / 2
    assert 0.0 < sill.origin[2] < 0.05


@pytest.mark.parametrize("seed", SEEDS)
def test_bay_window_projects_outside_with_a_seat(seed):
    _, p, _, a = build("bay_window", seed)
    ox = a.surface("opening").origin[0]
    wall_out = ox - p["wall_thickness"] / 2
    assert a.mesh.bounds[0][0] < wall_out - 0.3  # the bay sticks out to -X
    seat = a.surface("seat")
    assert seat.subpart == Subpart.SupportSurface
    xs = seat.corners()[:, 0]
    assert xs.min() < wall_out - 0.15 and seat.polygon.area > 0.3


# ----------------------------------------------------------------------------- staircases
def _levels(a) -> np.ndarray:
    return np.array(sorted(s.origin[2] for s in a.surfaces
                           if s.name.startswith(("tread_", "landing_"))))


def test_riser_count_keeps_risers_in_range():
    for rise in np.linspace(2.4, 3.6, 25):
        for target in (0.16, 0.175, 0.19):
            r = rise / riser_count(rise, target)
            assert RISER_MIN - 1e-9 <= r <= RISER_MAX + 1e-9


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("style", ["straight", "l_shaped", "u_shaped", "spiral"])
def test_staircase_risers_uniform(style, seed):
    """Treads and landings rise by one uniform riser of 0.15-0.20 m from the floor, the last
    one a riser below the total rise; landings take the place of a tread."""
    _, p, a = make("staircase", seed, style=style)
    z = _levels(a)
    steps = np.diff(np.r_[0.0, z, p["total_rise"]])
    r = steps[0]
    assert RISER_MIN - 1e-9 <= r <= RISER_MAX + 1e-9
    assert np.allclose(steps, r, atol=1e-9)
    treads = [s for s in a.surfaces if s.name.startswith("tread_")]
    landings = [s for s in a.surfaces if s.name.startswith("landing_")]
    assert len(landings) == (1 if style in ("l_shaped", "u_shaped") else 0)
    assert all(s.subpart == Subpart.SupportSurface for s in treads + landings)
    assert [s.name for s in treads] == [f"tread_{i}" for i in range(len(treads))]


@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("style", ["straight", "l_shaped", "u_shaped", "spiral"])
def test_staircase_going(style, seed):
    """Consecutive treads of a flight are one going (0.22-0.32 m) apart: along +X for the
    first flight, +-Y after an L landing, -X after a U landing; round the column (at the
    walking line) for a spiral."""
    f, p, a = make("staircase", seed, style=style)
    go = p["going"]
    assert 0.22 <= go <= 0.32
    treads = sorted((s for s in a.surfaces if s.name.startswith("tread_")), key=lambda s: s.origin[2])
    if style == "spiral":
        q = f._spiral_g(f._g(f.resolve(p)))
        angles = np.unwrap([math.atan2(s.u[1], s.u[0]) for s in treads])
        assert np.allclose(np.abs(np.diff(angles)) * q["rw"], go)
        return
    c = np.array([s.origin for s in treads])
    d = np.diff(c[:, :2], axis=0)
    step = np.linalg.norm(d, axis=1)
    flights = [0] + [i + 1 for i in np.nonzero(np.abs(step - go) > 1e-6)[0]] + [len(c)]
    assert len(flights) - 1 == (1 if style == "straight" else 2)
    first = d[:flights[1] - 1]
    assert np.allclose(first, (go, 0.0))  # climbing toward +X
    if style != "straight":
        second = d[flights[1]:]
        expect = {"l_shaped": (0.0, go if p["turn"] == "left" else -go), "u_shaped": (-go, 0.0)}[style]
        assert len(second) and np.allclose(second, expect)


@pytest.mark.parametrize("seed", SEEDS)
def test_straight_stair_starts_at_the_minus_x_end(seed):
    _, p, a = make("staircase", seed, style="straight")
    t0 = a.surface("tread_0")
    lo, hi = a.mesh.bounds
    assert t0.origin[0] < lo[0] + 0.25 * (hi[0] - lo[0])
    last = max((s for s in a.surfaces if s.name.startswith("tread_")), key=lambda s: s.origin[2])
    assert last.origin[0] > hi[0] - 0.25 * (hi[0] - lo[0])


@pytest.mark.parametrize("seed", SEEDS)
def test_handrail_height_above_the_nosings(seed):
    """Where a balustrade runs, the top of the stair near the middle of a flight is the
    handrail (plus newel caps at its ends), about `handrail_height` above the treads."""
    _, p, a = make("staircase", seed, style="straight", railing_side="both", baluster_style="round")
    t = a.surface("tread_3")
    cut = a.mesh.section(plane_normal=[1.0, 0.0, 0.0], plane_origin=t.origin)
    top = cut.vertices[:, 2].max() - t.origin[2]
    assert p["handrail_height"] - 0.01 < top < p["handrail_height"] + p["riser_target"] + 0.06


# --------------------------------------------------------------------------------- railing
@pytest.mark.parametrize("seed", SEEDS)
def test_stair_railing_dimensions(seed):
    f, p, _, a = build("stair_railing", seed)
    d, w, h = a.extents
    assert abs(w - p["length"]) < TOL and abs(h - (p["height"] + 0.06)) < TOL
    assert d < 0.15
    low = a.mesh.vertices[a.mesh.vertices[:, 2] < 1e-6]
    assert low[:, 1].min() < -p["length"] / 2 + p["post_size"] + 0.02  # posts stand at both ends
    assert low[:, 1].max() > p["length"] / 2 - p["post_size"] - 0.02
    gaps = np.diff(f._posts(f.resolve(p)))
    assert gaps.max() <= p["post_spacing"] + 1e-9
