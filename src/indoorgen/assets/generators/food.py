"""Food: drink cans and food tins, cereal/cracker boxes, chip bags and pouches, and fruit bowls.

Packaged food is closed, so each is a solid (no hidden voids). A fruit bowl is a hollow bowl
(`shapes.vessels.bowl_vessel`) with fruits dropped into it one by one: each fruit is a cluster
of spheres (an orange is one, an apple is one with dimples, a banana is a bent chain of them),
lowered until it touches the bowl's inner surface or a fruit already placed, then sunk 1.5 mm
so that everything unions into one shell.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.mesh import solid_union
from indoorgen.assets.shapes.primitives import Part, bevel_box, box_between, cylinder, lathe, rod
from indoorgen.assets.shapes.surfaces import support_rect
from indoorgen.assets.shapes.vessels import (
    SECTIONS,
    bowl_base_radius,
    bowl_params,
    bowl_vessel,
    cheap_cylinder,
    round_bottom,
    solid_revolve,
)
from indoorgen.model.tags import Semantics as S

#: how far a fruit sinks into what it rests on (the bowl, another fruit), so that they are
#: one shell (m)
FRUIT_SINK = 0.0015


# ------------------------------------------------------------------------------------- cans
@register
class Can(PartsFactory):
    """A drink can (necked-in top with a recessed lid and a pull tab, domed base) or a food tin
    (straight, rolled rims top and bottom, beads around the body, optional paper label)."""

    name = "can"
    tags = frozenset({S.Object, S.SmallObject, S.Food, S.Container, S.Can})
    size_class = "small"
    slots = ["metal", "paper"]
    material_choices = {"metal": {"painted_metal": 3.0, "brushed_steel": 1.0, "chrome": 0.5}}
    params = {
        "kind": Param(kind="choice", choices=("drink", "food"), doc="drink can or food tin"),
        "radius": Param(0.026, 0.05, doc="body radius (drink cans: capped at 34 mm) (m)"),
        "height": Param(0.09, 0.17, doc="height (m)"),
        "beads": Param(0, 5, kind="int", doc="grooves around a food tin's body"),
        "label": Param(kind="bool", doc="paper label around a food tin"),
        "pull_tab": Param(kind="bool", doc="pull tab on the lid (food tins: ring-pull lid)"),
        "lid_recess": Param(0.002, 0.005, doc="depth of the lid below the rim (m)"),
    }

    def _radius(self, p) -> float:
        return min(p["radius"], 0.034) if p["kind"] == "drink" else p["radius"]

    def _outer(self, p) -> list[tuple[float, float]]:
        R, H, rec = self._radius(p), p["height"], p["lid_recess"]
        if p["kind"] == "drink":
            rt = 0.87 * R
            return [(0.0, 0.008), (0.6 * R, 0.0), (0.8 * R, 0.0), (R, 0.012), (R, H - 0.016),
                    (rt, H - 0.004), (rt, H), (rt - 0.0025, H), (rt - 0.0025, H - rec),
                    (0.0, H - rec)]
        rim, body = R + 0.001, R
        pts = [(0.0, 0.0015), (R - 0.004, 0.0015), (R - 0.003, 0.0), (rim, 0.0), (rim, 0.004),
               (body, 0.005)]
        n = int(p["beads"])
        for zb in np.linspace(0.3, 0.7, n) * H if n else []:
            pts += [(body, zb - 0.003), (body - 0.0012, zb - 0.0015), (body - 0.0012, zb + 0.0015),
                    (body, zb + 0.003)]
        pts += [(body, H - 0.005), (rim, H - 0.004), (rim, H), (R - 0.003, H),
                (R - 0.004, H - rec), (0.0, H - rec)]
        return pts

    def _label(self, p) -> tuple[float, float] | None:
        if p["kind"] != "food" or not p["label"]:
            return None
        return 0.12 * p["height"], 0.88 * p["height"]

    def _tab(self, p) -> m3d.Manifold:
        R, H, rec = self._radius(p), p["height"], p["lid_recess"]
        r_lid = (0.87 * R - 0.0025) if p["kind"] == "drink" else R - 0.004
        length = min(0.022, 0.8 * r_lid) if p["kind"] == "drink" else 0.7 * r_lid
        z0 = H - rec - 0.0005
        plate = m3d.Manifold.hull(solid_union([
            cylinder(0.006, 0.0012, (0.0, 0.0, z0), 12),
            cylinder(0.006, 0.0012, (length - 0.006, 0.0, z0), 12)]))
        hole = cylinder(0.0035, 0.01, (length - 0.007, 0.0, z0 - 0.005), 12)
        rivet = cylinder(0.002, 0.0015, (0.001, 0.0, z0), 8)
        return solid_union([plate - hole, rivet])

    def parts(self, p, detail):
        """The can's solids: detailed, or the blocks of its placeholder."""
        R, H = self._radius(p), p["height"]
        lab = self._label(p)
        r_max = R + (0.001 if p["kind"] == "food" else 0.0)
        if not detail:
            return [cheap_cylinder(r_max + (0.0004 if lab else 0.0), 0.0, H, "metal")]
        out = [Part(solid_revolve(self._outer(p)[:-1]), "metal")]
        if lab:
            z0, z1 = lab
            out.append(Part(lathe([(R - 0.0015, z0), (R + 0.0004, z0), (R + 0.0004, z1),
                                   (R - 0.0015, z1)], SECTIONS), "paper"))
        if p["pull_tab"]:
            out.append(Part(self._tab(p), "metal"))
        return out

    def extra_surfaces(self, p):
        """The can's surfaces besides its bounding box's: bottom."""
        R = self._radius(p)
        if p["kind"] == "drink":
            return [round_bottom("bottom", 0.8 * R)]
        return [round_bottom("bottom", R + 0.001)]


