"""The dishwasher: a built-in, under-counter dishwasher with a drop-down door and wire baskets.
Front faces +X.
"""
from __future__ import annotations

from typing import Any

import manifold3d as m3d

from indoorgen.assets.generators.appliances._parts import rack_surface, slotted_plate, wire_rack
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.cabinet_parts import HANDLE_PROUD, joint_for, open_shell, pull_bar
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, hinge_motion
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between, cylinder
from indoorgen.assets.shapes.surfaces import bottom_rect
from indoorgen.model.tags import Semantics as S

BASKET_T, BASKET_PITCH = 0.005, 0.03  # dishwasher basket bar thickness and pitch (m)
BASKET_GAP = 0.011  # clearance between a basket and the tub's side walls (m)


def _basket_floor(x0: float, x1: float, y0: float, y1: float) -> tuple[float, float, float, float]:
    """(x0, x1, y0, y1) of the floor of a basket running on rails that span y0..y1 (sunk into
    the tub's side walls)."""
    return x0, x1, y0 + BASKET_GAP, y1 - BASKET_GAP


def _basket_inside(x0: float, x1: float, y0: float, y1: float) -> tuple[float, float, float, float]:
    """(x0, x1, y0, y1) inside the walls of the basket on rails spanning y0..y1."""
    fx0, fx1, fy0, fy1 = _basket_floor(x0, x1, y0, y1)
    return fx0 + BASKET_T, fx1 - BASKET_T, fy0 + BASKET_T, fy1 - BASKET_T


def _basket(x0: float, x1: float, y0: float, y1: float, z_top: float, wall_h: float) -> m3d.Manifold:
    """A dishwasher basket: a grille floor whose top is at z_top with grille walls `wall_h`
    high round its edges, on two rails along X whose ends (y0, y1) sink into the tub's walls."""
    t = BASKET_T
    fx0, fx1, fy0, fy1 = _basket_floor(x0, x1, y0, y1)
    floor = wire_rack(fx0, fx1, fy0, fy1, z_top, t / 2, BASKET_PITCH)
    z0 = z_top - 0.001
    sides = [slotted_plate(fx1 - fx0, wall_h, t, 0.025,
                           0.004).rotate((90.0, 0.0, 0.0)).translate((fx0, y, z0))
             for y in (fy0 + t, fy1)]
    ends = [slotted_plate(fy1 - fy0, wall_h, t, 0.025,
                          0.004).rotate((90.0, 0.0, 90.0)).translate((x, fy0, z0))
            for x in (fx0, fx1 - t)]
    zr = z_top - t
    rails = [box_between((fx0 + 0.02, ya, zr - 0.006), (fx1 - 0.02, yb, zr + 0.001))
             for ya, yb in ((y0, fy0 + t), (fy1 - t, y1))]
    return m3d.Manifold.batch_boolean([floor] + sides + ends + rails, m3d.OpType.Add)


