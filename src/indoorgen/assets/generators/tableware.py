"""Tableware: lathed plates and cups (a cup is a closed solid with an open cavity)."""
from __future__ import annotations

from indoorgen.assets.base import Param, register
from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.shapes.primitives import Part, box_between, circle_polygon, cylinder, lathe, torus
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart


@register
class Plate(PartsFactory):
    """A plate: flat foot/well of radius `foot_frac * radius`, a rim rising to `rim_height`;
    its top surface is the underside lifted by `thickness` (so walls keep their thickness)."""

    name = "plate"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Plate})
    size_class = "small"
    slots = ["ceramic"]
    solid_bottom = True
    params = {
        "radius": Param(0.09, 0.15, doc="outer radius (m)"),
        "rim_height": Param(0.015, 0.035, doc="Z extent (m)"),
        "thickness": Param(0.004, 0.008, doc="wall thickness (m)"),
        "foot_frac": Param(0.5, 0.7, doc="flat foot (and well) radius / radius"),
        "rim_curve": Param(1.0, 2.5, doc="rim profile exponent (1 = straight cone, >1 = curved)"),
        "rim_lip": Param(kind="bool", doc="add a flat lip at the rim"),
    }

    def underside(self, p, n: int) -> list[tuple[float, float]]:
        R, h, th = p["radius"], p["rim_height"], p["thickness"]
        rf = R * p["foot_frac"]
        lip = 0.12 * (R - rf) if p["rim_lip"] else 0.0
        pts = []
        for i in range(n + 1):
            u = i / n
            r = rf + (R - lip - rf) * u
            pts.append((r, (h - th) * u ** p["rim_curve"]))
        if lip:
            pts.append((R, h - th))
        return pts

    def parts(self, p, detail):
        R, h, th = p["radius"], p["rim_height"], p["thickness"]
        if not detail:
            return [Part(cylinder(R, h, (0, 0, 0), 16, circumscribed=True), "ceramic")]
        under = self.underside(p, 10)
        top = [(r, z + th) for r, z in reversed(under)]
        prof = [(0.0, 0.0)] + under + top + [(0.0, th)]
        return [Part(lathe(prof, 64), "ceramic")]

    def extra_surfaces(self, p):
        rf = p["radius"] * p["foot_frac"]
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(rf * 0.995, 64),
                                subpart=Subpart.Bottom, up=False),
                support_polygon("top", (0, 0, p["thickness"]), circle_polygon(rf * 0.95, 64))]


@register
class Cup(PartsFactory):
    """A cup or mug: a lathed body with a hollow, optionally a torus handle on +Y (clipped so
    none of it enters the cavity)."""

    name = "cup"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Cup})
    size_class = "small"
    slots = ["ceramic"]
    solid_bottom = True
    params = {
        "radius": Param(0.035, 0.05, doc="outer radius at the rim (m)"),
        "bottom_frac": Param(0.7, 1.0, doc="outer radius at the base / at the rim"),
        "height": Param(0.07, 0.12, doc="body height (m)"),
        "wall_thickness": Param(0.003, 0.006, doc="wall thickness (m)"),
        "base_thickness": Param(0.005, 0.012, doc="floor thickness (m)"),
        "handle": Param(kind="bool", doc="add a handle"),
        "handle_size": Param(0.018, 0.03, doc="handle loop radius (m)"),
        "handle_thickness": Param(0.004, 0.008, doc="handle cross-section radius (m)"),
    }

    def _r(self, p, z: float) -> float:
        rb, rt = p["radius"] * p["bottom_frac"], p["radius"]
        return rb + (rt - rb) * z / p["height"]

    def _handle_dims(self, p) -> tuple[float, float, float]:
        """(loop radius, tube radius, centre height), shrunk to stay within the body height."""
        H, hr = p["height"], p["handle_thickness"]
        R = min(p["handle_size"], 0.5 * H - hr - 0.012)
        return R, hr, H * 0.5

    def parts(self, p, detail):
        H, w, b = p["height"], p["wall_thickness"], p["base_thickness"]
        rb, rt = p["radius"] * p["bottom_frac"], p["radius"]
        out = []
        if detail:
            prof = [(0.0, 0.0), (rb, 0.0), (rt, H), (rt - w, H), (self._r(p, b) - w, b), (0.0, b)]
            body = lathe(prof, 48)
            out.append(Part(body, "ceramic"))
        else:
            out.append(Part(lathe([(0.0, 0.0), (rb, 0.0), (rt, H), (0.0, H)], 16, circumscribed=True),
                            "ceramic"))
        if p["handle"]:
            R, hr, zc = self._handle_dims(p)
            yc = self._r(p, zc)
            if detail:
                ring = torus(R, hr, sections=24, tube_sections=8).rotate((90.0, 0.0, 90.0))
                ring = ring.translate((0.0, yc, zc))
                cavity = lathe([(0.0, b), (self._r(p, b) - w + 0.0005, b),
                                (rt - w + 0.0005, H), (rt - w + 0.0005, H + 0.05), (0.0, H + 0.05)], 48)
                out.append(Part(ring - cavity, "ceramic"))
            else:
                out.append(Part(box_between((-hr, yc - 0.004, zc - R - hr), (hr, yc + R + hr, zc + R + hr)),
                                "ceramic"))
        return out

    def extra_surfaces(self, p):
        rb = p["radius"] * p["bottom_frac"]
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(rb * 0.995, 48),
                                subpart=Subpart.Bottom, up=False)]
