"""Relations every room program uses, named for what they mean in a room, the ceiling lights
every room counts and the headroom they leave, and the reach and clearance requirements rooms
share."""
from indoorgen.constraints import (
    Constraint,
    ObjSet,
    Problem,
    StableAgainst,
    SupportedBy,
    front_clearance,
    height,
    scene,
)
from indoorgen.model.tags import Semantics, Subpart

#: the highest an everyday thing rests (m): quality's reach rule (REACH_HEIGHT, standing reach)
REACH = 1.6
#: free depth before storage fronts (m): quality's FRONT_CLEAR (0.6 m to open a door or drawer
#: and stand before it)
FRONT_FREE = 0.6
#: free depth before a desk (m): its chair pulled up and pushed back (ergonomic guidance
#: 0.8-1.1 m); the chair itself stands in it
DESK_CHAIR_ROOM = 0.8
#: the least height (m) of a hanging light's bottom over open floor: clear of a tall person's
#: head (a 95th-percentile man is 1.87 m tall; doors are 2.03 m high). The quality report's
#: `light_headroom` measures the same
LIGHT_HEADROOM = 2.0
#: the least distance (m) from a ceiling light's centre to the walls: lighting layouts centre a
#: room's fixture, and keep recessed ones 2-3 ft (0.6-0.9 m) off the walls so the light falls on
#: the room, not in a corner. The quality report's `light_off_the_walls` measures the same (in
#: a room too narrow for it, most of the way to its middle)
LIGHT_FROM_WALLS = 0.6
#: how much farther off the walls the programs aim a light (m), and the weight of each metre
#: short of that: less than a light centred over a dining table
LIGHT_AIM, LIGHT_WEIGHT = 0.2, 4.0
#: the least height (m) of a light's bottom over a dining table: lighting guidance hangs it
#: 30-36 in (0.76-0.91 m) over the table's top, which stands 0.72-0.78 m high
OVER_TABLE_BOTTOM = 1.5

#: standing on the room's floor
on_floor = StableAgainst(Subpart.Bottom, Subpart.Floor)
#: back to a wall, 5 cm off it (skirting boards, cables)
against_wall = StableAgainst(Subpart.Back, Subpart.Wall, margin=0.05)
#: hanging flat on a wall (pictures, mirrors), not overhanging its edges
on_wall = StableAgainst(Subpart.Back, Subpart.Wall)
#: resting on a tabletop, shelf or stand without tipping over: its whole base on the surface
#: (a centroid over the edge let books and clocks at a shelf's edge fall in MuJoCo)
on_top = StableAgainst(Subpart.Bottom, Subpart.SupportSurface)
#: put away inside: on a shelf or floor behind a cabinet's, wardrobe's or fridge's doors
inside = SupportedBy(Subpart.Bottom, Subpart.Interior)
#: a chair pulled up to a table: its front 4 cm under the table's edge (clear of legs inset
#: from the edge and of stretchers between them)
at_table = StableAgainst(Subpart.Front, Subpart.Side, margin=-0.04, overhang=False)
#: hung from a rail by a hanger's hook (clothes in a wardrobe): the hook's centre on the rail,
#: turned across it (the solver's `placement.hung_yaw`), exported fixed to what holds the rail
hung_from = SupportedBy(Subpart.Hook, Subpart.Rail)
#: hanging from the ceiling by its top (ceiling lights, pendants)
on_ceiling = StableAgainst(Subpart.Top, Subpart.Ceiling)
#: a side flush against a wall (the second wall of a corner: a bathtub, a kitchen run's end)
side_to_wall = StableAgainst(Subpart.Side, Subpart.Wall, margin=0.02)
#: a coffee table before a seat: its back 0.45 m from the seat's front, its centre within the
#: seat's width (furniture-layout guidance: 0.3-0.6 m; quality's COFFEE_GAP)
before_seat = SupportedBy(Subpart.Back, Subpart.Front, margin=0.45)
#: how far a seating group's rug reaches under the seat (m): under its front legs (layout
#: guidance: at least the front legs of every seat of the group on the rug)
RUG_UNDER_SEAT = 0.25
#: a rug under a seating group: its back edge `RUG_UNDER_SEAT` behind the seat's front, its
#: centre within the seat's width (the coffee table before the seat lies on it)
under_seat_front = SupportedBy(Subpart.Back, Subpart.Front, margin=-RUG_UNDER_SEAT)
#: how far a bed's rug reaches under it from the foot (m): its lower two-thirds, for a 2.1 m bed
RUG_UNDER_BED = 1.4
#: a rug under a bed's lower two-thirds: its back edge `RUG_UNDER_BED` in from the foot, centred
under_bed_foot = SupportedBy(Subpart.Back, Subpart.Front, margin=-RUG_UNDER_BED)
#: beside: a side 5 cm from a seat's side, its centre within that side's depth (a side table at
#: the sofa's arm)
beside = SupportedBy(Subpart.Side, Subpart.Side, margin=0.05)
#: at the bedside: a side 10 cm from the bed's, its centre within the bed's length (room for a
#: nightstand's door to swing open past its side; quality's NIGHTSTAND_GAP is 0.15 m)
at_bedside = SupportedBy(Subpart.Side, Subpart.Side, margin=0.1)
#: a second seat in line with the first, 0.6 m off its arm (room for a side table between)
in_line_with = SupportedBy(Subpart.Side, Subpart.Side, margin=0.6)


