"""The microwave: a countertop microwave oven. Front faces +X."""
from __future__ import annotations

from typing import Any

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.cabinet_parts import joint_for, pull_bar, window_leaf
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, hinge_motion, knob
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, box_between, circle_polygon, cylinder
from indoorgen.assets.shapes.surfaces import support_polygon, support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


# ------------------------------------------------------------------------------ microwave
@register
class Microwave(PartsFactory):
    """A countertop microwave: a rounded box on four small feet, a side-hinged door (left)
    with a window over most of the front, a control panel on the right with a display and a
    keypad or two knobs, a bar handle or a door-release button, and a glass turntable in the
    cavity (`interior_0`). `top` is a support surface."""

    name = "microwave"
    tags = frozenset({S.Object, S.Appliance, S.KitchenAppliance, S.Microwave})
    size_class = "medium"
    slots = ["appliance", "plastic", "glass", "metal", "screen", "rubber"]
    params = {
        "width": Param(0.44, 0.6, doc="Y extent (m)"),
        "depth": Param(0.32, 0.45, doc="X extent of the body (m)"),
        "height": Param(0.25, 0.34, doc="Z extent (m)"),
        "door_frac": Param(0.68, 0.78, doc="door width / body width"),
        "controls": Param(kind="choice", choices=("keypad", "knobs"), doc="keypad or two dials"),
        "handle": Param(kind="choice", choices=("bar", "button"), doc="door handle or release button"),
        "window_frac": Param(0.55, 0.8, doc="window width / door width"),
        "corner_radius": Param(0.003, 0.02, doc="rounding of the body's edges (m)"),
        "foot_height": Param(0.008, 0.02, doc="height of the feet (m)"),
    }

    DOOR_T = 0.03
    WALL = 0.02

    def _cavity(self, p) -> tuple[float, float, float, float, float, float]:
        D, W, H, fh, w = p["depth"], p["width"], p["height"], p["foot_height"], self.WALL
        yd = -W / 2 + W * p["door_frac"]
        return -D / 2 + w, D / 2, -W / 2 + w, yd - 0.02, fh + w, H - w

    def _door(self, p) -> tuple[list[Part], Any]:
        D, W, H, fh = p["depth"], p["width"], p["height"], p["foot_height"]
        y0, y1 = -W / 2, -W / 2 + W * p["door_frac"] - 0.003
        z0, z1 = fh + 0.003, H - 0.003
        x0, x1 = D / 2 + MOVING_GAP, D / 2 + MOVING_GAP + self.DOOR_T
        dw = y1 - y0
        ww = dw * p["window_frac"]
        bl = 0.04
        border = (bl, dw - bl - ww, 0.05, 0.05)
        parts = window_leaf(x0, x1, y0, y1, z0, z1, border, "door", "plastic")
        if p["handle"] == "bar":
            yh = y1 - 0.025
            parts.append(Part(pull_bar(x1, (yh, z0 + 0.04), (yh, z1 - 0.04), 0.03, 0.008, 12), "metal",
                              "door"))
        return parts, hinge_motion("left", x1, y0, y1, z0, z1, "door")

    def _proud(self, p) -> float:
        """How far the door, its handle or the dials stand in front of the body (m)."""
        extra = max(0.03 if p["handle"] == "bar" else 0.0, 0.015 if p["controls"] == "knobs" else 0.0)
        return MOVING_GAP + self.DOOR_T + extra

    def parts(self, p, detail):
        """The microwave's solids: detailed, or the blocks of its placeholder."""
        D, W, H, fh = p["depth"], p["width"], p["height"], p["foot_height"]
        if not detail:
            return [Part(box_between((-D / 2, -W / 2, fh), (D / 2, W / 2, H)), "appliance"),
                    Part(box_between((D / 2 - 0.01, -W / 2, fh), (D / 2 + self._proud(p), W / 2, H)),
                         "appliance"),
                    Part(box_between((-D / 2 + 0.03, -W / 2 + 0.03, 0.0),
                                     (D / 2 - 0.03, W / 2 - 0.03, fh + OVERLAP)),
                         "rubber")]
        cx0, cx1, cy0, cy1, cz0, cz1 = self._cavity(p)
        r = min(p["corner_radius"], 0.3 * (H - fh))
        shell = bevel_box((D, W, H - fh), (0.0, 0.0, (H + fh) / 2), r, 2)
        out = [Part(shell - box_between((cx0, cy0, cz0), (cx1 + 0.01, cy1, cz1)), "appliance")]
        # the control panel: a plate flush with the door, display, keypad or dials
        yd = -W / 2 + W * p["door_frac"]
        xp = D / 2 + MOVING_GAP + self.DOOR_T - 0.006
        out.append(Part(box_between((D / 2 - 0.001, yd, fh + 0.01), (xp, W / 2 - r, H - 0.01)), "plastic"))
        pw = W / 2 - r - yd
        yc = (yd + W / 2 - r) / 2
        out.append(Part(box_between((xp - 0.001, yc - 0.35 * pw, H - 0.065),
                                    (xp + 0.002, yc + 0.35 * pw, H - 0.035)),
                        "screen"))
        if p["controls"] == "keypad":
            ph = H - 0.1 - fh - 0.06
            for i in range(3):
                for j in range(4):
                    yb = yc + (i - 1) * 0.28 * pw
                    zb = H - 0.09 - (j + 0.5) * ph / 4
                    out.append(Part(box_between((xp - 0.001, yb - 0.1 * pw, zb - 0.009),
                                                (xp + 0.003, yb + 0.1 * pw, zb + 0.009)),
                                    "metal"))
        else:
            for zk in (H - 0.11, H - 0.19):
                if zk - 0.025 > fh + 0.05:
                    out.append(Part(knob((xp - 0.001, yc, zk), min(0.022, 0.3 * pw), 0.022), "metal"))
        if p["handle"] == "button":
            out.append(Part(box_between((xp - 0.001, yc - 0.3 * pw, fh + 0.03),
                                        (xp + 0.005, yc + 0.3 * pw, fh + 0.06)),
                            "metal"))
        # turntable on a hub
        rt = min(cx1 - cx0, cy1 - cy0) / 2 - 0.015
        tc = ((cx0 + cx1) / 2 - 0.01, (cy0 + cy1) / 2)
        out.append(Part(cylinder(0.02, 0.012, (tc[0], tc[1], cz0 - 0.001), 16), "plastic"))
        out.append(Part(cylinder(rt, 0.006, (tc[0], tc[1], cz0 + 0.01), 48), "glass"))
        for sx in (-1, 1):
            for sy in (-1, 1):
                out.append(Part(cylinder(0.012, fh + OVERLAP,
                                         (sx * (D / 2 - 0.04), sy * (W / 2 - 0.04), 0.0), 12),
                                "rubber"))
        out += self._door(p)[0]
        return out

    def joints(self, p):
        """The microwave's joint: its door's."""
        return [joint_for(self._door(p)[1])]

    def extra_surfaces(self, p):
        """The microwave's surfaces besides its bounding box's: top, interior_0 (turntable)."""
        D, W, H, fh = p["depth"], p["width"], p["height"], p["foot_height"]
        cx0, cx1, cy0, cy1, cz0, _ = self._cavity(p)
        r = min(p["corner_radius"], 0.3 * (H - fh))
        rt = min(cx1 - cx0, cy1 - cy0) / 2 - 0.015
        tc = ((cx0 + cx1) / 2 - 0.01, (cy0 + cy1) / 2, cz0 + 0.016)
        return [support_rect("top", (0, 0, H), D / 2 - r - 0.01, W / 2 - r - 0.01),
                support_polygon("interior_0", tc, circle_polygon(rt - 0.01, 48), subpart=Subpart.Interior)]
