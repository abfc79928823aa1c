"""A balcony: a seat or two against the wall, potted plants, maybe a small table."""
from indoorgen.constraints import ObjSet, Problem, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, on_floor


def balcony(room: ObjSet) -> Problem:
    """Somewhere to sit and plenty of green, the plants by the walls."""
    floor = scene().related_to(room, on_floor)
    seats = floor[S.Seating].excluding(S.Sofa, S.OfficeChair, S.BarStool).related_to(room, against_wall)
    plants = floor[S.PottedPlant]
    return Problem(
        constraints={
            "somewhere to sit": seats.count().in_range(1, 2),
            "plants": plants.count().in_range(1, 4),
            "a small table at most": floor[S.SideTable].count().in_range(0, 1),
        },
        score_terms={
            "plants by the walls": plants.mean(lambda p: p.distance(room).hinge(0.0, 0.2)).minimize(1),
            "green": plants.count().maximize(0.3),
        },
    )
