"""More tableware: bowls, mugs, wine glasses, tumblers, bottles (wine, beer, soda) and jars.

Every vessel is a solid of revolution. Its outer half profile ((r, z) points from the axis at
the bottom up to the rim) is mirrored into a full cross-section, and `revolve_vessel` hollows it
by offsetting that section inward by the wall thickness (so sloped walls keep their thickness)
and clipping the cavity at the floor height: one closed shell whose cavity opens at the rim.
Capped bottles are solid (the contents fill them), so no shell hides a sealed void.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Sequence

import manifold3d as m3d
import numpy as np

from indoorgen.assets.base import Param, Surface, register
from indoorgen.assets.parts_factory import PartsFactory, make_joint
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.moving_parts import DoorJoint
from indoorgen.assets.shapes.primitives import (
    Part,
    bevel_box,
    box_between,
    circle_polygon,
    cylinder,
    lathe,
    torus,
)
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

#: lathe sections of detailed vessels (a multiple of 4: vertices on the +-X/+-Y axes)
SECTIONS = 32
#: lathe sections of placeholder cylinders
CHEAP = 16
_BIG = 10.0


# ----------------------------------------------------------------------------- shared helpers
@dataclass(frozen=True)
class Vessel:
    """A hollowed solid of revolution, as half cross-sections (revolved on demand, so surfaces
    can be computed without building meshes): the wall, the cavity, and the height and radius
    of the flat inner floor."""

    wall: m3d.CrossSection
    hollow: m3d.CrossSection
    floor_z: float
    floor_r: float
    sections: int = SECTIONS

    @property
    def shell(self) -> m3d.Manifold:
        """The closed shell (its cavity opens at the rim)."""
        return m3d.Manifold.revolve(self.wall, self.sections)

    @property
    def cavity(self) -> m3d.Manifold:
        """The cavity as a solid (to clip handles that would enter it)."""
        return m3d.Manifold.revolve(self.hollow, self.sections)


def mirrored_section(half: Sequence[tuple[float, float]]) -> m3d.CrossSection:
    """The full cross-section (both sides of the axis) of a solid of revolution whose half
    profile `half` runs from a point on the axis (r = 0) through r > 0 back to the axis."""
    pts = np.asarray(half, float)
    inner = pts[1:-1]
    full = np.vstack([pts, inner[::-1] * np.array([-1.0, 1.0])])
    return m3d.CrossSection([full], m3d.FillRule.NonZero)


def _rect(r0: float, z0: float, r1: float, z1: float) -> m3d.CrossSection:
    return m3d.CrossSection.square((r1 - r0, z1 - z0)).translate((r0, z0))


def revolve_vessel(outer: Sequence[tuple[float, float]], wall: float, floor_z: float,
                   sections: int = SECTIONS) -> Vessel:
    """Hollow vessel from its outer profile: `outer` runs from the axis at the bottom ((0, z))
    along the outside to the rim, its last point (r_rim, z_rim) being the outer top edge of the
    wall. The cavity is the section offset inward by `wall`, opened above the rim and cut flat
    at `floor_z` (which must be at least `wall` above the underside)."""
    pts = [tuple(map(float, q)) for q in outer]
    r_rim, z_rim = pts[-1]
    full = mirrored_section(pts + [(0.0, z_rim)])
    column = _rect(-r_rim, z_rim - 1e-4, r_rim, z_rim + 1.0)
    cav = (full + column).offset(-wall, m3d.JoinType.Miter, 2.0)
    cav = cav ^ _rect(-_BIG, floor_z, _BIG, z_rim + 0.5)
    half = _rect(0.0, -_BIG, _BIG, _BIG)
    cav_half = cav ^ half
    polys = [np.asarray(q, float) for q in cav_half.to_polygons()]
    on_floor = np.vstack(polys) if polys else np.zeros((0, 2))
    on_floor = on_floor[np.abs(on_floor[:, 1] - floor_z) < 1e-7]
    floor_r = float(on_floor[:, 0].max()) if len(on_floor) else 0.0
    return Vessel((full - cav) ^ half, cav_half, floor_z, floor_r, sections)


def solid_revolve(outer: Sequence[tuple[float, float]], sections: int = SECTIONS) -> m3d.Manifold:
    """A full solid of revolution from an outer profile running from the axis at the bottom to
    its last point, closed back to the axis at that point's height."""
    pts = [tuple(map(float, q)) for q in outer]
    return lathe(pts + [(0.0, pts[-1][1])], sections)


def cheap_cylinder(radius: float, z0: float, z1: float, slot: str) -> Part:
    """A placeholder cylinder (16-gon circumscribing `radius`) from z0 to z1."""
    return Part(cylinder(radius, z1 - z0, (0, 0, z0), CHEAP, circumscribed=True), slot)


def round_bottom(name: str, radius: float, sections: int = SECTIONS) -> Surface:
    """A round `bottom` surface (normal -Z) inside a mesh disc of `radius` built with
    `sections` segments (1/2 mm margin)."""
    return support_polygon(name, (0, 0, 0), circle_polygon(max(radius - 0.0005, 0.002), sections),
                           subpart=Subpart.Bottom, up=False)


