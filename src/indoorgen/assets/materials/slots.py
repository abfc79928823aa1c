"""Material slots: which materials an asset's named slot may be dressed in.

Asset generators label faces with slot names ("wood", "front", "upholstery", ...);
`choose_materials` turns a list of slot names into one registered material per slot, drawn with
relative weights from `SLOT_CHOICES` (or caller overrides), narrowed to the home's style if one
is given (`styles.styled`). Unknown slots fall back to "body".
"""
from __future__ import annotations

import numpy as np

from indoorgen.assets.materials.base import material_names
from indoorgen.assets.materials.styles import UNSTYLED_SLOTS, styled
from indoorgen.errors import UnknownGeneratorError

_WOODS = {"oak": 3.0, "walnut": 2.0, "pine_planks": 1.0, "plywood": 1.0, "painted_wood": 1.5}
_METALS = {"brushed_steel": 3.0, "chrome": 1.5, "painted_metal": 2.0, "brass": 1.0,
           "galvanized_steel": 0.5, "rusty_metal": 0.2}
_FABRICS = {"plain_weave": 3.0, "linen": 2.0, "velvet": 1.0, "knit": 0.7, "denim": 0.5}
_PLASTICS = {"glossy_plastic": 2.0, "matte_plastic": 3.0, "textured_plastic": 1.5}

#: slot name -> {material name: relative weight}
SLOT_CHOICES: dict[str, dict[str, float]] = {
    # material-named slots
    "wood": dict(_WOODS),
    "metal": dict(_METALS),
    "fabric": dict(_FABRICS),
    "leather": {"leather": 4.0, "suede": 1.0},
    "ceramic": {"glazed_ceramic": 3.0, "matte_ceramic": 2.0, "porcelain": 2.0},
    "porcelain": {"porcelain": 4.0, "glazed_ceramic": 1.0},
    "glass": {"clear_glass": 4.0, "frosted_glass": 1.0},
    "plastic": dict(_PLASTICS),
    "stone": {"marble": 2.0, "granite": 2.0, "slate": 1.5, "concrete": 1.5, "terrazzo": 1.0},
    "marble": {"marble": 1.0},
    "granite": {"granite": 1.0},
    "concrete": {"concrete": 1.0},
    "paper": {"paper": 1.0},
    "cardboard": {"cardboard": 1.0},
    "rubber": {"rubber": 1.0},
    "cork": {"cork": 1.0},
    "wax": {"wax": 1.0},
    "carpet": {"carpet": 3.0, "berber_carpet": 2.0, "patterned_rug": 1.0},
    "tile": {"square_tile": 3.0, "subway_tile": 2.0, "hex_tile": 1.5, "herringbone_tile": 1.0},
    "plaster": {"plaster": 4.0, "stucco": 1.0},
    "brick": {"brick": 3.0, "painted_brick": 1.0},
    "wallpaper": {"striped_wallpaper": 1.0, "damask_wallpaper": 1.0, "geometric_wallpaper": 1.0},
    "wall": {"plaster": 6.0, "stucco": 1.0, "striped_wallpaper": 0.7, "damask_wallpaper": 0.7,
             "geometric_wallpaper": 0.7, "brick": 0.5, "painted_brick": 0.5,
             "painted_wood": 0.3},
    "floor": {"oak": 3.0, "parquet": 2.0, "pine_planks": 1.5, "walnut": 1.0, "square_tile": 1.0,
              "concrete": 0.7, "terrazzo": 0.5, "slate": 0.5, "carpet": 1.0, "cork": 0.3},
    "ceiling": {"plaster": 1.0},
    # part-named slots
    "front": {"painted_wood": 3.0, "oak": 1.5, "walnut": 1.0, "plywood": 0.5,
              "glossy_plastic": 1.0, "matte_plastic": 0.7, "painted_metal": 0.5},
    "back": {"plywood": 3.0, "painted_wood": 1.5, "cardboard": 0.3, "oak": 0.5},
    "body": {"oak": 1.0, "walnut": 0.7, "painted_wood": 1.0, "matte_plastic": 1.0,
             "glossy_plastic": 0.7, "painted_metal": 0.7, "brushed_steel": 0.5,
             "glazed_ceramic": 0.5},
    "upholstery": {"plain_weave": 3.0, "linen": 2.0, "velvet": 2.0, "leather": 2.0,
                   "knit": 0.5, "denim": 0.3, "suede": 0.7},
    "cushion": {"plain_weave": 2.0, "linen": 2.0, "velvet": 1.5, "knit": 1.0, "leather": 0.7},
    "frame": {"oak": 2.0, "walnut": 1.5, "painted_wood": 1.5, "brushed_steel": 1.0,
              "brass": 0.7, "painted_metal": 1.0, "chrome": 0.5},
    "leg": {"oak": 2.0, "walnut": 1.5, "painted_wood": 1.0, "brushed_steel": 1.0,
            "painted_metal": 1.0, "chrome": 0.5, "brass": 0.5},
    "top": {"oak": 2.0, "walnut": 1.5, "marble": 1.0, "glossy_plastic": 0.5,
            "painted_wood": 1.0, "clear_glass": 0.3},
    "screen": {"screen_glass": 1.0},
    "shade": {"linen": 3.0, "plain_weave": 2.0, "paper": 1.5, "frosted_glass": 0.7},
    "bulb": {"frosted_glass": 3.0, "clear_glass": 1.0},
    "canvas": {"painting": 1.0},
    "mat": {"paper": 1.0},
    "backing": {"cardboard": 2.0, "plywood": 1.0},
    "mirror": {"mirror": 4.0, "chrome": 1.0},
    "foliage": {"leaf": 1.0},
    "water": {"water": 1.0},
    # light-emitting parts (bulbs, diffusers): the library has no emission channel, so this is
    # the diffuser's surface; exporters that light scenes should key emission on the slot name
    "emissive": {"frosted_glass": 4.0, "glossy_plastic": 1.0},
    "soil": {"soil": 1.0},
    "food": {"fruit_skin": 1.0},
    "countertop": {"marble": 3.0, "granite": 3.0, "oak": 1.5, "walnut": 0.7, "concrete": 1.0,
                   "terrazzo": 1.0},
    "appliance": {"painted_metal": 3.0, "brushed_steel": 3.0, "glossy_plastic": 1.0,
                  "matte_plastic": 1.0},
    "rug": {"patterned_rug": 3.0, "carpet": 1.5, "berber_carpet": 1.5},
    "binding": {"plain_weave": 2.0, "linen": 1.0, "leather": 0.5},
    "cover": {"book_cover": 1.0},
    "pages": {"paper": 1.0},
    "handle": {"brushed_steel": 2.0, "chrome": 1.5, "brass": 1.5, "matte_plastic": 0.5,
               "leather": 0.3},
    "sink": {"porcelain": 3.0, "brushed_steel": 2.0},
    "bathtub": {"porcelain": 1.0},
    "sanitary": {"porcelain": 1.0},
    "door": {"painted_wood": 3.0, "oak": 1.0, "walnut": 0.5},
}


