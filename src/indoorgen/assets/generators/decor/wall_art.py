"""Wall art: framed pictures (frame, mat, recessed print) and gallery-wrapped canvases, alone or as
a diptych / triptych. The back hangs on the wall; the picture faces +X."""
from __future__ import annotations

from typing import Any

import shapely.geometry as sg

from indoorgen.assets.generators.decor._parts import back_surface, framed_picture
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import SMALL_OVERLAP, Part, bevel_box, box, box_between
from indoorgen.model.tags import Semantics as S


@register
class WallArt(PartsFactory):
    """A framed picture (frame, optional mat, recessed picture on a backing board) or a
    gallery-wrapped canvas. Its back (-X) goes against the wall; the picture faces +X."""

    name = "wall_art"
    tags = frozenset({S.Object, S.Decor, S.WallDecoration, S.WallArt})
    size_class = "medium"
    slots = ["frame", "canvas", "mat", "backing"]
    solid_bottom = True
    params = {
        "width": Param(0.3, 1.5, doc="Y extent (m)"),
        "height": Param(0.3, 1.2, doc="Z extent (m)"),
        "style": Param(kind="choice", choices=("framed", "canvas"), doc="framed print or canvas"),
        "frame_width": Param(0.015, 0.08, doc="frame member width (m)"),
        "depth": Param(0.02, 0.05, doc="X extent: frame (or canvas stretcher) depth (m)"),
        "mat_width": Param(0.0, 0.08, doc="passe-partout width inside the frame (0 = none) (m)"),
        "recess": Param(0.004, 0.015, doc="how far the picture sits behind the frame's front (m)"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """A canvas block, or backing board, frame, mat and recessed print."""
        W, H, D = p["width"], p["height"], p["depth"]
        if p["style"] == "canvas":
            return [Part(box((D, W, H), (0, 0, H / 2)), "canvas")]
        return framed_picture(W, H, D, p["frame_width"], p["mat_width"], p["recess"], detail)


@register
class CanvasArt(PartsFactory):
    """A gallery-wrapped canvas print on a deep stretcher (no frame), or a diptych / triptych
    made as ONE wide canvas cut into panels by grooves from the front (a 3-panel one may have a
    taller middle panel). Its flat back hangs on the wall; the print faces +X."""

    name = "canvas_art"
    tags = frozenset({S.Object, S.Decor, S.WallDecoration, S.WallArt, S.WallMounted})
    size_class = "medium"
    slots = ["canvas", "wood"]
    params = {
        "panel_width": Param(0.3, 1.0, doc="Y extent of one panel (m)"),
        "height": Param(0.3, 1.1, doc="Z extent of the (outer) panels (m)"),
        "depth": Param(0.018, 0.045, doc="X extent: stretcher depth (m)"),
        "n_panels": Param(1, 3, kind="int", doc="panels side by side"),
        "groove_width": Param(0.01, 0.04, doc="gap between panels at the front (m)"),
        "groove_depth": Param(0.4, 0.85, doc="groove depth / canvas depth"),
        "edge_radius": Param(0.001, 0.006, doc="rounding of the wrapped edges (m)"),
        "center_scale": Param(1.0, 1.25, doc="3 panels: middle panel height / outer height"),
    }

    def _panels(self, p) -> list[tuple[float, float, float, float]]:
        """(y0, y1, z0, z1) of each panel."""
        w, g, n = p["panel_width"], p["groove_width"], int(p["n_panels"])
        H = p["height"]
        hs = [H * (p["center_scale"] if n == 3 and i == 1 else 1.0) for i in range(n)]
        Hm = max(hs)
        W = n * w + (n - 1) * g
        out = []
        for i, h in enumerate(hs):
            y0 = -W / 2 + i * (w + g)
            out.append((y0, y0 + w, (Hm - h) / 2, (Hm + h) / 2))
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """One bevelled block per panel and the wood behind the grooves joining them."""
        D, r = p["depth"], p["edge_radius"]
        panels = self._panels(p)
        out = []
        for y0, y1, z0, z1 in panels:
            ext, c = (D, y1 - y0, z1 - z0), (0.0, (y0 + y1) / 2, (z0 + z1) / 2)
            out.append(Part(bevel_box(ext, c, r, 2) if detail else box(ext, c), "canvas"))
        xb = -D / 2 + D * (1.0 - p["groove_depth"])
        for (_, a1, za0, za1), (b0, _, zb0, zb1) in zip(panels, panels[1:], strict=False):
            z0, z1 = max(za0, zb0) + r, min(za1, zb1) - r
            groove = box_between((-D / 2, a1 - SMALL_OVERLAP - r, z0), (xb, b0 + SMALL_OVERLAP + r, z1))
            out.append(Part(groove, "wood"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The rectangle all panels cover at the back, against the wall."""
        D, r = p["depth"], p["edge_radius"]
        panels = self._panels(p)
        z0 = max(q[2] for q in panels) + r + 0.002
        z1 = min(q[3] for q in panels) - r - 0.002
        y0, y1 = panels[0][0] + r + 0.002, panels[-1][1] - r - 0.002
        if len(panels) == 1:
            z0, z1 = panels[0][2] + r + 0.002, panels[0][3] - r - 0.002
        return [back_surface(sg.box(y0, z0, y1, z1), -D / 2)]