def interior_floor(name: str, z: float, radius: float, sections: int = SECTIONS) -> Surface:
    """An upward `Subpart.Interior` disc on a vessel's inner floor."""
    return support_polygon(name, (0, 0, z), circle_polygon(max(radius * 0.9, 0.003), sections),
                           subpart=Subpart.Interior)


# ------------------------------------------------------------------------------------ bowls
BOWL_SHAPES = ("round", "conical", "flared", "deep")


def bowl_wall_curve(shape: str, t: np.ndarray) -> np.ndarray:
    """Fraction (0..1) of the way from the base radius to the rim radius at height fraction t."""
    if shape == "round":
        return np.sin(0.5 * math.pi * t)
    if shape == "conical":
        return t
    if shape == "flared":
        return t ** 1.4
    return np.sin(0.5 * math.pi * t) ** 0.5  # deep: nearly cylindrical with a rounded bottom


def bowl_outer(p: dict[str, Any], n: int = 10) -> list[tuple[float, float]]:
    """Outer half profile of a bowl with params radius, height, foot_frac, shape, foot_ring,
    rim_flare, wall_thickness: axis at the bottom, out along the (ring) foot, up to the rim."""
    R, H, w = p["radius"], p["height"], p["wall_thickness"]
    rb = R * p["foot_frac"]
    fh = bowl_foot_height(p)
    flare = p["rim_flare"]
    lip = 1.5 * flare if flare > 5e-4 else 0.0
    if fh > 0:
        rw = max(2 * w, 0.004)
        pts = [(0.0, fh), (rb - rw, fh), (rb - rw, 0.0), (rb, 0.0)]
        z0 = fh
    else:
        c = min(0.003, 0.3 * H)
        pts = [(0.0, 0.0), (rb - c, 0.0)]
        z0 = 0.0
    t = np.linspace(0.0, 1.0, n + 1)
    f = bowl_wall_curve(p["shape"], t)
    zs = z0 + (H - lip - z0) * t
    rs = rb + (R - rb) * f
    if fh == 0:
        zs[0] += min(0.003, 0.3 * H)
    pts += list(zip(rs.tolist(), zs.tolist()))[0 if fh == 0 else 1:]
    if lip:
        pts.append((R + flare, H))
    return pts


def bowl_foot_height(p: dict[str, Any]) -> float:
    """Height of a bowl's foot ring (0 without one): 12% of the height, within 4-10 mm."""
    return min(max(0.12 * p["height"], 0.004), 0.01) if p["foot_ring"] else 0.0


def bowl_base_radius(p: dict[str, Any]) -> float:
    """Radius of the part of a bowl's underside that rests on the table (the flat base inside
    its edge rounding, or the foot ring's outer edge)."""
    rb = p["radius"] * p["foot_frac"]
    return rb if p["foot_ring"] else rb - min(0.003, 0.3 * p["height"])


def bowl_vessel(p: dict[str, Any]) -> Vessel:
    floor = bowl_foot_height(p) + p["base_thickness"]
    return revolve_vessel(bowl_outer(p), p["wall_thickness"], floor)


def bowl_params(r_lo: float, r_hi: float, h_lo: float, h_hi: float) -> dict[str, Param]:
    """The parameters of a bowl, with the given radius and height ranges (m)."""
    return {
        "radius": Param(r_lo, r_hi, doc="outer radius at the rim (m)"),
        "height": Param(h_lo, h_hi, doc="height of the rim (m)"),
        "foot_frac": Param(0.35, 0.6, doc="base radius / rim radius"),
        "shape": Param(kind="choice", choices=BOWL_SHAPES, doc="wall profile"),
        "wall_thickness": Param(0.003, 0.006, doc="wall thickness (m)"),
        "base_thickness": Param(0.006, 0.012, doc="floor thickness above the underside (m)"),
        "foot_ring": Param(kind="bool", doc="stand on a foot ring (recessed underside)"),
        "rim_flare": Param(0.0, 0.008, doc="outward flare of the rim (m; < 0.5 mm: none)"),
    }


@register
class Bowl(PartsFactory):
    """A bowl: round, conical, flared or deep wall profile from a flat base or a foot ring, with
    an optional flared rim; hollow, its inner floor an `interior` surface."""

    name = "bowl"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Container, S.Bowl})
    size_class = "small"
    slots = ["ceramic"]
    params = bowl_params(0.06, 0.13, 0.04, 0.09)

    def bottom_is_solid(self, params):
        return not self.resolve(params)["foot_ring"]

    def parts(self, p, detail):
        if not detail:
            return [cheap_cylinder(p["radius"] + p["rim_flare"], 0.0, p["height"], "ceramic")]
        return [Part(bowl_vessel(p).shell, "ceramic")]

    def extra_surfaces(self, p):
        v = bowl_vessel(p)
        return [round_bottom("bottom", bowl_base_radius(p)),
                interior_floor("interior", v.floor_z, v.floor_r)]


