"""Swivel office chairs: a five-star base on casters and everything above the gas spring on a
revolute `swivel` joint. Front (+X) is where one sits from."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
from numpy.typing import ArrayLike

from indoorgen.assets.generators.seating._parts import (
    bevel_points,
    points_box,
    shear_back,
    shear_points,
    soft_sheared,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.frames import frame
from indoorgen.assets.shapes.primitives import OVERLAP, Part, bevel_box, board, box, box_between, cylinder
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.model.tags import Semantics as S


@register
class OfficeChair(PartsFactory):
    """A swivel office chair: five-star base on twin-wheel casters, gas-lift column with a
    shroud, seat mechanism, padded seat, a padded or mesh back on a spine, optional armrests
    and headrest. Everything above the gas spring turns on a revolute `swivel` joint."""

    name = "office_chair"
    tags = frozenset({S.Object, S.Furniture, S.Seating, S.Chair, S.OfficeChair})
    size_class = "large"
    slots = ["plastic", "fabric", "metal"]
    params = {
        "base_radius": Param(0.28, 0.34, doc="distance of the casters from the column (m)"),
        "caster_radius": Param(0.022, 0.032, doc="caster wheel radius (m)"),
        "seat_height": Param(0.42, 0.54, doc="height of the seat's upper face (m)"),
        "seat_width": Param(0.46, 0.54, doc="seat Y extent (m)"),
        "seat_depth": Param(0.44, 0.52, doc="seat X extent (m)"),
        "seat_thickness": Param(0.06, 0.10, doc="seat cushion thickness (m)"),
        "back_height": Param(0.45, 0.68, doc="back panel height (m)"),
        "back_tilt": Param(4.0, 16.0, doc="backwards lean of the back (degrees)"),
        "back_style": Param(kind="choice", choices=("padded", "mesh"),
                            doc="upholstered back or a mesh stretched on a frame"),
        "armrests": Param(kind="bool", doc="add armrests"),
        "headrest": Param(kind="bool", doc="add a headrest above the back"),
    }
    SEAT_X = 0.02  # the seat sits slightly forward of the column (m)

    def _levels(self, p) -> dict[str, float]:
        cr = p["caster_radius"]
        z_tip = 2 * cr + 0.025  # underside of the star's arm tips
        z_hub0 = z_tip + 0.02
        z_hub1 = z_hub0 + 0.045
        z_seat0 = p["seat_height"] - p["seat_thickness"]
        z_mech0 = z_seat0 - 0.045
        z_gas = z_mech0 - 0.045
        return dict(tip=z_tip, hub0=z_hub0, hub1=z_hub1, seat0=z_seat0, mech0=z_mech0, gas=z_gas)

    def _base(self, p, detail) -> list[Part]:
        """Hub, five arms with their casters, gas spring and its shroud (placeholder: a box per
        arm with its caster, one cylinder for spring and shroud)."""
        L = self._levels(p)
        cr, R = p["caster_radius"], p["base_radius"]
        n = 16 if detail else 8
        out = [Part(cylinder(0.05, L["hub1"] + 0.01 - (L["hub0"] - 0.005), (0, 0, L["hub0"] - 0.005),
                             n * 2, circumscribed=not detail), "plastic")]
        for i in range(5):
            th = math.pi + 2 * math.pi * i / 5
            d = np.array([math.cos(th), math.sin(th), 0.0])
            t = np.array([-math.sin(th), math.cos(th), 0.0])
            arm = np.array([d * dist + t * sy * hw + (0, 0, z)
                            for dist, hw, zs in ((0.03, 0.026, (L["hub0"], L["hub1"])),
                                                 (R + 0.02, 0.018, (L["tip"], L["tip"] + 0.03)))
                            for sy in (-1, 1) for z in zs])
            c, sc = d * (R + 0.02), d * R  # wheel centre, swivel stem
            if not detail:  # the box around arm, wheel, hood and stem, from their corners
                pts: list[ArrayLike] = [arm]
                for ht, hd, zs in ((cr, 0.0225, (0.0, 2 * cr)), (0.88 * cr, 0.025, (cr, 2 * cr + 0.012))):
                    pts.append([c + a * t + b * d + (0, 0, z) for a in (-ht, ht) for b in (-hd, hd)
                                for z in zs])
                pts.append([sc + (a, b, z) for a in (-0.008, 0.008) for b in (-0.008, 0.008)
                            for z in (2 * cr, L["tip"] + OVERLAP)])
                out.append(Part(points_box(np.vstack(pts), 0.0), "plastic"))
                continue
            # a twin wheel on a radial axle, its hood and a swivel stem
            deg = math.degrees(th)
            wheel = cylinder(cr, 0.045, (0, 0, -0.0225), 16).rotate((90.0, 0.0, 0.0)).rotate(
                (0.0, 0.0, deg + 90.0)).translate((float(c[0]), float(c[1]), cr))
            hood = box((0.05, 1.76 * cr, cr + 0.012), (0, 0, 0)).rotate((0.0, 0.0, deg)).translate(
                (float(c[0]), float(c[1]), 1.5 * cr + 0.006))
            stem = cylinder(0.008, L["tip"] + OVERLAP - 2 * cr, (float(sc[0]), float(sc[1]), 2 * cr), 16)
            out += [Part(m3d.Manifold.hull_points(arm), "plastic"), Part(wheel, "plastic"),
                    Part(hood, "metal"), Part(stem, "metal")]
        zc0 = L["hub1"]
        hs = 0.6 * (L["gas"] - zc0)
        if detail:
            out.append(Part(cylinder(0.028, L["gas"] - zc0 + OVERLAP, (0, 0, zc0 - OVERLAP), 32), "metal"))
            out.append(Part(cylinder(0.042, hs, (0, 0, zc0 - OVERLAP), 32, radius_top=0.034), "plastic"))
        else:
            out.append(Part(cylinder(0.042, L["gas"] - zc0 + OVERLAP, (0, 0, zc0 - OVERLAP), 16,
                                     circumscribed=True), "plastic"))
        return out

    def _seat(self, p, detail) -> list[Part]:
        """Everything on the swivel: piston, mechanism, seat, spine, back, headrest, armrests
        (placeholder: one box for piston and mechanism, one per armrest, one for the headrest)."""
        L = self._levels(p)
        sd, sw, sh, st = p["seat_depth"], p["seat_width"], p["seat_height"], p["seat_thickness"]
        bh, tilt = p["back_height"], p["back_tilt"]
        x0 = self.SEAT_X
        link = "seat"
        seat = ((sd, sw, st), (x0, 0, sh - st / 2), min(0.03, st / 3))
        mech = ((-0.11, -0.1, L["mech0"]), (0.12, 0.1, L["seat0"] + OVERLAP))
        if detail:
            piston = cylinder(0.016, L["mech0"] - L["gas"] - 0.002 + OVERLAP, (0, 0, L["gas"] + 0.002), 16)
            out = [Part(piston, "metal", link),
                   board(*mech, "metal", link), Part(bevel_box(*seat, 2), "fabric", link)]
        else:
            out = [board((-0.11, -0.1, L["gas"] + 0.002), mech[1], "metal", link),
                   Part(box(*seat[:2]), "fabric", link)]
        # spine: under the seat to the back, then up behind the back panel
        xb = x0 - sd / 2  # seat rear
        zs0 = L["seat0"] - 0.04
        out.append(board((xb - 0.065, -0.03, zs0), (-0.08, 0.03, L["seat0"] - 0.01), "metal", link))
        zb0, zb1 = sh + 0.05, sh + 0.05 + bh
        spine = box_between((xb - 0.065, -0.03, zs0), (xb - 0.022, 0.03, zb0 + 0.5 * bh))
        out.append(Part(shear_back(spine, sh, tilt), "metal", link))
        bw, zm = 0.95 * sw, (zb0 + zb1) / 2
        if p["back_style"] == "padded":
            back = soft_sheared((0.06, bw, bh), (xb, 0, zm), 0.025, sh, tilt, detail)
            out.append(Part(back, "fabric", link))
        elif detail:
            ring = frame(bw, bh, 0.03, 0.035, (xb - 0.0125, 0, zm))
            mesh = box((0.008, bw - 0.06 + 2 * OVERLAP, bh - 0.06 + 2 * OVERLAP), (xb - 0.0125, 0, zm))
            out += [Part(shear_back(ring, sh, tilt), "plastic", link),
                    Part(shear_back(mesh, sh, tilt), "fabric", link)]
        else:
            back = shear_back(box((0.035, bw, bh), (xb - 0.0125, 0, zm)), sh, tilt)
            out.append(Part(back, "plastic", link))
        if p["headrest"]:
            post = ((xb - 0.03, -0.02, zb1 - 0.05), (xb - 0.002, 0.02, zb1 + 0.1))
            pad = ((0.06, 0.28, 0.13), (xb - 0.01, 0, zb1 + 0.08 + 0.065 - OVERLAP), 0.025)
            if detail:
                out += [Part(shear_back(box_between(*post), sh, tilt), "metal", link),
                        Part(soft_sheared(*pad, sh, tilt, True), "fabric", link)]
            else:
                corners = np.array([(x, y, z) for x in (post[0][0], post[1][0]) for y in (-0.02, 0.02)
                                    for z in (post[0][2], post[1][2])])
                pts = np.vstack([corners, bevel_points(*pad)])
                out.append(Part(points_box(shear_points(pts, sh, tilt), 0.0), "fabric", link))
        if p["armrests"]:
            za = sh + 0.2
            for s in (-1, 1):
                ya = s * (sw / 2 + 0.02)
                y0, y1 = sorted((s * 0.06, s * (sw / 2 + 0.035)))
                arm = [((-0.07, y0, zs0 + 0.005), (0.01, y1, L["seat0"] - 0.01)),   # bracket
                       ((-0.05, ya - 0.0125, zs0 + 0.005), (-0.01, ya + 0.0125, za + OVERLAP)),  # post
                       ((-0.145, ya - 0.0375, za), (0.105, ya + 0.0375, za + 0.03))]  # pad
                if detail:
                    out += [board(*arm[0], "metal", link), board(*arm[1], "plastic", link),
                            Part(bevel_box((0.25, 0.075, 0.03), (-0.02, ya, za + 0.015), 0.012, 2), "plastic",
                                 link)]
                else:
                    lo, hi = np.min([c[0] for c in arm], axis=0), np.max([c[1] for c in arm], axis=0)
                    out.append(board(lo, hi, "plastic", link))
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The five-star base, then everything on the swivel."""
        return self._base(p, detail) + self._seat(p, detail)

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """The seat's swivel about the column, a full turn."""
        return [Joint("swivel", "revolute", np.array([0.0, 0.0, 1.0]), np.zeros(3), -math.pi,
                      math.pi, "seat")]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The seat cushion's top."""
        sd, sw, sh = p["seat_depth"], p["seat_width"], p["seat_height"]
        m = min(0.03, p["seat_thickness"] / 3) + 0.01
        return [support_rect("seat", (self.SEAT_X, 0, sh), sd / 2 - m, sw / 2 - m)]
