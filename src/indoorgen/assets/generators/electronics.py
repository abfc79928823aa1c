"""Electronics: flat TVs on a pedestal or feet, laptops (the lid on a hinge joint) and TV remotes."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, DoorJoint, make_joint
from indoorgen.assets.shapes.primitives import (
    OVERLAP,
    SMALL_OVERLAP,
    Part,
    bevel_box,
    box,
    box_between,
    cylinder,
    lathe,
)
from indoorgen.assets.shapes.surfaces import bottom_rect, support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

ASPECTS = {"16:9": 9 / 16, "21:9": 9 / 21}


@register
class TV(PartsFactory):
    """A flat TV: a thin panel (with a glass screen on its front) standing on a pedestal or on
    two feet."""

    name = "tv"
    tags = frozenset({S.Object, S.Electronics, S.TV})
    size_class = "medium"
    slots = ["plastic", "screen", "metal"]
    params = {
        "screen_width": Param(0.8, 1.6, doc="panel Y extent (m), ~36-72 inch diagonal"),
        "aspect": Param(kind="choice", choices=tuple(ASPECTS), doc="panel aspect ratio"),
        "thickness": Param(0.025, 0.08, doc="panel X extent (m)"),
        "bezel": Param(0.005, 0.02, doc="border around the glass (m)"),
        "stand_style": Param(kind="choice", choices=("pedestal", "feet"), doc="stand type"),
        "foot_depth": Param(0.18, 0.3, doc="X extent of the stand (m)"),
        "foot_width_frac": Param(0.25, 0.5, doc="pedestal base width / panel width"),
        "clearance": Param(0.03, 0.1, doc="gap between the stand's base and the panel (m)"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Panel, glass screen and a pedestal or two feet."""
        W, th, bz = p["screen_width"], p["thickness"], p["bezel"]
        Hs = W * ASPECTS[p["aspect"]] + 2 * bz
        fd, z0 = p["foot_depth"], p["clearance"] + 0.015
        out = []
        body = (bevel_box((th, W, Hs), (0, 0, z0 + Hs / 2), min(0.006, th / 3), 1) if detail
                else box((th, W, Hs), (0, 0, z0 + Hs / 2)))
        out.append(Part(body, "plastic"))
        glass = box_between((th / 2 - 0.003, -W / 2 + bz, z0 + bz),
                            (th / 2 + 0.001, W / 2 - bz, z0 + Hs - bz))
        out.append(Part(glass, "screen"))
        if p["stand_style"] == "pedestal":
            fw = W * p["foot_width_frac"]
            out.append(Part(box_between((-fd / 2, -fw / 2, 0.0), (fd / 2, fw / 2, 0.015)), "metal"))
            out.append(Part(box_between((-th / 2 - 0.03, -0.04, 0.015 - OVERLAP),
                                        (-th / 2 + 0.005, 0.04, z0 + 0.15)), "metal"))
        else:
            for s in (-1, 1):
                yc = s * (W / 2 - min(0.12, W * 0.15))
                out.append(Part(box_between((-fd / 2, yc - 0.02, 0.0), (fd / 2, yc + 0.02, 0.012)), "metal"))
                out.append(Part(box_between((-0.02, yc - 0.015, 0.012 - OVERLAP),
                                            (0.0, yc + 0.015, z0 + 0.08)), "metal"))
        return out


