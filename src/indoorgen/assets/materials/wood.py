"""Wood: oak, walnut, pine planks, painted wood, plywood and herringbone parquet.

Growth rings are modelled as the contours of distance to the log's pith, a line running along the
board slightly below its surface: cutting a cylinder stack with a plane gives straight lines where
the pith is far away and cathedral arches where it tilts towards the surface. The tilt varies as a
cosine over the board's length so each board's pattern is periodic; low-frequency noise stretched
along the grain wobbles the rings, and finer stretched noise gives pores and streaks.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from indoorgen.assets.materials import noise as nz
from indoorgen.assets.materials.base import Layers, MaterialGenerator, register
from indoorgen.assets.materials.color import jitter, mix, modulate, rgb, scale_value
from indoorgen.assets.protocol import Param

F32 = np.float32
TAU = 2.0 * math.pi

FINISH_ROUGHNESS = {"gloss": (0.12, 0.22), "satin": (0.3, 0.45), "matte": (0.55, 0.72),
                    "oiled": (0.4, 0.55), "raw": (0.7, 0.85)}


def ring_profile(phase: np.ndarray, sharpness: float = 0.7) -> np.ndarray:
    """0 in earlywood rising to 1 in the latewood band at the end of each ring, back to 0 at the
    next ring: continuous, so fine rings do not alias into stair steps."""
    f = nz.fract(phase)
    start = 0.85 - 0.5 * sharpness
    return nz.smoothstep(start, 0.9, f) * (1.0 - nz.smoothstep(0.9, 1.0, f))


def board_rings(lay: nz.Layout, rng: np.random.Generator, rings: float, figure: float,
                wobble: np.ndarray, wobble_amp: float) -> np.ndarray:
    """Ring phase (rings counted from the pith) for each board of a grid layout whose length runs
    along u. `figure` (0..1) is how strongly the pith tilts towards the surface (cathedrals)."""
    n = lay.count
    yc = (rng.uniform(-1.5, 2.5, n) * lay.width).astype(F32)[lay.tile]
    z0 = (rng.uniform(0.8, 2.5, n) * lay.width).astype(F32)[lay.tile]
    tilt = (figure * rng.uniform(0.05, 0.15, n) * lay.width).astype(F32)[lay.tile]
    phi = rng.uniform(0, TAU, n).astype(F32)[lay.tile]
    z = np.abs(z0 + tilt * np.cos(TAU * lay.a / F32(lay.length) + phi))
    r = np.sqrt((lay.b - yc) ** 2 + z * z)
    start = rng.uniform(0, 1, n).astype(F32)[lay.tile]
    return r * F32(rings) + wobble * F32(wobble_amp) + start


def pores(res: int, rng: np.random.Generator, density: float, stretch: float = 24.0,
          along_v: bool = False) -> np.ndarray:
    """Elongated pore streaks in [0, 1] (0 = no pore), running along u (or v)."""
    s = (stretch, 1.0) if not along_v else (1.0, stretch)
    n = nz.spectral_noise(res, rng, knee=160.0, beta=1.0, hi=res * 0.3, stretch=s)
    thr = 3.0 - 1.2 * density
    return nz.smoothstep(thr, thr + 0.8, n)


def knots(res: int, rng: np.random.Generator, count: int,
          radius: float) -> tuple[np.ndarray, np.ndarray]:
    """`count` knots at random places: returns (weight 0..1 falling off around each knot,
    distance to the nearest knot centre in texture units). Distances wrap around the torus."""
    u, v = nz.grid(res)
    best = np.full((res, res), 10.0, F32)
    for _ in range(count):
        cu, cv = rng.random(2)
        du = np.abs(u - F32(cu))
        dv = np.abs(v - F32(cv))
        du = np.minimum(du, 1 - du) * F32(1.0)
        dv = np.minimum(dv, 1 - dv) * F32(1.6)  # knots are elongated along the grain (u)
        best = np.minimum(best, np.sqrt(du * du + dv * dv))
    weight = np.exp(-(best / F32(radius * 2.5)) ** 2)
    return weight.astype(F32), best


class _Wood(MaterialGenerator):
    family = "wood"
    light = "#c8a070"
    dark = "#8a5a30"
    pore_density = 0.5
    pore_dark = 0.35

    def board_layout(self, res: int, rng: np.random.Generator, rows: int, splits: int) -> nz.Layout:
        """The boards: `rows` rows of `splits` boards each, the rows' joints staggered."""
        return nz.grid_layout(res, splits, rows, nz.seam_safe_offsets(rng, rows))

    def grain(self, p: dict[str, Any], res: int, rng: np.random.Generator, lay: nz.Layout,
              rings: float, figure: float, wobble_amp: float, light: np.ndarray,
              dark: np.ndarray, contrast: float, pore_density: float,
              knot: tuple[np.ndarray, np.ndarray] | None = None
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Colour, a ring profile and a pore mask for boards laid along u."""
        wob = nz.spectral_noise(res, rng, knee=2.0, beta=2.0, hi=8.0, stretch=(4.0, 1.0))
        phase = board_rings(lay, rng, rings, figure, wob, wobble_amp)
        if knot is not None:
            w, d = knot
            phase = phase * (1 - w) + (d * F32(rings * 2.2)) * w
        # latewood bands vary in strength along and across the board
        band = nz.spectral_noise(res, rng, knee=6.0, beta=1.5, stretch=(3.0, 1.0))
        prof = ring_profile(phase) * np.clip(0.7 + 0.3 * band, 0.2, 1.0)
        pr = pores(res, rng, pore_density)
        streak = nz.spectral_noise(res, rng, knee=40.0, beta=1.0, stretch=(10.0, 1.0))
        tint = (1.0 + 0.14 * (rng.random(lay.count) - 0.5)).astype(F32)[lay.tile]
        shade = tint * (1.0 + 0.05 * streak)
        col = mix(light, dark, prof * F32(contrast))
        col = modulate(col, shade * (1.0 - F32(self.pore_dark) * pr))
        if knot is not None:
            w, d = knot
            core = nz.smoothstep(0.02, 0.008, d)
            col = mix(col, scale_value(dark, 0.55), np.maximum(core, 0.35 * w))
        return col, prof, pr

    def finish(self, p: dict[str, Any], res: int, rng: np.random.Generator, col: np.ndarray,
               prof: np.ndarray, pr: np.ndarray, joints: np.ndarray | None) -> Layers:
        """The layers: the finish's roughness with smudges and pores, relief from rings, pores, joints."""
        lo, hi = FINISH_ROUGHNESS[p.get("finish", "satin")]
        base_r = rng.uniform(lo, hi)
        smudge = nz.spectral_noise(res, rng, knee=4.0, beta=2.0)
        g = nz.grain(res, rng)
        col = modulate(col, 1.0 + 0.015 * g)
        rough = (F32(base_r) + F32(0.04) * smudge + F32(0.15) * pr + F32(0.04) * prof
                 + F32(0.015) * g)
        height = -0.25 * prof - 0.6 * pr
        if joints is not None:
            height = height * joints + 3.0 * joints
            col = modulate(col, 0.55 + 0.45 * joints)
            rough = rough * joints + F32(0.8) * (1 - joints)
        return Layers(col, rough, height.astype(F32), bump=0.6)


def _wood_params(rows: tuple[int, int], extra: dict[str, Param] | None = None) -> dict[str, Param]:
    out = {
        "boards": Param(rows[0], rows[1], "int", doc="boards across the texture (rows along v); "
                        "the grain runs along u"),
        "ring_density": Param(25.0, 70.0, doc="growth rings per texture width"),
        "figure": Param(0.0, 1.0, doc="cathedral figure: how far the pith tilts towards the "
                        "surface (0 = straight grain)"),
        "contrast": Param(0.4, 0.9, doc="latewood darkness relative to earlywood"),
        "finish": Param(kind="choice", choices=("gloss", "satin", "matte", "oiled"),
                        doc="surface finish; sets roughness"),
    }
    out.update(extra or {})
    return out


class _SolidWood(_Wood):
    """Boards of one species with optional visible joints."""

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Grain of the species (earlywood/latewood rings, rays) on boards with joints."""
        rows = int(p["boards"])
        splits = int(rng.integers(1, 3)) if rows > 1 else 1
        lay = self.board_layout(res, rng, rows, splits)
        light = jitter(rgb(self.light), rng)
        dark = jitter(rgb(self.dark), rng)
        col, prof, pr = self.grain(p, res, rng, lay, p["ring_density"], p["figure"], 0.5,
                                   light, dark, p["contrast"], self.pore_density)
        joints = nz.joint_mask(lay.edge, 0.0008, 0.002, res) if rows > 1 else None
        return self.finish(p, res, rng, col, prof, pr, joints)


@register
class Oak(_SolidWood):
    """White/red oak: warm tan, coarse open pores, pronounced latewood."""

    name = "oak"
    tile_param = ("boards", 0.15)
    density = 720.0
    light, dark = "#d2ac78", "#94663a"
    pore_density = 0.7
    pore_dark = 0.3
    params = _wood_params((1, 6))


@register
class Walnut(_SolidWood):
    """American black walnut: chocolate brown with purple-grey streaks, fine pores."""

    name = "walnut"
    tile_param = ("boards", 0.15)
    density = 640.0
    light, dark = "#7a5238", "#3e2618"
    pore_density = 0.45
    pore_dark = 0.3
    params = _wood_params((1, 4))


@register
class PinePlanks(_Wood):
    """Pine floor or wall planks: pale yellow, high-contrast latewood, knots, visible joints."""

    name = "pine_planks"
    tile_param = ("boards", 0.14)
    density = 510.0
    light, dark = "#e2c28c", "#b07a40"
    pore_density = 0.15
    pore_dark = 0.15
    params = _wood_params((3, 8), {
        "knots": Param(0, 3, "int", doc="knots per texture"),
        "finish": Param(kind="choice", choices=("satin", "matte", "oiled", "raw"),
                        doc="surface finish; sets roughness"),
    })

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Pale planks with contrasting latewood, knots and visible joints."""
        rows = int(p["boards"])
        lay = self.board_layout(res, rng, rows, int(rng.integers(1, 3)))
        light, dark = jitter(rgb(self.light), rng), jitter(rgb(self.dark), rng)
        kn = knots(res, rng, int(p["knots"]), 0.012) if p["knots"] else None
        col, prof, pr = self.grain(p, res, rng, lay, p["ring_density"] * 0.7, p["figure"], 0.6,
                                   light, dark, min(1.0, p["contrast"] + 0.2), self.pore_density,
                                   kn)
        joints = nz.joint_mask(lay.edge, 0.0012, 0.002, res)
        return self.finish(p, res, rng, col, prof, pr, joints)


PAINT_COLORS = {"white": "#eeece6", "cream": "#e8dcc0", "sage": "#a6b59a", "navy": "#2c3a55",
                "grey": "#8c9094", "black": "#2a2a2a", "duck_egg": "#a9c8c6", "red": "#a33a30"}


@register
class PaintedWood(_Wood):
    """Painted boards (tongue-and-groove, cabinet fronts): flat paint over faint grain relief."""

    name = "painted_wood"
    tile_param = ("boards", 0.12)
    density = 600.0
    params = {
        "boards": Param(1, 8, "int", doc="boards across the texture (1 = one plain panel)"),
        "color": Param(kind="choice", choices=tuple(PAINT_COLORS), doc="paint colour"),
        "sheen": Param(0.15, 0.6, doc="paint roughness (low = gloss enamel, high = chalk paint)"),
        "wear": Param(0.0, 0.35, doc="amount of worn-through paint showing bare wood"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """A flat paint colour over faint grain relief and board joints."""
        rows = int(p["boards"])
        lay = self.board_layout(res, rng, rows, 1)
        wood_col, prof, pr = self.grain(p, res, rng, lay, 40.0, 0.6, 0.5, rgb("#c9a57a"),
                                        rgb("#9a7048"), 0.6, 0.3)
        paint = jitter(rgb(PAINT_COLORS[p["color"]]), rng, 0.01, 0.04, 0.04)
        tone = nz.spectral_noise(res, rng, knee=3.0, beta=2.0)
        col = modulate(paint, 1.0 + 0.02 * tone - 0.05 * prof)
        worn = np.zeros((res, res), F32)
        if p["wear"] > 0.01:
            wn = nz.spectral_noise(res, rng, knee=6.0, beta=2.0, hi=60.0)
            edge_bias = nz.smoothstep(0.015, 0.0, lay.edge) if rows > 1 else 0.0
            thr = 3.0 - 2.6 * p["wear"]
            worn = nz.smoothstep(thr, thr + 0.25, wn + 1.2 * edge_bias)
            col = mix(col, wood_col, worn)
        g = nz.grain(res, rng)
        col = modulate(col, 1.0 + 0.008 * g)
        rough = F32(p["sheen"]) + F32(0.03) * tone + F32(0.015) * g
        rough = rough * (1 - worn) + F32(0.7) * worn
        height = -0.12 * prof - 0.1 * pr - 0.3 * worn
        if rows > 1:
            joints = nz.joint_mask(lay.edge, 0.001, 0.003, res)
            height = height + 3.0 * joints
            col = modulate(col, 0.6 + 0.4 * joints)
        return Layers(col, rough, height.astype(F32), bump=0.6)


@register
class Plywood(_Wood):
    """Birch plywood / rotary-cut veneer: pale, wide wavy grain, low contrast, no joints."""

    name = "plywood"
    tile_size = 0.6
    density = 600.0
    light, dark = "#e6cfa4", "#c39f6c"
    params = {
        "waviness": Param(0.5, 1.0, doc="how strongly the rotary-cut grain meanders"),
        "contrast": Param(0.3, 0.7, doc="ring contrast"),
        "finish": Param(kind="choice", choices=("matte", "satin", "raw"),
                        doc="surface finish; sets roughness"),
        "species": Param(kind="choice", choices=("birch", "pine", "oak_veneer"),
                         doc="face veneer species (colour)"),
    }
    TONES = {"birch": ("#e8d3aa", "#c9a676"), "pine": ("#e4c48e", "#be8a4e"),
             "oak_veneer": ("#d6b282", "#a47848")}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Rotary-cut veneer: wide wavy low-contrast grain, no joints."""
        lay = nz.grid_layout(res, 1, 1)
        lt, dk = self.TONES[p["species"]]
        light, dark = jitter(rgb(lt), rng), jitter(rgb(dk), rng)
        wob = nz.spectral_noise(res, rng, knee=2.5, beta=2.2, hi=10.0, stretch=(2.5, 1.0))
        phase = lay.b * F32(18.0) + wob * F32(3.0 * p["waviness"])
        prof = ring_profile(phase, 0.8)
        pr = pores(res, rng, 0.2)
        streak = nz.spectral_noise(res, rng, knee=30.0, beta=1.0, stretch=(8.0, 1.0))
        col = mix(light, dark, prof * F32(p["contrast"]))
        col = modulate(col, (1.0 + 0.05 * streak) * (1 - 0.2 * pr))
        return self.finish(p, res, rng, col, prof, pr, None)


@register
class Parquet(_Wood):
    """Herringbone parquet: short oak-like planks with straight grain along each plank."""

    name = "parquet"
    density = 700.0
    params = {
        "ratio": Param(3, 5, "int", doc="plank length in plank widths"),
        "repeats": Param(1, 2, "int", doc="pattern repeats across the texture"),
        "tone": Param(kind="choice", choices=("oak", "smoked_oak", "walnut", "maple"),
                      doc="wood species / stain"),
        "variation": Param(0.05, 0.25, doc="plank-to-plank brightness variation"),
        "finish": Param(kind="choice", choices=("gloss", "satin", "matte", "oiled"),
                        doc="surface finish; sets roughness"),
    }
    def tile_size_m(self, p: dict[str, Any]) -> float:
        """The texture's width in metres, for 70 mm wide planks."""
        return 2 * p["ratio"] * p["repeats"] * 0.07  # 70 mm wide planks

    TONES = {"oak": ("#d0a672", "#9a6a3c"), "smoked_oak": ("#8f6a4a", "#54392a"),
             "walnut": ("#7a5238", "#3e2618"), "maple": ("#ecd3a8", "#c9a070")}

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Short planks in herringbone, straight grain along each plank."""
        lay = nz.herringbone_layout(res, p["ratio"], p["repeats"])
        lt, dk = self.TONES[p["tone"]]
        light, dark = jitter(rgb(lt), rng), jitter(rgb(dk), rng)
        vert = lay.vertical
        assert vert is not None  # a herringbone layout flags its vertical planks
        wob_u = nz.spectral_noise(res, rng, knee=4.0, beta=2.0, hi=16.0, stretch=(4.0, 1.0))
        wob_v = nz.spectral_noise(res, rng, knee=4.0, beta=2.0, hi=16.0, stretch=(1.0, 4.0))
        wob = np.where(vert, wob_v, wob_u)
        offset = rng.random(lay.count).astype(F32)[lay.tile]
        rings = rng.uniform(2.5, 6.0, lay.count).astype(F32)[lay.tile]  # rings per plank width
        prof = ring_profile(lay.b / F32(lay.width) * rings + wob * F32(0.6) + offset * F32(10.0))
        pr = np.where(vert, pores(res, rng, 0.5, along_v=True), pores(res, rng, 0.5))
        tint = (1.0 + p["variation"] * 2 * (rng.random(lay.count) - 0.5)).astype(F32)[lay.tile]
        col = modulate(mix(light, dark, prof * F32(0.6)), tint * (1 - 0.3 * pr))
        joints = nz.joint_mask(lay.edge, 0.0006, 0.0015, res)
        return self.finish(p, res, rng, col, prof, pr, joints)
