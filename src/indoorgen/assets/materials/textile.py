"""Soft materials: woven and knitted fabrics, velvet, painted canvas, leather, suede and carpet.

Weaves are built per thread crossing: with warp threads along v and weft threads along u, the
cell (i, j) shows the warp on top when the weave's lift plan says so ((i + j) % 2 for plain
weave, a diagonal for twill). Each visible thread is a rounded ridge that bulges in the middle
of its float, with per-thread colour variation and fibre noise along its length. Thread counts
are integers (and multiples of the weave repeat), so the cloth tiles.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from indoorgen.assets.materials import noise as nz
from indoorgen.assets.materials.base import Layers, MaterialGenerator, register
from indoorgen.assets.materials.color import jitter, mix, modulate, ramp, rgb, scale_value, solid
from indoorgen.assets.protocol import Param

F32 = np.float32

FABRIC_COLORS = {"natural": "#d8ccb4", "white": "#ecebe6", "charcoal": "#3c3d40",
                 "grey": "#8c8c8a", "navy": "#283858", "rust": "#a4532e", "mustard": "#c8982e",
                 "olive": "#6e6e3e", "teal": "#28686a", "burgundy": "#6a2430",
                 "blush": "#d8aaa0", "sky": "#8ab0cc", "forest": "#2e4e3a", "camel": "#b08a5e"}


@dataclass
class Weave:
    """A woven thread pattern per pixel: its relief, which thread is on top, and thread ids."""

    height: np.ndarray      # relief, 0 (gaps) .. 1 (top of a float)
    warp_top: np.ndarray    # bool: the warp (vertical) thread is on top here
    across: np.ndarray      # 0 at a thread's edges .. 1 at its centre line
    warp_id: np.ndarray     # thread indices, (1, res) and (res, 1)
    weft_id: np.ndarray


def _thread_count(n: int, res: int, repeat: int) -> int:
    """Clamp a thread count so a thread is at least ~3 px wide, rounded to the weave repeat."""
    n = min(int(n), max(repeat, res // 3))
    return max(repeat, (n // repeat) * repeat)


def weave(res: int, n_warp: int, n_weft: int, pattern: str = "plain") -> Weave:
    """Thread geometry of a plain, twill (2/2) or basket (2x2) weave."""
    repeat = {"plain": 2, "twill": 4, "basket": 4}[pattern]
    nw, nf = _thread_count(n_warp, res, repeat), _thread_count(n_weft, res, repeat)
    u, v = nz.grid(res)
    # the seam falls a quarter into a thread: away from the crossings' steps and from the
    # crests, where the normal map changes fastest
    x = u * F32(nw) + F32(0.25)
    y = v * F32(nf) + F32(0.25)
    fi, fj = np.floor(x), np.floor(y)
    fx, fy = x - fi, y - fj
    i, j = fi.astype(np.int32), fj.astype(np.int32)
    if pattern == "plain":
        warp_top = (i + j) % 2 == 0
    elif pattern == "twill":
        warp_top = (i + j) % 4 < 2
    else:
        warp_top = (i // 2 + j // 2) % 2 == 0
    # cross-sections: rounded thread profiles; along-thread bulge in the middle of the cell
    across_warp = np.sqrt(np.clip(np.sin(np.pi * fx), 0, 1))
    across_weft = np.sqrt(np.clip(np.sin(np.pi * fy), 0, 1))
    along_warp = 0.6 + 0.4 * np.sin(np.pi * fy)
    along_weft = 0.6 + 0.4 * np.sin(np.pi * fx)
    h_warp = across_warp * along_warp
    h_weft = across_weft * along_weft
    height = np.where(warp_top, 0.35 + 0.65 * h_warp, 0.35 + 0.65 * h_weft)
    height = np.where(warp_top, np.maximum(height, 0.35 * h_weft),
                      np.maximum(height, 0.35 * h_warp))
    across = np.where(warp_top, across_warp, across_weft)
    return Weave(height.astype(F32), warp_top, across.astype(F32), i % nw, j % nf)


class _Fabric(MaterialGenerator):
    family = "fabric"
    density = 500.0

    def woven(self, res: int, rng: np.random.Generator, threads: int, pattern: str,
              warp_col: np.ndarray, weft_col: np.ndarray, slub: float = 0.0,
              thread_var: float = 0.08) -> tuple[np.ndarray, np.ndarray]:
        """Colour and height of a woven cloth (slub: irregular thread thickness, as in linen)."""
        wv = weave(res, threads, threads, pattern)
        nw = int(wv.warp_id.max()) + 1
        nf = int(wv.weft_id.max()) + 1
        tw = (1 + thread_var * 2 * (rng.random(nw) - 0.5)).astype(F32)[wv.warp_id]
        tf = (1 + thread_var * 2 * (rng.random(nf) - 0.5)).astype(F32)[wv.weft_id]
        fib_w = nz.spectral_noise(res, rng, knee=res / 6, beta=0.9, stretch=(1.0, 6.0))
        fib_f = nz.spectral_noise(res, rng, knee=res / 6, beta=0.9, stretch=(6.0, 1.0))
        height = wv.height
        if slub > 0:
            sw = nz.spectral_noise(res, rng, knee=8.0, beta=1.2, stretch=(1.0, 5.0))
            sf = nz.spectral_noise(res, rng, knee=8.0, beta=1.2, stretch=(5.0, 1.0))
            thick = np.where(wv.warp_top, sw, sf)
            height = height * (1 + F32(0.3 * slub) * thick)
            tw = tw * (1 + F32(0.06 * slub) * sw)
            tf = tf * (1 + F32(0.06 * slub) * sf)
        col = np.where(wv.warp_top[..., None], modulate(warp_col, tw * (1 + 0.06 * fib_w)),
                       modulate(weft_col, tf * (1 + 0.06 * fib_f)))
        shade = 0.62 + 0.38 * np.clip(height, 0, 1)
        col = modulate(col, shade)
        height = height + 0.08 * np.where(wv.warp_top, fib_w, fib_f)
        return col.astype(F32), height.astype(F32)


@register
class PlainWeave(_Fabric):
    """Plain-woven cotton / polyester (shirting, upholstery, curtains, cushion covers)."""

    name = "plain_weave"
    tile_param = ("threads", 0.0008)
    params = {
        "color": Param(kind="choice", choices=tuple(FABRIC_COLORS), doc="cloth colour"),
        "threads": Param(40, 110, "int", doc="threads across the texture"),
        "two_tone": Param(0.0, 0.3, doc="colour difference between warp and weft (chambray)"),
        "roughness": Param(0.75, 0.95, doc="mean roughness"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Over-under threads of the plain weave in the cloth's colour."""
        c = jitter(rgb(FABRIC_COLORS[p["color"]]), rng, 0.01, 0.05, 0.04)
        weft = mix(c, np.array([0.92, 0.92, 0.9], F32), F32(p["two_tone"]))
        col, height = self.woven(res, rng, p["threads"], "plain", c, weft)
        rough = F32(p["roughness"]) + F32(0.05) * (1 - height)
        return Layers(col, rough, 0.5 * height, bump=0.5)


