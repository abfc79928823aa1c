"""Room-level DSL terms: the solver's grid view agrees with the polygon-based defaults, the
evaluator stays incremental and exact under floorplan moves, and users can write programs."""
from __future__ import annotations

import math

import pytest
import shapely.geometry as sg

from indoorgen.constraints import Problem, scene
from indoorgen.constraints.evaluator import Evaluator
from indoorgen.constraints.room_terms import (
    SERVICE_ROOMS,
    RoomView,
    aspect_ratio,
    convexity,
    exterior_length,
    ideal_areas,
    narrow_area,
    ratio_mismatch,
    room_area,
    rooms_of,
    wall_count,
)
from indoorgen.floorplan.generate import FloorplanConfig, build_plan, generate_floorplan
from indoorgen.floorplan.solve import FloorplanAnnealConfig, anneal
from indoorgen.model.room_types import ROOM_TYPES
from indoorgen.model.tags import Semantics
from indoorgen.programs.floorplan import floorplan
from indoorgen.rng import stream


class PolygonView(RoomView):
    """The polygon-only defaults over a solver plan's current rooms (a second opinion)."""

    def __init__(self, plan):
        super().__init__()
        self.plan = plan

    def room_ids(self): return self.plan.room_ids()
    def storey_ids(self): return self.plan.storey_ids()
    def polygon(self, o): return sg.Polygon(self.plan.outline_points(o))
    def room_type(self, o): return self.plan.room_type(o)
    def level(self, o): return self.plan.level(o)
    def neighbours(self, o): return self.plan.neighbours(o)
    def contour(self, level): return self.plan.contour(level)
    def entry_point(self, level): return self.plan.entry_point(level)
    def entry_room(self, level): return self.plan.entry_room(level)
    def stair_polygon(self): return self.plan.stair_polygon()
    def typical_area(self, o): return self.plan.typical_area(o)


@pytest.mark.parametrize("seed, floors", [(0, 1), (4, 1), (2, 2)])
def test_grid_measures_match_polygon_measures(seed, floors):
    plan = build_plan(seed, FloorplanConfig(floors=floors))
    ref = PolygonView(plan)
    for o in plan.room_ids():
        for m in ("area", "aspect_ratio", "convexity", "wall_count", "exterior_length",
                  "exterior_corners", "stair_coverage", "stair_iou", "path_directness",
                  "ideal_area", "longest_exterior_wall"):
            assert getattr(plan, m)(o) == pytest.approx(getattr(ref, m)(o), abs=1e-6), (o, m)
        for w in (1.2, 2.0):
            assert plan.narrow_area(o, w) == pytest.approx(ref.narrow_area(o, w), abs=1e-6)
        for n in plan.neighbours(o):
            assert plan.shared_wall(o, n)[0] == pytest.approx(ref.shared_wall(o, n)[0], abs=1e-6)
        assert plan.missing_doors(o) == ref.missing_doors(o) == 0


def test_incremental_evaluation_is_exact_and_local():
    plan = build_plan(1, FloorplanConfig(floors=2))
    # check=True compares every incremental evaluation against a full one
    stats = anneal(plan, floorplan(), stream(1, "t"), FloorplanAnnealConfig(steps_per_storey=40,
                                                                   check=True))
    assert stats.accepted > 0
    ev = Evaluator(floorplan(), plan)
    ev.evaluate()
    full = ev.recomputed
    room = plan.names[0][-1]
    before = ev.recomputed
    ev.notify([room])
    ev.evaluate()
    assert 0 < ev.recomputed - before < full / 4


def test_annealing_lowers_the_objective():
    for seed in range(4):
        fp = generate_floorplan(seed, FloorplanConfig(anneal=FloorplanAnnealConfig(steps_per_storey=150)))
        a = fp.info["anneal"]
        assert a["objective_end"] < a["objective_start"]
        assert fp.info["stats"].end.violation == 0


def test_a_user_program_drives_the_solver():
    def compact(): 
        rooms = scene()[Semantics.Room]
        return Problem(
            constraints={"bedrooms are big": rooms_of(rooms, "bedroom").all(
                lambda r: room_area(r) >= 7.0)},
            score_terms={"square": rooms.sum(lambda r: (aspect_ratio(r) - 1) ** 2).minimize(),
                         "convex": rooms.sum(lambda r: convexity(r) - 1).minimize(2),
                         "few walls": rooms.sum(wall_count).minimize(0.1),
                         "no narrow bits": rooms.sum(lambda r: narrow_area(r, 2.0)).minimize(),
                         "balanced": rooms.sum(lambda r: ratio_mismatch(room_area(r), 12.0)
                                               ).minimize(),
                         "outside": rooms.sum(exterior_length).maximize(0.01)})
    fp = generate_floorplan(3, FloorplanConfig(program=compact,
                                               anneal=FloorplanAnnealConfig(steps_per_storey=100)))
    a = fp.info["anneal"]
    assert set(a["terms_end"]) == {"square", "convex", "few walls", "no narrow bits",
                                   "balanced", "outside"}
    assert a["objective_end"] <= a["objective_start"]


def _ideal(types: list[str], area: float) -> list[float]:
    return ideal_areas([ROOM_TYPES[t].typical_area for t in types],
                       [t in SERVICE_ROOMS for t in types], area)


TYPES = ["living_room", "kitchen", "bedroom", "bedroom", "bathroom", "closet", "utility"]


@pytest.mark.parametrize("area", [60.0, 97.0, 150.0, 240.0])
def test_ideal_areas_share_the_whole_storey(area):
    assert math.isclose(sum(_ideal(TYPES, area)), area)


def test_spare_area_goes_to_the_rooms_one_lives_in():
    """A storey larger than its rooms' typical areas keeps its bathroom, closet and utility room
    at their typical areas; the living room and the bedrooms grow."""
    got = dict(zip(range(len(TYPES)), _ideal(TYPES, 200.0), strict=True))
    for i, t in enumerate(TYPES):
        if t in SERVICE_ROOMS:
            assert got[i] == pytest.approx(ROOM_TYPES[t].typical_area)
        else:
            assert got[i] > ROOM_TYPES[t].typical_area


def test_a_tight_storey_shrinks_every_room_alike():
    typical = [ROOM_TYPES[t].typical_area for t in TYPES]
    got = _ideal(TYPES, 0.8 * sum(typical))
    assert got == pytest.approx([0.8 * a for a in typical])
