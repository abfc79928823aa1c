"""Plants: a floor plant and a tabletop plant in lathed pots, with procedural foliage.

Foliage is built from swept solids (`loft`): every leaf is a thin chevron-section blade swept
along a drooping arc, every stem a polygonal tube along the same kind of arc. Leaves start on
their stem's axis (or inside the rosette's crown), so the union of pot, soil, stems and leaves is
one watertight shell. The leaf skeletons are computed for all leaves at once with numpy; the
placeholder encloses them in one box computed from the very same points (so its bounding box is
exact and cheap).

`loft` lives in `assets.shapes.sweeps` (woven baskets use it too).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import manifold3d as m3d
import numpy as np

from indoorgen.assets.parts_factory import PartsFactory
from indoorgen.assets.protocol import Param, Surface
from indoorgen.assets.registry import register
from indoorgen.assets.shapes.primitives import Part, box_between, circle_polygon, cylinder, lathe
from indoorgen.assets.shapes.surfaces import support_polygon
from indoorgen.assets.shapes.sweeps import loft
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart

GOLDEN_ANGLE = math.pi * (3.0 - math.sqrt(5.0))
#: how far (radians) a leaf's direction turns downwards over its length at droop = 1
DROOP_TURN = 2.2
#: radius of the crown (short trunk) a rosette's leaves grow from (m)
CROWN_RADIUS = 0.018
Z = np.array([0.0, 0.0, 1.0])


# ------------------------------------------------------------------------------ swept solids


def arc_paths(base: np.ndarray, azimuth: np.ndarray, elevation: np.ndarray, length: np.ndarray,
              droop: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Planar drooping arcs, one per row of the (L,) inputs: each starts at `base` (L, 3) heading
    at `elevation` (radians above horizontal) towards `azimuth`, and turns down by
    droop * DROOP_TURN radians over its `length`. Returns points (L, n+1, 3), unit tangents
    (L, n+1, 3), the horizontal side vector (L, 3) and the local up normal (L, n+1, 3)."""
    s = np.linspace(0.0, 1.0, n + 1)
    ang = elevation[:, None] - droop[:, None] * DROOP_TURN * s[None, :] ** 1.5
    h = np.stack([np.cos(azimuth), np.sin(azimuth), np.zeros_like(azimuth)], axis=1)
    tang = np.cos(ang)[..., None] * h[:, None, :] + np.sin(ang)[..., None] * Z
    mid = 0.5 * (tang[:, :-1] + tang[:, 1:])
    steps = (length / n)[:, None, None] * mid
    pts = base[:, None, :] + np.concatenate([np.zeros((len(base), 1, 3)),
                                             np.cumsum(steps, axis=1)], axis=1)
    side = np.stack([-np.sin(azimuth), np.cos(azimuth), np.zeros_like(azimuth)], axis=1)
    normal = np.cross(tang, side[:, None, :])
    return pts, tang, side, normal


def stem_rings(pts: np.ndarray, side: np.ndarray, normal: np.ndarray, radius: np.ndarray,
               sections: int = 8) -> np.ndarray:
    """Circular rings (L, n, sections, 3) around planar paths `pts` (L, n, 3) whose cross
    sections are spanned by `side` (L, 3) and `normal` (L, n, 3); `radius` is (L, n)."""
    a = np.arange(sections) * 2 * math.pi / sections
    c, s = np.cos(a), np.sin(a)
    r = radius[..., None, None]
    return pts[:, :, None, :] + r * (c[:, None] * side[:, None, None, :]
                                     + s[:, None] * normal[:, :, None, :])


LEAF_SHAPES = ("lanceolate", "ovate", "round", "strap", "succulent")


