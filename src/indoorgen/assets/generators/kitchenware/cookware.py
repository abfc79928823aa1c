"""Cookware: cooking pots (with a lid on its own link), frying pans and pot lids.

Pots and pans are hollow vessels (`shapes.vessels.revolve_vessel`); long handles are swept
tubes (`kitchenware._parts.sweep`).
"""
from __future__ import annotations

import math

import manifold3d as m3d
import numpy as np

from indoorgen.assets.generators.kitchenware._parts import LID_GAP, sweep
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.moving_parts import DoorJoint, make_joint
from indoorgen.assets.shapes.primitives import Part, bevel_box, box_between, cylinder, lathe, torus
from indoorgen.assets.shapes.vessels import (
    SECTIONS,
    Vessel,
    cheap_cylinder,
    interior_floor,
    revolve_vessel,
    round_bottom,
)
from indoorgen.model.tags import Semantics as S

#: kitchen metals: stainless, chrome, enamelled (painted) and brass, never rusty
COOKWARE_METAL = {"brushed_steel": 4.0, "chrome": 1.0, "painted_metal": 1.5, "brass": 0.3}


# ------------------------------------------------------------------------------------- pots
def _dome(u: np.ndarray) -> np.ndarray:
    """Dome height fraction from the rim (u = 0) to the apex (u = 1)."""
    return np.sin(0.5 * math.pi * u) ** 0.8


def lid_solids(radius: float, dome: float, z0: float, knob: str, skirt_r: float = 0.0,
               thickness: float = 0.0025) -> list[m3d.Manifold]:
    """A domed lid whose rim's underside is at z0: a lathed shell `thickness` thick (open
    below), optionally a skirt (a short tube of outer radius `skirt_r` hanging 8 mm below the
    rim, to sit inside a pot) and a knob, a loop or a bar handle on top."""
    t = thickness
    u = np.linspace(0.0, 1.0, 9)
    r = radius * (1 - u)
    z = z0 + dome * _dome(u)
    outer = list(zip(r.tolist(), (z + t).tolist(), strict=True))
    inner = list(zip(r.tolist(), z.tolist(), strict=True))
    prof = [(radius, z0)] + outer + inner[::-1][:-1]
    out = [lathe(prof, SECTIONS)]
    if skirt_r > 0:
        z_in = z0 + dome * float(_dome(np.array([1 - skirt_r / radius]))[0])
        out.append(lathe([(skirt_r - t, z0 - 0.008), (skirt_r, z0 - 0.008),
                          (skirt_r, z_in + 0.5 * t), (skirt_r - t, z_in + 0.5 * t)], SECTIONS))
    top = z0 + t + dome

    def surface(rr: float) -> float:  # height of the dome's outer surface at radius rr, -1 mm
        return z0 + t + dome * float(_dome(np.array([max(1 - rr / radius, 0.0)]))[0]) - 0.001

    if knob == "knob":
        out += [cylinder(0.007, 0.014, (0, 0, top - 0.003), 16),
                lathe([(0.0, top + 0.01), (0.018, top + 0.012), (0.02, top + 0.018),
                       (0.014, top + 0.024), (0.0, top + 0.025)], 24)]
    elif knob == "loop":  # an arch whose feet (at r = 25 mm) sink into the dome
        zf = surface(0.026)
        ring = torus(1.0, 0.005 / 0.025, sections=20, tube_sections=8).rotate((90.0, 0.0, 0.0))
        ring = ring.scale((0.025, 0.025, (top + 0.027 - zf) / 1.2)).translate((0, 0, zf))
        out.append(ring.trim_by_plane((0, 0, 1), zf))
    else:  # bar: a flat bridge on two posts standing on the dome
        zf = surface(0.035)
        out += [box_between((-0.004, -0.035, zf), (0.004, -0.027, top + 0.02)),
                box_between((-0.004, 0.027, zf), (0.004, 0.035, top + 0.02)),
                bevel_box((0.012, 0.08, 0.008), (0, 0, top + 0.022), 0.003)]
    return out