# ------------------------------------------------------------------------------------- mugs
MUG_SHAPES = ("straight", "tapered", "barrel", "tulip")


@register
class Mug(PartsFactory):
    """A mug: straight, tapered, barrel or tulip body, hollow with a thick floor, and a handle on
    +Y (a round or ear-shaped torus segment, or a squared loop) whose ends sink into the wall."""

    name = "mug"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Cup, S.Mug})
    size_class = "small"
    slots = ["ceramic"]
    solid_bottom = True
    params = {
        "radius": Param(0.036, 0.05, doc="outer radius at the rim (m)"),
        "height": Param(0.08, 0.115, doc="height (m)"),
        "shape": Param(kind="choice", choices=MUG_SHAPES, doc="body profile"),
        "bottom_frac": Param(0.72, 0.95, doc="base radius / rim radius (straight: base bevel)"),
        "wall_thickness": Param(0.003, 0.006, doc="wall thickness (m)"),
        "base_thickness": Param(0.007, 0.012, doc="floor thickness (m)"),
        "handle_shape": Param(kind="choice", choices=("round", "ear", "square"), doc="handle loop"),
        "handle_size": Param(0.02, 0.032, doc="handle loop half-height (m)"),
        "handle_thickness": Param(0.004, 0.008, doc="handle cross-section radius (m)"),
    }

    def _radius(self, p, t: np.ndarray) -> np.ndarray:
        R, b, s = p["radius"], p["bottom_frac"], p["shape"]
        if s == "straight":
            return np.full_like(t, R)
        if s == "tapered":
            return R * (b + (1 - b) * t)
        if s == "barrel":
            return R * (b + (1 - b) * np.sin(math.pi * np.clip(t * 0.9 + 0.1, 0, 1)) ** 0.6 * 1.0)
        return R * (b + (1 - b) * np.sin(0.5 * math.pi * t) ** 2)  # tulip: widening to the rim

    def _outer(self, p) -> list[tuple[float, float]]:
        H = p["height"]
        t = np.linspace(0.0, 1.0, 13)
        r = self._radius(p, t)
        c = (1 - p["bottom_frac"]) * p["radius"] * 0.3 if p["shape"] == "straight" else 0.002
        c = max(c, 0.0015)
        pts = [(0.0, 0.0), (float(r[0]) - c, 0.0)]
        z = t * H
        z[0] = c
        return pts + list(zip(r.tolist(), z.tolist()))

    def _rmax(self, p) -> float:
        return float(max(q[0] for q in self._outer(p)))

    def _handle_dims(self, p) -> tuple[float, float, float, float, float]:
        """(loop half-height, tube radius, centre height, Y scale, attachment y)."""
        H, t = p["height"], p["handle_thickness"]
        sy, sz = {"round": (1.0, 1.0), "ear": (0.9, 1.15), "square": (0.9, 1.0)}[p["handle_shape"]]
        R = min(p["handle_size"] * sz, 0.5 * H - t - 0.008)
        zc = 0.52 * H
        tt = np.array([(zc - R) / H, zc / H, (zc + R) / H])
        yc = float(self._radius(p, tt).min()) - 0.5 * p["wall_thickness"]
        # at least 12 mm between the loop and the widest part of the body, for the fingers
        ry = max(R * sy / sz, self._rmax(p) - yc + 0.012 + t)
        return R, t, zc, ry, yc

    def _handle(self, p, cavity: m3d.Manifold) -> m3d.Manifold:
        R, t, zc, ry, yc = self._handle_dims(p)
        if p["handle_shape"] == "square":
            bars = [bevel_box((2 * t, ry + t, 2 * t), (0, yc + (ry + t) / 2, zc + R), t * 0.6),
                    bevel_box((2 * t, ry + t, 2 * t), (0, yc + (ry + t) / 2, zc - R), t * 0.6),
                    bevel_box((2 * t, 2 * t, 2 * R + 2 * t), (0, yc + ry, zc), t * 0.6)]
            loop = solid_union(bars)
        else:
            loop = torus(1.0, t / R, sections=24, tube_sections=8).rotate((90.0, 0.0, 90.0))
            loop = loop.scale((R, ry, R)).translate((0.0, yc, zc))
        keep = m3d.Manifold.cube((1.0, 1.0, 1.0), True).scale((0.2, 0.2, 0.2)).translate(
            (0.0, yc + 0.1 - 0.3 * ry, zc))
        return (loop ^ keep) - cavity

    def parts(self, p, detail):
        H = p["height"]
        R, t, zc, ry, yc = self._handle_dims(p)
        if not detail:
            rm = self._rmax(p)
            # a torus scaled by ry/R across reaches ry * (1 + t/R); the square loop ry + t
            reach = ry + t if p["handle_shape"] == "square" else ry * (1 + t / R)
            return [cheap_cylinder(rm, 0.0, H, "ceramic"),
                    Part(box_between((-t, rm - 0.003, zc - R - t), (t, yc + reach, zc + R + t)),
                         "ceramic")]
        v = revolve_vessel(self._outer(p), p["wall_thickness"], p["base_thickness"])
        return [Part(v.shell, "ceramic"), Part(self._handle(p, v.cavity), "ceramic")]

    def extra_surfaces(self, p):
        o = self._outer(p)
        v = revolve_vessel(o, p["wall_thickness"], p["base_thickness"])
        return [round_bottom("bottom", o[1][0]), interior_floor("interior", v.floor_z, v.floor_r)]


