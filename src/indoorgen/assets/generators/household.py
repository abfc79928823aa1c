"""Household objects: towels, folded clothes, baskets and storage boxes.

Textiles are solid extrusions of their side profile (a towel's serpentine folds, a rolled towel's
spiral with the end lying flat), so they stay single watertight shells with the layering
visible. A storage box's lid is its own link.
"""
from __future__ import annotations

import math
import zlib
from typing import Any

import manifold3d as m3d
import numpy as np
import shapely.geometry as sg

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Joint, Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.moving_parts import MOVING_GAP, DoorJoint, make_joint
from indoorgen.assets.shapes.outlines import ccw, largest_polygon
from indoorgen.assets.shapes.primitives import (
    SMALL_OVERLAP,
    Part,
    bevel_box,
    box_between,
    circle_polygon,
    cylinder,
    rounded_rect_section,
    torus,
)
from indoorgen.assets.shapes.surfaces import bottom_rect, support_polygon, support_rect
from indoorgen.assets.shapes.sweeps import loft, xz_extrude
from indoorgen.model.scene import as_saved
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

#: how far a rolled towel lying on its side is pressed flat, as a share of its radius: its
#: contact is a band about 0.8 of the radius wide under its centre (a soft roll settles so)
ROLL_SQUASH = 0.08


def _seed(p: dict[str, Any]) -> int:
    """A deterministic seed from the params as scene.json saves them (for small per-item
    variations that must come out the same when a saved scene is rebuilt)."""
    return zlib.crc32(repr(sorted(as_saved(p).items())).encode())