def lid_top(dome: float, z0: float, knob: str, thickness: float = 0.0025) -> float:
    """Highest point of `lid_solids`."""
    top = z0 + thickness + dome
    return top + {"knob": 0.025, "loop": 0.027, "bar": 0.026}[knob]


def long_handle(x0: float, z0: float, length: float, angle: float, style: str
                ) -> list[tuple[m3d.Manifold, str]]:
    """A pan's long handle leaving the body at (x0, z0) along +X, rising at `angle` (rad):
    "stick" (round metal with a hanging hole), "flat" (a metal strap with a hole) or "wood"
    (a metal shank into a wooden grip). Returns (solid, slot) pairs."""
    ca, sa = math.cos(angle), math.sin(angle)

    def line(a: float, b: float):
        return lambda t: np.c_[x0 + (a + (b - a) * t) * ca, np.zeros_like(t),
                               z0 + (a + (b - a) * t) * sa]

    def lerp(a: float, b: float):
        return lambda t: a + (b - a) * t

    end = np.array([x0 + (length - 0.025) * ca, 0.0, z0 + (length - 0.025) * sa])
    hole = cylinder(0.005, 0.1, (end[0], 0.0, end[2] - 0.05), 12)
    if style == "flat":
        strap = sweep(line(0.0, length), lerp(0.02, 0.032), lerp(0.007, 0.005), 6, "square")
        return [(strap - hole, "metal")]
    if style == "stick":
        stick = sweep(line(0.0, length), lerp(0.018, 0.026), lerp(0.014, 0.01), 8)
        return [(stick - hole, "metal")]
    shank = sweep(line(0.0, 0.35 * length + 0.01), lerp(0.012, 0.012), lerp(0.008, 0.008), 4)
    grip = sweep(line(0.35 * length, length), lerp(0.024, 0.03), lerp(0.02, 0.024), 10)
    return [(shank, "metal"), (grip, "wood")]


def long_handle_bounds(x0: float, z0: float, length: float, angle: float, style: str
                       ) -> tuple[float, float, float, float]:
    """(x_max, half width, z_min, z_max) enclosing `long_handle` (its sweeps' sections)."""
    w, th = {"flat": (0.032, 0.007), "stick": (0.026, 0.014), "wood": (0.03, 0.024)}[style]
    x1 = x0 + length * math.cos(angle) + 0.5 * th * math.sin(angle)
    z_hi = z0 + length * math.sin(angle) + 0.5 * th * math.cos(angle) + 1e-4
    return x1, 0.5 * w, z0 - 0.5 * th - 1e-4, z_hi


def side_handles(style: str, r_at: float, z: float, axis: str = "y",
                 sides: tuple[int, ...] = (-1, 1)) -> list[m3d.Manifold]:
    """Handles on the sides of a pot whose outer radius at height z is `r_at`: "loops" (half
    tori lying flat) or "tabs" (flat lugs), sunk into the wall (clip them with the cavity)."""
    out = []
    for s in sides:
        if style == "loops":
            ring = torus(0.026, 0.005, sections=24, tube_sections=8)
            if axis == "y":
                ring = ring.translate((0.0, s * r_at, z)).trim_by_plane((0, s, 0), r_at - 0.008)
            else:
                ring = ring.translate((s * r_at, 0.0, z)).trim_by_plane((s, 0, 0), r_at - 0.008)
            out.append(ring)
        else:
            c = (0.0, s * (r_at + 0.013), z) if axis == "y" else (s * (r_at + 0.013), 0.0, z)
            ext = (0.06, 0.04, 0.009) if axis == "y" else (0.04, 0.06, 0.009)
            out.append(bevel_box(ext, c, 0.003))
    return out


#: how far side handles reach beyond the wall (loops: major + minor radius; tabs: 0.013+0.02)
SIDE_REACH = {"loops": 0.031, "tabs": 0.033}
SIDE_HALF_H = {"loops": 0.005, "tabs": 0.0045}


