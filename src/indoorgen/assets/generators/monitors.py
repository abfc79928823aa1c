"""Computer monitors: a flat panel on a stand, for desks. Screen faces +X."""
from __future__ import annotations

import manifold3d as m3d
import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import Part, bevel_box, box, box_between, cylinder
from indoorgen.model.tags import Semantics as S

ASPECTS = {"16:9": 9 / 16, "16:10": 10 / 16, "21:9": 9 / 21}


@register
class Monitor(PartsFactory):
    """A computer monitor: a thin panel (glass screen on its front, a tapered housing bulge on
    its back) tilted back on a neck, on a rectangular plate, a round disc or a V of two feet."""

    name = "monitor"
    tags = frozenset({S.Object, S.Electronics, S.Monitor})
    size_class = "medium"
    slots = ["plastic", "screen", "metal"]
    params = {
        "screen_width": Param(0.45, 0.85, doc="panel Y extent (m), ~20-38 inch"),
        "aspect": Param(kind="choice", choices=tuple(ASPECTS), doc="panel aspect ratio"),
        "panel_thickness": Param(0.012, 0.03, doc="panel X extent (m)"),
        "bezel": Param(0.004, 0.02, doc="border around the screen (m)"),
        "base_style": Param(kind="choice", choices=("rect", "round", "v"), doc="stand base shape"),
        "base_depth": Param(0.15, 0.25, doc="X extent of the stand base (m)"),
        "clearance": Param(0.05, 0.15, doc="height of the panel's lower edge above the base (m)"),
        "tilt": Param(0.0, 10.0, doc="backwards tilt of the panel (degrees)"),
        "bulge": Param(0.015, 0.05, doc="depth of the housing bulge behind the panel (m)"),
    }

    BASE_T = 0.012

    def _panel_frame(self, p) -> tuple[float, float, float, np.ndarray]:
        """(panel height, z of its centre, x of the neck, pivot) of the untilted panel."""
        W, th = p["screen_width"], p["panel_thickness"]
        Hs = W * ASPECTS[p["aspect"]] + 2 * p["bezel"]
        zc = self.BASE_T + p["clearance"] + Hs / 2
        xn = -th / 2 - p["bulge"] * 0.5
        return Hs, zc, xn, np.array([xn, 0.0, zc])

    def _tilted(self, solid: m3d.Manifold, pivot: np.ndarray, tilt: float) -> m3d.Manifold:
        return solid.translate(tuple(-pivot)).rotate((0.0, -tilt, 0.0)).translate(tuple(pivot))

    def parts(self, p, detail):
        """The monitor's solids: detailed, or the blocks of its placeholder."""
        W, th, bz, bd = p["screen_width"], p["panel_thickness"], p["bezel"], p["base_depth"]
        Hs, zc, xn, pivot = self._panel_frame(p)
        tilt, bg = p["tilt"], p["bulge"]
        panel = (bevel_box((th, W, Hs), (0, 0, zc), min(0.004, th / 3), 1) if detail
                 else box_between((-th / 2, -W / 2, zc - Hs / 2), (th / 2 + 0.001, W / 2, zc + Hs / 2)))
        ends = ((-th / 2 + 0.001, 0.6 * W, 0.6 * Hs), (-th / 2 - bg, 0.3 * W, 0.35 * Hs))
        hump = m3d.Manifold.hull_points(np.array(
            [(x, sy * w / 2, zc + sz * h / 2) for x, w, h in ends for sy in (-1, 1) for sz in (-1, 1)]))
        out = [Part(self._tilted(panel, pivot, tilt), "plastic"),
               Part(self._tilted(hump, pivot, tilt), "plastic")]
        glass = box_between((th / 2 - 0.002, -W / 2 + bz, zc - Hs / 2 + bz),
                            (th / 2 + 0.001, W / 2 - bz, zc + Hs / 2 - bz))
        if detail:
            out.append(Part(self._tilted(glass, pivot, tilt), "screen"))
        # neck from the base up into the hump
        nw = 0.05
        out.append(Part(box_between((xn - 0.012, -nw / 2, self.BASE_T - 0.001),
                                    (xn + 0.012, nw / 2, zc + 0.03)), "metal"))
        xb0, xb1 = xn - 0.3 * bd, xn + 0.7 * bd
        style = p["base_style"]
        if style == "rect":
            bw = min(0.3, 0.45 * W)
            base = (bevel_box((bd, bw, self.BASE_T), ((xb0 + xb1) / 2, 0, self.BASE_T / 2), 0.005,
                              2) if detail
                    else box((bd, bw, self.BASE_T), ((xb0 + xb1) / 2, 0, self.BASE_T / 2)))
            out.append(Part(base, "metal"))
        elif style == "round":
            out.append(Part(cylinder(bd / 2, self.BASE_T, ((xb0 + xb1) / 2, 0, 0), 48 if detail else 12,
                                     radius_top=None, circumscribed=not detail), "metal"))
        else:  # two feet splayed forward from the neck
            spread = min(0.35, 0.5 * W) / 2
            for s in (-1, 1):
                foot = m3d.Manifold.hull_points(np.array(
                    [(x, y + dy, z) for x, y in ((xn - 0.02, 0.0), (xb1, s * spread))
                     for dy in (-0.015, 0.015) for z in (0.0, self.BASE_T)]))
                out.append(Part(foot, "metal"))
        return out
