"""Vases: a hollow lathed vessel with a bulb, cylinder, bottle, cone or amphora profile."""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import Part, circle_polygon, lathe
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

VASE_SHAPES = ("bulb", "cylinder", "bottle", "cone", "amphora")
#: the least foot radius per metre of height: a tall vase on a narrow foot stands at its
#: balance's edge (a 0.34 m cylinder on a 2.6 cm foot tipped over in Newton within a second);
#: at this ratio it leans some 13 degrees before its centre, about mid-height, passes the foot
STABLE_FOOT = 0.12


def vase_radius(p: dict[str, Any], t: float) -> float:
    """Outer radius of the vase at fraction t of its height (0 = base, 1 = rim)."""
    least = STABLE_FOOT * p["height"]          # the foot a vase this tall needs
    R, neck, belly = max(p["max_radius"], least), p["neck_frac"], p["belly_frac"]
    foot = max(p["foot_frac"], least / R)
    shape = p["shape"]

    def smooth(a: float, b: float, u: float) -> float:  # a to b along a half cosine, u in [0, 1]
        return a + (b - a) * (0.5 - 0.5 * math.cos(math.pi * min(max(u, 0.0), 1.0)))

    if shape == "cylinder":
        r = R * (foot + (1 - foot) * min(t / 0.05, 1.0)) if t < 0.05 else R
    elif shape == "cone":
        r = R * (foot + (1 - foot) * t)
    elif shape == "bottle":
        r = smooth(R * foot, R, t / 0.15) if t < 0.55 else smooth(R, R * neck * 0.6, (t - 0.55) / 0.2)
    elif shape == "amphora":
        r = (smooth(R * foot, R, t / belly) if t < belly
             else smooth(R, R * neck, (t - belly) / (0.85 - belly)) if t < 0.85
             else smooth(R * neck, R * (neck + 0.15), (t - 0.85) / 0.15))
    else:  # bulb
        r = smooth(R * foot, R, t / belly) if t < belly else smooth(R, R * neck, (t - belly) / (1 - belly))
    if p["lip"] and t > 0.94:
        r += 0.006 * (t - 0.94) / 0.06
    return max(r, p["wall_thickness"] + 0.006)


@register
class Vase(PartsFactory):
    """A lathed vase with a hollow interior: bulb, cylinder, bottle, cone or amphora profile."""

    name = "vase"
    tags = frozenset({S.Object, S.SmallObject, S.Decor, S.Vase})
    size_class = "small"
    slots = ["ceramic"]
    solid_bottom = True
    params = {
        "height": Param(0.15, 0.5, doc="Z extent (m)"),
        "max_radius": Param(0.05, 0.15, doc="widest outer radius (m; at least STABLE_FOOT x "
                                             "height)"),
        "shape": Param(kind="choice", choices=VASE_SHAPES, doc="profile family"),
        "foot_frac": Param(0.5, 0.9, doc="base radius / max radius (at least STABLE_FOOT x "
                                         "height, so that a tall vase stands)"),
        "neck_frac": Param(0.3, 0.9, doc="neck radius / max radius"),
        "belly_frac": Param(0.25, 0.6, doc="height of the widest point / height"),
        "wall_thickness": Param(0.003, 0.008, doc="wall thickness (m)"),
        "base_thickness": Param(0.005, 0.015, doc="floor thickness (m)"),
        "lip": Param(kind="bool", doc="flare the rim outwards"),
    }

    N_FINE = 24

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The hollow lathed vessel (placeholder: a solid envelope of its outer profile)."""
        H, w, b = p["height"], p["wall_thickness"], p["base_thickness"]
        ts = np.linspace(0.0, 1.0, self.N_FINE)
        rs = np.array([vase_radius(p, t) for t in ts])
        if detail:
            outer = [(0.0, 0.0)] + [(r, t * H) for r, t in zip(rs, ts, strict=True)]
            zi = np.linspace(b, H, self.N_FINE)
            inner = [(vase_radius(p, z / H) - w, z) for z in zi[::-1]]
            return [Part(lathe(outer + inner + [(0.0, b)], 48), "ceramic")]
        # placeholder: a solid envelope over 8 levels, each radius the max nearby
        idx = np.linspace(0, self.N_FINE - 1, 8).round().astype(int)
        env = []
        for j, i in enumerate(idx):
            lo = idx[max(j - 1, 0)]
            hi = idx[min(j + 1, len(idx) - 1)]
            env.append((float(rs[lo:hi + 1].max()), float(ts[i] * H)))
        return [Part(lathe([(0.0, 0.0)] + env + [(0.0, H)], 16, circumscribed=True), "ceramic")]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The round foot as the `bottom`."""
        r0 = vase_radius(p, 0.0)
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(r0 * 0.995, 48),
                                subpart=Subpart.Bottom, up=False)]
