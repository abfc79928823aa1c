"""Axis-aligned bounding boxes: which pairs overlap, the prefilter before any exact test."""
from __future__ import annotations

from collections.abc import Iterator

import numpy as np


def overlapping_pairs(boxes: np.ndarray, tol: float = 0.0) -> Iterator[tuple[int, int]]:
    """Index pairs (i, j), i < j, of boxes (N, 2, D: low and high corners) that overlap by more
    than `tol` along every axis, in order of i then j."""
    boxes = np.asarray(boxes, float)
    for i in range(len(boxes) - 1):
        lo, hi = boxes[i]
        near = np.all(boxes[i + 1:, 0] < hi - tol, axis=1) & np.all(boxes[i + 1:, 1] > lo + tol, axis=1)
        for j in np.nonzero(near)[0] + i + 1:
            yield i, int(j)
