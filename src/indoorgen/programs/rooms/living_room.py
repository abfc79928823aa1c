"""A living room: seating facing a TV, a coffee table, bookcases full of books, lamps and art."""
from indoorgen.constraints import (
    ObjSet,
    Problem,
    accessibility_cost,
    angle_alignment_cost,
    focus_score,
    height,
    scene,
)
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, fully_on, on_floor, on_top, on_wall


def living_room(room: ObjSet) -> Problem:
    """Seating facing the TV and a coffee table, filled bookcases, lamps and pictures."""
    floor = scene().related_to(room, on_floor)
    furniture = floor[S.Furniture]
    sofas = floor[S.Sofa].related_to(room, against_wall)
    armchairs = floor[S.Armchair]
    seating = sofas | armchairs
    stands = floor[S.TVStand].related_to(room, against_wall)
    tvs = scene()[S.TV].related_to(stands, fully_on)
    coffee_tables, side_tables, lamps = floor[S.CoffeeTable], floor[S.SideTable], floor[S.FloorLamp]
    bookcases = floor[S.Bookcase].related_to(room, against_wall)
    art = scene()[S.WallArt].related_to(room, on_wall)
    books = scene()[S.Book].related_to(bookcases, on_top)
    vases = scene()[S.Vase].related_to(coffee_tables | side_tables | stands, on_top)
    return Problem(
        constraints={
            "one or two sofas": sofas.count().in_range(1, 2),
            "up to two armchairs": armchairs.count().in_range(0, 2),
            "a TV stand": stands.count().in_range(1, 1),
            "a TV on the stand": stands.all(lambda s: tvs.related_to(s, fully_on).count() == 1),
            "a coffee table": coffee_tables.count().in_range(1, 1),
            "side tables": side_tables.count().in_range(0, 2),
            "bookcases": bookcases.count().in_range(1, 2),
            "floor lamps": lamps.count().in_range(1, 2),
            "pictures": art.count().in_range(1, 3),
            "filled bookcases": bookcases.all(lambda b: books.related_to(b, on_top).count().in_range(8, 24)),
            "vases": vases.count().in_range(1, 3),
        },
        score_terms={
            "seating faces the TV stand": focus_score(seating, stands).minimize(3),
            "the TV stand faces the sofa": focus_score(stands, sofas).minimize(2),
            "seating faces the coffee table": focus_score(seating, coffee_tables).minimize(2),
            "coffee table by the sofa": coffee_tables.mean(
                lambda c: c.distance(sofas).hinge(0.35, 0.6)).minimize(3),
            "lamps beside seating": lamps.mean(
                lambda lamp: lamp.distance(seating).hinge(0.0, 0.3)).minimize(1),
            "side tables beside seating": side_tables.mean(
                lambda t: t.distance(seating).hinge(0.0, 0.2)).minimize(1),
            "nothing but the coffee table before the seating": accessibility_cost(
                seating, floor.excluding(S.CoffeeTable, S.FloorCovering)).minimize(1),
            "furniture square to the walls": angle_alignment_cost(furniture, room).minimize(1),
            "TV faces the room": angle_alignment_cost(tvs, room).minimize(3),
            "screen in view": accessibility_cost(tvs, furniture).minimize(2),
            "books upright in rows": angle_alignment_cost(books, room).minimize(0.5),
            "pictures at eye level": art.mean(lambda a: height(a).hinge(1.4, 1.8)).minimize(2),
            "pictures in view": accessibility_cost(art, furniture).minimize(2),
            "many books": books.count().maximize(0.05),
        },
    )
