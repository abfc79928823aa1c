"""A user-written constraint program: a reading and dining room.

A round table with chairs spaced evenly around it, a sofa facing a TV, and bookcases against the
walls holding books. Run it with the CLI:

    indoorgen generate --seed 1 --size 6.5 5.5 --program examples/my_room.py:round_table_room

or from Python: `indoorgen.GenerateConfig(program=round_table_room, size=(6.5, 5.5))`.
"""
from indoorgen.constraints import (
    Problem,
    accessibility_cost,
    angle_alignment_cost,
    focus_score,
    rotational_asymmetry,
    scene,
)
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, at_table, on_floor, on_top


def round_table_room(room) -> Problem:
    floor = scene().related_to(room, on_floor)
    tables = floor[S.DiningTable].of_generator("dining_table_round")
    chairs = floor[S.DiningChair]
    sofas = floor[S.Sofa].related_to(room, against_wall)
    stands = floor[S.TVStand].related_to(room, against_wall)
    tvs = scene()[S.TV].related_to(stands, on_top)
    bookcases = floor[S.Bookcase].related_to(room, against_wall)
    books = scene()[S.Book].related_to(bookcases, on_top)
    return Problem(
        constraints={
            "one round table": tables.count() == 1,
            "four to six chairs at it": tables.all(
                lambda t: chairs.related_to(t, at_table).count().in_range(4, 6)),
            "a sofa": sofas.count() == 1,
            "a TV on a stand": stands.count() == 1,
            "the TV": stands.all(lambda s: tvs.related_to(s, on_top).count() == 1),
            "two bookcases": bookcases.count() == 2,
            "books on every bookcase": bookcases.all(
                lambda b: books.related_to(b, on_top).count().in_range(6, 20)),
        },
        score_terms={
            "chairs evenly around the table": tables.mean(
                lambda t: rotational_asymmetry(chairs.related_to(t, at_table))).minimize(5),
            "sofa faces the TV": focus_score(sofas, stands).minimize(4),
            "nothing between sofa and TV": accessibility_cost(sofas, floor).minimize(1),
            "table clear of the walls": tables.mean(lambda t: t.distance(room).hinge(1.0, 9.0)).minimize(2),
            "books upright in rows": angle_alignment_cost(books, room).minimize(0.5),
        },
    )
