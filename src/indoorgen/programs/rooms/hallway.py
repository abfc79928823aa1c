"""A hallway: a console table and a shoe rack by the walls, a mirror or pictures on them."""
from indoorgen.constraints import ObjSet, Problem, angle_alignment_cost, height, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, ceiling_lights, on_floor, on_top, on_wall


def hallway(room: ObjSet) -> Problem:
    """Somewhere for shoes and keys, a mirror or pictures at eye level, the passage kept square."""
    along_walls = scene().related_to(room, on_floor).related_to(room, against_wall)
    furniture = along_walls[S.ConsoleTable] | along_walls[S.ShoeRack]
    on_walls = scene().related_to(room, on_wall)
    return Problem(
        constraints={
            "a console table at most": along_walls[S.ConsoleTable].count().in_range(0, 1),
            "a shoe rack at most": along_walls[S.ShoeRack].count().in_range(0, 1),
            "a mirror or pictures": (on_walls[S.Mirror].count() + on_walls[S.WallArt].count()).in_range(1, 3),
            "ceiling lights": ceiling_lights(room).count().in_range(1, 2),
            "things on the console": scene()[S.Decor].related_to(
                along_walls[S.ConsoleTable], on_top).count().in_range(0, 2),
        },
        score_terms={
            "a place for shoes and keys": furniture.count().maximize(0.5),
            "pictures at eye level": on_walls.mean(lambda a: height(a).hinge(1.3, 1.8)).minimize(1),
            "square to the walls": angle_alignment_cost(along_walls, room).minimize(1),
        },
    )
