"""Procedural PBR material library: tileable base colour, roughness, normal and metallic maps
generated in numpy from a seed and documented parameters (no textures, no Blender).

    from indoorgen.assets.materials import bake, save_maps, choose_materials
    slots = choose_materials(asset.slots, rng)           # {"wood": "walnut", ...}
    maps = bake(slots["wood"], seed=3, resolution=512)   # MaterialMaps, memoised
    save_maps(maps, Path("textures"), "table_top")       # 8-bit PNGs
    uv_scale = 1.0 / maps.tile_size_m                    # metre UVs -> texture repeats

Modules: `base` (protocol, registry, bake, save_maps), `noise` (periodic building blocks),
`color`, `slots` (slot -> material choices), `styles` (a home's woods, metals and fabrics) and
one module per group of families: `wood`, `metal`, `stone`, `tiles` (tile, brick), `textile`
(fabric, leather, carpet), `surfaces` (ceramic, glass, plastic, rubber, cork, plaster) and
`paper` (paper, wallpaper).
"""
from indoorgen.assets.materials import metal, paper, stone, surfaces, textile, tiles, wood  # noqa: F401  (registers)
from indoorgen.assets.materials.base import (
           FAMILIES,
           MaterialGenerator,
           MaterialMaps,
           bake,
           get_material,
           material_names,
           materials_in_family,
           normal_from_height,
           register,
           save_maps,
)
from indoorgen.assets.materials.slots import SLOT_CHOICES, choose_materials
from indoorgen.assets.materials.styles import STYLES, check_style, draw_style, style_names

__all__ = ["FAMILIES", "STYLES", "MaterialGenerator", "MaterialMaps", "SLOT_CHOICES", "bake",
           "check_style", "choose_materials", "draw_style", "get_material", "material_names",
           "materials_in_family", "normal_from_height", "register", "save_maps", "style_names"]
