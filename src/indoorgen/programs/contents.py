"""What furniture holds, in every room: books and decor on shelves, dishes in kitchen cabinets,
food in the fridge, plates in the dishwasher, a bowl in the microwave, clothes (hung from the
rail and folded) and shoes in wardrobes, folded clothes in dressers' drawers, shoes on shoe
racks, books in nightstands and a lamp, a book or two and a little decor on them, lamps and
decor on dressers, tableware on dining tables; in a closet, clothes, towels, shoes, boxes and
baskets, and on a garage's or utility room's shelves, boxes, baskets, shoes, paint and
toolboxes (`HOLDS_BY_ROOM`); tools, paint and jars of screws on a workbench and a tool chest.
`contents(room, fullness, room_type)` is one `Problem` that `programs.get_program` adds to every
room program, so the room programs only say which furniture stands where.

Counts are per piece of furniture and scale with `fullness` (a per-scene factor: below 1 a
sparse home, above 1 a cluttered one). No lower bounds: a score term rewards every object put
away, so storage fills as far as its shelves have room, and the caps mix the kinds of things
(no single kind crowds a room). Everyday things stay within reach.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from indoorgen.constraints import Constraint, Not, ObjSet, Problem, Relation, scene
from indoorgen.constraints import height as height_of
from indoorgen.constraints.node import Tag
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import hung_from, inside, on_floor, on_top, on_wall

#: everyday objects rest no higher than eye level (~1.6 m, 50th-percentile adult eye height,
#: the top of the comfortable-reach zone in ergonomic storage guidance); the quality report's
#: `reach` rule measures the same
REACH_HEIGHT = 1.6
#: object classes used every day (the reach rule's subjects), which must rest within reach
EVERYDAY = (S.Laptop, S.Remote, S.Tableware, S.Book, S.Kitchenware, S.Food, S.Cup)
#: the violation per metre an everyday thing rests out of reach: a millimetre weighs as much
#: as a missing object (a room program's minimum), so the solver leaves a shelf short rather
#: than putting a book on top of the bookcase
OUT_OF_REACH = 1000.0
#: the weight of one object put away in the loss (the room programs' own terms weigh 0.5-4)
FILL_WEIGHT = 0.15
#: the weight of the mean height (m) of what is on display on shelving: decor drifts up, so
#: the shelves within reach hold the books
DISPLAY_WEIGHT = 0.5
#: the fullness of `indoorgen generate` without a preset's range: the middle of the default
DEFAULT_FULLNESS = 1.0


@dataclass(frozen=True)
class Load:
    """One kind of thing a piece of furniture holds: the tags every such thing carries (and
    those it must not), where it goes (`on_top` or `inside`) and how many at most per piece
    of furniture at fullness 1."""

    name: str
    tags: tuple[Tag, ...]
    relation: Relation
    most: int
    excluded: tuple[Tag, ...] = ()
    #: the cap never goes below this (a room program asking for at least so many)
    least: int = 1
    #: kept up high on shelving, leaving the shelves within reach to everyday things
    on_display: bool = False

    def things(self) -> ObjSet:
        """Every object of this kind, wherever it is."""
        return scene()[self.tags + tuple(Not(t) for t in self.excluded)]



#: small decor (vases, candles, table clocks, little plants); book stacks count as books and
#: balloons belong to parties
DECOR, NOT_DECOR = (S.Decor, S.SmallObject), (S.Book, S.Balloon)


def decor(most: int) -> Load:
    """Small decor on top, `most` per piece of furniture."""
    return Load("decor", DECOR, on_top, most, NOT_DECOR)


#: what each kind of furniture holds (the kinds: `holders`)
HOLDS: dict[str, tuple[Load, ...]] = {
    "shelving": (
        # the living room and the office ask for 8 and 6 books per bookcase at least
        Load("books", (S.Book,), on_top, 14, least=8),
        Load("decor", DECOR, on_top, 5, NOT_DECOR, on_display=True),
        Load("baskets", (S.Basket,), on_top, 2, on_display=True),
        Load("boxes", (S.Box,), on_top, 2, on_display=True),
    ),
    "base cabinets": (
        Load("plates", (S.Plate,), inside, 8),
        Load("bowls", (S.Bowl,), inside, 5, (S.Food,)),
        Load("pots", (S.Pot,), inside, 2),
        Load("pans", (S.Pan,), inside, 2),
        Load("jars", (S.Jar,), inside, 2),
    ),
    "wall cabinets": (
        Load("plates", (S.Plate,), inside, 5),
        Load("bowls", (S.Bowl,), inside, 4, (S.Food,)),
        Load("cups and glasses", (S.Cup,), inside, 8),
        Load("food", (S.Food,), inside, 3, (S.Tableware,)),
    ),
    "fridges": (
        Load("food", (S.Food,), inside, 10, (S.Tableware,)),
        Load("bottles", (S.Bottle,), inside, 5),
        Load("jars", (S.Jar,), inside, 3),
    ),
    "ranges": (
        # a pan left on the hob (on a glass top or a grate it stands on whole)
        Load("a pan", (S.Pan,), on_top, 1),
    ),
    "dishwashers": (
        Load("plates", (S.Plate,), inside, 6),
        Load("bowls", (S.Bowl,), inside, 3, (S.Food,)),
        Load("cups and glasses", (S.Cup,), inside, 4),
    ),
    "microwaves": (
        Load("a bowl", (S.Bowl,), inside, 1, (S.Food,)),
    ),
    "wardrobes": (
        Load("hung clothes", (S.Garment,), hung_from, 10),
        Load("folded clothes", (S.FoldedClothes,), inside, 14),
        Load("shoes", (S.Shoes,), inside, 3),
        Load("boxes", (S.Box,), inside, 3),
        Load("baskets", (S.Basket,), inside, 2),
    ),
    "cupboards": (
        Load("books", (S.Book,), inside, 4),
        Load("boxes", (S.Box,), inside, 2),
        Load("tableware", (S.Tableware,), inside, 8, (S.Food,)),
        Load("bottles", (S.Bottle,), inside, 3),
    ),
    "chests": (
        Load("a lamp", (S.TableLamp,), on_top, 1),
        decor(4),
        Load("books", (S.Book,), on_top, 3),
        Load("baskets", (S.Basket,), on_top, 1),
    ),
    "nightstand tops": (  # a 0.4 m top: the lamp, a book or two and a little decor, not nine things
        Load("a lamp", (S.TableLamp,), on_top, 1),
        decor(2),
        Load("books", (S.Book,), on_top, 2),
    ),
    "chests of drawers": (
        Load("folded clothes", (S.FoldedClothes,), inside, 6),
    ),
    "shoe racks": (
        Load("shoes", (S.Shoes,), on_top, 8),
    ),
    "bedside cupboards": (
        Load("books", (S.Book,), inside, 3),
        Load("boxes", (S.Box,), inside, 1),
    ),
    "dining tables": (
        Load("cutlery", (S.Cutlery,), on_top, 10),
        Load("glasses", (S.Wineglass,), on_top, 6),
        Load("bottles", (S.Bottle,), on_top, 2),
        Load("bowls", (S.Bowl,), on_top, 4),
        Load("candles", (S.Candle,), on_top, 2),
    ),
    "low tables": (
        Load("books", (S.Book,), on_top, 3),
        decor(3),
        Load("a remote", (S.Remote,), on_top, 1),
        Load("cups", (S.Cup,), on_top, 3),
    ),
    "desks": (
        Load("books", (S.Book,), on_top, 4),
        Load("a mug", (S.Mug,), on_top, 1),
        decor(2),
    ),
    "sofas": (
        Load("a book", (S.Book,), on_top, 1),
        Load("a laptop", (S.Laptop,), on_top, 1),
        Load("a remote", (S.Remote,), on_top, 1),
    ),
    "workbenches": (  # the tools at hand on the top, paint and boxes on the shelf under it
        Load("a toolbox", (S.Toolbox,), on_top, 1),
        Load("paint", (S.PaintCan,), on_top, 3),
        Load("jars of screws", (S.Jar,), on_top, 3),
        Load("boxes", (S.Box,), on_top, 2),
    ),
    "tool chests": (
        Load("a toolbox", (S.Toolbox,), on_top, 1),
        Load("paint", (S.PaintCan,), on_top, 2),
    ),
    "beds": (  # a laptop on every bed was the one prop repeated across bedrooms: desks hold them
        Load("folded clothes", (S.FoldedClothes,), on_top, 2),
        Load("a book", (S.Book,), on_top, 1),
    ),
}


#: what a closet's furniture holds instead: clothes, towels, shoes, boxes and baskets, where
#: the same shelves and cupboards in a living room hold books, decor and tableware
CLOSET_HOLDS: dict[str, tuple[Load, ...]] = {
    **HOLDS,
    "shelving": (
        Load("folded clothes", (S.FoldedClothes,), on_top, 5),
        Load("towels", (S.Towel,), on_top, 3),
        Load("shoes", (S.Shoes,), on_top, 2),
        Load("boxes", (S.Box,), on_top, 3),
        Load("baskets", (S.Basket,), on_top, 2),
    ),
    "cupboards": (
        Load("folded clothes", (S.FoldedClothes,), inside, 5),
        Load("shoes", (S.Shoes,), inside, 3),
        Load("boxes", (S.Box,), inside, 2),
    ),
    "chests": (
        Load("folded clothes", (S.FoldedClothes,), on_top, 2),
        Load("boxes", (S.Box,), on_top, 2),
        Load("baskets", (S.Basket,), on_top, 1),
    ),
    "shoe racks": (
        Load("shoes", (S.Shoes,), on_top, 6),
    ),
}
#: what shelving holds in a garage or a utility room: things stored (paint and tools among
#: them), not books and ornaments
STORE_HOLDS: dict[str, tuple[Load, ...]] = {
    **HOLDS,
    "shelving": (
        Load("boxes", (S.Box,), on_top, 4),
        Load("baskets", (S.Basket,), on_top, 2),
        Load("shoes", (S.Shoes,), on_top, 2),
        # two tins a shelf unit: more, and a utility room's few shelves held little else
        Load("paint", (S.PaintCan,), on_top, 2),
        Load("a toolbox", (S.Toolbox,), on_top, 1),
    ),
}
#: room types whose furniture holds other things than `HOLDS` says
HOLDS_BY_ROOM: dict[str, dict[str, tuple[Load, ...]]] = {
    "closet": CLOSET_HOLDS, "garage": STORE_HOLDS, "utility": STORE_HOLDS}


def holders(room: ObjSet) -> dict[str, ObjSet]:
    """The room's furniture by what it holds (the keys of `HOLDS`)."""
    floor = scene().related_to(room, on_floor)
    walls = scene().related_to(room, on_wall)
    return {
        "shelving": floor[S.Bookcase] | floor[S.Shelf].excluding(S.Warehouse, S.ShoeRack, S.Bookcase)
        | walls[S.WallShelf],
        "base cabinets": floor[S.KitchenCabinet].excluding(S.WallMounted),
        "wall cabinets": walls[S.WallCabinet],
        "fridges": floor[S.Fridge],
        "ranges": floor[S.Range],
        "dishwashers": floor[S.Dishwasher],
        "microwaves": scene()[S.Microwave].related_to(floor, on_top),
        "wardrobes": floor[S.Wardrobe],
        "cupboards": floor[S.Cabinet].excluding(S.KitchenCabinet, S.BathroomFixture, S.WallMounted),
        "chests": floor[S.Dresser] | floor[S.TVStand] | floor[S.ConsoleTable]
        | floor[S.Cabinet].excluding(S.KitchenCabinet, S.BathroomFixture, S.WallMounted),
        "nightstand tops": floor[S.Nightstand],
        "chests of drawers": floor[S.Dresser],
        "shoe racks": floor[S.ShoeRack],
        "bedside cupboards": bedside_cupboards(floor),
        "dining tables": floor[S.DiningTable],
        "low tables": floor[S.CoffeeTable] | floor[S.SideTable],
        "desks": floor[S.Desk],
        "sofas": floor[S.Sofa],
        "beds": floor[S.Bed],
        "workbenches": floor[S.Workbench],
        "tool chests": floor[S.ToolChest],
    }


