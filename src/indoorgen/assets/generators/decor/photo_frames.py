"""Standing picture frames: a photo frame held up by a hinged back strut, or a thick block frame
that stands on its own. The picture faces +X; home styles dress the frame through its slot."""
from __future__ import annotations

from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.generators.decor._parts import framed_picture
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import OVERLAP, Part
from indoorgen.model.tags import Semantics as S

#: thickness of a photo frame's back strut (m)
STRUT = 0.004


@register
class PhotoFrame(PartsFactory):
    """A standing picture frame: `strut` (a thin frame leaning on a back strut whose foot
    stands `strut_reach` x height behind it) or `block` (a deep frame standing on its own
    bottom). Frame ring, optional mat and a recessed picture on a backing board; faces +X."""

    name = "photo_frame"
    frequency = 1.5  # the commonest shelf decor
    tags = frozenset({S.Object, S.SmallObject, S.Decor})
    size_class = "small"
    slots = ["frame", "canvas", "mat", "backing"]
    params = {
        "style": Param(kind="choice", choices=("strut", "block"), doc="back strut or block frame"),
        "width": Param(0.1, 0.28, doc="Y extent of the frame (m)"),
        "height": Param(0.12, 0.3, doc="Z extent of the frame (m)"),
        "frame_width": Param(0.008, 0.035, doc="frame member width (m)"),
        "depth": Param(0.012, 0.022, doc="strut frame: X extent of the frame (m)"),
        "block_depth": Param(0.18, 0.3, doc="block frame: X extent / height (at least 25 mm)"),
        "mat_width": Param(0.0, 0.03, doc="passe-partout width inside the frame (0 = none) (m)"),
        "recess": Param(0.002, 0.006, doc="how far the picture sits behind the frame's front (m)"),
        "strut_reach": Param(0.3, 0.45, doc="strut foot's distance behind the frame / height"),
        "strut_width": Param(0.2, 0.4, doc="strut width / frame width"),
    }

    def bottom_is_solid(self, params: dict[str, Any]) -> bool:
        """A block frame rests on its whole bottom; a strut frame on its edge and the strut's foot."""
        return self.resolve(params)["style"] == "block"

    def _depth(self, p: dict[str, Any]) -> float:
        return max(p["block_depth"] * p["height"], 0.025) if p["style"] == "block" else p["depth"]

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The framed picture, centred on x = 0 (a strut frame: its front at the block's front,
        the strut behind it)."""
        W, H, D = p["width"], p["height"], self._depth(p)
        out = framed_picture(W, H, D, p["frame_width"], p["mat_width"], p["recess"], detail)
        if p["style"] == "block":
            return out
        return out + [Part(self._strut(p, D), "backing")]

    def _strut(self, p: dict[str, Any], D: float) -> m3d.Manifold:
        """A board hinged on the backing at 0.65 of the height, its foot flat on z = 0 at
        `strut_reach` x height behind the frame's back."""
        H, sw = p["height"], 0.5 * max(p["strut_width"] * p["width"], 0.025)
        xb, zt = -D / 2, 0.65 * H
        xf = xb - p["strut_reach"] * H
        pts = []
        for y in (-sw, sw):
            pts += [(xb + OVERLAP, y, zt), (xb + OVERLAP, y, zt - 0.02), (xb - STRUT, y, zt),
                    (xf, y, 0.0), (xf + 2 * STRUT, y, 0.0)]
        return m3d.Manifold.hull_points(np.array(pts, float))
