"""Lamps: floor lamps (base disc, pole, shade on spokes), desk lamps (architect arm or gooseneck,
the head tilting on a joint) and table lamps (lathed ceramic base, harp, shade)."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.generators.lighting._parts import (
    CHEAP,
    CHEAP_ROUND,
    FINE,
    LIGHT_SLOTS,
    Kit,
    aabb_part,
    build_groups,
)
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.moving_parts import DoorJoint, make_joint
from indoorgen.assets.shapes.primitives import (
    OVERLAP,
    Part,
    box_between,
    circle_polygon,
    cylinder,
    lathe,
    rod,
)
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


def shade_radius(p: dict[str, Any], t: float) -> float:
    """Outer shade radius at fraction t of its height (0 = bottom rim, 1 = top rim)."""
    rb, rt = p["shade_bottom_radius"], min(p["shade_top_radius"], p["shade_bottom_radius"])
    style = p["shade_style"]
    if style == "drum":
        return rb
    if style == "cone":
        return rb + (rt - rb) * t
    # bell: concave flare towards the bottom; stays inside the straight cone
    return rt + (rb - rt) * (1 - t) ** 2


@register
class FloorLamp(PartsFactory):
    """A floor lamp: weighted base disc, pole, bulb and a drum/cone/bell shade."""

    name = "floor_lamp"
    tags = frozenset({S.Object, S.Lighting, S.FloorLamp})
    size_class = "medium"
    slots = ["metal", "shade", "emissive"]
    solid_bottom = True
    params = {
        "height": Param(1.4, 1.8, doc="overall height = top of the shade (m)"),
        "base_radius": Param(0.12, 0.2, doc="base disc radius (m)"),
        "base_height": Param(0.015, 0.04, doc="base disc thickness (m)"),
        "pole_radius": Param(0.008, 0.016, doc="pole radius (m)"),
        "shade_bottom_radius": Param(0.16, 0.25, doc="shade radius at its lower rim (m)"),
        "shade_top_radius": Param(0.1, 0.2, doc="shade radius at its upper rim (m; capped at "
                                                "the lower rim's for cone/bell)"),
        "shade_height": Param(0.22, 0.35, doc="shade height (m)"),
        "shade_style": Param(kind="choice", choices=("drum", "cone", "bell"), doc="shade shape"),
        "shade_thickness": Param(0.002, 0.004, doc="shade wall thickness (m)"),
    }

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Base disc, pole, shade on three spokes, socket and bulb."""
        H, br, bh = p["height"], p["base_radius"], p["base_height"]
        pr, sh, st = p["pole_radius"], p["shade_height"], p["shade_thickness"]
        z_s0 = H - sh
        z_spoke = H - 0.012
        out = [Part(cylinder(br, bh, (0, 0, 0), 48 if detail else 16, circumscribed=not detail,
                             radius_top=(br - min(0.01, bh) if detail else None)), "metal"),
               Part(cylinder(pr, z_spoke - bh + OVERLAP + 0.004, (0, 0, bh - OVERLAP), 16 if detail else 8,
                             circumscribed=not detail), "metal")]
        if not detail:
            rb, rt = shade_radius(p, 0.0), shade_radius(p, 1.0)
            # (the bell's profile lies inside this straight frustum)
            out.append(Part(cylinder(rb, sh, (0, 0, z_s0), 16, radius_top=rt, circumscribed=True),
                            "shade"))
            return out
        ns = 2 if p["shade_style"] != "bell" else 10
        ts = np.linspace(0.0, 1.0, ns)
        outer = [(shade_radius(p, t), z_s0 + t * sh) for t in ts]
        inner = [(r - st, z) for r, z in reversed(outer)]
        out.append(Part(lathe(outer + inner, 64), "shade"))
        # three horizontal spokes from the pole to the middle of the shade wall
        r_mid = shade_radius(p, (z_spoke - z_s0) / sh) - st / 2
        for i in range(3):
            a = 2 * math.pi * i / 3 + math.pi / 6
            out.append(Part(rod((0, 0, z_spoke), (r_mid * math.cos(a), r_mid * math.sin(a), z_spoke),
                                0.003, 8), "metal"))
        out.append(Part(cylinder(0.015, 0.05, (0, 0, z_spoke - 0.05), 16), "metal"))  # socket
        bulb = m3d.Manifold.sphere(0.035, 24).translate((0.0, 0.0, z_spoke - 0.075))
        out.append(Part(bulb, "emissive"))
        return out

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The base disc's underside as the `bottom`."""
        br = p["base_radius"]
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(br * 0.995, 48),
                                subpart=Subpart.Bottom, up=False)]


