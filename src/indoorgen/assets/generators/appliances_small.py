"""Small appliances and electronics on worktops and desks: microwaves and computer monitors.
Fronts face +X."""
from __future__ import annotations

from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.base import Param, register
from indoorgen.assets.generators._kitchen_common import (
    OVERLAP,
    hinge_motion,
    joint_for,
    pull_bar,
    window_leaf,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, knob
from indoorgen.assets.shapes.primitives import Part, bevel_box, box, box_between, circle_polygon, cylinder
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
        dw, dh = y1 - y0, z1 - z0
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
        return [joint_for(self._door(p)[1])]

    def extra_surfaces(self, p):
        D, W, H, fh = p["depth"], p["width"], p["height"], p["foot_height"]
        cx0, cx1, cy0, cy1, cz0, _ = self._cavity(p)
        r = min(p["corner_radius"], 0.3 * (H - fh))
        rt = min(cx1 - cx0, cy1 - cy0) / 2 - 0.015
        tc = ((cx0 + cx1) / 2 - 0.01, (cy0 + cy1) / 2, cz0 + 0.016)
        return [support_rect("top", (0, 0, H), D / 2 - r - 0.01, W / 2 - r - 0.01),
                support_polygon("interior_0", tc, circle_polygon(rt - 0.01, 48), subpart=Subpart.Interior)]


# ------------------------------------------------------------------------------- monitor
ASPECTS = {"16:9": 9 / 16, "16:10": 10 / 16, "21:9": 9 / 21}


@register
class Monitor(PartsFactory):
    """A computer monitor: a thin panel (glass screen on its front, a tapered housing bulge on
    its back) tilted back on a neck, on a rectangular plate, a round disc or a V of two feet."""

    name = "monitor"
    tags = frozenset({S.Object, S.Electronics, S.Monitor})
    size_class = "medium"
    slots = ["plastic", "screen", "metal"]
    params = {
        "screen_width": Param(0.45, 0.85, doc="panel Y extent (m), ~20-38 inch"),
        "aspect": Param(kind="choice", choices=tuple(ASPECTS), doc="panel aspect ratio"),
        "panel_thickness": Param(0.012, 0.03, doc="panel X extent (m)"),
        "bezel": Param(0.004, 0.02, doc="border around the screen (m)"),
        "base_style": Param(kind="choice", choices=("rect", "round", "v"), doc="stand base shape"),
        "base_depth": Param(0.15, 0.25, doc="X extent of the stand base (m)"),
        "clearance": Param(0.05, 0.15, doc="height of the panel's lower edge above the base (m)"),
        "tilt": Param(0.0, 10.0, doc="backwards tilt of the panel (degrees)"),
        "bulge": Param(0.015, 0.05, doc="depth of the housing bulge behind the panel (m)"),
    }

    BASE_T = 0.012

    def _panel_frame(self, p) -> tuple[float, float, float, np.ndarray]:
        """(panel height, z of its centre, x of the neck, pivot) of the untilted panel."""
        W, th = p["screen_width"], p["panel_thickness"]
        Hs = W * ASPECTS[p["aspect"]] + 2 * p["bezel"]
        zc = self.BASE_T + p["clearance"] + Hs / 2
        xn = -th / 2 - p["bulge"] * 0.5
        return Hs, zc, xn, np.array([xn, 0.0, zc])

    def _tilted(self, solid: m3d.Manifold, pivot: np.ndarray, tilt: float) -> m3d.Manifold:
        return solid.translate(tuple(-pivot)).rotate((0.0, -tilt, 0.0)).translate(tuple(pivot))

    def parts(self, p, detail):
        W, th, bz, bd = p["screen_width"], p["panel_thickness"], p["bezel"], p["base_depth"]
        Hs, zc, xn, pivot = self._panel_frame(p)
        tilt, bg = p["tilt"], p["bulge"]
        panel = (bevel_box((th, W, Hs), (0, 0, zc), min(0.004, th / 3), 1) if detail
                 else box_between((-th / 2, -W / 2, zc - Hs / 2), (th / 2 + 0.001, W / 2, zc + Hs / 2)))
        ends = ((-th / 2 + 0.001, 0.6 * W, 0.6 * Hs), (-th / 2 - bg, 0.3 * W, 0.35 * Hs))
        hump = m3d.Manifold.hull_points(np.array(
            [(x, sy * w / 2, zc + sz * h / 2) for x, w, h in ends for sy in (-1, 1) for sz in (-1, 1)]))
        out = [Part(self._tilted(panel, pivot, tilt), "plastic"),
               Part(self._tilted(hump, pivot, tilt), "plastic")]
        glass = box_between((th / 2 - 0.002, -W / 2 + bz, zc - Hs / 2 + bz),
                            (th / 2 + 0.001, W / 2 - bz, zc + Hs / 2 - bz))
        if detail:
            out.append(Part(self._tilted(glass, pivot, tilt), "screen"))
        # neck from the base up into the hump
        nw = 0.05
        out.append(Part(box_between((xn - 0.012, -nw / 2, self.BASE_T - 0.001),
                                    (xn + 0.012, nw / 2, zc + 0.03)), "metal"))
        xb0, xb1 = xn - 0.3 * bd, xn + 0.7 * bd
        style = p["base_style"]
        if style == "rect":
            bw = min(0.3, 0.45 * W)
            base = (bevel_box((bd, bw, self.BASE_T), ((xb0 + xb1) / 2, 0, self.BASE_T / 2), 0.005,
                              2) if detail
                    else box((bd, bw, self.BASE_T), ((xb0 + xb1) / 2, 0, self.BASE_T / 2)))
            out.append(Part(base, "metal"))
        elif style == "round":
            out.append(Part(cylinder(bd / 2, self.BASE_T, ((xb0 + xb1) / 2, 0, 0), 48 if detail else 12,
                                     radius_top=None, circumscribed=not detail), "metal"))
        else:  # two feet splayed forward from the neck
            spread = min(0.35, 0.5 * W) / 2
            for s in (-1, 1):
                foot = m3d.Manifold.hull_points(np.array(
                    [(x, y + dy, z) for x, y in ((xn - 0.02, 0.0), (xb1, s * spread))
                     for dy in (-0.015, 0.015) for z in (0.0, self.BASE_T)]))
                out.append(Part(foot, "metal"))
        return out
