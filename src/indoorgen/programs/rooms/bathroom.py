"""A bathroom: a toilet with its clearances, a basin with a mirror hung over it, a bath or shower
in a corner with a bath mat before it, the rails, hooks and holders on its walls at the heights
the guidelines name, and towels and toiletries (a tumbler, jars, a candle, a small plant) on the
basin's counter."""
from indoorgen.constraints import (
    ObjSet,
    Problem,
    SupportedBy,
    accessibility_cost,
    angle_alignment_cost,
    center_of_support_distance,
    height,
    scene,
)
from indoorgen.model.tags import Semantics as S
from indoorgen.model.tags import Subpart
from indoorgen.programs.relations import (
    against_wall,
    ceiling_lights,
    hung_above,
    mounted_at,
    on_floor,
    on_top,
    on_wall,
    side_to_wall,
    within_reach,
)

#: mounting heights (m, bottoms over the floor) putting the centres where NKBA Bathroom Planning
#: Guideline 19 and common practice put them (the quality report's `accessory_heights`): a roll
#: holder's centre at 0.6-0.75 m (it is 0.05-0.15 m tall), towel bars' at 1.0-1.2 m. A bare bar
#: is 0.045-0.07 m tall, its centre 1.09-1.11 m; one with a towel draped over it is 0.23-0.45 m
#: tall (`towel_bar`'s towel_drop), so it hangs lower, its centre 1.04-1.16 m. Rings and their
#: towels (0.15-0.35 m drop) hang from 0.978 m.
ROLL_HOLDER_BOTTOM = 0.62
BARE_BAR_BOTTOM = 1.07
DRAPED_BAR_BOTTOM = 0.93
TOWEL_RING_BOTTOM = 0.978
HOOK_BOTTOM = 1.6
#: a mirror cabinet hangs this far over the basin's counter or deck, clear of its tap
MIRROR_GAP = 0.4
#: a bath mat before a bath's or shower's front, this far out (m), centred within its width
before_front = SupportedBy(Subpart.Back, Subpart.Front, margin=0.03)
#: a compact shower: the smallest standard tray (0.8 x 0.8 m, EN 14527's smallest square) in a
#: corner behind a sliding door, which sweeps nothing before it: what a 1.8 x 2.4 m bathroom
#: holds beside a toilet and a basin, where a hinged or larger enclosure finds no corner
COMPACT_SHOWER = {"layout": "corner_square", "tray_length": 0.8, "tray_depth": 0.8,
                  "door": "sliding"}
#: a compact shower only in a bathroom this small (m^2): a 1.8 m-wide one up to 4.4 m long
#: (a 7.1 m^2, 1.8 x 3.9 m bathroom of home seed 1 found no corner for a full-size enclosure);
#: a larger one takes a full-size enclosure or a bath
COMPACT_AREA = 8.0
#: how steeply the compact shower's allowance falls past COMPACT_AREA (per m^2: 0 from 8.1 m^2)
COMPACT_STEP = 10.0


