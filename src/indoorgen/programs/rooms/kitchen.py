"""A kitchen: the sink, cooker, dishwasher and fridge along the walls in a working triangle (a
requirement wherever the floor allows one), base units set in beside them and each other into
continuous runs (built, not searched for), wall cabinets hung over the counters and a hood over
the cooker at the heights the guidelines name, maybe an island with stools, and a counter in use:
kettle, toaster, knife block and utensil crock, kitchenware, crockery and food, and maybe an open
shelf over a counter with jars, mugs and herbs."""
from indoorgen.constraints import (
    InLine,
    ObjSet,
    Problem,
    Scalar,
    accessibility_cost,
    angle_alignment_cost,
    facing_angle,
    scene,
)
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from indoorgen.programs.relations import (
    against_wall,
    at_table,
    ceiling_lights,
    hung_above,
    on_floor,
    on_top,
    on_wall,
)

#: the work triangle's legs (m): NKBA Kitchen Planning Guideline 4, each leg 4-9 ft (the
#: quality report's `kitchen_work_triangle` measures the same)
TRIANGLE_LEG = (1.2, 2.7)
#: what the program aims the legs at (a score): inside TRIANGLE_LEG, measured as the report
#: measures them, between the appliances' front centres
TRIANGLE_AIM = (1.4, 2.5)
#: weight of the work triangle's legs outside TRIANGLE_LEG, per metre: four times a run's gap,
#: so a run is not closed up at the cost of a leg
TRIANGLE_WEIGHT = 40
#: the floor (m, each way) on which a work triangle is required: from a kitchen's smallest
#: single room (an L, or a galley with a 1.2 m aisle) to a home's longest. A score alone in
#: kitchens over 4.8 m let 4 of 10 homes' kitchens (5.3 x 4.8 m to 8.8 x 3.8 m, L-shaped and
#: stepped) miss it by 0.14-2.2 m; required, each of them met it (solved in 6-17 s). A
#: kitchen that cannot is solved again, and a home's plan given up (`pipeline.HOME_PLANS`)
TRIANGLE_ROOM_SIDES = (2.8, 9.0)
#: the most a missed triangle weighs as a hard violation (m): less than a missing object, so
#: the solver never drops an appliance to spare a leg
TRIANGLE_HARD_CAP = 0.5
#: the requirement's legs: the guideline's own, as the report measures them (widened by 5 cm,
#: 2 of 20 single kitchens kept legs of 1.187 and 2.735 m and failed the report's rule; exact,
#: both met it, a room's further solves and a home's next plan standing behind a miss)
TRIANGLE_REQUIRED = TRIANGLE_LEG
#: NKBA: wall cabinets 15-18 in above a 36 in counter (bottoms at 1.35-1.5 m): a cabinet hangs
#: this far over its counter (0.86-0.93 m high), so its bottom lands at 1.36-1.43 m
WALL_CABINET_GAP = 0.5
#: range hood 24-36 in (0.6-0.9 m) over the cooking surface (HVI, manufacturers' guides): the
#: hood hangs this far over the range's top (its hob, or its backguard up to 0.22 m above it)
HOOD_GAP = 0.65
#: weight of a hood's centre off the range's, per metre (the report allows 0.15 m across it)
HOOD_CENTRING = 20
#: the least angle (deg) at the cooker between its front and its hood's centre: a hood on the
#: cooker's wall stands behind it (180 when centred; 145 allows it 0.7 times its depth offset,
#: at most 0.2 m: 0.14 m, to a side), one on the next wall of a corner stands beside it (~90)
HOOD_BEHIND = 145
#: appliances "in the run": this close (m) to a counter beside them
IN_RUN = 0.05
#: weight of a run's gaps, per metre of gap (each gap is worth closing before another unit),
#: and the gap the program aims at (a filler strip; IN_RUN is what the report allows)
RUN_WEIGHT = 10
RUN_AIM = 0.01
#: the filler strip between neighbours in a run (m): a door opened to its limit swings up to
#: 2.7 cm (a fridge's up to 4.7 cm) past its unit's side within the first 6 cm before the
#: fronts (the solver's sweeps of these generators), where a neighbour's handles and worktop
#: edge stand; inside IN_RUN
RUN_FILLER = 0.048
#: in the run: a unit's side against its neighbour's across a filler strip, its centre within
#: the neighbour's side (its back on the run's wall, `against_wall`): base units and appliances
#: are set beside each other rather than searched for, placed in one stage (`InLine`)
in_run = InLine(Subpart.Side, Subpart.Side, margin=RUN_FILLER)
#: what a kitchen in use keeps out on its counters, one of each at most
COUNTER_KIT = (S.Kettle, S.Toaster, S.KnifeBlock, S.UtensilCrock)
#: the most jars, mugs and little plants an open shelf holds
SHELF_THINGS = 6
#: free floor round an island (m): NKBA Kitchen Planning Guideline 6, a walkway 36 in wide
ISLAND_AISLE = 0.9