# ---------------------------------------------------------------------------------- boxes
@register
class FoodBox(PartsFactory):
    """A cardboard food box (cereal, crackers, pasta, tea): a box with slightly rounded edges,
    standing or lying on its broad face, with a glued top flap along the back edge, a pour
    spout, or a cellophane window in its front; its upper face is a support surface."""

    name = "food_box"
    tags = frozenset({S.Object, S.SmallObject, S.Food, S.FoodBox})
    size_class = "small"
    slots = ["cardboard", "plastic"]
    params = {
        "height": Param(0.1, 0.32, doc="tall edge of the box (m)"),
        "width": Param(0.08, 0.22, doc="broad face width (m)"),
        "depth": Param(0.03, 0.09, doc="thickness between the broad faces (m)"),
        "edge_radius": Param(0.0005, 0.004, doc="edge rounding (m)"),
        "feature": Param(kind="choice", choices=("flap", "spout", "window", "plain"),
                         doc="top flap seam, pour spout, front window or none"),
        "lying": Param(kind="bool", doc="lying on its broad face (else standing upright)"),
    }

    FLAP = 0.0015  # how far the glued flap stands proud (m)

    def _rot(self, p, m: m3d.Manifold) -> m3d.Manifold:
        """Standing boxes are built as is; lying ones tip back onto their broad back face
        (-90 deg about Y: the front +X turns up, the top turns to -X)."""
        if not p["lying"]:
            return m
        return m.rotate((0.0, -90.0, 0.0)).translate((0.0, 0.0, p["depth"] / 2))

    def _features(self, p) -> list[Part]:
        H, W, D, r = p["height"], p["width"], p["depth"], p["edge_radius"]
        f = p["feature"]
        out = []
        if f == "flap":
            fw = min(0.012, 0.3 * D)
            out.append(Part(box_between((-D / 2 + r, -W / 2 + r, H - 0.001),
                                        (-D / 2 + r + fw, W / 2 - r, H + self.FLAP)),
                            "cardboard"))
        elif f == "spout":
            s = min(0.025, 0.4 * D)
            out.append(Part(box_between((-s / 2, W / 2 - r - 0.004 - 1.6 * s, H - 0.001),
                                        (s / 2, W / 2 - r - 0.004, H + 0.002)), "plastic"))
        return out

    def _window(self, p) -> tuple[m3d.Manifold, m3d.Manifold]:
        """(the recess cut in the front, the cellophane pane filling it to 0.5 mm below)."""
        H, W, D = p["height"], p["width"], p["depth"]
        y0, y1, z0, z1 = -0.3 * W, 0.3 * W, 0.35 * H, 0.75 * H
        cut = box_between((D / 2 - 0.0015, y0, z0), (D / 2 + 0.01, y1, z1))
        pane = box_between((D / 2 - 0.0016, y0 - 0.0005, z0 - 0.0005),
                           (D / 2 - 0.0005, y1 + 0.0005, z1 + 0.0005))
        return cut, pane

    def parts(self, p, detail):
        """The food box's solids: detailed, or the blocks of its placeholder."""
        H, W, D, r = p["height"], p["width"], p["depth"], p["edge_radius"]
        if not detail:
            top = H + (self.FLAP if p["feature"] == "flap" else 0.002 if p["feature"] == "spout"
                       else 0.0)
            return [Part(self._rot(p, box_between((-D / 2, -W / 2, 0.0), (D / 2, W / 2, top))),
                         "cardboard")]
        body = bevel_box((D, W, H), (0, 0, H / 2), r, 1)
        out = [Part(body, "cardboard")] + self._features(p)
        if p["feature"] == "window":
            cut, pane = self._window(p)
            out = [Part(body - cut, "cardboard"), Part(pane, "plastic")]
        return [Part(self._rot(p, q.solid), q.slot) for q in out]

    def extra_surfaces(self, p):
        """The food box's surfaces besides its bounding box's: top."""
        H, W, D, r = p["height"], p["width"], p["depth"], p["edge_radius"]
        m, f = r + 0.001, p["feature"]
        if p["lying"]:  # the front (+X) faces up at z = D; the old top points to -X
            x0, x1 = -H + m, -m
            if f == "window":  # the strip between the window and the old bottom end
                x0 = -0.35 * H + 0.001
            return [support_rect("top", ((x0 + x1) / 2, 0.0, D), (x1 - x0) / 2, W / 2 - m)]
        x0 = -D / 2 + m + (min(0.012, 0.3 * D) + 0.001 if f == "flap" else 0.0)
        y1 = W / 2 - m
        if f == "spout":
            y1 = W / 2 - r - 0.004 - 1.6 * min(0.025, 0.4 * D) - 0.002
        x1, y0 = D / 2 - m, -W / 2 + m
        return [support_rect("top", ((x0 + x1) / 2, (y0 + y1) / 2, H), (x1 - x0) / 2,
                             (y1 - y0) / 2)]


