"""Tiled and masonry surfaces: square, hexagonal, herringbone and subway tiles, brick and
painted brick.

All are a periodic `Layout` (noise.py) plus a face shader per tile: each tile gets its own colour
jitter, the joints are recessed grout or mortar (height 0, rough, grout-coloured), and tile edges
are bevelled with a smooth ramp so the normal map shows them.
"""
from __future__ import annotations

from typing import Any

import numpy as np

from indoorgen.assets.materials import noise as nz
from indoorgen.assets.materials.base import Layers, MaterialGenerator, register
from indoorgen.assets.materials.color import jitter, mix, modulate, rgb, solid
from indoorgen.assets.protocol import Param

F32 = np.float32

TILE_COLORS = {"white": "#f0efea", "cream": "#ebe2cc", "black": "#222326", "grey": "#9a9c9e",
               "sage": "#9db29a", "navy": "#263a5e", "terracotta": "#b4603e", "teal": "#2c7c80",
               "blush": "#e6bcb0", "mustard": "#d2a440", "forest": "#2e5a44", "sky": "#9cc4dc"}
GROUT_COLORS = {"white": "#e4e2dc", "light_grey": "#bcbcb8", "grey": "#8a8a88",
                "charcoal": "#3e3e40", "beige": "#cfc4ae"}


def tile_params(count: tuple[int, int], count_doc: str,
                colors: tuple[str, ...] = tuple(TILE_COLORS)) -> dict[str, Param]:
    """The params every tile material shares, with its own count range and colours."""
    return {
        "count": Param(count[0], count[1], "int", doc=count_doc),
        "color": Param(kind="choice", choices=colors, doc="main tile colour"),
        "accent": Param(0.0, 0.25, doc="fraction of tiles in a second (accent) colour; below "
                        "0.1 there are none"),
        "grout": Param(kind="choice", choices=tuple(GROUT_COLORS), doc="grout colour"),
        "grout_width": Param(0.02, 0.07, doc="grout joint width relative to the tile width"),
        "glaze": Param(kind="choice", choices=("gloss", "satin", "matte"), doc="tile glaze"),
        "variation": Param(0.0, 0.12, doc="tile-to-tile brightness variation"),
    }


GLAZE_ROUGHNESS = {"gloss": 0.06, "satin": 0.3, "matte": 0.6}


