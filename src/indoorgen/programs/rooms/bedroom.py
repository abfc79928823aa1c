"""A bedroom: the bed's head to a wall with free access to both sides, matching nightstands at
the head with lamps, a wardrobe or dresser with room before it, a rug at the bed's foot,
clothes, books and decor; a bookcase and wall shelves where there is room, plants, pictures and
a floor lamp; sometimes a desk with its chair, lamp and laptop, a reading chair, or a bench at
the bed's foot."""
from indoorgen.constraints import (
    Constraint,
    ObjSet,
    Problem,
    Scalar,
    SupportedBy,
    accessibility_cost,
    angle_alignment_cost,
    front_clearance,
    height,
    reflectional_asymmetry,
    scene,
)
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from indoorgen.programs.relations import (
    DESK_CHAIR_ROOM,
    DOOR_SWING,
    against_wall,
    at_bedside,
    at_table,
    bed_rugs,
    ceiling_lights,
    fronts_free,
    inside,
    on_floor,
    on_top,
    on_wall,
    under_bed_foot,
    within_reach,
)
from indoorgen.programs.windows import curtains_at_windows

#: free depth beside a bed to get in and make it, and for a nightstand (m): ergonomic guidance
#: 0.6-0.7 m; each side weighs at most 0.3 (half a violation per metre short), so a bed placed
#: with a side blocked still beats no bed and is then moved clear
BED_SIDE = 0.6
#: how far beside the bed its side clearance is probed (m)
SIDE_PROBE = 1.0
#: a bedroom whose plan box is larger than this (m^2) has a bookcase: a 12-15 m^2 bedroom holds
#: the bed, nightstands and a wardrobe with their clearances, and about 1 m^2 more (a bookcase
#: 0.3-0.4 m deep and its 0.6 m front) fits from 16 m^2 on
BOOKCASE_AREA = 16.0
#: a bedroom whose plan box is larger than this (m^2) has a wardrobe (a dresser alone is for
#: the smallest rooms, or those with a closet)
WARDROBE_AREA = 13.0
#: the violation of a larger room's missing wardrobe or bookcase (a missing bed weighs 1)
LARGER_ROOM = 0.5
#: the band a wall shelf's centre hangs in (m): above a nightstand or desk (0.7 m) and within
#: reach, its top board no higher than eye level (the reach rule's 1.6 m)
SHELF_BAND = (1.0, 1.45)
#: the reward of a rug under the bed's foot (a rug 0.5 m off centre costs 2 in `rugs_centred`)
RUG_REWARD = 2.5
#: a bedroom whose plan box is larger than this (m^2) is asked for a desk corner (a desk 1.0-1.4
#: x 0.5-0.7 m and its chair's 0.8 m pull-out: 2 m^2 past a 12-15 m^2 room's bed and storage)
DESK_AREA = 13.5
#: a bedroom whose plan box is larger than this (m^2) is asked for a dresser beside the wardrobe
#: (1.0-1.5 x 0.4-0.5 m and 0.6 m before its drawers: about 1.3 m^2 past the wardrobe's room)
DRESSER_AREA = 12.5
#: the reward of the dresser once the room is a square metre past DRESSER_AREA
DRESSER_REWARD = 1.5
#: the reward of a desk corner once the room is a square metre past DESK_AREA
DESK_REWARD = 1.0
#: storage boxes on top of a wardrobe at most (0.5-2.4 m wide: two or three side by side)
WARDROBE_TOP_BOXES = 3
#: the band a picture's centre hangs in (m): eye level (gallery hanging guidance: a centre at
#: 1.45-1.6 m), kept as a rule
EYE_LEVEL = (1.4, 1.8)
#: the band a wall clock's centre hangs in (m): at or over eye level, read across the room
CLOCK_BAND = (1.6, 2.1)
#: the violation per metre a picture's centre is off eye level: under a missing picture's 1 for
#: a picture up to half a metre off, so a picture is hung first and then moved into the band
EYE_LEVEL_WEIGHT = 2.0
#: a bedroom whose plan box is larger than this (m^2) is asked for a bench at the bed's foot
#: (0.35-0.45 m deep, with the 0.6 m walkway before it: about 1.5 m^2 past a desk corner)
BENCH_AREA = 15.0
#: the reward of the bench once the room is a square metre past BENCH_AREA
BENCH_REWARD = 1.0
#: a bench at the bed's foot: its back 5 cm off the foot, its centre within the bed's width
at_bed_foot = SupportedBy(Subpart.Back, Subpart.Front, margin=0.05)


