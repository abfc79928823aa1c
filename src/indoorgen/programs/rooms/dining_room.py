"""A dining room: a table centred in the room with a matching set of chairs pulled up, on a rug
under them both, a place laid before each chair, a light over the table, a sideboard with things
on it, a display shelf where it fits, plants and art."""
from indoorgen.constraints import (
    ObjSet,
    Problem,
    accessibility_cost,
    angle_alignment_cost,
    center_of_support_distance,
    height,
    rotational_asymmetry,
    scene,
)
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import (
    DOOR_SWING,
    against_wall,
    at_table,
    ceiling_lights,
    fronts_free,
    on_floor,
    on_top,
    on_wall,
    sized_rugs,
    within_reach,
)

#: free floor around a dining table to pull a chair out and pass behind it (m; ergonomic
#: guidance: 0.9 m from the table's edge to a wall)
TABLE_CLEAR = 0.9
#: the most (m, in plan) the light's centre stands off the table's: over its middle, where a
#: pendant hung low (`relations.OVER_TABLE_BOTTOM`) lights the table and no one walks into it
LIGHT_OFF_CENTRE = 0.3
#: a sideboard's height (m): a low cabinet whose top serves the table (and as wide as the
#: cabinet generator makes one)
SIDEBOARD_HEIGHT = 0.9
#: the rug under the table (m): round, wide enough that chairs pulled out stay on it (layout
#: guidance: 0.6 m beyond the table's edges)
RUG_DIAMETER = 2.8
#: a dining room smaller than this (m^2) seats two (a 2.4 x 2.9 m room: a small table for two
#: against a wall or a round one, the way a flat's dining corner is laid), from a square metre
#: more it seats four: the area a table for four needs with its chairs pulled out (0.9 x 0.9 m
#: table, 0.6 m of chair and 0.3 m of passage either side: 3 x 3 m)
TABLE_FOR_TWO_AREA = 8.0
#: chairs asked for per m^2 past TABLE_FOR_TWO_AREA (two more within a square metre)
CHAIRS_PER_M2 = 2.0