# ----------------------------------------------------------------------------------- bags
def _ellipse_ring(center: np.ndarray, ax_u: np.ndarray, ax_v: np.ndarray, a: float,
                  c_pos: float, c_neg: float, n: int = 16) -> np.ndarray:
    """n points of a half-ellipse pair about `center` in the plane of unit axes u, v: semi-axis
    `a` along u, `c_pos` along +v and `c_neg` along -v (a squashed pillow cross-section)."""
    phi = np.arange(n) * 2 * math.pi / n
    s = np.sin(phi)
    c = np.where(s >= 0, c_pos, c_neg)
    return center + np.outer(a * np.cos(phi), ax_u) + np.outer(c * s, ax_v)


@register
class FoodBag(PartsFactory):
    """A bag of food: a chip bag lying flat (a pillow squashed on the table, with sealed ends),
    a stand-up pouch (oval gusset base narrowing to a top seal) or a paper brick bag (flour,
    sugar, coffee: a block with a pinched, sealed top). Seals may be crimped."""

    name = "food_bag"
    tags = frozenset({S.Object, S.SmallObject, S.Food, S.FoodBag})
    size_class = "small"
    slots = ["plastic", "paper"]
    material_choices = {"plastic": {"glossy_plastic": 3.0, "matte_plastic": 1.0}}
    params = {
        "style": Param(kind="choice", choices=("pillow", "stand_up", "brick"), doc="bag type"),
        "length": Param(0.15, 0.35, doc="pillow: length including seals; others: height (m)"),
        "width": Param(0.1, 0.25, doc="width across the seals (m)"),
        "thickness": Param(0.03, 0.1, doc="thickest extent across the faces (m)"),
        "seal_width": Param(0.008, 0.025, doc="width of the sealed strips (m)"),
        "crimped": Param(kind="bool", doc="ridged (crimped) seals"),
        "squash": Param(0.2, 0.6, doc="pillow: flattening of the resting side; pouch: top "
                        "narrowing; brick: height of the pinched top / width"),
    }

    SEAL_T = 0.0015  # seal strip thickness (m)

    def _slot(self, p) -> str:
        return "paper" if p["style"] == "brick" else "plastic"

    def _extent(self, p) -> tuple[float, float, float]:
        """(X, Y, Z) size of the bag's bounding box."""
        L, W, T = p["length"], p["width"], p["thickness"]
        T = min(T, 0.6 * W)
        if p["style"] == "pillow":
            return L, W, 0.5 * T * (2 - p["squash"]) - 0.002
        return T, W, L

    def _ridges(self, x0: float, x1: float, W: float, z: float, along_x: bool
                ) -> list[m3d.Manifold]:
        """Crimp ridges across a seal strip spanning x0..x1 (or z0..z1 if not along_x)."""
        out = []
        for q in np.linspace(x0, x1, 6)[1:-1]:
            if along_x:
                out.append(box_between((q - 0.0006, -W / 2, z - self.SEAL_T), (q + 0.0006, W / 2,
                                                                               z + self.SEAL_T)))
            else:
                out.append(box_between((-self.SEAL_T, -W / 2, q - 0.0006), (self.SEAL_T, W / 2,
                                                                            q + 0.0006)))
        return out

    def _pillow(self, p) -> list[m3d.Manifold]:
        L, W, _ = p["length"], p["width"], p["thickness"]
        T = min(p["thickness"], 0.6 * W)
        s = p["seal_width"]
        lb = L - 2 * s
        c_up, c_low = 0.5 * T, 0.5 * T * (1 - p["squash"])
        zc = c_low - 0.002  # sunk 2 mm below the table, then trimmed flat
        pts = []
        for u in np.linspace(-1.0, 1.0, 11):
            k = max((1 - u * u) ** 0.6, 0.03)
            a = 0.5 * W * (1 - 0.12 * u ** 4)
            pts.append(_ellipse_ring(np.array([0.5 * lb * u, 0.0, zc]), np.array([0, 1.0, 0]),
                                     np.array([0, 0, 1.0]), a, c_up * k, c_low * k))
        body = m3d.Manifold.hull_points(np.vstack(pts)).trim_by_plane((0.0, 0.0, 1.0), 0.0)
        out = [body]
        for sx in (-1, 1):
            x0, x1 = sorted((sx * (lb / 2 - 0.003), sx * L / 2))
            out.append(box_between((x0, -W / 2, zc - self.SEAL_T / 2), (x1, W / 2,
                                                                        zc + self.SEAL_T / 2)))
            if p["crimped"]:
                out += self._ridges(x0 + 0.003 * (sx < 0), x1 - 0.003 * (sx > 0), W, zc, True)
        return out

    def _pouch(self, p) -> list[m3d.Manifold]:
        Hh, W, s = p["length"], p["width"], p["seal_width"]
        T = min(p["thickness"], 0.6 * W)
        hb = Hh - s
        pts = []
        for u in np.linspace(0.0, 1.0, 10):
            k = max(1 - u ** (1.5 + 2 * p["squash"]), 0.02)
            a = 0.5 * W * (0.92 + 0.08 * math.sin(math.pi * min(u * 1.3, 1.0)))
            pts.append(_ellipse_ring(np.array([0.0, 0.0, hb * u]), np.array([0, 1.0, 0]),
                                     np.array([1.0, 0, 0]), a, 0.5 * T * k, 0.5 * T * k))
        out = [m3d.Manifold.hull_points(np.vstack(pts)),
               box_between((-self.SEAL_T / 2, -W / 2, hb - 0.003), (self.SEAL_T / 2, W / 2, Hh))]
        if p["crimped"]:
            out += self._ridges(hb, Hh, W, 0.0, False)
        return out

    def _brick(self, p) -> list[m3d.Manifold]:
        Hh, W, s = p["length"], p["width"], p["seal_width"]
        T = min(p["thickness"], 0.6 * W)
        gable = min(p["squash"] * T, 0.3 * Hh)
        hb = Hh - s - gable
        body = bevel_box((T, W, hb), (0, 0, hb / 2), min(0.008, 0.2 * T), 2)
        top = m3d.Manifold.hull(solid_union([
            box_between((-T / 2 + 0.002, -W / 2 + 0.002, hb - 0.004),
                        (T / 2 - 0.002, W / 2 - 0.002, hb - 0.003)),
            box_between((-0.002, -W / 2 + 0.001, hb + gable - 0.001), (0.002, W / 2 - 0.001,
                                                                      hb + gable))]))
        out = [body, top, box_between((-self.SEAL_T / 2, -W / 2 + 0.001, hb + gable - 0.003),
                                      (self.SEAL_T / 2, W / 2 - 0.001, Hh))]
        if p["crimped"]:
            out += self._ridges(hb + gable, Hh, W - 0.002, 0.0, False)
        return out

    def parts(self, p, detail):
        """The food bag's solids: detailed, or the blocks of its placeholder."""
        slot = self._slot(p)
        X, Y, Z = self._extent(p)
        if not detail:
            x0 = -X / 2
            return [Part(box_between((x0, -Y / 2, 0.0), (x0 + X, Y / 2, Z)), slot)]
        build = {"pillow": self._pillow, "stand_up": self._pouch, "brick": self._brick}
        return [Part(m, slot) for m in build[p["style"]](p)]


