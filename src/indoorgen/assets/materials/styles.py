"""Home styles: one material family per home, so its rooms read as furnished by one household.

A style names the woods, metals, fabrics and leathers a household's furniture is made of, with
relative weights. `styled` narrows a slot's material choices to the style: within each of those
families, a slot keeps only the style's members (weighted by the style) when it allows any of
them, and its own choices otherwise (a slot that allows only oak stays oak); other families
(stone, glass, plastic, ceramic...) are left alone. Floors, walls and ceilings belong to the
building, not the furniture, and stay unstyled (`UNSTYLED_SLOTS`). The style is drawn per scene
from its seed (`draw_style`), so single rooms still vary across seeds, and recorded in
scene.json's `config.style`, so a re-export dresses the scene alike.
"""
from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from indoorgen.assets.materials.base import materials_in_family
from indoorgen.errors import ConfigError

#: the families a style fixes
STYLED_FAMILIES = ("wood", "metal", "fabric", "leather")
#: the building's surfaces: not chosen with the furniture
UNSTYLED_SLOTS = frozenset({"floor", "wall", "ceiling"})

#: style name -> family -> {material: relative weight}; interior-design families whose woods,
#: metals and textiles go together (light oak and linen, walnut and brass, painted wood and
#: chrome...)
STYLES: dict[str, dict[str, dict[str, float]]] = {
    "scandinavian": {"wood": {"oak": 3.0, "pine_planks": 1.0, "plywood": 1.0},
                     "metal": {"brushed_steel": 2.0, "painted_metal": 2.0},
                     "fabric": {"linen": 3.0, "knit": 2.0, "plain_weave": 1.0},
                     "leather": {"suede": 1.0}},
    "mid_century": {"wood": {"walnut": 3.0, "oak": 1.0},
                    "metal": {"brass": 3.0, "painted_metal": 1.0},
                    "fabric": {"velvet": 2.0, "plain_weave": 2.0},
                    "leather": {"leather": 1.0}},
    "industrial": {"wood": {"pine_planks": 2.0, "walnut": 1.0, "plywood": 1.0},
                   "metal": {"painted_metal": 3.0, "galvanized_steel": 1.0, "brushed_steel": 1.0},
                   "fabric": {"denim": 1.0, "plain_weave": 2.0},
                   "leather": {"leather": 1.0}},
    "classic": {"wood": {"walnut": 2.0, "painted_wood": 1.0},
                "metal": {"brass": 3.0, "chrome": 1.0},
                "fabric": {"velvet": 2.0, "linen": 1.0},
                "leather": {"leather": 1.0}},
    "modern": {"wood": {"painted_wood": 2.0, "oak": 1.0},
               "metal": {"chrome": 2.0, "brushed_steel": 2.0},
               "fabric": {"plain_weave": 2.0, "linen": 1.0},
               "leather": {"leather": 1.0, "suede": 0.5}},
    "farmhouse": {"wood": {"pine_planks": 2.0, "painted_wood": 2.0, "oak": 1.0},
                  "metal": {"painted_metal": 2.0, "galvanized_steel": 1.0},
                  "fabric": {"linen": 2.0, "denim": 1.0, "knit": 1.0},
                  "leather": {"suede": 1.0, "leather": 1.0}},
}


def style_names() -> list[str]:
    """Every style's name, sorted."""
    return sorted(STYLES)


def check_style(name: str) -> str:
    """`name` if it is a style, else a ConfigError naming the styles."""
    if name not in STYLES:
        raise ConfigError(f"unknown style {name!r}; valid: {', '.join(style_names())}")
    return name


def draw_style(rng: np.random.Generator) -> str:
    """One style, uniformly (one draw of `rng`)."""
    names = style_names()
    return names[int(rng.integers(len(names)))]


def styled(choices: Mapping[str, float], style: str | None) -> dict[str, float]:
    """`choices` narrowed to `style` (see the module): per styled family, the style's members the
    slot allows, at the slot's weight times the style's, in place of the family's others."""
    if style is None:
        return dict(choices)
    out = dict(choices)
    for family in STYLED_FAMILIES:
        mine = STYLES[style].get(family, {})
        members = set(materials_in_family(family))
        allowed = [m for m in choices if m in members]
        keep = [m for m in allowed if m in mine]
        if not keep:
            continue
        for m in allowed:
            if m in mine:
                out[m] = float(choices[m]) * mine[m]
            else:
                del out[m]
    return out
