"""Text on plan drawings that never collides: every label is measured (matplotlib's text extent
on the figure's renderer) and kept only where its box overlaps no label already placed and, for
a room, lies inside the room. Rooms try their pole of inaccessibility first (shapely's
polylabel, the inside point farthest from the walls), then other well-inside points, with their
name, then an abbreviation, then a number that the legend explains."""
from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

import numpy as np
import shapely
import shapely.geometry as sg
import shapely.ops
from matplotlib.axes import Axes
from matplotlib.text import Text
from matplotlib.transforms import Bbox

#: short names of room types, for rooms too small for their full name
ROOM_ABBREVIATIONS = {
    "living_room": "liv.", "dining_room": "din.", "kitchen": "kit.", "bedroom": "bed.",
    "bathroom": "bath", "closet": "cl.", "hallway": "hall", "garage": "gar.",
    "balcony": "balc.", "utility": "util.", "staircase_room": "stair", "office": "off.",
    "warehouse": "wareh.",
}
#: clear pixels kept between two labels
PAD_PX = 1.5
#: labels are drawn above everything else on a plan
TEXT_Z = 100_000


class LabelPlacer:
    """Places text on one axes so that no two placed labels' boxes overlap (keeps the boxes)."""

    def __init__(self, ax: Axes) -> None:
        """A placer for `ax`; the axes' position and limits must be final (text extents are
        measured in pixels)."""
        self.ax = ax
        self.renderer = ax.figure.canvas.get_renderer()  # type: ignore[attr-defined]
        self.boxes = np.zeros((0, 4))
        self.soft = np.zeros((0, 4))

    def place(self, texts: Sequence[str], points: Sequence[tuple[float, float]],
              inside: sg.Polygon | None = None, **kw: Any) -> Text | None:
        """Draw the first of `texts` (in order of preference) that fits at the first of
        `points` (data coordinates) where its box is free and, given `inside`, within that
        polygon; None (nothing drawn) when none fits."""
        t = self.ax.text(0.0, 0.0, "", **{"ha": "center", "va": "center", "zorder": TEXT_Z, **kw})
        frame = self.ax.bbox
        for strict in (True, False):  # keeping clear of the soft areas if at all possible
            for s in texts:
                t.set_text(s)
                for p in points:
                    t.set_position(p)
                    box = t.get_window_extent(self.renderer)
                    if not (box.x0 >= frame.x0 and box.x1 <= frame.x1 and box.y0 >= frame.y0
                            and box.y1 <= frame.y1):
                        continue
                    if not self.free(box) or (strict and _hits(self.soft, box)):
                        continue
                    if inside is not None and not self._within(box, inside):
                        continue
                    self.reserve(box)
                    return t
        t.remove()
        return None

    def free(self, box: Bbox) -> bool:
        """Whether `box` (pixels) keeps PAD_PX clear of every placed label."""
        return not _hits(self.boxes, box)

    def reserve(self, box: Bbox) -> None:
        """Mark `box` (pixels) as taken."""
        self.boxes = np.vstack([self.boxes, [box.x0, box.y0, box.x1, box.y1]])

    def keep_clear(self, areas: Sequence[sg.Polygon]) -> None:
        """Keep labels off the bounding boxes of `areas` (data coordinates; door swings, say)
        unless a label fits nowhere else."""
        for a in areas:
            x0, y0, x1, y1 = a.bounds
            (p0, q0), (p1, q1) = self.ax.transData.transform([(x0, y0), (x1, y1)])
            self.soft = np.vstack([self.soft, [min(p0, p1), min(q0, q1), max(p0, p1),
                                               max(q0, q1)]])

    def _within(self, box: Bbox, poly: sg.Polygon) -> bool:
        (x0, y0), (x1, y1) = self.ax.transData.inverted().transform(box.get_points())
        return bool(poly.contains(sg.box(x0, y0, x1, y1)))


def _hits(boxes: np.ndarray, box: Bbox) -> bool:
    """Whether `box` comes within PAD_PX of any of `boxes` ([x0, y0, x1, y1] rows, pixels)."""
    b = boxes
    return bool(((b[:, 0] < box.x1 + PAD_PX) & (b[:, 2] > box.x0 - PAD_PX)
                 & (b[:, 1] < box.y1 + PAD_PX) & (b[:, 3] > box.y0 - PAD_PX)).any())


def anchor_points(poly: sg.Polygon, n: int = 10) -> list[tuple[float, float]]:
    """Where a label inside `poly` may go, best first: the pole of inaccessibility, then points
    of a grid inside the polygon, farthest from its boundary first."""
    if poly.is_empty or poly.area <= 0:
        return []
    size = max(float(np.sqrt(poly.area)), 1e-3)
    pole = shapely.ops.polylabel(poly, tolerance=size / 50)
    x0, y0, x1, y1 = poly.bounds
    gx, gy = np.meshgrid(np.linspace(x0, x1, 9)[1:-1], np.linspace(y0, y1, 9)[1:-1])
    xs, ys = gx.ravel(), gy.ravel()
    keep = shapely.contains_xy(poly, xs, ys)
    xs, ys = xs[keep], ys[keep]
    clear = shapely.distance(poly.exterior, shapely.points(xs, ys))
    order = np.argsort(-clear, kind="stable")[: n - 1]
    return [(pole.x, pole.y)] + [(float(xs[i]), float(ys[i])) for i in order]


def room_label(name: str, room_type: str, several: bool) -> str:
    """A room's name for people: its type in words, with the scene's number when the home has
    several rooms of that type ("bedroom_2" -> "bedroom 2", a lone "kitchen_0" -> "kitchen")."""
    words = room_type.replace("_", " ")
    m = re.search(r"(\d+)$", name)
    return f"{words} {m.group(1)}" if several and m else words


def room_abbreviation(name: str, room_type: str, several: bool) -> str:
    """The short form of `room_label` ("bath 1"), for rooms too small for the full name."""
    short = ROOM_ABBREVIATIONS.get(room_type, room_type.replace("_", " ")[:4] + ".")
    m = re.search(r"(\d+)$", name)
    return f"{short} {m.group(1)}" if several and m else short


def place_room(placer: LabelPlacer, poly: sg.Polygon, names: Sequence[str], number: int,
               **kw: Any) -> bool | None:
    """Label the room `poly` inside itself with the first of `names` that fits (each also
    tried on two lines): True. Failing all, with `number`, inside the room or else near it:
    False (the legend must name it). None when not even the number finds a free spot."""
    pts = anchor_points(poly)
    texts: list[str] = []
    for s in names:
        texts.append(s)
        first, nl, rest = s.partition("\n")
        head, sep, tail = first.partition(" ")
        if sep and not tail.split("\n")[0].isdigit():  # never "bedroom" over a lone "2"
            texts.append(f"{head}\n{tail}{nl}{rest}")
    if placer.place(texts, pts, poly, **kw) is not None:
        return True
    if placer.place([str(number)], pts, poly, **kw) is not None:
        return False
    # a sliver too thin even for a digit: the number near it, wherever it is free
    x, y = pts[0] if pts else (poly.centroid.x, poly.centroid.y)
    ring = [(x + r * np.cos(a), y + r * np.sin(a)) for r in (0.4, 0.8, 1.2, 1.6)
            for a in np.linspace(0, 2 * np.pi, 8, endpoint=False)]
    return False if placer.place([str(number)], ring, None, **kw) is not None else None
