"""Paper-based materials: paper, cardboard, book covers, leaves (thin cellulose sheets, grouped
with paper) and wallpapers (stripes, damask, geometric).

Wallpaper motifs are drawn with signed distances inside a periodic cell, so every edge can be
anti-aliased by a one-pixel smoothstep and every motif repeats an integer number of times.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from indoorgen.assets.materials import noise as nz
from indoorgen.assets.materials.base import Layers, MaterialGenerator, register
from indoorgen.assets.materials.color import jitter, mix, modulate, rgb, scale_value, solid
from indoorgen.assets.materials.textile import weave
from indoorgen.assets.protocol import Param

F32 = np.float32


def fibres(res: int, rng: np.random.Generator) -> np.ndarray:
    """Paper fibre texture: fine isotropic grain plus short fibres in two random directions."""
    g = nz.spectral_noise(res, rng, knee=res / 4, beta=0.6)
    a = rng.uniform(0, np.pi)
    f1 = nz.spectral_noise(res, rng, knee=res / 10, beta=1.0, stretch=(5.0, 1.0), angle=a)
    f2 = nz.spectral_noise(res, rng, knee=res / 10, beta=1.0, stretch=(5.0, 1.0), angle=a + 1.3)
    return (0.5 * g + 0.35 * f1 + 0.35 * f2).astype(F32)


def aa_step(d: np.ndarray, res: int, width_px: float = 1.0) -> np.ndarray:
    """Anti-aliased inside test for a signed distance in texture units: 1 inside (d < 0)."""
    w = width_px / res
    return nz.smoothstep(w, -w, d)


PAPERS = {"white": "#f2f1ec", "ivory": "#efe8d6", "recycled": "#dcd8cc", "newsprint": "#d8d2c0",
          "kraft": "#c8a878", "yellowed": "#e6d8b0"}


@register
class Paper(MaterialGenerator):
    """Paper (book pages, notebooks, prints): fibrous, matte, optionally ruled."""

    name = "paper"
    tile_size = 0.21
    family = "paper"
    density = 800.0
    params = {
        "color": Param(kind="choice", choices=tuple(PAPERS), doc="paper stock"),
        "ruled": Param(kind="bool", doc="faint ruled lines (notebook)"),
        "roughness": Param(0.7, 0.92, doc="mean roughness (coated paper is lower)"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Fibrous matte paper in its tone, with ruled lines where asked."""
        c = jitter(rgb(PAPERS[p["color"]]), rng, 0.005, 0.05, 0.02)
        fb = fibres(res, rng)
        col = modulate(c, 1.0 + 0.025 * fb)
        if p["ruled"]:
            _, v = nz.grid(res)
            n = 24
            d = (np.abs(nz.fract(v * F32(n)) - F32(0.5)) / F32(n)) - F32(0.4 / res + 0.0006)
            line = np.broadcast_to(aa_step(d, res), (res, res))
            col = mix(col, rgb("#9ab4d4"), line * 0.8)
        rough = F32(p["roughness"]) + F32(0.03) * fb
        return Layers(col, rough, 0.06 * fb, bump=0.5)