@register
class Towel(PartsFactory):
    """A towel, or a few: `folded` (a stack of layers whose serpentine folds bulge at the front
    and back, free edges notched) or `rolled` (a spiral roll lying on its side with its end
    flat on the surface; 2-3 rolls side by side or in a pyramid)."""

    name = "towel"
    tags = frozenset({S.Object, S.SmallObject, S.Textile, S.Towel})
    size_class = "small"
    slots = ["fabric"]
    solid_bottom = False
    params = {
        "style": Param(kind="choice", choices=("folded", "rolled"), doc="folded or rolled"),
        "width": Param(0.2, 0.4, doc="Y extent: folded width / roll length (m)"),
        "depth": Param(0.15, 0.3, doc="X extent of a folded towel (m)"),
        "layer_thickness": Param(0.004, 0.01, doc="thickness of one towel layer (m)"),
        "n_layers": Param(2, 5, kind="int", doc="folded layers / turns of the roll"),
        "n_towels": Param(1, 3, kind="int", doc="towels stacked (folded) or rolled side by side"),
        "puff": Param(1.0, 1.6, doc="how far the folds bulge (x layer thickness)"),
        "tail_length": Param(0.02, 0.08, doc="rolled: length of the end lying flat (m)"),
    }

    # ---------------------------------------------------------------- folded
    @staticmethod
    def _folded_profile(d: float, t: float, n: int, puff: float) -> m3d.CrossSection:
        """Side profile (x, z) of n layers of thickness t, depth d: the layers' slab, a bulge
        at each fold (alternately at the front and back) and a notch between free edges."""
        slab = m3d.CrossSection.square((d, n * t), False).translate((-d / 2, 0.0))
        bulges, notches = [], []
        rb = 0.5 * t * puff
        for k in range(n - 1):
            z = (k + 1) * t
            side = 1.0 if k % 2 == 0 else -1.0
            c = np.array([side * d / 2, z])
            a = np.linspace(-math.pi / 2, math.pi / 2, 9)
            half = np.c_[c[0] + side * rb * 2 * np.cos(a) * 0.5, c[1] + t * np.sin(a)]
            bulges.append(m3d.CrossSection([ccw(np.vstack([half, [[c[0] - side * 0.01, z + t],
                                                                   [c[0] - side * 0.01, z - t]]]))]))
            nx = -side * d / 2
            notch = np.array([[nx - side * 0.001, z - 0.25 * t], [nx + side * 0.003, z],
                              [nx - side * 0.001, z + 0.25 * t]])
            notches.append(m3d.CrossSection([ccw(notch)]))
        out = slab
        if bulges:
            out = m3d.CrossSection.batch_boolean([slab] + bulges, m3d.OpType.Add)
        if notches:
            out = m3d.CrossSection.batch_boolean([out] + notches, m3d.OpType.Subtract)
        return out

    def _folded_items(self, p) -> list[tuple[float, float, float, float]]:
        """(depth, width, z0, x offset) of each towel in the stack, largest at the bottom."""
        t, n = p["layer_thickness"], int(p["n_layers"])
        out, z = [], 0.0
        for i in range(int(p["n_towels"])):
            k = 1.0 - 0.04 * i
            out.append((p["depth"] * k, p["width"] * k, z, 0.006 * (i % 2)))
            z += n * t - SMALL_OVERLAP
        return out

    def _folded(self, p, detail):
        t, n, puff = p["layer_thickness"], int(p["n_layers"]), p["puff"]
        out = []
        for d, w, z0, dx in self._folded_items(p):
            ext = 0.5 * t * puff
            prof = self._folded_profile(d, t, n, puff)
            if not detail:  # the profile's exact extent (the folds bulge on one or both ends)
                x0, _, x1, _ = prof.bounds()
                out.append(Part(box_between((dx + x0, -w / 2, z0), (dx + x1, w / 2, z0 + n * t)),
                                "fabric"))
                continue
            solid = xz_extrude(prof, -w / 2, w / 2)
            # soften the ends along Y (towels are folded there too)
            soft = bevel_box((d + 2 * ext + 0.01, w, n * t), (0.0, 0.0, n * t / 2),
                             min(0.45 * n * t, 0.02), 2)
            out.append(Part((solid ^ soft).translate((dx, 0.0, z0)), "fabric"))
        return out

    # ---------------------------------------------------------------- rolled
    def _roll_radius(self, p) -> float:
        t, turns = p["layer_thickness"], int(p["n_layers"])
        return 0.006 + turns * t + 0.85 * t

    def _roll_profile(self, p) -> np.ndarray:
        """Side profile (x, z) of a roll centred at (0, R): an Archimedean spiral band (0.85 of
        the pitch thick, so the turns show) ending at the bottom, then the tail lying flat."""
        t, turns = p["layer_thickness"], int(p["n_layers"])
        r0 = 0.006
        n = 24 * turns
        # theta measured from the bottom (angle -90 degrees), counter-clockwise in (x, z)
        th = np.linspace(0.0, 2 * math.pi * turns, n + 1)
        r_in = r0 + t * th / (2 * math.pi)
        r_out = r_in + 0.85 * t
        R = r_out[-1]
        ang = th - math.pi / 2
        inner = np.c_[r_in * np.cos(ang), R + r_in * np.sin(ang)]
        outer = np.c_[r_out * np.cos(ang), R + r_out * np.sin(ang)]
        tail = p["tail_length"]
        end = np.array([[tail, 0.0], [tail, 0.85 * t]])
        return ccw(np.vstack([outer, end, inner[::-1]]))

    def _roll_squash(self, p) -> float:
        """How far (m) a roll lying on the surface is pressed flat: `ROLL_SQUASH` of its radius."""
        return ROLL_SQUASH * self._roll_radius(p)

    def _squashed(self, p, pts: np.ndarray) -> m3d.CrossSection:
        """The roll profile `pts` pressed flat on the surface: cut `_roll_squash` up and lowered
        onto z = 0, its end still lying flat from the roll's middle outwards."""
        cs = m3d.CrossSection([pts], m3d.FillRule.NonZero)
        dz = self._roll_squash(p)
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        keep = m3d.CrossSection.square((hi[0] - lo[0] + 0.02, hi[1]), False).translate(
            (lo[0] - 0.01, dz))
        flat = m3d.CrossSection.batch_boolean([cs, keep], m3d.OpType.Intersect).translate((0, -dz))
        t = p["layer_thickness"]
        tail = m3d.CrossSection.square((max(p["tail_length"], 0.0015), 0.85 * t), False)
        return m3d.CrossSection.batch_boolean([flat, tail], m3d.OpType.Add)

    def _roll_centres(self, p) -> list[tuple[float, float]]:
        """Roll positions: side by side overlapping 2 mm (pressed flat by `_roll_squash`), a
        third one resting on the two."""
        R, t = self._roll_radius(p), p["layer_thickness"]
        pts = self._roll_profile(dict(p, tail_length=0.0015))
        span = pts[:, 0].max() - pts[:, 0].min()
        n = int(p["n_towels"])
        c1 = span - 2 * SMALL_OVERLAP
        out = [(0.0, 0.0), (c1, 0.0)][:n]
        if n == 3:
            reach = 2 * (R - 0.75 * t) - 2 * SMALL_OVERLAP  # the turns' smallest outer radius, twice
            out.append((c1 / 2, math.sqrt(max(reach ** 2 - (c1 / 2) ** 2, 0.0))
                        - self._roll_squash(p)))
        return out

    def _rolled(self, p, detail):
        w = p["width"]
        out = []
        centres = self._roll_centres(p)
        n_bottom = min(len(centres), 2)
        for i, (cx, cz) in enumerate(centres):
            # the last roll of the bottom row lets its end lie flat (outwards, +X); the bottom
            # row is pressed flat where it lies (a roll on a line contact rolls off in MuJoCo:
            # its end alone, beside its centre of mass, held it)
            tail = p["tail_length"] if i == n_bottom - 1 else 0.0
            pts = self._roll_profile(dict(p, tail_length=max(tail, 0.0015)))
            cs = (self._squashed(dict(p, tail_length=tail), pts) if i < n_bottom
                  else m3d.CrossSection([pts], m3d.FillRule.NonZero))
            if not detail:  # the profile's exact extent
                x0, z0, x1, z1 = cs.bounds()
                out.append(Part(box_between((cx + x0, -w / 2, cz + z0),
                                            (cx + x1, w / 2, cz + z1)), "fabric"))
                continue
            out.append(Part(xz_extrude(cs, -w / 2, w / 2).translate((cx, 0.0, cz)), "fabric"))
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """A stack of folded towels or rolled towels, by style."""
        return self._folded(p, detail) if p["style"] == "folded" else self._rolled(p, detail)


