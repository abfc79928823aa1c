"""The monitor generator (generators/monitors.py): its screen faces the front (the generic asset
contract runs on it in test_generators.py)."""
from __future__ import annotations

import math

import pytest

from indoorgen.assets.catalogue import get_factory
from indoorgen.model.tags import Semantics
from support.assetcheck import build
from support.generatorcheck import faces_of_slot

SEEDS = range(6)
TOL = 1e-3


def test_registered_with_tags():
    assert {Semantics.Object, Semantics.Electronics, Semantics.Monitor} <= get_factory("monitor").tags


@pytest.mark.parametrize("seed", SEEDS)
def test_monitor_screen_faces_front(seed):
    _, p, _, a = build("monitor", seed)
    screen = faces_of_slot(a, "screen")
    n = a.mesh.face_normals[screen]
    area = a.mesh.area_faces[screen]
    front = area[n[:, 0] > math.cos(math.radians(p["tilt"] + 1))].sum()
    assert front > 0.4 * area.sum()
    assert abs(a.extents[1] - p["screen_width"]) < TOL