def bedroom(room: ObjSet) -> Problem:
    """One bed against a wall, matching nightstands at its head, clothes storage, a rug and the
    things of a lived-in room."""
    floor = scene().related_to(room, on_floor)
    blockers = floor.excluding(S.FloorCovering)
    # no under-bed drawers: the nightstands at the head would stop them opening
    beds = floor[S.Bed].of_generator("bed", drawers=False).related_to(room, against_wall)
    nightstands = floor[S.Nightstand].related_to(room, against_wall).related_to(beds, at_bedside)
    wardrobes = floor[S.Wardrobe].related_to(room, against_wall)
    dressers = floor[S.Dresser].related_to(room, against_wall)
    desks = floor[S.Desk].related_to(room, against_wall)
    desk_chairs = floor[S.Chair].excluding(S.DiningChair, S.Armchair).related_to(desks, at_table)
    reading_chairs = floor[S.Armchair]
    bookcases = floor[S.Bookcase].related_to(room, against_wall)
    shelves = scene()[S.WallShelf].related_to(room, on_wall)
    floor_lamps = floor[S.FloorLamp]
    # a laundry basket and a pair of shoes stand on the floor by a wall
    floor_things = floor[S.Basket] | floor[S.Shoes]
    rugs = bed_rugs(floor).related_to(beds, under_bed_foot)
    benches = floor[S.Bench].of_generator("bench", back=False).related_to(beds, at_bed_foot)
    plants = floor[S.PottedPlant]
    art = scene()[S.WallArt].related_to(room, on_wall)
    mirrors = scene().of_generator("mirror").related_to(room, on_wall)
    wall_clocks = scene()[S.Clock, S.WallMounted].related_to(room, on_wall)
    # boxes kept on top of the wardrobe (out-of-season things; nothing used every day)
    stored_on_top = scene()[S.Box].related_to(wardrobes, on_top)
    lamps = scene()[S.TableLamp].related_to(nightstands, on_top)
    desk_lamps = scene()[S.DeskLamp].related_to(desks, on_top)
    laptops = scene()[S.Laptop].related_to(desks, on_top)
    surfaces = nightstands | dressers | desks
    books = scene()[S.Book].related_to(surfaces, on_top)
    # clothes laid on the bed, the dresser or a chair
    clothes = scene()[S.FoldedClothes].related_to(
        dressers | beds | reading_chairs | desk_chairs | benches, on_top)
    decor = scene()[S.SmallObject].excluding(
        S.Food, S.Kitchenware, S.Tableware, S.Lighting, S.Book, S.Textile, S.Balloon,
        S.Electronics, S.Shoes, S.Workshop).related_to(surfaces, on_top)
    # what the wardrobe and the shelves hold (clothes, shoes, boxes, books, decor)
    household = scene()[S.SmallObject].excluding(S.Workshop)
    kept = household.related_to(wardrobes, inside) | household.related_to(shelves | bookcases, on_top)

    def side_clearance(bed: ObjSet, side: str) -> Scalar:
        return front_clearance(bed, blockers.excluding(S.Nightstand) | room, probe=SIDE_PROBE,
                               face=side)

    def side_free(bed: ObjSet, side: str) -> Constraint:
        return side_clearance(bed, side) * 0.5 >= BED_SIDE * 0.5

    return Problem(
        constraints={
            "a bed": beds.count() == 1,
            "up to two nightstands at the head": nightstands.count().in_range(0, 2),
            "a wardrobe or a dresser": (wardrobes.count() + dressers.count()).in_range(1, 2),
            "a desk at most": desks.count().in_range(0, 1),
            "a chair at the desk": desks.all(lambda d: desk_chairs.related_to(d, at_table).count() == 1),
            "a reading chair at most": reading_chairs.count().in_range(0, 1),
            "a rug at most": rugs.count().in_range(0, 1),
            "a bench at most": benches.count().in_range(0, 1),
            "up to two plants": plants.count().in_range(0, 2),
            "a bookcase at most": bookcases.count().in_range(0, 1),
            # asked for once the bed stands, 0 up to the area, then up to LARGER_ROOM (any
            # fraction asks for one): a missing one weighs less than the bed, which comes first
            "a wardrobe in a larger room": beds.all(lambda b: wardrobes.count() >= (
                (room.volume((0, 1)) - WARDROBE_AREA) * LARGER_ROOM).clip(0.0, LARGER_ROOM)),
            "a bookcase in a larger room": beds.all(lambda b: bookcases.count() >= (
                (room.volume((0, 1)) - BOOKCASE_AREA) * LARGER_ROOM).clip(0.0, LARGER_ROOM)),
            "a wall shelf or two": shelves.count().in_range(1, 2),
            "a floor lamp at most": floor_lamps.count().in_range(0, 1),
            "a laundry basket at most": floor[S.Basket].count().in_range(0, 1),
            "shoes on the floor": floor[S.Shoes].count().in_range(0, 2),
            "a lamp on the desk": desks.all(lambda d: desk_lamps.related_to(d, on_top).count() <= 1),
            "a laptop on the desk": desks.all(lambda d: laptops.related_to(d, on_top).count() <= 1),
            "a ceiling light": ceiling_lights(room).count() == 1,
            "a lamp on each nightstand": nightstands.all(
                lambda n: lamps.related_to(n, on_top).count() == 1),
            "pictures": art.count().in_range(1, 3),
            # a wall shelf hung low over a nightstand leaves its lamp no room
            "wall shelves within reach": shelves.all(
                lambda s: (height(s) * EYE_LEVEL_WEIGHT).in_range(
                    SHELF_BAND[0] * EYE_LEVEL_WEIGHT, SHELF_BAND[1] * EYE_LEVEL_WEIGHT)),
            "pictures and the mirror centred at eye level": (art | mirrors).all(
                lambda a: (height(a) * EYE_LEVEL_WEIGHT).in_range(
                    EYE_LEVEL[0] * EYE_LEVEL_WEIGHT, EYE_LEVEL[1] * EYE_LEVEL_WEIGHT)),
            "a mirror at most": mirrors.count().in_range(0, 1),
            "a wall clock at most": wall_clocks.count().in_range(0, 1),
            "the clock above eye level": wall_clocks.all(
                lambda c: (height(c) * EYE_LEVEL_WEIGHT).in_range(
                    CLOCK_BAND[0] * EYE_LEVEL_WEIGHT, CLOCK_BAND[1] * EYE_LEVEL_WEIGHT)),
            "boxes on the wardrobe": wardrobes.all(
                lambda w: stored_on_top.related_to(w, on_top).count() <= WARDROBE_TOP_BOXES),
            "books": books.count().in_range(0, 10),
            "clothes": clothes.count().in_range(0, 6),
            "decor": decor.count().in_range(0, 12),
            "wardrobe doors free": fronts_free(wardrobes, blockers, room, margin=DOOR_SWING),
            # two constraints: one counts from the stage of its latest set on, so the large
            # furniture's fronts are kept free while the large stage places it
            "storage fronts free": fronts_free(dressers | bookcases, blockers, room),
            # the desk's own chair stands before it (it blocked its own desk: no chair was ever
            # pulled up); anything else keeps the chair's room free
            "room for the desk's chair": fronts_free(desks, blockers.excluding(S.Chair), room,
                                                     need=DESK_CHAIR_ROOM),
            "nightstand fronts free": fronts_free(nightstands, blockers, room),
            "the bed's foot free": fronts_free(beds, blockers.excluding(S.Bench), room),
            "the bench's front free": fronts_free(benches, blockers, room),
            # a narrow room's bed stands along a wall, free on one side; the score below asks
            # for both
            "free access to a side": beds.all(lambda b: side_free(b, "left") | side_free(b, "right")),
            "everyday things within reach": within_reach(books | decor | laptops),
        },
        score_terms={
            "nightstands match either side": beds.mean(
                lambda b: reflectional_asymmetry(nightstands, b)).minimize(2),
            "two nightstands": nightstands.count().maximize(2),
            "the bed centred on its wall": beds.mean(lambda b: b.center_distance(room)).minimize(0.5),
            "bed side free": accessibility_cost(beds, blockers.excluding(S.Nightstand)).minimize(2),
            "free access to both sides": beds.mean(
                lambda b: side_clearance(b, "left").hinge(BED_SIDE, SIDE_PROBE)
                + side_clearance(b, "right").hinge(BED_SIDE, SIDE_PROBE)).minimize(4),
            "furniture square to the walls": angle_alignment_cost(blockers, room).minimize(1),
            "plants by the walls": plants.mean(lambda p: p.distance(room).hinge(0.0, 0.1)).minimize(2),
            "pictures in view": accessibility_cost(art, blockers).minimize(2),
            # one term per stage (a term counts from the stage of its latest set on): the
            # furniture, what hangs on the walls, the things on and in the furniture
            "a furnished room": (bookcases.count() * 3 + dressers.count() + rugs.count()
                                 + plants.count() + floor_lamps.count()
                                 + floor_things.count()).maximize(0.3),
            # a rug is added off centre, so its reward must outweigh the centring term
            # (`rugs_centred`, weight 4) until a translate centres it
            "a rug under the bed's foot": rugs.count().maximize(RUG_REWARD),
            "a dresser as well in a larger room": (dressers.count() * (
                room.volume((0, 1)) - DRESSER_AREA).clip(0.0, 1.0)).maximize(DRESSER_REWARD),
            "a desk corner in a larger room": (desks.count() * (
                room.volume((0, 1)) - DESK_AREA).clip(0.0, 1.0)).maximize(DESK_REWARD),
            "a bench at the bed's foot in a larger room": (benches.count() * (
                room.volume((0, 1)) - BENCH_AREA).clip(0.0, 1.0)).maximize(BENCH_REWARD),
            "things on the floor by the walls": floor_things.mean(
                lambda t: t.distance(room).hinge(0.0, 0.1)).minimize(2),
            "things on the walls": (shelves.count() * 2 + art.count() + mirrors.count()
                                    + wall_clocks.count() + stored_on_top.count()).maximize(0.6),
            "a lived-in room": (books.count() + clothes.count() + decor.count() + desk_lamps.count()
                                + laptops.count()).maximize(0.3),
            "things kept in the wardrobe and on the shelves": kept.count().maximize(0.3),
            "shelves free": accessibility_cost(bookcases, blockers).minimize(1),
            "reading chair by a lamp or window": reading_chairs.mean(
                lambda c: c.distance(room).hinge(0.0, 0.3)).minimize(0.5),
        },
        matching={"nightstands": nightstands, "bedside lamps": lamps},
    ) + curtains_at_windows()
