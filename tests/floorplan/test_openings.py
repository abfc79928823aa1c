"""Doors, windows, the front door and stairs of a solved plan (indoorgen.floorplan.openings)
follow the room-type table."""
from __future__ import annotations

import numpy as np
import shapely.geometry as sg

from indoorgen.floorplan.generate import FloorplanConfig, generate_floorplan
from indoorgen.floorplan.openings import (
    DOOR_HEIGHT,
    END_DOOR_TYPES,
    END_MARGIN,
    MAX_OPENING,
    door_width,
)
from indoorgen.floorplan.rooms import room_type_of
from indoorgen.floorplan.solve import FloorplanAnnealConfig
from indoorgen.model.room_types import ROOM_TYPES
from support.plans import two_storey_home


def test_door_widths_come_from_the_table():
    assert door_width("bathroom_2") == 0.8 and door_width("bedroom_0") == 0.9
    assert door_width("garage_0") == ROOM_TYPES["garage"].door_width


def test_generated_openings_follow_the_table():
    fp, _ = two_storey_home()
    counts: dict[str, int] = {}
    for s in fp.storeys:
        for d in s.doors:
            assert d.height == DOOR_HEIGHT
            assert d.width in {door_width(r) for r in d.rooms}
        for w in s.windows:
            spec = ROOM_TYPES[room_type_of(w.room)].windows
            assert spec is not None, w.room
            assert spec.min_width - 1e-9 <= w.width <= spec.max_width + 1e-9
            assert (w.height, w.sill) == (spec.height, spec.sill)
            counts[w.room] = counts.get(w.room, 0) + 1
    for room, n in counts.items():
        assert n <= ROOM_TYPES[room_type_of(room)].windows.max_count, room
    assert fp.entrance is not None and fp.entrance.width == 1.0
    (st,) = fp.stairs
    assert (st.from_level, st.to_level) == (0, 1)


def test_kitchen_and_bathroom_doors_stand_near_a_corner():
    """A door into a kitchen or bathroom goes at an end of its wall, never mid-wall: by one of
    the room's corners, so the counter run or the fixtures keep the wall unbroken, or, where
    the other room meets the middle of a long wall, by that room's corner."""
    doors, by_own = 0, 0
    for seed in range(6):
        fp = generate_floorplan(seed, FloorplanConfig(anneal=FloorplanAnnealConfig(
            steps_per_storey=20)))
        for s in fp.storeys:
            for d in s.doors:
                for r in (r for r in d.rooms if room_type_of(r) in END_DOOR_TYPES):
                    gaps = [np.min(np.hypot(*(np.asarray(s.room(o).shape().exterior.coords)
                                             - np.asarray(d.center)).T)) - d.width / 2
                            for o in (r, *(o for o in d.rooms if o != r))]
                    doors += 1
                    by_own += gaps[0] <= END_MARGIN + 0.25
                    assert min(gaps) <= END_MARGIN + 0.25, (seed, d.name, gaps)
    assert doors >= 8 and by_own >= 0.8 * doors, (by_own, doors)


def test_an_open_connection_leaves_wall_either_side_when_its_wall_is_long():
    """An opening between a living and a dining room (or dining room and kitchen) is at most
    MAX_OPENING wide and centred in the wall the two rooms share: a long wall keeps a stretch
    either side for furniture."""
    walls = 0
    for seed in range(12):
        fp = generate_floorplan(seed, FloorplanConfig(anneal=FloorplanAnnealConfig(
            steps_per_storey=20)))
        for s in fp.storeys:
            for o in s.openings:
                a, b = (s.room(r).shape() for r in o.rooms)
                shared = a.boundary.intersection(b.boundary)
                assert o.width <= MAX_OPENING + 1e-9
                assert shared.distance(sg.Point(o.center)) < 1e-6
                if shared.length > MAX_OPENING + 1.0:
                    walls += 1
                    ends = [sg.Point(o.center).distance(sg.Point(e))
                            for g in getattr(shared, "geoms", [shared]) for e in g.coords]
                    assert min(ends) >= o.width / 2 + 0.5 - 1e-6, (seed, o.name)
    assert walls >= 1
