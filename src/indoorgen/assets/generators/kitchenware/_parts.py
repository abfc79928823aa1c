"""What the kitchenware generators share: swept tubes (handles) and the lid clearance."""
from __future__ import annotations

from collections.abc import Callable

import manifold3d as m3d
import numpy as np

#: radial clearance between a vessel's neck (or rim) and the lid over it, and between its rim
#: and the lid's top (m)
LID_GAP = 0.002


# ----------------------------------------------------------------------------- shared parts
def sweep(path: Callable[[np.ndarray], np.ndarray], width: Callable[[np.ndarray], np.ndarray],
          thick: Callable[[np.ndarray], np.ndarray], n: int = 16, section: str = "round",
          floor: bool = False) -> m3d.Manifold:
    """A tube along `path(t)` (t in [0, 1] -> (N, 3) points in the XZ plane, advancing along
    +X) whose section (an ellipse, or a rectangle if section="square") is `width(t)` across
    (along Y) and `thick(t)` in the path's plane, perpendicular to it. With `floor`, the
    section's lowest vertices sit exactly thick/2 below the path (not tilted with it), so an
    underside laid along the table by `lying_path` touches it exactly."""
    cs = (m3d.CrossSection.circle(0.5, 12) if section == "round"
          else m3d.CrossSection.square((1.0, 1.0), True))
    eps = 1e-4

    def warp(v: np.ndarray) -> np.ndarray:
        t = v[:, 2]
        p = path(t)
        d = path(np.minimum(t + eps, 1.0)) - path(np.maximum(t - eps, 0.0))
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        up = np.c_[-d[:, 2], np.zeros_like(t), d[:, 0]]
        out = (p + (v[:, 0] * width(t))[:, None] * np.array([0.0, 1.0, 0.0])
               + (v[:, 1] * thick(t))[:, None] * up)
        if floor:
            low = v[:, 1] < -0.5 + 1e-9
            out[low, 2] = p[low, 2] - 0.5 * thick(t[low])
        return out

    return m3d.Manifold.extrude(cs, 1.0, n).warp_batch(warp)