def ceiling_lights(room: ObjSet) -> ObjSet:
    """The lights hanging from `room`'s ceiling (every room program counts them)."""
    return scene()[Semantics.CeilingMounted, Semantics.Lighting].related_to(room, on_ceiling)


def flush_lights(room: ObjSet) -> ObjSet:
    """The flush-mounted ceiling lights of `room` (no pendant): what a garage, a utility room or
    a closet is lit by, where a hanging shade would meet a car's roof or a shelf's top box."""
    return ceiling_lights(room).excluding(Semantics.PendantLight)


def lights_clear(room: ObjSet, least: float = LIGHT_HEADROOM) -> Problem:
    """What every room asks of its ceiling lights: their bottoms `least` metres or more above the
    floor (a centimetre short weighs as much as a missing object), and their centres over the
    room, LIGHT_FROM_WALLS or more off the walls (as far as the room allows)."""
    lights = ceiling_lights(room)
    return Problem(
        constraints={"lights clear of heads": lights.all(
            lambda li: (height(li) - li.volume((2,)) * 0.5) * 100 >= least * 100)},
        score_terms={"lights over the room": lights.mean(
            lambda li: (li.distance(room) + li.volume((0,)) * 0.5)
            .hinge(LIGHT_FROM_WALLS + LIGHT_AIM, 99.0)).minimize(LIGHT_WEIGHT)})


def across_from(distance: float) -> StableAgainst:
    """Facing the parent across the floor: its front `distance` metres from the parent's front,
    turned to it, its centre within the parent's width (a sofa across from the TV stand)."""
    return SupportedBy(Subpart.Front, Subpart.Front, margin=distance)


def sized_rugs(floor: ObjSet, length: float, width: float, shape: str = "rect") -> ObjSet:
    """Rugs on `floor` of one size (m: `length` along the group, `width` across it; a round rug's
    diameter is its length, and its width is unused), big enough for what stands on them."""
    return floor.of_generator("rug", shape=shape, length=length, width=width)


def bed_rugs(floor: ObjSet) -> ObjSet:
    """Rugs on `floor` sized for a bed: 2.4 m across it (0.3 m or more each side of a double) and
    2.0 m along it, so one under its lower two-thirds (`under_bed_foot`) shows 0.6 m past its foot."""
    return sized_rugs(floor, 2.4, 2.0)


def rugs_centred(room: ObjSet) -> Problem:
    """What every room asks of its rugs: one under a bed's foot centred across the bed (the
    relation fixes how far under it lies, not where along the foot)."""
    beds = scene()[Semantics.Bed].related_to(room, on_floor)
    rugs = scene()[Semantics.Rug].related_to(room, on_floor).related_to(beds, under_bed_foot)
    return Problem(score_terms={
        "a bed's rug centred across it": rugs.mean(lambda r: r.center_distance(beds)).minimize(4)})


def mounted_at(height: float) -> StableAgainst:
    """Hung with its bottom `height` metres above the room's floor: with `on_wall`, a wall
    accessory at the mounting height a standard names (the height is the relation's, not luck)."""
    return StableAgainst(Subpart.Bottom, Subpart.Floor, margin=height)


def hung_above(gap: float, parent: Subpart = Subpart.SupportSurface) -> StableAgainst:
    """Hanging with its bottom `gap` metres above a parent's `parent` surface, its centre over
    it: with `on_wall`, a wall cabinet over a counter, a hood over a range, a mirror over a basin."""
    return StableAgainst(Subpart.Bottom, parent, margin=gap, overhang=False)


def within_reach(objs: ObjSet) -> Constraint:
    """Every member's centre at most `REACH` above its floor (laptops on desks, not wardrobes);
    a centimetre too high weighs as much as an object too few."""
    return objs.all(lambda o: height(o) * 100 <= REACH * 100)


def fronts_free(objs: ObjSet, blockers: ObjSet, room: ObjSet, need: float = FRONT_FREE,
                margin: float = 0.05) -> Constraint:
    """Every member keeps `need` metres free before its front (over its width less `margin` at
    either end; a negative margin widens the band for doors that swing past the sides), to the
    walls and `blockers`; a centimetre short weighs as much as an object too few."""
    return objs.all(lambda o: front_clearance(o, blockers | room, margin=margin) * 100 >= need * 100)


#: how far a hinged door swings past its carcass's side, opened to its limit (m)
DOOR_SWING = -0.15