class _Tile(MaterialGenerator):
    family = "tile"
    density = 2300.0
    bevel_ratio = 0.04  # bevel width relative to the tile width

    def layout(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> nz.Layout:
        """The tiling of the texture (a `noise.Layout`: tile ids, local coordinates, joint distance)."""
        raise NotImplementedError

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Glazed tiles (main and accent colours, bevelled edges) in grout on the layout."""
        lay = self.layout(p, res, rng)
        size = lay.width
        main = jitter(rgb(TILE_COLORS[p["color"]]), rng, 0.01, 0.05, 0.03)
        others = [k for k in self.params["color"].choices if k != p["color"]]
        accent = jitter(rgb(TILE_COLORS[others[int(rng.integers(len(others)))]]), rng)
        frac = max(0.0, p["accent"] - 0.1) / 0.15 * 0.25
        is_acc = (rng.random(lay.count) < frac)[lay.tile]
        tint = (1.0 + 2 * p["variation"] * (rng.random(lay.count) - 0.5)).astype(F32)[lay.tile]
        face = np.where(is_acc[..., None], accent, main).astype(F32)
        pool = nz.spectral_noise(res, rng, knee=6.0, beta=1.8)
        g = nz.grain(res, rng)
        face = modulate(face, tint * (1.0 + 0.012 * pool + 0.006 * g))
        grout = jitter(rgb(GROUT_COLORS[p["grout"]]), rng, 0.005, 0.05, 0.03)
        grout_field = modulate(solid(grout, res), 1.0 + 0.03 * g)
        mask = nz.joint_mask(lay.edge, 0.5 * p["grout_width"] * size, self.bevel_ratio * size, res)
        # glaze runs thin over the bevel and pools at its foot: a slightly lighter rim
        rim = mask * (1.0 - nz.smoothstep(0.5 * p["grout_width"] * size,
                                          (0.5 * p["grout_width"] + 2 * self.bevel_ratio) * size,
                                          lay.edge))
        face = modulate(face, 1.0 + 0.06 * rim)
        col = mix(grout_field, face, mask)
        r_face = F32(GLAZE_ROUGHNESS[p["glaze"]]) + F32(0.02) * pool
        rough = mix(np.full((res, res, 1), 0.9, F32), r_face[..., None], mask)[..., 0]
        rough = rough + F32(0.01) * g
        height = 1.5 * mask + 0.02 * pool * mask + 0.05 * g * (1 - mask)
        return Layers(col, rough, height, bump=0.5)


@register
class SquareTile(_Tile):
    """Square ceramic tiles on a grid (bathroom walls, kitchen floors)."""

    name = "square_tile"
    tile_param = ("count", 0.15)
    params = tile_params((3, 10), "tiles across the texture")

    def layout(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> nz.Layout:
        """A square grid, `count` tiles each way."""
        return nz.grid_layout(res, p["count"], p["count"])


@register
class HexTile(_Tile):
    """Hexagonal tiles (mosaic to large format)."""

    name = "hex_tile"
    tile_param = ("count", 0.1)
    bevel_ratio = 0.05
    params = tile_params((4, 14), "hexagons across the texture")

    def layout(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> nz.Layout:
        """Hexagons, `count` across."""
        return nz.hex_layout(res, p["count"])


@register
class HerringboneTile(_Tile):
    """Rectangular tiles (or stone pavers) laid in herringbone."""

    name = "herringbone_tile"
    bevel_ratio = 0.06
    params = {**tile_params((2, 4), "pattern repeats across the texture"),
              "ratio": Param(2, 4, "int", doc="tile length in tile widths")}

    def layout(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> nz.Layout:
        """Tiles `ratio` widths long in a herringbone, `count` repeats across."""
        return nz.herringbone_layout(res, p["ratio"], p["count"])

    def tile_size_m(self, p: dict[str, Any]) -> float:
        """The texture's width in metres, for 75 mm wide tiles."""
        return 2 * p["ratio"] * p["count"] * 0.075  # 75 mm wide tiles


@register
class SubwayTile(_Tile):
    """Subway (metro) tiles: 2:1 glossy bricks in running bond with rounded bevelled edges."""

    name = "subway_tile"
    tile_param = ("count", 0.15)
    bevel_ratio = 0.12
    params = {**tile_params((3, 6), "tiles across the texture (rows = 2 x count)",
                            ("white", "cream", "grey", "sage", "navy", "black", "forest", "sky",
                             "teal")),
              "glaze": Param(kind="choice", choices=("gloss", "satin"), doc="tile glaze")}

    def layout(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> nz.Layout:
        """2:1 bricks in running bond (every other row offset by half a tile)."""
        rows = 2 * int(p["count"])
        return nz.grid_layout(res, p["count"], rows, np.tile([0.25, 0.75], rows // 2))


BRICKS = {  # face colour range (light, dark)
    "red": ("#a8503a", "#7a3226"), "brown": ("#8a5a40", "#5a3a2a"),
    "orange": ("#c0703e", "#9a4e2e"), "buff": ("#d4b888", "#b08e62"),
    "grey": ("#8e8a84", "#64605a"), "mixed": ("#b06a48", "#5e3a2c"),
}
MORTARS = {"grey": "#a4a29c", "light": "#cfc8b8", "dark": "#5a5854", "white": "#e2ded6"}


class _Brick(MaterialGenerator):
    family = "brick"
    density = 1900.0

    def brick_layout(self, p: dict[str, Any], res: int) -> nz.Layout:
        nx = int(p["bricks"])
        rows = 3 * nx + (3 * nx) % 2  # a 225 x 75 mm module is 3:1; even, so the bond wraps
        return nz.grid_layout(res, nx, rows, np.tile([0.25, 0.75], rows // 2))

    def mortar_mask(self, p: dict[str, Any], res: int, rng: np.random.Generator,
                    lay: nz.Layout) -> np.ndarray:
        """1 on brick faces, 0 in mortar; edges chipped by noise."""
        chip = nz.spectral_noise(res, rng, knee=40.0, beta=1.2)
        edge = lay.edge - F32(0.06 * lay.width) * np.maximum(chip - 0.5, 0)
        return nz.joint_mask(edge, 0.5 * p["mortar_width"] * lay.width, 0.06 * lay.width, res)


@register
class Brick(_Brick):
    """Brick wall in running (stretcher) bond: varied clay colours, sandy faces with burnt
    spots, chipped edges and recessed mortar."""

    name = "brick"
    tile_param = ("bricks", 0.225)
    params = {
        "bricks": Param(3, 5, "int", doc="bricks across the texture (rows = 3 x bricks)"),
        "color": Param(kind="choice", choices=tuple(BRICKS), doc="clay colour"),
        "mortar": Param(kind="choice", choices=tuple(MORTARS), doc="mortar colour"),
        "mortar_width": Param(0.12, 0.3, doc="mortar joint width relative to the course height"),
        "variation": Param(0.3, 1.0, doc="brick-to-brick colour variation"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """Clay faces in varied colours, sandy and burnt, set in recessed mortar."""
        lay = self.brick_layout(p, res)
        light, dark = (jitter(rgb(c), rng, 0.01, 0.06, 0.05) for c in BRICKS[p["color"]])
        t = (0.5 + p["variation"] * (rng.random(lay.count) - 0.5)).astype(F32)[lay.tile]
        face = mix(light, dark, t)
        sand = nz.spectral_noise(res, rng, knee=res / 5, beta=0.7)
        blotch = nz.spectral_noise(res, rng, knee=14.0, beta=1.3)
        burnt = nz.smoothstep(1.0, 2.2, blotch)
        face = modulate(face, (1.0 + 0.07 * sand) * (1.0 - 0.3 * burnt))
        mortar = jitter(rgb(MORTARS[p["mortar"]]), rng, 0.005, 0.05, 0.04)
        mortar_f = modulate(solid(mortar, res), 1.0 + 0.08 * sand)
        mask = self.mortar_mask(p, res, rng, lay)
        col = mix(mortar_f, face, mask)
        rough = (F32(0.8) + F32(0.05) * sand) * mask + F32(0.92) * (1 - mask)
        height = 2.0 * mask + 0.1 * sand + 0.1 * blotch * mask
        return Layers(col, rough, height, bump=0.6)


@register
class PaintedBrick(_Brick):
    """Painted brick wall: the bond and texture show through a single paint colour."""

    name = "painted_brick"
    tile_param = ("bricks", 0.225)
    params = {
        "bricks": Param(3, 5, "int", doc="bricks across the texture (rows = 3 x bricks)"),
        "color": Param(kind="choice", choices=("white", "cream", "grey", "black", "sage", "navy"),
                       doc="paint colour"),
        "mortar_width": Param(0.12, 0.3, doc="mortar joint width relative to the course height"),
        "sheen": Param(0.55, 0.9, doc="paint roughness"),
    }

    def build(self, p: dict[str, Any], res: int, rng: np.random.Generator) -> Layers:
        """The brick relief under one paint colour, mortar painted alike."""
        lay = self.brick_layout(p, res)
        paint = jitter(rgb(TILE_COLORS.get(p["color"], "#f0efea")), rng, 0.005, 0.04, 0.03)
        sand = nz.spectral_noise(res, rng, knee=res / 5, beta=0.7)
        blotch = nz.spectral_noise(res, rng, knee=10.0, beta=1.4)
        mask = self.mortar_mask(p, res, rng, lay)
        tint = (1.0 + 0.04 * (rng.random(lay.count) - 0.5)).astype(F32)[lay.tile]
        tint = np.where(mask > 0.5, tint, 1)
        shade = (0.85 + 0.15 * mask) * (1 + 0.04 * sand + 0.02 * blotch) * tint
        col = modulate(paint, shade)
        rough = F32(p["sheen"]) + F32(0.05) * sand
        height = 2.0 * mask + 0.12 * sand + 0.1 * blotch
        return Layers(col, rough, height, bump=0.6)