GARMENTS = ("tshirt", "shirt", "sweater", "pants")


@register
class FoldedClothes(PartsFactory):
    """A stack of 1-5 folded garments (t-shirts with a collar rib, shirts with a collar and
    button placket, sweaters with a ribbed hem, pants with a crease and waistband), each a
    soft rounded slab, slightly varied in size and offset."""

    name = "folded_clothes"
    tags = frozenset({S.Object, S.SmallObject, S.Textile, S.FoldedClothes})
    size_class = "small"
    slots = ["fabric", "plastic"]
    params = {
        "n_items": Param(1, 5, kind="int", doc="garments in the stack"),
        "width": Param(0.25, 0.38, doc="Y extent of a folded garment (m)"),
        "depth": Param(0.2, 0.32, doc="X extent of a folded garment (m)"),
        "item_thickness": Param(0.015, 0.045, doc="thickness of one folded garment (m)"),
        "garment": Param(kind="choice", choices=GARMENTS, doc="kind of garment (the bottom one)"),
        "mixed": Param(kind="bool", doc="vary the kind of garment up the stack"),
        "size_jitter": Param(0.0, 0.1, doc="relative size variation between garments"),
        "offset_jitter": Param(0.0, 0.02, doc="misalignment between garments (m)"),
        "edge_radius": Param(0.004, 0.012, doc="rounding of the folded edges (m)"),
    }

    def _items(self, p) -> list[dict[str, Any]]:
        rng = np.random.default_rng(_seed(p))
        out, z = [], 0.0
        g0 = GARMENTS.index(p["garment"])
        for i in range(int(p["n_items"])):
            kind = GARMENTS[(g0 + i) % 4] if p["mixed"] else p["garment"]
            j = 1.0 + p["size_jitter"] * (rng.random(3) * 2 - 1)
            d, w, t = p["depth"] * j[0], p["width"] * j[1], p["item_thickness"] * j[2]
            if kind == "pants":
                d, w = d * 1.1, w * 0.75
            elif kind == "sweater":
                t *= 1.3
            off = p["offset_jitter"] * (rng.random(2) * 2 - 1)
            out.append(dict(kind=kind, d=d, w=w, t=t, z=z, x=off[0], y=off[1]))
            z += t - SMALL_OVERLAP
        return out

    @staticmethod
    def _details(it: dict[str, Any]) -> list[tuple[m3d.Manifold, str]]:
        """Raised details on top of one garment, in its own frame (top face at z = t)."""
        d, w, t, kind = it["d"], it["w"], it["t"], it["kind"]
        top = t - 0.0008
        out = []
        if kind in ("tshirt", "shirt"):
            rc = 0.055 if kind == "tshirt" else 0.065
            ring = torus(rc, 0.004 if kind == "tshirt" else 0.006, sections=24, tube_sections=8)
            # the back half of a collar ring, lying on the top near the back edge
            half = ring.trim_by_plane((-1.0, 0.0, 0.0), 0.0).translate((-d / 2 + rc + 0.02, 0, top))
            out.append((half, "fabric"))
            if kind == "shirt":
                x0, x1 = -d / 2 + rc + 0.02, d / 2 - 0.02
                out.append((box_between((x0, -0.012, top - 0.001), (x1, 0.012, top + 0.0015)),
                            "fabric"))
                for k in range(3):
                    xb = x0 + (k + 0.5) * (x1 - x0) / 3
                    out.append((cylinder(0.005, 0.0025, (xb, 0.0, top + 0.001), 12), "plastic"))
        elif kind == "sweater":
            for k in range(3):
                xr = d / 2 - 0.015 - 0.012 * k
                out.append((box_between((xr - 0.003, -w / 2 + 0.02, top - 0.001),
                                        (xr + 0.003, w / 2 - 0.02, top + 0.002)), "fabric"))
        else:  # pants: a crease along X and a waistband at the back
            out.append((box_between((-d / 2 + 0.05, -0.002, top - 0.001), (d / 2 - 0.02, 0.002,
                                                                          top + 0.0015)), "fabric"))
            out.append((box_between((-d / 2 + 0.008, -w / 2 + 0.01, top - 0.001),
                                    (-d / 2 + 0.045, w / 2 - 0.01, top + 0.003)), "fabric"))
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The folded garments, stacked, with the top one's collar, buttons or hem."""
        out = []
        items = self._items(p)
        for i, it in enumerate(items):
            d, w, t = it["d"], it["w"], it["t"]
            mv = (it["x"], it["y"], it["z"])
            if not detail:
                top = t + (0.006 if i == len(items) - 1 else 0.0)
                out.append(Part(box_between((-d / 2, -w / 2, 0.0), (d / 2, w / 2, top))
                                .translate(mv), "fabric"))
                continue
            r = min(p["edge_radius"], 0.45 * t)
            out.append(Part(bevel_box((d, w, t), (0.0, 0.0, t / 2), r, 2).translate(mv), "fabric"))
            if i == len(items) - 1:  # details show on the top garment only
                out += [Part(s.translate(mv), slot) for s, slot in self._details(it)]
        return out


