"""Catalogue doors, windows, stairs and railings placed on a plan (indoorgen.architecture.fixtures)."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.architecture import fixtures


def test_a_door_stands_in_its_wall_and_states_its_opening():
    fx = fixtures.door(3, "d0", False, (2.0, 5.0), np.array([0.0, 1.0]), 0.9, 2.05, 0.12, 3.0)
    assert fx is not None and fx.generator == "interior_door"
    w, h = fx.opening
    assert w >= 0.9 - 1e-6 and h >= 2.05 - 1e-6
    lo, hi = fx.mesh.bounds
    assert lo[2] == pytest.approx(3.0, abs=0.05) and hi[2] <= 3.0 + h + 0.2
    assert lo[0] < 2.0 < hi[0] and lo[1] < 5.0 < hi[1]
    assert fx.collision


def test_same_seed_same_fixture_and_a_railing_spans_its_side():
    a = fixtures.railing(1, "r0", (0.0, 0.0), (3.0, 0.0), 2.9)
    b = fixtures.railing(1, "r0", (0.0, 0.0), (3.0, 0.0), 2.9)
    assert a is not None and a.params == b.params
    assert np.allclose(a.mesh.vertices, b.mesh.vertices)
    lo, hi = a.mesh.bounds
    assert hi[0] - lo[0] == pytest.approx(3.0, abs=0.15) and lo[2] >= 2.9 - 1e-6


def test_unknown_values_fall_back_to_none():
    # a flight far too steep for the catalogue staircase: the caller builds a simple solid
    assert fixtures.stair(0, "s", [(0, 0), (1, 0), (1, 0.5), (0, 0.5)], 3.0, 0.0) is None
