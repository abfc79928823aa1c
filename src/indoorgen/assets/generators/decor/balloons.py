"""Balloons: one or a bunch on strings tied to a small weight, arranged so that no two touch."""
from __future__ import annotations

import math
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import Part, box, box_between, circle_polygon, cylinder, lathe, rod
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


def _balloon_profile(R: float, E: float, knot: float, n: int = 14) -> list[tuple[float, float]]:
    """A lathe profile of a balloon with its knot at z=0 and its crown at the top."""
    phi = np.linspace(0.0, math.pi, n)
    z = knot * 1.4 + E * R * (1 - np.cos(phi))
    r = R * np.sin(phi) * (0.78 + 0.22 * (1 - np.cos(phi)) / 2)
    pts = [(0.0, 0.0), (knot, 0.3 * knot), (0.9 * knot, knot), (0.5 * knot, knot * 1.45)]
    pts += [(float(a), float(b)) for a, b in zip(r[1:-1], z[1:-1], strict=True)]
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

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The weight, then each balloon with its string (placeholder: their boxes)."""
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

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The weight's underside as the `bottom`."""
        wt = self.WEIGHT
        if p["weight_style"] == "cube":
            poly = sg.box(-wt / 2 + 0.0005, -wt / 2 + 0.0005, wt / 2 - 0.0005, wt / 2 - 0.0005)
        else:
            poly = circle_polygon(wt / 2 - 0.0005, 24)
        return [support_polygon("bottom", (0, 0, 0), poly, subpart=Subpart.Bottom, up=False)]