# ------------------------------------------------------------------------------ fruit bowls
FRUIT_MIXES = {"mixed": {"apple": 3, "orange": 3, "banana": 2, "pear": 1, "lemon": 1},
               "apples": {"apple": 5, "pear": 1},
               "citrus": {"orange": 3, "lemon": 2},
               "tropical": {"banana": 2, "orange": 2, "apple": 1}}


#: radius of the largest ball inside a Manifold.sphere of radius 1 with 12 / 20 segments
_IN12, _IN20 = 0.92, 0.966


@dataclass(frozen=True)
class _Fruit:
    """A fruit about its origin: contact spheres (k, 4: x, y, z, r) inscribed in its solid,
    how far the solid reaches above the origin and sideways from it, and its solids."""

    contact: np.ndarray
    top: float
    reach: float
    solids: Callable[[np.ndarray], list[m3d.Manifold]]


def _at(m: m3d.Manifold, o: np.ndarray) -> m3d.Manifold:
    return m.translate(tuple(float(c) for c in o))


def _orange(r: float) -> _Fruit:
    return _Fruit(np.array([[0, 0, 0, _IN20 * r]]), r, r,
                  lambda o: [_at(m3d.Manifold.sphere(r, 20), o)])


def _apple(r: float, rng: np.random.Generator) -> _Fruit:
    """A lathed apple, a little wider above its middle, with a dimple and a stem on top."""
    dimple = 0.0012
    phi = np.linspace(0.0, math.pi, 11)
    rho = r * np.sin(phi) * (1 + 0.04 * np.sin(phi - 0.3))
    z = -r * np.cos(phi) - dimple * np.clip((phi - 0.8 * math.pi) / (0.2 * math.pi), 0, 1) ** 2
    prof = list(zip(rho.tolist(), z.tolist(), strict=True))
    prof[0], prof[-1] = (0.0, -r), (0.0, r - dimple)
    tilt = rng.uniform(-0.25, 0.25, 2) * r
    k = math.cos(math.pi / 16) * math.cos(math.pi / 20)

    def solids(o):
        o = np.asarray(o, float)
        stem = rod(o + (0, 0, r - 0.004), o + (tilt[0], tilt[1], r + 0.011), 0.0013, 6)
        return [_at(lathe(prof, 16), o), stem]
    return _Fruit(np.array([[0, 0, 0, k * r - dimple]]), r + 0.0125, r * 1.04, solids)


