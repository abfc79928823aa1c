"""Electronics: a laptop's lid and screen, a remote's buttons, every style, beyond the generic
contract in test_generators.py."""
from __future__ import annotations

import math

import pytest
import trimesh

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics
from support.assetcheck import (
    TOL,
    assert_clean_variant,
    assert_objects_tagged,
    build,
    choice_cases,
    slot_faces,
    slot_mesh,
    surface_gap,
    variant,
)

ELECTRONICS = ["laptop", "remote"]
SEEDS = range(5)


@pytest.mark.parametrize("name,key,value", choice_cases(ELECTRONICS))
def test_every_style_builds_one_clean_shell_per_link(name, key, value):
    assert_clean_variant(name, key, value)


def test_registered_with_tags():
    assert_objects_tagged(ELECTRONICS)
    assert {Semantics.Electronics, Semantics.Laptop} <= get_factory("laptop").tags


@pytest.mark.parametrize("seed", SEEDS)
def test_laptop_lid_closes_onto_the_base_and_opens_its_screen_forward(seed):
    _, p, _, a = build("laptop", seed)
    (j,) = a.joints
    assert j.child == "lid" and j.kind == "revolute"
    assert abs(j.lower + math.radians(p["open_angle"])) < 1e-9
    lid = a.link_mesh("lid")
    base = a.link_mesh("base")
    shut = trimesh.transform_points(lid.vertices, j.transform(j.lower))
    assert shut[:, 2].min() > base.bounds[1, 2]  # resting clear above the keys
    assert shut[:, 2].max() - base.bounds[1, 2] < 0.015  # but right on the base
    # opened to 100 degrees, the screen faces the user (+X)
    screen = slot_faces(a, "screen")
    opened = a.posed({j.name: math.radians(100) - math.radians(p["open_angle"])})
    n = opened.face_normals[screen]
    w = opened.area_faces[screen]
    assert (n[:, 0] * w).sum() / w.sum() > 0.8


def test_remote_buttons_on_top():
    _, p, a, _ = variant("remote", dpad=True, n_button_rows=5)
    rubber = slot_mesh(a, "rubber")
    body = slot_mesh(a, "plastic")
    assert len(rubber.split(only_watertight=False)) >= 1 + 2 + 3  # power, d-pad, rows
    assert rubber.bounds[1, 2] > body.bounds[1, 2]
    assert surface_gap(a, a.surface("bottom")) < TOL
