"""Plan symbols (indoorgen.render.symbols): openings drawn at their real width."""
from __future__ import annotations

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Arc

from indoorgen.architecture.walls import WallThickness, door_frame, window_frame
from indoorgen.model.floorplan import VehicleDoor
from indoorgen.model.floorplan_io import from_json
from indoorgen.render.symbols import (
    DOOR_COLOUR,
    WINDOW_COLOUR,
    draw_storey_openings,
    leaf_width,
    nice_length,
    storey_walls,
    vehicle_door_frame,
)
from support.plans import apartment


def _drawn(fp):
    fig = Figure()
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    storey = fp.storeys[0]
    draw_storey_openings(ax, fp, storey, WallThickness(), fp.room_depths())
    return ax, storey


def test_door_arcs_have_the_leaf_width_and_openings_none():
    fp = from_json(apartment())
    ax, storey = _drawn(fp)
    assert storey.openings, "the apartment has an open kitchen"
    arcs = [p for p in ax.patches if isinstance(p, Arc)]
    widths = [d.width for d in storey.doors] + [fp.entrance.width]
    assert len(arcs) == len(widths)  # one per hinged door, none for open connections
    assert sorted(a.width / 2 for a in arcs) == sorted(leaf_width(w) for w in widths)
    assert all(0.6 < a.width / 2 < 1.0 for a in arcs)
    for a in arcs:  # each arc is centred on a door's hinge, at a jamb of a real door
        hinge = np.asarray(a.center)
        near = [np.linalg.norm(hinge - door_frame(storey, d, WallThickness()).center)
                for d in storey.doors]
        ent = np.linalg.norm(hinge - np.asarray(fp.entrance.center))
        assert min(near + [ent]) < 0.6


def test_windows_are_a_double_line_across_their_width():
    fp = from_json(apartment())
    ax, storey = _drawn(fp)
    glass = [ln for ln in ax.lines if ln.get_color() == WINDOW_COLOUR]
    assert len(glass) == 2 * len(storey.windows)
    t = WallThickness()
    for w in storey.windows:
        f = window_frame(storey, w, t)
        mine = [np.asarray(ln.get_xydata()) for ln in glass
                if np.linalg.norm(np.asarray(ln.get_xydata()).mean(axis=0) - f.center) < 0.1]
        assert len(mine) == 2
        for xy in mine:
            assert abs(np.linalg.norm(xy[1] - xy[0]) - w.width) < 1e-9


def test_walls_are_cut_at_every_opening():
    fp = from_json(apartment())
    storey = fp.storeys[0]
    t = WallThickness()
    walls = storey_walls(fp, storey, t)
    for d in storey.doors + storey.openings:
        f = door_frame(storey, d, t)
        assert walls.intersection(f.rect(d.width - 0.02, -0.05, 0.05)).area < 1e-9


def test_vehicle_doors_cut_the_wall_and_are_drawn_at_their_width():
    fp = from_json(apartment())
    fp.vehicle_doors.append(VehicleDoor("kitchen_0", (8.0, 0.0), 2.4))  # its 4 m outside wall
    t = WallThickness()
    storey = fp.storeys[0]
    f = vehicle_door_frame(storey, fp.vehicle_doors[0], t)
    assert np.allclose(f.n, [0.0, -1.0])  # out of the house
    walls = storey_walls(fp, storey, t)
    assert walls.intersection(f.rect(2.38, -t.exterior / 2, t.exterior / 2)).area < 1e-9
    ax, _ = _drawn(fp)
    heavy = [np.asarray(ln.get_xydata()) for ln in ax.lines
             if ln.get_color() == DOOR_COLOUR and ln.get_linewidth() > 2]
    assert len(heavy) == 1  # the closed door, across the opening in the wall
    assert abs(np.linalg.norm(heavy[0][1] - heavy[0][0]) - 2.4) < 1e-9
    assert np.all(np.abs(heavy[0][:, 1]) < t.exterior / 2)


def test_scale_bar_lengths_are_round():
    assert nice_length(14.0) == 2.0
    assert nice_length(6.0) == 1.0
    assert nice_length(30.0) == 5.0
    assert nice_length(0.8) == 0.1
