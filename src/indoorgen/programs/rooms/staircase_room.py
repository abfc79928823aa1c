"""A staircase room: around the stairs only pictures on the walls and maybe a plant."""
from indoorgen.constraints import ObjSet, Problem, height, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, ceiling_lights, on_floor, on_wall


def staircase_room(room: ObjSet) -> Problem:
    """Little on the floor (the stairs take it), pictures at eye level, a light."""
    on_walls = scene().related_to(room, on_wall)
    plants = scene().related_to(room, on_floor)[S.PottedPlant].related_to(room, against_wall)
    return Problem(
        constraints={
            "pictures": on_walls[S.WallDecoration].count().in_range(0, 2),
            "a plant at most": plants.count().in_range(0, 1),
            "a light": ceiling_lights(room).count().in_range(1, 1),
        },
        score_terms={"pictures at eye level": on_walls.mean(lambda a: height(a).hinge(1.4, 1.8)).minimize(1)},
    )