def _lemon(r: float, yaw: float) -> _Fruit:
    """An ellipsoid 1.3x longer along a horizontal axis at angle `yaw`."""
    ax = np.array([math.cos(yaw), math.sin(yaw), 0.0])
    contact = np.array([[0, 0, 0, _IN20 * r]] + [[*(s * 0.3 * r * ax), 0.92 * _IN20 * r]
                                                 for s in (-1, 1)])
    return _Fruit(contact, r, 1.3 * r, lambda o: [_at(m3d.Manifold.sphere(1.0, 20).scale(
        (1.3 * r, r, r)).rotate((0.0, 0.0, math.degrees(yaw))), o)])


def _pear(r: float) -> _Fruit:
    """The hull of a round bottom and a narrower top, with a stem."""
    contact = np.array([[0, 0, 0, _IN20 * r], [0, 0, r, 0.95 * 0.6 * r]])

    def solids(o):
        body = m3d.Manifold.batch_hull([m3d.Manifold.sphere(r, 20),
                                        m3d.Manifold.sphere(0.6 * r, 16).translate((0, 0, r))])
        stem = cylinder(0.0015, 0.014, tuple(np.asarray(o) + (0, 0, 1.5 * r - 0.002)), 8)
        return [_at(body, o), stem]
    return _Fruit(contact, 1.5 * r + 0.012, r, solids)


