"""A good home floorplan, as a constraint program over rooms (Infinigen Indoors, D.3).

The hard constraints are what every accepted plan keeps; the twelve score terms are the paper's
objective. Write your own with the same terms (`indoorgen.constraints.room_terms`) and pass it
as `FloorplanConfig(program=...)`.
"""
from collections.abc import Callable

from indoorgen.constraints import ObjSet, Problem, Scalar, scene
from indoorgen.constraints.room_terms import (
    MIN_BALCONY_EXTERIOR_SHARE,
    MIN_BALCONY_FRONT,
    MIN_DOOR_WALL,
    MIN_GARAGE_WIDTH,
    MIN_VEHICLE_DOOR_WALL,
    STOREY,
    aspect_ratio,
    convexity,
    exterior_corners,
    exterior_length,
    ideal_area,
    longest_exterior_wall,
    min_area,
    missing_doors,
    narrow_area,
    on_storey,
    outline_corners,
    outline_length,
    path_directness,
    perimeter,
    ratio_mismatch,
    room_area,
    rooms_of,
    stair_coverage,
    stair_iou,
    storey_area,
    wall_count,
    wall_lines,
)
from indoorgen.constraints.scalars import ScalarLike
from indoorgen.model.tags import Semantics


def floorplan() -> Problem:
    """The default floorplan program: the solver's hard rules and D.3's twelve terms."""
    rooms, storeys = scene()[Semantics.Room], scene()[STOREY]
    stairs = rooms_of(rooms, "staircase_room")
    with_a_view = rooms_of(rooms, "bedroom", "balcony")
    functional = rooms_of(rooms, "kitchen", "bedroom", "living_room", "bathroom", "dining_room")
    square = rooms_of(rooms, "kitchen", "bedroom", "living_room", "dining_room", "bathroom",
                      "garage", "utility")

    def each_room(of: ObjSet, term: Callable[[ObjSet], ScalarLike]) -> Scalar:
        # summed storey by storey, so a move re-sums one storey only
        return storeys.sum(lambda s: on_storey(of, s).sum(term))

    def share(part: ObjSet, measure: Callable[[ObjSet], Scalar],
              total: Callable[[ObjSet], Scalar]) -> Scalar:
        # (part's share of each storey's total - 1)^2
        return storeys.sum(
            lambda s: (on_storey(part, s).sum(measure).safediv(total(s), 1.0) - 1) ** 2)

    return Problem(
        constraints={
            "graph neighbours share a door-wide wall": rooms.all(lambda r: missing_doors(r) == 0),
            "bedrooms have an outside wall": rooms_of(rooms, "bedroom").all(
                lambda r: longest_exterior_wall(r) >= MIN_DOOR_WALL),
            "garages have an outside wall for the vehicle door": rooms_of(rooms, "garage").all(
                lambda r: longest_exterior_wall(r) >= MIN_VEHICLE_DOOR_WALL),
            "balconies lie on the edge of the storey": rooms_of(rooms, "balcony").all(
                lambda r: (longest_exterior_wall(r) >= MIN_BALCONY_FRONT)
                & (exterior_length(r) >= MIN_BALCONY_EXTERIOR_SHARE * perimeter(r))),
            "garages at least 3 m wide": rooms_of(rooms, "garage").all(
                lambda r: narrow_area(r, MIN_GARAGE_WIDTH) <= 0.01),
            "the entrance has an outside wall for the front door": rooms["entrance"].all(
                lambda r: longest_exterior_wall(r) >= MIN_DOOR_WALL),
            "rooms at least 1.2 m wide": rooms.excluding("closet").all(
                lambda r: narrow_area(r, 1.2) <= 0.01),
            "closets at least 1 m wide": rooms_of(rooms, "closet").all(
                lambda r: narrow_area(r, 1.0) <= 0.01),
            "rooms big enough for their use": rooms.all(lambda r: room_area(r) >= min_area(r)),
            "the staircase room holds the stairs": stairs.all(
                lambda r: stair_coverage(r) >= 0.999),
        },
        score_terms={
            "shortest path to entrance": each_room(
                rooms, lambda r: (1 - path_directness(r)) ** 2).minimize(4),
            "typical room area": each_room(
                rooms, lambda r: ratio_mismatch(room_area(r), ideal_area(r)) - 1).minimize(2),
            "square rooms": each_room(square, lambda r: (aspect_ratio(r) - 1) ** 2).minimize(1),
            "convex rooms": each_room(rooms, lambda r: (convexity(r) - 1) ** 2).minimize(8),
            "concise walls": each_room(rooms, lambda r: (wall_count(r) - 4) ** 2).minimize(0.15),
            "functional area": share(functional, room_area, storey_area).minimize(4),
            "collinear walls": storeys.sum(
                lambda s: wall_lines(on_storey(rooms, s))).minimize(0.05),
            "few narrow passages": each_room(rooms.excluding("hallway", "closet"),
                                             lambda r: narrow_area(r, 2.0)).minimize(0.3),
            "bedrooms and balconies get the outside walls": share(
                with_a_view, exterior_length, outline_length).minimize(2),
            "bedrooms and balconies get the corners": share(
                with_a_view, exterior_corners, outline_corners).minimize(1),
            "staircase occupancy": stairs.sum(lambda r: (stair_coverage(r) - 1) ** 2).minimize(4),
            "staircase IoU": stairs.sum(lambda r: (stair_iou(r) - 1) ** 2).minimize(2),
        },
    )