def leaf_width_profile(shape: str, s: np.ndarray) -> np.ndarray:
    """Blade width / maximum width at fractions `s` of the leaf's length (0 = base)."""
    if shape == "strap":
        return np.clip(np.sin(np.pi * np.clip(s, 0, 1)) ** 0.25, 0.0, 1.0)
    if shape == "ovate":
        return np.sin(np.pi * np.clip(s, 0, 1) ** 0.7) ** 0.8
    if shape == "round":  # a petiole, then a round blade
        u = np.clip((s - 0.35) / 0.65, 0.0, 1.0)
        return np.where(s < 0.35, 0.0, np.sqrt(np.clip(1 - (2 * u - 1) ** 2, 0, 1)))
    if shape == "succulent":
        return np.sin(np.pi * (0.2 + 0.8 * np.clip(s, 0, 1))) ** 0.5
    return np.sin(np.pi * np.clip(s, 0, 1)) ** 0.6  # lanceolate


@dataclass
class Leaves:
    """A batch of leaves (arrays over leaves): where they start, where they head, their size."""

    base: np.ndarray
    azimuth: np.ndarray
    elevation: np.ndarray
    length: np.ndarray
    width: np.ndarray
    droop: np.ndarray
    shape: str = "lanceolate"
    thickness: float = 0.0016
    fold: float = 0.12  # V-fold depth along the midrib / width
    petiole: float = 0.004  # width of the blade's base (m)

    def rings(self, n: int = 6) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Chevron rings (L, n, 4, 3), start apexes (L, 3) and tip points (L, 3)."""
        pts, tang, side, normal = arc_paths(self.base, self.azimuth, self.elevation,
                                            self.length, self.droop, n)
        s = np.linspace(0.0, 1.0, n + 1)[:n]
        w = np.maximum(self.width[:, None] * leaf_width_profile(self.shape, s)[None, :],
                       self.petiole)
        if self.shape == "succulent":
            t = 0.45 * w + 0.001
            f = 0.05 * w
        else:
            t = np.full_like(w, self.thickness)
            f = self.fold * w
        c, nr = pts[:, :n], normal[:, :n]
        sd = side[:, None, :]
        ring = np.stack([c - 0.5 * w[..., None] * sd - f[..., None] * nr,
                         c + 0.5 * t[..., None] * nr,
                         c + 0.5 * w[..., None] * sd - f[..., None] * nr,
                         c - 0.5 * t[..., None] * nr], axis=2)
        start = pts[:, 0] - tang[:, 0] * 0.5 * self.petiole
        return ring, start, pts[:, n]

    def solids(self, n: int = 6) -> list[m3d.Manifold]:
        """One lofted solid per leaf."""
        ring, start, tip = self.rings(n)
        return [loft(ring[i], start[i], tip[i]) for i in range(len(ring))]

    def points(self, n: int = 6) -> np.ndarray:
        """Every vertex of every leaf (for the placeholder's bounding box)."""
        ring, start, tip = self.rings(n)
        return np.vstack([ring.reshape(-1, 3), start, tip])

    def lift_above(self, z_min: float, n: int = 6) -> None:
        """Reduce the droop (then the elevation) of leaves that would dip below `z_min`."""
        for _ in range(8):
            low = self.points_per_leaf(n).min(axis=1) < z_min
            if not low.any():
                return
            self.droop = np.where(low, self.droop * 0.6, self.droop)
            self.elevation = np.where(low & (self.droop < 0.05),
                                      np.minimum(self.elevation + 0.15, 1.5), self.elevation)

    def points_per_leaf(self, n: int = 6) -> np.ndarray:
        """The z of each leaf's vertices, one row per leaf."""
        ring, start, tip = self.rings(n)
        return np.concatenate([ring.reshape(len(ring), -1, 3), start[:, None], tip[:, None]],
                              axis=1)[..., 2]


def stem_solids(base: np.ndarray, azimuth: np.ndarray, elevation: np.ndarray,
                length: np.ndarray, droop: np.ndarray, r0: np.ndarray, r1: np.ndarray,
                n: int = 6, sections: int = 8, build: bool = True
                ) -> tuple[list[m3d.Manifold], np.ndarray]:
    """Tapered tubes along drooping arcs (radius r0 at the base to r1 at the tip). Returns the
    solids (none unless `build`) and all their vertices (for placeholders)."""
    pts, tang, side, normal = arc_paths(base, azimuth, elevation, length, droop, n)
    s = np.linspace(0.0, 1.0, n + 1)
    rad = r0[:, None] + (r1 - r0)[:, None] * s[None, :]
    rings = stem_rings(pts, side, normal, rad, sections)
    starts = pts[:, 0] - tang[:, 0] * r0[:, None] * 0.5
    ends = pts[:, -1] + tang[:, -1] * r1[:, None] * 0.8
    solids = [loft(rings[i], starts[i], ends[i]) for i in range(len(base))] if build else []
    return solids, np.vstack([rings.reshape(-1, 3), starts, ends])


def stem_points(base: np.ndarray, azimuth: np.ndarray, elevation: np.ndarray, length: np.ndarray,
                droop: np.ndarray, u: np.ndarray, n: int = 6
                ) -> tuple[np.ndarray, np.ndarray]:
    """Points (and tangents) at fractions `u` (L, m) along the stems' arcs, interpolated on the
    same polyline the stem tubes are swept along (so a point is on the stem's axis)."""
    pts, tang, _, _ = arc_paths(base, azimuth, elevation, length, droop, n)
    x = u * n
    i = np.clip(np.floor(x).astype(int), 0, n - 1)
    t = (x - i)[..., None]
    rows = np.arange(len(base))[:, None]
    p = pts[rows, i] * (1 - t) + pts[rows, i + 1] * t
    d = tang[rows, i] * (1 - t) + tang[rows, i + 1] * t
    return p, d / np.linalg.norm(d, axis=-1, keepdims=True)


def _leaf_parts(leaves: Leaves, build: bool, n: int = 6) -> list[Part]:
    """The leaves as foliage parts (none when only the placeholder is wanted)."""
    return [Part(s, "foliage") for s in leaves.solids(n)] if build else []


# ------------------------------------------------------------------------------------- pots
POT_SHAPES = ("cylinder", "taper", "bowl", "rimmed")


def pot_radius(p: dict[str, Any], t: float) -> float:
    """Outer pot radius at fraction t of the pot height (0 = base, 1 = rim)."""
    R, shape = p["pot_radius"], p["pot_shape"]
    if shape == "cylinder":
        return R * (0.94 + 0.06 * min(t / 0.06, 1.0))
    if shape == "bowl":
        return R * (0.55 + 0.45 * math.sin(0.5 * math.pi * min(t / 0.7, 1.0)))
    if shape == "rimmed":  # a taper, then a thick rolled rim band
        return R * (0.74 + 0.12 * t) if t < 0.8 else R * (0.836 + 0.164 * min((t - 0.8) / 0.05, 1.0))
    return R * (0.72 + 0.28 * t)  # taper


def pot_layout(p: dict[str, Any]) -> tuple[float, float, float, float]:
    """(pot height, wall thickness, soil top height, inner radius at the soil top)."""
    H = p["pot_height"]
    w = max(0.006, 0.07 * p["pot_radius"])
    zs = H - max(0.012, 0.1 * H)
    return H, w, zs, pot_radius(p, zs / H) - w


def pot_parts(p: dict[str, Any], detail: bool, z0: float = 0.0) -> list[Part]:
    """A lathed pot standing at z0, hollow down to the soil, and a soil disc whose top is at
    the pot's `soil top`; or (not detail) the circumscribed cylinder containing both."""
    H, w, zs, _ = pot_layout(p)
    t_floor = (zs - 0.01) / H
    ts = np.union1d(np.linspace(0.0, 1.0, 14), [t_floor])
    rs = np.array([pot_radius(p, t) for t in ts])
    if not detail:
        return [Part(cylinder(float(rs.max()), H, (0, 0, z0), 16, circumscribed=True), "ceramic")]
    outer = [(0.0, z0)] + [(float(r), z0 + float(t) * H) for r, t in zip(rs, ts, strict=True)]
    # the inner wall at the same heights as the outer one: a constant wall thickness
    inner = [(float(r) - w, z0 + float(t) * H) for r, t in zip(rs[::-1], ts[::-1], strict=True)
             if t >= t_floor]
    pot = lathe(outer + inner + [(0.0, z0 + zs - 0.01)], 48)
    # the soil follows the inner wall 0.8 mm into it, from just under the recess floor to 2 mm
    # above the nominal soil top (the same piecewise-linear profile: it never pokes outside)
    t_lo, t_hi = (zs - 0.011) / H, (zs + 0.002) / H
    tz = np.union1d(ts[(ts > t_lo) & (ts < t_hi)], [t_lo, t_hi])
    rz = np.interp(tz, ts, rs) - w + 0.0008
    soil = lathe([(0.0, z0 + t_lo * H)] + [(float(r), z0 + float(t) * H) for r, t in zip(rz, tz, strict=True)]
                 + [(0.0, z0 + t_hi * H)], 48)
    return [Part(pot, "ceramic"), Part(soil, "soil")]


def pot_foot_radius(p: dict[str, Any]) -> float:
    """The pot's radius at its base (what it stands on)."""
    return pot_radius(p, 0.0)


# -------------------------------------------------------------------------------- foliage
def rosette(p: dict[str, Any], z_soil: float, shape: str, height: float,
            length_outer: float, width: float) -> Leaves:
    """Leaves from one crown on the soil, outer (old) ones spread low, inner ones upright."""
    n = int(p["n_leaves"])
    k = np.arange(n)
    frac = k / max(n - 1, 1)  # 0 = outermost
    spread = p["spread"]
    e_out = math.radians(65 - 50 * spread)
    elev = e_out + (math.radians(86) - e_out) * frac ** 1.3
    length = length_outer + (height - length_outer) * frac
    az = k * GOLDEN_ANGLE
    # bases just inside the crown's surface, staggered upwards: leaves meet the crown, not
    # each other (many solids crossing at one point make the union slow)
    rb = CROWN_RADIUS - 0.004
    base = np.c_[rb * np.cos(az), rb * np.sin(az), z_soil + 0.004 + 0.02 * frac]
    droop = p["droop"] * (1.0 - 0.7 * frac)
    return Leaves(base, az, elev, length, np.full(n, width) * (0.75 + 0.25 * (1 - frac)),
                  droop, shape)


# ----------------------------------------------------------------------------- generators
class _PlantBase(PartsFactory):
    """Shared pot + foliage machinery; subclasses say how the foliage grows."""

    slots = ["ceramic", "soil", "foliage", "wood"]
    solid_bottom = True

    def foliage(self, p: dict[str, Any], z_soil: float, r_in: float, build: bool
                ) -> tuple[list[Part], np.ndarray]:
        """The plant's parts (none unless `build`) and all their vertices."""
        raise NotImplementedError

    def _z0(self, p) -> float:
        return 0.0

    def _foliage(self, p, build: bool):
        H, _, zs, r_in = pot_layout(p)
        return self.foliage(p, self._z0(p) + zs, r_in, build)

    def parts(self, p: dict[str, Any], detail: bool) -> list[Part]:
        z0 = self._z0(p)
        out = self._saucer(p, detail) + pot_parts(p, detail, z0)
        plant, pts = self._foliage(p, detail)
        if detail:
            return out + plant
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        out.append(Part(box_between(lo, hi), "foliage"))
        return out

    def _saucer(self, p, detail) -> list[Part]:
        return []

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        r = pot_foot_radius(p) - 0.0005
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(r, 48),
                                subpart=Subpart.Bottom, up=False)]