# --------------------------------------------------------------------------- glassware
#: wine glass bowl shapes: (height of the widest point / bowl height, radius scale)
GLASS_SHAPES = {"balloon": (0.45, 1.0), "tulip": (0.4, 0.9), "flute": (0.75, 0.62),
                "coupe": (1.0, 1.15)}


@register
class Wineglass(PartsFactory):
    """A stemmed glass: a thin foot disc, a stem and a hollow bowl (balloon, tulip, flute or
    coupe) whose rim may narrow inward; one lathed shell."""

    name = "wineglass"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Wineglass, S.Cup})
    size_class = "small"
    slots = ["glass"]
    solid_bottom = True
    params = {
        "height": Param(0.14, 0.24, doc="total height (m)"),
        "bowl_radius": Param(0.035, 0.05, doc="outer radius of the bowl at its widest (m)"),
        "bowl_frac": Param(0.4, 0.6, doc="bowl height / total height (coupe: halved)"),
        "shape": Param(kind="choice", choices=tuple(GLASS_SHAPES), doc="bowl shape"),
        "rim_narrowing": Param(0.0, 0.25, doc="how much the rim narrows from the widest point"),
        "foot_radius": Param(0.028, 0.042, doc="foot disc radius (m)"),
        "stem_radius": Param(0.003, 0.005, doc="stem radius (m)"),
        "wall_thickness": Param(0.0015, 0.0025, doc="bowl wall thickness (m)"),
    }

    def _dims(self, p) -> tuple[float, float, float]:
        """(stem top z, widest bowl radius, foot thickness)."""
        H, s = p["height"], p["shape"]
        bowl_h = H * p["bowl_frac"] * (0.5 if s == "coupe" else 1.0)
        return H - bowl_h, p["bowl_radius"] * GLASS_SHAPES[s][1], 0.003

    def _outer(self, p) -> list[tuple[float, float]]:
        H, rf, rs = p["height"], p["foot_radius"], p["stem_radius"]
        z0, Rb, tf = self._dims(p)
        shape = p["shape"]
        tm, _ = GLASS_SHAPES[shape]
        narrow = p["rim_narrowing"] * (0.5 if shape == "flute" else 1.0)
        rim = 1.0 - narrow - (0.08 if shape in ("balloon", "tulip") else 0.0)
        t = np.linspace(0.0, 1.0, 17)
        u = np.minimum(t / tm, 1.0)
        if shape == "coupe":
            g = np.sin(0.5 * math.pi * t) ** 0.6
        else:
            rise = (np.sqrt(1.0 - (1.0 - u) ** 2) if shape == "balloon"
                    else np.sin(0.5 * math.pi * u) ** 0.9)
            g = np.where(t <= tm, rise,
                         1.0 - (1.0 - rim) * ((t - tm) / (1.0 - tm)).clip(0, 1) ** 1.5)
        r0 = 1.6 * rs
        rb = r0 + (Rb - r0) * g
        zb = z0 + (H - z0) * t
        foot = [(0.0, 0.0), (rf, 0.0), (rf, tf * 0.6), (rf - 0.004, tf), (2.5 * rs, tf + 0.004),
                (rs, tf + 0.012), (rs, z0 - 0.004)]
        return foot + list(zip(rb.tolist(), zb.tolist()))

    def _vessel(self, p) -> Vessel:
        z0 = self._dims(p)[0]
        return revolve_vessel(self._outer(p), p["wall_thickness"], z0 + 0.006)

    def parts(self, p, detail):
        if detail:
            return [Part(self._vessel(p).shell, "glass")]
        z0 = self._dims(p)[0]
        rmax = max(r for r, z in self._outer(p) if z >= z0 - 0.004)
        return [cheap_cylinder(p["foot_radius"], 0.0, z0, "glass"),
                cheap_cylinder(rmax, z0 - 0.004, p["height"], "glass")]

    def extra_surfaces(self, p):
        return [round_bottom("bottom", p["foot_radius"])]


TUMBLER_STYLES = ("smooth", "faceted", "ribbed")


