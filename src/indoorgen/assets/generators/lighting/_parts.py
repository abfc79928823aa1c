"""Lighting's shared pieces: `Kit` builds round parts (lathes, shells, bulbs, candle flames, discs,
rods) at a level of detail, and placeholders are the axis-aligned boxes of groups of detailed
pieces (`build_groups`), so they enclose them and share their bounding box exactly."""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.protocol import Surface
from indoorgen.assets.shapes.primitives import Part, Vec3, box_between, circle_polygon, cylinder, lathe, rod
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.model.tags import Subpart

LIGHT_SLOTS = ["metal", "shade", "glass", "emissive", "wax", "ceramic", "plastic"]


def aabb_part(parts: Sequence[Part]) -> Part:
    """One box enclosing a group of parts (slot and link of the first)."""
    bbs = np.array([q.solid.bounding_box() for q in parts], float)
    return Part(box_between(bbs[:, :3].min(axis=0), bbs[:, 3:].max(axis=0)), parts[0].slot,
                parts[0].link)


def build_groups(groups: Sequence[Sequence[Part]], detail: bool) -> list[Part]:
    """The detailed parts, or (placeholder) one enclosing box per group."""
    if detail:
        return [q for g in groups for q in g]
    return [aabb_part(g) for g in groups if g]


def _shell(outer: Sequence[tuple[float, float]], thickness: float, sections: int = 48) -> m3d.Manifold:
    """A lathed shell open at both ends: the outer profile (radius, z) bottom to top, its wall
    `thickness` thick inwards."""
    inner = [(max(r - thickness, 0.001), z) for r, z in reversed(outer)]
    return lathe(list(outer) + inner, sections)


def _bulb(z0: float, r: float, x: float = 0.0, y: float = 0.0, sections: int = 24) -> m3d.Manifold:
    """A pear-shaped bulb standing on z0 (its neck down), `r` its widest radius."""
    prof = [(0.0, 0.0), (0.45 * r, 0.0), (0.5 * r, 0.35 * r), (0.85 * r, 0.8 * r), (r, 1.35 * r),
            (0.92 * r, 1.8 * r), (0.6 * r, 2.15 * r), (0.0, 2.3 * r)]
    return lathe(prof, sections).translate((x, y, z0))


def _flame(z0: float, r: float, x: float = 0.0, y: float = 0.0, sections: int = 16) -> m3d.Manifold:
    """A candle-flame bulb standing on z0, `r` its widest radius."""
    prof = [(0.0, 0.0), (0.55 * r, 0.0), (r, 0.9 * r), (0.8 * r, 2.0 * r), (0.3 * r, 3.0 * r),
            (0.0, 3.4 * r)]
    return lathe(prof, sections).translate((x, y, z0))


def top_disc(r: float, z: float) -> Surface:
    """The ceiling-facing `top` of a round canopy of radius r whose top face is at z."""
    return support_polygon("top", (0, 0, z), circle_polygon(0.995 * r, 48), subpart=Subpart.Top)


def top_rect(hx: float, hy: float, z: float) -> Surface:
    """The ceiling-facing `top` of a rectangular canopy, half sizes hx, hy, its top face at z."""
    return support_polygon("top", (0, 0, z), sg.box(-hx, -hy, hx, hy), subpart=Subpart.Top)


@dataclass(frozen=True)
class Kit:
    """Part builders at a level of detail: the real round pieces or, for placeholders (which
    only need each group's bounding box), their exact axis-aligned boxes (`boxes`) or coarse
    8-section versions with the same bounding box (lathes keep vertices on the axes; for parts
    that are then rotated about Y)."""

    detail: bool
    boxes: bool = True

    def n(self, sections: int) -> int:
        """The section count at this level of detail (8 for placeholders)."""
        return sections if self.detail else 8

    def _cheap_box(self, r: float, z0: float, z1: float, x: float = 0.0, y: float = 0.0):
        return box_between((x - r, y - r, z0), (x + r, y + r, z1))

    def lathe(self, profile: Sequence[tuple[float, float]], sections: int = 48) -> m3d.Manifold:
        """A lathed profile, or for boxed placeholders the box around it."""
        if self.detail or not self.boxes:
            return lathe(profile, self.n(sections))
        pts = np.asarray(profile, float)
        return self._cheap_box(pts[:, 0].max(), pts[:, 1].min(), pts[:, 1].max())

    def cylinder(self, radius: float, height: float, center: Vec3, sections: int = 32,
                 **kw: Any) -> m3d.Manifold:
        """A Z cylinder (or cone frustum), or its box."""
        if self.detail or not self.boxes:
            return cylinder(radius, height, center, self.n(sections), **kw)
        r = max(radius, kw.get("radius_top") or 0.0)
        x, y, z = (float(c) for c in center)
        return self._cheap_box(r, z, z + height, x, y)

    def disc(self, r: float, z0: float, h: float, x: float = 0.0, y: float = 0.0, n: int = 48
             ) -> m3d.Manifold:
        """A disc of radius r from z0 up by h centred on (x, y), or its box."""
        return self.cylinder(r, h, (x, y, z0), n)

    def shell(self, outer: Sequence[tuple[float, float]], thickness: float, sections: int = 48
              ) -> m3d.Manifold:
        """A lathed shell open at both ends (see `_shell`), or the box around its outer profile."""
        if self.detail or not self.boxes:
            return _shell(outer, thickness, self.n(sections))
        return self.lathe(outer)

    def bulb(self, z0: float, r: float, x: float = 0.0, y: float = 0.0) -> m3d.Manifold:
        """A pear-shaped bulb standing on z0, or its box."""
        if self.detail or not self.boxes:
            return _bulb(z0, r, x, y, self.n(24))
        return self._cheap_box(r, z0, z0 + 2.3 * r, x, y)

    def flame(self, z0: float, r: float, x: float = 0.0, y: float = 0.0) -> m3d.Manifold:
        """A candle-flame bulb standing on z0, or its box."""
        if self.detail or not self.boxes:
            return _flame(z0, r, x, y, self.n(16))
        return self._cheap_box(r, z0, z0 + 3.4 * r, x, y)

    def sphere(self, r: float, sections: int = 12) -> m3d.Manifold:
        """A sphere about the origin, or its box."""
        if self.detail or not self.boxes:
            return m3d.Manifold.sphere(r, self.n(sections))
        return self._cheap_box(r, -r, r)

    def rod(self, p0: Vec3, p1: Vec3, radius: float, sections: int = 12) -> m3d.Manifold:
        """A rod from p0 to p1, or the box with the exact extents of its end discs."""
        if self.detail:
            return rod(p0, p1, radius, sections)
        p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
        d = (p1 - p0) / np.linalg.norm(p1 - p0)
        pad = radius * np.sqrt(np.clip(1.0 - d ** 2, 0.0, 1.0))
        return box_between(np.minimum(p0, p1) - pad, np.maximum(p0, p1) + pad)


FINE, CHEAP, CHEAP_ROUND = Kit(True), Kit(False), Kit(False, boxes=False)
