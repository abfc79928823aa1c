"""Vessels: hollow solids of revolution (bowls, cups, glasses, bottles, jars, pots) and bowls.

A vessel's outer half profile ((r, z) points from the axis at the bottom up to the rim) is
mirrored into a full cross-section, and `revolve_vessel` hollows it by offsetting that section
inward by the wall thickness (so sloped walls keep their thickness) and clipping the cavity at
the floor height: one closed shell whose cavity opens at the rim. Shared by the tableware,
kitchenware and food generators (a fruit bowl is a bowl).
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.shapes.primitives import Part, circle_polygon, cylinder, lathe
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Subpart

#: lathe sections of detailed vessels (a multiple of 4: vertices on the +-X/+-Y axes)
SECTIONS = 32
#: lathe sections of placeholder cylinders
CHEAP = 16
_BIG = 10.0


# ------------------------------------------------------------------------------- vessels
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
    pts = [(float(q[0]), float(q[1])) for q in outer]
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
    pts = [(float(q[0]), float(q[1])) for q in outer]
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
    pts += list(zip(rs.tolist(), zs.tolist(), strict=True))[0 if fh == 0 else 1:]
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
    """The hollow of a bowl with `bowl_params`: its outer profile, walls and floor."""
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
