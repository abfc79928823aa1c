"""What stands out on a kitchen counter in use: an electric kettle, a toaster, a knife block and
a crock of cooking utensils. Each is one rigid body; its placeholder is its bounding box."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import (
    OVERLAP,
    Part,
    bevel_box,
    box,
    box_between,
    cylinder,
    lathe,
    rod,
)
from indoorgen.assets.shapes.vessels import revolve_vessel
from indoorgen.model.tags import Semantics as S

#: the radius of a handle bar (m): a grip about 2 cm thick
GRIP = 0.011


class CounterThing(PartsFactory):
    """A countertop object whose placeholder is the box round its detailed parts."""

    size_class = "small"

    def solids(self, p: dict[str, Any]) -> list[Part]:
        """The detailed parts."""
        raise NotImplementedError

    def parts(self, p, detail):
        """The detailed parts, or the box round them (the placeholder)."""
        full = self.solids(p)
        if detail:
            return full
        lo, hi = bounds(full)
        return [Part(box_between(lo, hi), full[0].slot)]


def bounds(parts: list[Part]) -> tuple[np.ndarray, np.ndarray]:
    """The lower and upper corners of the box round `parts`."""
    boxes = np.array([q.solid.bounding_box() for q in parts])
    return boxes[:, :3].min(axis=0), boxes[:, 3:].max(axis=0)


# ------------------------------------------------------------------------------------ kettle
@register
class Kettle(CounterThing):
    """An electric kettle on its round power base: a lathed body narrowing to the lid, a knob
    on the lid, a spout to one side and a handle on the other side (a loop) or arching over the
    lid."""

    name = "kettle"
    tags = frozenset({S.Object, S.SmallObject, S.Kitchenware, S.Kettle})
    slots = ["appliance", "plastic", "metal"]
    material_choices = {"appliance": {"glossy_plastic": 2.0, "brushed_steel": 2.0, "painted_metal": 1.0}}
    params = {
        "radius": Param(0.065, 0.095, doc="body radius at its foot (m)"),
        "height": Param(0.15, 0.24, doc="body height above the base (m)"),
        "taper": Param(0.6, 0.95, doc="radius at the lid / radius at the foot"),
        "base_height": Param(0.012, 0.03, doc="height of the power base (m)"),
        "spout_length": Param(0.025, 0.06, doc="how far the spout reaches past the body (m)"),
        "handle": Param(kind="choice", choices=("side", "top"), doc="a side loop or a bail over the lid"),
        "knob_radius": Param(0.008, 0.016, doc="radius of the lid's knob (m)"),
    }

    def solids(self, p):
        """The power base, body, lid knob, spout and handle."""
        r, h, t, bh = p["radius"], p["height"], p["taper"], p["base_height"]
        z0, z1 = bh - OVERLAP, bh + h
        out = [Part(cylinder(r + 0.008, bh, (0.0, 0.0, 0.0), 32), "plastic"),
               Part(lathe([(0.0, z0), (r, z0), (r, z0 + 0.3 * h), (r * t, z1), (0.0, z1)], 32),
                    "appliance"),
               Part(cylinder(p["knob_radius"], 0.018, (0.0, 0.0, z1 - OVERLAP), 16), "plastic")]
        zs, ls = bh + 0.6 * h, p["spout_length"]
        rs = r + (r * t - r) * 0.3 / 0.7  # the body's radius at the spout
        out.append(Part(rod((0.0, -0.5 * rs, zs), (0.0, -(rs + ls), zs + 0.8 * ls), 0.012),
                        "appliance"))
        ri = 0.5 * r * t  # well inside the body at any height
        if p["handle"] == "side":
            y = r + 0.035
            lo, hi = bh + 0.25 * h, bh + 0.85 * h
            out += [Part(rod((0.0, ri, z), (0.0, y + GRIP, z), GRIP), "plastic") for z in (lo, hi)]
            out.append(Part(rod((0.0, y, lo - GRIP), (0.0, y, hi + GRIP), GRIP), "plastic"))
        else:
            top = z1 + 0.07
            out += [Part(rod((0.0, s * ri, z1 - 0.02), (0.0, s * ri, top + GRIP), GRIP), "plastic")
                    for s in (-1.0, 1.0)]
            out.append(Part(rod((0.0, -ri - GRIP, top), (0.0, ri + GRIP, top), GRIP), "plastic"))
        return out


# ----------------------------------------------------------------------------------- toaster
@register
class Toaster(CounterThing):
    """A pop-up toaster: a rounded box with one or two rows of bread slots in its top, a lever
    and a browning dial on its front, on four small feet."""

    name = "toaster"
    tags = frozenset({S.Object, S.SmallObject, S.Kitchenware, S.Toaster})
    slots = ["appliance", "plastic", "metal"]
    material_choices = {"appliance": {"glossy_plastic": 1.0, "brushed_steel": 2.0, "painted_metal": 1.5}}
    params = {
        "width": Param(0.26, 0.4, doc="Y extent of the body (m)"),
        "depth": Param(0.15, 0.22, doc="X extent of the body (m)"),
        "height": Param(0.17, 0.22, doc="Z extent of the body (m)"),
        "rows": Param(1, 2, kind="int", doc="rows of bread slots (two or four slices)"),
        "corner_radius": Param(0.008, 0.03, doc="rounding of the body's edges (m)"),
        "foot_height": Param(0.005, 0.015, doc="height of the feet (m)"),
        "lever_width": Param(0.02, 0.04, doc="width of the slot lever's tab (m)"),
    }

    def solids(self, p):
        """The body with its slots cut, the feet, the lever and the dial."""
        w, d, h, fh = p["width"], p["depth"], p["height"], p["foot_height"]
        rc = min(p["corner_radius"], 0.3 * d)
        body = bevel_box((d, w, h), (0.0, 0.0, fh + h / 2), rc, 2)
        rows, sw = p["rows"], 0.03
        for i in range(rows):
            x = (i - (rows - 1) / 2) * d / (rows + 0.6)
            body = body - box((sw, w - 2 * rc - 0.05, 0.12), (x, 0.0, fh + h - 0.05))
        out = [Part(body, "appliance")]
        out += [Part(cylinder(0.008, fh + OVERLAP, (sx * (d / 2 - 0.025), sy * (w / 2 - 0.025), 0.0),
                              12), "plastic")
                for sx in (-1, 1) for sy in (-1, 1)]
        lw, xf = p["lever_width"], d / 2
        out.append(Part(box_between((xf - OVERLAP, w / 4 - lw / 2, fh + 0.55 * h),
                                    (xf + 0.02, w / 4 + lw / 2, fh + 0.55 * h + 0.012)), "plastic"))
        out.append(Part(m3d.Manifold.cylinder(0.012, 0.012, 0.012, 16).rotate((0.0, 90.0, 0.0))
                        .translate((xf - OVERLAP, -w / 4, fh + 0.35 * h)), "metal"))
        return out


# ------------------------------------------------------------------------------- knife block
@register
class KnifeBlock(CounterThing):
    """A wooden knife block leaning back on its foot, the handles of its knives standing out of
    its top in a row."""

    name = "knife_block"
    tags = frozenset({S.Object, S.SmallObject, S.Kitchenware, S.KnifeBlock})
    slots = ["wood", "plastic"]
    params = {
        "width": Param(0.08, 0.14, doc="Y extent of the block (m)"),
        "depth": Param(0.1, 0.16, doc="X extent of the block's foot (m)"),
        "height": Param(0.2, 0.28, doc="height of the block along its slant (m)"),
        "tilt": Param(10.0, 25.0, doc="lean of the block back from vertical (degrees)"),
        "knives": Param(3, 6, kind="int", doc="knife handles in the block"),
        "handle_length": Param(0.08, 0.12, doc="length of a handle standing out (m)"),
        "handle_radius": Param(0.008, 0.012, doc="radius of a handle (m)"),
    }

    def solids(self, p):
        """The leaning block on a flat foot, and the handles along its top."""
        w, d, h, n = p["width"], p["depth"], p["height"], p["knives"]
        a = math.radians(p["tilt"])
        # a block whose front leans back: its section is the foot d deep, its top d*cos(a)
        # deep, shifted back by h*sin(a)
        sl, top = h * math.sin(a), h * math.cos(a)
        dt = d * 0.8
        section = m3d.CrossSection([np.array([(d / 2, 0.0), (d / 2 - sl, top),
                                              (d / 2 - sl - dt, top), (-d / 2, 0.0)])])
        block = m3d.Manifold.extrude(section, w).translate((0.0, 0.0, -w / 2)).rotate((90.0, 0.0, 0.0))
        out = [Part(block, "wood")]
        axis = np.array([-math.sin(a), 0.0, math.cos(a)])
        rad, ln = p["handle_radius"], p["handle_length"]
        for i in range(n):
            y = (i - (n - 1) / 2) * min(2.4 * rad, (w - 2 * rad - 0.01) / max(n - 1, 1))
            x = d / 2 - sl - dt / 2 + (i % 2 - 0.5) * 0.3 * dt
            base = np.array([x, y, top - 0.02])
            out.append(Part(rod(base, base + axis * (ln + 0.02), rad), "plastic"))
        return out


# ---------------------------------------------------------------------------- utensil crock
@register
class UtensilCrock(CounterThing):
    """A ceramic crock of cooking utensils: an open lathed pot, wooden spoons and spatulas
    standing in it and leaning out over its rim."""

    name = "utensil_crock"
    tags = frozenset({S.Object, S.SmallObject, S.Kitchenware, S.UtensilCrock})
    slots = ["ceramic", "wood"]
    params = {
        "radius": Param(0.05, 0.075, doc="radius of the crock's foot (m)"),
        "height": Param(0.12, 0.18, doc="height of the crock (m)"),
        "flare": Param(1.0, 1.25, doc="radius at the rim / radius at the foot"),
        "utensils": Param(3, 6, kind="int", doc="utensils standing in it"),
        "utensil_length": Param(0.26, 0.34, doc="length of a utensil (m)"),
        "lean": Param(6.0, 16.0, doc="how far the utensils lean out (degrees)"),
    }

    def solids(self, p):
        """The open crock and the utensils from its floor out over its rim."""
        r, h, n = p["radius"], p["height"], p["utensils"]
        rim = r * p["flare"]
        crock = revolve_vessel([(0.0, 0.0), (r, 0.0), (rim, h)], 0.006, 0.01, 32)
        out = [Part(crock.shell, "ceramic")]
        lean, ln = math.radians(p["lean"]), p["utensil_length"]
        for i in range(n):
            az = 2 * math.pi * i / n + 0.3
            d = np.array([math.cos(az) * math.sin(lean), math.sin(az) * math.sin(lean), math.cos(lean)])
            foot = np.array([0.2 * r * math.cos(az), 0.2 * r * math.sin(az), 0.01 - OVERLAP])
            tip = foot + d * ln
            out.append(Part(rod(foot, tip, 0.006, 8), "wood"))
            # a spoon's bowl or a spatula's blade at the top
            out.append(Part(box((0.012, 0.05, 0.07), (0.0, 0.0, 0.0))
                            .rotate((0.0, math.degrees(lean), math.degrees(az)))
                            .translate(tuple(tip + d * 0.03)), "wood"))
        return out