@register
class CookingPot(PartsFactory):
    """A cooking pot: stock pot or casserole (two loop or tab handles) or saucepan (one long
    handle towards +X); straight or tapered hollow body with a rolled rim; optionally a domed
    lid (knob, loop or bar handle) on its own link that lifts straight off."""

    name = "cooking_pot"
    tags = frozenset({S.Object, S.SmallObject, S.Kitchenware, S.Container, S.Pot})
    size_class = "small"
    slots = ["metal", "glass", "wood", "plastic"]
    material_choices = {"metal": COOKWARE_METAL}
    solid_bottom = True
    params = {
        "radius": Param(0.08, 0.14, doc="outer radius at the rim (m)"),
        "height": Param(0.08, 0.2, doc="body height (m)"),
        "taper": Param(0.85, 1.0, doc="base radius / rim radius"),
        "wall_thickness": Param(0.002, 0.004, doc="wall thickness (m)"),
        "base_thickness": Param(0.004, 0.008, doc="floor thickness (m)"),
        "handle_style": Param(kind="choice", choices=("loops", "tabs", "long"),
                              doc="two side handles or one long handle"),
        "has_lid": Param(kind="bool", doc="with a lid"),
        "knob_style": Param(kind="choice", choices=("knob", "loop", "bar"), doc="lid handle"),
        "lid_dome": Param(0.01, 0.03, doc="lid dome height (m)"),
    }

    LIP = 0.002

    def _outer(self, p) -> list[tuple[float, float]]:
        R, H = p["radius"], p["height"]
        rb, c = R * p["taper"], min(0.012, 0.1 * H)
        arc = [(rb - c + c * math.sin(a), c - c * math.cos(a))
               for a in np.linspace(0.0, 0.5 * math.pi, 5)]
        return [(0.0, 0.0)] + arc + [(R, H - 0.004), (R + self.LIP, H)]

    def _r_at(self, p, z: float) -> float:
        rb = p["radius"] * p["taper"]
        return rb + (p["radius"] - rb) * z / p["height"]

    def _vessel(self, p) -> Vessel:
        return revolve_vessel(self._outer(p), p["wall_thickness"], p["base_thickness"])

    def _lid_z0(self, p) -> float:
        return p["height"] + LID_GAP

    def _handle_z(self, p) -> float:
        return p["height"] - 0.022 if p["handle_style"] != "long" else 0.8 * p["height"]

    def _long(self, p) -> tuple[float, float, float, float]:
        """(x0, z0, length, angle) of the long handle."""
        z = self._handle_z(p)
        return self._r_at(p, z) - 0.006, z, 1.3 * p["radius"] + 0.06, math.radians(10)

    def parts(self, p, detail):
        """The cooking pot's solids: detailed, or the blocks of its placeholder."""
        R, H, hs = p["radius"], p["height"], p["handle_style"]
        rl, z0 = R + self.LIP + 0.003, self._lid_z0(p)
        zh = self._handle_z(p)
        if not detail:
            out = [cheap_cylinder(R + self.LIP, 0.0, H, "metal")]
            if hs == "long":
                x1, hw, za, zb = long_handle_bounds(*self._long(p), "stick")
                out.append(Part(box_between((R - 0.01, -hw, za), (x1, hw, zb)), "metal"))
            else:
                reach, hh = self._r_at(p, zh) + SIDE_REACH[hs], SIDE_HALF_H[hs]
                half_x = 0.031 if hs == "loops" else 0.03
                out.append(Part(box_between((-half_x, -reach, zh - hh),
                                            (half_x, reach, zh + hh)), "metal"))
            if p["has_lid"]:
                out.append(cheap_cylinder(rl, H, lid_top(p["lid_dome"], z0, p["knob_style"]),
                                          "metal"))
            return out
        v = self._vessel(p)
        out = [Part(v.shell, "metal")]
        cav = v.cavity
        if hs == "long":
            out += [Part(s - cav, slot) for s, slot in long_handle(*self._long(p), "stick")]
        else:
            out += [Part(s - cav, "metal") for s in side_handles(hs, self._r_at(p, zh), zh)]
        if p["has_lid"]:
            # the skirt hangs 8 mm into the pot, clear of its (possibly tapering) wall
            skirt = self._r_at(p, H - 0.008) - p["wall_thickness"] - LID_GAP
            lid_slot = "glass" if p["knob_style"] == "knob" else "metal"
            knob_slot = "plastic" if p["knob_style"] == "knob" else "metal"
            solids = lid_solids(rl, p["lid_dome"], z0, p["knob_style"], skirt)
            out += [Part(solids[0], lid_slot, "lid"), Part(solids[1], lid_slot, "lid")]
            out += [Part(s, knob_slot, "lid") for s in solids[2:]]
        return out

    def joints(self, p):
        """The pot's joint: its lid lifting off."""
        if not p["has_lid"]:
            return []
        lift = DoorJoint("prismatic", np.array([0.0, 0.0, 1.0]),
                         np.array([0.0, 0.0, self._lid_z0(p)]), "lid")
        return [make_joint("lid", lift, 0.0, 0.12)]

    def extra_surfaces(self, p):
        """The cooking pot's surfaces besides its bounding box's: bottom, interior."""
        v = self._vessel(p)
        rb = p["radius"] * p["taper"] - min(0.012, 0.1 * p["height"])
        return [round_bottom("bottom", rb), interior_floor("interior", v.floor_z, v.floor_r)]


