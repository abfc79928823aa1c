"""The hard rules every generated floorplan keeps, checked room by room on the solver's plan.

They are the solver's own invariants (the default floorplan program states the same ones as
constraints): initial plans are resampled until they hold, and annealing rejects a move that
breaks them for a room it touched before the program is even evaluated. Annealing also keeps
service rooms from growing past `service_cap` (`grows_oversized`); an initial plan is never
dropped for one, so homes keep their planned widths.
"""
from __future__ import annotations

from indoorgen.constraints.room_terms import (
    MIN_BALCONY_EXTERIOR_SHARE,
    MIN_BALCONY_FRONT,
    MIN_DOOR_WALL,
    MIN_VEHICLE_DOOR_WALL,
    SERVICE_ROOMS,
)
from indoorgen.floorplan.rooms import min_width, planned_width, room_type_of
from indoorgen.floorplan.view import GridPlan
from indoorgen.model.room_types import BALCONY, GARAGE, ROOM_TYPES, STAIRCASE_ROOM


def room_problems(plan: GridPlan, o: str) -> list[str]:
    """The rules room `o` breaks (empty if none): a simple polygon, a door-wide wall with each
    graph neighbour, an outside wall where its type (or the front door) needs one, at least
    `planned_width` wide (`min_width` in a plan of a home's last tries) with no narrower neck
    between its parts, at least its least area (`GridPlan.min_area`: more for more doors), a
    balcony on the storey's edge, and the staircase room holding the whole staircase
    placeholder with a door-wide wall clear of its flights and stairwells for each graph
    neighbour."""
    t = room_type_of(o)
    if plan.outline_points(o) is None:
        return [f"{o} is not a simple polygon"]
    spec = ROOM_TYPES[t]
    out = []
    least = plan.min_area(o)
    if plan.area(o) < least - 1e-9:
        out.append(f"{o} is smaller than {least} m^2")
    if t == STAIRCASE_ROOM and plan.stair_coverage(o) < 0.999:
        out.append(f"{o} does not hold the stairs")
    if t == STAIRCASE_ROOM and plan.stair_missing_doors(o):
        out.append(f"{o} has no door-wide wall clear of the stairs with a graph neighbour")
    if (spec.exterior or o == plan.graph.entrance) and \
            plan.longest_exterior_wall(o) < exterior_wall_needed(o) - 1e-9:
        out.append(f"{o} has no outside wall long enough")
    if t == BALCONY and plan.exterior_length(o) < \
            MIN_BALCONY_EXTERIOR_SHARE * plan.perimeter(o) - 1e-9:
        out.append(f"{o} is not on the edge of the storey")
    width = planned_width(t) if plan.planned_widths else min_width(t)
    if plan.narrow_area(o, width) > 0.01:
        out.append(f"{o} is narrower than {width} m")
    elif plan.narrow_pieces(o, width) > 1:
        out.append(f"{o} has a neck narrower than {width} m")
    if plan.missing_doors(o):
        out.append(f"{o} lacks a door-wide wall with a graph neighbour")
    return out


def exterior_wall_needed(o: str) -> float:
    """The straight outside wall room `o` needs (m) if its type or the front door asks for
    one: a garage's vehicle door, a balcony's open front, else a door or window."""
    t = room_type_of(o)
    return MIN_VEHICLE_DOOR_WALL if t == GARAGE else MIN_BALCONY_FRONT if t == BALCONY else \
        MIN_DOOR_WALL


#: annealing grows a service room (`room_terms.SERVICE_ROOMS`) up to this many times its ideal area,
#: or SERVICE_SLACK m^2 over it where that is more (a 7 m^2 bathroom share: up to 10.5 m^2)
SERVICE_CAP = 1.5
SERVICE_SLACK = 3.0


def service_cap(plan: GridPlan, o: str) -> float:
    """The area (m^2) annealing grows service room `o` to at most."""
    ideal = plan.ideal_area(o)
    return max(SERVICE_CAP * ideal, ideal + SERVICE_SLACK)


def service_areas(plan: GridPlan) -> dict[str, float]:
    """Every service room's area now (m^2): what `grows_oversized` compares a move with."""
    return {o: plan.area(o) for o in plan.room_ids() if room_type_of(o) in SERVICE_ROOMS}


def grows_oversized(plan: GridPlan, rooms, before: dict[str, float]) -> bool:
    """Whether a move grew one of `rooms` that is a service room past its `service_cap`
    (`before`: `service_areas` before the move); shrinking one never counts."""
    return any(o in before and before[o] + 1e-9 < plan.area(o) > service_cap(plan, o)
               for o in sorted(rooms))


def breaks_rules(plan: GridPlan, rooms) -> bool:
    """Whether any of `rooms` breaks a rule (stops at the first)."""
    return any(room_problems(plan, r) for r in sorted(rooms))
