"""A dining room: one table with chairs evenly around it and places laid, a light over the table,
art on the walls."""
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
from indoorgen.programs.relations import against_wall, at_table, ceiling_lights, on_floor, on_top, on_wall


def dining_room(room: ObjSet) -> Problem:
    """One table with four to eight chairs evenly around it, places laid, a light over it, art
    in view."""
    floor = scene().related_to(room, on_floor)
    tables = floor[S.DiningTable]
    chairs = floor[S.DiningChair]
    sideboards = floor[S.Cabinet].excluding(
        S.KitchenCabinet, S.BathroomFixture, S.WallMounted).related_to(room, against_wall)
    shelves = floor[S.Bookcase].related_to(room, against_wall)
    storage = sideboards | shelves
    art = scene()[S.WallArt].related_to(room, on_wall)
    plates, cups = scene()[S.Plate], scene()[S.Cup]
    vases = scene()[S.Vase].related_to(tables | storage, on_top)
    lights = ceiling_lights(room)
    return Problem(
        constraints={
            "one table": tables.count() == 1,
            "chairs at each table": tables.all(
                lambda t: chairs.related_to(t, at_table).count().in_range(4, 8)),
            "places laid": tables.all(lambda t: plates.related_to(t, on_top).count().in_range(2, 8)),
            "cups": tables.all(lambda t: cups.related_to(t, on_top).count().in_range(1, 8)),
            "a sideboard or shelf at most": (sideboards.count() + shelves.count()).in_range(0, 1),
            "pictures": art.count().in_range(1, 2),
            "a vase": vases.count().in_range(0, 1),
            "a light": lights.count().in_range(1, 2),
        },
        score_terms={
            "chairs evenly around": tables.mean(
                lambda t: rotational_asymmetry(chairs.related_to(t, at_table))).minimize(3),
            "chairs face the table": tables.mean(
                lambda t: angle_alignment_cost(chairs.related_to(t, at_table), t)).minimize(2),
            "table clear of walls": tables.mean(lambda t: t.distance(room).hinge(0.9, 9.0)).minimize(3),
            "table square to the room": angle_alignment_cost(tables, room).minimize(1),
            "as many chairs as fit": chairs.count().maximize(0.3),
            "vase in the middle": center_of_support_distance(vases).minimize(1),
            "pictures at eye level": art.mean(lambda a: height(a).hinge(1.4, 1.8)).minimize(2),
            "pictures in view": accessibility_cost(art, floor).minimize(2),
            "a light centred over the table": lights.mean(
                lambda li: li.center_distance(tables).hinge(0.0, 0.2)).minimize(3),
        },
    )
