"""Laundry appliances: a front-loading washing machine. Front faces +X."""
from __future__ import annotations

from typing import Any

import manifold3d as m3d

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.cabinet_parts import joint_for, open_shell
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, hinge_motion, slide_motion
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box, box_between, cylinder, lathe, rod
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S


# ------------------------------------------------------------------------ washing machine
def _x_lathe(profile: list[tuple[float, float]], center: tuple[float, float, float],
             sections: int = 48, circumscribed: bool = False) -> m3d.Manifold:
    """A `lathe` of (radius, axial) points turned about the +X axis through `center` (axial
    0 at center's x)."""
    return lathe(profile, sections, circumscribed).rotate((0.0, 90.0, 0.0)).translate(center)


@register
class WashingMachine(PartsFactory):
    """A front-loading washing machine on four feet: a porthole door (a ring with a domed
    glass, hinged at its left or right edge) in front of a steel drum with lifters behind a
    rubber gasket, a control panel across the top with a program knob, buttons and an
    optional display, and a detergent drawer (prismatic) on the panel's other side. `top` is
    a support surface."""

    name = "washing_machine"
    tags = frozenset({S.Object, S.Appliance, S.WashingMachine})
    size_class = "large"
    slots = ["appliance", "metal", "rubber", "glass", "plastic", "screen"]
    params = {
        "width": Param(0.55, 0.62, doc="Y extent (m)"),
        "depth": Param(0.45, 0.62, doc="X extent of the cabinet (m)"),
        "height": Param(0.82, 0.87, doc="Z extent (m)"),
        "door_radius": Param(0.17, 0.24, doc="outer radius of the porthole door (m; capped by the front)"),
        "door_style": Param(kind="choice", choices=("chrome", "white", "dark"), doc="door ring finish"),
        "panel_height": Param(0.1, 0.16, doc="height of the control panel band (m)"),
        "display": Param(kind="bool", doc="a display on the control panel"),
        "knob_side": Param(kind="choice", choices=("right", "left"),
                           doc="side of the program knob (the drawer goes on the other)"),
        "foot_height": Param(0.01, 0.03, doc="height of the feet (m)"),
        "n_buttons": Param(2, 6, kind="int", doc="buttons on the panel"),
    }

    DOOR_DEPTH = 0.045

    def _door_geom(self, p) -> tuple[float, float, float]:
        """(radius, centre z, centre y) of the door."""
        W, H, ph, fh = p["width"], p["height"], p["panel_height"], p["foot_height"]
        zlo, zhi = fh + 0.06, H - ph - 0.03
        R = min(p["door_radius"], (zhi - zlo) / 2, W / 2 - 0.05)
        return R, (zlo + zhi) / 2, 0.0

    def _door(self, p) -> tuple[list[Part], Any]:
        D = p["depth"]
        R, zc, yc = self._door_geom(p)
        x0 = D / 2 + MOVING_GAP
        dd = self.DOOR_DEPTH
        style = p["door_style"]
        rg = R * {"chrome": 0.72, "white": 0.64, "dark": 0.8}[style]  # glass radius
        ring_slot = {"chrome": "metal", "white": "appliance", "dark": "plastic"}[style]
        if style == "chrome":  # a rounded bezel
            prof = [(rg, 0.0), (R, 0.0), (R, dd * 0.55), (R - 0.015, dd * 0.85), (rg + 0.01, dd * 0.7),
                    (rg, dd * 0.5)]
        elif style == "white":  # a wide flat ring
            prof = [(rg, 0.0), (R, 0.0), (R, dd * 0.6), (R - 0.006, dd * 0.66), (rg, dd * 0.66)]
        else:  # a slim ring round a big smoked dome
            prof = [(rg, 0.0), (R, 0.0), (R, dd * 0.4), (R - 0.01, dd * 0.5), (rg, dd * 0.45)]
        ring = _x_lathe(prof, (x0, yc, zc), 64)
        a = prof[-1][1] - 0.002
        glass = _x_lathe([(0.0, 0.004), (rg + 0.002, 0.004), (rg + 0.002, a),
                          (rg * 0.6, (a + dd) / 2 + 0.004),
                          (0.0, dd)], (x0, yc, zc), 64)
        hinge = "left" if p["knob_side"] == "right" else "right"
        sgn = 1.0 if hinge == "left" else -1.0  # the grip is on the free side
        grip = box_between((x0 + 0.005, yc + sgn * (R - 0.03) - 0.02, zc - 0.05),
                           (x0 + dd * 0.55 + 0.012, yc + sgn * (R - 0.03) + 0.02, zc + 0.05))
        parts = [Part(ring, ring_slot, "door"), Part(glass, "glass", "door"), Part(grip, "plastic", "door")]
        return parts, hinge_motion(hinge, x0 + dd, yc - R, yc + R, zc - R, zc + R, "door")

    def _drawer(self, p) -> tuple[list[Part], Any, tuple]:
        D, W, H, ph = p["depth"], p["width"], p["height"], p["panel_height"]
        dw = min(0.2, W * 0.33)
        s = -1.0 if p["knob_side"] == "right" else 1.0
        y0, y1 = (-W / 2 + 0.03, -W / 2 + 0.03 + dw) if s < 0 else (W / 2 - 0.03 - dw, W / 2 - 0.03)
        z0, z1 = H - ph + 0.015, H - 0.02
        fx = D / 2
        x0, x1 = fx + MOVING_GAP, fx + MOVING_GAP + 0.012
        front = box_between((x0, y0, z0), (x1, y1, z1))
        lip = box_between((x1 - 0.001, y0 + 0.02, z0), (x1 + 0.012, y1 - 0.02, z0 + 0.01))
        depth = min(0.3, D - 0.15)
        tray = open_shell((fx - depth, y0 + 0.004, z0 + 0.004), (x0 + 0.001, y1 - 0.004, z1 - 0.01), 0.003,
                          open_top=True)
        parts = [Part(front, "appliance", "drawer"), Part(lip, "plastic", "drawer"),
                 Part(tray, "plastic", "drawer")]
        cavity = box_between((fx - depth - 0.01, y0, z0), (fx + 0.01, y1, z1))
        return parts, slide_motion("drawer", (x1, (y0 + y1) / 2, z0)), (cavity, 0.8 * depth)

    def parts(self, p, detail):
        """The washing machine's solids: detailed, or the blocks of its placeholder."""
        D, W, H, ph, fh = p["depth"], p["width"], p["height"], p["panel_height"], p["foot_height"]
        R, zc, yc = self._door_geom(p)
        s = 1.0 if p["knob_side"] == "right" else -1.0
        yk = s * (W / 2 - 0.09)
        zk = H - ph / 2
        if not detail:
            return [Part(box_between((-D / 2, -W / 2, 0.0), (D / 2, W / 2, H)), "appliance"),
                    Part(box_between((D / 2 - 0.01, yc - R, zc - R),
                                     (D / 2 + MOVING_GAP + self.DOOR_DEPTH, yc + R, zc + R)),
                         "appliance"),
                    Part(box_between((D / 2 - 0.01, min(yk - 0.035, -W / 2 + 0.03), H - ph),
                                     (D / 2 + 0.04, max(yk + 0.035, W / 2 - 0.03), H)), "plastic")]
        drawer, _, (dcav, _) = self._drawer(p)
        ro = R * 0.72  # drum opening radius behind the door glass
        L = min(0.35, D - 0.12)
        body = box_between((-D / 2, -W / 2, fh), (D / 2, W / 2, H))
        opening = _x_lathe([(0.0, -L), (ro, -L), (ro, 0.01), (0.0, 0.01)], (D / 2, yc, zc), 48)
        out = [Part(m3d.Manifold.batch_boolean([body, opening, dcav], m3d.OpType.Subtract), "appliance")]
        # gasket at the mouth, steel drum behind it with three lifters
        out.append(Part(_x_lathe([(ro - 0.03, -0.06), (ro + 0.001, -0.06), (ro + 0.001, -0.002),
                                  (ro - 0.01, -0.002),
                                  (ro - 0.03, -0.02)], (D / 2, yc, zc), 48), "rubber"))
        drum = _x_lathe([(0.0, -L - 0.001), (ro + 0.001, -L - 0.001), (ro + 0.001, -0.059),
                         (ro - 0.004, -0.059),
                         (ro - 0.004, -L + 0.004), (0.0, -L + 0.004)], (D / 2, yc, zc), 48)
        out.append(Part(drum, "metal"))
        for k in range(3):
            lifter = box((L - 0.08, 0.035, 0.035), (0.0, 0.0, ro - 0.02)).rotate((120.0 * k, 0.0, 0.0))
            out.append(Part(lifter.translate((D / 2 - L / 2 - 0.03, yc, zc)), "metal"))
        # control panel: knob with a skirt, then buttons and display towards the drawer
        out.append(Part(rod((D / 2 - 0.001, yk, zk), (D / 2 + 0.012, yk, zk), 0.035, 32), "plastic"))
        out.append(Part(rod((D / 2 + 0.011, yk, zk), (D / 2 + 0.04, yk, zk), 0.025, 32), "metal"))
        for y0, y1, slot in self._panel_items(p):
            h = 0.018 if slot == "screen" else 0.008
            out.append(Part(box_between((D / 2 - 0.001, y0, zk - h),
                                        (D / 2 + (0.002 if slot == "screen" else 0.005), y1, zk + h)),
                            slot))
        for sx in (-1, 1):  # feet
            for sy in (-1, 1):
                out.append(Part(cylinder(0.022, fh + OVERLAP,
                                         (sx * (D / 2 - 0.05), sy * (W / 2 - 0.05), 0.0), 16),
                                "rubber"))
        out += self._door(p)[0] + drawer
        return out

    def _panel_items(self, p) -> list[tuple[float, float, str]]:
        """(y0, y1, slot) of the buttons and the display, laid out from the knob towards the
        drawer; as many of `n_buttons` as fit."""
        W = p["width"]
        s = 1.0 if p["knob_side"] == "right" else -1.0
        start = s * (W / 2 - 0.09 - 0.05)             # past the knob's skirt
        end = -s * (W / 2 - 0.03 - min(0.2, W * 0.33) - 0.02)  # before the drawer
        room = abs(start - end)
        items = []
        pos = 0.0
        if p["display"] and room >= 0.1:
            items.append((pos, pos + 0.08, "screen"))
            pos += 0.1
        for _ in range(int(p["n_buttons"])):
            if pos + 0.02 > room:
                break
            items.append((pos, pos + 0.02, "plastic"))
            pos += 0.03
        return [(min(start - s * a, start - s * b), max(start - s * a, start - s * b), slot)
                for a, b, slot in items]

    def joints(self, p):
        """The washing machine's joints: the porthole door's and the detergent drawer's."""
        _, m, (_, slide) = self._drawer(p)
        return [joint_for(self._door(p)[1]), joint_for(m, slide=slide)]

    def extra_surfaces(self, p):
        """The washing machine's surfaces besides its bounding box's: top."""
        D, W, H = p["depth"], p["width"], p["height"]
        return [support_rect("top", (0, 0, H), D / 2 - 0.02, W / 2 - 0.02)]
