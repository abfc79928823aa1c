"""Wall sconces: a wall plate (the `back`) and an arm carrying a shade, an up-light bowl, an opal
globe or a candle bulb."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.lighting._parts import CHEAP, FINE, LIGHT_SLOTS, Kit, build_groups
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between, circle_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


@register
class WallSconce(PartsFactory):
    """A wall sconce: a flat wall plate (its `back`, against the wall), an arm reaching out and
    rising to a fabric shade around an upright bulb, an up-light bowl, an opal globe or a candle
    with a flame bulb."""

    name = "wall_sconce"
    tags = frozenset({S.Object, S.Lighting, S.WallSconce, S.WallMounted})
    size_class = "medium"
    slots = LIGHT_SLOTS
    params = {
        "style": Param(kind="choice", choices=("shade", "uplight", "globe", "candle"),
                       doc="what the arm carries"),
        "plate_shape": Param(kind="choice", choices=("round", "rect"), doc="wall plate outline"),
        "plate_size": Param(0.08, 0.15, doc="wall plate diameter / height (m)"),
        "reach": Param(0.1, 0.25, doc="arm projection from the wall to the fixture axis (m)"),
        "arm_rise": Param(0.02, 0.15, doc="rise of the arm's upright part (m)"),
        "shade_diameter": Param(0.1, 0.25, doc="shade / bowl / globe diameter (m; kept clear of "
                                               "the wall)"),
        "shade_height": Param(0.08, 0.2, doc="shade / bowl height (m)"),
    }

    PLATE_T = 0.015

    def _R(self, p) -> float:
        """Fixture radius, at least 2.5 cm clear of the wall plate."""
        return min(p["shade_diameter"] / 2, p["reach"] - self.PLATE_T - 0.025)

    def _plate(self, p, zc: float, k: Kit) -> m3d.Manifold:
        s, t = p["plate_size"], self.PLATE_T
        if p["plate_shape"] == "round":
            return k.cylinder(s / 2, t, (0.0, 0.0, 0.0), 32, circumscribed=True).rotate((0.0, 90.0, 0.0)) \
                .translate((0.0, 0.0, zc))
        return box_between((0.0, -0.4 * s, zc - s / 2), (t, 0.4 * s, zc + s / 2))

    def _fixture(self, p, x: float, z: float, k: Kit) -> list[Part]:
        """What sits on the arm's end at (x, 0, z)."""
        R, sh, st = self._R(p), p["shade_height"], p["style"]
        o = OVERLAP
        cup = Part(k.disc(0.025, z - 0.012, 0.02, x, 0.0, 24), "metal")
        if st == "candle":
            return [Part(k.disc(min(R, 0.04), z - 0.006, 0.012, x, 0.0, 24), "metal"),
                    Part(k.disc(0.012, z + 0.006 - o, 0.08, x, 0.0, 16), "wax"),
                    Part(k.flame(z + 0.086 - o, 0.013, x), "emissive")]
        if st == "globe":
            rg = R
            us = np.linspace(-math.pi / 2 + 0.5, math.pi / 2 - 0.35, 12)
            prof = [(0.0, 0.0), (rg * math.cos(us[0]), 0.0)] + \
                   [(rg * math.cos(u), rg * (math.sin(u) - math.sin(us[0]))) for u in us[1:]]
            prof.append((0.0, prof[-1][1]))
            return [cup, Part(k.lathe(prof, 32).translate((x, 0.0, z + 0.008 - o)), "emissive")]
        if st == "uplight":
            th = 0.004
            zb = z + 0.008 - o
            us = np.linspace(0.0, 1.0, 8)
            outer = [(0.3 * R + 0.7 * R * math.sin(u * math.pi / 2),
                      zb + sh * (1 - math.cos(u * math.pi / 2))) for u in us]
            prof = [(0.0, zb)] + outer + [(R - th, outer[-1][1])] + \
                [(max(r - th, 0.001), zz + th) for r, zz in reversed(outer[:-1])] + [(0.0, zb + th)]
            rb = min(0.03, 0.4 * R)
            return [cup, Part(k.lathe(prof, 48).translate((x, 0.0, 0.0)), "shade"),
                    Part(k.disc(0.012, zb + th - o, 0.02, x, 0.0, 16), "metal"),
                    Part(k.bulb(zb + th + 0.02 - 2 * o, rb, x), "emissive")]
        # fabric shade on a spider around an upright bulb
        th = 0.003
        z_s0 = z + 0.02
        rt = 0.7 * R
        rb = min(0.03, 0.35 * rt)
        out = [cup, Part(k.disc(0.014, z + 0.008 - o, 0.035, x, 0.0, 16), "metal"),
               Part(k.bulb(z + 0.043 - o, rb, x), "emissive"),
               Part(k.shell([(R, z_s0), (rt, z_s0 + sh)], th).translate((x, 0.0, 0.0)), "shade")]
        z_sp = z_s0 + sh - 0.01
        r_sp = rt + (R - rt) * 0.01 / sh - th / 2
        hub = max(z + 0.043 + 2.3 * rb, z_sp)
        out.append(Part(k.rod((x, 0.0, z + 0.04), (x, 0.0, hub + 0.004), 0.003, 8), "metal"))
        for i in range(3):
            a = 2 * math.pi * i / 3
            spoke = k.rod((x, 0.0, hub), (x + r_sp * math.cos(a), r_sp * math.sin(a), z_sp), 0.0025, 8)
            out.append(Part(spoke, "metal"))
        return out

    def _zp(self, p) -> float:
        return 0.1  # plate centre height in the design frame (recentred later)

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Wall plate, arm and the fixture at its end (placeholder: one box each)."""
        k = FINE if detail else CHEAP
        zc = self._zp(p)
        reach, rise = p["reach"], p["arm_rise"]
        x1 = reach
        z1 = zc + rise
        arm = [Part(k.rod((self.PLATE_T - OVERLAP, 0.0, zc), (x1, 0.0, zc), 0.007, 12), "metal"),
               Part(k.sphere(0.007, 12).translate((x1, 0.0, zc)), "metal"),
               Part(k.rod((x1, 0.0, zc), (x1, 0.0, z1), 0.007, 12), "metal")]
        plate = [Part(self._plate(p, zc, k), "metal")]
        fixture = self._fixture(p, x1, z1, k)
        return build_groups([plate, arm, fixture], detail)

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The wall plate's outline as the `back`, against the wall."""
        s, zc = p["plate_size"], self._zp(p)
        if p["plate_shape"] == "round":
            poly = circle_polygon(0.99 * s / 2, 32)
        else:
            poly = sg.box(-0.4 * s + 0.001, -s / 2 + 0.001, 0.4 * s - 0.001, s / 2 - 0.001)
        return [Surface("back", Subpart.Back, np.array([0.0, 0.0, zc]), np.array([-1.0, 0.0, 0.0]),
                        np.array([0.0, 1.0, 0.0]), poly)]