HEAD_TILT = 0.6  # head joint range: +-0.6 rad (~34 degrees)


@register
class DeskLamp(PartsFactory):
    """A desk lamp: a round or square weighted base, an architect arm (pairs of rods between
    knuckles) or a gooseneck, and a cone, dome or cylinder head on a fork. The head tilts on a
    revolute joint (`head_joint`); the bulb inside it is emissive."""

    name = "desk_lamp"
    tags = frozenset({S.Object, S.Lighting, S.DeskLamp})
    size_class = "medium"
    slots = LIGHT_SLOTS
    solid_bottom = True
    params = {
        "style": Param(kind="choice", choices=("architect", "gooseneck"), doc="arm type"),
        "base_shape": Param(kind="choice", choices=("round", "square"), doc="base outline"),
        "base_size": Param(0.12, 0.2, doc="base diameter / side (m)"),
        "arm_length": Param(0.22, 0.4, doc="lower arm / gooseneck rise (m)"),
        "upper_length": Param(0.18, 0.35, doc="upper arm / gooseneck reach (m)"),
        "arm_angle": Param(55.0, 80.0, doc="lower arm elevation (degrees; architect)"),
        "head_shape": Param(kind="choice", choices=("cone", "dome", "cylinder"), doc="head shade"),
        "head_radius": Param(0.045, 0.075, doc="head rim radius (m)"),
        "head_angle": Param(45.0, 75.0, doc="head axis below horizontal (degrees)"),
    }

    BASE_H = 0.025
    KNUCKLE_R = 0.012
    KNUCKLE_W = 0.008  # half width of the head knuckle along Y
    CHEEK = (0.010, 0.018)  # the fork's cheeks span these |y|

    def _pivot(self, p, k: Kit = CHEAP) -> tuple[np.ndarray, np.ndarray, list[Part]]:
        """The head pivot P, the arm's direction there, and the arm's parts (up to the fork)."""
        b = p["base_size"]
        xb = -0.25 * b
        z0 = self.BASE_H + 0.03
        out = [Part(k.disc(0.016, self.BASE_H - OVERLAP, 0.03 + OVERLAP, xb, 0.0, 16), "metal")]
        P0 = np.array([xb, 0.0, z0])
        if p["style"] == "architect":
            a1 = math.radians(p["arm_angle"])
            P1 = P0 + p["arm_length"] * np.array([math.cos(a1), 0.0, math.sin(a1)])
            u = np.array([math.cos(math.radians(10)), 0.0, math.sin(math.radians(10))])
            Q = P1 + (p["upper_length"] - 0.025) * u
            for P in (P0, P1):  # knuckles across the rod pairs
                out.append(Part(k.rod(P + (0, -0.022, 0), P + (0, 0.022, 0), 0.011, 16), "metal"))
            for y in (-0.016, 0.016):
                off = np.array([0.0, y, 0.0])
                out.append(Part(k.rod(P0 + off, P1 + off, 0.004, 8), "metal"))
                out.append(Part(k.rod(P1 + off, Q + off, 0.004, 8), "metal"))
        else:  # gooseneck: straight rise, then a quarter bend towards +X
            rise, reach = p["arm_length"], p["upper_length"] - 0.025
            rc = min(0.5 * reach, 0.5 * rise)
            pts = [P0, P0 + (0, 0, rise - rc)]
            for t in np.linspace(0.0, math.pi / 2, 7)[1:]:
                pts.append(pts[1] + np.array([rc * (1 - math.cos(t)), 0.0, rc * math.sin(t)]))
            pts.append(pts[-1] + np.array([reach - rc, 0.0, 0.0]))
            for a, c in zip(pts, pts[1:], strict=False):
                out.append(Part(k.rod(a, c, 0.006, 8), "metal"))
                out.append(Part(k.sphere(0.006, 8).translate(tuple(c)), "metal"))
            Q = pts[-1]
            u = np.array([1.0, 0.0, 0.0])
        P = Q + 0.025 * u
        # the fork: a bridge across at Q and two cheeks reaching the pivot
        out.append(Part(k.rod(Q + (0, -self.CHEEK[1], 0), Q + (0, self.CHEEK[1], 0), 0.007, 12), "metal"))
        for s in (-1, 1):
            ya, yb = s * self.CHEEK[0], s * self.CHEEK[1]
            cheek = [k.rod(c + (0, min(ya, yb), 0), c + (0, max(ya, yb), 0), self.KNUCKLE_R * 0.9, 16)
                     for c in (P, Q)]
            out.append(Part(m3d.Manifold.batch_hull(cheek), "metal"))
        return P, u, out

    def _head(self, p, P: np.ndarray, k: Kit = CHEAP) -> list[Part]:
        """The head (knuckle, neck, shade, socket, bulb) on link "head", its axis pointing
        `head_angle` below horizontal."""
        R, kind = p["head_radius"], p["head_shape"]
        sh = 1.6 * R if kind != "dome" else 1.2 * R
        th, r0 = 0.002, 0.02
        if kind == "cone":
            outer = [(r0, 0.0), (R, -sh)]
        elif kind == "cylinder":
            outer = [(R, 0.0), (R, -sh)]
        else:
            us = np.linspace(0.0, 1.0, 8)
            outer = [(r0 + (R - r0) * math.sin(u * math.pi / 2), -sh * (1 - math.cos(u * math.pi / 2)) ** 0.7)
                     for u in us]
        prof = [(0.0, 0.0)] + outer + [(outer[-1][0] - th, outer[-1][1])] + \
            [(max(r - th, 0.001), z - th) for r, z in reversed(outer[:-1])] + [(0.0, -th)]
        cup = k.lathe(prof, 32)
        neck = 0.045
        rb = min(0.3 * R, 0.022)
        z_sock = -th - 0.03  # the socket reaches into the cup's back, the neck starts inside it
        local = [(cup, "shade"),
                 (k.cylinder(0.011, 0.03 + th / 2, (0.0, 0.0, z_sock), 16), "metal"),
                 (k.bulb(0.0, rb).mirror((0.0, 0.0, 1.0)).translate((0.0, 0.0, z_sock + OVERLAP)),
                  "emissive"),
                 (k.cylinder(0.0065, neck + OVERLAP + th / 2, (0.0, 0.0, -th / 2), 12), "metal")]
        beta = p["head_angle"] - 90.0
        d = np.array([math.cos(math.radians(p["head_angle"])), 0.0, -math.sin(math.radians(p["head_angle"]))])
        back = P + d * neck
        out = [Part(s.rotate((0.0, beta, 0.0)).translate(tuple(back)), slot, "head") for s, slot in local]
        out.append(Part(k.rod(P + (0, -self.KNUCKLE_W, 0), P + (0, self.KNUCKLE_W, 0), self.KNUCKLE_R, 16),
                        "metal", "head"))
        return out

    def _base(self, p, k: Kit = FINE) -> Part:
        b = p["base_size"]
        if p["base_shape"] == "round":
            return Part(k.cylinder(b / 2, self.BASE_H, (0, 0, 0), 48, radius_top=b / 2 - 0.006), "metal")
        return Part(box_between((-b / 2, -b / 2, 0.0), (b / 2, b / 2, self.BASE_H)), "metal")

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Base, arm and fork, and the head on its `head` link."""
        k = FINE if detail else CHEAP
        P, _, arm = self._pivot(p, k)
        head = self._head(p, P, k if detail else CHEAP_ROUND)  # rotated: boxes would grow
        if detail:
            return [self._base(p)] + arm + head
        return [self._base(p) if p["base_shape"] == "square" else
                Part(cylinder(p["base_size"] / 2, self.BASE_H, (0, 0, 0), 16, circumscribed=True), "metal"),
                aabb_part(arm), aabb_part(head)]

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """The head's tilt about the fork's pivot, +-`HEAD_TILT`."""
        P, _, _ = self._pivot(p)
        return [make_joint("head_joint", DoorJoint("revolute", np.array([0.0, 1.0, 0.0]), P, "head"),
                           -HEAD_TILT, HEAD_TILT)]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The base's underside as the `bottom`."""
        b = p["base_size"]
        poly = (circle_polygon(0.998 * b / 2, 48) if p["base_shape"] == "round"
                else sg.box(-b / 2 + 0.0005, -b / 2 + 0.0005, b / 2 - 0.0005, b / 2 - 0.0005))
        return [support_polygon("bottom", (0, 0, 0), poly, subpart=Subpart.Bottom, up=False)]


