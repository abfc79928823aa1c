"""More decor: round rugs, canvas prints, mirrors, aquariums, curtains, clocks, balloons and
candles.

Wall-mounted pieces (canvas, mirror, curtain, wall clock) hang with their flat back at the
bounding box's back (-X) and face +X; their `back` surface is the part of that plane the mesh
really covers. Flat outlines in the wall plane are `CrossSection`s in (y, z) extruded along X.
"""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory, make_joint
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import carcass
from indoorgen.assets.shapes.moving_parts import FRONT_PROUD, Front, cabinet_fronts
from indoorgen.assets.shapes.outlines import ccw, largest_polygon
from indoorgen.assets.shapes.primitives import (
    SMALL_OVERLAP,
    Part,
    bevel_box,
    box,
    box_between,
    circle_polygon,
    cylinder,
    lathe,
    rod,
    torus,
)
from indoorgen.assets.shapes.surfaces import support_polygon, support_rect
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

# ------------------------------------------------------------------------------ helpers


def _cs(pts: np.ndarray) -> m3d.CrossSection:
    """A cross-section from one simple polygon (any orientation)."""
    return m3d.CrossSection([ccw(pts)], m3d.FillRule.Positive)


def _circle_pts(r: float, n: int, center=(0.0, 0.0), circumscribed: bool = False) -> np.ndarray:
    """An n-gon on a circle (a vertex on +x), or circumscribed about it (flats on the axes)."""
    a = np.arange(n) * 2 * math.pi / n
    if circumscribed:
        a = a + math.pi / n
        r = r / math.cos(math.pi / n)
    return np.c_[center[0] + r * np.cos(a), center[1] + r * np.sin(a)]


def _yz_extrude(cs: m3d.CrossSection, x0: float, x1: float) -> m3d.Manifold:
    """Extrude a cross-section drawn in the wall plane (its x = our y, its y = our z) from
    x0 to x1 along X."""
    m = m3d.Manifold.extrude(cs, x1 - x0)
    return m.transform(np.array([[0.0, 0.0, 1.0, x0], [1.0, 0.0, 0.0, 0.0],
                                 [0.0, 1.0, 0.0, 0.0]]))


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


def _back_surface(poly_yz: sg.Polygon, x: float) -> Surface:
    """A `back` surface (normal -X) at x whose outline is `poly_yz` in (y, z) coordinates
    (the surface's v axis is -Z, so z is mirrored)."""
    pts = np.asarray(poly_yz.exterior.coords)[:-1]
    return Surface("back", Subpart.Back, np.array([x, 0.0, 0.0]), np.array([-1.0, 0.0, 0.0]),
                   np.array([0.0, 1.0, 0.0]), sg.Polygon(np.c_[pts[:, 0], -pts[:, 1]]))


def _outline(shape: str, width: float, height: float, n: int = 64,
             circumscribed: bool = False) -> m3d.CrossSection:
    """A wall-plane outline standing on z=0: "rect", "round" (diameter = width) or "arched"
    (a rectangle topped by a half disc as wide as it)."""
    if shape == "round":
        return _cs(_circle_pts(width / 2, n, (0.0, width / 2), circumscribed))
    if shape == "arched":
        r = width / 2
        body = m3d.CrossSection.square((width, max(height - r, 0.01)), False).translate((-r, 0.0))
        top = _cs(_circle_pts(r, n, (0.0, max(height - r, 0.01)), circumscribed))
        return body + top
    return m3d.CrossSection.square((width, height), False).translate((-width / 2, 0.0))


def _bbox_box(parts: list[Part], slot: str) -> Part:
    """One box spanning the bounding box of `parts` (a placeholder for small, intricate
    objects: exact bounds, contains everything)."""
    bbs = np.array([q.solid.bounding_box() for q in parts])
    return Part(box_between(bbs[:, :3].min(axis=0), bbs[:, 3:].max(axis=0)), slot)


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


