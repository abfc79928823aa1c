"""Labels that never collide (indoorgen.render.labels)."""
from __future__ import annotations

import shapely.geometry as sg
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from indoorgen.render.labels import (
    LabelPlacer,
    anchor_points,
    place_room,
    room_abbreviation,
    room_label,
)


def _axes(size: float = 10.0):
    fig = Figure(figsize=(5, 5), dpi=100)
    FigureCanvasAgg(fig)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, size)
    ax.set_ylim(0, size)
    return fig, ax


def test_anchors_start_at_the_pole_and_stay_inside():
    ell = sg.Polygon([(0, 0), (6, 0), (6, 1), (1, 1), (1, 6), (0, 6)])
    pts = anchor_points(ell)
    assert not ell.contains(ell.centroid)  # the centroid of an L is outside it
    assert all(ell.contains(sg.Point(p)) for p in pts)
    assert len(pts) > 3
    # the first point is the farthest from the walls
    clear = [ell.exterior.distance(sg.Point(p)) for p in pts]
    assert clear[0] >= max(clear) - 0.05


def test_placed_labels_never_overlap(drawn_text, text_overlaps):
    fig, ax = _axes()
    placer = LabelPlacer(ax)
    grid = [(x * 0.5, y * 0.5) for x in range(21) for y in range(21)]
    placed = [placer.place([f"label number {i}"], [grid[(i * 37) % len(grid)], (5.0, 5.0)])
              for i in range(200)]
    assert 5 < sum(p is not None for p in placed) < 200  # some fit, the crowd is dropped
    boxes = drawn_text(ax)
    assert len(boxes) == sum(p is not None for p in placed)
    assert text_overlaps(boxes) == []
    assert all(ax.bbox.x0 <= b.x0 and b.x1 <= ax.bbox.x1 for _, b in boxes)  # on the axes


def test_a_label_inside_a_room_stays_inside_or_is_refused():
    fig, ax = _axes()
    room = sg.box(1, 1, 3, 1.6)
    assert LabelPlacer(ax).place(["a very long room name indeed"], anchor_points(room),
                                 room, fontsize=12) is None
    t = LabelPlacer(ax).place(["a very long room name indeed", "x"], anchor_points(room),
                              room, fontsize=12)
    assert t is not None and t.get_text() == "x"


def test_rooms_fall_back_to_abbreviation_then_number(drawn_text):
    fig, ax = _axes()
    placer = LabelPlacer(ax)
    names = ["living room", "liv."]
    assert place_room(placer, sg.box(0.5, 0.5, 6, 4), names, 1, fontsize=10)
    assert ax.texts[-1].get_text() == "living room"
    assert place_room(placer, sg.box(6.5, 6.5, 7.6, 7.1), names, 2, fontsize=10)
    assert ax.texts[-1].get_text() == "liv."
    assert not place_room(placer, sg.box(8, 8, 8.35, 8.45), names, 3, fontsize=10)
    assert ax.texts[-1].get_text() == "3"
    boxes = [b for _, b in drawn_text(ax)]
    rooms = [sg.box(0.5, 0.5, 6, 4), sg.box(6.5, 6.5, 7.6, 7.1), sg.box(8, 8, 8.35, 8.45)]
    inv = ax.transData.inverted()
    for box, room in zip(boxes, rooms, strict=True):
        (x0, y0), (x1, y1) = inv.transform(box.get_points())
        assert room.contains(sg.box(x0, y0, x1, y1))


def test_room_names_for_people():
    assert room_label("bedroom_2", "bedroom", several=True) == "bedroom 2"
    assert room_label("kitchen_0", "kitchen", several=False) == "kitchen"
    assert room_abbreviation("bathroom_1", "bathroom", several=True) == "bath 1"
    assert room_abbreviation("den_0", "reading_den", several=False) == "read."
