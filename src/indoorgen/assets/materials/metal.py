"""Metals: brushed steel, chrome, brass (and bronze/copper), painted metal, rusty and galvanised
steel.

Per PBR convention a metal's base colour is its specular reflectance (bright, e.g. ~0.56-0.6 for
iron/steel, warm yellow for brass) and metallic is 1; painted, rusted or oxidised regions are
dielectric, so those materials carry a metallic map that drops to 0 there.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from indoorgen.assets.materials import noise as nz
from indoorgen.assets.materials.base import Layers, MaterialGenerator, register
from indoorgen.assets.materials.color import jitter, mix, modulate, ramp, rgb, scale_value
from indoorgen.assets.protocol import Param

F32 = np.float32

METAL_TONES = {"steel": "#b4b6b8", "stainless": "#c4c6c8", "aluminium": "#d2d4d6",
               "dark_steel": "#8e9094", "titanium": "#a8a49e"}


def brush_streaks(res: int, rng: np.random.Generator, length: float = 0.25) -> np.ndarray:
    """Fine scratches running along u, about `length` of the texture long and a pixel or two
    wide: noise whose u frequencies are compressed so that they stay around 1 / length."""
    knee = res / 6.0
    return nz.spectral_noise(res, rng, knee=knee, beta=0.7, hi=res * 0.45,
                             stretch=(max(2.0, knee * length), 1.0))


class _Metal(MaterialGenerator):
    family = "metal"
    density = 7850.0


@register
class BrushedSteel(_Metal):
    """Brushed stainless steel or aluminium: fine parallel scratches along u, anisotropic look."""

    name = "brushed_steel"
    tile_size = 0.4
    params = {
        "tone": Param(kind="choice", choices=("steel", "stainless", "aluminium", "dark_steel",
                                              "titanium"), doc="alloy colour"),
        "brush": Param(0.4, 1.0, doc="strength of the brushing scratches"),
        "roughness": Param(0.22, 0.45, doc="mean roughness"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Alloy colour with fine brushing streaks along u in colour, roughness and relief."""
        base = jitter(rgb(METAL_TONES[p["tone"]]), rng, 0.01, 0.05, 0.03)
        streak = brush_streaks(res, rng)
        coarse = brush_streaks(res, rng, 0.15)
        low = nz.spectral_noise(res, rng, knee=3.0, beta=2.0)
        g = nz.grain(res, rng)
        b = F32(p["brush"])
        col = modulate(base, 1.0 + b * (0.05 * streak + 0.03 * coarse) + 0.02 * low + 0.01 * g)
        rough = F32(p["roughness"]) + b * F32(0.05) * streak + F32(0.03) * low + F32(0.01) * g
        height = b * (0.04 * streak + 0.03 * coarse) + 0.01 * g
        return Layers(col, rough, height, bump=0.5, metallic=np.ones((res, res), F32))