@register
class FryingPan(PartsFactory):
    """A frying pan or skillet: a shallow hollow pan with flared walls and a thick base, a long
    handle towards +X (round stick, flat strap or wooden grip) rising at an angle, and
    optionally a small helper handle opposite."""

    name = "frying_pan"
    tags = frozenset({S.Object, S.SmallObject, S.Kitchenware, S.Pan})
    size_class = "small"
    slots = ["metal", "wood"]
    material_choices = {"metal": COOKWARE_METAL}
    solid_bottom = True
    params = {
        "radius": Param(0.1, 0.16, doc="outer radius at the rim (m)"),
        "depth": Param(0.035, 0.065, doc="height of the rim (m)"),
        "base_frac": Param(0.7, 0.85, doc="flat base radius / rim radius"),
        "wall_thickness": Param(0.0025, 0.005, doc="wall thickness (m)"),
        "handle_length": Param(0.16, 0.24, doc="handle length (m)"),
        "handle_angle": Param(5.0, 20.0, doc="handle rise (degrees)"),
        "handle_style": Param(kind="choice", choices=("stick", "flat", "wood"), doc="handle"),
        "helper_handle": Param(kind="bool", doc="small loop handle opposite the long one"),
    }

    def _outer(self, p) -> list[tuple[float, float]]:
        R, D = p["radius"], p["depth"]
        rb, c = R * p["base_frac"], 0.008
        arc = [(rb - c + c * math.sin(a), c - c * math.cos(a))
               for a in np.linspace(0.0, 0.5 * math.pi, 5)]
        t = np.linspace(0.0, 1.0, 6)[1:]
        wall = list(zip((rb + (R - rb) * t ** 1.3).tolist(), (c + (D - c) * t).tolist(), strict=True))
        return [(0.0, 0.0)] + arc + wall

    def _vessel(self, p) -> Vessel:
        return revolve_vessel(self._outer(p), p["wall_thickness"], p["wall_thickness"] + 0.002)

    def _handle(self, p) -> tuple[float, float, float, float]:
        R, D = p["radius"], p["depth"]
        z = D - 0.012
        rb = R * p["base_frac"]
        r_at = rb + (R - rb) * ((z - 0.008) / (D - 0.008)) ** (1 / 1.3)
        return r_at - 0.006, z, p["handle_length"], math.radians(p["handle_angle"])

    def parts(self, p, detail):
        """The frying pan's solids: detailed, or the blocks of its placeholder."""
        R, D, hs = p["radius"], p["depth"], p["handle_style"]
        zh = D - 0.012
        if not detail:
            x1, hw, za, zb = long_handle_bounds(*self._handle(p), hs)
            out = [cheap_cylinder(R, 0.0, D, "metal"),
                   Part(box_between((R - 0.01, -hw, za), (x1, hw, zb)), "metal")]
            if p["helper_handle"]:
                r_at = self._handle(p)[0] + 0.006
                out.append(Part(box_between((-r_at - SIDE_REACH["loops"], -0.031, zh - 0.005),
                                            (-r_at + 0.01, 0.031, zh + 0.005)), "metal"))
            return out
        v = self._vessel(p)
        cav = v.cavity
        out = [Part(v.shell, "metal")]
        out += [Part(s - cav, slot) for s, slot in long_handle(*self._handle(p), hs)]
        if p["helper_handle"]:
            r_at = self._handle(p)[0] + 0.006
            out += [Part(s - cav, "metal") for s in side_handles("loops", r_at, zh, "x", (-1,))]
        return out

    def extra_surfaces(self, p):
        """The frying pan's surfaces besides its bounding box's: bottom, interior."""
        v = self._vessel(p)
        return [round_bottom("bottom", p["radius"] * p["base_frac"] - 0.008),
                interior_floor("interior", v.floor_z, v.floor_r)]


