"""Smooth-surfaced materials: ceramic and porcelain, glass (with mirror and water), plastics
(including wax and fruit skin), rubber, cork and plaster.

Most of their character is in roughness and colour rather than pattern, so these generators are
mainly low-amplitude noise at the right scale: glaze pooling, sandblasting, stipple, orange peel.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from indoorgen.assets.materials import noise as nz
from indoorgen.assets.materials.base import Layers, MaterialGenerator, register
from indoorgen.assets.materials.color import jitter, mix, modulate, rgb, scale_value, solid
from indoorgen.assets.protocol import Param

F32 = np.float32


def speckles(res: int, rng: np.random.Generator, density: float, size: float = 0.6) -> np.ndarray:
    """Sparse small dots in [0, 1]: thresholded high-frequency noise. `size` (0..1) widens them."""
    n = nz.spectral_noise(res, rng, knee=res * (0.22 - 0.12 * size), beta=1.2, hi=res * 0.4)
    thr = 3.2 - 1.6 * density
    return nz.smoothstep(thr, thr + 0.4, n)


# --------------------------------------------------------------------------- ceramic

GLAZES = {"white": "#efeee9", "cream": "#ece2c8", "celadon": "#a8c4ae", "cobalt": "#2e4f8e",
          "terracotta": "#b8603c", "black": "#26272a", "sage": "#9fae92", "mustard": "#d0a23a",
          "blush": "#e2b4a6", "teal": "#2f7474"}


@register
class GlazedCeramic(MaterialGenerator):
    """Glossy glazed earthenware/stoneware: glaze pools darker and breaks lighter (variegation),
    with a few pinholes."""

    name = "glazed_ceramic"
    tile_size = 0.3
    family = "ceramic"
    density = 2400.0
    params = {
        "color": Param(kind="choice", choices=tuple(GLAZES), doc="glaze colour"),
        "variegation": Param(0.0, 1.0, doc="how strongly the glaze pools and breaks"),
        "roughness": Param(0.03, 0.14, doc="glaze roughness"),
        "pinholes": Param(0.0, 1.0, doc="density of small glaze pinholes"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Glossy glaze that pools darker and breaks lighter over the relief."""
        glaze = jitter(rgb(GLAZES[p["color"]]), rng, 0.01, 0.05, 0.04)
        pool = nz.spectral_noise(res, rng, knee=5.0, beta=1.6)
        fine = nz.spectral_noise(res, rng, knee=40.0, beta=1.2)
        v = F32(p["variegation"])
        col = modulate(glaze, 1.0 + v * (0.05 * pool + 0.015 * fine))
        col = mix(col, scale_value(glaze, 0.75), v * nz.smoothstep(1.0, 2.5, pool) * 0.4)
        holes = speckles(res, rng, 0.6 * p["pinholes"], 0.2)
        col = modulate(col, 1.0 - 0.3 * holes)
        rough = F32(p["roughness"]) + F32(0.01) * fine + F32(0.2) * holes
        height = 0.04 * pool - 0.5 * holes
        return Layers(col, rough, height, bump=0.5)


STONEWARE = {"oatmeal": "#d8ccb4", "grey": "#a9a7a2", "charcoal": "#4a4846",
             "terracotta": "#b8674a", "white": "#e4e0d8", "sand": "#cdb08a"}


