"""Clocks: wall clocks (round or square case, recessed dial) and table clocks (twin-bell alarm,
arched mantel, digital block), with hour markers and hands showing a time."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.decor._parts import (
    back_surface,
    bbox_part,
    circle_points,
    wall_outline,
    yz_extrude,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import SMALL_OVERLAP, Part, bevel_box, box_between, lathe, rod
from indoorgen.model.tags import Semantics as S


def _x_lathe(profile, center=(0.0, 0.0, 0.0), sections: int = 48,
             circumscribed: bool = False) -> m3d.Manifold:
    """A lathe about the X axis: profile points are (radius, x offset), revolved, then moved so
    that its axis passes through `center`."""
    return lathe(profile, sections, circumscribed).rotate((0.0, 90.0, 0.0)).translate(
        tuple(float(c) for c in center))


def _x_disc(r: float, x0: float, x1: float, y: float = 0.0, z: float = 0.0, sections: int = 48,
            circumscribed: bool = False) -> m3d.Manifold:
    """A disc (cylinder along X) of radius r from x0 to x1 with its axis through (y, z)."""
    return _x_lathe([(0.0, 0.0), (r, 0.0), (r, x1 - x0), (0.0, x1 - x0)], (x0, y, z), sections,
                    circumscribed)


def _hand(angle: float, length: float, tail: float, width: float, x0: float, x1: float,
          y: float, z: float) -> m3d.Manifold:
    """A clock hand in the plane x0..x1 pointing at `angle` (radians clockwise from 12 o'clock
    as seen from +X; 3 o'clock is +Y), pivoting at (y, z)."""
    hand = box_between((x0, -width / 2, -tail), (x1, width / 2, length))
    return hand.rotate((-math.degrees(angle), 0.0, 0.0)).translate((0.0, y, z))


def _clock_face(x_dial: float, y: float, z: float, r: float, hours: float, markers: str,
                hand_width: float, space: float) -> list[Part]:
    """Hour markers and hands on a dial whose face is the plane x = x_dial (facing +X), centred
    at (y, z), radius r. `space` is the depth available in front of the dial."""
    out: list[Part] = []
    lay = min(0.002, max(space - 0.001, 0.0015) / 2)
    hour_a = (hours % 12.0) / 12.0 * 2 * math.pi
    minute_a = (hours % 1.0) * 2 * math.pi
    hands = [_hand(hour_a, 0.5 * r, 0.12 * r, hand_width * 1.3, x_dial - SMALL_OVERLAP, x_dial + lay, y, z),
             _hand(minute_a, 0.78 * r, 0.15 * r, hand_width, x_dial + lay - SMALL_OVERLAP, x_dial + 2 * lay,
                   y, z)]
    cap = _x_disc(max(hand_width * 1.2, 0.004), x_dial - SMALL_OVERLAP, x_dial + 2 * lay + 0.001, y, z, 16)
    out += [Part(h, "metal") for h in hands + [cap]]
    if markers == "none":
        return out
    marks = []
    for k in range(12):
        a = k * math.pi / 6
        rm = 0.84 * r
        cy, cz = y + rm * math.sin(a), z + rm * math.cos(a)
        if markers == "dots":
            marks.append(_x_disc(0.025 * r * (1.5 if k % 3 == 0 else 1.0), x_dial - SMALL_OVERLAP,
                                 x_dial + 0.0012, cy, cz, 12))
        else:
            ln = 0.12 * r if k % 3 == 0 else 0.07 * r
            w = 0.022 * r if k % 3 == 0 else 0.012 * r
            tick = box_between((x_dial - SMALL_OVERLAP, -w / 2, -ln / 2), (x_dial + 0.0012, w / 2, ln / 2))
            marks.append(tick.rotate((-math.degrees(a), 0.0, 0.0)).translate((0.0, cy, cz)))
    out += [Part(m, "metal") for m in marks]
    return out


@register
class WallClock(PartsFactory):
    """A wall clock: a round (lathed) or square case with a recessed dial, tick or dot hour
    markers and hour/minute hands showing a time; flat back on the wall."""

    name = "clock"
    tags = frozenset({S.Object, S.Decor, S.WallDecoration, S.Clock, S.WallMounted})
    size_class = "medium"
    slots = ["frame", "paper", "metal"]
    params = {
        "shape": Param(kind="choice", choices=("round", "square"), doc="case outline"),
        "diameter": Param(0.2, 0.6, doc="case diameter / side (m)"),
        "depth": Param(0.03, 0.07, doc="X extent of the case (m)"),
        "rim_width": Param(0.008, 0.04, doc="width of the case rim around the dial (m)"),
        "dial_recess": Param(0.005, 0.015, doc="depth of the dial behind the rim (m)"),
        "markers": Param(kind="choice", choices=("ticks", "dots", "none"), doc="hour markers"),
        "time": Param(0.0, 12.0, doc="time shown (hours, sets the hands)"),
        "hand_width": Param(0.004, 0.012, doc="minute hand width (m)"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Case, recessed dial, markers and hands (placeholder: the case's envelope)."""
        Dm, D, rw = p["diameter"], p["depth"], p["rim_width"]
        R = Dm / 2
        rec = p["dial_recess"]
        x0, x1 = -D / 2, D / 2
        # a round case is sunk 0.5 mm into z=0 and trimmed: it stands on a thin flat strip
        zc = R - (0.0005 if p["shape"] == "round" else 0.0)
        if not detail:
            if p["shape"] == "round":
                return [Part(_x_disc(R, x0, x1, 0.0, zc, 16, circumscribed=True)
                             .trim_by_plane((0, 0, 1), 0.0), "frame")]
            return [Part(box_between((x0, -R, 0.0), (x1, R, Dm)), "frame")]
        xd = x1 - rec
        ri = R - rw
        if p["shape"] == "round":
            prof = [(0.0, 0.0), (R, 0.0), (R, 0.5 * (D - 0.004)), (R, D - 0.004), (R - 0.004, D),
                    (ri, D), (ri, D - rec - 0.002),
                    (0.0, D - rec - 0.002)]
            case = _x_lathe(prof, (x0, 0.0, zc), 64).trim_by_plane((0, 0, 1), 0.0)
            dial = _x_disc(ri + 0.0005, xd - 0.003, xd, 0.0, zc, 64)
        else:
            case = (box_between((x0, -R, 0.0), (x1, R, Dm))
                    - box_between((xd - 0.002, -ri, zc - ri), (x1 + 0.01, ri, zc + ri)))
            dial = box_between((xd - 0.003, -ri - 0.0005, zc - ri - 0.0005),
                               (xd, ri + 0.0005, zc + ri + 0.0005))
        out = [Part(case, "frame"), Part(dial, "paper")]
        out += _clock_face(xd, 0.0, zc, ri, p["time"], p["markers"], p["hand_width"], rec)
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The flat back of the case (round or square) against the wall."""
        R, D = p["diameter"] / 2, p["depth"]
        if p["shape"] == "round":
            poly = sg.Polygon(circle_points(R - 0.001, 64, (0.0, R)))
        else:
            poly = sg.box(-R + 0.001, 0.001, R - 0.001, 2 * R - 0.001)
        return [back_surface(poly, -D / 2)]


@register
class TableClock(PartsFactory):
    """A clock for a table or shelf: a twin-bell `alarm` clock (drum body on two feet), a
    `mantel` clock (arched case on a plinth with a round face) or a `digital` block with a
    screen."""

    name = "table_clock"
    frequency = 0.2  # a home holds one or two
    tags = frozenset({S.Object, S.SmallObject, S.Decor, S.Clock})
    size_class = "small"
    slots = ["body", "paper", "metal", "screen"]
    params = {
        "style": Param(kind="choice", choices=("alarm", "mantel", "digital"), doc="kind of clock"),
        "height": Param(0.08, 0.22, doc="overall height (m)"),
        "width_ratio": Param(0.8, 1.6, doc="mantel/digital width / height"),
        "depth": Param(0.04, 0.09, doc="X extent of the body (m)"),
        "face_ratio": Param(0.55, 0.85, doc="dial (or screen) size / body size"),
        "time": Param(0.0, 12.0, doc="time shown (hours)"),
        "foot_height": Param(0.005, 0.02, doc="feet / plinth height (m)"),
        "bezel": Param(0.003, 0.012, doc="rim around the dial (m)"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The clock of its style; the placeholder is the box around it."""
        build = {"alarm": self._alarm, "mantel": self._mantel, "digital": self._digital}[p["style"]]
        out = build(p, True)
        return out if detail else [bbox_part(out, "body")]

    def _alarm(self, p, detail):
        H, D, fh = p["height"], p["depth"], p["foot_height"]
        Rb = (H - fh) / (2 + 0.55)  # drum radius; the bells rise 0.55 Rb above the drum
        zc = fh + Rb
        x0, x1 = -D / 2, D / 2
        rb = 0.42 * Rb
        bells = []
        for s in (-1, 1):
            a = math.radians(38) * s
            c = np.array([0.0, Rb * math.sin(a) * 0.95, zc + Rb * math.cos(a) * 0.95])
            bells.append((c, a))
        top = max(zc + Rb * 0.95 * math.cos(math.radians(38)) + rb, zc + Rb + 0.12 * Rb)
        out = [Part(_x_lathe([(0.0, 0.0), (Rb, 0.0), (Rb, D - 0.003), (Rb - 0.003, D),
                              (0.0, D)], (x0, 0.0, zc), 48), "body")]
        rf = min(Rb * p["face_ratio"], Rb - p["bezel"] * 0.5 - 0.001)
        # a paper dial on the drum's front inside a raised metal bezel ring
        out.append(Part(_x_lathe([(rf - 0.0005, 0.0), (rf + p["bezel"] * 0.5, 0.0),
                                  (rf + p["bezel"] * 0.5, 0.007), (rf - 0.0005, 0.007)],
                                 (x1 - SMALL_OVERLAP, 0.0, zc), 48), "metal"))
        out.append(Part(_x_disc(rf, x1 - SMALL_OVERLAP, x1 + 0.001, 0.0, zc, 48), "paper"))
        out += _clock_face(x1 + 0.001, 0.0, zc, rf, p["time"], "ticks", 0.0025, 0.005)
        for c, a in bells:
            dome = lathe([(0.0, 0.0), (rb, 0.0), (rb * 0.96, rb * 0.35), (rb * 0.75, rb * 0.75),
                          (rb * 0.4, rb * 0.95), (0.0, rb)], 24)
            dome = dome.translate((0, 0, -rb * 0.2)).rotate((math.degrees(-a), 0, 0))
            out.append(Part(dome.translate(tuple(c)), "metal"))
        # handle loop standing on top and two angled feet
        out.append(Part(rod((0, 0, zc + Rb - 0.004), (0, 0, top), 0.003, 12), "metal"))
        out.append(Part(_x_disc(0.006, -0.004, 0.004, 0.0, top - 0.004, 16), "metal"))
        for s in (-1, 1):
            a = math.radians(35) * s
            p0 = (0.0, Rb * 0.9 * math.sin(a), zc - Rb * 0.9 * math.cos(a))
            out.append(Part(rod(p0, (0.0, Rb * 1.05 * math.sin(a), -0.01), 0.004, 12)
                            .trim_by_plane((0, 0, 1), 0.0), "metal"))
            # a foot pad front to back under each foot, so the clock stands (two rods 8 mm
            # across tipped it over in simulators)
            yf = Rb * 1.0 * math.sin(a)
            out.append(Part(box_between((x0 + 0.003, yf - 0.005, 0.0),
                                        (x1 - 0.003, yf + 0.005, 0.003)), "metal"))
        return out

    def _mantel(self, p, detail):
        H, D, fh = p["height"], p["depth"], p["foot_height"]
        W = H * p["width_ratio"]
        Hb = H - fh
        x0, x1 = -D / 2, D / 2
        shape = "arched" if W <= 1.25 * H else "rect"
        cs = wall_outline(shape, W, Hb).translate((0.0, fh - SMALL_OVERLAP))
        out = [Part(yz_extrude(cs, x0, x1), "body"),
               Part(box_between((x0 - 0.005, -W / 2 - 0.005, 0.0), (x1 + 0.005, W / 2 + 0.005, fh)),
                    "body")]
        rf = 0.5 * min(W, Hb) * p["face_ratio"]
        zc = fh + min(Hb - rf - p["bezel"] - 0.01, Hb * 0.55)
        zc = max(zc, fh + rf + p["bezel"] + 0.005)
        bz = p["bezel"]
        out.append(Part(_x_lathe([(0.0, 0.0), (rf + bz, 0.0), (rf + bz, 0.006), (rf, 0.006),
                                  (rf, 0.002), (0.0, 0.002)], (x1 - SMALL_OVERLAP, 0.0, zc), 48), "metal"))
        out.append(Part(_x_disc(rf + 0.0005, x1, x1 + 0.002, 0.0, zc, 48), "paper"))
        out += _clock_face(x1 + 0.002, 0.0, zc, rf, p["time"], "ticks", 0.003, 0.004 - 0.0005)
        return out

    def _digital(self, p, detail):
        H, D, fh = p["height"], p["depth"], p["foot_height"]
        W = H * p["width_ratio"]
        Hb = H - fh
        x1 = D / 2
        out = [Part(bevel_box((D, W, Hb), (0.0, 0.0, fh + Hb / 2 - SMALL_OVERLAP / 2), min(0.01, 0.2 * D), 2),
                    "body")]
        sw, sh = W * p["face_ratio"], Hb * p["face_ratio"] * 0.7
        zc = fh + Hb / 2
        pocket = box_between((x1 - 0.003, -sw / 2, zc - sh / 2), (x1 + 0.01, sw / 2, zc + sh / 2))
        out[0] = Part(out[0].solid - pocket, "body")
        # the screen fills the pocket 0.5 mm clear of its sides, 0.8 mm below the front
        out.append(Part(box_between((x1 - 0.003 - SMALL_OVERLAP, -sw / 2 + 0.0005, zc - sh / 2 + 0.0005),
                                    (x1 - 0.0008, sw / 2 - 0.0005, zc + sh / 2 - 0.0005)), "screen"))
        for s in (-1, 1):
            out.append(Part(box_between((-D / 2 + 0.01, s * W * 0.3 - 0.012, 0.0),
                                        (D / 2 - 0.01, s * W * 0.3 + 0.012, fh)), "metal"))
        return out
