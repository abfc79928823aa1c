"""Rotations about the vertical axis, the only rotation a placed object has (Z up, yaw in radians)."""
from __future__ import annotations

import math

import numpy as np


def yaw_matrix(yaw: float) -> np.ndarray:
    """3x3 rotation by `yaw` radians about +Z (counter-clockwise seen from above)."""
    c, s = math.cos(yaw), math.sin(yaw)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
