"""Workshop tools and supplies for a garage's workbench and shelves: a portable toolbox whose lid
is hinged along its back edge and carries the handle, and a paint tin with a pressed-in lid, a
label band and a wire bail standing up or folded down."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, DoorJoint, make_joint
from indoorgen.assets.shapes.outlines import largest_polygon
from indoorgen.assets.shapes.primitives import (
    SMALL_OVERLAP,
    Part,
    box_between,
    circle_polygon,
    lathe,
    rod,
    rounded_rect_section,
    torus,
)
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.assets.shapes.vessels import cheap_cylinder, round_bottom
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

#: how far a toolbox's lid opens about its back edge (rad): past upright, so it stays open
LID_OPEN = math.radians(105)


def _tapered(plan: m3d.CrossSection, z0: float, z1: float, s0: float, s1: float) -> m3d.Manifold:
    """`plan` extruded from z0 to z1, scaled about its centre by s0 at z0 and s1 at z1."""
    return m3d.Manifold.extrude(plan.scale((s0, s0)), z1 - z0, 0, 0.0, (s1 / s0, s1 / s0)).translate(
        (0.0, 0.0, z0))


def _front_slab(x_lo: float, x_hi: float, x_out: float, y0: float, y1: float, z0: float,
                z1: float) -> m3d.Manifold:
    """A plate on a (possibly sloping) +X face: its back at x_lo (at z0) and x_hi (at z1), its
    front at x_out, spanning y0..y1 and z0..z1."""
    pts = [(x, y, z) for y in (y0, y1) for x, z in ((x_lo, z0), (x_hi, z1), (x_out, z0), (x_out, z1))]
    return m3d.Manifold.hull_points(np.array(pts, float))


@register
class Toolbox(PartsFactory):
    """A portable toolbox: `metal` (a straight-walled painted steel box) or `plastic` (tapered
    towards its foot, corners rounded in plan). Its lid, an upturned tray on its own link
    ("lid"), is hinged along the back edge (revolute joint) and carries a grip bar on two posts;
    latches on the front hold it shut. No support surface on top: the handle stands there."""

    name = "toolbox"
    tags = frozenset({S.Object, S.SmallObject, S.Container, S.Workshop, S.Toolbox})
    size_class = "small"
    slots = ["metal", "plastic", "handle"]
    material_choices = {
        "metal": {"painted_metal": 5.0, "galvanized_steel": 0.7, "brushed_steel": 0.5,
                  "rusty_metal": 0.2},
        "plastic": {"matte_plastic": 3.0, "textured_plastic": 2.0, "glossy_plastic": 1.0},
        "handle": {"matte_plastic": 2.0, "rubber": 1.5, "brushed_steel": 1.0, "chrome": 0.5},
    }
    solid_bottom = True
    params = {
        "length": Param(0.3, 0.6, doc="Y extent of the box (m)"),
        "depth": Param(0.15, 0.25, doc="X extent of the box, latches aside (m)"),
        "height": Param(0.12, 0.25, doc="height to the top of the shut lid, handle aside (m)"),
        "style": Param(kind="choice", choices=("metal", "plastic"), doc="material / build"),
        "lid_frac": Param(0.2, 0.4, doc="lid height / height"),
        "wall_thickness": Param(0.0015, 0.004, doc="wall thickness of the box and the lid (m)"),
        "corner_radius": Param(0.008, 0.03, doc="plastic: corner rounding in plan (m)"),
        "taper": Param(0.9, 0.97, doc="plastic: size of the foot / size of the rim"),
        "handle_height": Param(0.025, 0.045, doc="height of the grip's axis above the lid (m)"),
        "handle_frac": Param(0.35, 0.6, doc="grip length / length"),
        "n_latches": Param(1, 3, kind="int", doc="latches on the front"),
    }
    LATCH_T = 0.006  # how far the latches stand proud of the front (m)
    LATCH_W = 0.028  # width of a latch (m)
    GRIP_R = 0.009  # radius of the grip bar (m)
    POST = 0.014  # side of the square handle posts (m)
    LID_TAPER = 0.96  # plastic: size of the lid's top / size of its rim

    def _slot(self, p: dict[str, Any]) -> str:
        return "plastic" if p["style"] == "plastic" else "metal"

    def _dims(self, p: dict[str, Any]) -> tuple[float, float, float, float, float, float]:
        """(box height, lid bottom z, lid height, foot scale, lid top scale, corner radius)."""
        hl = p["lid_frac"] * p["height"]
        hb = p["height"] - hl - MOVING_GAP
        if p["style"] == "plastic":
            return hb, hb + MOVING_GAP, hl, p["taper"], self.LID_TAPER, p["corner_radius"]
        return hb, hb + MOVING_GAP, hl, 1.0, 1.0, 0.0

    def _box_scale(self, p: dict[str, Any], z: float) -> float:
        hb, _, _, sc, _, _ = self._dims(p)
        return sc + (1.0 - sc) * z / hb

    def _lid_scale(self, p: dict[str, Any], z: float) -> float:
        _, z0, hl, _, st, _ = self._dims(p)
        return 1.0 + (st - 1.0) * (z - z0) / hl

    def _box(self, p: dict[str, Any]) -> m3d.Manifold:
        """The open box: tapered walls and floor."""
        D, W, wt = p["depth"], p["length"], p["wall_thickness"]
        hb, _, _, sc, _, r = self._dims(p)
        plan = rounded_rect_section(D, W, r)
        inner = plan.offset(-wt, m3d.JoinType.Miter, 2.0)
        top = hb + 0.01
        return _tapered(plan, 0.0, hb, sc, 1.0) - _tapered(
            inner, wt, top, self._box_scale(p, wt), self._box_scale(p, top))

    def _lid(self, p: dict[str, Any]) -> m3d.Manifold:
        """The lid: an upturned tray over the box's rim."""
        D, W, wt = p["depth"], p["length"], p["wall_thickness"]
        _, z0, hl, _, st, r = self._dims(p)
        plan = rounded_rect_section(D, W, r)
        inner = plan.offset(-wt, m3d.JoinType.Miter, 2.0)
        lo, hi = z0 - 0.005, z0 + hl - wt
        return _tapered(plan, z0, z0 + hl, 1.0, st) - _tapered(
            inner, lo, hi, self._lid_scale(p, lo), self._lid_scale(p, hi))

    def _handle(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The grip bar on two posts on top of the lid (on the lid's link)."""
        _, z0, hl, _, _, _ = self._dims(p)
        zt, half = z0 + hl, p["handle_frac"] * p["length"] / 2
        zg, g, q = zt + p["handle_height"], self.GRIP_R, self.POST / 2
        if not detail:
            return [Part(box_between((-g, -half, zt - SMALL_OVERLAP), (g, half, zg + g)), "handle", "lid")]
        yp = half - q - 0.004
        posts = [Part(box_between((-q, s * yp - q, zt - SMALL_OVERLAP), (q, s * yp + q, zg)),
                      self._slot(p), "lid") for s in (-1, 1)]
        return posts + [Part(rod((0.0, -half, zg), (0.0, half, zg), g, 16), "handle", "lid")]

    def _latches(self, p: dict[str, Any]) -> list[Part]:
        """A plate on the box's front below the rim and its catch on the lid's front, per latch."""
        D, W, n = p["depth"], p["length"], p["n_latches"]
        hb, z0, hl, _, _, _ = self._dims(p)
        xo, half = D / 2 + self.LATCH_T, self.LATCH_W / 2
        zp, zk = hb - min(0.035, 0.6 * hb), z0 + min(0.012, 0.5 * hl)
        out = []
        for y in np.linspace(-0.3 * W, 0.3 * W, n) if n > 1 else [0.0]:
            plate = _front_slab(D / 2 * self._box_scale(p, zp) - 0.001, D / 2 - 0.001, xo,
                                y - half, y + half, zp, hb - 0.0005)
            catch = _front_slab(D / 2 - 0.001, D / 2 * self._lid_scale(p, zk) - 0.001, xo,
                                y - 0.6 * half, y + 0.6 * half, z0 + 0.0005, zk)
            out += [Part(plate, "metal"), Part(catch, "metal", "lid")]
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The box and latch plates, and on the `lid` link the lid, its catches and handle."""
        D, W, slot = p["depth"], p["length"], self._slot(p)
        hb, z0, hl, _, _, _ = self._dims(p)
        if not detail:
            xo = D / 2 + self.LATCH_T
            return [Part(box_between((-D / 2, -W / 2, 0.0), (xo, W / 2, hb)), slot),
                    Part(box_between((-D / 2, -W / 2, z0), (xo, W / 2, z0 + hl)), slot, "lid")
                    ] + self._handle(p, False)
        return [Part(self._box(p), slot), Part(self._lid(p), slot, "lid")] + \
            self._latches(p) + self._handle(p, True)

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """The lid's hinge along the back edge of the rim: it opens up and over backwards."""
        z0 = self._dims(p)[1]
        hinge = DoorJoint("revolute", np.array([0.0, -1.0, 0.0]),
                          np.array([-p["depth"] / 2, 0.0, z0]), "lid")
        return [make_joint("lid_joint", hinge, 0.0, LID_OPEN)]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The underside: the box's foot, 0.5 mm in from its edge."""
        _, _, _, sc, _, r = self._dims(p)
        foot = largest_polygon(rounded_rect_section(p["depth"], p["length"], r).scale((sc, sc)).offset(
            -0.0005, m3d.JoinType.Miter, 2.0))
        return [support_polygon("bottom", (0, 0, 0), foot, subpart=Subpart.Bottom, up=False)]


@register
class PaintCan(PartsFactory):
    """A paint tin: a steel cylinder with a rolled chime at its foot and a rim at the top, the
    lid pressed in below the rim (one piece with the can), a label band round the middle,
    optional stiffening beads, and a wire bail hooked into two ear lugs (at +-Y), standing up
    over the lid or folded down flat round the front of the can. With the bail down the lid is
    a `top` support surface (a brush or another tin stands on it)."""

    name = "paint_can"
    tags = frozenset({S.Object, S.SmallObject, S.Container, S.Workshop, S.PaintCan})
    size_class = "small"
    slots = ["metal", "label"]
    material_choices = {
        "metal": {"brushed_steel": 2.0, "galvanized_steel": 1.5, "painted_metal": 1.5,
                  "rusty_metal": 0.2},
        "label": {"paper": 2.0, "painted_metal": 1.0},
    }
    solid_bottom = True
    params = {
        "radius": Param(0.05, 0.12, doc="radius of the can's wall (m)"),
        "height": Param(0.08, 0.25, doc="height to the top of the rim (m)"),
        "rim_height": Param(0.004, 0.008, doc="height of the rolled rim at the top (m)"),
        "lid_recess": Param(0.002, 0.005, doc="depth of the lid's centre below the rim (m)"),
        "label_frac": Param(0.4, 0.75, doc="label band height / height of the straight wall"),
        "beads": Param(0, 2, kind="int", doc="stiffening beads rolled round the wall"),
        "wire_radius": Param(0.0012, 0.0025, doc="radius of the bail's wire (m)"),
        "bail_up": Param(kind="bool", doc="the bail stands over the lid (else folded down)"),
    }
    SECTIONS = 48
    CHIME = 0.0025  # how far the foot chime and the top rim stand proud of the wall (m)
    FOOT = 0.004  # height of the foot chime (m)
    RIM_W = 0.007  # width of the top rim and the lid's channel, in from the wall (m)
    LABEL_T = 0.0006  # thickness of the label (m)
    EAR = 0.008  # distance of the bail's wire from the wall (m)
    EAR_HALF = (0.006, 0.007)  # half width (X) and half height (Z) of an ear lug (m)

    def _ear_z(self, p: dict[str, Any]) -> float:
        return p["height"] - p["rim_height"] - self.EAR_HALF[1]

    def _wall_span(self, p: dict[str, Any]) -> tuple[float, float]:
        """(bottom, top) z of the straight wall between the foot chime and the rim."""
        return self.FOOT + 0.0015, p["height"] - p["rim_height"]

    def _can(self, p: dict[str, Any]) -> m3d.Manifold:
        """The solid tin: foot chime, wall, rim, and the lid pressed in below the rim."""
        R, H, rh = p["radius"], p["height"], p["rim_height"]
        rc, ri, zl = R + self.CHIME, R - self.RIM_W, H - p["lid_recess"]
        prof = [(0.0, 0.0), (rc, 0.0), (rc, self.FOOT), (R, self.FOOT + 0.0015), (R, H - rh),
                (rc, H - rh + 0.0015), (rc, H - 0.001), (rc - 0.001, H), (ri, H), (ri, zl - 0.002),
                (ri - 0.003, zl - 0.002), (ri - 0.004, zl), (0.0, zl)]
        return lathe(prof, self.SECTIONS)

    def _bands(self, p: dict[str, Any]) -> list[Part]:
        """The label round the middle of the wall, and the beads above and below it."""
        R = p["radius"]
        z0, z1 = self._wall_span(p)
        zc, h = (z0 + z1) / 2, p["label_frac"] * (z1 - z0) / 2
        a, b = R - 0.001, R + self.LABEL_T
        out = [Part(lathe([(a, zc - h), (b, zc - h), (b, zc + h), (a, zc + h)], self.SECTIONS), "label")]
        for z in [(zc + h + z1) / 2, (z0 + zc - h) / 2][:p["beads"]]:
            bead = [(a, z - 0.0015), (R + 0.0012, z), (a, z + 0.0015)]
            out.append(Part(lathe(bead, self.SECTIONS), "metal"))
        return out

    def _ears(self, p: dict[str, Any]) -> list[Part]:
        """The two lugs at +-Y the bail hooks into."""
        R, ze = p["radius"], self._ear_z(p)
        ex, ez = self.EAR_HALF
        ye = R + self.EAR + p["wire_radius"] + 0.0015
        return [Part(box_between((-ex, min(s * (R - 0.001), s * ye), ze - ez),
                                 (ex, max(s * (R - 0.001), s * ye), ze + ez)), "metal")
                for s in (-1, 1)]

    def bail(self, p: dict[str, Any]) -> m3d.Manifold:
        """The wire bail (design frame): a half ring through the ears, standing up in the YZ
        plane or folded down flat round the can's front (+X)."""
        re, ze = p["radius"] + self.EAR, self._ear_z(p)
        ring = torus(re, p["wire_radius"], sections=self.SECTIONS, tube_sections=8)
        if p["bail_up"]:
            return ring.rotate((0.0, 90.0, 0.0)).trim_by_plane((0.0, 0.0, 1.0), 0.0).translate(
                (0.0, 0.0, ze))
        return ring.trim_by_plane((1.0, 0.0, 0.0), 0.0).translate((0.0, 0.0, ze))

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The tin with its label, beads, ears and bail, or their covering blocks."""
        if detail:
            return [Part(self._can(p), "metal")] + self._bands(p) + self._ears(p) + \
                [Part(self.bail(p), "metal")]
        R, H, w, ze = p["radius"], p["height"], p["wire_radius"], self._ear_z(p)
        ex, ez = self.EAR_HALF
        re, ye = R + self.EAR + w, R + self.EAR + w + 0.0015
        if p["bail_up"]:
            bail = box_between((-w, -re, ze), (w, re, ze + re))
        else:
            bail = box_between((0.0, -re, ze - w), (re, re, ze + w))
        return [cheap_cylinder(R + self.CHIME, 0.0, H, "metal"),
                Part(box_between((-ex, -ye, ze - ez), (ex, ye, ze + ez)), "metal"), Part(bail, "metal")]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The flat underside, and with the bail folded down the lid's centre as `top`."""
        R = p["radius"]
        out = [round_bottom("bottom", R + self.CHIME, self.SECTIONS)]
        if not p["bail_up"]:
            lid = circle_polygon(R - self.RIM_W - 0.005, self.SECTIONS)
            out.append(support_polygon("top", (0, 0, p["height"] - p["lid_recess"]), lid))
        return out
