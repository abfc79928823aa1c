"""Small sculptures: an abstract figure on a plinth: stacked pebbles, a lathed spindle or an
upright ring. Figure and plinth are dressed through their own slots (home styles apply)."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.generators.decor._parts import bbox_part
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box, cylinder, lathe, torus
from indoorgen.assets.shapes.vessels import SECTIONS, round_bottom
from indoorgen.model.tags import Semantics as S

FIGURES = ("stacked", "spindle", "ring")
#: a pebble's height / width (before a stack is squeezed to its height)
PEBBLE = 0.6


def _stones(p: dict[str, Any], z0: float, h: float, r: float) -> list[m3d.Manifold]:
    """`n_stones` flattened spheres, widest at the bottom, each sunk into the one below by a
    fifth of its height; a stack taller than `h` is squeezed to end at z0 + h."""
    n = int(p["n_stones"])
    radii = r * np.linspace(1.0, p["taper"], n)
    heights = 2 * radii * PEBBLE
    step = heights * 0.8
    k = min(h / (step[:-1].sum() + heights[-1]), 1.0)  # squeezed to fit the height, never stretched
    out, z = [], z0 - OVERLAP
    for i in range(n):
        hz = heights[i] * k
        rx = radii[i] * (1.0 if i % 2 else 0.85)  # alternate the long axis: pebbles, not beads
        s = m3d.Manifold.sphere(1.0, 24).scale((rx, radii[i], hz / 2))
        out.append(s.translate((0.0, 0.0, z + hz / 2)))
        z += step[i] * k
    return out


def _spindle(p: dict[str, Any], z0: float, h: float, r: float) -> m3d.Manifold:
    """A lathed abstract form: two swellings joined at a waist, tapering to a rounded tip."""
    w = p["waist"]
    t = np.linspace(0.0, 1.0, 25)
    rs = r * (w + (1 - w) * np.abs(np.sin(1.5 * math.pi * t + 0.25 * math.pi))) * (1 - 0.75 * t)
    rs[-1] = 0.0
    prof = [(0.0, z0 - OVERLAP)] + [(float(a), float(z0 - OVERLAP + (h + OVERLAP) * b))
                                    for a, b in zip(rs[:-1], t[:-1], strict=True)]
    return lathe(prof + [(0.0, z0 + h)], SECTIONS)


def _ring(p: dict[str, Any], z0: float, h: float) -> m3d.Manifold:
    """A torus standing on edge (its axis along X), sunk a little into the plinth."""
    k = p["ring_thickness"]
    major = (h + OVERLAP) / (2 * (1 + k))
    minor = k * major
    return torus(major, minor, sections=40, tube_sections=16).rotate((0.0, 90.0, 0.0)).translate(
        (0.0, 0.0, z0 - OVERLAP + major + minor))


@register
class Sculpture(PartsFactory):
    """An abstract figurine on a square or round plinth: a stack of pebbles (`stacked`), a
    lathed spindle with a waist (`spindle`) or a ring standing on edge (`ring`)."""

    name = "sculpture"
    tags = frozenset({S.Object, S.SmallObject, S.Decor})
    size_class = "small"
    slots = ["sculpture", "plinth"]
    solid_bottom = True
    material_choices = {
        "sculpture": {"glazed_ceramic": 2.0, "matte_ceramic": 2.0, "brass": 1.0, "marble": 1.5,
                      "walnut": 1.0, "painted_metal": 1.0, "porcelain": 1.0},
        "plinth": {"marble": 2.0, "granite": 1.0, "slate": 1.0, "walnut": 1.5, "oak": 1.0,
                   "concrete": 1.0, "painted_metal": 0.5},
    }
    params = {
        "figure": Param(kind="choice", choices=FIGURES, doc="kind of abstract figure"),
        "plinth": Param(kind="choice", choices=("square", "round"), doc="plinth outline"),
        "plinth_width": Param(0.06, 0.14, doc="plinth width / diameter (m)"),
        "plinth_height": Param(0.01, 0.04, doc="plinth height (m)"),
        "height": Param(0.12, 0.36, doc="Z extent, at most (m; a ring or a pebble stack may stand lower)"),
        "figure_width": Param(0.6, 0.95, doc="figure width / plinth width"),
        "n_stones": Param(2, 5, kind="int", doc="stacked: number of pebbles"),
        "taper": Param(0.4, 0.85, doc="stacked: top pebble width / bottom pebble width"),
        "waist": Param(0.2, 0.55, doc="spindle: radius at the waist / widest radius"),
        "ring_thickness": Param(0.12, 0.3, doc="ring: tube radius / ring radius"),
    }

    def _figure(self, p: dict[str, Any]) -> m3d.Manifold:
        z0, H = p["plinth_height"], p["height"]
        r = 0.5 * p["figure_width"] * p["plinth_width"]
        h = H - z0
        if p["figure"] == "stacked":
            out = _stones(p, z0, h, r)
            return m3d.Manifold.batch_boolean(out, m3d.OpType.Add)
        if p["figure"] == "spindle":
            return _spindle(p, z0, h, r)
        return _ring(p, z0, min(h, 2 * r))  # no wider than the figure

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The plinth and the figure on it (placeholder: the plinth and the figure's box)."""
        w, zb = p["plinth_width"], p["plinth_height"]
        if p["plinth"] == "round":
            base = cylinder(w / 2, zb, sections=SECTIONS, circumscribed=not detail)
        else:
            base = box((w, w, zb), (0.0, 0.0, zb / 2))
        fig = Part(self._figure(p), "sculpture")
        return [Part(base, "plinth"), fig if detail else bbox_part([fig], "sculpture")]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """A round plinth's disc as the `bottom` (a square plinth's is the box's)."""
        if p["plinth"] == "round":
            return [round_bottom("bottom", p["plinth_width"] / 2)]
        return []
