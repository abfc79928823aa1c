"""Shower enclosures: a tray lined by wall panels, a glass enclosure and a rain head.

Fronts face +X; the enclosure stands in the corner of the back (-X) and left (+Y) walls.
"""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.bathroom._parts import (
    FIXTURE_MATERIALS,
    Prim,
    corner_outline,
    drain_disc,
    outline_polygon,
    prim_bounds,
    prim_parts,
    prim_solid,
    rounded_rect,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, DoorJoint, make_joint
from indoorgen.assets.shapes.primitives import OVERLAP, Part, box_between, rod
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


def _arc_panel(c: tuple[float, float], r0: float, r1: float, z0: float, z1: float,
               phi0: float, phi1: float) -> m3d.Manifold:
    """A curved panel: the ring sector between radii r0 and r1 about the vertical axis through
    `c`, from angle phi0 to phi1 (degrees, counter-clockwise from +X), spanning z0..z1."""
    cs = m3d.CrossSection.square((r1 - r0, z1 - z0)).translate((r0, z0))
    n = max(4, int(math.ceil((phi1 - phi0) / 3.75)))
    return m3d.Manifold.revolve(cs, int(n * 360 / (phi1 - phi0)), phi1 - phi0).rotate(
        (0.0, 0.0, phi0)).translate((c[0], c[1], 0.0))


SURROUND = 0.008  # thickness of the wall panels lining the enclosure's two walls


@register
class ShowerEnclosure(PartsFactory):
    """A shower: a low ceramic tray lined by wall panels on its back (-X) and left (+Y) walls,
    a glass enclosure - a square corner (fixed side panel, front with a hinged or sliding
    door), a quadrant (curved front of two sliding curved doors between straight returns) or a
    walk-in (one fixed panel braced to the wall, open end) - frameless or framed, and a rain
    head on a riser over a bar mixer. Doors are articulated; the tray's floor is an interior
    surface and the back wall panel its back."""

    name = "shower_enclosure"
    tags = frozenset({S.Object, S.Furniture, S.BathroomFixture, S.Shower})
    size_class = "large"
    slots = ["ceramic", "tile", "glass", "metal"]
    material_choices = {k: FIXTURE_MATERIALS[k] for k in ("ceramic", "tile", "glass", "metal")}
    solid_bottom = True
    params = {
        "layout": Param(kind="choice", choices=("corner_square", "quadrant", "walk_in"),
                        doc="enclosure type"),
        "tray_length": Param(0.8, 1.6, doc="Y extent (quadrant: at most depth + 0.2; walk-in: "
                                           "at least 1.2) (m)"),
        "tray_depth": Param(0.8, 1.0, doc="X extent (m)"),
        "tray_height": Param(0.03, 0.12, doc="tray height (m)"),
        "glass_height": Param(1.85, 2.0, doc="height of the glass above the tray (m)"),
        "glass_thickness": Param(0.006, 0.01, doc="glass thickness (m)"),
        "door": Param(kind="choice", choices=("hinged", "sliding"), doc="door of a square corner"),
        "frame": Param(kind="choice", choices=("frameless", "framed"), doc="metal profiles"),
        "quadrant_radius": Param(0.45, 0.6, doc="radius of a quadrant's curved front (m)"),
        "panel_fraction": Param(0.5, 0.8, doc="walk-in panel length / tray length"),
        "head_radius": Param(0.08, 0.15, doc="rain head radius (m)"),
        "head_height": Param(1.95, 2.15, doc="height of the rain head above the floor (m)"),
    }

    # ---- layout
    def _g(self, p) -> dict[str, Any]:
        D = p["tray_depth"]
        W = p["tray_length"]
        if p["layout"] == "quadrant":
            W = min(W, D + 0.2)
        elif p["layout"] == "walk_in":
            W = max(W, 1.2)
        th, t = p["tray_height"], p["glass_thickness"]
        e = 0.03
        R = min(p["quadrant_radius"], min(D, W) - 0.25)
        return dict(D=D, W=W, th=th, t=t, e=e, x_f=D / 2 - e, y_s=-W / 2 + e, R=R,
                    c=(D / 2 - R, -W / 2 + R), R_arc=R - e, R_d=R - e - t - MOVING_GAP,
                    z0=th - OVERLAP, z1=th + p["glass_height"], x_w=-D / 2 + SURROUND,
                    y_w=W / 2 - SURROUND, framed=p["frame"] == "framed")

    def _tray_outline(self, p, g) -> m3d.CrossSection:
        if p["layout"] == "quadrant":
            return corner_outline(g["D"], g["W"], "quarter_round", g["R"])
        return rounded_rect(g["D"], g["W"], 0.0)

    def _recess(self, p, g) -> m3d.CrossSection:
        return self._tray_outline(p, g).offset(-0.07, m3d.JoinType.Round, 2.0, 24)

    def _hinged(self, g) -> dict[str, float]:
        """Square corner, hinged door: the door's y range, hinged on the wall (+Y) side."""
        y1 = g["y_w"] - 0.02
        span = y1 - (g["y_s"] - g["t"] / 2)
        y0 = y1 - min(0.65, 0.6 * span)
        return dict(y0=y0, y1=y1)

    def _sliding(self, g) -> dict[str, float]:
        """Square corner, sliding door: outside the fixed front panel, overlapping it 5 cm."""
        y1 = g["y_w"] - 0.015
        ym = (g["y_s"] + y1) / 2
        return dict(y0=ym - 0.05, y1=y1, ym=ym, x0=g["x_f"] + g["t"] / 2 + MOVING_GAP,
                    z1=g["z1"] - 0.04)

    def _door_handle(self, x_face: float, y: float, zc: float, sides: tuple[int, ...]) -> list[Prim]:
        """Vertical bar handles on the faces of a +X-facing glass leaf (side +1: outside, -1:
        inside; x_face is the outer face for +1, the inner face for -1)."""
        out = []
        for s, xf in zip(sides, (x_face,) * len(sides), strict=True):
            xb = xf + s * 0.03
            out += [("rod", (xb, y, zc - 0.15), (xb, y, zc + 0.15), 0.01),
                    ("rod", (xf - s * OVERLAP, y, zc - 0.12), (xb, y, zc - 0.12), 0.007),
                    ("rod", (xf - s * OVERLAP, y, zc + 0.12), (xb, y, zc + 0.12), 0.007)]
        return out

    def _moving(self, p, g) -> list[tuple[list[Part], DoorJoint, float]]:
        """(parts, motion, upper limit) of each door leaf."""
        t, z0, x_f = g["t"], g["th"] + 0.01, g["x_f"]
        zc = g["th"] + 1.05
        if p["layout"] == "walk_in":
            return []
        if p["layout"] == "quadrant":
            (cx, cy), rd, out = g["c"], g["R_d"], []
            z1 = g["z1"] - 0.04
            for i, (a0, a1, sgn) in enumerate(((-90.0, -46.0, -1.0), (-44.0, 0.0, 1.0))):
                leaf = _arc_panel((cx, cy), rd - t / 2, rd + t / 2, z0, z1, a0, a1)
                ah = math.radians(-46.0 - 4.0 if sgn < 0 else -44.0 + 4.0)
                ro = rd + t / 2
                knob = [("rod", (cx + (ro - OVERLAP) * math.cos(ah), cy + (ro - OVERLAP) * math.sin(ah), zc),
                         (cx + (ro + 0.025) * math.cos(ah), cy + (ro + 0.025) * math.sin(ah), zc), 0.012)]
                parts = [Part(leaf, "glass", f"door_{i}")] + [Part(s.solid, "metal", f"door_{i}")
                                                            for s in prim_parts(knob, True)]
                motion = DoorJoint("revolute", np.array([0.0, 0.0, sgn]), np.array([cx, cy, 0.0]),
                                   f"door_{i}")
                # a leaf slides round until its far end is 9 cm (mixer) from the back wall or
                # 2 cm from the left wall, at most 36 degrees
                room = (cx - g["x_w"] - 0.09) if sgn < 0 else (g["y_w"] - 0.02 - cy)
                out.append((parts, motion, min(math.asin(min(max(room / (rd + t / 2), 0.1), 1.0)),
                                               math.radians(36.0))))
            return out
        if p["door"] == "hinged":
            h = self._hinged(g)
            leaf = box_between((x_f - t / 2, h["y0"], z0), (x_f + t / 2, h["y1"], g["z1"] - 0.01))
            handle = self._door_handle(x_f + t / 2, h["y0"] + 0.06, zc, (1,)) + \
                self._door_handle(x_f - t / 2, h["y0"] + 0.06, zc, (-1,))
            parts = [Part(leaf, "glass", "door_0")] + [Part(prim_solid(q), "metal", "door_0") for q in handle]
            motion = DoorJoint("revolute", np.array([0.0, 0.0, 1.0]),
                               np.array([x_f + t / 2, h["y1"], 0.0]), "door_0")
            return [(parts, motion, math.radians(95.0))]
        s = self._sliding(g)
        leaf = box_between((s["x0"], s["y0"], z0), (s["x0"] + t, s["y1"], s["z1"]))
        handle = self._door_handle(s["x0"] + t, s["y0"] + 0.08, zc, (1,))
        parts = [Part(leaf, "glass", "door_0")] + [Part(prim_solid(q), "metal", "door_0") for q in handle]
        motion = DoorJoint("prismatic", np.array([0.0, -1.0, 0.0]), np.array([s["x0"], s["y0"], z0]),
                           "door_0")
        # it stops short of the corner clamp, which stands proud of the fixed glass
        travel = min(0.8 * (s["y1"] - s["y0"]), s["y0"] - (g["y_s"] + t / 2 + 0.006 + MOVING_GAP))
        return [(parts, motion, travel)]

    def _fixed(self, p, g) -> list[Part]:
        """Tray, wall panels, fixed glass, profiles and rails."""
        D, W, th, t = g["D"], g["W"], g["th"], g["t"]
        x_f, y_s, x_w, y_w, z0, z1 = g["x_f"], g["y_s"], g["x_w"], g["y_w"], g["z0"], g["z1"]
        tray = m3d.Manifold.extrude(self._tray_outline(p, g), th)
        tray = tray - m3d.Manifold.extrude(self._recess(p, g), 0.05).translate((0.0, 0.0, th - 0.008))
        out = [Part(tray, "ceramic"),
               Part(box_between((-D / 2, -W / 2, z0), (x_w, W / 2, z1)), "tile"),
               Part(box_between((-D / 2, y_w, z0), (x_f + t / 2 + 0.006, W / 2, z1)), "tile")]
        out += self._drain_parts(p, g)
        glass, metal = [], []
        pw = 0.015 + (0.01 if g["framed"] else 0.0)  # wall profile width
        if p["layout"] == "walk_in":
            y0 = y_w - p["panel_fraction"] * W
            glass.append(box_between((x_f - t / 2, y0, z0), (x_f + t / 2, y_w + OVERLAP, z1)))
            metal.append(box_between((x_f - t / 2 - 0.006, y_w - pw, z0),
                                     (x_f + t / 2 + 0.006, y_w + OVERLAP, z1)))
            metal.append(rod((x_f, y0 + 0.05, z1 - 0.06), (x_w - OVERLAP, y0 + 0.05, z1 - 0.06), 0.01, 12))
        elif p["layout"] == "quadrant":
            (cx, cy), ra = g["c"], g["R_arc"]
            glass.append(box_between((x_w - OVERLAP, y_s - t / 2, z0), (cx + 0.01, y_s + t / 2, z1)))
            glass.append(box_between((x_f - t / 2, cy - 0.01, z0), (x_f + t / 2, y_w + OVERLAP, z1)))
            rail_z0 = g["z1"] - 0.04 + MOVING_GAP
            metal.append(_arc_panel((cx, cy), ra - 0.014, ra + 0.014, rail_z0, z1 + 0.01, -90.0, 0.0))
            metal.append(box_between((cx - 0.01, y_s - 0.014, rail_z0), (cx + 0.011, y_s + 0.014, z1 + 0.01)))
            metal.append(box_between((x_f - 0.014, cy - 0.011, rail_z0), (x_f + 0.014, cy + 0.01, z1 + 0.01)))
            metal.append(_arc_panel((cx, cy), ra - 0.014, ra + 0.014, z0, th + 0.008, -90.0, 0.0))
        else:
            glass.append(box_between((x_w - OVERLAP, y_s - t / 2, z0), (x_f + t / 2, y_s + t / 2, z1)))
            if p["door"] == "hinged":
                h = self._hinged(g)
                glass.append(box_between((x_f - t / 2, y_s - t / 2, z0),
                                         (x_f + t / 2, h["y0"] - MOVING_GAP, z1)))
                for zh in (th + 0.3, g["z1"] - 0.3):  # hinges on the wall
                    metal.append(box_between((x_f - 0.02, h["y1"] + MOVING_GAP, zh - 0.04),
                                             (x_f + 0.02, y_w + OVERLAP, zh + 0.04)))
            else:
                s = self._sliding(g)
                glass.append(box_between((x_f - t / 2, y_s - t / 2, z0), (x_f + t / 2, s["ym"] + 0.05, z1)))
                metal.append(box_between((x_f - t / 2 - 0.006, y_s - t / 2 - 0.006, s["z1"] + MOVING_GAP),
                                         (s["x0"] + t + 0.008, y_w + OVERLAP, z1 + 0.01)))
            metal.append(box_between((x_f - t / 2 - 0.006, y_s - t / 2 - 0.006, z0),
                                     (x_f + t / 2 + 0.006, y_s + t / 2 + 0.006, z1)))  # corner clamp/post
        if p["layout"] != "walk_in":  # wall profile of the side panel
            metal.append(box_between((x_w - OVERLAP, y_s - t / 2 - 0.006, z0),
                                     (x_w + pw, y_s + t / 2 + 0.006, z1)))
        if g["framed"] and p["layout"] != "walk_in":  # top rail along the side panel
            x_end = g["c"][0] + 0.011 if p["layout"] == "quadrant" else x_f + t / 2 + 0.006
            metal.append(box_between((x_w - OVERLAP, y_s - t / 2 - 0.006, z1 - 0.03),
                                     (x_end, y_s + t / 2 + 0.006, z1 + 0.01)))
        return (out + [Part(s, "glass") for s in glass] + [Part(s, "metal") for s in metal]
                + [Part(prim_solid(q), "metal") for q in self._head(p, g)])

    def _head(self, p, g) -> list[Prim]:
        """Bar mixer on the back wall panel, riser, arm and round rain head."""
        x_w = g["x_w"]
        xr = x_w + 0.05
        zm = g["th"] + 0.95
        zh = max(p["head_height"], zm + 0.5)
        arm = min(0.35, g["D"] / 2)
        return [("box", (x_w - OVERLAP, -0.1, zm - 0.04), (x_w + 0.012, 0.1, zm + 0.04)),
                ("rod", (xr, -0.16, zm), (xr, 0.16, zm), 0.025),
                ("rod", (x_w + 0.01, -0.07, zm), (xr, -0.07, zm), 0.012),
                ("rod", (x_w + 0.01, 0.07, zm), (xr, 0.07, zm), 0.012),
                ("cyl", 0.011, zh - zm, (xr, 0.0, zm)),
                ("rod", (x_w - OVERLAP, 0.0, zh - 0.15), (xr, 0.0, zh - 0.15), 0.01),
                ("rod", (xr - 0.01, 0.0, zh - 0.008), (xr + arm, 0.0, zh - 0.008), 0.01),
                ("cyl", p["head_radius"], 0.014, (xr + arm, 0.0, zh - 0.03))]

    def parts(self, p, detail):
        """The shower's solids: detailed, or the blocks of its placeholder."""
        g = self._g(p)
        if detail:
            return self._fixed(p, g) + [q for parts, _, _ in self._moving(p, g) for q in parts]
        D, W = g["D"], g["W"]
        hl, hh = prim_bounds(self._head(p, g))
        x1, z1 = g["x_f"] + g["t"] / 2 + 0.006, g["z1"] + 0.01
        if p["layout"] == "corner_square":
            x1 = g["x_f"] + g["t"] / 2 + 0.03 + 0.01  # hinged door handle
            if p["door"] == "sliding":
                x1 = self._sliding(g)["x0"] + g["t"] + 0.03 + 0.01
        elif p["layout"] == "quadrant":
            x1 = g["x_f"] + g["t"] / 2
        elif p["layout"] == "walk_in":
            z1 = g["z1"]
        return [Part(box_between((-D / 2, -W / 2, 0.0), (D / 2, W / 2, g["th"])), "ceramic"),
                Part(box_between((-D / 2, -W / 2, g["z0"]), (max(x1, D / 2), W / 2, max(z1, hh[2]))),
                     "glass")]

    def joints(self, p):
        """The shower's joints, one per hinged or sliding door."""
        g = self._g(p)
        return [make_joint(f"{m.link}_joint", m, 0.0, up) for _, m, up in self._moving(p, g)]

    def extra_surfaces(self, p):
        """The shower's surfaces besides its bounding box's: tray, bottom, back."""
        g = self._g(p)
        rec = self._recess(p, g)
        c = outline_polygon(rec).centroid
        floor = outline_polygon(rec, 0.005).difference(sg.Point(c.x, c.y).buffer(0.05, 16))
        return [support_polygon("tray", (0, 0, g["th"] - 0.008), floor, subpart=Subpart.Interior),
                support_polygon("bottom", (0, 0, 0), outline_polygon(self._tray_outline(p, g), 0.0005),
                                Subpart.Bottom, up=False),
                Surface.rect("back", Subpart.Back, (-g["D"] / 2, 0.0, g["z1"] / 2), (-1, 0, 0), (0, 1, 0),
                             g["W"] / 2 - 0.001, g["z1"] / 2 - 0.001)]

    def _drain_parts(self, p, g) -> list[Part]:
        c = outline_polygon(self._recess(p, g)).centroid
        return [Part(drain_disc(c.x, c.y, g["th"] - 0.008, 0.045), "metal")]