@register
class Basket(PartsFactory):
    """A woven basket: `round` (a hollow lathe-like shell whose outer wall bulges in
    alternating weave bands) or `rect` (a floor, corner posts and rows of slats with gaps),
    flaring towards the top, with an optional rim band and an arched or two side handles.
    Its floor is an interior surface."""

    name = "basket"
    tags = frozenset({S.Object, S.SmallObject, S.Container, S.Basket})
    size_class = "small"
    slots = ["wood", "fabric"]
    solid_bottom = True
    params = {
        "shape": Param(kind="choice", choices=("round", "rect"), doc="plan shape"),
        "width": Param(0.2, 0.45, doc="Y extent at the top (m); a round basket's diameter"),
        "depth_ratio": Param(0.6, 1.0, doc="rect: X extent / Y extent"),
        "height": Param(0.1, 0.3, doc="height of the rim (m)"),
        "flare": Param(1.0, 1.25, doc="top size / bottom size"),
        "wall_thickness": Param(0.006, 0.012, doc="wall thickness (m)"),
        "weave_rows": Param(4, 10, kind="int", doc="horizontal weave bands / slat rows"),
        "handle": Param(kind="choice", choices=("none", "arch", "side"), doc="handles"),
        "rim": Param(kind="bool", doc="a thicker rim band at the top"),
    }
    FLOOR = 0.01
    WEAVE = 0.0025  # bulge of the weave bands (m)

    def _round_radii(self, p) -> tuple[float, float]:
        rt = p["width"] / 2 - self.WEAVE
        return rt / p["flare"], rt

    def _round_shell(self, p) -> m3d.Manifold:
        """Rings from the bottom centre out, up the woven outer wall, over the rim and down the
        smooth inner wall to the floor's centre (one closed sweep)."""
        return loft(self._round_rings(p), np.zeros(3), np.array([0.0, 0.0, self.FLOOR]))

    def _round_rings(self, p) -> np.ndarray:
        H, wt = p["height"], p["wall_thickness"]
        rb, rt = self._round_radii(p)
        rows = int(p["weave_rows"])
        k = 40
        th = np.arange(k) * 2 * math.pi / k
        per = 3
        zs = np.linspace(0.0, H, rows * per + 1)

        def rad(z: float) -> float:  # the wall's radius at height z
            return rb + (rt - rb) * z / H

        rings = [np.c_[rb * np.cos(th), rb * np.sin(th), np.zeros(k)]]
        for i, z in enumerate(zs[1:-1], start=1):
            row, u = divmod(i, per)
            bulge = self.WEAVE * math.sin(math.pi * u / per)
            phase = np.where(np.cos(th * 10 + math.pi * row) > 0, 1.0, 0.35)
            r = rad(z) + bulge * phase
            rings.append(np.c_[r * np.cos(th), r * np.sin(th), np.full(k, z)])
        lip = wt * (1.6 if p["rim"] else 1.0)
        for r_rim, z in ((rad(H), H), (rad(H) - lip, H)):
            rings.append(np.c_[r_rim * np.cos(th), r_rim * np.sin(th), np.full(k, z)])
        for z in np.linspace(H - 0.004, self.FLOOR, 4):
            r = rad(z) - wt
            rings.append(np.c_[r * np.cos(th), r * np.sin(th), np.full(k, z)])
        return np.array(rings)

    def _rect_dims(self, p) -> tuple[float, float, float, float]:
        Wt = p["width"]
        Dt = Wt * p["depth_ratio"]
        return Dt / p["flare"], Wt / p["flare"], Dt, Wt

    def _rect(self, p, detail) -> list[Part]:
        H, wt = p["height"], p["wall_thickness"]
        Db, Wb, Dt, Wt = self._rect_dims(p)
        if not detail:
            return [Part(box_between((-Dt / 2, -Wt / 2, 0.0), (Dt / 2, Wt / 2, H)), "wood")]
        out = [Part(box_between((-Db / 2, -Wb / 2, 0.0), (Db / 2, Wb / 2, self.FLOOR)), "wood")]

        def half(D: float, z: float) -> float:  # half the flaring wall's width D at height z
            return D / 2 + (D * p["flare"] - D) / 2 * z / H

        pw = 0.018
        for sx in (-1, 1):
            for sy in (-1, 1):
                pts = [(sx * (D / 2 - a), sy * (W / 2 - b), z) for D, W, z in ((Db, Wb, 0.0), (Dt, Wt, H))
                       for a in (0.0, pw) for b in (0.0, pw)]
                out.append(Part(m3d.Manifold.hull_points(np.array(pts)), "wood"))
        rows = int(p["weave_rows"])
        pitch = (H - self.FLOOR) / rows
        for r in range(rows):
            z0 = self.FLOOR + r * pitch + (0.0 if r == 0 else 0.3 * pitch)
            z1 = self.FLOOR + (r + 1) * pitch
            if r == 0:
                z0 -= SMALL_OVERLAP
            zm = (z0 + z1) / 2
            hx, hy = half(Db, zm), half(Wb, zm)
            for sx in (-1, 1):
                out.append(Part(box_between((min(sx * hx, sx * (hx - wt)), -hy + SMALL_OVERLAP, z0),
                                            (max(sx * hx, sx * (hx - wt)), hy - SMALL_OVERLAP, z1)), "wood"))
            for sy in (-1, 1):
                out.append(Part(box_between((-hx + SMALL_OVERLAP, min(sy * hy, sy * (hy - wt)), z0),
                                            (hx - SMALL_OVERLAP, max(sy * hy, sy * (hy - wt)), z1)), "wood"))
        if p["rim"]:
            ring = (box_between((-Dt / 2, -Wt / 2, H - 0.015), (Dt / 2, Wt / 2, H))
                    - box_between((-Dt / 2 + wt * 1.5, -Wt / 2 + wt * 1.5, H - 0.02),
                                  (Dt / 2 - wt * 1.5, Wt / 2 - wt * 1.5, H + 0.01)))
            out.append(Part(ring, "wood"))
        return out

    def _handles(self, p, detail) -> list[Part]:
        H, kind = p["height"], p["handle"]
        if kind == "none":
            return []
        if p["shape"] == "round":
            half_w = self._round_radii(p)[1] - p["wall_thickness"] / 2
        else:
            half_w = self._rect_dims(p)[3] / 2 - p["wall_thickness"] / 2
        m = 0.006
        if kind == "arch":
            R = half_w
            if not detail:
                return [Part(box_between((-m, -R - m, H - 0.01), (m, R + m, H + R + m)), "fabric")]
            arch = torus(R, m, sections=32, tube_sections=8).trim_by_plane((0, 1, 0), 0.0)
            return [Part(arch.rotate((90.0, 0.0, 0.0)).rotate((0.0, 0.0, 90.0))
                         .translate((0.0, 0.0, H - 0.01)), "fabric")]
        out = []
        R = 0.03
        for s in (-1, 1):
            y = s * half_w
            if not detail:
                out.append(Part(box_between((-R - m, y - m, H - 0.01), (R + m, y + m, H + R + m)),
                                "fabric"))
                continue
            loop = torus(R, m, sections=16, tube_sections=8).trim_by_plane((0, 1, 0), 0.0)
            out.append(Part(loop.rotate((90.0, 0.0, 0.0)).translate((0.0, y, H - 0.01)), "fabric"))
        return out

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The woven round shell or slatted rectangular body, and the handles."""
        if p["shape"] == "round":
            rb, rt = self._round_radii(p)
            if detail:
                body = [Part(self._round_shell(p), "wood")]
            else:  # a box on the woven wall's exact bounds
                pts = self._round_rings(p).reshape(-1, 3)
                body = [Part(box_between(pts.min(axis=0), pts.max(axis=0)), "wood")]
        else:
            body = self._rect(p, detail)
        return body + self._handles(p, detail)

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The underside (`bottom`) and the basket floor (`interior_0`)."""
        wt = p["wall_thickness"]
        if p["shape"] == "round":
            rb, _ = self._round_radii(p)
            ri = rb + (self._round_radii(p)[1] - rb) * self.FLOOR / p["height"] - wt
            return [support_polygon("bottom", (0, 0, 0), circle_polygon(rb - 0.0005, 40),
                                    subpart=Subpart.Bottom, up=False),
                    support_polygon("interior_0", (0, 0, self.FLOOR), circle_polygon(ri - 0.004, 40),
                                    subpart=Subpart.Interior)]
        Db, Wb, _, _ = self._rect_dims(p)
        return [bottom_rect((0, 0, 0), Db / 2 - 0.0005, Wb / 2 - 0.0005),
                support_polygon("interior_0", (0, 0, self.FLOOR),
                                sg.box(-Db / 2 + wt + 0.004, -Wb / 2 + wt + 0.004,
                                       Db / 2 - wt - 0.004, Wb / 2 - wt - 0.004),
                                subpart=Subpart.Interior)]


