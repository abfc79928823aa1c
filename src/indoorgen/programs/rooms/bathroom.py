"""A bathroom: a toilet, a basin with a mirror above it, a bath or shower in a corner, and the
rails, hooks and holders that go on its walls."""
from indoorgen.constraints import ObjSet, Problem, accessibility_cost, angle_alignment_cost, height, scene
from indoorgen.model.tags import Semantics as S
from indoorgen.programs.relations import against_wall, ceiling_lights, on_floor, on_top, on_wall, side_to_wall


def bathroom(room: ObjSet) -> Problem:
    """A toilet, a basin with a mirror above it, a bath or a shower, rails and hooks at hand."""
    floor = scene().related_to(room, on_floor)
    along_walls = floor.related_to(room, against_wall)
    toilets = along_walls[S.Toilet]
    basins = along_walls[S.BathroomSink, S.Furniture]
    baths = along_walls[S.Bathtub].related_to(room, side_to_wall)
    showers = along_walls[S.Shower].related_to(room, side_to_wall)
    on_walls = scene().related_to(room, on_wall)
    towel_rails = on_walls[S.TowelBar] | on_walls[S.TowelRing]
    roll_holders = on_walls[S.ToiletRollHolder]
    hooks = on_walls[S.RobeHook]
    lights = ceiling_lights(room)
    towels = scene()[S.Towel].related_to(basins | baths, on_top)
    return Problem(
        constraints={
            "a toilet": toilets.count() == 1,
            "a basin": basins.count().in_range(1, 2),
            "a bath or a shower": (baths.count() + showers.count()).in_range(1, 2),
            "a mirror": on_walls[S.MirrorCabinet].count().in_range(0, 1),
            "a towel rail": (on_walls[S.TowelBar].count() + on_walls[S.TowelRing].count()).in_range(1, 2),
            "a roll holder": roll_holders.count() == 1,
            "hooks": hooks.count().in_range(0, 2),
            "a ceiling light": lights.count() == 1,
            "towels": towels.count().in_range(0, 3),
        },
        score_terms={
            "mirror above the basin": on_walls[S.MirrorCabinet].mean(
                lambda m: m.distance(basins).hinge(0.0, 0.05)).minimize(3),
            "mirror at eye level": on_walls[S.MirrorCabinet].mean(
                lambda m: height(m).hinge(1.45, 1.7)).minimize(2),
            "roll holder by the toilet": roll_holders.mean(
                lambda r: r.distance(toilets).hinge(0.1, 0.4)).minimize(3),
            "rails at hand height": towel_rails.mean(lambda t: height(t).hinge(0.9, 1.3)).minimize(1),
            "hooks high": hooks.mean(lambda h: height(h).hinge(1.5, 1.8)).minimize(1),
            "fixtures free to use": accessibility_cost(along_walls, floor).minimize(2),
            "square to the walls": angle_alignment_cost(floor, room).minimize(1),
            "a towel out": towels.count().maximize(0.2),
        },
    )
