"""Bottles: wine, beer and soda bottles, solids of revolution from one shape spec.

Capped bottles are solid (the contents fill them), so no shell hides a sealed void; open ones
are hollow vessels (`shapes.vessels.revolve_vessel`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import Part, cylinder, lathe
from indoorgen.assets.shapes.vessels import (
    SECTIONS,
    Vessel,
    cheap_cylinder,
    revolve_vessel,
    round_bottom,
    solid_revolve,
)
from indoorgen.model.tags import Semantics as S


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
    pts += list(zip(r.tolist(), z.tolist(), strict=True))
    t = np.linspace(0.0, 1.0, 10)[1:]
    a = b.shoulder_exp
    rs = b.neck_r + (float(r[-1]) - b.neck_r) * (1.0 - t ** a) ** (1.0 / a)
    zs = b.shoulder_z + (b.neck_z - b.shoulder_z) * t
    pts += list(zip(rs.tolist(), zs.tolist(), strict=True))
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
    vessel = None
    if clo:
        dr, down, up, slot = clo
        out = [Part(solid_revolve(outer), b.body_slot),
               Part(cylinder(b.lip_r + dr, down + up, (0, 0, b.height - down), SECTIONS), slot)]
    else:
        vessel = revolve_vessel(outer, b.wall, b.punt + b.wall + 0.002)
        out = [Part(vessel.shell, b.body_slot)]
    if b.label:
        out.append(Part(_label(b, b.label, outer, vessel), "paper"))
    return out


def _label(b: BottleSpec, band: tuple[float, float], outer: list[tuple[float, float]],
           vessel: Vessel | None) -> m3d.Manifold:
    """A paper band around the body from z0 to z1 (`band`): a ring reaching 0.4 mm beyond the
    widest body radius there and sunk into the narrowest, clear of the cavity of open bottles."""
    z0, z1 = band
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
        """The shape of the wine bottle these params make."""
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
        """The shape of the beer bottle these params make."""
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
        """The shape of the soda bottle these params make."""
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