@register
class Chrome(_Metal):
    """Polished chrome / nickel plating: near-mirror, with faint smudges and hairline scratches."""

    name = "chrome"
    tile_size = 0.3
    params = {
        "roughness": Param(0.02, 0.08, doc="mean roughness (0 = perfect mirror)"),
        "smudges": Param(0.0, 1.0, doc="amount of fingerprint-like smudging"),
        "tint": Param(kind="choice", choices=("chrome", "nickel", "silver"),
                      doc="plating colour"),
    }
    TINTS = {"chrome": "#d8dadc", "nickel": "#d4cfc4", "silver": "#e6e6e4"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """A near-mirror plating with faint smudges and hairline scratches."""
        base = jitter(rgb(self.TINTS[p["tint"]]), rng, 0.005, 0.02, 0.02)
        smudge = nz.spectral_noise(res, rng, knee=6.0, beta=1.8)
        sm = nz.smoothstep(0.5, 1.8, smudge) * F32(p["smudges"])
        scratch = nz.spectral_noise(res, rng, knee=res / 4, beta=0.5, stretch=(30.0, 1.0),
                                    angle=0.4)
        hair = nz.smoothstep(3.0, 3.8, scratch)
        g = nz.grain(res, rng)
        col = modulate(base, 1.0 - 0.03 * sm - 0.05 * hair + 0.004 * g)
        rough = F32(p["roughness"]) + F32(0.12) * sm + F32(0.1) * hair + F32(0.006) * g
        return Layers(col, rough, 0.01 * g - 0.05 * hair, bump=0.5,
                      metallic=np.ones((res, res), F32))


@register
class Brass(_Metal):
    """Brass, bronze or copper, polished or brushed, with optional patchy tarnish."""

    name = "brass"
    tile_size = 0.3
    density = 8500.0
    params = {
        "alloy": Param(kind="choice", choices=("brass", "bronze", "copper", "gold"),
                       doc="alloy colour"),
        "brushed": Param(kind="bool", doc="brushed (true) or polished (false)"),
        "tarnish": Param(0.0, 0.4, doc="tarnished fraction: darker, rougher, duller patches"),
    }
    ALLOYS = {"brass": "#e0c27a", "bronze": "#c99a62", "copper": "#e0a080", "gold": "#f0cf72"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Polished or brushed brass, bronze or copper with patchy, less metallic tarnish."""
        base = jitter(rgb(self.ALLOYS[p["alloy"]]), rng, 0.008, 0.05, 0.03)
        streak = brush_streaks(res, rng) if p["brushed"] else nz.spectral_noise(res, rng, knee=4.0)
        amt = 0.05 if p["brushed"] else 0.01
        tn = nz.spectral_noise(res, rng, knee=4.0, beta=1.8)
        thr = 1.6 - 2.6 * p["tarnish"]
        tar = nz.smoothstep(thr - 0.6, thr + 1.4, tn) * F32(min(1.0, p["tarnish"] * 2.5))
        g = nz.grain(res, rng)
        col = modulate(base, 1.0 + F32(amt) * streak + 0.005 * g)
        col = mix(col, scale_value(base, 0.62) * rgb("#c8b8a0"), tar * 0.6)
        r0 = 0.28 if p["brushed"] else 0.08
        rough = F32(r0) + F32(amt) * streak + F32(0.4) * tar + F32(0.01) * g
        metal = 1.0 - 0.4 * tar
        return Layers(col, rough, F32(amt) * streak, bump=0.5, metallic=metal)


PAINTS = {"white": "#e9e9e6", "black": "#222324", "red": "#b3261e", "blue": "#2b5c9e",
          "green": "#3c6e47", "yellow": "#e0b422", "grey": "#7d8186", "cream": "#e6dcc4",
          "orange": "#d8642a", "teal": "#2a7a7a"}


@register
class PaintedMetal(_Metal):
    """Powder-coated / enamel-painted steel (appliances, filing cabinets, lamp bases): orange-peel
    texture; optional chips showing bare metal, which is where the metallic map is 1."""

    name = "painted_metal"
    tile_size = 0.5
    params = {
        "color": Param(kind="choice", choices=tuple(PAINTS), doc="paint colour"),
        "gloss": Param(0.0, 1.0, doc="0 = matte powder coat, 1 = glossy enamel"),
        "orange_peel": Param(0.2, 1.0, doc="strength of the orange-peel relief"),
        "chips": Param(0.0, 0.5, doc="amount of chipped paint"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Paint colour with orange-peel relief; chips show bare metal where asked."""
        paint = jitter(rgb(PAINTS[p["color"]]), rng, 0.01, 0.04, 0.04)
        peel = nz.band_noise(res, rng, 48.0, 20.0)
        low = nz.spectral_noise(res, rng, knee=3.0, beta=2.0)
        g = nz.grain(res, rng)
        col = modulate(paint, 1.0 + 0.015 * peel + 0.02 * low + 0.008 * g)
        rough = F32(0.55 - 0.45 * p["gloss"]) + F32(0.03) * peel + F32(0.01) * g
        height: np.ndarray = F32(0.1 * p["orange_peel"]) * peel
        metal: np.ndarray = np.zeros((res, res), F32)
        if p["chips"] > 0.02:
            cn = nz.spectral_noise(res, rng, knee=14.0, beta=1.6)
            thr = 3.2 - 2.2 * p["chips"]
            chip = nz.smoothstep(thr, thr + 0.15, cn)
            rim = nz.smoothstep(thr - 0.3, thr, cn) * (1 - chip)
            col = mix(col, rgb("#9a9ca0"), chip)
            col = modulate(col, 1.0 - 0.25 * rim)
            rough = rough * (1 - chip) + F32(0.4) * chip
            height = height - 0.4 * chip
            metal = chip
        return Layers(col, rough, height, bump=0.6, metallic=metal)


@register
class RustyMetal(_Metal):
    """Weathered steel with rust patches: the rust is rough, orange-brown, flaky and not
    metallic."""

    name = "rusty_metal"
    tile_size = 1.0
    density = 7800.0
    params = {
        "rust": Param(0.2, 0.95, doc="rusted fraction of the surface"),
        "pitting": Param(0.0, 1.0, doc="depth of corrosion pits and flakes"),
        "hue": Param(kind="choice", choices=("orange", "brown", "dark"), doc="rust colour"),
    }
    HUES = {"orange": ("#5a2e16", "#9c4a1e", "#c8743a"), "brown": ("#3e2414", "#6e3a1e", "#9a5a30"),
            "dark": ("#2a1a12", "#4e2a18", "#7a4424")}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Steel with rough, flaky, non-metallic rust patches."""
        c0, c1, c2 = (jitter(rgb(c), rng, 0.01, 0.05, 0.05) for c in self.HUES[p["hue"]])
        steel = jitter(rgb("#8f9194"), rng, 0.01, 0.05, 0.05)
        field = nz.smooth_warp(res, rng, 5.0, 0.015, beta=1.5)
        grain = nz.spectral_noise(res, rng, knee=80.0, beta=0.9)
        field = field + 0.3 * nz.spectral_noise(res, rng, knee=30.0, beta=1.0) + 0.15 * grain
        thr = 1.4 - 2.8 * p["rust"]
        rust = nz.smoothstep(thr - 0.35, thr + 0.35, field)
        tone = nz.unit(nz.spectral_noise(res, rng, knee=12.0, beta=1.4) + 0.3 * grain)
        rust_col = ramp(tone, [(0.0, c0), (0.5, c1), (1.0, c2)])
        streak = brush_streaks(res, rng, 0.15)
        col = mix(modulate(steel, 1.0 + 0.05 * streak), rust_col, rust)
        pits = nz.smoothstep(1.5, 2.5, grain) * F32(p["pitting"])
        rough = F32(0.4) + F32(0.05) * streak
        rough = rough * (1 - rust) + (F32(0.82) + F32(0.08) * grain) * rust
        height = 0.25 * rust + 0.12 * grain * rust - 0.5 * pits * rust
        return Layers(col, rough, height, bump=0.7, metallic=1.0 - rust)


@register
class GalvanizedSteel(_Metal):
    """Hot-dip galvanised steel: zinc spangle crystals of differing brightness and a white
    oxide bloom."""

    name = "galvanized_steel"
    tile_param = ("spangle", 0.02)
    params = {
        "spangle": Param(5, 14, "int", doc="spangle crystals across the texture"),
        "contrast": Param(0.05, 0.2, doc="brightness difference between crystals"),
        "oxide": Param(0.0, 0.6, doc="amount of dull white zinc-oxide bloom"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Zinc spangle crystals of differing brightness and white-rust bloom."""
        cells = nz.worley(res, p["spangle"], rng, 1.0)
        n = cells.n * cells.n
        bright = (1.0 + 2 * p["contrast"] * (rng.random(n) - 0.5)).astype(F32)[cells.cell]
        angle = rng.uniform(0, np.pi, n).astype(F32)[cells.cell]
        dend = nz.spectral_noise(res, rng, knee=res / 6, beta=0.8, stretch=(8.0, 1.0))
        dend2 = nz.spectral_noise(res, rng, knee=res / 6, beta=0.8, stretch=(1.0, 8.0))
        feather = np.cos(angle) ** 2 * dend + np.sin(angle) ** 2 * dend2
        base = jitter(rgb("#b8bcbe"), rng, 0.01, 0.05, 0.03)
        col = modulate(base, bright + 0.03 * feather)
        ox = nz.spectral_noise(res, rng, knee=6.0, beta=1.6)
        thr = 1.8 - 2.0 * p["oxide"]
        bloom = nz.smoothstep(thr, thr + 1.2, ox) * F32(min(1.0, 2 * p["oxide"]))
        col = mix(col, rgb("#d4d6d4"), bloom * 0.7)
        border = nz.smoothstep(0.0, 0.04, cells.border)
        rough = (0.3 + 0.2 * (bright - 1.0) / max(p["contrast"], 1e-3) * 0.5 + 0.03 * feather
                 + 0.35 * bloom + 0.015 * nz.grain(res, rng)).astype(F32)
        height = 0.05 * border + 0.02 * feather
        return Layers(col, rough, height, bump=0.5, metallic=1.0 - 0.6 * bloom)