def _draw(choices: dict[str, float], rng: np.random.Generator) -> str:
    names = list(choices)
    w = np.array([max(0.0, float(choices[n])) for n in names])
    if w.sum() <= 0:
        w = np.ones(len(names))
    return names[int(rng.choice(len(names), p=w / w.sum()))]


def choose_materials(slots: list[str], rng: np.random.Generator,
                     overrides: dict[str, dict[str, float]] | None = None,
                     style: str | None = None) -> dict[str, str]:
    """One material name per slot, drawn from `overrides.get(slot)` or `SLOT_CHOICES.get(slot)`
    (an unknown slot uses the "body" choices), narrowed to `style` (a home style's woods,
    metals and fabrics; floors, walls and ceilings aside). Deterministic given the rng: slots
    are drawn in the order given, one rng draw each; repeated slot names get a single draw.
    Override weights naming unregistered materials raise UnknownGeneratorError."""
    overrides = overrides or {}
    known = set(material_names())
    for slot, choices in overrides.items():
        bad = sorted(set(choices) - known)
        if bad:
            raise UnknownGeneratorError(
                f"slot {slot!r} override names unknown material(s) {', '.join(bad)}; valid: "
                + ", ".join(sorted(known)))
    out: dict[str, str] = {}
    for slot in slots:
        if slot in out:
            continue
        choices = overrides.get(slot) or SLOT_CHOICES.get(slot) or SLOT_CHOICES["body"]
        out[slot] = _draw(choices if slot in UNSTYLED_SLOTS else styled(choices, style), rng)
    return out