def _banana(scale: float, rng: np.random.Generator) -> _Fruit:
    """A ten-sided tube bent along a horizontal arc, tips turned up, tapering to a stalk: an
    extrusion warped in one vectorised pass (no booleans)."""
    arc, half = rng.uniform(0.1, 0.13) * scale, rng.uniform(0.55, 0.7)
    yaw = rng.uniform(0, 2 * math.pi)
    r0, lift = 0.017 * scale, 0.012 * scale

    def radius(t):
        return np.where(t < 0.92, r0 * np.maximum(0.35, 1 - 0.6 * (2 * t - 1) ** 2), 0.3 * r0)

    def centre(t):
        th = (2 * t - 1) * half
        sag = arc * (1 - math.sin(half) / half)  # centres the arc's mean on the origin
        return np.stack([arc * np.sin(th), arc * (1 - np.cos(th)) - sag,
                         lift * (2 * t - 1) ** 2], axis=-1), th

    c, s = math.cos(yaw), math.sin(yaw)
    rot = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])

    def warp(v):
        t = v[:, 2]
        cen, th = centre(t)
        nrm = np.stack([-np.sin(th), np.cos(th), np.zeros_like(th)], axis=-1)
        rad = radius(t)[:, None]
        out = cen + rad * (v[:, :1] * nrm + v[:, 1:2] * np.array([0, 0, 1.0]))
        return out @ rot.T

    tc = np.linspace(0.04, 0.9, 9)
    cen, _ = centre(tc)
    contact = np.c_[cen @ rot.T, 0.9 * radius(tc)]
    levels = np.linspace(0.0, 1.0, 18)  # the extrusion's 16 divisions and two ends
    ends, _ = centre(levels)
    reach = float((np.linalg.norm((ends @ rot.T)[:, :2], axis=1) + radius(levels)).max())
    top = float((ends[:, 2] + radius(levels)).max())
    return _Fruit(contact, top, reach, lambda o: [_at(m3d.Manifold.extrude(
        m3d.CrossSection.circle(1.0, 10), 1.0, 16).warp_batch(warp), o)])


