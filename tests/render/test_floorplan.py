"""`plan.png` of a bare floorplan (indoorgen.render.floorplan)."""
from __future__ import annotations

import matplotlib.image as mpimg
import numpy as np

from indoorgen.model.floorplan_io import from_json
from indoorgen.render.drawing import WALL_COLOUR, room_colour
from indoorgen.render.floorplan import draw_floorplan
from support.plans import apartment, two_storey_home


def _has_colour(img: np.ndarray, hex_colour: str) -> bool:
    rgb = np.array([int(hex_colour[i:i + 2], 16) for i in (1, 3, 5)]) / 255.0
    return bool((np.abs(img[..., :3] - rgb).max(axis=-1) < 1.5 / 255).any())


def test_rooms_are_filled_by_type_and_walls_drawn(tmp_path):
    fp = from_json(apartment())
    draw_floorplan(fp, tmp_path / "plan.png", title="apartment")
    img = mpimg.imread(tmp_path / "plan.png")
    assert img.shape[0] > 300
    for t in ("living_room", "kitchen", "bedroom", "bathroom"):
        assert _has_colour(img, room_colour(t)), t
    assert _has_colour(img, WALL_COLOUR)


def test_one_panel_per_storey(tmp_path):
    fp, _ = two_storey_home()
    draw_floorplan(fp, tmp_path / "one.png")
    wide = mpimg.imread(tmp_path / "one.png")
    flat = from_json(apartment())
    draw_floorplan(flat, tmp_path / "flat.png")
    assert wide.shape[1] > mpimg.imread(tmp_path / "flat.png").shape[1]
    assert _has_colour(wide, room_colour("staircase_room"))
