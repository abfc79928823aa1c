"""overlapping_pairs agrees with a brute-force overlap test."""
from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from indoorgen.model.boxes import overlapping_pairs


def _brute(boxes: np.ndarray, tol: float) -> list[tuple[int, int]]:
    n = len(boxes)
    return [(i, j) for i in range(n) for j in range(i + 1, n)
            if np.all(boxes[j, 0] < boxes[i, 1] - tol) and np.all(boxes[j, 1] > boxes[i, 0] + tol)]


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 40), st.integers(0, 2**31 - 1), st.sampled_from([0.0, 0.001, 0.05]))
def test_matches_brute_force(n, seed, tol):
    rng = np.random.default_rng(seed)
    lo = rng.uniform(0, 3, (n, 3))
    boxes = np.stack([lo, lo + rng.uniform(0.01, 1.0, (n, 3))], axis=1)
    assert list(overlapping_pairs(boxes, tol)) == _brute(boxes, tol)


def test_touching_boxes_do_not_overlap_beyond_tolerance():
    boxes = np.array([[[0, 0, 0], [1, 1, 1]], [[0.9995, 0, 0], [2, 1, 1]]], float)
    assert list(overlapping_pairs(boxes, 0.0)) == [(0, 1)]
    assert list(overlapping_pairs(boxes, 0.001)) == []
