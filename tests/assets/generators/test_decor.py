"""Decor: wall pieces' backs on the wall, mirrors, canvases, curtains, rugs, aquariums,
balloons, candles, clocks, photo frames, sculptures and decorative bowls, beyond the generic
contract in test_generators.py."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics, Subpart
from support.assetcheck import (
    TOL,
    assert_clean_variant,
    assert_objects_tagged,
    build,
    choice_cases,
    make,
    slot_faces,
    slot_mesh,
    surface_gap,
    variant,
)

DECOR = ["rug_round", "canvas_art", "mirror", "floor_mirror", "aquarium", "curtain", "clock", "table_clock",
         "balloon", "candle", "photo_frame", "sculpture", "decor_bowl"]
WALL = ["canvas_art", "mirror", "clock", "curtain"]
SEEDS = range(5)


@pytest.mark.parametrize("name,key,value", choice_cases(DECOR))
def test_every_style_builds_one_clean_shell_per_link(name, key, value):
    assert_clean_variant(name, key, value)


def test_registered_with_tags():
    assert_objects_tagged(DECOR)
    for name in WALL:
        assert Semantics.WallMounted in get_factory(name).tags


@pytest.mark.parametrize("name,seed", [(n, s) for n in WALL for s in SEEDS])
def test_wall_objects_back_lies_on_the_mesh(name, seed):
    _, _, _, a = build(name, seed)
    back = a.surface("back")
    assert back.subpart == Subpart.Back and np.allclose(back.normal, (-1, 0, 0))
    assert np.allclose(back.corners()[:, 0], a.mesh.bounds[0, 0], atol=TOL)
    assert surface_gap(a, back) < TOL
    # the back plane really is the rearmost: nothing of the mesh behind it
    assert a.mesh.bounds[0, 0] >= back.origin[0] - 1e-6


def test_round_mirror_back_is_the_disc_not_the_box():
    _, p, a, _ = variant("mirror", shape="round")
    back = a.surface("back")
    # a disc inscribed in the bbox: about pi/4 of the square
    d = a.extents[1]
    assert 0.7 * d * d < back.polygon.area < 0.8 * d * d
    assert surface_gap(a, back) < TOL
    assert len(slot_faces(a, "mirror")) > 0


def test_canvas_triptych_is_one_panel_with_grooves():
    _, p, a, _ = variant("canvas_art", n_panels=3, groove_width=0.03, groove_depth=0.7,
                          center_scale=1.0)
    assert a.mesh.body_count == 1
    w, g = p["panel_width"], p["groove_width"]
    x_front = a.mesh.bounds[1, 0]
    zc = a.extents[2] / 2
    groove_y = [-w / 2 - g / 2, w / 2 + g / 2]
    inside = a.mesh.contains([[x_front - 0.002, y, zc] for y in groove_y]
                             + [[x_front - 0.002, 0.0, zc]])
    assert not inside[0] and not inside[1] and inside[2]
    assert abs(a.extents[1] - (3 * w + 2 * g)) < TOL


def test_curtain_hangs_to_its_hem_and_covers_its_share():
    for cov in (0.4, 1.0):
        _, p, a, _ = variant("curtain", coverage=cov, n_panels=1)
        fab = slot_mesh(a, "fabric")
        assert abs(fab.bounds[0, 2]) < TOL  # the hem is the bottom
        span = fab.bounds[1, 1] - fab.bounds[0, 1]
        assert abs(span - cov * p["width"]) < 0.01
        assert fab.bounds[1, 2] > 0.95 * p["drop"]


def test_rug_fringe_extends_the_rug():
    _, p, a, _ = variant("rug_round", shape="round", edge="fringe")
    assert abs(a.extents[1] - (p["diameter"] + 2 * p["fringe_length"])) < 0.005
    _, p2, a2, _ = variant("rug_round", shape="round", edge="plain")
    assert abs(a2.extents[1] - p2["diameter"]) < 0.002
    # the tassels lie 1 mm off the floor: only the pile touches z=0
    low = a.mesh.vertices[a.mesh.vertices[:, 2] < 1e-6]
    assert np.linalg.norm(low[:, :2], axis=1).max() < p["diameter"] / 2 + TOL


def test_aquarium_lid_top_is_the_support_surface_and_water_is_inside():
    for style in ("tank", "on_stand"):
        _, p, a, _ = variant("aquarium", style=style, lid_style="hood")
        top = a.surface("top")
        assert top.subpart == Subpart.SupportSurface and np.allclose(top.normal, (0, 0, 1))
        assert abs(top.origin[2] - a.extents[2]) < TOL
        assert surface_gap(a, top) < TOL
        water, glass = slot_mesh(a, "water"), slot_mesh(a, "glass")
        assert len(water.faces) and len(slot_faces(a, "stone"))
        assert water.bounds[1, 2] < glass.bounds[1, 2]  # below the rim
        assert np.all(water.bounds[0, :2] >= glass.bounds[0, :2] - 1e-6)
        assert np.all(water.bounds[1, :2] <= glass.bounds[1, :2] + 1e-6)
        if style == "on_stand":
            assert len(a.joints) == 2 and all(j.kind == "revolute" for j in a.joints)
            assert glass.bounds[0, 2] > 0.55  # the tank stands on the cabinet
            (inner,) = a.surfaces_of(Subpart.Interior)
            assert surface_gap(a, inner) < TOL and inner.origin[2] < 0.1
        else:
            assert not a.joints


def test_balloons_do_not_touch_each_other():
    for n in range(1, 6):
        _, p, a, _ = variant("balloon", n_balloons=n, spread=0.0)
        bodies = slot_mesh(a, "plastic").split(only_watertight=False)
        assert len(bodies) == n
        assert a.mesh.body_count == 1  # strings tie them all to the weight


def test_lit_candle_has_an_emissive_flame_on_top():
    for style in ("pillar", "taper", "tealight", "jar"):
        _, p, a, _ = variant("candle", style=style, lit=True)
        flame = slot_faces(a, "emissive")
        assert len(flame)
        wax_top = a.mesh.triangles[slot_faces(a, "wax")][..., 2].max()
        assert a.mesh.triangles[flame][..., 2].max() > wax_top + 0.02
        if style != "jar":  # (a jar may be taller than its flame)
            assert abs(a.mesh.triangles[flame][..., 2].max() - a.extents[2]) < TOL
        _, _, dark, _ = variant("candle", style=style, lit=False)
        assert len(slot_faces(dark, "emissive")) == 0
        assert a.surface("bottom").subpart == Subpart.Bottom


def test_clock_hands_point_at_the_time():
    # 3 o'clock: the hour hand points to +Y (the viewer's right), the minute hand up
    _, p, a, _ = variant("clock", shape="round", time=3.0, markers="none")
    metal = slot_mesh(a, "metal")
    c = np.array([0.0, 0.0, a.extents[2] / 2])
    rel = metal.vertices - c
    r = p["diameter"] / 2 - p["rim_width"]
    slack = 0.02  # hand widths and the centre cap
    assert rel[:, 1].max() > 0.4 * r and rel[:, 1].min() > -0.12 * r - slack
    assert rel[:, 2].max() > 0.7 * r and rel[:, 2].min() > -0.15 * r - slack
    # far up there is only the (vertical) minute hand; far right only the hour hand
    assert np.abs(rel[rel[:, 2] > 0.55 * r, 1]).max() < slack
    assert np.abs(rel[rel[:, 1] > 0.3 * r, 2]).max() < slack


def test_shelf_decor_joins_decor_but_not_tableware():
    for name in ("photo_frame", "sculpture", "decor_bowl"):
        tags = get_factory(name).tags
        assert {Semantics.Decor, Semantics.SmallObject} <= tags
        assert not tags & {Semantics.Bowl, Semantics.Tableware, Semantics.Book, Semantics.Balloon}


def test_strut_photo_frame_stands_on_its_edge_and_the_struts_foot():
    for seed in SEEDS:
        _, p, a = make("photo_frame", seed, style="strut")
        canvas = slot_mesh(a, "canvas")
        # the picture faces +X, just behind the frame's front
        assert a.mesh.bounds[1, 0] - canvas.bounds[1, 0] == pytest.approx(p["recess"], abs=TOL)
        low = a.mesh.vertices[a.mesh.vertices[:, 2] < 1e-6]
        # contact at the frame's front edge and at the strut's foot, reach x height behind it
        spread = low[:, 0].max() - low[:, 0].min()
        assert spread == pytest.approx(p["depth"] + p["strut_reach"] * p["height"], abs=0.01)
        assert a.mesh.body_count == 1


def test_sculpture_figure_stands_on_its_plinth():
    for figure in ("stacked", "spindle", "ring"):
        _, p, a, _ = variant("sculpture", figure=figure)
        fig, base = slot_mesh(a, "sculpture"), slot_mesh(a, "plinth")
        assert fig.bounds[0, 2] == pytest.approx(p["plinth_height"], abs=0.003)
        assert np.all(np.abs(fig.bounds[:, :2]) <= p["plinth_width"] / 2 + TOL)
        assert base.bounds[0, 2] == pytest.approx(0.0, abs=1e-6) and a.mesh.body_count == 1


def test_decor_tray_is_low_and_wide_with_a_well():
    _, p, a, _ = variant("decor_bowl", style="tray")
    assert a.extents[2] == pytest.approx(p["tray_height"], abs=TOL)
    assert a.extents[0] == pytest.approx(p["tray_length"], abs=TOL)
    (well,) = a.surfaces_of(Subpart.Interior)
    assert surface_gap(a, well) < TOL and well.origin[2] == pytest.approx(p["base_thickness"])


@pytest.mark.parametrize("shape", ["bulb", "cylinder", "bottle", "cone", "amphora"])
def test_a_tall_narrow_vase_stands_on_a_foot_wide_enough_to_keep_it_up(shape):
    from indoorgen.assets.generators.decor.vases import STABLE_FOOT
    # the tallest, narrowest vase on the narrowest foot the ranges allow
    _, p, a = make("vase", 0, shape=shape, height=0.5, max_radius=0.05, foot_frac=0.5)
    base = a.mesh.vertices[a.mesh.vertices[:, 2] < 1e-6]
    foot = np.hypot(base[:, 0], base[:, 1]).max()
    assert foot >= STABLE_FOOT * p["height"] - 1e-3
    # leaning this far (about 13 degrees), its centre of mass still stands over the foot
    assert np.degrees(np.arctan2(foot, a.mesh.center_mass[2])) > 12.0
