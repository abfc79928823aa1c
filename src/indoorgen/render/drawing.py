"""What the plan drawings (`plan.py` for scenes, `floorplan.py` for bare floorplans) share:
shapely polygons as matplotlib paths, the wall colour and the room-type colours."""
from __future__ import annotations

from typing import Any

import numpy as np
import shapely.geometry as sg
from matplotlib.path import Path

from indoorgen.model.room_types import DEFAULT_COLOUR, ROOM_TYPES

WALL_COLOUR = "#3b3b3b"


def polygon_path(geom: Any) -> Path:
    """A matplotlib Path for a shapely Polygon or MultiPolygon, holes included."""
    polys = list(geom.geoms) if hasattr(geom, "geoms") else [geom]
    verts, codes = [], []
    for p in polys:
        if not isinstance(p, sg.Polygon) or p.is_empty:
            continue
        for ring in (p.exterior, *p.interiors):
            xy = np.asarray(ring.coords)[:, :2]
            verts.append(xy)
            c = np.full(len(xy), Path.LINETO, dtype=Path.code_type)
            c[0], c[-1] = Path.MOVETO, Path.CLOSEPOLY
            codes.append(c)
    if not verts:
        return Path(np.zeros((1, 2)), [Path.MOVETO])
    return Path(np.concatenate(verts), np.concatenate(codes))


def room_colour(room_type: str) -> str:
    """The fill colour of a room of `room_type` in plan drawings (the table's, or a neutral
    grey for types it does not know)."""
    spec = ROOM_TYPES.get(room_type)
    return spec.colour if spec is not None else DEFAULT_COLOUR