@register
class Laptop(PartsFactory):
    """A laptop: a bevelled base with a keyboard (chiclet keys in a well, or a flat key plate)
    and touchpad, and a screen lid on its own link hinged along the base's back edge. The lid
    is built at `open_angle` (0 = closed) and its joint runs from closed to 150 degrees."""

    name = "laptop"
    tags = frozenset({S.Object, S.SmallObject, S.Electronics, S.Laptop})
    size_class = "small"
    slots = ["body", "screen", "plastic"]
    solid_bottom = True
    MAX_ANGLE = 150.0
    params = {
        "width": Param(0.28, 0.4, doc="Y extent (m)"),
        "depth": Param(0.19, 0.27, doc="X extent of the base (m)"),
        "base_thickness": Param(0.012, 0.022, doc="base thickness (m)"),
        "lid_thickness": Param(0.005, 0.009, doc="lid thickness (m)"),
        "open_angle": Param(0.0, 125.0, doc="lid angle as built (degrees, 0 = closed)"),
        "bezel": Param(0.006, 0.016, doc="border around the screen (m)"),
        "corner_radius": Param(0.003, 0.01, doc="rounding of the edges (m)"),
        "touchpad_ratio": Param(0.25, 0.45, doc="touchpad width / laptop width"),
        "key_style": Param(kind="choice", choices=("chiclet", "flat"), doc="keyboard style"),
    }

    def _pivot(self, p) -> np.ndarray:
        return np.array([-p["depth"] / 2, 0.0, p["base_thickness"] + MOVING_GAP])

    def _open(self, solid: m3d.Manifold, p) -> m3d.Manifold:
        pv = self._pivot(p)
        return solid.translate(tuple(-pv)).rotate((0.0, -p["open_angle"], 0.0)).translate(tuple(pv))

    def _lid(self, p, detail) -> list[Part]:
        D, W, lt = p["depth"], p["width"], p["lid_thickness"]
        z0 = p["base_thickness"] + MOVING_GAP
        cr = min(p["corner_radius"], 0.45 * lt)
        shell = bevel_box((D, W, lt), (0.0, 0.0, z0 + lt / 2), cr, 2)
        b = p["bezel"]
        screen = box_between((-D / 2 + b, -W / 2 + b, z0 - 0.0003),
                             (D / 2 - b * 1.6, W / 2 - b, z0 + SMALL_OVERLAP))
        if not detail:  # the hull of shell and screen: exact bounds at any opening angle
            return [Part(self._open(m3d.Manifold.batch_hull([shell, screen]), p), "body", "lid")]
        return [Part(self._open(shell, p), "body", "lid"), Part(self._open(screen, p), "screen", "lid")]

    def _base(self, p, detail) -> list[Part]:
        D, W, bt = p["depth"], p["width"], p["base_thickness"]
        cr = p["corner_radius"]
        if not detail:
            return [Part(box((D, W, bt), (0.0, 0.0, bt / 2)), "body")]
        base = bevel_box((D, W, bt), (0.0, 0.0, bt / 2), min(cr, 0.45 * bt), 2)
        # keyboard well behind the touchpad (the hinge is at the back, -X)
        kx0, kx1 = -D / 2 + 0.02, -D / 2 + 0.02 + 0.5 * D
        ky = 0.44 * W
        well = box_between((kx0, -ky, bt - 0.0015), (kx1, ky, bt + 0.01))
        tw = W * p["touchpad_ratio"]
        tx0, tx1 = kx1 + 0.012, min(D / 2 - 0.012, kx1 + 0.012 + 0.6 * tw)
        pad_cut = box_between((tx0, -tw / 2, bt - 0.0006), (tx1, tw / 2, bt + 0.01))
        out = [Part(base - well - pad_cut, "body"),
               Part(box_between((tx0 + 0.0005, -tw / 2 + 0.0005, bt - 0.0016),
                                (tx1 - 0.0005, tw / 2 - 0.0005, bt - 0.0003)), "plastic")]
        if p["key_style"] == "flat":
            out.append(Part(box_between((kx0 + 0.001, -ky + 0.001, bt - 0.0025),
                                        (kx1 - 0.001, ky - 0.001, bt - 0.0005)), "plastic"))
            return out
        rows, cols = 6, 14
        pitch_x, pitch_y = (kx1 - kx0) / rows, 2 * ky / cols
        keys = []
        for r in range(rows):
            if r == rows - 1:  # bottom row (nearest the front): a space bar between small keys
                spans = [(-ky, -ky + 3 * pitch_y), (-ky + 3 * pitch_y, ky - 3 * pitch_y),
                         (ky - 3 * pitch_y, ky)]
            else:
                spans = [(-ky + c * pitch_y, -ky + (c + 1) * pitch_y) for c in range(cols)]
            x0 = kx0 + r * pitch_x
            for y0, y1 in spans:
                keys.append(box_between((x0 + 0.0012, y0 + 0.0012, bt - 0.0025),
                                        (x0 + pitch_x - 0.0012, y1 - 0.0012, bt - 0.0004)))
        out.append(Part(m3d.Manifold.compose(keys), "plastic"))
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The base with keyboard and touchpad, and the lid on its `lid` link."""
        return self._base(p, detail) + self._lid(p, detail)

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """The lid's hinge, from closed to `MAX_ANGLE` (relative to the built angle)."""
        a = math.radians(p["open_angle"])
        return [make_joint("lid_joint", DoorJoint("revolute", np.array([0.0, -1.0, 0.0]),
                                                  self._pivot(p), "lid"),
                           -a, math.radians(self.MAX_ANGLE) - a)]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The bevelled base's flat underside as the `bottom`."""
        D, W, cr = p["depth"], p["width"], min(p["corner_radius"], 0.45 * p["base_thickness"])
        # the bevelled base's flat underside, 0.5 mm in from its edge
        return [bottom_rect((0.0, 0.0, 0.0), D / 2 - cr - 0.0005, W / 2 - cr - 0.0005)]