def kitchen(room: ObjSet) -> Problem:
    """Cabinet runs with the sink, cooker and dishwasher in them and the fridge at an end, in a
    working triangle; wall cabinets over the counters, a hood over the cooker, and the everyday
    kit out on the counters."""
    floor = scene().related_to(room, on_floor)
    along_walls = floor.related_to(room, against_wall)
    # one stage builds the runs: the sink and the cooker against the walls a working distance
    # apart, the dishwasher set in beside the sink, base units beside the appliances and each
    # other, and the fridge closing a run's end beside a unit or the dishwasher (not beside the
    # sink or the cooker: the triangle's legs)
    sinks = along_walls[S.KitchenSink]
    cookers = along_walls[S.Range]
    dishwashers = in_the_run(along_walls[S.Dishwasher], sinks)
    units = along_walls[S.KitchenCabinet].excluding(S.KitchenIsland, S.WallMounted)
    fridges = in_the_run(along_walls[S.Fridge], units | dishwashers)
    cabinets = in_the_run(units, units | sinks | cookers | dishwashers)
    islands = floor[S.KitchenIsland]
    stools = floor[S.Stool]
    counters = cabinets | islands
    wall_cabinets = scene()[S.WallCabinet].related_to(room, on_wall).related_to(
        cabinets, hung_above(WALL_CABINET_GAP))
    shelves = scene()[S.WallShelf].related_to(room, on_wall).related_to(
        cabinets, hung_above(WALL_CABINET_GAP))
    shelf_things = scene()[S.Jar] | scene()[S.Cup] | scene()[S.PottedPlant, S.SmallObject]
    on_shelves = shelf_things.related_to(shelves, on_top)
    hoods = scene()[S.RangeHood].related_to(room, on_wall).related_to(
        cookers, hung_above(HOOD_GAP, Subpart.Top))
    lights = ceiling_lights(room)
    set_in_runs = sinks | cookers | dishwashers
    kitchenware = scene()[S.Kitchenware].excluding(*COUNTER_KIT).related_to(counters, on_top)
    kit = {tag: scene()[tag].related_to(cabinets, on_top) for tag in COUNTER_KIT}
    tableware = scene()[S.Tableware].related_to(counters, on_top)
    food = scene()[S.Food].related_to(counters, on_top)
    appliances_on_counters = scene()[S.Microwave].related_to(cabinets, on_top)
    return Problem(
        constraints={
            "cabinet runs": cabinets.count().in_range(1, 4),
            "a sink": sinks.count() == 1,
            "a fridge": fridges.count() == 1,
            "a cooker": cookers.count() == 1,
            "a dishwasher at most": dishwashers.count().in_range(0, 1),
            "units beside the sink": sinks.all(lambda s: beside(units, s).count().in_range(0, 2)),
            "units beside the cooker": cookers.all(lambda c: beside(units, c).count().in_range(0, 2)),
            "an island at most": islands.count().in_range(0, 1),
            "an island stands free": islands.all(
                lambda i: i.distance(along_walls | room) * 100 >= ISLAND_AISLE * 100),
            "stools only at the island": islands.all(
                lambda i: stools.related_to(i, at_table).count().in_range(0, 4)),
            "wall cabinets": wall_cabinets.count().in_range(0, 3),
            "open shelves": shelves.count().in_range(0, 2),
            "jars, mugs and herbs on a shelf": shelves.all(
                lambda sh: shelf_things.related_to(sh, on_top).count() <= SHELF_THINGS),
            "a hood at most": hoods.count().in_range(0, 1),
            # on the cooker's own wall, behind its centre, not on the next wall of a corner (the
            # angle at the cooker from its front to the hood; weighed under an object's worth)
            "a hood behind the cooker": hoods.all(
                lambda h: facing_angle(cookers, h) / 180 >= HOOD_BEHIND / 180),
            "a ceiling light": lights.count().in_range(1, 2),
            "a microwave at most": appliances_on_counters.count().in_range(0, 1),
            # NKBA Guideline 4 where a kitchen has the floor for it: the solver searches (and
            # repairs, and retries the room) until the legs are in range, rather than hoping;
            # capped below an object's worth, so no appliance is ever dropped to spare a leg
            "the work triangle where it fits": (
                work_triangle(sinks, cookers, fridges, TRIANGLE_REQUIRED)
                .clip(0.0, TRIANGLE_HARD_CAP)
                * room_for_triangle(room) <= 0),
            "kitchenware out": kitchenware.count().in_range(1, 6),
            **{f"a {tag.value.replace('_', ' ')} at most": things.count().in_range(0, 1)
               for tag, things in kit.items()},
            "crockery out": tableware.count().in_range(0, 5),
            "food out": food.count().in_range(0, 4),
        },
        score_terms={
            # continuous runs: every unit and appliance slid up to a neighbour along its wall
            "sink, cooker and dishwasher in a run": set_in_runs.mean(
                lambda a: a.distance(cabinets).hinge(0.0, RUN_AIM)).minimize(RUN_WEIGHT),
            "counter space": cabinets.count().maximize(1),
            "the sink set in a run": sinks.mean(
                lambda s: beside(units | dishwashers, s).count()).maximize(3),
            "the cooker set in a run": cookers.mean(lambda c: beside(units, c).count()).maximize(3),
            "a dishwasher": dishwashers.count().maximize(2),
            "an island where it fits": islands.count().maximize(1),
            # the work triangle: each leg between sink, cooker and fridge 1.2-2.7 m (NKBA), aimed
            # well inside so the front centres the report measures land inside too (a guideline
            # a small kitchen may miss: a score, measured by the quality report)
            "the work triangle": work_triangle(sinks, cookers, fridges, TRIANGLE_LEG)
            .minimize(TRIANGLE_WEIGHT),
            # as strong as the runs' gaps: appliances slid together must not close the triangle
            "a comfortable triangle": work_triangle(sinks, cookers, fridges, TRIANGLE_AIM)
            .minimize(2 * RUN_WEIGHT),
            "fronts free": accessibility_cost(along_walls, floor).minimize(2),
            "island clear of the runs": islands.mean(
                lambda i: i.distance(along_walls).hinge(1.0, 9.0)).minimize(3),
            "stools at the island": stools.count().maximize(0.3),
            "a hood centred over the cooker": hoods.mean(
                lambda h: h.center_distance(cookers).hinge(0.0, 0.08)).minimize(HOOD_CENTRING),
            # a hood over every cooker: worth more than its centring's most (a hood against the
            # wall is up to 0.2 m shallower than the range, so its centre always stands off)
            "extraction": hoods.count().maximize(5),
            "storage over the counters": wall_cabinets.count().maximize(0.3),
            "an open shelf over a counter": shelves.count().maximize(0.3),
            "jars, mugs and herbs on the shelves": on_shelves.count().maximize(0.2),
            "square to the walls": angle_alignment_cost(floor, room).minimize(1),
            "a lived-in kitchen": (kitchenware.count() + tableware.count() + food.count()).maximize(0.2),
            "the everyday kit out": sum_counts(list(kit.values())).maximize(0.5),
        },
    )


