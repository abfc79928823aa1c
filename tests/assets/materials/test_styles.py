"""Home styles: a slot's woods, metals and fabrics narrowed to the style's, everything else left
alone; drawn per scene, recorded in scene.json, so a home's furniture shares one family."""
from __future__ import annotations

import numpy as np
import pytest

from indoorgen.assets.materials import STYLES, choose_materials, draw_style, materials_in_family
from indoorgen.assets.materials.slots import SLOT_CHOICES
from indoorgen.assets.materials.styles import STYLED_FAMILIES, check_style, styled
from indoorgen.errors import ConfigError


@pytest.mark.parametrize("style", sorted(STYLES))
def test_a_style_names_real_materials_of_its_families(style):
    for family, members in STYLES[style].items():
        assert family in STYLED_FAMILIES
        assert set(members) <= set(materials_in_family(family)), (style, family)


def test_a_styled_slot_draws_only_the_styles_woods_and_metals():
    woods, metals = set(STYLES["mid_century"]["wood"]), set(STYLES["mid_century"]["metal"])
    drawn = {choose_materials(["leg"], np.random.default_rng(s), style="mid_century")["leg"]
             for s in range(60)}
    assert drawn <= woods | metals and drawn & woods and drawn & metals
    # other families are left as they were
    assert styled(SLOT_CHOICES["top"], "modern")["marble"] == SLOT_CHOICES["top"]["marble"]


def test_a_slot_without_the_styles_members_keeps_its_own_and_floors_stay_unstyled():
    assert styled({"oak": 1.0}, "mid_century") == {"oak": 1.0}
    floors = {choose_materials(["floor"], np.random.default_rng(s), style="mid_century")["floor"]
              for s in range(60)}
    assert "parquet" in floors  # no style names parquet: the building's floors are not styled


def test_styles_are_drawn_from_the_seed_and_checked_by_name():
    assert draw_style(np.random.default_rng(4)) == draw_style(np.random.default_rng(4))
    assert len({draw_style(np.random.default_rng(s)) for s in range(40)}) == len(STYLES)
    with pytest.raises(ConfigError, match="unknown style"):
        check_style("baroque")