@register
class PotLid(PartsFactory):
    """A loose pot lid resting on its rim: a domed glass or metal shell (open underneath) with
    a metal rim band, optionally a skirt, a steam vent, and a knob, loop or bar handle."""

    name = "pot_lid"
    tags = frozenset({S.Object, S.SmallObject, S.Kitchenware, S.Lid})
    size_class = "small"
    slots = ["glass", "metal", "plastic"]
    material_choices = {"metal": COOKWARE_METAL}
    params = {
        "radius": Param(0.08, 0.15, doc="radius (m)"),
        "dome": Param(0.01, 0.04, doc="dome height (m)"),
        "thickness": Param(0.002, 0.004, doc="shell thickness (m)"),
        "glass": Param(kind="bool", doc="glass shell with a metal rim band (else all metal)"),
        "knob_style": Param(kind="choice", choices=("knob", "loop", "bar"), doc="handle"),
        "skirt": Param(kind="bool", doc="a skirt under the rim that locates it in the pot"),
        "vent": Param(kind="bool", doc="a steam vent hole"),
    }

    def _z0(self, p) -> float:
        """The rim's underside: 8 mm up if the skirt hangs below it."""
        return 0.008 if p["skirt"] else 0.0

    def parts(self, p, detail):
        """The pot lid's solids: detailed, or the blocks of its placeholder."""
        R, z0, t = p["radius"], self._z0(p), p["thickness"]
        if not detail:
            return [cheap_cylinder(R, 0.0, lid_top(p["dome"], z0, p["knob_style"], t), "metal")]
        skirt = R - 0.006 if p["skirt"] else 0.0
        solids = lid_solids(R, p["dome"], z0, p["knob_style"], skirt, t)
        shell = solids[0]
        if p["vent"]:
            u = 0.55
            zv = z0 + p["dome"] * float(_dome(np.array([u]))[0])
            shell = shell - cylinder(0.0025, 0.03, (R * (1 - u), 0.0, zv - 0.01), 12)
        out = [Part(shell, "glass" if p["glass"] else "metal")]
        if p["glass"]:  # a metal band clasping the glass's rim
            band = lathe([(R - 0.005, z0 - 0.0005), (R, z0 - 0.0005), (R, z0 + t + 0.003),
                          (R - 0.005, z0 + t + 0.003)], SECTIONS)
            out.append(Part(band.trim_by_plane((0, 0, 1), 0.0), "metal"))
        # the skirt and handle pieces are metal, except a knob's plastic head (the last piece)
        knob = p["knob_style"] == "knob"
        out += [Part(s, "metal") for s in (solids[1:-1] if knob else solids[1:])]
        if knob:
            out.append(Part(solids[-1], "plastic"))
        return out
