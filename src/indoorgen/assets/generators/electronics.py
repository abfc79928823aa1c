"""Electronics: a flat-screen TV on a stand foot (it rests on a TV stand's top). Screen faces +X."""
from __future__ import annotations

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, box, box_between
from indoorgen.model.tags import Semantics as S

ASPECTS = {"16:9": 9 / 16, "21:9": 9 / 21}


@register
class TV(PartsFactory):
    """A flat TV: a thin panel (with a glass screen on its front) standing on a pedestal or on
    two feet."""

    name = "tv"
    tags = frozenset({S.Object, S.Electronics, S.TV})
    size_class = "medium"
    slots = ["plastic", "screen", "metal"]
    params = {
        "screen_width": Param(0.8, 1.6, doc="panel Y extent (m), ~36-72 inch diagonal"),
        "aspect": Param(kind="choice", choices=tuple(ASPECTS), doc="panel aspect ratio"),
        "thickness": Param(0.025, 0.08, doc="panel X extent (m)"),
        "bezel": Param(0.005, 0.02, doc="border around the glass (m)"),
        "stand_style": Param(kind="choice", choices=("pedestal", "feet"), doc="stand type"),
        "foot_depth": Param(0.18, 0.3, doc="X extent of the stand (m)"),
        "foot_width_frac": Param(0.25, 0.5, doc="pedestal base width / panel width"),
        "clearance": Param(0.03, 0.1, doc="gap between the stand's base and the panel (m)"),
    }

    def parts(self, p, detail):
        W, th, bz = p["screen_width"], p["thickness"], p["bezel"]
        Hs = W * ASPECTS[p["aspect"]] + 2 * bz
        fd, z0 = p["foot_depth"], p["clearance"] + 0.015
        out = []
        body = (bevel_box((th, W, Hs), (0, 0, z0 + Hs / 2), min(0.006, th / 3), 1) if detail
                else box((th, W, Hs), (0, 0, z0 + Hs / 2)))
        out.append(Part(body, "plastic"))
        glass = box_between((th / 2 - 0.003, -W / 2 + bz, z0 + bz), (th / 2 + 0.001, W / 2 - bz, z0 + Hs - bz))
        out.append(Part(glass, "screen"))
        if p["stand_style"] == "pedestal":
            fw = W * p["foot_width_frac"]
            out.append(Part(box_between((-fd / 2, -fw / 2, 0.0), (fd / 2, fw / 2, 0.015)), "metal"))
            out.append(Part(box_between((-th / 2 - 0.03, -0.04, 0.015 - OVERLAP),
                                        (-th / 2 + 0.005, 0.04, z0 + 0.15)), "metal"))
        else:
            for s in (-1, 1):
                yc = s * (W / 2 - min(0.12, W * 0.15))
                out.append(Part(box_between((-fd / 2, yc - 0.02, 0.0), (fd / 2, yc + 0.02, 0.012)), "metal"))
                out.append(Part(box_between((-0.02, yc - 0.015, 0.012 - OVERLAP),
                                            (0.0, yc + 0.015, z0 + 0.08)), "metal"))
        return out