def _base_radius(shape: str, R: float, t: float) -> float:
    """Lamp base radius at fraction t of its height (0 = foot, 1 = top)."""

    def bump(c: float, w: float) -> float:  # a Gaussian bump of width w centred on t = c
        return math.exp(-((t - c) / w) ** 2)

    if shape == "cylinder":
        return R
    if shape == "column":
        return R if t < 0.08 else 0.35 * R + 0.1 * R * bump(0.9, 0.05)
    if shape == "gourd":
        return 0.3 * R + 0.7 * R * max(bump(0.3, 0.2), 0.7 * bump(0.72, 0.13))
    return 0.25 * R + 0.75 * R * math.sin(math.pi * min(t * 1.05, 1.0)) ** 1.3  # vase


#: a table lamp's foot: at least this share of its base's widest radius and at least
#: `FOOT_MIN` (m), flaring out over the lowest share `FOOT_FLARE` of the base's height. A
#: gourd's or vase's own waist at the bottom (a quarter to a third of its widest radius, 3-4 cm)
#: under a shade twice as wide tipped lamps over in Newton (0.5-0.9 m, issue 12); real ceramic
#: lamps stand on a foot ring
FOOT_SHARE, FOOT_FLARE, FOOT_MIN = 0.6, 0.12, 0.05