@register
class Dishwasher(PartsFactory):
    """A built-in dishwasher: a stainless tub in an under-counter cabinet on a recessed kick
    plate, a drop-down door (its own link, opening flat) with either a visible control strip
    (display and buttons on the front) or an integrated cabinet-panel front with the buttons
    on its top edge; bar or pocket handle. Two or three wire racks are `interior_i` surfaces."""

    name = "dishwasher"
    tags = frozenset({S.Object, S.Appliance, S.KitchenAppliance, S.Dishwasher})
    size_class = "large"
    slots = ["appliance", "metal", "plastic", "front", "screen"]
    solid_bottom = True
    params = {
        "width": Param(0.44, 0.6, doc="Y extent (m)"),
        "depth": Param(0.55, 0.62, doc="X extent of the cabinet without its door (m)"),
        "height": Param(0.8, 0.87, doc="Z extent (fits under a countertop) (m)"),
        "kick_height": Param(0.08, 0.14, doc="kick plate height under the door (m)"),
        "panel": Param(kind="choice", choices=("visible", "integrated"),
                       doc="control strip on the front, or a cabinet panel with top controls"),
        "handle": Param(kind="choice", choices=("bar", "pocket"), doc="bar handle or a pocket grip"),
        "door_thickness": Param(0.04, 0.07, doc="door thickness (m)"),
        "n_buttons": Param(3, 7, kind="int", doc="program buttons"),
        "third_rack": Param(kind="bool", doc="a cutlery tray near the top of the tub"),
    }

    WALL = 0.025

    def _tub(self, p) -> tuple[float, float, float, float, float, float]:
        D, W, H, zk, w = p["depth"], p["width"], p["height"], p["kick_height"], self.WALL
        return -D / 2 + w, D / 2, -W / 2 + w, W / 2 - w, zk + w, H - w

    def _racks(self, p) -> list[float]:
        _, _, _, _, z0, z1 = self._tub(p)
        out = [z0 + 0.05, z0 + 0.5 * (z1 - z0)]
        if p["third_rack"]:
            out.append(z1 - 0.06)
        return out

    def _door(self, p) -> tuple[list[Part], Any]:
        D, W, H, zk, dt = p["depth"], p["width"], p["height"], p["kick_height"], p["door_thickness"]
        x0, x1 = D / 2 + MOVING_GAP, D / 2 + MOVING_GAP + dt
        y0, y1, z0, z1 = -W / 2, W / 2, zk + 0.003, H
        visible = p["panel"] == "visible"
        leaf = box_between((x0, y0, z0), (x1, y1, z1))
        parts = [Part(leaf, "appliance" if visible else "front", "door"),
                 Part(box_between((x0 - 0.001, y0 + 0.03, z0 + 0.03), (x0 + 0.001, y1 - 0.03, z1 - 0.03)),
                      "metal", "door")]  # the stainless inner face
        nb = int(p["n_buttons"])
        if visible:
            sh = 0.09
            parts.append(Part(box_between((x1 - 0.001, y0, z1 - sh), (x1 + 0.002, y1, z1)), "plastic",
                              "door"))
            parts.append(Part(box_between((x1 + 0.001, y1 - 0.17, z1 - 0.06),
                                          (x1 + 0.003, y1 - 0.05, z1 - 0.03)),
                              "screen", "door"))
            for i in range(nb):
                yb = y0 + 0.05 + i * 0.035
                parts.append(Part(box_between((x1 + 0.001, yb, z1 - 0.06),
                                              (x1 + 0.005, yb + 0.022, z1 - 0.045)),
                                  "metal", "door"))
            zh = z1 - sh - 0.035
        else:  # buttons on the top edge of the door
            for i in range(nb):
                yb = y1 - 0.06 - i * 0.03
                parts.append(Part(box_between((x0 + 0.012, yb - 0.02, z1 - 0.002),
                                              (x0 + 0.028, yb, z1 + 0.002)),
                                  "plastic", "door"))
            zh = z1 - 0.06
        if p["handle"] == "bar":
            parts.append(Part(pull_bar(x1, (-min(0.2, 0.35 * W), zh), (min(0.2, 0.35 * W), zh),
                                       HANDLE_PROUD, 0.007, 12),
                              "metal", "door"))
        else:  # a pocket grip recessed into the top of the door
            parts[0] = Part(leaf - box_between((x1 - 0.025, -0.1, z1 - 0.03), (x1 + 0.01, 0.1, z1 + 0.01)),
                            parts[0].slot, "door")
        return parts, hinge_motion("bottom", x1, y0, y1, z0, z1, "door")

    def _proud(self, p) -> float:
        return MOVING_GAP + p["door_thickness"] + (HANDLE_PROUD if p["handle"] == "bar" else 0.005)

    def parts(self, p, detail):
        """The dishwasher's solids: detailed, or the blocks of its placeholder."""
        D, W, H, zk = p["depth"], p["width"], p["height"], p["kick_height"]
        top_extra = 0.002 if p["panel"] == "integrated" else 0.0
        if not detail:
            return [Part(box_between((-D / 2, -W / 2, zk), (D / 2, W / 2, H)), "appliance"),
                    Part(box_between((-D / 2, -W / 2 + 0.02, 0.0),
                                     (D / 2 - 0.06, W / 2 - 0.02, zk + OVERLAP)), "plastic"),
                    Part(box_between((D / 2 - 0.01, -W / 2, zk),
                                     (D / 2 + self._proud(p), W / 2, H + top_extra)),
                         "appliance")]
        tx0, tx1, ty0, ty1, tz0, tz1 = self._tub(p)
        out = [Part(open_shell((-D / 2, -W / 2, zk), (D / 2, W / 2, H), self.WALL), "appliance"),
               Part(open_shell((tx0 - 0.001, ty0 - 0.001, tz0 - 0.001),
                               (tx1 - 0.002, ty1 + 0.001, tz1 + 0.001), 0.003),
                    "metal"),
               Part(box_between((-D / 2, -W / 2 + 0.02, 0.0), (D / 2 - 0.06, W / 2 - 0.02, zk + OVERLAP)),
                    "plastic")]
        for i, zr in enumerate(self._racks(p)):
            wall_h = 0.1 if i == 0 else 0.07 if i == 1 else 0.03
            out.append(Part(_basket(*self._basket_extent(p), zr, wall_h), "metal"))
        # spray arm under the lower rack
        zs = self._racks(p)[0] - 0.025
        xc = (tx0 + tx1) / 2 - 0.01
        out.append(Part(cylinder(0.02, zs - tz0 + 0.001, (xc, 0.0, tz0 - 0.001), 16), "plastic"))
        out.append(Part(box_between((xc - 0.02, ty0 + 0.06, zs - 0.004),
                                    (xc + 0.02, ty1 - 0.06, zs + 0.006)), "plastic"))
        out += self._door(p)[0]
        return out

    def joints(self, p):
        """The dishwasher's joint: its drop-down door's."""
        return [joint_for(self._door(p)[1])]

    def extra_surfaces(self, p):
        """The dishwasher's surfaces besides its bounding box's: bottom, interior_<i> (baskets)."""
        D, W = p["depth"], p["width"]
        out = [bottom_rect((-0.03, 0, 0), D / 2 - 0.03, W / 2 - 0.02)]
        extent = self._basket_extent(p)
        for i, z in enumerate(self._racks(p)):
            out.append(rack_surface(f"interior_{i}", *_basket_floor(*extent), z, BASKET_T / 2, BASKET_PITCH,
                                    _basket_inside(*extent)))
        return out

    def _basket_extent(self, p) -> tuple[float, float, float, float]:
        """(x0, x1, y0, y1) of the baskets' floors (their ends sunk into the tub's walls)."""
        tx0, tx1, ty0, ty1, _, _ = self._tub(p)
        return tx0 + 0.02, tx1 - 0.04, ty0 - 0.001, ty1 + 0.001
