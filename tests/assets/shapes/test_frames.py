"""Frames, legs and carcasses: where their members are."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.assets.shapes.frames import carcass, frame, legs


def bounds(solid) -> np.ndarray:
    return np.asarray(solid.bounding_box(), float).reshape(2, 3)


def test_frame_is_a_ring_of_its_border():
    f = frame(0.6, 0.4, 0.05, 0.02, (0.0, 0.0, 1.0))
    assert np.allclose(bounds(f), [(-0.01, -0.3, 0.8), (0.01, 0.3, 1.2)])
    assert f.volume() == pytest.approx(0.02 * (0.6 * 0.4 - 0.5 * 0.3))


@pytest.mark.parametrize("round_legs,taper", [(False, 1.0), (False, 0.6), (True, 1.0), (True, 0.7)])
def test_legs_stand_inset_under_the_footprint(round_legs, taper):
    four = legs((0.8, 0.5), 0.03, 0.04, 0.0, 0.7, taper=taper, round_legs=round_legs)
    assert len(four) == 4
    lo = np.min([bounds(leg)[0] for leg in four], axis=0)
    hi = np.max([bounds(leg)[1] for leg in four], axis=0)
    assert np.allclose(lo, (-0.37, -0.22, 0.0), atol=1e-9) and np.allclose(hi, (0.37, 0.22, 0.7), atol=1e-9)


def test_carcass_boards():
    parts = carcass(0.5, 0.8, 0.1, 0.9, 0.018, shelves=(0.5,), dividers=(0.0,), back_slot="back")
    assert len(parts) == 7  # two sides, bottom, back, top, a shelf, a divider
    assert [p.slot for p in parts].count("back") == 1
    hi = np.max([bounds(p.solid)[1] for p in parts], axis=0)
    lo = np.min([bounds(p.solid)[0] for p in parts], axis=0)
    assert np.allclose(lo, (-0.25, -0.4, 0.1)) and np.allclose(hi, (0.25, 0.4, 0.9))
    assert len(carcass(0.5, 0.8, 0.1, 0.9, 0.018, top=False)) == 4
