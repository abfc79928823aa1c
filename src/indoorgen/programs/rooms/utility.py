"""A utility room: a washing machine and shelves along the walls, baskets and boxes on them."""
from indoorgen.constraints import ObjSet, Problem, accessibility_cost, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, flush_lights, on_floor, on_top


def utility(room: ObjSet) -> Problem:
    """One or two washing machines with their doors free, and some storage."""
    along_walls = scene().related_to(room, on_floor).related_to(room, against_wall)
    washers = along_walls[S.WashingMachine]
    shelves = along_walls[S.Shelf].excluding(S.Warehouse)
    return Problem(
        constraints={
            "a washing machine": washers.count().in_range(1, 2),
            "shelves": shelves.count().in_range(0, 2),
            "a light": flush_lights(room).count().in_range(1, 1),
            "baskets and boxes": (scene()[S.Basket].related_to(shelves | washers, on_top).count()
                                  + scene()[S.Box].related_to(shelves, on_top).count()).in_range(0, 4),
        },
        score_terms={
            "doors free": accessibility_cost(washers, along_walls).minimize(2),
            "storage": shelves.count().maximize(0.5),
        },
    )