@register
class GlassTumbler(PartsFactory):
    """A drinking glass: straight or tapered, optionally bulging, smooth, faceted (12 sides) or
    ribbed near the base, with a thin wall and a thick (heavy) base."""

    name = "glass_tumbler"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Cup})
    size_class = "small"
    slots = ["glass"]
    solid_bottom = True
    params = {
        "radius": Param(0.03, 0.045, doc="outer radius at the rim (m)"),
        "height": Param(0.07, 0.16, doc="height (m)"),
        "bottom_frac": Param(0.75, 1.0, doc="base radius / rim radius"),
        "bulge": Param(0.0, 0.08, doc="outward bulge of the wall at mid-height / radius"),
        "wall_thickness": Param(0.0015, 0.003, doc="wall thickness (m)"),
        "base_thickness": Param(0.004, 0.018, doc="thickness of the solid base (m)"),
        "style": Param(kind="choice", choices=TUMBLER_STYLES, doc="surface style"),
    }

    def _sections(self, p) -> int:
        return 12 if p["style"] == "faceted" else SECTIONS

    def _outer(self, p) -> list[tuple[float, float]]:
        R, H, b = p["radius"], p["height"], p["bottom_frac"]
        n = 24 if p["style"] == "ribbed" else 10
        t = np.linspace(0.0, 1.0, n + 1)
        r = R * (b + (1 - b) * t + p["bulge"] * np.sin(math.pi * t))
        if p["style"] == "ribbed":
            r = r + 0.0012 * (np.abs(np.sin(math.pi * t * n / 2)) * (t < 0.5))
        c = 0.0015
        z = t * H
        z[0] = c
        return [(0.0, 0.0), (float(r[0]) - c, 0.0)] + list(zip(r.tolist(), z.tolist()))

    def _vessel(self, p) -> Vessel:
        return revolve_vessel(self._outer(p), p["wall_thickness"], p["base_thickness"],
                              self._sections(p))

    def parts(self, p, detail):
        if detail:
            return [Part(self._vessel(p).shell, "glass")]
        rmax = max(r for r, _ in self._outer(p))
        return [cheap_cylinder(rmax, 0.0, p["height"], "glass")]

    def extra_surfaces(self, p):
        o, n = self._outer(p), self._sections(p)
        v = self._vessel(p)
        # polygons with the mesh's own vertex angles, just inside its n-gons
        return [round_bottom("bottom", o[1][0], n), interior_floor("interior", v.floor_z,
                                                                   v.floor_r, n)]


# -------------------------------------------------------------------------------- bottles
@dataclass(frozen=True)
class BottleSpec:
    """The shape of a bottle (all in metres): glass height `height`, body radius `body_r` up to
    `shoulder_z`, a shoulder (superellipse exponent `shoulder_exp`: 1 conical, 2 round, 4 square)
    narrowing to `neck_r` at `neck_z`, a lip ring (`lip_r`, `lip_h`) at the top. `waist` (a
    fraction of the radius) pinches the body at `waist_z`, `ribs` rings groove it; `punt` is the
    depth of the domed recess under the base. `closure` is "open" (a hollow bottle) or a cap
    kind; `label` a (z0, z1) paper band or None."""

    height: float
    body_r: float
    shoulder_z: float
    neck_z: float
    shoulder_exp: float
    neck_r: float
    lip_r: float
    lip_h: float
    closure: str
    label: tuple[float, float] | None = None
    waist: float = 0.0
    waist_z: float = 0.0
    ribs: int = 0
    punt: float = 0.0
    support_ring: bool = False
    body_slot: str = "glass"
    wall: float = 0.003


#: closure kind -> (radius over the lip, length down from the top, height above it, slot)
CLOSURES = {"cork": (-0.0025, 0.002, 0.007, "cork"), "capsule": (0.0005, 0.045, 0.001, "metal"),
            "screwcap": (0.0008, 0.055, 0.002, "metal"), "crown": (0.0008, 0.005, 0.0015, "metal"),
            "plastic_cap": (0.0012, 0.013, 0.002, "plastic")}


def bottle_outer(b: BottleSpec) -> list[tuple[float, float]]:
    """Outer half profile of a bottle, from the axis under the base to the lip's top edge."""
    R, c = b.body_r, min(0.004, 0.12 * b.body_r)
    pts = [(0.0, b.punt), (0.72 * R, 0.0)] if b.punt > 1e-3 else [(0.0, 0.0)]
    pts.append((R - c, 0.0))
    dense = b.waist > 0 or b.ribs > 0
    z = np.linspace(c, b.shoulder_z, 18 if dense else 2)
    r = np.full_like(z, R)
    if b.waist > 0:
        span = 0.35 * b.shoulder_z
        r -= R * b.waist * np.exp(-(((z - b.waist_z) / span) ** 2) * 2.5)
    if b.ribs > 0:
        z_r = np.linspace(0.2, 0.85, b.ribs) * b.shoulder_z
        d = np.abs(z[:, None] - z_r[None, :]).min(axis=1)
        r -= 0.0015 * (d < 0.0045)
    pts += list(zip(r.tolist(), z.tolist()))
    t = np.linspace(0.0, 1.0, 10)[1:]
    a = b.shoulder_exp
    rs = b.neck_r + (float(r[-1]) - b.neck_r) * (1.0 - t ** a) ** (1.0 / a)
    zs = b.shoulder_z + (b.neck_z - b.shoulder_z) * t
    pts += list(zip(rs.tolist(), zs.tolist()))
    zl = b.height - b.lip_h
    if b.support_ring:
        zr = zl - 0.006
        pts += [(b.neck_r, zr - 0.0015), (b.lip_r + 0.002, zr - 0.0015), (b.lip_r + 0.002, zr),
                (b.neck_r, zr)]
    pts += [(b.neck_r, zl), (b.lip_r, zl), (b.lip_r, b.height)]
    return pts