@register
class PottedPlant(_PlantBase):
    """A floor plant: a lathed pot (cylinder, taper, bowl or rimmed; optional saucer) with soil,
    and foliage that grows as a `rosette` of arching leaves from one crown (dracaena, snake
    plant), as upright `stemmed` branches with leaves set by phyllotaxis (rubber plant, ficus),
    or as a `palm` of arching fronds carrying paired leaflets."""

    name = "potted_plant"
    tags = frozenset({S.Object, S.Decor, S.Plant, S.PottedPlant})
    size_class = "large"
    params = {
        "plant_type": Param(kind="choice", choices=("stemmed", "rosette", "palm"),
                            doc="growth habit"),
        "pot_radius": Param(0.12, 0.25, doc="pot outer radius at the rim (m)"),
        "pot_height": Param(0.2, 0.45, doc="pot height (m)"),
        "pot_shape": Param(kind="choice", choices=POT_SHAPES, doc="pot profile"),
        "saucer": Param(kind="bool", doc="stand the pot in a saucer"),
        "plant_height": Param(0.5, 1.4, doc="height of the foliage above the soil (m)"),
        "n_leaves": Param(14, 48, kind="int", doc="leaves (or leaflets of all fronds)"),
        "leaf_length": Param(0.12, 0.35, doc="typical leaf length (m)"),
        "leaf_width": Param(0.025, 0.1, doc="typical leaf width (m)"),
        "droop": Param(0.0, 0.8, doc="how much leaves arch downwards (0 = straight)"),
        "spread": Param(0.0, 1.0, doc="how far the foliage spreads out (0 = upright)"),
        "n_stems": Param(1, 4, kind="int", doc="stems (stemmed) or fronds - 2 (palm)"),
    }

    def _z0(self, p):
        return 0.004 if p["saucer"] else 0.0  # standing on the saucer's floor (1 mm into it)

    def _saucer(self, p, detail):
        if not p["saucer"]:
            return []
        rb = pot_foot_radius(p)
        R, h = rb + 0.03, 0.022
        if not detail:
            return [Part(cylinder(R, h, (0, 0, 0), 16, circumscribed=True), "ceramic")]
        prof = [(0.0, 0.0), (R - 0.012, 0.0), (R, h), (R - 0.005, h), (R - 0.015, 0.005),
                (0.0, 0.005)]
        return [Part(lathe(prof, 48), "ceramic")]

    def extra_surfaces(self, p: dict[str, Any]) -> list[Surface]:
        """The pot's foot (or the saucer's, with one) as the `bottom`."""
        r = (pot_foot_radius(p) + 0.03 - 0.012 if p["saucer"] else pot_foot_radius(p)) - 0.0005
        return [support_polygon("bottom", (0, 0, 0), circle_polygon(r, 48),
                                subpart=Subpart.Bottom, up=False)]

    def foliage(self, p: dict[str, Any], z_soil: float, r_in: float, build: bool
                ) -> tuple[list[Part], np.ndarray]:
        """A rosette, stemmed branches or a palm's fronds, by `plant_type`."""
        kind = p["plant_type"]
        if kind == "rosette":
            return self._rosette(p, z_soil, build)
        if kind == "palm":
            return self._palm(p, z_soil, r_in, build)
        return self._stemmed(p, z_soil, r_in, build)

    def _rosette(self, p, z_soil, build):
        Hp = p["plant_height"]
        shape = "strap" if p["leaf_width"] < 0.05 else "lanceolate"
        leaves = rosette(p, z_soil, shape, Hp, max(p["leaf_length"], 0.4 * Hp),
                         p["leaf_width"])
        leaves.lift_above(0.01)
        crown = cylinder(CROWN_RADIUS, 0.05, (0, 0, z_soil - 0.02), 12)
        parts = [Part(crown, "foliage")] + _leaf_parts(leaves, build)
        return parts, np.vstack([leaves.points(), [[0.0, 0.0, z_soil + 0.03]]])

    def _stem_layout(self, p, z_soil, r_in, n_stems, lean_deg, length, droop):
        k = np.arange(n_stems)
        az = k * 2 * math.pi / n_stems + 0.4
        off = 0.0 if n_stems == 1 else 0.35 * r_in
        base = np.c_[off * np.cos(az), off * np.sin(az), np.full(n_stems, z_soil - 0.01)]
        lean = np.radians(lean_deg) * (1.0 if n_stems > 1 else 0.3)
        elev = np.full(n_stems, math.pi / 2) - lean
        return base, az, elev, length, np.full(n_stems, droop)

    def _stemmed(self, p, z_soil, r_in, build):
        ns, Hp = int(p["n_stems"]), p["plant_height"]
        k = np.arange(ns)
        length = Hp * (1.0 - 0.18 * (k % 3) / 2)
        base, az, elev, length, droop = self._stem_layout(p, z_soil, r_in, ns,
                                                          8 + 22 * p["spread"], length, 0.05)
        r0 = np.full(ns, 0.006 + 0.01 * Hp / 1.4)
        stems, spts = stem_solids(base, az, elev, length, droop, r0, r0 * 0.45, 6, 8, build)
        # leaves by phyllotaxis along the upper part of each stem
        nl = int(p["n_leaves"])
        j = np.arange(nl)
        which = j % ns
        u = 0.3 + 0.7 * ((j // ns + 0.5) / math.ceil(nl / ns))
        lp, _ = stem_points(base[which], az[which], elev[which], length[which], droop[which],
                            u[:, None])
        lp = lp[:, 0]
        leaf_az = j * GOLDEN_ANGLE
        leaf_el = np.radians(40 - 30 * p["spread"]) + 0.5 * (u - 0.3)
        scale = 1.0 - 0.35 * (u - 0.3) / 0.7
        leaves = Leaves(lp, leaf_az, leaf_el, p["leaf_length"] * scale,
                        p["leaf_width"] * scale, np.full(nl, p["droop"]), "ovate")
        leaves.lift_above(0.01)
        parts = [Part(s, "wood") for s in stems] + _leaf_parts(leaves, build)
        return parts, np.vstack([spts, leaves.points()])

    def _palm(self, p, z_soil, r_in, build):
        nf, Hp = int(p["n_stems"]) + 2, p["plant_height"]
        k = np.arange(nf)
        az = k * GOLDEN_ANGLE * 1.0
        elev = np.radians(82 - 35 * p["spread"] * (0.6 + 0.4 * (k % 2)))
        length = Hp * (1.05 - 0.15 * (k % 3) / 2)
        base = np.c_[0.003 * np.cos(az), 0.003 * np.sin(az), np.full(nf, z_soil - 0.01)]
        droop = np.full(nf, 0.25 + 0.5 * p["droop"])
        r0 = np.full(nf, 0.007)
        fronds, fpts = stem_solids(base, az, elev, length, droop, r0, r0 * 0.4, 8, 6, build)
        per = max(8, int(round(1.5 * p["n_leaves"] / nf / 2)) * 2)  # leaflets per frond
        j = np.arange(per)
        u = 0.3 + 0.65 * (j // 2 + 0.5) / (per // 2)
        side = np.where(j % 2 == 0, 1.0, -1.0)
        uu = np.tile(u, (nf, 1))
        lp, ld = stem_points(base, az, elev, length, droop, uu, 8)
        fi = np.repeat(k, per)
        lp, ld = lp.reshape(-1, 3), ld.reshape(-1, 3)
        s_all = np.tile(side, nf)
        u_all = np.tile(u, nf)
        # leaflet heading: the frond's horizontal direction turned +-70 degrees, pointing forward
        laz = az[fi] + s_all * math.radians(70)
        lel = np.arcsin(np.clip(ld[:, 2], -1, 1)) * 0.5 + 0.1
        size = 1.0 - 0.5 * np.abs(u_all - 0.55) / 0.45
        leaves = Leaves(lp, laz, lel, p["leaf_length"] * size, p["leaf_width"] * 0.5 * size,
                        np.full(len(lp), 0.3 + 0.5 * p["droop"]), "lanceolate")
        leaves.lift_above(0.01)
        parts = [Part(s, "foliage") for s in fronds] + _leaf_parts(leaves, build)
        return parts, np.vstack([fpts, leaves.points()])


@register
class TabletopPlant(_PlantBase):
    """A small potted plant for tables and shelves: a `succulent` rosette of fleshy pointed
    leaves, a ribbed `cactus` column (with 0-3 arms) or a `leafy` plant of thin stems carrying
    round leaves (pilea, pothos)."""

    name = "tabletop_plant"
    tags = frozenset({S.Object, S.SmallObject, S.Decor, S.Plant, S.PottedPlant})
    size_class = "small"
    params = {
        "plant_type": Param(kind="choice", choices=("succulent", "cactus", "leafy"),
                            doc="kind of plant"),
        "pot_radius": Param(0.04, 0.09, doc="pot outer radius at the rim (m)"),
        "pot_height": Param(0.05, 0.12, doc="pot height (m)"),
        "pot_shape": Param(kind="choice", choices=POT_SHAPES, doc="pot profile"),
        "plant_height": Param(0.06, 0.25, doc="height of the plant above the soil (m)"),
        "n_leaves": Param(8, 30, kind="int", doc="leaves (succulent, leafy)"),
        "leaf_size": Param(0.02, 0.06, doc="leaf length (m)"),
        "spread": Param(0.0, 1.0, doc="how far leaves/stems lean out (0 = upright)"),
        "n_branches": Param(0, 3, kind="int", doc="cactus arms / extra leafy stems"),
        "n_ribs": Param(6, 14, kind="int", doc="cactus ribs"),
    }

    def foliage(self, p: dict[str, Any], z_soil: float, r_in: float, build: bool
                ) -> tuple[list[Part], np.ndarray]:
        """A succulent rosette, a ribbed cactus or a leafy plant, by `plant_type`."""
        kind = p["plant_type"]
        if kind == "cactus":
            return self._cactus(p, z_soil, r_in, build)
        if kind == "leafy":
            return self._leafy(p, z_soil, r_in, build)
        return self._succulent(p, z_soil, r_in, build)

    def _succulent(self, p, z_soil, r_in, build):
        n = int(p["n_leaves"])
        k = np.arange(n)
        frac = k / max(n - 1, 1)
        L = p["leaf_size"] * (1.0 - 0.55 * frac)
        e_out = math.radians(15 + 25 * (1 - p["spread"]))
        elev = e_out + (math.radians(75) - e_out) * frac
        az = k * GOLDEN_ANGLE
        z_top = z_soil + 0.25 * p["plant_height"]  # the rosette's centre, on a short stem
        rb = 0.006 * (1 - frac)  # leaves start inside the core, spiralling up and in
        base = np.c_[rb * np.cos(az), rb * np.sin(az), z_soil - 0.002 + (z_top - z_soil) * frac]
        leaves = Leaves(base, az, elev, L, 0.45 * L, np.full(n, 0.05), "succulent",
                        petiole=0.006)
        leaves.lift_above(0.005)
        core = cylinder(0.01, max(z_top - z_soil + 0.004, 0.006), (0, 0, z_soil - 0.004), 12)
        parts = [Part(core, "foliage")] + _leaf_parts(leaves, build, 5)
        return parts, np.vstack([leaves.points(5), [[0, 0, z_top]]])

    def _cactus(self, p, z_soil, r_in, build):
        Hp = p["plant_height"]
        R = min(0.55 * r_in, 0.018 + 0.12 * Hp)
        body, pts = self._ribbed(np.array([0.0, 0.0, z_soil - 0.01]), math.pi / 2, 0.0,
                                 Hp + 0.01, R, int(p["n_ribs"]), build=build)
        parts, allpts = ([Part(body, "foliage")] if build else []), [pts]
        for i in range(int(p["n_branches"])):
            az = 0.7 + i * 2 * math.pi / 3
            zb = z_soil + Hp * (0.3 + 0.15 * i)
            d = np.array([math.cos(az), math.sin(az), 0.0])
            start = np.array([0.0, 0.0, zb]) + d * 0.3 * R
            arm, apts = self._ribbed(start, math.radians(20 + 30 * p["spread"]), az,
                                     Hp * 0.45, 0.55 * R, int(p["n_ribs"]), curl=True,
                                     build=build)
            if build:
                parts.append(Part(arm, "foliage"))
            allpts.append(apts)
        return parts, np.vstack(allpts)

    @staticmethod
    def _ribbed(start, elev, az, length, R, ribs, curl=False, build=True):
        """A ribbed column (radius modulated by the rib count) with a domed top; `curl` makes it
        turn upwards (a cactus arm)."""
        n = 8
        # an arm turns from `elev` up to ~80 degrees
        droop = np.array([-(math.radians(80) - elev) / DROOP_TURN if curl else 0.0])
        pts, tang, side, normal = arc_paths(start[None], np.array([az]), np.array([elev]),
                                            np.array([length]), droop, n)
        s = np.linspace(0, 1, n + 1)
        prof = np.where(s < 0.75, 1.0, np.sqrt(np.clip(1 - ((s - 0.75) / 0.27) ** 2, 0.05, 1)))
        k = ribs * 2
        a = np.arange(k) * 2 * math.pi / k
        mod = np.where(np.arange(k) % 2 == 0, 1.0, 0.86)
        rad = R * prof[:, None] * mod[None, :]
        across = (np.cos(a)[None, :, None] * side[0]
                  + np.sin(a)[None, :, None] * normal[0][:, None, :])
        ring = pts[0, :, None, :] + rad[..., None] * across
        tip = pts[0, -1] + tang[0, -1] * 0.004
        solid = loft(ring, pts[0, 0] - tang[0, 0] * 0.002, tip) if build else None
        return solid, np.vstack([ring.reshape(-1, 3), tip])

    def _leafy(self, p, z_soil, r_in, build):
        ns = 3 + int(p["n_branches"])
        Hp = p["plant_height"]
        k = np.arange(ns)
        az = k * 2 * math.pi / ns + 0.3
        base = np.c_[0.2 * r_in * np.cos(az), 0.2 * r_in * np.sin(az), np.full(ns, z_soil - 0.006)]
        elev = np.full(ns, math.radians(85 - 45 * p["spread"]))
        length = Hp * (1.0 - 0.25 * (k % 3) / 2)
        droop = np.full(ns, 0.1 + 0.2 * p["spread"])
        r0 = np.full(ns, 0.0022)
        stems, spts = stem_solids(base, az, elev, length, droop, r0, r0 * 0.8, 5, 6, build)
        nl = int(p["n_leaves"])
        j = np.arange(nl)
        which = j % ns
        u = 0.35 + 0.65 * ((j // ns + 1.0) / math.ceil(nl / ns))
        lp, _ = stem_points(base[which], az[which], elev[which], length[which], droop[which],
                            np.minimum(u, 1.0)[:, None], 5)
        leaves = Leaves(lp[:, 0], j * GOLDEN_ANGLE, np.full(nl, math.radians(25)),
                        np.full(nl, p["leaf_size"]), np.full(nl, 0.6 * p["leaf_size"]),
                        np.full(nl, 0.35), "round", thickness=0.0014, petiole=0.0025)
        leaves.lift_above(0.005)
        parts = [Part(s, "foliage") for s in stems] + _leaf_parts(leaves, build, 6)
        return parts, np.vstack([spts, leaves.points(6)])
