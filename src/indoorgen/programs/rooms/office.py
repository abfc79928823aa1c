"""A home office or study: a desk with a chair and a screen, shelves of books and files."""
from indoorgen.constraints import ObjSet, Problem, accessibility_cost, angle_alignment_cost, height, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import (
    against_wall,
    at_table,
    ceiling_lights,
    on_floor,
    on_top,
    on_wall,
)

#: books' centres no higher than this (m): resting on a shelf below eye level (~1.6 m, the reach
#: rule's limit), where one takes them down every day
BOOK_REACH = 1.65


def office(room: ObjSet) -> Problem:
    """A desk with a chair and a screen, lit; bookcases of books; pictures at eye level."""
    floor = scene().related_to(room, on_floor)
    desks = floor[S.Desk].related_to(room, against_wall)
    chairs = floor[S.OfficeChair]
    bookcases = floor[S.Bookcase].related_to(room, against_wall)
    books = scene()[S.Book].related_to(bookcases, on_top)
    on_desks = scene().related_to(desks, on_top)
    return Problem(
        constraints={
            "a desk": desks.count().in_range(1, 2),
            "a chair at each desk": desks.all(lambda d: chairs.related_to(d, at_table).count() == 1),
            "screens on the desk": desks.all(
                lambda d: scene()[S.Monitor].related_to(d, on_top).count().in_range(0, 2)),
            "a lamp": on_desks[S.DeskLamp].count().in_range(0, 1),
            "a laptop at most": on_desks[S.Laptop].count().in_range(0, 1),
            "bookcases": bookcases.count().in_range(1, 2),
            "books": bookcases.all(lambda b: books.related_to(b, on_top).count().in_range(6, 24)),
            "a light": ceiling_lights(room).count() == 1,
            "pictures": scene()[S.WallDecoration].related_to(room, on_wall).count().in_range(0, 2),
        },
        score_terms={
            "a screen to work at": scene()[S.Monitor].related_to(desks, on_top).count().maximize(0.5),
            "desk well lit": on_desks[S.DeskLamp].count().maximize(0.3),
            "shelves free": accessibility_cost(bookcases, floor).minimize(1),
            "square to the walls": angle_alignment_cost(floor, room).minimize(1),
            "books upright": angle_alignment_cost(books, room).minimize(0.5),
            "books within reach": books.mean(lambda b: height(b).hinge(0.0, BOOK_REACH)).minimize(1),
            "pictures at eye level": scene()[S.WallDecoration].related_to(room, on_wall).mean(
                lambda a: height(a).hinge(1.3, 1.8)).minimize(1),
        },
    )