def bottle_parts(b: BottleSpec, detail: bool) -> list[Part]:
    """A bottle's pieces: a hollow body if open (else solid: full), its closure and label."""
    outer = bottle_outer(b)
    clo = CLOSURES.get(b.closure)
    top = b.height + (clo[2] if clo else 0.0)
    if not detail:
        r_body = max(r for r, z in outer if z <= b.neck_z) + (0.0004 if b.label else 0.0)
        r_neck = max([r for r, z in outer if z >= b.neck_z - 1e-9]
                     + ([b.lip_r + clo[0]] if clo else []))
        return [cheap_cylinder(r_body, 0.0, b.neck_z, b.body_slot),
                cheap_cylinder(r_neck, b.neck_z - 1e-3, top, b.body_slot)]
    vessel = None if clo else revolve_vessel(outer, b.wall, b.punt + b.wall + 0.002)
    out = [Part(solid_revolve(outer) if clo else vessel.shell, b.body_slot)]
    if clo:
        dr, down, up, slot = clo
        out.append(Part(cylinder(b.lip_r + dr, down + up, (0, 0, b.height - down), SECTIONS),
                        slot))
    if b.label:
        out.append(Part(_label(b, outer, vessel), "paper"))
    return out


def _label(b: BottleSpec, outer: list[tuple[float, float]], vessel: Vessel | None
           ) -> m3d.Manifold:
    """A paper band around the body from label z0 to z1: a ring reaching 0.4 mm beyond the
    widest body radius there and sunk into the narrowest, clear of the cavity of open bottles."""
    z0, z1 = b.label
    rs = [r for r, z in outer if z0 - 0.005 <= z <= z1 + 0.005] or [b.body_r]
    r_out, r_in = max(rs) + 0.0004, min(rs) - 0.0005
    ring = lathe([(r_in, z0), (r_out, z0), (r_out, z1), (r_in, z1)], SECTIONS)
    return ring - vessel.cavity if vessel is not None else ring


class _Bottle(PartsFactory):
    """Shared machinery of the bottle generators: subclasses turn params into a BottleSpec."""

    size_class = "small"
    slots = ["glass", "plastic", "metal", "cork", "paper"]
    material_choices = {"glass": {"clear_glass": 4.0, "frosted_glass": 0.5},
                        "metal": {"painted_metal": 3.0, "brushed_steel": 1.0, "brass": 0.5},
                        "plastic": {"glossy_plastic": 3.0, "matte_plastic": 1.0}}

    def spec(self, p: dict[str, Any]) -> BottleSpec:
        raise NotImplementedError

    def bottom_is_solid(self, params):
        return self.spec(self.resolve(params)).punt <= 1e-3

    def parts(self, p, detail):
        return bottle_parts(self.spec(p), detail)

    def extra_surfaces(self, p):
        b = self.spec(p)
        return [round_bottom("bottom", b.body_r - min(0.004, 0.12 * b.body_r))]


@register
class WineBottle(_Bottle):
    """A 75 cl wine bottle: Bordeaux (square shoulders), Burgundy (long sloping shoulders) or
    hock (tall and slender); a punt under the base, cork, foil capsule, screw cap or open (then
    hollow), and an optional paper label."""

    name = "wine_bottle"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Container, S.Bottle})
    params = {
        "height": Param(0.28, 0.34, doc="glass height (m)"),
        "body_radius": Param(0.036, 0.045, doc="body radius (m)"),
        "style": Param(kind="choice", choices=("bordeaux", "burgundy", "hock"),
                       doc="bottle shape"),
        "neck_radius": Param(0.0135, 0.016, doc="neck outer radius (m)"),
        "neck_frac": Param(0.22, 0.32, doc="neck length / height"),
        "closure": Param(kind="choice", choices=("cork", "capsule", "screwcap", "open"),
                         doc="what closes it (open: empty and hollow)"),
        "label": Param(kind="bool", doc="paper label on the body"),
        "punt_depth": Param(0.0, 0.025, doc="depth of the recess under the base (m; < 1 mm none)"),
    }

    def spec(self, p):
        H, style = p["height"], p["style"]
        R = p["body_radius"] * (0.85 if style == "hock" else 1.0)
        neck_z = H * (1.0 - p["neck_frac"])
        sh = {"bordeaux": 0.07, "burgundy": 0.2, "hock": 0.3}[style] * H
        exp = {"bordeaux": 3.5, "burgundy": 1.6, "hock": 1.15}[style]
        sz = neck_z - sh
        label = (0.18 * sz, 0.8 * sz) if p["label"] else None
        return BottleSpec(H, R, sz, neck_z, exp, p["neck_radius"], p["neck_radius"] + 0.0015,
                          0.004, p["closure"], label, punt=min(p["punt_depth"], 0.4 * sz))