# ------------------------------------------------------------------------------ round rug
@register
class RoundRug(PartsFactory):
    """A round or oval rug: a thin lathed pile, optionally braided (concentric grooves), with a
    plain edge, a raised bound edge or a fringe of tassels all round."""

    name = "rug_round"
    tags = frozenset({S.Object, S.Decor, S.FloorCovering, S.Rug})
    size_class = "large"
    slots = ["carpet", "fabric"]
    solid_bottom = True
    params = {
        "shape": Param(kind="choice", choices=("round", "oval"), doc="outline"),
        "diameter": Param(0.8, 2.4, doc="Y extent of the pile (m)"),
        "aspect": Param(0.55, 0.85, doc="oval: X extent / Y extent"),
        "thickness": Param(0.006, 0.015, doc="pile thickness (m)"),
        "edge": Param(kind="choice", choices=("plain", "bound", "fringe"), doc="edge finish"),
        "binding_width": Param(0.015, 0.045, doc="width of a bound edge's band (m)"),
        "fringe_length": Param(0.03, 0.08, doc="length of the fringe's tassels (m)"),
        "n_grooves": Param(0, 6, kind="int", doc="concentric braid grooves on top (0 = plain pile)"),
    }

    def _sx(self, p) -> float:
        return p["aspect"] if p["shape"] == "oval" else 1.0

    def parts(self, p, detail):
        R, t, sx = p["diameter"] / 2, p["thickness"], self._sx(p)
        bound, fringe = p["edge"] == "bound", p["edge"] == "fringe"
        top = t + (0.002 if bound else 0.0)
        r_out = R + (p["fringe_length"] if fringe else 0.0)
        if not detail:
            return [Part(cylinder(r_out, top, (0, 0, 0), 16, circumscribed=True).scale((sx, 1, 1)),
                         "carpet")]
        prof = [(0.0, 0.0), (R, 0.0), (R, t - 0.002), (R - 0.002, t)]
        n = int(p["n_grooves"])
        gw, gd = 0.012, 0.35 * t
        r_end = R - (p["binding_width"] if bound else 0.0) - 0.02
        for k in range(n, 0, -1):  # grooves from the outside in
            rk = r_end * k / (n + 1)
            prof += [(rk + gw / 2, t), (rk, t - gd), (rk - gw / 2, t)]
        prof.append((0.0, t))
        out = [Part(lathe(prof, 96).scale((sx, 1, 1)), "carpet")]
        if bound:
            bw = p["binding_width"]
            ring = [(R - 0.0015, 0.0), (R, 0.0), (R, top), (R - bw, top), (R - bw, t - 0.0005),
                    (R - 0.0015, t - 0.0005)]
            out.append(Part(lathe(ring, 96).scale((sx, 1, 1)), "fabric"))
        if fringe:
            out.append(Part(self._fringe(R, p["fringe_length"]).scale((sx, 1, 1)), "fabric"))
        return out

    @staticmethod
    def _fringe(R: float, length: float) -> m3d.Manifold:
        """A gear-shaped slab: tassels 4 mm wide every 12 mm, from 5 mm inside the pile's edge
        out to R + length, lifted 1 mm off the floor."""
        n = max(24, int(2 * math.pi * R / 0.012) // 4 * 4)
        half = 0.5 * 0.004 / R
        a = np.arange(n) * 2 * math.pi / n
        r_in, r_out = R - 0.005, R + length
        ang = np.stack([a - half, a - half, a + half, a + half], axis=1).ravel()
        rad = np.tile([r_in, r_out, r_out, r_in], n)
        gear = _cs(np.c_[rad * np.cos(ang), rad * np.sin(ang)])
        return m3d.Manifold.extrude(gear, 0.003).translate((0.0, 0.0, 0.001))

    def extra_surfaces(self, p):
        R, sx = p["diameter"] / 2 - 0.0005, self._sx(p)
        poly = circle_polygon(R, 96)
        poly = sg.Polygon(np.asarray(poly.exterior.coords)[:-1] * np.array([sx, 1.0]))
        return [support_polygon("bottom", (0, 0, 0), poly, subpart=Subpart.Bottom, up=False)]


# ------------------------------------------------------------------------------ canvas art
@register
class CanvasArt(PartsFactory):
    """A gallery-wrapped canvas print on a deep stretcher (no frame), or a diptych / triptych
    made as ONE wide canvas cut into panels by grooves from the front (a 3-panel one may have a
    taller middle panel). Its flat back hangs on the wall; the print faces +X."""

    name = "canvas_art"
    tags = frozenset({S.Object, S.Decor, S.WallDecoration, S.WallArt, S.WallMounted})
    size_class = "medium"
    slots = ["canvas", "wood"]
    params = {
        "panel_width": Param(0.3, 1.0, doc="Y extent of one panel (m)"),
        "height": Param(0.3, 1.1, doc="Z extent of the (outer) panels (m)"),
        "depth": Param(0.018, 0.045, doc="X extent: stretcher depth (m)"),
        "n_panels": Param(1, 3, kind="int", doc="panels side by side"),
        "groove_width": Param(0.01, 0.04, doc="gap between panels at the front (m)"),
        "groove_depth": Param(0.4, 0.85, doc="groove depth / canvas depth"),
        "edge_radius": Param(0.001, 0.006, doc="rounding of the wrapped edges (m)"),
        "center_scale": Param(1.0, 1.25, doc="3 panels: middle panel height / outer height"),
    }

    def _panels(self, p) -> list[tuple[float, float, float, float]]:
        """(y0, y1, z0, z1) of each panel."""
        w, g, n = p["panel_width"], p["groove_width"], int(p["n_panels"])
        H = p["height"]
        hs = [H * (p["center_scale"] if n == 3 and i == 1 else 1.0) for i in range(n)]
        Hm = max(hs)
        W = n * w + (n - 1) * g
        out = []
        for i, h in enumerate(hs):
            y0 = -W / 2 + i * (w + g)
            out.append((y0, y0 + w, (Hm - h) / 2, (Hm + h) / 2))
        return out

    def parts(self, p, detail):
        D, r = p["depth"], p["edge_radius"]
        panels = self._panels(p)
        out = []
        for y0, y1, z0, z1 in panels:
            ext, c = (D, y1 - y0, z1 - z0), (0.0, (y0 + y1) / 2, (z0 + z1) / 2)
            out.append(Part(bevel_box(ext, c, r, 2) if detail else box(ext, c), "canvas"))
        xb = -D / 2 + D * (1.0 - p["groove_depth"])
        for (_, a1, za0, za1), (b0, _, zb0, zb1) in zip(panels, panels[1:]):
            z0, z1 = max(za0, zb0) + r, min(za1, zb1) - r
            out.append(Part(box_between((-D / 2, a1 - SMALL_OVERLAP - r, z0), (xb, b0 + SMALL_OVERLAP + r, z1)), "wood"))
        return out

    def extra_surfaces(self, p):
        D, r = p["depth"], p["edge_radius"]
        panels = self._panels(p)
        z0 = max(q[2] for q in panels) + r + 0.002
        z1 = min(q[3] for q in panels) - r - 0.002
        y0, y1 = panels[0][0] + r + 0.002, panels[-1][1] - r - 0.002
        if len(panels) == 1:
            z0, z1 = panels[0][2] + r + 0.002, panels[0][3] - r - 0.002
        return [_back_surface(sg.box(y0, z0, y1, z1), -D / 2)]


# ------------------------------------------------------------------------------ mirrors
def _framed_mirror(p: dict[str, Any], detail: bool, shape: str, W: float, H: float,
                   D: float) -> list[Part]:
    """A framed mirror standing in the plane x in [-D/2, D/2], z in [0, H], facing +X: backing
    board, frame ring (flat, stepped or rounded moulding) and the glass recessed behind the
    frame's front."""
    fw = min(p["frame_width"], 0.2 * W)
    bk = 0.004
    if not detail:
        cs = _outline(shape, W, H, 16, circumscribed=True)
        return [Part(_yz_extrude(cs, -D / 2, D / 2), "frame")]
    cs = _outline(shape, W, H)
    inner = cs.offset(-fw, m3d.JoinType.Round, 2.0, 64)
    out = [Part(_yz_extrude(cs, -D / 2, -D / 2 + bk), "back")]
    steps = {"flat": [(0.0, 0.0, 1.0)], "stepped": [(0.0, 0.0, 0.55), (0.25, 0.15, 1.0)],
             "rounded": [(0.0, 0.0, 0.6), (0.08, 0.08, 0.8), (0.25, 0.25, 0.93), (0.42, 0.42, 1.0)]}
    x0 = -D / 2 + bk - SMALL_OVERLAP
    for out_in, in_in, xf in steps[p["frame_profile"]]:
        # each step a ring inset from the outer edge by out_in*fw and the inner edge by in_in*fw
        outer = cs.offset(-out_in * fw, m3d.JoinType.Round, 2.0, 64) if out_in else cs
        hole = cs.offset(-fw * (1 - in_in), m3d.JoinType.Round, 2.0, 64)
        out.append(Part(_yz_extrude(outer - hole, x0, -D / 2 + xf * D), "frame"))
        x0 = -D / 2 + xf * D - SMALL_OVERLAP
    glass = cs.offset(-fw + 0.004, m3d.JoinType.Round, 2.0, 64)
    xg = D / 2 - max(p["glass_recess"], D * 0.2)
    out.append(Part(_yz_extrude(glass, -D / 2 + bk - SMALL_OVERLAP, xg), "mirror"))
    return out


MIRROR_PARAMS = {
    "shape": Param(kind="choice", choices=("rect", "round", "arched"), doc="outline"),
    "frame_width": Param(0.015, 0.08, doc="frame moulding width (m)"),
    "frame_depth": Param(0.02, 0.05, doc="X extent of the frame (m)"),
    "frame_profile": Param(kind="choice", choices=("flat", "stepped", "rounded"),
                           doc="frame moulding profile"),
    "glass_recess": Param(0.004, 0.012, doc="how far the glass sits behind the frame front (m)"),
}


@register
class Mirror(PartsFactory):
    """A framed wall mirror: rectangular, round or arched, with a flat, stepped or rounded
    frame moulding and the glass set back behind it. Its flat backing board hangs on the wall."""

    name = "mirror"
    tags = frozenset({S.Object, S.Decor, S.WallDecoration, S.Mirror, S.WallMounted})
    size_class = "medium"
    slots = ["frame", "mirror", "back"]
    params = {
        **MIRROR_PARAMS,
        "width": Param(0.35, 1.0, doc="Y extent (m); a round mirror's diameter"),
        "height": Param(0.5, 1.4, doc="Z extent of rect/arched mirrors (m, >= width for arched)"),
    }

    def _dims(self, p) -> tuple[float, float]:
        W = p["width"]
        H = W if p["shape"] == "round" else (max(p["height"], W) if p["shape"] == "arched"
                                             else p["height"])
        return W, H

    def parts(self, p, detail):
        W, H = self._dims(p)
        return _framed_mirror(p, detail, p["shape"], W, H, p["frame_depth"])

    def extra_surfaces(self, p):
        W, H = self._dims(p)
        cs = _outline(p["shape"], W, H).offset(-0.001, m3d.JoinType.Miter, 2.0)
        return [_back_surface(largest_polygon(cs), -p["frame_depth"] / 2)]


def _bar(p0, p1, width: float, thick: float) -> m3d.Manifold:
    """A rectangular bar from p0 to p1 lying in an XZ plane: `width` along Y, `thick` across."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    d = p1 - p0
    d /= np.linalg.norm(d)
    n = np.cross(d, [0.0, 1.0, 0.0])
    n /= np.linalg.norm(n)
    y = np.array([0.0, width / 2, 0.0])
    pts = [q + sy * y + sn * n * thick / 2 for q in (p0, p1) for sy in (-1, 1) for sn in (-1, 1)]
    return m3d.Manifold.hull_points(np.array(pts))


@register
class FloorMirror(PartsFactory):
    """A full-length floor mirror: `leaning` against the wall (resting on its bottom edge),
    on an `easel` (a rear leg hinged at the top) or a `cheval` (tilting between two posts on
    feet). Rectangular or arched, framed like the wall mirror."""

    name = "floor_mirror"
    tags = frozenset({S.Object, S.Furniture, S.Decor, S.Mirror})
    size_class = "large"
    slots = ["frame", "mirror", "back", "wood"]
    params = {
        "style": Param(kind="choice", choices=("leaning", "easel", "cheval"), doc="how it stands"),
        "shape": Param(kind="choice", choices=("rect", "arched"), doc="outline"),
        "width": Param(0.4, 0.8, doc="mirror Y extent (m)"),
        "height": Param(1.4, 1.85, doc="mirror Z extent (m)"),
        "frame_width": Param(0.02, 0.07, doc="frame moulding width (m)"),
        "frame_depth": Param(0.02, 0.04, doc="X extent of the frame (m)"),
        "frame_profile": Param(kind="choice", choices=("flat", "stepped", "rounded"),
                               doc="frame moulding profile"),
        "glass_recess": Param(0.004, 0.01, doc="how far the glass sits behind the frame front (m)"),
        "tilt": Param(3.0, 12.0, doc="backwards lean of the mirror (degrees)"),
        "foot_depth": Param(0.3, 0.5, doc="X extent of the easel's stance / cheval's feet (m)"),
    }

    def _panel(self, p, detail: bool) -> tuple[list[Part], float]:
        """The mirror parts, tilted, plus the height of their lowest point before trimming."""
        W, H, D = p["width"], p["height"], p["frame_depth"]
        style = p["style"]
        Hp = H - 0.14 if style == "cheval" else H
        parts = _framed_mirror(p, True, p["shape"], W, Hp, D)
        if not detail:  # the convex hull of the detailed panel: exact bounds once tilted
            parts = [Part(m3d.Manifold.batch_hull([q.solid for q in parts]), "frame")]
        t = p["tilt"]
        if style == "cheval":
            # tilt about a horizontal axis at mid height, 12 cm off the floor
            zc = 0.12 + Hp / 2
            return [Part(q.solid.translate((0, 0, -Hp / 2)).rotate((0, -t, 0))
                         .translate((0, 0, zc)), q.slot) for q in parts], 0.0
        # lean back about the bottom back edge, sunk 2 mm into the floor then trimmed flat
        moved = [Part(q.solid.translate((D / 2, 0, 0)).rotate((0, -t, 0))
                      .translate((0, 0, -0.002)).trim_by_plane((0, 0, 1), 0.0), q.slot)
                 for q in parts]
        return moved, 0.0

    def parts(self, p, detail):
        out, _ = self._panel(p, detail)
        W, H, D, t = p["width"], p["height"], p["frame_depth"], math.radians(p["tilt"])
        style, fd = p["style"], p["foot_depth"]
        if style == "easel":
            # a rear leg from behind the top of the frame down to the floor
            h = 0.9 * H  # where the leg is hinged on the back, 6 mm into the panel
            top = np.array([-h * math.sin(t) + 0.006 * math.cos(t), 0.0,
                            h * math.cos(t) + 0.006 * math.sin(t) - 0.002])
            foot = np.array([-fd, 0.0, -0.01])
            leg = _bar(top, foot, 0.045, 0.022).trim_by_plane((0, 0, 1), 0.0)
            out.append(Part(leg, "wood"))
        elif style == "cheval":
            Hp = H - 0.14
            zc = 0.12 + Hp / 2
            pw, yp = 0.035, W / 2 + 0.006 + 0.035 / 2
            for s in (-1, 1):
                post = box_between((-pw / 2, s * yp - pw / 2, 0.02), (pw / 2, s * yp + pw / 2,
                                                                      zc + 0.12))
                feet = box_between((-fd / 2, s * yp - pw / 2, 0.0), (fd / 2, s * yp + pw / 2,
                                                                     0.025))
                pin = (rod((0, s * (W / 2 - 0.01), zc), (0, s * (yp + 0.005), zc), 0.006, 12)
                       if detail else box_between((-0.006, s * (W / 2 - 0.01) - 0.006, zc - 0.006),
                                                  (0.006, s * (yp + 0.005) + 0.006, zc + 0.006)))
                out += [Part(post, "wood"), Part(feet, "wood"), Part(pin, "wood")]
        return out


# ------------------------------------------------------------------------------ aquarium
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

    def joints(self, p):
        if p["style"] != "on_stand":
            return []
        return [make_joint(f"{m.link}_joint", m, 0.0, math.radians(100)) for _, m in self._fronts(p)]

    def parts(self, p, detail):
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
        out.append(Part(box_between((-Dt / 2 + g + SMALL_OVERLAP, -L / 2 + g + SMALL_OVERLAP, z0 + g - SMALL_OVERLAP),
                                    (Dt / 2 - g - SMALL_OVERLAP, L / 2 - g - SMALL_OVERLAP, zg)), "stone"))
        zw = z0 + H * p["water_level"]
        out.append(Part(box_between((-Dt / 2 + g + SMALL_OVERLAP, -L / 2 + g - SMALL_OVERLAP, zg + SMALL_OVERLAP),
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

    def extra_surfaces(self, p):
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


# ------------------------------------------------------------------------------ curtain
def _wave_band(y0: float, y1: float, x_mid: float, amp: float, pitch: float,
               thick: float) -> m3d.CrossSection:
    """The plan (x, y) of a pleated curtain panel: a sine wave of amplitude `amp` and wavelength
    `pitch` across y0..y1 about x = x_mid, thickened by `thick` along its normals (where a fold
    is tighter than the thickness, the fill rule resolves the overlap)."""
    n = max(16, int(round((y1 - y0) / pitch * 16)))
    y = np.linspace(y0, y1, n + 1)
    k = 2 * math.pi / pitch
    x = x_mid + amp * np.sin(k * (y - y0))
    dx = amp * k * np.cos(k * (y - y0))
    nrm = np.c_[np.ones_like(dx), -dx] / np.sqrt(1 + dx ** 2)[:, None]
    c = np.c_[x, y]
    pts = np.vstack([c + 0.5 * thick * nrm, (c - 0.5 * thick * nrm)[::-1]])
    return m3d.CrossSection([ccw(pts)], m3d.FillRule.NonZero)


@register
class Curtain(PartsFactory):
    """A curtain on a rod: one or two pleated fabric panels (a sine-folded solid sheet), hung
    from rings or gathered on the rod (rod pocket), drawn closed or open to the sides. The rod
    with its finials sits on brackets fixed to a wall board, whose back is the object's back."""

    name = "curtain"
    tags = frozenset({S.Object, S.Decor, S.Textile, S.Curtain, S.WallMounted})
    size_class = "medium"
    slots = ["fabric", "metal", "wood"]
    params = {
        "width": Param(1.0, 3.0, doc="span between the end brackets (m)"),
        "drop": Param(1.4, 2.6, doc="height from the hem to the rod (m)"),
        "n_panels": Param(1, 2, kind="int", doc="fabric panels (2 = a pair meeting in the middle)"),
        "coverage": Param(0.35, 1.0, doc="fraction of the width covered (< 1: drawn open)"),
        "fold_depth": Param(0.03, 0.09, doc="front-to-back depth of the folds (m)"),
        "fold_spacing": Param(0.1, 0.18, doc="fold wavelength when closed (m)"),
        "heading": Param(kind="choice", choices=("rings", "rod_pocket"), doc="how the fabric hangs"),
        "rod_radius": Param(0.01, 0.018, doc="rod radius (m)"),
        "finial": Param(kind="choice", choices=("ball", "disc", "cone"), doc="rod end finials"),
        "standoff": Param(0.07, 0.14, doc="rod axis distance from the wall (m)"),
    }
    THICK = 0.003

    def _geom(self, p) -> dict[str, float]:
        W, rr = p["width"], p["rod_radius"]
        pitch = p["fold_spacing"] * (0.5 + 0.5 * p["coverage"])
        amp = min(p["fold_depth"] / 2, 0.45 * pitch)
        xw = 0.0  # wall plane (the board's back)
        xr = max(p["standoff"], 0.018 + amp + self.THICK + 0.02, 0.018 + 0.025 + rr)
        zr = p["drop"] + (0.03 if p["heading"] == "rings" else 0.0)
        fr = 2.2 * rr if p["finial"] != "disc" else 2.0 * rr
        ext = 0.06
        tip = W / 2 + ext + {"ball": 2 * fr - 0.006, "disc": 0.012, "cone": 3.2 * fr - 0.004}[p["finial"]]
        ring_R, ring_m = rr + 0.004 + 0.003, 0.003
        # rings hang on the rod: their inner top edge 1 mm into the rod's top
        ring_zc = zr + rr - SMALL_OVERLAP - (ring_R - ring_m)
        return dict(W=W, rr=rr, pitch=pitch, amp=amp, xw=xw, xr=xr, zr=zr, fr=fr, ext=ext,
                    tip=tip, ring_R=ring_R, ring_m=ring_m, ring_zc=ring_zc)

    def _panels(self, p, g) -> list[tuple[float, float]]:
        W, cov = g["W"], p["coverage"]
        if int(p["n_panels"]) == 2:
            wp = cov * W / 2
            return [(-W / 2, -W / 2 + wp), (W / 2 - wp, W / 2)]
        return [(-W / 2, -W / 2 + cov * W)]

    def _fabric_top(self, p, g) -> float:
        if p["heading"] == "rings":
            return g["ring_zc"] - g["ring_R"] + 0.002
        return g["zr"] + g["rr"] + 0.03

    def parts(self, p, detail):
        g = self._geom(p)
        W, rr, xr, zr, xw, fr, ext = g["W"], g["rr"], g["xr"], g["zr"], g["xw"], g["fr"], g["ext"]
        amp, pitch = g["amp"], g["pitch"]
        zb0, zb1 = zr - 0.045, zr + 0.05
        yb = W / 2 + 0.04
        out = [Part(box_between((xw, -yb, zb0), (xw + 0.018, yb, zb1)), "wood")]
        zf = self._fabric_top(p, g)
        y_end = W / 2 + ext
        if not detail:
            out.append(Part(box_between((xw + 0.018 - SMALL_OVERLAP, -g["tip"], zr - fr),
                                        (xr + fr, g["tip"], zr + fr)), "metal"))
            for y0, y1 in self._panels(p, g):
                out.append(Part(box_between((xr - amp - self.THICK / 2, y0 - 0.003, 0.0),
                                            (xr + amp + self.THICK / 2, y1 + 0.003, zf + SMALL_OVERLAP)),
                                "fabric"))
            if p["heading"] == "rings":
                zc = g["ring_zc"]
                R = g["ring_R"] + g["ring_m"]
                out.append(Part(box_between((xr - R, -W / 2, zc - R), (xr + R, W / 2, zc + R)), "metal"))
            return out
        out.append(Part(rod((xr, -y_end, zr), (xr, y_end, zr), rr, 24), "metal"))
        for s in (-1, 1):
            out.append(Part(self._finial(p, g, s), "metal"))
            yb_ = s * (W / 2 + 0.02)
            out.append(Part(box_between((xw + 0.018 - SMALL_OVERLAP, yb_ - 0.008, zr - 0.012),
                                        (xr, yb_ + 0.008, zr + 0.012)), "metal"))
        for y0, y1 in self._panels(p, g):
            band = _wave_band(y0, y1, xr, amp, pitch, self.THICK)
            out.append(Part(m3d.Manifold.extrude(band, zf), "fabric"))
            if p["heading"] == "rings":
                zc = g["ring_zc"]
                n = int(math.floor((y1 - y0) / pitch + 1e-9))
                for k in range(n + 1):
                    yk = min(y0 + k * pitch, y1 - 0.004)
                    ring = torus(g["ring_R"], g["ring_m"], sections=12, tube_sections=6)
                    out.append(Part(ring.rotate((90.0, 0.0, 0.0)).translate((xr, yk, zc)), "metal"))
        return out

    @staticmethod
    def _finial(p, g, s: int) -> m3d.Manifold:
        rr, xr, zr, fr, y_end = g["rr"], g["xr"], g["zr"], g["fr"], g["W"] / 2 + g["ext"]
        y0 = s * (y_end - 0.004)
        if p["finial"] == "ball":
            ball = m3d.Manifold.sphere(fr, 24).translate((xr, s * (y_end + fr - 0.006), zr))
            return ball
        if p["finial"] == "disc":
            return rod((xr, y0, zr), (xr, s * (y_end + 0.012), zr), fr, 24)
        prof = [(0.0, 0.0), (fr, 0.0), (0.3 * fr, 3.0 * fr), (0.0, 3.2 * fr)]
        return lathe(prof, 24).rotate((-90.0 * s, 0.0, 0.0)).translate((xr, y0, zr))

    def extra_surfaces(self, p):
        g = self._geom(p)
        zr, yb = g["zr"], g["W"] / 2 + 0.04
        zb0, zb1 = zr - 0.045, zr + 0.05
        return [Surface.rect("back", Subpart.Back, (g["xw"], 0, (zb0 + zb1) / 2), (-1, 0, 0),
                             (0, 1, 0), yb - 0.002, (zb1 - zb0) / 2 - 0.002)]


# ------------------------------------------------------------------------------ clocks
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

    def parts(self, p, detail):
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

    def extra_surfaces(self, p):
        R, D = p["diameter"] / 2, p["depth"]
        if p["shape"] == "round":
            poly = sg.Polygon(_circle_pts(R - 0.001, 64, (0.0, R)))
        else:
            poly = sg.box(-R + 0.001, 0.001, R - 0.001, 2 * R - 0.001)
        return [_back_surface(poly, -D / 2)]


@register
class TableClock(PartsFactory):
    """A clock for a table or shelf: a twin-bell `alarm` clock (drum body on two feet), a
    `mantel` clock (arched case on a plinth with a round face) or a `digital` block with a
    screen."""

    name = "table_clock"
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

    def parts(self, p, detail):
        build = {"alarm": self._alarm, "mantel": self._mantel, "digital": self._digital}[p["style"]]
        out = build(p, True)
        return out if detail else [_bbox_box(out, "body")]

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
        return out

    def _mantel(self, p, detail):
        H, D, fh = p["height"], p["depth"], p["foot_height"]
        W = H * p["width_ratio"]
        Hb = H - fh
        x0, x1 = -D / 2, D / 2
        shape = "arched" if W <= 1.25 * H else "rect"
        cs = _outline(shape, W, Hb).translate((0.0, fh - SMALL_OVERLAP))
        out = [Part(_yz_extrude(cs, x0, x1), "body"),
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


# ------------------------------------------------------------------------------ balloons
def _balloon_profile(R: float, E: float, knot: float, n: int = 14) -> list[tuple[float, float]]:
    """A lathe profile of a balloon with its knot at z=0 and its crown at the top."""
    phi = np.linspace(0.0, math.pi, n)
    z = knot * 1.4 + E * R * (1 - np.cos(phi))
    r = R * np.sin(phi) * (0.78 + 0.22 * (1 - np.cos(phi)) / 2)
    pts = [(0.0, 0.0), (knot, 0.3 * knot), (0.9 * knot, knot), (0.5 * knot, knot * 1.45)]
    pts += [(float(a), float(b)) for a, b in zip(r[1:-1], z[1:-1])]
    pts.append((0.0, float(z[-1])))
    return pts


def _align_z(v: np.ndarray) -> tuple[float, float]:
    """(x, z) rotation angles in degrees that turn +Z to the unit vector v (about X, then Z)."""
    tilt = math.degrees(math.acos(max(-1.0, min(1.0, v[2]))))
    az = math.degrees(math.atan2(v[1], v[0]))
    return tilt, az


@register
class Balloon(PartsFactory):
    """One balloon or a bunch of 2-5 on strings tied to a small weight: lathed teardrop bodies
    with knots, thin strings, arranged so that no two balloons touch."""

    name = "balloon"
    tags = frozenset({S.Object, S.SmallObject, S.Decor, S.Balloon})
    size_class = "small"
    slots = ["plastic", "fabric", "metal"]
    solid_bottom = True
    params = {
        "n_balloons": Param(1, 5, kind="int", doc="balloons in the bunch"),
        "radius": Param(0.1, 0.16, doc="balloon radius (m)"),
        "elongation": Param(1.1, 1.35, doc="balloon height / width"),
        "string_length": Param(0.3, 1.0, doc="string length from the weight to the knot (m)"),
        "spread": Param(0.0, 1.0, doc="how far the bunch fans out"),
        "knot_size": Param(0.006, 0.012, doc="knot radius (m)"),
        "weight_style": Param(kind="choice", choices=("cube", "cylinder"), doc="weight shape"),
        "string_radius": Param(0.0008, 0.0018, doc="string radius (m)"),
    }
    WEIGHT = 0.04

    def _balloons(self, p) -> list[tuple[np.ndarray, np.ndarray]]:
        """(knot point, unit direction) of each balloon."""
        n, R, E, L = int(p["n_balloons"]), p["radius"], p["elongation"], p["string_length"]
        top = np.array([0.0, 0.0, self.WEIGHT])
        reach = E * R
        if n == 1:
            return [(top + np.array([0, 0, L]), np.array([0.0, 0.0, 1.0]))]
        ring = n - 1 if n >= 4 else n
        center = n >= 4
        tilt = math.radians(5 + 25 * p["spread"])
        for _ in range(60):  # lean the ring out until no two balloons touch
            pts = self._ring(ring, tilt, L, top, center)
            c = np.array([k + d * (1.4 * p["knot_size"] + reach) for k, d in pts])
            dist = np.linalg.norm(c[:, None] - c[None], axis=-1) + np.eye(len(c)) * 10
            if dist.min() > 2.1 * R * max(E, 1.0):
                break
            tilt += math.radians(2)
        return pts

    @staticmethod
    def _ring(ring, tilt, L, top, center):
        out = []
        for i in range(ring):
            a = 2 * math.pi * i / ring + 0.3
            d = np.array([math.sin(tilt) * math.cos(a), math.sin(tilt) * math.sin(a), math.cos(tilt)])
            li = L * (1.0 - 0.08 * (i % 2))
            out.append((top + d * li, d))
        if center:
            out.append((top + np.array([0, 0, L * 1.12]), np.array([0.0, 0.0, 1.0])))
        return out

    @staticmethod
    def _profile(p) -> list[tuple[float, float]]:
        return _balloon_profile(p["radius"], p["elongation"], p["knot_size"], 12)

    def _body(self, p, knot, d) -> m3d.Manifold:
        tilt, az = _align_z(d)
        return lathe(self._profile(p), 24).rotate((0.0, tilt, 0.0)).rotate((0.0, 0.0, az)).translate(
            tuple(float(v) for v in knot))

    def _body_bounds(self, p, knot, d) -> tuple[np.ndarray, np.ndarray]:
        """Bounds of the true solid of revolution (which contains its lathed polygon): a circle
        of radius r about axis d spans +-r*sqrt(1 - d_i^2) along world axis i."""
        prof = np.array(self._profile(p))
        r, z = prof[:, :1], prof[:, 1:]
        s = np.sqrt(np.clip(1.0 - d ** 2, 0.0, 1.0))[None, :]
        return knot + (z * d - r * s).min(axis=0), knot + (z * d + r * s).max(axis=0)

    def parts(self, p, detail):
        wt = self.WEIGHT
        cube = p["weight_style"] == "cube"
        w = (box((wt, wt, wt), (0, 0, wt / 2)) if cube or not detail
             else cylinder(wt / 2, wt, (0, 0, 0), 24))
        out = [Part(w, "metal")]
        rs = p["string_radius"]
        for i, (knot, d) in enumerate(self._balloons(p)):
            a = 2 * math.pi * i / 5
            anchor = np.array([0.006 * math.cos(a), 0.006 * math.sin(a), wt - 0.003])
            if detail:
                out.append(Part(self._body(p, knot, d), "plastic"))
                out.append(Part(rod(anchor, knot + d * 0.004, rs, 6), "fabric"))
            else:
                out.append(Part(box_between(*self._body_bounds(p, knot, d)), "plastic"))
                out.append(Part(rod(anchor, knot + d * 0.004, rs * 1.5, 4), "fabric"))
        return out

    def extra_surfaces(self, p):
        wt = self.WEIGHT
        if p["weight_style"] == "cube":
            poly = sg.box(-wt / 2 + 0.0005, -wt / 2 + 0.0005, wt / 2 - 0.0005, wt / 2 - 0.0005)
        else:
            poly = circle_polygon(wt / 2 - 0.0005, 24)
        return [support_polygon("bottom", (0, 0, 0), poly, subpart=Subpart.Bottom, up=False)]


# ------------------------------------------------------------------------------ candles
#: flame size (its height is 2.8 times this) (m)
FLAME = 0.011


def _flame(z0: float, size: float) -> m3d.Manifold:
    """A teardrop flame standing on z0 (its base overlaps the wick by 3 mm)."""
    prof = [(0.0, 0.0), (0.45 * size, 0.35 * size), (0.5 * size, 0.8 * size),
            (0.35 * size, 1.6 * size), (0.12 * size, 2.4 * size), (0.0, 2.8 * size)]
    return lathe(prof, 16).translate((0.0, 0.0, z0))


@register
class Candle(PartsFactory):
    """A candle: a `pillar` (with a melted pool and drips), a `taper` in a turned candlestick,
    a `tealight` in its metal cup, or a `jar` candle (wax in an open glass jar). Optionally lit:
    a wick and an emissive flame."""

    name = "candle"
    tags = frozenset({S.Object, S.SmallObject, S.Decor, S.Candle})
    size_class = "small"
    slots = ["wax", "metal", "glass", "fabric", "emissive"]
    solid_bottom = True
    params = {
        "style": Param(kind="choice", choices=("pillar", "taper", "tealight", "jar"),
                       doc="kind of candle"),
        "radius": Param(0.025, 0.045, doc="pillar / jar radius (m)"),
        "height": Param(0.06, 0.2, doc="pillar / jar / taper wax height (m)"),
        "lit": Param(kind="bool", doc="burning: wick and flame"),
        "melt_depth": Param(0.0, 0.012, doc="depth of the melted pool at the top (m)"),
        "drips": Param(0, 5, kind="int", doc="wax drips down the side (pillar, taper)"),
        "holder_radius": Param(0.035, 0.06, doc="candlestick base radius (m)"),
        "holder_height": Param(0.07, 0.18, doc="candlestick height (m)"),
    }

    def _base_radius(self, p) -> float:
        st = p["style"]
        if st == "taper":
            return p["holder_radius"]
        if st == "tealight":
            return 0.019
        return p["radius"]

    def _wax_top(self, p) -> tuple[float, float, float]:
        """(z of the wax top, wax radius, height the wick/flame start from)."""
        st, H, R = p["style"], p["height"], p["radius"]
        if st == "pillar":
            return H, R, H - p["melt_depth"]
        if st == "taper":
            zt = p["holder_height"] + H - 0.012
            return zt, 0.011, zt
        if st == "tealight":
            return 0.014, 0.017, 0.014
        zt = 0.65 * H
        return zt, R - 0.003, zt - 0.4 * p["melt_depth"]

    def parts(self, p, detail):
        st, H, R = p["style"], p["height"], p["radius"]
        z_wax, r_wax, z_wick = self._wax_top(p)
        top = max(z_wax, H if st == "jar" else 0.0)
        if p["lit"]:
            top = max(top, z_wick + 0.006 + 2.8 * FLAME)
        if not detail:
            return self._cheap(p, top)
        out = {"pillar": self._pillar, "taper": self._taper, "tealight": self._tealight,
               "jar": self._jar}[st](p)
        if p["lit"]:
            out.append(Part(rod((0, 0, z_wick - 0.004), (0, 0, z_wick + 0.009), 0.0012, 8), "fabric"))
            out.append(Part(_flame(z_wick + 0.006, FLAME), "emissive"))
        return out

    def _cheap(self, p, top):
        st = p["style"]
        if st == "taper":
            hr, hh = p["holder_radius"], p["holder_height"]
            return [Part(cylinder(hr, hh * 0.3 + 0.001, (0, 0, 0), 16, circumscribed=True), "metal"),
                    Part(cylinder(max(0.022, 0.45 * hr), top - hh * 0.3, (0, 0, hh * 0.3), 8,
                                  circumscribed=True), "wax")]
        out = [Part(cylinder(self._base_radius(p), top, (0, 0, 0), 16, circumscribed=True), "wax")]
        if st == "pillar":  # drips bulge out of the side: a box round each
            out += [_bbox_box([d], "wax") for d in self._drips(p, p["radius"] - 0.0015,
                                                               p["height"], 5)]
        return out

    def _drips(self, p, r: float, z_top: float, n_max: int) -> list[Part]:
        out = []
        for k in range(min(int(p["drips"]), n_max)):
            a = 2 * math.pi * (k * 0.382 + 0.1)
            ln = 0.015 + 0.012 * ((k * 7) % 3)
            c0 = np.array([r * math.cos(a), r * math.sin(a), z_top - 0.003])
            c1 = np.array([r * math.cos(a), r * math.sin(a), z_top - ln])
            drip = m3d.Manifold.hull_points(np.vstack([
                m3d.Manifold.sphere(0.0035, 8).translate(tuple(c0)).to_mesh().vert_properties,
                m3d.Manifold.sphere(0.0028, 8).translate(tuple(c1)).to_mesh().vert_properties]))
            out.append(Part(drip, "wax"))
        return out

    def _pillar(self, p):
        H, R, m = p["height"], p["radius"], p["melt_depth"]
        prof = [(0.0, 0.0), (R, 0.0), (R, H - 0.003), (R - 0.003, H), (R - 0.005, H)]
        if m > 0.001:
            prof += [(0.75 * R, H - 0.6 * m), (0.4 * R, H - m), (0.0, H - m)]
        else:
            prof += [(0.0, H)]
        return [Part(lathe(prof, 48), "wax")] + self._drips(p, R - 0.0015, H, 5)

    def _taper(self, p):
        hr, hh, H = p["holder_radius"], p["holder_height"], p["height"]
        stem_r, cup_r = 0.009, 0.02
        # a turned candlestick: foot, baluster stem, cup with a 14 mm socket for the candle
        prof = [(0.0, 0.0), (hr, 0.0), (hr, 0.08 * hh), (0.55 * hr, 0.16 * hh),
                (stem_r + 0.003, 0.24 * hh), (stem_r, 0.4 * hh), (1.5 * stem_r, 0.55 * hh),
                (stem_r, 0.7 * hh), (cup_r, hh - 0.018), (cup_r, hh), (0.0115, hh),
                (0.0115, hh - 0.014), (0.0, hh - 0.014)]
        holder = lathe(prof, 32)
        z0 = hh - 0.014 - SMALL_OVERLAP
        z1 = hh + H - 0.012
        candle = lathe([(0.0, z0), (0.011, z0), (0.0095, z1 - 0.002), (0.008, z1), (0.0, z1)], 24)
        return [Part(holder, "metal"), Part(candle, "wax")] + self._drips(p, 0.009, z1, 3)

    def _tealight(self, p):
        cup = lathe([(0.0, 0.0), (0.019, 0.0), (0.019, 0.016), (0.0185, 0.016), (0.0185, 0.0005),
                     (0.0, 0.0005)], 32)
        wax = cylinder(0.0187, 0.0145 - 0.0003, (0, 0, 0.0003), 32)
        return [Part(cup, "metal"), Part(wax, "wax")]

    def _jar(self, p):
        H, R = p["height"], p["radius"]
        w = 0.003
        jar = lathe([(0.0, 0.0), (R, 0.0), (R, H), (R - w, H), (R - w, 0.006), (0.0, 0.006)], 48)
        z_wax, _, _ = self._wax_top(p)
        m = p["melt_depth"]
        wax = lathe([(0.0, 0.006 - SMALL_OVERLAP), (R - w + 0.0005, 0.006 - SMALL_OVERLAP), (R - w + 0.0005, z_wax),
                     (0.6 * R, z_wax - 0.4 * m), (0.0, z_wax - 0.4 * m)], 48)
        return [Part(jar, "glass"), Part(wax, "wax")]

    def extra_surfaces(self, p):
        r = self._base_radius(p) - 0.0005
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(r, 32),
                                subpart=Subpart.Bottom, up=False)]


