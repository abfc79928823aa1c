"""What the plan drawings share (indoorgen.render.drawing)."""
from __future__ import annotations

import numpy as np
import shapely.geometry as sg
from matplotlib.path import Path

from indoorgen.model.room_types import DEFAULT_COLOUR, ROOM_TYPES
from indoorgen.render.drawing import polygon_path, room_colour


def test_polygon_path_keeps_holes_and_pieces():
    ring = sg.box(0, 0, 4, 4).difference(sg.box(1, 1, 3, 3))
    path = polygon_path(ring)
    assert (path.codes == Path.MOVETO).sum() == 2          # outline and hole
    assert [1.0, 1.0] in np.asarray(path.vertices).tolist()  # the hole's corner
    two = sg.MultiPolygon([sg.box(0, 0, 1, 1), sg.box(2, 0, 3, 1)])
    assert (polygon_path(two).codes == Path.MOVETO).sum() == 2
    empty = polygon_path(sg.Polygon())
    assert np.asarray(empty.vertices).shape == (1, 2)


def test_room_colours_come_from_the_table():
    assert room_colour("kitchen") == ROOM_TYPES["kitchen"].colour == "#e8a87c"
    assert room_colour("ballroom") == DEFAULT_COLOUR