#: the nightstand layouts with an open shelf or a door: a nightstand's drawers declare no floor
#: (a dresser's do: `chests of drawers`), so a nightstand of drawers only holds nothing inside
OPEN_NIGHTSTANDS = ("drawer_shelf", "drawer_door", "open")


def bedside_cupboards(floor: ObjSet) -> ObjSet:
    """The nightstands on `floor` with room inside (a shelf or a cupboard behind a door)."""
    return union([floor[S.Nightstand].of_generator("nightstand", layout=layout)
                  for layout in OPEN_NIGHTSTANDS])


def cap(load: Load, fullness: float) -> int:
    """The most things of `load`'s kind a piece of furniture holds at `fullness` (one of a
    kind, a lamp or a remote, stays one)."""
    return 1 if load.most == 1 else max(load.least, round(load.most * fullness))


def contents(room: ObjSet, fullness: float = DEFAULT_FULLNESS, room_type: str = "") -> Problem:
    """What the room's furniture holds (as `room_type`'s furniture does), `fullness` times the
    usual amount at most; everyday things within reach."""
    constraints, put_away, shown = {}, [], []
    kinds: dict[tuple[tuple[Tag, ...], tuple[Tag, ...]], ObjSet] = {}  # one set per kind of thing
    holds = HOLDS_BY_ROOM.get(room_type, HOLDS)
    for kind, furniture in holders(room).items():
        for load in holds[kind]:
            things = kinds.setdefault((load.tags, load.excluded), load.things())
            most = cap(load, fullness)
            constraints[f"{kind} hold {load.name}"] = furniture.all(
                at_most(things, load.relation, most))
            put_away.append(things.related_to(furniture, load.relation))
            if load.on_display:
                shown.append(put_away[-1])
    constraints["everyday things within reach"] = everyday(room).all(
        lambda o: height_of(o) * OUT_OF_REACH <= REACH_HEIGHT * OUT_OF_REACH)
    scores = {"things put away": union(put_away).count().maximize(FILL_WEIGHT)}
    if shown:
        scores["decor on display up high"] = union(shown).mean(height_of).maximize(DISPLAY_WEIGHT)
    return Problem(constraints, scores)


def at_most(things: ObjSet, relation: Relation, most: int) -> Callable[[ObjSet], Constraint]:
    """"A piece of furniture holds at most `most` of `things` by `relation`", for `all`."""
    return lambda piece: things.related_to(piece, relation).count() <= most


def everyday(room: ObjSet) -> ObjSet:
    """The everyday small things resting on or in anything of `room`."""
    furniture = scene().related_to(room, on_floor) | scene().related_to(room, on_wall)
    small = scene()[S.SmallObject]
    held = small.related_to(furniture, on_top) | small.related_to(furniture, inside)
    return union([held[t] for t in EVERYDAY])


def union(sets: list[ObjSet]) -> ObjSet:
    """The members of any of `sets` (at least one)."""
    out = sets[0]
    for s in sets[1:]:
        out = out | s
    return out
