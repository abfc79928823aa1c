"""Stone and mineral materials: marble, granite, concrete, terrazzo, slate, and soil (potting
soil, grouped with stone as a granular mineral surface).

Marble veins are the zero-crossings of domain-warped noise (thin, branching, flowing lines whose
width varies with the local gradient); granite and terrazzo are cellular (Worley) mosaics with a
random mineral or chip colour per cell.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from indoorgen.assets.materials import noise as nz
from indoorgen.assets.materials.base import Layers, MaterialGenerator, register
from indoorgen.assets.materials.color import jitter, mix, modulate, rgb, solid
from indoorgen.assets.protocol import Param

F32 = np.float32

STONE_FINISH = {"polished": (0.04, 0.12), "honed": (0.3, 0.45), "matte": (0.55, 0.7)}


def _finish_roughness(rng: np.random.Generator, finish: str) -> float:
    lo, hi = STONE_FINISH[finish]
    return float(rng.uniform(lo, hi))


def veins(res: int, rng: np.random.Generator, freq: float, width: float,
          warp_amount: float) -> np.ndarray:
    """Thin flowing lines in [0, 1] at the zero-crossings of warped noise. `freq` sets vein
    spacing (cycles per texture), `width` their thickness (noise units), `warp_amount` how
    turbulent they are (texture units)."""
    base = nz.smooth_warp(res, rng, freq, warp_amount, stretch=(1.0, 0.5),
                          angle=rng.uniform(0, 3.1))
    detail = nz.spectral_noise(res, rng, knee=freq * 6, beta=1.2, hi=res / 3)
    f = base + 0.04 * detail
    return nz.smoothstep(width, 0.0, np.abs(f)) + 0.25 * nz.smoothstep(width * 6, 0.0, np.abs(f))


MARBLES = {  # ground, secondary cloud, vein
    "carrara": ("#eceae6", "#d4d4d4", "#7c8088"),
    "calacatta": ("#f2efe8", "#e4dccc", "#8a7a60"),
    "nero_marquina": ("#1e1e20", "#2c2c30", "#e8e6e2"),
    "verde": ("#1e3a30", "#2e5244", "#d8e4dc"),
    "grey": ("#8c8e90", "#a8aaac", "#e4e4e2"),
    "rosa": ("#e4c8bc", "#d8b0a0", "#a07060"),
}


@register
class Marble(MaterialGenerator):
    """Marble: cloudy ground crossed by branching veins at two scales."""

    name = "marble"
    tile_size = 1.2
    family = "stone"
    density = 2700.0
    params = {
        "kind": Param(kind="choice", choices=tuple(MARBLES), doc="marble variety (colours)"),
        "vein_density": Param(1.5, 5.0, doc="major veins across the texture"),
        "vein_width": Param(0.04, 0.15, doc="major vein thickness (in units of the vein noise)"),
        "turbulence": Param(0.02, 0.1, doc="domain-warp strength: how wild the veins flow"),
        "finish": Param(kind="choice", choices=("polished", "honed"), doc="surface finish"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """A cloudy ground crossed by branching veins at two scales."""
        g, c, v = (jitter(rgb(x), rng, 0.01, 0.05, 0.03) for x in MARBLES[p["kind"]])
        cloud = nz.spectral_noise(res, rng, knee=3.0, beta=1.8, hi=40.0)
        col = mix(solid(g, res), c, nz.smoothstep(-1.0, 2.0, cloud))
        major = veins(res, rng, p["vein_density"], p["vein_width"], p["turbulence"])
        minor = veins(res, rng, p["vein_density"] * 3, p["vein_width"] * 0.5, p["turbulence"] * 0.6)
        fine = nz.spectral_noise(res, rng, knee=60.0, beta=1.0)
        col = mix(col, v, np.clip(0.8 * major + 0.25 * minor, 0, 1) * (0.85 + 0.15 * fine))
        g = nz.grain(res, rng)
        col = modulate(col, 1.0 + 0.02 * fine + 0.012 * g)
        rough = (F32(_finish_roughness(rng, p["finish"])) + F32(0.01) * fine + F32(0.03) * major
                 + F32(0.01) * g)
        return Layers(col, rough, 0.02 * fine - 0.03 * major, bump=0.4)


GRANITES = {  # mineral colours and their proportions
    "salt_pepper": [("#e8e6e2", 0.45), ("#8e8c8a", 0.35), ("#1e1e20", 0.2)],
    "black_galaxy": [("#121214", 0.8), ("#2a2826", 0.15), ("#c8a860", 0.05)],
    "pink": [("#d49a8c", 0.45), ("#b8b4ae", 0.3), ("#2a2624", 0.25)],
    "kashmir": [("#ece6dc", 0.6), ("#b0aaa2", 0.3), ("#8a2e2a", 0.1)],
    "blue_pearl": [("#3a4450", 0.55), ("#6a7a8a", 0.3), ("#1c1e22", 0.15)],
    "baltic_brown": [("#6a4a36", 0.5), ("#2a2420", 0.35), ("#a88a6a", 0.15)],
}


@register
class Granite(MaterialGenerator):
    """Granite: a polished mosaic of mineral crystals (quartz, feldspar, mica), two grain sizes."""

    name = "granite"
    tile_param = ("grain", 0.006)
    family = "stone"
    density = 2700.0
    params = {
        "kind": Param(kind="choice", choices=tuple(GRANITES), doc="granite variety (minerals)"),
        "grain": Param(40, 90, "int", doc="crystals across the texture"),
        "finish": Param(kind="choice", choices=("polished", "honed", "matte"),
                        doc="surface finish"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """A polished mosaic of mineral crystals in two grain sizes."""
        minerals = GRANITES[p["kind"]]
        cols = np.stack([jitter(rgb(c), rng, 0.01, 0.08, 0.06) for c, _ in minerals])
        probs = np.array([w for _, w in minerals], float)
        probs /= probs.sum()
        big = nz.worley(res, p["grain"], rng, 1.0)
        small = nz.worley(res, p["grain"] * 2, rng, 1.0)
        nb, ns = big.n ** 2, small.n ** 2
        kb = rng.choice(len(cols), nb, p=probs)[big.cell]
        ks = rng.choice(len(cols), ns, p=probs)[small.cell]
        use_small = (rng.random(ns) < 0.4)[small.cell]
        k = np.where(use_small, ks, kb)
        shade = (0.85 + 0.3 * rng.random(nb)).astype(F32)[big.cell]
        col = modulate(cols[k], shade)
        low = nz.spectral_noise(res, rng, knee=4.0, beta=2.0)
        col = modulate(col, 1.0 + 0.04 * low)
        rough = F32(_finish_roughness(rng, p["finish"])) + F32(0.05) * (k == 0)
        height = 0.05 * nz.smoothstep(0.0, 0.1, big.border)
        return Layers(col, rough, height, bump=0.4)


@register
class Concrete(MaterialGenerator):
    """Cast concrete: grey cement with cloudy mottling, fine sand grain and air-bubble pits;
    optionally polished (exposed fines, lower roughness)."""

    name = "concrete"
    tile_size = 1.5
    family = "stone"
    density = 2400.0
    params = {
        "tone": Param(kind="choice", choices=("grey", "light", "dark", "warm"),
                      doc="cement colour"),
        "mottling": Param(0.2, 1.0, doc="strength of the cloudy tone variation"),
        "pits": Param(0.0, 1.0, doc="density of air-bubble pits"),
        "polished": Param(kind="bool", doc="polished (smooth, aggregate visible) or cast"),
    }
    TONES = {"grey": "#9c9c98", "light": "#c4c2bc", "dark": "#6c6c6a", "warm": "#aca496"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Mottled grey cement with sand grain and air-bubble pits."""
        base = jitter(rgb(self.TONES[p["tone"]]), rng, 0.01, 0.06, 0.04)
        cloud = nz.spectral_noise(res, rng, knee=5.0, beta=1.3)
        sand = nz.spectral_noise(res, rng, knee=res / 4, beta=0.6)
        mid = nz.spectral_noise(res, rng, knee=30.0, beta=1.0)
        m = F32(p["mottling"])
        col = modulate(base, 1.0 + m * 0.08 * cloud + 0.04 * sand + 0.03 * mid)
        pits = nz.smoothstep(3.3 - 1.0 * p["pits"], 3.6 - 1.0 * p["pits"],
                             nz.spectral_noise(res, rng, knee=res / 8, beta=1.2))
        col = modulate(col, 1.0 - 0.45 * pits)
        height = 0.06 * sand + 0.05 * mid - 0.6 * pits
        if p["polished"]:
            agg = nz.worley(res, 28, rng, 1.0)
            keep = (rng.random(agg.n ** 2) < 0.35)[agg.cell]
            stones = nz.smoothstep(0.25, 0.35, agg.border) * keep
            tone = (0.8 + 0.4 * rng.random(agg.n ** 2)).astype(F32)[agg.cell]
            col = mix(col, modulate(base, tone * 0.9), stones * 0.6)
            rough = F32(0.25) + F32(0.05) * sand + F32(0.3) * pits
        else:
            rough = F32(0.85) + F32(0.05) * sand - F32(0.05) * m * cloud
        return Layers(col, rough, height, bump=0.6)