@register
class StorageBox(PartsFactory):
    """A storage box: `cardboard` (straight walls, optional hand holes) or `plastic` (tapered,
    rounded corners, a rim flange), with a lid on its own link: a skirted `lift_off` lid
    (prismatic joint up) or a flat `hinged` lid (revolute joint at the back). The box floor
    is an interior surface and the lid's top a support surface."""

    name = "storage_box"
    tags = frozenset({S.Object, S.Storage, S.Container, S.Box})
    size_class = "medium"
    slots = ["cardboard", "plastic"]
    solid_bottom = True
    params = {
        "width": Param(0.25, 0.6, doc="Y extent of the box (m)"),
        "depth": Param(0.2, 0.45, doc="X extent of the box (m)"),
        "height": Param(0.12, 0.4, doc="height of the box walls (m)"),
        "style": Param(kind="choice", choices=("cardboard", "plastic"), doc="material / build"),
        "wall_thickness": Param(0.003, 0.008, doc="wall thickness (m)"),
        "lid_style": Param(kind="choice", choices=("lift_off", "hinged"), doc="lid type"),
        "lid_height": Param(0.02, 0.05, doc="skirt height of a lift-off lid (m)"),
        "hand_holes": Param(kind="bool", doc="hand holes in the short sides"),
        "corner_radius": Param(0.005, 0.025, doc="plastic: corner rounding in plan (m)"),
    }
    FLANGE = 0.004  # plastic rim flange overhang (m)

    def _plastic(self, p) -> bool:
        return p["style"] == "plastic"

    def _dims(self, p):
        """(top depth, top width, bottom scale, corner radius, overhang of the rim)."""
        D, W = p["depth"], p["width"]
        if self._plastic(p):
            return D, W, 0.94, p["corner_radius"], self.FLANGE
        return D, W, 1.0, 0.0, 0.0

    def _lid_z(self, p) -> float:
        return p["height"] + MOVING_GAP

    def _base(self, p, detail) -> list[Part]:
        D, W, sc, r, fl = self._dims(p)
        H, wt = p["height"], p["wall_thickness"]
        if not detail:
            return [Part(box_between((-D / 2 - fl, -W / 2 - fl, 0.0), (D / 2 + fl, W / 2 + fl, H)),
                         "plastic" if self._plastic(p) else "cardboard")]
        slot = "plastic" if self._plastic(p) else "cardboard"
        plan = rounded_rect_section(D, W, r)
        outer = m3d.Manifold.extrude(plan.scale((sc, sc)), H, 0, 0.0, (1.0 / sc, 1.0 / sc))
        inner_plan = plan.offset(-wt, m3d.JoinType.Round, 2.0, 24)
        cavity = m3d.Manifold.extrude(inner_plan.scale((sc, sc)), H, 0, 0.0,
                                      (1.0 / sc, 1.0 / sc)).translate((0.0, 0.0, wt))
        body = outer - cavity
        if p["hand_holes"]:
            hw, hh = min(0.1, 0.4 * D), min(0.03, 0.2 * H)
            zc = H - 0.03 - hh / 2
            for s in (-1, 1):
                slot_cut = (m3d.CrossSection.square((hw - hh, 0.001), True)
                            .offset(hh / 2, m3d.JoinType.Round, 2.0, 12))  # a stadium hw x hh
                cut = m3d.Manifold.extrude(slot_cut, 0.1, 0, 0.0, (1.0, 1.0)).translate(
                    (0.0, 0.0, -0.05)).rotate((90.0, 0.0, 0.0)).translate((0.0, s * W / 2, zc))
                body = body - cut
        out = [Part(body, slot)]
        if fl:
            ring = (m3d.Manifold.extrude(rounded_rect_section(D + 2 * fl, W + 2 * fl, r + fl), 0.008)
                    - m3d.Manifold.extrude(plan.offset(-0.5 * wt, m3d.JoinType.Round, 2.0, 24), 0.02)
                    .translate((0.0, 0.0, -0.005))).translate((0.0, 0.0, H - 0.008))
            out.append(Part(ring, slot))
        return out

    def _lid(self, p, detail) -> list[Part]:
        D, W, sc, r, fl = self._dims(p)
        wt = p["wall_thickness"]
        z0 = self._lid_z(p)
        slot = "plastic" if self._plastic(p) else "cardboard"
        lt = max(wt, 0.004)
        lift = p["lid_style"] == "lift_off"
        # a lift-off lid's skirt hangs outside the walls (and flange) with MOVING_GAP clearance
        g = MOVING_GAP if lift else 0.0
        Dl, Wl = D + 2 * fl + 2 * (g + wt if lift else 0.0), W + 2 * fl + 2 * (g + wt if lift else 0.0)
        sk = p["lid_height"] if lift else 0.0
        if not detail:
            return [Part(box_between((-Dl / 2, -Wl / 2, z0 - sk), (Dl / 2, Wl / 2, z0 + lt)),
                         slot, "lid")]
        lid_plan = rounded_rect_section(Dl, Wl, r + fl + g + wt if r else 0.0)
        plate = m3d.Manifold.extrude(lid_plan, lt).translate((0.0, 0.0, z0))
        parts = [plate]
        if lift:
            outer = m3d.Manifold.extrude(lid_plan, sk + SMALL_OVERLAP)
            skirt_in = rounded_rect_section(Dl - 2 * wt, Wl - 2 * wt, r + fl + g if r else 0.0)
            inner = m3d.Manifold.extrude(skirt_in, sk + 0.02).translate((0.0, 0.0, -0.01))
            parts.append((outer - inner).translate((0.0, 0.0, z0 - sk)))
        else:  # a raised stacking rim on the flat lid
            rim = (m3d.Manifold.extrude(rounded_rect_section(Dl - 0.01, Wl - 0.01, r), 0.006)
                   - m3d.Manifold.extrude(rounded_rect_section(Dl - 0.02, Wl - 0.02, r), 0.02)
                   .translate((0.0, 0.0, -0.005))).translate((0.0, 0.0, z0 + lt - SMALL_OVERLAP))
            parts.append(rim)
        return [Part(q, slot, "lid") for q in parts]

    def _lid_dims(self, p) -> tuple[float, float, float]:
        D, W, sc, r, fl = self._dims(p)
        wt = p["wall_thickness"]
        lift = p["lid_style"] == "lift_off"
        extra = 2 * (MOVING_GAP + wt) if lift else 0.0
        return D + 2 * fl + extra, W + 2 * fl + extra, max(wt, 0.004)

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        """The box and its lid (on the `lid` link)."""
        return self._base(p, detail) + self._lid(p, detail)

    def joints(self, p: dict[str, Any]) -> list[Joint]:
        """The lid's motion: lifted straight up, or hinged at the back."""
        Dl, Wl, lt = self._lid_dims(p)
        z0 = self._lid_z(p)
        if p["lid_style"] == "lift_off":
            return [Joint("lid_joint", "prismatic", np.array([0.0, 0.0, 1.0]),
                          np.array([0.0, 0.0, z0]), 0.0, 0.25, "lid")]
        return [make_joint("lid_joint", DoorJoint("revolute", np.array([0.0, -1.0, 0.0]),
                                                  np.array([-Dl / 2, 0.0, z0]), "lid"),
                           0.0, math.radians(110))]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The underside, the lid's `top` and the box floor (`interior_0`)."""
        D, W, sc, r, fl = self._dims(p)
        wt = p["wall_thickness"]
        Dl, Wl, lt = self._lid_dims(p)
        z_top = self._lid_z(p) + lt
        rim = 0.0 if p["lid_style"] == "lift_off" else 0.012
        inset = max(r, 0.0) + 0.002
        # the underside: the (scaled) plan 0.5 mm in from its edge
        foot = largest_polygon(rounded_rect_section(D, W, r).scale((sc, sc)).offset(
            -0.0005, m3d.JoinType.Miter, 2.0))
        return [support_polygon("bottom", (0, 0, 0), foot, subpart=Subpart.Bottom, up=False),
                support_rect("top", (0, 0, z_top), Dl / 2 - inset - rim, Wl / 2 - inset - rim),
                support_polygon("interior_0", (0, 0, wt),
                                sg.box(-sc * D / 2 + wt + inset, -sc * W / 2 + wt + inset,
                                       sc * D / 2 - wt - inset, sc * W / 2 - wt - inset),
                                subpart=Subpart.Interior)]