@register
class TableLamp(PartsFactory):
    """A table lamp: a lathed ceramic base (vase, gourd, column or cylinder), a neck, socket and
    bulb, a harp carrying a drum, empire or bell shade on a spider."""

    name = "table_lamp"
    tags = frozenset({S.Object, S.Lighting, S.TableLamp})
    size_class = "medium"
    slots = LIGHT_SLOTS
    solid_bottom = True
    params = {
        "base_shape": Param(kind="choice", choices=("vase", "gourd", "column", "cylinder"),
                            doc="base profile"),
        "base_height": Param(0.15, 0.4, doc="base height (m)"),
        "base_radius": Param(0.05, 0.12, doc="base radius at its widest (m)"),
        "shade_shape": Param(kind="choice", choices=("drum", "empire", "bell"), doc="shade profile"),
        "shade_radius": Param(0.12, 0.22, doc="shade radius at its lower rim (m)"),
        "shade_height": Param(0.14, 0.28, doc="shade height (m)"),
        "neck_height": Param(0.03, 0.12, doc="gap from the base's top to the shade's rim (m)"),
    }

    def _foot_r(self, p) -> float:
        """The foot's radius: the base flares out to `FOOT_SHARE` of its widest radius (at
        least `FOOT_MIN`), so the lamp stands on a foot as wide as a real one's."""
        return max(_base_radius(p["base_shape"], p["base_radius"], 0.0),
                   FOOT_SHARE * p["base_radius"], FOOT_MIN)

    def _profile_r(self, p, t: float) -> float:
        """The base's radius at fraction t of its height: its shape, flaring out to the foot
        over the lowest `FOOT_FLARE` of it."""
        r = _base_radius(p["base_shape"], p["base_radius"], t)
        if t >= FOOT_FLARE:
            return r
        return max(r, self._foot_r(p) + (r - self._foot_r(p)) * t / FOOT_FLARE)

    def _shade_outer(self, p, z0: float) -> list[tuple[float, float]]:
        Rb, sh, kind = p["shade_radius"], p["shade_height"], p["shade_shape"]
        if kind == "drum":
            return [(Rb, z0), (Rb, z0 + sh)]
        Rt = 0.6 * Rb
        if kind == "empire":
            return [(Rb, z0), (Rt, z0 + sh)]
        ts = np.linspace(0.0, 1.0, 10)
        return [(Rt + (Rb - Rt) * (1 - t) ** 2, z0 + t * sh) for t in ts]

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """Ceramic base, neck, socket, bulb, harp and shade on its spider."""
        k = FINE if detail else CHEAP
        hb = p["base_height"]
        o = OVERLAP
        ts = np.linspace(0.0, 1.0, 24)
        prof = [(0.0, 0.0), (self._foot_r(p), 0.0)]
        prof += [(max(self._profile_r(p, t), 0.016), t * hb) for t in ts[1:]]
        prof += [(0.0, hb)]
        base = [Part(k.lathe(prof, 48), "ceramic")]
        z_sb = hb + p["neck_height"]
        sh = p["shade_height"]
        z_st = z_sb + sh
        rb = 0.03
        z_bulb = z_sb + 0.35 * sh - rb
        z_sock = z_bulb - 0.035
        fit = [Part(k.rod((0.0, 0.0, hb - 0.01), (0.0, 0.0, z_sock + o), 0.009, 12), "metal"),
               Part(k.disc(0.018, z_sock, 0.035 + o, n=16), "metal"),
               Part(k.bulb(z_bulb, rb), "emissive")]
        # the harp: two uprights from a saddle under the socket to a top bar, a finial on it
        yh = 0.05
        z_h = z_st - 0.012
        fit.append(Part(k.rod((0.0, -yh, z_sock + 0.006), (0.0, yh, z_sock + 0.006), 0.004, 8), "metal"))
        for y in (-yh, yh):
            fit.append(Part(k.rod((0.0, y, z_sock + 0.002), (0.0, y, z_h + 0.004), 0.0035, 8), "metal"))
        fit.append(Part(k.rod((0.0, -yh - 0.0035, z_h), (0.0, yh + 0.0035, z_h), 0.004, 8), "metal"))
        fit.append(Part(k.disc(0.01, z_h - o, 0.02, n=12), "metal"))
        outer = self._shade_outer(p, z_sb)
        th = 0.003
        shade = [Part(k.shell(outer, th), "shade")]
        r_sp = outer[-1][0] + (outer[-2][0] - outer[-1][0]) * 0.012 / (outer[-1][1] - outer[-2][1]) - th / 2
        for i in range(3):
            a = 2 * math.pi * i / 3 + math.pi / 2
            spoke = k.rod((0.0, 0.0, z_h), (r_sp * math.cos(a), r_sp * math.sin(a), z_h), 0.0025, 8)
            shade.append(Part(spoke, "metal"))
        return build_groups([base, fit, shade], detail)

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The base's round foot as the `bottom`."""
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(0.995 * self._foot_r(p), 48),
                                subpart=Subpart.Bottom, up=False)]