TERRAZZO_MATRIX = {"white": "#ece8e0", "grey": "#a8a8a4", "pink": "#e8cfc4", "green": "#9cb0a0",
                   "charcoal": "#4a4a4c"}
TERRAZZO_CHIPS = ["#f4f2ee", "#2a2a2c", "#b8b2a8", "#c8836a", "#d6b87a", "#6a8a78", "#8c4a3a",
                  "#e0d4c2", "#5a6a80"]


@register
class Terrazzo(MaterialGenerator):
    """Terrazzo: angular marble/glass chips of several colours in a polished cement matrix."""

    name = "terrazzo"
    tile_param = ("chip_size", 0.02)
    family = "stone"
    density = 2500.0
    params = {
        "matrix": Param(kind="choice", choices=tuple(TERRAZZO_MATRIX), doc="binder colour"),
        "chip_size": Param(8, 24, "int", doc="large chips across the texture (more = smaller)"),
        "chip_fill": Param(0.3, 0.8, doc="fraction of cells holding a large chip"),
        "colors": Param(2, 5, "int", doc="number of chip colours"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Angular chips of several colours in a polished cement matrix."""
        matrix = jitter(rgb(TERRAZZO_MATRIX[p["matrix"]]), rng, 0.01, 0.05, 0.03)
        pal_idx = rng.choice(len(TERRAZZO_CHIPS), int(p["colors"]), replace=False)
        pal = np.stack([jitter(rgb(TERRAZZO_CHIPS[i]), rng, 0.01, 0.05, 0.05) for i in pal_idx])
        col = modulate(solid(matrix, res), 1.0 + 0.03 * nz.grain(res, rng))
        chip_any = np.zeros((res, res), F32)
        for n, fill in ((int(p["chip_size"]), p["chip_fill"]), (int(p["chip_size"]) * 3, 0.35)):
            cells = nz.worley(res, n, rng, 1.0)
            cnt = cells.n ** 2
            shrink = rng.uniform(0.12, 0.35, cnt).astype(F32)[cells.cell]
            present = (rng.random(cnt) < fill)[cells.cell]
            chip = nz.smoothstep(shrink, shrink + 1.5 * n / res, cells.border) * present
            ccol = pal[rng.integers(0, len(pal), cnt)][cells.cell]
            ccol = ccol * (0.9 + 0.2 * rng.random(cnt)).astype(F32)[cells.cell][..., None]
            col = mix(col, ccol, chip)
            chip_any = np.maximum(chip_any, chip)
        rough = (F32(rng.uniform(0.08, 0.2)) + F32(0.05) * (1 - chip_any)
                 + F32(0.015) * nz.grain(res, rng))
        return Layers(col, rough, 0.03 * chip_any, bump=0.4)


SLATES = {"charcoal": ("#2e3134", "#4a4e52"), "blue_grey": ("#3a4450", "#5a6472"),
          "green": ("#3a4a42", "#5a6a60"), "rust": ("#4a3a32", "#8a6448"),
          "purple": ("#3e3440", "#5c4e5a")}


@register
class Slate(MaterialGenerator):
    """Natural cleft slate: dark layered stone with stepped terraces where sheets split off and
    faint lamination streaks."""

    name = "slate"
    tile_size = 0.6
    family = "stone"
    density = 2800.0
    params = {
        "kind": Param(kind="choice", choices=tuple(SLATES), doc="slate colour"),
        "cleft": Param(0.2, 1.0, doc="relief of the split (cleft) surface"),
        "layers": Param(3, 8, "int", doc="terrace levels in the cleft relief"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Dark layered stone with stepped cleft terraces."""
        c0, c1 = (jitter(rgb(x), rng, 0.01, 0.06, 0.05) for x in SLATES[p["kind"]])
        n = nz.spectral_noise(res, rng, knee=3.0, beta=1.7)
        lv = float(p["layers"])
        q = (n + 3.0) * lv / 6.0
        terr = np.floor(q) + nz.smoothstep(0.75, 1.0, nz.fract(q))  # soft steps
        lam = nz.spectral_noise(res, rng, knee=40.0, beta=1.1, stretch=(6.0, 1.0), angle=0.3)
        fine = nz.spectral_noise(res, rng, knee=res / 4, beta=0.7)
        t = nz.unit(terr) * 0.6 + 0.2 * nz.smoothstep(-1.5, 1.5, lam)
        col = modulate(mix(solid(c0, res), c1, t), 1.0 + 0.04 * fine)
        rough = F32(0.65) + F32(0.08) * fine - F32(0.05) * lam
        height = F32(p["cleft"]) * (0.25 * terr / lv * 4.0 + 0.05 * lam) + 0.03 * fine
        return Layers(col, rough, height, bump=0.6)


@register
class Soil(MaterialGenerator):
    """Potting soil / earth: dark crumbly clumps, lighter grit and bits of bark. Grouped with
    stone (a granular mineral surface)."""

    name = "soil"
    tile_size = 0.25
    family = "stone"
    density = 1300.0
    params = {
        "tone": Param(kind="choice", choices=("peat", "loam", "clay", "dry"), doc="soil colour"),
        "moisture": Param(0.0, 1.0, doc="wetness: darker and slightly glossier"),
        "grit": Param(0.0, 1.0, doc="amount of light grit / perlite"),
    }
    TONES = {"peat": "#3a2a1e", "loam": "#4e3a28", "clay": "#7a5a40", "dry": "#8a7258"}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Dark crumbly clumps with lighter grit and bits of bark."""
        base = jitter(rgb(self.TONES[p["tone"]]), rng, 0.01, 0.06, 0.06)
        clumps = nz.worley(res, 36, rng, 1.0)
        crumb = nz.spectral_noise(res, rng, knee=res / 5, beta=0.8)
        body = nz.smoothstep(0.0, 0.5, clumps.border)
        shade = (0.8 + 0.4 * rng.random(clumps.n ** 2)).astype(F32)[clumps.cell]
        wet = F32(1.0 - 0.35 * p["moisture"])
        col = modulate(base, shade * (0.6 + 0.4 * body) * (1 + 0.12 * crumb) * wet)
        gr = nz.smoothstep(3.2 - 1.2 * p["grit"], 3.5 - 1.2 * p["grit"],
                           nz.spectral_noise(res, rng, knee=res / 6, beta=1.0))
        col = mix(col, rgb("#d8d2c4"), gr * 0.8)
        rough = F32(0.95 - 0.2 * p["moisture"]) + F32(0.03) * crumb
        height = 0.6 * body * shade + 0.15 * crumb + 0.3 * gr
        return Layers(col, rough, height, bump=0.8)