@register
class Cardboard(MaterialGenerator):
    """Corrugated cardboard / paperboard packaging: kraft fibres, flute ridges showing through,
    optionally printed with a colour band and text-like blocks."""

    name = "cardboard"
    tile_param = ("flutes", 0.008)
    family = "paper"
    density = 180.0
    params = {
        "color": Param(kind="choice", choices=("kraft", "brown", "white_top", "grey"),
                       doc="liner colour"),
        "flutes": Param(16, 40, "int", doc="corrugation flutes across the texture"),
        "printed": Param(kind="bool", doc="add a printed colour band and text blocks"),
    }
    COLORS = {"kraft": "#c09a6a", "brown": "#a07a50", "white_top": "#e8e4da", "grey": "#a8a49c"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Kraft fibres with the flute ridges showing through."""
        c = jitter(rgb(self.COLORS[p["color"]]), rng, 0.01, 0.05, 0.04)
        fb = fibres(res, rng)
        specks = nz.smoothstep(2.8, 3.3, nz.spectral_noise(res, rng, knee=res / 6, beta=1.0))
        u, _ = nz.grid(res)
        flute = np.broadcast_to(0.5 + 0.5 * np.cos(2 * np.pi * (u * int(p["flutes"]) + 0.125)),
                                (res, res))
        col = modulate(c, (1.0 + 0.04 * fb) * (1 - 0.3 * specks) * (0.97 + 0.03 * flute))
        if p["printed"]:
            col = self.print_band(res, rng, col)
        rough = F32(0.85) + F32(0.04) * fb
        return Layers(col, rough, 0.3 * flute + 0.06 * fb, bump=0.5)

    @staticmethod
    def print_band(res: int, rng: np.random.Generator, col: np.ndarray) -> np.ndarray:
        """A horizontal ink band and rows of 'text' rectangles, both periodic."""
        ink = rgb(["#b82a24", "#1e4a8a", "#2a6a3a", "#222222"][int(rng.integers(4))])
        u, v = nz.grid(res)
        vc = rng.uniform(0.2, 0.4)
        band = aa_step(np.abs(v - F32(vc)) - F32(rng.uniform(0.05, 0.1)), res)
        col = mix(col, ink, np.broadcast_to(band, (res, res)) * 0.9)
        lines = nz.grid_layout(res, 12, 24, nz.seam_safe_offsets(rng, 24))
        on = (rng.random(lines.count) < 0.55)[lines.tile]
        row = lines.tile // 12
        text_rows = (row >= 15) & (row <= 19) & on
        glyph = aa_step(
            np.maximum(np.abs(lines.b - F32(lines.width / 2)) - F32(lines.width * 0.25),
                       np.abs(lines.a - F32(lines.length / 2)) - F32(lines.length * 0.42)), res)
        return mix(col, F32(0.15) * ink + F32(0.1), glyph * text_rows * 0.85)


BOOK_COLORS = {"oxblood": "#6a1e22", "navy": "#1e2a4a", "forest": "#22422e", "black": "#1c1c1e",
               "mustard": "#c09030", "teal": "#1e5a5e", "cream": "#e4dac4", "grey": "#6a6a6c",
               "orange": "#d0602a", "sky": "#7aa8cc", "red": "#b02a28", "tan": "#a8845a"}


@register
class BookCover(MaterialGenerator):
    """Book covers: cloth-bound (linen weave), leatherette, or printed paper, with optional
    gold-foil title bands (the foil is metallic)."""

    name = "book_cover"
    tile_size = 0.2
    family = "paper"
    density = 750.0
    params = {
        "color": Param(kind="choice", choices=tuple(BOOK_COLORS), doc="cover colour"),
        "binding": Param(kind="choice", choices=("cloth", "leatherette", "printed"),
                         doc="cover material"),
        "foil": Param(kind="bool", doc="gold or silver foil title bands"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Cloth weave, leatherette grain or printed paper, with optional foil."""
        c = jitter(rgb(BOOK_COLORS[p["color"]]), rng, 0.01, 0.06, 0.05)
        u, v = nz.grid(res)
        if p["binding"] == "cloth":
            wv = weave(res, 96, 96, "plain")
            fb = nz.spectral_noise(res, rng, knee=res / 5, beta=0.8)
            col = modulate(c, (0.8 + 0.2 * wv.height) * (1 + 0.04 * fb))
            height, rough = 0.4 * wv.height, F32(0.85) + 0.0 * fb
        elif p["binding"] == "leatherette":
            cells = nz.worley(res, 60, rng, 1.0)
            peb = nz.smoothstep(0.0, 0.4, cells.border)
            col = modulate(c, 0.8 + 0.2 * peb)
            height, rough = 0.5 * peb, F32(0.45) + 0.1 * (1 - peb)
        else:
            fb = fibres(res, rng)
            accent = rgb(BOOK_COLORS[list(BOOK_COLORS)[int(rng.integers(len(BOOK_COLORS)))]])
            centre, half = rng.uniform(0.3, 0.7), rng.uniform(0.03, 0.12)
            stripe = aa_step(np.abs(v - F32(centre)) - F32(half), res)
            col = mix(solid(c, res), accent, np.broadcast_to(stripe, (res, res)))
            col = modulate(col, 1 + 0.015 * fb)
            height, rough = 0.03 * fb, F32(0.3) + 0.02 * fb
        metal = None
        if p["foil"]:
            foil_c = rgb("#d8b860") if rng.random() < 0.75 else rgb("#d0d2d4")
            lines = []
            for vc in (0.2, 0.8):
                lines.append(aa_step(np.abs(v - F32(vc)) - F32(0.006), res))
            text = nz.grid_layout(res, 10, 1)
            glyphs = aa_step(np.abs(text.a - F32(text.length / 2)) - F32(text.length * 0.3), res)
            title = glyphs * aa_step(np.abs(v - F32(0.5)) - F32(0.025), res)
            foil = np.clip(lines[0] + lines[1] + title, 0, 1)
            foil = np.broadcast_to(foil, (res, res)).astype(F32)
            col = mix(col, foil_c, foil)
            rough = rough * (1 - foil) + F32(0.25) * foil
            height = height - 0.3 * foil
            metal = foil
        return Layers(col, np.broadcast_to(rough, (res, res)), height, bump=0.5, metallic=metal)


LEAVES = {"fresh": ("#4a7a2e", "#8ab85a"), "dark": ("#1e4424", "#4a7a4a"),
          "yellow_green": ("#8aa83a", "#c8d878"), "blue_green": ("#2e5a4e", "#6a9a8a"),
          "autumn": ("#b0602a", "#e0a848")}


@register
class Leaf(MaterialGenerator):
    """Leaf surface (house-plant foliage): waxy green blade with a raised, lighter vein network
    at two scales. Grouped with paper as a thin cellulose sheet."""

    name = "leaf"
    tile_param = ("veins", 0.015)
    family = "paper"
    density = 700.0
    params = {
        "kind": Param(kind="choice", choices=tuple(LEAVES), doc="leaf colour"),
        "veins": Param(3, 8, "int", doc="major vein cells across the texture"),
        "gloss": Param(0.0, 1.0, doc="waxiness: 1 = glossy (ficus), 0 = matte (fern)"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """A waxy green blade with a raised, lighter vein network."""
        dark, light = (jitter(rgb(x), rng, 0.01, 0.06, 0.05) for x in LEAVES[p["kind"]])
        major = nz.worley(res, p["veins"], rng, 0.9)
        minor = nz.worley(res, int(p["veins"]) * 5, rng, 1.0)
        # vein widths in cell units, but never thinner than about a pixel (no aliasing)
        vm = nz.smoothstep(max(0.06, 1.5 * major.n / res), 0.0, major.border)
        vn = nz.smoothstep(max(0.08, 1.2 * minor.n / res), 0.0, minor.border)
        mott = nz.spectral_noise(res, rng, knee=8.0, beta=1.5)
        cellt = nz.grain(res, rng)
        col = modulate(dark, 1.0 + 0.08 * mott + 0.03 * cellt)
        col = mix(col, light, np.clip(0.8 * vm + 0.35 * vn, 0, 1))
        rough = F32(0.65 - 0.4 * p["gloss"]) + F32(0.05) * vn + F32(0.02) * cellt
        height = -0.6 * vm - 0.2 * vn + 0.05 * cellt
        return Layers(col, rough, height, bump=0.5)


# --------------------------------------------------------------------------- wallpapers

WALLPAPER_PALETTES = {  # background, main, accent
    "regency": ("#e8e0cc", "#6a8a7a", "#c8a860"),
    "navy_cream": ("#ece4d0", "#263a5e", "#b8a070"),
    "blush": ("#f0ddd6", "#c88a80", "#ffffff"),
    "charcoal_gold": ("#2e3034", "#4a4c50", "#c8a458"),
    "sage": ("#dfe4d6", "#8a9c80", "#f4f2ea"),
    "ochre": ("#efe2c2", "#c8923a", "#6a4a2a"),
    "grey": ("#d8d8d6", "#a0a2a4", "#f2f2f0"),
    "teal": ("#1e4a50", "#2e6a70", "#d8c89a"),
}


class _Wallpaper(MaterialGenerator):
    family = "wallpaper"
    density = 800.0

    def colors(self, p: dict[str, Any], rng: np.random.Generator) -> tuple[np.ndarray, ...]:
        return tuple(jitter(rgb(c), rng, 0.008, 0.05, 0.03)
                     for c in WALLPAPER_PALETTES[p["palette"]])

    def paper(self, res: int, rng: np.random.Generator, col: np.ndarray, motif: np.ndarray,
              sheen: float) -> Layers:
        """Finish: paper grain, slightly embossed motif, and a sheen difference on the motif
        (printed inks / flock are glossier or rougher than the ground)."""
        fb = fibres(res, rng)
        col = modulate(col, 1.0 + 0.02 * fb)
        rough = F32(0.8) - F32(sheen) * motif + F32(0.03) * fb
        return Layers(col, rough, 0.05 * fb + 0.3 * motif, bump=0.5)


def _pal_param() -> Param:
    return Param(kind="choice", choices=tuple(WALLPAPER_PALETTES), doc="colour scheme")


@register
class StripedWallpaper(_Wallpaper):
    """Regency-style vertical stripes: a main stripe with optional flanking pinstripes."""

    name = "striped_wallpaper"
    tile_size = 0.53
    params = {
        "palette": _pal_param(),
        "repeats": Param(3, 10, "int", doc="stripe repeats across the texture"),
        "main_width": Param(0.2, 0.55, doc="main stripe width, fraction of a repeat"),
        "pinstripes": Param(kind="bool", doc="thin accent stripes beside the main stripe"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """A main stripe and its pinstripes on the paper ground."""
        bg, main, accent = self.colors(p, rng)
        n = int(p["repeats"])
        u, _ = nz.grid(res)
        # distance from the stripe centre at mid-repeat, in texture units; the seam (u = 0)
        # is the middle of the background gap, so no edge falls on it.
        d = np.abs(nz.fract(u * F32(n)) - F32(0.5)) / F32(n)
        half = F32(p["main_width"] / 2 / n)
        stripe = aa_step(d - half, res)
        col = mix(solid(bg, res), main, np.broadcast_to(stripe, (res, res)))
        motif = np.broadcast_to(stripe, (res, res)).astype(F32)
        if p["pinstripes"]:
            pin = aa_step(np.abs(d - half - F32(0.08 / n)) - F32(0.012 / n), res)
            col = mix(col, accent, np.broadcast_to(pin, (res, res)))
            motif = np.maximum(motif, pin)
        return self.paper(res, rng, col, motif, 0.15)


def _ellipse(x: np.ndarray, y: np.ndarray, cx: float, cy: float, rx: float, ry: float,
             angle: float = 0.0) -> np.ndarray:
    """Approximate signed distance to a (rotated) ellipse, in the units of x and y."""
    c, s = np.cos(angle), np.sin(angle)
    dx, dy = x - cx, y - cy
    ex, ey = c * dx + s * dy, -s * dx + c * dy
    return (np.sqrt((ex / rx) ** 2 + (ey / ry) ** 2) - 1.0) * min(rx, ry)


def _damask_sdf(s: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A bilaterally symmetric damask ornament centred in a cell (cell units, t grows
    downwards): a fleur-de-lis (central petal, two out-curving side petals with scrolled tips, a
    collar band and two small lower petals) inside an ogee (pointed-oval) frame. Returns the
    approximate signed distances of (fleur, frame outline)."""
    k = 0.75  # fleur scale
    a, tt = np.abs(s) / k, t / k
    centre = _ellipse(a, tt, 0.0, -0.1, 0.065, 0.18)
    side = _ellipse(a, tt, 0.12, -0.04, 0.045, 0.15, 0.55)
    scroll = np.abs(np.sqrt((a - 0.215) ** 2 + (tt + 0.17) ** 2) - 0.035) - 0.013
    collar = np.maximum(a - 0.15, np.abs(tt - 0.07) - 0.025)
    lower = _ellipse(a, tt, 0.07, 0.16, 0.03, 0.08, -0.6)
    bud = _ellipse(a, tt, 0.0, 0.19, 0.025, 0.05)
    fleur = np.minimum.reduce([centre, side, scroll, collar, lower, bud]) * k
    a = np.abs(s)
    half_width = 0.46 * np.cos(np.pi * np.clip(t, -0.5, 0.5))
    frame = np.abs(a - half_width) * 0.8 - 0.012
    return fleur, frame


@register
class DamaskWallpaper(_Wallpaper):
    """Damask-like wallpaper: a symmetric floral ornament in a half-drop repeat, tone-on-tone
    or contrasting, with a satin sheen on the motif."""

    name = "damask_wallpaper"
    tile_param = ("repeats", 0.53)
    params = {
        "palette": _pal_param(),
        "repeats": Param(1, 2, "int", doc="pairs of motif columns across the texture (the "
                         "half-drop repeat needs an even column count)"),
        "tone_on_tone": Param(kind="bool",
                              doc="motif a shade of the ground instead of the main colour"),
        "outline": Param(kind="bool", doc="inner outline detail in the accent colour"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """A symmetric floral ornament in a half-drop repeat, tone on tone."""
        bg, main, accent = self.colors(p, rng)
        n = 2 * int(p["repeats"])
        rows = n
        # columns are half-dropped: shift v by half a cell in odd columns
        u, v = nz.grid(res)
        x = u * F32(n) + F32(0.75)  # seam a quarter cell off the motif's mirror axis
        col_idx = np.floor(x)
        s = nz.fract(x) - F32(0.5)
        y = v * F32(rows) + F32(0.5) * (col_idx % 2)
        t = nz.fract(y) - F32(0.5)
        fleur, frame = _damask_sdf(s, t)
        fill = aa_step(fleur / F32(n), res)
        line = aa_step(frame / F32(n), res)
        # small diamond fillers where the frames meet
        dd = (np.abs(s) + np.abs(np.abs(t) - 0.5)) / F32(n) - F32(0.035 / n)
        motif = np.clip(fill + line + aa_step(dd, res), 0, 1)
        motif_c = scale_value(bg, 0.82) if p["tone_on_tone"] else main
        col = mix(solid(bg, res), motif_c, motif)
        if p["outline"]:
            ring = aa_step(np.abs(fleur + F32(0.018)) / F32(n) - F32(0.004 / n), res) * fill
            col = mix(col, accent, ring)
        return self.paper(res, rng, col, motif, 0.3)


@register
class GeometricWallpaper(_Wallpaper):
    """Geometric wallpaper: diamonds (argyle lattice), chevrons, polka dots, trellis or
    hexagon outlines."""

    name = "geometric_wallpaper"
    tile_size = 0.53
    params = {
        "palette": _pal_param(),
        "pattern": Param(kind="choice",
                         choices=("diamond", "chevron", "dots", "trellis", "hexagon"), doc="motif"),
        "repeats": Param(4, 12, "int", doc="pattern repeats across the texture"),
        "line_width": Param(0.02, 0.1, doc="line / feature weight, fraction of a repeat"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """The chosen geometric motif printed on the paper ground."""
        bg, main, accent = self.colors(p, rng)
        n = int(p["repeats"])
        w = F32(p["line_width"] / n)
        u, v = nz.grid(res)
        kind = p["pattern"]
        if kind == "diamond":
            a = np.abs(nz.fract((u + v) * F32(n)) - F32(0.5)) / F32(n)
            b = np.abs(nz.fract((u - v) * F32(n)) - F32(0.5)) / F32(n)
            cellc = (np.floor((u + v) * F32(n)) + np.floor((u - v) * F32(n))) % 2
            col = mix(solid(bg, res), main, np.broadcast_to(cellc * 0.35, (res, res)))
            line = aa_step(np.minimum(a, b) - w * 0.5, res)
            col = mix(col, accent, line)
            motif = line
        elif kind == "chevron":
            zig = np.abs(nz.fract(u * F32(n)) - F32(0.5))  # 0..0.5 triangle wave
            stripes = nz.fract(v * F32(n) + zig + F32(0.25))
            d = np.abs(stripes - F32(0.5)) / F32(n) - F32(0.25 / n)
            motif = aa_step(d, res, 1.4)
            col = mix(solid(bg, res), main, motif)
        elif kind == "dots":
            m = n + n % 2  # alternating rows need an even row count to wrap
            lay = nz.grid_layout(res, m, m, np.tile([0.0, 0.5], m // 2))
            d = np.sqrt((lay.a - F32(lay.length / 2)) ** 2 + (lay.b - F32(lay.width / 2)) ** 2)
            motif = aa_step(d - F32(0.18 / m + p["line_width"] * 0.5 / m), res)
            col = mix(solid(bg, res), main, motif)
        elif kind == "trellis":
            motif = np.zeros((res, res), F32)
            for du, dv in ((0.0, 0.0), (0.5, 0.5)):
                lu = nz.fract(u * F32(n) + F32(du)) - F32(0.5)
                lv = nz.fract(v * F32(n) + F32(dv)) - F32(0.5)
                ring = np.abs(np.sqrt(lu * lu + lv * lv) - F32(0.5)) / F32(n)
                motif = np.maximum(motif, aa_step(ring - w * 0.5, res))
            col = mix(solid(bg, res), main, motif)
        else:
            lay = nz.hex_layout(res, n)
            motif = aa_step(lay.edge - w * 0.5, res)
            col = mix(solid(bg, res), main, motif)
            dot = aa_step(np.sqrt(lay.a ** 2 + lay.b ** 2) - F32(0.06 / n), res)
            col = mix(col, accent, dot)
        return self.paper(res, rng, col, motif, 0.2)
