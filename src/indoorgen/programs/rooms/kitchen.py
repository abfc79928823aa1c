"""A kitchen: cabinet runs along the walls with a sink, a fridge and a cooker, wall cabinets
above, maybe an island with stools, and kitchenware on the counters."""
from indoorgen.constraints import ObjSet, Problem, accessibility_cost, angle_alignment_cost, height, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import (
    against_wall,
    at_table,
    ceiling_lights,
    fully_on,
    on_floor,
    on_top,
    on_wall,
)

#: the work triangle's legs (m): NKBA Kitchen Planning Guideline 4, each leg 4-9 ft (the
#: quality report's `kitchen_work_triangle` measures the same)
TRIANGLE_LEG = (1.2, 2.7)


def kitchen(room: ObjSet) -> Problem:
    """Cabinet runs with a sink, a fridge and a cooker in a working triangle, a hood over the
    cooker."""
    floor = scene().related_to(room, on_floor)
    along_walls = floor.related_to(room, against_wall)
    cabinets = along_walls[S.KitchenCabinet].excluding(S.KitchenIsland, S.WallMounted)
    sinks = along_walls[S.KitchenSink]
    fridges = along_walls[S.Fridge]
    cookers = along_walls[S.Range]
    dishwashers = along_walls[S.Dishwasher]
    islands = floor[S.KitchenIsland]
    stools = floor[S.Stool]
    wall_cabinets = scene()[S.WallCabinet].related_to(room, on_wall)
    hoods = scene()[S.RangeHood].related_to(room, on_wall)
    lights = ceiling_lights(room)
    counters = cabinets | islands
    kitchenware = scene()[S.Kitchenware].related_to(counters, on_top)
    tableware = scene()[S.Tableware].related_to(counters, on_top)
    food = scene()[S.Food].related_to(counters, on_top)
    appliances_on_counters = scene()[S.Microwave].related_to(cabinets, fully_on)
    return Problem(
        constraints={
            "cabinet runs": cabinets.count().in_range(1, 4),
            "a sink": sinks.count() == 1,
            "a fridge": fridges.count() == 1,
            "a cooker": cookers.count() == 1,
            "a dishwasher at most": dishwashers.count().in_range(0, 1),
            "an island at most": islands.count().in_range(0, 1),
            "stools only at the island": islands.all(
                lambda i: stools.related_to(i, at_table).count().in_range(0, 4)),
            "wall cabinets": wall_cabinets.count().in_range(0, 3),
            "a hood at most": hoods.count().in_range(0, 1),
            "a ceiling light": lights.count().in_range(1, 2),
            "a microwave at most": appliances_on_counters.count().in_range(0, 1),
            "kitchenware out": kitchenware.count().in_range(1, 6),
            "crockery out": tableware.count().in_range(0, 6),
            "food out": food.count().in_range(0, 4),
        },
        score_terms={
            # the work triangle: each leg between sink, cooker and fridge 1.2-2.7 m (NKBA)
            "sink to cooker": sinks.mean(lambda s: s.distance(cookers).hinge(*TRIANGLE_LEG)).minimize(2),
            "sink to fridge": sinks.mean(lambda s: s.distance(fridges).hinge(*TRIANGLE_LEG)).minimize(2),
            "cooker to fridge": fridges.mean(lambda f: f.distance(cookers).hinge(*TRIANGLE_LEG)).minimize(2),
            "counter space": cabinets.count().maximize(1),
            "fronts free": accessibility_cost(along_walls, floor).minimize(2),
            "island clear of the runs": islands.mean(
                lambda i: i.distance(along_walls).hinge(1.0, 9.0)).minimize(3),
            "stools at the island": stools.count().maximize(0.3),
            "a hood centred over the cooker": hoods.mean(
                lambda h: h.center_distance(cookers).hinge(0.0, 0.1)).minimize(3),
            "hood at head height": hoods.mean(lambda h: height(h).hinge(1.7, 2.0)).minimize(2),
            "extraction": hoods.count().maximize(0.5),
            "wall cabinets over counters": wall_cabinets.mean(
                lambda w: w.distance(cabinets).hinge(0.0, 0.05)).minimize(2),
            "square to the walls": angle_alignment_cost(floor, room).minimize(1),
            "a lived-in kitchen": (kitchenware.count() + tableware.count() + food.count()).maximize(0.2),
        },
    )