@register
class BeerBottle(_Bottle):
    """A beer bottle: long-neck, stubby or steinie, crown cap or open (hollow), with an optional
    label band."""

    name = "beer_bottle"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Container, S.Bottle})
    params = {
        "height": Param(0.19, 0.25, doc="glass height of a long-neck (stubby: x0.7) (m)"),
        "body_radius": Param(0.027, 0.034, doc="body radius (m)"),
        "style": Param(kind="choice", choices=("longneck", "stubby", "steinie"),
                       doc="bottle shape"),
        "neck_radius": Param(0.0105, 0.0135, doc="neck outer radius (m)"),
        "shoulder_frac": Param(0.1, 0.25, doc="shoulder length / height"),
        "closure": Param(kind="choice", choices=("crown", "open"), doc="crown cap or open"),
        "label": Param(kind="bool", doc="paper label on the body"),
        "label_frac": Param(0.25, 0.45, doc="label height / body height"),
    }

    def spec(self, p):
        style = p["style"]
        H = p["height"] * (0.7 if style == "stubby" else 1.0)
        R = p["body_radius"] * (1.12 if style == "stubby" else 1.0)
        neck = {"longneck": 0.28, "stubby": 0.12, "steinie": 0.16}[style] * H
        exp = {"longneck": 1.5, "stubby": 1.3, "steinie": 2.6}[style]
        neck_z = H - neck
        sz = neck_z - p["shoulder_frac"] * H
        lz = 0.15 * sz
        label = (lz, lz + p["label_frac"] * sz) if p["label"] else None
        return BottleSpec(H, R, sz, neck_z, exp, p["neck_radius"], p["neck_radius"] + 0.0018,
                          0.005, p["closure"], label)


@register
class SodaBottle(_Bottle):
    """A soft-drink bottle: a contoured glass bottle (waisted), a PET bottle (plastic, grooved,
    with a neck support ring) or a classic straight glass bottle; screw cap, crown or open."""

    name = "soda_bottle"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Container, S.Bottle})
    params = {
        "height": Param(0.2, 0.33, doc="bottle height (m)"),
        "body_radius": Param(0.03, 0.048, doc="body radius (m)"),
        "style": Param(kind="choice", choices=("contour", "pet", "classic"), doc="bottle type"),
        "waist": Param(0.0, 0.15, doc="pinch of the body at its waist / radius"),
        "closure": Param(kind="choice", choices=("screwcap", "crown", "open"),
                         doc="closure (PET bottles always have a screw cap unless open)"),
        "label": Param(kind="bool", doc="paper label band"),
        "ribs": Param(0, 6, kind="int", doc="number of grooves around the body"),
        "neck_radius": Param(0.0105, 0.0135, doc="neck outer radius (m)"),
    }

    def spec(self, p):
        H, style = p["height"], p["style"]
        R = p["body_radius"]
        neck = {"contour": 0.2, "pet": 0.1, "classic": 0.25}[style] * H
        shoulder = {"contour": 0.25, "pet": 0.15, "classic": 0.2}[style] * H
        exp = {"contour": 1.4, "pet": 2.2, "classic": 1.2}[style]
        neck_z = H - neck
        sz = neck_z - shoulder
        closure = p["closure"]
        if closure != "open":
            closure = "plastic_cap" if style == "pet" or closure == "screwcap" else "crown"
        waist = p["waist"] + (0.08 if style == "contour" else 0.0)
        label = (0.12 * sz, 0.12 * sz + 0.3 * sz) if p["label"] else None
        return BottleSpec(H, R, sz, neck_z, exp, p["neck_radius"], p["neck_radius"] + 0.0015,
                          0.004 if style == "pet" else 0.005, closure, label, waist=waist,
                          waist_z=0.62 * sz, ribs=int(p["ribs"]), support_ring=style == "pet",
                          body_slot="plastic" if style == "pet" else "glass",
                          wall=0.0015 if style == "pet" else 0.003)


# ----------------------------------------------------------------------------------- jars
JAR_SHAPES = ("cylinder", "mason", "round", "octagonal")
#: radial clearance between a jar's neck and its lid, and between rim and lid top (m)
LID_GAP = 0.002