@register
class MatteCeramic(MaterialGenerator):
    """Unglazed or satin-glazed stoneware: speckled with iron spots, dry and rough."""

    name = "matte_ceramic"
    tile_size = 0.3
    family = "ceramic"
    density = 2300.0
    params = {
        "color": Param(kind="choice", choices=tuple(STONEWARE), doc="clay / glaze colour"),
        "speckle": Param(0.0, 1.0, doc="density of dark iron speckles"),
        "roughness": Param(0.5, 0.85, doc="mean roughness"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Dry, rough stoneware speckled with iron spots."""
        base = jitter(rgb(STONEWARE[p["color"]]), rng, 0.01, 0.05, 0.04)
        low = nz.spectral_noise(res, rng, knee=4.0, beta=1.8)
        grain = nz.spectral_noise(res, rng, knee=100.0, beta=1.0)
        sp = speckles(res, rng, p["speckle"])
        col = modulate(base, 1.0 + 0.04 * low + 0.03 * grain)
        col = mix(col, rgb("#3a2a20"), sp * 0.8)
        rough = F32(p["roughness"]) + F32(0.05) * grain
        return Layers(col, rough, 0.06 * grain + 0.03 * low, bump=0.6)


@register
class Porcelain(MaterialGenerator):
    """Fine glazed porcelain (sanitaryware, tableware): pure white with a cool tint, very smooth."""

    name = "porcelain"
    tile_size = 0.3
    family = "ceramic"
    density = 2400.0
    params = {
        "tint": Param(kind="choice", choices=("white", "cool", "warm", "bone"),
                      doc="body colour"),
        "roughness": Param(0.03, 0.12, doc="glaze roughness"),
    }
    TINTS = {"white": "#f4f4f2", "cool": "#eef1f4", "warm": "#f4f0e8", "bone": "#ece6d8"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Pure white, very smooth, with a faint cool tint."""
        base = jitter(rgb(self.TINTS[p["tint"]]), rng, 0.005, 0.05, 0.01)
        low = nz.spectral_noise(res, rng, knee=3.0, beta=2.0)
        col = modulate(base, 1.0 + 0.006 * low)
        rough = F32(p["roughness"]) + F32(0.01) * low
        return Layers(col, rough, 0.02 * low, bump=0.3)


# --------------------------------------------------------------------------- glass

@register
class ClearGlass(MaterialGenerator):
    """Clear float glass: a faint green tint, mirror-smooth, mostly transparent (opacity < 1)."""

    name = "clear_glass"
    tile_size = 1.0
    family = "glass"
    density = 2500.0
    params = {
        "tint": Param(kind="choice", choices=("clear", "green", "bronze", "grey", "blue"),
                      doc="body tint"),
        "opacity": Param(0.08, 0.3, doc="opacity (1 - transmission) for exporters"),
    }
    TINTS = {"clear": "#eef4f2", "green": "#d4e8dc", "bronze": "#c8b49a", "grey": "#a8acae",
             "blue": "#c8dcec"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Faintly green, mirror-smooth, mostly transparent glass."""
        base = jitter(rgb(self.TINTS[p["tint"]]), rng, 0.005, 0.05, 0.02)
        wave = nz.spectral_noise(res, rng, knee=2.0, beta=2.5)
        dust = speckles(res, rng, 0.3, 0.1)
        g = nz.grain(res, rng)
        col = modulate(base, 1.0 - 0.05 * dust + 0.004 * g)
        rough = F32(0.015) + F32(0.2) * dust + F32(0.004) * g
        return Layers(col, rough, 0.05 * wave + 0.005 * g, bump=0.3, opacity=p["opacity"],
                      ior=1.52)


@register
class FrostedGlass(MaterialGenerator):
    """Sandblasted / acid-etched glass: diffusing, rough, translucent."""

    name = "frosted_glass"
    tile_size = 0.3
    family = "glass"
    density = 2500.0
    params = {
        "roughness": Param(0.4, 0.75, doc="roughness of the etched face"),
        "opacity": Param(0.4, 0.8, doc="opacity for exporters"),
        "tint": Param(kind="choice", choices=("white", "green", "grey"), doc="body tint"),
    }
    TINTS = {"white": "#eceeee", "green": "#dce8e2", "grey": "#c8cacc"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Rough, diffusing, translucent sandblasted glass."""
        base = jitter(rgb(self.TINTS[p["tint"]]), rng, 0.005, 0.05, 0.02)
        blast = nz.spectral_noise(res, rng, knee=res / 5, beta=0.8)
        low = nz.spectral_noise(res, rng, knee=4.0, beta=2.0)
        col = modulate(base, 1.0 + 0.02 * blast + 0.01 * low)
        rough = F32(p["roughness"]) + F32(0.05) * blast
        return Layers(col, rough, 0.08 * blast, bump=0.5, opacity=p["opacity"], ior=1.52)


@register
class ScreenGlass(MaterialGenerator):
    """A switched-off display: near-black glossy glass with faint smudges. Opaque."""

    name = "screen_glass"
    tile_size = 0.5
    family = "glass"
    density = 2500.0
    params = {
        "roughness": Param(0.02, 0.1, doc="roughness of the cover glass / anti-glare coating"),
        "smudges": Param(0.0, 1.0, doc="amount of fingerprint smudging"),
        "tint": Param(kind="choice", choices=("black", "blue_black", "grey"), doc="panel colour"),
    }
    TINTS = {"black": "#0e0f10", "blue_black": "#0b0e14", "grey": "#1c1d1f"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Near-black glossy glass with faint smudges and a pixel grid."""
        base = jitter(rgb(self.TINTS[p["tint"]]), rng, 0.005, 0.05, 0.05)
        smudge = nz.spectral_noise(res, rng, knee=8.0, beta=1.6)
        sm = nz.smoothstep(0.6, 1.8, smudge) * F32(p["smudges"])
        pixel = nz.spectral_noise(res, rng, knee=res / 3, beta=0.5)
        col = modulate(base, 1.0 + 0.3 * sm + 0.04 * pixel)
        rough = F32(p["roughness"]) + F32(0.15) * sm + F32(0.01) * pixel
        return Layers(col, rough, 0.01 * pixel, bump=0.2)


@register
class Mirror(MaterialGenerator):
    """Silvered mirror: rendered as a near-perfect metallic reflector (metallic 1). Family glass
    because that is what it is physically (and what its density is)."""

    name = "mirror"
    tile_size = 1.0
    family = "glass"
    density = 2500.0
    params = {
        "roughness": Param(0.0, 0.04, doc="roughness (blur of reflections)"),
        "tint": Param(kind="choice", choices=("silver", "bronze", "grey"), doc="silvering tint"),
        "age": Param(0.0, 0.3, doc="desilvering spots of an old mirror"),
    }
    TINTS = {"silver": "#e8eaea", "bronze": "#cdb89c", "grey": "#a4a8aa"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """A near-perfect metallic reflector, dimmed where the silvering has aged."""
        base = jitter(rgb(self.TINTS[p["tint"]]), rng, 0.004, 0.03, 0.02)
        spots = nz.spectral_noise(res, rng, knee=24.0, beta=1.2)
        thr = 3.0 - 3.0 * p["age"]
        old = nz.smoothstep(thr, thr + 0.6, spots) * F32(min(1.0, 3 * p["age"]))
        g = nz.grain(res, rng)
        col = mix(modulate(base, 1.0 + 0.004 * g), rgb("#4a4a46"), old * 0.7)
        rough = F32(p["roughness"]) + F32(0.3) * old + F32(0.004) * g
        return Layers(col, rough, 0.003 * g, bump=0.3, metallic=1.0 - 0.8 * old, ior=1.52)


@register
class Water(MaterialGenerator):
    """Still water (vases, glasses, aquariums): clear, faintly tinted, with gentle ripples.
    Family glass: it renders as a transparent dielectric, with water's own IOR and density."""

    name = "water"
    family = "glass"
    density = 1000.0
    tile_size = 0.3
    params = {
        "tint": Param(kind="choice", choices=("clear", "blue", "green"), doc="body tint"),
        "ripples": Param(0.0, 1.0, doc="ripple strength"),
        "opacity": Param(0.05, 0.25, doc="opacity for exporters"),
    }
    TINTS = {"clear": "#eef6f6", "blue": "#d4e6ee", "green": "#d6e8dc"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Clear, faintly tinted water with gentle ripples."""
        base = jitter(rgb(self.TINTS[p["tint"]]), rng, 0.005, 0.05, 0.02)
        ripple = nz.band_noise(res, rng, 6.0, 3.0, stretch=(1.0, 1.6))
        g = nz.grain(res, rng)
        col = modulate(base, 1.0 + 0.01 * ripple + 0.003 * g)
        rough = F32(0.01) + F32(0.003) * g
        return Layers(col, rough, F32(0.6 * p["ripples"]) * ripple + 0.003 * g, bump=0.5,
                      opacity=p["opacity"], ior=1.33)


# --------------------------------------------------------------------------- plastics

PLASTICS = {"white": "#ecebe8", "black": "#1e1f21", "red": "#c02a24", "blue": "#2458b0",
            "yellow": "#f0c020", "green": "#3a9a4a", "grey": "#8a8d90", "beige": "#d8ccb0",
            "orange": "#e86a20", "pink": "#e888a8", "teal": "#209898", "charcoal": "#3a3c3e"}


def _plastic_params(rough: tuple[float, float]) -> dict[str, Param]:
    return {"color": Param(kind="choice", choices=tuple(PLASTICS), doc="pigment colour"),
            "roughness": Param(rough[0], rough[1], doc="mean roughness")}


@register
class GlossyPlastic(MaterialGenerator):
    """Injection-moulded glossy plastic (ABS, acrylic): saturated, smooth, faint flow marks."""

    name = "glossy_plastic"
    tile_size = 0.3
    family = "plastic"
    density = 1050.0
    params = _plastic_params((0.04, 0.2))

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Saturated, smooth plastic with faint flow marks."""
        base = jitter(rgb(PLASTICS[p["color"]]), rng, 0.01, 0.05, 0.04)
        flow = nz.spectral_noise(res, rng, knee=3.0, beta=2.2, stretch=(3.0, 1.0))
        col = modulate(base, 1.0 + 0.015 * flow)
        rough = F32(p["roughness"]) + F32(0.02) * flow
        return Layers(col, rough, 0.02 * flow, bump=0.3)


@register
class MattePlastic(MaterialGenerator):
    """Matte plastic (polypropylene, bead-blasted ABS): fine uniform micro-grain."""

    name = "matte_plastic"
    tile_size = 0.2
    family = "plastic"
    density = 1000.0
    params = _plastic_params((0.45, 0.8))

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Plastic with a fine uniform micro-grain."""
        base = jitter(rgb(PLASTICS[p["color"]]), rng, 0.01, 0.05, 0.04)
        grain = nz.spectral_noise(res, rng, knee=res / 4, beta=0.7)
        low = nz.spectral_noise(res, rng, knee=3.0, beta=2.0)
        col = modulate(base, 1.0 + 0.012 * grain + 0.015 * low)
        rough = F32(p["roughness"]) + F32(0.04) * grain
        return Layers(col, rough, 0.05 * grain, bump=0.4)


@register
class TexturedPlastic(MaterialGenerator):
    """Textured (stippled or leather-grain) moulded plastic, as on appliance housings and
    monitor backs: a cellular bump pattern."""

    name = "textured_plastic"
    tile_param = ("cells", 0.001)
    family = "plastic"
    density = 1050.0
    params = {**_plastic_params((0.4, 0.7)),
              "cells": Param(40, 110, "int", doc="stipple cells across the texture"),
              "depth": Param(0.3, 1.0, doc="relief depth")}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Stippled or leather-grain moulded plastic."""
        base = jitter(rgb(PLASTICS[p["color"]]), rng, 0.01, 0.05, 0.04)
        cells = nz.worley(res, p["cells"], rng, 0.9)
        bump = nz.smoothstep(0.0, 0.35, cells.border)
        col = modulate(base, 0.95 + 0.05 * bump)
        rough = F32(p["roughness"]) + F32(0.08) * (1 - bump)
        return Layers(col, rough, F32(p["depth"]) * 0.5 * bump, bump=0.7)


WAXES = {"ivory": "#eee4cc", "white": "#f2efe6", "red": "#a8242a", "honey": "#d8a452",
         "sage": "#a8b496", "navy": "#2e3a5a", "lavender": "#b8a8c8"}


@register
class Wax(MaterialGenerator):
    """Candle wax (paraffin, beeswax): soft waxy sheen, faint vertical drips and mottling.
    Family plastic: it renders as a smooth non-metal dielectric."""

    name = "wax"
    tile_size = 0.1
    family = "plastic"
    density = 900.0
    params = {
        "color": Param(kind="choice", choices=tuple(WAXES), doc="wax colour"),
        "roughness": Param(0.3, 0.55, doc="mean roughness"),
        "drips": Param(0.0, 1.0, doc="strength of vertical drip streaks"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Soft waxy sheen with faint vertical drips and mottling."""
        base = jitter(rgb(WAXES[p["color"]]), rng, 0.01, 0.05, 0.04)
        drip = nz.spectral_noise(res, rng, knee=10.0, beta=1.4, stretch=(1.0, 8.0))
        mottle = nz.spectral_noise(res, rng, knee=6.0, beta=1.6)
        d = F32(p["drips"])
        col = modulate(base, 1.0 + 0.04 * mottle + 0.04 * d * drip)
        rough = F32(p["roughness"]) + F32(0.05) * mottle
        return Layers(col, rough, 0.08 * d * drip + 0.03 * mottle, bump=0.5)


FRUITS = {  # base, blush/secondary, spot colour
    "red_apple": ("#b8282a", "#d8b040", "#e8d8a0"),
    "green_apple": ("#8cc050", "#c8d060", "#e8ecc0"),
    "orange": ("#f08a1c", "#f8a030", "#f8b848"),
    "lemon": ("#f2d43a", "#e8e050", "#f8e878"),
    "lime": ("#6aa830", "#88b840", "#a8cc60"),
    "pear": ("#c8c050", "#a89038", "#806028"),
}


@register
class FruitSkin(MaterialGenerator):
    """Fruit skin for food props: apple (blush, lenticel dots, waxy), citrus (dimpled peel) or
    pear (russet speckles). Family plastic: a waxy cuticle renders like a smooth dielectric."""

    name = "fruit_skin"
    tile_size = 0.08
    family = "plastic"
    density = 850.0
    params = {
        "fruit": Param(kind="choice", choices=tuple(FRUITS), doc="kind of fruit"),
        "blush": Param(0.0, 1.0, doc="amount of secondary colour (apple blush, uneven ripening)"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Apple, citrus or other fruit skin: blush, dimples, lenticels."""
        c0, c1, c2 = (jitter(rgb(c), rng, 0.01, 0.05, 0.05) for c in FRUITS[p["fruit"]])
        citrus = p["fruit"] in ("orange", "lemon", "lime")
        streak = nz.spectral_noise(res, rng, knee=6.0, beta=1.6, stretch=(1.0, 4.0))
        blush = nz.smoothstep(-0.5, 1.5, streak) * F32(p["blush"])
        col = mix(solid(c0, res), c1, blush)
        if citrus:
            f = min(70.0, res / 4)  # oil-gland dimples, ~70 across the texture
            dimples = nz.band_noise(res, rng, f, f / 3)
            col = modulate(col, 1.0 + 0.05 * dimples)
            height = 0.3 * dimples
            rough = F32(0.45) + F32(0.05) * dimples
        else:
            dots = speckles(res, rng, 0.5 if p["fruit"] != "pear" else 0.9, 0.3)
            g = nz.grain(res, rng)
            col = modulate(mix(col, c2, dots * 0.8), 1.0 + 0.01 * g)
            height = 0.1 * dots + 0.01 * g
            rough = F32(0.3 if p["fruit"] != "pear" else 0.6) + F32(0.2) * dots + F32(0.02) * g
        return Layers(col, rough, height, bump=0.6)


# --------------------------------------------------------------------------- rubber, cork, plaster

@register
class Rubber(MaterialGenerator):
    """Moulded rubber (mats, feet, seals, tyres): dark, matte, optionally coin-studded or
    ribbed."""

    name = "rubber"
    tile_param = ("pattern_scale", 0.025)
    family = "rubber"
    density = 1150.0
    params = {
        "color": Param(kind="choice", choices=("black", "charcoal", "grey", "red", "blue"),
                       doc="compound colour"),
        "pattern": Param(kind="choice", choices=("smooth", "coin", "ribbed"),
                         doc="moulded relief"),
        "pattern_scale": Param(6, 16, "int", doc="studs or ribs across the texture"),
        "roughness": Param(0.7, 0.95, doc="mean roughness"),
    }
    COLORS = {"black": "#1c1c1d", "charcoal": "#2e2f30", "grey": "#56585a", "red": "#7a2420",
              "blue": "#28384e"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Dark matte rubber, optionally with a coin-stud or ribbed relief."""
        base = jitter(rgb(self.COLORS[p["color"]]), rng, 0.01, 0.05, 0.06)
        grain = nz.spectral_noise(res, rng, knee=res / 4, beta=0.8)
        low = nz.spectral_noise(res, rng, knee=4.0, beta=2.0)
        n = int(p["pattern_scale"])
        height = 0.04 * grain
        if p["pattern"] == "coin":
            lay = nz.grid_layout(res, n, n)
            dx = lay.a - F32(lay.length / 2)
            dy = lay.b - F32(lay.width / 2)
            d = np.sqrt(dx * dx + dy * dy) * F32(n)
            relief = nz.smoothstep(0.3 + 1.5 / res * n, 0.3, d)
        elif p["pattern"] == "ribbed":
            _, v = nz.grid(res)
            relief = np.broadcast_to(0.5 + 0.5 * np.cos(2 * np.pi * v * n), (res, res))
            relief = nz.smoothstep(0.25, 0.75, relief)
        else:
            relief = np.zeros((res, res), F32)
        col = modulate(base, 1.0 + 0.04 * low + 0.03 * grain + 0.08 * relief)
        rough = F32(p["roughness"]) + F32(0.03) * grain - F32(0.06) * relief
        return Layers(col, rough, height + 0.6 * relief, bump=0.7)


@register
class Cork(MaterialGenerator):
    """Agglomerated cork board / tiles: pressed granules of varying tone with dark gaps."""

    name = "cork"
    tile_param = ("granules", 0.005)
    family = "cork"
    density = 240.0
    params = {
        "granules": Param(35, 80, "int", doc="granules across the texture"),
        "tone": Param(kind="choice", choices=("natural", "light", "dark"), doc="cork colour"),
        "contrast": Param(0.15, 0.4, doc="granule-to-granule tone variation"),
    }
    TONES = {"natural": "#b88a58", "light": "#d0aa78", "dark": "#8a5e38"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Pressed granules of varying tone with dark gaps between them."""
        base = jitter(rgb(self.TONES[p["tone"]]), rng, 0.01, 0.05, 0.04)
        cells = nz.worley(res, p["granules"], rng, 1.0)
        n = cells.n * cells.n
        tone = (1.0 + 2 * p["contrast"] * (rng.random(n) - 0.5)).astype(F32)[cells.cell]
        gap = nz.smoothstep(0.0, 0.12, cells.border)
        fine = nz.spectral_noise(res, rng, knee=res / 4, beta=0.8)
        pits = speckles(res, rng, 0.6, 0.4)
        col = modulate(base, tone * (0.6 + 0.4 * gap) * (1 + 0.05 * fine) * (1 - 0.4 * pits))
        rough = F32(0.85) + F32(0.05) * fine
        height = 0.5 * gap + 0.2 * (tone - 1) + 0.05 * fine - 0.4 * pits
        return Layers(col, rough, height, bump=0.6)


WALL_PAINTS = {"white": "#f0eee8", "warm_white": "#eee6d6", "greige": "#cbc2b4",
               "pale_blue": "#c8d6de", "pale_green": "#cfd8c4", "terracotta": "#c48a6c",
               "charcoal": "#4e5052", "blush": "#e4c8be", "ochre": "#d8b470", "sage": "#a9b39c"}


@register
class Plaster(MaterialGenerator):
    """Painted smooth plaster wall: barely visible trowel undulation and fine paint texture."""

    name = "plaster"
    tile_size = 1.5
    family = "plaster"
    density = 1100.0
    params = {
        "color": Param(kind="choice", choices=tuple(WALL_PAINTS), doc="paint colour"),
        "trowel": Param(0.0, 1.0, doc="visibility of trowel marks (0 = perfectly flat)"),
        "roughness": Param(0.7, 0.95, doc="paint roughness (matte to eggshell)"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Painted plaster with faint trowel undulation and fine paint texture."""
        base = jitter(rgb(WALL_PAINTS[p["color"]]), rng, 0.005, 0.04, 0.02)
        trowel = nz.spectral_noise(res, rng, knee=4.0, beta=1.8, angle=rng.uniform(0, 3.14),
                                   stretch=(1.0, 2.0))
        fine = nz.spectral_noise(res, rng, knee=res / 4, beta=0.8)
        t = F32(p["trowel"])
        col = modulate(base, 1.0 + 0.025 * t * trowel + 0.01 * fine)
        rough = F32(p["roughness"]) + F32(0.03) * fine - F32(0.04) * t * trowel
        return Layers(col, rough, 0.15 * t * trowel + 0.03 * fine, bump=0.5)


@register
class Stucco(MaterialGenerator):
    """Textured plaster: knock-down (flattened splatter plateaus) or sand-float finish."""

    name = "stucco"
    tile_size = 1.0
    family = "plaster"
    density = 1800.0
    params = {
        "color": Param(kind="choice", choices=tuple(WALL_PAINTS), doc="paint colour"),
        "style": Param(kind="choice", choices=("knockdown", "sand", "venetian"),
                       doc="texture style"),
        "scale": Param(6.0, 16.0, doc="feature size: splats across the texture"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Knock-down plateaus or a sand-float finish in plaster."""
        base = jitter(rgb(WALL_PAINTS[p["color"]]), rng, 0.005, 0.04, 0.03)
        if p["style"] == "knockdown":
            n = nz.spectral_noise(res, rng, knee=p["scale"] * 1.5, beta=1.3)
            height: np.ndarray = nz.smoothstep(0.2, 0.5, n) + 0.2 * nz.smoothstep(0.9, 1.1, n)
            col = modulate(base, 0.95 + 0.06 * height)
            rough = F32(0.85) - F32(0.08) * height
        elif p["style"] == "sand":
            n = nz.spectral_noise(res, rng, knee=res / 4, beta=0.6)
            low = nz.spectral_noise(res, rng, knee=p["scale"], beta=1.8)
            height = 0.3 * n + 0.1 * low
            col = modulate(base, 1.0 + 0.04 * n + 0.02 * low)
            rough = F32(0.9) + F32(0.04) * n
        else:
            n = nz.spectral_noise(res, rng, knee=p["scale"] * 0.6, beta=1.5, stretch=(1.0, 2.5),
                                  angle=0.6)
            f = nz.spectral_noise(res, rng, knee=p["scale"] * 3, beta=1.3, stretch=(2.0, 1.0))
            col = modulate(base, 1.0 + 0.08 * n + 0.04 * f)
            rough = F32(0.35) + F32(0.1) * nz.smoothstep(-1, 1, f)
            height = 0.05 * n
        return Layers(col, rough, height, bump=0.6)
