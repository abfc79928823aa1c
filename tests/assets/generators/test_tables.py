"""Tables: oval tables' tangent side facets, desks' drawers and knee space, console tables,
beyond the generic contract in test_generators.py."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from support.assetcheck import TOL, assert_furniture_tags, assert_on_mesh, build, make, point_inside


@pytest.mark.parametrize("name,must,must_not", [
    ("dining_table_oval", {S.Table, S.DiningTable}, set()),
    ("desk", {S.Table, S.Desk}, {S.DiningTable}),
    ("console_table", {S.Table, S.ConsoleTable}, {S.DiningTable}),
])
def test_tags(name, must, must_not):
    assert_furniture_tags(name, must, must_not)


@pytest.mark.parametrize("seed", range(6))
def test_oval_table_sides_tangent(seed):
    f, p, _, a = build("dining_table_oval", seed)
    sides = [s for s in a.surfaces if s.name.startswith("side_") and s.name[5:].isdigit()]
    n = len(sides)
    assert n >= 4 and n % 2 == 0 and [s.name for s in sides] == [f"side_{i}" for i in range(n)]
    w, ln, h = a.extents
    assert abs(w - p["width"]) < TOL and abs(ln - p["length"]) < TOL
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


@pytest.mark.parametrize("seed", range(6))
def test_workbench_top_shelf_and_drawer(seed):
    """A workbench's top is at standing work height, in front of any pegboard's hooks; its
    shelf has room under the top; a drawer, if any, slides out under the top."""
    f, p, _, a = build("workbench", seed)
    assert {S.Table, S.Workbench} <= f.tags
    top, shelf = a.surface("top"), a.surface("shelf")
    assert 0.86 - TOL <= top.origin[2] <= 0.95 + TOL
    assert_on_mesh(a, top)
    assert_on_mesh(a, shelf)
    hit = a.mesh.ray.intersects_location([shelf.origin + (0, 0, 0.001)], [[0.0, 0.0, 1.0]])[0]
    assert hit[:, 2].min() - shelf.origin[2] >= 0.45  # a paint can or a box fits under the top
    # nothing stands above the top's surface within 0.3 m (the hooks are behind it)
    x0, y0, x1, y1 = top.polygon.bounds
    probes = [top.to_world(np.array([[x, y]]))[0] + (0, 0, 0.01)
              for x in (x0, x1) for y in (y0, 0.0, y1)]
    for q in probes:
        up = a.mesh.ray.intersects_location([q], [[0.0, 0.0, 1.0]])[0]
        assert len(up) == 0 or up[:, 2].min() - q[2] > 0.3
    assert len(a.joints) == (1 if p["drawer"] else 0)
    for j in a.joints:
        assert j.kind == "prismatic" and np.allclose(j.axis, (1, 0, 0)) and j.upper > 0.3
        lo, hi = a.link_mesh(j.child).bounds
        assert hi[2] <= p["height"] - p["top_thickness"] + TOL


def test_workbench_pegboard_and_hooks():
    f, p, a = make("workbench", 1, pegboard=True, pegboard_height=0.6, n_hooks=5)
    assert abs(a.extents[2] - p["height"] - 0.6) < TOL
    assert a.surface("top").polygon.bounds[0] + a.surface("top").origin[0] > -p["depth"] / 2 + 0.08
