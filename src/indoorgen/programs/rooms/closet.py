"""A closet: storage along the walls with clothes and boxes put away on it."""
from indoorgen.constraints import ObjSet, Problem, accessibility_cost, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, ceiling_lights, on_floor, on_top


def closet(room: ObjSet) -> Problem:
    """As much storage as fits along the walls, doors free, things put away on it."""
    along_walls = scene().related_to(room, on_floor).related_to(room, against_wall)
    storage = along_walls[S.Storage, S.Furniture].excluding(
        S.Warehouse, S.KitchenCabinet, S.TVStand, S.Vanity, S.WallMounted, S.BathroomFixture)
    stored = scene()[S.Textile].related_to(storage, on_top) | scene()[S.Box].related_to(storage, on_top)
    return Problem(
        constraints={
            "storage along the walls": storage.count().in_range(1, 3),
            "a light": ceiling_lights(room).count() == 1,
            "folded clothes": scene()[S.FoldedClothes].related_to(storage, on_top).count().in_range(0, 6),
            "boxes": scene()[S.Box].related_to(storage, on_top).count().in_range(0, 3),
        },
        score_terms={
            "as much storage as fits": storage.count().maximize(1),
            "things put away": stored.count().maximize(0.2),
            "doors free": accessibility_cost(storage, along_walls).minimize(1),
        },
    )
