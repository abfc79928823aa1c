"""Shoes: a pair of mirror-image shoes, every style, beyond the generic contract in
test_generators.py."""
from __future__ import annotations

import numpy as np
import pytest

from support.assetcheck import assert_clean_variant, assert_objects_tagged, choice_cases, variant


@pytest.mark.parametrize("name,key,value", choice_cases(["shoes"]))
def test_every_style_builds_one_clean_shell(name, key, value):
    assert_clean_variant(name, key, value)


def test_registered_with_tags():
    assert_objects_tagged(["shoes"])


def test_a_pair_is_two_mirror_images_side_by_side():
    _, _, a, _ = variant("shoes", splay=8.0)
    v = a.mesh.vertices
    lo, hi = a.mesh.bounds
    assert lo[1] == pytest.approx(-hi[1], abs=1e-4)
    # each half holds a whole shoe's length; mirror images have the same extents
    left, right = v[v[:, 1] > 0.003], v[v[:, 1] < -0.003]
    assert np.ptp(left[:, 0]) == pytest.approx(np.ptp(right[:, 0]), abs=1e-4)
    assert np.ptp(left[:, 0]) > 0.2


def test_toes_splay_apart():
    _, _, a, _ = variant("shoes", splay=12.0)
    v = a.mesh.vertices
    lo, hi = a.mesh.bounds
    toes, heels = v[v[:, 0] > hi[0] - 0.05], v[v[:, 0] < lo[0] + 0.05]
    assert np.abs(toes[:, 1]).min() > np.abs(heels[:, 1]).min()


def test_boots_rise_above_sneakers_above_loafers():
    heights = {s: variant("shoes", style=s, upper_height=0.07)[2].mesh.bounds[1][2]
               for s in ("boot", "sneaker", "loafer")}
    assert heights["boot"] > heights["sneaker"] > heights["loafer"]
    assert 0.08 < heights["sneaker"] < 0.15
