"""The small and service rooms of a home: closet, hallway, utility room, staircase room, garage
and balcony. Each is short: what stands along the walls, what hangs on them, and what sits on
the shelves."""
from indoorgen.constraints import Problem, accessibility_cost, angle_alignment_cost, height, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.common import against_wall, on_ceiling, on_floor, on_top, on_wall


def _ceiling_light(room, lo: int = 1, hi: int = 1):
    return scene()[S.CeilingMounted, S.Lighting].related_to(room, on_ceiling).count().in_range(lo, hi)


def closet(room) -> Problem:
    along_walls = scene().related_to(room, on_floor).related_to(room, against_wall)
    storage = along_walls[S.Storage, S.Furniture].excluding(
        S.Warehouse, S.KitchenCabinet, S.TVStand, S.Vanity, S.WallMounted, S.BathroomFixture)
    stored = scene()[S.Textile].related_to(storage, on_top) | scene()[S.Box].related_to(storage, on_top)
    return Problem(
        constraints={
            "storage along the walls": storage.count().in_range(1, 3),
            "a light": _ceiling_light(room, 0, 1),
            "folded clothes": scene()[S.FoldedClothes].related_to(storage, on_top).count().in_range(0, 6),
            "boxes": scene()[S.Box].related_to(storage, on_top).count().in_range(0, 3),
        },
        score_terms={
            "as much storage as fits": storage.count().maximize(1),
            "things put away": stored.count().maximize(0.2),
            "doors free": accessibility_cost(storage, along_walls).minimize(1),
        },
    )


def hallway(room) -> Problem:
    along_walls = scene().related_to(room, on_floor).related_to(room, against_wall)
    furniture = along_walls[S.ConsoleTable] | along_walls[S.ShoeRack]
    on_walls = scene().related_to(room, on_wall)
    return Problem(
        constraints={
            "a console table at most": along_walls[S.ConsoleTable].count().in_range(0, 1),
            "a shoe rack at most": along_walls[S.ShoeRack].count().in_range(0, 1),
            "a mirror or pictures": (on_walls[S.Mirror].count() + on_walls[S.WallArt].count()).in_range(1, 3),
            "ceiling lights": _ceiling_light(room, 1, 2),
            "things on the console": scene()[S.Decor].related_to(
                along_walls[S.ConsoleTable], on_top).count().in_range(0, 2),
        },
        score_terms={
            "a place for shoes and keys": furniture.count().maximize(0.5),
            "pictures at eye level": on_walls.mean(lambda a: height(a).hinge(1.3, 1.8)).minimize(1),
            "square to the walls": angle_alignment_cost(along_walls, room).minimize(1),
        },
    )


def utility(room) -> Problem:
    along_walls = scene().related_to(room, on_floor).related_to(room, against_wall)
    washers = along_walls[S.WashingMachine]
    shelves = along_walls[S.Shelf].excluding(S.Warehouse)
    return Problem(
        constraints={
            "a washing machine": washers.count().in_range(1, 2),
            "shelves": shelves.count().in_range(0, 2),
            "a light": _ceiling_light(room),
            "baskets and boxes": (scene()[S.Basket].related_to(shelves | washers, on_top).count()
                                  + scene()[S.Box].related_to(shelves, on_top).count()).in_range(0, 4),
        },
        score_terms={
            "doors free": accessibility_cost(washers, along_walls).minimize(2),
            "storage": shelves.count().maximize(0.5),
        },
    )


def staircase_room(room) -> Problem:
    on_walls = scene().related_to(room, on_wall)
    plants = scene().related_to(room, on_floor)[S.PottedPlant].related_to(room, against_wall)
    return Problem(
        constraints={
            "pictures": on_walls[S.WallDecoration].count().in_range(0, 2),
            "a plant at most": plants.count().in_range(0, 1),
            "a light": _ceiling_light(room),
        },
        score_terms={"pictures at eye level": on_walls.mean(lambda a: height(a).hinge(1.4, 1.8)).minimize(1)},
    )


def garage(room) -> Problem:
    along_walls = scene().related_to(room, on_floor).related_to(room, against_wall)
    shelving = along_walls[S.Shelf].excluding(S.WallMounted, S.Warehouse)
    boxes = scene()[S.Box].related_to(shelving, on_top)
    return Problem(
        constraints={
            "shelving": shelving.count().in_range(1, 3),
            "boxes on the shelves": boxes.count().in_range(1, 10),
            "lights": _ceiling_light(room, 1, 2),
        },
        score_terms={
            "storage": boxes.count().maximize(0.2),
            "shelves reachable": accessibility_cost(shelving, along_walls).minimize(1),
        },
    )


def balcony(room) -> Problem:
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
