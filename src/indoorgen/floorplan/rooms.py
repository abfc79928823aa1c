"""Rooms as the floorplan stage names and counts them: a room is called ``<type>_<k>``, user
room lists read ``bedroom=2,bathroom=1``, and rooms are at least MIN_WIDTH wide (types that may
be narrow, closets, MIN_CLOSET_WIDTH; garages MIN_GARAGE_WIDTH), and generated plans make the
main rooms wider still (`PLANNED_WIDTHS`). Everything else about a type is in
`indoorgen.model.room_types`.
"""
from __future__ import annotations

from typing import Any

from indoorgen.constraints.room_terms import MIN_GARAGE_WIDTH, PLANNED_WIDTHS
from indoorgen.errors import ConfigError
from indoorgen.model.room_types import GARAGE, LIVING_ROOM, ROOM_TYPES, room_type

#: Narrowest a room may be (m); types that may be narrow down to MIN_CLOSET_WIDTH.
MIN_WIDTH = 1.2
MIN_CLOSET_WIDTH = 1.0


def room_type_of(name: str) -> str:
    """The type of a room called ``<type>_<k>``."""
    return name.rsplit("_", 1)[0]


def min_width(t: str) -> float:
    """The narrowest a room of type `t` may be (m)."""
    if t == GARAGE:
        return MIN_GARAGE_WIDTH
    spec = ROOM_TYPES.get(t)
    return MIN_CLOSET_WIDTH if spec is not None and spec.narrow_ok else MIN_WIDTH


def planned_width(t: str) -> float:
    """The narrowest a generated plan makes a room of type `t` (m): `PLANNED_WIDTHS`, at least
    `min_width`."""
    return max(min_width(t), PLANNED_WIDTHS.get(t, 0.0))


def parse_room_counts(spec: str | dict | None) -> dict[str, int]:
    """Parse ``"bedroom=2,bathroom=1"`` (or a dict) into {type: count}.

    Raises UnknownRoomTypeError for an unknown type and ConfigError for a malformed entry or a
    negative count."""
    if spec is None or spec == "":
        return {}
    items: list[tuple[Any, Any]]
    if isinstance(spec, dict):
        items = list(spec.items())
    else:
        items = [(k, v if eq else None) for k, eq, v in
                 (p.partition("=") for p in str(spec).split(",") if p.strip())]
    out: dict[str, int] = {}
    for k, v in items:
        if v is None:
            raise ConfigError(f"--rooms entry {k!r} must be TYPE=COUNT, e.g. bedroom=2")
        t = room_type(k, floorplan=True).name
        try:
            n = int(v)
        except (TypeError, ValueError):
            raise ConfigError(f"--rooms count for {k!r} must be a whole number, "
                              f"got {v!r}") from None
        if n < 0 or n > 12:
            raise ConfigError(f"--rooms count for {k!r} is {n}; it must be between 0 and 12")
        out[t] = n
    if out.get(LIVING_ROOM, 1) < 1:
        raise ConfigError("--rooms living_room=0: a home needs at least one living room")
    return out
