"""A garage: shelving along the walls with boxes stored on it."""
from indoorgen.constraints import ObjSet, Problem, accessibility_cost, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, ceiling_lights, on_floor, on_top


def garage(room: ObjSet) -> Problem:
    """Shelving along the walls, reachable, full of boxes; the floor left for the car."""
    along_walls = scene().related_to(room, on_floor).related_to(room, against_wall)
    # not a shoe rack: its tiers hold no box (a garage given one alone was solved again for
    # want of boxes; what shelving holds here: `programs.contents.STORE_HOLDS`)
    shelving = along_walls[S.Shelf].excluding(S.WallMounted, S.Warehouse, S.ShoeRack)
    boxes = scene()[S.Box].related_to(shelving, on_top)
    return Problem(
        constraints={
            "shelving": shelving.count().in_range(1, 3),
            "boxes on the shelves": boxes.count().in_range(1, 10),
            "lights": ceiling_lights(room).count().in_range(1, 2),
        },
        score_terms={
            "storage": boxes.count().maximize(0.2),
            "shelves reachable": accessibility_cost(shelving, along_walls).minimize(1),
        },
    )