def bathroom(room: ObjSet) -> Problem:
    """A toilet, a basin with a mirror over it, a bath or a shower, rails and hooks at hand."""
    floor = scene().related_to(room, on_floor)
    along_walls = floor.related_to(room, against_wall)
    toilets = along_walls[S.Toilet]
    basins = along_walls[S.BathroomSink, S.Furniture]
    baths = along_walls[S.Bathtub].related_to(room, side_to_wall)
    # a full-size enclosure (a hinged square corner, a quadrant, a walk-in) or, in a small
    # bathroom, a compact one; the door param keeps the two sets apart
    showers = along_walls.of_generator("shower_enclosure", door="hinged").related_to(
        room, side_to_wall)
    compact_showers = along_walls.of_generator("shower_enclosure", **COMPACT_SHOWER).related_to(
        room, side_to_wall)
    bathing = baths | showers | compact_showers
    on_walls = scene().related_to(room, on_wall)

    def hung_at(objs: ObjSet, bottom: float) -> ObjSet:
        # the height first: a chain whose first link is the wall alone would be judged a
        # medium-stage set while the whole is placed with the floor-standing things
        return objs.related_to(room, mounted_at(bottom)).related_to(room, on_wall)
    bare_bars = hung_at(scene().of_generator("towel_bar", towel=False), BARE_BAR_BOTTOM)
    draped_bars = hung_at(scene().of_generator("towel_bar", towel=True), DRAPED_BAR_BOTTOM)
    rings = hung_at(scene()[S.TowelRing], TOWEL_RING_BOTTOM)
    roll_holders = hung_at(scene()[S.ToiletRollHolder], ROLL_HOLDER_BOTTOM)
    hooks = hung_at(scene()[S.RobeHook], HOOK_BOTTOM)
    mirrors = on_walls[S.MirrorCabinet].related_to(basins, hung_above(MIRROR_GAP))
    lights = ceiling_lights(room)
    # rolled towels on a basin's or vanity's counter; a bath's rim is too narrow to hold one
    # still (one on an alcove tub's end deck rolled off in MuJoCo, home seed 0)
    towels = scene()[S.Towel].related_to(basins, on_top)
    on_basins = scene().related_to(basins, on_top)
    # a tumbler, jars, a candle, a small plant (counted as a sum: the solver adds to each set)
    kinds = [on_basins[S.Cup], on_basins[S.Jar], on_basins[S.Candle], on_basins[S.SmallObject, S.Plant]]
    toiletries = kinds[0] | kinds[1] | kinds[2] | kinds[3]
    toiletry_count = kinds[0].count() + kinds[1].count() + kinds[2].count() + kinds[3].count()
    # a mat on the floor where one steps out of the bath or shower
    mats = floor[S.BathMat].related_to(bathing, before_front)
    return Problem(
        constraints={
            "a toilet": toilets.count() == 1,
            "a basin": basins.count().in_range(1, 2),
            "a bath or a shower": (baths.count() + showers.count()
                                   + compact_showers.count()).in_range(1, 2),
            "a compact shower only in a small bathroom": compact_showers.count() <= (
                (COMPACT_AREA - room.volume((0, 1))) * COMPACT_STEP).clip(0.0, 1.0),
            "a mirror": mirrors.count().in_range(0, 1),
            "a towel rail": (bare_bars.count() + draped_bars.count()
                             + rings.count()).in_range(1, 2),
            "a roll holder": roll_holders.count() == 1,
            "hooks": hooks.count().in_range(0, 2),
            "a ceiling light": lights.count() == 1,
            "towels": towels.count().in_range(0, 3),
            "toiletries": toiletry_count.in_range(0, 4),
            "a bath mat": mats.count().in_range(0, 1),
            "toiletries within reach": within_reach(toiletries),
        },
        score_terms={
            "a mirror over the basin": mirrors.count().maximize(2),
            "roll holder by the toilet": roll_holders.mean(
                lambda r: r.distance(toilets).hinge(0.1, 0.4)).minimize(3),
            "rails near the basin or bath": (bare_bars | draped_bars | rings).mean(
                lambda t: t.distance(basins | bathing).hinge(0.0, 1.0)).minimize(0.5),
            "fixtures free to use": accessibility_cost(along_walls, floor).minimize(2),
            "square to the walls": angle_alignment_cost(floor, room).minimize(1),
            "a towel out": towels.count().maximize(0.5),
            "toiletries out": toiletry_count.maximize(0.3),
            "a bath mat": mats.count().maximize(1),
            "the mat centred on the bath or shower": mats.mean(
                lambda m: m.center_distance(bathing)).minimize(1),
            "toiletries in the middle": center_of_support_distance(toiletries).minimize(0.3),
            "hooks high": hooks.mean(lambda h: height(h).hinge(1.6, 1.9)).minimize(0.1),
        },
    )