@register
class Remote(PartsFactory):
    """A TV remote: a bevelled slab tapering towards its tail, a red power button at the head
    (+X), an optional direction pad (ring and OK button) and rows of round or square buttons."""

    name = "remote"
    tags = frozenset({S.Object, S.SmallObject, S.Electronics, S.Remote})
    size_class = "small"
    slots = ["plastic", "rubber"]
    solid_bottom = True
    params = {
        "length": Param(0.14, 0.22, doc="X extent (m)"),
        "width": Param(0.035, 0.055, doc="Y extent at the head (m)"),
        "thickness": Param(0.012, 0.025, doc="Z extent of the body (m)"),
        "taper": Param(0.75, 1.0, doc="width at the tail / width at the head"),
        "n_button_rows": Param(3, 7, kind="int", doc="rows of three buttons"),
        "button_style": Param(kind="choice", choices=("round", "square"), doc="button shape"),
        "dpad": Param(kind="bool", doc="direction pad (ring and OK button)"),
        "edge_radius": Param(0.003, 0.008, doc="rounding of the body's edges (m)"),
    }
    RAISE = 0.0015  # how far buttons stand above the top

    def _body(self, p, detail) -> m3d.Manifold:
        L, w, th = p["length"], p["width"], p["thickness"]
        r = min(p["edge_radius"], 0.45 * th)
        wt = w * p["taper"]
        if not detail:
            return box((L, w, th), (0.0, 0.0, th / 2))
        head = bevel_box((0.02, w, th), (L / 2 - 0.01, 0.0, th / 2), r, 2)
        tail = bevel_box((0.02, wt, th), (-L / 2 + 0.01, 0.0, th / 2), r, 2)
        return m3d.Manifold.batch_hull([head, tail])

    def _buttons(self, p) -> list[Part]:
        L, w, th = p["length"], p["width"], p["thickness"]
        r = min(p["edge_radius"], 0.45 * th)
        z0, z1 = th - 0.0008, th + self.RAISE
        out = [Part(cylinder(0.0045, z1 - z0, (L / 2 - 0.016, w / 2 - r - 0.0065, z0), 16), "rubber")]
        x = L / 2 - 0.03
        if p["dpad"]:
            rd = min(0.4 * w - r, 0.018)
            ring = lathe([(0.55 * rd, 0.0), (rd, 0.0), (rd, z1 - z0), (0.55 * rd, z1 - z0)], 24)
            out.append(Part(ring.translate((x - rd, 0.0, z0)), "rubber"))
            out.append(Part(cylinder(0.4 * rd, z1 - z0, (x - rd, 0.0, z0), 16), "rubber"))
            x -= 2 * rd + 0.008
        wt = w * p["taper"]
        for row in range(int(p["n_button_rows"])):
            xc = x - 0.004 - row * 0.013
            if xc < -L / 2 + 0.015:
                break
            wl = wt + (w - wt) * (xc + L / 2) / L  # body width at this x
            pitch = min(0.013, (wl - 2 * r - 0.004) / 3)
            for c in (-1, 0, 1):
                yc = c * pitch
                if p["button_style"] == "round":
                    b = cylinder(0.35 * pitch, z1 - z0, (xc, yc, z0), 12)
                else:
                    b = box_between((xc - 0.0045, yc - 0.35 * pitch, z0),
                                    (xc + 0.0045, yc + 0.35 * pitch, z1))
                out.append(Part(b, "rubber"))
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The tapering body and its buttons (placeholder: one box)."""
        L, w, th = p["length"], p["width"], p["thickness"]
        if not detail:
            return [Part(box_between((-L / 2, -w / 2, 0.0), (L / 2, w / 2, th + self.RAISE)), "plastic")]
        return [Part(self._body(p, True), "plastic")] + self._buttons(p)

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The flat, tapering underside as the `bottom`."""
        L, w, th = p["length"], p["width"], p["thickness"]
        r = min(p["edge_radius"], 0.45 * th)
        wt = w * p["taper"]
        # the flat underside: a trapezoid from the tail to the head, 0.5 mm in from its edge
        h, t = w / 2 - r - 0.0005, wt / 2 - r - 0.0005
        x0, x1 = -L / 2 + r + 0.0005, L / 2 - r - 0.0005
        poly = sg.Polygon([(x0, -t), (x1, -h), (x1, h), (x0, t)])
        return [support_polygon("bottom", (0, 0, 0), poly, subpart=Subpart.Bottom, up=False)]
