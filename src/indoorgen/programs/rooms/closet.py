"""A closet: storage along the walls, with clothes, towels, shoes, boxes and baskets put away on and in
it (what it holds: `programs.contents.CLOSET_HOLDS`)."""
from indoorgen.constraints import ObjSet, Problem, accessibility_cost, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, flush_lights, on_floor


def closet(room: ObjSet) -> Problem:
    """As much storage as fits along the walls (wardrobes, shelving, dressers, cupboards, shoe
    racks; no bedside, living-room or garage pieces), doors free."""
    along_walls = scene().related_to(room, on_floor).related_to(room, against_wall)
    storage = along_walls[S.Storage, S.Furniture].excluding(
        S.Warehouse, S.KitchenCabinet, S.TVStand, S.Vanity, S.WallMounted, S.BathroomFixture,
        S.Nightstand, S.ToolChest, S.StorageRack)
    return Problem(
        constraints={
            "storage along the walls": storage.count().in_range(1, 3),
            "a light": flush_lights(room).count() == 1,
        },
        score_terms={
            "as much storage as fits": storage.count().maximize(1),
            "doors free": accessibility_cost(storage, along_walls).minimize(1),
        },
    )
