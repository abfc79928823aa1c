"""`plan.png` of a bare floorplan (indoorgen.render.floorplan)."""
from __future__ import annotations

from collections import Counter

import matplotlib.image as mpimg
import numpy as np

from indoorgen.model.floorplan_io import from_json
from indoorgen.render.drawing import WALL_COLOUR, room_colour
from indoorgen.render.floorplan import draw_floorplan, floorplan_figure
from indoorgen.render.labels import room_abbreviation, room_label
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


def test_floorplan_text_never_collides(drawn_text, text_overlaps):
    fp, _ = two_storey_home()
    fig = floorplan_figure(fp, title="two storeys")
    assert len(fig.axes) == 2
    legend = " ".join(t.get_text() for leg in fig.legends for t in leg.get_texts())
    kinds = Counter(r.type for _, r in fp.rooms())
    for ax, storey in zip(fig.axes, fp.storeys, strict=True):
        boxes = drawn_text(ax)
        assert text_overlaps(boxes) == []
        texts = [t.get_text().split("\n")[0] if "m²" in t.get_text()
                 else t.get_text().replace("\n", " ") for t, _ in boxes]
        # every room is named (with its area when it fits) or numbered and named in the legend
        for r in storey.rooms:
            several = kinds[r.type] > 1
            full = room_label(r.name, r.type, several)
            names = {full, full.replace(" ", "\n", 1).split("\n")[0],
                     room_abbreviation(r.name, r.type, several)}
            numbered = [n for n in texts if n.isdigit() and f"{n}: {full}" in legend]
            assert len([s for s in texts if s in names]) + len(numbered) >= 1, r.name