def work_triangle(sinks: ObjSet, cookers: ObjSet, fridges: ObjSet,
                  legs: tuple[float, float]) -> Scalar:
    """How far (m) the work triangle's three legs, sink-cooker, sink-fridge and cooker-fridge
    (between front centres, as the quality report measures them), fall outside `legs`."""
    return (sinks.mean(lambda s: s.front_distance(cookers).hinge(*legs)
                       + s.front_distance(fridges).hinge(*legs))
            + cookers.mean(lambda c: c.front_distance(fridges).hinge(*legs)))


def room_for_triangle(room: ObjSet) -> Scalar:
    """1 in a kitchen TRIANGLE_ROOM_SIDES each way (its box), where an L or two facing runs fit
    the triangle; 0 where a side is 0.2 m outside them, between the two in between."""
    lo, hi = TRIANGLE_ROOM_SIDES
    x, y = (room.volume((axis,)) for axis in (0, 1))
    return within(x, lo, hi) * within(y, lo, hi)


def within(side: Scalar, lo: float, hi: float) -> Scalar:
    """1 where `side` is between `lo` and `hi` metres, 0 from 0.2 m outside them."""
    return ((side - lo) * 5 + 1).clip(0.0, 1.0) * ((hi - side) * 5 + 1).clip(0.0, 1.0)


def sum_counts(sets: list[ObjSet]) -> Scalar:
    """How many members `sets` hold together."""
    total = sets[0].count()
    for s in sets[1:]:
        total = total + s.count()
    return total


def in_the_run(units: ObjSet, beside: ObjSet) -> ObjSet:
    """Those of `units` (against a wall) set into the run beside one of `beside`."""
    return units.related_to(beside, in_run)


def beside(units: ObjSet, neighbour: ObjSet) -> ObjSet:
    """Those of `units` set into the run beside `neighbour`."""
    return units.related_to(neighbour, in_run)
