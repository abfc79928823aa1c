"""Storage jars: hollow glass bodies with a screw or domed lid that lifts off."""
from __future__ import annotations

import math

import manifold3d as m3d
import numpy as np

from indoorgen.assets.generators.kitchenware._parts import LID_GAP
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.moving_parts import DoorJoint, make_joint
from indoorgen.assets.shapes.primitives import Part, cylinder, lathe
from indoorgen.assets.shapes.vessels import (
    SECTIONS,
    cheap_cylinder,
    interior_floor,
    revolve_vessel,
    round_bottom,
)
from indoorgen.model.tags import Semantics as S

JAR_SHAPES = ("cylinder", "mason", "round", "octagonal")


@register
class Jar(PartsFactory):
    """A storage jar: cylindrical, mason (square shoulder), round (bulbous) or octagonal body,
    hollow and open at a neck; a screw lid or a domed lid with a knob sits over the neck on its
    own link ("lid"), lifting straight off (prismatic joint along +Z)."""

    name = "jar"
    tags = frozenset({S.Object, S.SmallObject, S.Kitchenware, S.Container, S.Jar})
    size_class = "small"
    slots = ["glass", "metal", "plastic"]
    material_choices = {"glass": {"clear_glass": 4.0, "frosted_glass": 0.5},
                        "metal": {"painted_metal": 3.0, "brushed_steel": 1.5, "brass": 0.5}}
    solid_bottom = True
    params = {
        "radius": Param(0.035, 0.06, doc="body radius (m)"),
        "height": Param(0.07, 0.18, doc="height of the glass up to the rim (m)"),
        "shape": Param(kind="choice", choices=JAR_SHAPES, doc="body shape"),
        "neck_frac": Param(0.7, 0.95, doc="neck radius / body radius"),
        "shoulder_frac": Param(0.06, 0.2, doc="shoulder height / height"),
        "wall_thickness": Param(0.002, 0.004, doc="glass wall thickness (m)"),
        "lid_style": Param(kind="choice", choices=("screw", "dome"), doc="lid kind"),
        "lid_height": Param(0.008, 0.02, doc="lid skirt length (m)"),
    }

    def _sections(self, p) -> int:
        return 8 if p["shape"] == "octagonal" else SECTIONS

    def _dims(self, p) -> tuple[float, float, float]:
        """(neck radius, neck bottom z, shoulder bottom z)."""
        H = p["height"]
        rn = p["radius"] * p["neck_frac"]
        neck_z = H - p["lid_height"] - 0.004
        return rn, neck_z, neck_z - p["shoulder_frac"] * H

    def _outer(self, p) -> list[tuple[float, float]]:
        R, H = p["radius"], p["height"]
        rn, neck_z, sz = self._dims(p)
        c = 0.003
        if p["shape"] == "round":
            t = np.linspace(0.0, 1.0, 11)
            zs = c + (neck_z - c) * t
            rs = 0.75 * R + 0.25 * R * np.sin(math.pi * np.minimum(t * 1.15, 1.0)) ** 0.7
            rs = np.maximum(rs, rn)
            body = list(zip(rs.tolist(), zs.tolist(), strict=True))
            body[-1] = (rn, neck_z)
        else:
            a = 3.0 if p["shape"] == "mason" else 1.8
            t = np.linspace(0.0, 1.0, 8)
            rs = rn + (R - rn) * (1.0 - t ** a) ** (1.0 / a)
            body = [(R, c)] + list(zip(rs.tolist(), (sz + (neck_z - sz) * t).tolist(), strict=True))
        r0 = body[0][0]
        return [(0.0, 0.0), (r0 - c, 0.0)] + body + [(rn, H)]

    def _lid(self, p) -> list[m3d.Manifold]:
        rn, _, _ = self._dims(p)
        H, sk, n = p["height"], p["lid_height"], self._sections(p)
        ri, t = rn + LID_GAP, 0.0015
        ro = ri + t
        zt = H + LID_GAP + 0.002
        prof = [(0.0, H + LID_GAP), (ri, H + LID_GAP), (ri, H - sk), (ro, H - sk), (ro, zt)]
        if p["lid_style"] == "dome":
            dome = [(ro * (1 - u), zt + 0.35 * ro * math.sin(math.pi / 2 * u) * 0.4)
                    for u in np.linspace(0.0, 1.0, 6)[1:]]
            lid = lathe(prof + dome, n)
            top = zt + 0.14 * ro
            knob = [cylinder(0.006, 0.008, (0, 0, top - 0.002), 16),
                    cylinder(0.011, 0.005, (0, 0, top + 0.005), 16)]
            return [lid] + knob
        return [lathe(prof + [(0.0, zt)], n)]

    def lid_top(self, p) -> float:
        """Height of the lid's top (the knob of a domed lid) above the jar's underside (m)."""
        rn = self._dims(p)[0]
        zt = p["height"] + LID_GAP + 0.002
        return zt + (0.14 * (rn + LID_GAP + 0.0015) + 0.011 if p["lid_style"] == "dome" else 0.0)

    def parts(self, p, detail):
        """The jar's solids: detailed, or the blocks of its placeholder."""
        rn = self._dims(p)[0]
        lid_slot = "metal" if p["lid_style"] == "screw" else "glass"
        if not detail:
            r = max(max(q[0] for q in self._outer(p)), rn + LID_GAP + 0.0015)
            return [cheap_cylinder(r, 0.0, self.lid_top(p), "glass")]
        v = revolve_vessel(self._outer(p), p["wall_thickness"], 0.006, self._sections(p))
        return [Part(v.shell, "glass")] + [Part(s, lid_slot, "lid") for s in self._lid(p)]

    def joints(self, p):
        """The jar's joint: its lid lifting off."""
        lift = DoorJoint("prismatic", np.array([0.0, 0.0, 1.0]),
                         np.array([0.0, 0.0, p["height"]]), "lid")
        return [make_joint("lid", lift, 0.0, 0.08)]

    def extra_surfaces(self, p):
        """The jar's surfaces besides its bounding box's: bottom, interior."""
        n = self._sections(p)
        v = revolve_vessel(self._outer(p), p["wall_thickness"], 0.006, n)
        return [round_bottom("bottom", self._outer(p)[1][0], n),
                interior_floor("interior", v.floor_z, v.floor_r, n)]