def dining_room(room: ObjSet) -> Problem:
    """One table with four to eight matching chairs evenly around it (two in a small room),
    places laid, a light over it, a sideboard, a display shelf where it fits and art in view."""
    floor = scene().related_to(room, on_floor)
    blockers = floor.excluding(S.FloorCovering)
    tables = floor[S.DiningTable]
    chairs = floor[S.DiningChair].related_to(tables, at_table)
    sideboards = floor.of_generator("cabinet", height=SIDEBOARD_HEIGHT, width=1.0, n_doors=2).related_to(
        room, against_wall)
    shelves = floor[S.Bookcase].related_to(room, against_wall)
    plants = floor[S.PottedPlant]
    art = scene()[S.WallArt].related_to(room, on_wall)
    plates = scene()[S.Plate].related_to(tables, on_top)
    cups = scene()[S.Cup].related_to(tables, on_top)
    forks, knives, spoons = (scene()[t].related_to(tables, on_top) for t in (S.Fork, S.Knife, S.Spoon))
    centrepieces = (scene()[S.Vase].related_to(tables, on_top),
                    scene()[S.FruitBowl].related_to(tables, on_top),
                    scene()[S.Candle].related_to(tables, on_top))
    on_sideboard = scene()[S.SmallObject].excluding(
        S.Food, S.Laptop, S.Cutlery, S.Kitchenware, S.Box, S.Bottle, S.Can, S.Textile, S.Shoes,
        S.Workshop).related_to(sideboards, on_top)
    lights = ceiling_lights(room)
    table_rugs = sized_rugs(floor, RUG_DIAMETER, 2.0, shape="round")
    return Problem(
        constraints={
            "one table": tables.count() == 1,
            "chairs at each table": tables.all(
                lambda t: chairs.related_to(t, at_table).count().in_range(2, 8)),
            "four chairs where the room seats four": tables.all(
                lambda t: chairs.related_to(t, at_table).count() >= (
                    2.0 + (room.volume((0, 1)) - TABLE_FOR_TWO_AREA) * CHAIRS_PER_M2).clip(2.0, 4.0)),
            "a place laid for each chair": tables.all(
                lambda t: plates.related_to(t, on_top).count()
                == chairs.related_to(t, at_table).count()),
            "a glass for each place": tables.all(
                lambda t: cups.related_to(t, on_top).count()
                <= chairs.related_to(t, at_table).count()),
            "cutlery": (forks.count() + knives.count() + spoons.count()).in_range(0, 16),
            "a centrepiece": sum((c.count() for c in centrepieces[1:]),
                                 centrepieces[0].count()).in_range(0, 2),
            "a sideboard": sideboards.count().in_range(1, 1),
            "things on the sideboard": on_sideboard.count().in_range(1, 4),
            "a display shelf at most": shelves.count().in_range(0, 1),
            "plants": plants.count().in_range(0, 2),
            "pictures": art.count().in_range(1, 2),
            "a light": lights.count().in_range(1, 1),
            # over the table, not the floor beside it (the table's light, hung low over it)
            "the light over the table": lights.all(
                lambda li: li.center_distance(tables) * 10 <= LIGHT_OFF_CENTRE * 10),
            "a rug at most": table_rugs.count().in_range(0, 1),
            "sideboard front free": fronts_free(sideboards, blockers, room, margin=DOOR_SWING),
            "shelf front free": fronts_free(shelves, blockers, room),
            "within reach": within_reach(on_sideboard),
        },
        score_terms={
            "chairs evenly around": tables.mean(
                lambda t: rotational_asymmetry(chairs.related_to(t, at_table))).minimize(3),
            "table clear of walls": tables.mean(
                lambda t: t.distance(blockers.excluding(S.DiningTable, S.DiningChair) | room)
                .hinge(TABLE_CLEAR, 9.0)).minimize(3),
            "table centred in the room": tables.mean(
                lambda t: t.center_distance(room)).minimize(4),
            "table square to the room": angle_alignment_cost(tables, room).minimize(4),
            "a rug under the table": table_rugs.count().maximize(3),
            "the rug centred under the table": table_rugs.mean(
                lambda r: r.center_distance(tables)).minimize(6),
            "as many chairs as fit": chairs.count().maximize(0.3),
            "places before the chairs": plates.mean(
                lambda p: p.distance(chairs).hinge(0.0, 0.12)).minimize(3),
            "glasses by the plates": cups.mean(lambda c: c.distance(plates).hinge(0.0, 0.12)).minimize(1),
            "cutlery beside the plates": sum(
                (c.mean(lambda x: x.distance(plates).hinge(0.0, 0.06)) for c in (knives, spoons)),
                forks.mean(lambda x: x.distance(plates).hinge(0.0, 0.06))).minimize(1),
            "a laid table": (cups.count() + forks.count() + knives.count()
                             + spoons.count()).maximize(0.3),
            "centrepiece in the middle": sum(
                (center_of_support_distance(c) for c in centrepieces[1:]),
                center_of_support_distance(centrepieces[0])).minimize(1),
            "furniture square to the walls": angle_alignment_cost(blockers, room).minimize(1),
            "plants by the walls": plants.mean(lambda p: p.distance(room).hinge(0.0, 0.1)).minimize(2),
            "pictures at eye level": art.mean(lambda a: height(a).hinge(1.4, 1.8)).minimize(2),
            "pictures in view": accessibility_cost(art, blockers).minimize(2),
            "a light centred over the table": lights.mean(
                lambda li: li.center_distance(tables).hinge(0.0, 0.1)).minimize(6),
            "a display shelf": shelves.count().maximize(1),
            "a furnished room": (on_sideboard.count() + plants.count()
                                 + sum((c.count() for c in centrepieces[1:]),
                                       centrepieces[0].count())).maximize(0.3),
        },
        matching={"chairs": chairs},
    )