@register
class Linen(_Fabric):
    """Linen: plain weave with slubby, uneven flax threads in natural tones."""

    name = "linen"
    tile_param = ("threads", 0.001)
    density = 550.0
    params = {
        "color": Param(kind="choice", choices=("flax", "oatmeal", "white", "stone", "sage",
                                               "terracotta", "washed_navy"), doc="cloth colour"),
        "threads": Param(40, 90, "int", doc="threads across the texture"),
        "slub": Param(0.4, 1.0, doc="thread irregularity"),
    }
    COLORS = {"flax": "#c8b48e", "oatmeal": "#d8ccb0", "white": "#ece8de", "stone": "#a8a294",
              "sage": "#9aa88e", "terracotta": "#b8714e", "washed_navy": "#4a5a72"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Plain weave of slubby, uneven flax threads in natural tones."""
        c = jitter(rgb(self.COLORS[p["color"]]), rng, 0.01, 0.05, 0.04)
        col, height = self.woven(res, rng, p["threads"], "plain", c, scale_value(c, 1.05),
                                 slub=p["slub"], thread_var=0.15)
        rough = F32(0.88) + F32(0.05) * (1 - height)
        return Layers(col, rough, 0.5 * height, bump=0.6)


@register
class Denim(_Fabric):
    """Twill-woven denim / chino / tweed-like cloth: diagonal ribs from a 2/2 twill."""

    name = "denim"
    tile_param = ("threads", 0.0007)
    density = 600.0
    params = {
        "color": Param(kind="choice", choices=("indigo", "black", "light_wash", "khaki", "olive",
                                               "grey"), doc="warp colour"),
        "threads": Param(48, 110, "int", doc="threads across the texture"),
        "fade": Param(0.0, 0.6, doc="wash-out fading"),
    }
    COLORS = {"indigo": "#243a64", "black": "#222428", "light_wash": "#6a86ac",
              "khaki": "#b4a27a", "olive": "#5e6240", "grey": "#6a6c70"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Diagonal 2/2 twill ribs in the warp colour, washed out by `fade`."""
        c = jitter(rgb(self.COLORS[p["color"]]), rng, 0.01, 0.05, 0.04)
        weft = mix(c, rgb("#e4e0d6"), 0.7)
        col, height = self.woven(res, rng, p["threads"], "twill", c, weft, slub=0.3)
        fade = nz.spectral_noise(res, rng, knee=4.0, beta=1.5)
        col = mix(col, rgb("#c8d0dc"), np.clip(F32(p["fade"]) * (0.3 + 0.2 * fade), 0, 1))
        rough = F32(0.85) + F32(0.05) * (1 - height)
        return Layers(col, rough, 0.5 * height, bump=0.6)


@register
class Knit(_Fabric):
    """Stockinette knit (jumpers, throws, knitted cushions): rows of V-shaped stitches."""

    name = "knit"
    tile_param = ("stitches", 0.004)
    density = 350.0
    params = {
        "color": Param(kind="choice", choices=tuple(FABRIC_COLORS), doc="yarn colour"),
        "stitches": Param(10, 28, "int", doc="stitch columns (wales) across the texture"),
        "heather": Param(0.0, 0.5, doc="two-tone fleck in the yarn"),
        "stripes": Param(0, 4, "int", doc="contrast stripes per texture (0 = none)"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Rows of V-shaped stockinette stitches."""
        c = jitter(rgb(FABRIC_COLORS[p["color"]]), rng, 0.01, 0.05, 0.04)
        nc = min(int(p["stitches"]), res // 6)
        nr = int(round(nc * 1.4))  # stitches are wider than tall
        u, v = nz.grid(res)
        x = u * F32(nc) + F32(0.5)
        y = v * F32(nr) + F32(0.5)
        fx, fy = nz.fract(x), nz.fract(y)
        row = np.floor(y).astype(np.int32) % nr
        # two legs of the V: centre lines slanting from the top corners to the bottom middle
        t = 1.0 - fy
        d_left = np.abs(fx - (0.5 - 0.38 * t)) * F32(0.8)
        d_right = np.abs(fx - (0.5 + 0.38 * t)) * F32(0.8)
        leg = lambda d: np.sqrt(np.clip(1.0 - (d / 0.24) ** 2, 0, 1))  # noqa: E731
        bulge = 0.55 + 0.45 * np.sin(np.pi * fy)
        height = np.maximum(leg(d_left), leg(d_right)) * bulge
        fib = nz.spectral_noise(res, rng, knee=res / 6, beta=0.9)
        yarn = c
        if p["stripes"]:
            others = [k for k in FABRIC_COLORS if k != p["color"]]
            sc = rgb(FABRIC_COLORS[others[int(rng.integers(len(others)))]])
            period = max(1, nr // int(p["stripes"]))
            is_stripe = (row % period) < max(1, period // 3)
            yarn = np.where(is_stripe[..., None], sc, c)
            yarn = np.broadcast_to(yarn, (res, res, 3))
        heath = nz.smoothstep(0.5, 1.5, nz.spectral_noise(res, rng, knee=res / 5, beta=0.8))
        col = mix(yarn, scale_value(c, 1.35), heath * F32(p["heather"]))
        col = modulate(col, (0.55 + 0.45 * height) * (1 + 0.05 * fib))
        rough = F32(0.92) + F32(0.04) * fib
        return Layers(col, rough, height + 0.05 * fib, bump=0.6)


@register
class Velvet(_Fabric):
    """Velvet / velour upholstery: deep saturated pile with crushed-pile sheen variation."""

    name = "velvet"
    tile_size = 0.3
    density = 400.0
    params = {
        "color": Param(kind="choice", choices=("emerald", "navy", "blush", "mustard", "teal",
                                               "burgundy", "grey", "rust"), doc="pile colour"),
        "crush": Param(0.0, 1.0, doc="strength of the crushed sheen pattern"),
    }
    COLORS = {"emerald": "#1e5a44", "navy": "#1e2a4a", "blush": "#d49a92", "mustard": "#c08a1e",
              "teal": "#1e5a60", "burgundy": "#5a1a26", "grey": "#6a6a6e", "rust": "#8a3e22"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Deep saturated pile with crushed-pile sheen patches."""
        c = jitter(rgb(self.COLORS[p["color"]]), rng, 0.01, 0.05, 0.04)
        crush = nz.spectral_noise(res, rng, knee=5.0, beta=1.5, stretch=(1.0, 1.8), angle=0.5)
        pile = nz.spectral_noise(res, rng, knee=res / 4, beta=0.6)
        k = F32(p["crush"])
        col = modulate(c, 1.0 + k * 0.12 * np.tanh(crush) + 0.04 * pile)
        rough = F32(0.82) + F32(0.06) * pile - k * F32(0.06) * crush
        return Layers(col, rough, 0.05 * pile + 0.05 * k * crush, bump=0.4)


PAINTING_PALETTES = [
    ["#1d3557", "#457b9d", "#a8dadc", "#f1faee", "#e63946"],
    ["#264653", "#2a9d8f", "#e9c46a", "#f4a261", "#e76f51"],
    ["#3d2c1e", "#8c5a3c", "#d9a86c", "#efe0c0", "#6a7a5a"],
    ["#0b132b", "#1c2541", "#3a506b", "#5bc0be", "#e0e1dd"],
    ["#5f0f40", "#9a031e", "#fb8b24", "#e36414", "#0f4c5c"],
    ["#2b2d42", "#8d99ae", "#edf2f4", "#ef233c", "#d90429"],
    ["#606c38", "#283618", "#fefae0", "#dda15e", "#bc6c25"],
]


@register
class Painting(_Fabric):
    """An abstract oil/acrylic painting on canvas (for wall art): colour fields from warped
    noise in a curated palette, directional brush strokes and the canvas weave beneath."""

    name = "painting"
    tile_size = 0.6
    density = 700.0
    params = {
        "palette": Param(0, len(PAINTING_PALETTES) - 1, "int", doc="palette index"),
        "regions": Param(2.0, 6.0, doc="colour fields across the texture"),
        "strokes": Param(0.2, 1.0, doc="visibility of brush strokes"),
        "varnish": Param(0.3, 0.7, doc="roughness (low = glossy varnish)"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Colour fields and brush strokes over the canvas weave."""
        pal = [rgb(c) for c in PAINTING_PALETTES[int(p["palette"])]]
        order = rng.permutation(len(pal))
        field = nz.smooth_warp(res, rng, p["regions"], 0.03)
        wu = nz.spectral_noise(res, rng, knee=3.0, beta=2.0, hi=12.0)
        t = np.clip((field + 2.2) / 4.4, 0, 1)
        stops = [(k / (len(pal) - 1), pal[order[k]]) for k in range(len(pal))]
        col = ramp(t, stops)
        s1 = nz.spectral_noise(res, rng, knee=res / 8, beta=0.8, stretch=(6.0, 1.0), angle=0.3)
        s2 = nz.spectral_noise(res, rng, knee=res / 8, beta=0.8, stretch=(6.0, 1.0), angle=1.9)
        strokes = np.where(wu > 0, s1, s2)
        k = F32(p["strokes"])
        col = modulate(col, 1.0 + 0.08 * k * strokes + 0.015 * nz.grain(res, rng))
        _, canvas_h = self.woven(res, rng, 90, "plain", rgb("#e8e0d0"), rgb("#e8e0d0"))
        rough = F32(p["varnish"]) + F32(0.05) * strokes
        return Layers(col, rough, 0.15 * canvas_h + 0.25 * k * strokes, bump=0.5)


# --------------------------------------------------------------------------- leather

LEATHERS = {"cognac": "#9a5a2e", "dark_brown": "#4a2e1e", "black": "#1e1c1c",
            "oxblood": "#5a1e1e", "tan": "#b88a5a", "cream": "#e0d4bc", "grey": "#6e6c6a",
            "olive": "#5a5a3a"}


@register
class Leather(MaterialGenerator):
    """Full-grain leather (sofas, chairs, book covers): pebbled cellular grain with darker
    creases, mottled dye and a waxy sheen."""

    name = "leather"
    tile_param = ("grain", 0.0015)
    family = "leather"
    density = 860.0
    params = {
        "color": Param(kind="choice", choices=tuple(LEATHERS), doc="dye colour"),
        "grain": Param(40, 90, "int", doc="pebbles across the texture"),
        "depth": Param(0.3, 1.0, doc="grain relief"),
        "roughness": Param(0.3, 0.6, doc="mean roughness (low = polished / patent)"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Pebbled cellular grain with darker creases."""
        c = jitter(rgb(LEATHERS[p["color"]]), rng, 0.01, 0.06, 0.05)
        n = min(int(p["grain"]), res // 4)
        cells = nz.worley(res, n, rng, 1.0)
        crease = nz.smoothstep(max(0.2, 2.0 * n / res), 0.0, cells.border)  # thin creases
        dome = np.clip(1.0 - cells.f1 * cells.f1, 0, 1)  # rounded pebbles
        wrinkle = nz.spectral_noise(res, rng, knee=res / 5, beta=0.8)
        mottle = nz.spectral_noise(res, rng, knee=6.0, beta=1.5)
        d = F32(p["depth"])
        col = modulate(c, (1.0 + 0.08 * mottle) * (1.0 - 0.18 * crease) * (1 + 0.03 * wrinkle))
        rough = F32(p["roughness"]) + F32(0.12) * crease - F32(0.05) * mottle + F32(0.02) * wrinkle
        height = d * (0.35 * dome - 0.4 * crease + 0.03 * wrinkle)
        return Layers(col, rough, height, bump=0.6)


@register
class Suede(MaterialGenerator):
    """Suede / nubuck: velvety napped leather, very rough, with brushed light-dark patches."""

    name = "suede"
    tile_size = 0.2
    family = "leather"
    density = 800.0
    params = {
        "color": Param(kind="choice", choices=("tan", "taupe", "chocolate", "olive", "navy",
                                               "grey", "rust"), doc="dye colour"),
        "nap": Param(0.2, 1.0, doc="strength of the brushed-nap patches"),
    }
    COLORS = {"tan": "#b08458", "taupe": "#8e7e6e", "chocolate": "#4e3426", "olive": "#6a6a44",
              "navy": "#2e3a54", "grey": "#7a7a7c", "rust": "#9a4e2e"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Very rough napped leather with brushed light and dark patches."""
        c = jitter(rgb(self.COLORS[p["color"]]), rng, 0.01, 0.06, 0.05)
        nap = nz.spectral_noise(res, rng, knee=5.0, beta=1.6, stretch=(1.0, 1.5), angle=1.0)
        fib = nz.spectral_noise(res, rng, knee=res / 4, beta=0.5)
        col = modulate(c, 1.0 + F32(p["nap"]) * 0.12 * np.tanh(nap) + 0.05 * fib)
        rough = F32(0.92) + F32(0.04) * fib
        return Layers(col, rough, 0.08 * fib, bump=0.4)


# --------------------------------------------------------------------------- carpet

CARPET_COLORS = {"beige": "#c8b89c", "grey": "#8e8c88", "charcoal": "#45464a",
                 "cream": "#e4dccb", "navy": "#2a3450", "sage": "#8a9a80", "rust": "#9a5436",
                 "burgundy": "#6a2a30", "taupe": "#8a7a6a"}


@register
class Carpet(MaterialGenerator):
    """Cut-pile carpet: dense tufts, soft shading, optional heathered yarn."""

    name = "carpet"
    tile_param = ("tufts", 0.003)
    family = "carpet"
    density = 300.0
    params = {
        "color": Param(kind="choice", choices=tuple(CARPET_COLORS), doc="yarn colour"),
        "tufts": Param(60.0, 140.0, doc="tufts across the texture"),
        "heather": Param(0.0, 0.5, doc="two-tone fleck in the yarn"),
        "shading": Param(0.0, 1.0, doc="pile shading (lighter/darker tracks)"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Dense cut-pile tufts with soft shading, optionally heathered."""
        c = jitter(rgb(CARPET_COLORS[p["color"]]), rng, 0.01, 0.06, 0.05)
        f = min(p["tufts"], res / 3.0)
        tuft = nz.band_noise(res, rng, f, f * 0.4)
        fib = nz.spectral_noise(res, rng, knee=res / 3, beta=0.5)
        shade = nz.spectral_noise(res, rng, knee=4.0, beta=1.6)
        fleck = nz.smoothstep(0.6, 1.6, nz.spectral_noise(res, rng, knee=res / 4, beta=0.7))
        col = mix(solid(c, res), scale_value(c, 0.6), fleck * F32(p["heather"]))
        col = modulate(col, (1 + 0.12 * np.tanh(tuft)) * (1 + 0.04 * fib)
                       * (1 + 0.08 * F32(p["shading"]) * shade))
        rough = F32(0.92) + F32(0.04) * fib
        return Layers(col, rough, 0.4 * tuft + 0.1 * fib, bump=0.5)


BERBER = {"oat": ("#d8ccb4", "#8a7a64"), "grey": ("#a8a6a0", "#4e4e50"),
          "sand": ("#cdb894", "#6e5a44"), "slate": ("#6a6e74", "#2e3034")}


@register
class BerberCarpet(MaterialGenerator):
    """Loop-pile (berber) carpet: rows of yarn loops with dark flecks."""

    name = "berber_carpet"
    tile_param = ("loops", 0.005)
    family = "carpet"
    density = 320.0
    params = {
        "color": Param(kind="choice", choices=tuple(BERBER), doc="yarn and fleck colours"),
        "loops": Param(24, 56, "int", doc="loops across the texture"),
        "fleck": Param(0.05, 0.3, doc="fraction of fleck-coloured loops"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Rows of yarn loops with dark flecks."""
        base, fleck = (jitter(rgb(x), rng, 0.01, 0.05, 0.05) for x in BERBER[p["color"]])
        n = min(int(p["loops"]), res // 5)
        rows = n + n % 2  # even, so the alternating offsets wrap
        lay = nz.grid_layout(res, n, rows, np.tile([0.25, 0.75], rows // 2))
        da = (lay.a - F32(lay.length / 2)) / F32(lay.length)
        db = (lay.b - F32(lay.width / 2)) / F32(lay.width)
        r = np.sqrt((da / 0.5) ** 2 + (db / 0.42) ** 2)
        loop = np.sqrt(np.clip(1.0 - r * r, 0, 1))
        is_f = (rng.random(lay.count) < p["fleck"])[lay.tile]
        tone = (1 + 0.1 * (rng.random(lay.count) - 0.5)).astype(F32)[lay.tile]
        fib = nz.spectral_noise(res, rng, knee=res / 4, beta=0.6)
        col = np.where(is_f[..., None], fleck, base)
        col = modulate(col, tone * (0.55 + 0.45 * loop) * (1 + 0.05 * fib))
        rough = F32(0.93) + F32(0.03) * fib
        return Layers(col, rough, loop + 0.05 * fib, bump=0.6)


RUG_PALETTES = {
    "persian": ["#7a1e22", "#1e2a4e", "#e8dcc0", "#c89a4a", "#2e4a3a"],
    "modern": ["#2e3440", "#d8dee9", "#88a0b8", "#c8a06a", "#eceff4"],
    "kilim": ["#a8442a", "#e0b050", "#2e3a5a", "#ece0c8", "#3a5a3a"],
    "moroccan": ["#ece6da", "#2e2a28", "#c8b8a0", "#8a7a6a", "#ece6da"],
}


@register
class PatternedRug(MaterialGenerator):
    """A patterned rug field: a lattice of stepped diamond medallions in a traditional or modern
    palette, with pile texture on top."""

    name = "patterned_rug"
    tile_param = ("medallions", 0.5)
    family = "carpet"
    density = 300.0
    params = {
        "palette": Param(kind="choice", choices=tuple(RUG_PALETTES), doc="colour scheme"),
        "medallions": Param(1, 4, "int", doc="medallions across the texture"),
        "bands": Param(3, 6, "int", doc="concentric bands per medallion"),
        "star": Param(0.0, 0.3, doc="star-shaped distortion of the bands"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """A lattice of stepped diamond medallions in the palette, pile texture on top."""
        pal = np.stack([jitter(rgb(c), rng, 0.01, 0.05, 0.05) for c in RUG_PALETTES[p["palette"]]])
        k = int(p["medallions"])
        u, v = nz.grid(res)
        s = nz.fract((u + v) * F32(k) + F32(0.5)) - F32(0.5)
        t = nz.fract((u - v) * F32(k) + F32(0.5)) - F32(0.5)
        r = np.maximum(np.abs(s), np.abs(t)) * F32(2.0)  # 0 at centre, 1 at the diamond edge
        ang = np.arctan2(t, s)
        r = r * (1.0 + F32(p["star"]) * np.cos(8 * ang) * r)
        nb = int(p["bands"])
        q = r * F32(nb)
        band = np.clip(np.floor(q), 0, nb).astype(np.int32)
        order = rng.integers(0, len(pal), nb + 1)
        for i in range(1, nb + 1):  # avoid equal neighbouring bands
            if order[i] == order[i - 1]:
                order[i] = (order[i] + 1) % len(pal)
        col_a = pal[order[band]]
        col_b = pal[order[np.minimum(band + 1, nb)]]
        edge = nz.smoothstep(1.0 - 1.5 * nb * k / res * 2, 1.0, nz.fract(q))
        col = mix(col_a, col_b, edge)
        tuft = nz.band_noise(res, rng, min(120.0, res / 3), 30.0)
        fib = nz.spectral_noise(res, rng, knee=res / 4, beta=0.6)
        wear = nz.spectral_noise(res, rng, knee=4.0, beta=1.8)
        col = modulate(col, (1 + 0.1 * np.tanh(tuft)) * (1 + 0.04 * fib) * (1 + 0.04 * wear))
        rough = F32(0.9) + F32(0.04) * fib
        return Layers(col, rough, 0.4 * tuft + 0.1 * fib, bump=0.5)