@register
class Jar(PartsFactory):
    """A storage jar: cylindrical, mason (square shoulder), round (bulbous) or octagonal body,
    hollow and open at a neck; a screw lid or a domed lid with a knob sits over the neck on its
    own link ("lid"), lifting straight off (prismatic joint along +Z)."""

    name = "jar"
    tags = frozenset({S.Object, S.SmallObject, S.Kitchenware, S.Container, S.Jar})
    size_class = "small"
    slots = ["glass", "metal", "plastic"]
    material_choices = {"glass": {"clear_glass": 4.0, "frosted_glass": 0.5},
                        "metal": {"painted_metal": 3.0, "brushed_steel": 1.5, "brass": 0.5}}
    solid_bottom = True
    params = {
        "radius": Param(0.035, 0.06, doc="body radius (m)"),
        "height": Param(0.07, 0.18, doc="height of the glass up to the rim (m)"),
        "shape": Param(kind="choice", choices=JAR_SHAPES, doc="body shape"),
        "neck_frac": Param(0.7, 0.95, doc="neck radius / body radius"),
        "shoulder_frac": Param(0.06, 0.2, doc="shoulder height / height"),
        "wall_thickness": Param(0.002, 0.004, doc="glass wall thickness (m)"),
        "lid_style": Param(kind="choice", choices=("screw", "dome"), doc="lid kind"),
        "lid_height": Param(0.008, 0.02, doc="lid skirt length (m)"),
    }

    def _sections(self, p) -> int:
        return 8 if p["shape"] == "octagonal" else SECTIONS

    def _dims(self, p) -> tuple[float, float, float]:
        """(neck radius, neck bottom z, shoulder bottom z)."""
        H = p["height"]
        rn = p["radius"] * p["neck_frac"]
        neck_z = H - p["lid_height"] - 0.004
        return rn, neck_z, neck_z - p["shoulder_frac"] * H

    def _outer(self, p) -> list[tuple[float, float]]:
        R, H = p["radius"], p["height"]
        rn, neck_z, sz = self._dims(p)
        c = 0.003
        if p["shape"] == "round":
            t = np.linspace(0.0, 1.0, 11)
            zs = c + (neck_z - c) * t
            rs = 0.75 * R + 0.25 * R * np.sin(math.pi * np.minimum(t * 1.15, 1.0)) ** 0.7
            rs = np.maximum(rs, rn)
            body = list(zip(rs.tolist(), zs.tolist()))
            body[-1] = (rn, neck_z)
        else:
            a = 3.0 if p["shape"] == "mason" else 1.8
            t = np.linspace(0.0, 1.0, 8)
            rs = rn + (R - rn) * (1.0 - t ** a) ** (1.0 / a)
            body = [(R, c)] + list(zip(rs.tolist(), (sz + (neck_z - sz) * t).tolist()))
        r0 = body[0][0]
        return [(0.0, 0.0), (r0 - c, 0.0)] + body + [(rn, H)]

    def _lid(self, p) -> list[m3d.Manifold]:
        rn, _, _ = self._dims(p)
        H, sk, n = p["height"], p["lid_height"], self._sections(p)
        ri, t = rn + LID_GAP, 0.0015
        ro = ri + t
        zt = H + LID_GAP + 0.002
        prof = [(0.0, H + LID_GAP), (ri, H + LID_GAP), (ri, H - sk), (ro, H - sk), (ro, zt)]
        if p["lid_style"] == "dome":
            dome = [(ro * (1 - u), zt + 0.35 * ro * math.sin(math.pi / 2 * u) * 0.4)
                    for u in np.linspace(0.0, 1.0, 6)[1:]]
            lid = lathe(prof + dome, n)
            top = zt + 0.14 * ro
            knob = [cylinder(0.006, 0.008, (0, 0, top - 0.002), 16),
                    cylinder(0.011, 0.005, (0, 0, top + 0.005), 16)]
            return [lid] + knob
        return [lathe(prof + [(0.0, zt)], n)]

    def lid_top(self, p) -> float:
        rn = self._dims(p)[0]
        zt = p["height"] + LID_GAP + 0.002
        return zt + (0.14 * (rn + LID_GAP + 0.0015) + 0.011 if p["lid_style"] == "dome" else 0.0)

    def parts(self, p, detail):
        rn = self._dims(p)[0]
        lid_slot = "metal" if p["lid_style"] == "screw" else "glass"
        if not detail:
            r = max(max(q[0] for q in self._outer(p)), rn + LID_GAP + 0.0015)
            return [cheap_cylinder(r, 0.0, self.lid_top(p), "glass")]
        v = revolve_vessel(self._outer(p), p["wall_thickness"], 0.006, self._sections(p))
        return [Part(v.shell, "glass")] + [Part(s, lid_slot, "lid") for s in self._lid(p)]

    def joints(self, p):
        lift = DoorJoint("prismatic", np.array([0.0, 0.0, 1.0]),
                         np.array([0.0, 0.0, p["height"]]), "lid")
        return [make_joint("lid", lift, 0.0, 0.08)]

    def extra_surfaces(self, p):
        n = self._sections(p)
        v = revolve_vessel(self._outer(p), p["wall_thickness"], 0.006, n)
        return [round_bottom("bottom", self._outer(p)[1][0], n),
                interior_floor("interior", v.floor_z, v.floor_r, n)]
