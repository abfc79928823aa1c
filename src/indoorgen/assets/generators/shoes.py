"""Shoes: a pair standing side by side (sneakers, loafers or ankle boots), toes towards +X.

Each shoe is a sole (its footprint, the hull of toe, ball and heel discs, extruded) under an
upper whose side profile falls from the collar to the toe, with the foot opening cut into it;
the pair, mirror images, is splayed a little, toes apart, the soles touching where they come
closest (one shell, as a pair put down together). The placeholder is each shoe's footprint
prism.
"""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.affinity as sa
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.outlines import ccw
from indoorgen.assets.shapes.primitives import SMALL_OVERLAP, Part
from indoorgen.assets.shapes.sweeps import xz_extrude
from indoorgen.model.tags import Semantics as S

#: the upper's height at the collar, per style, as a share of `upper_height` (a boot's shaft
#: rises above the ankle; a loafer is cut low)
COLLAR = {"sneaker": 1.0, "loafer": 0.75, "boot": 1.9}
#: how far each sole crosses the pair's centreline, so the two join (m)
TOUCH = 0.002
#: the upper's height at the toe, as a share of `upper_height`
TOE = {"sneaker": 0.5, "loafer": 0.42, "boot": 0.5}


def _prism(poly: sg.Polygon, z0: float, z1: float) -> m3d.Manifold:
    """`poly` (in plan) extruded from z0 to z1."""
    cs = m3d.CrossSection([ccw(np.asarray(poly.exterior.coords)[:-1])])
    return m3d.Manifold.extrude(cs, z1 - z0).translate((0.0, 0.0, z0))


@register
class Shoes(PartsFactory):
    """A pair of shoes side by side, toes splayed apart: `sneaker` (a thick sole, a padded
    collar), `loafer` (a thin sole, a low cut) or `boot` (an ankle shaft, a heel block)."""

    name = "shoes"
    tags = frozenset({S.Object, S.SmallObject, S.Shoes})
    size_class = "small"
    slots = ["leather", "rubber"]
    params = {
        "style": Param(kind="choice", choices=tuple(COLLAR), doc="kind of shoe"),
        "length": Param(0.22, 0.31, doc="shoe length along X (m)"),
        "width_ratio": Param(0.34, 0.42, doc="ball width / length"),
        "upper_height": Param(0.055, 0.09, doc="upper height at the collar of a sneaker (m)"),
        "sole_thickness": Param(0.01, 0.03, doc="sole thickness (m)"),
        "heel_height": Param(0.0, 0.03, doc="extra heel block under the back third (m)"),
        "opening": Param(0.32, 0.45, doc="foot opening length / shoe length"),
        "splay": Param(0.0, 12.0, doc="each toe turned outwards (deg)"),
    }

    def _footprint(self, p: dict[str, Any]) -> sg.Polygon:
        """One shoe's sole outline, heel at -X, toe at +X, centred on the origin."""
        L, w = p["length"], p["length"] * p["width_ratio"]
        toe, heel = 0.32 * w, 0.34 * w
        discs = [sg.Point(L / 2 - toe, 0.04 * w).buffer(toe, 12),
                 sg.Point(0.18 * L, 0.0).buffer(w / 2, 12),
                 sg.Point(-L / 2 + heel, 0.0).buffer(heel, 12)]
        return sg.MultiPolygon(discs).convex_hull

    def _heights(self, p: dict[str, Any]) -> tuple[float, float, float]:
        """(sole top, upper top at the collar, upper top at the toe) over the floor."""
        zs = p["sole_thickness"] + p["heel_height"] * 0.5
        return (zs, zs + COLLAR[p["style"]] * p["upper_height"],
                zs + TOE[p["style"]] * p["upper_height"])

    def _offset(self, p: dict[str, Any]) -> float:
        """How far the left shoe's centre lies off the pair's centreline: its sole, turned by
        the splay, crosses the line by `TOUCH`."""
        foot = sa.rotate(self._footprint(p), p["splay"], origin=(0, 0))
        return -TOUCH - foot.bounds[1]

    def _shoe(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """One shoe, toe at +X, in its own frame."""
        L = p["length"]
        foot = self._footprint(p)
        zs, zc, zt = self._heights(p)
        if not detail:
            return [Part(_prism(foot, 0.0, zc), "leather")]
        heel = p["heel_height"]
        out = [Part(_prism(foot, 0.0, p["sole_thickness"]), "rubber")]
        if heel > 0.002:
            back = foot.intersection(sg.box(-L / 2, -L, -L / 6, L))
            out.append(Part(_prism(back, p["sole_thickness"] - SMALL_OVERLAP,
                                   p["sole_thickness"] + heel), "rubber"))
        # the upper: the inset footprint cut by its side profile (collar high, toe low, rounded)
        inset = foot.buffer(-0.003, 8)
        xo = -L / 2 + p["opening"] * L
        xs = np.linspace(xo, L / 2, 8)
        toe = zt + (zc - zt) * 0.55 * np.cos(np.linspace(0, math.pi / 2, 8))
        toe[-1] = zt * 0.6 + zs * 0.4
        profile = [(-L, zs - SMALL_OVERLAP), (L, zs - SMALL_OVERLAP), (L, toe[-1]),
                   *zip(xs[::-1], toe[::-1], strict=True), (-L / 2 + 0.6 * p["opening"] * L, zc),
                   (-L, zc)]
        side = xz_extrude(m3d.CrossSection([ccw(profile)]), -L, L)
        upper = _prism(inset, zs - SMALL_OVERLAP, zc) ^ side
        # the foot opening: an oval down to the insole
        hole = sa.scale(sg.Point(0, 0).buffer(1.0, 16), p["opening"] * L / 2 - 0.012,
                        inset.bounds[3] - 0.012)
        hole = sa.translate(hole, -L / 2 + p["opening"] * L / 2 + 0.008, 0.0)
        upper -= _prism(hole, zs + 0.006, zc + 0.05)
        out.append(Part(upper, "leather"))
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The two shoes side by side, mirror images, toes splayed outwards."""
        y = self._offset(p)
        left = [Part(q.solid.rotate((0.0, 0.0, p["splay"])).translate((0.0, y, 0.0)), q.slot)
                for q in self._shoe(p, detail)]
        return left + [Part(q.solid.mirror((0.0, 1.0, 0.0)), q.slot) for q in left]