def _make_fruit(kind: str, scale: float, rng: np.random.Generator) -> _Fruit:
    if kind == "orange":
        return _orange(rng.uniform(0.036, 0.042) * scale)
    if kind == "apple":
        return _apple(rng.uniform(0.034, 0.041) * scale, rng)
    if kind == "lemon":
        return _lemon(rng.uniform(0.027, 0.031) * scale, rng.uniform(0, 2 * math.pi))
    if kind == "pear":
        return _pear(rng.uniform(0.03, 0.036) * scale)
    return _banana(scale, rng)


def _drop(spheres: np.ndarray, xy: np.ndarray, surf: np.ndarray, placed: np.ndarray
          ) -> np.ndarray:
    """Heights of a fruit's origin when its contact spheres (k, 4), moved to each of the
    positions `xy` (m, 2), are lowered until they touch the bowl's inner surface `surf` ((r, z)
    points of its meridian) or a placed sphere (n, 4)."""
    cx = spheres[None, :, 0] + xy[:, 0:1]                          # (m, k)
    cy = spheres[None, :, 1] + xy[:, 1:2]
    r = spheres[None, :, 3, None]                                  # (1, k, 1)
    dr = surf[:, 0] - np.sqrt(cx * cx + cy * cy)[..., None]        # (m, k, S)
    h2 = r * r - dr * dr
    need = np.where(h2 > 0, surf[:, 1] + np.sqrt(np.maximum(h2, 0.0)), -np.inf).max(axis=2)
    if len(placed):
        dx, dy = cx[..., None] - placed[:, 0], cy[..., None] - placed[:, 1]
        rr = r + placed[:, 3]
        h2 = rr * rr - dx * dx - dy * dy
        top = np.where(h2 > 0, placed[:, 2] + np.sqrt(np.maximum(h2, 0.0)), -np.inf)
        need = np.maximum(need, top.max(axis=2))
    return (need - spheres[None, :, 2]).max(axis=1)


def _lowest(spheres: np.ndarray, xy: np.ndarray, surf: np.ndarray, placed: np.ndarray
            ) -> tuple[np.ndarray, float]:
    """The position among `xy` (m, 2) where a fruit's contact spheres come to rest lowest
    (`_drop`), and the height of its origin there."""
    z = _drop(spheres, xy, surf, placed)
    i = int(np.argmin(z))
    return xy[i], z[i]


def _inner_surface(p: dict[str, Any]) -> tuple[np.ndarray, float]:
    """(r, z) points at most 4 mm apart along a bowl's inner surface, and the opening's
    radius."""
    v = bowl_vessel(p)
    poly = max((np.asarray(q, float) for q in v.hollow.to_polygons()), key=len)
    a, b = poly, np.roll(poly, -1, axis=0)
    top = poly[:, 1].max()
    # the axis and the open top are not surfaces
    on_axis = (a[:, 0] < 1e-9) & (b[:, 0] < 1e-9)
    on_top = (a[:, 1] >= top - 1e-9) & (b[:, 1] >= top - 1e-9)
    a, b = a[~(on_axis | on_top)], b[~(on_axis | on_top)]
    n = np.maximum(2, (np.linalg.norm(b - a, axis=1) / 0.004).astype(int) + 1)  # per segment
    seg = np.repeat(np.arange(len(a)), n)
    u = (np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)) / np.repeat(n - 1, n)
    pts = a[seg] + u[:, None] * (b[seg] - a[seg])
    return pts, p["radius"] - p["wall_thickness"]


