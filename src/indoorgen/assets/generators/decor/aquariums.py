"""Aquariums: a glass tank with gravel, water and a lid, alone or on a stand cabinet with doors."""
from __future__ import annotations

from typing import Any

import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import carcass
from indoorgen.assets.shapes.moving_parts import DOOR_OPEN, FRONT_PROUD, Front, cabinet_fronts, make_joint
from indoorgen.assets.shapes.primitives import SMALL_OVERLAP, Part, box_between
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


@register
class Aquarium(PartsFactory):
    """A glass aquarium: hollow tank (optionally with plastic trim at the top and bottom
    edges), a gravel bed, water filling it to a level, and a lid (a light hood or a glass cover)
    with a cut-out at the back for cables (so the air above the water is open, not a sealed
    void). Alone (on furniture) or on a matching stand cabinet with two doors. Its lid top is
    a support surface."""

    name = "aquarium"
    tags = frozenset({S.Object, S.Decor, S.Aquarium})
    size_class = "large"
    slots = ["glass", "water", "stone", "plastic", "wood", "front", "metal"]
    params = {
        "style": Param(kind="choice", choices=("tank", "on_stand"), doc="alone or on a stand"),
        "length": Param(0.4, 1.2, doc="Y extent of the tank (m)"),
        "depth": Param(0.25, 0.5, doc="X extent of the tank (m, at most 70% of the length)"),
        "tank_height": Param(0.25, 0.55, doc="glass height (m)"),
        "glass_thickness": Param(0.004, 0.01, doc="glass thickness (m)"),
        "water_level": Param(0.75, 0.92, doc="water height / tank height"),
        "gravel_depth": Param(0.02, 0.06, doc="gravel bed depth (m)"),
        "lid_style": Param(kind="choice", choices=("hood", "cover"), doc="light hood or glass cover"),
        "trim": Param(kind="bool", doc="plastic trim frames at the top and bottom edges"),
        "stand_height": Param(0.6, 0.8, doc="height of the stand's top (m)"),
    }

    def _dims(self, p):
        L = p["length"]
        Dt = min(p["depth"], 0.7 * L)
        z0 = p["stand_height"] if p["style"] == "on_stand" else 0.0
        return L, Dt, z0

    def _lid(self, p) -> tuple[float, float]:
        """(lid bottom, lid top) heights."""
        L, Dt, z0 = self._dims(p)
        zt = z0 + p["tank_height"]
        return zt - SMALL_OVERLAP, zt - SMALL_OVERLAP + (0.06 if p["lid_style"] == "hood" else 0.006)

    def _stand(self, p, detail) -> list[Part]:
        L, Dt, z0 = self._dims(p)
        Ws, Ds, t = L + 0.04, Dt + 0.04, 0.018
        zb = 0.06
        out = carcass(Ds, Ws, zb, z0, t, back=t)
        out.append(Part(box_between((-Ds / 2, -Ws / 2 + 0.01, 0.0), (Ds / 2 - 0.01, Ws / 2 - 0.01,
                                                                     zb + SMALL_OVERLAP)), "wood"))
        if detail:
            out += [q for parts, _ in self._fronts(p) for q in parts]
        else:
            out.append(Part(box_between((-Ds / 2 + t, -Ws / 2 + t, zb + t),
                                        (Ds / 2 + FRONT_PROUD, Ws / 2 - t, z0 - t)), "front"))
        return out

    def _fronts(self, p):
        L, Dt, z0 = self._dims(p)
        Ws, Ds, t, zb = L + 0.04, Dt + 0.04, 0.018, 0.06
        cells = [Front(-Ws / 2 + t, 0.0, zb + t, z0 - t, "left"),
                 Front(0.0, Ws / 2 - t, zb + t, z0 - t, "right")]
        return cabinet_fronts(Ds / 2, cells, Ds - 2 * t)

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """The stand doors' hinges (none for a tank alone)."""
        if p["style"] != "on_stand":
            return []
        return [make_joint(f"{m.link}_joint", m, 0.0, DOOR_OPEN) for _, m in self._fronts(p)]

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Stand (if any), glass tank, gravel, water, trims and the notched lid."""
        L, Dt, z0 = self._dims(p)
        H, g = p["tank_height"], p["glass_thickness"]
        zt = z0 + H
        lb, lt = self._lid(p)
        tr = 0.004 if p["trim"] else 0.0
        out = self._stand(p, detail) if p["style"] == "on_stand" else []
        if not detail:
            out.append(Part(box_between((-Dt / 2 - tr, -L / 2 - tr, z0), (Dt / 2 + tr, L / 2 + tr, lt)),
                            "glass"))
            return out
        zo = z0 - (SMALL_OVERLAP if p["style"] == "on_stand" else 0.0)  # 1 mm into the stand's top
        outer = box_between((-Dt / 2, -L / 2, zo), (Dt / 2, L / 2, zt))
        cavity = box_between((-Dt / 2 + g, -L / 2 + g, z0 + g), (Dt / 2 - g, L / 2 - g, zt + 0.01))
        out.append(Part(outer - cavity, "glass"))
        # gravel on the bottom glass, 1 mm clear of the walls; water joined to the front and side
        # walls, 1 mm above the gravel and 1 mm clear of the back wall: both stay visible through
        # the glass and the gap round the gravel opens to the air (no sealed void)
        zg = z0 + g + p["gravel_depth"]
        out.append(Part(box_between((-Dt / 2 + g + SMALL_OVERLAP, -L / 2 + g + SMALL_OVERLAP,
                                     z0 + g - SMALL_OVERLAP),
                                    (Dt / 2 - g - SMALL_OVERLAP, L / 2 - g - SMALL_OVERLAP, zg)), "stone"))
        zw = z0 + H * p["water_level"]
        out.append(Part(box_between((-Dt / 2 + g + SMALL_OVERLAP, -L / 2 + g - SMALL_OVERLAP,
                                     zg + SMALL_OVERLAP),
                                    (Dt / 2 - g + SMALL_OVERLAP, L / 2 - g + SMALL_OVERLAP, zw)), "water"))
        if tr:
            for za, zb in ((z0, z0 + 0.02), (zt - 0.02, zt)):
                ring = (box_between((-Dt / 2 - tr, -L / 2 - tr, za), (Dt / 2 + tr, L / 2 + tr, zb))
                        - box_between((-Dt / 2 + SMALL_OVERLAP, -L / 2 + SMALL_OVERLAP, za - 0.01),
                                      (Dt / 2 - SMALL_OVERLAP, L / 2 - SMALL_OVERLAP, zb + 0.01)))
                out.append(Part(ring, "plastic"))
        lid = box_between((-Dt / 2 - tr, -L / 2 - tr, lb), (Dt / 2 + tr, L / 2 + tr, lt))
        notch = box_between((-Dt / 2 - tr - 0.01, -0.3 * L, lb - 0.01),
                            (-Dt / 2 + g + 0.03, 0.3 * L, lt + 0.01))
        out.append(Part(lid - notch, "plastic" if p["lid_style"] == "hood" else "glass"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The lid's `top` and, on a stand, the cabinet floor behind its doors."""
        L, Dt, z0 = self._dims(p)
        _, lt = self._lid(p)
        x0, x1 = -Dt / 2 + p["glass_thickness"] + 0.04, Dt / 2 - 0.01
        out = [support_rect("top", ((x0 + x1) / 2, 0, lt), (x1 - x0) / 2, L / 2 - 0.01)]
        if p["style"] == "on_stand":  # the stand cabinet's floor, behind its doors
            Ws, Ds, t, zb = L + 0.04, Dt + 0.04, 0.018, 0.06
            out.append(Surface("interior_0", Subpart.Interior, np.array([t / 2, 0.0, zb + t]),
                               np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
                               sg.box(-Ds / 2 + 0.01, -Ws / 2 + t + 0.01, Ds / 2 - 0.01,
                                      Ws / 2 - t - 0.01)))
        return out
