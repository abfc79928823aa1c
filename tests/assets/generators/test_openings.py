"""Doors and windows (generators/openings/): what the generic contract cannot know about them
(openings in the wall plane, leaves swinging into +X, sliding leaves clearing the opening,
sashes opening outward, sills and bay seats)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from indoorgen.assets.catalogue import get_factory
from indoorgen.assets.shapes.architectural import opening_size
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import build, make

DOORS = ["interior_door", "sliding_door", "exterior_door"]
WINDOWS = ["window", "bay_window"]
OPENINGS = DOORS + WINDOWS
SEEDS = range(8)
TOL = 1e-3


def link_vertices(asset, link: str, values: dict | None = None) -> np.ndarray:
    """The vertices of one link, posed with joint `values` (closed when None)."""
    mesh = asset.posed(values or {})
    return mesh.vertices[np.unique(mesh.faces[asset.link_faces(link)])]


# ------------------------------------------------------------------------------ declarations
def test_tags():
    for name in OPENINGS:
        f = get_factory(name)
        assert {Semantics.Object, Semantics.Architecture} <= f.tags and f.size_class == "large"
    for name in DOORS:
        assert Semantics.Door in get_factory(name).tags
    assert Semantics.InteriorDoor in get_factory("interior_door").tags
    assert Semantics.InteriorDoor in get_factory("sliding_door").tags
    assert Semantics.ExteriorDoor in get_factory("exterior_door").tags
    for name in WINDOWS:
        assert Semantics.Window in get_factory(name).tags


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