@register
class FruitBowl(PartsFactory):
    """A fruit bowl: a wide bowl (the bowl family's shapes, foot ring and rim) holding 3-7
    fruits (apples with stems, oranges, lemons, pears, bananas) settled into a pile, the bowl
    and fruits one shell. `layout` picks the fruits and their arrangement."""

    name = "fruit_bowl"
    tags = frozenset({S.Object, S.SmallObject, S.Tableware, S.Container, S.Bowl, S.Food,
                      S.FruitBowl})
    size_class = "small"
    slots = ["ceramic", "food"]
    params = {**bowl_params(0.1, 0.16, 0.05, 0.1),
              "n_fruits": Param(3, 7, kind="int", doc="number of fruits"),
              "fruit_mix": Param(kind="choice", choices=tuple(FRUIT_MIXES), doc="kinds of fruit"),
              "fruit_scale": Param(0.85, 1.15, doc="fruit size factor"),
              "layout": Param(0, 999, kind="int", doc="which fruits go where (a variant number)")}

    def bottom_is_solid(self, params):
        """Whether the bowl rests on a flat base, not on a foot ring."""
        return not self.resolve(params)["foot_ring"]

    def _fruits(self, p) -> list[tuple[_Fruit, np.ndarray]]:
        """The fruits and where their origins go, settled one by one: each is dropped at the
        lowest-resting of 8 random spots, then rolls downhill to the lowest resting spot on two
        rings around it (2 and 0.8 cm away), so none balances on top of another."""
        rng = np.random.default_rng(int(p["layout"]))
        surf, opening = _inner_surface(p)
        mix = FRUIT_MIXES[p["fruit_mix"]]
        kinds, w = list(mix), np.array(list(mix.values()), float)
        ring = np.exp(1j * np.linspace(0, 2 * math.pi, 8, endpoint=False))
        ring = np.concatenate([0.02 * ring, 0.008 * ring * np.exp(1j * math.pi / 8)])
        ring = np.stack([ring.real, ring.imag], axis=1)
        placed = np.zeros((0, 4))
        out = []
        for _ in range(int(p["n_fruits"])):
            kind = kinds[int(np.searchsorted(np.cumsum(w) / w.sum(), rng.random()))]
            fruit = _make_fruit(kind, p["fruit_scale"], rng)
            room = opening - 0.003 - fruit.reach
            if room <= 0:
                continue
            rho, th = room * np.sqrt(rng.random(8)), rng.uniform(0, 2 * math.pi, 8)
            dropped = np.stack([rho * np.cos(th), rho * np.sin(th)], axis=1)
            landed, _ = _lowest(fruit.contact, dropped, surf, placed)
            # then it rolls to the lowest spot on the rings around where it landed (or stays)
            around = landed[None, :] + ring
            r = np.linalg.norm(around, axis=1, keepdims=True)
            around = around * np.minimum(1.0, room / np.maximum(r, 1e-9))
            best, z_best = _lowest(fruit.contact, np.vstack([landed, around]), surf, placed)
            off = np.array([best[0], best[1], z_best - FRUIT_SINK])
            placed = np.vstack([placed, fruit.contact + np.append(off, 0.0)])
            out.append((fruit, off))
        return out

    def parts(self, p, detail):
        """The fruit bowl's solids: detailed, or the blocks of its placeholder."""
        fruits = self._fruits(p)
        if not detail:
            top = max([p["height"]] + [o[2] + f.top for f, o in fruits])
            return [cheap_cylinder(p["radius"] + p["rim_flare"], 0.0, top, "ceramic")]
        return [Part(bowl_vessel(p).shell, "ceramic")] + [
            Part(s, "food") for f, o in fruits for s in f.solids(o)]

    def extra_surfaces(self, p):
        """The fruit bowl's surfaces besides its bounding box's: bottom (no interior: fruit fill it)."""
        return [round_bottom("bottom", bowl_base_radius(p))]
