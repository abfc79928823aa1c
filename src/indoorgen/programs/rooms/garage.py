"""A garage: shelving along the walls full of boxes, paint and tools, a workbench with its tools
and maybe a tool chest beside it, and storage boxes on the floor against a wall, all along the
walls (what the furniture holds: `programs.contents.STORE_HOLDS`)."""
from indoorgen.constraints import ObjSet, Problem, accessibility_cost, angle_alignment_cost, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, flush_lights, on_floor, on_top

#: the most storage boxes standing on the floor along the walls
FLOOR_BOXES = 4
#: a tool chest this close (m) to the workbench is at hand from it
AT_HAND = 1.5


def garage(room: ObjSet) -> Problem:
    """Shelving along the walls, reachable, full of boxes; a workbench and a tool chest with
    their fronts free; boxes on the floor by the walls."""
    along_walls = scene().related_to(room, on_floor).related_to(room, against_wall)
    # steel racks or cube shelves: not a shoe rack (its tiers hold no box: a garage given one
    # alone was solved again for want of boxes), nor a corner shelf out of its corner
    shelving = along_walls[S.Shelf].excluding(S.WallMounted, S.Warehouse, S.ShoeRack,
                                              S.CornerShelf)
    boxes = scene()[S.Box].related_to(shelving, on_top)
    benches = along_walls[S.Workbench]
    chests = along_walls[S.ToolChest]
    floor_boxes = along_walls[S.Box]
    return Problem(
        constraints={
            "shelving": shelving.count().in_range(1, 3),
            "boxes on the shelves": boxes.count().in_range(1, 10),
            "a workbench at most": benches.count().in_range(0, 1),
            "a tool chest at most": chests.count().in_range(0, 1),
            "boxes on the floor": floor_boxes.count().in_range(0, FLOOR_BOXES),
            "lights": flush_lights(room).count().in_range(1, 2),
        },
        score_terms={
            "storage": boxes.count().maximize(0.2),
            "a workbench": benches.count().maximize(2),
            "a tool chest": chests.count().maximize(1),
            "the tool chest at hand from the bench": chests.mean(
                lambda c: c.distance(benches).hinge(0.0, AT_HAND)).minimize(1),
            "boxes stored on the floor": floor_boxes.count().maximize(0.3),
            "fronts reachable": accessibility_cost(shelving | benches | chests,
                                                   along_walls).minimize(1),
            "square to the walls": angle_alignment_cost(along_walls, room).minimize(1),
        },
    )
